#!/bin/sh
# The folders of src/ are layers, lowest first in the Makefile's LAYERS;
# every include must point down (or stay in its own folder), physics must
# not see any I/O library, and no two files may include each other, or
# call each other, directly or round a longer circle.
# Prints "ok NAME" / "not ok NAME" lines; run by tests/run_all.sh.
# One awk pass reads every include of every source file, a second every
# definition and use of a function or variable.
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
	ok["tools"] = "util diag spec catalog template result physics sizing parts engine input formats fs pdf study cli"
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

# No circles of calls between files either: a file uses another when it
# names a function or variable that the other defines (not static).  The
# include graph cannot show this where a header declares what another file
# defines (a shared x_int.h), so the report's driver and its sections once
# called each other through report_int.h while every include pointed one
# way.  Read from the source text (comments, strings, members and struct
# tags left out), so it needs no build; a call made inside a header's
# macro is not seen.  Two passes over the same files: the first finds the
# definitions, the second the uses.
set -- src/*/*.c
awk -v first_file="$1" -v q="'" '
BEGIN { pass = 1 }
function clean(s,    out, c, i, n) {
	out = ""
	n = length(s)
	for (i = 1; i <= n; i++) {
		c = substr(s, i, 1)
		if (incomment) {
			if (c == "*" && substr(s, i + 1, 1) == "/") { incomment = 0; i++ }
			continue
		}
		if (quote != "") {
			if (c == "\\") { i++; continue }
			if (c == quote) quote = ""
			continue
		}
		if (c == "/" && substr(s, i + 1, 1) == "*") { incomment = 1; i++; continue }
		if (c == "/" && substr(s, i + 1, 1) == "/") break
		if (c == "\"" || c == q) { quote = c; out = out " "; continue }
		out = out c
	}
	return out
}
FNR == 1 {
	if (FILENAME == first_file && seen_first) pass = 2
	if (FILENAME == first_file) seen_first = 1
	file = FILENAME
	sub(/^src\//, "", file)
	sub(/\.c$/, "", file)
	depth = 0; incomment = 0; quote = ""; prev = ""; cont = 0
}
{
	line = clean($0)
	if (cont || line ~ /^[ \t]*#/) {        # preprocessor, with continuations
		cont = line ~ /\\[ \t]*$/
		next
	}
	if (pass == 1 && depth == 0 && line !~ /^extern[ \t]/ && line !~ /(^|[ \t])typedef[ \t]/) {
		name = ""
		if (match(line, /^[A-Za-z_][A-Za-z0-9_]*\(/))
			name = substr(line, 1, RLENGTH - 1)    # the name under its type
		else if (match(line, /^[A-Za-z_][A-Za-z0-9_ \t*]*[ \t*][A-Za-z_][A-Za-z0-9_]*\(/) && \
		         line !~ /;[ \t]*$/) {
			name = substr(line, 1, RLENGTH - 1)    # type and name on one line
			sub(/.*[ \t*]/, "", name)
		} else if (line !~ /^(struct|union|enum)[ \t]+[A-Za-z_0-9]+[ \t]*[;{]/ && \
		         match(line, /[A-Za-z_][A-Za-z0-9_]*[ \t]*(\[[^]]*\][ \t]*)*(=|;)/) && \
		         line ~ /^[A-Za-z_]/ && substr(line, 1, RSTART - 1) ~ /[A-Za-z_0-9*][ \t*]*$/) {
			name = substr(line, RSTART, RLENGTH)   # a variable
			sub(/[ \t\[=;].*/, "", name)
		}
		if (name != "" && name !~ /^_/) {
			if (line ~ /^static[ \t]/ || prev ~ /^static[ \t]/)
				local[file, name] = 1
			else
				def[name] = file
		}
	}
	if (pass == 2) {
		t = line        # a member or a struct tag of that name is no use
		gsub(/(\.|->)[ \t]*[A-Za-z_][A-Za-z0-9_]*/, " ", t)
		gsub(/(struct|union|enum)[ \t]+[A-Za-z_][A-Za-z0-9_]*/, " ", t)
		n = split(t, tok, /[^A-Za-z0-9_]+/)
		for (i = 1; i <= n; i++)
			if ((tok[i] in def) && def[tok[i]] != file && !((file, tok[i]) in local))
				edge[file " " def[tok[i]]] = 1
	}
	t = line
	depth += gsub(/\{/, "", t)
	t = line
	depth -= gsub(/\}/, "", t)
	if (line ~ /[^ \t]/) prev = line
}
END {
	for (e in edge) print e
}
' "$@" "$@" >"$tmp/calls"
if tsort "$tmp/calls" >/dev/null 2>"$tmp/tsort"; then
	echo "ok no_call_cycles"
else
	sed 's/^/check-layers: /' "$tmp/tsort"
	echo "not ok no_call_cycles"
fi
