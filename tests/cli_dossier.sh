#!/bin/sh
# cli_dossier.sh — every example's dossier read as its client reads it
# (pdftotext), against its own result.json and bom_totals.csv: one design of
# record on the cover (its MTOW is the bill of materials plus the payload,
# its regulatory class follows that mass), nothing from the catalogue's
# provenance notes, no price of an unknown part printed as zero, no number
# cut across two lines, no "auto" field printed as 0, the J-score explained
# wherever it is shown, downwash only where the role limits it, the
# document control and contents after the cover, clean text extraction;
# and a design whose parts do not close, or fail a check, says so first.
# Prints "ok NAME" / "not ok NAME" lines.
AE=${AEROEVAL:-build/aeroeval}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

ok() { echo "ok $1"; }
notok() { echo "not ok $1${2:+ # $2}"; }
check() {
	name=$1
	shift
	if "$@" >/dev/null 2>&1; then ok "$name"; else notok "$name"; fi
}

# The split-number detector itself: a number cut in a table cell is found,
# a column of lone figure labels is not.
printf 'Peak power (W)        3340\n                      .2\n' >"$T/cut1.txt"
printf 'Energy (Wh)   1206\n                 1\n' >"$T/cut2.txt"
printf '   153\n    21\n    19        177\n    16\n' >"$T/labels.txt"
check split_numbers_finds_a_cut_decimal sh -c "! awk -f tests/split_numbers.awk '$T/cut1.txt'"
check split_numbers_finds_a_cut_integer sh -c "! awk -f tests/split_numbers.awk '$T/cut2.txt'"
check split_numbers_ignores_figure_labels awk -f tests/split_numbers.awk "$T/labels.txt"

SOURCE_DATE_EPOCH=1767225600 "$AE" build -q -o "$T/out" examples/ 2>"$T/err"
if [ $? -gt 1 ]; then
	cat "$T/err"
	notok dossier_build_of_examples
	exit 1
fi

# The fields whose 0 means "automatic", as the field table says (schema).
"$AE" schema | awk '/^  [a-z_.]+  \(/ { f = $1 } /0 = automatic/ { print f }' >"$T/auto_fields"
check dossier_schema_names_auto_fields test -s "$T/auto_fields"

# The first status callout of a cover text: FEASIBLE, NOT FEASIBLE AS BUILT
# NOT BUILDABLE or BEYOND REACH (whichever line comes first).
first_status() {
	grep -m 1 -E '^ *(FEASIBLE|NOT FEASIBLE AS BUILT|NOT BUILDABLE|BEYOND REACH)$' "$1" | sed 's/^ *//'
}

# The bill of materials' mass in kg, parts plus payload, from
# bom_totals.csv: its one record's parts_mass_g and payload_mass_g.
bom_plus_payload_kg() {
	awk -F, 'NR == 2 { printf "%.4f\n", ($1 + $2) / 1000 }' "$1"
}

for f in examples/*.json; do
	n=$(basename "$f" .json)
	d="$T/out/$n"
	pdf="$d/dossier.pdf"
	# poppler reads each dossier once (about 0.4 s a dossier): its pages
	# are split out of the whole text at the form feeds, and what pdfinfo
	# says is kept.
	pdftotext -layout "$pdf" "$d/all.txt" 2>"$d/warn.txt"
	awk 'BEGIN { RS = "\f" } NR == 1' "$d/all.txt" >"$d/cover.txt"
	awk 'BEGIN { RS = "\f" } NR == 2' "$d/all.txt" >"$d/page2.txt"
	pdfinfo -meta "$pdf" >"$d/meta.txt" 2>/dev/null
	pdfinfo "$pdf" >"$d/info.txt" 2>/dev/null

	check "dossier_${n}_text_extracts_without_tounicode_warning" \
		sh -c "[ -s '$d/cover.txt' ] && [ ! -s '$d/warn.txt' ]"

	# PDF/A-3b as poppler reads it (tests/test_pdfa.c checks the objects):
	# the XMP stream declares it, every font is embedded, no encryption,
	# the mission is attached.
	check "dossier_${n}_declares_pdfa_3b" sh -c "grep -q '<pdfaid:part>3</pdfaid:part>' \
		'$d/meta.txt' && grep -q '<pdfaid:conformance>B</pdfaid:conformance>' '$d/meta.txt'"
	check "dossier_${n}_has_metadata_and_no_encryption" sh -c "grep -q \
		'^Metadata Stream: *yes' '$d/info.txt' && grep -q '^Encrypted: *no' '$d/info.txt'"
	check "dossier_${n}_embeds_every_font" sh -c "pdffonts '$pdf' | awk 'NR > 2 { n++; \
		if (\$(NF - 4) != \"yes\") bad++ } END { exit !(n > 0 && bad == 0) }'"
	check "dossier_${n}_attaches_its_mission" sh -c "pdfdetach -list '$pdf' | grep -q '$n.json'"

	# One design of record: the cover's MTOW is the BOM plus the payload.
	# A design the parts do not close has no BOM aircraft: its cover mass
	# is the continuous design's, which result.json's top level names.
	cover=$(awk '/^Takeoff mass \(MTOW\)/ { print $4; exit }' "$d/cover.txt")
	bom=$(bom_plus_payload_kg "$d/bom_totals.csv")
	rec=$(sed -n 's/^  "takeoff_mass_kg": *\([0-9.e+-]*\),$/\1/p' "$d/result.json" | head -n 1)
	grep -q '"buildable": false' "$d/result.json" && bom=$rec
	if [ -n "$cover" ] && awk -v c="$cover" -v b="$bom" -v r="$rec" \
		'BEGIN { d1 = c - b; d2 = c - r; exit !(d1 < 0.0011 && d1 > -0.0011 && d2 < 0.0006 && d2 > -0.0006) }'; then
		ok "dossier_${n}_cover_mtow_is_bom_plus_payload"
	else
		notok "dossier_${n}_cover_mtow_is_bom_plus_payload" "cover $cover kg, BOM + payload $bom kg, record $rec kg"
	fi

	# The regulatory class follows the mass of record.
	eu=$(sed -n 's/^ *"eu_open_category": *"\([^"]*\)".*/\1/p' "$d/result.json" | head -n 1)
	[ "$eu" = specific ] && eu="specific category"
	check "dossier_${n}_regulatory_class_follows_the_record" \
		grep -Eq "^Regulatory class by mass +EU $eu," "$d/cover.txt"

	# Client-safe: the catalogue's provenance notes stay in the catalogue.
	check "dossier_${n}_has_no_catalogue_notes" \
		sh -c "! grep -Eiq 'recalled|secondary copy|screening|SwRI|confidence|re-read|transcri|note:' '$d/all.txt'"

	# An unknown price is never printed as zero.
	check "dossier_${n}_prints_no_zero_price" \
		sh -c "! grep -Eq '(^|[^0-9.])0\.00 ?USD|USD,? 0\.00' '$d/all.txt' &&
		       ! awk '/^[0-9]+ +Bill of materials$/ { on = 1 } /^[0-9]+ +Checks$/ { on = 0 }
		              on && / 0\.00( |$)/ { bad = 1 } END { exit !bad }' '$d/all.txt'"

	check "dossier_${n}_splits_no_number_across_lines" awk -f tests/split_numbers.awk "$d/all.txt"

	# "auto", never 0, for a field whose 0 means automatic.
	zeros=""
	while read -r field; do
		grep -Eq "^ *$field +0( |\$)" "$d/all.txt" && zeros="$zeros $field"
	done <"$T/auto_fields"
	if [ -z "$zeros" ]; then ok "dossier_${n}_prints_auto_not_zero"
	else notok "dossier_${n}_prints_auto_not_zero" "$zeros"; fi

	check "dossier_${n}_explains_j_where_shown" \
		sh -c "! grep -Eq 'J \(%\)|J = ' '$d/all.txt' ||
		       grep -q 'J is the estimated takeoff-mass penalty' '$d/all.txt'"

	# Downwash is checked where the role limits it, and only there.
	if grep -q '"name": *"Downwash' "$d/result.json"; then
		check "dossier_${n}_checks_downwash_where_limited" \
			grep -Eq "Downwash \(crop damage and spray" "$d/all.txt"
	else
		check "dossier_${n}_shows_no_downwash_check_without_a_limit" \
			sh -c "! grep -Eq 'Downwash \(|Downwash,' '$d/all.txt'"
	fi

	# The cover's gap sentence says the right way round (+ heavier,
	# − lighter), names the mass lines that carry the gap and closes.
	if grep -q '"buildable": true' "$d/result.json"; then
		check "dossier_${n}_cover_gap_names_its_lines" \
			awk '/^What the physics/ { on = 1 } on { t = t " " $0 } on && /^$/ { on = 0 }
			     END { ok = (t ~ /\(\+[0-9.]+ %\) heavier/ || t ~ /\(−[0-9.]+ %\) lighter/) &&
			               t ~ /lines that differ most: [a-zA-Z ]+ (\+|−)[0-9.]+ kg/ &&
			               t ~ /every line\)\. *$/
			           exit !ok }' "$d/cover.txt"
	fi

	# The verdict's sentences end before the next begins.
	check "dossier_${n}_verdict_sentences_are_closed" \
		sh -c "! grep -Eq '[a-z0-9)] Do not build' '$d/all.txt'"

	# A sentence that compares two numbers says the right way round: "flies
	# X, above the Y" only where X >= Y (result.json keeps it on one line).
	check "dossier_${n}_says_above_only_of_a_larger_number" \
		awk 'match($0, /flies [0-9.]+, above the [0-9.]+/) {
			split(substr($0, RSTART, RLENGTH), w, /[ ,]+/)
			if (w[2] + 0 < w[5] + 0) bad = 1 }
		     END { exit bad }' "$d/result.json"

	check "dossier_${n}_has_document_control_and_contents_after_the_cover" \
		sh -c "grep -q '^Document control' '$d/page2.txt' && grep -q '^Contents' '$d/page2.txt' &&
		       grep -Eq '^ *1 +Executive summary.* [0-9]+$' '$d/page2.txt' &&
		       grep -q '^Checked by' '$d/page2.txt' && grep -q '^Approved by' '$d/page2.txt'"

	# The verdict comes first on the cover and matches the record.
	want=FEASIBLE
	grep -q '"buildable": false' "$d/result.json" && want="NOT BUILDABLE"
	grep -q '"ceiling": {' "$d/result.json" && want="BEYOND REACH"
	if [ "$want" = FEASIBLE ] &&
		awk '/"design_of_record"/ { on = 1 } on && /"feasible":/ { f = /false/; exit } END { exit !f }' "$d/result.json"; then
		want="NOT FEASIBLE AS BUILT"
	fi
	got=$(first_status "$d/cover.txt")
	if [ "$got" = "$want" ]; then ok "dossier_${n}_cover_states_the_verdict_first"
	else notok "dossier_${n}_cover_states_the_verdict_first" "got '$got', want '$want'"; fi
done

# The class on the cover follows each design's own mass: the record's
# first, the continuous optimum's beside it (EU open category: C0 below
# 0.25 kg, C1 below 0.9, C2 below 4, C3/C4 below 25).
eu_class() {
	awk -v m="$1" 'BEGIN { print (m < 0.25 ? "C0" : m < 0.9 ? "C1" : m < 4 ? "C2" : m < 25 ? "C3/C4" : "specific") }'
}
for n in fpv_racing_quad sar_imaging_quad; do
	d="$T/out/$n"
	rec=$(sed -n 's/^  "takeoff_mass_kg": *\([0-9.e+-]*\),$/\1/p' "$d/result.json" | head -n 1)
	cont=$(awk '/^  "custom": \{/ { on = 1 } on && /"total_mass_kg":/ { gsub(/[^0-9.e+-]/, "", $2); print $2; exit }' "$d/result.json")
	if grep -q '"buildable": false' "$d/result.json"; then
		want="^Regulatory class by mass +EU $(eu_class "$rec"),"
	else
		want="^Regulatory class by mass +EU $(eu_class "$rec"), .* EU $(eu_class "$cont"),"
	fi
	check "dossier_${n}_class_follows_each_designs_mass" grep -Eq "$want" "$d/cover.txt"
done

# A catalogue that closes nothing: the cover says NOT BUILDABLE first, and
# the continuous design is labelled so wherever it stands for the record.
"$AE" build -q -o "$T/nb" --db tests/fixtures/catalog/good examples/sar_imaging_quad.json 2>/dev/null
nb="$T/nb/sar_imaging_quad"
pdftotext -layout -f 1 -l 1 "$nb/dossier.pdf" "$nb/cover.txt" 2>/dev/null
pdftotext -layout "$nb/dossier.pdf" "$nb/all.txt" 2>/dev/null
check dossier_unbuildable_cover_says_so_first sh -c "[ \"\$(grep -m 1 -E '^ *(FEASIBLE|NOT FEASIBLE AS BUILT|NOT BUILDABLE)$' '$nb/cover.txt' | sed 's/^ *//')\" = 'NOT BUILDABLE' ]"
check dossier_unbuildable_labels_the_continuous_design grep -q "Continuous design (not buildable)" "$nb/all.txt"
check dossier_unbuildable_prints_no_bom_price sh -c "! grep -q 'Bill of materials price' '$nb/cover.txt'"

# The document control names the checker and the approver the mission gives.
mkdir -p "$T/m"
sed 's/"author": *"\([^"]*\)"/"author": "\1", "checked_by": "R. Checker", "approved_by": "A. Approver"/' \
	examples/sar_imaging_quad.json >"$T/m/signed.json"
"$AE" build -q -o "$T/signed" "$T/m/signed.json" 2>/dev/null
pdftotext -layout -f 2 -l 2 "$T/signed/signed/dossier.pdf" "$T/signed.txt" 2>/dev/null
check dossier_document_control_names_checker_and_approver \
	sh -c "grep -q '^Checked by *R. Checker' '$T/signed.txt' && grep -q '^Approved by *A. Approver' '$T/signed.txt'"

# Web addresses are links: the BOM's maker page is a URI annotation
# (libharu writes the slashes of the string as \057).
check dossier_web_addresses_are_links grep -aq '/URI (https:\\057\\057' \
	"$T/out/sar_imaging_quad/dossier.pdf"
exit 0
