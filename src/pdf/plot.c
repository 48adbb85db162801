/* plot.c — figures in data units, laid out and drawn as vectors (plot.h).
 *
 * Drawing works in figure coordinates: points, origin at the figure's top
 * left, y down (cairo's convention).  Every path is built with cairo on an
 * unbounded recording surface (a small image surface silently drops
 * geometry outside it: docs/libraries.md, cairo) and then replayed into the
 * libharu page with y flipped; text never goes through cairo, so no
 * fontconfig is involved.
 */
#include "pdf/plot.h"

#include <cairo.h>
#include <hpdf.h>
#include <hpdf_pages.h>      /* internals: a page's content stream and mode */
#include <hpdf_utils.h>      /* HPDF_FToA: numbers as libharu writes them */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/strbuf.h"
#include "util/xalloc.h"

/* Type sizes and strokes of an engineering figure (points). */
#define FS_TICK 7.0         /* tick labels */
#define FS_AXIS 7.5         /* axis titles */
#define FS_LEGEND 7.0
#define FS_TITLE 8.5        /* panel title */
#define FS_NOTE 6.8         /* reference-line labels, point labels */
#define LW_GRID 0.35
#define LW_MINOR 0.2
#define LW_FRAME 0.6
#define LW_SERIES 1.2
#define MARKER_PT 4.5
#define TICK_LEN 2.5
#define PANEL_GAP 8.0       /* between panels of a grid */
#define TICK_TARGET_X 7     /* about this many ticks on an x axis */
#define TICK_TARGET_Y 6
#define AXIS_PAD 0.03    /* automatic range headroom, fraction of the span */
#define COLOUR_WHITE 200   /* internal: text on dark bar segments */

enum item_kind {
	IT_SERIES, IT_BAND, IT_HLINE, IT_VLINE, IT_CROSS, IT_TEXT, IT_PLABEL,
	IT_BARS, IT_TORNADO
};

/* One thing drawn in a panel.  Which fields are used depends on kind. */
struct item {
	enum item_kind kind;
	size_t n;                 /* points in x/y/y2 */
	double *x, *y, *y2;       /* series: x,y; band: x,lo,hi; tornado: -,lo,hi */
	double px, py;            /* single-point items; tornado: centre in px */
	char *label;              /* legend or annotation text, may be NULL */
	int colour;               /* resolved: palette index or enum plot_colour */
	enum plot_dash dash;
	double width_pt;          /* line width, < 0 no line */
	enum plot_marker marker;
	double marker_pt;
	int open_marker;
	double alpha;             /* band fill opacity */
	enum plot_align align;    /* text */
	int n_cat;                /* bars: bars; tornado: rows */
	int n_stack;              /* bars: segments per bar */
	char **cat_labels;        /* n_cat labels */
	char **stack_labels;      /* bars: n_stack; tornado: 2 (lo, hi) */
	double *values;           /* bars: n_cat * n_stack */
	int decimals;             /* bars: value label decimals, < 0 none */
};

enum panel_kind { PK_XY, PK_BARS, PK_TORNADO };

struct plot_panel {
	char *title;
	char *axis_title[2];
	int log10[2];
	int fixed[2];
	double fix_lo[2], fix_hi[2];
	enum plot_legend legend;
	int legend_set;           /* caller chose the legend place */
	int next_colour;          /* next palette index for AUTO */
	enum panel_kind kind;
	struct item *items;
	int n_items, cap_items;
};

struct plot {
	double width_pt, height_pt;  /* width 0: text width */
	int n_rows, n_cols;
	struct plot_panel *panels;   /* row-major */
	struct label_log *log;       /* NULL, or where render records its labels */
};

/* The annotation labels of the last render (plot_keep_label_boxes). */
struct label_log {
	struct plot_label_box *v;
	int n, cap;
};

/* ---- building ----------------------------------------------------------- */

struct plot *
plot_alloc(double width_pt, double height_pt, int n_rows, int n_cols)
{
	struct plot *p = xcalloc(1, sizeof *p);
	p->width_pt = isfinite(width_pt) && width_pt > 0 ? width_pt : 0.0;
	p->height_pt = isfinite(height_pt) && height_pt > 40 ? height_pt : 200.0;
	p->n_rows = n_rows > 0 ? n_rows : 1;
	p->n_cols = n_cols > 0 ? n_cols : 1;
	p->panels = xcalloc((size_t)(p->n_rows * p->n_cols), sizeof *p->panels);
	return p;
}

static void
item_free(struct item *it)
{
	free(it->x);
	free(it->y);
	free(it->y2);
	free(it->label);
	for (int i = 0; it->cat_labels != NULL && i < it->n_cat; i++)
		free(it->cat_labels[i]);
	free(it->cat_labels);
	for (int i = 0; it->stack_labels != NULL && i < it->n_stack; i++)
		free(it->stack_labels[i]);
	free(it->stack_labels);
	free(it->values);
}

void
plot_free(struct plot *p)
{
	if (p == NULL)
		return;
	for (int i = 0; i < p->n_rows * p->n_cols; i++) {
		struct plot_panel *pp = &p->panels[i];
		for (int k = 0; k < pp->n_items; k++)
			item_free(&pp->items[k]);
		free(pp->items);
		free(pp->title);
		free(pp->axis_title[0]);
		free(pp->axis_title[1]);
	}
	free(p->panels);
	if (p->log != NULL)
		free(p->log->v);
	free(p->log);
	free(p);
}

void
plot_keep_label_boxes(struct plot *p)
{
	if (p->log == NULL)
		p->log = xcalloc(1, sizeof *p->log);
}

int
plot_label_boxes(const struct plot *p, const struct plot_label_box **out)
{
	*out = p->log != NULL ? p->log->v : NULL;
	return p->log != NULL ? p->log->n : 0;
}

double plot_width_pt(const struct plot *p) { return p->width_pt; }
double plot_height_pt(const struct plot *p) { return p->height_pt; }

struct plot_panel *
plot_panel(struct plot *p, int row, int col)
{
	if (row < 0 || row >= p->n_rows)
		row = 0;
	if (col < 0 || col >= p->n_cols)
		col = 0;
	return &p->panels[row * p->n_cols + col];
}

static char *
dup_or_null(const char *s)
{
	return s != NULL ? xstrdup(s) : NULL;
}

static void
replace_str(char **dst, const char *s)
{
	free(*dst);
	*dst = dup_or_null(s);
}

void plot_title(struct plot_panel *pp, const char *t) { replace_str(&pp->title, t); }

void
plot_axis_title(struct plot_panel *pp, enum plot_axis_id ax, const char *title)
{
	replace_str(&pp->axis_title[ax == PLOT_Y], title);
}

void
plot_axis_log(struct plot_panel *pp, enum plot_axis_id ax, int log10)
{
	pp->log10[ax == PLOT_Y] = log10 != 0;
}

void
plot_axis_range(struct plot_panel *pp, enum plot_axis_id ax, double lo, double hi)
{
	int a = ax == PLOT_Y;
	if (!isfinite(lo) || !isfinite(hi) || !(hi > lo))
		return;   /* a bad fixed range falls back to the automatic one */
	pp->fixed[a] = 1;
	pp->fix_lo[a] = lo;
	pp->fix_hi[a] = hi;
}

void
plot_legend(struct plot_panel *pp, enum plot_legend where)
{
	pp->legend = where;
	pp->legend_set = 1;
}

static struct item *
new_item(struct plot_panel *pp, enum item_kind kind, const char *label)
{
	if (pp->n_items == pp->cap_items) {
		pp->cap_items = pp->cap_items ? 2 * pp->cap_items : 8;
		pp->items = xrealloc(pp->items, (size_t)pp->cap_items * sizeof *pp->items);
	}
	struct item *it = &pp->items[pp->n_items++];
	memset(it, 0, sizeof *it);
	it->kind = kind;
	it->label = dup_or_null(label);
	it->width_pt = LW_SERIES;
	it->alpha = 1.0;
	return it;
}

static double *
dup_doubles(const double *v, size_t n)
{
	if (v == NULL || n == 0)
		return NULL;
	double *d = xmalloc(n * sizeof *d);
	memcpy(d, v, n * sizeof *d);
	return d;
}

static int
resolve_colour(struct plot_panel *pp, int colour)
{
	if (colour == PLOT_COLOUR_AUTO || colour < 0)
		return pp->next_colour++;
	return colour;
}

void
plot_series(struct plot_panel *pp, const double *x, const double *y, size_t n,
            const char *label, const struct plot_style *st)
{
	struct plot_style def = { .auto_colour = 1 };
	if (st == NULL)
		st = &def;
	struct item *it = new_item(pp, IT_SERIES, label);
	it->n = (x != NULL && y != NULL) ? n : 0;
	it->x = dup_doubles(x, it->n);
	it->y = dup_doubles(y, it->n);
	it->colour = resolve_colour(pp, st->auto_colour ? PLOT_COLOUR_AUTO : st->colour);
	it->dash = st->dash;
	it->width_pt = st->line_width_pt == 0 ? LW_SERIES : st->line_width_pt;
	it->marker = st->marker;
	it->marker_pt = st->marker_size_pt > 0 ? st->marker_size_pt : MARKER_PT;
	it->open_marker = st->open_marker;
}

void
plot_line(struct plot_panel *pp, const double *x, const double *y, size_t n,
          const char *label, int colour, enum plot_dash dash)
{
	struct plot_style st = { .colour = colour, .auto_colour = colour == PLOT_COLOUR_AUTO,
	                         .dash = dash };
	plot_series(pp, x, y, n, label, &st);
}

void
plot_scatter(struct plot_panel *pp, const double *x, const double *y, size_t n,
             const char *label, enum plot_marker marker, int colour)
{
	struct plot_style st = { .colour = colour, .auto_colour = colour == PLOT_COLOUR_AUTO,
	                         .line_width_pt = -1,
	                         .marker = marker == PLOT_MARKER_NONE ? PLOT_MARKER_CIRCLE : marker };
	plot_series(pp, x, y, n, label, &st);
}

static struct item *
point_item(struct plot_panel *pp, enum item_kind kind, double x, double y, const char *text)
{
	struct item *it = new_item(pp, kind, text);
	it->px = x;
	it->py = y;
	return it;
}

void
plot_point_label(struct plot_panel *pp, double x, double y, const char *text)
{
	point_item(pp, IT_PLABEL, x, y, text)->colour = PLOT_COLOUR_TEXT;
}

void
plot_text(struct plot_panel *pp, double x, double y, const char *text, enum plot_align align)
{
	struct item *it = point_item(pp, IT_TEXT, x, y, text);
	it->colour = PLOT_COLOUR_MUTED;
	it->align = align;
}

static void
ref_line(struct plot_panel *pp, enum item_kind kind, double x, double y, const char *label,
         int colour, enum plot_dash dash)
{
	struct item *it = point_item(pp, kind, x, y, label);
	it->colour = colour < 0 ? PLOT_COLOUR_MUTED : colour;
	it->dash = dash;
	it->width_pt = 0.9;
}

void
plot_hline(struct plot_panel *pp, double y, const char *label, int colour, enum plot_dash dash)
{
	ref_line(pp, IT_HLINE, NAN, y, label, colour, dash);
}

void
plot_vline(struct plot_panel *pp, double x, const char *label, int colour, enum plot_dash dash)
{
	ref_line(pp, IT_VLINE, x, NAN, label, colour, dash);
}

void
plot_crosshair(struct plot_panel *pp, double x, double y, const char *label, int colour)
{
	ref_line(pp, IT_CROSS, x, y, label, colour < 0 ? PLOT_COLOUR_ACCENT : colour,
	         PLOT_DASH_DASHED);
}

void
plot_band(struct plot_panel *pp, const double *x, const double *y_lo, const double *y_hi,
          size_t n, const char *label, int colour, double alpha)
{
	struct item *it = new_item(pp, IT_BAND, label);
	it->n = (x != NULL && y_lo != NULL && y_hi != NULL) ? n : 0;
	it->x = dup_doubles(x, it->n);
	it->y = dup_doubles(y_lo, it->n);
	it->y2 = dup_doubles(y_hi, it->n);
	it->colour = resolve_colour(pp, colour);
	it->alpha = isfinite(alpha) && alpha > 0 && alpha <= 1 ? alpha : 0.25;
}

static char **
dup_labels(const char *const *labels, int n)
{
	char **d = xcalloc((size_t)(n > 0 ? n : 1), sizeof *d);
	for (int i = 0; i < n; i++)
		d[i] = xstrdup(labels != NULL && labels[i] != NULL ? labels[i] : "");
	return d;
}

void
plot_stacked_bars(struct plot_panel *pp, int n_bars, const char *const *bar_labels,
                  int n_stack, const char *const *stack_labels, const double *values,
                  int decimals)
{
	if (n_bars <= 0 || n_stack <= 0 || values == NULL)
		return;
	struct item *it = new_item(pp, IT_BARS, NULL);
	it->n_cat = n_bars;
	it->n_stack = n_stack;
	it->cat_labels = dup_labels(bar_labels, n_bars);
	it->stack_labels = dup_labels(stack_labels, n_stack);
	it->values = dup_doubles(values, (size_t)(n_bars * n_stack));
	it->decimals = decimals > 6 ? 6 : decimals;
	pp->kind = PK_BARS;
	if (!pp->legend_set)
		pp->legend = PLOT_LEGEND_RIGHT;
}

void
plot_tornado(struct plot_panel *pp, int n, const char *const *labels, const double *lo,
             const double *hi, double centre, const char *lo_label, const char *hi_label)
{
	if (n <= 0 || lo == NULL || hi == NULL)
		return;
	const char *lh[2] = { lo_label != NULL ? lo_label : "low",
	                      hi_label != NULL ? hi_label : "high" };
	struct item *it = new_item(pp, IT_TORNADO, NULL);
	it->n_cat = n;
	it->n = (size_t)n;
	it->cat_labels = dup_labels(labels, n);
	it->n_stack = 2;
	it->stack_labels = dup_labels(lh, 2);
	it->y = dup_doubles(lo, (size_t)n);
	it->y2 = dup_doubles(hi, (size_t)n);
	it->px = centre;
	pp->kind = PK_TORNADO;
	if (!pp->legend_set)
		pp->legend = PLOT_LEGEND_BELOW;
}

/* ---- ticks and scales ---------------------------------------------------- */

void
plot_ticks_linear(double dmin, double dmax, int target, struct plot_ticks *out)
{
	memset(out, 0, sizeof *out);
	if (target < 2)
		target = 2;
	if (target > PLOT_MAX_TICKS / 2)
		target = PLOT_MAX_TICKS / 2;
	if (!isfinite(dmin) && !isfinite(dmax)) {
		dmin = 0.0;
		dmax = 1.0;
	} else if (!isfinite(dmin)) {
		dmin = dmax;
	} else if (!isfinite(dmax)) {
		dmax = dmin;
	}
	if (dmax < dmin) {
		double t = dmin;
		dmin = dmax;
		dmax = t;
	}
	double mag = fmax(fabs(dmin), fabs(dmax));
	if (dmax - dmin <= 1e-12 * mag || dmax == dmin) {
		/* One value: a +-10 % window around it (or 0..1 around zero). */
		if (mag == 0.0) {
			dmin = 0.0;
			dmax = 1.0;
		} else {
			dmin -= 0.1 * mag;
			dmax += 0.1 * mag;
		}
	}
	static const double mant[] = { 1.0, 2.0, 2.5, 5.0, 10.0 };
	double raw = (dmax - dmin) / (target - 1);
	double p10 = pow(10.0, floor(log10(raw)));
	double step = 0.0, lo = 0.0, hi = 0.0;
	int k = 0, n = 0;
	for (;;) {
		while (k < 4 && mant[k] * p10 < raw * (1.0 - 1e-9))
			k++;
		step = mant[k] * p10;
		lo = floor(dmin / step + 1e-9) * step;
		hi = ceil(dmax / step - 1e-9) * step;
		n = (int)lround((hi - lo) / step) + 1;
		if (n <= target + 2 || k == 4)
			break;
		k++;
	}
	if (n > PLOT_MAX_TICKS)
		n = PLOT_MAX_TICKS;
	out->lo = lo;
	out->hi = hi;
	out->n = n;
	for (int i = 0; i < n; i++) {
		double v = lo + i * step;
		if (fabs(v) < 1e-9 * step)
			v = 0.0;   /* never print "-0.0" */
		out->v[i] = v;
		out->labelled[i] = 1;
	}
	int dec = (int)-floor(log10(step) + 1e-9);
	if (k == 2)
		dec++;   /* 2.5 x 10^k needs one more digit */
	out->decimals = dec > 0 ? dec : 0;
}

/* The largest 1-2-5 x 10^k value <= v (dir < 0) or smallest >= v (dir > 0). */
static double
nice125(double v, int dir)
{
	static const double m[] = { 1.0, 2.0, 5.0, 10.0 };
	double p10 = pow(10.0, floor(log10(v)));
	if (dir < 0) {
		double best = p10;
		for (int i = 0; i < 4; i++)
			if (m[i] * p10 <= v * (1.0 + 1e-9))
				best = m[i] * p10;
		return best;
	}
	for (int i = 0; i < 4; i++)
		if (m[i] * p10 >= v * (1.0 - 1e-9))
			return m[i] * p10;
	return 10.0 * p10;
}

static void
add_tick(struct plot_ticks *t, double v, int labelled)
{
	if (t->n < PLOT_MAX_TICKS && v >= t->lo * (1 - 1e-9) && v <= t->hi * (1 + 1e-9)) {
		t->v[t->n] = v;
		t->labelled[t->n] = labelled;
		t->n++;
	}
}

void
plot_ticks_log(double dmin, double dmax, struct plot_ticks *out)
{
	memset(out, 0, sizeof *out);
	out->log10 = 1;
	int okmin = isfinite(dmin) && dmin > 0, okmax = isfinite(dmax) && dmax > 0;
	if (!okmin && !okmax) {
		dmin = 1.0;
		dmax = 10.0;
	} else if (!okmin) {
		dmin = dmax;
	} else if (!okmax) {
		dmax = dmin;
	}
	if (dmax < dmin) {
		double t = dmin;
		dmin = dmax;
		dmax = t;
	}
	double lo = nice125(dmin, -1), hi = nice125(dmax, +1);
	if (hi <= lo * (1 + 1e-9)) {
		lo = nice125(lo * 0.999, -1);
		hi = nice125(hi * 1.001, +1);
	}
	out->lo = lo;
	out->hi = hi;
	double decades = log10(hi / lo);
	int e0 = (int)floor(log10(lo) + 1e-9), e1 = (int)ceil(log10(hi) - 1e-9);
	int every = decades > 8 ? (int)ceil(decades / 8) : 1;
	for (int e = e0; e <= e1; e++) {
		double p10 = pow(10.0, e);
		if (decades <= 3.05) {
			add_tick(out, p10, 1);
			add_tick(out, 2 * p10, 1);
			add_tick(out, 5 * p10, 1);
		} else {
			add_tick(out, p10, (e - e0) % every == 0);
			if (decades <= 8)
				for (int m = 2; m <= 9; m++)
					add_tick(out, m * p10, 0);
		}
	}
}

void
plot_tick_label(const struct plot_ticks *t, int i, char *buf, size_t cap)
{
	if (i < 0 || i >= t->n) {
		snprintf(buf, cap, "%s", "");
		return;
	}
	double v = t->v[i];
	double mag = fmax(fabs(t->lo), fabs(t->hi));
	if (t->log10 || t->decimals > 6 || mag >= 1e7)
		snprintf(buf, cap, "%g", v);
	else
		snprintf(buf, cap, "%.*f", t->decimals, v);
}

double
plot_scale_map(const struct plot_scale *s, double v)
{
	double a = s->lo, b = s->hi;
	if (!isfinite(v))
		return NAN;
	if (s->log10) {
		if (v <= 0 || a <= 0 || b <= 0)
			return NAN;
		v = log10(v);
		a = log10(a);
		b = log10(b);
	}
	if (b == a)
		return 0.5 * (s->p0 + s->p1);
	return s->p0 + (v - a) / (b - a) * (s->p1 - s->p0);
}

/* ---- rendering context, path replay, text --------------------------------- */

struct rctx {
	const struct plot_render *r;
	cairo_surface_t *surf;   /* unbounded recording surface: the path builder */
	cairo_t *cr;
	int failed;              /* cairo reported an error */
};

enum rp_op { RP_STROKE, RP_FILL, RP_CLIP };

static double px_(const struct rctx *c, double x) { return c->r->x_pt + x; }
static double py_(const struct rctx *c, double y) { return c->r->y_top_pt - y; }

/* Writes cairo's path as the page's path construction operators (m l c h),
 * in one piece into the page's content stream, and leaves the page
 * holding a path as libharu's own path calls would, so that libharu's
 * paint operator follows.  The bytes are the ones libharu's calls write
 * (its number format, one operator a line), but each of its path calls
 * costs ~3000 instructions of bookkeeping (it clears a 512-byte buffer
 * byte by byte) and a figure replays thousands of them.  Returns -1, having written
 * nothing, when the page is not between paths, for libharu's own calls
 * to raise the error. */
static int
write_path(struct rctx *c, const cairo_path_t *path)
{
	HPDF_Page pg = c->r->page;
	if (HPDF_Page_GetGMode(pg) != HPDF_GMODE_PAGE_DESCRIPTION)
		return -1;
	/* A number takes at most 12 bytes and its space 1: a curve (four
	 * path data) writes 6 numbers and "c\n". */
	char *buf = xmalloc((size_t)path->num_data * 24 + 16), *p = buf;
	HPDF_Point start = { 0, 0 }, at = { 0, 0 };
	for (int i = 0; i < path->num_data; i += path->data[i].header.length) {
		const cairo_path_data_t *d = &path->data[i];
		int n_pts = d->header.type == CAIRO_PATH_CURVE_TO ? 3
		          : d->header.type == CAIRO_PATH_CLOSE_PATH ? 0 : 1;
		for (int k = 1; k <= n_pts; k++) {
			at.x = (HPDF_REAL)px_(c, d[k].point.x);
			at.y = (HPDF_REAL)py_(c, d[k].point.y);
			p = HPDF_FToA(p, at.x, p + 13);
			*p++ = ' ';
			p = HPDF_FToA(p, at.y, p + 13);
			*p++ = ' ';
		}
		switch (d->header.type) {
		case CAIRO_PATH_MOVE_TO:
			*p++ = 'm';
			start = at;
			break;
		case CAIRO_PATH_LINE_TO:
			*p++ = 'l';
			break;
		case CAIRO_PATH_CURVE_TO:
			*p++ = 'c';
			break;
		case CAIRO_PATH_CLOSE_PATH:
			*p++ = 'h';
			at = start;
			break;
		}
		*p++ = '\n';
	}
	HPDF_PageAttr attr = pg->attr;
	HPDF_STATUS st = HPDF_Stream_Write(attr->stream, (const HPDF_BYTE *)buf, (HPDF_UINT)(p - buf));
	free(buf);
	attr->gmode = HPDF_GMODE_PATH_OBJECT;
	attr->str_pos = start;
	attr->cur_pos = at;
	if (st != HPDF_OK)
		c->failed = 1;
	return 0;
}

/* Replays cairo's current path into the page with the cairo state's colour,
 * line width and dash, then applies op.  An empty path emits nothing
 * (libharu raises an error for a paint operator without a path). */
static void
rp_apply(struct rctx *c, enum rp_op op)
{
	HPDF_Page pg = c->r->page;
	cairo_path_t *path = cairo_copy_path(c->cr);
	if (path == NULL || path->status != CAIRO_STATUS_SUCCESS) {
		c->failed = 1;
		cairo_path_destroy(path);
		cairo_new_path(c->cr);
		return;
	}
	if (path->num_data == 0) {
		cairo_path_destroy(path);
		return;
	}
	double r, g, b, a;
	if (cairo_pattern_get_rgba(cairo_get_source(c->cr), &r, &g, &b, &a) != CAIRO_STATUS_SUCCESS)
		r = g = b = 0.0;
	if (op == RP_STROKE) {
		HPDF_Page_SetRGBStroke(pg, (HPDF_REAL)r, (HPDF_REAL)g, (HPDF_REAL)b);
		HPDF_Page_SetLineWidth(pg, (HPDF_REAL)cairo_get_line_width(c->cr));
		HPDF_Page_SetLineJoin(pg, cairo_get_line_join(c->cr) == CAIRO_LINE_JOIN_ROUND
		                              ? HPDF_ROUND_JOIN : HPDF_MITER_JOIN);
		HPDF_Page_SetLineCap(pg, cairo_get_line_cap(c->cr) == CAIRO_LINE_CAP_ROUND
		                             ? HPDF_ROUND_END : HPDF_BUTT_END);
		int nd = cairo_get_dash_count(c->cr);
		if (nd > 0 && nd <= 8) {
			double d[8], off;
			HPDF_UINT16 u[8];
			cairo_get_dash(c->cr, d, &off);
			/* libharu dashes are integers (docs/libraries.md, libharu). */
			for (int i = 0; i < nd; i++)
				u[i] = (HPDF_UINT16)(d[i] < 1.0 ? 1 : lround(d[i]));
			HPDF_Page_SetDash(pg, u, (HPDF_UINT)nd, (HPDF_UINT)lround(off));
		} else {
			HPDF_Page_SetDash(pg, NULL, 0, 0);
		}
	} else if (op == RP_FILL) {
		HPDF_Page_SetRGBFill(pg, (HPDF_REAL)r, (HPDF_REAL)g, (HPDF_REAL)b);
	}
	/* The path in one piece; libharu's own path calls only where that
	 * cannot be (they then raise the error). */
	int from = write_path(c, path) == 0 ? path->num_data : 0;
	for (int i = from; i < path->num_data; i += path->data[i].header.length) {
		const cairo_path_data_t *d = &path->data[i];
		switch (d->header.type) {
		case CAIRO_PATH_MOVE_TO:
			HPDF_Page_MoveTo(pg, (HPDF_REAL)px_(c, d[1].point.x), (HPDF_REAL)py_(c, d[1].point.y));
			break;
		case CAIRO_PATH_LINE_TO:
			HPDF_Page_LineTo(pg, (HPDF_REAL)px_(c, d[1].point.x), (HPDF_REAL)py_(c, d[1].point.y));
			break;
		case CAIRO_PATH_CURVE_TO:
			HPDF_Page_CurveTo(pg, (HPDF_REAL)px_(c, d[1].point.x), (HPDF_REAL)py_(c, d[1].point.y),
			                  (HPDF_REAL)px_(c, d[2].point.x), (HPDF_REAL)py_(c, d[2].point.y),
			                  (HPDF_REAL)px_(c, d[3].point.x), (HPDF_REAL)py_(c, d[3].point.y));
			break;
		case CAIRO_PATH_CLOSE_PATH:
			HPDF_Page_ClosePath(pg);
			break;
		}
	}
	cairo_path_destroy(path);
	cairo_new_path(c->cr);
	if (op == RP_STROKE) {
		HPDF_Page_Stroke(pg);
	} else if (op == RP_FILL) {
		HPDF_Page_Fill(pg);
	} else {
		HPDF_Page_Clip(pg);
		HPDF_Page_EndPath(pg);
	}
}

static struct template_colour
colour_rgb(const struct template *t, int colour)
{
	if (colour >= 0 && colour < PLOT_COLOUR_TEXT) {
		/* Past the palette, repeat it lightened, so that up to 2n stacked
		 * segments stay distinguishable. */
		struct template_colour c = t->series[colour % t->n_series];
		if ((colour / t->n_series) % 2 == 1) {
			c.r = 0.5 * (c.r + 1.0);
			c.g = 0.5 * (c.g + 1.0);
			c.b = 0.5 * (c.b + 1.0);
		}
		return c;
	}
	switch (colour) {
	case PLOT_COLOUR_PRIMARY: return t->primary;
	case PLOT_COLOUR_ACCENT: return t->accent;
	case PLOT_COLOUR_MUTED: return t->muted;
	case PLOT_COLOUR_GRID: return t->grid;
	case PLOT_COLOUR_PASS: return t->pass;
	case PLOT_COLOUR_FAIL: return t->fail;
	case PLOT_COLOUR_WARN: return t->warn;
	case COLOUR_WHITE: return (struct template_colour){ 1.0, 1.0, 1.0 };
	default: return t->text;
	}
}

static void
set_source(struct rctx *c, int colour)
{
	struct template_colour k = colour_rgb(c->r->tpl, colour);
	cairo_set_source_rgb(c->cr, k.r, k.g, k.b);
}

static void
set_pen(struct rctx *c, int colour, double width, enum plot_dash dash)
{
	static const double dashed[] = { 4.0, 2.5 }, dotted[] = { 1.0, 2.0 },
	                    dashdot[] = { 5.0, 2.0, 1.0, 2.0 };
	set_source(c, colour);
	cairo_set_line_width(c->cr, width);
	cairo_set_line_join(c->cr, CAIRO_LINE_JOIN_ROUND);
	cairo_set_line_cap(c->cr, dash == PLOT_DASH_DOTTED ? CAIRO_LINE_CAP_ROUND
	                                                   : CAIRO_LINE_CAP_BUTT);
	switch (dash) {
	case PLOT_DASH_DASHED: cairo_set_dash(c->cr, dashed, 2, 0); break;
	case PLOT_DASH_DOTTED: cairo_set_dash(c->cr, dotted, 2, 0); break;
	case PLOT_DASH_DASHDOT: cairo_set_dash(c->cr, dashdot, 4, 0); break;
	default: cairo_set_dash(c->cr, NULL, 0, 0); break;
	}
}

static double
text_width(HPDF_Font f, double size, const char *s)
{
	if (s == NULL || *s == '\0')
		return 0.0;
	HPDF_TextWidth tw = HPDF_Font_TextWidth(f, (const HPDF_BYTE *)s, (HPDF_UINT)strlen(s));
	return tw.width * size / 1000.0;
}

void
plot_begin_text(HPDF_Page pg, HPDF_Font f, double size, struct template_colour k)
{
	HPDF_REAL sz = (HPDF_REAL)size;
	HPDF_REAL r = (HPDF_REAL)k.r, g = (HPDF_REAL)k.g, b = (HPDF_REAL)k.b;
	HPDF_Page_BeginText(pg);
	if (HPDF_Page_GetCurrentFont(pg) != f || HPDF_Page_GetCurrentFontSize(pg) != sz)
		HPDF_Page_SetFontAndSize(pg, f, sz);
	HPDF_RGBColor now = HPDF_Page_GetRGBFill(pg);
	if (HPDF_Page_GetFillingColorSpace(pg) != HPDF_CS_DEVICE_RGB ||
	    now.r != r || now.g != g || now.b != b)
		HPDF_Page_SetRGBFill(pg, r, g, b);
}

/* Draws text with baseline start (x, y) in figure coordinates, aligned on
 * x (or along the rotated baseline when rot90, reading bottom to top). */
static void
draw_text(struct rctx *c, HPDF_Font f, double size, double x, double y, const char *s,
          enum plot_align al, int rot90, int colour)
{
	if (s == NULL || *s == '\0')
		return;
	HPDF_Page pg = c->r->page;
	double w = text_width(f, size, s);
	double shift = al == PLOT_ALIGN_CENTER ? w / 2 : al == PLOT_ALIGN_RIGHT ? w : 0.0;
	struct template_colour k = colour_rgb(c->r->tpl, colour);
	plot_begin_text(pg, f, size, k);
	if (rot90)
		HPDF_Page_SetTextMatrix(pg, 0, 1, -1, 0, (HPDF_REAL)px_(c, x),
		                        (HPDF_REAL)py_(c, y + shift));
	else
		HPDF_Page_SetTextMatrix(pg, 1, 0, 0, 1, (HPDF_REAL)px_(c, x - shift),
		                        (HPDF_REAL)py_(c, y));
	HPDF_Page_ShowText(pg, s);
	HPDF_Page_EndText(pg);
	if (c->r->transcript != NULL) {
		strbuf_append_str(c->r->transcript, "| ");
		strbuf_append_str(c->r->transcript, s);
		strbuf_append_str(c->r->transcript, "\n");
	}
}

/* ---- panel layout ---------------------------------------------------------- */

struct legend_entry {
	const char *label;
	int colour;
	int swatch;              /* 0 line (+ marker), 1 filled box */
	enum plot_dash dash;
	double width_pt;
	enum plot_marker marker;
	int open_marker;
	double alpha;
};

#define MAX_LEGEND 48
#define MAX_LABELS 48      /* annotation labels of one panel kept for placing */
#define LABEL_CLEAR 2.0    /* space kept between a label and the data, pt */

/* Everything computed about a panel before it is drawn. */
struct layout {
	double cx, cy, cw, ch;          /* the panel's cell */
	double l, t, r, b;              /* plot area edges (figure coordinates) */
	struct plot_ticks tx, ty;       /* ticks (linear axes of bars/tornado too) */
	struct plot_scale sx, sy;       /* data -> figure */
	struct legend_entry le[MAX_LEGEND];
	int n_le;
	double le_w, le_h;              /* inside/right legend box size */
	int le_rows;                    /* below: rows used */
	enum plot_legend le_where;      /* resolved: AUTO means inside at le_x/le_y */
	double le_x, le_y;              /* inside/right legend box top-left */
	int n_cat;                      /* categories of bars/tornado */
	int has_xtitle;                 /* the x axis has a title */
	int panel;                      /* index of the panel, row-major */
	struct plot_label_box placed[MAX_LABELS]; /* annotation labels so far */
	int n_placed;
};

static void
widen(double *lo, double *hi, double v, int log10)
{
	if (!isfinite(v) || (log10 && v <= 0))
		return;
	if (v < *lo)
		*lo = v;
	if (v > *hi)
		*hi = v;
}

/* Data ranges of an x-y panel. */
static void
xy_ranges(const struct plot_panel *pp, double *x0, double *x1, double *y0, double *y1)
{
	int lx = pp->log10[0], ly = pp->log10[1];
	*x0 = *y0 = INFINITY;
	*x1 = *y1 = -INFINITY;
	for (int k = 0; k < pp->n_items; k++) {
		const struct item *it = &pp->items[k];
		switch (it->kind) {
		case IT_SERIES:
		case IT_BAND:
			for (size_t i = 0; i < it->n; i++) {
				int ok = isfinite(it->x[i]) && isfinite(it->y[i]) &&
				         !(lx && it->x[i] <= 0) && !(ly && it->y[i] <= 0);
				if (it->kind == IT_BAND)
					ok = ok && isfinite(it->y2[i]) && !(ly && it->y2[i] <= 0);
				if (!ok)
					continue;
				widen(x0, x1, it->x[i], lx);
				widen(y0, y1, it->y[i], ly);
				if (it->kind == IT_BAND)
					widen(y0, y1, it->y2[i], ly);
			}
			break;
		case IT_HLINE:
			widen(y0, y1, it->py, ly);
			break;
		case IT_VLINE:
			widen(x0, x1, it->px, lx);
			break;
		case IT_CROSS:
		case IT_TEXT:
		case IT_PLABEL:
			if (isfinite(it->px) && isfinite(it->py)) {
				widen(x0, x1, it->px, lx);
				widen(y0, y1, it->py, ly);
			}
			break;
		default:
			break;
		}
	}
}

/* Widens [lo, hi] by AXIS_PAD of its span (a factor on log axes), without
 * pushing a non-negative range below zero. */
static void
pad_range(double *lo, double *hi, int log10)
{
	if (!isfinite(*lo) || !isfinite(*hi) || *hi <= *lo)
		return;
	if (log10) {
		double f = pow(*hi / *lo, AXIS_PAD);
		*lo /= f;
		*hi *= f;
		return;
	}
	double pad = AXIS_PAD * (*hi - *lo);
	*lo = (*lo >= 0 && *lo - pad < 0) ? 0.0 : *lo - pad;
	*hi = (*hi <= 0 && *hi + pad > 0) ? 0.0 : *hi + pad;
}

static void
axis_ticks(const struct plot_panel *pp, int a, double d0, double d1, int target,
           struct plot_ticks *t)
{
	if (pp->fixed[a]) {
		d0 = pp->fix_lo[a];
		d1 = pp->fix_hi[a];
	}
	if (pp->log10[a] && !(pp->fixed[a] && d0 <= 0))
		plot_ticks_log(d0, d1, t);
	else
		plot_ticks_linear(d0, d1, target, t);
	if (pp->fixed[a]) {
		/* Keep the caller's range exactly; drop ticks outside it. */
		t->lo = d0;
		t->hi = d1;
		int m = 0;
		for (int i = 0; i < t->n; i++) {
			if (t->v[i] >= d0 - 1e-9 * fabs(d1 - d0) && t->v[i] <= d1 + 1e-9 * fabs(d1 - d0)) {
				t->v[m] = t->v[i];
				t->labelled[m] = t->labelled[i];
				m++;
			}
		}
		t->n = m;
	}
}

static void
legend_collect(const struct plot_panel *pp, struct layout *L)
{
	L->n_le = 0;
	for (int k = 0; k < pp->n_items && L->n_le < MAX_LEGEND; k++) {
		const struct item *it = &pp->items[k];
		if (it->kind == IT_SERIES || it->kind == IT_BAND) {
			if (it->label == NULL || it->label[0] == '\0')
				continue;
			struct legend_entry *e = &L->le[L->n_le++];
			memset(e, 0, sizeof *e);
			e->label = it->label;
			e->colour = it->colour;
			e->swatch = it->kind == IT_BAND;
			e->dash = it->dash;
			e->width_pt = it->width_pt;
			e->marker = it->marker;
			e->open_marker = it->open_marker;
			e->alpha = it->alpha;
		} else if (it->kind == IT_BARS || it->kind == IT_TORNADO) {
			for (int j = 0; j < it->n_stack && L->n_le < MAX_LEGEND; j++) {
				/* Bars list the top segment first, as the eye meets them. */
				int s = it->kind == IT_BARS ? it->n_stack - 1 - j : j;
				struct legend_entry *e = &L->le[L->n_le++];
				memset(e, 0, sizeof *e);
				e->label = it->stack_labels[s];
				e->colour = s;
				e->swatch = 1;
				e->alpha = 1.0;
			}
		}
	}
}

#define LE_SWATCH 14.0
#define LE_ROW 9.5
#define LE_PAD 4.0

static double
legend_entry_w(const struct rctx *c, const struct legend_entry *e)
{
	return LE_SWATCH + 3.0 + text_width(c->r->font, FS_LEGEND, e->label);
}

/* Rows needed to flow the legend entries across width w. */
static int
legend_rows(const struct rctx *c, const struct layout *L, double w)
{
	int rows = L->n_le > 0 ? 1 : 0;
	double x = 0.0;
	for (int i = 0; i < L->n_le; i++) {
		double ew = legend_entry_w(c, &L->le[i]) + 10.0;
		if (x > 0 && x + ew > w) {
			rows++;
			x = 0;
		}
		x += ew;
	}
	return rows;
}

/* How many data features fall inside the box (figure coordinates). */
static int
count_inside(const struct plot_panel *pp, const struct layout *L, double x0, double y0,
             double x1, double y1)
{
	int hits = 0;
#define INSIDE(X, Y) ((X) >= x0 && (X) <= x1 && (Y) >= y0 && (Y) <= y1)
	for (int k = 0; k < pp->n_items; k++) {
		const struct item *it = &pp->items[k];
		if (it->kind == IT_SERIES || it->kind == IT_BAND) {
			double qx = NAN, qy = NAN, qy2 = NAN;
			for (size_t i = 0; i < it->n; i++) {
				double X = plot_scale_map(&L->sx, it->x[i]);
				double Y = plot_scale_map(&L->sy, it->y[i]);
				double Y2 = it->kind == IT_BAND ? plot_scale_map(&L->sy, it->y2[i]) : Y;
				if (INSIDE(X, Y) || INSIDE(X, Y2))
					hits++;
				/* A band covers everything between its edges. */
				if (it->kind == IT_BAND && X >= x0 && X <= x1 &&
				    fmin(Y, Y2) <= y1 && fmax(Y, Y2) >= y0)
					hits++;
				/* Segments crossing the box with both ends outside. */
				for (int s = 1; s < 8 && isfinite(qx) && isfinite(X); s++) {
					double f = s / 8.0;
					double mx = qx + f * (X - qx);
					if (INSIDE(mx, qy + f * (Y - qy)) || INSIDE(mx, qy2 + f * (Y2 - qy2)))
						hits++;
				}
				qx = X;
				qy = Y;
				qy2 = Y2;
			}
		} else if (it->kind == IT_HLINE) {
			double Y = plot_scale_map(&L->sy, it->py);
			hits += Y >= y0 - 10 && Y <= y1 + 2;   /* its label sits above it */
		} else if (it->kind == IT_VLINE) {
			double X = plot_scale_map(&L->sx, it->px);
			hits += X >= x0 - 10 && X <= x1 + 10;
		} else if (it->kind == IT_CROSS || it->kind == IT_PLABEL || it->kind == IT_TEXT) {
			double X = plot_scale_map(&L->sx, it->px), Y = plot_scale_map(&L->sy, it->py);
			hits += X >= x0 - 60 && X <= x1 + 10 && Y >= y0 - 10 && Y <= y1 + 10;
		}
	}
#undef INSIDE
	return hits;
}

static void
set_scales(struct layout *L, const struct plot_panel *pp)
{
	if (pp->kind == PK_BARS) {
		L->sx = (struct plot_scale){ 0, L->n_cat, 0, L->l, L->r };
		L->sy = (struct plot_scale){ L->ty.lo, L->ty.hi, 0, L->b, L->t };
	} else if (pp->kind == PK_TORNADO) {
		L->sx = (struct plot_scale){ L->tx.lo, L->tx.hi, 0, L->l, L->r };
		L->sy = (struct plot_scale){ 0, L->n_cat, 0, L->t, L->b };
	} else {
		L->sx = (struct plot_scale){ L->tx.lo, L->tx.hi, L->tx.log10, L->l, L->r };
		L->sy = (struct plot_scale){ L->ty.lo, L->ty.hi, L->ty.log10, L->b, L->t };
	}
}

static void
layout_panel(const struct rctx *c, const struct plot_panel *pp, struct layout *L)
{
	char buf[64];
	double x0, x1, y0, y1;
	const struct item *cat = NULL;
	for (int k = 0; k < pp->n_items; k++)
		if (pp->items[k].kind == IT_BARS || pp->items[k].kind == IT_TORNADO)
			cat = &pp->items[k];
	L->n_cat = 0;
	if (pp->kind == PK_BARS && cat != NULL) {
		double top = 0.0;
		for (int i = 0; i < cat->n_cat; i++) {
			double s = 0.0;
			for (int k = 0; k < cat->n_stack; k++) {
				double v = cat->values[i * cat->n_stack + k];
				s += isfinite(v) && v > 0 ? v : 0.0;
			}
			top = fmax(top, s);
		}
		L->n_cat = cat->n_cat;
		axis_ticks(pp, 1, 0.0, top * 1.04, TICK_TARGET_Y, &L->ty);
		memset(&L->tx, 0, sizeof L->tx);
	} else if (pp->kind == PK_TORNADO && cat != NULL) {
		x0 = x1 = cat->px;
		for (int i = 0; i < cat->n_cat; i++) {
			widen(&x0, &x1, cat->y[i], 0);
			widen(&x0, &x1, cat->y2[i], 0);
		}
		L->n_cat = cat->n_cat;
		axis_ticks(pp, 0, x0, x1, TICK_TARGET_X, &L->tx);
		memset(&L->ty, 0, sizeof L->ty);
	} else {
		xy_ranges(pp, &x0, &x1, &y0, &y1);
		/* Headroom so that data and reference lines never sit on the frame;
		 * x only when markers could be cut in half at the edges. */
		pad_range(&y0, &y1, pp->log10[1]);
		for (int k = 0; k < pp->n_items; k++)
			if (pp->items[k].kind == IT_SERIES && pp->items[k].marker != PLOT_MARKER_NONE) {
				pad_range(&x0, &x1, pp->log10[0]);
				break;
			}
		axis_ticks(pp, 0, x0, x1, TICK_TARGET_X, &L->tx);
		axis_ticks(pp, 1, y0, y1, TICK_TARGET_Y, &L->ty);
	}

	/* Left margin: the widest y label (numbers, or tornado row names). */
	double ylab_w = 0.0;
	if (pp->kind == PK_TORNADO && cat != NULL) {
		for (int i = 0; i < cat->n_cat; i++)
			ylab_w = fmax(ylab_w, text_width(c->r->font, FS_TICK, cat->cat_labels[i]));
	} else {
		for (int i = 0; i < L->ty.n; i++) {
			if (!L->ty.labelled[i])
				continue;
			plot_tick_label(&L->ty, i, buf, sizeof buf);
			ylab_w = fmax(ylab_w, text_width(c->r->font, FS_TICK, buf));
		}
	}
	double last_xlab_w = 0.0;
	for (int i = 0; i < L->tx.n; i++) {
		if (!L->tx.labelled[i])
			continue;
		plot_tick_label(&L->tx, i, buf, sizeof buf);
		last_xlab_w = text_width(c->r->font, FS_TICK, buf);
	}

	L->has_xtitle = pp->axis_title[0] != NULL;
	legend_collect(pp, L);
	L->le_where = L->n_le == 0 ? PLOT_LEGEND_NONE : pp->legend;
	L->le_w = 0.0;
	for (int i = 0; i < L->n_le; i++)
		L->le_w = fmax(L->le_w, legend_entry_w(c, &L->le[i]));
	L->le_w += 2 * LE_PAD;
	L->le_h = L->n_le * LE_ROW + 2 * LE_PAD - 2.0;

	L->t = L->cy + (pp->title != NULL ? FS_TITLE + 6.0 : 5.0);
	L->l = L->cx + (pp->axis_title[1] != NULL ? FS_AXIS + 5.0 : 0.0) + ylab_w + TICK_LEN + 3.0;
	L->r = L->cx + L->cw - fmax(4.0, last_xlab_w / 2 + 1.0);
	if (L->le_where == PLOT_LEGEND_RIGHT) {
		L->r = L->cx + L->cw - L->le_w - 8.0;
	}
	double bottom_text = TICK_LEN + FS_TICK + 4.0 +
	                     (pp->axis_title[0] != NULL ? FS_AXIS + 5.0 : 0.0);
	L->b = L->cy + L->ch - bottom_text;
	set_scales(L, pp);

	if (L->le_where == PLOT_LEGEND_AUTO) {
		/* Try the four corners inside the plot, take the first free one. */
		double best_x = 0, best_y = 0;
		int best = -1;
		for (int corner = 0; corner < 4; corner++) {
			double bx = (corner % 2 == 0) ? L->r - L->le_w - 4 : L->l + 4;
			double by = (corner < 2) ? L->t + 4 : L->b - L->le_h - 4;
			int h = count_inside(pp, L, bx, by, bx + L->le_w, by + L->le_h);
			if (best < 0 || h < best) {
				best = h;
				best_x = bx;
				best_y = by;
			}
		}
		if (best == 0 && L->le_w < 0.6 * (L->r - L->l) && L->le_h < 0.6 * (L->b - L->t)) {
			L->le_x = best_x;
			L->le_y = best_y;
		} else {
			L->le_where = PLOT_LEGEND_BELOW;
		}
	}
	if (L->le_where == PLOT_LEGEND_BELOW) {
		L->le_rows = legend_rows(c, L, L->cx + L->cw - L->l);
		L->b -= L->le_rows * LE_ROW + 6.0;
		set_scales(L, pp);
	} else if (L->le_where == PLOT_LEGEND_RIGHT) {
		L->le_x = L->r + 8.0;
		L->le_y = L->t;
	}
}

/* ---- drawing --------------------------------------------------------------- */

static void
rect_path(struct rctx *c, double x0, double y0, double x1, double y1)
{
	cairo_rectangle(c->cr, fmin(x0, x1), fmin(y0, y1), fabs(x1 - x0), fabs(y1 - y0));
}

static void
marker_path(struct rctx *c, enum plot_marker m, double x, double y, double size)
{
	double h = size / 2;
	cairo_t *cr = c->cr;
	switch (m) {
	case PLOT_MARKER_SQUARE:
		h *= 0.88;
		cairo_rectangle(cr, x - h, y - h, 2 * h, 2 * h);
		break;
	case PLOT_MARKER_TRIANGLE:
		cairo_move_to(cr, x, y - 1.15 * h);
		cairo_line_to(cr, x + 1.1 * h, y + 0.75 * h);
		cairo_line_to(cr, x - 1.1 * h, y + 0.75 * h);
		cairo_close_path(cr);
		break;
	case PLOT_MARKER_DIAMOND:
		cairo_move_to(cr, x, y - 1.2 * h);
		cairo_line_to(cr, x + h, y);
		cairo_line_to(cr, x, y + 1.2 * h);
		cairo_line_to(cr, x - h, y);
		cairo_close_path(cr);
		break;
	case PLOT_MARKER_CROSS:
		cairo_move_to(cr, x - h, y - h);
		cairo_line_to(cr, x + h, y + h);
		cairo_move_to(cr, x - h, y + h);
		cairo_line_to(cr, x + h, y - h);
		break;
	default:
		cairo_new_sub_path(cr);
		cairo_arc(cr, x, y, h, 0, 2 * M_PI);
		cairo_close_path(cr);
		break;
	}
}

static void
draw_marker(struct rctx *c, enum plot_marker m, double x, double y, double size, int colour,
            int open)
{
	marker_path(c, m, x, y, size);
	if (m == PLOT_MARKER_CROSS || open) {
		set_pen(c, colour, m == PLOT_MARKER_CROSS ? 1.1 : 0.9, PLOT_DASH_SOLID);
		rp_apply(c, RP_STROKE);
	} else {
		set_source(c, colour);
		rp_apply(c, RP_FILL);
	}
}

static HPDF_ExtGState
alpha_state(struct rctx *c, double alpha)
{
	HPDF_ExtGState gs = HPDF_CreateExtGState(c->r->pdf);
	if (gs != NULL)
		HPDF_ExtGState_SetAlphaFill(gs, (HPDF_REAL)alpha);
	return gs;
}

static void
draw_band(struct rctx *c, const struct layout *L, const struct item *it)
{
	/* Each run of valid points is one closed polygon: along y_hi, back
	 * along y_lo.  Invalid points split the band. */
	size_t i = 0;
	HPDF_ExtGState gs = it->alpha < 1.0 ? alpha_state(c, it->alpha) : NULL;
	HPDF_Page_GSave(c->r->page);
	if (gs != NULL)
		HPDF_Page_SetExtGState(c->r->page, gs);
	while (i < it->n) {
		size_t j = i;
		while (j < it->n && isfinite(plot_scale_map(&L->sx, it->x[j])) &&
		       isfinite(plot_scale_map(&L->sy, it->y[j])) &&
		       isfinite(plot_scale_map(&L->sy, it->y2[j])))
			j++;
		if (j - i >= 2) {
			for (size_t k = i; k < j; k++) {
				double X = plot_scale_map(&L->sx, it->x[k]);
				double Y = plot_scale_map(&L->sy, it->y2[k]);
				if (k == i)
					cairo_move_to(c->cr, X, Y);
				else
					cairo_line_to(c->cr, X, Y);
			}
			for (size_t k = j; k-- > i;)
				cairo_line_to(c->cr, plot_scale_map(&L->sx, it->x[k]),
				              plot_scale_map(&L->sy, it->y[k]));
			cairo_close_path(c->cr);
		}
		i = j + 1;
	}
	set_source(c, it->colour);
	rp_apply(c, RP_FILL);
	HPDF_Page_GRestore(c->r->page);
}

static void
draw_series(struct rctx *c, const struct layout *L, const struct item *it)
{
	if (it->width_pt > 0) {
		int pen_down = 0;
		for (size_t i = 0; i < it->n; i++) {
			double X = plot_scale_map(&L->sx, it->x[i]);
			double Y = plot_scale_map(&L->sy, it->y[i]);
			if (!isfinite(X) || !isfinite(Y)) {
				pen_down = 0;   /* a gap, never a jump across it */
				continue;
			}
			if (pen_down)
				cairo_line_to(c->cr, X, Y);
			else
				cairo_move_to(c->cr, X, Y);
			pen_down = 1;
		}
		set_pen(c, it->colour, it->width_pt, it->dash);
		rp_apply(c, RP_STROKE);
	}
	if (it->marker != PLOT_MARKER_NONE) {
		/* All markers of a series as one path, painted once. */
		for (size_t i = 0; i < it->n; i++) {
			double X = plot_scale_map(&L->sx, it->x[i]);
			double Y = plot_scale_map(&L->sy, it->y[i]);
			if (isfinite(X) && isfinite(Y))
				marker_path(c, it->marker, X, Y, it->marker_pt);
		}
		if (it->marker == PLOT_MARKER_CROSS || it->open_marker) {
			set_pen(c, it->colour, it->marker == PLOT_MARKER_CROSS ? 1.1 : 0.9,
			        PLOT_DASH_SOLID);
			rp_apply(c, RP_STROKE);
		} else {
			set_source(c, it->colour);
			rp_apply(c, RP_FILL);
		}
	}
}

static double
luminance(struct template_colour k)
{
	return 0.299 * k.r + 0.587 * k.g + 0.114 * k.b;
}

static void
draw_bars(struct rctx *c, const struct layout *L, const struct item *it)
{
	double slot = (L->r - L->l) / it->n_cat;
	double bw = fmin(0.5 * slot, 70.0);
	char buf[48];
	for (int i = 0; i < it->n_cat; i++) {
		double xc = plot_scale_map(&L->sx, i + 0.5), acc = 0.0;
		for (int k = 0; k < it->n_stack; k++) {
			double v = it->values[i * it->n_stack + k];
			if (!isfinite(v) || v <= 0)
				continue;
			double y0 = plot_scale_map(&L->sy, acc), y1 = plot_scale_map(&L->sy, acc + v);
			acc += v;
			rect_path(c, xc - bw / 2, y0, xc + bw / 2, y1);
			set_source(c, k);
			rp_apply(c, RP_FILL);
			/* A thin white seam keeps adjacent segments apart. */
			cairo_move_to(c->cr, xc - bw / 2, y1);
			cairo_line_to(c->cr, xc + bw / 2, y1);
			cairo_set_source_rgb(c->cr, 1, 1, 1);
			cairo_set_line_width(c->cr, 0.5);
			cairo_set_dash(c->cr, NULL, 0, 0);
			rp_apply(c, RP_STROKE);
			/* One segment: its value is the total printed above. */
			if (it->decimals >= 0 && it->n_stack > 1 && fabs(y0 - y1) >= FS_NOTE + 2.0) {
				snprintf(buf, sizeof buf, "%.*f", it->decimals, v);
				if (text_width(c->r->font, FS_NOTE, buf) < bw - 2) {
					int dark = luminance(colour_rgb(c->r->tpl, k)) > 0.6;
					draw_text(c, c->r->font, FS_NOTE, xc, 0.5 * (y0 + y1) + FS_NOTE * 0.35,
					          buf, PLOT_ALIGN_CENTER, 0, dark ? PLOT_COLOUR_TEXT : COLOUR_WHITE);
				}
			}
		}
		if (it->decimals >= 0) {
			snprintf(buf, sizeof buf, "%.*f", it->decimals, acc);
			draw_text(c, c->r->bold, FS_TICK, xc, plot_scale_map(&L->sy, acc) - 3.0, buf,
			          PLOT_ALIGN_CENTER, 0, PLOT_COLOUR_TEXT);
		}
		draw_text(c, c->r->font, FS_TICK, xc, L->b + TICK_LEN + FS_TICK + 1.0,
		          it->cat_labels[i], PLOT_ALIGN_CENTER, 0, PLOT_COLOUR_TEXT);
	}
}

static void
draw_tornado(struct rctx *c, const struct layout *L, const struct item *it)
{
	double row = (L->b - L->t) / it->n_cat;
	double xc = plot_scale_map(&L->sx, it->px);
	for (int i = 0; i < it->n_cat; i++) {
		double yc = plot_scale_map(&L->sy, i + 0.5);
		double v[2] = { it->y[i], it->y2[i] };
		for (int s = 0; s < 2; s++) {
			double X = plot_scale_map(&L->sx, v[s]);
			if (!isfinite(X) || !isfinite(xc))
				continue;
			rect_path(c, xc, yc - 0.32 * row, X, yc + 0.32 * row);
			set_source(c, s);
			rp_apply(c, RP_FILL);
		}
		draw_text(c, c->r->font, FS_TICK, L->l - TICK_LEN - 3.0, yc + FS_TICK * 0.35,
		          it->cat_labels[i], PLOT_ALIGN_RIGHT, 0, PLOT_COLOUR_TEXT);
	}
	if (isfinite(xc)) {
		cairo_move_to(c->cr, xc, L->t);
		cairo_line_to(c->cr, xc, L->b);
		set_pen(c, PLOT_COLOUR_TEXT, 0.8, PLOT_DASH_SOLID);
		rp_apply(c, RP_STROKE);
	}
}

/* Reference lines, crosshairs (inside the clip). */
static void
draw_refs(struct rctx *c, const struct layout *L, const struct item *it)
{
	double X = plot_scale_map(&L->sx, it->px), Y = plot_scale_map(&L->sy, it->py);
	if ((it->kind == IT_HLINE || it->kind == IT_CROSS) && isfinite(Y)) {
		cairo_move_to(c->cr, L->l, Y);
		cairo_line_to(c->cr, L->r, Y);
	}
	if ((it->kind == IT_VLINE || it->kind == IT_CROSS) && isfinite(X)) {
		cairo_move_to(c->cr, X, L->t);
		cairo_line_to(c->cr, X, L->b);
	}
	set_pen(c, it->colour, it->kind == IT_CROSS ? 0.7 : it->width_pt, it->dash);
	rp_apply(c, RP_STROKE);
	if (it->kind == IT_CROSS && isfinite(X) && isfinite(Y)) {
		cairo_new_sub_path(c->cr);
		cairo_arc(c->cr, X, Y, 4.0, 0, 2 * M_PI);
		cairo_close_path(c->cr);
		set_pen(c, it->colour, 1.2, PLOT_DASH_SOLID);
		rp_apply(c, RP_STROKE);
	}
}

/* A white rectangle under an annotation label. */
static void
label_ground(struct rctx *c, double x0, double y0, double x1, double y1)
{
	rect_path(c, x0, y0, x1, y1);
	cairo_set_source_rgb(c->cr, 1, 1, 1);
	rp_apply(c, RP_FILL);
}

/* ---- annotation labels: placed where they cover nothing ------------------ */

static int
boxes_meet(const struct plot_label_box *a, double x0, double y0, double x1, double y1)
{
	return a->x0 < x1 && x0 < a->x1 && a->y0 < y1 && y0 < a->y1;
}

/* Does the segment (ax, ay)-(bx, by) cross or touch the box?  Clipped
 * against the box's slabs (Liang-Barsky). */
static int
segment_meets_box(double ax, double ay, double bx, double by, double x0, double y0,
                  double x1, double y1)
{
	double t0 = 0.0, t1 = 1.0, dx = bx - ax, dy = by - ay;
	double p[4] = { -dx, dx, -dy, dy }, q[4] = { ax - x0, x1 - ax, ay - y0, y1 - ay };
	for (int i = 0; i < 4; i++) {
		if (p[i] == 0.0) {
			if (q[i] < 0.0)
				return 0;
			continue;
		}
		double t = q[i] / p[i];
		if (p[i] < 0.0)
			t0 = fmax(t0, t);
		else
			t1 = fmin(t1, t);
		if (t0 > t1)
			return 0;
	}
	return 1;
}

/* The page points of a panel's series, mapped once for all the places a
 * label is tried at (label_cost): mapping a point on a log scale takes
 * three logarithms. */
struct mapped_points {
	double *X, *Y;           /* per item: its points, NULL for other items */
};

static void
map_series(const struct plot_panel *pp, const struct layout *L, struct mapped_points *mp)
{
	for (int k = 0; k < pp->n_items; k++) {
		const struct item *it = &pp->items[k];
		mp[k].X = mp[k].Y = NULL;
		if (it->kind != IT_SERIES || it->n == 0)
			continue;
		mp[k].X = xmalloc(2 * it->n * sizeof *mp[k].X);
		mp[k].Y = mp[k].X + it->n;
		for (size_t i = 0; i < it->n; i++) {
			mp[k].X[i] = plot_scale_map(&L->sx, it->x[i]);
			mp[k].Y[i] = plot_scale_map(&L->sy, it->y[i]);
		}
	}
}

/* What a label at the box would cover: data lines and markers, other
 * reference lines, the labels placed before it and the legend.  Two labels
 * on top of each other, or a label leaving the plot, cost most; a label
 * over the data costs per segment it hides. */
static double
label_cost(const struct plot_panel *pp, const struct layout *L, const struct item *self,
           const struct mapped_points *mp, double x0, double y0, double x1, double y1,
           int *data_hits)
{
	double cost = 0.0;
	int hits = 0;
	/* Data is kept LABEL_CLEAR away from the text, not just off it. */
	x0 -= LABEL_CLEAR, y0 -= LABEL_CLEAR, x1 += LABEL_CLEAR, y1 += LABEL_CLEAR;
	double m = 0.5 + LABEL_CLEAR;
	if (x0 < L->l - m || x1 > L->r + m || y0 < L->t - m || y1 > L->b + m)
		cost += 500.0;
	for (int i = 0; i < L->n_placed; i++)
		if (boxes_meet(&L->placed[i], x0, y0, x1, y1))
			cost += 1000.0;
	if (L->le_where == PLOT_LEGEND_AUTO) {
		struct plot_label_box le = { L->le_x, L->le_y, L->le_x + L->le_w, L->le_y + L->le_h, 0, 0, 0 };
		if (boxes_meet(&le, x0, y0, x1, y1))
			cost += 1000.0;
	}
	for (int k = 0; k < pp->n_items; k++) {
		const struct item *it = &pp->items[k];
		if (it == self)
			continue;
		if (it->kind == IT_SERIES) {
			double qx = NAN, qy = NAN, r = it->marker != PLOT_MARKER_NONE ? 0.5 * it->marker_pt : 0.0;
			for (size_t i = 0; i < it->n; i++) {
				double X = mp[k].X[i], Y = mp[k].Y[i];
				if (!isfinite(X) || !isfinite(Y)) {
					qx = NAN;
					continue;
				}
				if (r > 0.0 && X >= x0 - r && X <= x1 + r && Y >= y0 - r && Y <= y1 + r)
					hits++;
				if (it->width_pt > 0 && isfinite(qx) && segment_meets_box(qx, qy, X, Y, x0, y0, x1, y1))
					hits++;
				qx = X;
				qy = Y;
			}
		} else if (it->kind == IT_HLINE || it->kind == IT_CROSS) {
			double Y = plot_scale_map(&L->sy, it->py);
			cost += isfinite(Y) && Y >= y0 && Y <= y1 ? 20.0 : 0.0;
		}
		if (it->kind == IT_VLINE || it->kind == IT_CROSS) {
			double X = plot_scale_map(&L->sx, it->px);
			cost += isfinite(X) && X >= x0 && X <= x1 ? 20.0 : 0.0;
		}
	}
	*data_hits = hits;
	return cost + 30.0 * hits;
}

/* Candidate places of one label, best first by convention. */
struct label_spot {
	double x0, y0, x1, y1;    /* the box the text fills */
	double tx, ty;            /* where draw_text starts */
	enum plot_align align;
	int rot90;
};

static int
label_spots(const struct layout *L, const struct item *it, double w, struct label_spot *s)
{
	double X = plot_scale_map(&L->sx, it->px), Y = plot_scale_map(&L->sy, it->py);
	double asc = 0.75 * FS_NOTE, desc = 0.2 * FS_NOTE;
	int n = 0;
	switch (it->kind) {
	case IT_HLINE:
		if (!isfinite(Y) || Y < L->t - 0.5 || Y > L->b + 0.5)
			return 0;
		/* Above the line, then below it; at the right end, then the
		 * left, then the middle. */
		for (int side = 0; side < 2; side++) {
			double by = side == 0 ? Y - 3.0 : Y + FS_NOTE + 2.0;
			double xs[3] = { L->r - 3.0 - w, L->l + 3.0, 0.5 * (L->l + L->r - w) };
			for (int k = 0; k < 3; k++)
				s[n++] = (struct label_spot){ xs[k] - 1.0, by - asc, xs[k] + w + 1.0, by + desc,
				                              xs[k], by, PLOT_ALIGN_LEFT, 0 };
		}
		break;
	case IT_VLINE:
		if (!isfinite(X) || X < L->l - 0.5 || X > L->r + 0.5)
			return 0;
		/* Along the line reading upwards: at the top, right of the line
		 * then left of it; then at the bottom. */
		for (int end = 0; end < 2; end++) {
			double y0 = end == 0 ? L->t + 3.0 : L->b - 3.0 - w;
			for (int side = 0; side < 2; side++) {
				double bx = side == 0 ? X + 2.0 + asc : X - 2.0 - desc;
				s[n++] = (struct label_spot){ bx - asc, y0 - 1.0, bx + desc, y0 + w + 1.0,
				                              bx, y0, PLOT_ALIGN_RIGHT, 1 };
			}
		}
		break;
	case IT_CROSS:
	case IT_PLABEL:
		if (!isfinite(X) || !isfinite(Y))
			return 0;
		/* Crosshair labels below the point first, point labels above it,
		 * so that a chosen part near the optimum does not write over it. */
		for (int v = 0; v < 4; v++) {
			/* Then the same places one line further out. */
			int below = (v % 2 == 0) == (it->kind == IT_CROSS);
			double off = v < 2 ? 4.0 : 4.0 + 1.3 * FS_NOTE;
			double by = below ? Y + off + FS_NOTE : Y - off;
			for (int h = 0; h < 2; h++) {
				double x0 = h == 0 ? X + 5.0 : X - 5.0 - w;
				s[n++] = (struct label_spot){ x0 - 1.0, by - asc, x0 + w + 1.0, by + desc,
				                              x0, by, PLOT_ALIGN_LEFT, 0 };
			}
		}
		break;
	default:
		break;
	}
	return n;
}

/* Labels of annotations (outside the clip so they are never cut): each in
 * the candidate place that covers least, on a white ground that keeps it
 * legible over grid lines. */
static void
draw_annotation_text(struct rctx *c, const struct plot_panel *pp, struct layout *L,
                     const struct item *it, struct label_log *log)
{
	HPDF_Font f = c->r->font;
	if (it->label == NULL)
		return;
	if (it->kind == IT_TEXT) {
		double X = plot_scale_map(&L->sx, it->px), Y = plot_scale_map(&L->sy, it->py);
		if (isfinite(X) && isfinite(Y))
			draw_text(c, f, FS_NOTE, X, Y, it->label, it->align, 0, it->colour);
		return;
	}
	double w = text_width(f, FS_NOTE, it->label);
	struct label_spot spot[12];
	int n = label_spots(L, it, w, spot), best = -1, best_hits = 0;
	double best_cost = INFINITY;
	struct mapped_points *mp = xcalloc((size_t)(pp->n_items > 0 ? pp->n_items : 1), sizeof *mp);
	if (n > 0)
		map_series(pp, L, mp);
	for (int i = 0; i < n; i++) {
		int hits;
		double cost = label_cost(pp, L, it, mp, spot[i].x0, spot[i].y0, spot[i].x1, spot[i].y1,
		                         &hits) + 0.5 * i;
		if (cost < best_cost) {
			best_cost = cost;
			best = i;
			best_hits = hits;
		}
	}
	for (int k = 0; k < pp->n_items; k++)
		free(mp[k].X);
	free(mp);
	if (best < 0)
		return;
	const struct label_spot *b = &spot[best];
	label_ground(c, b->x0, b->y0, b->x1, b->y1);
	draw_text(c, f, FS_NOTE, b->tx, b->ty, it->label, b->align, b->rot90, it->colour);
	struct plot_label_box box = { b->x0, b->y0, b->x1, b->y1, L->panel, best_hits, 0 };
	for (int i = 0; i < L->n_placed; i++)
		if (boxes_meet(&L->placed[i], b->x0, b->y0, b->x1, b->y1))
			box.overlaps++;
	if (L->n_placed < MAX_LABELS)
		L->placed[L->n_placed++] = box;
	if (log != NULL) {
		if (log->n == log->cap) {
			log->cap = log->cap ? 2 * log->cap : 16;
			log->v = xrealloc(log->v, (size_t)log->cap * sizeof *log->v);
		}
		log->v[log->n++] = box;
	}
}

static void
draw_legend_swatch(struct rctx *c, const struct legend_entry *e, double x, double yc)
{
	if (e->swatch) {
		HPDF_ExtGState gs = e->alpha < 1.0 ? alpha_state(c, e->alpha) : NULL;
		HPDF_Page_GSave(c->r->page);
		if (gs != NULL)
			HPDF_Page_SetExtGState(c->r->page, gs);
		rect_path(c, x + 1, yc - 3.5, x + LE_SWATCH - 1, yc + 3.5);
		set_source(c, e->colour);
		rp_apply(c, RP_FILL);
		HPDF_Page_GRestore(c->r->page);
		return;
	}
	if (e->width_pt > 0) {
		cairo_move_to(c->cr, x, yc);
		cairo_line_to(c->cr, x + LE_SWATCH, yc);
		set_pen(c, e->colour, e->width_pt, e->dash);
		rp_apply(c, RP_STROKE);
	}
	if (e->marker != PLOT_MARKER_NONE)
		draw_marker(c, e->marker, x + LE_SWATCH / 2, yc, MARKER_PT, e->colour, e->open_marker);
}

static void
draw_legend(struct rctx *c, const struct layout *L)
{
	if (L->le_where == PLOT_LEGEND_NONE || L->n_le == 0)
		return;
	if (L->le_where == PLOT_LEGEND_BELOW) {
		double x = L->l, y = L->b + TICK_LEN + FS_TICK + 4.0 +
		           (L->has_xtitle ? FS_AXIS + 5.0 : 0.0) + FS_LEGEND + 3.0;
		double right = L->cx + L->cw;
		for (int i = 0; i < L->n_le; i++) {
			double ew = legend_entry_w(c, &L->le[i]) + 10.0;
			if (x > L->l && x + ew > right) {
				x = L->l;
				y += LE_ROW;
			}
			draw_legend_swatch(c, &L->le[i], x, y - 2.5);
			draw_text(c, c->r->font, FS_LEGEND, x + LE_SWATCH + 3.0, y, L->le[i].label,
			          PLOT_ALIGN_LEFT, 0, PLOT_COLOUR_TEXT);
			x += ew;
		}
		return;
	}
	/* Boxed legend inside the plot (white background) or at its right. */
	if (L->le_where == PLOT_LEGEND_AUTO) {
		rect_path(c, L->le_x, L->le_y, L->le_x + L->le_w, L->le_y + L->le_h);
		cairo_set_source_rgb(c->cr, 1, 1, 1);
		rp_apply(c, RP_FILL);
		rect_path(c, L->le_x, L->le_y, L->le_x + L->le_w, L->le_y + L->le_h);
		set_pen(c, PLOT_COLOUR_GRID, 0.5, PLOT_DASH_SOLID);
		rp_apply(c, RP_STROKE);
	}
	for (int i = 0; i < L->n_le; i++) {
		double yb = L->le_y + LE_PAD + (i + 1) * LE_ROW - 2.5;
		draw_legend_swatch(c, &L->le[i], L->le_x + LE_PAD, yb - 2.5);
		draw_text(c, c->r->font, FS_LEGEND, L->le_x + LE_PAD + LE_SWATCH + 3.0, yb,
		          L->le[i].label, PLOT_ALIGN_LEFT, 0, PLOT_COLOUR_TEXT);
	}
}

static void
draw_axes(struct rctx *c, const struct plot_panel *pp, const struct layout *L)
{
	char buf[64];
	/* Grid: light lines at the ticks; minor log ticks thinner still. */
	for (int pass = 0; pass < 2; pass++) {
		for (int i = 0; i < L->tx.n; i++) {
			if (L->tx.labelled[i] != (pass == 1))
				continue;
			double X = plot_scale_map(&L->sx, L->tx.v[i]);
			cairo_move_to(c->cr, X, L->t);
			cairo_line_to(c->cr, X, L->b);
		}
		if (pp->kind == PK_XY || pp->kind == PK_BARS) {
			for (int i = 0; i < L->ty.n; i++) {
				if (L->ty.labelled[i] != (pass == 1))
					continue;
				double Y = plot_scale_map(&L->sy, L->ty.v[i]);
				cairo_move_to(c->cr, L->l, Y);
				cairo_line_to(c->cr, L->r, Y);
			}
		}
		set_pen(c, PLOT_COLOUR_GRID, pass == 1 ? LW_GRID : LW_MINOR, PLOT_DASH_SOLID);
		rp_apply(c, RP_STROKE);
	}
	/* Frame and outward ticks. */
	rect_path(c, L->l, L->t, L->r, L->b);
	for (int i = 0; i < L->tx.n; i++) {
		double X = plot_scale_map(&L->sx, L->tx.v[i]);
		cairo_move_to(c->cr, X, L->b);
		cairo_line_to(c->cr, X, L->b + (L->tx.labelled[i] ? TICK_LEN : TICK_LEN * 0.6));
	}
	if (pp->kind != PK_TORNADO) {
		for (int i = 0; i < L->ty.n; i++) {
			double Y = plot_scale_map(&L->sy, L->ty.v[i]);
			cairo_move_to(c->cr, L->l, Y);
			cairo_line_to(c->cr, L->l - (L->ty.labelled[i] ? TICK_LEN : TICK_LEN * 0.6), Y);
		}
	}
	set_pen(c, PLOT_COLOUR_MUTED, LW_FRAME, PLOT_DASH_SOLID);
	rp_apply(c, RP_STROKE);

	for (int i = 0; i < L->tx.n; i++) {
		if (!L->tx.labelled[i])
			continue;
		plot_tick_label(&L->tx, i, buf, sizeof buf);
		draw_text(c, c->r->font, FS_TICK, plot_scale_map(&L->sx, L->tx.v[i]),
		          L->b + TICK_LEN + FS_TICK + 1.0, buf, PLOT_ALIGN_CENTER, 0, PLOT_COLOUR_TEXT);
	}
	for (int i = 0; pp->kind != PK_TORNADO && i < L->ty.n; i++) {
		if (!L->ty.labelled[i])
			continue;
		plot_tick_label(&L->ty, i, buf, sizeof buf);
		draw_text(c, c->r->font, FS_TICK, L->l - TICK_LEN - 2.0,
		          plot_scale_map(&L->sy, L->ty.v[i]) + FS_TICK * 0.35, buf, PLOT_ALIGN_RIGHT,
		          0, PLOT_COLOUR_TEXT);
	}
	if (pp->axis_title[0] != NULL)
		draw_text(c, c->r->font, FS_AXIS, 0.5 * (L->l + L->r),
		          L->b + TICK_LEN + FS_TICK + 4.0 + FS_AXIS + 1.5, pp->axis_title[0],
		          PLOT_ALIGN_CENTER, 0, PLOT_COLOUR_TEXT);
	if (pp->axis_title[1] != NULL)
		draw_text(c, c->r->font, FS_AXIS, L->cx + FS_AXIS * 0.8, 0.5 * (L->t + L->b),
		          pp->axis_title[1], PLOT_ALIGN_CENTER, 1, PLOT_COLOUR_TEXT);
	if (pp->title != NULL)
		draw_text(c, c->r->bold, FS_TITLE, L->cx, L->cy + FS_TITLE, pp->title,
		          PLOT_ALIGN_LEFT, 0, PLOT_COLOUR_TEXT);
}

static void
draw_panel(struct rctx *c, const struct plot_panel *pp, struct layout *L, struct label_log *log)
{
	layout_panel(c, pp, L);
	draw_axes(c, pp, L);

	HPDF_Page_GSave(c->r->page);
	rect_path(c, L->l, L->t, L->r, L->b);
	rp_apply(c, RP_CLIP);
	/* Painter's order: areas, then lines and markers, then reference lines. */
	static const enum item_kind order[] = { IT_BAND, IT_BARS, IT_TORNADO, IT_SERIES,
	                                        IT_HLINE, IT_VLINE, IT_CROSS };
	for (size_t o = 0; o < sizeof order / sizeof order[0]; o++) {
		for (int k = 0; k < pp->n_items; k++) {
			const struct item *it = &pp->items[k];
			if (it->kind != order[o])
				continue;
			switch (it->kind) {
			case IT_BAND: draw_band(c, L, it); break;
			case IT_SERIES: draw_series(c, L, it); break;
			case IT_HLINE: case IT_VLINE: case IT_CROSS: draw_refs(c, L, it); break;
			default: break;
			}
		}
	}
	HPDF_Page_GRestore(c->r->page);
	/* Bars and tornado rows carry their category labels outside the plot
	 * area, so they are drawn unclipped (their bars lie inside anyway). */
	for (int k = 0; k < pp->n_items; k++) {
		const struct item *it = &pp->items[k];
		if (it->kind == IT_BARS)
			draw_bars(c, L, it);
		else if (it->kind == IT_TORNADO)
			draw_tornado(c, L, it);
	}
	/* Reference-line labels first (their places are fewest), then the
	 * labels of points. */
	static const enum item_kind label_order[] = { IT_HLINE, IT_VLINE, IT_CROSS, IT_PLABEL, IT_TEXT };
	for (size_t o = 0; o < sizeof label_order / sizeof label_order[0]; o++)
		for (int k = 0; k < pp->n_items; k++)
			if (pp->items[k].kind == label_order[o])
				draw_annotation_text(c, pp, L, &pp->items[k], log);
	draw_legend(c, L);
}

int
plot_render(const struct plot *p, const struct plot_render *r)
{
	struct rctx c = { .r = r };
	c.surf = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, NULL);
	c.cr = cairo_create(c.surf);
	if (cairo_status(c.cr) != CAIRO_STATUS_SUCCESS)
		c.failed = 1;
	double w = r->width_pt, h = p->height_pt;
	double cw = (w - (p->n_cols - 1) * PANEL_GAP) / p->n_cols;
	double ch = (h - (p->n_rows - 1) * PANEL_GAP) / p->n_rows;
	struct layout *L = xmalloc(sizeof *L);
	if (p->log != NULL)
		p->log->n = 0;
	for (int i = 0; !c.failed && i < p->n_rows; i++) {
		for (int j = 0; j < p->n_cols; j++) {
			memset(L, 0, sizeof *L);
			L->cx = j * (cw + PANEL_GAP);
			L->cy = i * (ch + PANEL_GAP);
			L->cw = cw;
			L->ch = ch;
			L->panel = i * p->n_cols + j;
			draw_panel(&c, &p->panels[i * p->n_cols + j], L, p->log);
		}
	}
	free(L);
	if (cairo_status(c.cr) == CAIRO_STATUS_NO_MEMORY)
		xalloc_die(0);  /* the one out-of-memory error, not a failed figure */
	if (cairo_status(c.cr) != CAIRO_STATUS_SUCCESS)
		c.failed = 1;
	cairo_destroy(c.cr);
	cairo_surface_destroy(c.surf);
	return c.failed ? -1 : 0;
}

void
plot_global_cleanup(void)
{
	cairo_debug_reset_static_data();
}
