#!/bin/sh
# cli_check.sh — `aeroeval check` and `aeroeval schema` as a user runs them.
#
# For each tests/bad/NAME.json: `check` must exit 2 and print exactly
# tests/bad/NAME.stderr on stderr (nothing on stdout).  Then: a good mission
# passes silently, every file is checked even after a failure, a missing file
# is reported, `schema` lists every field of src/spec/spec.h, and
# `schema --json` equals the committed data/mission.schema.json.
#
# usage: AEROEVAL=build/aeroeval sh tests/cli_check.sh   (from the repo root)
# Prints "ok NAME" / "not ok NAME" per check.
#
# The checks run in a scratch directory holding a copy of tests/bad; the
# program finds the shipped data/ next to itself, so the expected chemistry
# list is that of data/chemistries.json.

root=$(pwd)
bin=${AEROEVAL:-build/aeroeval}
case "$bin" in /*) ;; *) bin="$root/$bin" ;; esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/tests" "$work/data"
cp -R "$root/tests/bad" "$work/tests/bad"
cd "$work" || exit 1

ok() { echo "ok $1"; }
notok() { echo "not ok $1${2:+ # $2}"; }

# Run `aeroeval ARGS`; stdout in out.txt, stderr in err.txt, status in $rc.
run() {
	"$bin" "$@" >out.txt 2>err.txt
	rc=$?
}

for json in tests/bad/*.json; do
	name=$(basename "$json" .json)
	run check "$json"
	if [ "$rc" -ne 2 ]; then
		notok "check_$name" "exit $rc, want 2"
	elif [ -s out.txt ]; then
		notok "check_$name" "wrote to stdout"
	elif ! cmp -s err.txt "tests/bad/$name.stderr"; then
		notok "check_$name" "stderr differs"
		diff "tests/bad/$name.stderr" err.txt | sed 's/^/# /'
	else
		ok "check_$name"
	fi
done

good='{
  "$schema": "../data/mission.schema.json",
  "name": "survey quad",
  "payload_kg": 1.2,
  "max_diameter_m": 0.65,
  "t_hover_s": 900,
  "v_forward_ms": "auto",
  "battery_chemistry": "LiHV",
  "locks": {"is_motor_locked": true, "locked_kv": 400},
  "payload_role": {"type": "mapping"}
}'
printf '%s\n' "$good" >good.json

run check good.json
if [ "$rc" -eq 0 ] && [ ! -s out.txt ] && [ ! -s err.txt ]; then
	ok check_good_is_silent
else
	notok check_good_is_silent "exit $rc"
fi

# Every file is checked, in order, even after a failure; one bad file makes
# the whole run exit 2.
run check tests/bad/unknown.json good.json tests/bad/range.json
if [ "$rc" -eq 2 ] &&
   cat tests/bad/unknown.stderr tests/bad/range.stderr | cmp -s - err.txt; then
	ok check_reports_every_file
else
	notok check_reports_every_file "exit $rc"
fi

# A mission without its essentials is refused by check and by solve, which
# prints nothing (tests/bad/empty_object.json is `check {}`); one complete
# through requirements{} passes.
printf '{}\n' >empty.json
run solve empty.json
if [ "$rc" -eq 2 ] && [ ! -s out.txt ] && grep -q '^empty.json:1:1: error: payload_kg: missing field' err.txt
then
	ok solve_without_essentials_is_refused
else
	notok solve_without_essentials_is_refused "exit $rc"
fi
printf '{"requirements": {"payload_preset": "survey_lidar", "transport": "car_trunk"}, "t_forward_s": 600}\n' \
	>req.json
run check req.json
if [ "$rc" -eq 0 ] && [ ! -s err.txt ]; then
	ok check_requirements_first_mission_passes
else
	notok check_requirements_first_mission_passes "exit $rc"
fi

run check no_such_mission.json
if [ "$rc" -eq 2 ] && [ "$(cat err.txt)" = \
   "no_such_mission.json: error: cannot read file: No such file or directory" ]; then
	ok check_missing_file
else
	notok check_missing_file "exit $rc"
fi

run check
if [ "$rc" -eq 2 ] && grep -q '^usage: aeroeval check' err.txt; then
	ok check_without_files_is_usage_error
else
	notok check_without_files_is_usage_error "exit $rc"
fi

run check --frobnicate good.json
if [ "$rc" -eq 2 ]; then ok check_unknown_option; else notok check_unknown_option "exit $rc"; fi

# `schema` names every field of the table in src/spec/spec.h.
run schema
missing=""
for path in $(sed -n 's/^X([A-Z_0-9]*, "\([^"]*\)".*/\1/p' "$root/src/spec/spec.h"); do
	grep -q "^  $path  (" out.txt || missing="$missing $path"
done
n=$(sed -n 's/^X([A-Z_0-9]*, "\([^"]*\)".*/\1/p' "$root/src/spec/spec.h" | wc -l)
if [ "$rc" -eq 0 ] && [ -z "$missing" ] && [ "$n" -gt 50 ]; then
	ok schema_lists_every_field
else
	notok schema_lists_every_field "exit $rc, missing:$missing"
fi

run schema --json
if [ "$rc" -eq 0 ] && cmp -s out.txt "$root/data/mission.schema.json"; then
	ok schema_json_equals_committed_file
else
	notok schema_json_equals_committed_file "regenerate: aeroeval schema --json > data/mission.schema.json"
fi

run schema --yaml
if [ "$rc" -eq 2 ]; then ok schema_bad_option; else notok schema_bad_option "exit $rc"; fi
