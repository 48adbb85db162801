/* sens_report.c — the sensitivity suite as text, JSON and PDF (see
 * sens_report.h). */
#include "study/sens_report.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "util/jsonw.h"
#include "util/units.h"
#include "util/xalloc.h"

/* Parameters per grid figure of the PDF, and its layout. */
#define GRID_COLS        2
#define GRID_ROWS        4
#define GRID_PANEL_H_PT  140.0

/* ---- text ------------------------------------------------------------------ */

/* "+1.692 kg/kg", or "n/a" when the value is not finite. */
static void
fmt_rate(char *buf, size_t n, double v, const char *unit, const char *per,
         const char *side)
{
	if (!isfinite(v)) {
		snprintf(buf, n, "n/a");
		return;
	}
	if (fabs(v) < 5e-4)
		v = 0.0;  /* no "-0.000" */
	snprintf(buf, n, "%+.3f %s/%s%s", v, unit, per, side);
}

/* A value with its unit: 4 significant digits, whole numbers from 1000 up
 * (no exponent in a table meant for people). */
static void
fmt_value(char *buf, size_t n, double v, const char *unit)
{
	const char *sep = unit[0] ? " " : "";
	if (fabs(v) < 1e-12)
		v = 0.0;
	if (fabs(v) >= 1000.0)
		snprintf(buf, n, "%.0f%s%s", v, sep, unit);
	else
		snprintf(buf, n, "%.4g%s%s", v, sep, unit);
}

void
sens_report_row(const struct sens_curve *c, struct sens_row *row)
{
	const struct sens_param_info *pi = &sens_params[c->id];
	memset(row, 0, sizeof *row);
	if (c->role_substituted && pi->role >= 0)
		snprintf(row->param, sizeof row->param, "%s (on a %s copy)", pi->label,
		    spec_enum_role[pi->role]);
	else
		snprintf(row->param, sizeof row->param, "%s", pi->label);
	fmt_value(row->at, sizeof row->at, c->x0, pi->unit);
	const char *side = c->fd_kind == 1 ? " (fwd)" : c->fd_kind == -1 ? " (bwd)" : "";
	if (c->fd_kind == 2) {
		snprintf(row->mtow, sizeof row->mtow, "n/a");
		snprintf(row->hover, sizeof row->hover, "n/a");
		snprintf(row->flight, sizeof row->flight, "n/a");
	} else {
		fmt_rate(row->mtow, sizeof row->mtow, c->d_mtow, "kg", pi->step_text, side);
		fmt_rate(row->hover, sizeof row->hover, c->d_hover_min, "min", pi->step_text, side);
		fmt_rate(row->flight, sizeof row->flight, c->d_flight_min, "min", pi->step_text, side);
	}
	char a[64] = "", b[64] = "";
	if (c->nominal.status != SENS_OK) {
		snprintf(row->cross, sizeof row->cross, "nominal design %s (%s)",
		    sens_status_name(c->nominal.status), c->nominal.reason);
		return;
	}
	if (c->cross_lo) {
		fmt_value(a, sizeof a, c->x_cross_lo, pi->unit);
		snprintf(row->cross, sizeof row->cross, "below %s (%s)", a, c->why_lo);
	}
	if (c->cross_hi) {
		size_t used = strlen(row->cross);
		fmt_value(b, sizeof b, c->x_cross_hi, pi->unit);
		snprintf(row->cross + used, sizeof row->cross - used, "%sabove %s (%s)",
		    used ? "; " : "", b, c->why_hi);
	}
	if (!c->cross_lo && !c->cross_hi)
		snprintf(row->cross, sizeof row->cross, "none in range");
}

int
sens_report_text(FILE *out, const struct sens_result *s)
{
	fprintf(out, "Sensitivity of %s (%s role): nominal MTOW %.3f kg, hover "
	    "flight time %.2f min, %s; %d solves.\n", s->mission,
	    spec_enum_role[s->role], s->nominal.mtow_kg,
	    s->nominal.hover_endurance_s / S_PER_MIN,
	    s->nominal.status == SENS_OK ? "feasible" : s->nominal.reason, s->n_solves);
	fprintf(out, "%-44s %-14s %-28s %-30s %s\n", "Parameter", "Mission value",
	    "MTOW sensitivity", "Hover flight time sensitivity", "Crossing");
	for (int i = 0; i < SENS_N_PARAMS; i++) {
		struct sens_row row;
		sens_report_row(&s->c[i], &row);
		fprintf(out, "%-44s %-14s %-28s %-30s %s\n", row.param, row.at, row.mtow,
		    row.hover, row.cross);
	}
	return ferror(out) ? -1 : 0;
}

/* A number for the TSV table, "" when it is not to be printed. */
static const char *
tsv_num(char *buf, size_t n, bool have, double v)
{
	if (!have || !isfinite(v))
		buf[0] = '\0';
	else
		snprintf(buf, n, "%.6g", fabs(v) < 1e-12 ? 0.0 : v);
	return buf;
}

int
sens_report_tsv(FILE *out, const struct sens_result *s)
{
	static const char *const kinds[] = { "central", "forward", "none", "backward" };
	fprintf(out, "key\tx0\tunit\tdifference\td_mtow_kg\td_hover_min\t"
	    "d_flight_min\tcross_low\twhy_low\tcross_high\twhy_high\n");
	for (int i = 0; i < SENS_N_PARAMS; i++) {
		const struct sens_curve *c = &s->c[i];
		bool d = c->fd_kind != 2;
		char b[6][32];
		fprintf(out, "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n",
		    sens_params[i].key, tsv_num(b[0], 32, true, c->x0), sens_params[i].unit,
		    kinds[c->fd_kind == -1 ? 3 : c->fd_kind],
		    tsv_num(b[1], 32, d, c->d_mtow), tsv_num(b[2], 32, d, c->d_hover_min),
		    tsv_num(b[3], 32, d, c->d_flight_min),
		    tsv_num(b[4], 32, c->cross_lo, c->x_cross_lo), c->cross_lo ? c->why_lo : "",
		    tsv_num(b[5], 32, c->cross_hi, c->x_cross_hi), c->cross_hi ? c->why_hi : "");
	}
	return ferror(out) ? -1 : 0;
}

/* ---- JSON ------------------------------------------------------------------ */

/* Adds key: v (printed exactly by jsonw); a non-finite v is left out. */
static void
add_num(cJSON *o, const char *key, double v)
{
	if (isfinite(v))
		cJSON_AddNumberToObject(o, key, v);
}

/* A sweep's crossing {x, reason} at key, or null when it has none. */
static void
add_crossing(cJSON *o, const char *key, bool crosses, double x, const char *why)
{
	if (!crosses) {
		cJSON_AddNullToObject(o, key);
		return;
	}
	cJSON *c = cJSON_CreateObject();
	add_num(c, "x", x);
	cJSON_AddStringToObject(c, "reason", why);
	cJSON_AddItemToObject(o, key, c);
}

static cJSON *
point_json(const struct sens_point *p, bool with_x)
{
	cJSON *o = cJSON_CreateObject();
	if (with_x)
		add_num(o, "x", p->x);
	cJSON_AddStringToObject(o, "status", sens_status_name(p->status));
	if (p->reason[0])
		cJSON_AddStringToObject(o, "reason", p->reason);
	/* A runaway or unconverged loop has no design to report. */
	if (p->status == SENS_OK || p->status == SENS_INFEASIBLE) {
		add_num(o, "mtow_kg", p->mtow_kg);
		add_num(o, "hover_endurance_s", p->hover_endurance_s);
		add_num(o, "flight_time_s", p->flight_time_s);
	}
	if (p->has_margin)
		add_num(o, "worst_check_margin", p->margin);
	return o;
}

static cJSON *
curve_json(const struct sens_curve *c)
{
	static const char *const kinds[] = { "central", "forward", "none", "backward" };
	const struct sens_param_info *pi = &sens_params[c->id];
	cJSON *o = cJSON_CreateObject();
	cJSON_AddStringToObject(o, "key", pi->key);
	cJSON_AddStringToObject(o, "label", pi->label);
	cJSON_AddStringToObject(o, "unit", pi->unit);
	add_num(o, "per_step", pi->step);
	cJSON_AddStringToObject(o, "per_step_text", pi->step_text);
	if (pi->role >= 0)
		cJSON_AddStringToObject(o, "evaluated_role", spec_enum_role[pi->role]);
	cJSON_AddBoolToObject(o, "role_substituted", c->role_substituted);
	add_num(o, "x0", c->x0);
	cJSON_AddItemToObject(o, "nominal", point_json(&c->nominal, false));
	int k = c->fd_kind == -1 ? 3 : c->fd_kind;
	cJSON_AddStringToObject(o, "difference", kinds[k]);
	add_num(o, "h", c->h);
	if (c->fd_kind != 2) {
		add_num(o, "d_mtow_kg_per_step", c->d_mtow);
		add_num(o, "d_hover_flight_time_min_per_step", c->d_hover_min);
		add_num(o, "d_flight_time_min_per_step", c->d_flight_min);
	}
	if (c->has_fd_lo)
		cJSON_AddItemToObject(o, "fd_low", point_json(&c->fd_lo, true));
	if (c->has_fd_hi)
		cJSON_AddItemToObject(o, "fd_high", point_json(&c->fd_hi, true));
	add_crossing(o, "crossing_low", c->cross_lo, c->x_cross_lo, c->why_lo);
	add_crossing(o, "crossing_high", c->cross_hi, c->x_cross_hi, c->why_hi);
	cJSON *g = cJSON_CreateObject();
	add_num(g, "x_low", c->x_good_lo);
	add_num(g, "x_high", c->x_good_hi);
	add_num(g, "mtow_low_kg", c->mtow_good_lo_kg);
	add_num(g, "mtow_high_kg", c->mtow_good_hi_kg);
	cJSON_AddItemToObject(o, "good_range", g);
	cJSON *pts = cJSON_AddArrayToObject(o, "points");
	for (int i = 0; i < c->n; i++)
		cJSON_AddItemToArray(pts, point_json(&c->pt[i], true));
	return o;
}

char *
sens_report_json(const struct sens_result *s, const char *aeroeval_version)
{
	cJSON *root = cJSON_CreateObject();
	cJSON_AddStringToObject(root, "aeroeval_version", aeroeval_version);
	cJSON_AddStringToObject(root, "mission", s->mission);
	cJSON_AddStringToObject(root, "role", spec_enum_role[s->role]);
	cJSON_AddItemToObject(root, "nominal", point_json(&s->nominal, false));
	cJSON_AddNumberToObject(root, "n_solves", s->n_solves);
	cJSON *arr = cJSON_AddArrayToObject(root, "parameters");
	for (int i = 0; i < SENS_N_PARAMS; i++)
		cJSON_AddItemToArray(arr, curve_json(&s->c[i]));
	char *text = jsonw_print(root, NULL);
	cJSON_Delete(root);
	return text;
}

/* ---- PDF ------------------------------------------------------------------- */

static const struct doc_column table_cols[] = {
	{ "Parameter", 2.6, DOC_ALIGN_LEFT },
	{ "Mission value", 1.2, DOC_ALIGN_RIGHT },
	{ "MTOW sensitivity", 1.9, DOC_ALIGN_RIGHT },
	{ "Hover flight time sensitivity", 2.0, DOC_ALIGN_RIGHT },
	{ "Leaves the feasible region", 2.4, DOC_ALIGN_LEFT },
};

static void
section_table(struct doc *d, const struct sens_result *s)
{
	struct doc_table t;
	doc_table_init(&t, table_cols, 5);
	for (int i = 0; i < SENS_N_PARAMS; i++) {
		struct sens_row row;
		sens_report_row(&s->c[i], &row);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", row.param);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", row.at);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", row.mtow);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", row.hover);
		doc_table_cell(&t, s->c[i].cross_lo || s->c[i].cross_hi
		    ? DOC_CELL_WARN : DOC_CELL_MUTED, "%s", row.cross);
	}
	doc_table(d, &t);
	doc_table_clear(&t);
}

/* Percent change of v from ref, NAN when not meaningful. */
static double
pct(double v, double ref)
{
	return ref > 0.0 && isfinite(v) ? 100.0 * (v / ref - 1.0) : NAN;
}

static void
tornado_figure(struct doc *d, const struct sens_result *s)
{
	char labels[SENS_N_PARAMS][128];
	const char *lp[SENS_N_PARAMS];
	double lo[SENS_N_PARAMS], hi[SENS_N_PARAMS];
	for (int i = 0; i < SENS_N_PARAMS; i++) {
		const struct sens_curve *c = &s->c[i];
		const struct sens_param_info *pi = &sens_params[i];
		char a[48], b[48];
		fmt_value(a, sizeof a, c->x_good_lo, "");
		fmt_value(b, sizeof b, c->x_good_hi, pi->unit);
		snprintf(labels[i], sizeof labels[i], "%s %s–%s", pi->label, a, b);
		lp[i] = labels[i];
		double ref = c->nominal.mtow_kg;
		lo[i] = c->nominal.status == SENS_OK ? pct(c->mtow_good_lo_kg, ref) : 0.0;
		hi[i] = c->nominal.status == SENS_OK ? pct(c->mtow_good_hi_kg, ref) : 0.0;
		if (!isfinite(lo[i]))
			lo[i] = 0.0;
		if (!isfinite(hi[i]))
			hi[i] = 0.0;
	}
	struct plot *p = plot_alloc(0, 320, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "MTOW change from the nominal design (%)");
	plot_tornado(pp, SENS_N_PARAMS, lp, lo, hi, 0.0, "low end of the range",
	    "high end of the range");
	doc_figure(d, p, "MTOW change over each sweep's feasible range (the "
	    "contiguous run of good points around the mission's value).");
	plot_free(p);
}

/* Heading, the nominal design, the method, the table and the tornado. */
static int
section(struct doc *d, const char *heading, const struct sens_result *s)
{
	doc_heading(d, 1, heading);
	char para[1024];
	snprintf(para, sizeof para, "Nominal design (%s role): MTOW %.3f kg, hover "
	    "flight time %.2f min, approved mission time %.2f min, %s.",
	    spec_enum_role[s->role], s->nominal.mtow_kg,
	    s->nominal.hover_endurance_s / S_PER_MIN,
	    s->nominal.flight_time_s / S_PER_MIN,
	    s->nominal.status == SENS_OK ? "feasible" : s->nominal.reason);
	doc_paragraph(d, para);
	snprintf(para, sizeof para, "Each of the 14 parameters of the paper's "
	    "sensitivity study was swept over a range around this mission's value, "
	    "re-sizing the whole aircraft at every point (%d solves in all).  The "
	    "table gives the partial derivatives of the takeoff mass and of the "
	    "hover flight time at the mission's value, by central differences "
	    "unless marked fwd/bwd (one-sided, where a neighbour falls outside the "
	    "allowed range or the feasible region), and where each sweep leaves "
	    "the feasible, converged region.  Role-specific parameters are "
	    "evaluated on a copy of the mission with that role when the mission "
	    "has another.", s->n_solves);
	doc_paragraph(d, para);
	section_table(d, s);
	tornado_figure(d, s);
	return doc_error(d) == NULL ? 0 : -1;
}

int
sens_report_section(struct doc *d, const struct template *t,
                    const struct sens_result *s)
{
	const struct template_section *sec = template_section_get(t,
	    TEMPLATE_SEC_SENSITIVITY);
	return section(d, sec != NULL && sec->title[0] ? sec->title : "Sensitivity", s);
}

/* One panel: MTOW and hover flight time of curve c as % of its nominal. */
static void
curve_panel(struct plot_panel *pp, const struct sens_curve *c)
{
	const struct sens_param_info *pi = &sens_params[c->id];
	double x[SENS_MAX_POINTS], m[SENS_MAX_POINTS], h[SENS_MAX_POINTS];
	double xi[SENS_MAX_POINTS], mi[SENS_MAX_POINTS];
	int ni = 0;
	for (int i = 0; i < c->n; i++) {
		const struct sens_point *p = &c->pt[i];
		x[i] = p->x;
		bool ok = p->status == SENS_OK;
		m[i] = ok ? pct(p->mtow_kg, c->nominal.mtow_kg) : NAN;
		h[i] = ok ? pct(p->hover_endurance_s, c->nominal.hover_endurance_s) : NAN;
		if (p->status == SENS_INFEASIBLE) {
			xi[ni] = p->x;
			mi[ni++] = pct(p->mtow_kg, c->nominal.mtow_kg);
		}
	}
	char title[160];
	if (c->role_substituted && pi->role >= 0)
		snprintf(title, sizeof title, "%s (%s copy)", pi->label,
		    spec_enum_role[pi->role]);
	else
		snprintf(title, sizeof title, "%s", pi->label);
	plot_title(pp, title);
	char xt[96];
	snprintf(xt, sizeof xt, "%s%s%s%s", pi->label, pi->unit[0] ? " (" : "",
	    pi->unit, pi->unit[0] ? ")" : "");
	plot_axis_title(pp, PLOT_X, xt);
	plot_axis_title(pp, PLOT_Y, "Change (%)");
	struct plot_style st = { .colour = 0, .marker = PLOT_MARKER_CIRCLE,
		.marker_size_pt = 3.0 };
	if (c->nominal.status == SENS_OK) {
		plot_series(pp, x, m, (size_t)c->n, "MTOW", &st);
		st.colour = 1;
		st.marker = PLOT_MARKER_SQUARE;
		plot_series(pp, x, h, (size_t)c->n, "Hover time", &st);
		if (ni > 0) {
			struct plot_style si = { .colour = PLOT_COLOUR_FAIL,
				.line_width_pt = -1.0, .marker = PLOT_MARKER_CIRCLE,
				.marker_size_pt = 3.0, .open_marker = 1 };
			plot_series(pp, xi, mi, (size_t)ni, "MTOW, infeasible", &si);
		}
	}
	plot_vline(pp, c->x0, NULL, PLOT_COLOUR_MUTED, PLOT_DASH_DOTTED);
	if (c->cross_lo)
		plot_vline(pp, c->x_cross_lo, c->why_lo, PLOT_COLOUR_FAIL, PLOT_DASH_DASHED);
	if (c->cross_hi)
		plot_vline(pp, c->x_cross_hi, c->why_hi, PLOT_COLOUR_FAIL, PLOT_DASH_DASHED);
	plot_legend(pp, PLOT_LEGEND_AUTO);
}

static void
grid_figures(struct doc *d, const struct sens_result *s)
{
	int per = GRID_COLS * GRID_ROWS;
	for (int first = 0; first < SENS_N_PARAMS; first += per) {
		int count = SENS_N_PARAMS - first < per ? SENS_N_PARAMS - first : per;
		int rows = (count + GRID_COLS - 1) / GRID_COLS;
		struct plot *p = plot_alloc(0, GRID_PANEL_H_PT * rows, rows, GRID_COLS);
		for (int k = 0; k < count; k++)
			curve_panel(plot_panel(p, k / GRID_COLS, k % GRID_COLS),
			    &s->c[first + k]);
		char cap[256];
		snprintf(cap, sizeof cap, "Parameters %d–%d: MTOW and hover flight "
		    "time against the parameter, in %% of the design at the mission's "
		    "value (dotted line); dashed red lines mark where the sweep leaves "
		    "the feasible region.", first + 1, first + count);
		doc_figure(d, p, cap);
		plot_free(p);
	}
}

int
sens_report_pdf(const struct sens_result *s, const struct template *t,
                const char *date, unsigned char **out, size_t *n, char *err,
                size_t errlen)
{
	char title[SPEC_STR_MAX + 32];
	snprintf(title, sizeof title, "Sensitivity study: %s", s->mission);
	struct doc_info info = { .title = "Sensitivity study", .mission = s->mission,
		.subject = "14-parameter sensitivity of MTOW and flight time",
		.date = date };
	struct doc *d = doc_alloc(t, &info);
	section(d, title, s);
	doc_heading(d, 1, "Sweeps");
	grid_figures(d, s);
	int rc = doc_save_mem(d, out, n);
	if (rc != 0)
		snprintf(err, errlen, "sensitivity.pdf: %s",
		    doc_error(d) ? doc_error(d) : "cannot render");
	doc_free(d);
	return rc == 0 ? 0 : -1;
}
