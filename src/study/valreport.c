/* valreport.c — the validation dossier PDF (see valreport.h). */
#include "study/valreport.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pdf/doc.h"
#include "pdf/plot.h"
#include "template/template.h"
#include "util/xalloc.h"

const char *const valreport_rule_text[] = {
	"One rule, applied identically to every row, using only the row's own facts; "
	"the takeoff mass, the empty mass, the battery mass and anything derived from "
	"them are never read.",
	"Payload: payload_kg; unknown skips the row (a takeoff figure is the aircraft "
	"plus what it carries). The load case: max_payload_kg where it exceeds the "
	"payload; motors, ESCs, propellers and structure are built for it.",
	"Rotors: rotor_count; unknown skips the row. Coaxial: as given; unknown is a "
	"flat layout. Class: airframe_class; unknown skips the row. Role: role; "
	"unknown is \"none\".",
	"Wheelbase: diagonal_wheelbase_mm; else the smallest wheelbase whose overlap "
	"limit admits the row's propeller, W = D / ((1 - 0.05) sin(pi / N_arms)); "
	"else the row is skipped.",
	"Propeller: the diameter is locked at prop_diameter_in when it fits the "
	"wheelbase's overlap limit (pitch as given, else 0.45 D, which enters no "
	"mass); a larger propeller is not locked and the engine uses the limit.",
	"Battery: chemistry as given when it names a loaded profile; \"Li-ion\" is "
	"read as Li-ion NMC (the lower specific energy of the two Li-ion profiles); "
	"else LiHV, the engine's default. Pack count as given, else 1. Series cells as "
	"given, else chosen by the solver. Capacity sized from the endurance; with "
	"validate --pack, a row's published pack (cells, capacity) is locked instead.",
	"Endurance: one hover phase, no climb, no forward flight. The engine sizes "
	"capacity as 1.2 x the charge the mission draws, while manufacturer times run "
	"the pack to empty, so t_hover = hover_time_min / 1.2, else 0.8 x "
	"max_flight_time_min / 1.2 (the advertised maximum is flown at the "
	"best-endurance speed, at roughly 0.8 of hover power); else the row is skipped.",
	"Everything else keeps the mission defaults (sea level, ISA, role and class "
	"defaults). The prediction is the custom run's takeoff mass. Rows whose mass "
	"loop converges count, feasible or not; the others are listed apart.",
	NULL
};

/* Headline numbers and the coefficients in use. */
static void
section_summary(struct doc *d, const struct validate_report *v,
                const struct model_calibration *cal, const char *cohort_name)
{
	char b[8][96];
	snprintf(b[0], sizeof b[0], "%zu of %zu", v->n_ok, v->n_rows);
	snprintf(b[1], sizeof b[1], "%.1f %% (95 %% CI %.1f–%.1f %%)", v->mtow.mape_pct,
	    v->ci_lo_pct, v->ci_hi_pct);
	snprintf(b[2], sizeof b[2], "%.1f %%", v->mtow.median_ape_pct);
	snprintf(b[3], sizeof b[3], "%.3f kg", v->mtow.rmse_kg);
	snprintf(b[4], sizeof b[4], "%.2f ± %.2f", v->mtow.k_mean, v->mtow.k_sd);
	if (v->battery.n > 0)
		snprintf(b[5], sizeof b[5], "%.1f %% over %zu rows", v->battery.mape_pct,
		    v->battery.n);
	else
		snprintf(b[5], sizeof b[5], "no row gives a battery mass");
	snprintf(b[6], sizeof b[6], "%.2f / %.2f / %.2f / %.2f / %.2f",
	    cal->lambda[LAMBDA_MICRO], cal->lambda[LAMBDA_CONSUMER],
	    cal->lambda[LAMBDA_ENTERPRISE_QUAD], cal->lambda[LAMBDA_ENTERPRISE_MULTI],
	    cal->lambda[LAMBDA_AGRI]);
	snprintf(b[7], sizeof b[7], "%.3f / %.3f / %.3f / %.3f kg, %.3f",
	    cal->equip_kg[AF_MICRO_AIO], cal->equip_kg[AF_CONSUMER_FOLDING],
	    cal->equip_kg[AF_ENTERPRISE_RUGGED], cal->equip_kg[AF_AGRICULTURAL],
	    cal->equip_exponent);
	const char *kv[] = {
		"Cohort file", cohort_name,
		"Rows in the statistics", b[0],
		"MTOW MAPE", b[1],
		"Median absolute error", b[2],
		"RMSE", b[3],
		"k = actual / predicted", b[4],
		"Battery mass MAPE", b[5],
		"λ Micro / Consumer / Ent. quad / Ent. multi / Agri", b[6],
		"Equipment at 1 kg (Micro / Consumer / Ent. / Agri), exponent", b[7],
	};
	doc_kv_table(d, kv, 9);
	char txt[256];
	snprintf(txt, sizeof txt, "The confidence interval is a percentile bootstrap of "
	    "the MAPE over the rows in the statistics (%d resamples, fixed seed %u), "
	    "so it is reproducible.", VALIDATE_BOOT_RESAMPLES, VALIDATE_BOOT_SEED);
	doc_paragraph(d, txt);
}

static void
figure_scatter(struct doc *d, const struct cohort *c, const struct validate_report *v)
{
	double lo = INFINITY, hi = 0.0;
	for (size_t i = 0; i < v->n_rows; i++) {
		const struct validate_row *vr = &v->rows[i];
		if (vr->status != VALIDATE_ROW_OK)
			continue;
		lo = fmin(lo, fmin(vr->actual_kg, vr->predicted_kg));
		hi = fmax(hi, fmax(vr->actual_kg, vr->predicted_kg));
	}
	if (!(hi > 0.0))
		return;
	/* Whole decades around the data, so the bands span the plot. */
	double line[2] = { pow(10.0, floor(log10(lo / 1.3))), pow(10.0, ceil(log10(hi * 1.3))) };
	double lo10[2], hi10[2], lo25[2], hi25[2];
	for (int i = 0; i < 2; i++) {
		lo10[i] = 0.9 * line[i];
		hi10[i] = 1.1 * line[i];
		lo25[i] = 0.75 * line[i];
		hi25[i] = 1.25 * line[i];
	}
	struct plot *p = plot_alloc(0, 330, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_log(pp, PLOT_X, 1);
	plot_axis_log(pp, PLOT_Y, 1);
	plot_axis_range(pp, PLOT_X, line[0], line[1]);
	plot_axis_range(pp, PLOT_Y, line[0], line[1]);
	plot_axis_title(pp, PLOT_X, "Actual takeoff mass (kg)");
	plot_axis_title(pp, PLOT_Y, "Predicted takeoff mass (kg)");
	plot_band(pp, line, lo25, hi25, 2, "±25 %", PLOT_COLOUR_MUTED, 0.15);
	plot_band(pp, line, lo10, hi10, 2, "±10 %", PLOT_COLOUR_ACCENT, 0.25);
	plot_line(pp, line, line, 2, "predicted = actual", PLOT_COLOUR_TEXT, PLOT_DASH_SOLID);
	static const enum plot_marker mk[AF_CLASS_MAX] = { PLOT_MARKER_TRIANGLE,
		PLOT_MARKER_CIRCLE, PLOT_MARKER_SQUARE, PLOT_MARKER_DIAMOND };
	double *x = xmalloc((v->n_rows + 1) * sizeof *x);
	double *y = xmalloc((v->n_rows + 1) * sizeof *y);
	for (int k = 0; k < AF_CLASS_MAX; k++) {
		size_t n = 0;
		for (size_t i = 0; i < v->n_rows; i++) {
			if (v->rows[i].status != VALIDATE_ROW_OK || (int)c->rows[i].airframe_class != k)
				continue;
			x[n] = v->rows[i].actual_kg;
			y[n] = v->rows[i].predicted_kg;
			n++;
		}
		if (n > 0)
			plot_scatter(pp, x, y, n, spec_enum_airframe[k], mk[k], k);
	}
	free(x);
	free(y);
	plot_legend(pp, PLOT_LEGEND_BELOW);
	doc_figure(d, p, "Predicted vs actual takeoff mass, log-log, with the identity "
	    "line and ±10 % / ±25 % bands; one marker per class.");
	plot_free(p);
}

static void
figure_classes(struct doc *d, const struct validate_report *v)
{
	if (v->n_classes == 0)
		return;
	const char **labels = xmalloc(v->n_classes * sizeof *labels);
	char (*text)[64] = xmalloc(v->n_classes * sizeof *text);
	double *mape = xmalloc(v->n_classes * sizeof *mape);
	for (size_t g = 0; g < v->n_classes; g++) {
		snprintf(text[g], sizeof text[g], "%s (n=%zu)", v->by_class[g].key,
		    v->by_class[g].n);
		labels[g] = text[g];
		mape[g] = v->by_class[g].mape_pct;
	}
	static const char *const stack[] = { "MAPE" };
	struct plot *p = plot_alloc(0, 220, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_Y, "MTOW MAPE (%)");
	plot_stacked_bars(pp, (int)v->n_classes, labels, 1, stack, mape, 1);
	plot_legend(pp, PLOT_LEGEND_NONE);
	doc_figure(d, p, "Mean absolute percentage error of the takeoff mass per airframe class.");
	plot_free(p);
	free(labels);
	free(text);
	free(mape);
}

static void
table_rows(struct doc *d, const struct cohort *c, const struct validate_report *v)
{
	static const struct doc_column cols[] = {
		{ "Platform", 2.3, DOC_ALIGN_LEFT }, { "Class", 2.0, DOC_ALIGN_LEFT },
		{ "Actual (kg)", 1.0, DOC_ALIGN_RIGHT }, { "Predicted (kg)", 1.1, DOC_ALIGN_RIGHT },
		{ "Error", 0.9, DOC_ALIGN_RIGHT }, { "k", 0.7, DOC_ALIGN_RIGHT },
		{ "Battery error", 1.0, DOC_ALIGN_RIGHT }, { "Checks", 0.9, DOC_ALIGN_CENTER },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 8);
	for (size_t i = 0; i < v->n_rows; i++) {
		const struct validate_row *vr = &v->rows[i];
		if (vr->status != VALIDATE_ROW_OK)
			continue;
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", c->rows[i].name);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", validate_class_key(&c->rows[i]));
		doc_table_cell(&t, DOC_CELL_NORMAL, "%.3f", vr->actual_kg);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%.3f", vr->predicted_kg);
		doc_table_cell(&t, fabs(vr->err_pct) <= 10.0 ? DOC_CELL_PASS
		    : fabs(vr->err_pct) <= 25.0 ? DOC_CELL_WARN : DOC_CELL_FAIL,
		    "%+.1f %%", vr->err_pct);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%.2f", vr->k);
		if (vr->has_battery)
			doc_table_cell(&t, DOC_CELL_NORMAL, "%+.1f %%", vr->battery_err_pct);
		else
			doc_table_cell(&t, DOC_CELL_MUTED, "–");
		doc_table_cell(&t, vr->feasible ? DOC_CELL_NORMAL : DOC_CELL_MUTED, "%s",
		    vr->feasible ? "pass" : "fail");
	}
	doc_table(d, &t);
	doc_table_clear(&t);
	doc_paragraph(d, "Error = (predicted − actual) / actual; k = actual / predicted. "
	    "\"Checks fail\" means the sized design breaks a constraint of the engine; "
	    "its converged mass still counts.");
}

static void
table_excluded(struct doc *d, const struct cohort *c, const struct validate_report *v)
{
	static const struct doc_column cols[] = {
		{ "Platform", 2.6, DOC_ALIGN_LEFT }, { "Line", 0.6, DOC_ALIGN_RIGHT },
		{ "Status", 1.2, DOC_ALIGN_LEFT }, { "Why", 4.0, DOC_ALIGN_LEFT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 4);
	for (size_t i = 0; i < v->n_rows; i++) {
		const struct validate_row *vr = &v->rows[i];
		if (vr->status == VALIDATE_ROW_OK)
			continue;
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", c->rows[i].name);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%zu", c->rows[i].line);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", validate_status_text(vr->status));
		if (vr->status == VALIDATE_ROW_SKIPPED)
			doc_table_cell(&t, DOC_CELL_NORMAL, "%s", validate_skip_text(vr->skip));
		else if (vr->status == VALIDATE_ROW_NOT_CONVERGED)
			doc_table_cell(&t, DOC_CELL_NORMAL, "mass loop did not converge "
			    "(last %.3f kg)", vr->predicted_kg);
		else
			doc_table_cell(&t, DOC_CELL_NORMAL, "rejected by the feasibility gate");
	}
	if (t.n_cells > 0)
		doc_table(d, &t);
	else
		doc_paragraph(d, "Every row of the cohort is in the statistics.");
	doc_table_clear(&t);
}

static void
table_notes(struct doc *d, const struct cohort *c, const struct validate_report *v)
{
	static const struct doc_column cols[] = {
		{ "Platform", 2.6, DOC_ALIGN_LEFT }, { "Stand-ins the rule used", 5.2, DOC_ALIGN_LEFT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 2);
	for (size_t i = 0; i < v->n_rows; i++) {
		const struct validate_row *vr = &v->rows[i];
		if (vr->status == VALIDATE_ROW_SKIPPED || vr->notes == 0)
			continue;
		char buf[512];
		size_t used = 0;
		buf[0] = '\0';
		for (int b = 0; b < VALIDATE_NOTE_COUNT; b++) {
			if (!(vr->notes & (1u << b)))
				continue;
			int w = snprintf(buf + used, sizeof buf - used, "%s%s", used ? "; " : "",
			    validate_note_text(1u << b));
			if (w < 0 || (size_t)w >= sizeof buf - used)
				break;
			used += (size_t)w;
		}
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", c->rows[i].name);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", buf);
	}
	if (t.n_cells > 0)
		doc_table(d, &t);
	doc_table_clear(&t);
}

int
valreport_render(const struct cohort *c, const struct validate_report *v,
                 const struct model_calibration *cal, const char *cohort_name,
                 const char *date, unsigned char **pdf, size_t *n,
                 char *err, size_t errlen)
{
	*pdf = NULL;
	*n = 0;
	struct template *tpl = template_default();
	const char *base = strrchr(cohort_name, '/');
	base = base ? base + 1 : cohort_name;
	struct doc_info info = { .title = "Validation against real aircraft",
	                         .mission = base, .subject = "aeroeval accuracy",
	                         .date = date };
	struct doc *d = doc_alloc(tpl, &info);
	char sub[256];
	snprintf(sub, sizeof sub, "Cohort %s: predicted vs actual takeoff mass", base);
	doc_title(d, "Validation against real aircraft", sub);
	section_summary(d, v, cal, cohort_name);

	doc_heading(d, 1, "1  Predicted vs actual");
	figure_scatter(d, c, v);
	figure_classes(d, v);

	doc_heading(d, 1, "2  Per-row results");
	table_rows(d, c, v);
	doc_heading(d, 2, "2.1  Rows not in the statistics");
	table_excluded(d, c, v);
	doc_heading(d, 2, "2.2  Stand-ins for missing facts");
	table_notes(d, c, v);

	doc_heading(d, 1, "3  The mission rule");
	int nr = 0;
	while (valreport_rule_text[nr] != NULL)
		nr++;
	doc_bullets(d, valreport_rule_text, nr);

	int rc = doc_save_mem(d, pdf, n);
	if (rc != 0)
		snprintf(err, errlen, "%s", doc_error(d) ? doc_error(d) : "PDF rendering failed");
	doc_free(d);
	template_free(tpl);
	return rc;
}
