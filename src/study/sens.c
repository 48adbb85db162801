/* sens.c — the 14-parameter sensitivity suite and the shedding study
 * (see sens.h). */
#include "study/sens.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <pthread.h>
#include <unistd.h>

#include "physics/aero.h"
#include "engine/engine.h"
#include "util/units.h"
#include "util/xalloc.h"

const struct sens_param_info sens_params[SENS_N_PARAMS] = {
	[SENS_PAYLOAD]    = { "payload", "Payload mass", "kg", 1.0, "kg", -1 },
	[SENS_DIAM_LIMIT] = { "prop_diameter_limit", "Propeller diameter limit", "in",
	                      1.0, "in", -1 },
	[SENS_V_FORWARD]  = { "forward_speed", "Forward speed", "m/s", 1.0, "m/s", -1 },
	[SENS_V_CLIMB]    = { "climb_speed", "Climb speed", "m/s", 1.0, "m/s", -1 },
	[SENS_ALTITUDE]   = { "altitude", "Altitude", "m", 1000.0, "1000 m", -1 },
	[SENS_AMBIENT]    = { "ambient_temperature", "Ambient temperature", "°C", 10.0,
	                      "10 °C", -1 },
	[SENS_AUX_POWER]  = { "aux_power", "Aux power", "W", 10.0, "10 W", -1 },
	[SENS_DRAG_AREA]  = { "added_drag_area", "Added drag area", "m²", 0.1, "0.1 m²",
	                      -1 },
	[SENS_CG_SHIFT]   = { "cg_shift", "Centre of gravity shift", "m", 0.05, "5 cm",
	                      -1 },
	[SENS_BATT_LOCK]  = { "battery_capacity_lock", "Battery capacity lock", "mAh",
	                      1000.0, "1000 mAh", -1 },
	[SENS_PROP_LOCK]  = { "prop_diameter_lock", "Propeller diameter lock", "in",
	                      1.0, "in", -1 },
	[SENS_DROP_MASS]  = { "delivery_drop_mass", "Delivery drop mass", "kg", 1.0,
	                      "kg", ROLE_DELIVERY },
	[SENS_DROP_RATIO] = { "delivery_drop_time_ratio", "Delivery drop time ratio", "",
	                      0.1, "0.1 ratio", ROLE_DELIVERY },
	[SENS_SPRAY_RATE] = { "spray_rate", "Spray rate", "kg/s", 0.005, "0.005 kg/s",
	                      ROLE_AGRICULTURE },
};

const char *
sens_status_name(enum sens_status s)
{
	static const char *const names[] = { "ok", "infeasible", "not_converged",
		"runaway", "gate", "error" };
	return (unsigned)s < sizeof names / sizeof names[0] ? names[s] : "error";
}

/* The spec after the requirements layer and the role/class defaults: the
 * values the engine actually used. */
static void
resolved(const struct mission_spec *spec, const struct model_data *md,
         struct mission_spec *out)
{
	*out = *spec;
	engine_resolve(out, md, NULL);
}

/* Prop-diameter limit per metre of wheelbase: the overlap limit is linear
 * in W, so the limit in inches maps back to a wheelbase exactly. */
static double
limit_per_wheelbase(const struct mission_spec *rs)
{
	int arms = rs->coaxial_layout ? rs->num_rotors / 2 : rs->num_rotors;
	if (arms < 3)
		arms = 3;
	return aero_overlap_limit_m(1.0, arms, AERO_TIP_CLEARANCE);
}

/* Solves s once into the caller's scratch result. */
static int
solve(const struct mission_spec *s, const struct model_data *md,
      struct solve_result *r)
{
	memset(r, 0, sizeof *r);
	r->skip_ceiling = true; /* a point is classified, not explained */
	return engine_solve(s, md, NULL, r);
}

/* Keeps the custom run's checks that have a limit; the smallest margin is
 * the point's margin. */
static void
keep_checks(const struct res_run *o, struct sens_point *pt)
{
	for (int i = 0; i < o->n_checks && pt->n_checks < SENS_MAX_CHECKS; i++) {
		const struct res_check *c = &o->checks[i];
		if (c->limit == 0.0 || !isfinite(c->margin))
			continue;
		int k = pt->n_checks++;
		snprintf(pt->check_name[k], sizeof pt->check_name[k], "%s", c->name);
		pt->check_margin[k] = c->margin;
		if (!pt->has_margin || c->margin < pt->margin)
			pt->margin = c->margin;
		pt->has_margin = true;
	}
}

/* Classifies the custom run of r into *pt. */
static void
classify(const struct solve_result *r, int rc, double x, struct sens_point *pt)
{
	const struct res_run *o = &r->custom;
	memset(pt, 0, sizeof *pt);
	pt->x = x;
	const char *code = "";
	for (int i = 0; i < r->n_violations; i++)
		if (strcmp(r->violations[i].run, "custom") == 0) {
			code = r->violations[i].code;
			break;
		}
	bool runaway = false, noconv = false;
	for (int i = 0; i < r->n_violations; i++) {
		if (strcmp(r->violations[i].run, "custom") != 0)
			continue;
		runaway |= strcmp(r->violations[i].code, "MASS_RUNAWAY") == 0;
		noconv |= strcmp(r->violations[i].code, "NOT_CONVERGED") == 0;
	}
	if (rc != 0)
		pt->status = SENS_ERROR;
	else if (!o->ran)
		pt->status = SENS_GATE;
	else if (runaway)
		pt->status = SENS_RUNAWAY;
	else if (noconv || !o->converged)
		pt->status = SENS_NOT_CONVERGED;
	else if (!o->feasible)
		pt->status = SENS_INFEASIBLE;
	else
		pt->status = SENS_OK;
	snprintf(pt->reason, sizeof pt->reason, "%s",
	    pt->status == SENS_OK ? "" : code[0] ? code : sens_status_name(pt->status));
	if (o->ran && pt->status != SENS_ERROR) {
		pt->mtow_kg = o->mass.total_kg;
		pt->hover_endurance_s = o->hover_endurance_s;
		pt->flight_time_s = o->flight_time_s;
		if (!isfinite(pt->mtow_kg) || !isfinite(pt->hover_endurance_s)
		    || !isfinite(pt->flight_time_s)) {
			pt->status = SENS_ERROR;
			pt->mtow_kg = pt->hover_endurance_s = pt->flight_time_s = 0.0;
		}
	}
	if (o->ran && o->converged && pt->status != SENS_ERROR)
		keep_checks(o, pt);
}

/* The spec a sweep of id starts from: the mission with the role the
 * parameter needs, and for the lock parameters the lock switched on at the
 * nominal design (cells and pitch from the nominal custom run). */
static bool
prepare(const struct mission_spec *spec, const struct model_data *md,
        enum sens_param id, struct mission_spec *out, struct solve_result *r,
        int *n_solves)
{
	struct mission_spec rs;
	bool substituted = false;
	*out = *spec;
	resolved(spec, md, &rs);
	int need = sens_params[id].role;
	if (need >= 0 && rs.payload_role.type != need) {
		out->payload_role.type = need;
		out->given[SPECF_ROLE_TYPE] = true;
		substituted = true;
	}
	bool solved = false;
	int rc = 0;
	struct spec_locks *lk = &out->locks;
	if ((id == SENS_BATT_LOCK && !lk->is_battery_locked)
	    || (id == SENS_PROP_LOCK && !lk->is_prop_locked)) {
		if (!solved) {
			rc = solve(out, md, r);
			if (n_solves)
				(*n_solves)++;
		}
		const struct res_run *o = &r->custom;
		if (rc == 0 && o->ran && o->capacity_mah > 0.0 && o->cell_count > 0
		    && o->opt.prop_diameter_in > 0.0) {
			if (id == SENS_BATT_LOCK) {
				lk->is_battery_locked = true;
				lk->locked_capacity_mah = o->capacity_mah;
				lk->locked_cell_count = o->cell_count;
				out->given[SPECF_LOCK_BATTERY] = true;
				out->given[SPECF_LOCK_CAPACITY_MAH] = true;
				out->given[SPECF_LOCK_CELL_COUNT] = true;
			} else {
				lk->is_prop_locked = true;
				lk->locked_diameter_in = o->opt.prop_diameter_in;
				lk->locked_pitch_in = o->opt.prop_pitch_in;
				out->given[SPECF_LOCK_PROP] = true;
				out->given[SPECF_LOCK_DIAMETER_IN] = true;
				out->given[SPECF_LOCK_PITCH_IN] = true;
			}
		}
	}
	return substituted;
}

/* Writes x into the prepared spec s (in place). */
static void
set_x(struct mission_spec *s, const struct model_data *md, enum sens_param id,
      double x)
{
	struct spec_role *pr = &s->payload_role;
	switch (id) {
	case SENS_PAYLOAD:
		s->payload_kg = x;
		s->given[SPECF_PAYLOAD_KG] = true;
		break;
	case SENS_DIAM_LIMIT: {
		struct mission_spec rs;
		resolved(s, md, &rs);
		s->max_diameter_m = in_to_m(x) / limit_per_wheelbase(&rs);
		s->given[SPECF_MAX_DIAMETER_M] = true;
		break;
	}
	case SENS_V_FORWARD:
		s->v_forward_ms = x;
		s->v_forward_auto = false;
		s->given[SPECF_V_FORWARD_MS] = true;
		break;
	case SENS_V_CLIMB:
		s->v_climb_ms = x;
		s->given[SPECF_V_CLIMB_MS] = true;
		break;
	case SENS_ALTITUDE:
		/* Ambient stays derived (ISA at the new altitude) unless the
		 * mission fixed it. */
		s->altitude_m = x;
		s->given[SPECF_ALTITUDE_M] = true;
		break;
	case SENS_AMBIENT:
		s->ambient_temp_c = x;
		s->given[SPECF_AMBIENT_TEMP_C] = true;
		break;
	case SENS_AUX_POWER:
		pr->aux_power_w = x;
		s->given[SPECF_ROLE_AUX_POWER_W] = true;
		break;
	case SENS_DRAG_AREA:
		pr->added_drag_m2 = x;
		s->given[SPECF_ROLE_ADDED_DRAG_M2] = true;
		break;
	case SENS_CG_SHIFT:
		pr->cg_shift_m = x;
		s->given[SPECF_ROLE_CG_SHIFT_M] = true;
		break;
	case SENS_BATT_LOCK:
		s->locks.locked_capacity_mah = x;
		s->given[SPECF_LOCK_CAPACITY_MAH] = true;
		break;
	case SENS_PROP_LOCK:
		/* Pitch follows the diameter at the nominal pitch/diameter ratio:
		 * a locked pitch on a much smaller prop is not a design anyone
		 * would fly. */
		if (s->locks.locked_diameter_in > 0.0)
			s->locks.locked_pitch_in *= x / s->locks.locked_diameter_in;
		s->locks.locked_diameter_in = x;
		s->given[SPECF_LOCK_DIAMETER_IN] = true;
		s->given[SPECF_LOCK_PITCH_IN] = true;
		break;
	case SENS_DROP_MASS:
		pr->delivery_drop_mass_kg = x;
		s->given[SPECF_ROLE_DROP_MASS_KG] = true;
		break;
	case SENS_DROP_RATIO:
		pr->delivery_drop_time_ratio = x;
		s->given[SPECF_ROLE_DROP_TIME_RATIO] = true;
		break;
	case SENS_SPRAY_RATE:
		pr->spray_rate_kg_per_s = x;
		s->given[SPECF_ROLE_SPRAY_RATE] = true;
		break;
	case SENS_N_PARAMS:
		break;
	}
}

/* One point on a prepared spec. */
static void
eval_prepared(const struct mission_spec *prep, const struct model_data *md,
              enum sens_param id, double x, struct solve_result *r,
              struct sens_point *pt)
{
	struct mission_spec s = *prep;
	set_x(&s, md, id, x);
	int rc = solve(&s, md, r);
	classify(r, rc, x, pt);
}

/* Mission time a spray spreads the payload over when the rate is auto and
 * the nominal design gives none. */
static double
mission_time_s(const struct mission_spec *rs)
{
	return rs->t_climb_s + rs->t_forward_s + rs->t_hover_s;
}

/* x0 on a prepared spec; r is scratch.  The forward speed of an "auto"
 * mission is the minimum-power speed the nominal design flies. */
static double
nominal_prepared(const struct mission_spec *prep, const struct model_data *md,
                 enum sens_param id, struct solve_result *r, int *n_solves)
{
	struct mission_spec rs;
	resolved(prep, md, &rs);
	const struct spec_role *pr = &rs.payload_role;
	switch (id) {
	case SENS_PAYLOAD: return rs.payload_kg;
	case SENS_DIAM_LIMIT: return m_to_in(rs.max_diameter_m * limit_per_wheelbase(&rs));
	case SENS_V_FORWARD:
		if (!rs.v_forward_auto)
			return rs.v_forward_ms;
		solve(prep, md, r);
		if (n_solves)
			(*n_solves)++;
		return r->custom.ran && r->custom.optimal_speed_ms > 0.0
		    ? r->custom.optimal_speed_ms : rs.v_forward_ms;
	case SENS_V_CLIMB: return rs.v_climb_ms;
	case SENS_ALTITUDE: return rs.altitude_m;
	case SENS_AMBIENT: return rs.ambient_temp_c;
	case SENS_AUX_POWER: return pr->aux_power_w;
	case SENS_DRAG_AREA: return pr->added_drag_m2;
	case SENS_CG_SHIFT: return pr->cg_shift_m;
	case SENS_BATT_LOCK: return rs.locks.locked_capacity_mah;
	case SENS_PROP_LOCK: return rs.locks.locked_diameter_in;
	case SENS_DROP_MASS: return pr->delivery_drop_mass_kg;
	case SENS_DROP_RATIO: return pr->delivery_drop_time_ratio;
	case SENS_SPRAY_RATE: {
		if (pr->spray_rate_kg_per_s > 0.0)
			return pr->spray_rate_kg_per_s;
		/* "Auto" empties the tank over the passes the nominal design
		 * flies (its duty profile), else over the mission. */
		solve(prep, md, r);
		if (n_solves)
			(*n_solves)++;
		if (r->custom.ran && r->custom.duty.spray_rate_kg_s > 0.0)
			return r->custom.duty.spray_rate_kg_s;
		double t = mission_time_s(&rs);
		return t > 0.0 && rs.payload_kg > 0.0 ? rs.payload_kg / t : 0.005;
	}
	case SENS_N_PARAMS: break;
	}
	return 0.0;
}

/* Hard bounds of x: the mission table's ranges, and physics (a drop of more
 * than the payload, a spray rate of 0 = "auto"). */
static void
bounds(const struct mission_spec *rs, enum sens_param id, double *lo, double *hi)
{
	*lo = -INFINITY;
	*hi = INFINITY;
	switch (id) {
	case SENS_PAYLOAD: *lo = 0.0; *hi = 500.0; break;
	case SENS_DIAM_LIMIT: *lo = 0.5; *hi = m_to_in(5.0 * limit_per_wheelbase(rs)); break;
	case SENS_V_FORWARD: *lo = 1.0; *hi = 40.0; break;
	case SENS_V_CLIMB: *lo = 0.1; *hi = 20.0; break;
	case SENS_ALTITUDE: *lo = 0.0; *hi = 20000.0; break;
	case SENS_AMBIENT: *lo = -40.0; *hi = 55.0; break;
	case SENS_AUX_POWER: *lo = 0.0; *hi = 5000.0; break;
	case SENS_DRAG_AREA: *lo = 0.0; *hi = 5.0; break;
	case SENS_CG_SHIFT: *lo = 0.0; *hi = 5.0; break;
	case SENS_BATT_LOCK: *lo = 50.0; *hi = 500000.0; break;
	case SENS_PROP_LOCK: *lo = 1.0; *hi = 80.0; break;
	case SENS_DROP_MASS: *lo = 0.0; *hi = rs->payload_kg; break;
	case SENS_DROP_RATIO: *lo = 0.0; *hi = 1.0; break;
	case SENS_SPRAY_RATE: *lo = 1e-4; *hi = 20.0; break;
	case SENS_N_PARAMS: break;
	}
}

/* The suite's default range and point count around x0. */
static void
default_range(const struct mission_spec *rs, enum sens_param id, double x0,
              double *lo, double *hi, int *n)
{
	double w = rs->max_diameter_m;
	double d;
	switch (id) {
	case SENS_PAYLOAD:
		*lo = x0 > 0.0 ? 0.5 * x0 : 0.0;
		*hi = x0 > 0.0 ? 1.5 * x0 : 1.0;
		*n = 11;
		break;
	case SENS_DIAM_LIMIT:
		*lo = 0.7 * x0; *hi = 1.3 * x0; *n = 13;
		break;
	case SENS_V_FORWARD:
		/* Wide on purpose: the paper's divergence lies near 25.5 m/s. */
		*lo = fmax(1.0, 0.25 * x0); *hi = fmax(30.0, 1.5 * x0); *n = 15;
		break;
	case SENS_V_CLIMB:
		*lo = 0.5 * x0; *hi = 2.0 * x0; *n = 11;
		break;
	case SENS_ALTITUDE:
		*lo = 0.0; *hi = fmax(5000.0, x0 + 1000.0); *n = 11;
		break;
	case SENS_AMBIENT:
		*lo = x0 - 30.0; *hi = x0 + 30.0; *n = 13;
		break;
	case SENS_AUX_POWER:
		d = fmax(50.0, 0.5 * x0);
		*lo = x0 - d; *hi = x0 + d; *n = 11;
		break;
	case SENS_DRAG_AREA:
		/* 0.1 m² (the paper's step) on a large aircraft, less on a small
		 * one whose whole frontal area is a few hundredths of that. */
		d = fmax(x0, fmin(0.1, 0.1 * w * w));
		*lo = x0 - d; *hi = x0 + d; *n = 11;
		break;
	case SENS_CG_SHIFT:
		*lo = x0 - 0.1 * w; *hi = x0 + 0.4 * w; *n = 13;
		break;
	case SENS_BATT_LOCK:
		*lo = 0.5 * x0; *hi = 1.5 * x0; *n = 11;
		break;
	case SENS_PROP_LOCK:
		/* Beyond the nominal prop, which is usually the overlap limit:
		 * the sweep shows the gate closing. */
		*lo = 0.6 * x0; *hi = 1.1 * x0; *n = 11;
		break;
	case SENS_DROP_MASS:
		*lo = 0.0; *hi = fmax(rs->payload_kg, 1e-3); *n = 11;
		break;
	case SENS_DROP_RATIO:
		*lo = 0.0; *hi = 1.0; *n = 11;
		break;
	case SENS_SPRAY_RATE:
		*lo = 0.5 * x0; *hi = 2.0 * x0; *n = 13;
		break;
	case SENS_N_PARAMS:
		*lo = *hi = x0; *n = 2;
		break;
	}
}

static bool
good(const struct sens_point *p)
{
	return p->status == SENS_OK;
}

/* A converged design, feasible or not: its MTOW is a real number to
 * differentiate (an agricultural mission over its downwash cap still has a
 * mass sensitivity). */
static bool
usable(const struct sens_point *p)
{
	return p->status == SENS_OK || p->status == SENS_INFEASIBLE;
}

/* Where the good region ends between last (good) and bad. */
static double
crossing(const struct sens_point *last, const struct sens_point *bad)
{
	int worst = -1;
	for (int i = 0; i < bad->n_checks; i++)
		if (bad->check_margin[i] < 0.0
		    && (worst < 0 || bad->check_margin[i] < bad->check_margin[worst]))
			worst = i;
	for (int j = 0; worst >= 0 && j < last->n_checks; j++) {
		if (strcmp(last->check_name[j], bad->check_name[worst]) != 0)
			continue;
		double a = last->check_margin[j], b = bad->check_margin[worst];
		if (a >= 0.0 && a > b) {
			double t = a / (a - b);
			return last->x + t * (bad->x - last->x);
		}
		break;
	}
	return 0.5 * (last->x + bad->x);
}

/* Finite differences in the paper's units from two points. */
static void
differences(struct sens_curve *c, const struct sens_point *a,
            const struct sens_point *b)
{
	double dx = b->x - a->x;
	double k = sens_params[c->id].step / dx;
	c->d_mtow = (b->mtow_kg - a->mtow_kg) * k;
	c->d_hover_min = (b->hover_endurance_s - a->hover_endurance_s) / S_PER_MIN * k;
	c->d_flight_min = (b->flight_time_s - a->flight_time_s) / S_PER_MIN * k;
}

/* Crossings and the good run around x0 (needs the grid and the nominal). */
static void
edges(struct sens_curve *c)
{
	const struct sens_point *last = &c->nominal;
	c->x_good_lo = c->x_good_hi = c->x0;
	c->mtow_good_lo_kg = c->mtow_good_hi_kg = c->nominal.mtow_kg;
	if (!good(&c->nominal))
		return;
	for (int i = c->n - 1; i >= 0; i--) {
		const struct sens_point *p = &c->pt[i];
		if (p->x >= c->x0)
			continue;
		if (!good(p)) {
			c->cross_lo = true;
			c->x_cross_lo = crossing(last, p);
			snprintf(c->why_lo, sizeof c->why_lo, "%s", p->reason);
			break;
		}
		last = p;
	}
	c->x_good_lo = last->x;
	c->mtow_good_lo_kg = last->mtow_kg;
	last = &c->nominal;
	for (int i = 0; i < c->n; i++) {
		const struct sens_point *p = &c->pt[i];
		if (p->x <= c->x0)
			continue;
		if (!good(p)) {
			c->cross_hi = true;
			c->x_cross_hi = crossing(last, p);
			snprintf(c->why_hi, sizeof c->why_hi, "%s", p->reason);
			break;
		}
		last = p;
	}
	c->x_good_hi = last->x;
	c->mtow_good_hi_kg = last->mtow_kg;
}

static void
sweep_scratch(const struct mission_spec *spec, const struct model_data *md,
              enum sens_param id, double lo, double hi, int n,
              struct sens_curve *c, int *n_solves, struct solve_result *r)
{
	int solves = 0;
	struct mission_spec prep, rs;
	memset(c, 0, sizeof *c);
	c->id = id;
	c->role_substituted = prepare(spec, md, id, &prep, r, &solves);
	resolved(&prep, md, &rs);
	c->x0 = nominal_prepared(&prep, md, id, r, &solves);

	double blo, bhi;
	bounds(&rs, id, &blo, &bhi);
	if (lo == 0.0 && hi == 0.0)
		default_range(&rs, id, c->x0, &lo, &hi, &n);
	lo = fmax(lo, blo);
	hi = fmin(hi, bhi);
	if (n < 2)
		n = 2;
	if (n > SENS_MAX_POINTS)
		n = SENS_MAX_POINTS;
	if (!(hi > lo))
		hi = lo + 1e-9;

	eval_prepared(&prep, md, id, c->x0, r, &c->nominal);
	solves++;
	c->n = n;
	for (int i = 0; i < n; i++) {
		double x = lo + (hi - lo) * (double)i / (double)(n - 1);
		eval_prepared(&prep, md, id, x, r, &c->pt[i]);
		solves++;
	}

	/* Derivatives: h is the grid step. */
	c->h = (hi - lo) / (double)(n - 1);
	bool can_lo = c->x0 - c->h >= blo - 1e-12;
	bool can_hi = c->x0 + c->h <= bhi + 1e-12;
	c->has_fd_lo = can_lo;
	c->has_fd_hi = can_hi;
	if (can_lo) {
		eval_prepared(&prep, md, id, c->x0 - c->h, r, &c->fd_lo);
		solves++;
	}
	if (can_hi) {
		eval_prepared(&prep, md, id, c->x0 + c->h, r, &c->fd_hi);
		solves++;
	}
	/* Differences across the feasibility boundary mix two regimes, so a
	 * feasible nominal takes feasible neighbours only. */
	bool (*fit)(const struct sens_point *) = good(&c->nominal) ? good : usable;
	bool lo_ok = can_lo && fit(&c->fd_lo), hi_ok = can_hi && fit(&c->fd_hi);
	if (!usable(&c->nominal))
		c->fd_kind = 2;
	else if (lo_ok && hi_ok)
		c->fd_kind = 0;
	else if (hi_ok)
		c->fd_kind = 1;
	else if (lo_ok)
		c->fd_kind = -1;
	else
		c->fd_kind = 2;
	if (c->fd_kind == 0)
		differences(c, &c->fd_lo, &c->fd_hi);
	else if (c->fd_kind == 1)
		differences(c, &c->nominal, &c->fd_hi);
	else if (c->fd_kind == -1)
		differences(c, &c->fd_lo, &c->nominal);
	edges(c);
	if (n_solves)
		*n_solves += solves;
}

void
sens_sweep(const struct mission_spec *spec, const struct model_data *md,
           enum sens_param id, double lo, double hi, int n,
           struct sens_curve *c, int *n_solves)
{
	struct solve_result *r = xmalloc(sizeof *r);
	sweep_scratch(spec, md, id, lo, hi, n, c, n_solves, r);
	free(r);
}

void
sens_eval(const struct mission_spec *spec, const struct model_data *md,
          enum sens_param id, double x, struct sens_point *pt)
{
	struct solve_result *r = xmalloc(sizeof *r);
	struct mission_spec prep;
	prepare(spec, md, id, &prep, r, NULL);
	eval_prepared(&prep, md, id, x, r, pt);
	free(r);
}

double
sens_nominal_x(const struct mission_spec *spec, const struct model_data *md,
               enum sens_param id)
{
	struct solve_result *r = xmalloc(sizeof *r);
	struct mission_spec prep;
	prepare(spec, md, id, &prep, r, NULL);
	double x0 = nominal_prepared(&prep, md, id, r, NULL);
	free(r);
	return x0;
}

static double
now_s(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One worker of sens_run: sweeps i = first, first + stride, ... */
struct sens_worker {
	const struct mission_spec *spec;
	const struct model_data *md;
	struct sens_result *out;
	int solves[SENS_N_PARAMS];   /* per sweep, summed by the caller */
	int first, stride;
};

static void *
sens_worker_main(void *arg)
{
	struct sens_worker *w = arg;
	struct solve_result *r = xmalloc(sizeof *r);
	for (int i = w->first; i < SENS_N_PARAMS; i += w->stride)
		sweep_scratch(w->spec, w->md, (enum sens_param)i, 0.0, 0.0, 0,
		    &w->out->c[i], &w->solves[i], r);
	free(r);
	return NULL;
}

int
sens_run(const struct mission_spec *spec, const struct model_data *md,
         struct sens_result *out)
{
	double t0 = now_s();
	struct solve_result *r = xmalloc(sizeof *r);
	memset(out, 0, sizeof *out);
	snprintf(out->mission, sizeof out->mission, "%s", spec->name);
	struct mission_spec rs;
	resolved(spec, md, &rs);
	out->role = rs.payload_role.type;
	int rc = solve(spec, md, r);
	classify(r, rc, 0.0, &out->nominal);
	free(r);
	out->n_solves = 1;

	/* The sweeps are independent and the engine is reentrant, so they run
	 * on every core; each sweep is computed the same way whichever thread
	 * runs it, so the result does not depend on the thread count. */
	long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
	int nt = ncpu < 1 ? 1 : ncpu > SENS_N_PARAMS ? SENS_N_PARAMS : (int)ncpu;
	struct sens_worker *w = xcalloc((size_t)nt, sizeof *w);
	pthread_t *tid = xcalloc((size_t)nt, sizeof *tid);
	bool *started = xcalloc((size_t)nt, sizeof *started);
	for (int t = 0; t < nt; t++) {
		w[t] = (struct sens_worker){ .spec = spec, .md = md, .out = out,
			.first = t, .stride = nt };
		started[t] = t > 0 && pthread_create(&tid[t], NULL, sens_worker_main,
		    &w[t]) == 0;
	}
	/* Thread 0's share runs here, and so does the share of any thread that
	 * could not be started. */
	sens_worker_main(&w[0]);
	for (int t = 1; t < nt; t++) {
		if (started[t])
			pthread_join(tid[t], NULL);
		else
			sens_worker_main(&w[t]);
	}
	for (int t = 0; t < nt; t++)
		for (int i = 0; i < SENS_N_PARAMS; i++)
			out->n_solves += w[t].solves[i];
	free(started);
	free(tid);
	free(w);
	out->seconds = now_s() - t0;
	return good(&out->nominal) ? 0 : 1;
}

/* ---- shedding ------------------------------------------------------------- */

/* Time-mean aircraft mass over the discharge trace (trapezoids). */
static double
mean_mass_kg(const struct res_run *o)
{
	if (o->n_trace < 2)
		return o->mass.total_kg;
	double area = 0.0, t = 0.0;
	for (int i = 1; i < o->n_trace; i++) {
		double dt = o->trace[i].t_s - o->trace[i - 1].t_s;
		if (!(dt > 0.0))
			continue;
		area += 0.5 * dt * (o->trace[i].mass_kg + o->trace[i - 1].mass_kg);
		t += dt;
	}
	return t > 0.0 ? area / t : o->mass.total_kg;
}

static double
structure_kg(const struct res_mass *m)
{
	return m->frame_kg + m->arm_kg + m->other_kg;
}

void
sens_shedding(const struct mission_spec *stat, const struct mission_spec *dyn,
              const struct model_data *md, struct sens_shedding *out)
{
	struct solve_result *r = xmalloc(sizeof *r);
	struct mission_spec s = stat != NULL ? *stat : *dyn;
	memset(out, 0, sizeof *out);
	if (stat == NULL) {
		s.payload_role.mass_shedding = false;
		s.given[SPECF_ROLE_MASS_SHEDDING] = true;
	}
	int rc = solve(&s, md, r);
	bool ok = rc == 0 && r->custom.ran && r->custom.converged;
	out->mtow_static_kg = r->custom.mass.total_kg;
	out->energy_static_wh = r->custom.energy_wh;
	out->frame_static_kg = structure_kg(&r->custom.mass);

	rc = solve(dyn, md, r);
	ok = ok && rc == 0 && r->custom.ran && r->custom.converged;
	out->mtow_dynamic_kg = r->custom.mass.total_kg;
	out->energy_dynamic_wh = r->custom.energy_wh;
	out->frame_dynamic_kg = structure_kg(&r->custom.mass);
	out->avg_mass_dynamic_kg = mean_mass_kg(&r->custom);
	free(r);

	out->ok = ok && out->energy_static_wh > 0.0 && out->frame_static_kg > 0.0
	    && out->mtow_static_kg > 0.0;
	if (out->ok) {
		out->energy_saving = 1.0 - out->energy_dynamic_wh / out->energy_static_wh;
		out->frame_saving = 1.0 - out->frame_dynamic_kg / out->frame_static_kg;
		out->avg_mass_reduction = 1.0 - out->avg_mass_dynamic_kg / out->mtow_static_kg;
	}
}
