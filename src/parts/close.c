/* close.c — an option closed on real parts: its ESC set and battery, the
 * takeoff mass found again with the real masses, the mission flown on the
 * real drive and every check of the design of record (see parts.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parts/parts_int.h"
#include "parts/screen.h"
#include "physics/aero.h"
#include "physics/mission.h"
#include "physics/therm.h"
#include "sizing/airframe.h"
#include "sizing/feasibility.h"
#include "util/units.h"
#include "util/xalloc.h"

#define CLOSE_MAX_ITER   100     /* takeoff-mass fixed point on real parts */
#define CLOSE_TOL_KG     1e-7
#define FIX_LEN          RES_TEXT

/* ---- pack arrangements ---------------------------------------------------- */

/* The chemistry family of a profile name: packs of one family share their
 * voltages and may replace one another. */
static const char *
chem_family(const char *name)
{
	if (strcmp(name, "LiHV") == 0 || strcmp(name, "LiPo_highvoltage") == 0)
		return "LiHV";
	if (strncmp(name, "LiPo", 4) == 0)
		return "LiPo";
	if (strncmp(name, "Li-ion", 6) == 0)
		return "Li-ion";
	return name;
}

static int
cmp_pack(const void *a, const void *b)
{
	const struct parts_pack *x = a, *y = b;
	int sx = x->b->cells_series * x->series, sy = y->b->cells_series * y->series;
	if (sx != sy)
		return sx < sy ? -1 : 1;
	if (x->mass_kg != y->mass_kg)
		return x->mass_kg < y->mass_kg ? -1 : 1;
	int c = strcmp(x->b->id, y->b->id);
	if (c != 0)
		return c;
	return x->parallel - y->parallel;
}

/* May pack b fly this mission?  The mission's chemistry when it names one
 * (its family), any profile the model knows otherwise; the locks. */
static bool
pack_allowed(const struct parts_ctx *x, const struct catalog_battery *b)
{
	if (!b->usable || model_chem(x->md, b->chemistry) == NULL)
		return false;
	if (x->lock_battery != NULL)
		return b == x->lock_battery;
	char why[256];
	if (screen_battery(b, why, sizeof why) != NULL
	    || screen_doubt_battery(b, why, sizeof why) != NULL)
		return false;
	if (x->spec->given[SPECF_BATTERY_CHEMISTRY]
	    && strcmp(chem_family(b->chemistry),
	    chem_family(x->spec->battery_chemistry)) != 0)
		return false;
	return true;
}

void
parts_packs_init(struct parts_ctx *x)
{
	const struct catalog *cat = x->cat;
	const struct spec_locks *lk = &x->spec->locks;
	size_t nb = catalog_n_batteries(cat);
	size_t cap = nb * PARTS_MAX_SERIES * PARTS_MAX_PARALLEL;
	x->packs = xmalloc((cap ? cap : 1) * sizeof *x->packs);
	x->n_packs = 0;
	for (size_t i = 0; i < nb; i++) {
		const struct catalog_battery *b = catalog_battery(cat, i);
		if (!pack_allowed(x, b))
			continue;
		const struct batt_chem *chem = model_chem(x->md, b->chemistry);
		for (int s = 1; s <= PARTS_MAX_SERIES; s++) {
			int cells = s * b->cells_series;
			if (cells < x->cells_lo || cells > x->cells_hi)
				continue;
			for (int q = 1; q <= PARTS_MAX_PARALLEL
			    && s * q <= PARTS_MAX_PACKS; q++) {
				struct parts_pack *pk = &x->packs[x->n_packs];
				pk->b = b;
				pk->series = s;
				pk->parallel = q;
				pk->chem = chem;
				/* Single cells need a pack built around them
				 * (README: 10-15 % for pack hardware). */
				pk->mass_kg = (double)(s * q) * b->mass_kg
				    * (b->cells_series == 1 ? PARTS_CELL_PACK_FACTOR : 1.0);
				pk->capacity_ah = (double)q * b->capacity_ah;
				pk->energy_wh = (double)cells * chem->v_nom * pk->capacity_ah;
				pk->max_continuous_a = b->continuous_c * pk->capacity_ah;
				pk->max_burst_a = (b->burst_c > b->continuous_c
				    ? b->burst_c : b->continuous_c) * pk->capacity_ah;
				/* The paper's lock: total capacity and cells. */
				if (lk->is_battery_locked && x->lock_battery == NULL
				    && (cells != lk->locked_cell_count
				    || fabs(pk->capacity_ah * 1000.0
				    / lk->locked_capacity_mah - 1.0) > 0.1))
					continue;
				x->n_packs++;
			}
		}
	}
	qsort(x->packs, (size_t)x->n_packs, sizeof *x->packs, cmp_pack);
}

void
parts_packs_free(struct parts_ctx *x)
{
	free(x->packs);
	x->packs = NULL;
	x->n_packs = 0;
}

const struct parts_pack *
parts_packs_for(const struct parts_ctx *x, const struct parts_option *o, int *n)
{
	int first = -1;
	*n = 0;
	for (int i = 0; i < x->n_packs; i++) {
		const struct parts_pack *pk = &x->packs[i];
		if (pk->b->cells_series * pk->series != o->cells)
			continue;
		if (first < 0)
			first = i;
		(*n)++;
	}
	return first >= 0 ? &x->packs[first] : NULL;
}

/* ---- ESC ------------------------------------------------------------------ */

bool
parts_pick_esc(const struct parts_ctx *x, const struct parts_option *o,
               const struct catalog_esc **esc, int *n)
{
	const struct sizing_params *p = x->p;
	*esc = NULL;
	*n = 0;
	if (o->motor->integrated)
		return true;
	/* One motor's currents: the ranking's hover, and full throttle. */
	double hover_a = o->hover_power_w / ((double)o->cells * x->p->chem->v_nom
	    * (double)p->n_rotors);
	bool takes_fc = parts_kit_takes_board_fc(x);
	double best_kg = INFINITY;
	for (size_t i = 0; i < catalog_n_escs(x->cat); i++) {
		const struct catalog_esc *e = catalog_esc(x->cat, i);
		if (!e->usable || (x->lock_esc != NULL && e != x->lock_esc))
			continue;
		bool locked = e == x->lock_esc;
		char why[256];
		if (!locked && (screen_esc(e, why, sizeof why) != NULL
		    || screen_doubt_esc(e, why, sizeof why) != NULL))
			continue;
		/* The ESC class against the motor and the bus (compat.c). */
		if (!locked && compat_esc(e, o->motor, o->cells, hover_a,
		    o->full_current_a, PARTS_CURRENT_MARGIN, PERF_FULL_THROTTLE_S,
		    why, sizeof why) != NULL)
			continue;
		int boards;
		if (e->channels <= 1) {
			boards = p->n_rotors;
		} else {
			/* A multi-channel board sits in the centre stack: small
			 * frames only, and the rotors must fill its channels. */
			if (p->wheelbase_m > PARTS_STACK_MAX_WHEELBASE_M
			    || p->n_rotors % e->channels != 0)
				continue;
			boards = p->n_rotors / e->channels;
		}
		/* An all-in-one board's flight controller flies the aircraft. */
		if (!locked && compat_board_fc(e, boards, takes_fc, why, sizeof why) != NULL)
			continue;
		double kg = (double)boards * e->mass_kg;
		if (kg < best_kg) {
			best_kg = kg;
			*esc = e;
			*n = boards;
		}
	}
	return *esc != NULL;
}

/* ---- closing -------------------------------------------------------------- */

/* The craft's masses at takeoff mass mass_kg: the parts' own, the
 * airframe's for the loads they put on it, the kit's (kit.c). */
static double
craft_masses(const struct sizing_params *q, const struct parts_option *o,
             const struct parts_kit *kit, double fixed_kg, double mass_kg,
             struct perf_craft *c)
{
	double n = (double)q->n_rotors;
	double tip = o->motor->mass_kg + (o->prop != NULL ? o->prop->mass_kg : 0.0);
	struct airframe_loads al = { mass_kg + q->extra_payload_kg,
		o->full_thrust_n, tip, n * o->full_current_a, c->battery_kg };
	struct airframe_masses am;
	airframe_masses(q, &al, &am);
	c->arm = am.arm;
	struct res_mass *m = &c->mass;
	/* A frame kit replaces the arm tubes and the centre frame. */
	m->arm_kg = kit->frame != NULL ? 0.0 : am.arm_kg;
	m->frame_kg = kit->frame != NULL ? kit->frame->mass_kg : am.frame_kg;
	/* The fasteners are mounts, with the body. */
	m->other_kg = am.other_kg + parts_kit_fastener_kg(kit);
	/* The harness in copper for the real parts' currents (harness.c),
	 * not the continuous model's coefficient. */
	m->wiring_kg = kit->harness_kg + kit->connector_kg;
	m->avionics_kg = kit->avionics_kg;
	/* Role hardware the class's items supply is not counted twice. */
	m->role_aux_kg = fmax(0.0, am.role_aux_kg - kit->role_supplied_kg);
	m->payload_kg = q->payload_kg;
	return fixed_kg + q->payload_kg + m->arm_kg + m->frame_kg + m->other_kg
	    + m->wiring_kg + m->avionics_kg + m->role_aux_kg;
}

/* The takeoff mass with the real parts: the airframe follows the mass it
 * carries (the CG thrust of its arms), a contraction far below 1.  False
 * on a runaway (*ran_away set) or a number that is none. */
static bool
close_mass(const struct sizing_params *q, const struct parts_option *o,
           const struct parts_kit *kit, double fixed_kg, double start_kg,
           struct perf_craft *c, double *mass_kg, bool *converged,
           bool *ran_away)
{
	double mass = start_kg;
	*converged = false;
	for (int k = 0; k < CLOSE_MAX_ITER && !*converged; k++) {
		double next = craft_masses(q, o, kit, fixed_kg, mass, c);
		*converged = fabs(next - mass) < CLOSE_TOL_KG;
		mass = next;
		*ran_away = mass > SIZING_RUNAWAY_KG;
		if (!isfinite(mass) || *ran_away)
			return false;
	}
	craft_masses(q, o, kit, fixed_kg, mass, c);
	*mass_kg = mass;
	return true;
}

/* The mass loop with the kit: custom arms first; then the lightest frame
 * kit that fits the aircraft they give, kept if it still fits the mass
 * it closes at. */
static bool
close_with_kit(const struct parts_ctx *x, const struct sizing_params *q,
               const struct parts_option *o, struct parts_kit *kit,
               double fixed_kg, struct perf_craft *c, bool *converged,
               bool *ran_away)
{
	double mass;
	kit->frame = NULL;
	if (!close_mass(q, o, kit, fixed_kg, x->aim.mass_kg, c, &mass, converged,
	    ran_away))
		return false;
	double prop_in = m_to_in(c->prop_diameter_m);
	double custom_kg = c->mass.arm_kg + c->mass.frame_kg;
	kit->frame = parts_kit_frame(x, prop_in, mass, c->arm.d_out_m, custom_kg);
	if (kit->frame == NULL)
		return true;
	double with_kit;
	if (close_mass(q, o, kit, fixed_kg, mass, c, &with_kit, converged, ran_away)
	    && parts_kit_frame_fits(x, kit->frame, prop_in, with_kit,
	    c->arm.d_out_m, custom_kg))
		return true;
	kit->frame = NULL;
	return close_mass(q, o, kit, fixed_kg, mass, c, &mass, converged, ran_away);
}

/* The highest current of a phase the mission flies, at the pack. */
static double
sustained_battery_a(const struct res_run *o)
{
	double a = 0.0;
	for (int i = 0; i < PHASE_MAX; i++)
		if (o->phase[i].duration_s > 0.0 && o->phase[i].current_a > a)
			a = o->phase[i].current_a;
	return a;
}

/* What the flown closing asks of its kit: the mission's sustained
 * current, full throttle as flown (the estimate where the drive gave no
 * full-throttle point), and its takeoff mass without the kit's own
 * Remote ID module (whether one is needed is decided without it). */
static void
flown_load(const struct parts_kit *kit, const struct res_run *o,
           struct parts_load *load)
{
	load->sustained_a = sustained_battery_a(o);
	const struct res_op *full = &o->perf.op[OP_FULL];
	if (full->valid && full->battery_current_a > 0.0) {
		load->full_a = full->battery_current_a;
		load->motor_full_a = full->motor_current_a;
	}
	load->mass_kg = o->mass.total_kg;
	for (int i = 0; i < kit->n_part; i++)
		if (strcmp(kit->part[i]->kind, "remote_id") == 0)
			load->mass_kg -= kit->part[i]->mass_kg;
}

bool
parts_close_figures(const struct parts_ctx *x, struct parts_closed *cl)
{
	struct sizing_params q = *x->p;
	q.chem = cl->pack.chem;
	return perf_figures(&q, &cl->o.craft, &cl->r->closed);
}

bool
parts_close(const struct parts_ctx *x, const struct parts_option *o,
            const struct parts_pack *pk, const struct catalog_esc *esc,
            int n_esc, struct parts_closed *out)
{
	struct sizing_params q = *x->p;
	q.chem = pk->chem;
	/* Nothing of the buffer's last closing may stand for this one. */
	out->finite = false;
	out->ran_away = false;
	out->failed = 0;
	out->o = *o;
	out->esc = esc;
	out->n_esc = n_esc;
	out->pack = *pk;
	struct perf_craft *c = &out->o.craft;
	double n = (double)q.n_rotors;
	c->cells = o->cells;
	c->capacity_ah = pk->capacity_ah;
	c->battery_kg = pk->mass_kg;
	c->battery_continuous_c = pk->b->continuous_c;
	c->battery_burst_c = pk->b->burst_c;
	c->esc_current_a = esc != NULL ? esc->continuous_current_a
	    : (o->motor->integrated_esc_current_a > 0.0
	    ? o->motor->integrated_esc_current_a : o->motor->max_current_a);
	memset(&c->mass, 0, sizeof c->mass);
	c->mass.motor_kg = n * o->motor->mass_kg;
	c->mass.prop_kg = o->prop != NULL ? n * o->prop->mass_kg : 0.0;
	c->mass.esc_kg = esc != NULL ? (double)n_esc * esc->mass_kg : 0.0;
	c->mass.battery_kg = pk->mass_kg;
	double fixed = c->mass.motor_kg + c->mass.prop_kg + c->mass.esc_kg
	    + c->mass.battery_kg;

	/* The kit is sized for the closing's currents and mass: first the
	 * ranking's estimates (hover, and every motor at full throttle with
	 * the auxiliaries), then, if the kit they give differs, what the
	 * flown mission drew. */
	double v_bus = (double)o->cells * q.chem->v_nom;
	struct parts_load load = {
		.sustained_a = o->hover_power_w / v_bus,
		.full_a = n * o->full_current_a
		    + sizing_aux_w(&q, x->aim.mass_kg) / v_bus,
		.motor_full_a = o->full_current_a,
		.mass_kg = x->aim.mass_kg,
	};
	struct solve_result *r = out->r;
	bool converged = false;
	for (int pass = 0; pass < 2; pass++) {
		parts_kit_pick(x, o, pk, esc, &load, &out->kit);
		if (!close_with_kit(x, &q, o, &out->kit, fixed, c, &converged,
		    &out->ran_away))
			return false;
		struct res_mass *m = &c->mass;
		m->total_kg = m->payload_kg + m->battery_kg + m->frame_kg + m->arm_kg
		    + m->motor_kg + m->prop_kg + m->esc_kg + m->wiring_kg
		    + m->avionics_kg + m->role_aux_kg + m->other_kg;
		r->n_violations = 0;
		out->finite = perf_fly(&q, c, &r->closed);
		if (!out->finite)
			break;
		flown_load(&out->kit, &r->closed, &load);
		struct parts_kit again;
		parts_kit_pick(x, o, pk, esc, &load, &again);
		if (parts_kit_same(&again, &out->kit))
			break;
	}
	r->closed.converged = converged;
	parts_record_checks(x, out, r);
	out->failed = 0;
	for (int i = 0; i < r->closed.n_checks; i++)
		out->failed += !r->closed.checks[i].pass;
	return out->finite;
}

/* ---- the design of record's checks ---------------------------------------- */

/* A check that fails becomes a violation with its fixes. */
static void
violate(struct solve_result *r, const struct res_check *c, const char *stage,
        const char *code, const char *const *fx, const char *message)
{
	if (c == NULL || c->pass)
		return;
	feasibility_violation(r, "closed", stage, code, fx, "%s", message);
}

/* A motor current against the rating its maker's basis allows. */
static void
motor_current(struct solve_result *r, const char *name, const char *code,
              const char *when, const char *fix2, double value_a,
              double limit_a, const char *rating)
{
	char f1[FIX_LEN] = "", f2[FIX_LEN] = "", f3[FIX_LEN] = "", msg[RES_TEXT] = "";
	const char *fx[4] = { f1, f2, f3, NULL };
	struct res_check *k = feasibility_add_check(&r->closed, name, "A",
	    value_a, limit_a, true);
	if (k == NULL || k->pass)
		return;
	feasibility_fix(r, f1, "A motor rated above %.0f A", value_a);
	feasibility_fix(r, f2, "%s", fix2);
	feasibility_fix(r, f3, "Fewer series cells or a lower-KV motor");
	if (!r->terse)
		snprintf(msg, sizeof msg, "Each motor draws %.1f A %s, above its "
		    "%.1f A %s.", value_a, when, limit_a, rating);
	violate(r, k, "parts", code, fx, msg);
}

void
parts_record_checks(const struct parts_ctx *x, const struct parts_closed *cl,
                    struct solve_result *r)
{
	const struct sizing_params *p = x->p;
	const struct perf_craft *c = &cl->o.craft;
	struct res_run *o = &r->closed;
	const struct res_perf *pf = &o->perf;
	const struct res_op *full = &pf->op[OP_FULL];
	char f1[FIX_LEN] = "", f2[FIX_LEN] = "", f3[FIX_LEN] = "", msg[RES_TEXT] = "";
	const char *fx[4] = { f1, f2, f3, NULL };
	struct res_check *k;
	o->n_checks = 0;

	/* The mission, down to the reserve. */
	k = feasibility_add_check(o, "State of charge at landing (reserve)", "%",
	    100.0 * o->end_soc, 100.0 * o->reserve_soc, false);
	if (k && !k->pass) {
		feasibility_fix(r, f1, "Choose a larger pack (locks.battery_part) or more packs in parallel");
		feasibility_fix(r, f2, "Shorten the mission or lighten the payload");
		feasibility_fix(r, f3, "Allow goal relaxation: locks.auto_reduce_flight_time = true");
		if (!r->terse)
			snprintf(msg, sizeof msg, "The real pack lands at %.1f %% state of "
			    "charge, below the %.1f %% reserve (%.80s).", 100.0 * o->end_soc,
			    100.0 * o->reserve_soc, o->termination);
		violate(r, k, "discharge", "RESERVE", fx, msg);
	}
	/* The T/W requirement holds with the largest payload aboard (the
	 * mission's payload when it gives no larger one). */
	double m_max = o->mass.total_kg + p->extra_payload_kg;
	k = feasibility_add_check(o, p->extra_payload_kg > 0.0
	    ? "Thrust-to-weight with the largest payload" : "Thrust-to-weight at full throttle",
	    "", o->thrust_to_weight * o->mass.total_kg / m_max, x->aim.tw_required,
	    false);
	if (k && !k->pass) {
		feasibility_fix(r, f1, "A stronger motor or a larger propeller (locks.motor_part, locks.prop_part)");
		feasibility_fix(r, f2, p->extra_payload_kg > 0.0 ? "A lower max_payload_kg"
		    : "Reduce the thrust margin (payload_role.thrust_margin_override)");
		feasibility_fix(r, f3, "Add series cells (nominal_cell_count)");
		if (!r->terse)
			snprintf(msg, sizeof msg, "The real motor and propeller give T/W "
			    "%.2f at full throttle with %.2f kg aboard; the requirement is %.2f.",
			    k->value, p->payload_kg + p->extra_payload_kg, k->limit);
		violate(r, k, "parts", "THRUST", fx, msg);
	}

	k = feasibility_add_check(o, "Throttle the mission needs (real drive)", "%",
	    100.0 * pf->throttle_needed, 100.0, true);
	feasibility_fix(r, f1, "A motor of higher KV or a larger propeller");
	feasibility_fix(r, f2, "Add series cells");
	fx[2] = NULL;
	if (k && !k->pass && !r->terse)
		snprintf(msg, sizeof msg, "The mission needs %.0f %% throttle: more "
		    "voltage than the pack gives.", 100.0 * pf->throttle_needed);
	violate(r, k, "parts", "THROTTLE", fx, msg);
	fx[2] = f3;


	/* Ratings of the real parts: the motor's through the mission and at
	 * full throttle, each against the rating its maker's basis allows
	 * (rank.c, parts_motor_limits()). */
	struct parts_motor_limits lim;
	parts_motor_limits(cl->o.motor, &lim);
	motor_current(r, "Motor current, mission (sustained)",
	    "MOTOR_CURRENT_SUSTAINED", "through the mission",
	    "A larger propeller or more rotors (lower disk loading)",
	    pf->sustained_motor_current_a, lim.sustained_a, lim.sustained_text);
	if (lim.full_a > 0.0)
		motor_current(r, "Motor current at full throttle", "MOTOR_CURRENT",
		    "at full throttle", "A smaller or lower-pitch propeller",
		    full->motor_current_a, lim.full_a, lim.full_text);
	if (c->motor_max_power_w > 0.0 && !cl->o.motor->integrated) {
		k = feasibility_add_check(o, "Motor input power at full throttle", "W",
		    full->power_in_w, c->motor_max_power_w, true);
		feasibility_fix(r, f1, "A motor rated above %.0f W", full->power_in_w);
		feasibility_fix(r, f2, "A smaller or lower-pitch propeller");
		f3[0] = '\0';
		if (!r->terse)
			snprintf(msg, sizeof msg, "Each motor takes %.0f W at full "
			    "throttle, above its %.0f W rating.", full->power_in_w,
			    c->motor_max_power_w);
		fx[2] = NULL;
		violate(r, k, "parts", "MOTOR_POWER", fx, msg);
		fx[2] = f3;
	}
	if (cl->esc != NULL) {
		/* The rating that holds for the full-throttle burst (compat.c). */
		struct compat_rating er = { cl->esc->continuous_current_a,
			cl->esc->burst_current_a, cl->esc->burst_s };
		double esc_a = compat_rating_for(&er, PERF_FULL_THROTTLE_S);
		k = feasibility_add_check(o, "ESC current at full throttle", "A",
		    full->motor_current_a, esc_a, true);
		if (k && !k->pass) {
			feasibility_fix(r, f1, "An ESC rated above %.0f A continuous", full->motor_current_a);
			feasibility_fix(r, f2, "Remove locks.esc_part to let the search choose");
			fx[2] = NULL;
			if (!r->terse)
				snprintf(msg, sizeof msg, "Each motor draws %.1f A at full "
				    "throttle, above the ESC's %.0f A rating for a %.0f s "
				    "burst.", full->motor_current_a, esc_a,
				    PERF_FULL_THROTTLE_S);
			violate(r, k, "parts", "ESC_CURRENT", fx, msg);
			fx[2] = f3;
		}
	}
	/* The power module and the battery connectors (kit.c) carry the
	 * sustained current. */
	const struct parts_kit *kit = &cl->kit;
	double sustained_a = 0.0;
	for (int i = 0; i < PHASE_MAX; i++)
		if (o->phase[i].duration_s > 0.0 && o->phase[i].current_a > sustained_a)
			sustained_a = o->phase[i].current_a;
	for (int i = 0; i < kit->n_part; i++) {
		const struct catalog_avionics *a = kit->part[i];
		if (!(a->max_current_a > 0.0))
			continue;
		k = feasibility_add_check(o, "Power module current, mission", "A",
		    sustained_a, a->max_current_a, true);
		feasibility_fix(r, f1, "A power module rated above %.0f A", sustained_a);
		fx[1] = NULL;
		if (k && !k->pass && !r->terse)
			snprintf(msg, sizeof msg, "The mission draws %.1f A through the "
			    "power module, above its %.0f A rating.", sustained_a,
			    a->max_current_a);
		violate(r, k, "parts", "POWER_MODULE_CURRENT", fx, msg);
		fx[1] = f2;
	}
	if (kit->connector != NULL) {
		int per_pack = kit->n_connectors / (cl->pack.series * cl->pack.parallel);
		k = feasibility_add_check(o, "Battery connector current, mission", "A",
		    sustained_a / (double)cl->pack.parallel,
		    (double)per_pack * kit->connector->max_current_a, true);
		feasibility_fix(r, f1, "Fewer, larger packs or a higher-rated connector");
		fx[1] = NULL;
		if (k && !k->pass && !r->terse)
			snprintf(msg, sizeof msg, "Each pack's connector carries %.1f A, "
			    "above its %.0f A rating.", k->value, k->limit);
		violate(r, k, "parts", "CONNECTOR_CURRENT", fx, msg);
		fx[1] = f2;
	}
	if (kit->frame != NULL && kit->frame->max_takeoff_kg > 0.0)
		feasibility_add_check(o, "Takeoff mass within the frame kit's maximum",
		    "kg", o->mass.total_kg, kit->frame->max_takeoff_kg, true);
	/* The pack: the highest sustained phase current within its
	 * continuous rating, full throttle within its burst rating. */
	double sustained = sustained_a;
	k = feasibility_add_check(o, "Battery current, mission (continuous rating)", "A",
	    sustained, cl->pack.max_continuous_a, true);
	feasibility_fix(r, f1, "A pack with a higher C rating or more capacity");
	feasibility_fix(r, f2, "More packs in parallel");
	fx[2] = NULL;
	if (k && !k->pass && !r->terse)
		snprintf(msg, sizeof msg, "The mission draws %.1f A, above the pack's "
		    "%.0f A continuous rating.", sustained, cl->pack.max_continuous_a);
	violate(r, k, "parts", "BATTERY_CURRENT", fx, msg);
	k = feasibility_add_check(o, "Battery current, full throttle (burst rating)", "A",
	    full->battery_current_a, cl->pack.max_burst_a, true);
	if (k && !k->pass && !r->terse)
		snprintf(msg, sizeof msg, "Full throttle draws %.1f A, above the pack's "
		    "%.0f A burst rating.", full->battery_current_a, cl->pack.max_burst_a);
	violate(r, k, "parts", "BATTERY_BURST", fx, msg);
	fx[2] = f3;

	/* The rotor. */
	k = feasibility_add_check(o, "Propeller diameter (overlap limit)", "in",
	    m_to_in(c->prop_diameter_m), o->overlap_limit_in * (1.0 + 1e-6), true);
	k = feasibility_add_check(o, "Tip Mach number at full throttle", "",
	    full->tip_mach, AERO_TIP_MACH_MAX, true);
	feasibility_fix(r, f1, "A larger, slower propeller");
	feasibility_fix(r, f2, "A lower-KV motor");
	fx[2] = NULL;
	if (k && !k->pass && !r->terse)
		snprintf(msg, sizeof msg, "The tip reaches Mach %.2f at full throttle "
		    "(limit %.2f).", full->tip_mach, AERO_TIP_MACH_MAX);
	violate(r, k, "parts", "TIP_MACH", fx, msg);
	if (c->prop_max_rpm > 0.0) {
		k = feasibility_add_check(o, "Propeller speed at full throttle", "rpm",
		    full->rpm, c->prop_max_rpm, true);
		if (k && !k->pass && !r->terse)
			snprintf(msg, sizeof msg, "The propeller turns at %.0f rpm at "
			    "full throttle, above the maker's %.0f rpm limit.", full->rpm,
			    c->prop_max_rpm);
		violate(r, k, "parts", "PROP_RPM", fx, msg);
	}
	fx[2] = f3;

	/* Heat and voltage. */
	k = feasibility_add_check(o, "Battery peak temperature", "°C",
	    o->max_battery_temp_c, THERM_RUNAWAY_C, true);
	feasibility_fix(r, f1, "More capacity or packs in parallel (lower C-rate, more mass to heat)");
	feasibility_fix(r, f2, "A lower-resistance pack");
	feasibility_fix(r, f3, "A lower ambient temperature limit for the mission");
	if (k && !k->pass && !r->terse)
		snprintf(msg, sizeof msg, "The pack reaches %.1f °C, above %.0f °C.",
		    o->max_battery_temp_c, THERM_RUNAWAY_C);
	violate(r, k, "discharge", "THERMAL_RUNAWAY", fx, msg);
	k = feasibility_add_check(o, "Motor winding temperature, hover (steady)", "°C",
	    o->winding_temp_c, MOTOR_WINDING_MAX_C, true);
	feasibility_fix(r, f1, "A larger motor (lower losses, more surface)");
	feasibility_fix(r, f2, "A larger propeller (lower disk loading)");
	fx[2] = NULL;
	if (k && !k->pass && !r->terse)
		snprintf(msg, sizeof msg, "The winding settles at %.0f °C in hover "
		    "(limit %.0f °C).", o->winding_temp_c, MOTOR_WINDING_MAX_C);
	violate(r, k, "parts", "WINDING_TEMPERATURE_HOVER", fx, msg);
	fx[2] = f3;
	k = feasibility_add_check(o, "Motor winding temperature, full-throttle burst", "°C",
	    full->winding_temp_c, MOTOR_WINDING_MAX_C, true);
	feasibility_fix(r, f1, "A larger motor (lower losses, more surface)");
	feasibility_fix(r, f2, "A smaller or lower-pitch propeller");
	fx[2] = NULL;
	if (k && !k->pass && !r->terse)
		snprintf(msg, sizeof msg, "The winding reaches %.0f °C after %.0f s at "
		    "full throttle (limit %.0f °C).", full->winding_temp_c,
		    PERF_FULL_THROTTLE_S, MOTOR_WINDING_MAX_C);
	violate(r, k, "parts", "WINDING_TEMPERATURE", fx, msg);
	fx[2] = f3;
	k = feasibility_add_check(o, "Minimum terminal voltage", "V",
	    o->min_terminal_voltage_v, o->voltage_floor_v, false);
	feasibility_fix(r, f1, "More capacity or a lower-resistance pack");
	feasibility_fix(r, f2, "Add series cells");
	fx[2] = NULL;
	if (k && !k->pass && !r->terse)
		snprintf(msg, sizeof msg, "The pack falls to %.2f V, below the %.2f V "
		    "cut-off.", o->min_terminal_voltage_v, o->voltage_floor_v);
	violate(r, k, "discharge", "VOLTAGE_FLOOR", fx, msg);
	fx[2] = f3;

	/* Structure. */
	k = feasibility_add_check(o, "Arm root bending stress (FoS 1.5, fatigue 0.4)",
	    "MPa", o->arm_stress_mpa, o->arm_stress_allow_mpa, true);
	if (k)
		k->sized = true;
	k = feasibility_add_check(o, "Arm mode clear of the blade-pass band", "",
	    o->resonance_margin, 0.0, false);
	feasibility_fix(r, f1, "Stiffen the arm above %.0f Hz (larger tube)",
	    STRUCT_RESONANCE_MARGIN * o->blade_pass_frequency_hz);
	feasibility_fix(r, f2, "Or soften it below %.0f Hz (soft mounts)",
	    o->blade_pass_low_hz / STRUCT_RESONANCE_MARGIN);
	feasibility_fix(r, f3, "Another blade count moves the band");
	if (k && !k->pass && !r->terse)
		snprintf(msg, sizeof msg, "The arm's first mode (%.0f Hz) lies inside "
		    "the blade-pass band (%.0f–%.0f Hz) without the 1.5 margin.",
		    o->arm_natural_frequency_hz, o->blade_pass_low_hz,
		    o->blade_pass_frequency_hz);
	violate(r, k, "structure", "ARM_RESONANCE", fx, msg);
	int arms = p->coaxial ? p->n_rotors / 2 : p->n_rotors;
	feasibility_add_check(o, "Payload CG offset", "m", p->cg_shift_m,
	    0.5 * p->wheelbase_m * cos(M_PI / (double)arms), true);

	/* The role's own limits. */
	if (p->downwash_cap_ms > 0.0) {
		k = feasibility_add_check(o, "Downwash (role limit)", "m/s",
		    o->downwash_ms, p->downwash_cap_ms, true);
		feasibility_fix(r, f1, "A larger wheelbase: larger rotors lower the downwash");
		feasibility_fix(r, f2, "More rotors");
		feasibility_fix(r, f3, "Raise payload_role.ag_max_downwash_ms if the crop allows");
		if (k && !k->pass && !r->terse)
			snprintf(msg, sizeof msg, "The downwash of %.1f m/s exceeds the "
			    "role's %.1f m/s limit.", o->downwash_ms, p->downwash_cap_ms);
		violate(r, k, "feasibility", "DOWNWASH", fx, msg);
	}
	if (p->duration_s[PHASE_FORWARD] > 0.0) {
		feasibility_add_check(o, "Forward body pitch", "°", o->forward_pitch_deg,
		    MISSION_PITCH_MAX_DEG, true);
		k = feasibility_add_check(o, "Forward speed within full thrust", "m/s",
		    o->optimal_speed_ms, o->v_max_ms, true);
		feasibility_fix(r, f1, "Reduce v_forward_ms to %.1f m/s or less", o->v_max_ms);
		feasibility_fix(r, f2, "Use \"auto\" for the minimum-power speed");
		fx[2] = NULL;
		if (k && !k->pass && !r->terse)
			snprintf(msg, sizeof msg, "At %.1f m/s the real rotors run out of "
			    "thrust or pitch; they reach %.1f m/s.", o->optimal_speed_ms,
			    o->v_max_ms);
		violate(r, k, "mission", "FORWARD_SPEED", fx, msg);
		fx[2] = f3;
	}
	o->feasible = true;
	for (int i = 0; i < o->n_checks; i++)
		if (!o->checks[i].pass)
			o->feasible = false;
	/* A failed check without a violation of its own (overlap, CG, pitch)
	 * must still say why the design fails. */
	bool unexplained = !o->feasible && r->n_violations == 0;
	for (int i = 0; unexplained && i < o->n_checks; i++) {
		const struct res_check *ck = &o->checks[i];
		if (ck->pass)
			continue;
		if (!r->terse)
			snprintf(msg, sizeof msg, "%s is %.4g%s%s, beyond its limit of "
			    "%.4g%s%s.", ck->name, ck->value, ck->unit[0] ? " " : "",
			    ck->unit, ck->limit, ck->unit[0] ? " " : "", ck->unit);
		feasibility_violation(r, "closed", "checks", "CHECK_FAILED", NULL,
		    "%s", msg);
	}
}
