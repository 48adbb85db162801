/* validate.c — cohort row -> mission rule, per-row solve, statistics
 * (see validate.h for the rule itself). */
#include "study/validate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "physics/aero.h"
#include "engine/engine.h"
#include "sizing/sizing.h"
#include "util/units.h"
#include "util/xalloc.h"

static const char *const note_text[VALIDATE_NOTE_COUNT] = {
	"wheelbase from the propeller's overlap limit",
	"propeller above the overlap limit: not locked",
	"chemistry \"Li-ion\" read as Li-ion NMC",
	"chemistry unknown: LiHV",
	"coaxial unknown: flat layout",
	"role unknown: none",
	"endurance from the max flight time, flown level",
	"the published pack locked",
};

const char *
validate_note_text(unsigned note)
{
	for (int i = 0; i < VALIDATE_NOTE_COUNT; i++)
		if (note == 1u << i)
			return note_text[i];
	return "";
}

const char *
validate_skip_text(enum validate_skip s)
{
	switch (s) {
	case VALIDATE_SKIP_PAYLOAD: return "payload of the takeoff figure unknown";
	case VALIDATE_SKIP_ROTORS: return "rotor count unknown";
	case VALIDATE_SKIP_CLASS: return "airframe class unknown";
	case VALIDATE_SKIP_WHEELBASE: return "neither wheelbase nor propeller diameter known";
	case VALIDATE_SKIP_ENDURANCE: return "neither hover time nor max flight time known";
	case VALIDATE_SKIP_RANGE: return "a fact outside the mission contract's range";
	default: return "";
	}
}

const char *
validate_status_text(enum validate_status s)
{
	switch (s) {
	case VALIDATE_ROW_SKIPPED: return "skipped";
	case VALIDATE_ROW_OK: return "ok";
	case VALIDATE_ROW_NOT_CONVERGED: return "not converged";
	case VALIDATE_ROW_NOT_RUN: return "not run";
	default: return "";
	}
}

const char *
validate_class_key(const struct cohort_row *row)
{
	return row->has_airframe_class ? spec_enum_airframe[row->airframe_class] : "";
}

/* Is v inside the contract's range of field id?  A row whose fact the
 * mission format cannot hold is skipped rather than clamped. */
static bool
in_range(enum spec_field id, double v)
{
	const struct spec_field_info *f = &spec_fields[id];
	if (!isfinite(v) || v > f->max)
		return false;
	return (f->flags & SPEC_F_MIN_EXCL) ? v > f->min : v >= f->min;
}

/* The loaded profile whose name matches (case ignored), or NULL. */
static const char *
find_chem(const struct model_data *md, const char *name)
{
	for (int i = 0; i < md->n_chem; i++)
		if (strcasecmp(md->chem[i].name, name) == 0)
			return md->chem[i].name;
	return NULL;
}

static void
set_chem(struct mission_spec *s, const char *name)
{
	snprintf(s->battery_chemistry, sizeof s->battery_chemistry, "%s", name);
	s->given[SPECF_BATTERY_CHEMISTRY] = true;
}

/* The fact of a row that puts a mission field out of the contract's
 * range, for the skip message; returns VALIDATE_SKIP_RANGE. */
static enum validate_skip
out_of_range(struct validate_fact *fact, const char *column, double value,
             enum spec_field field, double field_value)
{
	if (fact != NULL)
		*fact = (struct validate_fact){ column, value, field, field_value };
	return VALIDATE_SKIP_RANGE;
}

void
validate_fact_text(const struct validate_fact *f, char *buf, size_t n)
{
	char range[128];
	if (f->column == NULL) {
		snprintf(buf, n, "%s", validate_skip_text(VALIDATE_SKIP_RANGE));
		return;
	}
	const struct spec_field_info *fi = &spec_fields[f->field];
	spec_range_text(fi, range, sizeof range);
	snprintf(buf, n, "%s %.6g gives %s %.6g, outside the mission contract's range (%s)",
	         f->column, f->value, fi->path, f->field_value, range);
}

enum validate_skip
validate_mission_from_row(const struct cohort_row *row, const struct model_data *md,
                          struct mission_spec *out, unsigned *notes)
{
	return validate_mission_explained(row, md, VALIDATE_FROM_ENDURANCE, out, notes, NULL);
}

enum validate_skip
validate_mission_explained(const struct cohort_row *row, const struct model_data *md,
                           enum validate_rule rule, struct mission_spec *out, unsigned *notes,
                           struct validate_fact *fact)
{
	struct mission_spec *s = out;
	unsigned nt = 0;
	spec_defaults(s);
	*notes = 0;
	if (fact != NULL)
		memset(fact, 0, sizeof *fact);

	if (!row->has_payload_kg)
		return VALIDATE_SKIP_PAYLOAD;
	if (!row->has_rotor_count)
		return VALIDATE_SKIP_ROTORS;
	if (!row->has_airframe_class)
		return VALIDATE_SKIP_CLASS;
	if (!row->has_hover_time_min && !row->has_max_flight_time_min)
		return VALIDATE_SKIP_ENDURANCE;
	if (!row->has_diagonal_wheelbase_mm && !row->has_prop_diameter_in)
		return VALIDATE_SKIP_WHEELBASE;

	snprintf(s->name, sizeof s->name, "%s", row->name);
	s->given[SPECF_NAME] = true;

	s->payload_kg = row->payload_kg;
	s->given[SPECF_PAYLOAD_KG] = true;
	/* The load case the airframe is built for: the maker's largest
	 * payload, where published, when it exceeds the row's. */
	if (row->has_max_payload_kg && row->max_payload_kg > row->payload_kg) {
		s->max_payload_kg = row->max_payload_kg;
		s->given[SPECF_MAX_PAYLOAD_KG] = true;
	}

	s->num_rotors = row->rotor_count;
	s->given[SPECF_NUM_ROTORS] = true;
	s->coaxial_layout = row->has_coaxial && row->coaxial;
	if (!row->has_coaxial)
		nt |= VALIDATE_NOTE_COAX_DEFAULT;
	s->given[SPECF_COAXIAL_LAYOUT] = true;
	s->airframe_class = row->airframe_class;
	s->given[SPECF_AIRFRAME_CLASS] = true;
	s->payload_role.type = row->has_role ? row->role : ROLE_NONE;
	if (!row->has_role)
		nt |= VALIDATE_NOTE_ROLE_DEFAULT;
	s->given[SPECF_ROLE_TYPE] = true;
	/* A published endurance is flown at one takeoff mass (a hover time
	 * states its takeoff weight; a delivery or spraying time is quoted
	 * with the load on board), so a shedding role sheds nothing here. */
	if (md->role[s->payload_role.type].shedding != SHED_NONE) {
		s->payload_role.mass_shedding = false;
		s->given[SPECF_ROLE_MASS_SHEDDING] = true;
	}
	if (!in_range(SPECF_NUM_ROTORS, row->rotor_count))
		return out_of_range(fact, "rotor_count", row->rotor_count, SPECF_NUM_ROTORS,
		                    row->rotor_count);
	if (!in_range(SPECF_PAYLOAD_KG, s->payload_kg))
		return out_of_range(fact, "payload_kg", row->payload_kg, SPECF_PAYLOAD_KG,
		                    s->payload_kg);
	if (!in_range(SPECF_MAX_PAYLOAD_KG, s->max_payload_kg))
		return out_of_range(fact, "max_payload_kg", row->max_payload_kg,
		                    SPECF_MAX_PAYLOAD_KG, s->max_payload_kg);

	/* Wheelbase: the row's, else the smallest one whose overlap limit
	 * admits its propeller (the inverse of paper eq. overlap). */
	int arms = s->coaxial_layout ? s->num_rotors / 2 : s->num_rotors;
	if (arms < 2)   /* a coaxial layout of 3 rotors: one arm */
		return out_of_range(fact, "rotor_count", row->rotor_count, SPECF_NUM_ROTORS,
		                    2.0 * arms);
	double sin_arm = sin(M_PI / (double)arms);
	double d_m = row->has_prop_diameter_in ? in_to_m(row->prop_diameter_in) : 0.0;
	if (row->has_diagonal_wheelbase_mm) {
		s->max_diameter_m = row->diagonal_wheelbase_mm / 1000.0;
	} else {
		s->max_diameter_m = d_m / ((1.0 - AERO_TIP_CLEARANCE) * sin_arm);
		nt |= VALIDATE_NOTE_WHEELBASE_PROP;
	}
	s->given[SPECF_MAX_DIAMETER_M] = true;
	if (!in_range(SPECF_MAX_DIAMETER_M, s->max_diameter_m))
		return row->has_diagonal_wheelbase_mm ?
		    out_of_range(fact, "diagonal_wheelbase_mm", row->diagonal_wheelbase_mm,
		                 SPECF_MAX_DIAMETER_M, s->max_diameter_m) :
		    out_of_range(fact, "prop_diameter_in", row->prop_diameter_in,
		                 SPECF_MAX_DIAMETER_M, s->max_diameter_m);

	/* Propeller: locked at the row's diameter when the model's geometry
	 * admits it, with the gate's own slack (a derived wheelbase puts the
	 * limit at D by construction, to rounding). */
	if (row->has_prop_diameter_in) {
		double limit_m = (1.0 - AERO_TIP_CLEARANCE) * s->max_diameter_m * sin_arm;
		if (d_m <= limit_m * (1.0 + AERO_OVERLAP_REL_TOL)) {
			s->locks.is_prop_locked = true;
			s->locks.locked_diameter_in = row->prop_diameter_in;
			s->locks.locked_pitch_in = row->has_prop_pitch_in ? row->prop_pitch_in
			    : VALIDATE_PITCH_RATIO * row->prop_diameter_in;
			s->given[SPECF_LOCK_PROP] = true;
			s->given[SPECF_LOCK_DIAMETER_IN] = true;
			s->given[SPECF_LOCK_PITCH_IN] = true;
			if (!in_range(SPECF_LOCK_DIAMETER_IN, s->locks.locked_diameter_in))
				return out_of_range(fact, "prop_diameter_in", row->prop_diameter_in,
				                    SPECF_LOCK_DIAMETER_IN, s->locks.locked_diameter_in);
			if (!in_range(SPECF_LOCK_PITCH_IN, s->locks.locked_pitch_in))
				return out_of_range(fact, row->has_prop_pitch_in ? "prop_pitch_in"
				                    : "prop_diameter_in", row->has_prop_pitch_in ?
				                    row->prop_pitch_in : row->prop_diameter_in,
				                    SPECF_LOCK_PITCH_IN, s->locks.locked_pitch_in);
		} else {
			nt |= VALIDATE_NOTE_PROP_OVER;
		}
	}

	/* Chemistry. */
	const char *chem = row->battery_chemistry[0] ? find_chem(md, row->battery_chemistry) : NULL;
	if (chem != NULL) {
		set_chem(s, chem);
	} else if (strcasecmp(row->battery_chemistry, "Li-ion") == 0 &&
	    (chem = find_chem(md, "Li-ion NMC")) != NULL) {
		set_chem(s, chem);
		nt |= VALIDATE_NOTE_CHEM_FAMILY;
	} else {
		set_chem(s, "LiHV");
		nt |= VALIDATE_NOTE_CHEM_DEFAULT;
	}

	if (row->has_battery_pack_count) {
		s->battery_pack_count = row->battery_pack_count;
		s->given[SPECF_BATTERY_PACK_COUNT] = true;
		if (!in_range(SPECF_BATTERY_PACK_COUNT, row->battery_pack_count))
			return out_of_range(fact, "battery_pack_count", row->battery_pack_count,
			                    SPECF_BATTERY_PACK_COUNT, row->battery_pack_count);
	}
	if (row->has_cell_count) {
		s->nominal_cell_count = row->cell_count;
		s->given[SPECF_NOMINAL_CELL_COUNT] = true;
		if (!in_range(SPECF_NOMINAL_CELL_COUNT, row->cell_count))
			return out_of_range(fact, "cell_count", row->cell_count,
			                    SPECF_NOMINAL_CELL_COUNT, row->cell_count);
	}

	/* The published pack, locked under VALIDATE_PACK_LOCKED. */
	if (rule == VALIDATE_PACK_LOCKED && row->has_cell_count
	    && row->has_battery_capacity_mah) {
		int packs = row->has_battery_pack_count ? row->battery_pack_count : 1;
		s->locks.is_battery_locked = true;
		s->locks.locked_cell_count = row->cell_count;
		s->locks.locked_capacity_mah = row->battery_capacity_mah * packs;
		s->given[SPECF_LOCK_BATTERY] = true;
		s->given[SPECF_LOCK_CELL_COUNT] = true;
		s->given[SPECF_LOCK_CAPACITY_MAH] = true;
		nt |= VALIDATE_NOTE_PACK_LOCKED;
		if (!in_range(SPECF_LOCK_CAPACITY_MAH, s->locks.locked_capacity_mah))
			return out_of_range(fact, "battery_capacity_mah", row->battery_capacity_mah,
			                    SPECF_LOCK_CAPACITY_MAH, s->locks.locked_capacity_mah);
		if (!in_range(SPECF_LOCK_CELL_COUNT, row->cell_count))
			return out_of_range(fact, "cell_count", row->cell_count,
			                    SPECF_LOCK_CELL_COUNT, row->cell_count);
	}

	/* Endurance: the manufacturer's to-empty time brought to the engine's
	 * reserve convention, flown as the maker flew it: a hover time in
	 * hover; a maximum flight time in level flight at the published
	 * cruise speed, else at the minimum-power speed. */
	s->t_climb_s = 0.0;
	s->t_hover_s = 0.0;
	s->t_forward_s = 0.0;
	s->given[SPECF_T_HOVER_S] = true;
	s->given[SPECF_T_CLIMB_S] = true;
	s->given[SPECF_T_FORWARD_S] = true;
	if (row->has_hover_time_min) {
		s->t_hover_s = row->hover_time_min * 60.0 / SIZING_CAP_MARGIN;
		if (!in_range(SPECF_T_HOVER_S, s->t_hover_s))
			return out_of_range(fact, "hover_time_min", row->hover_time_min,
			                    SPECF_T_HOVER_S, s->t_hover_s);
	} else {
		nt |= VALIDATE_NOTE_MAX_FLIGHT;
		s->t_forward_s = row->max_flight_time_min * 60.0 / SIZING_CAP_MARGIN;
		if (!in_range(SPECF_T_FORWARD_S, s->t_forward_s))
			return out_of_range(fact, "max_flight_time_min", row->max_flight_time_min,
			                    SPECF_T_FORWARD_S, s->t_forward_s);
		if (row->has_cruise_speed_ms) {
			s->v_forward_ms = row->cruise_speed_ms;
			s->v_forward_auto = false;
			if (!in_range(SPECF_V_FORWARD_MS, s->v_forward_ms))
				return out_of_range(fact, "cruise_speed_ms", row->cruise_speed_ms,
				                    SPECF_V_FORWARD_MS, s->v_forward_ms);
		} else {
			s->v_forward_auto = true;
		}
		s->given[SPECF_V_FORWARD_MS] = true;
	}

	*notes = nt;
	return VALIDATE_SKIP_NONE;
}

void
validate_forward(const struct cohort_row *row, const struct mission_spec *pack_spec,
                 const struct model_data *md, struct validate_forward *out)
{
	memset(out, 0, sizeof *out);
	out->hover_pub_s = row->has_hover_time_min ? 60.0 * row->hover_time_min : 0.0;
	out->max_pub_s = row->has_max_flight_time_min ? 60.0 * row->max_flight_time_min : 0.0;
	if (!pack_spec->locks.is_battery_locked || (row->has_role && row->role == ROLE_RACING)
	    || !(out->hover_pub_s > 0.0 || out->max_pub_s > 0.0))
		return;
	struct sizing_endurance e;
	if (!engine_endurance_at_mass(pack_spec, md, row->takeoff_mass_kg, 1.0,
	    row->has_cruise_speed_ms ? row->cruise_speed_ms : 0.0, &e))
		return;
	out->valid = true;
	out->hover_model_s = out->hover_pub_s > 0.0 ? e.hover_s : 0.0;
	out->max_model_s = out->max_pub_s > 0.0 ? e.forward_s : 0.0;
	out->speed_ms = e.forward_speed_ms;
}

void
validate_solve_row(const struct mission_spec *spec, const struct model_data *md,
                   struct solve_result *work, struct validate_row *vr)
{
	memset(work, 0, sizeof *work);
	work->skip_ceiling = true; /* a row that does not size is listed so */
	int rc = engine_solve(spec, md, NULL, work);
	const struct res_run *o = &work->custom;
	vr->predicted_kg = 0.0;
	vr->feasible = false;
	vr->cells = 0;
	vr->capacity_mah = 0.0;
	vr->thrust_to_weight = 0.0;
	if (rc != 0 || !o->ran || !isfinite(o->mass.total_kg) || !(o->mass.total_kg > 0.0)) {
		vr->status = VALIDATE_ROW_NOT_RUN;
		return;
	}
	vr->predicted_kg = o->mass.total_kg;
	vr->feasible = work->feasible;
	vr->cells = o->cell_count;
	vr->capacity_mah = o->capacity_mah;
	vr->thrust_to_weight = o->thrust_to_weight;
	vr->battery_pred_kg = o->mass.battery_kg;
	vr->lipschitz = o->lipschitz;
	vr->dry_pred_kg = o->mass.total_kg - o->mass.payload_kg - o->mass.battery_kg;
	vr->status = o->converged ? VALIDATE_ROW_OK : VALIDATE_ROW_NOT_CONVERGED;
}

void
validate_report_free(struct validate_report *v)
{
	if (v == NULL)
		return;
	free(v->rows);
	free(v->by_class);
	memset(v, 0, sizeof *v);
}

int
validate_cohort(const struct cohort *c, const struct model_data *md,
                enum validate_rule rule, struct validate_report *out)
{
	memset(out, 0, sizeof *out);
	out->rule = rule;
	out->n_rows = c->n_rows;
	out->rows = xcalloc(c->n_rows ? c->n_rows : 1, sizeof *out->rows);
	struct solve_result *work = xmalloc(sizeof *work);
	const struct model_accuracy *acc = &md->cal.accuracy[rule == VALIDATE_PACK_LOCKED
	    ? MODEL_PACK_LOCKED : MODEL_FROM_ENDURANCE];
	out->has_interval = acc->valid;
	out->interval_level = acc->level;
	double open_dry = 0.0, open_batt = 0.0, fw_ape = 0.0;
	for (size_t i = 0; i < c->n_rows; i++) {
		struct validate_row *vr = &out->rows[i];
		const struct cohort_row *row = &c->rows[i];
		vr->index = i;
		vr->actual_kg = row->takeoff_mass_kg;
		vr->skip = validate_mission_explained(row, md, rule, &vr->spec, &vr->notes, &vr->fact);
		struct mission_spec pack;
		unsigned pack_notes;
		if (validate_mission_explained(row, md, VALIDATE_PACK_LOCKED, &pack,
		    &pack_notes, NULL) == VALIDATE_SKIP_NONE) {
			validate_forward(row, &pack, md, &vr->forward);
			const struct validate_forward *f = &vr->forward;
			if (f->valid) {
				out->n_forward_rows++;
				if (f->hover_pub_s > 0.0) {
					fw_ape += fabs(f->hover_model_s / f->hover_pub_s - 1.0);
					out->n_forward_figures++;
				}
				if (f->max_pub_s > 0.0) {
					fw_ape += fabs(f->max_model_s / f->max_pub_s - 1.0);
					out->n_forward_figures++;
				}
			}
		}
		if (vr->skip != VALIDATE_SKIP_NONE) {
			vr->status = VALIDATE_ROW_SKIPPED;
			continue;
		}
		validate_solve_row(&vr->spec, md, work, vr);
		if (vr->status != VALIDATE_ROW_OK) {
			vr->battery_pred_kg = 0.0;
			continue;
		}
		vr->err_pct = 100.0 * (vr->predicted_kg - vr->actual_kg) / vr->actual_kg;
		vr->k = vr->actual_kg / vr->predicted_kg;
		if (acc->valid) {
			const struct model_interval *iv = model_interval_for(acc,
			    vr->spec.airframe_class);
			double r = log(vr->actual_kg / vr->predicted_kg);
			vr->inside = r >= iv->log_lo && r <= iv->log_hi;
			out->n_inside += vr->inside;
		}
		/* The loop's slope at the real mass: whether the real aircraft
		 * is a fixed point the loop can reach (docs/validation.md). */
		struct sizing_open lo, hi;
		double m = row->takeoff_mass_kg;
		if (engine_at_mass(&vr->spec, md, 0.99 * m, 0.0, &lo)
		    && engine_at_mass(&vr->spec, md, 1.01 * m, lo.prop_frac, &hi))
			vr->slope_at_real = (hi.mass.total_kg - lo.mass.total_kg) / (0.02 * m);
		/* Open loop at the real mass, where the dry mass is known. */
		struct sizing_open o;
		double dry = row->takeoff_mass_kg - row->payload_kg
		    - (row->has_battery_mass_kg ? row->battery_mass_kg : 0.0);
		if (row->has_battery_mass_kg && dry > 0.0
		    && engine_at_mass(&vr->spec, md, row->takeoff_mass_kg, 0.0, &o)) {
			open_dry += fabs(o.dry_kg / dry - 1.0);
			open_batt += fabs(o.mass.battery_kg / row->battery_mass_kg - 1.0);
			out->n_open++;
		}
		if (row->has_battery_mass_kg && vr->battery_pred_kg > 0.0) {
			vr->has_battery = true;
			vr->battery_actual_kg = row->battery_mass_kg;
			vr->battery_err_pct = 100.0 * (vr->battery_pred_kg - row->battery_mass_kg)
			    / row->battery_mass_kg;
		}
	}
	free(work);
	out->forward_mape_pct = out->n_forward_figures > 0
	    ? 100.0 * fw_ape / (double)out->n_forward_figures : 0.0;
	if (out->n_open > 0) {
		out->open_dry_mape_pct = 100.0 * open_dry / (double)out->n_open;
		out->open_battery_mape_pct = 100.0 * open_batt / (double)out->n_open;
	}
	return validate_summarize(c, out);
}

int
validate_summarize(const struct cohort *c, struct validate_report *out)
{
	free(out->by_class);
	out->by_class = NULL;
	out->n_classes = 0;
	/* Parallel arrays over the rows that count. */
	size_t n = out->n_rows ? out->n_rows : 1;
	double *a = xmalloc(n * sizeof *a), *p = xmalloc(n * sizeof *p);
	double *ba = xmalloc(n * sizeof *ba), *bp = xmalloc(n * sizeof *bp);
	const char **keys = xmalloc(n * sizeof *keys);
	size_t m = 0, nb = 0;
	for (size_t i = 0; i < out->n_rows; i++) {
		const struct validate_row *vr = &out->rows[i];
		if (vr->status != VALIDATE_ROW_OK)
			continue;
		a[m] = vr->actual_kg;
		p[m] = vr->predicted_kg;
		keys[m] = validate_class_key(&c->rows[i]);
		m++;
		if (vr->has_battery) {
			ba[nb] = vr->battery_actual_kg;
			bp[nb] = vr->battery_pred_kg;
			nb++;
		}
	}
	out->n_ok = m;
	int rc = 0;
	if (stats_summarize(a, p, m, &out->mtow) != 0 ||
	    stats_bootstrap_mape_ci(a, p, m, VALIDATE_BOOT_RESAMPLES, VALIDATE_BOOT_SEED,
	        &out->ci_lo_pct, &out->ci_hi_pct) != 0 ||
	    stats_group_mape(keys, a, p, m, &out->by_class, &out->n_classes) != 0 ||
	    stats_summarize(ba, bp, nb, &out->battery) != 0)
		rc = -1;
	free(a);
	free(p);
	free(ba);
	free(bp);
	free(keys);
	return rc;
}
