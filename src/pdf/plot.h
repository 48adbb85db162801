/* plot.h — engineering figures described in data units, drawn as vectors.
 *
 * A figure (struct plot) is a grid of panels (1x1 for most figures, 2x2 for
 * small multiples).  Each panel holds items added in data units: line and
 * scatter series, shaded bands, reference lines, crosshairs, text, stacked
 * bars, tornado bars.  Nothing is drawn until the document places the figure
 * (doc_figure in doc.h calls plot_render): every path is then built with
 * cairo on an unbounded recording surface and replayed element by element
 * into the libharu page, so the figure stays vector; all text is drawn by
 * libharu with the document's TTF font, so it is selectable and searchable.
 *
 * Rules the drawing follows:
 *   - non-finite points (and points <= 0 on a log axis) are skipped: a line
 *     is broken there, a marker is not drawn;
 *   - an empty panel or a degenerate range gives a sensible axis, never a
 *     crash (0..1 for no data, +-10 % around a single value);
 *   - colours come from the template: PLOT_COLOUR_AUTO takes the panel's next
 *     palette colour, 0..7 name a palette entry, PLOT_COLOUR_TEXT.. the
 *     template's semantic colours;
 *   - the legend goes in the corner of the plot area that covers no data,
 *     or below the plot if every corner would cover some.
 *
 * Ownership: a plot copies every array and string it is given; the caller's
 * buffers may be freed right after the call.
 *
 * Who may include it: the PDF layer (doc, report) and the study reports.
 * Includes hpdf.h.
 *
 * Example (a power-vs-speed figure with the minimum-power speed marked):
 *     struct plot *p = plot_alloc(0, 220, 1, 1);    // full text width
 *     struct plot_panel *pp = plot_panel(p, 0, 0);
 *     plot_axis_title(pp, PLOT_X, "Forward speed (m/s)");
 *     plot_axis_title(pp, PLOT_Y, "Electrical power (W)");
 *     plot_line(pp, v_ms, p_w, n, "Custom", PLOT_COLOUR_AUTO, PLOT_DASH_SOLID);
 *     plot_vline(pp, v_min_ms, "minimum-power speed", PLOT_COLOUR_ACCENT, PLOT_DASH_DASHED);
 *     doc_figure(doc, p, "Power required vs forward speed.");
 *     plot_free(p);
 */
#ifndef AEROEVAL_PLOT_H
#define AEROEVAL_PLOT_H

#include <stddef.h>

#include <hpdf.h>

#include "template/template.h"

struct plot;
struct plot_panel;

/* Colours: a palette index 0..TEMPLATE_MAX_SERIES-1, or one of these. */
enum plot_colour {
	PLOT_COLOUR_AUTO = -1,     /* next palette colour of the panel */
	PLOT_COLOUR_TEXT = 100,
	PLOT_COLOUR_PRIMARY,
	PLOT_COLOUR_ACCENT,
	PLOT_COLOUR_MUTED,
	PLOT_COLOUR_GRID,
	PLOT_COLOUR_PASS,
	PLOT_COLOUR_FAIL,
	PLOT_COLOUR_WARN
};

enum plot_marker {
	PLOT_MARKER_NONE,
	PLOT_MARKER_CIRCLE,
	PLOT_MARKER_SQUARE,
	PLOT_MARKER_TRIANGLE,
	PLOT_MARKER_DIAMOND,
	PLOT_MARKER_CROSS
};

enum plot_dash {
	PLOT_DASH_SOLID,
	PLOT_DASH_DASHED,
	PLOT_DASH_DOTTED,
	PLOT_DASH_DASHDOT
};

enum plot_axis_id {
	PLOT_X,
	PLOT_Y
};

enum plot_legend {
	PLOT_LEGEND_AUTO,    /* a free corner inside, else below */
	PLOT_LEGEND_BELOW,   /* under the x axis title, entries in rows */
	PLOT_LEGEND_RIGHT,   /* right of the plot area, one entry per line */
	PLOT_LEGEND_NONE
};

enum plot_align {
	PLOT_ALIGN_LEFT,
	PLOT_ALIGN_CENTER,
	PLOT_ALIGN_RIGHT
};

/* How a general series looks (plot_series).  Zero-initialised means:
 * palette colour 0, solid 1.2 pt line, no marker; set auto_colour to take
 * the panel's next palette colour instead.  A NULL style means auto colour. */
struct plot_style {
	int colour;               /* enum plot_colour or palette index; 0 is palette 0 */
	int auto_colour;          /* nonzero: ignore colour, take the next palette colour */
	enum plot_dash dash;
	double line_width_pt;     /* 0: 1.2 pt; < 0: no line (markers only) */
	enum plot_marker marker;
	double marker_size_pt;    /* 0: 4.5 pt */
	int open_marker;          /* nonzero: outline only */
};

/* ---- building a figure ------------------------------------------------- */

/* A figure of n_rows x n_cols panels.  width_pt 0 means the full text width
 * of the page it is placed on.  Ownership: free with plot_free(). */
struct plot *plot_alloc(double width_pt, double height_pt, int n_rows, int n_cols);
void plot_free(struct plot *p);   /* NULL is a no-op */

double plot_width_pt(const struct plot *p);   /* 0 = text width */
double plot_height_pt(const struct plot *p);

/* The panel at (row, col), counted from the top left. */
struct plot_panel *plot_panel(struct plot *p, int row, int col);

void plot_title(struct plot_panel *pp, const char *title);
/* Axis title with its unit, e.g. "Battery temperature (°C)". */
void plot_axis_title(struct plot_panel *pp, enum plot_axis_id ax, const char *title);
void plot_axis_log(struct plot_panel *pp, enum plot_axis_id ax, int log10);
/* A fixed range instead of the automatic nice range. */
void plot_axis_range(struct plot_panel *pp, enum plot_axis_id ax, double lo, double hi);
void plot_legend(struct plot_panel *pp, enum plot_legend where);

/* A line series; label NULL keeps it out of the legend. */
void plot_line(struct plot_panel *pp, const double *x, const double *y, size_t n,
               const char *label, int colour, enum plot_dash dash);
/* Markers only. */
void plot_scatter(struct plot_panel *pp, const double *x, const double *y, size_t n,
                  const char *label, enum plot_marker marker, int colour);
/* Any combination of line and markers. */
void plot_series(struct plot_panel *pp, const double *x, const double *y, size_t n,
                 const char *label, const struct plot_style *st);
/* A small label next to the data point (x, y). */
void plot_point_label(struct plot_panel *pp, double x, double y, const char *text);
/* Free text at (x, y), baseline there, in the muted colour. */
void plot_text(struct plot_panel *pp, double x, double y, const char *text,
               enum plot_align align);
/* Horizontal / vertical reference line across the plot, with a label drawn
 * along it (e.g. "60 °C runaway limit"); label may be NULL. */
void plot_hline(struct plot_panel *pp, double y, const char *label, int colour,
                enum plot_dash dash);
void plot_vline(struct plot_panel *pp, double x, const char *label, int colour,
                enum plot_dash dash);
/* Dashed crosshair through (x, y) with a ring marker and a label. */
void plot_crosshair(struct plot_panel *pp, double x, double y, const char *label,
                    int colour);
/* Shaded band between y_lo(x) and y_hi(x), fill opacity alpha in (0, 1]. */
void plot_band(struct plot_panel *pp, const double *x, const double *y_lo,
               const double *y_hi, size_t n, const char *label, int colour,
               double alpha);
/* Vertical stacked bars: n_bars bars (x categories bar_labels), each made of
 * n_stack segments (legend stack_labels); values[i_bar * n_stack + i_stack]
 * >= 0 (others count as 0).  Segments taller than the label get their value
 * printed with `decimals` decimals (when a bar has more than one), and each
 * bar its total above it;
 * decimals < 0 prints no numbers.  Makes the panel a bar chart. */
void plot_stacked_bars(struct plot_panel *pp, int n_bars, const char *const *bar_labels,
                       int n_stack, const char *const *stack_labels,
                       const double *values, int decimals);
/* Horizontal bars around `centre` (tornado chart), one row per label, top
 * to bottom: lo[i] and hi[i] are the outputs at the low and high setting of
 * parameter i, drawn in palette colours 0 and 1 (legend lo_label, hi_label).
 * Makes the panel a tornado chart. */
void plot_tornado(struct plot_panel *pp, int n, const char *const *labels,
                  const double *lo, const double *hi, double centre,
                  const char *lo_label, const char *hi_label);

/* ---- axes, exposed for tests and for callers that need the numbers ------ */

#define PLOT_MAX_TICKS 64

/* Tick positions of one axis and the (expanded) range they span. */
struct plot_ticks {
	double lo, hi;              /* axis range, nice values covering the data */
	int log10;                  /* nonzero: logarithmic axis */
	int n;                      /* ticks in v[] */
	double v[PLOT_MAX_TICKS];   /* tick values, ascending */
	int labelled[PLOT_MAX_TICKS]; /* nonzero: major tick with a label */
	int decimals;               /* digits after the point for linear labels */
};

/* Nice linear ticks covering [dmin, dmax] with about `target` ticks (steps of
 * 1, 2, 2.5 or 5 x 10^k).  Non-finite or reversed input is repaired. */
void plot_ticks_linear(double dmin, double dmax, int target, struct plot_ticks *out);
/* Log10 ticks covering [dmin, dmax] (both > 0, else 1..10): 1-2-5 labels for
 * up to 3 decades, else labelled decades with minor ticks at 2..9. */
void plot_ticks_log(double dmin, double dmax, struct plot_ticks *out);
/* The label of tick i ("0.0015", "250", "0.2", "1e+06"). */
void plot_tick_label(const struct plot_ticks *t, int i, char *buf, size_t cap);

/* Linear or log mapping from data [lo, hi] to page [p0, p1]. */
struct plot_scale {
	double lo, hi;   /* data range */
	int log10;       /* nonzero: map log10(v) */
	double p0, p1;   /* page coordinates of lo and hi (p1 < p0 allowed) */
};
/* The page coordinate of v; NAN if v is non-finite or <= 0 on a log scale. */
double plot_scale_map(const struct plot_scale *s, double v);

/* ---- where the labels went (for tests) ---------------------------------- */

/* The box an annotation label (reference line, crosshair, point label)
 * was drawn in, figure coordinates (points, y down), and what it covers:
 * data_hits counts the data segments and markers under it, overlaps the
 * labels drawn before it in its panel that it meets.  The renderer places
 * each label where it covers least; these let a test check it. */
struct plot_label_box {
	double x0, y0, x1, y1;
	int panel;                /* row-major index */
	int data_hits;
	int overlaps;
};

/* Asks the next plot_render to record its label boxes. */
void plot_keep_label_boxes(struct plot *p);
/* The boxes of the last render (valid until the next render or
 * plot_free); returns how many. */
int plot_label_boxes(const struct plot *p, const struct plot_label_box **out);

/* ---- drawing (called by doc_figure) ------------------------------------ */

struct strbuf;

struct plot_render {
	HPDF_Doc pdf;
	HPDF_Page page;
	HPDF_Font font;                /* regular, UTF-8 */
	HPDF_Font bold;                /* bold, UTF-8 */
	const struct template *tpl;
	double x_pt, y_top_pt;         /* figure's top-left corner on the page */
	double width_pt;               /* resolved width (plot width or text width) */
	struct strbuf *transcript;     /* NULL, or: every text drawn, "| text\n" */
};

/* Draws the figure; returns 0, or -1 if libharu or cairo failed. */
int plot_render(const struct plot *p, const struct plot_render *r);

/* Begins a text object on pg in font f at size, filled with k.  The font
 * and the fill colour are set only where they differ from the page's
 * current ones (libharu tracks both in the graphics state, which lasts
 * from one text object to the next): most of a dossier's text repeats the
 * font and colour of the text before it, and every operator costs libharu
 * a few thousand instructions and the PDF bytes to deflate. */
void plot_begin_text(HPDF_Page pg, HPDF_Font f, double size, struct template_colour k);

/* Releases cairo's static caches; call once at program exit (valgrind). */
void plot_global_cleanup(void);

#endif
