/* report_tables.c — the dossier's table sections: the mass budget, the
 * bill of materials, the checks and the appendix (the whole defaulted
 * mission and the catalogue entries used).
 *
 * What a client reads here is what a procurement team orders from and an
 * archive files: makers, part numbers, the makers' pages and the dates of
 * the prices.  The catalogue's provenance notes (how a number was found,
 * how sure its curator is) stay in the catalogue.
 */
#include "pdf/report_tables.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "catalog/catalog.h"
#include "pdf/doc.h"
#include "pdf/plot.h"
#include "formats/bom_csv.h"
#include "pdf/report_util.h"
#include "util/strbuf.h"
#include "util/xalloc.h"

/* ---- mass budget ------------------------------------------------------------ */

/* Section: stacked bars of every mass item (baseline, continuous optimum,
 * design of record) and the same numbers as a table with each item's
 * share of its design's takeoff mass. */
void
report_sec_mass(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *rec = rp->rec, *b = &r->baseline, *c = &r->custom;
	struct strbuf sb = STRBUF_INIT;
	char b1[48];
	int n_it = report_n_mass_items;
	report_heading(rp, title);
	const struct res_run *runs[3] = { b, c, rec };
	int n_bars = rp->buildable ? 3 : 2;
	const char *const bar_labels[3] = { REP_NAME_BASELINE, report_continuous_name(rp), REP_NAME_RECORD };
	const char *stack_labels[16];
	double v[3 * 16];
	for (int i = 0; i < n_it; i++)
		stack_labels[i] = report_mass_items[i].label;
	for (int k = 0; k < n_bars; k++)
		for (int i = 0; i < n_it; i++)
			v[k * n_it + i] = report_mass_get(&runs[k]->mass, i) * rp->mass_scale;

	doc_paragraph(rp->d, report_sfmt(&sb, "Takeoff mass by item (Figure %d): the design of record beside "
	              "the continuous optimum (what the physics asks for) and the baseline (the same mission "
	              "without the role's equipment, its payload carried as dead weight). Percentages are "
	              "of each design's own takeoff mass.",
	              doc_next_figure_number(rp->d)));
	struct plot *p = plot_alloc(0, 300, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_Y, report_sfmt(&sb, "Mass (%s)", rp->mass_unit));
	plot_legend(pp, PLOT_LEGEND_RIGHT);
	double top = 0.0;
	for (int k = 0; k < n_bars; k++)
		top = fmax(top, rp->mass_scale * runs[k]->mass.total_kg);
	plot_stacked_bars(pp, n_bars, bar_labels, n_it, stack_labels, v,
	                  top >= 100.0 ? 0 : top >= 10.0 ? 1 : 2);
	doc_figure(rp->d, p, report_sfmt(&sb, "Mass budget (%s), every mass item stacked; the total is "
	           "printed above each bar.", rp->mass_unit));
	plot_free(p);

	struct doc_column cols[7] = {
		{ "Mass item", 2.3, DOC_ALIGN_LEFT },
		{ report_record_name(rp), 1.1, DOC_ALIGN_RIGHT }, { "%", 0.6, DOC_ALIGN_RIGHT },
		{ report_continuous_name(rp), 1.1, DOC_ALIGN_RIGHT }, { "%", 0.6, DOC_ALIGN_RIGHT },
		{ REP_NAME_BASELINE, 1.0, DOC_ALIGN_RIGHT }, { "%", 0.6, DOC_ALIGN_RIGHT },
	};
	const struct res_run *shown[3] = { rec, c, b };
	int n_shown = 3;
	if (!rp->buildable) {   /* the record is the continuous design */
		shown[1] = b;
		cols[3] = cols[5];
		n_shown = 2;
	}
	struct doc_table t;
	doc_table_init(&t, cols, 1 + 2 * n_shown);
	for (int i = 0; i <= n_it; i++) {
		int total = i == n_it;
		doc_table_cell(&t, total ? DOC_CELL_BOLD : DOC_CELL_NORMAL, "%s (%s)",
		               total ? "Takeoff mass" : report_mass_items[i].label, rp->mass_unit);
		for (int k = 0; k < n_shown; k++) {
			double mk = total ? shown[k]->mass.total_kg : report_mass_get(&shown[k]->mass, i);
			doc_table_cell(&t, k == 0 || total ? DOC_CELL_BOLD : DOC_CELL_NORMAL, "%s",
			               report_mass(rp, b1, sizeof b1, mk));
			report_cell_num(&t, DOC_CELL_MUTED, 100.0 * report_div(mk, shown[k]->mass.total_kg), 1);
		}
	}
	t.total_row = 1;
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	if (rp->buildable)
		doc_paragraph(rp->d, report_sfmt(&sb, "Everything but the payload is the bill of materials "
		              "(%s" NBSP "%s); the payload is furnished by the customer.",
		              report_mass(rp, b1, sizeof b1, r->bom_mass_kg), rp->mass_unit));
	if (rec->arm_wall_floor_binds || rec->min_fraction_binds)
		doc_paragraph(rp->d, report_sfmt(&sb, "Structure floors that bind in the %s:%s%s.",
		              rp->buildable ? "design of record" : "continuous design",
		              rec->arm_wall_floor_binds ? " the minimum arm wall thickness" : "",
		              rec->min_fraction_binds ? (rec->arm_wall_floor_binds ? " and the minimum "
		              "structural mass fraction" : " the minimum structural mass fraction") : ""));
	strbuf_free(&sb);
}

/* ---- bill of materials ------------------------------------------------------ */

/* What the continuous design asks a supplier for, item by item: the
 * procurement brief when no catalogue parts close the design. */
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
	/* "auto" is plastic below 12 in, carbon above (spec.h). */
	int pc = m->aerodynamic_overrides.propeller_class;
	const char *material = pc > PROP_AUTO && pc < PROP_CLASS_MAX ? spec_enum_prop[pc]
	                     : c->opt.prop_diameter_in < 12.0 ? "plastic" : "carbon";
	struct {
		const char *item;
		int qty;
		double total_kg;
		char *spec;
	} row[7] = {
		{ "Motor", n_rot, c->mass.motor_kg, xstrdup(report_sfmt(&sb, "Brushless outrunner, KV ≈ %s" NBSP
		  "rpm/V, peak %s" NBSP "A / %s" NBSP "W, for %dS", report_num(b1, sizeof b1, c->opt.motor_kv, 0),
		  report_num(b2, sizeof b2, c->opt.motor_peak_current_a, 1),
		  report_num(b3, sizeof b3, c->opt.motor_peak_power_w, 0), c->cell_count)) },
		{ "Propeller", n_rot, c->mass.prop_kg, xstrdup(report_sfmt(&sb, "%s" NBSP "×" NBSP "%s" NBSP "in, "
		  "%d blades, %s", report_num(b1, sizeof b1, c->opt.prop_diameter_in, 1),
		  report_num(b2, sizeof b2, c->opt.prop_pitch_in, 1), m->structural_overrides.num_blades,
		  material)) },
		{ "Battery pack", packs, c->mass.battery_kg, xstrdup(report_sfmt(&sb, "%dS %s, %s" NBSP "mAh "
		  "(%s" NBSP "Wh) in total, %s" NBSP "C continuous at full throttle", c->cell_count, report_chemistry(c->chemistry),
		  report_num(b1, sizeof b1, c->capacity_mah, 0), report_num(b2, sizeof b2, c->energy_wh, 1),
		  report_num(b3, sizeof b3, c->peak_c_rate, 1))) },
		{ "ESC", n_rot, c->mass.esc_kg, xstrdup(report_sfmt(&sb, "≥" NBSP "%s" NBSP "A per channel, %dS",
		  report_num(b1, sizeof b1, c->opt.motor_peak_current_a, 0), c->cell_count)) },
		{ "Arm", n_arms, c->mass.arm_kg, xstrdup(report_sfmt(&sb, "CFRP tube Ø%s" NBSP "mm × %s" NBSP "mm "
		  "wall, %s" NBSP "mm long", report_num(b1, sizeof b1, c->arm_outer_diameter_mm, 1),
		  report_num(b2, sizeof b2, c->arm_wall_thickness_mm, 2),
		  report_num(b3, sizeof b3, 1000.0 * c->arm_length_m, 0))) },
		{ "Wiring", 1, c->mass.wiring_kg, xstrdup(report_sfmt(&sb, "Power harness for %s" NBSP "A peak",
		  report_num(b1, sizeof b1, c->peak_current_a, 0))) },
		{ "Frame", 1, c->mass.frame_kg, xstrdup("Centre plates and spar joints") },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 5);
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

/* The parts lines (the payload aside) with mass and price totals, then
 * the payload and the takeoff mass of record. */
static void
bom_table(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48];
	static const struct doc_column cols[] = {
		{ "#", 0.3, DOC_ALIGN_RIGHT }, { "Qty", 0.4, DOC_ALIGN_RIGHT },
		{ "Part, maker's page and price date", 4.6, DOC_ALIGN_LEFT },
		{ "Each (g)", 0.7, DOC_ALIGN_RIGHT }, { "Total (g)", 0.75, DOC_ALIGN_RIGHT },
		{ "Each (USD)", 0.75, DOC_ALIGN_RIGHT }, { "Total (USD)", 0.85, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 7);
	double mass = 0, price = 0, payload = 0;
	int n = r->n_bom < RES_MAX_BOM ? r->n_bom : RES_MAX_BOM;
	for (int i = 0; i < n; i++) {
		const struct res_bom_line *l = &r->bom[i];
		if (strcmp(l->category, "payload") == 0) {
			payload += l->total_mass_kg;
			continue;
		}
		doc_table_cell(&t, DOC_CELL_NORMAL, "%d", l->item);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%d", l->qty);
		strbuf_reset(&sb);
		if (strcmp(l->category, "custom") == 0)
			strbuf_printf(&sb, "%s (custom part)", l->part_number);
		else
			strbuf_printf(&sb, "%s %s (%s)", l->manufacturer, bom_csv_part_number(r, l),
			              l->category);
		if (l->description[0] != '\0')
			strbuf_printf(&sb, "\n%s", l->description);
		if (l->source_url[0] != '\0')
			strbuf_printf(&sb, "\n%s", l->source_url);
		if (l->unit_price_usd > 0)
			strbuf_printf(&sb, "\nprice: store snapshot of %s",
			              l->price_date[0] != '\0' ? l->price_date : "unknown date");
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", strbuf_str(&sb));
		report_cell_num(&t, DOC_CELL_NORMAL, 1000.0 * l->unit_mass_kg, 1);
		report_cell_num(&t, DOC_CELL_NORMAL, 1000.0 * l->total_mass_kg, 1);
		if (l->unit_price_usd > 0) {
			report_cell_num(&t, DOC_CELL_NORMAL, l->unit_price_usd, 2);
			report_cell_num(&t, DOC_CELL_NORMAL, l->total_price_usd, 2);
			price += l->total_price_usd;
		} else {
			doc_table_cell(&t, DOC_CELL_MUTED, "—");
			doc_table_cell(&t, DOC_CELL_MUTED, "—");
		}
		mass += l->total_mass_kg;
	}
	int priced = r->bom_priced_lines, lines = r->bom_parts_lines;
	const char *tot[7] = { "", "", "Bill of materials (parts)", report_num(b1, sizeof b1, 1000.0 * mass, 1),
	                       "", "", priced <= 0 ? "—" : report_sfmt(&sb, "%s%s", priced < lines ? "≥" NBSP : "",
	                                                               report_num(b2, sizeof b2, price, 2)) };
	doc_table_row(&t, tot);
	t.total_row = 1;
	doc_table(rp->d, &t);
	doc_table_clear(&t);

	char *v[4];
	v[0] = xstrdup(report_sfmt(&sb, "%s" NBSP "g", report_num(b1, sizeof b1, 1000.0 * mass, 1)));
	v[1] = xstrdup(report_sfmt(&sb, "%s" NBSP "g, furnished by the customer (not in the bill of "
	                           "materials)", report_num(b1, sizeof b1, 1000.0 * payload, 1)));
	v[2] = xstrdup(report_sfmt(&sb, "%s" NBSP "g = %s" NBSP "kg", report_num(b1, sizeof b1,
	                           1000.0 * (mass + payload), 1), report_num(b2, sizeof b2, mass + payload, 3)));
	v[3] = xstrdup(report_price(rp, &sb));
	const char *kv[] = { "Parts", v[0], "Payload", v[1], "Takeoff mass of record", v[2], "Price", v[3] };
	report_kv(rp, kv, 4, -1);
	for (int i = 0; i < 4; i++)
		free(v[i]);
	if (priced < lines)
		doc_paragraph(rp->d, "—: no published price (custom parts, or none found). The price is a "
		              "lower bound: it sums the priced lines only. Prices are store snapshots of the "
		              "date given, not quotations.");
	strbuf_free(&sb);
}

/* Section: the BOM lines with totals.  Without a parts selection it says
 * why, and lists what the continuous design asks of suppliers instead
 * (when its loop converged). */
void
report_sec_bom(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	report_heading(rp, title);
	if (!rp->buildable && !r->custom.converged) {
		/* A loop that did not converge specifies nothing to source. */
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "NOT BUILDABLE", report_no_parts_reason(rp));
		doc_paragraph(rp->d, "There is no specification to source: the figures of the loop's last "
		              "iterate are not a design. Relax the mission (see the checks section's fixes) "
		              "and compile it again.");
		return;
	}
	if (!rp->buildable) {
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "NOT BUILDABLE", report_no_parts_reason(rp));
		report_subheading(rp, "Specification to source (continuous design)", REP_KEEP_PT);
		doc_paragraph(rp->d, "What the continuous design asks of each supplier; the masses are the sizing "
		              "model's. Order against these, or rebuild with a parts catalogue (--db DIR).");
		sourcing_table(rp);
		if (r->n_bom == 0)
			return;
		report_subheading(rp, "Lines on record", REP_KEEP_PT);
	} else if (!rp->rec_ok) {
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "NOT FEASIBLE AS BUILT", "These parts build the design of "
		            "record, which fails a check: do not order against this list before the checks "
		            "section's failures are resolved.");
	}
	if (r->n_bom > 0)
		bom_table(rp);
}

/* ---- checks ------------------------------------------------------------------ */

/* One design's checks: value, limit with its direction, margin (warning
 * colour when tight), PASS/FAIL.  With failing_first the failures lead. */
static void
checks_table(struct rep *rp, const struct res_run *run, int failing_first)
{
	static const struct doc_column cols[] = {
		{ "Check", 2.7, DOC_ALIGN_LEFT }, { "Condition", 1.25, DOC_ALIGN_LEFT },
		{ "Value", 0.9, DOC_ALIGN_RIGHT }, { "Limit", 0.95, DOC_ALIGN_RIGHT },
		{ "Margin", 0.75, DOC_ALIGN_RIGHT }, { "Result", 0.65, DOC_ALIGN_CENTER },
	};
	char b1[48];
	struct doc_table t;
	doc_table_init(&t, cols, 6);
	for (int pass = 0; pass < 2; pass++) {
		for (int i = 0; i < run->n_checks && i < RES_MAX_CHECKS; i++) {
			const struct res_check *c = &run->checks[i];
			/* Failing checks first when asked, else table order. */
			if (failing_first ? c->pass != (pass == 1) : pass == 1)
				continue;
			const char *unit = c->unit[0] != '\0' ? NBSP : "";
			if (c->basis[0] != '\0')
				doc_table_cell(&t, DOC_CELL_NORMAL, "%s (%s)", c->name, c->basis);
			else
				doc_table_cell(&t, DOC_CELL_NORMAL, "%s", c->name);
			doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_or_absent(c->condition));
			doc_table_cell(&t, DOC_CELL_NORMAL, "%s%s%s", report_auto(b1, sizeof b1, c->value), unit, c->unit);
			doc_table_cell(&t, DOC_CELL_NORMAL, "%s" NBSP "%s%s%s", c->upper ? "≤" : "≥",
			               report_auto(b1, sizeof b1, c->limit), unit, c->unit);
			/* A limit the design is sized to holds by construction:
			 * its zero margin is no warning. */
			enum doc_cell ms = !c->pass ? DOC_CELL_FAIL
			                 : c->sized ? DOC_CELL_MUTED
			                 : c->margin < REP_TIGHT_MARGIN ? DOC_CELL_WARN : DOC_CELL_NORMAL;
			/* "Sized to it" only where the design sits at the limit (a
			 * reserve sized for energy is not at it when power sized the
			 * pack); a margin against a zero limit is no fraction of it. */
			if (c->sized && c->pass && c->margin < REP_TIGHT_MARGIN)
				doc_table_cell(&t, DOC_CELL_MUTED, "sized to it");
			else if (c->limit == 0.0)
				doc_table_cell(&t, ms == DOC_CELL_MUTED ? DOC_CELL_NORMAL : ms, "—");
			else
				doc_table_cell(&t, ms == DOC_CELL_MUTED ? DOC_CELL_NORMAL : ms, "%s",
				               report_margin(b1, sizeof b1, c->margin));
			doc_table_cell(&t, c->pass ? DOC_CELL_PASS : DOC_CELL_FAIL, "%s", c->pass ? "PASS" : "FAIL");
		}
	}
	if (t.n_cells > 0)
		doc_table(rp->d, &t);
	else
		doc_paragraph(rp->d, "No checks were evaluated for this design (it stopped at the feasibility gate).");
	doc_table_clear(&t);
}

/* Section: the verdict on the design of record, the violations with fixes,
 * the record's checks, then those of the two references. */
void
report_sec_checks(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	struct strbuf sb = STRBUF_INIT;
	report_heading(rp, title);
	if (!rp->buildable)
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "NOT BUILDABLE", "No catalogue parts close the design; "
		            "the checks below are those of the continuous design.");
	else if (!rp->rec_ok)
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "NOT FEASIBLE AS BUILT", "The design of record fails the "
		            "checks marked FAIL; each violation is listed with the fixes the solver suggests.");
	else
		doc_callout(rp->d, DOC_CALLOUT_PASS, "FEASIBLE", r->feasible
		            ? "Every constraint of the design of record holds."
		            : "Every constraint of the design of record holds; a reference design fails one "
		              "(listed below).");
	if (r->n_violations > 0) {
		report_subheading(rp, "Violations and suggested fixes", REP_KEEP_PT);
		report_violations(rp);
	}
	report_subheading(rp, report_sfmt(&sb, "%s%s", report_record_name(rp),
	                  rp->buildable ? " (real parts)" : ""), REP_KEEP_PT);
	doc_paragraph(rp->d, "Value: what the design achieves; limit: what it must stay at or below (≤) or "
	              "reach (≥); margin: the distance to the limit as a fraction of the limit. Margins "
	              "under 5 % are highlighted; \"sized to it\": the design is sized to that limit, so "
	              "it holds by construction. Only the limits that apply to this role are checked.");
	checks_table(rp, rp->rec, 1);
	if (rp->buildable) {
		report_subheading(rp, report_continuous_heading(rp, &sb, "reference: what the physics asks for"),
		                  REP_KEEP_PT);
		checks_table(rp, &r->custom, 1);
	}
	report_subheading(rp, REP_BASELINE_HEADING, REP_KEEP_PT);
	checks_table(rp, &r->baseline, 0);
	strbuf_free(&sb);
}

/* ---- appendix ---------------------------------------------------------------- */

/* A field's unit as printed ("degC" -> "°C", "m2" -> "m²"). */
static void
unit_text(const char *unit, char *buf, size_t n)
{
	if (strcmp(unit, "degC") == 0)
		snprintf(buf, n, "°C");
	else if (strncmp(unit, "m2", 2) == 0)
		snprintf(buf, n, "m²%.40s", unit + 2);
	else
		snprintf(buf, n, "%.40s", unit);
}

/* The value of one mission field as the appendix prints it: the field
 * table's own text (spec_format_value), except that a field whose zero
 * means "choose automatically" (SPEC_F_ZERO_AUTO in the table) prints
 * "auto" at zero, an empty string "not set", and the unit stays with its
 * number in its printed form ("4 cells", "1 pack", "5.25 °C"). */
static void
field_text(const struct mission_spec *s, const struct spec_field_info *f, char *buf, size_t n)
{
	const void *p = spec_member_const(s, f);
	int num = f->type == SPEC_NUM || f->type == SPEC_INT || f->type == SPEC_SPEED;
	double v = f->type == SPEC_INT ? *(const int *)p : num ? *(const double *)p : NAN;
	if (f->type == SPEC_SPEED && s->v_forward_auto) {
		snprintf(buf, n, "auto (minimum-power speed)");
		return;
	}
	if (num && v == 0.0 && (f->flags & SPEC_F_ZERO_AUTO)) {
		snprintf(buf, n, "auto");
		return;
	}
	if ((f->type == SPEC_STR || f->type == SPEC_DATE) && ((const char *)p)[0] == '\0') {
		snprintf(buf, n, "not set");
		return;
	}
	spec_format_value(s, f, buf, n);
	size_t ul = strlen(f->unit), bl = strlen(buf);
	if (!num || ul == 0 || bl <= ul + 1 || strcmp(buf + bl - ul, f->unit) != 0 || buf[bl - ul - 1] != ' ')
		return;
	char unit[48];
	unit_text(f->unit, unit, sizeof unit);
	/* The units of counts are plurals: "1 pack", "4 cells". */
	size_t pl = strlen(unit);
	if (v == 1.0 && pl > 1 && unit[pl - 1] == 's')
		unit[pl - 1] = '\0';
	buf[bl - ul - 1] = '\0';
	size_t at = strlen(buf);
	snprintf(buf + at, n - at, NBSP "%s", unit);
}

/* Published data of one chosen part, from the loaded catalogue. */
static void
part_data(struct strbuf *sb, const struct catalog *cat, const struct res_part *part, int kind)
{
	char b1[48], b2[48], b3[48];
	strbuf_reset(sb);
	strbuf_printf(sb, "%s %s", part->manufacturer, part->part_number);
	if (cat == NULL)
		return;
	if (kind == 0) {
		const struct catalog_motor *m = catalog_find_motor(cat, part->id);
		if (m != NULL)
			strbuf_printf(sb, "\nKV" NBSP "%s" NBSP "rpm/V, %s" NBSP "g, %s" NBSP "A max",
			              report_num(b1, sizeof b1, m->kv_rpm_per_v, 0),
			              report_num(b2, sizeof b2, 1000.0 * m->mass_kg, 1),
			              report_num(b3, sizeof b3, m->max_current_a, 1));
	} else if (kind == 1) {
		const struct catalog_prop *p = catalog_find_prop(cat, part->id);
		if (p != NULL)
			strbuf_printf(sb, "\n%s" NBSP "×" NBSP "%s" NBSP "in, %s" NBSP "g",
			              report_num(b1, sizeof b1, p->diameter_in, 1), report_num(b2, sizeof b2, p->pitch_in, 1),
			              report_num(b3, sizeof b3, 1000.0 * p->mass_kg, 1));
	} else if (kind == 2) {
		const struct catalog_battery *bt = catalog_find_battery(cat, part->id);
		if (bt != NULL)
			strbuf_printf(sb, "\n%dS %s %s" NBSP "mAh, %s" NBSP "g, %s" NBSP "C", bt->cells_series,
			              report_chemistry(bt->chemistry), report_num(b1, sizeof b1, 1000.0 * bt->capacity_ah, 0),
			              report_num(b2, sizeof b2, 1000.0 * bt->mass_kg, 0),
			              report_num(b3, sizeof b3, bt->continuous_c, 0));
	} else {
		const struct catalog_esc *e = catalog_find_esc(cat, part->id);
		if (e != NULL)
			strbuf_printf(sb, "\n%s" NBSP "A continuous, %d channel%s, %s" NBSP "g",
			              report_num(b1, sizeof b1, e->continuous_current_a, 0), e->channels,
			              e->channels == 1 ? "" : "s", report_num(b2, sizeof b2, 1000.0 * e->mass_kg, 1));
	}
}

/* The catalogue entries behind the chosen parts: their published data,
 * the maker's page and the date of the price. */
static void
catalogue_used(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	struct strbuf sb = STRBUF_INIT, src = STRBUF_INIT;
	char b1[48];
	report_subheading(rp, "Catalogue entries used", r->parts_selected ? 120.0 : 40.0);
	if (!r->parts_selected) {
		doc_paragraph(rp->d, "None: no catalogue parts were selected.");
		strbuf_free(&sb);
		strbuf_free(&src);
		return;
	}
	static const struct doc_column cols[] = {
		{ "Catalogue id", 1.7, DOC_ALIGN_LEFT }, { "Part and published data", 3.0, DOC_ALIGN_LEFT },
		{ "Maker's page and price", 3.0, DOC_ALIGN_LEFT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 3);
	const struct res_part *parts[4] = { &r->motor, &r->prop, &r->battery, &r->esc };
	for (int i = 0; i < 4; i++) {
		const struct res_part *part = parts[i];
		if (!part->chosen)
			continue;
		part_data(&sb, rp->in->cat, part, i);
		strbuf_reset(&src);
		strbuf_append_str(&src, part->source_url[0] != '\0' ? part->source_url : "no maker's page on record");
		if (part->unit_price_usd > 0)
			strbuf_printf(&src, "\n%s" NBSP "USD, price of %s", report_num(b1, sizeof b1, part->unit_price_usd, 2),
			              part->price_date[0] != '\0' ? part->price_date : "an undated snapshot");
		else
			strbuf_append_str(&src, "\nno published price");
		doc_table_cell(&t, DOC_CELL_MONO, "%s", part->id);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", strbuf_str(&sb));
		doc_table_cell(&t, DOC_CELL_MUTED, "%s", strbuf_str(&src));
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	strbuf_free(&sb);
	strbuf_free(&src);
}

/* The solver's own vocabulary, kept here: the method and its figures for
 * whoever checks the computation (the pages before say the same in an
 * engineer's terms: sizing passes, mass growth, mission flown). */
static void
solver_row(struct doc_table *t, const char *name, const struct res_run *run)
{
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", name);
	if (!run->ran) {
		for (int k = 0; k < 4; k++)
			doc_table_cell(t, DOC_CELL_MUTED, "—");
	} else {
		doc_table_cell(t, DOC_CELL_NORMAL, "%d", run->iterations);
		doc_table_cell(t, DOC_CELL_NORMAL, "%s", run->converged ? "yes" : "no");
		report_cell_num(t, DOC_CELL_NORMAL, run->converged ? run->lipschitz : NAN, 3);
		report_cell_num(t, DOC_CELL_NORMAL, run->time_scale, 2);
	}
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", run->termination[0] != '\0' ? run->termination : "—");
}

static void
solver_details(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	report_subheading(rp, "Appendix: solver details", REP_KEEP_PT);
	doc_paragraph(rp->d, "The sizing implements the physics-based model of the aeroeval paper "
	              "(Multi-Domain Physics-Based MDO of Multirotor UAVs): ISA atmosphere, a three-phase "
	              "mission, Glauert rotor aerodynamics with a Reynolds-scaled figure of merit, CFRP arm "
	              "sizing, a Tremblay–Dessaint battery with transient heating, and a Banach fixed-point "
	              "iteration on the takeoff mass with under-relaxation, a ratchet and a divergence guard. "
	              "The baseline is the paper's dead-weight run (no role, hover throttle 60 %), beside "
	              "the custom run of the mission's role (the paper's dual run). Goal relaxation scales "
	              "every phase by γ when the mission allows a shorter flight. The parts search then "
	              "closes each candidate combination of catalogue parts on its own masses (a fixed "
	              "point of its own) and keeps the lowest J.");
	static const struct doc_column cols[] = {
		{ "Run", 1.6, DOC_ALIGN_LEFT }, { "Iterations", 0.9, DOC_ALIGN_RIGHT },
		{ "Converged", 0.9, DOC_ALIGN_CENTER }, { "Lipschitz dF/dM", 1.1, DOC_ALIGN_RIGHT },
		{ "Goal γ", 0.7, DOC_ALIGN_RIGHT }, { "Termination", 2.4, DOC_ALIGN_LEFT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 6);
	solver_row(&t, "Baseline (dead-weight run)", &r->baseline);
	solver_row(&t, report_continuous_name(rp), &r->custom);
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	doc_paragraph(rp->d, "Lipschitz dF/dM: the loop's gain at its fixed point, the mass growth of "
	              "the convergence section; below 1 the iteration is a contraction. Goal γ: the factor "
	              "the mission times were scaled by (1 = as requested). A run that did not converge has "
	              "no fixed point, so no estimate.");
}

/* Section: every field of the mission contract as this build used it
 * (spec_fields[] order), marking where each value came from. */
void
report_sec_appendix(struct rep *rp, const char *title)
{
	const struct mission_spec *s = &rp->r->mission;
	report_heading(rp, title);
	report_subheading(rp, "Mission, fully defaulted", REP_KEEP_PT);
	doc_paragraph(rp->d, "Every field of the mission contract with the value this build used. \"file\": "
	              "set by the mission file; \"derived\": not set, derived from the role, the airframe "
	              "class or the requirements; \"default\": not set, the contract's default. \"auto\": the "
	              "solver chooses (the field's zero means so). The mission file itself is attached to "
	              "this PDF.");
	static const struct doc_column cols[] = {
		{ "Field", 2.4, DOC_ALIGN_LEFT }, { "Value", 1.6, DOC_ALIGN_LEFT },
		{ "Set by", 0.7, DOC_ALIGN_LEFT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 3);
	char val[SPEC_STR_MAX + 64];
	for (int i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		int given = s->given[f->id];
		field_text(s, f, val, sizeof val);
		/* The role's auxiliary power is given for its reference aircraft
		 * and scales with the aircraft's mass: the value flown stands
		 * beside it, the one every other page prints (res_figures()). */
		if (f->id == SPECF_ROLE_AUX_POWER_W && fabs(rp->fig.aux_power_w - s->payload_role.aux_power_w) >= 0.5) {
			char flown[48];
			size_t at = strlen(val);
			snprintf(val + at, sizeof val - at, " as set; %s" NBSP "W flown (scaled with this "
			         "aircraft's mass)", report_num(flown, sizeof flown, rp->fig.aux_power_w, 0));
		}
		doc_table_cell(&t, DOC_CELL_MONO, "%s", f->path);
		doc_table_cell(&t, given ? DOC_CELL_BOLD : DOC_CELL_NORMAL, "%s", val);
		doc_table_cell(&t, given ? DOC_CELL_NORMAL : DOC_CELL_MUTED, "%s",
		               given ? "file" : (f->flags & SPEC_F_DERIVED) ? "derived" : "default");
	}
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	catalogue_used(rp);
	solver_details(rp);
}
