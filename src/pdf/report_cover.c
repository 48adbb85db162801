/* report_cover.c — the dossier's opening: the cover a client signs, the
 * document control and contents page, the executive summary and the
 * design rationale.  All of them describe the design of record; the
 * continuous optimum and the baseline stand beside it as references.
 */
#include "pdf/report_cover.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pdf/doc.h"
#include "pdf/report_util.h"
#include "util/strbuf.h"
#include "util/xalloc.h"

#define REP_KG_PER_LB 0.45359237

static double
minutes(double s)
{
	return s / 60.0;
}

/* A run's hover endurance: the record's is the one of its figures
 * (res_figures()); a run that did not size (a runaway) has none. */
static double
hover_endurance_s(const struct rep *rp, const struct res_run *run)
{
	if (run == rp->rec)
		return rp->fig.hover_endurance_s;
	return run->converged && run->hover_endurance_s > 0.0 ? run->hover_endurance_s : NAN;
}

/* A figure of a reference run that only means something when its mass
 * loop settled: NAN (printed "—") for a runaway's last iterate. */
static double
settled(const struct res_run *run, double x)
{
	return run->ran && run->converged ? x : NAN;
}

/* "6S2P LiPo, 8000 mAh" */
static const char *
battery_text(struct strbuf *sb, const struct res_run *run)
{
	char b[48];
	strbuf_reset(sb);
	strbuf_printf(sb, "%dS", run->cell_count);
	if (run->pack_count > 1)
		strbuf_printf(sb, "%dP", run->pack_count);
	strbuf_printf(sb, " %s, %s" NBSP "mAh", report_chemistry(run->chemistry), report_num(b, sizeof b, run->capacity_mah, 0));
	return strbuf_str(sb);
}

/* The EU class and the US Part 107 limit in one line, for the cover. */
static const char *
class_text(struct strbuf *sb, double kg)
{
	const char *eu = res_eu_class(kg);
	int specific = strcmp(eu, "specific") == 0;
	return report_sfmt(sb, "EU" NBSP "%s, US" NBSP "%s", specific ? "specific category" : eu,
	                   kg < RES_US_107_KG ? "Part" NBSP "107" : "above Part" NBSP "107");
}

/* ---- cover ------------------------------------------------------------------ */

/* The status callout.  A design whose parts do not close, or whose parts
 * close but fail a check, says so before anything else. */
static void
cover_status(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct res_run *rec = rp->rec;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48], b4[48];
	int n_fail = 0;
	for (int i = 0; i < rec->n_checks && i < RES_MAX_CHECKS; i++)
		n_fail += !rec->checks[i].pass;
	const struct res_ceiling *cl = &r->ceiling;
	if (cl->valid) {
		report_sfmt(&sb, "This mission is beyond what a %d-rotor aircraft on a %s" NBSP "mm "
		            "wheelbase in the %s class can fly: %s", r->mission.num_rotors,
		            report_num(b1, sizeof b1, 1000.0 * r->mission.max_diameter_m, 0),
		            spec_enum_airframe[r->mission.airframe_class],
		            cl->binds[0] ? cl->binds : "it fails a check.");
		if (cl->endurance_found)
			strbuf_printf(&sb, " The longest flight that sizes at the asked payload is %s of the "
			              "%s" NBSP "min asked (%s" NBSP "%%), on a %s" NBSP "kg aircraft: the pages "
			              "that follow describe that aircraft, not one that flies the mission as "
			              "asked.", report_auto(b1, sizeof b1, cl->flight_time_s / 60.0),
			              report_auto(b2, sizeof b2, cl->flight_time_s / cl->time_scale / 60.0),
			              report_num(b3, sizeof b3, 100.0 * cl->time_scale, 0),
			              report_num(b4, sizeof b4, cl->mass_kg, 2));
		else
			strbuf_printf(&sb, " Not even %s" NBSP "%% of the mission sizes at the asked payload, "
			              "so this dossier shows no aircraft.",
			              report_num(b1, sizeof b1, 100.0 * cl->min_time_scale, 0));
		if (cl->payload_found)
			strbuf_printf(&sb, " The largest payload that flies the whole mission is %s of the "
			              "%s" NBSP "kg asked, on a %s" NBSP "kg aircraft.",
			              report_num(b1, sizeof b1, cl->max_payload_kg, 2),
			              report_num(b2, sizeof b2, r->mission.payload_kg, 2),
			              report_num(b3, sizeof b3, cl->mass_at_payload_kg, 2));
		else if (r->mission.payload_kg > 0.0)
			strbuf_append_str(&sb, " Even without payload the whole mission does not size.");
		strbuf_append_str(&sb, " The checks section lists what stops the mission as asked, with "
		                  "the fixes.");
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "BEYOND REACH", strbuf_str(&sb));
	} else if (!rp->buildable && r->custom.ran && !r->custom.converged) {
		/* No parts were searched: the physics gave no design to match. */
		report_sfmt(&sb, "This mission cannot be sized: the mass loop did not converge (%s), so "
		            "there is no design and no bill of materials. The figures in this dossier are "
		            "the loop's last iterate, shown to say why: the checks section and the "
		            "convergence history show what diverges, the fixes what to relax.",
		            r->custom.termination);
		if (n_fail > 0)
			strbuf_printf(&sb, " It fails %d of its %d checks.", n_fail, rec->n_checks);
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "NOT BUILDABLE", strbuf_str(&sb));
	} else if (!rp->buildable) {
		report_sfmt(&sb, "No combination of catalogue parts closes this design, so there is no "
		            "bill of materials to build from. The figures in this dossier are those of the "
		            "continuous design: what the physics asks for, which cannot be bought as "
		            "specified. %s", report_no_parts_reason(rp));
		if (n_fail > 0)
			strbuf_printf(&sb, " The continuous design itself fails %d of its %d checks (see the "
			              "checks section).", n_fail, rec->n_checks);
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "NOT BUILDABLE", strbuf_str(&sb));
	} else if (!rec->feasible) {
		strbuf_reset(&sb);
		strbuf_printf(&sb, "The aircraft the bill of materials builds fails %d of its %d checks", n_fail,
		              rec->n_checks);
		for (int i = 0; i < r->n_violations; i++)
			if (strcmp(r->violations[i].run, "closed") == 0 &&
			    strcmp(r->violations[i].stage, "parts") != 0 && r->violations[i].message[0] != '\0') {
				strbuf_printf(&sb, "; the first: %s", r->violations[i].message);
				break;
			}
		const char *so_far = strbuf_str(&sb);
		if (so_far[0] != '\0' && so_far[strlen(so_far) - 1] != '.')
			strbuf_append_str(&sb, ".");
		strbuf_append_str(&sb, " Do not build it as specified: the checks section lists every "
		                  "failure with the fixes the solver suggests.");
		doc_callout(rp->d, DOC_CALLOUT_FAIL, "NOT FEASIBLE AS BUILT", strbuf_str(&sb));
	} else {
		const struct res_check *c = res_tightest_check(rec);
		strbuf_reset(&sb);
		strbuf_printf(&sb, "The aircraft the bill of materials builds passes all %d of its checks.",
		              rec->n_checks);
		if (c != NULL)
			strbuf_printf(&sb, " The tightest is \"%s\" (%s) with a margin of %s" NBSP "%%.",
			              c->name, c->condition, report_num(b1, sizeof b1, 100.0 * c->margin, 1));
		if (!r->feasible)
			strbuf_append_str(&sb, " The continuous reference design fails a check (see the checks "
			                  "section); the aircraft as built does not.");
		doc_callout(rp->d, DOC_CALLOUT_PASS, "FEASIBLE", strbuf_str(&sb));
	}
	strbuf_free(&sb);
}

/* Every way the design shown flies less than the mission asks, on the
 * cover (a requirement is never relaxed without the cover saying so): a
 * shorter flight, a climb or a forward speed the thrust cannot reach
 * flown slower.  The ceiling of a mission beyond reach has its own
 * callout (cover_status()). */
static void
cover_relaxed(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct mission_spec *m = &r->mission;
	const struct res_run *rec = rp->rec;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	int n = 0;
	if (rec->time_scale > 0.0 && rec->time_scale < 0.9995 && !r->ceiling.shown) {
		strbuf_printf(&sb, "%sA shorter flight: every phase is flown at %s" NBSP "%% of its "
		              "requested time (%s of %s" NBSP "min), as the mission allows "
		              "(locks.auto_reduce_flight_time).", n++ ? " " : "",
		              report_num(b1, sizeof b1, 100.0 * rec->time_scale, 0),
		              report_num(b2, sizeof b2, rec->flight_time_s / 60.0, 1),
		              report_num(b3, sizeof b3, rec->flight_time_s / rec->time_scale / 60.0, 1));
	}
	if (rec->climb_limit_ms > 0.0 && rec->climb_limit_ms < m->v_climb_ms)
		strbuf_printf(&sb, "%sA slower climb: %s" NBSP "m/s instead of the %s" NBSP "m/s asked, "
		              "the fastest the thrust reaches.", n++ ? " " : "",
		              report_num(b1, sizeof b1, rec->climb_limit_ms, 1),
		              report_num(b2, sizeof b2, m->v_climb_ms, 1));
	const struct res_phase *fw = &rec->phase[PHASE_FORWARD];
	if (!m->v_forward_auto && fw->duration_s > 0.0 && fw->speed_ms < m->v_forward_ms - 0.05)
		strbuf_printf(&sb, "%sSlower forward flight: %s" NBSP "m/s instead of the %s" NBSP "m/s "
		              "asked, the fastest the thrust and the 35° pitch limit allow.", n++ ? " " : "",
		              report_num(b1, sizeof b1, fw->speed_ms, 1),
		              report_num(b2, sizeof b2, m->v_forward_ms, 1));
	if (n > 0) {
		strbuf_append_str(&sb, " Every figure in this dossier is for the mission as flown; the "
		                  "checks section says what binds.");
		doc_callout(rp->d, DOC_CALLOUT_WARN, "REQUIREMENTS RELAXED", strbuf_str(&sb));
	}
	strbuf_free(&sb);
}

/* One row "label | record | continuous" of the cover's key figures; the
 * continuous column only when the record is not itself continuous. */
static void
key_row(struct rep *rp, struct doc_table *t, const char *label, const char *rec, const char *cont)
{
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", label);
	doc_table_cell(t, DOC_CELL_BOLD, "%s", rec);
	if (rp->buildable)
		doc_table_cell(t, DOC_CELL_NORMAL, "%s", cont);
}

/* Append to sb where the record's mass departs from the continuous
 * design's: the (up to) three mass lines that differ most, largest
 * first, then a full stop.  Real parts are not the continuous laws'
 * median parts: the reader sees which lines carry the difference. */
static void
gap_lines(struct strbuf *sb, const struct res_mass *rec, const struct res_mass *c)
{
	const struct { const char *name; double dkg; } line[] = {
		{ "motors", rec->motor_kg - c->motor_kg },
		{ "propellers", rec->prop_kg - c->prop_kg },
		{ "battery", rec->battery_kg - c->battery_kg },
		{ "ESCs", rec->esc_kg - c->esc_kg },
		{ "power harness", rec->wiring_kg - c->wiring_kg },
		{ "frame and arms", rec->frame_kg + rec->arm_kg - c->frame_kg - c->arm_kg },
		{ "avionics", rec->avionics_kg - c->avionics_kg },
		{ "body and equipment", rec->other_kg - c->other_kg },
		{ "role hardware", rec->role_aux_kg - c->role_aux_kg },
	};
	enum { N_LINES = sizeof line / sizeof line[0], SHOWN = 3 };
	bool used[N_LINES] = { false };
	char b[48];
	int n = 0;
	for (int k = 0; k < SHOWN; k++) {
		int best = -1;
		for (int i = 0; i < N_LINES; i++)
			if (!used[i] && (best < 0 || fabs(line[i].dkg) > fabs(line[best].dkg)))
				best = i;
		/* Differences under a gram, or under 1 % of the largest, are noise. */
		if (best < 0 || fabs(line[best].dkg) < 0.0005
		    || (n > 0 && fabs(line[best].dkg) < 0.01 * fabs(line[0].dkg)))
			break;
		used[best] = true;
		strbuf_printf(sb, "%s %s %s%s" NBSP "kg", n == 0 ? "; the lines that differ most:" : ",",
		              line[best].name, line[best].dkg >= 0.0 ? "+" : "−",
		              report_num(b, sizeof b, fabs(line[best].dkg), 3));
		n++;
	}
	strbuf_append_str(sb, n > 0 ? " (the mass breakdown lists every line)." : ".");
}

static void
cover_key_figures(struct rep *rp)
{
	/* No aircraft sizes (report_render() leaves the design pages out):
	 * no figures to key. */
	if (rp->r->ceiling.valid && !rp->r->ceiling.shown)
		return;
	const struct solve_result *r = rp->r;
	const struct res_run *rec = rp->rec, *c = &r->custom;
	struct strbuf s1 = STRBUF_INIT, s2 = STRBUF_INIT;
	char b1[48], b2[48], b3[48], b4[48];
	double mtow = report_mtow(rp);
	report_subheading(rp, "Key figures", REP_KEEP_PT);
	struct doc_column cols[3] = {
		{ "", 1.9, DOC_ALIGN_LEFT }, { report_record_name(rp), 1.7, DOC_ALIGN_RIGHT },
		{ report_continuous_name(rp), 1.7, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, rp->buildable ? 3 : 2);
	key_row(rp, &t, "Takeoff mass (MTOW)",
	        report_sfmt(&s1, "%s" NBSP "kg", report_num(b1, sizeof b1, mtow, 3)),
	        report_sfmt(&s2, "%s" NBSP "kg", report_num(b2, sizeof b2, c->mass.total_kg, 3)));
	if (rp->buildable)
		key_row(rp, &t, "  of which parts (BOM) + payload",
		        report_sfmt(&s1, "%s + %s" NBSP "kg", report_num(b1, sizeof b1, r->bom_mass_kg, 3),
		                    report_num(b2, sizeof b2, mtow - r->bom_mass_kg, 3)), "—");
	if (r->mtow_interval.valid)
		key_row(rp, &t, report_sfmt(&s2, "  %s" NBSP "%% interval (%s)",
		                            report_num(b3, sizeof b3, 100.0 * r->mtow_interval.level, 0),
		                            r->intervals.from_parts ? "estimated lines" : "model error"),
		        report_sfmt(&s1, "%s–%s" NBSP "kg", report_num(b1, sizeof b1, r->mtow_interval.lo_kg, 2),
		                    report_num(b2, sizeof b2, r->mtow_interval.hi_kg, 2)), "—");
	key_row(rp, &t, "Battery", battery_text(&s1, rec), battery_text(&s2, c));
	key_row(rp, &t, "Motor",
	        rp->buildable && r->motor.chosen
	        ? report_sfmt(&s1, "%s %s", r->motor.manufacturer, r->motor.part_number)
	        : report_sfmt(&s1, "KV" NBSP "%s", report_num(b1, sizeof b1, rec->opt.motor_kv, 0)),
	        report_sfmt(&s2, "KV" NBSP "%s", report_num(b2, sizeof b2, c->opt.motor_kv, 0)));
	key_row(rp, &t, "Propeller (in)",
	        report_sfmt(&s1, "%s" NBSP "×" NBSP "%s", report_num(b1, sizeof b1, rec->opt.prop_diameter_in, 1),
	                    report_num(b2, sizeof b2, rec->opt.prop_pitch_in, 1)),
	        report_sfmt(&s2, "%s" NBSP "×" NBSP "%s", report_num(b3, sizeof b3, c->opt.prop_diameter_in, 1),
	                    report_num(b4, sizeof b4, c->opt.prop_pitch_in, 1)));
	const struct res_figures *f = &rp->fig;
	key_row(rp, &t, "Mission flight time (min)", report_num(b1, sizeof b1, minutes(f->flight_time_s), 1),
	        report_num(b2, sizeof b2, minutes(c->flight_time_s), 1));
	/* The figures with an interval print it after the value of record,
	 * which is res_figures()'s (the interval is built around it). */
	const struct res_design_intervals *di = &r->intervals;
	key_row(rp, &t, "Hover power at takeoff mass (W)",
	        di->power_valid
	        ? report_sfmt(&s1, "%s (%s–%s)", report_num(b1, sizeof b1, f->hover_power_w, 0),
	                      report_num(b2, sizeof b2, di->hover_power_lo_w, 0),
	                      report_num(b3, sizeof b3, di->hover_power_hi_w, 0))
	        : report_num(b1, sizeof b1, f->hover_power_w, 0),
	        report_num(b4, sizeof b4, c->hover_power_w, 0));
	if (f->sheds)
		key_row(rp, &t, "Hover power after shedding (W)",
		        report_num(b1, sizeof b1, f->hover_power_shed_w, 0),
		        report_num(b2, sizeof b2, c->phase[PHASE_HOVER].power_w, 0));
	key_row(rp, &t, "Hover endurance to reserve (min)",
	        di->power_valid
	        ? report_sfmt(&s1, "%s (%s–%s)", report_num(b1, sizeof b1, minutes(f->hover_endurance_s), 1),
	                      report_num(b2, sizeof b2, minutes(di->endurance_lo_s), 1),
	                      report_num(b3, sizeof b3, minutes(di->endurance_hi_s), 1))
	        : report_num(b1, sizeof b1, minutes(f->hover_endurance_s), 1),
	        report_num(b4, sizeof b4, minutes(c->hover_endurance_s), 1));
	key_row(rp, &t, "Thrust-to-weight ratio", report_num(b1, sizeof b1, rec->thrust_to_weight, 2),
	        report_num(b2, sizeof b2, c->thrust_to_weight, 2));
	key_row(rp, &t, "Battery peak temperature (°C)", report_num(b1, sizeof b1, rec->max_battery_temp_c, 1),
	        report_num(b2, sizeof b2, c->max_battery_temp_c, 1));
	if (rp->buildable)
		key_row(rp, &t, "Bill of materials price", report_price(rp, &s1), "—");
	key_row(rp, &t, "Regulatory class by mass", class_text(&s1, mtow), class_text(&s2, c->mass.total_kg));
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	if (rp->buildable) {
		double dm = mtow - c->mass.total_kg;
		report_sfmt(&s1, "What the physics asks for (continuous optimum) weighs %s" NBSP "kg; the "
		            "design of record is %s" NBSP "kg (%s%s" NBSP "%%) %s",
		            report_num(b1, sizeof b1, c->mass.total_kg, 3),
		            report_num(b2, sizeof b2, fabs(dm), 3), dm >= 0 ? "+" : "−",
		            report_num(b3, sizeof b3, fabs(100.0 * report_div(dm, c->mass.total_kg)), 1),
		            dm >= 0 ? "heavier" : "lighter");
		gap_lines(&s1, &rec->mass, &c->mass);
		doc_paragraph(rp->d, strbuf_str(&s1));
	}
	strbuf_free(&s1);
	strbuf_free(&s2);
}

/* The issue date, or "undated" when the mission gives none and
 * SOURCE_DATE_EPOCH is unset (fsout_resolve_date). */
static const char *
report_date_text(const struct rep *rp)
{
	return rp->in->date != NULL && rp->in->date[0] != '\0' ? rp->in->date : "undated";
}

/* The document number: from the input's fingerprint, so that the same
 * mission file always carries the same number ("AE-4FBB-C60E"). */
const char *
report_doc_number(const struct solve_result *r, char *buf, size_t n)
{
	const char *h = r->input_sha256;
	char u[9];
	for (int i = 0; i < 8; i++) {
		char c = h[0] != '\0' && (int)strlen(h) > i ? h[i] : '0';
		u[i] = c >= 'a' && c <= 'f' ? (char)(c - 'a' + 'A') : c;
	}
	u[8] = '\0';
	snprintf(buf, n, "AE-%.4s-%.4s", u, u + 4);
	return buf;
}

/* The cover: title, the status first (a design that cannot be built as
 * specified says so before anything else), the key figures of the design
 * of record beside the continuous optimum, and the dossier's identity.
 * `first` is nonzero when the cover opens the document.  Not numbered. */
void
report_sec_cover(struct rep *rp, int first)
{
	const struct solve_result *r = rp->r;
	const struct mission_spec *m = &r->mission;
	struct strbuf sb = STRBUF_INIT, sb2 = STRBUF_INIT;
	char b1[48], b2[48];
	if (!first)
		doc_new_page(rp->d);
	const char *mname = rp->in->mission_name != NULL ? rp->in->mission_name : m->name;
	doc_title(rp->d, m->report.title[0] != '\0' ? m->report.title : "Design dossier",
	          report_sfmt(&sb, "Multirotor design dossier: %s%s%s", report_or_absent(mname),
	                      m->report.revision[0] != '\0' ? ", revision " : "", m->report.revision));
	cover_status(rp);
	cover_relaxed(rp);
	cover_key_figures(rp);

	report_subheading(rp, "Document", REP_KEEP_PT);
	const char *kv[] = {
		"Client", m->report.client,
		"Project", m->report.project_id,
		"Document number", report_doc_number(rp->r, b1, sizeof b1),
		"Revision", m->report.revision,
		"Date", report_date_text(rp),
		"Prepared by", m->report.author,
		"Mission", report_sfmt(&sb2, "%s (%s%s, %d rotors, %s" NBSP "%s payload); the file %s is "
		                       "attached to this PDF", report_or_absent(mname),
		                       m->payload_role.type == ROLE_NONE ? "no role" : report_role_name(r),
		                       m->payload_role.type == ROLE_NONE ? "" : " role",
		                       m->num_rotors, report_mass(rp, b2, sizeof b2, m->payload_kg), rp->mass_unit,
		                       report_or_absent(rp->in->mission_file_name)),
		"Engine", report_sfmt(&sb, "aeroeval %s", report_or_absent(rp->in->engine_version)),
	};
	/* The input and catalogue fingerprints stand in the document control
	 * on the next page: the cover keeps to one page with a long title. */
	report_kv(rp, kv, (int)(sizeof kv / sizeof kv[0]) / 2, 8);
	strbuf_free(&sb);
	strbuf_free(&sb2);
}

/* ---- document control and contents ------------------------------------------ */

/* A name, or a line to sign on when none is given. */
static const char *
signatory(const char *name)
{
	return name != NULL && name[0] != '\0' ? name : "________________________  (name, signature, date)";
}

/* The page after the cover: who prepared, checked and approved this
 * revision, its history, then the contents with page numbers. */
void
report_sec_control(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct mission_spec *m = &r->mission;
	struct strbuf sb = STRBUF_INIT;
	char num[48];
	doc_new_page(rp->d);
	report_subheading(rp, "Document control", REP_KEEP_PT);
	const char *kv[] = {
		"Document number", report_doc_number(rp->r, num, sizeof num),
		"Title", m->report.title[0] != '\0' ? m->report.title : "Design dossier",
		"Revision", m->report.revision,
		"Issue date", report_date_text(rp),
		"Prepared by", signatory(m->report.author),
		"Checked by", signatory(m->report.checked_by),
		"Approved by", signatory(m->report.approved_by),
		"Input SHA-256", r->input_sha256,
		"Catalogue SHA-256", r->catalogue_sha256,
	};
	report_kv(rp, kv, (int)(sizeof kv / sizeof kv[0]) / 2, -1);
	static const struct doc_column hcols[] = {
		{ "Revision", 0.8, DOC_ALIGN_LEFT }, { "Date", 1.0, DOC_ALIGN_LEFT },
		{ "Description", 3.6, DOC_ALIGN_LEFT }, { "Prepared by", 1.4, DOC_ALIGN_LEFT },
	};
	report_subheading(rp, "Revision history", 60.0);
	struct doc_table t;
	doc_table_init(&t, hcols, 4);
	doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_or_absent(m->report.revision));
	doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_date_text(rp));
	doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_sfmt(&sb, "Issued: compiled by aeroeval %s from %s "
	               "(input SHA-256 %.12s…)", report_or_absent(rp->in->engine_version),
	               report_or_absent(rp->in->mission_file_name), r->input_sha256));
	doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_or_absent(m->report.author));
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	int n = 0;
	for (int i = 0; i < rp->tpl->n_sections; i++)
		n += rp->tpl->sections[i].enabled && rp->tpl->sections[i].id != TEMPLATE_SEC_COVER;
	doc_contents(rp->d, "Contents", n);
	strbuf_free(&sb);
}

/* ---- executive summary ------------------------------------------------------ */

/* One row "label | record | continuous | baseline" of the comparison. */
static void
cmp_row(const struct rep *rp, struct doc_table *t, const char *label, double rec, double cont,
        double base, int dec)
{
	doc_table_cell(t, DOC_CELL_NORMAL, "%s", label);
	report_cell_num(t, DOC_CELL_BOLD, rec, dec);
	if (rp->buildable)
		report_cell_num(t, DOC_CELL_NORMAL, cont, dec);
	report_cell_num(t, DOC_CELL_MUTED, base, dec);
}

/* The regulatory class by the takeoff mass of record, as bullets.  Only
 * mass is judged: the dossier cannot know the rest of a class declaration,
 * so the text says "informative". */
static void
regulatory(struct rep *rp)
{
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	double m = report_mtow(rp), mc = rp->r->custom.mass.total_kg;
	const char *eu = res_eu_class(m);
	char *own[4];
	int n = 0;
	if (strcmp(eu, "specific") == 0)
		report_sfmt(&sb, "EU (Regulation 2019/945): at %s" NBSP "kg the aircraft is above the 25" NBSP
		            "kg limit of the open-category classes; it operates in the specific category "
		            "(operational authorisation, SORA).", report_num(b1, sizeof b1, m, 2));
	else
		report_sfmt(&sb, "EU (Regulation 2019/945): a takeoff mass of %s" NBSP "kg falls within class "
		            "%s by mass (C0 < 250" NBSP "g, C1 < 900" NBSP "g, C2 < 4" NBSP "kg, C3/C4 < 25" NBSP
		            "kg).", report_num(b1, sizeof b1, m, 3), eu);
	own[n++] = xstrdup(strbuf_str(&sb));
	if (m < RES_US_107_KG)
		report_sfmt(&sb, "US (14 CFR Part 107): %s" NBSP "kg (%s" NBSP "lb) is below the 55" NBSP "lb "
		            "(24.9" NBSP "kg) small-UAS limit.", report_num(b1, sizeof b1, m, 2),
		            report_num(b3, sizeof b3, m / REP_KG_PER_LB, 1));
	else
		report_sfmt(&sb, "US (14 CFR Part 107): %s" NBSP "kg (%s" NBSP "lb) is at or above the 55" NBSP
		            "lb (24.9" NBSP "kg) small-UAS limit; an exemption (49 U.S.C. 44807) or Part 91 "
		            "operation is needed.", report_num(b1, sizeof b1, m, 2),
		            report_num(b3, sizeof b3, m / REP_KG_PER_LB, 1));
	own[n++] = xstrdup(strbuf_str(&sb));
	if (rp->buildable && (strcmp(res_eu_class(mc), eu) != 0 || (mc < RES_US_107_KG) != (m < RES_US_107_KG)))
		own[n++] = xstrdup(report_sfmt(&sb, "The class follows the aircraft as built: the continuous "
		                   "optimum (%s" NBSP "kg) would fall in %s, but the parts of record weigh "
		                   "%s" NBSP "kg.", report_num(b1, sizeof b1, mc, 3), res_eu_class(mc),
		                   report_num(b2, sizeof b2, m, 3)));
	own[n++] = xstrdup("Informative only: a class mark also depends on the manufacturer's declaration "
	                   "of conformity (noise, geo-awareness, remote identification, speed limits).");
	doc_bullets(rp->d, (const char *const *)own, n);
	for (int i = 0; i < n; i++)
		free(own[i]);
	strbuf_free(&sb);
}

/* The chosen catalogue parts with quantity, unit mass and J-score. */
static void
parts_table(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	static const struct doc_column cols[] = {
		{ "Part", 0.9, DOC_ALIGN_LEFT }, { "Maker and part number", 3.4, DOC_ALIGN_LEFT },
		{ "Qty", 0.5, DOC_ALIGN_RIGHT }, { "Unit mass (g)", 1.0, DOC_ALIGN_RIGHT },
		{ "J (%)", 0.8, DOC_ALIGN_RIGHT },
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
		/* J scores the motor and propeller pair; the battery and ESC
		 * follow from it. */
		if (i < 2)
			report_cell_num(&t, DOC_CELL_NORMAL, p[i]->j_score, 1);
		else
			doc_table_cell(&t, DOC_CELL_MUTED, "—");
	}
	if (t.n_cells > 0)
		doc_table(rp->d, &t);
	doc_table_clear(&t);
}

/* What the model assumes and how accurate it is on real aircraft: the
 * calibration's figures when it carries them, else where they are kept. */
static void
assumptions(struct rep *rp)
{
	const struct solve_result *r = rp->r;
	const struct res_accuracy *a = &r->accuracy;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48], b4[48], b5[48];
	doc_paragraph(rp->d, "The continuous design comes from a coupled model of mass, battery, rotor "
	              "aerodynamics and structure (its method is cited in the appendix): ISA atmosphere at "
	              "the mission altitude, steady flight phases, the pack discharged in a time simulation "
	              "with its heating. The design of record is then sized again on the catalogue parts' "
	              "masses and flown on their published "
	              "motor constants and propeller coefficients, or on estimates where the catalogue has "
	              "none (the propulsion section says which). Masses of the parts the model sizes (arms, "
	              "frame, harness, body) are estimates. Prices are store snapshots, not quotations.");
	const struct res_design_intervals *di = &r->intervals;
	if (a->valid && r->mtow_interval.valid) {
		strbuf_reset(&sb);
		if (di->from_parts)
			strbuf_printf(&sb, "Accuracy of this design: its takeoff mass lies between %s and %s"
			              NBSP "kg (%s" NBSP "%% interval). The catalogue parts weigh as "
			              "published; the %s" NBSP "kg the model estimates (frame, arms, harness, "
			              "body and allowances) carry the error of its dry-mass model on real "
			              "aircraft.",
			              report_num(b1, sizeof b1, r->mtow_interval.lo_kg, 2),
			              report_num(b2, sizeof b2, r->mtow_interval.hi_kg, 2),
			              report_num(b3, sizeof b3, 100.0 * r->mtow_interval.level, 0),
			              report_num(b4, sizeof b4, di->estimated_kg, 3));
		else
			strbuf_printf(&sb, "Accuracy of this design: its takeoff mass lies between %s and %s"
			              NBSP "kg (%s" NBSP "%% interval): the model's errors on the dry mass "
			              "and on the energy of real aircraft, carried through this design's own "
			              "mass loop (each error grows by %s times as the loop closes).",
			              report_num(b1, sizeof b1, r->mtow_interval.lo_kg, 2),
			              report_num(b2, sizeof b2, r->mtow_interval.hi_kg, 2),
			              report_num(b3, sizeof b3, 100.0 * r->mtow_interval.level, 0),
			              report_num(b4, sizeof b4, di->loop_gain, 1));
		if (di->power_valid)
			strbuf_printf(&sb, " Its hover power lies between %s and %s" NBSP "W and its hover "
			              "endurance between %s and %s" NBSP "min: the error of the model's power "
			              "chain on the published flight times of real aircraft.",
			              report_num(b1, sizeof b1, di->hover_power_lo_w, 0),
			              report_num(b2, sizeof b2, di->hover_power_hi_w, 0),
			              report_num(b3, sizeof b3, minutes(di->endurance_lo_s), 1),
			              report_num(b4, sizeof b4, minutes(di->endurance_hi_s), 1));
		strbuf_printf(&sb, " On its calibration cohort (%d aircraft, leave-one-out) the model's own "
		              "designs hold %s" NBSP "%% of the real aircraft inside intervals built this "
		              "way; a continuous design sized from the same facts as this one misses their "
		              "takeoff mass by %s" NBSP "%% on average (battery mass %s" NBSP "%%).",
		              a->n_rows, report_num(b5, sizeof b5, 100.0 * a->design_coverage, 0),
		              report_num(b1, sizeof b1, 100.0 * a->mape, 1),
		              report_num(b2, sizeof b2, 100.0 * a->battery_mape, 1));
		doc_paragraph(rp->d, strbuf_str(&sb));
	} else {
		doc_paragraph(rp->d, "Accuracy: the model's accuracy on real aircraft is documented in "
		              "docs/validation.md; this dossier quotes no accuracy figure or prediction interval "
		              "for this design.");
	}
	strbuf_free(&sb);
}

/* Section: the design of record beside its two references, the parts, the
 * role overhead of the continuous runs, the regulatory class, the
 * assumptions. */
void
report_sec_summary(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	const struct res_run *rec = rp->rec, *b = &r->baseline, *c = &r->custom;
	struct strbuf sb = STRBUF_INIT;
	char b1[48], b2[48], b3[48];
	report_heading(rp, title);
	if (rp->buildable)
		doc_paragraph(rp->d, report_sfmt(&sb, "The design of record is the aircraft the bill of materials "
		              "builds: %s" NBSP "kg at takeoff, sized on the real parts' masses and flown on their own "
		              "constants. Beside it stand what the physics asks for, the continuous optimum "
		              "(%s" NBSP "kg), and the baseline (%s" NBSP "kg): the same mission without the "
		              "role's equipment, its payload carried as dead weight. It is %s.", report_num(b1, sizeof b1, report_mtow(rp), 3),
		              report_num(b2, sizeof b2, c->mass.total_kg, 3),
		              report_num(b3, sizeof b3, b->mass.total_kg, 3),
		              rp->rec_ok ? "feasible: every check passes"
		                         : "NOT feasible as built (see the checks section)"));
	else
		doc_paragraph(rp->d, report_sfmt(&sb, "No catalogue parts close this design: the numbers are those "
		              "of the continuous design (%s" NBSP "kg), what the physics asks for, which is NOT "
		              "buildable as specified. The baseline (%s" NBSP "kg: the same mission without the "
		              "role's equipment, its payload carried as dead weight) is shown for reference.", report_num(b1, sizeof b1, c->mass.total_kg, 3),
		              report_num(b2, sizeof b2, b->mass.total_kg, 3)));

	struct doc_column cols[4] = {
		{ "Quantity", 2.6, DOC_ALIGN_LEFT }, { report_record_name(rp), 1.2, DOC_ALIGN_RIGHT },
		{ report_continuous_name(rp), 1.2, DOC_ALIGN_RIGHT }, { REP_NAME_BASELINE, 1.0, DOC_ALIGN_RIGHT },
	};
	if (!rp->buildable)
		cols[2] = cols[3];
	struct doc_table t;
	doc_table_init(&t, cols, rp->buildable ? 4 : 3);
	cmp_row(rp, &t, "Takeoff mass MTOW (kg)", report_mtow(rp), c->mass.total_kg, b->mass.total_kg, 3);
	cmp_row(rp, &t, "Battery mass (kg)", rec->mass.battery_kg, c->mass.battery_kg, b->mass.battery_kg, 3);
	cmp_row(rp, &t, "Battery capacity (mAh)", rec->capacity_mah, c->capacity_mah, b->capacity_mah, 0);
	cmp_row(rp, &t, "Series cells", rec->cell_count, c->cell_count, b->cell_count, 0);
	cmp_row(rp, &t, "Battery energy (Wh)", rec->energy_wh, c->energy_wh, b->energy_wh, 1);
	cmp_row(rp, &t, "Thrust-to-weight ratio", rec->thrust_to_weight, c->thrust_to_weight,
	        b->thrust_to_weight, 2);
	cmp_row(rp, &t, "Hover throttle (%)", 100.0 * rec->hover_throttle, 100.0 * c->hover_throttle,
	        100.0 * b->hover_throttle, 1);
	const struct res_figures *f = &rp->fig;
	cmp_row(rp, &t, "Mission flight time (min)", minutes(f->flight_time_s), minutes(c->flight_time_s),
	        minutes(b->flight_time_s), 1);
	cmp_row(rp, &t, "Hover endurance to reserve (min)", minutes(hover_endurance_s(rp, rec)),
	        minutes(hover_endurance_s(rp, c)), minutes(hover_endurance_s(rp, b)), 1);
	if (b->marketing_endurance_s > 0 || c->marketing_endurance_s > 0)
		cmp_row(rp, &t, "Best-case (marketing) endurance (min)", NAN,
		        minutes(c->marketing_endurance_s), minutes(b->marketing_endurance_s), 1);
	/* Hover power at the takeoff mass for all three; where payload leaves
	 * on the way, the mission's hover phase (after it) too.  The baseline
	 * carries its payload as dead weight: nothing leaves. */
	cmp_row(rp, &t, "Hover power at takeoff mass (W)", f->hover_power_w, settled(c, c->hover_power_w),
	        settled(b, b->hover_power_w), 0);
	if (f->sheds)
		cmp_row(rp, &t, "Hover power after shedding (W)", f->hover_power_shed_w,
		        settled(c, c->phase[PHASE_HOVER].power_w), NAN, 0);
	cmp_row(rp, &t, "Hover battery current at takeoff mass (A)", f->hover_current_a,
	        f->sheds ? NAN : settled(c, c->phase[PHASE_HOVER].current_a),
	        settled(b, b->phase[PHASE_HOVER].current_a), 1);
	cmp_row(rp, &t, "Auxiliary power (W)", f->aux_power_w, c->aux_power_w, b->aux_power_w, 0);
	cmp_row(rp, &t, "State of charge at landing (%)", 100.0 * f->landing_soc,
	        settled(c, 100.0 * c->end_soc), settled(b, 100.0 * b->end_soc), 1);
	cmp_row(rp, &t, "Motor KV (rpm/V)", rec->opt.motor_kv, c->opt.motor_kv, b->opt.motor_kv, 0);
	cmp_row(rp, &t, "Propeller diameter (in)", rec->opt.prop_diameter_in, c->opt.prop_diameter_in,
	        b->opt.prop_diameter_in, 1);
	cmp_row(rp, &t, "Battery peak temperature (°C)", rec->max_battery_temp_c, c->max_battery_temp_c,
	        b->max_battery_temp_c, 1);
	doc_table(rp->d, &t);
	doc_table_clear(&t);
	if (b->marketing_endurance_s > 0 || c->marketing_endurance_s > 0)
		doc_paragraph(rp->d, "The best-case (marketing) endurance is computed for the continuous designs "
		              "only (—: not computed).");

	report_subheading(rp, "Parts of record", REP_KEEP_PT);
	if (r->parts_selected) {
		parts_table(rp);
		struct strbuf price = STRBUF_INIT;
		doc_paragraph(rp->d, report_sfmt(&sb, "%s The bill of materials holds %s" NBSP "kg of catalogue and "
		              "custom parts at %s; the payload (%s" NBSP "kg) is furnished by the customer.",
		              REP_J_NOTE, report_num(b1, sizeof b1, r->bom_mass_kg, 3), report_price(rp, &price),
		              report_num(b2, sizeof b2, report_mtow(rp) - r->bom_mass_kg, 3)));
		strbuf_free(&price);
	} else {
		doc_paragraph(rp->d, report_sfmt(&sb, "None. %s The design is given by its continuous optimum "
		              "(propeller size, motor KV, battery); the bill of materials section lists what to "
		              "source.", report_no_parts_reason(rp)));
	}

	/* Heading, sentence and the table of up to 12 rows: about 240 pt. */
	report_subheading(rp, "Role overhead (continuous designs)", 240.0);
	if (r->mission.payload_role.type == ROLE_NONE)
		doc_paragraph(rp->d, r->ceiling.shown
		              ? "The mission has no role, so there is no role equipment to add: the design "
		                "shown differs from the baseline only in the baseline's sizing rules (a fixed "
		                "60 % hover throttle, its own forward flight) and in flying the shorter flight "
		                "the cover states."
		              : "The mission has no role, so there is no role equipment to add: the "
		                "continuous optimum differs from the baseline only in the baseline's sizing "
		                "rules (a fixed 60 % hover throttle, its own forward flight).");
	else
		doc_paragraph(rp->d, report_sfmt(&sb, "What the %s role adds to the continuous optimum over "
		              "the baseline (the same mission without the role's equipment), item by item.",
		              report_role_name(r)));
	const struct doc_column ocols[] = {
		{ "Mass item", 2.6, DOC_ALIGN_LEFT }, { REP_NAME_BASELINE, 1.1, DOC_ALIGN_RIGHT },
		{ report_continuous_name(rp), 1.3, DOC_ALIGN_RIGHT }, { "Overhead", 1.0, DOC_ALIGN_RIGHT },
	};
	doc_table_init(&t, ocols, 4);
	for (int i = 0; i < report_n_mass_items; i++) {
		double o = report_mass_get(&r->role_overhead, i);
		if (fabs(o) * rp->mass_scale < 0.5 * pow(10.0, -rp->mass_dec))
			continue;
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s (%s)", report_mass_items[i].label, rp->mass_unit);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_mass(rp, b1, sizeof b1, report_mass_get(&b->mass, i)));
		doc_table_cell(&t, DOC_CELL_NORMAL, "%s", report_mass(rp, b1, sizeof b1, report_mass_get(&c->mass, i)));
		doc_table_cell(&t, DOC_CELL_BOLD, "%s", report_delta(rp, b1, sizeof b1, o));
	}
	doc_table_cell(&t, DOC_CELL_BOLD, "Total (%s)", rp->mass_unit);
	doc_table_cell(&t, DOC_CELL_BOLD, "%s", report_mass(rp, b1, sizeof b1, b->mass.total_kg));
	doc_table_cell(&t, DOC_CELL_BOLD, "%s", report_mass(rp, b1, sizeof b1, c->mass.total_kg));
	doc_table_cell(&t, DOC_CELL_BOLD, "%s", report_delta(rp, b1, sizeof b1, r->role_overhead.total_kg));
	t.total_row = 1;
	doc_table(rp->d, &t);
	doc_table_clear(&t);

	report_subheading(rp, "Regulatory class (informative)", REP_KEEP_PT);
	regulatory(rp);
	report_subheading(rp, "Assumptions and accuracy", REP_KEEP_PT);
	assumptions(rp);
	strbuf_free(&sb);
}

/* ---- design rationale ------------------------------------------------------- */

/* Section: the engine's rationale sentences in order.  A design that
 * cannot be built as specified leads with what failed. */
void
report_sec_rationale(struct rep *rp, const char *title)
{
	const struct solve_result *r = rp->r;
	report_heading(rp, title);
	if (!r->feasible) {
		doc_callout(rp->d, DOC_CALLOUT_FAIL, rp->rec_ok ? "A REFERENCE FAILS" : "NOT FEASIBLE",
		            rp->rec_ok ? "The design of record meets every constraint, a reference design does "
		                         "not. The violations come first; the decisions the solver took follow."
		                       : "The design does not meet every constraint. The violations come first; "
		                         "the decisions the solver took follow.");
		report_subheading(rp, "Violations", REP_KEEP_PT);
		report_violations(rp);
		report_subheading(rp, "Solver decisions", REP_KEEP_PT);
	}
	doc_paragraph(rp->d, "Each decision the solver took, in the order it took them: first the continuous "
	              "optimum (what the physics asks for), then the catalogue parts that build the design of "
	              "record.");
	const char *items[RES_MAX_RATIONALE];
	int n = r->n_rationale < RES_MAX_RATIONALE ? r->n_rationale : RES_MAX_RATIONALE, has_j = 0;
	for (int i = 0; i < n; i++) {
		items[i] = r->rationale[i];
		has_j |= strstr(items[i], "J = ") != NULL;
	}
	if (n == 0)
		doc_paragraph(rp->d, "The solver recorded no decisions.");
	report_numbered(rp, items, n, 1);
	if (has_j)
		doc_paragraph(rp->d, REP_J_NOTE);
}
