#!/bin/sh
# Golden outputs of every example: result.json, bom.csv, bom_totals.csv,
# the dossier's text (pdftotext -layout) and, for a buildable design, the
# ArduPilot hand-off (vehicle_components.json, ardupilot.param,
# qgroundcontrol.params) are pinned under
# tests/golden/NAME/, so that a changed number is a visible diff in review.
# A hand-off file must exist in both places or in neither.
#
#   sh tests/cli_golden.sh          compare (ok / not ok lines; run_all.sh)
#   sh tests/cli_golden.sh update   rewrite the pinned files (make golden)
mode=${1:-check}
AE=${AEROEVAL:-build/aeroeval}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
# A fixed date: the dossier's cover and metadata carry it.
SOURCE_DATE_EPOCH=1767225600 "$AE" build -q -o "$T/out" examples/ 2>"$T/err"
rc=$?
if [ "$rc" -gt 1 ]; then
	cat "$T/err"
	echo "not ok golden_build_of_examples"
	exit 1
fi
for f in examples/*.json; do
	n=$(basename "$f" .json)
	pdftotext -layout "$T/out/$n/dossier.pdf" "$T/out/$n/dossier.txt" 2>/dev/null
	for g in result.json bom.csv bom_totals.csv dossier.txt vehicle_components.json \
	    ardupilot.param qgroundcontrol.params; do
		if [ ! -e "$T/out/$n/$g" ] && [ ! -e "tests/golden/$n/$g" ]; then
			continue  # no hand-off for a design that is not buildable
		fi
		if [ "$mode" = update ]; then
			mkdir -p "tests/golden/$n"
			if [ -e "$T/out/$n/$g" ]; then cp "$T/out/$n/$g" "tests/golden/$n/$g"
			else rm -f "tests/golden/$n/$g"; fi
		elif cmp -s "$T/out/$n/$g" "tests/golden/$n/$g"; then
			echo "ok golden_${n}_$g"
		else
			diff -u "tests/golden/$n/$g" "$T/out/$n/$g" | head -40
			echo "not ok golden_${n}_$g"
		fi
	done
done
[ "$mode" = update ] && echo "golden: updated tests/golden/ from $(ls examples/*.json | wc -l) examples"
exit 0
