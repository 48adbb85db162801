/* closure.c — an option closed on real parts: its ESC set and battery, the
 * takeoff mass found again with the real masses, the mission flown on the
 * real drive and every check of the design of record (see parts.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "result/checks.h"
#include "parts/parts_int.h"
#include "parts/screen.h"
#include "physics/aero.h"
#include "physics/mission.h"
#include "physics/therm.h"
#include "sizing/airframe.h"
#include "sizing/feasibility.h"
#include "util/strbuf.h"
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
				pk->plug = NULL;      /* parts_kit_init() finds it */
				pk->plug_name = NULL;
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

/* The first of x->packs (sorted by bus) on a bus of at least cells. */
static int
first_on_bus(const struct parts_ctx *x, int cells)
{
	int lo = 0, hi = x->n_packs;
	while (lo < hi) {
		int mid = lo + (hi - lo) / 2;
		if (x->packs[mid].b->cells_series * x->packs[mid].series < cells)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

const struct parts_pack *
parts_packs_on(const struct parts_ctx *x, int cells, int *n)
{
	int first = first_on_bus(x, cells);
	*n = first_on_bus(x, cells + 1) - first;
	return *n > 0 ? &x->packs[first] : NULL;
}

/* ---- ESC ------------------------------------------------------------------ */

void
parts_escs_init(struct parts_ctx *x)
{
	size_t n = catalog_n_escs(x->cat);
	x->esc_offered = xcalloc(n > 0 ? n : 1, sizeof *x->esc_offered);
	for (size_t i = 0; i < n; i++) {
		const struct catalog_esc *e = catalog_esc(x->cat, i);
		char why[256];
		x->esc_offered[i] = e->usable && screen_esc(e, why, sizeof why) == NULL
		    && screen_doubt_esc(e, why, sizeof why) == NULL;
	}
}

void
parts_escs_free(struct parts_ctx *x)
{
	free(x->esc_offered);
	x->esc_offered = NULL;
}

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
		if (!locked && !x->esc_offered[i])
			continue;
		/* The ESC class against the motor and the bus (compat.c). */
		if (!locked && compat_esc(e, o->motor, o->cells, hover_a,
		    o->full_current_a, PARTS_CURRENT_MARGIN, PERF_FULL_THROTTLE_S,
		    NULL, 0) != NULL)
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
		if (!locked && compat_board_fc(e, boards, takes_fc, NULL, 0) != NULL)
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
	/* Q = P / 2πn = T D C_P / (2π C_T): the reaction torque at full thrust. */
	double d_m = c->prop_diameter_m;
	double torque_nm = c->prop.ct > 0.0
	    ? o->full_thrust_n * d_m * c->prop.cp / (2.0 * M_PI * c->prop.ct) : 0.0;
	struct airframe_loads al = { .mass_kg = mass_kg + q->extra_payload_kg,
		.peak_thrust_n = o->full_thrust_n, .tip_mass_kg = tip,
		.peak_current_a = n * o->full_current_a, .peak_torque_nm = torque_nm,
		.prop_diameter_m = d_m };
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
		/* A trial's shortcuts (perf_fly()) are off in the exhaustive
		 * search, against which test_sweep holds them. */
		out->finite = perf_fly(&q, c, r->terse && !x->exhaustive, &r->closed);
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

/* "maker part, rating" of a catalogue part, as check id's basis. */
static void
part_basis(struct check_values *v, enum check_id id, const char *maker,
           const char *part, double rating_a, const char *per)
{
	checks_basis(v, id, "%.16s %.44s, %.0f A%s", maker, part, rating_a, per);
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
	struct check_values v;
	checks_init(&v);
	v.terse = r->terse;
	feasibility_common_checks(p, o, &v);

	/* The T/W requirement holds with the largest payload aboard. */
	double m_max = o->mass.total_kg + p->extra_payload_kg;
	checks_set(&v, CK_THRUST, o->thrust_to_weight * o->mass.total_kg / m_max,
	    x->aim.tw_required);
	checks_basis(&v, CK_THRUST, "the role's requirement, %.2f kg aboard",
	    p->payload_kg + p->extra_payload_kg);
	checks_set(&v, CK_THROTTLE, 100.0 * pf->throttle_needed, 100.0);

	/* The power path, pack to motor, at the mission's sustained peak and
	 * at a full-throttle burst. */
	double sustained_a = sustained_battery_a(o);
	double full_a = full->battery_current_a;
	const struct parts_pack *pk = &cl->pack;
	checks_set(&v, CK_BATTERY_CONTINUOUS, sustained_a, pk->max_continuous_a);
	checks_set(&v, CK_BATTERY_BURST, full_a, pk->max_burst_a);
	checks_basis(&v, CK_BATTERY_CONTINUOUS, "%d × %.0f C continuous",
	    pk->parallel, pk->b->continuous_c);
	checks_basis(&v, CK_BATTERY_BURST, "%d × %.0f C burst", pk->parallel,
	    pk->b->burst_c > 0.0 ? pk->b->burst_c : pk->b->continuous_c);
	/* Each element against the rating that holds for it: the
	 * continuous one through the mission, for the burst the one its
	 * maker publishes for at least that long (compat.c). */
	const struct parts_kit *kit = &cl->kit;
	if (kit->connector != NULL) {
		/* The plug that bounds the pack: its own family's row when the
		 * pair bought is another. */
		const struct catalog_avionics *k = kit->plug != NULL
		    && kit->plug->max_current_a > 0.0 ? kit->plug : kit->connector;
		struct compat_rating cr = { k->max_current_a, k->burst_current_a,
			k->burst_s };
		double burst = compat_rating_for(&cr, PERF_FULL_THROTTLE_S);
		checks_set(&v, CK_CONNECTOR_MISSION, sustained_a / (double)pk->parallel,
		    k->max_current_a);
		checks_set(&v, CK_CONNECTOR_FULL, full_a / (double)pk->parallel, burst);
		part_basis(&v, CK_CONNECTOR_MISSION, k->manufacturer,
		    k->part_number, k->max_current_a, " per pack");
		part_basis(&v, CK_CONNECTOR_FULL, k->manufacturer,
		    k->part_number, burst, burst > k->max_current_a
		    ? " burst, per pack" : " per pack");
	}
	if (kit->power_module != NULL) {
		const struct catalog_avionics *a = kit->power_module;
		struct compat_rating pr = { a->max_current_a, a->burst_current_a,
			a->burst_s };
		double burst = compat_rating_for(&pr, PERF_FULL_THROTTLE_S);
		checks_set(&v, CK_POWER_MODULE_MISSION, sustained_a, a->max_current_a);
		checks_set(&v, CK_POWER_MODULE_FULL, full_a, burst);
		part_basis(&v, CK_POWER_MODULE_MISSION, a->manufacturer,
		    a->part_number, a->max_current_a, "");
		part_basis(&v, CK_POWER_MODULE_FULL, a->manufacturer,
		    a->part_number, burst, burst > a->max_current_a ? " burst" : "");
	}
	if (kit->harness_main.awg != NULL) {
		checks_set(&v, CK_HARNESS_FULL, full_a, kit->harness_main.ampacity_a);
		checks_basis(&v, CK_HARNESS_FULL, "main lead %d × %s AWG copper",
		    kit->harness_main.parallel, kit->harness_main.awg);
	}
	if (cl->esc != NULL) {
		struct compat_rating er = { cl->esc->continuous_current_a,
			cl->esc->burst_current_a, cl->esc->burst_s };
		double esc_a = compat_rating_for(&er, PERF_FULL_THROTTLE_S);
		checks_set(&v, CK_ESC_CURRENT, full->motor_current_a, esc_a);
		part_basis(&v, CK_ESC_CURRENT, cl->esc->manufacturer,
		    cl->esc->part_number, esc_a, esc_a > cl->esc->continuous_current_a
		    ? " burst" : " continuous");
	}
	struct parts_motor_limits lim;
	parts_motor_limits(cl->o.motor, &lim);
	checks_set(&v, CK_MOTOR_CURRENT_MISSION, pf->sustained_motor_current_a,
	    lim.sustained_a);
	str_copy(v.basis[CK_MOTOR_CURRENT_MISSION], RES_BASIS, lim.sustained_text);
	if (lim.full_a > 0.0) {
		checks_set(&v, CK_MOTOR_CURRENT_FULL, full->motor_current_a, lim.full_a);
		str_copy(v.basis[CK_MOTOR_CURRENT_FULL], RES_BASIS, lim.full_text);
	}
	if (c->motor_max_power_w > 0.0 && !cl->o.motor->integrated)
		checks_set(&v, CK_MOTOR_POWER, full->power_in_w, c->motor_max_power_w);
	/* The pack's terminal voltage in a burst, mid-discharge, against the
	 * floor the battery failsafe is set to. */
	if (full->valid)
		checks_set(&v, CK_VOLTAGE_FULL, full->bus_voltage_v, o->voltage_floor_v);

	checks_set(&v, CK_WINDING_HOVER, o->winding_temp_c, MOTOR_WINDING_MAX_C);
	checks_set(&v, CK_WINDING_FULL, full->winding_temp_c, MOTOR_WINDING_MAX_C);
	if (c->prop_max_rpm > 0.0)
		checks_set(&v, CK_PROP_RPM, full->rpm, c->prop_max_rpm);
	if (kit->frame != NULL && kit->frame->max_takeoff_kg > 0.0)
		checks_set(&v, CK_FRAME_MTOW, o->mass.total_kg, kit->frame->max_takeoff_kg);
	checks_apply(&v, "closed", o, r);
}
