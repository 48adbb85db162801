#!/bin/sh
# cli_doc.sh — checks the demo dossier written by build/tests/test_doc with
# the poppler tools: searchable figure text, UTF-8 symbols, embedded fonts,
# the attachment (bare name, identical bytes), the outline, the contents,
# clean text extraction, numbers kept whole and web addresses as links.
# Prints "ok NAME" / "not ok NAME" lines.
build=$(dirname "${AEROEVAL:-build/aeroeval}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Its own copy, so that it never reads one a test program is writing.
AEROEVAL_TEST_OUT="$tmp" "$build/tests/test_doc" >/dev/null 2>&1
pdf="$tmp/doc_demo.pdf"

check() {
	name=$1
	shift
	if "$@" >/dev/null 2>&1; then echo "ok $name"; else echo "not ok $name"; fi
}

pdftotext "$pdf" "$tmp/text.txt" 2>/dev/null
pdftotext -layout "$pdf" "$tmp/layout.txt" 2>/dev/null
has() { grep -qF -- "$1" "$tmp/text.txt"; }
check doc_pdf_exists test -s "$pdf"
check doc_text_has_figure_caption has "Figure 1: Power required vs forward speed"
check doc_text_has_axis_title has "Forward speed (m/s)"
check doc_text_has_reference_label has "60 °C runaway limit"
check doc_text_has_tick_label has "1200"
check doc_text_has_legend has "Custom (spray role)"
check doc_text_has_band_legend has "±25 %"
check doc_text_has_utf8_symbols has "°C±µΩ²≤"
check doc_text_has_page_numbers grep -Eq "^9 ?/ ?9$" "$tmp/text.txt"
check doc_text_has_running_header has "Design dossier — agri-sprayer"
check doc_text_has_repeated_table_header sh -c "[ \$(grep -c '^Price (USD)' '$tmp/text.txt') -ge 3 ]"
pdfdetach -list "$pdf" >"$tmp/list.txt" 2>/dev/null
check doc_attachment_listed_by_bare_name grep -q "^1: agri-sprayer.json$" "$tmp/list.txt"
check doc_attachment_extracts sh -c "cd '$tmp' && pdfdetach -saveall '$pdf' && grep -q '\"payload_kg\": 10.0' agri-sprayer.json"
pdffonts "$pdf" >"$tmp/fonts.txt" 2>/dev/null
check doc_fonts_embedded sh -c "grep -q 'DejaVuSans,Book' '$tmp/fonts.txt' && ! awk 'NR>2 && \$(NF-4)!=\"yes\"' '$tmp/fonts.txt' | grep -q ."
pdfinfo "$pdf" >"$tmp/info.txt" 2>/dev/null
check doc_info_creator grep -q "^Creator: *aeroeval " "$tmp/info.txt"
check doc_info_date_from_caller grep -q "^CreationDate: *Sun Nov 22 00:00:00 2026" "$tmp/info.txt"
check doc_not_encrypted grep -q "^Encrypted: *no" "$tmp/info.txt"
check doc_has_outline grep -aq "/Outlines" "$pdf"
# Text extraction without poppler's ToUnicode warning (the maps are
# rewritten as bfrange identity maps: doc.c fix_to_unicode).
check doc_text_extracts_without_tounicode_warning sh -c "! pdftotext '$pdf' - 2>&1 >/dev/null | grep -q ."
# The contents: every level-1 heading after it, with its page, linked.
check doc_contents_lists_headings_with_pages sh -c "grep -Eq '^2 Figures +[0-9]+\$' '$tmp/layout.txt' &&
	grep -Eq '^3 Bill of materials +[0-9]+\$' '$tmp/layout.txt'"
check doc_contents_entries_are_links grep -aq "/Subtype /Link" "$pdf"
# Numbers in narrow columns: never cut, never parted from their unit.
check doc_table_keeps_numbers_whole awk -f tests/split_numbers.awk "$tmp/layout.txt"
check doc_table_keeps_number_with_unit grep -q "3340.25 kg" "$tmp/layout.txt"
check doc_table_keeps_bound_with_price grep -q "≥ 1199.96" "$tmp/layout.txt"
# A web address wraps only after '/' or '-', and is a link.
check doc_url_wraps_at_slash_or_hyphen sh -c "grep -o 'https://example[^ ]*' '$tmp/layout.txt' | grep -q '[/-]\$' &&
	! grep -o 'https://example[^ ]*' '$tmp/layout.txt' | grep -Eqv '([/-]|motor-[0-9])\$'"
check doc_url_is_a_link grep -aq '/URI (https:\\057\\057example.com' "$pdf"
