#!/bin/sh
# cli_hostile.sh — hostile mission files (issue 9): whatever a client sends,
# aeroeval gives a clear error (exit 2, stderr names the file) or a safe
# result (exit 0/1 with finite numbers), never crashes or hangs (each run is
# bounded by `timeout`), and never writes outside the output directory.
#
# usage: AEROEVAL=build/aeroeval sh tests/cli_hostile.sh   (from the repo root)
# Prints "ok NAME" / "not ok NAME # why" per check.

root=$(pwd)
bin=${AEROEVAL:-build/aeroeval}
case "$bin" in /*) ;; *) bin="$root/$bin" ;; esac
export AEROEVAL_DATA="$root/data"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/m" "$work/cwd/a/b"
cd "$work" || exit 1

ok() { echo "ok $1"; }
notok() { echo "not ok $1${2:+ # $2}"; }

# run ARGS...: stdout in out.txt, stderr in err.txt, status in $rc.
run() {
	timeout 30 "$bin" "$@" >out.txt 2>err.txt
	rc=$?
}

# A mission that compiles; variants below are built from it.
good='"payload_kg": 1.5, "max_diameter_m": 0.7, "t_hover_s": 600'
printf '{%s}\n' "$good" >m/good.json

# fails NAME WANT ARGS...: `aeroeval ARGS...` exits 2, no crash or hang,
# WANT in stderr, nothing written to out/.
fails() {
	name=$1
	want=$2
	shift 2
	rm -rf out
	run "$@"
	if [ "$rc" -ge 124 ]; then
		notok "$name" "exit $rc (crash or timeout)"
	elif [ "$rc" -ne 2 ]; then
		notok "$name" "exit $rc, want 2"; sed 's/^/# /' err.txt | head -3
	elif ! grep -qF -- "$want" err.txt; then
		notok "$name" "stderr lacks: $want"; sed 's/^/# /' err.txt | head -3
	elif [ -n "$(find out -type f 2>/dev/null)" ]; then
		notok "$name" "wrote output"
	else
		ok "$name"
	fi
}

# rejected NAME FILE [CMD]: `aeroeval CMD FILE` (default build) exits 2 with
# a diagnostic that names FILE, writes nothing to out/, and nothing else.
rejected() {
	if [ "${3:-build}" = build ]; then fails "$1" "$2" build -o out "$2"
	else fails "$1" "$2" "$3" "$2"; fi
}

# safe NAME FILE: `build` exits 0 or 1, result.json has no NaN/Infinity.
safe() {
	rm -rf out
	run build -o out "$2"
	name=$(basename "$2" .json)
	if [ "$rc" -ne 0 ] && [ "$rc" -ne 1 ]; then
		notok "$1" "exit $rc, want 0 or 1"; sed 's/^/# /' err.txt | head -3
	elif [ ! -s "out/$name/result.json" ]; then
		notok "$1" "no result.json"
	elif grep -qE '(^|[]:, [])-?(nan|NaN|inf|Inf|Infinity)([], ]|$)' "out/$name/result.json"; then
		notok "$1" "non-finite number in result.json"
	else
		ok "$1"
	fi
}

# either NAME FILE: a clear rejection or a safe result are both fine.
either() {
	rm -rf out
	run build -o out "$2"
	if [ "$rc" -eq 2 ]; then
		rejected "$1" "$2"
	else
		safe "$1" "$2"
	fi
}

# ---- size and shape -------------------------------------------------------
# > 4 MiB: a valid mission padded with spaces.
{ printf '{%s' "$good"; head -c 4300000 /dev/zero | tr '\0' ' '; printf '}\n'; } >m/huge.json
rejected huge_file_is_refused m/huge.json
grep -qi 'too large' err.txt || notok huge_file_error_says_too_large
rejected huge_file_is_refused_by_check m/huge.json check
rejected huge_file_is_refused_by_solve m/huge.json solve

awk 'BEGIN { s = ""; for (i = 0; i < 10000; i++) s = s "["; print s }' >m/deep.json
rejected deep_nesting m/deep.json
awk 'BEGIN { printf "{\"report\": "; for (i = 0; i < 10000; i++) printf "{\"a\":"; print "1" }' >m/deep_obj.json
rejected deep_object_nesting m/deep_obj.json

: >m/empty.json
rejected empty_file m/empty.json
rejected empty_file_by_check m/empty.json check
printf '   \n\t\n' >m/blank.json
rejected whitespace_only m/blank.json
printf '\0\0\0\0' >m/nul.json
rejected nul_bytes m/nul.json
head -c 4096 /dev/urandom >m/random.json 2>/dev/null
rejected random_bytes m/random.json
printf '{%s}\n\0{"payload_kg": 2}' "$good" >m/after_nul.json
rejected text_after_a_nul m/after_nul.json

# ---- numbers --------------------------------------------------------------
printf '{"payload_kg": 1e308, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/n_big.json
rejected number_1e308_out_of_range m/n_big.json
printf '{"payload_kg": 1e400, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/n_overflow.json
rejected number_1e400_overflows m/n_overflow.json
printf '{"payload_kg": -1e400, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/n_neg_overflow.json
rejected number_minus_1e400_overflows m/n_neg_overflow.json
printf '{"payload_kg": 1e-320, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/n_subnormal.json
either number_subnormal_payload m/n_subnormal.json
printf '{"payload_kg": -0, "max_diameter_m": 0.7, "t_hover_s": 600, "ambient_temp_c": -0.0}' >m/n_negzero.json
safe number_negative_zero m/n_negzero.json
grep -q -- '-0[,. ]' out/n_negzero/result.json 2>/dev/null && notok negative_zero_printed_as_minus_zero
printf '{"payload_kg": 1, "max_diameter_m": 1e-320, "t_hover_s": 600}' >m/n_tiny_wheelbase.json
rejected tiny_wheelbase_below_range m/n_tiny_wheelbase.json
printf '{"payload_kg": 1, "max_diameter_m": 0.7, "t_hover_s": 1e-320}' >m/n_tiny_time.json
either tiny_hover_time m/n_tiny_time.json
printf '{"payload_kg": 1, "num_rotors": 4.0000000000000001, "t_hover_s": 600}' >m/n_int_rounding.json
either integer_that_rounds_to_integer m/n_int_rounding.json
printf '{"payload_kg": 1, "num_rotors": 1e300, "t_hover_s": 600}' >m/n_int_huge.json
rejected huge_integer m/n_int_huge.json
printf '{"payload_kg": 1, "nominal_cell_count": -2147483649, "t_hover_s": 600}' >m/n_int_min.json
rejected integer_below_int_min m/n_int_min.json
awk 'BEGIN { printf "{\"payload_kg\": 1."; for (i = 0; i < 100000; i++) printf "1"; print "}" }' >m/n_long.json
either number_with_100000_digits m/n_long.json

# ---- strings --------------------------------------------------------------
printf '{"name": "caf\351", %s}' "$good" >m/latin1.json
rejected non_utf8_latin1_in_string m/latin1.json
printf '{"report": {"title": "\355\240\200"}, %s}' "$good" >m/surrogate.json
rejected non_utf8_encoded_surrogate m/surrogate.json
printf '{"report": {"title": "\300\257"}, %s}' "$good" >m/overlong.json
rejected non_utf8_overlong m/overlong.json
printf '{"name": "\\ud800", %s}' "$good" >m/lone_escape.json
either lone_surrogate_escape m/lone_escape.json
printf '{"payload_kg": 1, "payload_kg": 2, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/dup.json
rejected duplicate_key m/dup.json
printf '{"locks": {"is_prop_locked": true}, "locks": {}, %s}' "$good" >m/dup_group.json
rejected duplicate_group m/dup_group.json
awk -v g="$good" 'BEGIN { printf "{\"name\": \""; for (i = 0; i < 200000; i++) printf "x"; print "\", " g "}" }' >m/long_string.json
rejected very_long_string m/long_string.json
awk -v g="$good" 'BEGIN { printf "{\""; for (i = 0; i < 200000; i++) printf "k"; print "\": 1, " g "}" }' >m/long_key.json
rejected very_long_unknown_key m/long_key.json
printf '\357\273\277{%s}\n' "$good" >m/bom.json
either utf8_bom m/bom.json
printf '{"name": "a\\u0000b", %s}' "$good" >m/escaped_nul.json
rejected escaped_nul_in_string m/escaped_nul.json

# ---- paths ----------------------------------------------------------------
mkdir -p m/adir
rejected directory_as_mission_solve m/adir solve
rejected directory_as_mission_check m/adir check
mkdir -p m/dirs/trap.json
rm -rf out
run build -o out m/dirs
if [ "$rc" -ne 2 ] || ! grep -qF 'trap.json' err.txt; then
	notok directory_named_json_inside_a_build_dir "exit $rc"
else
	ok directory_named_json_inside_a_build_dir
fi
rejected missing_file m/nope.json
rejected missing_file_check m/nope.json check
mkfifo m/fifo.json 2>/dev/null && {
	rejected fifo_as_mission m/fifo.json
	rejected fifo_as_mission_check m/fifo.json check
}
[ -c /dev/zero ] && rejected dev_zero_as_mission_check /dev/zero check
[ -c /dev/zero ] && rejected dev_zero_as_mission_solve /dev/zero solve
ln -s loop.json m/loop.json 2>/dev/null && rejected symlink_loop m/loop.json

# `../../etc.json` from a deeper directory: output goes to out/etc only.
printf '{%s}\n' "$good" >cwd/etc.json
before=$(cd "$work" && find . -path ./cwd/a/b/out -prune -o -print | sort)
(cd cwd/a/b && timeout 30 "$bin" build -o out ../../etc.json >/dev/null 2>&1)
rc=$?
after=$(cd "$work" && find . -path ./cwd/a/b/out -prune -o -print | sort)
if [ "$rc" -gt 1 ]; then
	notok dotdot_path_compiles "exit $rc"
elif [ "$before" != "$after" ]; then
	notok dotdot_path_writes_only_under_out "files appeared outside out/"
elif [ ! -f cwd/a/b/out/etc/result.json ]; then
	notok dotdot_path_writes_only_under_out "no out/etc/result.json"
else
	ok dotdot_path_writes_only_under_out
fi

printf '{%s}\n' "$good" >"m/with space.json"
printf '{%s}\n' "$good" >"m/mïssion.json"
printf '{%s}\n' "$good" >"m/-dash.json"
printf '{%s}\n' "$good" >"m/..json"
for f in "m/with space.json" "m/mïssion.json" "m/..json"; do
	rm -rf out
	run build -o out "$f"
	if [ "$rc" -eq 2 ] && grep -qF "$f" err.txt && [ -z "$(find out -type f 2>/dev/null)" ]; then
		ok "odd_name_rejected_clearly: $f"
	elif [ "$rc" -le 1 ] && [ -n "$(find out -name result.json)" ]; then
		ok "odd_name_compiled_inside_out: $f"
	else
		notok "odd_name: $f" "exit $rc"
	fi
done
rm -rf out
run build -o out ./m/-dash.json
if [ "$rc" -le 1 ] && [ -f out/-dash/result.json ]; then ok dash_name_with_path_prefix
else notok dash_name_with_path_prefix "exit $rc"; fi

# Every hostile file above in one build: each is refused on its own, the
# good mission still compiles, and the build ends (exit 2).
rm -rf out
run build -o out m
if [ "$rc" -eq 2 ] && [ -f out/good/result.json ]; then ok one_build_of_every_hostile_file
else notok one_build_of_every_hostile_file "exit $rc"; fi

# Lose nothing: a mission that turns bad keeps its last good output.
rm -rf out
run build -o out m/good.json
cp out/good/result.json good_before.json 2>/dev/null
printf '{"payload_kg": "heavy"}' >m/good.json
run build -o out m/good.json
if [ "$rc" -eq 2 ] && cmp -s out/good/result.json good_before.json; then
	ok rejected_rebuild_keeps_previous_output
else
	notok rejected_rebuild_keeps_previous_output "exit $rc"
fi
printf '{%s}\n' "$good" >m/good.json
if [ -z "$(find out -name '.*tmp*')" ]; then ok no_temporary_files_left
else notok no_temporary_files_left; fi

# Output directory that is a file, and an output folder that is a file.
: >outfile
run build -o outfile m/good.json
if [ "$rc" -ge 2 ] && [ "$rc" -lt 124 ] && grep -q outfile err.txt; then ok output_dir_is_a_file
else notok output_dir_is_a_file "exit $rc"; fi
rm -rf out && mkdir -p out && : >out/good
run build -o out m/good.json
if [ "$rc" -ge 2 ] && [ "$rc" -lt 124 ] && grep -q 'out/good' err.txt; then ok output_folder_is_a_file
else notok output_folder_is_a_file "exit $rc"; fi

# Nothing at all was written outside the scratch directory's out folders:
# the shared data/ and the repository are untouched.
if [ -n "$(cd "$root" && git status --porcelain --untracked-files=all -- data examples 2>/dev/null)" ]; then
	notok repository_untouched
else
	ok repository_untouched
fi

# ---- size: linear work, capped output --------------------------------------
# 150 000 unknown keys: reported, counted, and quick (the reader indexes
# every key instead of scanning the ones before it: this took over 60 s).
mkdir -p big
awk 'BEGIN { printf "{"; for (i = 0; i < 150000; i++) printf "%s\"unknown_%d\": 1", (i ? ", " : ""), i; print "}" }' >big/unknown.json
timeout 20 "$bin" check big/unknown.json >out.txt 2>err.txt
rc=$?
if [ "$rc" -ne 2 ]; then notok unknown_keys_150000_checked_quickly "exit $rc"
elif [ "$(wc -l <err.txt)" -gt 51 ]; then notok unknown_keys_150000_checked_quickly "$(wc -l <err.txt) lines"
elif ! grep -q 'note: more errors not shown: 149950' err.txt; then notok unknown_keys_150000_checked_quickly "no summary line"
else ok unknown_keys_150000_checked_quickly; fi
# 100 000 repeats of one key printed 199 998 lines; now the cap and a summary.
awk 'BEGIN { printf "{"; for (i = 0; i < 100000; i++) printf "%s\"payload_kg\": 1", (i ? ", " : ""); print "}" }' >big/dup.json
timeout 20 "$bin" check big/dup.json >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 2 ] && [ "$(wc -l <err.txt)" -le 51 ] && grep -q 'more errors not shown' err.txt; then
	ok duplicate_keys_100000_capped
else
	notok duplicate_keys_100000_capped "exit $rc, $(wc -l <err.txt) lines"
fi

# ---- the other inputs: catalogue, template, cohort --------------------------
# A catalogue directory made from the test fixtures, one file changed.
# db_with FILE SED-SCRIPT
db_with() {
	rm -rf db && mkdir db && cp "$root"/tests/fixtures/catalog/good/*.json db/
	sed "$2" "$root/tests/fixtures/catalog/good/$1" >"db/$1"
}
db_with motors.json 's/x/x/'
rm db/motors.json && mkfifo db/motors.json 2>/dev/null &&
	fails fifo_as_catalogue_file "db/motors.json: error: cannot read file: not a regular file" \
	    build -o out --db db m/good.json
db_with propellers.json 's/"FX18x6.1"/"=HYPERLINK(\\"http:\/\/x.example\\",\\"buy\\")"/'
fails formula_in_catalogue_text "db/propellers.json:2:63: error: propellers[0].part_number: text starts like a spreadsheet formula" \
    build -o out --db db m/good.json
db_with propellers.json "s/\"Fixture\"/\"Fixtur$(printf '\351')\"/"
fails latin1_in_catalogue_text "db/propellers.json:2:37: error: propellers[0].manufacturer: string is not valid UTF-8" \
    solve --db db m/good.json
db_with propellers.json 's/"source": "fixture"/"source": "fix\\u0000ture"/'
fails nul_in_catalogue_text "propellers[0].source: string contains a NUL character" \
    solve --db db m/good.json
db_with escs.json 's/"channels": 4/"channels": 4, "channels": 1/'
fails duplicate_key_in_catalogue "escs[0].channels: duplicate field" solve --db db m/good.json
rm -rf db

# Templates: what they name is judged when they load, before any solve.
mkdir -p tpl
printf '\211PNG\r\n\032\n\0\0\0\rIHDR\0\0\0\020\0\0\0\020\010\002\0\0\0\220\221h6\0\0\0\012IDATxxxxxxxxxx\0\0\0\0' >tpl/logo.png
printf '{"logo": "logo.png"}' >tpl/logo.json
fails corrupt_png_logo_at_template_load "tpl/logo.json:1:10: error: logo: not a usable PNG image: tpl/logo.png" \
    build -o out --template tpl/logo.json m/good.json
printf '{"fonts": {"regular": "logo.json"}}' >tpl/font.json
fails non_font_at_template_load "tpl/font.json:1:23: error: fonts.regular: not a usable TrueType font: tpl/logo.json" \
    build -o out --template tpl/font.json m/good.json
printf '{"fonts": {"bold": "/dev/zero"}}' >tpl/zero.json
fails dev_zero_as_font "fonts.bold: cannot read file: /dev/zero: not a regular file" \
    build -o out --template tpl/zero.json m/good.json
[ -c /dev/zero ] && fails dev_zero_as_template "/dev/zero: error: cannot read file: not a regular file" \
    build -o out --template /dev/zero m/good.json
fails directory_as_template "tpl: error: cannot read file: not a regular file" \
    sensitivity -o out --template tpl m/good.json
mkdir -p emptydir
fails empty_directory_build_names_it "emptydir: error: no mission file (*.json) in this directory" \
    build -o out emptydir

# Cohorts: valid JSON out whatever the names, a clear end when nothing validates.
{ cat "$root/tests/fixtures/validate/tiny.csv"; printf 'Caf\351 racer,0.6,4,0,220,5,5,MicroAIO,inspection,0.1,\n'; } >latin1.csv
run validate --json latin1.csv
if [ "$rc" -ne 0 ]; then
	notok validate_json_with_a_latin1_row "exit $rc"
elif ! grep -q 'latin1.csv:[0-9]*: error: name: not valid UTF-8' err.txt; then
	notok validate_json_with_a_latin1_row "the row is not named"
elif ! iconv -f UTF-8 -t UTF-8 out.txt >/dev/null 2>&1; then
	notok validate_json_with_a_latin1_row "stdout is not UTF-8"
elif [ "$(grep -c '^	"rows":' out.txt)" -ne 1 ] || ! grep -q '^	"n_rows":' out.txt; then
	notok validate_json_with_a_latin1_row "a key appears twice"
else
	ok validate_json_with_a_latin1_row
fi
printf 'name,takeoff_mass_kg\nA,2.5\nB,3.1\n' >nothing.csv
fails validate_with_no_usable_row "nothing.csv: error: no row could be validated (2 rows; 2 skipped: payload of the takeoff figure unknown)" \
    validate nothing.csv
AEROEVAL_PROGRESS_S=0 timeout 60 "$bin" calibrate "$root/tests/fixtures/cohort/calibration.csv" >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 0 ] && grep -q '^calibrate: fitting, pass [0-9]*, row [0-9]* of [0-9]*, [0-9]* solves' err.txt; then
	ok calibrate_shows_progress
else
	notok calibrate_shows_progress "exit $rc"
fi

# ---- valgrind: a whole build of one example, no memory error, no leak -----
# (skipped where valgrind is not installed; ASan covers the unit suite)
if command -v valgrind >/dev/null 2>&1; then
	rm -rf out
	timeout 300 valgrind -q --leak-check=full --errors-for-leak-kinds=definite \
	    --error-exitcode=99 "$bin" build -o out "$root/examples/delivery_quad.json" \
	    >out.txt 2>err.txt
	rc=$?
	if [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ]; then ok valgrind_build_clean
	else notok valgrind_build_clean "exit $rc"; grep '==' err.txt | head -20 | sed 's/^/# /'; fi
fi
