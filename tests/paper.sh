#!/bin/sh
# tests/paper.sh — the paper's studies (§VII-C..E), run by `make paper`.
#
# Runs `aeroeval solve` on the six case-study examples and the three
# shedding examples, the shedding comparisons and the 14-parameter
# sensitivity suite, and prints our numbers beside the paper's with a
# one-line reason where the difference is understood.  Differences are
# reported as they are; nothing here tunes anything.  Results stay in
# $PAPER_OUT (default out/paper): result JSON per example, sensitivity.json
# and sensitivity.pdf.
#
# No JSON tool is needed: `aeroeval sensitivity --case-row RESULT.json`
# reads the result.json `solve` printed, `--compare-shedding` solves the
# static/dynamic pairs, and `--tsv` gives the sensitivity table as fields.
#
# usage: sh tests/paper.sh [BUILD]      (AEROEVAL overrides the program)
# Exit status: 0 when every run worked (whatever the numbers), 1 otherwise.

build=${1:-build}
ae=${AEROEVAL:-$build/aeroeval}
out=${PAPER_OUT:-out/paper}
sens_mission=${PAPER_SENS_MISSION:-examples/sar_imaging_quad.json}
status=0
mkdir -p "$out" || exit 1

# ---- §VII-C case studies ----------------------------------------------------
echo "== Case studies (paper Table: Representative Case Study Results)"
printf '%-24s | %-62s | %s\n' "example" "ours (custom run, continuous optimum)" "paper"
while IFS='|' read -r name paper why; do
	[ -n "$name" ] || continue
	"$ae" solve "examples/$name.json" >"$out/$name.result.json"
	rc=$?
	if [ "$rc" -gt 1 ]; then
		echo "$name: aeroeval solve failed with status $rc"
		status=1
		continue
	fi
	row=$("$ae" sensitivity --case-row "$out/$name.result.json") || status=1
	printf '%-24s | %-62s | %s\n' "$name" "$row" "$paper"
	printf '%-24s   why: %s\n' "" "$why"
done <<'EOF'
sar_imaging_quad|5.57 kg 26x9 KV 200 4S 12650 mAh|paper mission inputs unpublished (examples/ are reconstructions); our cell count comes from a 60 A x sqrt(M) current budget, KV is the continuous target (no catalogue pick in solve)
delivery_quad|12.41 kg 39.5x14 KV 80 6S 36861 mAh|the paper's 6S 36.9 Ah (~800 Wh) pack implies a much longer or heavier mission than the reconstructed example; same current-budget cell rule
agri_spray_octo|50.33 kg 38x12 KV 50 12S 14568 mAh|our agricultural class picks 18S for a 46 kg craft (current budget); the paper's 12S draws ~40 % more current; frame floor departs from the paper (README)
fpv_racing_quad|0.31 kg 5x2 KV 2300 4S 1264 mAh|racing role T/W 11 from thrust margin 0.70; our cell rule picks 6S for the burst power; the paper's 4S 1264 mAh looks like a catalogue pick
lidar_mapping_quad|2.81 kg 21x7 KV 200 3S 7071 mAh|closest match; remaining gap is the reconstructed mission (1200 s forward at the minimum-power speed)
coaxial_inspection_quad|7.77 kg 15x4 KV 450 6S 26881 mAh|coaxial X8 on a 600 mm wheelbase; the paper's 26.9 Ah pack implies a longer hover than the reconstructed 20 min
EOF

# ---- §VII-D shedding ----------------------------------------------------------
echo
echo "== Mass shedding (paper §VII-D)"
for f in agri_static_20kg agri_dynamic_20kg delivery_drop_3p5kg; do
	"$ae" solve "examples/$f.json" >"$out/$f.result.json"
	rc=$?
	if [ "$rc" -gt 1 ]; then
		echo "$f: aeroeval solve failed with status $rc"
		status=1
	else
		echo "$f: $("$ae" sensitivity --case-row "$out/$f.result.json")"
	fi
done
agri=$("$ae" sensitivity --compare-shedding examples/agri_static_20kg.json \
    examples/agri_dynamic_20kg.json) || status=1
dlv=$("$ae" sensitivity --compare-shedding examples/delivery_drop_3p5kg.json) || status=1
get() { printf '%s\n' "$1" | sed -n "s/^$2=//p"; }
printf '%-44s %10s %10s\n' "quantity" "ours" "paper"
printf '%-44s %10s %10s\n' "agri energy capacity saving (%)" "$(get "$agri" energy_saving_pct)" 33.7
printf '%-44s %10s %10s\n' "agri structure (frame+arms+other) saving (%)" "$(get "$agri" structure_saving_pct)" 40.6
printf '%-44s %10s %10s\n' "agri MTOW, dynamic (kg)" "$(get "$agri" mtow_dynamic_kg)" 35.27
printf '%-44s %10s %10s\n' "agri MTOW, static (kg)" "$(get "$agri" mtow_static_kg)" 48.48
printf '%-44s %10s %10s\n' "delivery average takeoff mass reduction (%)" "$(get "$dlv" avg_mass_reduction_pct)" 27.1
echo "why: energy saving = 1 - E_dyn/E_static of the custom runs; structure = frame + arms + other (body, gear)."
echo "why: our structure saving is small because the minimum structural fraction floors an agricultural"
echo "     frame by wheelbase and mass, not by payload path (README: where aeroeval departs from the paper)."
echo "why: delivery reduction = 1 - time-mean mass of the dynamic run / static MTOW (payload dropped at r = 0.5)."

# ---- §VII-E sensitivity -------------------------------------------------------
echo
echo "== 14-parameter sensitivity on $sens_mission (paper Table: Sensitivity Analysis Summary)"
"$ae" sensitivity --tsv -o "$out" "$sens_mission" >"$out/sensitivity.tsv"
rc=$?
if [ "$rc" -gt 1 ]; then
	echo "aeroeval sensitivity failed with status $rc"
	exit 1
fi
# Paper values per key: MTOW sensitivity, flight-time sensitivity, unit, reason.
awk -F'\t' '
NR == FNR {
	paper_m[$1] = $2; paper_t[$1] = $3; unit[$1] = $4; why[$1] = $5; order[++n] = $1
	next
}
FNR > 1 {
	ours_m[$1] = $5; ours_t[$1] = $6; kind[$1] = $4
	cross[$1] = ($8 != "" ? "below " $8 " (" $9 ")" : "") \
	    ($8 != "" && $10 != "" ? "; " : "") \
	    ($10 != "" ? "above " $10 " (" $11 ")" : "")
}
END {
	printf "%-26s %-16s | %9s %9s | %9s %9s | %s\n", "parameter", "per", \
	    "MTOW ours", "paper", "time ours", "paper", "crossing (ours)"
	for (i = 1; i <= n; i++) {
		k = order[i]
		m = ours_m[k] == "" ? "n/a" : sprintf("%+.3f", ours_m[k])
		t = ours_t[k] == "" ? "n/a" : sprintf("%+.3f", ours_t[k])
		printf "%-26s %-16s | %9s %9s | %9s %9s | %s\n", k, unit[k], m, \
		    paper_m[k], t, paper_t[k], cross[k] == "" ? "none" : cross[k]
		if (kind[k] != "central")
			printf "%-26s   (%s difference)\n", "", kind[k]
		if (why[k] != "")
			printf "%-26s   why: %s\n", "", why[k]
	}
}' - "$out/sensitivity.tsv" <<'EOF'
payload	+1.692	-1.703	kg	our mass-growth factor is the whole re-sized aircraft (battery, structure, propulsion) of this mission
prop_diameter_limit	+0.080	+0.011	in	wheelbase and prop limit move together here; structure grows with the wheelbase
forward_speed	+0.062	-0.691	m/s	hover time is the endurance of the re-sized design: a faster forward leg buys a bigger battery; paper diverges >25.5 m/s
climb_speed	+0.128	-0.461	m/s	same: the battery is re-sized for the mission, so its hover endurance grows with any mission demand
altitude	+0.030	-0.200	1000 m	ambient follows ISA with altitude; cell-count steps make the curve kinked
ambient_temperature	+0.004	+0.037	10 degC	density effect dominates; the paper's positive time slope is its battery-temperature model
aux_power	+0.200	-0.385	10 W	re-sized battery carries the aux energy, so hover endurance rises (paper: fixed battery, presumably)
added_drag_area	+0.062	-2.531	0.1 m2	same re-sizing effect; drag only acts in the forward leg
cg_shift	0.000	-0.169	5 cm	CG offset sizes the arms and gates trim only; no trim-power penalty in our hover model
battery_capacity_lock	+0.100	+0.100	1000 mAh	locked at the nominal capacity and cell count; sign agrees
prop_diameter_lock	-0.150	0.000	in	the nominal prop is the overlap limit, so only the smaller side exists (one-sided)
delivery_drop_mass	-0.022	0.000	kg	evaluated on a delivery copy when the mission has another role
delivery_drop_time_ratio	+0.033	0.000	0.1 ratio	evaluated on a delivery copy when the mission has another role
spray_rate	-0.490	0.000	0.005 kg/s	evaluated on an agriculture copy; the nominal rate is payload / mission time
EOF
echo
echo "Outputs: $out/sensitivity.json, $out/sensitivity.pdf, $out/*.result.json"
exit $status
