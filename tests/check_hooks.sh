#!/bin/sh
# The test hooks (faults and delays injected from the environment:
# AEROEVAL_FAIL_ALLOC, AEROEVAL_FAIL_WRITE, AEROEVAL_TEST_*) are in the
# test build of the program and nowhere in the program `make` builds and
# installs: their names are in one binary and not in the other.
# Prints "ok NAME" / "not ok NAME" lines; run by tests/run_all.sh.
build=$(dirname "${AEROEVAL:-build/aeroeval-test}")
release="$build/aeroeval" test="$build/aeroeval-test"
hooks='AEROEVAL_FAIL_ALLOC AEROEVAL_FAIL_WRITE AEROEVAL_TEST_WORKER AEROEVAL_TEST_WRITE_DELAY_MS AEROEVAL_TEST_NO_EXCHANGE AEROEVAL_TEST_EXHAUSTIVE AEROEVAL_PROGRESS_S'
in_release="" missing_in_test=""
for h in $hooks; do
	grep -q -a "$h" "$release" && in_release="$in_release $h"
	grep -q -a "$h" "$test" || missing_in_test="$missing_in_test $h"
done
if [ -f "$release" ] && [ -z "$in_release" ]; then echo "ok release_program_has_no_test_hooks"
else echo "not ok release_program_has_no_test_hooks # $release:$in_release"; fi
if [ -f "$test" ] && [ -z "$missing_in_test" ]; then echo "ok test_program_has_the_test_hooks"
else echo "not ok test_program_has_the_test_hooks # $test lacks$missing_in_test"; fi
# Every getenv of a hook lies between #ifdef AEROEVAL_TEST_HOOKS and its #endif.
bad=$(awk '
	FNR == 1 { depth = 0 }
	/^#if(n?def)? *.*AEROEVAL_TEST_HOOKS/ { depth = 1; next }
	depth && /^#if/ { depth++ }
	depth && /^#endif/ { depth--; next }
	/getenv\("AEROEVAL_(FAIL|TEST|PROGRESS)/ && !depth { print FILENAME ":" FNR }' src/*/*.c)
if [ -z "$bad" ]; then echo "ok test_hooks_read_only_in_test_builds"
else echo "not ok test_hooks_read_only_in_test_builds # $bad"; fi
