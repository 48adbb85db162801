#!/bin/sh
# The folders of src/ are layers; every include must point down (or stay in
# its own folder), physics must not see any I/O library, and no two files
# may include each other, directly or round a longer circle.
# Prints "ok NAME" / "not ok NAME" lines; run by tests/run_all.sh.
# One awk pass reads every include of every source file.
cd "$(dirname "$0")/.." || exit 1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# What each layer may include besides itself.
awk '
BEGIN {
	ok["util"] = ""
	ok["core"] = "util"
	ok["physics"] = "util core"
	ok["sizing"] = "util core physics"
	ok["parts"] = "util core physics sizing"
	ok["engine"] = "util core physics sizing parts"
	ok["study"] = "util core physics sizing parts engine input output"
	ok["input"] = "util core"
	ok["output"] = "util core"
	ok["cli"] = "util core physics sizing parts engine study input output"
}
FNR == 1 {
	n = split(FILENAME, part, "/")
	layer = part[2]
	me = part[2] "/" part[3]
	sub(/\.[ch]$/, "", me)
	sub(/_int$/, "", me)     # x_int.h belongs to module x
}
/^#include "/ {
	inc = $0
	sub(/^#include "/, "", inc)
	sub(/".*/, "", inc)
	if (inc !~ /\//) {
		print "check-layers: " FILENAME " includes a header without its folder" >"/dev/stderr"
		bad = 1
		next
	}
	split(inc, ip, "/")
	if (ip[1] != layer && index(" " ok[layer] " ", " " ip[1] " ") == 0) {
		print "check-layers: " FILENAME " (" layer ") includes " ip[1] "/" >"/dev/stderr"
		bad = 1
	}
	mod = inc
	sub(/\.h$/, "", mod)
	sub(/_int$/, "", mod)
	if (mod != me)
		print me, mod      # the module graph, for tsort
}
layer == "physics" && /^#include *<(cjson\/|cJSON|hpdf|cairo|stdio\.h|fcntl\.h|unistd\.h|dirent\.h)/ {
	print "check-layers: " FILENAME " (physics) includes an I/O header" >"/dev/stderr"
	io = 1
}
END {
	print bad ? "not ok layers_include_only_downward" : "ok layers_include_only_downward" >"/dev/stderr"
	print io ? "not ok physics_includes_no_io_header" : "ok physics_includes_no_io_header" >"/dev/stderr"
}' src/*/*.c src/*/*.h 2>"$tmp/report" >"$tmp/pairs"
cat "$tmp/report"

# No include cycles between modules (a module is x.c with x.h and its
# internal header x_int.h): tsort reports a loop in the module graph.
if tsort "$tmp/pairs" >/dev/null 2>"$tmp/tsort"; then
	echo "ok no_include_cycles"
else
	sed 's/^/check-layers: /' "$tmp/tsort"
	echo "not ok no_include_cycles"
fi
