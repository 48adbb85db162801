#!/bin/sh
# bench.sh — how fast aeroeval is, as a table (`make bench`; not a test).
#
# usage: sh tests/bench.sh BUILD        (from the repository root)
# 1. in-process solve time per example (BUILD/bench: median of 200 solves,
#    with and without the parts catalogue)
# 2. whole-process `aeroeval solve` and `aeroeval build` per example
#    (mean wall time of REPEAT runs, dossier included once build writes it)
# 3. a batch of BATCH missions (examples/delivery_quad.json with the payload
#    varied) compiled by one `aeroeval build -j 2`
# 4. peak memory (max RSS) of a solve, a build and the batch
# 5. instructions of one in-process solve per example, with and without the
#    parts catalogue (valgrind's callgrind, calling thread only: the
#    baseline's loop runs on a second thread, and the parts search is kept
#    to the calling thread, engine_solve_unhelped()); they repeat to 0.2 %,
#    where the wall times of a shared virtual machine drift by tens of per
#    cent and the helper's share of the search depends on timing
# Budgets (issue 9): a solve well under 1 ms in process, a full dossier well
# under 200 ms, memory under 50 MB.
build=${1:-build}
bin="$build/aeroeval"
REPEAT=${REPEAT:-15}
BATCH=${BATCH:-1000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

now_ms() { date +%s%N | awk '{ printf "%.3f", $1 / 1e6 }'; }

# mean_ms CMD...: mean wall time of REPEAT runs of CMD, in ms (one clock
# read before and after the loop, so forking `date` is not counted).
mean_ms() {
	t0=$(now_ms)
	for _ in $(seq "$REPEAT"); do
		"$@" >/dev/null 2>&1
	done
	t1=$(now_ms)
	echo "$t0 $t1 $REPEAT" | awk '{ printf "%.1f", ($2 - $1) / $3 }'
}

# max_rss_kib CMD...: peak resident memory of CMD (GNU time, else "n/a").
max_rss_kib() {
	if [ -x /usr/bin/time ]; then
		/usr/bin/time -f '%M' -o "$work/rss" "$@" >/dev/null 2>&1
		cat "$work/rss" | tail -n 1
	else
		echo n/a
	fi
}

echo "== 1. in-process solve (engine_solve only; render = result.json text)"
"$build/bench" -n 200 examples/*.json
echo

echo "== 2. whole process, mean of $REPEAT runs (ms)"
printf '%-32s %10s %10s\n' mission solve_ms build_ms
for f in examples/*.json; do
	s=$(mean_ms "$bin" solve "$f")
	b=$(mean_ms "$bin" build --force -o "$work/out" "$f")
	printf '%-32s %10s %10s\n' "$(basename "$f")" "$s" "$b"
done
echo

echo "== 3. batch of $BATCH missions, one build"
mkdir -p "$work/batch"
i=0
while [ "$i" -lt "$BATCH" ]; do
	p=$(awk -v i="$i" -v n="$BATCH" 'BEGIN { printf "%.4f", 0.5 + 5.5 * i / n }')
	sed "s/\"payload_kg\": *[0-9.]*/\"payload_kg\": $p/" examples/delivery_quad.json \
	    >"$work/batch/m$i.json"
	i=$((i + 1))
done
jobs="-j 2"
"$bin" build -j 2 -o "$work/probe" examples/fpv_racing_quad.json >/dev/null 2>&1
if [ $? -eq 2 ]; then
	jobs="" # build has no -j yet: the batch runs one mission at a time
	echo "(aeroeval build does not accept -j yet: sequential)"
fi
t0=$(now_ms)
# shellcheck disable=SC2086 # $jobs is empty or two words
"$bin" build $jobs -o "$work/bout" "$work/batch" >/dev/null 2>&1
rc=$?
t1=$(now_ms)
n_out=$(find "$work/bout" -name result.json | wc -l)
echo "$t0 $t1 $BATCH $n_out $rc" | awk '{ printf "%d missions in %.2f s (%.2f ms per mission), %d result.json written, exit %d\n", $3, ($2 - $1) / 1000, ($2 - $1) / $3, $4, $5 }'
echo

echo "== 4. peak memory (max RSS, KiB)"
printf '%-40s %10s\n' run max_rss_kib
printf '%-40s %10s\n' "solve agri_spray_octo" "$(max_rss_kib "$bin" solve examples/agri_spray_octo.json)"
printf '%-40s %10s\n' "build delivery_quad" "$(max_rss_kib "$bin" build -o "$work/out" examples/delivery_quad.json)"
# shellcheck disable=SC2086
printf '%-40s %10s\n' "build batch of $BATCH ${jobs:-(sequential)}" "$(max_rss_kib "$bin" build $jobs -o "$work/bout2" "$work/batch")"
echo

echo "== 5. instructions of one in-process solve (callgrind, calling thread, no helper; millions)"
if command -v valgrind >/dev/null 2>&1; then
	printf '%-32s %10s %10s\n' mission parts_M noparts_M
	for f in examples/*.json; do
		row=""
		for mode in parts noparts; do
			n=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null \
			    --toggle-collect=counted_solve "$build/bench" -c "$mode" "$f" 2>&1 \
			    | awk '/Collected :/ { printf "%.2f", $NF / 1e6 }')
			row="$row $(printf '%10s' "${n:-n/a}")"
		done
		printf '%-32s%s\n' "$(basename "$f")" "$row"
	done
else
	echo "(valgrind is not installed: skipped)"
fi
