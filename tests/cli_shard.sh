#!/bin/sh
# Whole-compiler tests of a study spread over machines: `build --shard K/N`
# into one shared folder gives, byte for byte, the folder one build gives,
# index.csv and index.json included, whether the shards run one after the
# other or at once; `summary` rebuilds the same table; the split is stable
# when unrelated missions are added; K/N is checked.
# Prints "ok NAME" / "not ok NAME"; run by tests/run_all.sh with $AEROEVAL.
AE=${AEROEVAL:-build/aeroeval}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
check() { if [ "$1" -eq 0 ]; then echo "ok $2"; else echo "not ok $2"; fi; }
export SOURCE_DATE_EPOCH=1767225600

# The study: the examples and a few variants of them.
M="$T/missions"
mkdir -p "$M"
cp examples/*.json "$M/"
for k in 1 2 3 4 5; do
	sed -e 's/"payload_kg": \([0-9]*\)\(\.[0-9]*\)\{0,1\}/"payload_kg": \1.2'"$k"'/' \
	    examples/lidar_mapping_quad.json >"$M/lidar_v$k.json"
done
n=$(ls "$M" | wc -l)

"$AE" build -q -j 2 -o "$T/one" "$M" 2>"$T/one.err"; rc_one=$?
[ "$rc_one" -le 1 ] && [ -s "$T/one/index.csv" ]; check $? "unsharded_build_writes_the_table"

# ---- three shards, one after the other, into one folder --------------------------
total=0
for k in 1 2 3; do
	"$AE" build -j 2 -o "$T/three" --shard "$k/3" "$M" 2>"$T/s$k.err"
	c=$(sed -n 's/^build: \([0-9]*\) compiled.*/\1/p' "$T/s$k.err")
	total=$((total + ${c:-0}))
	grep -q "missions (shard $k/3 of $n) in " "$T/s$k.err" || total=-1000
done
[ "$total" -eq "$n" ]; check $? "three_shards_compile_each_mission_once"
diff -r "$T/one" "$T/three" >"$T/diff.txt" 2>&1; rc=$?
[ $rc -ne 0 ] && head -5 "$T/diff.txt"
check $rc "three_shards_union_is_byte_identical_to_one_build"

# Each shard alone holds its own share, and no mission is in two shares.
for k in 1 2 3; do
	"$AE" build -q -j 2 -o "$T/only$k" --shard "$k/3" "$M" 2>/dev/null
done
all=$(for k in 1 2 3; do ls -d "$T/only$k"/*/ 2>/dev/null; done | xargs -n1 basename | sort)
[ "$(echo "$all" | wc -l)" -eq "$n" ] && [ -z "$(echo "$all" | uniq -d)" ]
check $? "shares_are_disjoint_and_cover_the_study"

# ---- three shards at once (a job array) -----------------------------------------
for k in 1 2 3; do
	"$AE" build -q -j 1 -o "$T/par" --shard "$k/3" "$M" 2>/dev/null &
done
wait
diff -r "$T/one" "$T/par" >/dev/null; check $? "concurrent_shards_union_is_byte_identical"
# Hidden entries but the table's stamp (cli_summary.h) are leftovers.
[ -z "$(ls -A "$T/par" | grep '^\.' | grep -vx '\.aeroeval-index-stamp')" ]
check $? "concurrent_shards_leave_no_lock_or_temporary"

# ---- summary ---------------------------------------------------------------------
cp "$T/three/index.csv" "$T/index.before"
rm "$T/three/index.csv" "$T/three/index.json"
"$AE" summary "$T/three" 2>"$T/sum.err"; rc=$?
[ $rc -eq 0 ] && cmp -s "$T/three/index.csv" "$T/one/index.csv" \
	&& cmp -s "$T/three/index.json" "$T/one/index.json"
check $? "summary_rebuilds_the_same_table"
grep -q "^summary: $n missions (" "$T/sum.err" && pdfinfo "$T/three/overview.pdf" >/dev/null 2>&1
check $? "summary_reports_and_draws_the_overview"
"$AE" summary --stdout "$T/one" >"$T/stdout.csv" 2>/dev/null
cmp -s "$T/stdout.csv" "$T/one/index.csv" && [ ! -e "$T/one/overview.pdf" ]
check $? "summary_stdout_prints_the_table_and_writes_nothing"
[ "$(wc -l <"$T/one/index.csv")" -eq $((n + 1)) ]; check $? "table_has_a_row_per_mission"
"$AE" summary "$T/missions" 2>"$T/empty.err"; rc=$?
[ $rc -eq 2 ] && grep -q "no compiled mission" "$T/empty.err"
check $? "summary_of_a_folder_without_missions_is_exit_2"

# Once summary has drawn overview.pdf, build keeps it current with the table.
cp -R "$T/three" "$T/ov"
cp "$T/ov/overview.pdf" "$T/ov.before"
sed 's/"payload_kg": [0-9.]*/"payload_kg": 1.234/' examples/sar_imaging_quad.json \
	>"$T/sar_imaging_quad.json"
"$AE" build -q -o "$T/ov" "$T/sar_imaging_quad.json" 2>/dev/null
cp "$T/ov/overview.pdf" "$T/ov.after"
"$AE" summary -q "$T/ov" 2>/dev/null
! cmp -s "$T/ov.before" "$T/ov.after" && cmp -s "$T/ov.after" "$T/ov/overview.pdf" \
	&& grep -q '^sar_imaging_quad,.*,1.234,' "$T/ov/index.csv"
check $? "build_keeps_a_drawn_overview_current"

# Nothing under the folder is followed, and a broken result.json is named
# and left out while the rest of the table is written.
cp -R "$T/one" "$T/odd"
rm -f "$T/odd/index.csv"
ln -s "$T/one/sar_imaging_quad" "$T/odd/linked"
mkdir "$T/odd/broken" && echo '{"status": ' >"$T/odd/broken/result.json"
mkdir "$T/odd/linkres" && ln -s "$T/one/sar_imaging_quad/result.json" "$T/odd/linkres/result.json"
"$AE" summary --no-pdf "$T/odd" 2>"$T/odd.err"; rc=$?
[ $rc -eq 2 ] && grep -q "odd/broken/result.json:.*error: malformed JSON" "$T/odd.err" \
	&& grep -q "odd/linkres/result.json: error: cannot read file: .*symbolic link" "$T/odd.err" \
	&& cmp -s "$T/odd/index.csv" "$T/one/index.csv" && [ ! -e "$T/odd/overview.pdf" ]
check $? "summary_follows_no_link_and_names_a_broken_result"

# ---- the split is stable when unrelated missions are added -------------------------
sed 's/"payload_kg": [0-9.]*/"payload_kg": 0.777/' examples/sar_imaging_quad.json >"$M/zz_added.json"
sed 's/"payload_kg": [0-9.]*/"payload_kg": 0.555/' examples/sar_imaging_quad.json >"$M/aa_added.json"
stable=0
for k in 1 2 3; do
	"$AE" build -q -j 2 -o "$T/more$k" --shard "$k/3" "$M" 2>/dev/null
	before=$(ls -d "$T/only$k"/*/ 2>/dev/null | xargs -n1 basename | sort)
	after=$(ls -d "$T/more$k"/*/ 2>/dev/null | xargs -n1 basename | grep -v '_added$' | sort)
	[ "$before" = "$after" ] || stable=1
done
check $stable "adding_missions_moves_no_other_mission"

# ---- K/N is checked ----------------------------------------------------------------
bad=0
for s in 0/3 4/3 3 abc 1/0 -1/3 "1/3 " ""; do
	"$AE" build -o "$T/bad" --shard "$s" "$M" 2>"$T/bad.err"; rc=$?
	{ [ $rc -eq 2 ] && grep -q '^aeroeval build: error: --shard' "$T/bad.err" \
	    && [ ! -e "$T/bad" ]; } || { bad=1; echo "# --shard '$s': exit $rc"; }
done
check $bad "bad_shard_is_exit_2_with_a_clear_error"

# A share without a mission is no error: the other machines have them.
mkdir -p "$T/single"
cp examples/sar_imaging_quad.json "$T/single/"
empty_ok=1
for k in 1 2 3; do
	"$AE" build -o "$T/e$k" --shard "$k/3" "$T/single" 2>"$T/e.err"; rc=$?
	if grep -q "holds none of the 1 missions" "$T/e.err"; then
		[ $rc -eq 0 ] && [ -z "$(ls -A "$T/e$k" 2>/dev/null)" ] && empty_ok=0
	fi
done
check $empty_ok "empty_share_is_exit_0_and_writes_nothing"
exit 0
