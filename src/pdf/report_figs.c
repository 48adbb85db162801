/* report_figs.c — the dossier sections built around figures: mission and
 * energy, thermal and electrical traces, structure and resonance,
 * convergence and the endurance explorer.  Each shows the design of
 * record, with the continuous optimum and the baseline as references.
 *
 * Colours by design (report.h): baseline palette 0, continuous optimum
 * palette 1, design of record palette 2; limits in the fail colour, design
 * points and optima in the accent colour.
 */
#include "pdf/report_figs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "result/checks.h"
#include "spec/model.h"
#include "pdf/doc.h"
#include "pdf/plot.h"
#include "pdf/report_util.h"
#include "util/strbuf.h"
#include "util/xalloc.h"

/* Points of the resonance figure's rpm axis. */
#define REP_RPM_POINTS 64
/* The structure module's resonance rule: the arm mode must sit 1.5x clear
 * of the in-flight blade-pass band (structure.h, STRUCT_RESONANCE_MARGIN). */
#define REP_RESONANCE_FACTOR 1.5

/* Room a phase table needs under its heading: header, three phases and
 * the mission total, pt. */
#define REP_PHASE_PT 130.0

/* Phase names for table rows (res_phase_name is the lower-case key). */
static const char *const phase_title[PHASE_MAX] = { "Climb", "Forward", "Hover" };

static int
dmin_i(int a, int b)
{
	return a < b ? a : b;
}

/* The palette colour of the design of record (the continuous one when no
 * parts closed, which then is the record). */
static int
rec_colour(const struct rep *rp)
{
	return rp->buildable ? REP_COL_CLOSED : REP_COL_CUSTOM;
}

/* ---- mission and energy ------------------------------------------------------ */

/* One design's phases as a table, phases not flown left out, with the
 * mission totals of time and energy. */
static void
phase_table(struct rep *rp, const struct res_run *run)
{
	static const struct doc_column cols[] = {
		{ "Phase", 1.15, DOC_ALIGN_LEFT }, { "Time (s)", 0.85, DOC_ALIGN_RIGHT },
		{ "v (m/s)", 0.75, DOC_ALIGN_RIGHT }, { "T/rotor (N)", 0.95, DOC_ALIGN_RIGHT },
		{ "P shaft (W)", 0.95, DOC_ALIGN_RIGHT }, { "P el. (W)", 0.9, DOC_ALIGN_RIGHT },
		{ "Mean I (A)", 0.8, DOC_ALIGN_RIGHT }, { "E (Wh)", 0.8, DOC_ALIGN_RIGHT },
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

static void
sweep_line(struct plot_panel *pp, const struct res_run *run, const char *label, int colour)
{
	plot_line(pp, run->sweep_v_ms, run->sweep_power_w, (size_t)dmin_i(run->n_sweep, RES_MAX_SWEEP),
	          label, colour, PLOT_DASH_SOLID);
}

/* The power-vs-speed figure: the three designs' sweeps, the record's
 * minimum-power speed, flown speed and highest speed marked. */
static void
sweep_figure(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct res_run *rec = rp->rec;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	struct plot *p = plot_alloc(0, 250, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Forward speed (m/s)");
	plot_axis_title(pp, PLOT_Y, "Electrical power (W)");
	const struct res_run *runs[3] = { &r->baseline, &r->custom, rec };
	double vtop = rec->v_max_ms;
	for (int k = 0; k < 3; k++)
		for (int i = 0; i < dmin_i(runs[k]->n_sweep, RES_MAX_SWEEP); i++)
			vtop = fmax(vtop, runs[k]->sweep_v_ms[i]);
	if (vtop > 0)
		plot_axis_range(pp, PLOT_X, 0, vtop + 1.0);
	sweep_line(pp, &r->baseline, REP_NAME_BASELINE, REP_COL_BASELINE);
	sweep_line(pp, &r->custom, report_continuous_name(rp), REP_COL_CUSTOM);
	if (rp->buildable)
		sweep_line(pp, rec, REP_NAME_RECORD, REP_COL_CLOSED);
	if (rec->v_min_power_ms > 0)
		plot_vline(pp, rec->v_min_power_ms,
		           report_sfmt(&sb, "minimum power %s m/s", report_num(b1, sizeof b1, rec->v_min_power_ms, 1)),
		           PLOT_COLOUR_ACCENT, PLOT_DASH_DASHED);
	if (rec->v_max_ms > 0)
		plot_vline(pp, rec->v_max_ms, report_sfmt(&sb, "v max %s m/s", report_num(b1, sizeof b1, rec->v_max_ms, 1)),
		           PLOT_COLOUR_FAIL, PLOT_DASH_DOTTED);
	double fv = rec->optimal_speed_ms;
	double fp = interp(rec->sweep_v_ms, rec->sweep_power_w, dmin_i(rec->n_sweep, RES_MAX_SWEEP), fv);
	if (isfinite(fp)) {
		struct plot_style st = { .colour = rec_colour(rp), .line_width_pt = -1,
		                         .marker = PLOT_MARKER_DIAMOND, .marker_size_pt = 7 };
		plot_series(pp, &fv, &fp, 1, "flown speed", &st);
		plot_point_label(pp, fv, fp, report_sfmt(&sb, "%s m/s, %s W", report_num(b1, sizeof b1, fv, 1),
		                 report_num(b2, sizeof b2, fp, 0)));
	}
	doc_figure(rp->d, p, report_sfmt(&sb, "Electrical power required vs forward speed at takeoff mass; "
	           "for the %s the minimum-power speed (%s m/s), the flown speed (%s m/s) and the highest "
	           "speed (%s m/s, %s).", rp->buildable ? "design of record" : "continuous design",
	           report_num(b1, sizeof b1, rec->v_min_power_ms, 1), report_num(b2, sizeof b2, fv, 1),
	           report_num(b3, sizeof b3, rec->v_max_ms, 1),
	           report_limit_phrase(rec->v_max_limit, false)));
	plot_free(p);
	strbuf_free(&sb);
}

/* The duty cycle the design of record flew, in one paragraph (nothing
 * for the paper's three phases, which the next paragraph states). */
static void
duty_paragraph(struct rep *rp)
{
	const struct res_run *rec = rp->rec;
	const struct res_duty *d = &rec->duty;
	const struct mission_spec *s = &rp->r->mission;
	struct strbuf sb = STRBUF_INIT, tail = STRBUF_INIT, mid = STRBUF_INIT;
	char b[8][48];
	double reserve = 100.0 * rec->reserve_soc;
	report_sfmt(&tail, " The pack lands at %s" NBSP "%% charge (reserve %s" NBSP "%%) and "
	    "peaks at %s" NBSP "°C in %s" NBSP "°C air. The profile and its sources are in "
	    "data/roles.json; result.json lists every segment (duty_profile).",
	    report_num(b[6], sizeof b[6], 100.0 * rec->end_soc, 0),
	    report_num(b[7], sizeof b[7], reserve, 0),
	    report_num(b[4], sizeof b[4], rec->max_battery_temp_c, 1),
	    report_num(b[5], sizeof b[5], s->ambient_temp_c, 1));
	switch (d->kind) {
	case DUTY_RACE:
		doc_paragraph(rp->d, report_sfmt(&sb, "The forward time is flown as a race: %d laps "
		    "of %s" NBSP "s, each a full-throttle burst, a high-speed run and a corner, drawing "
		    "%s" NBSP "W on average (%s" NBSP "%% of the %s" NBSP "W full-throttle power) and "
		    "%s" NBSP "A from the pack; the climb and the hover are flown as asked.%s",
		    d->n_laps, report_num(b[0], sizeof b[0], d->lap_s, 1),
		    report_num(b[1], sizeof b[1], d->race_mean_power_w, 0),
		    report_num(b[2], sizeof b[2], 100.0 * d->lap_mean_fraction, 0),
		    report_num(b[3], sizeof b[3], d->full_throttle_power_w, 0),
		    report_num(b[4], sizeof b[4], d->race_mean_current_a, 1), strbuf_str(&tail)));
		break;
	case DUTY_SPRAY:
		doc_paragraph(rp->d, report_sfmt(&sb, "The forward distance is flown as a spray sortie: "
		    "%s" NBSP "m to the field, %d passes of %s" NBSP "m (the swath length "
		    "%s" NBSP "m) with %d turns of %s" NBSP "s at the swath ends (brake, yaw, "
		    "accelerate), and %s" NBSP "m back; %s.%s",
		    report_num(b[0], sizeof b[0], d->transit_m, 0), d->n_passes,
		    report_num(b[1], sizeof b[1], d->pass_m, 0),
		    report_num(b[2], sizeof b[2], d->swath_length_m, 0), d->n_turns,
		    report_num(b[3], sizeof b[3], d->turn_s, 1),
		    report_num(b[6], sizeof b[6], d->transit_m, 0),
		    d->tank_shed_kg > 0.0 ? report_sfmt(&mid, "%s" NBSP "kg of liquid is shed "
		    "while spraying", report_num(b[7], sizeof b[7], d->tank_shed_kg, 2))
		    : "the tank is carried full throughout (static sizing)", strbuf_str(&tail)));
		break;
	case DUTY_OUT_AND_BACK: {
		double out_s = 0.0, back_s = 0.0, hover_s = 0.0;
		for (int i = 0; i < d->n_groups; i++) {
			const struct res_duty_group *g = &d->group[i];
			if (g->phase == PHASE_HOVER)
				hover_s += g->duration_s;
			else if (g->phase == PHASE_FORWARD && out_s == 0.0)
				out_s = g->duration_s;
			else if (g->phase == PHASE_FORWARD)
				back_s += g->duration_s;
		}
		if (d->drop_time_s >= 0.0 && d->drop_mass_kg > 0.0)
			doc_paragraph(rp->d, report_sfmt(&sb, "The mission is flown out and back: "
			    "%s" NBSP "s out with the %s" NBSP "kg parcel, %s" NBSP "s hovering over "
			    "the drop point, the release at %s" NBSP "s, and %s" NBSP "s back "
			    "without it.%s", report_num(b[0], sizeof b[0], out_s, 0),
			    report_num(b[1], sizeof b[1], d->drop_mass_kg, 2),
			    report_num(b[2], sizeof b[2], hover_s, 0),
			    report_num(b[3], sizeof b[3], d->drop_time_s, 0),
			    report_num(b[6], sizeof b[6], back_s, 0), strbuf_str(&tail)));
		else
			doc_paragraph(rp->d, report_sfmt(&sb, "The mission is flown out and back "
			    "with the payload aboard throughout (static sizing): %s" NBSP "s out, "
			    "%s" NBSP "s hovering at the far end and %s" NBSP "s back.%s",
			    report_num(b[0], sizeof b[0], out_s, 0),
			    report_num(b[2], sizeof b[2], hover_s, 0),
			    report_num(b[6], sizeof b[6], back_s, 0), strbuf_str(&tail)));
		break;
	}
	default:
		break;
	}
	strbuf_free(&mid);
	strbuf_free(&tail);
	strbuf_free(&sb);
}

/* Section: the phase tables of the record and its references and the
 * power-vs-speed sweep. */
void
report_sec_mission(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *rec = rp->rec;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48];
	report_heading(rp, title);
	duty_paragraph(rp);
	int shed = rp->fig.sheds;
	bool profile = rec->duty.kind != DUTY_PHASES;
	doc_paragraph(rp->d, report_sfmt(&sb, "%s%s. "
	              "Electrical power is at the battery terminals and includes %s" NBSP "W of auxiliary "
	              "load (avionics and role equipment); energy is what each phase draws from the pack of "
	              "the %s (%s" NBSP "Wh nominal, %dS %s). Power and current are each phase's mean in "
	              "the discharge simulation: the pack's voltage falls as it empties, so the same power "
	              "draws more current late in the flight than the operating points quote at the pack's "
	              "nominal voltage.",
	              profile ? "The tables total the segments by the phase whose time they fly"
	                      : "The mission is flown as climb, forward flight and hover",
	              shed ? "; payload leaves the aircraft on the way (drop or spray), so the later "
	                     "phases fly lighter than the takeoff mass" : profile ? "" : " at the takeoff mass",
	              report_num(b1, sizeof b1, rp->fig.aux_power_w, 0),
	              rp->buildable ? "design of record" : "continuous design",
	              report_num(b2, sizeof b2, rec->energy_wh, 1), rec->cell_count,
	              report_chemistry(rec->chemistry)));
	report_subheading(rp, report_record_name(rp), REP_PHASE_PT);
	phase_table(rp, rec);
	if (rec->n_sweep > 0 || r->custom.n_sweep > 0 || r->baseline.n_sweep > 0)
		sweep_figure(rp);
	if (rp->buildable) {
		report_subheading(rp, report_continuous_heading(rp, &sb, "reference"), REP_PHASE_PT);
		phase_table(rp, &r->custom);
	}
	report_subheading(rp, REP_BASELINE_HEADING, REP_PHASE_PT);
	phase_table(rp, &r->baseline);
	strbuf_free(&sb);
}

/* ---- thermal and electrical traces ------------------------------------------- */

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

/* The four panels of the discharge trace with their limits. */
static void
trace_figure(struct rep *rp, const struct res_run *run)
{
	struct strbuf sb = STRBUF_INIT;
	char b1[48];
	int n = dmin_i(run->n_trace, RES_MAX_TRACE), col = rec_colour(rp);
	double *t = xcalloc((size_t)n, sizeof *t), *y1 = xcalloc((size_t)n, sizeof *y1),
	       *y2 = xcalloc((size_t)n, sizeof *y2);
	struct plot *p = plot_alloc(0, 360, 2, 2);
	struct plot_panel *a = plot_panel(p, 0, 0), *v = plot_panel(p, 0, 1),
	                  *s = plot_panel(p, 1, 0), *i = plot_panel(p, 1, 1);
	for (int k = 0; k < n; k++)
		t[k] = run->trace[k].t_s;

	plot_title(a, "Battery temperature");
	plot_axis_title(a, PLOT_Y, "Temperature (°C)");
	for (int k = 0; k < n; k++)
		y1[k] = run->trace[k].temp_c;
	plot_line(a, t, y1, (size_t)n, NULL, col, PLOT_DASH_SOLID);
	plot_hline(a, REP_RUNAWAY_C, "60 °C runaway limit", PLOT_COLOUR_FAIL, PLOT_DASH_DASHED);
	phase_marks(a, run, 1);

	plot_title(v, "Pack voltage");
	plot_axis_title(v, PLOT_Y, "Voltage (V)");
	for (int k = 0; k < n; k++) {
		y1[k] = run->trace[k].v_term_v;
		y2[k] = run->trace[k].v_oc_v;
	}
	plot_line(v, t, y2, (size_t)n, "open circuit", PLOT_COLOUR_MUTED, PLOT_DASH_DASHED);
	plot_line(v, t, y1, (size_t)n, "terminal", col, PLOT_DASH_SOLID);
	plot_hline(v, run->voltage_floor_v, report_sfmt(&sb, "floor %s V", report_num(b1, sizeof b1, run->voltage_floor_v, 2)),
	           PLOT_COLOUR_FAIL, PLOT_DASH_DASHED);
	phase_marks(v, run, 0);

	plot_title(s, "State of charge");
	plot_axis_title(s, PLOT_X, "Time (s)");
	plot_axis_title(s, PLOT_Y, "SOC (%)");
	for (int k = 0; k < n; k++)
		y1[k] = 100.0 * run->trace[k].soc;
	plot_axis_range(s, PLOT_Y, 0, 100);
	plot_line(s, t, y1, (size_t)n, NULL, col, PLOT_DASH_SOLID);
	plot_hline(s, 100.0 * run->reserve_soc,
	           report_sfmt(&sb, "reserve %s %%", report_num(b1, sizeof b1, 100.0 * run->reserve_soc, 0)),
	           PLOT_COLOUR_WARN, PLOT_DASH_DASHED);
	phase_marks(s, run, 0);

	plot_title(i, "Battery current");
	plot_axis_title(i, PLOT_X, "Time (s)");
	plot_axis_title(i, PLOT_Y, "Current (A)");
	for (int k = 0; k < n; k++)
		y1[k] = run->trace[k].current_a;
	plot_line(i, t, y1, (size_t)n, NULL, col, PLOT_DASH_SOLID);
	phase_marks(i, run, 0);

	doc_figure(rp->d, p, report_sfmt(&sb, "Discharge of the %s over the mission: battery temperature with "
	           "the 60 °C runaway limit, terminal and open-circuit voltage with the voltage floor, state "
	           "of charge with the reserve, and battery current; dotted lines mark the phase changes.",
	           rp->buildable ? "design of record" : "continuous design"));
	plot_free(p);
	free(t);
	free(y1);
	free(y2);
	strbuf_free(&sb);
}

/* One row "quantity | value | limit | margin" of the margins table. */
static void
margin_row(struct doc_table *t, const char *what, const char *value, const char *limit,
           const char *margin, int fail)
{
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", what);
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", value);
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", limit);
	doc_table_cell(t, fail ? DOC_CELL_FAIL : DOC_CELL_NORMAL, "%s", margin);
}

/* Section: the record's discharge trace, then every thermal and electrical
 * margin in one table: the pack against 60 °C and the windings against
 * their limit in kelvin, the landing charge against the reserve. */
void
report_sec_thermal(struct rep *rp, const char *title)
{
	const struct res_run *rec = rp->rec;
	const struct res_perf *pf = &rec->perf;
	struct strbuf sb = STRBUF_INIT, s2 = STRBUF_INIT, s3 = STRBUF_INIT;
	char b1[48], b2[48], b3[48], b4[48];
	report_heading(rp, title);
	int n = dmin_i(rec->n_trace, RES_MAX_TRACE);
	char end[RES_TEXT];
	snprintf(end, sizeof end, "%s", rec->termination[0] != '\0' ? rec->termination : "mission flown");
	if (end[0] >= 'a' && end[0] <= 'z')
		end[0] = (char)(end[0] - 'a' + 'A');
	doc_paragraph(rp->d, report_sfmt(&sb, "The discharge simulation of the %s: pack temperature from its "
	              "losses, terminal and open-circuit voltage, state of charge and current over the mission "
	              "(%d samples). %s.", rp->buildable ? "design of record on its real pack"
	              : "continuous design", n, end));
	if (n > 0)
		trace_figure(rp, rec);

	report_subheading(rp, "Thermal and electrical margins", REP_KEEP_PT);
	if (rp->buildable && pf->valid)
		doc_paragraph(rp->d, report_sfmt(&sb, "Temperature margins in kelvin: the pack against the "
		              "60 °C onset of thermal runaway, the windings against the %s °C their enamel and "
		              "magnets take (estimated from each operating point's losses; full throttle as a "
		              "short burst).", report_num(b1, sizeof b1, REP_WINDING_MAX_C, 0)));
	static const struct doc_column cols[] = {
		{ "Quantity", 2.6, DOC_ALIGN_LEFT }, { "Value", 1.1, DOC_ALIGN_RIGHT },
		{ "Limit", 1.3, DOC_ALIGN_RIGHT }, { "Margin", 1.1, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 4);
	double dk = REP_RUNAWAY_C - rec->max_battery_temp_c;
	margin_row(&t, "Battery peak temperature",
	           report_sfmt(&sb, "%s" NBSP "°C", report_num(b1, sizeof b1, rec->max_battery_temp_c, 1)),
	           report_sfmt(&s2, "≤" NBSP "%s" NBSP "°C", report_num(b2, sizeof b2, REP_RUNAWAY_C, 0)),
	           report_sfmt(&s3, "%s" NBSP "K", report_num(b3, sizeof b3, dk, 1)), dk < 0);
	if (rp->buildable && pf->valid) {
		for (int k = 0; k < OP_MAX; k++) {
			const struct res_op *op = &pf->op[k];
			const char *what = report_sfmt(&s2, "Motor winding, %s%s (estimated)", res_op_name[k],
			                               k == OP_FULL ? " burst" : "");
			char *w = xstrdup(what);
			if (!op->valid) {
				margin_row(&t, w, "out of reach", "—", "—", 0);
			} else {
				double wk = REP_WINDING_MAX_C - op->winding_temp_c;
				margin_row(&t, w, report_sfmt(&sb, "%s" NBSP "°C", report_num(b1, sizeof b1, op->winding_temp_c, 0)),
				           report_sfmt(&s2, "≤" NBSP "%s" NBSP "°C", report_num(b2, sizeof b2, REP_WINDING_MAX_C, 0)),
				           report_sfmt(&s3, "%s" NBSP "K", report_num(b3, sizeof b3, wk, 0)), wk < 0);
			}
			free(w);
		}
	} else {
		margin_row(&t, "Motor winding at hover (assumed: ambient + 40 K)",
		           report_sfmt(&sb, "%s" NBSP "°C", report_num(b1, sizeof b1, rec->winding_temp_c, 0)),
		           report_sfmt(&s2, "≤" NBSP "%s" NBSP "°C", report_num(b2, sizeof b2, REP_WINDING_MAX_C, 0)),
		           report_sfmt(&s3, "%s" NBSP "K", report_num(b3, sizeof b3, REP_WINDING_MAX_C - rec->winding_temp_c, 0)),
		           0);
	}
	double ds = 100.0 * (rec->end_soc - rec->reserve_soc);
	margin_row(&t, "State of charge at landing",
	           report_sfmt(&sb, "%s" NBSP "%%", report_num(b1, sizeof b1, 100.0 * rec->end_soc, 1)),
	           report_sfmt(&s2, "≥" NBSP "%s" NBSP "%% (reserve)", report_num(b2, sizeof b2, 100.0 * rec->reserve_soc, 1)),
	           report_sfmt(&s3, "%s%s" NBSP "points", ds >= 0 ? "+" : "", report_num(b3, sizeof b3, ds, 1)),
	           ds < -0.05);
	double dv = rec->min_terminal_voltage_v - rec->voltage_floor_v;
	margin_row(&t, "Minimum terminal voltage",
	           report_sfmt(&sb, "%s" NBSP "V", report_num(b1, sizeof b1, rec->min_terminal_voltage_v, 2)),
	           report_sfmt(&s2, "≥" NBSP "%s" NBSP "V (floor)", report_num(b2, sizeof b2, rec->voltage_floor_v, 2)),
	           report_sfmt(&s3, "%s" NBSP "V", report_num(b3, sizeof b3, dv, 2)), dv < 0);
	/* The pack's burst rating, where the parts search checked it. */
	const struct res_check *burst = checks_find(rec, "BATTERY_BURST");
	margin_row(&t, "Full-throttle battery current",
	           report_sfmt(&sb, "%s" NBSP "A (%s" NBSP "C)", report_num(b1, sizeof b1, rec->peak_current_a, 1),
	                       report_num(b2, sizeof b2, rec->peak_c_rate, 1)),
	           burst != NULL ? report_sfmt(&s2, "≤" NBSP "%s" NBSP "A (burst rating)",
	                                       report_num(b3, sizeof b3, burst->limit, 0)) : "—",
	           burst != NULL ? report_sfmt(&s3, "%s" NBSP "A", report_num(b4, sizeof b4,
	                                       burst->limit - rec->peak_current_a, 0)) : "—",
	           burst != NULL && !burst->pass);
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	strbuf_free(&sb);
	strbuf_free(&s2);
	strbuf_free(&s3);
}

/* ---- structure and resonance -------------------------------------------------- */

/* One design's arm tube: geometry, stress against allowable, tip mass,
 * first mode and resonance margin; failing margins in the fail colour. */
static void
arm_row(struct doc_table *t, const char *name, const struct res_run *run)
{
	double margin = report_div(run->arm_stress_allow_mpa - run->arm_stress_mpa, run->arm_stress_allow_mpa);
	/* Sized to the allowable stress: a margin of -1e-15 is a zero. */
	if (fabs(margin) < 1e-9)
		margin = 0.0;
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

/* The resonance figure of one design: frequency vs rotor speed, where the
 * arm mode sits against the blade-pass band. */
static void
resonance_figure(struct rep *rp, const struct res_run *c)
{
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48], b4[48];
	/* Blades per rotor as the engine used them: f_bpf = N_b rpm / 60. */
	double n_b = c->rpm_peak > 0 ? c->blade_pass_frequency_hz / (c->rpm_peak / 60.0)
	                             : (double)rp->r->mission.structural_overrides.num_blades;
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
	          rec_colour(rp), PLOT_DASH_SOLID);
	plot_hline(pp, c->arm_natural_frequency_hz,
	           report_sfmt(&sb, "arm first mode %s Hz", report_num(b1, sizeof b1, c->arm_natural_frequency_hz, 1)),
	           PLOT_COLOUR_ACCENT, PLOT_DASH_SOLID);
	plot_vline(pp, c->rpm_hover, report_sfmt(&sb, "hover %s rpm", report_num(b1, sizeof b1, c->rpm_hover, 0)),
	           PLOT_COLOUR_MUTED, PLOT_DASH_DASHED);
	plot_vline(pp, c->rpm_peak, report_sfmt(&sb, "full throttle %s rpm", report_num(b1, sizeof b1, c->rpm_peak, 0)),
	           PLOT_COLOUR_MUTED, PLOT_DASH_DASHED);
	plot_legend(pp, PLOT_LEGEND_BELOW);
	doc_figure(rp->d, p, report_sfmt(&sb, "Resonance check of the %s's arm: blade-pass frequency over the "
	           "rotor-speed range with its 1.5× margins, the in-flight band %s–%s Hz and the arm's first "
	           "bending mode at %s Hz (resonance margin %s %%).",
	           rp->buildable ? "design of record" : "continuous design",
	           report_num(b1, sizeof b1, c->blade_pass_low_hz, 0),
	           report_num(b2, sizeof b2, c->blade_pass_frequency_hz, 0),
	           report_num(b3, sizeof b3, c->arm_natural_frequency_hz, 1),
	           report_num(b4, sizeof b4, 100.0 * c->resonance_margin, 0)));
	plot_free(p);
	strbuf_free(&sb);
}

/* Section: the arm sizing of the three designs and the record's resonance
 * figure. */
void
report_sec_structure(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *rec = rp->rec;
	report_heading(rp, title);
	doc_paragraph(rp->d, "Each arm is a carbon-fibre tube sized as a cantilever for root bending "
	              "under the role's load factor; its first bending mode must sit 1.5× clear of the "
	              "blade-pass frequencies the rotors sweep in flight (from 0.7 × hover rpm up to full "
	              "throttle): either stiffer than 1.5 × the highest, or softer than the lowest / 1.5.");
	static const struct doc_column cols[] = {
		{ "Design", 1.3, DOC_ALIGN_LEFT }, { "Length (mm)", 0.9, DOC_ALIGN_RIGHT },
		{ "OD (mm)", 0.75, DOC_ALIGN_RIGHT }, { "Wall (mm)", 0.75, DOC_ALIGN_RIGHT },
		{ "Stress (MPa)", 0.85, DOC_ALIGN_RIGHT }, { "Allow. (MPa)", 0.85, DOC_ALIGN_RIGHT },
		{ "Margin (%)", 0.8, DOC_ALIGN_RIGHT }, { "Tip mass (g)", 0.85, DOC_ALIGN_RIGHT },
		{ "f1 (Hz)", 0.7, DOC_ALIGN_RIGHT }, { "Res. margin (%)", 0.95, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 10);
	arm_row(&t, report_record_name(rp), rec);
	if (rp->buildable)
		arm_row(&t, report_continuous_name(rp), &r->custom);
	arm_row(&t, REP_NAME_BASELINE, &r->baseline);
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	if (rec->arm_wall_floor_binds)
		doc_paragraph(rp->d, "The minimum manufacturable wall thickness binds: the arm is stronger than "
		              "bending alone requires, which shows as a stress margin.");
	if (rec->min_fraction_binds)
		doc_paragraph(rp->d, "The minimum structural mass fraction for this wheelbase binds: the frame "
		              "mass is raised to it, beyond what the arm sizing needs.");
	resonance_figure(rp, rec);
}

/* ---- convergence ------------------------------------------------------------- */

/* One design's mass history against iteration number. */
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

/* One design's sizing in plain terms: passes, settled, mass growth, what
 * a kilogram of payload costs, the share of the mission flown, how the
 * flight ended; a run the gate stopped shows "not run".  The solver's own
 * figures for it stand in the appendix (report_solver_details()). */
static void
conv_row(struct doc_table *t, const char *name, const struct res_run *run)
{
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", name);
	if (!run->ran) {
		doc_table_cell(t, DOC_CELL_MUTED, "—");
		doc_table_cell(t, DOC_CELL_FAIL, "not run");
		for (int k = 0; k < 3; k++)
			doc_table_cell(t, DOC_CELL_MUTED, "—");
	} else {
		doc_table_cell(t, DOC_CELL_NORMAL, "%d", run->iterations);
		doc_table_cell(t, run->converged ? DOC_CELL_PASS : DOC_CELL_FAIL, "%s", run->converged ? "yes" : "no");
		/* A run that did not settle has no growth at a design point. */
		bool g = run->converged && run->lipschitz > 0.0;
		report_cell_num(t, !g || run->lipschitz < 1.0 ? DOC_CELL_NORMAL : DOC_CELL_FAIL,
		                g ? run->lipschitz : NAN, 2);
		report_cell_num(t, DOC_CELL_NORMAL, g && run->lipschitz < 1.0 ? 1.0 / (1.0 - run->lipschitz) : NAN, 1);
		report_cell_num(t, run->time_scale < 1.0 ? DOC_CELL_WARN : DOC_CELL_NORMAL, 100.0 * run->time_scale, 0);
	}
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", run->termination[0] != '\0' ? run->termination : "—");
}

/* Section: how the takeoff mass settled, in an engineer's terms (sizing
 * passes, mass growth, the share of the mission flown); the solver's own
 * figures are in the appendix. */
void
report_sec_convergence(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *rec = rp->rec;
	struct strbuf sb = STRBUF_INIT;
	report_heading(rp, title);
	doc_paragraph(rp->d, report_sfmt(&sb, "The takeoff mass is found by sizing the aircraft again and "
	              "again: each pass sizes battery, propulsion and structure for the mass of the pass "
	              "before, until the mass changes by less than %.0f" NBSP "g. Mass growth is the "
	              "kilograms of battery, structure and motors that one more kilogram aboard calls for: "
	              "below 1 the sizing settles, and a kilogram of payload then costs 1 / (1 − growth) "
	              "kilograms of takeoff mass; at 1 or above the mass runs away. The appendix gives the "
	              "solver's own figures.",
	              1000.0 * r->custom.tolerance_kg));
	struct plot *p = plot_alloc(0, 240, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Sizing pass");
	plot_axis_title(pp, PLOT_Y, "Takeoff mass (kg)");
	/* Markers show the individual passes while they stay apart. */
	int n_max = dmin_i(RES_MAX_HISTORY, r->baseline.n_history > r->custom.n_history
	                                    ? r->baseline.n_history : r->custom.n_history);
	int mk = n_max <= 80;
	history_series(pp, &r->baseline, REP_NAME_BASELINE, REP_COL_BASELINE, mk ? PLOT_MARKER_CIRCLE : PLOT_MARKER_NONE);
	history_series(pp, &r->custom, report_continuous_name(rp), REP_COL_CUSTOM, mk ? PLOT_MARKER_SQUARE : PLOT_MARKER_NONE);
	if (rp->buildable && rec->mass.total_kg > 0) {
		plot_hline(pp, rec->mass.total_kg, "design of record (on its real parts)", REP_COL_CLOSED,
		           PLOT_DASH_DASHED);
	}
	doc_figure(rp->d, p, rp->buildable
	           ? "Takeoff mass per sizing pass, baseline and continuous optimum; the dashed line is "
	             "the takeoff mass of the design of record on its real parts."
	           : "Takeoff mass per sizing pass, baseline and continuous design.");
	plot_free(p);

	static const struct doc_column cols[] = {
		{ "Design", 1.5, DOC_ALIGN_LEFT }, { "Sizing passes", 0.9, DOC_ALIGN_RIGHT },
		{ "Settled", 0.8, DOC_ALIGN_CENTER }, { "Mass growth (kg/kg)", 1.0, DOC_ALIGN_RIGHT },
		{ "Payload cost (kg/kg)", 1.0, DOC_ALIGN_RIGHT }, { "Mission flown (%)", 0.9, DOC_ALIGN_RIGHT },
		{ "End of flight", 2.2, DOC_ALIGN_LEFT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 7);
	conv_row(&t, REP_NAME_BASELINE, &r->baseline);
	conv_row(&t, report_continuous_name(rp), &r->custom);
	if (rp->buildable) {
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", REP_NAME_RECORD);
		doc_table_cell(&t, DOC_CELL_MUTED, "—");
		doc_table_cell(&t, rec->converged ? DOC_CELL_PASS : DOC_CELL_FAIL, "%s", rec->converged ? "yes" : "no");
		doc_table_cell(&t, DOC_CELL_MUTED, "—");
		doc_table_cell(&t, DOC_CELL_MUTED, "—");
		report_cell_num(&t, rec->time_scale < 1.0 ? DOC_CELL_WARN : DOC_CELL_NORMAL, 100.0 * rec->time_scale, 0);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", rec->termination[0] != '\0' ? rec->termination : "—");
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	doc_paragraph(rp->d, "Mission flown: the share of each phase's requested time the design flies "
	              "(100 % unless the mission allows a shorter flight or asks more than the geometry "
	              "can reach; the cover says so when it is below 100 %).");
	if (rp->buildable)
		doc_paragraph(rp->d, "The design of record is sized again on the real parts' masses, so it has "
		              "no pass count or mass growth of its own here.");
	/* A sudden fall in the history is the sizing restarting from its seed
	 * after a discrete change (the cell count); say so, or it looks odd. */
	int restarts = 0;
	const struct res_run *runs[2] = { &r->baseline, &r->custom };
	for (int k = 0; k < 2; k++)
		for (int i = 1; i < dmin_i(runs[k]->n_history, RES_MAX_HISTORY); i++)
			if (runs[k]->history_kg[i] < 0.9 * runs[k]->history_kg[i - 1])
				restarts++;
	if (restarts > 0)
		doc_paragraph(rp->d, "The sudden drops in the history are restarts: when the sizing changes a "
		              "discrete choice such as the series cell count, it starts again from its seed "
		              "mass with the new choice.");
	strbuf_free(&sb);
}

/* ---- endurance explorer ------------------------------------------------------- */

/* One design's explorer points on both panels (time on top, mass below). */
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

/* Section: hover endurance and takeoff mass against capacity scale for the
 * continuous designs, with the design point, the mass-growth inflection
 * and where the design of record sits. */
void
report_sec_endurance(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *c = &r->custom, *rec = rp->rec;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48];
	report_heading(rp, title);
	doc_paragraph(rp->d, "Hover endurance to the reserve against battery capacity: each point re-sizes "
	              "the continuous design with its battery capacity scaled by the factor on the x axis "
	              "(1 = the design) and the cell count kept. More battery hovers longer, but the mass it "
	              "adds needs more power; past the inflection each extra watt-hour buys less than half "
	              "the time the first ones did.");
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
	endurance_series(pt, pm, &r->baseline, REP_NAME_BASELINE, REP_COL_BASELINE);
	endurance_series(pt, pm, c, report_continuous_name(rp), REP_COL_CUSTOM);
	/* The design point as a marker on the curves (its label would collide
	 * with the inflection line's, which often sits close to 1). */
	plot_vline(pt, 1.0, NULL, PLOT_COLOUR_ACCENT, PLOT_DASH_DASHED);
	plot_vline(pm, 1.0, NULL, PLOT_COLOUR_ACCENT, PLOT_DASH_DASHED);
	double one = 1.0, t1 = c->hover_endurance_s / 60.0, m1 = c->mass.total_kg;
	struct plot_style dp = { .colour = PLOT_COLOUR_ACCENT, .line_width_pt = -1,
	                         .marker = PLOT_MARKER_DIAMOND, .marker_size_pt = 7 };
	plot_series(pt, &one, &t1, 1, report_sfmt(&sb, "continuous design point (%s min)", report_num(b1, sizeof b1, t1, 1)), &dp);
	plot_series(pm, &one, &m1, 1, report_sfmt(&sb, "continuous design point (%s kg)", report_num(b1, sizeof b1, m1, 2)), &dp);
	/* The record on the same axes: its capacity relative to the
	 * continuous design's, its hover time on real parts, its mass. */
	double xs = report_div(rec->capacity_mah, c->capacity_mah);
	if (rp->buildable && rec->perf.valid && xs > 0) {
		double tr = rec->perf.hover_time_s / 60.0, mr = rec->mass.total_kg;
		struct plot_style rs = { .colour = REP_COL_CLOSED, .line_width_pt = -1,
		                         .marker = PLOT_MARKER_SQUARE, .marker_size_pt = 7 };
		plot_series(pt, &xs, &tr, 1, report_sfmt(&sb, "design of record (%s min)", report_num(b2, sizeof b2, tr, 1)), &rs);
		plot_series(pm, &xs, &mr, 1, report_sfmt(&sb, "design of record (%s kg)", report_num(b2, sizeof b2, mr, 2)), &rs);
	}
	if (c->endurance_inflection_scale > 0) {
		plot_vline(pt, c->endurance_inflection_scale,
		           report_sfmt(&sb, "inflection ×%s", report_num(b1, sizeof b1, c->endurance_inflection_scale, 2)),
		           PLOT_COLOUR_WARN, PLOT_DASH_DOTTED);
		plot_vline(pm, c->endurance_inflection_scale, NULL, PLOT_COLOUR_WARN, PLOT_DASH_DOTTED);
	}
	doc_figure(rp->d, p, c->endurance_inflection_scale > 0
	           ? report_sfmt(&sb, "Endurance explorer: hover endurance (top) and takeoff mass (bottom) vs battery "
	                  "capacity scale; the continuous design point is at 1, its mass-growth inflection at "
	                  "×%s%s.", report_num(b1, sizeof b1, c->endurance_inflection_scale, 2),
	                  rp->buildable ? "; the square is the design of record on its real parts" : "")
	           : report_sfmt(&sb, "Endurance explorer: hover endurance (top) and takeoff mass (bottom) vs "
	                  "battery capacity scale; the continuous design point is at 1, no inflection inside "
	                  "the explored range%s.", rp->buildable ? "; the square is the design of record" : ""));
	plot_free(p);
	strbuf_free(&sb);
}
