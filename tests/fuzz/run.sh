#!/bin/sh
# Builds and runs every libFuzzer harness tests/fuzz/fuzz_*.c (see `make fuzz`).
# usage: sh tests/fuzz/run.sh BUILD CC 'FLAGS' SECONDS
# Each harness runs SECONDS from a scratch copy of its seed corpus
# (tests/fuzz/corpus/NAME, plus the regression inputs tests/regress/NAME-*),
# with a 10 s per-input timeout; a crash, leak, hang or sanitizer report
# stops it and leaves the input in BUILD/fuzz/NAME/ as crash-*, leak-* or
# timeout-*.  Exit status 1 if any harness found something.
build=$1 cc=$2 flags=$3 secs=$4
pkg="$(pkg-config --cflags --libs cairo libcjson libcrypto) -lhpdf -lm -lpthread"
export AEROEVAL_DATA="${AEROEVAL_DATA:-$PWD/data}"
status=0
for src in tests/fuzz/fuzz_*.c; do
	name=$(basename "$src" .c)
	short=${name#fuzz_}
	bin="$build/$name"
	# shellcheck disable=SC2086 # flags and pkg are word lists
	$cc $flags -D_DEFAULT_SOURCE -Isrc -Itests -o "$bin" "$src" \
	    "$build/libaeroeval.a" $pkg || { status=1; continue; }
	work="$build/fuzz/$short"
	rm -rf "$work"
	mkdir -p "$work/corpus"
	cp tests/fuzz/corpus/"$short"/* "$work/corpus/" 2>/dev/null
	cp tests/regress/"$short"-* "$work/corpus/" 2>/dev/null
	echo "fuzz: $name for ${secs}s"
	if ! "$bin" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 \
	    -max_len=65536 -artifact_prefix="$work/" -print_final_stats=1 \
	    "$work/corpus" >"$work/log" 2>&1; then
		echo "fuzz: $name FOUND A PROBLEM (see $work/log)"
		grep -E 'ERROR|SUMMARY|runtime error|fuzz_solve:' "$work/log" | head -5
		ls "$work"/crash-* "$work"/leak-* "$work"/timeout-* 2>/dev/null
		status=1
	else
		grep -E '^stat::number_of_executed_units|^Done' "$work/log" | tr '\n' ' '
		echo
	fi
done
exit $status
