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

# The shipped catalogue comes from the program's snapshot while its files
# are unchanged (src/input/catalog_snap.h); read from its JSON (--db) it
# gives the same bytes.  A copy of data/ with the same files' times (cp -p)
# and one motor's mass edited is read from its JSON: the edit is reported,
# not hidden by the snapshot.
for f in examples/*.json; do
	n=$(basename "$f" .json)
	"$AE" solve "$f" >"$T/snap.json" 2>/dev/null
	"$AE" solve --db data/catalog "$f" >"$T/json.json" 2>/dev/null
	cmp -s "$T/snap.json" "$T/json.json"; check $? "snapshot_equals_json_catalogue_$n"
done
cp -Rp data "$T/data2"
AEROEVAL_DATA="$T/data2" "$AE" solve examples/sar_imaging_quad.json >"$T/copy.json" 2>/dev/null
"$AE" solve examples/sar_imaging_quad.json >"$T/snap.json" 2>/dev/null
cmp -s "$T/copy.json" "$T/snap.json"; check $? "snapshot_copy_of_data_solves_the_same"
sed -i '0,/"mass_g": [0-9.]*/s//"mass_g": -1/' "$T/data2/catalog/motors.json"
AEROEVAL_DATA="$T/data2" "$AE" solve examples/sar_imaging_quad.json >/dev/null 2>"$T/edit.err"; rc=$?
[ "$rc" -eq 2 ] && grep -q "motors.json:.*mass_g" "$T/edit.err"
check $? "snapshot_edited_catalogue_is_read_not_the_snapshot"

# catsnap, which make runs to write the snapshot: a catalogue that does not
# load does not build (its diagnostics, exit 2, no file left behind); the
# shipped one does.
cs="$(dirname "$AE")/catsnap"
if [ -x "$cs" ]; then
	"$cs" "$T/data2" "$T/snap.bin" 2>"$T/cs.err"; rc=$?
	[ "$rc" -eq 2 ] && grep -q "motors.json:.*mass_g" "$T/cs.err" \
	    && [ ! -e "$T/snap.bin" ] && [ ! -e "$T/snap.bin.tmp" ]
	check $? "catsnap_refuses_a_catalogue_that_does_not_load"
	"$cs" data "$T/snap.bin" 2>/dev/null && [ -s "$T/snap.bin" ]
	check $? "catsnap_writes_the_shipped_catalogue"
fi

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
