#!/bin/sh
# bench.sh — what users wait for, beside the speed targets (`make bench`;
# not a test: nothing here fails the build).
#
# usage: sh tests/bench.sh BUILD        (from the repository root)
#
# Instructions, not seconds, for the single commands: valgrind's callgrind
# counts them the same on every run of this noisy shared machine.  A count is
# the whole command: program start, every process (--trace-children=yes;
# `build` forks a worker per mission) and exit.  --dump-before=fork writes
# the parent's count at each fork and starts it again from zero, so a forked
# worker's own file holds only what the worker did; the sum of all the files
# is then the command's total, nothing counted twice.
#   1. `aeroeval solve` of every example, with the shipped catalogue and with
#      one FACTOR (4) times its size (every entry repeated with a new id,
#      built by BUILD/bench into a temporary --db directory);
#   2. `aeroeval build` of one mission, dossier included, for every example;
#   3. BATCH (1000) varied missions made from SEED (BUILD/bench missions)
#      compiled by one `aeroeval build -j 2`: wall time (it depends on what
#      else runs: the load average is printed beside it) and the peak resident
#      memory of the largest process of the run (GNU time's %M: the parent or
#      any one worker, whichever was larger);
#   4. with PAPER_ENGINE set (the paper's engine, as a command that takes a
#      mission file as its last argument), the instructions of that engine on
#      every example, beside aeroeval solve.
#   0. the closure reports first (BUILD/bench closure): CLOSURE (200)
#      plausible missions of each seed of CLOSURE_SEEDS (1-3) solved, the
#      share that closes on real parts and the closed-vs-continuous
#      takeoff-mass gap; then (BUILD/bench aircraft) the missions of the
#      calibration cohort's real aircraft (docs/performance.md).
# Environment: BATCH, SEED, FACTOR, CLOSURE, CLOSURE_SEEDS, PAPER_ENGINE;
# NO_BATCH=1 skips part 3.
build=${1:-build}
bin="$build/aeroeval"
BATCH=${BATCH:-1000}
SEED=${SEED:-1}
FACTOR=${FACTOR:-4}
CLOSURE=${CLOSURE:-200}
CLOSURE_SEEDS=${CLOSURE_SEEDS:-1-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "== closure on real parts ($CLOSURE missions per seed, seeds $CLOSURE_SEEDS)"
"$build/bench" closure "$CLOSURE_SEEDS" "$CLOSURE" "$bin" data/catalog || exit 2
echo
echo "== closure on the missions real aircraft fly (data/cohorts/calibration.csv)"
"$build/bench" aircraft data/cohorts/calibration.csv data/catalog || exit 2
echo

if ! command -v valgrind >/dev/null 2>&1; then
	echo "bench: valgrind is needed (apt-get install valgrind)" >&2
	exit 2
fi

# minstr CMD...: millions of instructions of CMD, every process included.
minstr() {
	rm -rf "$work/cg" && mkdir "$work/cg"
	valgrind --tool=callgrind --trace-children=yes --dump-before=fork \
	    --callgrind-out-file="$work/cg/cg.%p" "$@" >/dev/null 2>&1
	cat "$work/cg"/cg.* | awk '/^summary:/ { s += $2 } END { printf "%.1f", s / 1e6 }'
}

# max_of FILE: the largest number in FILE (one per line).
max_of() { sort -g "$1" | tail -n 1; }

mkdir "$work/db"
"$build/bench" catalog data/catalog "$work/db" "$FACTOR" || exit 2
kb_1=$(cat data/catalog/*.json | wc -c)
kb_n=$(cat "$work"/db/*.json | wc -c)

echo "== instructions per command (millions; callgrind, every process)"
printf '%-34s %10s %10s %10s\n' example solve "solve_x$FACTOR" build
: >"$work/solve"
: >"$work/solve_n"
: >"$work/build"
for f in examples/*.json; do
	s=$(minstr "$bin" solve "$f")
	n=$(minstr "$bin" solve --db "$work/db" "$f")
	b=$(minstr "$bin" build -o "$work/out" "$f")
	rm -rf "$work/out"
	echo "$s" >>"$work/solve"
	echo "$n" >>"$work/solve_n"
	echo "$b" >>"$work/build"
	printf '%-34s %10s %10s %10s\n' "$(basename "$f" .json)" "$s" "$n" "$b"
done
echo

if [ -z "$NO_BATCH" ]; then
	mkdir "$work/missions"
	"$build/bench" missions "$SEED" "$BATCH" "$work/missions" || exit 2
	load0=$(cut -d' ' -f1 /proc/loadavg)
	/usr/bin/time -f '%e %M' -o "$work/time" \
	    "$bin" build -j 2 -q -o "$work/bout" "$work/missions" >/dev/null 2>&1
	load1=$(cut -d' ' -f1 /proc/loadavg)
	wall=$(cut -d' ' -f1 "$work/time" | tail -n 1)
	rss=$(tail -n 1 "$work/time" | awk '{ printf "%.1f", $2 / 1024 }')
	n_out=$(find "$work/bout" -name dossier.pdf | wc -l)
fi

echo "== against the targets (docs/performance.md)"
# The SAR example's line in the per-example lists (examples/*.json order).
sar_at=$(ls examples/*.json | grep -n sar_imaging_quad | cut -d: -f1)
sar_solve=$(sed -n "${sar_at}p" "$work/solve")
sar_build=$(sed -n "${sar_at}p" "$work/build")
printf '%-52s %12s %10s\n' measure value target
printf '%-52s %12s %10s\n' "solve of the SAR example, whole process (M instr)" \
    "$sar_solve" "60"
printf '%-52s %12s %10s\n' "one SAR dossier build, whole process (M instr)" \
    "$sar_build" "200"
printf '%-52s %12s %10s\n' "solve, max of the examples (M instr)" \
    "$(max_of "$work/solve")" "-"
printf '%-52s %12s %10s\n' "solve with the catalogue x$FACTOR ($((kb_n / 1024)) KiB, not $((kb_1 / 1024)))" \
    "$(max_of "$work/solve_n")" "-"
printf '%-52s %12s %10s\n' "one dossier build, max of the examples (M instr)" \
    "$(max_of "$work/build")" "-"
if [ -z "$NO_BATCH" ]; then
	printf '%-52s %12s %10s\n' "$BATCH missions, build -j 2, wall (s)" "$wall" "20"
	printf '%-52s %12s %10s\n' "  peak RSS of the largest process (MiB)" "$rss" "30"
	echo "  ($n_out dossiers written; load average $load0 before, $load1 after," \
	    "on $(nproc) cores)"
fi

if [ -n "$PAPER_ENGINE" ]; then
	echo
	echo "== the paper's engine ($PAPER_ENGINE), instructions per mission (millions)"
	printf '%-34s %10s %10s\n' example paper aeroeval
	i=0
	for f in examples/*.json; do
		i=$((i + 1))
		# shellcheck disable=SC2086 # PAPER_ENGINE may carry arguments
		p=$(minstr $PAPER_ENGINE "$f")
		printf '%-34s %10s %10s\n' "$(basename "$f" .json)" "$p" \
		    "$(sed -n "${i}p" "$work/solve")"
	done
fi
