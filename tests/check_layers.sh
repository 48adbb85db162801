#!/bin/sh
# The folders of src/ are layers, lowest first in the Makefile's LAYERS;
# every include must point down (or stay in its own folder), physics must
# not see any I/O library, and no two files may include each other,
# directly or round a longer circle.
# Prints "ok NAME" / "not ok NAME" lines; run by tests/run_all.sh.
# One awk pass reads every include of every source file.
cd "$(dirname "$0")/.." || exit 1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# What each layer may include besides itself.  Every folder of src/ is a
# layer of this table, and each may include only layers that the
# Makefile's LAYERS (lowest first) lists before it.
layers=$(awk '/^LAYERS *:=/ { on = 1; sub(/^LAYERS *:=/, "") }
	on { more = sub(/\\$/, ""); printf "%s ", $0; if (!more) exit }' Makefile)
awk -v layers="$layers" '
BEGIN {
	ok["util"] = ""
	ok["diag"] = "util"
	ok["spec"] = "util"
	ok["catalog"] = "util"
	ok["template"] = "util"
	ok["result"] = "util spec"
	ok["physics"] = "util spec result"
	ok["sizing"] = "util spec result physics"
	ok["parts"] = "util spec catalog result physics sizing"
	ok["engine"] = "util spec catalog result physics sizing parts"
	ok["input"] = "util diag spec catalog template result"
	ok["formats"] = "util spec catalog result"
	ok["fs"] = "util formats"
	ok["pdf"] = "util spec catalog template result formats"
	ok["study"] = "util spec catalog template result physics sizing parts engine input pdf"
	ok["cli"] = "util diag spec catalog template result physics sizing parts engine input formats fs pdf study"
	n_layers = split(layers, order, " ")
	for (i = 1; i <= n_layers; i++) {
		pos[order[i]] = i
		if (!(order[i] in ok)) {
			print "check-layers: the Makefile lists " order[i] ", which the table lacks" >"/dev/stderr"
			table_bad = 1
		}
	}
	for (l in ok) {
		if (!(l in pos)) {
			print "check-layers: the table has " l ", which the Makefile does not list" >"/dev/stderr"
			table_bad = 1
			continue
		}
		n = split(ok[l], below, " ")
		for (i = 1; i <= n; i++)
			if (!(below[i] in pos) || pos[below[i]] >= pos[l]) {
				print "check-layers: " l " may include " below[i] ", not listed before it in the Makefile" >"/dev/stderr"
				table_bad = 1
			}
	}
}
FNR == 1 {
	n = split(FILENAME, part, "/")
	layer = part[2]
	me = part[2] "/" part[3]
	if (!(layer in ok) && !(layer in unknown)) {
		print "check-layers: src/" layer " is no layer of the table" >"/dev/stderr"
		unknown[layer] = 1
		table_bad = 1
	}
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
	print table_bad ? "not ok layer_table_matches_makefile" : "ok layer_table_matches_makefile" >"/dev/stderr"
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
