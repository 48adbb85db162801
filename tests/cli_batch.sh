#!/bin/sh
# Whole-compiler tests of `aeroeval build` as a batch compiler: parallel
# workers, per-mission reports and summary, byte-identical output whatever
# -j, interruption that loses nothing, incremental rebuilds, help and man page.
# Prints "ok NAME" / "not ok NAME"; run by tests/run_all.sh with $AEROEVAL.
AE=${AEROEVAL:-build/aeroeval}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
check() { if [ "$1" -eq 0 ]; then echo "ok $2"; else echo "not ok $2"; fi; }
# The summary line of a build's stderr.
summary() { grep '^build: ' "$1" | tail -n 1; }

# ---- a batch with bad missions ---------------------------------------------
mkdir -p "$T/in"
cp examples/*.json "$T/in/"
cp tests/bad/syntax.json "$T/in/bad_syntax.json"
cp tests/bad/range.json "$T/in/bad_range.json"
n_ex=$(ls examples/*.json | wc -l)
"$AE" build -j 4 -o "$T/a" "$T/in" 2>"$T/a.err"; rc=$?
[ "$rc" -eq 2 ]; check $? "batch_with_bad_missions_exits_2"
ok=1
for f in examples/*.json; do
	n=$(basename "$f" .json)
	[ -s "$T/a/$n/result.json" ] && [ -s "$T/a/$n/bom.csv" ] || ok=0
done
[ $ok -eq 1 ]; check $? "batch_compiles_every_good_mission"
[ ! -e "$T/a/bad_syntax" ] && [ ! -e "$T/a/bad_range" ]
check $? "batch_writes_nothing_for_bad_missions"
grep -q "bad_syntax.json:3:3: error: malformed JSON" "$T/a.err" \
	&& grep -q "bad_range.json:5:28: error: payload_role.spray_rate_kg_per_s" "$T/a.err"
check $? "batch_reports_each_bad_mission"
[ "$(grep -c ': rejected$' "$T/a.err")" -eq 2 ]; check $? "batch_reports_two_rejected"
n_inf=$(grep -c ': compiled (infeasible' "$T/a.err")
summary "$T/a.err" | grep -q "^build: $n_ex compiled ($n_inf infeasible), 0 up to date (0 infeasible), 2 rejected, 0 internal errors; $((n_ex + 2)) missions in "
check $? "batch_summary_counts_outcomes"
# A mission's lines come out together: its diagnostic, then its verdict.
grep -A1 "bad_range.json:5:28: error" "$T/a.err" | tail -n 1 | grep -q "bad_range.json: rejected$"
check $? "batch_mission_block_is_contiguous"

# ---- -j does not change a byte --------------------------------------------------
"$AE" build -q -j 1 -o "$T/j1" examples/ 2>"$T/j1.err"; rc1=$?
"$AE" build -q -j 4 -o "$T/j4" examples/ 2>"$T/j4.err"; rc4=$?
[ "$rc1" -eq "$rc4" ] && [ "$rc1" -le 1 ]; check $? "j1_and_j4_same_exit_status"
diff -r "$T/j1" "$T/j4" >/dev/null; check $? "j1_and_j4_byte_identical_trees"
[ ! -s "$T/j1.err" ]; check $? "quiet_build_prints_nothing_when_all_compile"

# ---- incremental --------------------------------------------------------------------
"$AE" build -j 4 -o "$T/j1" examples/ 2>"$T/u.err"; rc=$?
[ "$rc" -eq "$rc1" ]; check $? "up_to_date_run_keeps_exit_status"
[ "$(grep -c ': up to date' "$T/u.err")" -eq "$n_ex" ]; check $? "second_run_says_up_to_date"
summary "$T/u.err" | grep -q "^build: 0 compiled (0 infeasible), $n_ex up to date ($n_inf infeasible)"
check $? "second_run_summary_counts_skipped"
diff -r "$T/j1" "$T/j4" >/dev/null; check $? "skipped_outputs_unchanged"
"$AE" build --force -j 4 -o "$T/j1" examples/ 2>"$T/f.err"
summary "$T/f.err" | grep -q "^build: $n_ex compiled"; check $? "force_rebuilds_everything"
diff -r "$T/j1" "$T/j4" >/dev/null; check $? "forced_rebuild_is_byte_identical"

mkdir -p "$T/ex"; cp examples/*.json "$T/ex/"
"$AE" build -q -o "$T/m" "$T/ex" 2>/dev/null
sed 's/"t_hover_s": [0-9]*/"t_hover_s": 95/' examples/lidar_mapping_quad.json >"$T/ex/lidar_mapping_quad.json"
"$AE" build -o "$T/m" "$T/ex" 2>"$T/m.err"
summary "$T/m.err" | grep -q "^build: 1 compiled (0 infeasible), $((n_ex - 1)) up to date" \
	&& grep -q "lidar_mapping_quad.json: compiled" "$T/m.err"
check $? "changed_mission_alone_rebuilds"
# No output depends on a file's times (the dossier date is report.date,
# SOURCE_DATE_EPOCH or "undated"): a touched mission stays up to date, and
# rebuilt by force it gives the same bytes, every output and the stamp,
# with report.date and without (the SAR quad's removed: "undated").
unset SOURCE_DATE_EPOCH
mkdir -p "$T/tx"; cp examples/*.json "$T/tx/"
sed 's/"date": "[0-9-]*"/"date": ""/' examples/sar_imaging_quad.json >"$T/tx/undated.json"
"$AE" build -q -o "$T/t1" "$T/tx" 2>/dev/null
cp -R "$T/t1" "$T/t1.before"
touch -d 2001-01-01 "$T/tx/"*.json
"$AE" build -o "$T/t1" "$T/tx" 2>"$T/t1.err"
summary "$T/t1.err" | grep -q "^build: 0 compiled"; check $? "touched_missions_stay_up_to_date"
"$AE" build -q --force -o "$T/t1" "$T/tx" 2>/dev/null
diff -r "$T/t1.before" "$T/t1" >/dev/null; check $? "touched_missions_give_the_same_bytes"
touch -d 2031-07-07 "$T/tx/"*.json
"$AE" build -q -o "$T/t2" "$T/tx" 2>/dev/null
diff -r "$T/t1.before" "$T/t2" >/dev/null; check $? "missions_of_any_file_time_give_the_same_bytes"
pdftotext -f 1 -l 1 "$T/t2/undated/dossier.pdf" - 2>/dev/null | grep -q "undated" \
	&& ! pdfinfo "$T/t2/undated/dossier.pdf" 2>/dev/null | grep -q "^CreationDate"
check $? "mission_without_a_date_is_undated"

# rebuilds_after_change NAME OPTION ARG FILE: build twice with OPTION ARG (the
# second run is up to date), change FILE, and expect every mission rebuilt.
rebuilds_after_change() {
	"$AE" build -q "$2" "$3" -o "$T/$1" examples/ 2>/dev/null
	"$AE" build "$2" "$3" -o "$T/$1" examples/ 2>"$T/$1.1.err"
	echo >>"$4"
	"$AE" build "$2" "$3" -o "$T/$1" examples/ 2>"$T/$1.2.err"
	summary "$T/$1.1.err" | grep -q "^build: 0 compiled" \
		&& summary "$T/$1.2.err" | grep -q "^build: $n_ex compiled"
	check $? "changed_$1_rebuilds"
}
cp templates/a4.json "$T/tpl.json"
rebuilds_after_change template --template "$T/tpl.json" "$T/tpl.json"
cp -R data/catalog "$T/db"
rebuilds_after_change catalogue --db "$T/db" "$T/db/motors.json"
# A rebuilt compiler (a new mtime on the program file) recompiles everything.
cp "$AE" "$T/ae-copy"
AEROEVAL_DATA="$(pwd)/data" "$T/ae-copy" build -q -o "$T/exe" examples/ 2>/dev/null
AEROEVAL_DATA="$(pwd)/data" "$T/ae-copy" build -o "$T/exe" examples/ 2>"$T/exe.1.err"
touch -d 2030-03-03 "$T/ae-copy"
AEROEVAL_DATA="$(pwd)/data" "$T/ae-copy" build -o "$T/exe" examples/ 2>"$T/exe.2.err"
summary "$T/exe.1.err" | grep -q "^build: 0 compiled" \
	&& summary "$T/exe.2.err" | grep -q "^build: $n_ex compiled"
check $? "rebuilt_compiler_rebuilds"

rm "$T/j1/sar_imaging_quad/bom.csv"
"$AE" build -o "$T/j1" examples/ 2>"$T/r.err"
grep -q "sar_imaging_quad.json: compiled" "$T/r.err" && cmp -s "$T/j1/sar_imaging_quad/bom.csv" "$T/j4/sar_imaging_quad/bom.csv"
check $? "missing_output_rebuilds"

# ---- a worker that crashes or hangs does not take the run down --------------------
AEROEVAL_TEST_WORKER=abort:fpv_racing_quad "$AE" build -j 2 -o "$T/x" examples/ 2>"$T/x.err"; rc=$?
[ "$rc" -eq 3 ] && grep -q "fpv_racing_quad.json: internal error: the worker died of signal" "$T/x.err" \
	&& summary "$T/x.err" | grep -q "^build: $((n_ex - 1)) compiled.*, 1 internal errors;"
check $? "crashed_worker_is_an_internal_error_for_its_mission"
# The timeout (3 s) is well above a mission's time even while the rest of
# `make test` keeps every core busy; the hung worker is stopped by it.
AEROEVAL_BUILD_TIMEOUT_S=3 AEROEVAL_TEST_WORKER=hang:fpv_racing_quad \
	"$AE" build -j 2 -o "$T/h" examples/ 2>"$T/h.err"; rc=$?
[ "$rc" -eq 3 ] && grep -q "fpv_racing_quad.json: internal error: no result after" "$T/h.err" \
	&& [ -s "$T/h/sar_imaging_quad/result.json" ]
check $? "hung_worker_is_stopped_by_the_timeout"

# ---- 90 missions: one call, then an interrupted one -------------------------------
# Nine variants of each example but the FPV racer (its search alone costs
# as much as three other missions, and what is tested here is the count).
M="$T/many"
mkdir -p "$M"
for f in examples/*.json; do
	n=$(basename "$f" .json)
	[ "$n" = fpv_racing_quad ] && continue
	for k in 1 2 3 4 5 6 7 8 9; do
		sed -e 's/"payload_kg": \([0-9]*\)\(\.[0-9]*\)\{0,1\}/"payload_kg": \1.1'"$k"'/' \
		    -e 's/"t_hover_s": [0-9]*/"t_hover_s": '"$((50 + 10 * k))"'/' \
		    "$f" >"$M/${n}_v$k.json"
	done
done
n_many=$(ls "$M" | wc -l)
"$AE" build -j 2 -o "$T/big" "$M" 2>"$T/big.err"; rc=$?
[ "$rc" -le 1 ] && summary "$T/big.err" | grep -q "^build: $n_many compiled (.*), 0 up to date (0 infeasible), 0 rejected, 0 internal errors; $n_many missions in "
check $? "many_missions_compile_in_one_call"
[ "$(find "$T/big" -mindepth 1 -maxdepth 1 -type d | wc -l)" -eq "$n_many" ]
check $? "many_missions_each_have_a_folder"
# ... and a row each in the table the build keeps (a header line besides).
[ "$(wc -l <"$T/big/index.csv")" -eq "$((n_many + 1))" ]; check $? "many_missions_each_have_a_row"

# A shell gives background jobs SIGINT ignored; env restores the default so
# the build sees the signal as from a terminal.
if env --default-signal=INT true 2>/dev/null; then bg="env --default-signal=INT"; else bg=""; fi
$bg "$AE" build -j 2 -o "$T/k" "$M" 2>"$T/k.err" &
pid=$!
sleep 0.4
kill -INT "$pid"
wait "$pid"; rc=$?
[ "$rc" -eq 130 ]; check $? "interrupted_build_exits_130"
summary "$T/k.err" | grep -q "^build: interrupted (SIGINT): .* not started; $n_many missions"
check $? "interrupted_build_prints_a_summary"
[ -z "$(find "$T/k" -name '.*.tmp.*')" ]; check $? "interrupted_build_leaves_no_temp_file"
ok=1
for f in "$T"/k/*/result.json; do
	[ -e "$f" ] || continue
	[ "$(tail -c 2 "$f" | od -An -c | tr -d ' ')" = '}\n' ] || ok=0
done
for f in "$T"/k/*/bom.csv; do
	[ -e "$f" ] || continue
	[ "$(tail -c 1 "$f" | od -An -c | tr -d ' ')" = '\n' ] || ok=0
done
[ $ok -eq 1 ]; check $? "interrupted_build_leaves_only_complete_files"
ok=1
for s in "$T"/k/*/.aeroeval-stamp; do
	[ -e "$s" ] || continue
	d=$(dirname "$s")
	cmp -s "$d/result.json" "$T/big/$(basename "$d")/result.json" || ok=0
done
[ $ok -eq 1 ]; check $? "interrupted_build_stamps_only_complete_folders"

# On a terminal: one progress line redrawn with \r, no line per good mission.
if command -v script >/dev/null 2>&1; then
	script -qec "$AE build -j 2 -o $T/p examples/" /dev/null >"$T/p.tty" 2>&1
	grep -q "$(printf '\r')\[[0-9]*/$n_ex\] compiling " "$T/p.tty" \
		&& ! grep -q "sar_imaging_quad.json: compiled" "$T/p.tty" \
		&& grep -q "build: $n_ex compiled" "$T/p.tty"
	check $? "terminal_shows_one_progress_line"
else
	echo "ok terminal_shows_one_progress_line # skip: no script(1)"
fi

# ---- usage, help, version, man page ------------------------------------------------
"$AE" build -j 0 examples/ 2>/dev/null; [ $? -eq 2 ]; check $? "bad_jobs_value_exits_2"
"$AE" build --frobnicate examples/ 2>/dev/null; [ $? -eq 2 ]; check $? "unknown_option_exits_2"
"$AE" build 2>/dev/null; [ $? -eq 2 ]; check $? "no_mission_exits_2"
"$AE" --version | grep -q '^aeroeval [0-9][0-9.]*$'; check $? "version_prints_name_and_number"
"$AE" --help >"$T/help.txt"; rc=$?
ok=$rc
for c in build solve check schema validate calibrate sensitivity summary; do
	grep -q "^  $c " "$T/help.txt" || ok=1
done
grep -q "man aeroeval" "$T/help.txt" || ok=1
[ $ok -eq 0 ]; check $? "help_lists_every_command"
"$AE" help build | grep -q -- "-j N" && "$AE" build --help | grep -q -- "--force"
check $? "build_help_lists_its_options"
"$AE" help nonsense 2>/dev/null; [ $? -eq 2 ]; check $? "help_for_unknown_command_exits_2"
if command -v man >/dev/null 2>&1; then
	MANWIDTH=80 man -l src/cli/aeroeval.1 2>"$T/man.err" >"$T/man.txt"
	ok=0
	for s in NAME SYNOPSIS DESCRIPTION OPTIONS "EXIT STATUS" FILES EXAMPLES "SEE ALSO"; do
		grep -q "^$s" "$T/man.txt" || ok=1
	done
	[ ! -s "$T/man.err" ] || ok=1
	[ $ok -eq 0 ]; check $? "man_page_renders_every_section"
else
	echo "ok man_page_renders_every_section # skip: no man"
fi
exit 0
