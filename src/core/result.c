/* result.c — the few constants and helpers of the result contract (see
 * result.h). */
#include "core/result.h"

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

/* Spellings of enum res_phase_id, as written to result.json, bom.csv and the
 * dossier; index = enum value. */
const char *const res_phase_name[PHASE_MAX] = { "climb", "forward", "hover" };
const char *const res_op_name[OP_MAX] = { "hover", "climb", "cruise", "full throttle" };
const char *const res_limit_name[RES_LIMIT_MAX] = { "none", "propeller_inflow",
	"pitch_limit", "search_bound" };

const struct res_check *
res_tightest_check(const struct res_run *run)
{
	const struct res_check *best = NULL;
	for (int i = 0; i < run->n_checks; i++) {
		const struct res_check *c = &run->checks[i];
		if (c->pass && !c->sized && (best == NULL || c->margin < best->margin))
			best = c;
	}
	return best;
}

/* Where a run's samples end. */
static size_t
trace_end(void)
{
	return offsetof(struct res_run, trace) + sizeof ((struct res_run *)0)->trace;
}

void
res_run_clear_untraced(struct res_run *run)
{
	char *base = (char *)run;
	memset(base, 0, offsetof(struct res_run, trace));
	memset(base + trace_end(), 0, sizeof *run - trace_end());
}

void
res_rationale(struct solve_result *r, const char *fmt, ...)
{
	if (r == NULL || r->n_rationale >= RES_MAX_RATIONALE)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(r->rationale[r->n_rationale++], RES_TEXT, fmt, ap);
	va_end(ap);
}

const struct res_run *
res_record(const struct solve_result *r, bool *buildable)
{
	bool real = r->parts_selected && r->closed.ran;
	if (buildable != NULL)
		*buildable = real;
	return real ? &r->closed : &r->custom;
}

const char *
res_price_text(const struct solve_result *r, char *buf, size_t n)
{
	buf[0] = '\0';
	if (!r->parts_selected)
		return buf;
	int lines = 0, priced = 0;
	int n_bom = r->n_bom < 0 ? 0 : r->n_bom > RES_MAX_BOM ? RES_MAX_BOM : r->n_bom;
	for (int i = 0; i < n_bom; i++) {
		if (strcmp(r->bom[i].category, "payload") == 0)
			continue;
		lines++;
		priced += r->bom[i].unit_price_usd > 0.0;
	}
	int unpriced = lines - priced;
	if (priced == 0)
		snprintf(buf, n, "unpriced (%d lines)", lines);
	else if (unpriced == 0)
		snprintf(buf, n, "%.2f USD", r->bom_price_usd);
	else
		snprintf(buf, n, "≥ %.2f USD, %d of %d lines unpriced",
		    r->bom_price_usd, unpriced, lines);
	return buf;
}

const char *
res_eu_class(double mass_kg)
{
	if (mass_kg < RES_EU_C0_KG)
		return "C0";
	if (mass_kg < RES_EU_C1_KG)
		return "C1";
	if (mass_kg < RES_EU_C2_KG)
		return "C2";
	if (mass_kg < RES_EU_C3_KG)
		return "C3/C4";
	return "specific";
}
