/* report_int.h — what report.c shares with report_figs.c (the dossier's
 * figure-heavy sections).  Internal to the report module: include it from
 * report*.c only.
 */
#ifndef AEROEVAL_REPORT_INT_H
#define AEROEVAL_REPORT_INT_H

#include <stddef.h>

#include "output/doc.h"
#include "output/report.h"
#include "util/strbuf.h"

/* Series colours by role, the same in every figure (report.h). */
#define REP_COL_BASELINE 0
#define REP_COL_CUSTOM   1
#define REP_COL_CLOSED   2

/* Room a sub-heading keeps for what follows: table header and three rows, pt. */
#define REP_KEEP_PT 100.0

/* The state of one render, passed to every section writer. */
struct rep {
	struct doc *d;                    /* the document being written */
	const struct report_input *in;    /* caller's input */
	const struct solve_result *r;     /* = in->r */
	const struct template *tpl;       /* = in->tpl */
	int n_section;                    /* numbered sections written so far */
	double mass_scale;                /* kg -> displayed mass unit */
	const char *mass_unit;            /* "g" for small aircraft, else "kg" */
	int mass_dec;                     /* decimals of displayed masses */
};

/* Starts a numbered section: new page, bookmark, "n  title". */
void report_heading(struct rep *rp, const char *title);

/* A level-2 heading kept with at least keep_pt of what follows (a table
 * header and its first rows), so no heading is left alone at a page foot. */
void report_subheading(struct rep *rp, const char *title, double keep_pt);

/* x with `dec` decimals into buf, or "—" if x is not finite. */
const char *report_num(char *buf, size_t n, double x, int dec);
/* x with about three significant digits, no exponent ("1289", "13.2",
 * "0.588"), or "—" if not finite. */
const char *report_auto(char *buf, size_t n, double x);
/* printf into sb after emptying it; returns its text (valid until sb
 * changes).  For building one-off sentences and labels. */
const char *report_sfmt(struct strbuf *sb, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* a/b, or 0 when b is zero or the quotient is not finite. */
double report_div(double a, double b);

/* Appends a number cell: "—" when x is not finite. */
void report_cell_num(struct doc_table *t, enum doc_cell style, double x, int dec);

/* The figure-heavy sections (report_figs.c). */
void report_sec_mission(struct rep *rp, const char *title);
void report_sec_thermal(struct rep *rp, const char *title);
void report_sec_structure(struct rep *rp, const char *title);
void report_sec_propulsion(struct rep *rp, const char *title);
void report_sec_convergence(struct rep *rp, const char *title);
void report_sec_endurance(struct rep *rp, const char *title);

#endif
