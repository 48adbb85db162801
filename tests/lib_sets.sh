# lib_sets.sh — shell helpers the whole-compiler tests share about a
# mission's output folder; sourced (`. tests/lib_sets.sh`), never run.

# set_of DIR: the digests of a set's three outputs, "" if one is missing.
set_of() {
	[ -f "$1/bom.csv" ] && [ -f "$1/result.json" ] && [ -f "$1/dossier.pdf" ] &&
	    sha256sum "$1/bom.csv" "$1/result.json" "$1/dossier.pdf" | cut -c1-64 | tr '\n' ' '
}

# stamp_vouches DIR: every "sha256 HEX FILE" line of the stamp holds.
stamp_vouches() {
	[ -f "$1/.aeroeval-stamp" ] || return 1
	grep '^sha256 ' "$1/.aeroeval-stamp" | while read -r _ h f; do
		[ "$(sha256sum <"$1/$f" | cut -c1-64)" = "$h" ] || echo bad
	done | grep -q bad && return 1
	return 0
}

# temps_in DIR: hidden entries left beside the output folders (the
# table's stamp, cli_summary.h, is no leftover).
temps_in() { ls -A "$1" | grep '^\.' | grep -vx '\.aeroeval-index-stamp' ; }
