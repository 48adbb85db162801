#!/bin/sh
# Runs test programs and scripts side by side and closes with one line
# "N passed, N failed".
#
# usage: sh tests/run_all.sh [-j N] [--scripts BUILD] [--meanwhile CMD DIR] WHAT...
#   --scripts BUILD  every check tests/check_*.sh and whole-compiler script
#                    tests/cli_*.sh, run on BUILD/aeroeval-test (the test
#                    build of the program: its test hooks compiled in);
#   --meanwhile CMD DIR  runs the command CMD (a build of DIR) alongside the
#                    rest; the programs of DIR start once it has ended, and
#                    a failure of it counts as one;
#   WHAT             a build folder (one cmocka program per tests/test_*.c
#                    in WHAT/tests) or one cmocka program.
# The programs and scripts are independent, so they run N at a time (the
# longest first); each one's output is kept and printed whole, in the order
# given, once all have ended.  A cmocka program's counts come from its own
# summary lines; one that crashes before printing them counts as one
# failure.  A script prints "ok NAME" / "not ok NAME" lines (TAP-like) that
# are counted here.  A program writes what it leaves to look at into its
# own build folder ($AEROEVAL_TEST_OUT).

# One job (internal): sh tests/run_all.sh --job DIR ID
if [ "$1" = "--job" ]; then
	dir=$2 id=$3
	set -- $(sed -n "${id}p" "$dir/jobs")
	kind=$1 path=$2 build=$3
	if [ "$build" = "$(cat "$dir/meanwhile.dir" 2>/dev/null)" ]; then
		while [ ! -e "$dir/meanwhile.rc" ]; do sleep 0.2; done
	fi
	t0=$(date +%s%N)
	if [ "$kind" = unit ]; then
		AEROEVAL_TEST_OUT="$build" "$path" >"$dir/$id.log" 2>&1
	else
		AEROEVAL="$build/aeroeval-test" sh "$path" >"$dir/$id.log" 2>&1
	fi
	echo $? >"$dir/$id.rc"
	echo "$(( ($(date +%s%N) - t0) / 1000000 )) $path" >"$dir/$id.ms"
	exit 0
fi

jobs=2
scripts=""
meanwhile=""
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
while [ $# -gt 0 ]; do
	case $1 in
	-j) jobs=$2; shift 2 ;;
	--scripts) scripts=$2; shift 2 ;;
	--meanwhile) meanwhile=$2; echo "$3" >"$dir/meanwhile.dir"; shift 3 ;;
	*) break ;;
	esac
done
if [ -n "$meanwhile" ]; then
	{ sh -c "$meanwhile" >"$dir/meanwhile.log" 2>&1; echo $? >"$dir/meanwhile.rc.tmp"; \
	  mv "$dir/meanwhile.rc.tmp" "$dir/meanwhile.rc"; } &
fi

# The job list, in the order of the report: kind, path, build folder, and
# the heading of the group it opens.
{
	for what in "$@"; do
		if [ -d "$what" ] || [ "$what" = "$(cat "$dir/meanwhile.dir" 2>/dev/null)" ]; then
			for t in tests/test_*.c; do
				echo "unit $what/tests/$(basename "$t" .c) $what"
			done
		else
			echo "unit $what $(dirname "$(dirname "$what")")"
		fi
	done
	if [ -n "$scripts" ]; then
		for s in tests/check_*.sh tests/cli_*.sh; do
			[ -f "$s" ] && echo "script $s $scripts"
		done
	fi
} >"$dir/jobs"
n=$(wc -l <"$dir/jobs")

# Start the slowest first, so that the last to end is a short one; the
# programs that wait for the build running meanwhile come after the rest.
slow='test_sweep test_monotone cli_hostile cli_batch cli_shard cli_dossier test_catalog_io test_report'
later=$(cat "$dir/meanwhile.dir" 2>/dev/null)
{
	for s in $slow; do grep -n "/$s[ .]" "$dir/jobs" | grep -v " ${later:-/}\$" | cut -d: -f1; done
	grep -n -v " ${later:-/}\$" "$dir/jobs" | cut -d: -f1
	for s in $slow; do grep -n "/$s[ .]" "$dir/jobs" | cut -d: -f1; done
	seq 1 "$n"
} | awk '!seen[$0]++' | xargs -P "$jobs" -n 1 sh "$0" --job "$dir"
wait

passed=0
failed=0
if [ -n "$meanwhile" ]; then
	rc=$(cat "$dir/meanwhile.rc")
	if [ "$rc" -ne 0 ]; then
		cat "$dir/meanwhile.log"
		echo "not ok the build run meanwhile: $meanwhile (exit $rc)"
		failed=1
	fi
fi

i=0
group=""
while read -r kind path jbuild; do
	i=$((i + 1))
	log="$dir/$i.log"
	rc=$(cat "$dir/$i.rc" 2>/dev/null || echo 1)
	if [ "$kind $jbuild" != "$group" ]; then
		group="$kind $jbuild"
		if [ "$kind" = unit ]; then echo "== cmocka programs of $jbuild/"
		else echo "== scripts, on $jbuild/aeroeval-test"; fi
	fi
	cat "$log"
	if [ "$kind" = unit ]; then
		p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test(s)\./\1/p' "$log" | tail -n 1)
		f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test(s), listed below:/\1/p' "$log" | tail -n 1)
	else
		p=$(grep -c '^ok ' "$log")
		f=$(grep -c '^not ok ' "$log")
	fi
	p=${p:-0}
	f=${f:-0}
	if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
	passed=$((passed + p))
	failed=$((failed + f))
done <"$dir/jobs"

# The slowest jobs, for whoever wants the whole run quicker.
echo "== the slowest (wall seconds, while the others ran beside them)"
cat "$dir"/*.ms 2>/dev/null | sort -rn | head -n 8 |
	awk '{ printf "  %6.1f  %s\n", $1 / 1000, $2 }'
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
