#!/bin/sh
# cli_report.sh — checks the dossiers written by build/tests/test_report with
# the poppler tools: every section title is in the text, the verdict on the
# cover, the mission file attached byte for byte, fonts embedded, an outline.
# Prints "ok NAME" / "not ok NAME" lines.
build=$(dirname "${AEROEVAL:-build/aeroeval}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Its own copies, so that it never reads one a test program is writing.
AEROEVAL_TEST_OUT="$tmp" "$build/tests/test_report" >/dev/null 2>&1
ok_pdf="$tmp/dossier_sar_imaging_quad.pdf"
bad_pdf="$tmp/dossier_infeasible_compact_lifter.pdf"

check() {
	name=$1
	shift
	if "$@" >/dev/null 2>&1; then echo "ok $name"; else echo "not ok $name"; fi
}

pdftotext "$ok_pdf" "$tmp/ok.txt" 2>/dev/null
pdftotext "$bad_pdf" "$tmp/bad.txt" 2>/dev/null
has() { grep -qF -- "$2" "$tmp/$1.txt"; }

check report_pdf_exists test -s "$ok_pdf"
# The default template's titles, numbered in order after the cover.
n=1
for title in "Executive summary" "Design rationale" "Mass budget" "Mission and energy" \
	"Thermal and electrical traces" "Structure and resonance" "Propulsion selection" \
	"Convergence" "Endurance explorer" "Bill of materials" "Checks" "Appendix"; do
	slug=$(echo "$title" | tr 'A-Z ' 'a-z_')
	check "report_has_section_$slug" grep -Eq "^$n +$title\$" "$tmp/ok.txt"
	n=$((n + 1))
done
check report_feasible_cover has ok "FEASIBLE"
check report_infeasible_cover_says_so_first sh -c "grep -qF 'NOT FEASIBLE AS BUILT' '$tmp/bad.txt' || grep -qF 'NOT BUILDABLE' '$tmp/bad.txt'"
check report_infeasible_names_the_fix has bad "Fix: "
check report_has_regulatory_class has ok "Part 107"
check report_has_runaway_line has ok "60 °C runaway limit"
check report_has_every_mission_field has ok "aerodynamic_overrides.propeller_class"
check report_has_page_numbers grep -Eq "^1 ?/ ?[0-9]+$" "$tmp/ok.txt"
check report_no_sensitivity_by_default sh -c "! grep -qF 'aeroeval sensitivity' '$tmp/ok.txt'"
check report_attachment_listed sh -c "pdfdetach -list '$ok_pdf' | grep -q '1: sar_imaging_quad.json'"
check report_attachment_identical sh -c "cd '$tmp' && pdfdetach -save 1 -o att.json '$ok_pdf' && cmp att.json '$PWD/examples/sar_imaging_quad.json'"
check report_fonts_embedded sh -c "pdffonts '$ok_pdf' | awk 'NR > 2 && \$(NF-4) != \"yes\" { bad = 1 } END { exit bad }'"
check report_has_outline grep -aq "/Outlines" "$ok_pdf"
