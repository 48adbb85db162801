#!/bin/sh
# tests/paper.sh — the paper's studies (§VII-C..E), run by `make paper`.
#
# Runs `aeroeval solve` on the six case-study examples and the three
# shedding examples, the shedding comparisons and the 14-parameter
# sensitivity suite, and prints our numbers beside the paper's with a
# one-line reason where the difference is understood.  Differences are
# reported as they are; nothing here tunes anything.  Results stay in
# $PAPER_OUT (default out/paper): result JSON per example, and
# sensitivity.json and sensitivity.pdf in the folder of the sensitivity
# mission (as `build` would name it).
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
sar_imaging_quad|5.57 kg 26x9 KV 200 4S 12650 mAh|mission inputs are not published (examples/ are reconstructions); our cell count comes from the 60 A x sqrt(M) current budget; KV is the continuous target at our bus voltage, not a catalogue motor
delivery_quad|12.41 kg 39.5x14 KV 80 6S 36861 mAh|the paper's pack (6S 36.9 Ah, ~820 Wh) holds more energy than ours: its mission must be longer or heavier than the reconstructed one; our propeller is the lightest of the diameters the propeller search tries (docs/model.md), not the largest the wheelbase admits
agri_spray_octo|50.33 kg 38x12 KV 50 12S 14568 mAh|ours is about 20 % heavier (T/W 2.78 from the role's 40 % margin, the calibrated Agricultural equipment law) and feasible under the 17 m/s downwash limit (docs/model.md), where the paper's 8 m/s cap rules out every real sprayer; 18S from the current budget against the paper's 12S, hence the lower KV
fpv_racing_quad|0.31 kg 5x2 KV 2300 4S 1264 mAh|ours is heavier: the calibrated MicroAIO equipment law and a 6S pack from the burst power, although the example asks for T/W 8.2 (thrust margin 0.65) against the paper's T/W 25
lidar_mapping_quad|2.81 kg 21x7 KV 200 3S 7071 mAh|ours is heavier, on 6S from the current budget against the paper's 3S; our propeller is the lightest of the diameters the propeller search tries (docs/model.md), below the 21 in the wheelbase admits
coaxial_inspection_quad|7.77 kg 15x4 KV 450 6S 26881 mAh|the paper's pack (6S 26.9 Ah, ~600 Wh) holds several times our energy: mission inputs are not published
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
echo "why: the minimum structural fraction binds in both agricultural runs, so our structure scales with MTOW"
echo "     (structure saving = MTOW saving); the paper's frame saving exceeds its MTOW saving."
echo "why: both agricultural runs are six-rotor sprayers on a 2145 mm wheelbase (the cohort's six-rotor T16 spans 1883 mm,"
echo "     the eight-rotor T40 2184 mm): on a coaxial X8 of 2.0 m no catalogue power system meets both its overlap limit"
echo "     and the 17 m/s downwash limit; both are feasible (the paper's 8 m/s cap rules out every real sprayer)."
echo "why: delivery reduction = 1 - time-mean mass of the dynamic run / static MTOW (parcel dropped at r = 0.5)."

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
payload	+1.692	-1.703	kg	both re-size the whole aircraft; our growth factor is larger for this mission (reason for the size of the gap not known)
prop_diameter_limit	+0.080	+0.011	in	the limit moves with the wheelbase: a larger prop saves power while arms and frame grow, and the two nearly cancel here
forward_speed	+0.062	-0.691	m/s	our hover time is the endurance of the re-sized design: a faster forward leg buys a bigger battery, so it rises; the paper's divergence is at 25.5 m/s
climb_speed	+0.128	-0.461	m/s	same re-sizing effect on hover time as forward speed
altitude	+0.030	-0.200	1000 m	ambient follows ISA (thinner and colder air together); time agrees, our MTOW slope is several times the paper's (reason not known)
ambient_temperature	+0.004	+0.037	10 degC	MTOW sign agrees (warmer air is thinner); our hover time falls with density, the paper's rises
aux_power	+0.200	-0.385	10 W	the re-sized battery carries the aux energy, so hover endurance rises; the paper's sign suggests a fixed battery
added_drag_area	+0.062	-2.531	0.1 m2	same re-sizing effect on hover time; drag acts in the forward leg only
cg_shift	0.000	-0.169	5 cm	MTOW agrees (0); a CG offset only sizes the arms and gates trim here, with no trim-power cost in hover
battery_capacity_lock	+0.100	+0.100	1000 mAh	locked at the nominal capacity and cell count; signs agree, our slopes are larger
prop_diameter_lock	-0.150	0.000	in	the nominal prop is the overlap limit, so only the smaller side exists (one-sided); our slope near it is small and of the other sign (reason not established)
delivery_drop_mass	-0.022	0.000	kg	on a delivery copy of the mission; the lighter return leg lets the battery shrink (size of the gap not known)
delivery_drop_time_ratio	+0.033	0.000	0.1 ratio	on a delivery copy; a later drop carries the parcel longer
spray_rate	-0.490	0.000	0.005 kg/s	on an agriculture copy; the nominal rate is payload / mission time; faster spraying sheds the tank sooner, so less energy and mass
EOF
echo
sens_dir="$out/$(basename "$sens_mission" .json)"
echo "Outputs: $sens_dir/sensitivity.json, $sens_dir/sensitivity.pdf, $out/*.result.json"
exit $status
