/* doc_int.h — what doc.c (the document, its pages and flow) shares with
 * doc_table.c (tables and the web addresses in them).  Internal to the
 * doc module: include it from doc*.c only.
 */
#ifndef AEROEVAL_DOC_INT_H
#define AEROEVAL_DOC_INT_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#include <hpdf.h>

#include "pdf/doc.h"
#include "util/strbuf.h"
#include "util/sha256.h"

#define LEADING 1.38          /* line height / font size for body text */
#define TABLE_SCALE 0.9       /* table text size / body size */
#define CELL_PAD_X 3.5        /* table cell padding, points */
#define CELL_PAD_Y 2.6

/* One line of the contents: a level-1 heading and where it is. */
struct toc_entry {
	char *text;
	int page;                   /* index into pages[] */
	double y;                   /* the heading's top, PDF coordinates */
};

/* The document's identity for its XMP metadata (doc_pdfa.c): copies of
 * doc_info's texts, "" where none was given. */
struct doc_meta {
	char *title, *author, *subject;
	char *doc_number, *revision, *input_sha256, *catalogue_sha256;
};

struct doc {
	HPDF_Doc pdf;
	struct template tpl;        /* copy: the caller's may go away */
	HPDF_Font font, bold, mono; /* mono loaded on first use */
	HPDF_Encoder utf8;          /* for outline titles */
	HPDF_Dict to_unicode;       /* the fonts' shared ToUnicode map, once made */
	HPDF_Page *pages;           /* every page, for header/footer at save */
	int n_pages, cap_pages;
	HPDF_Page page;             /* current page */
	double page_w, page_h;      /* points */
	double left, right, top, bottom; /* text block, PDF coordinates */
	double y;                   /* cursor: top of the next element */
	int at_top;                 /* nothing placed on this page yet */
	int after_heading;          /* the last thing placed is a level-2/3 heading */
	HPDF_Outline outline_l1;    /* last level-1 bookmark (parent of level 2) */
	int n_figures;              /* figures placed */
	char *title, *mission;      /* running header */
	int saved;                  /* doc_save_mem ran */
	/* contents (doc_contents): the level-1 headings after it, listed on
	 * the area it reserved when the document is saved */
	int toc_on;                 /* headings are being collected */
	int toc_page, toc_rows;     /* page index of the list, rows reserved */
	double toc_top;             /* top of the reserved area */
	struct toc_entry *toc;
	int n_toc, cap_toc;
	char err[128];              /* first error, "" if none */
	/* PDF/A (doc_pdfa.c) */
	struct doc_meta meta;
	char date[11];              /* "YYYY-MM-DD", "" undated */
	HPDF_Array af;              /* the catalogue's associated files, or NULL */
	struct sha256_ctx id_ctx;   /* the attachments, then the XMP: the /ID */
	struct strbuf *transcript;  /* the caller's, or NULL (doc_set_transcript()) */
};

/* One output line: a slice of the source text. */
struct line {
	const char *s;
	size_t len;
};

struct lines {
	struct line *v;
	int n, cap;
};

/* PDF/A-3b (doc_pdfa.c): the output intent when the document is made;
 * an attachment's file specification and stream made an associated file;
 * the metadata, the trailer /ID and printable annotations before it is
 * saved.  Each records a failure in d. */
void doc_pdfa_begin(struct doc *d);
void doc_pdfa_associate(struct doc *d, HPDF_Dict spec, HPDF_Dict file, const char *name,
                        const void *data, size_t n);
void doc_pdfa_finish(struct doc *d);

/* Appends one element's text to the transcript, if one is kept: prefix,
 * then text (a no-break space as a space), then a newline. */
void doc_transcribe(struct doc *d, const char *prefix, const char *text);

/* Remembers the first error (later ones are its consequences).  Here, not
 * in doc.c, because doc_pdfa.c records its failures too and doc.c calls
 * doc_pdfa.c: the two files must not call each other. */
static inline void doc_fail(struct doc *d, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
static inline void
doc_fail(struct doc *d, const char *fmt, ...)
{
	if (d->err[0] != '\0')
		return;   /* keep the first, it is the cause */
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(d->err, sizeof d->err, fmt, ap);
	va_end(ap);
}

/* An error has been recorded: every element does nothing from then on. */
static inline int
doc_failed(const struct doc *d)
{
	return d->err[0] != '\0';
}

/* Width of len bytes of s in font f at size, points. */
double doc_width(HPDF_Font f, double size, const char *s, size_t len);
/* Greedy word wrap of text into lines no wider than width: spaces and
 * "\n" separate words (a no-break space does not); a word wider than the
 * line breaks after '/' or '-', a number never. */
void doc_wrap(HPDF_Font f, double size, double width, const char *text, struct lines *out);
/* May the word [s, e) break after its character c? */
int doc_breaks_after(const char *s, const char *c, const char *e);
/* Draws s aligned between x0 and x1 at baseline y; returns the x it
 * starts at. */
double doc_put_aligned(struct doc *d, HPDF_Font f, double size, double x0, double x1, double y,
                       const char *s, size_t len, enum doc_align al, struct template_colour k);
void doc_fill_rect(struct doc *d, double x, double y, double w, double h, struct template_colour k);
void doc_hrule(struct doc *d, double x0, double x1, double y, double width, struct template_colour k);
/* k mixed with white: f = 1 is k, f = 0 white. */
struct template_colour doc_mix_white(struct template_colour k, double f);
/* Starts a new page; the cursor goes to its top. */
void doc_add_page(struct doc *d);
/* Moves the cursor down by h after placing something. */
void doc_advance(struct doc *d, double h);
/* The monospace font, loaded on first use. */
HPDF_Font doc_mono_font(struct doc *d);

#endif
