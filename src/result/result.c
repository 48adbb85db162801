/* result.c — the few constants and helpers of the result contract (see
 * result.h). */
#include "result/result.h"

#include <math.h>
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

double
res_lightest_mass_kg(const struct res_run *run)
{
	double m = run->mass.total_kg;
	int n = run->n_trace < 0 ? 0 : run->n_trace > RES_MAX_TRACE ? RES_MAX_TRACE : run->n_trace;
	for (int i = 0; i < n; i++)
		if (run->trace[i].mass_kg > 0.0 && run->trace[i].mass_kg < m)
			m = run->trace[i].mass_kg;
	return m;
}

/* Does the record's discharge trace show payload leaving the aircraft?
 * (A gram's fall is a drop or a spray; the trace keeps the mass.) */
static bool
sheds(const struct res_run *run)
{
	int n = run->n_trace < 0 ? 0 : run->n_trace > RES_MAX_TRACE ? RES_MAX_TRACE : run->n_trace;
	for (int i = 0; i < n; i++)
		if (run->trace[i].mass_kg < run->mass.total_kg - 1e-3)
			return true;
	return false;
}

void
res_figures(const struct solve_result *r, struct res_figures *f)
{
	bool buildable;
	const struct res_run *rec = res_record(r, &buildable);
	memset(f, 0, sizeof *f);
	f->buildable = buildable;
	/* The takeoff mass of record is what the bill of materials builds
	 * plus the payload it carries (the engine holds the record's own
	 * mass to it within a gram), else the continuous design's. */
	f->takeoff_mass_kg = rec->mass.total_kg;
	f->payload_kg = rec->mass.payload_kg;
	if (buildable && r->n_bom > 0) {
		double payload = 0.0;
		int n_bom = r->n_bom > RES_MAX_BOM ? RES_MAX_BOM : r->n_bom;
		for (int i = 0; i < n_bom; i++)
			if (strcmp(r->bom[i].category, "payload") == 0)
				payload += r->bom[i].total_mass_kg;
		f->takeoff_mass_kg = r->bom_mass_kg + payload;
		f->payload_kg = payload;
	}
	f->sheds = sheds(rec);
	f->hover_power_w = rec->hover_power_w;
	f->hover_power_shed_w = f->sheds ? rec->hover_power_shed_w : NAN;
	if (buildable && rec->perf.valid)
		f->hover_current_a = rec->perf.op[OP_HOVER].battery_current_a;
	else
		f->hover_current_a = f->sheds ? NAN : rec->phase[PHASE_HOVER].current_a;
	f->aux_power_w = rec->aux_power_w;
	f->hover_endurance_s = rec->hover_endurance_s;
	f->flight_time_s = rec->flight_time_s;
	f->landing_soc = rec->end_soc;
	f->reserve_soc = rec->reserve_soc;
	if (r->parts_selected) {
		f->bom_mass_kg = r->bom_mass_kg;
		f->bom_price_usd = r->bom_price_usd;
		f->bom_lines = r->bom_parts_lines;
		f->unpriced_lines = r->bom_parts_lines - r->bom_priced_lines;
	}
}

const char *
res_price_text(const struct solve_result *r, char *buf, size_t n)
{
	buf[0] = '\0';
	if (!r->parts_selected)
		return buf;
	/* The counts of the parts search (parts/bom.c), as every writer
	 * prints them. */
	int lines = r->bom_parts_lines, priced = r->bom_priced_lines;
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

const char *
res_chemistry_text(const char *name, char *buf, size_t n)
{
	const char *us = strchr(name, '_');
	if (us == NULL || us[1] == '\0') {
		snprintf(buf, n, "%s", name);
		return buf;
	}
	const char *grade = strcmp(us + 1, "highvoltage") == 0 ? "high-voltage" : us + 1;
	snprintf(buf, n, "%.*s (%s grade)", (int)(us - name), name, grade);
	return buf;
}
