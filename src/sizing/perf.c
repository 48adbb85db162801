/* perf.c — a design on real parts, flown (see perf.h). */
#include "sizing/perf.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "physics/aero.h"
#include "physics/batt.h"
#include "physics/discharge.h"
#include "physics/mission.h"
#include "physics/therm.h"
#include "sizing/airframe.h"
#include "util/strbuf.h"
#include "util/units.h"

#define TEMP_ITERATIONS   8      /* winding temperature ↔ resistance */
#define BUS_ITERATIONS    50     /* bisection steps of the full-throttle voltage */
#define RPS_ITERATIONS    100    /* bound on the steps of the full-throttle
                                    rotor speed at an advance ratio */
#define RPS_REL_TOL       1e-13  /* ... to this share of the no-load speed,
                                    or of the pack's voltage in the gap */
#define CLIMB_MAX_MS      30.0   /* highest climb rate searched for a
                                    propeller without a pitch (no zero-
                                    thrust speed to bound it): then reported
                                    as the search's bound */
#define ENVELOPE_TOL_MS   1e-3   /* top speed and climb to 1 mm/s */
#define ENVELOPE_ITERATIONS 64   /* their bisections' bound */
#define GAMMA_BISECT      8      /* goal-relaxation bisection steps */
#define ENDURANCE_STEPS   60

/* What every evaluation of one aircraft shares. */
struct perf_ctx {
	const struct sizing_params *p;
	const struct perf_craft *c;
	struct mission_model model;   /* the real drive */
	struct discharge_pack pack;
	double v_oc_nom_v;            /* cells × nominal cell voltage */
	double r_sys_ohm;             /* pack and ESC resistance at ambient */
	double kq_nm_s2;              /* installed torque factor, Q = kq n² */
	double hover_temp_c;          /* steady winding temperature at hover */
	double v_climb_ms;            /* the climb flown: the mission's, or the
	                                 fastest full thrust allows */
	double j0;                    /* the propeller's zero-thrust advance
	                                 ratio (prop.h; 0 without a pitch) */
	double thrust_scale;          /* full thrust over the model's at rest:
	                                 below 1 for an integrated system its
	                                 maker caps (capped_full_throttle()) */
	double full_w;                /* battery power at full throttle */
	double full_shaft_w;          /* its shaft power, all rotors */
	double full_v;                /* ... on this terminal voltage */
};

static int
n_arms(const struct sizing_params *p)
{
	return p->coaxial ? p->n_rotors / 2 : p->n_rotors;
}

/* The rotor's installed figure of merit: the real propeller's static FoM
 * with the installation penalty κ and the arm interference of the
 * continuous model (paper §IV-F), or the mission's override. */
static double
installed_fom(const struct sizing_params *p, const struct perf_craft *c,
              double k_int)
{
	double fom = p->fom_override > 0.0 ? p->fom_override
	    : prop_fom(&c->prop) / (p->fom_isolated_mode ? 1.0 : p->kappa);
	if (p->fom_override <= 0.0 && fom < AERO_FOM_FLOOR)
		fom = AERO_FOM_FLOOR;
	return fom / k_int;
}

static void
build(const struct sizing_params *p, const struct perf_craft *c,
      struct perf_ctx *x)
{
	memset(x, 0, sizeof *x);
	x->p = p;
	x->c = c;
	x->v_climb_ms = p->v_climb_ms;
	struct mission_model *m = &x->model;
	sizing_mission_model(p, c->mass.total_kg + p->extra_payload_kg, m);
	m->rotor.diameter_m = c->prop_diameter_m;
	m->rotor.ct = c->prop.ct;
	m->rotor.n_blades = c->prop_blades;
	m->rotor.fom = installed_fom(p, c, aero_interference(p->interference_c,
	    c->arm.d_out_m, c->prop_diameter_m));
	m->eta_drive = 1.0; /* not read: the motor gives the drive's losses */
	x->j0 = c->prop_diameter_m > 0.0 ? prop_j0(c->prop_pitch_m
	    / c->prop_diameter_m) : 0.0;
	m->prop_j0 = x->j0;
	x->thrust_scale = 1.0;
	x->v_oc_nom_v = (double)c->cells * p->chem->v_nom;
	m->bus_voltage_v = x->v_oc_nom_v;
	m->real_drive = true;
	m->motor = c->motor;
	m->motor_temp_c = p->ambient_c;
	x->pack.chem = p->chem;
	x->pack.cells = c->cells;
	x->pack.capacity_ah = c->capacity_ah;
	x->pack.mass_kg = c->battery_kg;
	x->pack.cycles = p->cycles;
	x->pack.n_rotors = p->n_rotors;
	x->pack.h_conv_w_m2k = p->h_conv_w_m2k;
	/* A real pack's resistance follows its maker's rating. */
	if (c->battery_continuous_c > 0.0)
		x->pack.r_cells_ohm = (double)c->cells * batt_rated_cell_ohm(p->chem,
		    c->capacity_ah, c->battery_continuous_c);
	struct batt_r_sys rs;
	batt_r_sys_init(p->chem, c->cells, c->capacity_ah, p->cycles, p->n_rotors,
	    &rs);
	if (x->pack.r_cells_ohm > 0.0)
		rs.r_cells_ohm = x->pack.r_cells_ohm;
	x->r_sys_ohm = batt_r_sys_at(&rs, p->ambient_c);
}

/* Battery current and terminal voltage for a load of power_w on the pack
 * at its nominal open-circuit voltage (mid-discharge, as eCalc quotes). */
static bool
bus_load(const struct perf_ctx *x, double power_w, double *i_a, double *v_v)
{
	if (batt_current_a(x->v_oc_nom_v, x->r_sys_ohm, power_w, i_a) != BATT_OK)
		return false;
	*v_v = x->v_oc_nom_v - *i_a * x->r_sys_ohm;
	return true;
}

static double
motor_loss_w(const struct motor_point *mp)
{
	return mp->copper_loss_w + mp->no_load_loss_w;
}

/* The hover winding temperature, settled: losses set the temperature, the
 * temperature the winding's resistance and so the losses. */
static void
settle_hover(struct perf_ctx *x, double mass_kg)
{
	double rth = motor_thermal_resistance_k_w(x->c->motor.mass_kg);
	for (int k = 0; k < TEMP_ITERATIONS; k++) {
		struct mission_power mp;
		mission_power(&x->model, mass_kg, 0.0, 0.0, &mp);
		x->model.motor_temp_c = x->p->ambient_c + motor_loss_w(&mp.motor) * rth;
	}
	x->hover_temp_c = x->model.motor_temp_c;
	/* The installed torque the propeller asks at hover, as Q = kq n²: the
	 * full-throttle point turns the same rotor faster. */
	struct mission_power mp;
	mission_power(&x->model, mass_kg, 0.0, 0.0, &mp);
	double n = mp.rotor.rps;
	x->kq_nm_s2 = mp.rotor.p_shaft_w / (2.0 * M_PI * n * n * n);
}

/* One row of the operating-point table from a phase's power. */
static void
op_from(const struct perf_ctx *x, const struct mission_power *mp,
        double winding_c, struct res_op *op)
{
	memset(op, 0, sizeof *op);
	double i_b, v_b;
	if (!bus_load(x, mp->electrical_w, &i_b, &v_b))
		return;
	op->valid = true;
	op->thrust_n = mp->thrust_per_rotor_n;
	op->rpm = mp->rotor.rps * S_PER_MIN;
	op->motor_current_a = mp->motor.current_a;
	op->motor_voltage_v = mp->motor.voltage_v;
	op->power_in_w = mp->motor.power_in_w;
	op->power_shaft_w = mp->motor.power_shaft_w;
	op->motor_efficiency = mp->motor.efficiency;
	op->g_per_w = op->power_in_w > 0.0
	    ? op->thrust_n / G0_M_S2 * 1000.0 / op->power_in_w : 0.0;
	op->winding_temp_c = winding_c;
	op->tip_mach = mp->rotor.tip_mach;
	op->battery_current_a = i_b;
	op->bus_voltage_v = v_b;
	op->throttle = v_b > 0.0 ? op->motor_voltage_v / v_b : 0.0;
	op->c_load = i_b / x->c->capacity_ah;
	op->electrical_w = mp->electrical_w;
	/* A point that needs more voltage than the pack gives is not one the
	 * design can fly: kept for the checks, marked unreachable. */
	if (op->throttle > 1.0)
		op->valid = false;
}

/* A phase's operating point at mass_kg with its steady winding temperature. */
static void
phase_op(struct perf_ctx *x, double mass_kg, double v_climb_ms,
         double v_fwd_ms, struct mission_power *mp, struct res_op *op)
{
	mission_power(&x->model, mass_kg, v_climb_ms, v_fwd_ms, mp);
	double rth = motor_thermal_resistance_k_w(x->c->motor.mass_kg);
	op_from(x, mp, x->p->ambient_c + motor_loss_w(&mp->motor) * rth, op);
}

/* A full-throttle row of the table from the motor's point pt at thrust_n
 * (one rotor), with the pack's current i_b and terminal voltage v_b. */
static void
full_op(const struct perf_ctx *x, const struct motor_point *pt,
        double thrust_n, double throttle, double i_b, double v_b,
        struct res_op *op)
{
	const struct perf_craft *c = x->c;
	memset(op, 0, sizeof *op);
	op->valid = true;
	op->thrust_n = thrust_n;
	op->rpm = pt->rps * S_PER_MIN;
	op->throttle = throttle;
	op->motor_current_a = pt->current_a;
	op->motor_voltage_v = pt->voltage_v;
	op->power_in_w = pt->power_in_w;
	op->power_shaft_w = pt->power_shaft_w;
	op->motor_efficiency = pt->efficiency;
	op->g_per_w = op->thrust_n / G0_M_S2 * 1000.0 / pt->power_in_w;
	op->winding_temp_c = motor_temp_step_c(c->motor.mass_kg, x->hover_temp_c,
	    x->p->ambient_c, motor_loss_w(pt), PERF_FULL_THROTTLE_S);
	op->tip_mach = M_PI * c->prop_diameter_m * pt->rps / x->model.air.sound_m_s;
	op->battery_current_a = i_b;
	op->bus_voltage_v = v_b;
	op->c_load = i_b / c->capacity_ah;
	op->electrical_w = v_b * i_b;
}

/* The pack's terminal voltage when the motors draw i_motor_a each and the
 * rest (ESC switching, auxiliary load) other_w: the larger root of
 * V = V_oc - R (N I + P_other / V), V² - (V_oc - R N I) V + R P_other = 0.
 * False when the pack cannot deliver it (the voltage collapses). */
static bool
bus_voltage(const struct perf_ctx *x, double i_motor_a, double other_w,
            double *v_b)
{
	double a = x->v_oc_nom_v - x->r_sys_ohm * (double)x->model.n_rotors
	    * i_motor_a;
	double disc = a * a - 4.0 * x->r_sys_ohm * other_w;
	if (!(a > 0.0) || disc < 0.0)
		return false;
	*v_b = 0.5 * (a + sqrt(disc));
	return true;
}

/* At full throttle with an axial inflow of v_axial_ms, the rotor turning
 * n rev/s: the voltage the motor needs, 2π K n + I R(T) with the current
 * the propeller's torque kq C_P(J)/C_P0 n² sets (I = Q / K + I0), less the
 * voltage the pack gives at that current (*v_pack; 0 where it collapses).
 * It rises with n. */
static double
throttle_gap(const struct perf_ctx *x, double v_axial_ms, double n,
             double other_w, double *v_pack)
{
	const struct perf_craft *c = x->c;
	double k = motor_k_nm_a(c->motor.kv_rpm_per_v);
	double r = therm_winding_resistance_ohm(c->motor.resistance_ohm,
	    x->hover_temp_c);
	double q = x->kq_nm_s2 * prop_cp_ratio(prop_advance_ratio(v_axial_ms, n,
	    c->prop_diameter_m), x->j0) * n * n;
	double i_m = q / k + c->motor.no_load_current_a;
	if (!bus_voltage(x, i_m, other_w, v_pack))
		*v_pack = 0.0;
	return 2.0 * M_PI * k * n + i_m * r - *v_pack;
}

/* Full throttle with an axial inflow of v_axial_ms: the motor on the
 * pack's loaded voltage turns the rotor until its torque meets the
 * propeller's, and the pack's voltage sags under the current that draws.
 * *pt gets one motor's point, *i_b and *v_b the pack's current and
 * voltage.  False when the motor cannot turn at all.
 *
 * At rest (v_axial_ms 0) the propeller's torque is kq n² (the installed
 * kq) and motor_at_voltage() solves the motor on a voltage V; the
 * terminal voltage solves V = V_oc - R (N I_motor(V) + P_other / V), whose
 * right side falls as V rises, so bisection on V finds it.  With an inflow
 * the torque is kq C_P(J)/C_P0 n², J = V / (n D) (prop.h): then the speed
 * n is solved for instead.  At n the propeller's torque sets the current,
 * I = Q / K + I0, and so the voltage the motor needs, 2π K n + I R(T);
 * both rise with n while the voltage the pack gives at that current falls,
 * so they meet once between rest and the no-load speed on the full pack
 * (throttle_gap()). */
static bool
full_throttle_at(const struct perf_ctx *x, double v_axial_ms,
                 struct motor_point *pt, double *i_b, double *v_b)
{
	const struct perf_craft *c = x->c;
	const struct mission_model *m = &x->model;
	double n_rot = (double)m->n_rotors;
	double other_w = 0.5 * MISSION_F_PWM_HZ * MISSION_C_OSS_F
	    * x->v_oc_nom_v * x->v_oc_nom_v * n_rot + m->aux_w;
	if (!(v_axial_ms > 0.0) || !(x->j0 > 0.0)) {
		double lo = 0.0, hi = x->v_oc_nom_v;
		if (!motor_at_voltage(&c->motor, x->hover_temp_c, hi, x->kq_nm_s2,
		    pt))
			return false;
		for (int k = 0; k < BUS_ITERATIONS; k++) {
			double v = 0.5 * (lo + hi);
			double i = motor_at_voltage(&c->motor, x->hover_temp_c, v,
			    x->kq_nm_s2, pt) ? n_rot * pt->current_a : 0.0;
			i += other_w / v;
			if (x->v_oc_nom_v - x->r_sys_ohm * i > v)
				lo = v;
			else
				hi = v;
		}
		*v_b = lo;
		if (!motor_at_voltage(&c->motor, x->hover_temp_c, lo, x->kq_nm_s2, pt))
			return false;
		*i_b = n_rot * pt->current_a + other_w / lo;
		return true;
	}
	/* Regula falsi with the Illinois step (the end that stays put has
	 * its gap halved): the gap is smooth and monotone, so it closes in a
	 * few steps where bisection takes fifty. */
	double k = motor_k_nm_a(c->motor.kv_rpm_per_v);
	double lo = 0.0, hi = x->v_oc_nom_v / (2.0 * M_PI * k), v_pack = 0.0;
	double g_lo = throttle_gap(x, v_axial_ms, lo, other_w, &v_pack);
	double g_hi = throttle_gap(x, v_axial_ms, hi, other_w, &v_pack);
	if (!(g_lo < 0.0))
		return false;   /* the pack cannot even push the no-load current */
	double n = hi, tol = RPS_REL_TOL * hi;
	int side = 0;
	for (int i = 0; i < RPS_ITERATIONS && g_hi > 0.0 && hi - lo > tol; i++) {
		n = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
		if (!(n > lo && n < hi))
			n = 0.5 * (lo + hi);
		double g = throttle_gap(x, v_axial_ms, n, other_w, &v_pack);
		if (fabs(g) <= RPS_REL_TOL * x->v_oc_nom_v)
			break;
		if (g < 0.0) {
			lo = n;
			g_lo = g;
			if (side < 0)
				g_hi *= 0.5;
			side = -1;
		} else {
			hi = n;
			g_hi = g;
			if (side > 0)
				g_lo *= 0.5;
			side = 1;
		}
	}
	(void)throttle_gap(x, v_axial_ms, n, other_w, &v_pack);
	if (!(v_pack > 0.0))
		return false;
	motor_at_voltage_rps(&c->motor, x->hover_temp_c, v_pack, n, pt);
	*v_b = v_pack;
	*i_b = n_rot * pt->current_a + other_w / v_pack;
	return true;
}

/* Full throttle at rest: the table's row. */
static bool
full_throttle(const struct perf_ctx *x, struct res_op *op)
{
	const struct perf_craft *c = x->c;
	struct motor_point pt;
	double i_b, v_b;
	if (!full_throttle_at(x, 0.0, &pt, &i_b, &v_b))
		return false;
	full_op(x, &pt, prop_thrust_n(&c->prop, x->model.air.rho_kg_m3, pt.rps,
	    c->prop_diameter_m), 1.0, i_b, v_b, op);
	return true;
}

/* One rotor's full thrust with an axial inflow of v_axial_ms: C_T(J) of
 * the propeller at the speed the torque balance gives, times the maker's
 * cap of an integrated system (thrust_scale); 0 when the motor cannot
 * turn, negative past the zero-thrust advance ratio. */
static double
full_thrust_at_n(const struct perf_ctx *x, double v_axial_ms)
{
	const struct perf_craft *c = x->c;
	struct motor_point pt;
	double i_b, v_b;
	if (!full_throttle_at(x, v_axial_ms, &pt, &i_b, &v_b))
		return 0.0;
	double d = c->prop_diameter_m;
	return x->thrust_scale * prop_ct_ratio(prop_advance_ratio(v_axial_ms,
	    pt.rps, d), x->j0) * prop_thrust_n(&c->prop, x->model.air.rho_kg_m3,
	    pt.rps, d);
}

/* An integrated power system gives at most the thrust its maker
 * publishes (perf_craft.max_thrust_n): where the model of its motor and
 * propeller promises more, the full-throttle point is the one at that
 * thrust, on the same rotor.  False when the model cannot reach it. */
static bool
capped_full_throttle(const struct perf_ctx *x, struct res_op *op)
{
	const struct perf_craft *c = x->c;
	if (!(c->max_thrust_n > 0.0) || op->thrust_n <= c->max_thrust_n)
		return true;
	double rho = x->model.air.rho_kg_m3;
	double d = c->prop_diameter_m;
	double n = sqrt(c->max_thrust_n / (c->prop.ct * rho * pow(d, 4.0)));
	struct motor_point pt;
	motor_at_shaft(&c->motor, x->hover_temp_c,
	    x->kq_nm_s2 * 2.0 * M_PI * n * n * n, n, &pt);
	/* Nor past its own ESC's continuous rating on the installed rotor:
	 * the torque K (I - I0) meets kq n² at n_esc. */
	double i0 = c->motor.no_load_current_a;
	if (c->esc_current_a > i0 && pt.current_a > c->esc_current_a) {
		n = sqrt(motor_k_nm_a(c->motor.kv_rpm_per_v)
		    * (c->esc_current_a - i0) / x->kq_nm_s2);
		motor_at_shaft(&c->motor, x->hover_temp_c,
		    x->kq_nm_s2 * 2.0 * M_PI * n * n * n, n, &pt);
	}
	double thrust_n = fmin(c->max_thrust_n, prop_thrust_n(&c->prop, rho, n, d));
	double n_rot = (double)x->model.n_rotors;
	double other_w = 0.5 * MISSION_F_PWM_HZ * MISSION_C_OSS_F
	    * x->v_oc_nom_v * x->v_oc_nom_v * n_rot + x->model.aux_w;
	double i_b, v_b;
	if (!bus_load(x, n_rot * pt.power_in_w + other_w, &i_b, &v_b))
		return false;
	full_op(x, &pt, thrust_n, v_b > 0.0 && pt.voltage_v < v_b
	    ? pt.voltage_v / v_b : 1.0, i_b, v_b, op);
	return true;
}

/* An integrated system's full thrust at rest is capped at its maker's
 * figure (capped_full_throttle()); the envelope scales the model's thrust
 * at every inflow by the same share.  After settle_hover(). */
static void
set_thrust_scale(struct perf_ctx *x)
{
	struct res_op op;
	x->thrust_scale = 1.0;
	if (x->c->max_thrust_n > 0.0 && full_throttle(x, &op)
	    && op.thrust_n > x->c->max_thrust_n)
		x->thrust_scale = x->c->max_thrust_n / op.thrust_n;
}

/* Fly the mission at goal relaxation gamma into run's trace and dis. */
static void
fly(const struct perf_ctx *x, double gamma, double v_fwd_ms,
    struct res_run *run, struct discharge_out *dis)
{
	const struct sizing_params *p = x->p;
	struct duty_plan plan;
	sizing_plan(p, gamma, x->v_climb_ms, v_fwd_ms, &plan);
	struct discharge_mission dm;
	memset(&dm, 0, sizeof dm);
	dm.model = &x->model;
	dm.dry_mass_kg = x->c->mass.total_kg - p->payload_kg;
	dm.plan = &plan;
	dm.full_throttle_w = x->full_w;
	dm.full_throttle_shaft_w = x->full_shaft_w;
	dm.full_throttle_v = x->full_v;
	dm.ambient_c = p->ambient_c;
	discharge_run(&x->pack, &dm, SIZING_FINAL_STEPS,
	    run != NULL ? run->trace : NULL, run != NULL ? RES_MAX_TRACE : 0,
	    run != NULL ? &run->n_trace : NULL, dis);
}

/* Lands with at least the reserve: the mission is flown. */
static bool
landed(const struct discharge_out *dis, double reserve_soc)
{
	return dis->end == DIS_COMPLETED && dis->end_soc >= reserve_soc - 1e-9;
}

/* The largest γ in [γ_min, 1] whose mission lands at the reserve, by
 * bisection (the mission only gets harder with γ); 0 when none does. */
static double
relaxed_gamma(const struct perf_ctx *x, double v_fwd_ms, double reserve_soc)
{
	struct discharge_out dis;
	fly(x, SIZING_GAMMA_MIN, v_fwd_ms, NULL, &dis);
	if (!landed(&dis, reserve_soc))
		return 0.0;
	double lo = SIZING_GAMMA_MIN, hi = 1.0;
	for (int k = 0; k < GAMMA_BISECT; k++) {
		double mid = 0.5 * (lo + hi);
		fly(x, mid, v_fwd_ms, NULL, &dis);
		if (landed(&dis, reserve_soc))
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

/* Does full throttle at a vertical climb of v_ms still carry the weight
 * and the climb's drag, the propeller's thrust taken at the climb's
 * inflow? */
static bool
climb_within(const struct perf_ctx *x, double mass_kg, double v_ms)
{
	struct mission_power mp;
	mission_power(&x->model, mass_kg, v_ms, 0.0, &mp);
	return mp.thrust_per_rotor_n <= full_thrust_at_n(x, v_ms);
}

/* The highest vertical climb rate at full throttle: thrust falls with the
 * climb's inflow as C_T(J) does while the motor speeds up as the
 * propeller's torque falls, and weight plus drag must still be carried.
 * Bisection to 1 mm/s between rest and the zero-thrust speed at the motor's
 * no-load speed on the full pack, J0 n D: the propeller gives no thrust
 * there at any speed the motor turns, so the bound is never the answer.
 * Without a pitch (no J0) CLIMB_MAX_MS bounds it, reported as the bound
 * when reached.  0 when full throttle does not even hover. */
static double
max_climb_ms(const struct perf_ctx *x, double mass_kg, enum res_limit *limit,
             double *rpm)
{
	*limit = RES_LIMIT_INFLOW;
	*rpm = 0.0;
	if (!climb_within(x, mass_kg, 0.0))
		return 0.0;
	double k = motor_k_nm_a(x->c->motor.kv_rpm_per_v);
	double hi = x->j0 > 0.0 ? prop_zero_thrust_speed_ms(x->j0,
	    x->v_oc_nom_v / (2.0 * M_PI * k), x->c->prop_diameter_m) : CLIMB_MAX_MS;
	if (climb_within(x, mass_kg, hi)) {
		*limit = RES_LIMIT_BOUND;
		return hi;
	}
	double lo = 0.0;
	for (int i = 0; i < ENVELOPE_ITERATIONS && hi - lo > ENVELOPE_TOL_MS; i++) {
		double mid = 0.5 * (lo + hi);
		if (climb_within(x, mass_kg, mid))
			lo = mid;
		else
			hi = mid;
	}
	struct motor_point pt;
	double i_b, v_b;
	if (full_throttle_at(x, lo, &pt, &i_b, &v_b))
		*rpm = pt.rps * S_PER_MIN;
	return lo;
}

/* Is level flight at v_ms within the limits: the pitch under
 * MISSION_PITCH_MAX_DEG, and full throttle's thrust at the axial inflow
 * V sin θ through the tilted disk carrying weight and drag?  *pitch_over
 * says whether the pitch is past its limit. */
static bool
level_within(const struct perf_ctx *x, double mass_kg, double v_ms,
             bool *pitch_over)
{
	struct mission_power mp;
	mission_power(&x->model, mass_kg, 0.0, v_ms, &mp);
	*pitch_over = mp.pitch_deg > MISSION_PITCH_MAX_DEG;
	return !*pitch_over
	    && mp.thrust_per_rotor_n <= full_thrust_at_n(x, mp.axial_ms);
}

/* The top level speed of the design of record: the pitch limit's speed
 * (mission.h) when full thrust still carries the aircraft there, else the
 * speed where it no longer does, by bisection to 1 mm/s.  Past the pitch
 * limit's speed the pitch alone is beyond it, so the search's bound is a
 * physical limit (MISSION_SPEED_CAP_MS only for a body without drag,
 * reported as the bound).  0 when full throttle does not even hover.
 * With enough_ms > 0 the bisection stops once the speed is known to be at
 * least enough_ms (the result is then a lower bound at or above it): a
 * trial closing asks only whether its mission's speed is reached, and
 * every use of the top speed (the clamp of the speed flown, the
 * FORWARD_SPEED check) then reads the same as with the exact one. */
static double
max_level_ms(const struct perf_ctx *x, double mass_kg, enum res_limit *limit,
             double enough_ms)
{
	bool pitch_over;
	*limit = RES_LIMIT_INFLOW;
	if (!level_within(x, mass_kg, 0.0, &pitch_over))
		return 0.0;
	double hi = mission_pitch_limit_speed_ms(&x->model, mass_kg);
	if (level_within(x, mass_kg, hi, &pitch_over)) {
		*limit = hi >= MISSION_SPEED_CAP_MS ? RES_LIMIT_BOUND : RES_LIMIT_PITCH;
		return hi;
	}
	double lo = 0.0;
	bool hi_pitch = pitch_over;
	for (int i = 0; i < ENVELOPE_ITERATIONS && hi - lo > ENVELOPE_TOL_MS; i++) {
		double mid = 0.5 * (lo + hi);
		if (level_within(x, mass_kg, mid, &pitch_over)) {
			lo = mid;
			if (enough_ms > 0.0 && lo >= enough_ms)
				break;
		} else {
			hi = mid;
			hi_pitch = pitch_over;
		}
	}
	*limit = hi_pitch ? RES_LIMIT_PITCH : RES_LIMIT_INFLOW;
	return lo;
}

/* The performance figures beyond the mission. */
static void
figures(struct perf_ctx *x, struct res_run *run, struct res_perf *pf)
{
	const struct sizing_params *p = x->p;
	double mass = x->c->mass.total_kg;
	double weight_n = mass * G0_M_S2;
	double n_rot = (double)p->n_rotors;
	const struct res_op *full = &pf->op[OP_FULL];
	double reserve = run->reserve_soc;

	pf->hover_time_s = discharge_hover_endurance_steps_s(&x->pack, &x->model,
	    mass, p->ambient_c, reserve, ENDURANCE_STEPS);
	/* The run's own figures: one number each, on every page and file. */
	run->hover_endurance_s = pf->hover_time_s;
	run->hover_power_w = pf->op[OP_HOVER].electrical_w;
	struct mission_power shed;
	mission_power(&x->model, res_lightest_mass_kg(run), 0.0, 0.0, &shed);
	run->hover_power_shed_w = shed.electrical_w;
	pf->full_throttle_time_s = discharge_power_endurance_s(&x->pack,
	    full->electrical_w, p->ambient_c, reserve, ENDURANCE_STEPS);
	/* The mission's mix repeated to the reserve: its time scaled by the
	 * usable charge over the charge it drew. */
	double used = 1.0 - run->end_soc;
	pf->mixed_time_s = used > 0.0 && run->flight_time_s > 0.0
	    ? run->flight_time_s * (1.0 - reserve) / used : 0.0;
	pf->max_climb_ms = max_climb_ms(x, mass, &pf->max_climb_limit,
	    &pf->max_climb_rpm);
	double ratio = n_rot * full->thrust_n / weight_n;
	pf->max_tilt_deg = ratio > 1.0 ? acos(1.0 / ratio) * 180.0 / M_PI : 0.0;
	/* T/W of the role's thrust target, 1 / θ² (paper §II-E). */
	double theta = 1.0 - p->thrust_margin;
	double tw_target = 1.0 / (theta * theta);
	double spare = n_rot * full->thrust_n / (G0_M_S2 * tw_target) - mass;
	pf->spare_payload_kg = spare > 0.0 ? spare : 0.0;
	/* One motor out: the opposite one throttles back to keep yaw and roll
	 * trimmed, so N - 2 rotors carry the weight (a conservative rule for
	 * hexa- and octocopters; a quadcopter cannot fly on three). */
	if (p->n_rotors >= 6) {
		pf->motor_out_rotors = p->n_rotors - 2;
		pf->motor_out_ratio = (double)pf->motor_out_rotors * full->thrust_n
		    / weight_n;
		pf->motor_out_holds = pf->motor_out_ratio >= 1.0;
	}
}

/* The masses, battery and structure of the craft into run. */
static void
record_craft(const struct perf_ctx *x, struct res_run *run)
{
	const struct sizing_params *p = x->p;
	const struct perf_craft *c = x->c;
	run->mass = c->mass;
	str_copy(run->chemistry, sizeof run->chemistry, p->chem->name);
	run->cell_count = c->cells;
	run->pack_count = 1;
	run->capacity_mah = c->capacity_ah * 1000.0;
	run->nominal_voltage_v = x->v_oc_nom_v;
	run->energy_wh = c->capacity_ah * x->v_oc_nom_v;
	run->packaging_factor = 0.0;
	run->reserve_soc = sizing_reserve_soc();
	run->fom_installed = x->model.rotor.fom;
	run->interference = aero_interference(p->interference_c, c->arm.d_out_m,
	    c->prop_diameter_m);
	double area = 0.25 * M_PI * c->prop_diameter_m * c->prop_diameter_m;
	run->overlap_limit_in = m_to_in(aero_overlap_limit_m(p->wheelbase_m,
	    n_arms(p), AERO_TIP_CLEARANCE));
	run->disk_loading_n_m2 = c->mass.total_kg * G0_M_S2
	    / ((double)n_arms(p) * area);
	run->downwash_ms = aero_downwash_ms(c->mass.total_kg, p->air.rho_kg_m3,
	    n_arms(p), area);
	airframe_record_arm(&c->arm, c->prop_diameter_m, run);
	run->arm_tip_mass_kg = (c->mass.motor_kg + c->mass.prop_kg)
	    / (double)p->n_rotors * (p->coaxial ? 2.0 : 1.0);
}

/* Each phase: its duration and what the discharge drew, its operating
 * point at its time-averaged mass (a drop or a spray lightens it along the
 * phase; the mean power, convex in mass, is then at least that point's). */
static void
record_phases(struct perf_ctx *x, double gamma, double v_fwd_ms,
              const struct discharge_out *dis, struct res_run *run)
{
	const struct sizing_params *p = x->p;
	struct duty_plan plan;
	sizing_plan(p, gamma, x->v_climb_ms, v_fwd_ms, &plan);
	const double *d = plan.phase_s;
	discharge_duty_record(&plan, dis, x->full_w,
	    p->duty != NULL ? p->duty->source : NULL, &run->duty);
	double dry = x->c->mass.total_kg - p->payload_kg;
	run->flight_time_s = 0.0;
	for (int i = 0; i < PHASE_MAX; i++) {
		struct res_phase *ph = &run->phase[i];
		double v_c = i == PHASE_CLIMB ? x->v_climb_ms : 0.0;
		double v_f = i == PHASE_FORWARD ? v_fwd_ms : 0.0;
		struct mission_power mp;
		struct res_op op;
		phase_op(x, dry + duty_phase_mean_payload(&plan, i), v_c, v_f,
		    &mp, &op);
		run->approved_time_s[i] = d[i];
		run->flight_time_s += d[i];
		ph->duration_s = d[i];
		ph->speed_ms = v_c + v_f;
		ph->thrust_per_rotor_n = mp.thrust_per_rotor_n;
		/* A profile's phase is segments of their own powers (laps,
		 * turns): its shaft power is theirs, as flown. */
		ph->shaft_power_w = plan.kind != DUTY_PHASES
		    && dis->phase_mean_shaft_w[i] > 0.0
		    ? dis->phase_mean_shaft_w[i] : mp.shaft_w;
		ph->power_w = dis->phase_mean_power_w[i] > 0.0
		    ? dis->phase_mean_power_w[i] : mp.electrical_w;
		ph->current_a = dis->phase_mean_current_a[i];
		ph->energy_wh = dis->phase_energy_wh[i];
		ph->rpm = op.rpm;
		/* Saturated when out of reach (the checks say so). */
		ph->throttle = op.throttle < 1.0 ? op.throttle : 1.0;
		if (d[i] > 0.0 && op.throttle > run->perf.throttle_needed)
			run->perf.throttle_needed = op.throttle;
		if (d[i] > 0.0 && op.motor_current_a
		    > run->perf.sustained_motor_current_a)
			run->perf.sustained_motor_current_a = op.motor_current_a;
		ph->pitch_deg = mp.pitch_deg;
		ph->tip_mach = mp.rotor.tip_mach;
	}
	run->forward_pitch_deg = run->phase[PHASE_FORWARD].pitch_deg;
}

bool
perf_fly(const struct sizing_params *p, const struct perf_craft *c,
         bool trial, struct res_run *run)
{
	struct perf_ctx x;
	build(p, c, &x);
	res_run_clear_untraced(run);
	run->ran = true;
	run->converged = true;
	run->thrust_margin = p->thrust_margin;
	run->aux_power_w = x.model.aux_w;
	record_craft(&x, run);
	double mass = c->mass.total_kg;
	struct res_perf *pf = &run->perf;

	/* Hover settles the winding; full throttle sets what the rotor can do. */
	settle_hover(&x, mass);
	struct mission_power mp;
	phase_op(&x, mass, 0.0, 0.0, &mp, &pf->op[OP_HOVER]);
	pf->throttle_needed = pf->op[OP_HOVER].throttle;
	pf->sustained_motor_current_a = pf->op[OP_HOVER].motor_current_a;
	/* A drive that cannot turn on this pack (the voltage collapses under
	 * the current) gives no full-throttle point: no thrust to spare, which
	 * the checks then fail. */
	if (!full_throttle(&x, &pf->op[OP_FULL])
	    || !capped_full_throttle(&x, &pf->op[OP_FULL]))
		memset(&pf->op[OP_FULL], 0, sizeof pf->op[OP_FULL]);
	const struct res_op *full = &pf->op[OP_FULL];
	/* A race's pieces are fractions of this power. */
	x.full_w = full->electrical_w;
	x.full_shaft_w = full->power_shaft_w * (double)p->n_rotors;
	x.full_v = full->bus_voltage_v;

	/* Forward speed: the minimum-power speed when "auto", found on the
	 * sweep's grid within the rotor's limits (the sweep itself is a
	 * figure: perf_figures()); the top speed, the real motor and
	 * propeller at the inflow through the tilted disk. */
	set_thrust_scale(&x);
	double v_top_search_ms; /* the model's own, at a held rotor speed: unused */
	if (p->v_auto || !trial)
		mission_speed_search(&x.model, mass, full->thrust_n,
		    &run->v_min_power_ms, &v_top_search_ms);
	double v_fwd = p->v_auto ? run->v_min_power_ms : p->v_forward_ms;
	run->v_max_ms = max_level_ms(&x, mass, &run->v_max_limit,
	    trial ? v_fwd : 0.0);
	run->optimal_speed_ms = v_fwd;
	/* What full thrust (or the pitch limit) does not reach is flown at the
	 * fastest it does (FORWARD_SPEED, CLIMB_SPEED report the shortfall). */
	if (v_fwd > run->v_max_ms)
		v_fwd = run->v_max_ms;
	x.v_climb_ms = p->v_climb_ms;
	if (p->v_climb_ms > 0.0 && !climb_within(&x, mass, p->v_climb_ms)) {
		enum res_limit climb_limit;
		double climb_rpm;
		x.v_climb_ms = max_climb_ms(&x, mass, &climb_limit, &climb_rpm);
	}
	run->climb_limit_ms = x.v_climb_ms < p->v_climb_ms ? x.v_climb_ms : 0.0;
	phase_op(&x, mass, x.v_climb_ms > 0.0 ? x.v_climb_ms : 1.0, 0.0, &mp,
	    &pf->op[OP_CLIMB]);
	phase_op(&x, mass, 0.0, v_fwd > 0.0 ? v_fwd : 1.0, &mp, &pf->op[OP_CRUISE]);

	/* The mission: whole, or relaxed when the mission allows it. */
	struct discharge_out dis;
	double gamma = 1.0;
	fly(&x, gamma, v_fwd, run, &dis);
	if (!landed(&dis, run->reserve_soc) && p->allow_relax) {
		double g = relaxed_gamma(&x, v_fwd, run->reserve_soc);
		if (g > 0.0) {
			gamma = g;
			fly(&x, gamma, v_fwd, run, &dis);
		}
	}
	run->time_scale = gamma;
	record_phases(&x, gamma, v_fwd, &dis, run);
	run->max_battery_temp_c = dis.peak_temp_c;
	run->thermal_margin_c = THERM_RUNAWAY_C - dis.peak_temp_c;
	run->min_terminal_voltage_v = dis.min_v_term_v;
	run->voltage_floor_v = (double)c->cells * p->chem->v_cutoff;
	run->end_soc = dis.end_soc;
	str_copy(run->termination, sizeof run->termination,
	    discharge_end_text[dis.end]);

	/* Propulsion summary, as the continuous run states it. */
	const struct res_op *hov = &pf->op[OP_HOVER];
	run->thrust_to_weight = (double)p->n_rotors * full->thrust_n
	    / (mass * G0_M_S2);
	run->hover_throttle = hov->throttle < 1.0 ? hov->throttle : 1.0;
	run->rpm_hover = hov->rpm;
	run->rpm_peak = full->rpm;
	run->tip_mach_peak = full->tip_mach;
	run->reynolds_tip = mp.rotor.reynolds_tip;
	run->peak_power_w = full->electrical_w;
	run->peak_current_a = full->battery_current_a;
	run->peak_c_rate = full->c_load;
	/* The blade-pass band up to full throttle (to hover, without one). */
	double rpm_top = full->valid ? full->rpm : hov->rpm;
	run->blade_pass_frequency_hz = (double)c->prop_blades * rpm_top / S_PER_MIN;
	run->blade_pass_low_hz = (double)c->prop_blades * SIZING_LOW_FLIGHT_RPM
	    * hov->rpm / S_PER_MIN;
	run->resonance_margin = structure_resonance_margin(c->arm.f_nat_hz,
	    run->blade_pass_low_hz, run->blade_pass_frequency_hz);
	run->winding_temp_c = x.hover_temp_c;
	run->motor_winding_resistance_ohm = therm_winding_resistance_ohm(
	    c->motor.resistance_ohm, x.hover_temp_c);
	struct mission_power hp;
	mission_power(&x.model, mass, 0.0, 0.0, &hp);
	run->motor_copper_loss_w = hp.motor.copper_loss_w;
	run->opt.prop_diameter_in = m_to_in(c->prop_diameter_m);
	run->opt.prop_pitch_in = m_to_in(c->prop_pitch_m);
	run->opt.motor_kv = c->motor.kv_rpm_per_v;
	run->opt.motor_mass_kg = c->motor.mass_kg;
	run->opt.motor_peak_current_a = full->motor_current_a;
	run->opt.motor_peak_power_w = full->power_in_w;

	pf->valid = true;
	pf->motor_resistance_ohm = c->motor.resistance_ohm;
	pf->motor_no_load_a = c->motor.no_load_current_a;
	pf->motor_r_estimated = c->motor_r_estimated;
	pf->prop_ct = c->prop.ct;
	pf->prop_cp = c->prop.cp;
	pf->prop_coeffs_measured = c->prop.measured;
	pf->prop_fom = prop_fom(&c->prop);
	run->kappa = p->fom_override > 0.0 || p->fom_isolated_mode ? 1.0 : p->kappa;
	pf->max_speed_ms = run->v_max_ms;
	pf->max_speed_limit = run->v_max_limit;
	pf->landing_soc = run->end_soc;

	/* Every number it produced must be a number. */
	const double v[] = { run->max_battery_temp_c, run->min_terminal_voltage_v,
		run->peak_power_w, run->peak_current_a, run->thrust_to_weight,
		run->hover_throttle, run->end_soc, run->downwash_ms,
		run->resonance_margin };
	for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
		if (!isfinite(v[i]))
			return false;
	for (int i = 0; i < OP_MAX; i++)
		if (!isfinite(pf->op[i].power_in_w) || !isfinite(pf->op[i].throttle))
			return false;
	return true;
}

bool
perf_figures(const struct sizing_params *p, const struct perf_craft *c,
             struct res_run *run)
{
	/* The state perf_fly() left them: built, hover settled. */
	struct perf_ctx x;
	build(p, c, &x);
	if (run->climb_limit_ms > 0.0)
		x.v_climb_ms = run->climb_limit_ms;
	settle_hover(&x, c->mass.total_kg);
	set_thrust_scale(&x);
	struct res_perf *pf = &run->perf;
	figures(&x, run, pf);
	/* The power-vs-speed figure, limited by the real rotor's full thrust;
	 * its speeds are the search's of perf_fly(). */
	double v_min_power_ms, v_max_ms;
	run->n_sweep = mission_speed_sweep(&x.model, c->mass.total_kg,
	    pf->op[OP_FULL].thrust_n, run->sweep_v_ms, run->sweep_power_w,
	    RES_MAX_SWEEP, &v_min_power_ms, &v_max_ms);
	const double v[] = { pf->hover_time_s, pf->mixed_time_s,
		pf->full_throttle_time_s, pf->max_climb_ms, pf->max_tilt_deg,
		pf->spare_payload_kg, pf->motor_out_ratio };
	for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
		if (!isfinite(v[i]))
			return false;
	return true;
}
