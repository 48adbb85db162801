#!/bin/sh
# Runs every cmocka program under BUILD/tests, then every whole-compiler
# script tests/cli_*.sh, and closes with one line "N passed, N failed".
#
# usage: sh tests/run_all.sh BUILD [unit]
# A cmocka program's counts come from its own summary lines; a program that
# crashes before printing them counts as one failure.  A cli_*.sh script
# prints "ok NAME" / "not ok NAME" lines (TAP-like) that are counted here.
build=${1:-build}
only=${2:-all}
passed=0
failed=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT

for t in "$build"/tests/test_*; do
	[ -x "$t" ] || continue
	case "$t" in *.d) continue ;; esac
	"$t" >"$log" 2>&1
	rc=$?
	cat "$log"
	p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test(s)\./\1/p' "$log" | tail -n 1)
	f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test(s), listed below:/\1/p' "$log" | tail -n 1)
	p=${p:-0}
	f=${f:-0}
	if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
	passed=$((passed + p))
	failed=$((failed + f))
done

if [ "$only" != unit ]; then
	for s in tests/check_*.sh tests/cli_*.sh; do
		[ -f "$s" ] || continue
		AEROEVAL="$build/aeroeval" sh "$s" >"$log" 2>&1
		rc=$?
		cat "$log"
		p=$(grep -c '^ok ' "$log")
		f=$(grep -c '^not ok ' "$log")
		if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
		passed=$((passed + p))
		failed=$((failed + f))
	done
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
