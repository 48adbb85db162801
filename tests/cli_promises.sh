#!/bin/sh
# cli_promises.sh — every command keeps the file-system promises `build`
# keeps (issue 36): the study table is a function of the mission folders,
# a failed write to stdout fails, the two-rename swap never loses the old
# set, every writer goes through the one file-system layer, the program's own
# names are not mission names, and the smaller input rules.  Each check
# failed on the main branch before issue 36.
#
# usage: AEROEVAL=build/aeroeval sh tests/cli_promises.sh   (from the repo root)
# Prints "ok NAME" / "not ok NAME # why" per check.

root=$(pwd)
bin=${AEROEVAL:-build/aeroeval}
case "$bin" in /*) ;; *) bin="$root/$bin" ;; esac
export AEROEVAL_DATA="$root/data"
work=$(mktemp -d)
mounted=""  # tmpfs mounts, undone on exit
trap 'for m in $mounted; do umount "$m"; done; rm -rf "$work"' EXIT
cd "$work" || exit 1

ok() { echo "ok $1"; }
notok() { echo "not ok $1${2:+ # $2}"; }
# check NAME: ok when the last command succeeded.
check() { if [ $? -eq 0 ]; then ok "$1"; else notok "$1" "$2"; fi; }

# run ARGS...: stdout in out.txt, stderr in err.txt, status in $rc.
run() {
	timeout 60 "$bin" "$@" >out.txt 2>err.txt
	rc=$?
}

# mission PAYLOAD_KG: a small quad that compiles in a tenth of a second.
mission() {
	printf '{"payload_kg": %s, "max_diameter_m": 0.7, "t_hover_s": 600}\n' "$1"
}

# set_of, stamp_vouches, temps_in.
. "$root/tests/lib_sets.sh"

# A shell gives background jobs SIGINT ignored; env restores the default so
# the build sees the signal as from a terminal.
if env --default-signal=INT true 2>/dev/null; then bg="env --default-signal=INT"; else bg=""; fi

# wait_until SECONDS CMD...: polls CMD every 20 ms; false on time-out.
wait_until() {
	limit=$(($1 * 50))
	shift
	i=0
	while ! "$@"; do
		i=$((i + 1))
		[ "$i" -gt "$limit" ] && return 1
		sleep 0.02
	done
	return 0
}

# ---- 1. the study table is a function of the mission folders ----------------
# table_is_current DIR: index.csv and index.json hold what `summary` writes
# for the folders there now.
table_is_current() {
	rm -rf tcopy && cp -R "$1" tcopy && rm -f tcopy/index.csv tcopy/index.json &&
	    "$bin" summary -q --no-pdf tcopy 2>/dev/null &&
	    cmp -s "$1/index.csv" tcopy/index.csv && cmp -s "$1/index.json" tcopy/index.json
}

mkdir -p study
for i in 01 02 03 04 05 06 07 08 09 10; do mission 2.0 >study/m$i.json; done
"$bin" build -q -j 1 -o s2 study 2>/dev/null
for i in 01 02 03 04 05 06 07 08 09 10; do mission 0.5 >study/m$i.json; done
# SIGINT once three missions have compiled: their rows must be in the table
# (the interrupted build left it listing payload 2.0 where result.json said 0.5).
AEROEVAL_TEST_WRITE_DELAY_MS=30 $bg "$bin" build -j 1 -o s2 study 2>int.err &
p=$!
three_compiled() { [ "$(grep -c ': compiled' int.err)" -ge 3 ]; }
wait_until 60 three_compiled
kill -INT "$p"
wait "$p" 2>/dev/null
rc=$?
[ "$rc" -eq 130 ] && table_is_current s2
check interrupted_build_leaves_the_table_current "exit $rc"
run build -o s2 study
[ "$rc" -eq 0 ] && table_is_current s2
check build_after_an_interruption_leaves_the_table_current "exit $rc"

# A damaged or missing table is noticed by a build with nothing to compile.
echo garbage >s2/index.csv
run build -o s2 study
[ "$rc" -eq 0 ] && grep -q '10 up to date' err.txt && table_is_current s2
check garbage_index_csv_is_rebuilt "exit $rc"
rm s2/index.json
run build -o s2 study
[ "$rc" -eq 0 ] && [ -f s2/index.json ] && table_is_current s2
check missing_index_json_is_rebuilt "exit $rc"
printf '{"aeroeval_version": "0", "missions": []}\n' >s2/index.json
run build -o s2 study
[ "$rc" -eq 0 ] && table_is_current s2
check damaged_index_json_is_rebuilt "exit $rc"
# A row changed by another run (here a folder removed): the table follows.
rm -rf s2/m10
run build -o s2 study/m01.json
[ "$rc" -eq 0 ] && table_is_current s2 && ! grep -q '^m10,' s2/index.csv
check table_drops_a_removed_folder "exit $rc"
# A current table is not rewritten (its bytes and time stay).
run build -o s2 study
touch -d '2001-01-01' s2/index.csv
run build -o s2 study
[ "$rc" -eq 0 ] && [ "$(date -r s2/index.csv +%Y)" = 2001 ]
check current_table_is_left_alone "exit $rc"

# ---- 2. a failed write to stdout is exit 2 with a message --------------------
mkdir -p m
mission 1.5 >m/good.json
printf 'name,takeoff_mass_kg,rotor_count,coaxial,diagonal_wheelbase_mm,hover_time_min,airframe_class,role,payload_kg\n' >tiny.csv
printf 'Consumer one,1.2,4,0,350,20,ConsumerFolding,imaging,0.3\n' >>tiny.csv
printf 'Consumer two,2.5,4,0,450,16,ConsumerFolding,imaging,0.4\n' >>tiny.csv
"$bin" build -q -o sumdir m/good.json 2>/dev/null
if [ -w /dev/full ]; then
	for cmd in "solve m/good.json" "solve --summary m/good.json" "schema" "schema --json" \
	    "summary --stdout sumdir" "validate tiny.csv" "validate --json tiny.csv" \
	    "sensitivity --tsv -o sens m/good.json" "calibrate tiny.csv" "--help" "--version" \
	    "help build" "build --help"; do
		# shellcheck disable=SC2086
		timeout 60 "$bin" $cmd >/dev/full 2>err.txt
		rc=$?
		name=$(echo "$cmd" | tr ' ' '_' | tr -d '-')
		[ "$rc" -eq 2 ] && grep -q 'cannot write to standard output' err.txt
		check "stdout_to_dev_full_is_exit_2: $name" "exit $rc"
	done
else
	ok "stdout_to_dev_full_is_exit_2 # skip: no /dev/full"
fi
# A file system that fills up in the middle of result.json (as root).
if [ "$(id -u)" -eq 0 ] && mkdir -p tiny && mount -t tmpfs -o size=64k tmpfs tiny 2>/dev/null; then
	mounted="$work/tiny"
	timeout 60 "$bin" solve "$root/examples/sar_imaging_quad.json" >tiny/result.json 2>err.txt
	rc=$?
	[ "$rc" -eq 2 ] && grep -q 'standard output' err.txt
	check solve_onto_a_full_file_system_is_exit_2 "exit $rc"
	umount tiny
	mounted=""
fi

# ---- 3. the two-rename swap never deletes the only copy of the old set -------
# AEROEVAL_TEST_NO_EXCHANGE forces the swap where renameat2 is missing (NFS);
# AEROEVAL_TEST_WRITE_DELAY_MS holds each step long enough to signal it.
export SOURCE_DATE_EPOCH=1700000000
mkdir -p fbv/old fbv/new fbm
mission 1.5 >fbv/old/m5.json
mission 1.0 >fbv/new/m5.json
"$bin" build -q -o fbo fbv/old/m5.json 2>/dev/null
"$bin" build -q -o fbn fbv/new/m5.json 2>/dev/null
set_o=$(set_of fbo/m5) set_n=$(set_of fbn/m5)
# tmp_files: files in the new set being written (-1 before it exists).
tmp_files() {
	for d in fb/.m5.tmp.*; do
		# Counted with the shell's own globs: this runs every 20 ms.
		[ -d "$d" ] || continue
		n=0
		for f in "$d"/* "$d"/.[!.]* "$d"/..?*; do
			[ -e "$f" ] && n=$((n + 1))
		done
		echo "$n"
		return
	done
	echo -1
}
at_files() { [ "$(tmp_files)" -eq "$1" ]; }
between_renames() { [ ! -e fb/m5 ]; }
# start_swap: the old set in fb/m5, then a slowed build of the new one.
start_swap() {
	rm -rf fb
	cp fbv/old/m5.json fbm/m5.json
	"$bin" build -q -o fb fbm/m5.json 2>/dev/null
	cp fbv/new/m5.json fbm/m5.json
	AEROEVAL_TEST_NO_EXCHANGE=1 AEROEVAL_TEST_WRITE_DELAY_MS=200 \
	    setsid $bg "$bin" build -q -j 1 -o fb fbm/m5.json >/dev/null 2>&1 &
	p=$!
}
# Every moment: before each file of the new set (0..5 written), before the
# swap (6 written) and between the two renames; SIGINT to the whole group
# (a ^C) and SIGTERM to the build (a batch system stopping it).
for sig in INT TERM; do
	bad=""
	for at in 0 1 2 3 4 5 6 between; do
		start_swap
		if [ "$at" = between ]; then wait_until 20 between_renames || bad="$bad $at:missed"
		else wait_until 20 at_files "$at" || bad="$bad $at:missed"; fi
		if [ "$sig" = INT ]; then kill -INT "-$p"; else kill -TERM "$p"; fi
		wait "$p"
		s=$(set_of fb/m5)
		{ [ -n "$s" ] && { [ "$s" = "$set_o" ] || [ "$s" = "$set_n" ]; } && stamp_vouches fb/m5 &&
		    [ -z "$(temps_in fb)" ]; } || bad="$bad $at"
	done
	[ -z "$bad" ]
	check "fallback_swap_signalled_keeps_the_old_or_new_set: SIG$sig" "lost or mixed at:$bad"
done
# SIGKILL of the worker between the renames: the build's own clean-up puts
# the old set back (it deleted the set-aside folder, the only copy).
start_swap
wait_until 20 between_renames
w=$(cat "/proc/$p/task/$p/children" 2>/dev/null | cut -d' ' -f1)
[ -n "$w" ] && kill -KILL "$w"
wait "$p" 2>/dev/null
if [ -z "$w" ]; then
	ok "fallback_swap_worker_killed_between_renames_keeps_the_old_set # skip: no /proc children list"
else
	[ "$(set_of fb/m5)" = "$set_o" ] && stamp_vouches fb/m5 && [ -z "$(temps_in fb)" ]
	check fallback_swap_worker_killed_between_renames_keeps_the_old_set
fi
# kill -9 of everything between the renames: the next build recovers the
# set-aside folder (the old mission again: up to date, nothing compiled).
start_swap
wait_until 20 between_renames
kill -KILL "-$p"
wait "$p" 2>/dev/null
cp fbv/old/m5.json fbm/m5.json
run build -o fb fbm/m5.json
[ "$rc" -eq 0 ] && grep -q 'm5.json: up to date' err.txt && [ "$(set_of fb/m5)" = "$set_o" ] &&
    [ -z "$(temps_in fb)" ]
check fallback_swap_killed_between_renames_is_recovered_by_the_next_build "exit $rc"
unset SOURCE_DATE_EPOCH

# ---- 4. every writer goes through the one file-system layer ------------------
# sensitivity writes into the mission's folder as `build` does, and `build`
# still calls the folder its own, up to date or forced.
rm -rf out
run sensitivity m/good.json
[ "$rc" -eq 0 ] && [ -s out/good/sensitivity.json ] && [ -s out/good/sensitivity.pdf ]
check sensitivity_writes_into_the_mission_folder "exit $rc"
run build -o out m/good.json
[ "$rc" -eq 0 ]
check build_after_sensitivity_works "exit $rc"
run sensitivity m/good.json
run build -o out m/good.json
[ "$rc" -eq 0 ] && grep -q 'good.json: up to date' err.txt && [ -s out/good/sensitivity.pdf ] &&
    stamp_vouches out/good
check sensitivity_keeps_the_build_up_to_date "exit $rc"
run build --force -o out m/good.json
[ "$rc" -eq 0 ] && stamp_vouches out/good && table_is_current out
check forced_build_after_sensitivity_works "exit $rc"
# A link planted at out/<name> is refused, its target untouched.
rm -rf out elsewhere && mkdir -p out elsewhere
ln -s ../elsewhere out/good
run sensitivity m/good.json
[ "$rc" -eq 2 ] && grep -q 'symbolic link' err.txt && [ -z "$(ls -A elsewhere)" ]
check sensitivity_refuses_a_planted_link "exit $rc"
rm -rf out elsewhere
# The root and "" are no output folder, for any writer.  What a writer
# that does not refuse puts into / is removed again (and the check skipped
# where such a file was there before).
in_root="/good /sensitivity.json /sensitivity.pdf /01-Consumer-one.json /02-Consumer-two.json"
# root_spoiled: something of in_root appeared in / (removed).
root_spoiled() {
	found=1
	for f in $in_root; do
		if [ -e "$f" ]; then
			rm -rf "$f"
			found=0
		fi
	done
	return $found
}
clean_root=1
for f in $in_root; do [ -e "$f" ] && clean_root=0; done
for o in / //. ""; do
	[ "$clean_root" -eq 1 ] || { ok "writers_refuse_output_folder: '$o' # skip: / holds their names"; continue; }
	run sensitivity -o "$o" m/good.json
	! root_spoiled && [ "$rc" -eq 2 ]
	check "sensitivity_refuses_output_folder: '$o'" "exit $rc"
	run validate --missions "$o" tiny.csv
	! root_spoiled && [ "$rc" -eq 2 ]
	check "validate_missions_refuses_folder: '$o'" "exit $rc"
done
: >afile
run sensitivity -o afile m/good.json
[ "$rc" -eq 2 ] && grep -q 'names a file' err.txt
check sensitivity_refuses_a_file_as_output_folder "exit $rc"
# validate --missions DIR is a folder of the program's own, replaced whole.
run validate --missions vm tiny.csv
[ "$rc" -eq 0 ] && [ "$(ls vm | wc -l)" -eq 2 ] && [ -z "$(ls -A . | grep '^\.')" ]
check validate_missions_writes_a_folder "exit $rc"
head -2 tiny.csv >tiny1.csv
run validate --missions vm tiny1.csv
[ "$rc" -eq 0 ] && [ "$(ls vm)" = 01-Consumer-one.json ]
check validate_missions_replaces_the_folder_whole "exit $rc"
: >vm/notes.txt
run validate --missions vm tiny.csv
[ "$rc" -eq 2 ] && grep -q 'vm/notes.txt: error: not an output of aeroeval' err.txt &&
    [ "$(ls vm | wc -l)" -eq 2 ]
check validate_missions_refuses_a_foreign_file "exit $rc"
rm -rf vm elsewhere && mkdir elsewhere && ln -s elsewhere vm
run validate --missions vm tiny.csv
[ "$rc" -eq 2 ] && grep -q 'symbolic link' err.txt && [ -z "$(ls -A elsewhere)" ]
check validate_missions_refuses_a_link "exit $rc"
rm -f vm
# Single files: a link, a folder or a device is never replaced.
echo keep >target.json
ln -s target.json cal.json
run calibrate --write cal.json tiny.csv
[ "$rc" -eq 2 ] && [ "$(cat target.json)" = keep ] && [ -L cal.json ]
check calibrate_write_refuses_a_link "exit $rc"
mkdir -p calf
run calibrate --write calf tiny.csv
[ "$rc" -eq 2 ] && grep -q 'is a folder' err.txt && [ -z "$(ls -A calf)" ]
check calibrate_write_refuses_a_folder "exit $rc"
run calibrate --write "" tiny.csv
[ "$rc" -eq 2 ]
check calibrate_write_refuses_an_empty_name "exit $rc"
ln -s target.json rep.pdf
run validate --report rep.pdf tiny.csv
[ "$rc" -eq 2 ] && [ "$(cat target.json)" = keep ]
check validate_report_refuses_a_link "exit $rc"

# ---- 5. names the program keeps for itself -----------------------------------
mkdir -p rn
for n in index.csv index.json overview.pdf .x.tmp.999999.0 .hidden; do
	mission 1.5 >"rn/$n.json"
	rm -rf rno
	run build -o rno "rn/$n.json"
	[ "$rc" -eq 2 ] && grep -qF "rn/$n.json: error: the file name" err.txt &&
	    [ -z "$(ls -A rno 2>/dev/null | grep -vx '\.aeroeval-index-stamp')" ]
	check "reserved_mission_name_is_refused: $n.json" "exit $rc"
	rm "rn/$n.json"
done
# summary keeps working beside them.
run build -o rno m/good.json
run summary rno
[ "$rc" -eq 0 ] && [ -s rno/overview.pdf ]
check summary_works_in_a_folder_with_its_own_files "exit $rc"
# A hidden mission named like a dead writer's temporary of mission x once
# compiled, out of the table, and the next build of x deleted its outputs:
# now nothing of it is written, and x is untouched.
mission 1.5 >rn/x.json
mission 1.5 >rn/.x.tmp.999999.0.json
rm -rf rno && "$bin" build -q -o rno rn/x.json 2>/dev/null
set_x=$(set_of rno/x)
run build -o rno rn/.x.tmp.999999.0.json
[ ! -e rno/.x.tmp.999999.0 ] && "$bin" build -q -o rno rn/x.json 2>/dev/null &&
    [ "$(set_of rno/x)" = "$set_x" ]
check hidden_mission_cannot_pose_as_a_temporary "exit $rc"
# The output name is part of the fingerprint: a folder copied over another
# mission's with the same bytes and times is rebuilt, not "up to date".
mkdir -p ab
mission 1.5 >ab/alpha.json
cp -p ab/alpha.json ab/beta.json
touch -r ab/alpha.json ab/beta.json
rm -rf abo && "$bin" build -q -o abo ab 2>/dev/null
rm -rf abo/beta && cp -Rp abo/alpha abo/beta
run build -o abo ab
[ "$rc" -eq 0 ] && grep -q 'beta.json: compiled' err.txt && ! grep -q 'alpha' abo/beta/ardupilot.param
check output_name_is_in_the_fingerprint "exit $rc"
# build -o . . skips its own table (index.json was read as a mission).
mkdir -p here && mission 1.5 >here/h.json
(cd here && timeout 60 "$bin" build -o . . >../out.txt 2>../err.txt && timeout 60 "$bin" build -o . . >../out.txt 2>../err.txt)
rc=$?
[ "$rc" -eq 0 ] && ! grep -q 'index' err.txt && [ ! -e here/index ]
check build_into_its_own_input_folder_skips_its_table "exit $rc"

# ---- 6. smaller ones ----------------------------------------------------------
for c in "solve --db '' m/good.json" "build -o dbo --db '' m/good.json"; do
	eval "run $c"
	[ "$rc" -eq 2 ] && grep -q 'empty' err.txt && [ ! -e dbo ]
	check "empty_db_is_refused: $(echo "$c" | cut -d' ' -f1)" "exit $rc"
done
# validate: a rejected cohort row makes the exit status 2, as its error says.
{ cat tiny.csv; printf 'Bad one,-3,4,0,350,20,ConsumerFolding,imaging,0.3\n'; } >badrow.csv
run validate badrow.csv
[ "$rc" -eq 2 ] && grep -q 'badrow.csv:4: error: takeoff_mass_kg' err.txt && grep -q 'MAPE' out.txt
check validate_with_a_rejected_row_is_exit_2 "exit $rc"
run validate tiny.csv
[ "$rc" -eq 0 ]
check validate_of_a_clean_cohort_is_exit_0 "exit $rc"
# Control characters in any text field, the cohort's rule.
printf '{"name": "red\\u001b[31m", "payload_kg": 1.5, "max_diameter_m": 0.7, "t_hover_s": 600}\n' >m/esc.json
printf '{"report": {"title": "a\\r\\nb"}, "payload_kg": 1.5, "max_diameter_m": 0.7, "t_hover_s": 600}\n' >m/crlf.json
printf '{"report": {"client": "x\342\200\256gnp.exe"}, "payload_kg": 1.5, "max_diameter_m": 0.7, "t_hover_s": 600}\n' >m/bidi.json
for t in "esc m/esc.json:1:10: error: name: string contains a control character" \
    "crlf m/crlf.json:1:22: error: report.title: string contains a control character" \
    "bidi m/bidi.json:1:23: error: report.client: string contains a control character"; do
	f=m/${t%% *}.json
	rm -rf cco
	run build -o cco "$f"
	[ "$rc" -eq 2 ] && grep -qF "${t#* }" err.txt && [ ! -e "cco/${t%% *}" ]
	check "control_character_in_text_is_refused: ${t%% *}" "exit $rc"
done
# Memory bounded per input byte: a 3.8 MB array once took 278 MB.
awk 'BEGIN { printf "["; for (i = 0; i < 1900000; i++) printf "0,"; print "0]" }' >m/array.json
awk 'BEGIN { printf "{\"x\": ["; for (i = 0; i < 1200000; i++) printf "[],"; print "[]]}" }' >m/nested.json
for f in array nested; do
	(ulimit -v 200000; exec timeout 60 "$bin" check "m/$f.json") >out.txt 2>err.txt
	rc=$?
	[ "$rc" -eq 2 ] && grep -q "m/$f.json: error: too many entries" err.txt
	check "memory_is_bounded_per_input_byte: $f" "exit $rc"
done
# A 3-rotor coaxial mission: the layout is refused, with no CG message
# built from a one-arm "polygon" ("Mount the payload within -0.500 m").
printf '{"payload_kg": 0.5, "max_diameter_m": 1.0, "t_hover_s": 600, "num_rotors": 3, "coaxial_layout": true}\n' >m/co3.json
run solve m/co3.json
[ "$rc" -eq 1 ] && grep -q 'COAXIAL_LAYOUT' out.txt && ! grep -q 'CG_OFFSET' out.txt &&
    ! grep -q 'within -' out.txt
check coaxial_3_rotors_gets_no_spurious_cg_message "exit $rc"
exit 0
