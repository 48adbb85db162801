#!/bin/sh
# Whole-compiler tests of `aeroeval build` and `aeroeval solve`: outputs,
# exit statuses, reproducibility, nothing written for a bad mission.
# Prints "ok NAME" / "not ok NAME"; run by tests/run_all.sh with $AEROEVAL.
AE=${AEROEVAL:-build/aeroeval}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
check() { if [ "$1" -eq 0 ]; then echo "ok $2"; else echo "not ok $2"; fi; }

# Every example compiles to result.json and bom.csv.
"$AE" build -o "$T/a" examples/ 2>"$T/a.err"; rc=$?
[ "$rc" -le 1 ]; check $? "build_examples_exit_status_is_0_or_1"
for f in examples/*.json; do
	n=$(basename "$f" .json)
	[ -s "$T/a/$n/result.json" ] && [ -s "$T/a/$n/bom.csv" ]
	check $? "build_writes_outputs_$n"
done
n=$(ls examples/*.json | wc -l); grep -q "build: $n compiled" "$T/a.err"; check $? "build_summary_counts_missions"

# Reproducible: a second build is byte-identical.
"$AE" build -o "$T/b" examples/ 2>/dev/null
diff -r "$T/a" "$T/b" >/dev/null; check $? "build_is_byte_reproducible"

# The catalogue is read from its JSON on every run, so catalogue_sha256 is
# the hash of what was used: a copy of data/ solves to the same bytes; the
# leading digit of every motor's mass raised to 9 in place, the file's size
# and times kept (touch -r), moves the design and the catalogue hash.
cp -Rp data "$T/data2"
AEROEVAL_DATA="$T/data2" "$AE" solve examples/sar_imaging_quad.json >"$T/copy.json" 2>/dev/null
"$AE" solve examples/sar_imaging_quad.json >"$T/orig.json" 2>/dev/null
cmp -s "$T/copy.json" "$T/orig.json"; check $? "catalogue_copy_of_data_solves_the_same"
m="$T/data2/catalog/motors.json"
cp -p "$m" "$T/motors.keep"
sed -i 's/"mass_g": [1-8]/"mass_g": 9/g' "$m"
touch -r "$T/motors.keep" "$m"
sz() { wc -c <"$1"; }
AEROEVAL_DATA="$T/data2" "$AE" solve examples/sar_imaging_quad.json >"$T/edit.json" 2>/dev/null
sha() { grep -o '"catalogue_sha256": "[0-9a-f]*"' "$1"; }
[ "$(sz "$m")" -eq "$(sz "$T/motors.keep")" ] && ! cmp -s "$m" "$T/motors.keep" \
    && [ ! "$m" -nt "$T/motors.keep" ] && [ ! "$m" -ot "$T/motors.keep" ] \
    && [ -n "$(sha "$T/edit.json")" ] && [ "$(sha "$T/edit.json")" != "$(sha "$T/orig.json")" ]
check $? "catalogue_edited_in_place_same_size_and_time_changes_its_hash"
grep -o '"takeoff_mass_kg": [0-9.e-]*' "$T/edit.json" | head -n 1 >"$T/m1"
grep -o '"takeoff_mass_kg": [0-9.e-]*' "$T/orig.json" | head -n 1 >"$T/m0"
[ -s "$T/m1" ] && ! cmp -s "$T/m0" "$T/m1"
check $? "catalogue_edited_in_place_same_size_and_time_moves_the_design"

# A bad mission: exit 2, nothing written, previous outputs intact.
mkdir -p "$T/m"
cp examples/sar_imaging_quad.json "$T/m/good.json"
"$AE" build -o "$T/c" "$T/m/good.json" 2>/dev/null
cp "$T/c/good/result.json" "$T/keep.json"
printf '{ "payload_kg": -1 }\n' > "$T/m/good.json"
"$AE" build -o "$T/c" "$T/m/good.json" 2>"$T/bad.err"; rc=$?
[ "$rc" -eq 2 ]; check $? "bad_mission_exits_2"
cmp -s "$T/c/good/result.json" "$T/keep.json"; check $? "bad_mission_keeps_previous_outputs"
grep -q "good.json:1:17: error: payload_kg" "$T/bad.err"; check $? "bad_mission_diagnostic_has_position"

# solve prints the result JSON with every run key.
"$AE" solve examples/lidar_mapping_quad.json >"$T/s.json"; rc=$?
[ "$rc" -eq 0 ]; check $? "solve_feasible_exits_0"
for k in aeroeval_version input_sha256 catalogue_sha256 mission baseline custom role_overhead status violations total_mass_kg convergence_history lipschitz_estimate time_series arm_natural_frequency_hz; do
	grep -q "\"$k\"" "$T/s.json"; check $? "solve_json_has_$k"
done
! grep -qiE '[:,[] *-?(nan|inf)' "$T/s.json"; check $? "solve_json_has_no_nan_or_inf"

# Name clashes are refused before anything is written.
mkdir -p "$T/d1" "$T/d2"
cp examples/lidar_mapping_quad.json "$T/d1/x.json"
cp examples/lidar_mapping_quad.json "$T/d2/x.json"
"$AE" build -o "$T/e" "$T/d1/x.json" "$T/d2/x.json" 2>/dev/null; rc=$?
[ "$rc" -eq 2 ] && [ ! -e "$T/e" ]; check $? "name_clash_is_an_error_before_writing"
# A template that enables the optional Sensitivity section gets it.
sed 's/"enabled": false/"enabled": true/' templates/a4.json > "$T/sens.json"
sed -i "s|\"fonts/|\"$(pwd)/templates/fonts/|g" "$T/sens.json"
"$AE" build -o "$T/f" --template "$T/sens.json" examples/lidar_mapping_quad.json 2>/dev/null
pdftotext "$T/f/lidar_mapping_quad/dossier.pdf" - 2>/dev/null | grep -q "sensitivity study was swept"
check $? "template_switch_adds_the_sensitivity_section"
exit 0
