/* report_util.h — what the dossier's sections share: the state of one
 * render (struct rep) and the helpers every section uses.  Internal to the
 * dossier: include it from report*.c only.
 *
 * The files split along what the reader meets; report.c includes the
 * sections, the sections include only this (and the document's own
 * headers), so no section reaches back into the driver:
 *   report.c         the driver: the sections in the template's order;
 *   report_util.c    these helpers;
 *   report_cover.c   cover, document control and contents, executive
 *                    summary, design rationale;
 *   report_tables.c  mass budget, bill of materials, checks, appendix;
 *   report_figs.c    mission and energy, thermal and electrical traces,
 *                    structure and resonance, convergence, endurance;
 *   report_prop.c    propulsion selection: the parts, the operating points
 *                    and what the aircraft can do beyond its mission.
 * The helpers keep the dossier's prefix, report_, as the sections do: the
 * module is the dossier, and this file is the part of it they all call.
 *
 * Every section describes the design of record (res_record(): the aircraft
 * the bill of materials builds); the continuous optimum ("what the physics
 * asks for") and the baseline (the paper's dead-weight reference) are shown
 * beside it as references.
 */
#ifndef AEROEVAL_REPORT_UTIL_H
#define AEROEVAL_REPORT_UTIL_H

#include <stdbool.h>
#include <stddef.h>

#include "pdf/doc.h"
#include "pdf/report_input.h"
#include "result/result.h"
#include "template/template.h"
#include "util/strbuf.h"

/* Series colours by role, the same in every figure (report.h). */
#define REP_COL_BASELINE 0
#define REP_COL_CUSTOM   1
#define REP_COL_CLOSED   2

/* Room a sub-heading keeps for what follows: table header and three rows, pt. */
#define REP_KEEP_PT 100.0
/* A passing margin under this fraction is printed in the warning colour. */
#define REP_TIGHT_MARGIN 0.05
/* Battery thermal-runaway limit, °C (therm.h THERM_RUNAWAY_C; the PDF
 * layer may not include physics headers). */
#define REP_RUNAWAY_C 60.0
/* Motor winding limit kept in flight, °C (motor.h MOTOR_WINDING_MAX_C). */
#define REP_WINDING_MAX_C 150.0

/* A no-break space (U+00A0): between a number and its unit, so that the
 * two never land on different lines (doc.c draws it as a space). */
#define NBSP "\xc2\xa0"

/* How the three designs are named wherever they are shown. */
#define REP_NAME_RECORD     "Design of record"
#define REP_NAME_CONTINUOUS "Continuous optimum"
#define REP_NAME_BASELINE   "Baseline"
/* The baseline as its sub-headings name it: the same mission sized
 * without the role's equipment, its payload carried as dead weight. */
#define REP_BASELINE_HEADING "Baseline (the same mission without the role's equipment)"
/* The one sentence that explains a J-score, wherever one is shown. */
#define REP_J_NOTE "J is the estimated takeoff-mass penalty of a parts combination over " \
	"the continuous design, in percent (negative: lighter than the continuous design); " \
	"the parts search keeps the lowest."

/* The state of one render, passed to every section writer. */
struct rep {
	struct doc *d;                    /* the document being written */
	const struct report_input *in;    /* caller's input */
	const struct solve_result *r;     /* = in->r */
	const struct template *tpl;       /* = in->tpl */
	const struct res_run *rec;        /* the design of record, res_record() */
	bool buildable;                   /* rec is the aircraft the BOM builds */
	bool rec_ok;                      /* buildable and every check of rec passes */
	struct res_figures fig;           /* the record's figures, one number each
	                                     (res_figures()): every page prints these */
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
/* s, or "—" when s is NULL or empty. */
const char *report_or_absent(const char *s);
/* What ends an envelope figure (a top speed, a climb when climb), in one
 * short phrase of the client's words: "limited by the 35° pitch limit";
 * "" for a climb whose limit was not worked out. */
const char *report_limit_phrase(enum res_limit l, bool climb);

/* Appends a number cell: "—" when x is not finite. */
void report_cell_num(struct doc_table *t, enum doc_cell style, double x, int dec);

/* A mass in the dossier's mass unit, without the unit. */
const char *report_mass(const struct rep *rp, char *buf, size_t n, double kg);
/* A mass change with its sign ("+0.268", "-0.013", "0.000"). */
const char *report_delta(const struct rep *rp, char *buf, size_t n, double kg);

/* The name of the design of record where it is shown: "Design of
 * record", or "Continuous design (not buildable)" when no parts closed. */
const char *report_record_name(const struct rep *rp);

/* The name of the continuous optimum where it is shown beside the
 * record: "Continuous optimum", with "(not buildable)" when the record
 * fails its checks (no parts build it either), or "Continuous design (not
 * buildable)" when it stands in for the record. */
const char *report_continuous_name(const struct rep *rp);

/* A heading for the continuous design, "Continuous optimum (what)", with
 * "; not buildable" inside the brackets when report_continuous_name()
 * says so; written into sb, returned. */
const char *report_continuous_heading(const struct rep *rp, struct strbuf *sb, const char *what);

/* The takeoff mass of record: the bill of materials plus the payload
 * (the engine's invariant makes it the record's takeoff mass), or the
 * continuous design's when nothing is buildable. */
double report_mtow(const struct rep *rp);
/* The price of the bill of materials as the lower bound it is: "1 234.56
 * USD", "≥ 1199.96 USD, 11 of 12 lines unpriced", or "not known (none of
 * the 12 lines has a price)"; written into sb, returned. */
const char *report_price(const struct rep *rp, struct strbuf *sb);

/* The check of run whose name starts with prefix, or NULL. */
/* A check's margin for a table: "12.5 %", "140 %", "> 999 %". */
const char *report_margin(char *buf, size_t n, double margin);

/* A label/value table with a narrow label column; values from mono_from
 * on (>= 0) in the monospace font (fingerprints). */
void report_kv(struct rep *rp, const char *const *kv, int n_pairs, int mono_from);
/* A numbered list as a two-column table without rules: hanging indent. */
void report_numbered(struct rep *rp, const char *const *items, int n, int first_no);
/* The violations as a numbered list with the fixes under each; each names
 * the design it belongs to. */
void report_violations(struct rep *rp);
/* Why no catalogue parts were selected, in one plain sentence. */
const char *report_no_parts_reason(const struct rep *rp);
/* A chemistry profile's name as a reader says it (res_chemistry_text()),
 * from a ring of four per-thread buffers: valid for the next three calls,
 * so two may stand in one sentence. */
const char *report_chemistry(const char *name);
/* The mission's role name ("imaging"). */
const char *report_role_name(const struct solve_result *r);

/* The mass items of struct res_mass, in the order of result.json. */
struct report_mass_item {
	const char *label;
	size_t offset;
};
extern const struct report_mass_item report_mass_items[];
extern const int report_n_mass_items;
double report_mass_get(const struct res_mass *m, int i);

#endif
