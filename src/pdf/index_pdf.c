/* index_pdf.c — overview.pdf (see index_pdf.h). */
#include "pdf/index_pdf.h"

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

#include "pdf/doc.h"
#include "pdf/plot.h"
#include "util/xalloc.h"

/* How each verdict is drawn, in enum table_row_status order. */
static const struct {
	enum plot_marker marker;
	int colour;
} looks[TABLE_ROW_STATUS_MAX] = {
	{ PLOT_MARKER_CIRCLE, PLOT_COLOUR_PASS },
	{ PLOT_MARKER_CROSS, PLOT_COLOUR_FAIL },
	{ PLOT_MARKER_TRIANGLE, PLOT_COLOUR_MUTED },
};

/* The x, y pair of a row in a figure; false when the row has none. */
typedef bool (*point_fn)(const struct table_row *w, double *x, double *y);

static bool
mtow_point(const struct table_row *w, double *x, double *y)
{
	*x = w->payload_kg;
	*y = w->takeoff_mass_kg;
	return true;
}

static bool
cost_point(const struct table_row *w, double *x, double *y)
{
	*x = w->hover_endurance_s / 60.0;
	*y = w->cost_usd;
	return w->status != TABLE_ROW_NOT_BUILDABLE && w->has_cost && w->has_endurance;
}

/* One scatter series per verdict, and the names when few. */
static void
scatter_by_status(struct plot_panel *pp, const struct table_rows *s, point_fn fn)
{
	double *x = xmalloc((s->n + 1) * sizeof *x), *y = xmalloc((s->n + 1) * sizeof *y);
	size_t shown = 0;
	for (int st = 0; st < TABLE_ROW_STATUS_MAX; st++) {
		size_t n = 0;
		for (size_t i = 0; i < s->n; i++)
			if (s->rows[i].status == (enum table_row_status)st && fn(&s->rows[i], &x[n], &y[n]))
				n++;
		if (n > 0)
			plot_scatter(pp, x, y, n, table_row_status_name(st), looks[st].marker,
			    looks[st].colour);
		shown += n;
	}
	for (size_t i = 0; shown <= INDEX_PDF_MAX_LABELS && i < s->n; i++)
		if (fn(&s->rows[i], &x[0], &y[0]))
			plot_point_label(pp, x[0], y[0], s->rows[i].name);
	free(x);
	free(y);
}

static void
figure_mtow(struct doc *d, const struct table_rows *s)
{
	struct plot *p = plot_alloc(0, 300, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Payload (kg)");
	plot_axis_title(pp, PLOT_Y, "Takeoff mass of record (kg)");
	/* A study spans racing quads to sprayers: logarithmic axes keep the
	 * small ones readable, unless a payload of zero has no place on one. */
	bool log_x = true;
	for (size_t i = 0; i < s->n; i++)
		log_x = log_x && s->rows[i].payload_kg > 0.0;
	plot_axis_log(pp, PLOT_X, log_x);
	plot_axis_log(pp, PLOT_Y, 1);
	for (size_t i = 0; i < s->n; i++) {
		const struct table_row *w = &s->rows[i];
		if (!w->has_interval)
			continue;
		double x[2] = { w->payload_kg, w->payload_kg };
		double y[2] = { w->mtow_lo_kg, w->mtow_hi_kg };
		plot_line(pp, x, y, 2, NULL, PLOT_COLOUR_MUTED, PLOT_DASH_SOLID);
	}
	scatter_by_status(pp, s, mtow_point);
	plot_legend(pp, PLOT_LEGEND_BELOW);
	doc_figure(d, p, "Takeoff mass of record against payload, one marker per verdict; "
	    "a vertical bar is the prediction interval where result.json gives one.");
	plot_free(p);
}

static void
figure_cost(struct doc *d, const struct table_rows *s)
{
	size_t n = 0;
	double x, y;
	for (size_t i = 0; i < s->n; i++)
		n += cost_point(&s->rows[i], &x, &y);
	if (n == 0) {
		doc_paragraph(d, "No design of this study is buildable with known prices, so "
		    "there is no cost figure.");
		return;
	}
	struct plot *p = plot_alloc(0, 260, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Hover endurance (min)");
	plot_axis_title(pp, PLOT_Y, "Cost of the priced parts (USD)");
	scatter_by_status(pp, s, cost_point);
	plot_legend(pp, PLOT_LEGEND_BELOW);
	doc_figure(d, p, "Cost against hover endurance of the buildable designs.  The cost "
	    "is the sum of the known catalogue prices: a lower bound where some are unknown "
	    "(index.csv, unpriced_lines).");
	plot_free(p);
}

static void
table_rows(struct doc *d, const struct table_rows *s)
{
	static const struct doc_column cols[] = {
		{ "Mission", 2.4, DOC_ALIGN_LEFT }, { "Verdict", 1.3, DOC_ALIGN_LEFT },
		{ "MTOW (kg)", 1.0, DOC_ALIGN_RIGHT }, { "Payload (kg)", 1.0, DOC_ALIGN_RIGHT },
		{ "Hover (min)", 0.9, DOC_ALIGN_RIGHT }, { "Cost (USD)", 1.2, DOC_ALIGN_RIGHT },
		{ "Tightest check", 2.4, DOC_ALIGN_LEFT },
	};
	static const enum doc_cell verdict_cell[TABLE_ROW_STATUS_MAX] = {
		DOC_CELL_PASS, DOC_CELL_FAIL, DOC_CELL_WARN
	};
	struct doc_table t;
	doc_table_init(&t, cols, 7);
	for (size_t i = 0; i < s->n; i++) {
		const struct table_row *w = &s->rows[i];
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", w->name);
		doc_table_cell(&t, verdict_cell[w->status], "%s", table_row_status_name(w->status));
		doc_table_cell(&t, DOC_CELL_NORMAL, "%.3f", w->takeoff_mass_kg);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%.3f", w->payload_kg);
		if (w->has_endurance)
			doc_table_cell(&t, DOC_CELL_NORMAL, "%.1f", w->hover_endurance_s / 60.0);
		else
			doc_table_cell(&t, DOC_CELL_MUTED, "–");
		if (w->has_cost)
			doc_table_cell(&t, DOC_CELL_NORMAL, "%.2f%s", w->cost_usd,
			    w->unpriced_lines > 0 ? "+" : "");
		else
			doc_table_cell(&t, DOC_CELL_MUTED, "–");
		if (w->tightest[0] != '\0')
			doc_table_cell(&t, DOC_CELL_NORMAL, "%s (%+.1f %%)", w->tightest,
			    100.0 * w->tightest_margin);
		else
			doc_table_cell(&t, DOC_CELL_MUTED, "–");
	}
	doc_table(d, &t);
	doc_table_clear(&t);
}

int
index_pdf_render(const struct table_rows *s, const struct template *tpl,
                 unsigned char **pdf, size_t *n, char *err, size_t errlen)
{
	*pdf = NULL;
	*n = 0;
	size_t c[TABLE_ROW_STATUS_MAX];
	table_row_count(s, c);
	char sub[160];
	snprintf(sub, sizeof sub, "%zu compiled missions: %zu feasible, %zu infeasible, "
	    "%zu not buildable", s->n, c[TABLE_ROW_FEASIBLE], c[TABLE_ROW_INFEASIBLE],
	    c[TABLE_ROW_NOT_BUILDABLE]);
	struct doc_info info = { .title = "Design space", .mission = "overview",
	                         .subject = "aeroeval study overview" };
	struct doc *d = doc_alloc(tpl, &info);
	doc_title(d, "Design space", sub);
	doc_heading(d, 2, "1  Mass and payload");
	figure_mtow(d, s);
	doc_ensure_space(d, 330);  /* the heading stays with its figure */
	doc_heading(d, 2, "2  Cost and endurance");
	figure_cost(d, s);
	doc_heading(d, 2, "3  Every mission");
	doc_paragraph(d, "Cost marked + omits parts whose price the catalogue does not "
	    "know.  The tightest check is the failing check of an infeasible design, else "
	    "the passing check with the least margin; checks the design is sized to by "
	    "construction are left out.");
	table_rows(d, s);
	int rc = doc_save_mem(d, pdf, n);
	if (rc != 0)
		snprintf(err, errlen, "%s", doc_error(d) ? doc_error(d) : "PDF rendering failed");
	doc_free(d);
	return rc;
}
