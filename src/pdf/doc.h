/* doc.h — the dossier document: flow layout over libharu.
 *
 * An opaque document with a cursor that flows down the page: headings (with
 * outline bookmarks), wrapped paragraphs, bullets, key/value and full tables
 * (header repeated after a page break), coloured callouts and numbered
 * figures (plot.h).  Text is UTF-8 in the template's embedded TrueType fonts
 * (° ± µ Ω ² ≤ print and stay selectable).  The running header (document
 * title, mission name) and the footer "n / N" are drawn on every page but
 * the first when the document is saved.  The output is byte-for-byte
 * reproducible: no clock is read, no encryption, no PDF/A (docs/libraries.md,
 * libharu).
 *
 * Errors are sticky, like a cairo context: the first libharu error (or bad
 * argument) is remembered, every later call does nothing and returns -1, and
 * doc_save_mem() fails, so a broken PDF is never produced.  Section writers
 * may therefore ignore the return codes and check once at the end.
 *
 * Who may include it: the PDF layer (report*.c, index_pdf.c), the study
 * reports (sens_report.c, valreport.c) and the commands (cli_*.c).
 *
 * Writing a section (a few dozen lines):
 *
 *     static void
 *     section_checks(struct doc *d, const struct template *tpl, const struct result *r)
 *     {
 *         static const struct doc_column cols[] = {
 *             { "Constraint", 3.0, DOC_ALIGN_LEFT },  { "Value", 1.2, DOC_ALIGN_RIGHT },
 *             { "Limit", 1.2, DOC_ALIGN_RIGHT },      { "Margin", 1.0, DOC_ALIGN_RIGHT },
 *             { "Result", 1.0, DOC_ALIGN_CENTER },
 *         };
 *         const struct template_section *s = template_section_get(tpl, TEMPLATE_SEC_CHECKS);
 *         if (s == NULL || !s->enabled)
 *             return;
 *         doc_heading(d, 1, s->title);
 *         doc_paragraph(d, "Every constraint of the design, with its margin.");
 *         struct doc_table t;
 *         doc_table_init(&t, cols, 5);
 *         for (int i = 0; i < r->n_checks; i++) {
 *             const struct check *c = &r->checks[i];
 *             doc_table_cell(&t, DOC_CELL_NORMAL, "%s", c->name);
 *             doc_table_cell(&t, DOC_CELL_NORMAL, "%.1f %s", c->value, c->unit);
 *             doc_table_cell(&t, DOC_CELL_NORMAL, "%.1f %s", c->limit, c->unit);
 *             doc_table_cell(&t, DOC_CELL_NORMAL, "%+.0f %%", 100 * c->margin);
 *             doc_table_cell(&t, c->pass ? DOC_CELL_PASS : DOC_CELL_FAIL,
 *                            "%s", c->pass ? "PASS" : "FAIL");
 *         }
 *         doc_table(d, &t);
 *         doc_table_clear(&t);
 *         if (!r->feasible)
 *             doc_callout(d, DOC_CALLOUT_FAIL, "INFEASIBLE", r->why);
 *     }
 *
 * and the whole document:
 *
 *     struct doc_info info = { .title = "Design dossier", .mission = "agri-sprayer",
 *                              .author = client, .date = "2026-11-22" };
 *     struct doc *d = doc_alloc(tpl, &info);
 *     section_cover(d, ...); section_checks(d, tpl, r); ...
 *     doc_attach(d, "agri-sprayer.json", mission_bytes, mission_len);
 *     unsigned char *pdf; size_t n;
 *     if (doc_save_mem(d, &pdf, &n) != 0) { fprintf(stderr, "%s\n", doc_error(d)); ... }
 *     ... write pdf atomically ...; free(pdf); doc_free(d);
 *     (at program exit: doc_global_cleanup();)
 */
#ifndef AEROEVAL_DOC_H
#define AEROEVAL_DOC_H

#include <stddef.h>

#include "pdf/plot.h"
#include "template/template.h"

struct doc;
struct strbuf;

/* Document metadata.  Every string is copied; NULL means absent. */
struct doc_info {
	const char *title;    /* PDF /Title and the running header (left) */
	const char *mission;  /* running header (right), e.g. the mission name */
	const char *author;   /* PDF /Author */
	const char *subject;  /* PDF /Subject */
	const char *date;     /* "YYYY-MM-DD" -> /CreationDate and /ModDate;
	                         NULL or "": no date (never the clock) */
	/* The document's identity in its XMP metadata; NULL: left out. */
	const char *doc_number;       /* dc:identifier, aeroeval:DocumentNumber */
	const char *revision;         /* xmpMM:VersionID, aeroeval:Revision */
	const char *input_sha256;     /* aeroeval:InputSHA256 */
	const char *catalogue_sha256; /* aeroeval:CatalogueSHA256 */
};

enum doc_align {
	DOC_ALIGN_LEFT,
	DOC_ALIGN_RIGHT,
	DOC_ALIGN_CENTER
};

/* How one table cell is printed. */
enum doc_cell {
	DOC_CELL_NORMAL,
	DOC_CELL_BOLD,
	DOC_CELL_MUTED,
	DOC_CELL_MONO,        /* fingerprints, part numbers */
	DOC_CELL_PASS,        /* bold, template pass colour */
	DOC_CELL_FAIL,        /* bold, template fail colour */
	DOC_CELL_WARN         /* bold, template warn colour */
};

enum doc_callout_style {
	DOC_CALLOUT_INFO,     /* primary colour */
	DOC_CALLOUT_PASS,     /* e.g. FEASIBLE */
	DOC_CALLOUT_FAIL,     /* e.g. INFEASIBLE */
	DOC_CALLOUT_WARN
};

struct doc_column {
	const char *title;    /* header text */
	double weight;        /* relative width; the table spans the text width */
	enum doc_align align;
};

/* A table under construction: columns plus cells appended row-major.
 * Initialise with doc_table_init, fill with doc_table_cell/_row, draw with
 * doc_table, release with doc_table_clear. */
struct doc_table {
	const struct doc_column *cols;  /* caller's, must outlive the table */
	int n_cols;
	int n_cells;                    /* cells appended so far */
	int cap_cells;
	char **cells;                   /* owned */
	unsigned char *styles;          /* owned, enum doc_cell per cell */
	int total_row;                  /* nonzero: last row is a bold total row */
	int no_header;                  /* nonzero: no header row */
	int no_zebra;                   /* nonzero: no alternate row shading */
};

/* ---- the document ------------------------------------------------------ */

/* A new document with one empty page.  Never NULL; a failure (bad font,
 * bad date) is sticky and reported by doc_error()/doc_save_mem().
 * Ownership: free with doc_free(). */
struct doc *doc_alloc(const struct template *tpl, const struct doc_info *info);
void doc_free(struct doc *d);            /* NULL is a no-op */

/* NULL while all is well, else the first error, e.g. "libharu error 0x1025". */
const char *doc_error(const struct doc *d);

/* Renders header/footer and the PDF into a new buffer (*out, *n).  Returns
 * 0, or -1 (nothing returned) after any error.  Call once.  Ownership: the
 * caller frees *out with free(). */
int doc_save_mem(struct doc *d, unsigned char **out, size_t *n);

/* Pages so far (the cover counts). */
int doc_page_count(const struct doc *d);

/* Releases library caches (cairo) at program exit so valgrind is clean. */
void doc_global_cleanup(void);

/* ---- flow elements (all return 0 or -1) -------------------------------- */

/* Title block for a cover page: big title, subtitle, the template's logo,
 * and a level-1 outline bookmark named by the title. */
int doc_title(struct doc *d, const char *title, const char *subtitle);
/* Level 1 starts a section on a new page with an outline bookmark; level 2
 * adds a nested bookmark; level 3 is a run-in heading without bookmark. */
int doc_heading(struct doc *d, int level, const char *text);
/* Wrapped text; "\n" breaks a line, a blank line separates paragraphs.
 * Words wider than the line are broken between characters. */
int doc_paragraph(struct doc *d, const char *text);
/* Same in the monospace font, smaller (hashes, file contents). */
int doc_code(struct doc *d, const char *text);
int doc_bullets(struct doc *d, const char *const *items, int n);
/* Two-column table: kv[2i] the key, kv[2i+1] the value, n_pairs rows. */
int doc_kv_table(struct doc *d, const char *const *kv, int n_pairs);
/* Draws the table across the text width; rows never split, the header is
 * repeated on every page the table reaches.  A cell count that does not
 * fill whole rows is an error. */
int doc_table(struct doc *d, const struct doc_table *t);
/* A tinted box with a bar in the style colour: title big and bold (may be
 * NULL), text wrapped below (may be NULL). */
int doc_callout(struct doc *d, enum doc_callout_style style, const char *title,
                const char *text);
/* Places the figure (full text width if its width is 0, never wider) with
 * the caption "Figure n: caption" under it, on a new page if it does not fit
 * in what is left of this one; returns n, or -1.  A figure taller than the
 * text block is not scaled down: keep heights under about 600 pt. */
int doc_figure(struct doc *d, const struct plot *p, const char *caption);
/* The number the next doc_figure will get (for "see Figure 3" ahead). */
int doc_next_figure_number(const struct doc *d);
/* A table of contents here: a level-2 heading `title`, then room for
 * n_rows lines, filled when the document is saved with every level-1
 * heading placed after this call, each with its page number and a link to
 * it (headings beyond n_rows are left out).  Once per document. */
int doc_contents(struct doc *d, const char *title, int n_rows);
/* A new page if fewer than h_pt remain. */
int doc_ensure_space(struct doc *d, double h_pt);
int doc_new_page(struct doc *d);
/* Height left on the current page and the text width, in points. */
double doc_space_left(const struct doc *d);
double doc_text_width(const struct doc *d);

/* From now on every text the document draws is also appended to sb (the
 * caller's, which must outlive d), one element to a line, in the order
 * drawn: a heading as "# " (level 1), "## " or "### " and its text; a
 * title, paragraph, bullet ("• ") or callout line as its whole text,
 * unwrapped; a table row as its cells joined by tabs (the header row
 * first, once); a figure as "Figure n: caption" after one "| label" line
 * for each text inside the figure.  A no-break space is written as a
 * space, as it is drawn.  For tests and tools that read what a dossier
 * says without reading the PDF back; NULL stops it. */
void doc_set_transcript(struct doc *d, struct strbuf *sb);

/* Embeds data as the attached file `name` (a bare file name, no '/'). */
int doc_attach(struct doc *d, const char *name, const void *data, size_t n);

/* ---- tables -------------------------------------------------------------- */

void doc_table_init(struct doc_table *t, const struct doc_column *cols, int n_cols);
/* Appends the next cell (row-major), printf-style. */
void doc_table_cell(struct doc_table *t, enum doc_cell style, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* Appends a whole row of n_cols plain strings (NULL prints as empty). */
void doc_table_row(struct doc_table *t, const char *const *cells);
void doc_table_clear(struct doc_table *t);

#endif
