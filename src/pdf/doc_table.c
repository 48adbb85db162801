/* doc_table.c — the document's tables (doc.h): columns sized to what
 * they hold, rows kept whole, the header repeated on every page, web
 * addresses in cells made clickable.
 */
#include "pdf/doc.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hpdf.h>

#include "pdf/doc_int.h"
#include "util/xalloc.h"

/* ---- web addresses -------------------------------------------------------- */

#define URI_MAX 1024

/* The web address that the byte p of text (its start at text) belongs to:
 * its start and length, or 0 when p is not inside one.  An address is a
 * run of non-blank characters starting with "http://", "https://" or
 * "www.". */
static size_t
url_around(const char *text, const char *p, const char **start)
{
	const char *a = p;
	while (a > text && a[-1] != ' ' && a[-1] != '\n')
		a--;
	if (strncmp(a, "http://", 7) != 0 && strncmp(a, "https://", 8) != 0 &&
	    strncmp(a, "www.", 4) != 0)
		return 0;
	*start = a;
	return strcspn(a, " \n");
}

/* Does line [s, s + len) of text lie inside a web address? */
static int
line_is_url(const char *text, const char *s, size_t len)
{
	const char *a;
	size_t n = url_around(text, s, &a);
	return n > 0 && s + len <= a + n;
}

/* Makes the parts of a drawn line that belong to web addresses clickable:
 * a URI link annotation (no border) over each, targeting the whole
 * address even when it wraps over several lines. */
static void
link_line(struct doc *d, HPDF_Font f, double size, double x, double y, const char *text,
          const char *s, size_t len)
{
	const char *p = s, *e = s + len;
	/* Most cells hold no address: look for its marks once per cell
	 * before trying every byte of the line. */
	if (strstr(text, "http://") == NULL && strstr(text, "https://") == NULL &&
	    strstr(text, "www.") == NULL)
		return;
	while (p < e) {
		const char *a;
		size_t n = url_around(text, p, &a);
		if (n == 0) {
			p++;
			continue;
		}
		const char *b = a + n < e ? a + n : e;
		char uri[URI_MAX];
		int ascii = n + 9 < sizeof uri;
		for (size_t i = 0; ascii && i < n; i++)
			ascii = (unsigned char)a[i] > 0x20 && (unsigned char)a[i] < 0x7f;
		if (ascii) {
			snprintf(uri, sizeof uri, "%s%.*s", a[0] == 'w' ? "https://" : "", (int)n, a);
			double xa = x + doc_width(f, size, s, (size_t)(p - s));
			double xb = xa + doc_width(f, size, p, (size_t)(b - p));
			HPDF_Rect rect = { (HPDF_REAL)xa, (HPDF_REAL)(y - 0.25 * size),
			                   (HPDF_REAL)xb, (HPDF_REAL)(y + 0.85 * size) };
			HPDF_Annotation an = HPDF_Page_CreateURILinkAnnot(d->page, rect, uri);
			if (an != NULL)
				HPDF_LinkAnnot_SetBorderStyle(an, 0, 0, 0);
		}
		p = b;
	}
}

/* ---- tables ------------------------------------------------------------------ */

void
doc_table_init(struct doc_table *t, const struct doc_column *cols, int n_cols)
{
	memset(t, 0, sizeof *t);
	t->cols = cols;
	t->n_cols = n_cols;
}

static void
table_push(struct doc_table *t, enum doc_cell style, char *s)
{
	if (t->n_cells == t->cap_cells) {
		t->cap_cells = t->cap_cells ? 2 * t->cap_cells : 32;
		t->cells = xrealloc(t->cells, (size_t)t->cap_cells * sizeof *t->cells);
		t->styles = xrealloc(t->styles, (size_t)t->cap_cells);
	}
	t->cells[t->n_cells] = s;
	t->styles[t->n_cells] = (unsigned char)style;
	t->n_cells++;
}

void
doc_table_cell(struct doc_table *t, enum doc_cell style, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	int n = vsnprintf(NULL, 0, fmt, ap);
	va_end(ap);
	char *s = xmalloc(n > 0 ? (size_t)n + 1 : 1);
	s[0] = '\0';
	if (n > 0) {
		va_start(ap, fmt);
		vsnprintf(s, (size_t)n + 1, fmt, ap);
		va_end(ap);
	}
	table_push(t, style, s);
}

void
doc_table_row(struct doc_table *t, const char *const *cells)
{
	for (int i = 0; i < t->n_cols; i++)
		table_push(t, DOC_CELL_NORMAL, xstrdup(cells != NULL && cells[i] != NULL ? cells[i] : ""));
}

void
doc_table_clear(struct doc_table *t)
{
	for (int i = 0; i < t->n_cells; i++)
		free(t->cells[i]);
	free(t->cells);
	free(t->styles);
	memset(t, 0, sizeof *t);
}

/* Column edges and cell fonts of a table being drawn. */
struct tstate {
	const struct doc_table *t;
	double x[65];        /* column edges, n_cols + 1 */
	double size;         /* text size */
	double lh;           /* line height */
};

static HPDF_Font
cell_font(struct doc *d, enum doc_cell s)
{
	if (s == DOC_CELL_MONO)
		return doc_mono_font(d);
	if (s == DOC_CELL_BOLD || s == DOC_CELL_PASS || s == DOC_CELL_FAIL || s == DOC_CELL_WARN)
		return d->bold;
	return d->font;
}

static struct template_colour
cell_colour(const struct doc *d, enum doc_cell s)
{
	switch (s) {
	case DOC_CELL_MUTED: return d->tpl.muted;
	case DOC_CELL_PASS: return d->tpl.pass;
	case DOC_CELL_FAIL: return d->tpl.fail;
	case DOC_CELL_WARN: return d->tpl.warn;
	default: return d->tpl.text;
	}
}

/* Wraps every cell of a row; returns the row height. */
static double
row_layout(struct doc *d, const struct tstate *ts, const char *const *cells,
           const enum doc_cell *styles, struct lines *L)
{
	int nl = 1;
	for (int c = 0; c < ts->t->n_cols; c++) {
		L[c].n = 0;
		HPDF_Font f = cell_font(d, styles[c]);
		double size = styles[c] == DOC_CELL_MONO ? 0.92 * ts->size : ts->size;
		doc_wrap(f, size, ts->x[c + 1] - ts->x[c] - 2 * CELL_PAD_X, cells[c], &L[c]);
		if (L[c].n > nl)
			nl = L[c].n;
	}
	return nl * ts->lh + 2 * CELL_PAD_Y;
}

/* Draws a laid-out row; web addresses in the cells (not the header) are
 * drawn in the primary colour and made clickable. */
static void
row_draw(struct doc *d, const struct tstate *ts, const char *const *cells,
         const enum doc_cell *styles, const struct lines *L, double h,
         const struct template_colour *bg, int header)
{
	if (bg != NULL)
		doc_fill_rect(d, ts->x[0], d->y - h, ts->x[ts->t->n_cols] - ts->x[0], h, *bg);
	for (int c = 0; c < ts->t->n_cols; c++) {
		HPDF_Font f = header ? d->bold : cell_font(d, styles[c]);
		double size = !header && styles[c] == DOC_CELL_MONO ? 0.92 * ts->size : ts->size;
		struct template_colour k = header ? (struct template_colour){ 1, 1, 1 }
		                                  : cell_colour(d, styles[c]);
		for (int i = 0; i < L[c].n; i++) {
			const char *s = L[c].v[i].s;
			size_t len = L[c].v[i].len;
			int url = !header && line_is_url(cells[c], s, len);
			double y = d->y - CELL_PAD_Y - i * ts->lh - 0.8 * ts->size - 0.5;
			double x = doc_put_aligned(d, f, size, ts->x[c] + CELL_PAD_X, ts->x[c + 1] - CELL_PAD_X,
			                       y, s, len, ts->t->cols[c].align, url ? d->tpl.primary : k);
			if (!header)
				link_line(d, f, size, x, y, cells[c], s, len);
		}
	}
	doc_advance(d, h);
}

/* Lays out the header row (column titles, bold); returns its height. */
static double
header_layout(struct doc *d, const struct tstate *ts, struct lines *L, enum doc_cell *st)
{
	const char *titles[64];
	for (int c = 0; c < ts->t->n_cols; c++) {
		titles[c] = ts->t->cols[c].title != NULL ? ts->t->cols[c].title : "";
		st[c] = DOC_CELL_BOLD;
	}
	return row_layout(d, ts, titles, st, L);
}

static void
header_draw(struct doc *d, const struct tstate *ts, struct lines *L)
{
	enum doc_cell st[64];
	const char *titles[64];
	double h = header_layout(d, ts, L, st);
	for (int c = 0; c < ts->t->n_cols; c++)
		titles[c] = ts->t->cols[c].title != NULL ? ts->t->cols[c].title : "";
	row_draw(d, ts, titles, st, L, h, &d->tpl.primary, 1);
}

/* The widest piece of text that cannot be broken, in points: words are
 * separated by spaces and line breaks (a no-break space joins), and a word
 * may also break after a '/' or '-' (word_cut), so a web address or a part
 * id counts by its longest piece. */
static double
widest_word(HPDF_Font f, double size, const char *text)
{
	double best = 0.0;
	const char *p = text;
	while (*p != '\0') {
		size_t n = strcspn(p, " \n");
		const char *a = p, *e = p + n;
		for (const char *c = p; c < e; c++) {
			if (doc_breaks_after(p, c, e) || c + 1 == e) {
				best = fmax(best, doc_width(f, size, a, (size_t)(c + 1 - a)));
				a = c + 1;
			}
		}
		p = e;
		if (*p != '\0')
			p++;
	}
	return best;
}

/* Column edges: the caller's weights share the text width, then every
 * column is widened to its widest word (a number with its unit, a part
 * number) where the others have room to give, so that a number is never
 * cut across two lines.  A word wider than MAX_WORD_SHARE of the table (a
 * web address) still wraps, at '/' or '-' (word_cut). */
#define MAX_WORD_SHARE 0.45
static void
column_edges(struct doc *d, struct tstate *ts)
{
	const struct doc_table *t = ts->t;
	double total = d->right - d->left, wsum = 0.0;
	double w[64], need[64];
	for (int c = 0; c < t->n_cols; c++)
		wsum += t->cols[c].weight > 0 ? t->cols[c].weight : 1.0;
	for (int c = 0; c < t->n_cols; c++) {
		w[c] = total * (t->cols[c].weight > 0 ? t->cols[c].weight : 1.0) / wsum;
		need[c] = t->no_header ? 0.0
		        : widest_word(d->bold, ts->size, t->cols[c].title != NULL ? t->cols[c].title : "");
	}
	for (int i = 0; i < t->n_cells; i++) {
		int c = i % t->n_cols;
		enum doc_cell st = (enum doc_cell)t->styles[i];
		if (t->total_row && i >= t->n_cells - t->n_cols && st == DOC_CELL_NORMAL)
			st = DOC_CELL_BOLD;   /* as doc_table draws it */
		double size = st == DOC_CELL_MONO ? 0.92 * ts->size : ts->size;
		need[c] = fmax(need[c], widest_word(cell_font(d, st), size, t->cells[i]));
	}
	double short_by = 0.0, spare = 0.0;
	for (int c = 0; c < t->n_cols; c++) {
		need[c] = fmin(need[c] + 2 * CELL_PAD_X + 0.5, MAX_WORD_SHARE * total);
		if (need[c] > w[c])
			short_by += need[c] - w[c];
		else
			spare += w[c] - need[c];
	}
	if (short_by > 0.0 && spare > 0.0) {
		/* Give each short column what it needs, taking it from the
		 * others in proportion to their room; if the room is not
		 * enough, the short columns share what there is. */
		double give = fmin(1.0, spare / short_by), take = fmin(1.0, short_by / spare);
		for (int c = 0; c < t->n_cols; c++)
			w[c] += need[c] > w[c] ? give * (need[c] - w[c]) : -take * (w[c] - need[c]);
	}
	ts->x[0] = d->left;
	for (int c = 0; c < t->n_cols; c++)
		ts->x[c + 1] = ts->x[c] + w[c];
}

/* Row r's cells and their styles as drawn (a total row in bold). */
static void
row_cells(const struct doc_table *t, int r, int n_rows, const char **cells, enum doc_cell *st)
{
	int total = t->total_row && r == n_rows - 1;
	for (int c = 0; c < t->n_cols; c++) {
		cells[c] = t->cells[r * t->n_cols + c];
		st[c] = (enum doc_cell)t->styles[r * t->n_cols + c];
		if (total && st[c] == DOC_CELL_NORMAL)
			st[c] = DOC_CELL_BOLD;
	}
}

/* Tables up to this share of the text block are never split. */
#define SHORT_TABLE_SHARE 0.3

int
doc_table(struct doc *d, const struct doc_table *t)
{
	if (doc_failed(d))
		return -1;
	if (t->n_cols < 1 || t->n_cols > 64 || t->cols == NULL) {
		doc_fail(d, "table with %d columns", t->n_cols);
		return -1;
	}
	struct tstate ts = { .t = t, .size = TABLE_SCALE * d->tpl.font_size_pt };
	ts.lh = ts.size * 1.25;
	if (t->n_cells % t->n_cols != 0) {
		doc_fail(d, "table: %d cells do not fill rows of %d columns", t->n_cells, t->n_cols);
		return -1;
	}
	column_edges(d, &ts);
	struct lines *L = xcalloc((size_t)t->n_cols, sizeof *L);
	int n_rows = t->n_cells / t->n_cols;
	enum doc_cell hst[64];
	double hh = t->no_header ? 0.0 : header_layout(d, &ts, L, hst);
	struct template_colour zebra = doc_mix_white(d->tpl.grid, 0.35);
	const char **cells = xmalloc((size_t)t->n_cols * sizeof *cells);
	enum doc_cell *st = xmalloc((size_t)t->n_cols * sizeof *st);
	double *rh = xmalloc((size_t)(n_rows > 0 ? n_rows : 1) * sizeof *rh);
	double all = hh;
	for (int r = 0; r < n_rows; r++) {
		row_cells(t, r, n_rows, cells, st);
		rh[r] = row_layout(d, &ts, cells, st, L);
		all += rh[r];
	}
	/* A short table is kept whole on the next page rather than split,
	 * unless a heading on this page announces it (the heading has kept
	 * room for its first rows, and would be left alone). */
	if (!d->at_top && !d->after_heading && d->y - all < d->bottom &&
	    all <= SHORT_TABLE_SHARE * (d->top - d->bottom))
		doc_add_page(d);
	/* The transcript: the header row once, then every row, cells by tabs. */
	if (d->transcript != NULL) {
		struct strbuf row = STRBUF_INIT;
		for (int r = t->no_header ? 0 : -1; r < n_rows; r++) {
			strbuf_reset(&row);
			for (int c = 0; c < t->n_cols; c++) {
				if (c > 0)
					strbuf_append_str(&row, "\t");
				strbuf_append_str(&row, r < 0 ? t->cols[c].title
				    : t->cells[r * t->n_cols + c]);
			}
			doc_transcribe(d, NULL, strbuf_str(&row));
		}
		strbuf_free(&row);
	}
	int need_header = !t->no_header;
	for (int r = 0; r < n_rows && !doc_failed(d); r++) {
		int total = t->total_row && r == n_rows - 1;
		row_cells(t, r, n_rows, cells, st);
		double h = row_layout(d, &ts, cells, st, L);
		double head = need_header ? hh : 0.0;
		/* A total row never stands alone: the row before it goes along. */
		double keep = t->total_row && r == n_rows - 2 ? rh[r + 1] : 0.0;
		if (d->y - head - h - keep < d->bottom && !d->at_top) {
			doc_add_page(d);
			need_header = !t->no_header;   /* repeat the header on the new page */
		}
		if (need_header) {
			header_draw(d, &ts, L);
			need_header = 0;
			h = row_layout(d, &ts, cells, st, L);
		}
		if (total)
			doc_hrule(d, ts.x[0], ts.x[t->n_cols], d->y, 0.8, d->tpl.text);
		row_draw(d, &ts, cells, st, L, h, (!t->no_zebra && r % 2 == 1 && !total) ? &zebra : NULL, 0);
	}
	if (n_rows == 0 && need_header)
		header_draw(d, &ts, L);
	doc_hrule(d, ts.x[0], ts.x[t->n_cols], d->y, 0.6, d->tpl.grid);
	d->y -= 0.9 * d->tpl.font_size_pt;
	for (int c = 0; c < t->n_cols; c++)
		free(L[c].v);
	free(L);
	free(cells);
	free(st);
	free(rh);
	return doc_failed(d) ? -1 : 0;
}

int
doc_kv_table(struct doc *d, const char *const *kv, int n_pairs)
{
	static const struct doc_column cols[2] = { { "", 2.0, DOC_ALIGN_LEFT },
	                                           { "", 3.0, DOC_ALIGN_LEFT } };
	struct doc_table t;
	doc_table_init(&t, cols, 2);
	t.no_header = 1;
	for (int i = 0; i < n_pairs; i++) {
		table_push(&t, DOC_CELL_MUTED, xstrdup(kv[2 * i] != NULL ? kv[2 * i] : ""));
		table_push(&t, DOC_CELL_NORMAL, xstrdup(kv[2 * i + 1] != NULL ? kv[2 * i + 1] : ""));
	}
	int rc = doc_table(d, &t);
	doc_table_clear(&t);
	return rc;
}

