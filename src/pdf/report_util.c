/* report_util.c — the helpers every section of the dossier shares
 * (report_util.h): numbers and units, the designs' names, headings, lists
 * and small tables, the mass items.
 */
#include "pdf/report_util.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pdf/doc.h"
#include "util/numfmt.h"
#include "util/strbuf.h"

/* ---- numbers and text ---------------------------------------------------- */

double
report_div(double a, double b)
{
	if (b == 0.0)
		return 0.0;
	double q = a / b;
	return isfinite(q) ? q : 0.0;
}

const char *
report_limit_phrase(enum res_limit l, bool climb)
{
	switch (l) {
	case RES_LIMIT_INFLOW:
		return climb ? "limited by the propellers' thrust at the climb's inflow"
		    : "limited by the propellers' thrust against drag at that speed's inflow";
	case RES_LIMIT_PITCH:
		return "limited by the 35° pitch limit";
	case RES_LIMIT_BOUND:
		return "at least: the search's bound, not a limit of the aircraft";
	case RES_LIMIT_NONE:
	case RES_LIMIT_MAX:
	default:
		return climb ? "" : "within full thrust and 35° pitch";
	}
}

const char *
report_num(char *buf, size_t n, double x, int dec)
{
	if (numfmt_fixed(buf, n, x, dec) == 0)
		snprintf(buf, n, "—");
	return buf;
}

const char *
report_auto(char *buf, size_t n, double x)
{
	if (!isfinite(x))
		return report_num(buf, n, x, 0);
	double a = fabs(x);
	int dec = a == 0.0 ? 0 : 2 - (int)floor(log10(a));
	dec = dec < 0 ? 0 : dec > 4 ? 4 : dec;
	return report_num(buf, n, x, dec);
}

const char *
report_sfmt(struct strbuf *sb, const char *fmt, ...)
{
	va_list ap;
	strbuf_reset(sb);
	va_start(ap, fmt);
	strbuf_vprintf(sb, fmt, ap);
	va_end(ap);
	return strbuf_str(sb);
}

const char *
report_or_absent(const char *s)
{
	return s != NULL && s[0] != '\0' ? s : "—";
}

void
report_cell_num(struct doc_table *t, enum doc_cell style, double x, int dec)
{
	char b[48];
	doc_table_cell(t, style, "%s", report_num(b, sizeof b, x, dec));
}

const char *
report_mass(const struct rep *rp, char *buf, size_t n, double kg)
{
	return report_num(buf, n, kg * rp->mass_scale, rp->mass_dec);
}

const char *
report_delta(const struct rep *rp, char *buf, size_t n, double kg)
{
	char tmp[40];
	report_mass(rp, tmp, sizeof tmp, kg);
	int zero = strspn(tmp, "0.") == strlen(tmp) || strcmp(tmp, "—") == 0;
	snprintf(buf, n, "%s%s", kg > 0 && !zero ? "+" : "", tmp);
	return buf;
}

const char *
report_chemistry(const char *name)
{
	static _Thread_local char ring[4][64];
	static _Thread_local int next;
	char *b = ring[next++ % 4];
	return res_chemistry_text(name != NULL ? name : "", b, sizeof ring[0]);
}

const char *
report_role_name(const struct solve_result *r)
{
	int t = r->mission.payload_role.type;
	return t >= 0 && t < ROLE_MAX ? spec_enum_role[t] : "?";
}

/* ---- the design of record ------------------------------------------------ */

const char *
report_record_name(const struct rep *rp)
{
	if (rp->r->ceiling.shown)
		return "Ceiling design (a shorter flight)";
	return rp->buildable ? REP_NAME_RECORD : "Continuous design (not buildable)";
}

const char *
report_continuous_name(const struct rep *rp)
{
	if (rp->r->ceiling.shown)
		return "Ceiling design (a shorter flight)";
	if (!rp->buildable)
		return "Continuous design (not buildable)";
	return rp->rec_ok ? REP_NAME_CONTINUOUS : REP_NAME_CONTINUOUS " (not buildable)";
}

const char *
report_continuous_heading(const struct rep *rp, struct strbuf *sb, const char *what)
{
	return report_sfmt(sb, "%s (%s%s)", rp->buildable ? REP_NAME_CONTINUOUS : "Continuous design", what,
	                   rp->rec_ok ? "" : "; not buildable");
}

double
report_mtow(const struct rep *rp)
{
	return rp->fig.takeoff_mass_kg;
}

const char *
report_price(const struct rep *rp, struct strbuf *sb)
{
	const struct solve_result *r = rp->r;
	char b[48];
	int lines = r->bom_parts_lines, priced = r->bom_priced_lines;
	strbuf_reset(sb);
	if (lines <= 0)
		strbuf_append_str(sb, "no bill of materials");
	else if (priced <= 0)
		strbuf_printf(sb, "not known (none of the %d lines has a price)", lines);
	else if (priced >= lines)
		strbuf_printf(sb, "%s" NBSP "USD", report_num(b, sizeof b, r->bom_price_usd, 2));
	else
		strbuf_printf(sb, "≥" NBSP "%s" NBSP "USD, %d of %d lines unpriced",
		              report_num(b, sizeof b, r->bom_price_usd, 2), lines - priced, lines);
	return strbuf_str(sb);
}

const char *
report_margin(char *buf, size_t n, double margin)
{
	/* A margin of ten times the limit or more says only "far": no
	 * absurd percentages. */
	if (margin >= 10.0 || margin <= -10.0) {
		str_copy(buf, n, margin > 0.0 ? ">" NBSP "999" NBSP "%" : "<" NBSP "−999" NBSP "%");
		return buf;
	}
	char num[32];
	report_num(num, sizeof num, 100.0 * margin, fabs(margin) >= 1.0 ? 0 : 1);
	snprintf(buf, n, "%s" NBSP "%%", num);
	return buf;
}

/* ---- headings, lists, small tables ---------------------------------------- */

void
report_heading(struct rep *rp, const char *title)
{
	char h[TEMPLATE_TITLE_MAX + 16];
	snprintf(h, sizeof h, "%d  %s", ++rp->n_section, title);
	doc_heading(rp->d, 1, h);
}

void
report_subheading(struct rep *rp, const char *title, double keep_pt)
{
	doc_ensure_space(rp->d, keep_pt);
	doc_heading(rp->d, 2, title);
}

void
report_kv(struct rep *rp, const char *const *kv, int n_pairs, int mono_from)
{
	static const struct doc_column cols[2] = { { "", 1.35, DOC_ALIGN_LEFT },
	                                           { "", 4.0, DOC_ALIGN_LEFT } };
	struct doc_table t;
	doc_table_init(&t, cols, 2);
	t.no_header = 1;
	for (int i = 0; i < n_pairs; i++) {
		doc_table_cell(&t, DOC_CELL_MUTED, "%s", report_or_absent(kv[2 * i]));
		doc_table_cell(&t, mono_from >= 0 && i >= mono_from ? DOC_CELL_MONO : DOC_CELL_NORMAL,
		               "%s", report_or_absent(kv[2 * i + 1]));
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
}

void
report_numbered(struct rep *rp, const char *const *items, int n, int first_no)
{
	static const struct doc_column cols[] = { { "", 0.5, DOC_ALIGN_RIGHT },
	                                          { "", 9.0, DOC_ALIGN_LEFT } };
	struct doc_table t;
	doc_table_init(&t, cols, 2);
	t.no_header = 1;
	t.no_zebra = 1;
	for (int i = 0; i < n; i++) {
		doc_table_cell(&t, DOC_CELL_MUTED, "%d.", first_no + i);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", items[i]);
	}
	if (n > 0)
		doc_table(rp->d, &t);
	doc_table_clear(&t);
}

/* The design a violation's run names, as the reader knows it. */
static const char *
run_title(const char *run)
{
	if (strcmp(run, "closed") == 0)
		return "design of record";
	if (strcmp(run, "custom") == 0)
		return "continuous optimum";
	if (strcmp(run, "baseline") == 0)
		return "baseline";
	return run;
}

void
report_violations(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	struct strbuf sb = STRBUF_INIT;
	for (int i = 0; i < r->n_violations && i < RES_MAX_VIOLATIONS; i++) {
		const struct res_violation *v = &r->violations[i];
		strbuf_reset(&sb);
		strbuf_printf(&sb, "%s (%s)", v->message, run_title(v->run));
		for (int k = 0; k < v->n_fixes && k < RES_MAX_FIXES; k++)
			strbuf_printf(&sb, "\nFix: %s", v->fixes[k]);
		const char *item = strbuf_str(&sb);
		report_numbered(rp, &item, 1, i + 1);
	}
	strbuf_free(&sb);
}

const char *
report_no_parts_reason(const struct rep *rp)
{
	const struct solve_result *r = rp->r;
	for (int i = 0; i < r->n_violations; i++)
		if (strcmp(r->violations[i].stage, "parts") == 0 && r->violations[i].message[0] != '\0')
			return r->violations[i].message;
	if (rp->in->cat == NULL)
		return "No parts catalogue was loaded for this build, so no parts were searched.";
	if (!r->custom.ran)
		return "The continuous design stopped at the feasibility gate, so there was no "
		       "sized requirement to match parts against.";
	if (!r->custom.converged)
		return "The continuous design's mass loop did not converge, so there was no sized "
		       "requirement to match parts against.";
	if (r->n_candidates == 0)
		return "The parts search scored no catalogue motor for this design.";
	return "No combination of catalogue motor, propeller, battery and ESC closes the design.";
}

/* ---- mass items ------------------------------------------------------------ */

const struct report_mass_item report_mass_items[] = {
	{ "Payload", offsetof(struct res_mass, payload_kg) },
	{ "Battery", offsetof(struct res_mass, battery_kg) },
	{ "Frame", offsetof(struct res_mass, frame_kg) },
	{ "Arms", offsetof(struct res_mass, arm_kg) },
	{ "Motors", offsetof(struct res_mass, motor_kg) },
	{ "Propellers", offsetof(struct res_mass, prop_kg) },
	{ "ESCs", offsetof(struct res_mass, esc_kg) },
	{ "Wiring", offsetof(struct res_mass, wiring_kg) },
	{ "Avionics", offsetof(struct res_mass, avionics_kg) },
	{ "Role hardware", offsetof(struct res_mass, role_aux_kg) },
	{ "Other (body, gear, mounts)", offsetof(struct res_mass, other_kg) },
};
const int report_n_mass_items = (int)(sizeof report_mass_items / sizeof report_mass_items[0]);

double
report_mass_get(const struct res_mass *m, int i)
{
	return *(const double *)(const void *)((const char *)m + report_mass_items[i].offset);
}
