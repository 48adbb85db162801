/* report_figs.c — the dossier sections built around figures: mission and
 * energy, thermal and electrical traces, structure and resonance,
 * propulsion selection, convergence and the endurance explorer.
 *
 * Colours by role (report.h): baseline palette 0, custom palette 1, the
 * BOM-closed run palette 2; limits in the fail colour, design points and
 * optima in the accent colour.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/catalog.h"
#include "output/doc.h"
#include "output/plot.h"
#include "output/report_int.h"
#include "util/strbuf.h"
#include "util/units.h"
#include "util/xalloc.h"

/* J-scores at or above this mark a candidate the optimizer pruned. */
#define REP_J_PRUNED 1e8
/* Points of the resonance figure's rpm axis. */
#define REP_RPM_POINTS 64
/* The structure module's resonance rule: the arm mode must sit 1.5x clear
 * of the in-flight blade-pass band (structure.h, STRUCT_RESONANCE_MARGIN). */
#define REP_RESONANCE_FACTOR 1.5
/* Battery thermal-runaway limit drawn on the temperature trace, °C. */
#define REP_RUNAWAY_C 60.0

/* Phase names for table rows (res_phase_name is the lower-case key). */
static const char *const phase_title[PHASE_MAX] = { "Climb", "Forward", "Hover" };

static int
dmin_i(int a, int b)
{
	return a < b ? a : b;
}

/* ---- 5 mission and energy ------------------------------------------------ */

/* One run's phases as a table, phases not flown left out, with the mission
 * totals of time and energy. */
static void
phase_table(struct rep *rp, const struct res_run *run)
{
	static const struct doc_column cols[] = {
		{ "Phase", 1.15, DOC_ALIGN_LEFT }, { "Time (s)", 0.85, DOC_ALIGN_RIGHT },
		{ "v (m/s)", 0.75, DOC_ALIGN_RIGHT }, { "T/rotor (N)", 0.95, DOC_ALIGN_RIGHT },
		{ "P shaft (W)", 0.95, DOC_ALIGN_RIGHT }, { "P el. (W)", 0.9, DOC_ALIGN_RIGHT },
		{ "I (A)", 0.75, DOC_ALIGN_RIGHT }, { "E (Wh)", 0.8, DOC_ALIGN_RIGHT },
		{ "rpm", 0.8, DOC_ALIGN_RIGHT }, { "Thr. (%)", 0.8, DOC_ALIGN_RIGHT },
		{ "Pitch (°)", 0.8, DOC_ALIGN_RIGHT }, { "Tip M", 0.7, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 12);
	double time_s = 0.0, energy_wh = 0.0;
	for (int i = 0; i < PHASE_MAX; i++) {
		const struct res_phase *ph = &run->phase[i];
		if (ph->duration_s <= 0.0)
			continue;
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", phase_title[i]);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->duration_s, 0);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->speed_ms, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->thrust_per_rotor_n, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->shaft_power_w, 0);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->power_w, 0);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->current_a, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->energy_wh, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->rpm, 0);
		report_cell_num(&t, DOC_CELL_NORMAL, 100.0 * ph->throttle, 0);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->pitch_deg, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, ph->tip_mach, 2);
		time_s += ph->duration_s;
		energy_wh += ph->energy_wh;
	}
	doc_table_cell(&t, DOC_CELL_BOLD, "Mission");
	report_cell_num(&t, DOC_CELL_BOLD, time_s, 0);
	for (int k = 0; k < 5; k++)
		doc_table_cell(&t, DOC_CELL_BOLD, "%s", "");
	report_cell_num(&t, DOC_CELL_BOLD, energy_wh, 1);
	for (int k = 0; k < 4; k++)
		doc_table_cell(&t, DOC_CELL_BOLD, "%s", "");
	t.total_row = 1;
	doc_table(rp->d, &t);
	doc_table_clear(&t);
}

/* Linear interpolation of y(x) over an ascending grid; NAN outside it. */
static double
interp(const double *x, const double *y, int n, double at)
{
	for (int i = 1; i < n; i++)
		if (at >= x[i - 1] && at <= x[i]) {
			double w = report_div(at - x[i - 1], x[i] - x[i - 1]);
			return y[i - 1] + w * (y[i] - y[i - 1]);
		}
	return NAN;
}

/* Section 5: phase tables of both runs and the power-vs-speed sweep with
 * the minimum-power speed, the flown speed and v_max marked. */
void
report_sec_mission(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *b = &r->baseline, *c = &r->custom;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	report_heading(rp, title);
	int shed = r->mission.payload_role.mass_shedding &&
	           (r->mission.payload_role.type == ROLE_DELIVERY ||
	            r->mission.payload_role.type == ROLE_AGRICULTURE);
	doc_paragraph(rp->d, report_sfmt(&sb, "The mission is flown as climb, forward flight and hover%s. "
	              "Electrical power is at the battery terminals and includes %s W of auxiliary load; "
	              "energy is what each phase draws from the pack (%s Wh nominal, %dS %s).",
	              shed ? "; the custom run sheds payload on the way (drop or spray), so its later "
	                     "phases fly lighter than the takeoff mass" : " at the takeoff mass",
	              report_num(b1, sizeof b1, r->mission.payload_role.aux_power_w, 0),
	              report_num(b2, sizeof b2, c->energy_wh, 1), c->cell_count, c->chemistry));
	report_subheading(rp, "Custom run", REP_KEEP_PT);
	phase_table(rp, c);
	report_subheading(rp, "Baseline run", REP_KEEP_PT);
	phase_table(rp, b);

	if (c->n_sweep > 0 || b->n_sweep > 0) {
		struct plot *p = plot_alloc(0, 250, 1, 1);
		struct plot_panel *pp = plot_panel(p, 0, 0);
		plot_axis_title(pp, PLOT_X, "Forward speed (m/s)");
		plot_axis_title(pp, PLOT_Y, "Electrical power (W)");
		double vtop = 0.0;
		for (int k = 0; k < dmin_i(c->n_sweep, RES_MAX_SWEEP); k++)
			vtop = fmax(vtop, c->sweep_v_ms[k]);
		for (int k = 0; k < dmin_i(b->n_sweep, RES_MAX_SWEEP); k++)
			vtop = fmax(vtop, b->sweep_v_ms[k]);
		vtop = fmax(vtop, c->v_max_ms);
		if (vtop > 0)
			plot_axis_range(pp, PLOT_X, 0, vtop + 1.0);
		plot_line(pp, b->sweep_v_ms, b->sweep_power_w, (size_t)dmin_i(b->n_sweep, RES_MAX_SWEEP),
		          "Baseline", REP_COL_BASELINE, PLOT_DASH_SOLID);
		plot_line(pp, c->sweep_v_ms, c->sweep_power_w, (size_t)dmin_i(c->n_sweep, RES_MAX_SWEEP),
		          "Custom", REP_COL_CUSTOM, PLOT_DASH_SOLID);
		if (c->v_min_power_ms > 0)
			plot_vline(pp, c->v_min_power_ms,
			           report_sfmt(&sb, "minimum power %s m/s", report_num(b1, sizeof b1, c->v_min_power_ms, 1)),
			           PLOT_COLOUR_ACCENT, PLOT_DASH_DASHED);
		if (c->v_max_ms > 0)
			plot_vline(pp, c->v_max_ms,
			           report_sfmt(&sb, "v max %s m/s", report_num(b1, sizeof b1, c->v_max_ms, 1)),
			           PLOT_COLOUR_FAIL, PLOT_DASH_DOTTED);
		double fv = c->optimal_speed_ms;
		double fp = interp(c->sweep_v_ms, c->sweep_power_w, dmin_i(c->n_sweep, RES_MAX_SWEEP), fv);
		if (isfinite(fp)) {
			struct plot_style st = { .colour = REP_COL_CUSTOM, .line_width_pt = -1,
			                         .marker = PLOT_MARKER_DIAMOND, .marker_size_pt = 7 };
			plot_series(pp, &fv, &fp, 1, "flown speed (custom)", &st);
			plot_point_label(pp, fv, fp, report_sfmt(&sb, "%s m/s, %s W", report_num(b1, sizeof b1, fv, 1),
			                 report_num(b2, sizeof b2, fp, 0)));
		}
		doc_figure(rp->d, p, report_sfmt(&sb, "Electrical power required vs forward speed at takeoff mass, "
		           "baseline and custom runs; the custom run's minimum-power speed (%s m/s), its flown "
		           "speed (%s m/s) and the highest speed its thrust margin allows (%s m/s).",
		           report_num(b1, sizeof b1, c->v_min_power_ms, 1), report_num(b2, sizeof b2, fv, 1),
		           report_num(b3, sizeof b3, c->v_max_ms, 1)));
		plot_free(p);
	}
	strbuf_free(&sb);
}

/* ---- 6 thermal and electrical traces ------------------------------------ */

/* Marks the phase changes of the trace as vertical lines (labelled on the
 * first panel only, to keep the small panels readable). */
static void
phase_marks(struct plot_panel *pp, const struct res_run *run, int labelled)
{
	int n = dmin_i(run->n_trace, RES_MAX_TRACE);
	for (int i = 1; i < n; i++) {
		int ph = run->trace[i].phase;
		if (ph == run->trace[i - 1].phase)
			continue;
		const char *label = labelled && ph >= 0 && ph < PHASE_MAX ? res_phase_name[ph] : NULL;
		plot_vline(pp, run->trace[i].t_s, label, PLOT_COLOUR_MUTED, PLOT_DASH_DOTTED);
	}
}

/* Section 6: the custom run's discharge trace as four panels with their
 * limits (runaway temperature, voltage floor, SOC reserve), then the
 * headline numbers as a table. */
void
report_sec_thermal(struct rep *rp, const char *title)
{
	const struct res_run *c = &rp->r->custom;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48];
	report_heading(rp, title);
	int n = dmin_i(c->n_trace, RES_MAX_TRACE);
	char end[RES_TEXT];
	snprintf(end, sizeof end, "%s", c->termination[0] != '\0' ? c->termination : "mission flown");
	if (end[0] >= 'a' && end[0] <= 'z')
		end[0] = (char)(end[0] - 'a' + 'A');
	doc_paragraph(rp->d, report_sfmt(&sb, "The discharge simulation of the custom run: pack temperature, "
	              "terminal and open-circuit voltage, state of charge and current over the mission "
	              "(%d samples). %s.", n, end));
	if (n > 0) {
		double *t = xcalloc((size_t)n, sizeof *t), *y1 = xcalloc((size_t)n, sizeof *y1),
		       *y2 = xcalloc((size_t)n, sizeof *y2);
		struct plot *p = plot_alloc(0, 400, 2, 2);
		struct plot_panel *a = plot_panel(p, 0, 0), *v = plot_panel(p, 0, 1),
		                  *s = plot_panel(p, 1, 0), *i = plot_panel(p, 1, 1);
		for (int k = 0; k < n; k++)
			t[k] = c->trace[k].t_s;

		plot_title(a, "Battery temperature");
		plot_axis_title(a, PLOT_Y, "Temperature (°C)");
		for (int k = 0; k < n; k++)
			y1[k] = c->trace[k].temp_c;
		plot_line(a, t, y1, (size_t)n, NULL, REP_COL_CUSTOM, PLOT_DASH_SOLID);
		plot_hline(a, REP_RUNAWAY_C, "60 °C runaway limit", PLOT_COLOUR_FAIL, PLOT_DASH_DASHED);
		phase_marks(a, c, 1);

		plot_title(v, "Pack voltage");
		plot_axis_title(v, PLOT_Y, "Voltage (V)");
		for (int k = 0; k < n; k++) {
			y1[k] = c->trace[k].v_term_v;
			y2[k] = c->trace[k].v_oc_v;
		}
		plot_line(v, t, y2, (size_t)n, "open circuit", PLOT_COLOUR_MUTED, PLOT_DASH_DASHED);
		plot_line(v, t, y1, (size_t)n, "terminal", REP_COL_CUSTOM, PLOT_DASH_SOLID);
		plot_hline(v, c->voltage_floor_v, report_sfmt(&sb, "floor %s V", report_num(b1, sizeof b1, c->voltage_floor_v, 2)),
		           PLOT_COLOUR_FAIL, PLOT_DASH_DASHED);
		phase_marks(v, c, 0);

		plot_title(s, "State of charge");
		plot_axis_title(s, PLOT_X, "Time (s)");
		plot_axis_title(s, PLOT_Y, "SOC (%)");
		for (int k = 0; k < n; k++)
			y1[k] = 100.0 * c->trace[k].soc;
		plot_axis_range(s, PLOT_Y, 0, 100);
		plot_line(s, t, y1, (size_t)n, NULL, REP_COL_CUSTOM, PLOT_DASH_SOLID);
		plot_hline(s, 100.0 * c->reserve_soc,
		           report_sfmt(&sb, "reserve %s %%", report_num(b1, sizeof b1, 100.0 * c->reserve_soc, 0)),
		           PLOT_COLOUR_WARN, PLOT_DASH_DASHED);
		phase_marks(s, c, 0);

		plot_title(i, "Battery current");
		plot_axis_title(i, PLOT_X, "Time (s)");
		plot_axis_title(i, PLOT_Y, "Current (A)");
		for (int k = 0; k < n; k++)
			y1[k] = c->trace[k].current_a;
		plot_line(i, t, y1, (size_t)n, NULL, REP_COL_CUSTOM, PLOT_DASH_SOLID);
		phase_marks(i, c, 0);

		doc_figure(rp->d, p, "Discharge of the custom run over the mission: battery temperature with "
		           "the 60 °C runaway limit, terminal and open-circuit voltage with the voltage floor, "
		           "state of charge with the reserve, and battery current; dotted lines mark the phase "
		           "changes.");
		plot_free(p);
		free(t);
		free(y1);
		free(y2);
	}
	char *v0 = xstrdup(report_sfmt(&sb, "%s °C (margin %s °C to 60 °C)",
	                               report_num(b1, sizeof b1, c->max_battery_temp_c, 1),
	                               report_num(b2, sizeof b2, c->thermal_margin_c, 1)));
	char *v1 = xstrdup(report_sfmt(&sb, "%s V (floor %s V)", report_num(b1, sizeof b1, c->min_terminal_voltage_v, 2),
	                        report_num(b2, sizeof b2, c->voltage_floor_v, 2)));
	char *v2 = xstrdup(report_sfmt(&sb, "%s %% (reserve %s %%)", report_num(b1, sizeof b1, 100.0 * c->end_soc, 1),
	                        report_num(b2, sizeof b2, 100.0 * c->reserve_soc, 1)));
	char *v3 = xstrdup(report_sfmt(&sb, "%s A (%s C)", report_num(b1, sizeof b1, c->peak_current_a, 1),
	                        report_num(b2, sizeof b2, c->peak_c_rate, 1)));
	char *v4 = xstrdup(c->motor_copper_loss_w > 0
	                   ? report_sfmt(&sb, "%s °C assumed; copper loss %s W per motor at hover",
	                          report_num(b1, sizeof b1, c->winding_temp_c, 0),
	                          report_num(b2, sizeof b2, c->motor_copper_loss_w, 1))
	                   : report_sfmt(&sb, "%s °C assumed (ambient + 40 K)", report_num(b1, sizeof b1, c->winding_temp_c, 0)));
	const char *rows[] = { "Peak battery temperature", v0, "Minimum terminal voltage", v1,
	                       "State of charge at landing", v2, "Full-throttle current", v3,
	                       "Motor winding temperature", v4 };
	doc_kv_table(rp->d, rows, 5);
	free(v0);
	free(v1);
	free(v2);
	free(v3);
	free(v4);
	strbuf_free(&sb);
}

/* ---- 7 structure and resonance ------------------------------------------ */

/* One run's arm tube: geometry, stress against allowable, tip mass, first
 * mode and resonance margin; failing margins in the fail colour. */
static void
arm_row(struct doc_table *t, const char *name, const struct res_run *run)
{
	double margin = report_div(run->arm_stress_allow_mpa - run->arm_stress_mpa, run->arm_stress_allow_mpa);
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", name);
	report_cell_num(t, DOC_CELL_NORMAL, 1000.0 * run->arm_length_m, 0);
	report_cell_num(t, DOC_CELL_NORMAL, run->arm_outer_diameter_mm, 1);
	report_cell_num(t, DOC_CELL_NORMAL, run->arm_wall_thickness_mm, 2);
	report_cell_num(t, DOC_CELL_NORMAL, run->arm_stress_mpa, 0);
	report_cell_num(t, DOC_CELL_NORMAL, run->arm_stress_allow_mpa, 0);
	report_cell_num(t, margin < 0 ? DOC_CELL_FAIL : DOC_CELL_NORMAL, 100.0 * margin, 1);
	report_cell_num(t, DOC_CELL_NORMAL, 1000.0 * run->arm_tip_mass_kg, 0);
	report_cell_num(t, DOC_CELL_NORMAL, run->arm_natural_frequency_hz, 1);
	report_cell_num(t, run->resonance_margin < 0 ? DOC_CELL_FAIL : DOC_CELL_NORMAL,
	                100.0 * run->resonance_margin, 0);
}

/* Section 7: arm sizing table and the resonance figure (frequency vs rotor
 * speed) that shows where the arm mode sits against the blade-pass band. */
void
report_sec_structure(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *c = &r->custom;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48], b4[48];
	report_heading(rp, title);
	doc_paragraph(rp->d, "Each arm is a carbon-fibre tube sized as a cantilever for root bending "
	              "under the role's load factor; its first bending mode must sit 1.5× clear of the "
	              "blade-pass frequencies the rotors sweep in flight (from 0.7 × hover rpm up to full "
	              "throttle): either stiffer than 1.5 × the highest, or softer than the lowest / 1.5.");
	static const struct doc_column cols[] = {
		{ "Run", 1.0, DOC_ALIGN_LEFT }, { "Length (mm)", 0.9, DOC_ALIGN_RIGHT },
		{ "OD (mm)", 0.75, DOC_ALIGN_RIGHT }, { "Wall (mm)", 0.75, DOC_ALIGN_RIGHT },
		{ "Stress (MPa)", 0.85, DOC_ALIGN_RIGHT }, { "Allow. (MPa)", 0.85, DOC_ALIGN_RIGHT },
		{ "Margin (%)", 0.8, DOC_ALIGN_RIGHT }, { "Tip mass (g)", 0.85, DOC_ALIGN_RIGHT },
		{ "f1 (Hz)", 0.7, DOC_ALIGN_RIGHT }, { "Res. margin (%)", 0.95, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 10);
	arm_row(&t, "Baseline", &r->baseline);
	arm_row(&t, "Custom", c);
	if (r->parts_selected && r->closed.ran)
		arm_row(&t, "Real parts", &r->closed);
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	if (c->arm_wall_floor_binds)
		doc_paragraph(rp->d, "In the custom run the minimum manufacturable wall thickness binds: the "
		              "arm is stronger than bending alone requires, which shows as a stress margin.");
	if (c->min_fraction_binds)
		doc_paragraph(rp->d, "In the custom run the minimum structural mass fraction for this wheelbase "
		              "binds: the frame mass is raised to it, beyond what the arm sizing needs.");

	/* Blades per rotor as the engine used them: f_bpf = N_b rpm / 60. */
	double n_b = c->rpm_peak > 0 ? c->blade_pass_frequency_hz / (c->rpm_peak / 60.0)
	                             : (double)r->mission.structural_overrides.num_blades;
	if (!(n_b > 0))
		n_b = 2;
	double rpm_top = c->rpm_peak > 0 ? 1.05 * c->rpm_peak : 1.0;
	double rpm[REP_RPM_POINTS], f[REP_RPM_POINTS], lo[REP_RPM_POINTS], hi[REP_RPM_POINTS];
	for (int k = 0; k < REP_RPM_POINTS; k++) {
		rpm[k] = rpm_top * k / (REP_RPM_POINTS - 1);
		f[k] = n_b * rpm[k] / 60.0;
		lo[k] = f[k] / REP_RESONANCE_FACTOR;
		hi[k] = f[k] * REP_RESONANCE_FACTOR;
	}
	double rpm_low = c->blade_pass_low_hz * 60.0 / n_b;
	struct plot *p = plot_alloc(0, 260, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Rotor speed (rpm)");
	plot_axis_title(pp, PLOT_Y, "Frequency (Hz)");
	double ftop = fmax(REP_RESONANCE_FACTOR * c->blade_pass_frequency_hz, c->arm_natural_frequency_hz);
	plot_axis_range(pp, PLOT_X, 0, rpm_top);
	plot_axis_range(pp, PLOT_Y, 0, 1.15 * (ftop > 0 ? ftop : 1.0));
	plot_band(pp, rpm, lo, hi, REP_RPM_POINTS, "blade pass ÷1.5 … ×1.5", PLOT_COLOUR_MUTED, 0.18);
	if (rpm_low > 0 && rpm_low < c->rpm_peak) {
		/* The zone the arm mode must avoid, over the in-flight rpm range. */
		double bx[2] = { rpm_low, c->rpm_peak };
		double by_lo[2] = { c->blade_pass_low_hz / REP_RESONANCE_FACTOR,
		                    c->blade_pass_low_hz / REP_RESONANCE_FACTOR };
		double by_hi[2] = { REP_RESONANCE_FACTOR * c->blade_pass_frequency_hz,
		                    REP_RESONANCE_FACTOR * c->blade_pass_frequency_hz };
		plot_band(pp, bx, by_lo, by_hi, 2, "excluded for the arm mode (in flight)", PLOT_COLOUR_FAIL, 0.10);
	}
	plot_line(pp, rpm, f, REP_RPM_POINTS, report_sfmt(&sb, "blade pass N_b·rpm/60 (N_b = %.0f)", n_b),
	          REP_COL_CUSTOM, PLOT_DASH_SOLID);
	plot_hline(pp, c->arm_natural_frequency_hz,
	           report_sfmt(&sb, "arm first mode %s Hz", report_num(b1, sizeof b1, c->arm_natural_frequency_hz, 1)),
	           PLOT_COLOUR_ACCENT, PLOT_DASH_SOLID);
	plot_vline(pp, c->rpm_hover, report_sfmt(&sb, "hover %s rpm", report_num(b1, sizeof b1, c->rpm_hover, 0)),
	           PLOT_COLOUR_MUTED, PLOT_DASH_DASHED);
	plot_vline(pp, c->rpm_peak, report_sfmt(&sb, "full throttle %s rpm", report_num(b1, sizeof b1, c->rpm_peak, 0)),
	           PLOT_COLOUR_MUTED, PLOT_DASH_DASHED);
	plot_legend(pp, PLOT_LEGEND_BELOW);
	doc_figure(rp->d, p, report_sfmt(&sb, "Resonance check of the custom arm: blade-pass frequency over the "
	           "rotor-speed range with its 1.5× margins, the in-flight band %s–%s Hz and the arm's first "
	           "bending mode at %s Hz (resonance margin %s %%).",
	           report_num(b1, sizeof b1, c->blade_pass_low_hz, 0),
	           report_num(b2, sizeof b2, c->blade_pass_frequency_hz, 0),
	           report_num(b3, sizeof b3, c->arm_natural_frequency_hz, 1),
	           report_num(b4, sizeof b4, 100.0 * c->resonance_margin, 0)));
	plot_free(p);
	strbuf_free(&sb);
}

/* ---- 8 propulsion selection --------------------------------------------- */

/* qsort order for doubles, ascending. */
static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The motor crosshair: the usable catalogue as a muted cloud, the scored
 * candidates coloured by J-score tercile (pruned ones as crosses), the
 * continuous optimum as a crosshair and the chosen motor in the custom
 * colour.  Both axes are logarithmic: catalogues span decades of KV. */
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
		double mkv = 0.0;
		for (int i = 0; i < n_cand; i++)
			if (strcmp(r->candidates[i].id, r->motor.id) == 0)
				mkv = r->candidates[i].kv;
		const struct catalog_motor *m = cat != NULL ? catalog_find_motor(cat, r->motor.id) : NULL;
		if (m != NULL)
			mkv = m->kv_rpm_per_v;
		double mg = 1000.0 * r->motor.unit_mass_kg;
		if (mkv > 0) {
			struct plot_style st = { .colour = REP_COL_CUSTOM, .line_width_pt = -1,
			                         .marker = PLOT_MARKER_SQUARE, .marker_size_pt = 8 };
			plot_series(pp, &mkv, &mg, 1, "chosen motor", &st);
			plot_point_label(pp, mkv, mg, report_sfmt(&sb, "%s (J = %s)", r->motor.part_number,
			                                   report_num(b1, sizeof b1, r->motor.j_score, 3)));
		}
	}
	const char *cap;
	if (r->parts_selected)
		cap = report_sfmt(&sb, "Motor selection: every usable catalogue motor by KV and mass (log axes), the "
		           "scored candidates coloured by J-score, the continuous optimum (crosshair) and the "
		           "chosen %s %s.", r->motor.manufacturer, r->motor.part_number);
	else
		cap = report_sfmt(&sb, "Motor selection: every usable catalogue motor by KV and mass (log axes) and the "
		           "continuous optimum (crosshair). No part was selected%s.",
		           cat == NULL ? " (no catalogue loaded)" : "");
	doc_figure(rp->d, p, cap);
	plot_free(p);
	strbuf_free(&sb);
}

/* One eCalc-style operating point. */
struct op_point {
	const char *name;
	double current_a, power_w, shaft_w, rpm, throttle, thrust_n, tip_mach;
	int shaft_estimated;      /* shaft power not simulated, estimated */
};

/* The operating-point table eCalc users know: hover, climb, cruise and full
 * throttle, derived from the phases and the peak values of the custom run. */
static void
op_table(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct res_run *c = &r->custom;
	double n_rot = r->mission.num_rotors;
	struct op_point op[4];
	static const int ph[3] = { PHASE_HOVER, PHASE_CLIMB, PHASE_FORWARD };
	static const char *const names[3] = { "Hover", "Climb", "Cruise" };
	int n = 0;
	for (int k = 0; k < 3; k++) {
		const struct res_phase *x = &c->phase[ph[k]];
		if (x->duration_s <= 0 && ph[k] != PHASE_HOVER)
			continue;
		op[n++] = (struct op_point){ names[k], x->current_a, x->power_w, x->shaft_power_w, x->rpm,
		                             x->throttle, x->thrust_per_rotor_n * n_rot, x->tip_mach, 0 };
	}
	/* Full throttle: battery power and current are simulated; the shaft
	 * power is estimated through the drive efficiency after the aux load. */
	double eta = r->mission.aerodynamic_overrides.propulsive_efficiency;
	double shaft = fmax(0.0, c->peak_power_w - r->mission.payload_role.aux_power_w) * eta;
	op[n++] = (struct op_point){ "Full throttle", c->peak_current_a, c->peak_power_w, shaft,
	                             c->rpm_peak, 1.0, c->thrust_to_weight * c->mass.total_kg * G0_M_S2,
	                             c->tip_mach_peak, 1 };
	static const struct doc_column cols[] = {
		{ "Point", 1.2, DOC_ALIGN_LEFT }, { "I (A)", 0.75, DOC_ALIGN_RIGHT },
		{ "U (V)", 0.7, DOC_ALIGN_RIGHT }, { "rpm", 0.75, DOC_ALIGN_RIGHT },
		{ "Thr. (%)", 0.7, DOC_ALIGN_RIGHT }, { "P el. (W)", 0.85, DOC_ALIGN_RIGHT },
		{ "P shaft (W)", 0.9, DOC_ALIGN_RIGHT }, { "η (%)", 0.6, DOC_ALIGN_RIGHT },
		{ "g/W", 0.6, DOC_ALIGN_RIGHT }, { "C-load", 0.7, DOC_ALIGN_RIGHT },
		{ "Tip M", 0.6, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 11);
	double cap_ah = c->capacity_mah / 1000.0;
	for (int k = 0; k < n; k++) {
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", op[k].name);
		report_cell_num(&t, DOC_CELL_NORMAL, op[k].current_a, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, report_div(op[k].power_w, op[k].current_a), 1);
		report_cell_num(&t, DOC_CELL_NORMAL, op[k].rpm, 0);
		report_cell_num(&t, DOC_CELL_NORMAL, 100.0 * op[k].throttle, 0);
		report_cell_num(&t, DOC_CELL_NORMAL, op[k].power_w, 0);
		char b[48];
		doc_table_cell(&t, op[k].shaft_estimated ? DOC_CELL_MUTED : DOC_CELL_NORMAL, "%s%s",
		               report_num(b, sizeof b, op[k].shaft_w, 0), op[k].shaft_estimated ? "*" : "");
		report_cell_num(&t, DOC_CELL_NORMAL, 100.0 * report_div(op[k].shaft_w, op[k].power_w), 0);
		report_cell_num(&t, DOC_CELL_NORMAL, report_div(1000.0 * op[k].thrust_n / G0_M_S2, op[k].power_w), 2);
		report_cell_num(&t, DOC_CELL_NORMAL, report_div(op[k].current_a, cap_ah), 1);
		report_cell_num(&t, DOC_CELL_NORMAL, op[k].tip_mach, 2);
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	doc_paragraph(rp->d, "Battery current and voltage at the pack; η is shaft over electrical power "
	              "(the electrical power includes the auxiliary load); g/W is total thrust per "
	              "electrical watt; C-load is current over pack capacity. *Shaft power at full throttle "
	              "is estimated as (battery power − auxiliary load) × drive efficiency.");
}

/* The custom check whose name starts with prefix, or NULL. */
static const struct res_check *
find_check(const struct res_run *run, const char *prefix)
{
	for (int i = 0; i < run->n_checks && i < RES_MAX_CHECKS; i++)
		if (strncmp(run->checks[i].name, prefix, strlen(prefix)) == 0)
			return &run->checks[i];
	return NULL;
}

/* The three feasibility gates (overlap, tip Mach, downwash) as the checks
 * recorded them; downwash is limited only for agriculture. */
static void
gate_table(struct rep *rp)
{
	const struct res_run *c = &rp->r->custom;
	static const struct doc_column cols[] = {
		{ "Gate", 2.6, DOC_ALIGN_LEFT }, { "Value", 1.0, DOC_ALIGN_RIGHT },
		{ "Limit", 1.0, DOC_ALIGN_RIGHT }, { "Result", 0.8, DOC_ALIGN_CENTER },
	};
	static const char *const gates[3][2] = {
		{ "Propeller diameter", "Rotor overlap: propeller diameter (in)" },
		{ "Tip Mach", "Tip Mach number at full throttle" },
		{ "Downwash", "Downwash, crop and drift (m/s)" },
	};
	char b1[48];
	struct doc_table t;
	doc_table_init(&t, cols, 4);
	for (int k = 0; k < 3; k++) {
		const struct res_check *ck = find_check(c, gates[k][0]);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", gates[k][1]);
		if (ck == NULL) {
			/* Downwash is only limited for agriculture. */
			doc_table_cell(&t, DOC_CELL_MUTED, "%s", k == 2 ? report_num(b1, sizeof b1, c->downwash_ms, 1) : "—");
			doc_table_cell(&t, DOC_CELL_MUTED, "none");
			doc_table_cell(&t, DOC_CELL_MUTED, "n/a");
			continue;
		}
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_auto(b1, sizeof b1, ck->value));
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_auto(b1, sizeof b1, ck->limit));
		doc_table_cell(&t, ck->pass ? DOC_CELL_PASS : DOC_CELL_FAIL, "%s", ck->pass ? "PASS" : "FAIL");
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
}

/* Section 8: continuous optimum, motor crosshair, operating points and the
 * feasibility gates. */
void
report_sec_propulsion(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *c = &r->custom;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	report_heading(rp, title);
	report_subheading(rp, "Continuous optimum", REP_KEEP_PT);
	doc_paragraph(rp->d, "The sizing loop produces a continuous design; the parts search looks for "
	              "catalogue parts nearest to it.");
	char *v[12];
	v[0] = xstrdup(report_sfmt(&sb, "%s × %s in (overlap limit %s in)", report_num(b1, sizeof b1, c->opt.prop_diameter_in, 1),
	                    report_num(b2, sizeof b2, c->opt.prop_pitch_in, 1),
	                    report_num(b3, sizeof b3, c->overlap_limit_in, 1)));
	v[1] = xstrdup(report_sfmt(&sb, "%s rpm/V", report_num(b1, sizeof b1, c->opt.motor_kv, 0)));
	v[2] = xstrdup(report_sfmt(&sb, "%s g each (scaling law)", report_num(b1, sizeof b1, 1000.0 * c->opt.motor_mass_kg, 0)));
	v[3] = xstrdup(report_sfmt(&sb, "%s A, %s W per motor", report_num(b1, sizeof b1, c->opt.motor_peak_current_a, 1),
	                    report_num(b2, sizeof b2, c->opt.motor_peak_power_w, 0)));
	v[4] = xstrdup(report_sfmt(&sb, "%s rpm hover, %s rpm full throttle", report_num(b1, sizeof b1, c->rpm_hover, 0),
	                    report_num(b2, sizeof b2, c->rpm_peak, 0)));
	v[5] = xstrdup(report_sfmt(&sb, "%s installed (interference k_int %s)", report_num(b1, sizeof b1, c->fom_installed, 3),
	                    report_num(b2, sizeof b2, c->interference, 3)));
	v[6] = xstrdup(report_sfmt(&sb, "%s N/m², downwash %s m/s", report_num(b1, sizeof b1, c->disk_loading_n_m2, 0),
	                    report_num(b2, sizeof b2, c->downwash_ms, 1)));
	v[7] = xstrdup(report_sfmt(&sb, "%s (Reynolds at the tip %s)", report_num(b1, sizeof b1, c->tip_mach_peak, 2),
	                    report_auto(b2, sizeof b2, c->reynolds_tip)));
	if (c->pack_count > 1)
		snprintf(b3, sizeof b3, "%dS%dP", c->cell_count, c->pack_count);
	else
		snprintf(b3, sizeof b3, "%dS", c->cell_count);
	v[8] = xstrdup(report_sfmt(&sb, "%s %s, %s mAh, %s V nominal", b3, c->chemistry,
	                    report_num(b1, sizeof b1, c->capacity_mah, 0), report_num(b2, sizeof b2, c->nominal_voltage_v, 1)));
	const char *kv[] = {
		"Propeller", v[0], "Motor KV", v[1], "Motor mass", v[2], "Motor peak load", v[3],
		"Rotor speed", v[4], "Figure of merit", v[5], "Disk loading", v[6], "Tip Mach (full throttle)", v[7],
		"Battery", v[8],
	};
	doc_kv_table(rp->d, kv, 9);
	for (int i = 0; i < 9; i++)
		free(v[i]);

	report_subheading(rp, "Motor selection", REP_KEEP_PT);
	if (!r->parts_selected)
		doc_paragraph(rp->d, "No catalogue parts were selected; the figure places the continuous "
		              "optimum among the catalogue's motors for orientation.");
	motor_figure(rp);
	if (r->parts_selected && r->prop.chosen)
		doc_paragraph(rp->d, report_sfmt(&sb, "Propeller: %s %s (J = %s), %d per aircraft.", r->prop.manufacturer,
		              r->prop.part_number, report_num(b1, sizeof b1, r->prop.j_score, 3), r->prop.qty));

	/* Keep the operating-point table with its heading and note (about
	 * 200 pt): a lone row on the next page reads badly. */
	report_subheading(rp, "Operating points (custom run)", 210.0);
	op_table(rp);
	report_subheading(rp, "Feasibility gates", REP_KEEP_PT);
	gate_table(rp);
	strbuf_free(&sb);
}

/* ---- 9 convergence -------------------------------------------------------- */

/* One run's mass history against iteration number. */
static void
history_series(struct plot_panel *pp, const struct res_run *run, const char *label, int colour,
               enum plot_marker mk)
{
	int n = dmin_i(run->n_history, RES_MAX_HISTORY);
	if (n <= 0)
		return;
	double *it = xcalloc((size_t)n, sizeof *it);
	for (int i = 0; i < n; i++)
		it[i] = i + 1;
	struct plot_style st = { .colour = colour, .marker = mk, .marker_size_pt = 2.5,
	                         .open_marker = 1 };
	plot_series(pp, it, run->history_kg, (size_t)n, label, &st);
	free(it);
}

/* One run's loop statistics; a run the gate stopped shows "not run". */
static void
conv_row(struct doc_table *t, const char *name, const struct res_run *run)
{
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", name);
	if (!run->ran) {
		doc_table_cell(t, DOC_CELL_MUTED, "—");
		doc_table_cell(t, DOC_CELL_FAIL, "not run");
		doc_table_cell(t, DOC_CELL_MUTED, "—");
		doc_table_cell(t, DOC_CELL_MUTED, "—");
	} else {
		doc_table_cell(t, DOC_CELL_NORMAL, "%d", run->iterations);
		doc_table_cell(t, run->converged ? DOC_CELL_PASS : DOC_CELL_FAIL, "%s", run->converged ? "yes" : "no");
		report_cell_num(t, run->lipschitz < 1.0 ? DOC_CELL_NORMAL : DOC_CELL_FAIL, run->lipschitz, 3);
		report_cell_num(t, run->time_scale < 1.0 ? DOC_CELL_WARN : DOC_CELL_NORMAL, run->time_scale, 2);
	}
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", run->termination[0] != '\0' ? run->termination : "—");
}

/* Section 9: mass history of both runs, tolerance, Lipschitz estimates,
 * iterations, goal relaxation and termination. */
void
report_sec_convergence(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	int closed = r->parts_selected && r->closed.ran;
	struct strbuf sb = STRBUF_INIT;
	report_heading(rp, title);
	doc_paragraph(rp->d, report_sfmt(&sb, "The takeoff mass is found by fixed-point iteration: each pass sizes "
	              "battery, propulsion and structure for the current mass and sums them into the next. "
	              "The loop stops when the mass changes by less than %.0f g between iterations. The "
	              "Lipschitz estimate dF/dM at the fixed point must be below 1 for the loop to "
	              "contract; the closer to 1, the more every added gram costs.", 1000.0 * r->custom.tolerance_kg));
	struct plot *p = plot_alloc(0, 240, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Iteration");
	plot_axis_title(pp, PLOT_Y, "Takeoff mass (kg)");
	/* Markers show the individual iterations while they stay apart. */
	int n_max = dmin_i(RES_MAX_HISTORY, fmax(r->baseline.n_history, r->custom.n_history));
	int mk = n_max <= 80;
	history_series(pp, &r->baseline, "Baseline", REP_COL_BASELINE, mk ? PLOT_MARKER_CIRCLE : PLOT_MARKER_NONE);
	history_series(pp, &r->custom, "Custom", REP_COL_CUSTOM, mk ? PLOT_MARKER_SQUARE : PLOT_MARKER_NONE);
	if (closed)
		history_series(pp, &r->closed, "Custom, real parts", REP_COL_CLOSED,
		               mk ? PLOT_MARKER_TRIANGLE : PLOT_MARKER_NONE);
	doc_figure(rp->d, p, "Takeoff mass per iteration of the mass loop, baseline and custom runs.");
	plot_free(p);

	static const struct doc_column cols[] = {
		{ "Run", 1.2, DOC_ALIGN_LEFT }, { "Iterations", 1.0, DOC_ALIGN_RIGHT },
		{ "Converged", 1.05, DOC_ALIGN_CENTER }, { "Lipschitz", 0.95, DOC_ALIGN_RIGHT },
		{ "Goal γ", 0.8, DOC_ALIGN_RIGHT }, { "Termination", 2.8, DOC_ALIGN_LEFT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 6);
	conv_row(&t, "Baseline", &r->baseline);
	conv_row(&t, "Custom", &r->custom);
	if (closed)
		conv_row(&t, "Custom, real parts", &r->closed);
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	doc_paragraph(rp->d, "Goal γ is the factor the mission times were scaled by to close the design "
	              "(1 = as requested; below 1 only when the mission allows automatic reduction).");
	/* A sudden fall in the history is the loop restarting from its seed
	 * after a discrete change (the cell count); say so, or it looks odd. */
	int restarts = 0;
	const struct res_run *runs[2] = { &r->baseline, &r->custom };
	for (int k = 0; k < 2; k++)
		for (int i = 1; i < dmin_i(runs[k]->n_history, RES_MAX_HISTORY); i++)
			if (runs[k]->history_kg[i] < 0.9 * runs[k]->history_kg[i - 1])
				restarts++;
	if (restarts > 0)
		doc_paragraph(rp->d, "The sudden drops in the history are restarts: when the solver changes a "
		              "discrete choice such as the series cell count, the loop starts again from its "
		              "seed mass with the new choice.");
	strbuf_free(&sb);
}

/* ---- 10 endurance explorer ------------------------------------------------ */

/* One run's explorer points on both panels (time on top, mass below). */
static void
endurance_series(struct plot_panel *pt, struct plot_panel *pm, const struct res_run *run,
                 const char *label, int colour)
{
	int n = dmin_i(run->n_endurance, RES_MAX_ENDURANCE);
	if (n <= 0)
		return;
	double tmin[RES_MAX_ENDURANCE];
	for (int i = 0; i < n; i++)
		tmin[i] = run->endurance_time_s[i] / 60.0;
	struct plot_style st = { .colour = colour, .marker = PLOT_MARKER_CIRCLE, .marker_size_pt = 3.0 };
	plot_series(pt, run->endurance_scale, tmin, (size_t)n, label, &st);
	plot_series(pm, run->endurance_scale, run->endurance_mass_kg, (size_t)n, label, &st);
}

/* Section 10: hover endurance and takeoff mass against capacity scale,
 * with the design point and the mass-growth inflection. */
void
report_sec_endurance(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *c = &r->custom;
	struct strbuf sb = STRBUF_INIT;
	char b1[48];
	report_heading(rp, title);
	doc_paragraph(rp->d, "Hover endurance to the reserve against battery capacity: each point re-sizes "
	              "the aircraft with the battery capacity scaled by the factor on the x axis (1 = the "
	              "design) and the cell count kept. More battery hovers longer, but the mass it adds "
	              "needs more power; past the inflection each extra watt-hour buys less than half the "
	              "time the first ones did.");
	if (c->n_endurance <= 0 && r->baseline.n_endurance <= 0) {
		doc_paragraph(rp->d, "The endurance explorer did not run for this design.");
		strbuf_free(&sb);
		return;
	}
	struct plot *p = plot_alloc(0, 380, 2, 1);
	struct plot_panel *pt = plot_panel(p, 0, 0), *pm = plot_panel(p, 1, 0);
	plot_axis_title(pt, PLOT_Y, "Hover endurance (min)");
	plot_axis_title(pm, PLOT_X, "Battery capacity scale");
	plot_axis_title(pm, PLOT_Y, "Takeoff mass (kg)");
	endurance_series(pt, pm, &r->baseline, "Baseline", REP_COL_BASELINE);
	endurance_series(pt, pm, c, "Custom", REP_COL_CUSTOM);
	/* The design point as a marker on the curves (its label would collide
	 * with the inflection line's, which often sits close to 1). */
	plot_vline(pt, 1.0, NULL, PLOT_COLOUR_ACCENT, PLOT_DASH_DASHED);
	plot_vline(pm, 1.0, NULL, PLOT_COLOUR_ACCENT, PLOT_DASH_DASHED);
	double one = 1.0, t1 = c->hover_endurance_s / 60.0, m1 = c->mass.total_kg;
	struct plot_style dp = { .colour = PLOT_COLOUR_ACCENT, .line_width_pt = -1,
	                         .marker = PLOT_MARKER_DIAMOND, .marker_size_pt = 7 };
	plot_series(pt, &one, &t1, 1, report_sfmt(&sb, "design point (%s min)", report_num(b1, sizeof b1, t1, 1)), &dp);
	plot_series(pm, &one, &m1, 1, report_sfmt(&sb, "design point (%s kg)", report_num(b1, sizeof b1, m1, 2)), &dp);
	if (c->endurance_inflection_scale > 0) {
		plot_vline(pt, c->endurance_inflection_scale,
		           report_sfmt(&sb, "inflection ×%s", report_num(b1, sizeof b1, c->endurance_inflection_scale, 2)),
		           PLOT_COLOUR_WARN, PLOT_DASH_DOTTED);
		plot_vline(pm, c->endurance_inflection_scale, NULL, PLOT_COLOUR_WARN, PLOT_DASH_DOTTED);
	}
	doc_figure(rp->d, p, c->endurance_inflection_scale > 0
	           ? report_sfmt(&sb, "Endurance explorer: hover endurance (top) and takeoff mass (bottom) vs battery "
	                  "capacity scale; the design point is at 1, the custom run's mass-growth inflection at "
	                  "×%s.", report_num(b1, sizeof b1, c->endurance_inflection_scale, 2))
	           : "Endurance explorer: hover endurance (top) and takeoff mass (bottom) vs battery capacity "
	             "scale; the design point is at 1, no inflection inside the explored range.");
	plot_free(p);
	strbuf_free(&sb);
}
