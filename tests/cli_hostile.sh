#!/bin/sh
# cli_hostile.sh — hostile mission files (issue 9): whatever a client sends,
# aeroeval gives a clear error (exit 2, stderr names the file) or a safe
# result (exit 0/1 with finite numbers), never crashes or hangs (each run is
# bounded by `timeout`), and never writes outside the output directory.
#
# usage: AEROEVAL=build/aeroeval sh tests/cli_hostile.sh   (from the repo root)
# Prints "ok NAME" / "not ok NAME # why" per check.

root=$(pwd)
bin=${AEROEVAL:-build/aeroeval}
case "$bin" in /*) ;; *) bin="$root/$bin" ;; esac
export AEROEVAL_DATA="$root/data"
work=$(mktemp -d)
mounted=""  # tmpfs mounts of the file-system tests, undone on exit
trap 'for m in $mounted; do umount "$m"; done; rm -rf "$work"' EXIT
mkdir -p "$work/m" "$work/cwd/a/b"
cd "$work" || exit 1

ok() { echo "ok $1"; }
notok() { echo "not ok $1${2:+ # $2}"; }

# run ARGS...: stdout in out.txt, stderr in err.txt, status in $rc.
run() {
	timeout 30 "$bin" "$@" >out.txt 2>err.txt
	rc=$?
}

# A mission that compiles; variants below are built from it.
good='"payload_kg": 1.5, "max_diameter_m": 0.7, "t_hover_s": 600'
printf '{%s}\n' "$good" >m/good.json

# fails NAME WANT ARGS...: `aeroeval ARGS...` exits 2, no crash or hang,
# WANT in stderr, nothing written to out/.
fails() {
	name=$1
	want=$2
	shift 2
	rm -rf out
	run "$@"
	if [ "$rc" -ge 124 ]; then
		notok "$name" "exit $rc (crash or timeout)"
	elif [ "$rc" -ne 2 ]; then
		notok "$name" "exit $rc, want 2"; sed 's/^/# /' err.txt | head -3
	elif ! grep -qF -- "$want" err.txt; then
		notok "$name" "stderr lacks: $want"; sed 's/^/# /' err.txt | head -3
	elif [ -n "$(find out -type f 2>/dev/null)" ]; then
		notok "$name" "wrote output"
	else
		ok "$name"
	fi
}

# rejected NAME FILE [CMD]: `aeroeval CMD FILE` (default build) exits 2 with
# a diagnostic that names FILE, writes nothing to out/, and nothing else.
rejected() {
	if [ "${3:-build}" = build ]; then fails "$1" "$2" build -o out "$2"
	else fails "$1" "$2" "$3" "$2"; fi
}

# safe NAME FILE: `build` exits 0 or 1, result.json has no NaN/Infinity.
safe() {
	rm -rf out
	run build -o out "$2"
	name=$(basename "$2" .json)
	if [ "$rc" -ne 0 ] && [ "$rc" -ne 1 ]; then
		notok "$1" "exit $rc, want 0 or 1"; sed 's/^/# /' err.txt | head -3
	elif [ ! -s "out/$name/result.json" ]; then
		notok "$1" "no result.json"
	elif grep -qE '(^|[]:, [])-?(nan|NaN|inf|Inf|Infinity)([], ]|$)' "out/$name/result.json"; then
		notok "$1" "non-finite number in result.json"
	else
		ok "$1"
	fi
}

# either NAME FILE: a clear rejection or a safe result are both fine.
either() {
	rm -rf out
	run build -o out "$2"
	if [ "$rc" -eq 2 ]; then
		rejected "$1" "$2"
	else
		safe "$1" "$2"
	fi
}

# ---- size and shape -------------------------------------------------------
# > 4 MiB: a valid mission padded with spaces.
{ printf '{%s' "$good"; head -c 4300000 /dev/zero | tr '\0' ' '; printf '}\n'; } >m/huge.json
rejected huge_file_is_refused m/huge.json
grep -qi 'too large' err.txt || notok huge_file_error_says_too_large
rejected huge_file_is_refused_by_check m/huge.json check
rejected huge_file_is_refused_by_solve m/huge.json solve

awk 'BEGIN { s = ""; for (i = 0; i < 10000; i++) s = s "["; print s }' >m/deep.json
rejected deep_nesting m/deep.json
awk 'BEGIN { printf "{\"report\": "; for (i = 0; i < 10000; i++) printf "{\"a\":"; print "1" }' >m/deep_obj.json
rejected deep_object_nesting m/deep_obj.json

: >m/empty.json
rejected empty_file m/empty.json
rejected empty_file_by_check m/empty.json check
printf '   \n\t\n' >m/blank.json
rejected whitespace_only m/blank.json
printf '\0\0\0\0' >m/nul.json
rejected nul_bytes m/nul.json
head -c 4096 /dev/urandom >m/random.json 2>/dev/null
rejected random_bytes m/random.json
printf '{%s}\n\0{"payload_kg": 2}' "$good" >m/after_nul.json
rejected text_after_a_nul m/after_nul.json

# ---- numbers --------------------------------------------------------------
printf '{"payload_kg": 1e308, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/n_big.json
rejected number_1e308_out_of_range m/n_big.json
printf '{"payload_kg": 1e400, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/n_overflow.json
rejected number_1e400_overflows m/n_overflow.json
printf '{"payload_kg": -1e400, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/n_neg_overflow.json
rejected number_minus_1e400_overflows m/n_neg_overflow.json
printf '{"payload_kg": 1e-320, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/n_subnormal.json
either number_subnormal_payload m/n_subnormal.json
printf '{"payload_kg": -0, "max_diameter_m": 0.7, "t_hover_s": 600, "ambient_temp_c": -0.0}' >m/n_negzero.json
safe number_negative_zero m/n_negzero.json
grep -Eq -- '-0(\.0*)?([,} ]|$)' out/n_negzero/result.json 2>/dev/null && notok negative_zero_printed_as_minus_zero
printf '{"payload_kg": 1, "max_diameter_m": 1e-320, "t_hover_s": 600}' >m/n_tiny_wheelbase.json
rejected tiny_wheelbase_below_range m/n_tiny_wheelbase.json
printf '{"payload_kg": 1, "max_diameter_m": 0.7, "t_hover_s": 1e-320}' >m/n_tiny_time.json
either tiny_hover_time m/n_tiny_time.json
printf '{"payload_kg": 1, "num_rotors": 4.0000000000000001, "t_hover_s": 600}' >m/n_int_rounding.json
either integer_that_rounds_to_integer m/n_int_rounding.json
printf '{"payload_kg": 1, "num_rotors": 1e300, "t_hover_s": 600}' >m/n_int_huge.json
rejected huge_integer m/n_int_huge.json
printf '{"payload_kg": 1, "nominal_cell_count": -2147483649, "t_hover_s": 600}' >m/n_int_min.json
rejected integer_below_int_min m/n_int_min.json
awk 'BEGIN { printf "{\"payload_kg\": 1."; for (i = 0; i < 100000; i++) printf "1"; print "}" }' >m/n_long.json
either number_with_100000_digits m/n_long.json

# ---- strings --------------------------------------------------------------
printf '{"name": "caf\351", %s}' "$good" >m/latin1.json
rejected non_utf8_latin1_in_string m/latin1.json
printf '{"report": {"title": "\355\240\200"}, %s}' "$good" >m/surrogate.json
rejected non_utf8_encoded_surrogate m/surrogate.json
printf '{"report": {"title": "\300\257"}, %s}' "$good" >m/overlong.json
rejected non_utf8_overlong m/overlong.json
printf '{"name": "\\ud800", %s}' "$good" >m/lone_escape.json
either lone_surrogate_escape m/lone_escape.json
printf '{"payload_kg": 1, "payload_kg": 2, "max_diameter_m": 0.7, "t_hover_s": 600}' >m/dup.json
rejected duplicate_key m/dup.json
printf '{"locks": {"is_prop_locked": true}, "locks": {}, %s}' "$good" >m/dup_group.json
rejected duplicate_group m/dup_group.json
awk -v g="$good" 'BEGIN { printf "{\"name\": \""; for (i = 0; i < 200000; i++) printf "x"; print "\", " g "}" }' >m/long_string.json
rejected very_long_string m/long_string.json
awk -v g="$good" 'BEGIN { printf "{\""; for (i = 0; i < 200000; i++) printf "k"; print "\": 1, " g "}" }' >m/long_key.json
rejected very_long_unknown_key m/long_key.json
printf '\357\273\277{%s}\n' "$good" >m/bom.json
either utf8_bom m/bom.json
printf '{"name": "a\\u0000b", %s}' "$good" >m/escaped_nul.json
rejected escaped_nul_in_string m/escaped_nul.json

# ---- paths ----------------------------------------------------------------
mkdir -p m/adir
rejected directory_as_mission_solve m/adir solve
rejected directory_as_mission_check m/adir check
mkdir -p m/dirs/trap.json
rm -rf out
run build -o out m/dirs
if [ "$rc" -ne 2 ] || ! grep -qF 'trap.json' err.txt; then
	notok directory_named_json_inside_a_build_dir "exit $rc"
else
	ok directory_named_json_inside_a_build_dir
fi
rejected missing_file m/nope.json
rejected missing_file_check m/nope.json check
mkfifo m/fifo.json 2>/dev/null && {
	rejected fifo_as_mission m/fifo.json
	rejected fifo_as_mission_check m/fifo.json check
}
[ -c /dev/zero ] && rejected dev_zero_as_mission_check /dev/zero check
[ -c /dev/zero ] && rejected dev_zero_as_mission_solve /dev/zero solve
ln -s loop.json m/loop.json 2>/dev/null && rejected symlink_loop m/loop.json

# `../../etc.json` from a deeper directory: output goes to out/etc only.
printf '{%s}\n' "$good" >cwd/etc.json
before=$(cd "$work" && find . -path ./cwd/a/b/out -prune -o -print | sort)
(cd cwd/a/b && timeout 30 "$bin" build -o out ../../etc.json >/dev/null 2>&1)
rc=$?
after=$(cd "$work" && find . -path ./cwd/a/b/out -prune -o -print | sort)
if [ "$rc" -gt 1 ]; then
	notok dotdot_path_compiles "exit $rc"
elif [ "$before" != "$after" ]; then
	notok dotdot_path_writes_only_under_out "files appeared outside out/"
elif [ ! -f cwd/a/b/out/etc/result.json ]; then
	notok dotdot_path_writes_only_under_out "no out/etc/result.json"
else
	ok dotdot_path_writes_only_under_out
fi

printf '{%s}\n' "$good" >"m/with space.json"
printf '{%s}\n' "$good" >"m/mïssion.json"
printf '{%s}\n' "$good" >"m/-dash.json"
printf '{%s}\n' "$good" >"m/..json"
for f in "m/with space.json" "m/mïssion.json" "m/..json"; do
	rm -rf out
	run build -o out "$f"
	if [ "$rc" -eq 2 ] && grep -qF "$f" err.txt && [ -z "$(find out -type f 2>/dev/null)" ]; then
		ok "odd_name_rejected_clearly: $f"
	elif [ "$rc" -le 1 ] && [ -n "$(find out -name result.json)" ]; then
		ok "odd_name_compiled_inside_out: $f"
	else
		notok "odd_name: $f" "exit $rc"
	fi
done
rm -rf out
run build -o out ./m/-dash.json
if [ "$rc" -le 1 ] && [ -f out/-dash/result.json ]; then ok dash_name_with_path_prefix
else notok dash_name_with_path_prefix "exit $rc"; fi

# Every hostile file above in one build: each is refused on its own, the
# good mission still compiles, and the build ends (exit 2).
rm -rf out
run build -o out m
if [ "$rc" -eq 2 ] && [ -f out/good/result.json ]; then ok one_build_of_every_hostile_file
else notok one_build_of_every_hostile_file "exit $rc"; fi

# Lose nothing: a mission that turns bad keeps its last good output.
rm -rf out
run build -o out m/good.json
cp out/good/result.json good_before.json 2>/dev/null
printf '{"payload_kg": "heavy"}' >m/good.json
run build -o out m/good.json
if [ "$rc" -eq 2 ] && cmp -s out/good/result.json good_before.json; then
	ok rejected_rebuild_keeps_previous_output
else
	notok rejected_rebuild_keeps_previous_output "exit $rc"
fi
printf '{%s}\n' "$good" >m/good.json
if [ -z "$(find out -name '.*tmp*')" ]; then ok no_temporary_files_left
else notok no_temporary_files_left; fi

# Output directory that is a file, and an output folder that is a file.
: >outfile
run build -o outfile m/good.json
if [ "$rc" -ge 2 ] && [ "$rc" -lt 124 ] && grep -q outfile err.txt; then ok output_dir_is_a_file
else notok output_dir_is_a_file "exit $rc"; fi
rm -rf out && mkdir -p out && : >out/good
run build -o out m/good.json
if [ "$rc" -ge 2 ] && [ "$rc" -lt 124 ] && grep -q 'out/good' err.txt; then ok output_folder_is_a_file
else notok output_folder_is_a_file "exit $rc"; fi

# Nothing at all was written outside the scratch directory's out folders:
# the shared data/ and the repository are untouched.
if [ -n "$(cd "$root" && git status --porcelain --untracked-files=all -- data examples 2>/dev/null)" ]; then
	notok repository_untouched
else
	ok repository_untouched
fi

# ---- the file system (issue 25): never write outside, never mix, never hang
# A mission's outputs are one set: whole old or whole new after any fault.
mkdir -p fs
# A feasible mission of its own, so these tests do not hang on an example's
# verdict.
printf '{"name": "File-system probe", "payload_kg": 1.5, "max_diameter_m": 0.7, "t_hover_s": 600, "payload_role": {"type": "delivery"}}\n' >fs/zz_fs25.json
sed 's/"t_hover_s": [0-9]*/"t_hover_s": 95/' fs/zz_fs25.json >fs/new.json
# set_of, stamp_vouches, temps_in.
. "$root/tests/lib_sets.sh"
# one_error PATH: stderr has one error line, naming PATH once, and no
# internal error.
one_error() {
	[ "$(grep -c ': error: ' err.txt)" -eq 1 ] && [ "$(grep -o -F "$1" err.txt | wc -l)" -eq 1 ] &&
	    ! grep -q ': internal error' err.txt
}

# -o "" once wrote /zz_fs25/; the root, however spelled, is refused too.
run build -o "" fs/zz_fs25.json
if [ "$rc" -eq 2 ] && grep -q 'empty' err.txt && [ ! -e /zz_fs25 ]; then ok o_empty_is_refused
else notok o_empty_is_refused "exit $rc"; fi
for o in / // /. /tmp/..; do
	run build -o "$o" fs/zz_fs25.json
	if [ "$rc" -eq 2 ] && grep -q 'root folder' err.txt && [ ! -e /zz_fs25 ]; then
		ok "o_root_is_refused: $o"
	else
		notok "o_root_is_refused: $o" "exit $rc"
	fi
done

# Planted links: out/NAME itself, a file in it, the stamp's old temporary
# name, the lock.  Each is an error naming it (exit 2); nothing outside
# out/ changes.
rm -rf out elsewhere && mkdir -p out elsewhere && ln -s ../elsewhere out/zz_fs25
run build -o out fs/zz_fs25.json
if [ "$rc" -eq 2 ] && grep -q '^out/zz_fs25: error: .*symbolic link' err.txt &&
    [ -z "$(ls -A elsewhere)" ]; then ok linked_output_folder_is_refused
else notok linked_output_folder_is_refused "exit $rc"; fi
printf 'precious\n' >victim
rm -rf out && run build -o out fs/zz_fs25.json
good_set=$(set_of out/zz_fs25)
for planted in out/zz_fs25/..aeroeval-stamp.tmp.12345.0 out/zz_fs25/dossier.pdf out/.zz_fs25.lock; do
	rm -f "$planted" && ln -s "$work/victim" "$planted"
	for force in "" --force; do
		run build $force -o out fs/zz_fs25.json
		if [ "$rc" -eq 2 ] && one_error "$planted" && grep -q 'symbolic link' err.txt &&
		    [ "$(cat victim)" = precious ]; then
			ok "planted_link_is_refused_not_followed: $planted $force"
		else
			notok "planted_link_is_refused_not_followed: $planted $force" "exit $rc"
			sed 's/^/# /' err.txt | head -3
		fi
	done
	rm -f "$planted"
done

# A FIFO where an output goes, or where the folder goes: refused at once,
# whether the build only checks (up to date?) or writes (--force).
rm -rf out && run build -o out fs/zz_fs25.json
rm out/zz_fs25/dossier.pdf && mkfifo out/zz_fs25/dossier.pdf
for force in "" --force; do
	timeout 10 "$bin" build $force -o out fs/zz_fs25.json >out.txt 2>err.txt
	rc=$?
	if [ "$rc" -eq 2 ] && one_error out/zz_fs25/dossier.pdf; then ok "fifo_where_an_output_goes $force"
	else notok "fifo_where_an_output_goes $force" "exit $rc"; fi
done
rm -rf out && mkdir out && mkfifo out/zz_fs25
timeout 10 "$bin" build -o out fs/zz_fs25.json >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 2 ] && one_error out/zz_fs25; then ok fifo_where_the_output_folder_goes
else notok fifo_where_the_output_folder_goes "exit $rc"; fi

# Corrupted outputs are rebuilt, not "up to date": the stamp vouches for
# the SHA-256 of each file.
rm -rf out && run build -o out fs/zz_fs25.json
good_set=$(set_of out/zz_fs25)
for how in empty_dossier garbage_result appended_bom no_stamp; do
	case $how in
	empty_dossier) : >out/zz_fs25/dossier.pdf ;;
	garbage_result) printf 'garbage' >out/zz_fs25/result.json ;;
	appended_bom) printf 'x\n' >>out/zz_fs25/bom.csv ;;
	no_stamp) rm out/zz_fs25/.aeroeval-stamp ;;
	esac
	run build -o out fs/zz_fs25.json
	if [ "$rc" -le 1 ] && grep -q 'zz_fs25.json: compiled' err.txt &&
	    [ "$(set_of out/zz_fs25)" = "$good_set" ] && stamp_vouches out/zz_fs25; then
		ok "corrupted_output_is_rebuilt: $how"
	else
		notok "corrupted_output_is_rebuilt: $how" "exit $rc"
	fi
done
run build -o out fs/zz_fs25.json
if grep -q 'zz_fs25.json: up to date' err.txt; then ok whole_set_is_up_to_date
else notok whole_set_is_up_to_date; fi

# A full disk during a rebuild keeps the whole old set; on a fresh folder
# it leaves nothing.  A small tmpfs where we may mount one, else a
# file-size limit (ulimit -f: EFBIG instead of ENOSPC).
full_disk() {  # full_disk DIR SIZE_KB ARGS...: build into DIR on a full disk
	d=$1 kb=$2
	shift 2
	if [ "$disk" = tmpfs ]; then
		mkdir -p "$d" && mount -t tmpfs -o "size=${kb}k" tmpfs "$d" && mounted="$mounted $work/$d"
		timeout 30 "$bin" "$@" >out.txt 2>err.txt
	else
		mkdir -p "$d"
		(ulimit -f 200; exec timeout 30 "$bin" "$@") >out.txt 2>err.txt
	fi
	rc=$?
}
disk=ulimit
if [ "$(id -u)" -eq 0 ] && mkdir -p probe && mount -t tmpfs -o size=64k tmpfs probe 2>/dev/null; then
	umount probe && disk=tmpfs
fi
full_disk full1 200 build -o full1 fs/zz_fs25.json
if [ "$rc" -eq 2 ] && one_error full1/zz_fs25 && grep -qE 'No space left|File too large' err.txt &&
    [ ! -e full1/zz_fs25 ] && [ -z "$(temps_in full1)" ]; then ok "full_disk_on_a_fresh_folder_leaves_nothing ($disk)"
else notok "full_disk_on_a_fresh_folder_leaves_nothing ($disk)" "exit $rc"; sed 's/^/# /' err.txt | head -3; fi
if [ "$disk" = tmpfs ]; then
	# Room for one set, not two: the old set on disk, the new one fails.
	# The size is measured, so the test holds whatever a set weighs.
	"$bin" build -q -o measure fs/zz_fs25.json 2>/dev/null
	set_kb=$(du -sk measure/zz_fs25 | cut -f1)
	rm -rf measure
	mkdir -p full2 && mount -t tmpfs -o size=$((set_kb * 3 / 2 + 16))k tmpfs full2 && mounted="$mounted $work/full2"
	"$bin" build -q -o full2 fs/zz_fs25.json 2>/dev/null
else
	"$bin" build -q -o full2 fs/zz_fs25.json 2>/dev/null
fi
old_set=$(set_of full2/zz_fs25)
cp fs/new.json fs/zz_fs25.json.new && mv fs/zz_fs25.json fs/zz_fs25.json.old && mv fs/zz_fs25.json.new fs/zz_fs25.json
if [ "$disk" = tmpfs ]; then
	run build -o full2 fs/zz_fs25.json
else
	(ulimit -f 200; exec timeout 30 "$bin" build -o full2 fs/zz_fs25.json) >out.txt 2>err.txt
	rc=$?
fi
mv fs/zz_fs25.json.old fs/zz_fs25.json
if [ "$rc" -eq 2 ] && one_error full2/zz_fs25 && [ -n "$old_set" ] &&
    [ "$(set_of full2/zz_fs25)" = "$old_set" ] && stamp_vouches full2/zz_fs25 &&
    [ -z "$(temps_in full2)" ]; then ok "full_disk_on_a_rebuild_keeps_the_whole_old_set ($disk)"
else notok "full_disk_on_a_rebuild_keeps_the_whole_old_set ($disk)" "exit $rc"; sed 's/^/# /' err.txt | head -3; fi
for m in $mounted; do umount "$m"; done
mounted=""

# Every write failing in turn (ENOSPC, EIO) through the fault hook: exit 2,
# one message, the old set whole, no temporary left.
rm -rf out && run build -o out fs/zz_fs25.json
old_set=$(set_of out/zz_fs25)
for n in 1 2 3 4 1:EIO 3:EIO 4:EDQUOT; do
	AEROEVAL_FAIL_WRITE=$n run build --force -o out fs/zz_fs25.json
	if [ "$rc" -eq 2 ] && one_error out/zz_fs25/ && [ "$(set_of out/zz_fs25)" = "$old_set" ] &&
	    stamp_vouches out/zz_fs25 && [ -z "$(temps_in out)" ]; then ok "failed_write_keeps_the_old_set: $n"
	else notok "failed_write_keeps_the_old_set: $n" "exit $rc"; sed 's/^/# /' err.txt | head -3; fi
done

# A read-only output folder: exit 2 and one message; an up-to-date check
# still works there.
rm -rf out && run build -o out fs/zz_fs25.json
if [ "$(id -u)" -eq 0 ]; then
	mkdir -p ro && mount -t tmpfs tmpfs ro 2>/dev/null && mounted="$work/ro"
	"$bin" build -q -o ro fs/zz_fs25.json 2>/dev/null
	[ -n "$mounted" ] && mount -o remount,ro ro
else
	"$bin" build -q -o ro fs/zz_fs25.json 2>/dev/null
	chmod 555 ro ro/zz_fs25
fi
ro_set=$(set_of ro/zz_fs25)
run build -o ro fs/zz_fs25.json
if [ "$rc" -eq 0 ] && grep -q 'zz_fs25.json: up to date' err.txt; then ok read_only_folder_can_be_up_to_date
else notok read_only_folder_can_be_up_to_date "exit $rc"; fi
run build --force -o ro fs/zz_fs25.json
if [ "$rc" -eq 2 ] && one_error ro/zz_fs25 && grep -qE 'Read-only|Permission denied' err.txt &&
    [ "$(set_of ro/zz_fs25)" = "$ro_set" ]; then ok read_only_folder_is_exit_2_with_one_message
else notok read_only_folder_is_exit_2_with_one_message "exit $rc"; sed 's/^/# /' err.txt | head -3; fi
if [ -n "$mounted" ]; then umount ro; else chmod -R u+w ro 2>/dev/null; fi
mounted=""

# -o naming a file: one message, exit 2.
: >afile
run build -o afile fs/zz_fs25.json
if [ "$rc" -eq 2 ] && one_error afile; then ok o_naming_a_file_is_exit_2
else notok o_naming_a_file_is_exit_2 "exit $rc"; fi

# TMPDIR plays no part (the mission is attached from memory): unusable or
# a file, the build works and the dossier is byte-identical.
for t in /nonexistent "$work/afile"; do
	rm -rf tmpd && TMPDIR=$t run build -o tmpd fs/zz_fs25.json
	if [ "$rc" -eq 0 ] && [ "$(set_of tmpd/zz_fs25)" = "$good_set" ]; then ok "unusable_tmpdir_is_harmless: $t"
	else notok "unusable_tmpdir_is_harmless: $t" "exit $rc"; sed 's/^/# /' err.txt | head -3; fi
done

# Outputs do not depend on the working directory (or the path spelling).
rm -rf cwd1 cwd2 && mkdir -p cwd2/x
"$bin" build -q -o cwd1 fs/zz_fs25.json 2>/dev/null
(cd cwd2/x && "$bin" build -q -o "$work/cwd2/out" "$work/fs/../fs/zz_fs25.json" 2>/dev/null)
if diff -r cwd1/zz_fs25 cwd2/out/zz_fs25 >/dev/null; then ok outputs_identical_across_working_directories
else notok outputs_identical_across_working_directories; fi

# Mission names: 200 characters work; longer ones are refused before the
# solve (they once failed after it, "attachment name must be a bare file name").
n200=$(awk 'BEGIN { while (i++ < 200) printf "n" }')
cp fs/zz_fs25.json "fs/$n200.json"
run build -o names "fs/$n200.json"
if [ "$rc" -eq 0 ] && [ -s "names/$n200/dossier.pdf" ]; then ok name_of_200_characters_compiles
else notok name_of_200_characters_compiles "exit $rc"; sed 's/^/# /' err.txt | head -2; fi
rm "fs/$n200.json"
for len in 201 245; do
	long=$(awk -v n=$len 'BEGIN { while (i++ < n) printf "n" }')
	cp fs/zz_fs25.json "fs/$long.json"
	run build -o names "fs/$long.json"
	if [ "$rc" -eq 2 ] && grep -q 'too long' err.txt && ! grep -q 'attachment' err.txt &&
	    [ ! -e "names/$long" ]; then ok "name_of_${len}_characters_is_refused_up_front"
	else notok "name_of_${len}_characters_is_refused_up_front" "exit $rc"; fi
	rm "fs/$long.json"
done

# Stale temporaries of a killed build go at the next build of that mission
# (only its own, only when their owner is gone), --force included.
sh -c 'exit 0' &
dead=$!
wait $dead
for force in "" --force; do
	rm -rf out && "$bin" build -q -o out fs/zz_fs25.json 2>/dev/null
	mkdir out/.zz_fs25.tmp.$dead.0 out/.zz_fs25.tmp.$$.0 out/.other.tmp.$dead.0
	: >out/.zz_fs25.tmp.$dead.0/dossier.pdf
	run build $force -o out fs/zz_fs25.json
	if [ "$rc" -eq 0 ] && [ ! -e out/.zz_fs25.tmp.$dead.0 ] && [ -d out/.zz_fs25.tmp.$$.0 ] &&
	    [ -d out/.other.tmp.$dead.0 ]; then ok "stale_temporaries_are_removed $force"
	else notok "stale_temporaries_are_removed $force" "exit $rc"; fi
done

# Out of memory anywhere, libharu included, is the one out-of-memory
# error (exit 3), and the previous set stays whole.  T is the number of
# allocations of the whole build (-j 1), found by bisection.
rm -rf oom && "$bin" build -q -j 1 -o oom fs/zz_fs25.json 2>/dev/null
oom_set=$(set_of oom/zz_fs25)
alloc_fails() {
	AEROEVAL_FAIL_ALLOC=$1 timeout 30 "$bin" build -q -j 1 --force -o oom fs/zz_fs25.json >out.txt 2>err.txt
	rc=$?
	[ "$rc" -ne 0 ]
}
lo=1 hi=8388608
while [ $((hi - lo)) -gt 1 ]; do
	mid=$(((lo + hi) / 2))
	if alloc_fails $mid; then lo=$mid; else hi=$mid; fi
done
bad=""
for k in 1 2 3 5 8 13 21 34 55 89 144 233; do
	n=$((lo - lo * k / 256))
	alloc_fails $n
	if [ "$rc" -ne 3 ] || ! grep -q 'out of memory' err.txt || grep -q 'libharu' err.txt ||
	    [ "$(set_of oom/zz_fs25)" != "$oom_set" ]; then bad="$bad $n:$rc"; fi
done
if [ -z "$bad" ] && [ "$lo" -gt 1000 ]; then ok "out_of_memory_is_one_message_and_keeps_the_set ($lo allocations)"
else notok out_of_memory_is_one_message_and_keeps_the_set "failed at$bad (T=$lo)"; fi

# Two builds into one folder at once with different templates: afterwards
# the folder is one build's whole set with a stamp that vouches for it, and
# a build with either template calls it up to date only if it is its own.
rm -rf refa refb
"$bin" build -q -o refa --template "$root/templates/a4.json" fs/zz_fs25.json 2>/dev/null
"$bin" build -q -o refb --template "$root/templates/letter.json" fs/zz_fs25.json 2>/dev/null
set_a=$(set_of refa/zz_fs25) set_b=$(set_of refb/zz_fs25)
bad=""
[ "$set_a" != "$set_b" ] || bad="the templates give one dossier"
for round in 1 2 3 4 5 6 7 8; do
	[ $((round % 3)) -eq 1 ] && rm -rf pair
	"$bin" build -q -o pair --template "$root/templates/a4.json" fs/zz_fs25.json 2>/dev/null &
	p1=$!
	"$bin" build -q -o pair --template "$root/templates/letter.json" fs/zz_fs25.json 2>/dev/null &
	p2=$!
	wait $p1 $p2
	s=$(set_of pair/zz_fs25)
	{ [ "$s" = "$set_a" ] || [ "$s" = "$set_b" ]; } && stamp_vouches pair/zz_fs25 || bad="$bad mixed:$round"
	for t in a4:"$set_a" letter:"$set_b"; do
		run build -o pair --template "$root/templates/${t%%:*}.json" fs/zz_fs25.json
		if grep -q 'zz_fs25.json: up to date' err.txt && [ "$s" != "${t#*:}" ]; then
			bad="$bad false_up_to_date:$round"
		fi
		s=$(set_of pair/zz_fs25)
		[ "$s" = "${t#*:}" ] || bad="$bad not_rebuilt:$round"
	done
done
if [ -z "$bad" ] && [ -z "$(temps_in pair)" ]; then ok concurrent_builds_with_two_templates_stay_consistent
else notok concurrent_builds_with_two_templates_stay_consistent "$bad"; fi

# kill -9 (the whole build, workers too) at random moments while the set
# changes between two versions: the folder always holds one whole set.
# Writes are slowed (AEROEVAL_TEST_WRITE_DELAY_MS) so kills land in them.
export SOURCE_DATE_EPOCH=1700000000
mkdir -p kv/old kv/new kk
cp fs/zz_fs25.json kv/old/zz_fs25.json
cp fs/new.json kv/new/zz_fs25.json
rm -rf krefo krefn kout
"$bin" build -q -o krefo kv/old/zz_fs25.json 2>/dev/null
"$bin" build -q -o krefn kv/new/zz_fs25.json 2>/dev/null
"$bin" build -q -o kout kv/old/zz_fs25.json 2>/dev/null
set_o=$(set_of krefo/zz_fs25) set_n=$(set_of krefn/zz_fs25)
bad="" v=new n_kept=0 n_changed=0 before=$set_o
for round in $(seq 1 20); do
	cp kv/$v/zz_fs25.json kk/zz_fs25.json
	r=$(od -An -N2 -tu2 /dev/urandom | tr -d ' ')
	AEROEVAL_TEST_WRITE_DELAY_MS=30 setsid "$bin" build -q -o kout kk/zz_fs25.json 2>/dev/null &
	p=$!
	sleep "$(awk -v r="$r" 'BEGIN { printf "%.3f", (r % 300) / 1000 }')"
	kill -9 -$p 2>/dev/null
	wait $p 2>/dev/null
	s=$(set_of kout/zz_fs25)
	{ [ "$s" = "$set_o" ] || [ "$s" = "$set_n" ]; } && stamp_vouches kout/zz_fs25 || bad="$bad $round"
	if [ "$s" = "$before" ]; then n_kept=$((n_kept + 1)); else n_changed=$((n_changed + 1)); fi
	before=$s
	# The next round builds the version the folder does not hold.
	[ "$s" = "$set_o" ] && v=new
	[ "$s" = "$set_n" ] && v=old
done
echo "# kill -9 rounds: $n_kept kept the previous set, $n_changed got the next one"
"$bin" build -q -o kout kk/zz_fs25.json 2>/dev/null
if [ -z "$bad" ] && [ -z "$(temps_in kout)" ]; then ok kill_9_leaves_the_whole_old_or_new_set
else notok kill_9_leaves_the_whole_old_or_new_set "mixed in rounds$bad; left: $(temps_in kout | tr '\n' ' ')"; fi
unset SOURCE_DATE_EPOCH

# A catalogue file over 64 MiB is hashed whole: a byte past 64 MiB changes
# catalogue_sha256 and makes the mission rebuild.
mkdir -p bigdb && cp "$root/data/catalog/"*.json bigdb/
{ cat "$root/data/catalog/motors.json"; head -c 67108864 /dev/zero | tr '\0' ' '; printf ' \n'; } >bigdb/motors.json
rm -rf big && run build --db bigdb -o big fs/zz_fs25.json
sha1=$(grep -o '"catalogue_sha256": *"[0-9a-f]*"' big/zz_fs25/result.json 2>/dev/null)
printf '\t\n' | dd of=bigdb/motors.json bs=1 seek=$(($(wc -c <bigdb/motors.json) - 2)) conv=notrunc 2>/dev/null
run build --db bigdb -o big fs/zz_fs25.json
sha2=$(grep -o '"catalogue_sha256": *"[0-9a-f]*"' big/zz_fs25/result.json 2>/dev/null)
if [ "$rc" -le 1 ] && grep -q 'compiled' err.txt && [ -n "$sha1" ] && [ "$sha1" != "$sha2" ]; then
	ok catalogue_over_64_mib_is_hashed_whole
else
	notok catalogue_over_64_mib_is_hashed_whole "exit $rc"
fi
rm -rf bigdb big

# ---- size: linear work, capped output --------------------------------------
# 150 000 unknown keys: reported, counted, and quick (the reader indexes
# every key instead of scanning the ones before it: this took over 60 s).
mkdir -p big
awk 'BEGIN { printf "{"; for (i = 0; i < 150000; i++) printf "%s\"unknown_%d\": 1", (i ? ", " : ""), i; print "}" }' >big/unknown.json
timeout 20 "$bin" check big/unknown.json >out.txt 2>err.txt
rc=$?
if [ "$rc" -ne 2 ]; then notok unknown_keys_150000_checked_quickly "exit $rc"
elif [ "$(wc -l <err.txt)" -gt 51 ]; then notok unknown_keys_150000_checked_quickly "$(wc -l <err.txt) lines"
elif ! grep -q 'note: more errors not shown: 149950' err.txt; then notok unknown_keys_150000_checked_quickly "no summary line"
else ok unknown_keys_150000_checked_quickly; fi
# 100 000 repeats of one key printed 199 998 lines; now the cap and a summary.
awk 'BEGIN { printf "{"; for (i = 0; i < 100000; i++) printf "%s\"payload_kg\": 1", (i ? ", " : ""); print "}" }' >big/dup.json
timeout 20 "$bin" check big/dup.json >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 2 ] && [ "$(wc -l <err.txt)" -le 51 ] && grep -q 'more errors not shown' err.txt; then
	ok duplicate_keys_100000_capped
else
	notok duplicate_keys_100000_capped "exit $rc, $(wc -l <err.txt) lines"
fi

# ---- the other inputs: catalogue, template, cohort --------------------------
# A catalogue directory made from the test fixtures, one file changed.
# db_with FILE SED-SCRIPT
db_with() {
	rm -rf db && mkdir db && cp "$root"/tests/fixtures/catalog/good/*.json db/
	sed "$2" "$root/tests/fixtures/catalog/good/$1" >"db/$1"
}
db_with motors.json 's/x/x/'
rm db/motors.json && mkfifo db/motors.json 2>/dev/null &&
	fails fifo_as_catalogue_file "db/motors.json: error: cannot read file: not a regular file" \
	    build -o out --db db m/good.json
db_with propellers.json 's/"FX18x6.1"/"=HYPERLINK(\\"http:\/\/x.example\\",\\"buy\\")"/'
fails formula_in_catalogue_text "db/propellers.json:2:63: error: propellers[0].part_number: text starts like a spreadsheet formula" \
    build -o out --db db m/good.json
db_with propellers.json "s/\"Fixture\"/\"Fixtur$(printf '\351')\"/"
fails latin1_in_catalogue_text "db/propellers.json:2:37: error: propellers[0].manufacturer: string is not valid UTF-8" \
    solve --db db m/good.json
db_with propellers.json 's/"source": "fixture"/"source": "fix\\u0000ture"/'
fails nul_in_catalogue_text "propellers[0].source: string contains a NUL character" \
    solve --db db m/good.json
db_with escs.json 's/"channels": 4/"channels": 4, "channels": 1/'
fails duplicate_key_in_catalogue "escs[0].channels: duplicate field" solve --db db m/good.json
rm -rf db

# Templates: what they name is judged when they load, before any solve.
mkdir -p tpl
printf '\211PNG\r\n\032\n\0\0\0\rIHDR\0\0\0\020\0\0\0\020\010\002\0\0\0\220\221h6\0\0\0\012IDATxxxxxxxxxx\0\0\0\0' >tpl/logo.png
printf '{"logo": "logo.png"}' >tpl/logo.json
fails corrupt_png_logo_at_template_load "tpl/logo.json:1:10: error: logo: not a usable PNG image: tpl/logo.png" \
    build -o out --template tpl/logo.json m/good.json
printf '{"fonts": {"regular": "logo.json"}}' >tpl/font.json
fails non_font_at_template_load "tpl/font.json:1:23: error: fonts.regular: not a usable TrueType font: tpl/logo.json" \
    build -o out --template tpl/font.json m/good.json
printf '{"fonts": {"bold": "/dev/zero"}}' >tpl/zero.json
fails dev_zero_as_font "fonts.bold: cannot read file: /dev/zero: not a regular file" \
    build -o out --template tpl/zero.json m/good.json
[ -c /dev/zero ] && fails dev_zero_as_template "/dev/zero: error: cannot read file: not a regular file" \
    build -o out --template /dev/zero m/good.json
fails directory_as_template "tpl: error: cannot read file: not a regular file" \
    sensitivity -o out --template tpl m/good.json
mkdir -p emptydir
fails empty_directory_build_names_it "emptydir: error: no mission file (*.json) in this directory" \
    build -o out emptydir

# Cohorts: valid JSON out whatever the names, a clear end when nothing validates.
# A rejected row is an error: the report covers the others, exit 2.
{ cat "$root/tests/fixtures/validate/tiny.csv"; printf 'Caf\351 racer,0.6,4,0,220,5,5,MicroAIO,inspection,0.1,\n'; } >latin1.csv
run validate --json latin1.csv
if [ "$rc" -ne 2 ]; then
	notok validate_json_with_a_latin1_row "exit $rc"
elif ! grep -q 'latin1.csv:[0-9]*: error: name: not valid UTF-8' err.txt; then
	notok validate_json_with_a_latin1_row "the row is not named"
elif ! iconv -f UTF-8 -t UTF-8 out.txt >/dev/null 2>&1; then
	notok validate_json_with_a_latin1_row "stdout is not UTF-8"
elif [ "$(grep -c '^  "rows":' out.txt)" -ne 1 ] || ! grep -q '^  "n_rows":' out.txt; then
	notok validate_json_with_a_latin1_row "a key appears twice"
else
	ok validate_json_with_a_latin1_row
fi
printf 'name,takeoff_mass_kg\nA,2.5\nB,3.1\n' >nothing.csv
fails validate_with_no_usable_row "nothing.csv: error: no row could be validated (2 rows; 2 skipped: payload of the takeoff figure unknown)" \
    validate nothing.csv
AEROEVAL_PROGRESS_S=0 timeout 120 "$bin" calibrate "$root/tests/fixtures/cohort/calibration.csv" >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 0 ] && grep -q '^calibrate: fit on [0-9]* rows, [0-9]* sized, [0-9]* solves' err.txt \
    && grep -q '^calibrate: leave-one-out [0-9]* of [0-9]*, [0-9]* solves' err.txt; then
	ok calibrate_shows_progress
else
	notok calibrate_shows_progress "exit $rc"
fi

# ---- valgrind: a whole build of one example, no memory error, no leak -----
# (skipped where valgrind is not installed; ASan covers the unit suite)
if command -v valgrind >/dev/null 2>&1; then
	rm -rf out
	timeout 300 valgrind -q --leak-check=full --errors-for-leak-kinds=definite \
	    --error-exitcode=99 "$bin" build -o out "$root/examples/delivery_quad.json" \
	    >out.txt 2>err.txt
	rc=$?
	if [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ]; then ok valgrind_build_clean
	else notok valgrind_build_clean "exit $rc"; grep '==' err.txt | head -20 | sed 's/^/# /'; fi
fi
