/* report_prop.c — the propulsion section: the parts of record, the
 * continuous optimum they were aimed at, the motor crosshair, the
 * operating points on the real parts in the layout eCalc users know, what
 * the aircraft can do beyond its mission, the model constants used and the
 * feasibility gates.
 */
#include "pdf/report_prop.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "result/checks.h"
#include "catalog/catalog.h"
#include "pdf/doc.h"
#include "pdf/plot.h"
#include "pdf/report_util.h"
#include "util/strbuf.h"
#include "util/units.h"
#include "util/xalloc.h"

/* J-scores at or above this mark a candidate the optimizer pruned. */
#define REP_J_PRUNED 1e8

static int
dmin_i(int a, int b)
{
	return a < b ? a : b;
}

/* qsort order for doubles, ascending. */
static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* ---- the motor crosshair ------------------------------------------------------- */

/* Every usable catalogue motor as a muted cloud, the scored candidates
 * coloured by J-score tercile (pruned ones as crosses), the continuous
 * optimum as a crosshair and the motor of record.  Both axes are
 * logarithmic: catalogues span decades of KV. */
static void
motor_figure(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct res_run *c = &r->custom;
	const struct catalog *cat = rp->in->cat;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48];
	struct plot *p = plot_alloc(0, 280, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Motor KV (rpm/V)");
	plot_axis_title(pp, PLOT_Y, "Motor mass (g)");
	plot_axis_log(pp, PLOT_X, 1);
	plot_axis_log(pp, PLOT_Y, 1);
	plot_legend(pp, PLOT_LEGEND_BELOW);

	size_t n_cat = cat != NULL ? catalog_n_motors(cat) : 0, n_used = 0;
	double *kv = xcalloc(n_cat + RES_MAX_CANDIDATES + 1, sizeof *kv);
	double *g = xcalloc(n_cat + RES_MAX_CANDIDATES + 1, sizeof *g);
	for (size_t i = 0; i < n_cat; i++) {
		const struct catalog_motor *m = catalog_motor(cat, i);
		if (m == NULL || !m->usable || m->kv_rpm_per_v <= 0 || m->mass_kg <= 0)
			continue;
		kv[n_used] = m->kv_rpm_per_v;
		g[n_used++] = 1000.0 * m->mass_kg;
	}
	if (n_used > 0) {
		struct plot_style st = { .colour = PLOT_COLOUR_MUTED, .line_width_pt = -1,
		                         .marker = PLOT_MARKER_CIRCLE, .marker_size_pt = 3.5,
		                         .open_marker = 1 };
		plot_series(pp, kv, g, n_used, report_sfmt(&sb, "catalogue motors (%zu)", n_used), &st);
	}

	/* Scored candidates in thirds of their J-score (lower is better). */
	int n_cand = dmin_i(r->n_candidates, RES_MAX_CANDIDATES), n_ok = 0;
	double js[RES_MAX_CANDIDATES];
	for (int i = 0; i < n_cand; i++)
		if (r->candidates[i].feasible && r->candidates[i].j_score < REP_J_PRUNED)
			js[n_ok++] = r->candidates[i].j_score;
	qsort(js, (size_t)n_ok, sizeof js[0], cmp_double);
	double t1 = n_ok > 0 ? js[n_ok / 3] : 0, t2 = n_ok > 0 ? js[(2 * n_ok) / 3] : 0;
	static const char *const tier_name[4] = { "scored, best third of J", "scored, middle third",
	                                          "scored, worst third", "pruned" };
	static const int tier_colour[4] = { PLOT_COLOUR_PASS, PLOT_COLOUR_WARN, PLOT_COLOUR_FAIL,
	                                    PLOT_COLOUR_MUTED };
	for (int tier = 0; tier < 4; tier++) {
		size_t k = 0;
		for (int i = 0; i < n_cand; i++) {
			const struct res_candidate *cd = &r->candidates[i];
			int ok = cd->feasible && cd->j_score < REP_J_PRUNED;
			int my = !ok ? 3 : cd->j_score < t1 ? 0 : cd->j_score < t2 ? 1 : 2;
			if (my != tier)
				continue;
			kv[k] = cd->kv;
			g[k++] = 1000.0 * cd->mass_kg;
		}
		if (k > 0)
			plot_scatter(pp, kv, g, k, tier_name[tier],
			             tier == 3 ? PLOT_MARKER_CROSS : PLOT_MARKER_CIRCLE, tier_colour[tier]);
	}
	free(kv);
	free(g);

	plot_crosshair(pp, c->opt.motor_kv, 1000.0 * c->opt.motor_mass_kg,
	               report_sfmt(&sb, "continuous optimum: KV %s, %s g", report_num(b1, sizeof b1, c->opt.motor_kv, 0),
	                           report_num(b2, sizeof b2, 1000.0 * c->opt.motor_mass_kg, 0)),
	               PLOT_COLOUR_ACCENT);
	if (r->parts_selected && r->motor.chosen) {
		const struct catalog_motor *m = cat != NULL ? catalog_find_motor(cat, r->motor.id) : NULL;
		double mkv = m != NULL ? m->kv_rpm_per_v : 0.0;
		for (int i = 0; mkv <= 0.0 && i < n_cand; i++)
			if (strcmp(r->candidates[i].id, r->motor.id) == 0)
				mkv = r->candidates[i].kv;
		double mg = 1000.0 * r->motor.unit_mass_kg;
		if (mkv > 0) {
			struct plot_style st = { .colour = REP_COL_CLOSED, .line_width_pt = -1,
			                         .marker = PLOT_MARKER_SQUARE, .marker_size_pt = 8 };
			plot_series(pp, &mkv, &mg, 1, "motor of record", &st);
			plot_point_label(pp, mkv, mg, report_sfmt(&sb, "%s (J = %s %%)", r->motor.part_number,
			                                          report_num(b1, sizeof b1, r->motor.j_score, 1)));
		}
	}
	const char *cap;
	if (r->parts_selected)
		cap = report_sfmt(&sb, "Motor selection: every usable catalogue motor by KV and mass (log axes), the "
		                  "scored candidates coloured by J, the continuous optimum (crosshair) and the motor "
		                  "of record, %s %s. %s", r->motor.manufacturer, r->motor.part_number, REP_J_NOTE);
	else
		cap = report_sfmt(&sb, "Motor selection: every usable catalogue motor by KV and mass (log axes) and "
		                  "the continuous optimum (crosshair). No part was selected%s.",
		                  cat == NULL ? " (no catalogue loaded)" : "");
	doc_figure(rp->d, p, cap);
	plot_free(p);
	strbuf_free(&sb);
}

/* ---- the parts and the optimum --------------------------------------------------- */

/* The continuous optimum the parts search aimed at. */
static void
optimum_table(struct rep *rp)
{
	const struct res_run *c = &rp->r->custom;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	char *v[9];
	v[0] = xstrdup(report_sfmt(&sb, "%s" NBSP "×" NBSP "%s" NBSP "in (overlap limit %s" NBSP "in)",
	                           report_num(b1, sizeof b1, c->opt.prop_diameter_in, 1),
	                           report_num(b2, sizeof b2, c->opt.prop_pitch_in, 1),
	                           report_num(b3, sizeof b3, c->overlap_limit_in, 1)));
	v[1] = xstrdup(report_sfmt(&sb, "%s" NBSP "rpm/V", report_num(b1, sizeof b1, c->opt.motor_kv, 0)));
	v[2] = xstrdup(report_sfmt(&sb, "%s" NBSP "g each (scaling law)",
	                           report_num(b1, sizeof b1, 1000.0 * c->opt.motor_mass_kg, 0)));
	v[3] = xstrdup(report_sfmt(&sb, "%s" NBSP "A, %s" NBSP "W per motor",
	                           report_num(b1, sizeof b1, c->opt.motor_peak_current_a, 1),
	                           report_num(b2, sizeof b2, c->opt.motor_peak_power_w, 0)));
	v[4] = xstrdup(report_sfmt(&sb, "%s" NBSP "rpm hover, %s" NBSP "rpm full throttle",
	                           report_num(b1, sizeof b1, c->rpm_hover, 0), report_num(b2, sizeof b2, c->rpm_peak, 0)));
	v[5] = xstrdup(report_sfmt(&sb, "%s installed (interference k_int %s)",
	                           report_num(b1, sizeof b1, c->fom_installed, 3),
	                           report_num(b2, sizeof b2, c->interference, 3)));
	v[6] = xstrdup(report_sfmt(&sb, "%s" NBSP "N/m², downwash %s" NBSP "m/s",
	                           report_num(b1, sizeof b1, c->disk_loading_n_m2, 0),
	                           report_num(b2, sizeof b2, c->downwash_ms, 1)));
	v[7] = xstrdup(report_sfmt(&sb, "%s (Reynolds number at the tip %s)",
	                           report_num(b1, sizeof b1, c->tip_mach_peak, 2), report_auto(b2, sizeof b2, c->reynolds_tip)));
	if (c->pack_count > 1)
		snprintf(b3, sizeof b3, "%dP", c->pack_count);
	else
		b3[0] = '\0';
	v[8] = xstrdup(report_sfmt(&sb, "%dS%s %s, %s" NBSP "mAh, %s" NBSP "V nominal", c->cell_count, b3, report_chemistry(c->chemistry),
	                           report_num(b1, sizeof b1, c->capacity_mah, 0),
	                           report_num(b2, sizeof b2, c->nominal_voltage_v, 1)));
	const char *kv[] = {
		"Propeller", v[0], "Motor KV", v[1], "Motor mass", v[2], "Motor peak load", v[3],
		"Rotor speed", v[4], "Figure of merit", v[5], "Disk loading", v[6], "Tip Mach (full throttle)", v[7],
		"Battery", v[8],
	};
	report_kv(rp, kv, 9, -1);
	for (int i = 0; i < 9; i++)
		free(v[i]);
	strbuf_free(&sb);
}

/* The parts of record with the constants the performance model flew. */
static void
record_parts(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct res_run *rec = rp->rec;
	const struct res_perf *pf = &rec->perf;
	const struct catalog *cat = rp->in->cat;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48], b4[48];
	const struct catalog_motor *m = cat != NULL ? catalog_find_motor(cat, r->motor.id) : NULL;
	char *v[4];
	v[0] = xstrdup(report_sfmt(&sb, "%d × %s %s, KV" NBSP "%s, %s" NBSP "g (J = %s" NBSP "%%)", r->motor.qty,
	                           r->motor.manufacturer, r->motor.part_number,
	                           report_num(b1, sizeof b1, m != NULL ? m->kv_rpm_per_v : rec->opt.motor_kv, 0),
	                           report_num(b2, sizeof b2, 1000.0 * r->motor.unit_mass_kg, 0),
	                           report_num(b3, sizeof b3, r->motor.j_score, 1)));
	v[1] = xstrdup(report_sfmt(&sb, "%d × %s %s, %s" NBSP "×" NBSP "%s" NBSP "in, %s" NBSP "g", r->prop.qty,
	                           r->prop.manufacturer, r->prop.part_number,
	                           report_num(b1, sizeof b1, rec->opt.prop_diameter_in, 1),
	                           report_num(b2, sizeof b2, rec->opt.prop_pitch_in, 1),
	                           report_num(b3, sizeof b3, 1000.0 * r->prop.unit_mass_kg, 0)));
	v[2] = xstrdup(report_sfmt(&sb, "%d × %s %s (%d in series × %d in parallel): %dS %s, %s" NBSP "mAh, "
	                           "%s" NBSP "kg", r->battery.qty, r->battery.manufacturer, r->battery.part_number,
	                           r->battery_series_packs, r->battery_parallel_packs, rec->cell_count,
	                           report_chemistry(rec->chemistry), report_num(b1, sizeof b1, rec->capacity_mah, 0),
	                           report_num(b4, sizeof b4, rec->mass.battery_kg, 2)));
	v[3] = xstrdup(report_sfmt(&sb, "%d × %s %s", r->esc.qty, r->esc.manufacturer, r->esc.part_number));
	const char *kv[] = { "Motor", v[0], "Propeller", v[1], "Battery", v[2], "ESC", v[3] };
	report_kv(rp, kv, 4, -1);
	for (int i = 0; i < 4; i++)
		free(v[i]);
	if (pf->valid)
		doc_paragraph(rp->d, report_sfmt(&sb, "Constants flown: motor winding resistance %s" NBSP "Ω and "
		              "no-load current %s" NBSP "A (%s); propeller static thrust and power coefficients "
		              "C_T" NBSP "=" NBSP "%s and C_P" NBSP "=" NBSP "%s (%s). %s",
		              report_num(b1, sizeof b1, pf->motor_resistance_ohm, 4),
		              report_num(b2, sizeof b2, pf->motor_no_load_a, 2),
		              pf->motor_r_estimated ? "estimated from the catalogue's motors: the maker publishes "
		                                      "no value" : "published by the maker",
		              report_num(b3, sizeof b3, pf->prop_ct, 4), report_num(b4, sizeof b4, pf->prop_cp, 4),
		              pf->prop_coeffs_measured ? "published" : "estimated from the propeller's size and "
		                                         "pitch: no measured coefficients are published",
		              REP_J_NOTE));
	strbuf_free(&sb);
}

/* ---- operating points ------------------------------------------------------------ */

/* One quantity of an operating point, with how to print it. */
struct op_row {
	const char *label;
	int dec;
	double (*get)(const struct res_op *op);
};

static double op_thrust_g(const struct res_op *o) { return 1000.0 * o->thrust_n / G0_M_S2; }
static double op_throttle(const struct res_op *o) { return 100.0 * o->throttle; }
static double op_current(const struct res_op *o) { return o->motor_current_a; }
static double op_voltage(const struct res_op *o) { return o->motor_voltage_v; }
static double op_rpm(const struct res_op *o) { return o->rpm; }
static double op_power_in(const struct res_op *o) { return o->power_in_w; }
static double op_shaft(const struct res_op *o) { return o->power_shaft_w; }
static double op_eff(const struct res_op *o) { return 100.0 * o->motor_efficiency; }
static double op_gw(const struct res_op *o) { return o->g_per_w; }
static double op_wind(const struct res_op *o) { return o->winding_temp_c; }
static double op_mach(const struct res_op *o) { return o->tip_mach; }
static double op_batt_i(const struct res_op *o) { return o->battery_current_a; }
static double op_batt_v(const struct res_op *o) { return o->bus_voltage_v; }
static double op_c(const struct res_op *o) { return o->c_load; }
static double op_el(const struct res_op *o) { return o->electrical_w; }

static const struct op_row op_rows[] = {
	{ "Thrust per motor (g)", 0, op_thrust_g },
	{ "Throttle (%)", 0, op_throttle },
	{ "Motor current (A)", 1, op_current },
	{ "Motor voltage (V)", 2, op_voltage },
	{ "Speed (rpm)", 0, op_rpm },
	{ "Electrical power per motor (W)", 0, op_power_in },
	{ "Shaft power per motor (W)", 0, op_shaft },
	{ "Motor efficiency (%)", 1, op_eff },
	{ "Thrust per electrical watt (g/W)", 2, op_gw },
	{ "Winding temperature, estimated (°C)", 0, op_wind },
	{ "Propeller tip Mach", 3, op_mach },
	{ "Battery current, aircraft (A)", 1, op_batt_i },
	{ "Battery voltage under load (V)", 2, op_batt_v },
	{ "Battery load (C)", 1, op_c },
	{ "Electrical power, aircraft (W)", 0, op_el },
};
#define N_OP_ROWS ((int)(sizeof op_rows / sizeof op_rows[0]))

/* The eCalc layout: one column per operating point, one row per quantity;
 * a point the drive cannot reach says so instead of giving numbers. */
static void
op_table(struct rep *rp)
{
	const struct res_perf *pf = &rp->rec->perf;
	static const struct doc_column cols[] = {
		{ "Per motor unless noted", 2.6, DOC_ALIGN_LEFT }, { "Hover", 1.0, DOC_ALIGN_RIGHT },
		{ "Climb", 1.0, DOC_ALIGN_RIGHT }, { "Cruise", 1.0, DOC_ALIGN_RIGHT },
		{ "Full throttle", 1.0, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 1 + OP_MAX);
	for (int i = 0; i < N_OP_ROWS; i++) {
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", op_rows[i].label);
		for (int k = 0; k < OP_MAX; k++) {
			if (!pf->op[k].valid)
				doc_table_cell(&t, DOC_CELL_FAIL, "out of reach");
			else
				report_cell_num(&t, k == OP_HOVER ? DOC_CELL_BOLD : DOC_CELL_NORMAL,
				                op_rows[i].get(&pf->op[k]), op_rows[i].dec);
		}
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
}

/* What the aircraft can do beyond its mission, on its real parts. */
static void
performance(struct rep *rp)
{
	const struct res_run *rec = rp->rec;
	const struct res_perf *pf = &rec->perf;
	const struct mission_spec *m = &rp->r->mission;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	char *v[8];
	const char *k[8];
	int n = 0;
	k[n] = "Flight time to the reserve";
	v[n++] = xstrdup(report_sfmt(&sb, "%s" NBSP "min hover, %s" NBSP "min mixed (the mission's phases "
	                             "repeated), %s" NBSP "min at full throttle",
	                             report_num(b1, sizeof b1, pf->hover_time_s / 60.0, 1),
	                             report_num(b2, sizeof b2, pf->mixed_time_s / 60.0, 1),
	                             report_num(b3, sizeof b3, pf->full_throttle_time_s / 60.0, 1)));
	k[n] = "Maximum level speed";
	v[n++] = xstrdup(report_sfmt(&sb, "%s" NBSP "m/s (%s)",
	                             report_num(b1, sizeof b1, pf->max_speed_ms, 1),
	                             report_limit_phrase(pf->max_speed_limit, false)));
	k[n] = "Maximum climb rate";
	v[n++] = xstrdup(report_sfmt(&sb, "%s" NBSP "m/s (vertical, full throttle%s%s)",
	                             report_num(b1, sizeof b1, pf->max_climb_ms, 1),
	                             pf->max_climb_limit != RES_LIMIT_NONE ? "; " : "",
	                             report_limit_phrase(pf->max_climb_limit, true)));
	k[n] = "Maximum tilt";
	v[n++] = xstrdup(report_sfmt(&sb, "%s° holding altitude at full throttle",
	                             report_num(b1, sizeof b1, pf->max_tilt_deg, 0)));
	/* The role's thrust-to-weight target, 1 / (1 - margin)² (paper §II-E). */
	double theta = 1.0 - rec->thrust_margin;
	double tw_target = report_div(1.0, theta * theta);
	k[n] = "Spare payload";
	if (pf->spare_payload_kg > 0.0)
		v[n++] = xstrdup(report_sfmt(&sb, "%s" NBSP "kg more before the full-throttle thrust-to-weight "
		                             "ratio falls to the role's target of %s",
		                             report_num(b1, sizeof b1, pf->spare_payload_kg, 3),
		                             report_num(b2, sizeof b2, tw_target, 2)));
	else
		v[n++] = xstrdup(report_sfmt(&sb, "none: the full-throttle thrust-to-weight ratio (%s) is already "
		                             "at or below the role's target of %s",
		                             report_num(b1, sizeof b1, rec->thrust_to_weight, 2),
		                             report_num(b2, sizeof b2, tw_target, 2)));
	k[n] = "Throttle the mission needs";
	v[n++] = xstrdup(report_sfmt(&sb, "%s" NBSP "%% at most%s", report_num(b1, sizeof b1, 100.0 * pf->throttle_needed, 0),
	                             pf->throttle_needed > 1.0 ? ": OUT OF REACH of the drive" : ""));
	k[n] = "One motor out";
	if (pf->motor_out_rotors > 0)
		v[n++] = xstrdup(report_sfmt(&sb, "%s: with the opposite motor throttled back, %d rotors give "
		                             "thrust-to-weight %s at full throttle", pf->motor_out_holds
		                             ? "holds altitude and lands" : "CANNOT hold altitude",
		                             pf->motor_out_rotors, report_num(b1, sizeof b1, pf->motor_out_ratio, 2)));
	else
		v[n++] = xstrdup(report_sfmt(&sb, "not survivable with %d rotors (needs 6 or more)", m->num_rotors));
	const char *kv[16];
	for (int i = 0; i < n; i++) {
		kv[2 * i] = k[i];
		kv[2 * i + 1] = v[i];
	}
	report_kv(rp, kv, n, -1);
	for (int i = 0; i < n; i++)
		free(v[i]);
	strbuf_free(&sb);
}

/* ---- feasibility gates ------------------------------------------------------------- */

/* The propulsion gates as the record's checks recorded them: rotor
 * overlap, tip Mach, the propeller's speed limit, and downwash only where
 * the role limits it. */
static void
gate_table(struct rep *rp)
{
	static const struct doc_column cols[] = {
		{ "Gate", 2.8, DOC_ALIGN_LEFT }, { "Value", 1.0, DOC_ALIGN_RIGHT },
		{ "Limit", 1.0, DOC_ALIGN_RIGHT }, { "Result", 0.8, DOC_ALIGN_CENTER },
	};
	static const char *const gates[][2] = {
		{ "PROP_OVERLAP", "Rotor overlap: propeller diameter (in)" },
		{ "TIP_MACH", "Tip Mach number at full throttle" },
		{ "PROP_RPM", "Propeller speed at full throttle (rpm)" },
		{ "DOWNWASH", "Downwash, crop and drift (m/s)" },
	};
	char b1[48];
	struct doc_table t;
	doc_table_init(&t, cols, 4);
	for (size_t k = 0; k < sizeof gates / sizeof gates[0]; k++) {
		const struct res_check *ck = checks_find(rp->rec, gates[k][0]);
		if (ck == NULL)
			continue;   /* not a limit of this role or these parts */
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", gates[k][1]);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_auto(b1, sizeof b1, ck->value));
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s" NBSP "%s", ck->upper ? "≤" : "≥",
		               report_auto(b1, sizeof b1, ck->limit));
		doc_table_cell(&t, ck->pass ? DOC_CELL_PASS : DOC_CELL_FAIL, "%s", ck->pass ? "PASS" : "FAIL");
	}
	if (t.n_cells > 0)
		doc_table(rp->d, &t);
	doc_table_clear(&t);
}

/* Section: the parts of record, the optimum they aim at, the crosshair,
 * the operating points and performance on the real parts, the gates. */
/* The installation loss the operating points are flown with: the
 * propeller's own figure of merit divided by the calibrated installation
 * factor κ and the arm interference k_int (paper §IV-F), as a share of
 * power; said where it applies, with its values. */
static void
install_loss(struct rep *rp)
{
	const struct res_run *rec = rp->rec;
	const struct res_perf *pf = &rec->perf;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48], b4[48], b5[48];
	double extra = report_div(pf->prop_fom, rec->fom_installed) - 1.0;
	if (!(pf->prop_fom > 0.0) || !(rec->fom_installed > 0.0) || fabs(extra) < 0.005) {
		doc_paragraph(rp->d, "No installation loss is applied: the rotor flies on the propeller's "
		              "own figure of merit.");
		strbuf_free(&sb);
		return;
	}
	if (rec->kappa > 1.0)
		report_sfmt(&sb, "Installation loss: the propeller's own figure of merit, %s, falls to %s "
		            "installed: divided by the calibrated installation factor κ" NBSP "=" NBSP "%s "
		            "(rotor–rotor and rotor–body interaction, fitted on real aircraft) and by the "
		            "interference of the arm under the rotor, k_int" NBSP "=" NBSP "%s. Hover, climb "
		            "and cruise therefore take %s" NBSP "%% more shaft power than the propeller's "
		            "coefficients alone give.",
		            report_num(b1, sizeof b1, pf->prop_fom, 3),
		            report_num(b2, sizeof b2, rec->fom_installed, 3),
		            report_num(b3, sizeof b3, rec->kappa, 3),
		            report_num(b4, sizeof b4, rec->interference, 3),
		            report_num(b5, sizeof b5, 100.0 * extra, 0));
	else
		report_sfmt(&sb, "Installation loss: the propeller's own figure of merit, %s, falls to %s "
		            "installed (the mission's figure of merit or its isolated mode, and the "
		            "interference of the arm under the rotor, k_int" NBSP "=" NBSP "%s): %s" NBSP
		            "%% more shaft power than the propeller's coefficients alone give.",
		            report_num(b1, sizeof b1, pf->prop_fom, 3),
		            report_num(b2, sizeof b2, rec->fom_installed, 3),
		            report_num(b4, sizeof b4, rec->interference, 3),
		            report_num(b5, sizeof b5, 100.0 * extra, 0));
	doc_paragraph(rp->d, strbuf_str(&sb));
	strbuf_free(&sb);
}

void
report_sec_propulsion(struct rep *rp, const char *title)
{
	const struct res_run *rec = rp->rec;
	report_heading(rp, title);
	if (rp->buildable) {
		report_subheading(rp, "Parts of record", REP_KEEP_PT);
		record_parts(rp);
	} else {
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "NOT BUILDABLE", report_no_parts_reason(rp));
	}
	struct strbuf sb = STRBUF_INIT;
	report_subheading(rp, report_continuous_heading(rp, &sb, "what the physics asks for"), REP_KEEP_PT);
	strbuf_free(&sb);
	doc_paragraph(rp->d, "The sizing loop's continuous design; the parts search looks for catalogue parts "
	              "that close the lightest aircraft around it.");
	optimum_table(rp);

	/* The figure and its caption are about 330 pt: keep the heading on
	 * their page. */
	report_subheading(rp, "Motor selection", 340.0);
	motor_figure(rp);

	/* The table with its heading and note is about 330 pt: keep it whole. */
	int ops = rp->buildable && rec->perf.valid;
	report_subheading(rp, "Operating points on the real parts", ops ? 330.0 : REP_KEEP_PT);
	if (ops) {
		doc_paragraph(rp->d, "Hover, climb and cruise at the mission's takeoff mass, the pack at its "
		              "nominal voltage under load; full throttle on the pack's terminal voltage under "
		              "load: the motor's own KV, resistance and no-load current on the propeller's own "
		              "coefficients, with the installation loss below. Thrust per electrical watt is the "
		              "motor's thrust over its electrical input.");
		install_loss(rp);
		op_table(rp);
		report_subheading(rp, "Beyond the mission", REP_KEEP_PT);
		performance(rp);
	} else {
		doc_paragraph(rp->d, "None: no catalogue parts close this design, so there is no real motor and "
		              "propeller to fly. The mission section gives the continuous design's rotor speeds, "
		              "powers and currents phase by phase.");
	}
	report_subheading(rp, "Feasibility gates", REP_KEEP_PT);
	gate_table(rp);
}
