#!/bin/sh
# The folders of src/ are layers; every include must point down (or stay in
# its own folder), physics must not see any I/O library, and no two files
# may include each other, directly or round a longer circle.
# Prints "ok NAME" / "not ok NAME" lines; run by tests/run_all.sh.
cd "$(dirname "$0")/.." || exit 1

# What each layer may include besides itself.
allowed() {
	case $1 in
	util)    echo "" ;;
	core)    echo "util" ;;
	physics) echo "util core" ;;
	sizing)  echo "util core physics" ;;
	parts)   echo "util core physics sizing" ;;
	engine)  echo "util core physics sizing parts" ;;
	study)   echo "util core physics sizing parts engine input output" ;;
	input)   echo "util core" ;;
	output)  echo "util core" ;;
	cli)     echo "util core physics sizing parts engine study input output" ;;
	*)       echo "?" ;;
	esac
}

bad=0
for f in src/*/*.c src/*/*.h; do
	layer=$(basename "$(dirname "$f")")
	ok=$(allowed "$layer")
	for inc in $(sed -n 's/^#include "\([a-z]*\)\/[a-z_0-9]*\.h".*/\1/p' "$f" | sort -u); do
		[ "$inc" = "$layer" ] && continue
		case " $ok " in *" $inc "*) ;; *)
			echo "check-layers: $f ($layer) includes $inc/"
			bad=1 ;;
		esac
	done
	if grep -q '^#include "[a-z_0-9]*\.h"' "$f"; then
		echo "check-layers: $f includes a header without its folder"
		bad=1
	fi
done
[ $bad -eq 0 ] && echo "ok layers_include_only_downward" || echo "not ok layers_include_only_downward"

# Physics is pure: no JSON, PDF, cairo or file handling.
if grep -l -E '#include *<(cjson/|cJSON|hpdf|cairo|stdio\.h|fcntl\.h|unistd\.h|dirent\.h)' \
    src/physics/*.[ch] 2>/dev/null; then
	echo "not ok physics_includes_no_io_header"
else
	echo "ok physics_includes_no_io_header"
fi

# No include cycles between modules (a module is x.c with x.h and its
# internal header x_int.h): tsort reports a loop in the module graph.
pairs=$(for f in src/*/*.[ch]; do
	me=${f#src/}
	me=${me%.[ch]}
	me=${me%_int}
	for inc in $(sed -n 's/^#include "\([a-z]*\/[a-z_0-9]*\)\.h".*/\1/p' "$f"); do
		inc=${inc%_int}
		[ "$inc" = "$me" ] || echo "$me $inc"
	done
done)
if echo "$pairs" | tsort >/dev/null 2>"${TMPDIR:-/tmp}/aeroeval-tsort.$$"; then
	echo "ok no_include_cycles"
else
	sed 's/^/check-layers: /' "${TMPDIR:-/tmp}/aeroeval-tsort.$$"
	echo "not ok no_include_cycles"
fi
rm -f "${TMPDIR:-/tmp}/aeroeval-tsort.$$"
