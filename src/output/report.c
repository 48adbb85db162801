/* report.c — the design dossier: cover, summary, rationale, mass budget,
 * bill of materials, checks and appendix, and the driver that walks the
 * template's section list.  The figure-heavy sections are in report_figs.c.
 *
 * Every number printed here comes from the const solve_result; nothing is
 * recomputed beyond ratios, unit conversions and sums, so the dossier says
 * exactly what result.json says.
 */
#include "output/report.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/catalog.h"
#include "output/doc.h"
#include "util/numfmt.h"
#include "output/plot.h"
#include "output/report_int.h"
#include "util/strbuf.h"
#include "util/units.h"
#include "util/xalloc.h"

/* Aircraft lighter than this get their masses in grams. */
#define REP_GRAM_BELOW_KG 2.0
/* A passing margin under this fraction is printed in the warning colour. */
#define REP_TIGHT_MARGIN 0.05
#define REP_KG_PER_LB 0.45359237

/* ---- small helpers shared with report_figs.c ---------------------------- */

double
report_div(double a, double b)
{
	if (b == 0.0)
		return 0.0;
	double q = a / b;
	return isfinite(q) ? q : 0.0;
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

void
report_cell_num(struct doc_table *t, enum doc_cell style, double x, int dec)
{
	char b[48];
	doc_table_cell(t, style, "%s", report_num(b, sizeof b, x, dec));
}

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


/* ---- local helpers ------------------------------------------------------- */

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

/* A mass in the dossier's mass unit, without the unit. */
static const char *
mass_txt(const struct rep *rp, char *buf, size_t n, double kg)
{
	return report_num(buf, n, kg * rp->mass_scale, rp->mass_dec);
}

/* A mass change with its sign ("+0.268", "-0.013", "0.000"): the plus
 * only when the printed value is not zero. */
static const char *
delta_txt(const struct rep *rp, char *buf, size_t n, double kg)
{
	char tmp[40];
	mass_txt(rp, tmp, sizeof tmp, kg);
	int zero = strspn(tmp, "0.") == strlen(tmp) || strcmp(tmp, "—") == 0;
	snprintf(buf, n, "%s%s", kg > 0 && !zero ? "+" : "", tmp);
	return buf;
}

static const char *
or_absent(const char *s)
{
	return s != NULL && s[0] != '\0' ? s : "—";
}

static double
minutes(double s)
{
	return s / 60.0;
}

/* A label/value table with a narrow label column (hashes fit on one line). */
static void
kv_table(struct doc *d, const char *const *kv, int n_pairs, int mono_from)
{
	static const struct doc_column cols[2] = { { "", 1.35, DOC_ALIGN_LEFT },
	                                           { "", 4.0, DOC_ALIGN_LEFT } };
	struct doc_table t;
	doc_table_init(&t, cols, 2);
	t.no_header = 1;
	for (int i = 0; i < n_pairs; i++) {
		doc_table_cell(&t, DOC_CELL_MUTED, "%s", or_absent(kv[2 * i]));
		doc_table_cell(&t, mono_from >= 0 && i >= mono_from ? DOC_CELL_MONO : DOC_CELL_NORMAL,
		               "%s", or_absent(kv[2 * i + 1]));
	}
	doc_table(d, &t);
	doc_table_clear(&t);
}

/* The mass items of struct res_mass, in the order of result.json. */
struct mass_item {
	const char *label;
	size_t offset;
};

static const struct mass_item mass_items[] = {
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
#define N_MASS_ITEMS ((int)(sizeof mass_items / sizeof mass_items[0]))

static double
mass_get(const struct res_mass *m, int i)
{
	return *(const double *)(const void *)((const char *)m + mass_items[i].offset);
}

static const char *
role_name(const struct solve_result *r)
{
	int t = r->mission.payload_role.type;
	return t >= 0 && t < ROLE_MAX ? spec_enum_role[t] : "?";
}

/* ---- 1 cover ------------------------------------------------------------- */

/* Section 1, the page a client signs: identity, fingerprints, verdict and
 * the few numbers everyone asks for first.  `first` is nonzero when the
 * cover opens the document (else it starts its own page).  The cover is
 * not numbered: numbering starts with the first section after it. */
static void
sec_cover(struct rep *rp, int first)
{
	const struct solve_result *r = rp->r;
	const struct mission_spec *m = &r->mission;
	struct strbuf sb = STRBUF_INIT, sb2 = STRBUF_INIT;
	char b1[48], b2[48];
	if (!first)
		doc_new_page(rp->d);
	const char *mname = rp->in->mission_name != NULL ? rp->in->mission_name : m->name;
	doc_title(rp->d, m->report.title[0] != '\0' ? m->report.title : "Design dossier",
	          report_sfmt(&sb, "Multirotor sizing: %s%s%s", or_absent(mname),
	               m->report.revision[0] != '\0' ? ", revision " : "", m->report.revision));

	/* The verdict first: it is what the reader looks for. */
	if (r->feasible) {
		const struct res_check *c = res_tightest_check(&r->custom);
		if (c != NULL)
			report_sfmt(&sb, "Every check of the custom design passes. The tightest is "
			     "\"%s\" with a margin of %s %%.", c->name,
			     report_num(b1, sizeof b1, 100.0 * c->margin, 1));
		else
			report_sfmt(&sb, "Every check of the custom design passes.");
		doc_callout(rp->d, DOC_CALLOUT_PASS, "FEASIBLE", strbuf_str(&sb));
	} else {
		strbuf_reset(&sb);
		strbuf_printf(&sb, "%d constraint%s violated. ", r->n_violations,
		              r->n_violations == 1 ? " is" : "s are");
		if (r->n_violations > 0)
			strbuf_printf(&sb, "First: %s ", r->violations[0].message);
		strbuf_append_str(&sb, "The checks section lists every failure with suggested fixes.");
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "INFEASIBLE", strbuf_str(&sb));
	}

	const char *kv[] = {
		"Client", m->report.client,
		"Project", m->report.project_id,
		"Revision", m->report.revision,
		"Prepared by", m->report.author,
		"Date", rp->in->date,
		"Mission", mname,
		"Mission file", rp->in->mission_file_name,
		"Engine", report_sfmt(&sb2, "aeroeval %s", or_absent(rp->in->engine_version)),
		"Input SHA-256", r->input_sha256,
		"Catalogue SHA-256", r->catalogue_sha256,
	};
	kv_table(rp->d, kv, (int)(sizeof kv / sizeof kv[0]) / 2, 8);

	report_subheading(rp, "Key figures", REP_KEEP_PT);
	static const struct doc_column cols[] = {
		{ "", 2.6, DOC_ALIGN_LEFT }, { "Baseline", 1.3, DOC_ALIGN_RIGHT },
		{ "Custom", 1.3, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 3);
	const struct res_run *run[2] = { &r->baseline, &r->custom };
	doc_table_cell(&t, DOC_CELL_NORMAL, "Takeoff mass (kg)");
	for (int k = 0; k < 2; k++)
		report_cell_num(&t, k ? DOC_CELL_BOLD : DOC_CELL_NORMAL, run[k]->mass.total_kg, 3);
	doc_table_cell(&t, DOC_CELL_NORMAL, "Battery");
	for (int k = 0; k < 2; k++)
		doc_table_cell(&t, DOC_CELL_NORMAL, "%dS %s mAh", run[k]->cell_count,
		               report_num(b1, sizeof b1, run[k]->capacity_mah, 0));
	doc_table_cell(&t, DOC_CELL_NORMAL, "Mission flight time (min)");
	for (int k = 0; k < 2; k++)
		report_cell_num(&t, DOC_CELL_NORMAL, minutes(run[k]->flight_time_s), 1);
	doc_table_cell(&t, DOC_CELL_NORMAL, "Hover endurance to reserve (min)");
	for (int k = 0; k < 2; k++)
		report_cell_num(&t, DOC_CELL_NORMAL, minutes(run[k]->hover_endurance_s), 1);
	doc_table_cell(&t, DOC_CELL_NORMAL, "Thrust-to-weight ratio");
	for (int k = 0; k < 2; k++)
		report_cell_num(&t, DOC_CELL_NORMAL, run[k]->thrust_to_weight, 2);
	doc_table_cell(&t, DOC_CELL_NORMAL, "Propeller (in)");
	for (int k = 0; k < 2; k++)
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s × %s", report_num(b1, sizeof b1, run[k]->opt.prop_diameter_in, 1),
		               report_num(b2, sizeof b2, run[k]->opt.prop_pitch_in, 1));
	doc_table_cell(&t, DOC_CELL_NORMAL, "Battery peak temperature (°C)");
	for (int k = 0; k < 2; k++)
		report_cell_num(&t, DOC_CELL_NORMAL, run[k]->max_battery_temp_c, 1);
	if (r->parts_selected) {
		doc_table_cell(&t, DOC_CELL_NORMAL, "Bill of materials (USD)");
		doc_table_cell(&t, DOC_CELL_MUTED, "—");
		report_cell_num(&t, DOC_CELL_NORMAL, r->bom_price_usd, 2);
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);

	report_subheading(rp, "Mission", REP_KEEP_PT);
	char *v[5];
	v[0] = xstrdup(report_sfmt(&sb, "%s role, %s airframe, %d rotors%s on a %s mm wheelbase", role_name(r),
	                    m->airframe_class >= 0 && m->airframe_class < AF_CLASS_MAX
	                    ? spec_enum_airframe[m->airframe_class] : "?",
	                    m->num_rotors, m->coaxial_layout ? " (coaxial pairs)" : "",
	                    report_num(b1, sizeof b1, 1000.0 * m->max_diameter_m, 0)));
	v[1] = xstrdup(report_sfmt(&sb, "%s kg", report_num(b1, sizeof b1, m->payload_kg, 3)));
	strbuf_reset(&sb);
	strbuf_printf(&sb, "climb %s s at %s m/s", report_num(b1, sizeof b1, m->t_climb_s, 0),
	              report_num(b2, sizeof b2, m->v_climb_ms, 1));
	if (m->t_forward_s > 0)
		strbuf_printf(&sb, ", forward %s s at %s", report_num(b1, sizeof b1, m->t_forward_s, 0),
		              m->v_forward_auto ? "the minimum-power speed"
		                                : report_sfmt(&sb2, "%s m/s", report_num(b2, sizeof b2, m->v_forward_ms, 1)));
	strbuf_printf(&sb, ", hover %s s", report_num(b1, sizeof b1, m->t_hover_s, 0));
	v[2] = xstrdup(strbuf_str(&sb));
	v[3] = xstrdup(report_sfmt(&sb, "%s m altitude, %s °C ambient", report_num(b1, sizeof b1, m->altitude_m, 0),
	                    report_num(b2, sizeof b2, m->ambient_temp_c, 1)));
	v[4] = xstrdup(report_sfmt(&sb, "%s, %s", m->battery_chemistry,
	                    m->locks.is_battery_locked ? "capacity and cells locked"
	                    : m->nominal_cell_count > 0 ? report_sfmt(&sb2, "%d cells in series", m->nominal_cell_count)
	                    : "cell count chosen by the solver"));
	const char *mkv[] = { "Aircraft", v[0], "Payload", v[1], "Profile", v[2], "Environment", v[3],
	                      "Battery", v[4] };
	kv_table(rp->d, mkv, 5, -1);
	for (int i = 0; i < 5; i++)
		free(v[i]);
	doc_paragraph(rp->d, report_sfmt(&sb, "The baseline run sizes the same mission with no role (payload as "
	              "dead weight, hover throttle 60 %%); the custom run applies the %s role. The "
	              "mission file is attached to this PDF.", role_name(r)));
	strbuf_free(&sb);
	strbuf_free(&sb2);
}

/* ---- 2 executive summary ------------------------------------------------ */

/* One row "label | baseline | custom | change" of the comparison table. */
static void
cmp_row(struct doc_table *t, const char *label, double base, double custom, int dec)
{
	char b[48];
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", label);
	report_cell_num(t, DOC_CELL_NORMAL, base, dec);
	report_cell_num(t, DOC_CELL_BOLD, custom, dec);
	double delta = custom - base;
	if (fabs(delta) < 0.5 * pow(10.0, -dec))
		doc_table_cell(t, DOC_CELL_MUTED, "0");
	else
		doc_table_cell(t, DOC_CELL_MUTED, "%s%s", delta > 0 ? "+" : "",
		               report_num(b, sizeof b, delta, dec));
}

/* The regulatory class by takeoff mass, as bullets.  Only mass is judged
 * here: the dossier cannot know the rest of a class declaration, so the
 * text says "informative". */
static void
regulatory(struct rep *rp)
{
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b3[48];
	double m = rp->r->custom.mass.total_kg;
	const char *eu = res_eu_class(m);
	const char *items[3];
	char *own[3];
	if (strcmp(eu, "specific") == 0)
		report_sfmt(&sb, "EU (Regulation 2019/945): at %s kg the aircraft is above the 25 kg limit of the "
		     "open-category classes; it operates in the specific category (operational "
		     "authorisation, SORA).", report_num(b1, sizeof b1, m, 2));
	else
		report_sfmt(&sb, "EU (Regulation 2019/945): a takeoff mass of %s kg falls within class %s by mass "
		     "(C0 < 250 g, C1 < 900 g, C2 < 4 kg, C3/C4 < 25 kg).", report_num(b1, sizeof b1, m, 3), eu);
	own[0] = xstrdup(strbuf_str(&sb));
	if (m < RES_US_107_KG)
		report_sfmt(&sb, "US (14 CFR Part 107): %s kg (%s lb) is below the 55 lb (24.9 kg) small-UAS limit.",
		     report_num(b1, sizeof b1, m, 2), report_num(b3, sizeof b3, m / REP_KG_PER_LB, 1));
	else
		report_sfmt(&sb, "US (14 CFR Part 107): %s kg (%s lb) is at or above the 55 lb (24.9 kg) small-UAS "
		     "limit; an exemption (49 U.S.C. 44807) or Part 91 operation is needed.",
		     report_num(b1, sizeof b1, m, 2), report_num(b3, sizeof b3, m / REP_KG_PER_LB, 1));
	own[1] = xstrdup(strbuf_str(&sb));
	own[2] = xstrdup("Informative only: a class mark also depends on the manufacturer's declaration "
	                 "of conformity (noise, geo-awareness, remote identification, speed limits).");
	for (int i = 0; i < 3; i++)
		items[i] = own[i];
	doc_bullets(rp->d, items, 3);
	for (int i = 0; i < 3; i++)
		free(own[i]);
	strbuf_free(&sb);
}

/* The chosen catalogue parts with quantity and J-score (lower is better). */
static void
parts_table(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	static const struct doc_column cols[] = {
		{ "Part", 1.0, DOC_ALIGN_LEFT }, { "Manufacturer and part number", 3.4, DOC_ALIGN_LEFT },
		{ "Qty", 0.5, DOC_ALIGN_RIGHT }, { "Unit mass (g)", 1.1, DOC_ALIGN_RIGHT },
		{ "J-score", 0.9, DOC_ALIGN_RIGHT },
	};
	const struct res_part *p[4] = { &r->motor, &r->prop, &r->battery, &r->esc };
	static const char *const what[4] = { "Motor", "Propeller", "Battery", "ESC" };
	struct doc_table t;
	doc_table_init(&t, cols, 5);
	for (int i = 0; i < 4; i++) {
		if (!p[i]->chosen)
			continue;
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", what[i]);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s %s", p[i]->manufacturer, p[i]->part_number);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%d", p[i]->qty);
		report_cell_num(&t, DOC_CELL_NORMAL, 1000.0 * p[i]->unit_mass_kg, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, p[i]->j_score, 3);
	}
	if (t.n_cells > 0)
		doc_table(rp->d, &t);
	doc_table_clear(&t);
}

/* Section 2: baseline against custom side by side, the selected parts and
 * BOM cost, the role overhead item by item, the regulatory class. */
static void
sec_summary(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *b = &r->baseline, *c = &r->custom;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	report_heading(rp, title);
	/* Shedding roles (spray, drop) can size lighter than the baseline. */
	doc_paragraph(rp->d, report_sfmt(&sb, "The %s role %s the takeoff mass from %s kg (baseline, no role) "
	              "to %s kg (%s%s %%). The custom design is %s.", role_name(r),
	              c->mass.total_kg >= b->mass.total_kg ? "raises" : "lowers",
	              report_num(b1, sizeof b1, b->mass.total_kg, 3),
	              report_num(b2, sizeof b2, c->mass.total_kg, 3),
	              c->mass.total_kg >= b->mass.total_kg ? "+" : "",
	              report_num(b3, sizeof b3,
	                         100.0 * report_div(c->mass.total_kg - b->mass.total_kg, b->mass.total_kg), 1),
	              r->feasible ? "feasible" : "INFEASIBLE (see the checks section)"));

	static const struct doc_column cols[] = {
		{ "Quantity", 2.6, DOC_ALIGN_LEFT }, { "Baseline", 1.1, DOC_ALIGN_RIGHT },
		{ "Custom", 1.1, DOC_ALIGN_RIGHT }, { "Change", 1.0, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 4);
	cmp_row(&t, "Takeoff mass MTOW (kg)", b->mass.total_kg, c->mass.total_kg, 3);
	cmp_row(&t, "Battery mass (kg)", b->mass.battery_kg, c->mass.battery_kg, 3);
	cmp_row(&t, "Battery capacity (mAh)", b->capacity_mah, c->capacity_mah, 0);
	cmp_row(&t, "Series cells", b->cell_count, c->cell_count, 0);
	cmp_row(&t, "Battery energy (Wh)", b->energy_wh, c->energy_wh, 1);
	cmp_row(&t, "Thrust-to-weight ratio", b->thrust_to_weight, c->thrust_to_weight, 2);
	cmp_row(&t, "Hover throttle (%)", 100.0 * b->hover_throttle, 100.0 * c->hover_throttle, 1);
	cmp_row(&t, "Mission flight time (min)", minutes(b->flight_time_s), minutes(c->flight_time_s), 1);
	cmp_row(&t, "Hover endurance to reserve (min)", minutes(b->hover_endurance_s),
	        minutes(c->hover_endurance_s), 1);
	if (b->marketing_endurance_s > 0 || c->marketing_endurance_s > 0)
		cmp_row(&t, "Best-case (marketing) endurance (min)", minutes(b->marketing_endurance_s),
		        minutes(c->marketing_endurance_s), 1);
	cmp_row(&t, "Hover power (W)", b->phase[PHASE_HOVER].power_w, c->phase[PHASE_HOVER].power_w, 0);
	cmp_row(&t, "Motor KV (rpm/V)", b->opt.motor_kv, c->opt.motor_kv, 0);
	cmp_row(&t, "Battery peak temperature (°C)", b->max_battery_temp_c, c->max_battery_temp_c, 1);
	doc_table(rp->d, &t);
	doc_table_clear(&t);

	report_subheading(rp, "Selected parts", REP_KEEP_PT);
	if (r->parts_selected) {
		parts_table(rp);
		doc_paragraph(rp->d, report_sfmt(&sb, "Bill of materials: %s USD for %s kg of catalogue and custom parts "
		              "(prices are store snapshots; 0 means unknown).",
		              report_num(b1, sizeof b1, r->bom_price_usd, 2),
		              report_num(b2, sizeof b2, r->bom_mass_kg, 3)));
	} else {
		doc_paragraph(rp->d, "No catalogue parts were selected for this dossier; the design is "
		              "given by its continuous optimum (propeller size, motor KV, battery). "
		              "The bill of materials section says why.");
	}

	report_subheading(rp, "Role overhead", REP_KEEP_PT);
	static const struct doc_column ocols[] = {
		{ "Mass item", 2.6, DOC_ALIGN_LEFT }, { "Baseline", 1.1, DOC_ALIGN_RIGHT },
		{ "Custom", 1.1, DOC_ALIGN_RIGHT }, { "Overhead", 1.0, DOC_ALIGN_RIGHT },
	};
	doc_table_init(&t, ocols, 4);
	for (int i = 0; i < N_MASS_ITEMS; i++) {
		double o = mass_get(&r->role_overhead, i);
		if (fabs(o) * rp->mass_scale < 0.5 * pow(10.0, -rp->mass_dec))
			continue;
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s (%s)", mass_items[i].label, rp->mass_unit);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", mass_txt(rp, b1, sizeof b1, mass_get(&b->mass, i)));
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", mass_txt(rp, b1, sizeof b1, mass_get(&c->mass, i)));
		doc_table_cell(&t, DOC_CELL_BOLD, "%s", delta_txt(rp, b1, sizeof b1, o));
	}
	doc_table_cell(&t, DOC_CELL_BOLD, "Total (%s)", rp->mass_unit);
	doc_table_cell(&t, DOC_CELL_BOLD, "%s", mass_txt(rp, b1, sizeof b1, b->mass.total_kg));
	doc_table_cell(&t, DOC_CELL_BOLD, "%s", mass_txt(rp, b1, sizeof b1, c->mass.total_kg));
	doc_table_cell(&t, DOC_CELL_BOLD, "%s", delta_txt(rp, b1, sizeof b1, r->role_overhead.total_kg));
	t.total_row = 1;
	doc_table(rp->d, &t);
	doc_table_clear(&t);

	report_subheading(rp, "Regulatory class (informative)", REP_KEEP_PT);
	regulatory(rp);
	strbuf_free(&sb);
}

/* ---- 3 design rationale -------------------------------------------------- */

/* A numbered list as a two-column table without rules: hanging indent. */
static void
numbered(struct doc *d, const char *const *items, int n, int first_no)
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
		doc_table(d, &t);
	doc_table_clear(&t);
}

/* The violations as a numbered list with the fixes under each. */
static void
violation_list(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	struct strbuf sb = STRBUF_INIT;
	for (int i = 0; i < r->n_violations; i++) {
		const struct res_violation *v = &r->violations[i];
		strbuf_reset(&sb);
		strbuf_printf(&sb, "%s [%s run, %s, %s]", v->message, v->run, v->stage, v->code);
		for (int k = 0; k < v->n_fixes && k < RES_MAX_FIXES; k++)
			strbuf_printf(&sb, "\nFix: %s", v->fixes[k]);
		const char *item = strbuf_str(&sb);
		numbered(rp->d, &item, 1, i + 1);
	}
	strbuf_free(&sb);
}

/* Section 3: the engine's rationale sentences in order.  An infeasible
 * design leads with what failed, since that is what the reader must act on. */
static void
sec_rationale(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	report_heading(rp, title);
	if (!r->feasible) {
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "INFEASIBLE",
		            "The design does not meet every constraint. The violations come first; the "
		            "decisions the solver took follow.");
		report_subheading(rp, "Violations", REP_KEEP_PT);
		violation_list(rp);
		report_subheading(rp, "Solver decisions", REP_KEEP_PT);
	} else {
		doc_paragraph(rp->d, "Each decision the solver took, in the order it took them.");
	}
	const char *items[RES_MAX_RATIONALE];
	int n = r->n_rationale < RES_MAX_RATIONALE ? r->n_rationale : RES_MAX_RATIONALE;
	for (int i = 0; i < n; i++)
		items[i] = r->rationale[i];
	if (n == 0)
		doc_paragraph(rp->d, "The solver recorded no decisions.");
	numbered(rp->d, items, n, 1);
}

/* ---- 4 mass budget ------------------------------------------------------- */

/* Section 4: stacked bars of every mass item (baseline, custom, and the
 * real-parts run when there is one) and the same numbers as a table with
 * each item's share of its run's takeoff mass. */
static void
sec_mass(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	struct strbuf sb = STRBUF_INIT;
	char b1[48];
	report_heading(rp, title);
	const struct res_run *runs[3] = { &r->baseline, &r->custom, &r->closed };
	int n_bars = r->parts_selected && r->closed.ran ? 3 : 2;
	static const char *const bar_labels[3] = { "Baseline", "Custom", "Custom, real parts" };
	const char *stack_labels[N_MASS_ITEMS];
	double v[3 * N_MASS_ITEMS];
	for (int i = 0; i < N_MASS_ITEMS; i++)
		stack_labels[i] = mass_items[i].label;
	for (int k = 0; k < n_bars; k++)
		for (int i = 0; i < N_MASS_ITEMS; i++)
			v[k * N_MASS_ITEMS + i] = mass_get(&runs[k]->mass, i) * rp->mass_scale;

	doc_paragraph(rp->d, report_sfmt(&sb, "Takeoff mass by item; the role overhead is the custom run minus "
	              "the baseline. Percentages are of each run's own takeoff mass (Figure %d).",
	              doc_next_figure_number(rp->d)));
	struct plot *p = plot_alloc(0, 300, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_Y, report_sfmt(&sb, "Mass (%s)", rp->mass_unit));
	plot_legend(pp, PLOT_LEGEND_RIGHT);
	/* About three significant digits on the segment labels. */
	double top = rp->mass_scale * fmax(r->baseline.mass.total_kg, r->custom.mass.total_kg);
	plot_stacked_bars(pp, n_bars, bar_labels, N_MASS_ITEMS, stack_labels, v,
	                  top >= 100.0 ? 0 : top >= 10.0 ? 1 : 2);
	doc_figure(rp->d, p, report_sfmt(&sb, "Mass budget, baseline vs custom run (%s), every mass item stacked; "
	                          "the total is printed above each bar.", rp->mass_unit));
	plot_free(p);

	static const struct doc_column cols[] = {
		{ "Mass item", 2.5, DOC_ALIGN_LEFT },
		{ "Baseline", 1.0, DOC_ALIGN_RIGHT }, { "%", 0.7, DOC_ALIGN_RIGHT },
		{ "Custom", 1.0, DOC_ALIGN_RIGHT }, { "%", 0.7, DOC_ALIGN_RIGHT },
		{ "Overhead", 1.0, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 6);
	const struct res_run *b = &r->baseline, *c = &r->custom;
	for (int i = 0; i < N_MASS_ITEMS; i++) {
		double mb = mass_get(&b->mass, i), mc = mass_get(&c->mass, i), o = mass_get(&r->role_overhead, i);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s (%s)", mass_items[i].label, rp->mass_unit);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", mass_txt(rp, b1, sizeof b1, mb));
		report_cell_num(&t, DOC_CELL_MUTED, 100.0 * report_div(mb, b->mass.total_kg), 1);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", mass_txt(rp, b1, sizeof b1, mc));
		report_cell_num(&t, DOC_CELL_MUTED, 100.0 * report_div(mc, c->mass.total_kg), 1);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", delta_txt(rp, b1, sizeof b1, o));
	}
	doc_table_cell(&t, DOC_CELL_BOLD, "Takeoff mass (%s)", rp->mass_unit);
	doc_table_cell(&t, DOC_CELL_BOLD, "%s", mass_txt(rp, b1, sizeof b1, b->mass.total_kg));
	doc_table_cell(&t, DOC_CELL_BOLD, "100.0");
	doc_table_cell(&t, DOC_CELL_BOLD, "%s", mass_txt(rp, b1, sizeof b1, c->mass.total_kg));
	doc_table_cell(&t, DOC_CELL_BOLD, "100.0");
	doc_table_cell(&t, DOC_CELL_BOLD, "%s", delta_txt(rp, b1, sizeof b1, r->role_overhead.total_kg));
	t.total_row = 1;
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	if (n_bars == 3)
		doc_paragraph(rp->d, report_sfmt(&sb, "With the real catalogue parts the custom design closes at %s kg "
		              "(third bar).", report_num(b1, sizeof b1, r->closed.mass.total_kg, 3)));
	if (c->arm_wall_floor_binds || c->min_fraction_binds)
		doc_paragraph(rp->d, report_sfmt(&sb, "Structure floors that bind in the custom run:%s%s.",
		              c->arm_wall_floor_binds ? " the minimum arm wall thickness" : "",
		              c->min_fraction_binds ? (c->arm_wall_floor_binds ? " and the minimum "
		              "structural mass fraction" : " the minimum structural mass fraction") : ""));
	strbuf_free(&sb);
}

/* ---- 11 bill of materials ------------------------------------------------ */

/* Why there is no parts selection: a parts-stage violation says it best. */
static const char *
no_parts_reason(const struct rep *rp)
{
	const struct solve_result *r = rp->r;
	for (int i = 0; i < r->n_violations; i++)
		if (strcmp(r->violations[i].stage, "parts") == 0)
			return r->violations[i].message;
	if (rp->in->cat == NULL)
		return "No parts catalogue was loaded for this build, so the optimizer did not run.";
	if (!r->custom.ran)
		return "The custom run stopped at the feasibility gate, so there was no sized "
		       "requirement to match parts against.";
	if (r->n_candidates == 0)
		return "The parts search did not score any catalogue motor for this design, so no "
		       "parts were chosen; the dossier shows the continuous optimum only.";
	return "The parts search returned no combination of catalogue motor, propeller, battery and "
	       "ESC that meets the sized requirement; the dossier shows the continuous optimum only.";
}

/* What the continuous design asks a supplier for, item by item: the
 * procurement brief when no catalogue parts were selected. */
static void
sourcing_table(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct res_run *c = &r->custom;
	const struct mission_spec *m = &r->mission;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	int n_rot = m->num_rotors > 0 ? m->num_rotors : 1;
	int n_arms = m->coaxial_layout ? (n_rot + 1) / 2 : n_rot;
	int packs = c->pack_count > 0 ? c->pack_count : 1;
	static const struct doc_column cols[] = {
		{ "Item", 1.1, DOC_ALIGN_LEFT }, { "Qty", 0.45, DOC_ALIGN_RIGHT },
		{ "Specification", 4.2, DOC_ALIGN_LEFT }, { "Each (g)", 0.8, DOC_ALIGN_RIGHT },
		{ "Total (g)", 0.85, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 5);
	struct {
		const char *item;
		int qty;
		double total_kg;
		char *spec;
	} row[7];
	row[0].spec = xstrdup(report_sfmt(&sb, "Brushless outrunner, KV ≈ %s rpm/V, peak %s A / %s W, for %dS",
	                           report_num(b1, sizeof b1, c->opt.motor_kv, 0),
	                           report_num(b2, sizeof b2, c->opt.motor_peak_current_a, 1),
	                           report_num(b3, sizeof b3, c->opt.motor_peak_power_w, 0), c->cell_count));
	row[0].item = "Motor", row[0].qty = n_rot, row[0].total_kg = c->mass.motor_kg;
	/* "auto" is plastic below 12 in, carbon above (spec.h). */
	int pc = m->aerodynamic_overrides.propeller_class;
	const char *material = pc > PROP_AUTO && pc < PROP_CLASS_MAX ? spec_enum_prop[pc]
	                     : c->opt.prop_diameter_in < 12.0 ? "plastic" : "carbon";
	row[1].spec = xstrdup(report_sfmt(&sb, "%s × %s in, %d blades, %s", report_num(b1, sizeof b1, c->opt.prop_diameter_in, 1),
	                           report_num(b2, sizeof b2, c->opt.prop_pitch_in, 1),
	                           m->structural_overrides.num_blades, material));
	row[1].item = "Propeller", row[1].qty = n_rot, row[1].total_kg = c->mass.prop_kg;
	row[2].spec = xstrdup(report_sfmt(&sb, "%dS %s, %s mAh (%s Wh) in total, %s C continuous at full throttle",
	                           c->cell_count, c->chemistry, report_num(b1, sizeof b1, c->capacity_mah, 0),
	                           report_num(b2, sizeof b2, c->energy_wh, 1),
	                           report_num(b3, sizeof b3, c->peak_c_rate, 1)));
	row[2].item = "Battery pack", row[2].qty = packs, row[2].total_kg = c->mass.battery_kg;
	row[3].spec = xstrdup(report_sfmt(&sb, "≥ %s A per channel, %dS", report_num(b1, sizeof b1, c->opt.motor_peak_current_a, 0),
	                           c->cell_count));
	row[3].item = "ESC", row[3].qty = n_rot, row[3].total_kg = c->mass.esc_kg;
	row[4].spec = xstrdup(report_sfmt(&sb, "CFRP tube Ø%s mm × %s mm wall, %s mm long",
	                           report_num(b1, sizeof b1, c->arm_outer_diameter_mm, 1),
	                           report_num(b2, sizeof b2, c->arm_wall_thickness_mm, 2),
	                           report_num(b3, sizeof b3, 1000.0 * c->arm_length_m, 0)));
	row[4].item = "Arm", row[4].qty = n_arms, row[4].total_kg = c->mass.arm_kg;
	row[5].spec = xstrdup(report_sfmt(&sb, "Power harness for %s A peak", report_num(b1, sizeof b1, c->peak_current_a, 0)));
	row[5].item = "Wiring", row[5].qty = 1, row[5].total_kg = c->mass.wiring_kg;
	row[6].spec = xstrdup("Centre plates and spar joints");
	row[6].item = "Frame", row[6].qty = 1, row[6].total_kg = c->mass.frame_kg;
	for (int i = 0; i < 7; i++) {
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", row[i].item);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%d", row[i].qty);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", row[i].spec);
		report_cell_num(&t, DOC_CELL_NORMAL, 1000.0 * row[i].total_kg / row[i].qty, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, 1000.0 * row[i].total_kg, 1);
		free(row[i].spec);
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	strbuf_free(&sb);
}

/* Section 11: the BOM lines with totals.  Without a parts selection it says
 * why, and lists what the sized design asks of suppliers instead. */
static void
sec_bom(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48];
	report_heading(rp, title);
	if (!r->parts_selected) {
		doc_callout(rp->d, DOC_CALLOUT_WARN, "No catalogue parts selected", no_parts_reason(rp));
		report_subheading(rp, "Specification to source (custom run)", REP_KEEP_PT);
		doc_paragraph(rp->d, "What the sized design asks of each supplier; the masses are the sizing "
		              "model's. Order against these, or rebuild with a parts catalogue (--db DIR).");
		sourcing_table(rp);
	}
	if (r->n_bom == 0) {
		strbuf_free(&sb);
		return;
	}
	if (!r->parts_selected)
		report_subheading(rp, "Lines on record", REP_KEEP_PT);
	static const struct doc_column cols[] = {
		{ "#", 0.35, DOC_ALIGN_RIGHT }, { "Qty", 0.5, DOC_ALIGN_RIGHT },
		{ "Category", 0.9, DOC_ALIGN_LEFT }, { "Part", 3.1, DOC_ALIGN_LEFT },
		{ "Unit (g)", 0.8, DOC_ALIGN_RIGHT }, { "Total (g)", 0.85, DOC_ALIGN_RIGHT },
		{ "Unit (USD)", 0.85, DOC_ALIGN_RIGHT }, { "Total (USD)", 0.9, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 8);
	double mass = 0, price = 0;
	int unknown_price = 0;
	int n = r->n_bom < RES_MAX_BOM ? r->n_bom : RES_MAX_BOM;
	for (int i = 0; i < n; i++) {
		const struct res_bom_line *l = &r->bom[i];
		doc_table_cell(&t, DOC_CELL_NORMAL, "%d", l->item);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%d", l->qty);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", l->category);
		strbuf_reset(&sb);
		if (l->manufacturer[0] != '\0')
			strbuf_printf(&sb, "%s ", l->manufacturer);
		strbuf_append_str(&sb, l->part_number);
		if (l->description[0] != '\0')
			strbuf_printf(&sb, "%s%s", sb.len > 0 ? "\n" : "", l->description);
		if (l->catalogue_id[0] != '\0')
			strbuf_printf(&sb, "\ncatalogue id %s", l->catalogue_id);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", strbuf_str(&sb));
		report_cell_num(&t, DOC_CELL_NORMAL, 1000.0 * l->unit_mass_kg, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, 1000.0 * l->total_mass_kg, 1);
		if (l->unit_price_usd > 0) {
			report_cell_num(&t, DOC_CELL_NORMAL, l->unit_price_usd, 2);
			report_cell_num(&t, DOC_CELL_NORMAL, l->total_price_usd, 2);
		} else {
			unknown_price++;
			doc_table_cell(&t, DOC_CELL_MUTED, "unknown");
			doc_table_cell(&t, DOC_CELL_MUTED, "—");
		}
		mass += l->total_mass_kg;
		price += l->total_price_usd;
	}
	const char *tot[8] = { "", "", "", "Total", report_num(b1, sizeof b1, 1000.0 * mass, 1), "", "",
	                       report_num(b2, sizeof b2, price, 2) };
	doc_table_row(&t, tot);
	t.total_row = 1;
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	if (unknown_price > 0)
		doc_paragraph(rp->d, report_sfmt(&sb, "%d line%s no published price (custom parts, or none found); "
		              "the price total covers the priced lines only.", unknown_price,
		              unknown_price == 1 ? " has" : "s have"));
	strbuf_free(&sb);
}

/* ---- 12 checks ----------------------------------------------------------- */

/* One run's checks: value, limit with its direction, margin (warning colour
 * when tight), PASS/FAIL.  With failing_first the failures lead. */
static void
checks_table(struct rep *rp, const struct res_run *run, int failing_first)
{
	static const struct doc_column cols[] = {
		{ "Constraint", 3.2, DOC_ALIGN_LEFT }, { "Value", 1.0, DOC_ALIGN_RIGHT },
		{ "Limit", 1.0, DOC_ALIGN_RIGHT }, { "Margin", 0.85, DOC_ALIGN_RIGHT },
		{ "Result", 0.8, DOC_ALIGN_CENTER },
	};
	char b1[48];
	struct doc_table t;
	doc_table_init(&t, cols, 5);
	for (int pass = 0; pass < 2; pass++) {
		for (int i = 0; i < run->n_checks && i < RES_MAX_CHECKS; i++) {
			const struct res_check *c = &run->checks[i];
			/* Failing checks first when asked, else table order. */
			if (failing_first ? c->pass != (pass == 1) : pass == 1)
				continue;
			const char *unit = c->unit[0] != '\0' ? " " : "";
			doc_table_cell(&t, DOC_CELL_NORMAL, "%s", c->name);
			doc_table_cell(&t, DOC_CELL_NORMAL, "%s%s%s", report_auto(b1, sizeof b1, c->value), unit, c->unit);
			doc_table_cell(&t, DOC_CELL_NORMAL, "%s %s%s%s", c->upper ? "≤" : "≥",
			               report_auto(b1, sizeof b1, c->limit), unit, c->unit);
			enum doc_cell ms = !c->pass ? DOC_CELL_FAIL
			                 : c->margin < REP_TIGHT_MARGIN ? DOC_CELL_WARN : DOC_CELL_NORMAL;
			doc_table_cell(&t, ms, "%s %%", report_num(b1, sizeof b1, 100.0 * c->margin, 1));
			doc_table_cell(&t, c->pass ? DOC_CELL_PASS : DOC_CELL_FAIL, "%s", c->pass ? "PASS" : "FAIL");
		}
	}
	if (t.n_cells > 0)
		doc_table(rp->d, &t);
	else
		doc_paragraph(rp->d, "No checks were evaluated for this run (it stopped at the feasibility gate).");
	doc_table_clear(&t);
}

/* Section 12: the verdict, the violations with fixes (infeasible only),
 * the custom run's checks, then the baseline's for comparison. */
static void
sec_checks(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	struct strbuf sb = STRBUF_INIT;
	report_heading(rp, title);
	if (!r->feasible) {
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "INFEASIBLE",
		            report_sfmt(&sb, "%d constraint%s violated. Each is listed below with the fixes the "
		                 "solver suggests, then every check with its margin.", r->n_violations,
		                 r->n_violations == 1 ? " is" : "s are"));
		report_subheading(rp, "Violations and suggested fixes", REP_KEEP_PT);
		violation_list(rp);
	} else {
		doc_callout(rp->d, DOC_CALLOUT_PASS, "FEASIBLE", "Every constraint of the custom design holds.");
	}
	report_subheading(rp, "Custom run", REP_KEEP_PT);
	doc_paragraph(rp->d, "Value: what the design achieves; limit: what it must stay at or below (≤) or "
	              "reach (≥); margin: the distance to the limit as a fraction of the limit. Margins "
	              "under 5 % are highlighted.");
	checks_table(rp, &r->custom, !r->feasible);
	if (r->parts_selected && r->closed.ran) {
		report_subheading(rp, "Custom run with the real parts", REP_KEEP_PT);
		checks_table(rp, &r->closed, !r->feasible);
	}
	report_subheading(rp, "Baseline run (for comparison)", REP_KEEP_PT);
	checks_table(rp, &r->baseline, 0);
	strbuf_free(&sb);
}

/* ---- 13 appendix --------------------------------------------------------- */

/* The catalogue entries behind the chosen parts, with their published data
 * and source, so the archive shows where each number came from. */
static void
catalogue_used(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct catalog *cat = rp->in->cat;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	/* A part row with its source runs to ~10 lines: keep the heading with it. */
	report_subheading(rp, "Catalogue entries used", r->parts_selected ? 160.0 : 40.0);
	if (!r->parts_selected) {
		doc_paragraph(rp->d, "None: no catalogue parts were selected.");
		strbuf_free(&sb);
		return;
	}
	static const struct doc_column cols[] = {
		{ "Id", 2.1, DOC_ALIGN_LEFT }, { "Part and published data", 3.2, DOC_ALIGN_LEFT },
		{ "Source", 2.7, DOC_ALIGN_LEFT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 3);
	const struct catalog_motor *m = cat != NULL ? catalog_find_motor(cat, r->motor.id) : NULL;
	const struct catalog_prop *p = cat != NULL ? catalog_find_prop(cat, r->prop.id) : NULL;
	const struct catalog_battery *bt = cat != NULL ? catalog_find_battery(cat, r->battery.id) : NULL;
	const struct catalog_esc *e = cat != NULL ? catalog_find_esc(cat, r->esc.id) : NULL;
	const struct res_part *parts[4] = { &r->motor, &r->prop, &r->battery, &r->esc };
	for (int i = 0; i < 4; i++) {
		const struct res_part *rp_ = parts[i];
		if (!rp_->chosen)
			continue;
		const char *src = "", *conf = "";
		strbuf_reset(&sb);
		strbuf_printf(&sb, "%s %s", rp_->manufacturer, rp_->part_number);
		if (i == 0 && m != NULL) {
			strbuf_printf(&sb, "\nKV %s rpm/V, %s g, %s A max", report_num(b1, sizeof b1, m->kv_rpm_per_v, 0),
			              report_num(b2, sizeof b2, 1000.0 * m->mass_kg, 1),
			              report_num(b3, sizeof b3, m->max_current_a, 1));
			src = m->source, conf = m->confidence;
		} else if (i == 1 && p != NULL) {
			strbuf_printf(&sb, "\n%s × %s in, %s g", report_num(b1, sizeof b1, p->diameter_in, 1),
			              report_num(b2, sizeof b2, p->pitch_in, 1),
			              report_num(b3, sizeof b3, 1000.0 * p->mass_kg, 1));
			src = p->source, conf = p->confidence;
		} else if (i == 2 && bt != NULL) {
			strbuf_printf(&sb, "\n%dS %s %s mAh, %s g, %s C", bt->cells_series, bt->chemistry,
			              report_num(b1, sizeof b1, 1000.0 * bt->capacity_ah, 0),
			              report_num(b2, sizeof b2, 1000.0 * bt->mass_kg, 0),
			              report_num(b3, sizeof b3, bt->continuous_c, 0));
			src = bt->source, conf = bt->confidence;
		} else if (i == 3 && e != NULL) {
			strbuf_printf(&sb, "\n%s A continuous, %d channel%s, %s g",
			              report_num(b1, sizeof b1, e->continuous_current_a, 0), e->channels,
			              e->channels == 1 ? "" : "s", report_num(b2, sizeof b2, 1000.0 * e->mass_kg, 1));
			src = e->source, conf = e->confidence;
		}
		doc_table_cell(&t, DOC_CELL_MONO, "%s", rp_->id);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", strbuf_str(&sb));
		if (src[0] != '\0')
			doc_table_cell(&t, DOC_CELL_MUTED, "%s (confidence %s)", src, or_absent(conf));
		else
			doc_table_cell(&t, DOC_CELL_MUTED, "not in the loaded catalogue");
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	strbuf_free(&sb);
}

/* Section 13: every field of the mission contract as this build used it
 * (spec_fields[] order), marking the ones the file left to their default. */
static void
sec_appendix(struct rep *rp, const char *title)
{
	const struct mission_spec *s = &rp->r->mission;
	report_heading(rp, title);
	report_subheading(rp, "Mission, fully defaulted", REP_KEEP_PT);
	doc_paragraph(rp->d, "Every field of the mission contract with the value this build used. Fields "
	              "the mission file did not set are marked \"default\" (the table default, or a value "
	              "derived from the role, airframe class or requirements). The mission file itself "
	              "is attached to this PDF.");
	static const struct doc_column cols[] = {
		{ "Field", 2.4, DOC_ALIGN_LEFT }, { "Value", 1.6, DOC_ALIGN_LEFT },
		{ "Set by", 0.7, DOC_ALIGN_LEFT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 3);
	char val[SPEC_STR_MAX + 32];
	for (int i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		int given = s->given[f->id];
		spec_format_value(s, f, val, sizeof val);
		doc_table_cell(&t, DOC_CELL_MONO, "%s", f->path);
		doc_table_cell(&t, given ? DOC_CELL_BOLD : DOC_CELL_NORMAL, "%s", val);
		doc_table_cell(&t, given ? DOC_CELL_NORMAL : DOC_CELL_MUTED, "%s", given ? "file" : "default");
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	catalogue_used(rp);
}

/* ---- sensitivity (optional, template switch) ----------------------------- */

static void
sec_sensitivity(struct rep *rp, const char *title)
{
	if (rp->in->sensitivity != NULL) {
		rp->in->sensitivity(rp->d, rp->tpl, rp->in->sensitivity_arg);
		return;
	}
	report_heading(rp, title);
	doc_paragraph(rp->d, "The trade study was not run for this dossier; "
	    "`aeroeval sensitivity` produces it.");
}

/* ---- the document -------------------------------------------------------- */

int
report_render(const struct report_input *in, unsigned char **pdf, size_t *n,
              char *err, size_t errlen)
{
	*pdf = NULL;
	*n = 0;
	if (in == NULL || in->r == NULL || in->tpl == NULL) {
		snprintf(err, errlen, "report: no result or no template");
		return -1;
	}
	const struct solve_result *r = in->r;
	const struct mission_spec *m = &r->mission;
	struct rep rp = { .in = in, .r = r, .tpl = in->tpl };
	int small = r->custom.mass.total_kg < REP_GRAM_BELOW_KG &&
	            r->baseline.mass.total_kg < REP_GRAM_BELOW_KG;
	rp.mass_scale = small ? 1000.0 : 1.0;
	rp.mass_unit = small ? "g" : "kg";
	rp.mass_dec = small ? 1 : 3;

	char title[SPEC_STR_MAX + 32];
	snprintf(title, sizeof title, "%s", m->report.title[0] != '\0' ? m->report.title : "Design dossier");
	struct doc_info info = {
		.title = title,
		.mission = in->mission_name != NULL ? in->mission_name : m->name,
		.author = m->report.author[0] != '\0' ? m->report.author : NULL,
		.subject = m->report.client[0] != '\0' ? m->report.client : "Multirotor UAV sizing",
		.date = in->date != NULL && in->date[0] != '\0' ? in->date : NULL,
	};
	rp.d = doc_alloc(in->tpl, &info);

	int first = 1;
	for (int i = 0; i < in->tpl->n_sections; i++) {
		const struct template_section *s = &in->tpl->sections[i];
		if (!s->enabled)
			continue;
		switch (s->id) {
		case TEMPLATE_SEC_COVER: sec_cover(&rp, first); break;
		case TEMPLATE_SEC_SUMMARY: sec_summary(&rp, s->title); break;
		case TEMPLATE_SEC_RATIONALE: sec_rationale(&rp, s->title); break;
		case TEMPLATE_SEC_MASS: sec_mass(&rp, s->title); break;
		case TEMPLATE_SEC_MISSION: report_sec_mission(&rp, s->title); break;
		case TEMPLATE_SEC_THERMAL: report_sec_thermal(&rp, s->title); break;
		case TEMPLATE_SEC_STRUCTURE: report_sec_structure(&rp, s->title); break;
		case TEMPLATE_SEC_PROPULSION: report_sec_propulsion(&rp, s->title); break;
		case TEMPLATE_SEC_CONVERGENCE: report_sec_convergence(&rp, s->title); break;
		case TEMPLATE_SEC_ENDURANCE: report_sec_endurance(&rp, s->title); break;
		case TEMPLATE_SEC_BOM: sec_bom(&rp, s->title); break;
		case TEMPLATE_SEC_CHECKS: sec_checks(&rp, s->title); break;
		case TEMPLATE_SEC_APPENDIX: sec_appendix(&rp, s->title); break;
		case TEMPLATE_SEC_SENSITIVITY: sec_sensitivity(&rp, s->title); break;
		case TEMPLATE_SEC_MAX: break;
		}
		first = 0;
	}
	if (in->mission_bytes != NULL && in->mission_file_name != NULL)
		doc_attach(rp.d, in->mission_file_name, in->mission_bytes, in->mission_len);
	int rc = doc_save_mem(rp.d, pdf, n);
	if (rc != 0)
		snprintf(err, errlen, "dossier: %s", doc_error(rp.d) != NULL ? doc_error(rp.d) : "cannot render");
	doc_free(rp.d);
	return rc == 0 ? 0 : -1;
}
