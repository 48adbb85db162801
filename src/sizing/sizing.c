/* sizing.c — the Banach fixed-point mass loop (see sizing.h). */
#include "sizing/sizing.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics/aero.h"
#include "sizing/airframe.h"
#include "physics/discharge.h"
#include "physics/mission.h"
#include "physics/prop.h"
#include "util/strbuf.h"
#include "physics/structure.h"
#include "physics/therm.h"
#include "util/units.h"

#define LOOP_STEPS        30    /* discharge steps per loop iteration */
#define FINAL_STEPS       SIZING_FINAL_STEPS
#define BLADE_INCIDENCE_DEG 4.0 /* best-L/D incidence at blade Reynolds numbers */
#define MIN_THROTTLE      0.20  /* t_hover floor of paper §V-D */
#define LIPSCHITZ_STEP    0.01  /* ±1 % of M for dF/dM */
#define GAMMA_BISECT      8     /* bisection steps of the goal relaxation */
#define ENDURANCE_SCALES  RES_MAX_ENDURANCE
#define EXPLORER_MAX_ITER 80
#define EXPLORER_ENDURANCE_STEPS 30 /* a curve, not the design point */

/* Loop state carried from one iteration to the next. */
struct loop_state {
	int cells;            /* series cells in use */
	double arm_width_m;   /* arm outer diameter (rotor-arm interference) */
	double gamma_time;    /* goal relaxation factor */
	/* the loop's last speed search (iterate() owns it; NULL elsewhere):
	 * the next iteration's, at a mass close by, starts from it */
	struct mission_speed_hint *speed_hint;
};

/* Everything evaluated at one takeoff mass. */
struct eval {
	double mass_kg;                 /* M at which it was evaluated */
	double capacity_ah;             /* capacity used */
	struct mission_model model;
	double v_climb_ms;              /* flown */
	double climb_limit_ms;          /* > 0: the asked climb was beyond it */
	double v_fwd_ms;                /* flown */
	double v_fwd_request_ms;        /* asked: the mission's, or "auto"'s */
	double v_min_power_ms, v_max_ms;
	struct mission_power ph[PHASE_MAX];
	bool phases_done;               /* ph and pitch_m set (eval_phases()) */
	struct mission_power peak;
	double throttle;                /* hover throttle target */
	double t_hover_n, t_peak_n;     /* per rotor */
	double design_mass_kg;          /* M plus the payload beyond the mission's */
	double rps_hover, rps_peak;
	double fom_inst, k_int;
	double overlap_limit_m;
	double pitch_m;
	int cells;
	double kv;
	double eta_pkg;
	bool power_binds;               /* battery sized by power, not energy */
	struct structure_arm arm;
	bool cg_ok;
	bool min_fraction_binds;
	double shell_kg;                /* body shell, part of mass.other_kg */
	struct res_mass mass;
	double peak_current_a;
	struct discharge_out dis;
	double c_target_ah;
};

double
sizing_reserve_soc(void)
{
	/* A 20 % capacity margin leaves 1 - 1/1.2 of the pack at the end. */
	return 1.0 - 1.0 / SIZING_CAP_MARGIN;
}

double
sizing_seed_kg(double payload_kg, double rho_kg_m3)
{
	double base = payload_kg > 0.05 ? payload_kg : 0.05;
	double scale = sqrt(RHO_SL_KG_M3 / rho_kg_m3);
	/* Paper: applied only when the factor exceeds 1. */
	return base / SIZING_SEED_FRACTION * (scale > 1.0 ? scale : 1.0);
}

double
sizing_pitch_m(double diameter_m, double induced_ms, double rps)
{
	double r75 = 0.375 * diameter_m;
	double omega_r = 2.0 * M_PI * rps * r75;
	if (!(omega_r > 0.0))
		return 0.4 * diameter_m;
	double phi = atan(induced_ms / omega_r);
	double theta = phi + BLADE_INCIDENCE_DEG * M_PI / 180.0;
	return 2.0 * M_PI * r75 * tan(theta);
}

enum res_limit
sizing_limit(enum mission_limit l)
{
	switch (l) {
	case MISSION_LIMIT_THRUST:
		return RES_LIMIT_INFLOW;
	case MISSION_LIMIT_PITCH:
		return RES_LIMIT_PITCH;
	case MISSION_LIMIT_BOUND:
		return RES_LIMIT_BOUND;
	case MISSION_LIMIT_NONE:
	default:
		return RES_LIMIT_NONE;
	}
}

static int
n_arms(const struct sizing_params *p)
{
	return p->coaxial ? p->n_rotors / 2 : p->n_rotors;
}


void
sizing_durations(const struct sizing_params *p, double gamma_time, double *d)
{
	for (int i = 0; i < PHASE_MAX; i++)
		d[i] = p->duration_s[i] * gamma_time;
}

double
sizing_total_duration(const struct sizing_params *p, double gamma_time)
{
	double d[PHASE_MAX], t = 0.0;
	sizing_durations(p, gamma_time, d);
	for (int i = 0; i < PHASE_MAX; i++)
		t += d[i];
	return t;
}

void
sizing_plan(const struct sizing_params *p, double gamma_time, double v_climb_ms,
            double v_fwd_ms, struct duty_plan *out)
{
	struct duty_input in;
	memset(&in, 0, sizeof in);
	in.duty = p->duty;
	sizing_durations(p, gamma_time, in.duration_s);
	in.v_climb_ms = v_climb_ms;
	in.v_fwd_ms = v_fwd_ms;
	in.payload_kg = p->payload_kg;
	in.shed = p->shed;
	in.drop_mass_kg = p->drop_mass_kg;
	in.drop_ratio = p->drop_ratio;
	in.spray_rate_kg_s = p->spray_rate_kg_s;
	duty_plan_build(&in, out);
}

/* A real catalogue battery (BOM-closed run): its capacity is fixed. */
static bool
battery_fixed(const struct sizing_params *p)
{
	return p->parts.active && p->parts.battery_kg > 0.0;
}

/* A capacity the loop does not choose (locked, or a catalogue battery):
 * the masses then never depend on the mission's flights. */
static bool
capacity_given(const struct sizing_params *p)
{
	return p->capacity_locked || battery_fixed(p);
}

/* The battery that the loop state describes. */
static void
pack_of(const struct sizing_params *p, const struct eval *e,
        struct discharge_pack *pk)
{
	pk->chem = p->chem;
	pk->cells = e->cells;
	pk->capacity_ah = e->capacity_ah;
	pk->mass_kg = e->mass.battery_kg;
	pk->cycles = p->cycles;
	pk->n_rotors = p->n_rotors;
	pk->h_conv_w_m2k = p->h_conv_w_m2k;
	pk->r_cells_ohm = 0.0; /* the chemistry profile's (eq. rsys) */
	/* A role whose packs burst above the ordinary twice their continuous
	 * power (racing's high-C packs, data/roles.json) delivers that power
	 * through proportionally less resistance than the profile's. */
	if (p->burst_factor > SIZING_BURST_ORDINARY) {
		struct batt_r_sys rs;
		batt_r_sys_init(p->chem, e->cells, e->capacity_ah, p->cycles,
		    p->n_rotors, &rs);
		pk->r_cells_ohm = rs.r_cells_ohm * SIZING_BURST_ORDINARY
		    / p->burst_factor;
	}
}

/* The three phase powers of an evaluation, and the hover pitch they give
 * (unless the propeller is locked); once, when first needed. */
static void
eval_phases(const struct sizing_params *p, struct eval *e)
{
	if (e->phases_done)
		return;
	const struct mission_model *m = &e->model;
	mission_power(m, e->mass_kg, e->v_climb_ms, 0.0, &e->ph[PHASE_CLIMB]);
	mission_power(m, e->mass_kg, 0.0, e->v_fwd_ms, &e->ph[PHASE_FORWARD]);
	mission_power(m, e->mass_kg, 0.0, 0.0, &e->ph[PHASE_HOVER]);
	if (!p->prop_locked)
		e->pitch_m = sizing_pitch_m(m->rotor.diameter_m,
		    e->ph[PHASE_HOVER].rotor.induced_ms, e->rps_hover);
	e->phases_done = true;
}

/* What the masses of an evaluation share whatever its series cells
 * (evaluate_masses() may try several): the motors and propellers, sized by
 * shaft power and speed, and the airframe their loads size, its harness
 * aside (that carries the bus current). */
struct drive_masses {
	double motor_total_kg;         /* all motors */
	double prop_each_kg;           /* one propeller */
	struct airframe_masses am;     /* wiring_kg unset: airframe_harness() */
};

/* The drive_masses of evaluation e (rotor, powers and thrusts set by
 * evaluate_masses()) on propellers of diameter d. */
static void
drive_masses(const struct sizing_params *p, const struct eval *e, double d,
             struct drive_masses *dv)
{
	int nr = p->n_rotors;
	double p_motor_w = e->peak.shaft_w / (double)nr / p->eta_drive;
	dv->motor_total_kg = p->parts.active && p->parts.motor_kg_each > 0.0
	    ? p->parts.motor_kg_each * (double)nr
	    : fmax(SIZING_MOTOR_MIN_KG, (double)nr * p->c_motor
	        * sizing_motor_kg(p_motor_w, 2.0 * M_PI * e->rps_peak));
	dv->prop_each_kg = p->parts.active && p->parts.prop_kg_each > 0.0
	    ? p->parts.prop_kg_each
	    : p->prop_kg_per_m22 * pow(d, SIZING_PROP_EXPONENT)
	        * (double)p->n_blades / 2.0;
	double torque_nm = e->rps_peak > 0.0
	    ? e->peak.shaft_w / (double)nr / (2.0 * M_PI * e->rps_peak) : 0.0;
	/* The bus current does not enter the structure. */
	struct airframe_loads al = { .mass_kg = e->design_mass_kg,
		.peak_thrust_n = e->t_peak_n,
		.tip_mass_kg = dv->motor_total_kg / (double)nr + dv->prop_each_kg,
		.peak_torque_nm = torque_nm, .prop_diameter_m = d };
	airframe_structure(p, &al, &dv->am);
}

/* The masses of evaluation e (rotor, powers and thrusts already set by
 * evaluate_masses()) that depend on its series cells: the bus, the KV, the
 * currents, the battery storing energy_wh (unless locked or a real part),
 * and with the drive dv's motors, propellers and airframe, the harness
 * and ESCs. */
static void
cells_masses(const struct sizing_params *p, int cells, double energy_wh,
             const struct drive_masses *dv, struct eval *e)
{
	int nr = p->n_rotors;
	e->cells = cells < 1 ? 1 : cells;
	double v_nom = (double)e->cells * p->chem->v_nom;
	e->kv = p->kv_locked ? p->kv
	    : 60.0 * e->rps_peak / ((double)e->cells * p->chem->v_full);
	e->peak_current_a = e->peak.electrical_w / v_nom;

	/* Battery: energy-sized capacity, floored by the power the cells can
	 * deliver (specific power), unless locked or a real part. */
	e->capacity_ah = energy_wh / v_nom;
	if (battery_fixed(p))
		e->capacity_ah = p->parts.capacity_ah;
	else if (p->capacity_locked)
		e->capacity_ah = p->capacity_locked_ah;
	/* The pack's mass from the chemistry's pack-level law; eta_pkg is the
	 * overhead over the bare cells it implies (cell / pack specific
	 * energy), which also brings the cells' specific power to the pack. */
	double e_nom_wh = e->capacity_ah * v_nom;
	double m_energy = batt_pack_mass_kg(p->chem, e_nom_wh, p->pack_count,
	    e->cells, p->e_pack_override_wh_kg);
	e->eta_pkg = p->chem->e_spec_wh_kg * m_energy / e_nom_wh;
	/* Cells deliver their specific power continuously and about twice it
	 * in a 10 s burst: the pack must carry the highest sustained phase
	 * power and the full-throttle burst (the check of feasibility.c). */
	double p_sustained = 0.0;
	for (int i = 0; i < PHASE_MAX; i++)
		if (p->duration_s[i] > 0.0 && e->ph[i].electrical_w > p_sustained)
			p_sustained = e->ph[i].electrical_w;
	/* A race sustains its laps' mean power (its bursts are the burst's). */
	if (p->duration_s[PHASE_FORWARD] > 0.0) {
		double race_w = duty_lap_mean_fraction(p->duty) * e->peak.electrical_w;
		if (race_w > p_sustained)
			p_sustained = race_w;
	}
	/* A role's high-burst packs (racing) carry their sustained power in
	 * the same proportion: burst_factor / SIZING_BURST_ORDINARY times the
	 * profile's (the racing packs of data/roles.json deliver about 2.4
	 * times its continuous specific power). */
	double sustain = p->burst_factor > SIZING_BURST_ORDINARY
	    ? p->burst_factor / SIZING_BURST_ORDINARY : 1.0;
	/* The cells that deliver it store e_spec / p_spec of energy per watt;
	 * the pack is that energy's pack (its own packaging, not the
	 * energy-sized one's: a longer mission never lightens it). */
	double e_power_wh = fmax(p_sustained / sustain,
	    e->peak.electrical_w / p->burst_factor)
	    / p->chem->p_spec_w_kg * p->chem->e_spec_wh_kg;
	double m_power = e_power_wh > e_nom_wh ? batt_pack_mass_kg(p->chem,
	    e_power_wh, p->pack_count, e->cells, p->e_pack_override_wh_kg)
	    : m_energy;
	if (battery_fixed(p)) {
		e->mass.battery_kg = p->parts.battery_kg;
	} else if (!p->capacity_locked && m_power > m_energy) {
		e->power_binds = true;
		e->mass.battery_kg = m_power;
		e->capacity_ah = e_power_wh / v_nom;
		e->eta_pkg = p->chem->e_spec_wh_kg * m_power / e_power_wh;
	} else {
		e->mass.battery_kg = m_energy;
	}

	e->mass.motor_kg = dv->motor_total_kg;
	e->mass.prop_kg = dv->prop_each_kg * (double)nr;

	/* Arms, frame, body and avionics of the drive; the harness for this
	 * bus's current. */
	struct airframe_masses am = dv->am;
	airframe_harness(p, e->peak_current_a, &am);
	e->arm = am.arm;
	e->cg_ok = am.cg_ok;
	e->min_fraction_binds = am.min_fraction_binds;
	e->mass.arm_kg = am.arm_kg;
	e->mass.frame_kg = am.frame_kg;
	e->mass.other_kg = am.other_kg;
	e->shell_kg = am.shell_kg;
	e->mass.wiring_kg = am.wiring_kg;
	e->mass.avionics_kg = am.avionics_kg;

	/* ESCs scale with the current they carry (paper §VI-E). */
	double scale = airframe_s_scale(am.frame_total_kg + p->payload_kg);
	double i_rotor = fmax(SIZING_ESC_MIN_A,
	    SIZING_ESC_RATING * e->peak_current_a / (double)nr);
	e->mass.esc_kg = p->parts.active && p->parts.esc_kg_total > 0.0
	    ? p->parts.esc_kg_total
	    : SIZING_ESC_KG_PER_A * i_rotor * (double)nr * p->c_esc * scale;
	e->mass.role_aux_kg = am.role_aux_kg;
	e->mass.payload_kg = p->payload_kg;
	e->mass.total_kg = e->mass.payload_kg + e->mass.battery_kg
	    + e->mass.frame_kg + e->mass.arm_kg + e->mass.motor_kg
	    + e->mass.prop_kg + e->mass.esc_kg + e->mass.wiring_kg
	    + e->mass.avionics_kg + e->mass.role_aux_kg + e->mass.other_kg;

}

/*
 * Evaluate every subsystem at takeoff mass M with capacity C, all but the
 * discharge: the masses of the map f of eq. (implicit), which do not depend
 * on it.  The speed sweep is recorded into rec when given (the final
 * evaluation).
 */
static void
evaluate_masses(const struct sizing_params *p, const struct loop_state *ls,
                double mass_kg, double capacity_ah, struct res_run *rec,
                struct eval *e)
{
	const struct atmo_state *air = &p->air;
	int nr = p->n_rotors;
	memset(e, 0, sizeof *e);
	e->mass_kg = mass_kg;

	/* Propeller: the locked one, or the chosen share of the largest the
	 * overlap limit allows (engine.c tries several). */
	e->overlap_limit_m = aero_overlap_limit_m(p->wheelbase_m, n_arms(p),
	    AERO_TIP_CLEARANCE);
	double d = p->prop_locked ? p->prop_diameter_m : e->overlap_limit_m
	    * (p->prop_frac > 0.0 ? p->prop_frac : 1.0);

	/* Thrust target: T/W = 1 / θ² (paper §II-E) with the largest payload
	 * aboard, the load case motors and structure are built for. */
	double theta = 1.0 - p->thrust_margin;
	if (theta < MIN_THROTTLE)
		theta = MIN_THROTTLE;
	e->design_mass_kg = mass_kg + p->extra_payload_kg;
	e->t_hover_n = mass_kg * G0_M_S2 / (double)nr;
	e->t_peak_n = e->design_mass_kg * G0_M_S2 / (double)nr / (theta * theta);
	e->throttle = sqrt(e->t_hover_n / e->t_peak_n);
	e->rps_hover = aero_rps_for_thrust(e->t_hover_n, p->ct, air->rho_kg_m3, d);
	e->rps_peak = e->rps_hover / e->throttle;

	/* Installed FoM at the hover tip Reynolds number, with interference. */
	double re = aero_tip_reynolds(air, M_PI * d * e->rps_hover,
	    aero_chord_m(d, p->n_blades));
	e->fom_inst = p->fom_override > 0.0 ? p->fom_override
	    : aero_fom_installed(p->fom_isolated, p->kappa, p->fom_isolated_mode, re,
	        p->re_ref);
	e->k_int = aero_interference(p->interference_c, ls->arm_width_m, d);

	struct mission_model *m = &e->model;
	sizing_mission_model(p, e->design_mass_kg, m);
	m->rotor.diameter_m = d;
	m->rotor.ct = p->ct;
	m->rotor.fom = e->fom_inst / e->k_int;
	m->rotor.n_blades = p->n_blades;
	m->eta_drive = p->eta_drive;
	m->bus_voltage_v = (double)ls->cells * p->chem->v_nom;
	/* The envelope: full thrust falls with the inflow as the propeller's
	 * C_T(J) does, for the pitch the rotor gets (eval_phases()'s: the
	 * locked one, or the hover-inflow law). */
	double pitch_m = p->prop_locked ? p->prop_pitch_m : sizing_pitch_m(d,
	    aero_hover_induced_ms(e->t_hover_n, air->rho_kg_m3,
	    0.25 * M_PI * d * d), e->rps_hover);
	m->prop_j0 = prop_j0(pitch_m / d);

	/* Forward speed: the minimum-power speed when "auto". */
	e->v_fwd_ms = p->v_forward_ms;
	if (rec != NULL)
		rec->n_sweep = mission_speed_sweep(m, mass_kg, e->t_peak_n,
		    rec->sweep_v_ms, rec->sweep_power_w, RES_MAX_SWEEP,
		    &e->v_min_power_ms, &e->v_max_ms);
	else if (p->v_auto)
		/* The loop needs the speeds only. */
		mission_speed_search_hinted(m, mass_kg, e->t_peak_n,
		    &e->v_min_power_ms, &e->v_max_ms, ls->speed_hint);
	if (p->v_auto)
		e->v_fwd_ms = e->v_min_power_ms;
	/* A forward speed or climb rate the thrust (or the pitch limit) does
	 * not reach is flown at the fastest it does, so no phase runs above
	 * full throttle; FORWARD_SPEED and CLIMB_SPEED report the shortfall
	 * against what was asked. */
	e->v_fwd_request_ms = e->v_fwd_ms;
	if (e->v_fwd_ms > 0.0)
		e->v_fwd_ms = mission_forward_flown_ms(m, mass_kg, e->t_peak_n,
		    e->v_fwd_ms, 0.0);
	e->v_climb_ms = p->v_climb_ms > 0.0 ? mission_max_climb_ms(m, mass_kg,
	    e->t_peak_n, p->v_climb_ms) : p->v_climb_ms;
	e->climb_limit_ms = e->v_climb_ms < p->v_climb_ms ? e->v_climb_ms : 0.0;

	/* The phase powers size a free battery (the specific-power floor
	 * below) and go into the record; a given capacity (locked, or a
	 * catalogue battery) leaves them to the record, which asks for them
	 * (eval_phases()): most loop evaluations are never recorded. */
	mission_peak_power(m, e->t_peak_n, &e->peak);
	if (p->prop_locked)
		e->pitch_m = p->prop_pitch_m;
	if (!capacity_given(p))
		eval_phases(p, e);

	/* Series cells: a part's, locked, set by a locked KV, or chosen. */
	double energy_wh = capacity_ah * (double)ls->cells * p->chem->v_nom;
	int fixed = 0;
	if (p->parts.active && p->parts.cells > 0)
		fixed = p->parts.cells;
	else if (p->cells_fixed > 0)
		fixed = p->cells_fixed;
	else if (p->kv_locked)
		fixed = (int)ceil(60.0 * e->rps_peak / (p->kv * p->chem->v_full));
	struct drive_masses dv;
	drive_masses(p, e, d, &dv);
	if (fixed > 0 || p->cells_lo >= p->cells_hi) {
		cells_masses(p, fixed > 0 ? fixed : p->cells_lo, energy_wh, &dv, e);
		return;
	}
	/* The series count is a design variable: the lightest aircraft whose
	 * full-throttle current stays within the harness budget (more cells
	 * lighten the harness and ESCs, but at the same energy make smaller,
	 * heavier cells: batt_pack_wh_kg).  Where no count keeps within the
	 * budget, the most cells the class allows.  The budget only admits
	 * fewer counts as a requirement grows, so the lightest admitted design
	 * never gets lighter (docs/model.md, monotone sizing). */
	double budget_a = SIZING_CURRENT_BUDGET_A * sqrt(mass_kg);
	struct eval best, t;
	bool found = false;
	for (int cells = p->cells_lo; cells <= p->cells_hi; cells++) {
		t = *e;
		cells_masses(p, cells, energy_wh, &dv, &t);
		if (t.peak_current_a > budget_a)
			continue;
		if (!found || t.mass.total_kg < best.mass.total_kg) {
			best = t;
			found = true;
		}
	}
	if (!found) {
		best = *e;
		cells_masses(p, p->cells_hi, energy_wh, &dv, &best);
	}
	*e = best;
}

/* The mission an evaluation e flies at goal relaxation gamma_time: its
 * role's plan at e's speeds (into *plan) and the discharge's view of it,
 * the full-throttle power of e's thrust target included. */
static void
mission_of(const struct sizing_params *p, double gamma_time,
           const struct eval *e, struct duty_plan *plan,
           struct discharge_mission *dm)
{
	sizing_plan(p, gamma_time, e->v_climb_ms, e->v_fwd_ms, plan);
	dm->model = &e->model;
	dm->dry_mass_kg = e->mass_kg - p->payload_kg;
	dm->plan = plan;
	dm->full_throttle_w = e->peak.electrical_w;
	dm->full_throttle_shaft_w = e->peak.shaft_w;
	/* The KV is chosen to reach full-throttle rpm at full charge. */
	dm->full_throttle_v = (double)e->cells * p->chem->v_full;
	dm->ambient_c = p->ambient_c;
}

/* Fly the mission of an evaluate_masses() result e in `steps` steps at
 * goal relaxation gamma_time, trace into rec when given, and set the
 * capacity it needs. */
static void
evaluate_flight(const struct sizing_params *p, double gamma_time, int steps,
                struct res_run *rec, struct eval *e)
{
	struct discharge_pack pk;
	pack_of(p, e, &pk);
	struct duty_plan plan;
	struct discharge_mission dm;
	memset(&dm, 0, sizeof dm);
	mission_of(p, gamma_time, e, &plan, &dm);
	discharge_run(&pk, &dm, steps, rec ? rec->trace : NULL,
	    rec ? RES_MAX_TRACE : 0, rec ? &rec->n_trace : NULL, &e->dis);

	/* Capacity the mission needs, with the 20 % margin. */
	double t_req = plan.total_s;
	switch (e->dis.end) {
	case DIS_COMPLETED:
		e->c_target_ah = SIZING_CAP_MARGIN * e->dis.ah_used;
		break;
	case DIS_DEPLETED:
	case DIS_VOLTAGE_FLOOR:
	case DIS_THERMAL: {
		/* Extrapolate the charge to the whole mission. */
		double frac = t_req > 0.0 && e->dis.t_end_s > 0.0
		    ? t_req / e->dis.t_end_s : 2.0;
		e->c_target_ah = SIZING_CAP_MARGIN * fmax(e->dis.ah_used * frac,
		    e->capacity_ah * 1.1);
		break;
	}
	case DIS_COLLAPSE:
	case DIS_OVERFLOW:
	default:
		/* More capacity lowers R_sys (C_ref / C) and the sag. */
		e->c_target_ah = 1.5 * e->capacity_ah;
		break;
	}
}

/* Both: the map f at (M, C) with the mission flown in `steps` steps; steps
 * <= 0 when the caller needs the masses or powers only (the seeds, the
 * last Lipschitz round, the endurance explorer's locked-capacity loops),
 * not the mission's discharge. */
static void
evaluate(const struct sizing_params *p, const struct loop_state *ls,
         double mass_kg, double capacity_ah, int steps, struct res_run *rec,
         struct eval *e)
{
	evaluate_masses(p, ls, mass_kg, capacity_ah, rec, e);
	if (steps <= 0) {
		e->dis.end = DIS_COMPLETED;
		e->c_target_ah = e->capacity_ah;
		return;
	}
	evaluate_flight(p, ls->gamma_time, steps, rec, e);
}

void
sizing_mission_model(const struct sizing_params *p, double design_mass_kg,
                     struct mission_model *m)
{
	m->air = p->air;
	m->n_rotors = p->n_rotors;
	m->coaxial = p->coaxial;
	m->f_scale = p->f_scale;
	m->added_drag_m2 = p->added_drag_m2;
	m->fwd_drag_mult = p->fwd_drag_mult;
	m->cd_h = p->cd_h;
	m->cd_v = p->cd_v;
	m->wake_share = p->wake_share;
	m->aux_w = sizing_aux_w(p, design_mass_kg);
}

double
sizing_aux_w(const struct sizing_params *p, double design_mass_kg)
{
	if (!p->aux_scaled || !(design_mass_kg > 0.0) || !(p->aux_ref_kg > 0.0))
		return p->aux_w;
	return p->aux_w * pow(design_mass_kg / p->aux_ref_kg, 2.0 / 3.0);
}

double
sizing_motor_kg(double power_max_w, double omega_max_rad_s)
{
	return SIZING_MOTOR_K * pow(power_max_w, SIZING_MOTOR_EXP_P)
	    * pow(omega_max_rad_s, -SIZING_MOTOR_EXP_W);
}


/* Initial capacity: nominal energy of the mission at the seed mass, at
 * the series count the evaluation chooses there (into ls->cells). */
static double
seed_capacity_ah(const struct sizing_params *p, struct loop_state *ls,
                 double mass_kg)
{
	/* The phase powers alone: no discharge (they are computed, the
	 * capacity being free here; see evaluate_masses()). */
	struct eval e;
	evaluate(p, ls, mass_kg, 1.0, 0, NULL, &e);
	struct duty_plan plan;
	struct discharge_mission dm;
	memset(&dm, 0, sizeof dm);
	mission_of(p, ls->gamma_time, &e, &plan, &dm);
	double wh = discharge_plan_energy_wh(&dm);
	ls->cells = e.cells;
	double v = (double)e.cells * p->chem->v_nom;
	double c = SIZING_CAP_MARGIN * wh / v;
	return c > 0.05 ? c : 0.05;
}

/* The Aitken acceleration's guards (iterate()). */
#define AITKEN_R_MIN   0.5   /* extrapolate only slow contractions */
#define AITKEN_R_MAX   0.98  /* and never a ratio near 1 (divergence) */
#define AITKEN_R_AGREE 0.05  /* successive ratios within 5 % */

/* Forget what a recording evaluation wrote into rec (the trace and the
 * speed sweep): the next one then starts from the record that sizing_run
 * began with.  A recording writes exactly the first n_trace samples (the
 * only ones read, see res_run_clear_untraced()) and n_sweep points, and
 * each one is cleared before the next, so only those points can be
 * non-zero. */
static void
clear_record(struct res_run *rec)
{
	rec->n_trace = 0;
	memset(rec->sweep_v_ms, 0, (size_t)rec->n_sweep * sizeof rec->sweep_v_ms[0]);
	memset(rec->sweep_power_w, 0, (size_t)rec->n_sweep * sizeof rec->sweep_power_w[0]);
	rec->n_sweep = 0;
}

/* The converged loop's evaluation at the final resolution, recorded into
 * rec when given (cleared first: only the last recording stands). */
static void
confirm(const struct sizing_params *p, const struct loop_state *ls,
        double mass_kg, double capacity_ah, struct res_run *rec, struct eval *fin)
{
	if (rec != NULL)
		clear_record(rec);
	evaluate(p, ls, mass_kg, capacity_ah, FINAL_STEPS, rec, fin);
}

/* The loop's evaluations of the last three iterations, and what is known of
 * their flights: the Aitken test looks back three iterations. */
#define LOOP_RING 3
struct loop_ring {
	struct eval e[LOOP_RING];
	signed char flown[LOOP_RING];  /* -1 not flown yet, else whether it flew */
	bool cells_steady[LOOP_RING];
	int steps;                     /* discharge steps of a loop flight */
};

/* Whether iteration k's evaluation flew the mission, flying it the first
 * time it is asked. */
static bool
loop_flown(const struct sizing_params *p, double gamma_time,
           struct loop_ring *r, int k)
{
	int i = k % LOOP_RING;
	if (r->flown[i] < 0) {
		evaluate_flight(p, gamma_time, r->steps, NULL, &r->e[i]);
		r->flown[i] = r->e[i].dis.end == DIS_COMPLETED;
	}
	return r->flown[i] != 0;
}

/* Were the three iterations up to k steady (same cells, mission flown)
 * since the last Aitken jump at iteration last_jump (0: none)?  That is
 * the loop's count of steady steps reaching 3. */
static bool
loop_steady(const struct sizing_params *p, double gamma_time,
            struct loop_ring *r, int k, int last_jump)
{
	if (k - 2 <= last_jump)
		return false;
	for (int j = k - 2; j <= k; j++)
		if (!r->cells_steady[j % LOOP_RING] || !loop_flown(p, gamma_time, r, j))
			return false;
	return true;
}

/* The fixed-point iteration at goal-relaxation factor gamma_time.  The
 * series-cell count is the locked one, or the one each evaluation chooses
 * (evaluate_masses()); the loop carries the capacity across a change of
 * count as stored energy.  The least fixed point is the design: the map
 * rises with the mass and with every requirement, so iterating from below
 * it keeps every iterate below it (a seed the first evaluation finds above
 * a fixed point is replaced by the payload alone) and a harder mission's
 * fixed point is never lighter.
 *
 * A loop that converges on a flown mission confirms it at the final
 * resolution: that evaluation, at (*m_star, *c_star, *ls_out), goes to
 * *fin with *fin_done set, and its trace and sweep into rec unless rec is
 * NULL.  It is the evaluation sizing_run would make next, so sizing_run
 * keeps it instead of flying the same mission again.  *last is the last
 * loop evaluation; its flight (dis) is there only when the loop ran away
 * or out of iterations (sizing_run reads it for a runaway's record). */
static enum sizing_status
iterate(const struct sizing_params *p, double gamma_time, struct res_run *out,
        struct res_run *rec, struct eval *last, struct eval *fin,
        bool *fin_done, double *m_star, double *c_star,
        struct loop_state *ls_out)
{
	*fin_done = false;
	out->n_history = 0;
	out->iterations = 0;
	/* Start from the seed of eq. (altcorrect). */
	double m = sizing_seed_kg(p->payload_kg, p->air.rho_kg_m3);
	int cells = p->cells_fixed > 0 ? p->cells_fixed : p->cells_lo;
	if (p->parts.active && p->parts.cells > 0)
		cells = p->parts.cells;
	struct mission_speed_hint hint = { false, 0, 0, 0 };
	struct loop_state ls = { cells, 0.02 * p->wheelbase_m, gamma_time, &hint };
	/* A catalogue battery's capacity is the part's whatever c says (see
	 * evaluate_masses()), so it needs no seed evaluation. */
	double c = p->capacity_locked ? p->capacity_locked_ah
	    : battery_fixed(p) ? p->parts.capacity_ah : seed_capacity_ah(p, &ls, m);
	double c_failed_wh = 0.0;   /* the largest stored energy that failed */
	bool reseeded = false;
	int max_iter = p->max_iter > 0 ? p->max_iter : SIZING_MAX_ITER;
	enum sizing_status st = SIZING_MAX_ITERATIONS;
	/* A locked or catalogue capacity takes nothing from the flights: the
	 * masses do not depend on them, and what reads them (convergence,
	 * the Aitken test, the record) asks for the ones it needs.  A free
	 * capacity is re-targeted from every flight. */
	bool lazy = capacity_given(p);
	struct loop_ring ring;
	ring.steps = LOOP_STEPS;

	/* Aitken Δ² acceleration (Steffensen): the last mass steps and
	 * capacities, and the iteration of the last jump. */
	double dm_prev = 0.0, dm_prev2 = 0.0, c_prev = 0.0;
	int last_jump = 0, k = 1;
	for (; k <= max_iter; k++) {
		struct eval *e = &ring.e[k % LOOP_RING];
		evaluate_masses(p, &ls, m, c, NULL, e);
		ring.flown[k % LOOP_RING] = -1;
		double f = e->mass.total_kg;
		if (out->n_history < RES_MAX_HISTORY)
			out->history_kg[out->n_history++] = f;
		out->iterations++;
		double c_used = e->capacity_ah;
		double v_bus = (double)e->cells * p->chem->v_nom;
		/* The first iterate lies below the seed: the seed is above a
		 * fixed point.  Restart from the payload, below every fixed
		 * point (from above, the loop could settle on a larger one
		 * than the least, which is the design). */
		if (k == 1 && f < m && !reseeded && p->payload_kg < m) {
			reseeded = true;
			m = p->payload_kg > 0.0 ? p->payload_kg : f;
			out->n_history = 0;
			out->iterations = 0;
			k = 0;
			continue;
		}
		if (!lazy) {
			if (!loop_flown(p, gamma_time, &ring, k)
			    && c_used * v_bus > c_failed_wh)
				c_failed_wh = c_used * v_bus;
			/* Eq. (relaxation) with the ratchet floor. */
			c = SIZING_RELAX_ALPHA * e->c_target_ah
			    + (1.0 - SIZING_RELAX_ALPHA) * c_used;
			if (c_failed_wh > 0.0 && c * v_bus < SIZING_RATCHET * c_failed_wh)
				c = SIZING_RATCHET * c_failed_wh / v_bus;
		}
		if (!isfinite(f) || f > SIZING_RUNAWAY_KG) {
			st = SIZING_RUNAWAY;
			break;
		}
		/* The next iteration sees this one's arm (rotor-arm interference)
		 * and, when automatic, its series-cell count. */
		ls.arm_width_m = e->arm.d_out_m;
		bool cells_steady = e->cells == ls.cells;
		ls.cells = e->cells;
		ring.cells_steady[k % LOOP_RING] = cells_steady;
		/* A power-bound battery is as large as the peak power needs; its
		 * energy target is then below it and has no further say. */
		bool cap_steady = lazy
		    || (e->power_binds && e->c_target_ah <= c_used)
		    || fabs(c - c_used) <= 1e-4 * c_used;
		if (fabs(f - m) < SIZING_TOL_KG && cap_steady && cells_steady) {
			m = f;
			/* Confirm with the discharge resolution of the final
			 * record, so that a mission the coarse loop flew is not
			 * lost to discretisation in the dossier's trace.  When
			 * this is the run's record (no goal relaxation follows)
			 * and the coarse flight is still unflown (a locked or
			 * catalogue battery: its masses never needed it), the
			 * final flight alone says whether the mission is flown. */
			bool flown;
			if (ring.flown[k % LOOP_RING] < 0 && rec != NULL && !p->allow_relax) {
				confirm(p, &ls, m, e->capacity_ah, rec, fin);
				*fin_done = true;
				flown = fin->dis.end == DIS_COMPLETED;
			} else {
				flown = loop_flown(p, gamma_time, &ring, k);
				if (flown) {
					confirm(p, &ls, m, e->capacity_ah, rec, fin);
					*fin_done = true;
					flown = fin->dis.end == DIS_COMPLETED;
					if (!flown && !lazy && ring.steps != FINAL_STEPS) {
						/* The coarse steps hid a voltage or
						 * thermal limit at the edge: go on at
						 * the final resolution, with this
						 * capacity as failed. */
						ring.steps = FINAL_STEPS;
						c_failed_wh = fmax(c_failed_wh,
						    e->capacity_ah * v_bus);
						c = fmax(c, SIZING_RATCHET * c_failed_wh / v_bus);
						*fin_done = false;
						last_jump = k;
						continue;
					}
					/* The coarse steps landed it on the reserve,
					 * the final ones short of it: size the
					 * capacity at the final resolution. */
					if (flown && !lazy && ring.steps != FINAL_STEPS
					    && fin->dis.end_soc < sizing_reserve_soc()
					    - SIZING_RESERVE_TOL) {
						ring.steps = FINAL_STEPS;
						*fin_done = false;
						last_jump = k;
						continue;
					}
				}
			}
			st = flown ? SIZING_CONVERGED : SIZING_DISCHARGE_FAIL;
			break;
		}
		/* A slow linear contraction (L near 1) is extrapolated to its
		 * limit once two successive step ratios agree and the last three
		 * steps were steady; the loop then re-anchors on the true map at
		 * the extrapolated point. */
		double dm = f - m;
		if (dm_prev != 0.0 && dm_prev2 != 0.0) {
			double r1 = dm_prev / dm_prev2, r2 = dm / dm_prev;
			if (r2 > AITKEN_R_MIN && r2 < AITKEN_R_MAX
			    && fabs(r2 - r1) < AITKEN_R_AGREE * r2
			    && loop_steady(p, gamma_time, &ring, k, last_jump)) {
				double gain = r2 / (1.0 - r2);
				f += gain * dm;
				/* The history holds the iterates the loop used. */
				out->history_kg[out->n_history - 1] = f;
				if (!p->capacity_locked && !p->parts.active)
					c += gain * (c - c_prev);
				dm = 0.0;
				last_jump = k;
			}
		}
		dm_prev2 = dm_prev;
		dm_prev = dm;
		c_prev = c;
		m = f;
	}
	/* The last evaluation, flown where it is read: by the record of a
	 * runaway, and here when the iterations ran out. */
	if (k > max_iter)
		k = max_iter;
	if (st == SIZING_RUNAWAY || st == SIZING_MAX_ITERATIONS) {
		bool flown = loop_flown(p, gamma_time, &ring, k);
		if (st == SIZING_MAX_ITERATIONS && !flown
		    && (p->capacity_locked || p->parts.active))
			st = SIZING_DISCHARGE_FAIL;
	}
	*last = ring.e[k % LOOP_RING];
	*m_star = m;
	*c_star = last->capacity_ah;
	*ls_out = ls;
	ls_out->speed_hint = NULL; /* the hint lives no longer than this loop */
	return st;
}

/* dF/dM at the fixed point by central differences, with the capacity
 * re-targeted at each side (the full coupling of eq. lipschitz).  The
 * series count is held at the fixed point's: the design's own growth, not
 * the step to the next bus a heavier aircraft would choose (a step the
 * fixed point lies below, so the loop never crosses it). */
static double
lipschitz(const struct sizing_params *p_in, const struct loop_state *ls,
          double m_star, double c_star)
{
	struct sizing_params held = *p_in;
	if (held.cells_fixed <= 0 && !held.kv_locked)
		held.cells_fixed = ls->cells;
	const struct sizing_params *p = &held;
	double h = LIPSCHITZ_STEP * m_star;
	struct eval a, b;
	double ca = c_star, cb = c_star;
	/* Its evaluations lie within 2h of one another: one speed hint. */
	struct mission_speed_hint hint = { false, 0, 0, 0 };
	struct loop_state near = *ls;
	near.speed_hint = &hint;
	ls = &near;
	/* A locked or catalogue capacity ignores the re-targeted one: further
	 * rounds would repeat the first exactly. */
	int rounds = capacity_given(p) ? 1 : 3;
	for (int k = 0; k < rounds; k++) {
		/* The masses come before the discharge in evaluate(): the last
		 * round, whose capacity target nobody reads, needs no flight. */
		int steps = k + 1 < rounds ? LOOP_STEPS : 0;
		evaluate(p, ls, m_star + h, ca, steps, NULL, &a);
		evaluate(p, ls, m_star - h, cb, steps, NULL, &b);
		ca = a.c_target_ah;
		cb = b.c_target_ah;
	}
	return (a.mass.total_kg - b.mass.total_kg) / (2.0 * h);
}

/* Copy the evaluated design into the run record. */
static void
record_run(const struct sizing_params *p, struct eval *e,
           const struct loop_state *ls, struct res_run *out)
{
	eval_phases(p, e);
	struct duty_plan plan;
	sizing_plan(p, ls->gamma_time, e->v_climb_ms, e->v_fwd_ms, &plan);
	const double *d = plan.phase_s;
	discharge_duty_record(&plan, &e->dis, e->peak.electrical_w,
	    p->duty != NULL ? p->duty->source : NULL, &out->duty);
	out->mass = e->mass;
	out->aux_power_w = e->model.aux_w;
	out->reserve_soc = sizing_reserve_soc();
	out->tolerance_kg = SIZING_TOL_KG;
	str_copy(out->chemistry, sizeof out->chemistry, p->chem->name);
	out->cell_count = e->cells;
	out->pack_count = p->pack_count;
	out->capacity_mah = e->capacity_ah * 1000.0;
	out->nominal_voltage_v = (double)e->cells * p->chem->v_nom;
	out->energy_wh = e->capacity_ah * out->nominal_voltage_v;
	out->packaging_factor = e->eta_pkg;
	out->battery_power_binds = e->power_binds;
	out->time_scale = ls->gamma_time;
	out->flight_time_s = 0.0;
	/* Each phase's table at its time-averaged mass: a drop or a spray
	 * lightens the aircraft along it, and its mean power (the discharge's)
	 * is that of the mean mass or more (power is convex in mass), so
	 * shaft and electrical power stay in order. */
	double dry = e->mass_kg - p->payload_kg;
	for (int i = 0; i < PHASE_MAX; i++) {
		struct res_phase *r = &out->phase[i];
		struct mission_power mean_mp;
		mission_power(&e->model, dry + duty_phase_mean_payload(&plan, i),
		    i == PHASE_CLIMB ? e->v_climb_ms : 0.0,
		    i == PHASE_FORWARD ? e->v_fwd_ms : 0.0, &mean_mp);
		const struct mission_power *mp = &mean_mp;
		out->approved_time_s[i] = d[i];
		out->flight_time_s += d[i];
		r->duration_s = d[i];
		r->speed_ms = i == PHASE_CLIMB ? e->v_climb_ms
		    : i == PHASE_FORWARD ? e->v_fwd_ms : 0.0;
		r->thrust_per_rotor_n = mp->thrust_per_rotor_n;
		/* A profile's phase is segments of their own powers (laps,
		 * turns): its shaft power is theirs, as flown. */
		r->shaft_power_w = plan.kind != DUTY_PHASES
		    && e->dis.phase_mean_shaft_w[i] > 0.0
		    ? e->dis.phase_mean_shaft_w[i] : mp->shaft_w;
		r->power_w = e->dis.phase_mean_power_w[i] > 0.0
		    ? e->dis.phase_mean_power_w[i] : mp->electrical_w;
		r->current_a = e->dis.phase_mean_current_a[i];
		r->energy_wh = e->dis.phase_energy_wh[i];
		r->rpm = mp->rotor.rps * 60.0;
		r->throttle = e->rps_peak > 0.0 ? mp->rotor.rps / e->rps_peak : 0.0;
		r->pitch_deg = mp->pitch_deg;
		r->tip_mach = mp->rotor.tip_mach;
	}
	out->optimal_speed_ms = e->v_fwd_request_ms;
	out->climb_limit_ms = e->climb_limit_ms;
	out->v_min_power_ms = e->v_min_power_ms;
	out->v_max_ms = e->v_max_ms;
	out->v_max_limit = e->v_max_ms > 0.0 ? sizing_limit(mission_top_speed_limit(
	    &e->model, e->mass_kg, e->v_max_ms)) : RES_LIMIT_NONE;

	out->thrust_to_weight = 1.0 / (e->throttle * e->throttle);
	out->hover_throttle = e->throttle;
	out->forward_pitch_deg = e->ph[PHASE_FORWARD].pitch_deg;
	/* A coaxial pair pushes its whole thrust through one disk: loading and
	 * downwash count distinct disks (arms), not rotors. */
	double area = 0.25 * M_PI * e->model.rotor.diameter_m * e->model.rotor.diameter_m;
	out->disk_loading_n_m2 = e->mass_kg * G0_M_S2 / ((double)n_arms(p) * area);
	out->downwash_ms = aero_downwash_ms(e->mass_kg, p->air.rho_kg_m3,
	    n_arms(p), area);
	out->fom_installed = e->fom_inst;
	out->kappa = p->fom_override > 0.0 || p->fom_isolated_mode ? 1.0 : p->kappa;
	out->interference = e->k_int;
	out->reynolds_tip = e->ph[PHASE_HOVER].rotor.reynolds_tip;
	out->rpm_hover = e->rps_hover * 60.0;
	out->rpm_peak = e->rps_peak * 60.0;
	out->tip_mach_peak = M_PI * e->model.rotor.diameter_m * e->rps_peak
	    / p->air.sound_m_s;
	out->overlap_limit_in = m_to_in(e->overlap_limit_m);
	out->peak_power_w = e->peak.electrical_w;
	out->peak_current_a = e->peak_current_a;
	out->peak_c_rate = e->capacity_ah > 0.0 ? e->peak_current_a / e->capacity_ah : 0.0;
	out->opt.prop_diameter_in = m_to_in(e->model.rotor.diameter_m);
	out->opt.prop_pitch_in = m_to_in(e->pitch_m);
	out->opt.motor_kv = e->kv;
	out->opt.motor_mass_kg = e->mass.motor_kg / (double)p->n_rotors;
	out->opt.motor_peak_current_a = e->peak_current_a / (double)p->n_rotors;
	out->opt.motor_peak_power_w = e->peak.shaft_w / (double)p->n_rotors
	    / p->eta_drive;

	airframe_record_arm(&e->arm, e->model.rotor.diameter_m, out);
	out->blade_pass_frequency_hz = (double)p->n_blades * e->rps_peak;
	out->blade_pass_low_hz = (double)p->n_blades * SIZING_LOW_FLIGHT_RPM
	    * e->rps_hover;
	out->resonance_margin = structure_resonance_margin(e->arm.f_nat_hz,
	    out->blade_pass_low_hz, out->blade_pass_frequency_hz);
	out->arm_tip_mass_kg = (e->mass.motor_kg / (double)p->n_rotors
	    + e->mass.prop_kg / (double)p->n_rotors) * (p->coaxial ? 2.0 : 1.0);
	out->min_fraction_binds = e->min_fraction_binds;

	out->max_battery_temp_c = e->dis.peak_temp_c;
	out->thermal_margin_c = THERM_RUNAWAY_C - e->dis.peak_temp_c;
	out->min_terminal_voltage_v = e->dis.min_v_term_v;
	out->voltage_floor_v = (double)e->cells * p->chem->v_cutoff;
	out->end_soc = e->dis.end_soc;
	/* Motor copper loss at hover with the winding resistance corrected to
	 * its running temperature (paper §V-D); needs a real motor's R. */
	out->winding_temp_c = p->ambient_c + SIZING_WINDING_RISE_K;
	if (p->parts.active && p->parts.motor_resistance_ohm > 0.0) {
		double i_m = e->ph[PHASE_HOVER].electrical_w / out->nominal_voltage_v
		    / (double)p->n_rotors;
		out->motor_winding_resistance_ohm = therm_winding_resistance_ohm(
		    p->parts.motor_resistance_ohm, out->winding_temp_c);
		out->motor_copper_loss_w = i_m * i_m * out->motor_winding_resistance_ohm;
	}
	str_copy(out->termination, sizeof out->termination,
	    discharge_end_text[e->dis.end]);
}

/* The parameters and loop state run, a sizing_run() of p, closed at: p
 * with the thrust margin it flew (a relaxation may have lowered it), and
 * its fixed point's cells, arm and γ. */
static void
at_fixed_point(const struct sizing_params *p, const struct res_run *run,
               struct sizing_params *q, struct loop_state *ls)
{
	const struct res_fixed_point *fx = &run->fixed;
	*q = *p;
	q->thrust_margin = run->thrust_margin;
	*ls = (struct loop_state){ fx->cells, fx->arm_width_m, fx->time_scale,
	    NULL };
}

/* Endurance explorer: hover endurance vs capacity scale with the mass loop
 * re-closed at each locked capacity (the mass-growth penalty). */
void
sizing_explore(const struct sizing_params *p, struct res_run *out)
{
	struct sizing_params q;
	struct loop_state ls;
	at_fixed_point(p, out, &q, &ls);
	double c_star = out->fixed.capacity_ah;
	q.capacity_locked = true;
	q.allow_relax = false;
	q.max_iter = EXPLORER_MAX_ITER;
	q.parts.active = false;
	q.cells_fixed = out->cell_count;
	/* The design's minimum-power speed, not a new sweep per evaluation. */
	q.v_auto = false;
	q.v_forward_ms = out->optimal_speed_ms;
	out->n_endurance = 0;
	double first_slope = 0.0;
	out->endurance_inflection_scale = 0.0;
	/* Each point starts from the line through the two points before it
	 * (the mass grows smoothly with the capacity), the second from the
	 * first and the first from the seed, so a few iterations close it. */
	double m_prev = sizing_seed_kg(q.payload_kg, q.air.rho_kg_m3);
	for (int i = 0; i < ENDURANCE_SCALES; i++) {
		double s = 0.25 + 2.75 * (double)i / (double)(ENDURANCE_SCALES - 1);
		q.capacity_locked_ah = c_star * s;
		struct loop_state l2 = ls;
		int n_pts = out->n_endurance;
		double m = n_pts >= 2
		    ? 2.0 * m_prev - out->endurance_mass_kg[n_pts - 2] : m_prev;
		struct eval e;
		for (int k = 0; k < EXPLORER_MAX_ITER; k++) {
			evaluate(&q, &l2, m, q.capacity_locked_ah, 0, NULL, &e);
			l2.arm_width_m = e.arm.d_out_m;
			double f = e.mass.total_kg;
			if (!isfinite(f) || f > SIZING_RUNAWAY_KG)
				break;
			bool done = fabs(f - m) < SIZING_TOL_KG;
			m = f;
			if (done)
				break;
		}
		if (!isfinite(m) || m > SIZING_RUNAWAY_KG)
			break;
		m_prev = m;
		struct discharge_pack pk;
		pack_of(&q, &e, &pk);
		double t = discharge_hover_endurance_steps_s(&pk, &e.model, m,
		    q.ambient_c, sizing_reserve_soc(), EXPLORER_ENDURANCE_STEPS);
		int n = out->n_endurance++;
		out->endurance_scale[n] = s;
		out->endurance_time_s[n] = t;
		out->endurance_mass_kg[n] = m;
		if (n >= 1) {
			double slope = (t - out->endurance_time_s[n - 1])
			    / (s - out->endurance_scale[n - 1]);
			if (n == 1)
				first_slope = slope;
			else if (out->endurance_inflection_scale == 0.0
			    && first_slope > 0.0 && slope < 0.5 * first_slope)
				out->endurance_inflection_scale = s;
		}
	}
}

/* Hover endurance to the reserve of design e at takeoff mass m_star. */
static double
hover_endurance_s(const struct sizing_params *p, const struct eval *e,
                  double m_star)
{
	struct discharge_pack pk;
	pack_of(p, e, &pk);
	return discharge_hover_endurance_s(&pk, &e->model, m_star, p->ambient_c,
	    sizing_reserve_soc());
}

/* Marketing mode: the manufacturer's best case — hover without payload or
 * auxiliary load, ISA sea level at 25 °C, down to an empty pack. */
static double
marketing_endurance_s(const struct sizing_params *p, const struct eval *e,
                      double m_star)
{
	struct mission_model m = e->model;
	atmo_at(0.0, c_to_k(25.0), &m.air);
	m.aux_w = 0.0;
	struct discharge_pack pk;
	pack_of(p, e, &pk);
	return discharge_hover_endurance_s(&pk, &m, m_star - p->payload_kg, 25.0,
	    BATT_SOC_MIN);
}

/* The evaluation fin at the fixed point (m_star, c_star, ls) and the fixed
 * point itself, into out. */
static void
record_at(const struct sizing_params *p, struct eval *fin,
          const struct loop_state *ls, double m_star, double c_star,
          struct res_run *out)
{
	record_run(p, fin, ls, out);
	out->fixed = (struct res_fixed_point){ m_star, c_star, ls->arm_width_m,
	    ls->gamma_time, ls->cells };
}

/* What a run that reached its fixed point (m_star, c_star) at ls records:
 * the final evaluation fin, the fixed point, the Lipschitz constant and
 * the extras. */
static void
record_fixed_point(const struct sizing_params *p, enum sizing_status st,
                   struct eval *fin, const struct loop_state *ls,
                   double m_star, double c_star, struct res_run *out)
{
	record_at(p, fin, ls, m_star, c_star, out);
	out->lipschitz = lipschitz(p, ls, m_star, c_star);
	out->hover_endurance_s = hover_endurance_s(p, fin, m_star);
	struct mission_power hover;
	mission_power(&fin->model, m_star, 0.0, 0.0, &hover);
	out->hover_power_w = hover.electrical_w;
	mission_power(&fin->model, res_lightest_mass_kg(out), 0.0, 0.0, &hover);
	out->hover_power_shed_w = hover.electrical_w;
	if (p->marketing)
		out->marketing_endurance_s = marketing_endurance_s(p, fin, m_star);
	if (st == SIZING_MAX_ITERATIONS)
		snprintf(out->termination, sizeof out->termination,
		    "no convergence in %d iterations", out->iterations);
}

/* A trial loop of the relaxations: iterate() recording nothing, with its
 * final state in *ls, *m_star, *c_star (the fixed point when it closed). */
static enum sizing_status
trial(const struct sizing_params *p, double gamma_time, struct res_run *out,
      struct loop_state *ls, double *m_star, double *c_star)
{
	struct eval last, fin;
	bool fin_done;
	return iterate(p, gamma_time, out, NULL, &last, &fin, &fin_done, m_star,
	    c_star, ls);
}

/* Goal relaxation: the largest γ in [0.05, 1) that closes, by bisection
 * (the loop is monotone in mission time).  The trials record nothing; the
 * final loop, at that γ if one closes, else at the requested mission,
 * records into out and leaves its state as iterate() does. */
static enum sizing_status
relax_time(const struct sizing_params *p, struct res_run *out,
           struct eval *last, struct eval *fin, bool *fin_done,
           double *m_star, double *c_star, struct loop_state *ls)
{
	double good = 0.0, lo = SIZING_GAMMA_MIN, hi = 1.0;
	struct loop_state l2;
	double m2, c2;
	if (trial(p, lo, out, &l2, &m2, &c2) == SIZING_CONVERGED) {
		good = lo;
		for (int k = 0; k < GAMMA_BISECT; k++) {
			double mid = 0.5 * (lo + hi);
			if (trial(p, mid, out, &l2, &m2, &c2) == SIZING_CONVERGED) {
				good = mid;
				lo = mid;
			} else {
				hi = mid;
			}
		}
	}
	return iterate(p, good > 0.0 ? good : 1.0, out, out, last, fin,
	    fin_done, m_star, c_star, ls);
}

enum sizing_status
sizing_run(const struct sizing_params *p, struct res_run *out)
{
	struct eval last, fin;
	bool fin_done;
	struct loop_state ls;
	double m_star = 0.0, c_star = 0.0;

	res_run_clear_untraced(out);
	out->ran = true;
	out->thrust_margin = p->thrust_margin;
	double gamma = p->time_scale > 0.0 ? p->time_scale : 1.0;
	enum sizing_status st = iterate(p, gamma, out, out, &last, &fin, &fin_done,
	    &m_star, &c_star, &ls);
	/* The thrust requirement is never relaxed: a mission that does not
	 * close at it is reported unmet (the engine's ceiling says what is
	 * reachable).  Only the mission's own opt-in shortens the flight. */
	if (st != SIZING_CONVERGED && p->allow_relax)
		st = relax_time(p, out, &last, &fin, &fin_done, &m_star, &c_star, &ls);
	/* A confirming evaluation of an earlier iteration may have recorded
	 * into out: only the last one's record stands. */
	if (!fin_done)
		clear_record(out);

	/* The mass loop converged even when the mission then cannot be flown
	 * (a locked battery too small): that is a discharge failure. */
	out->converged = st == SIZING_CONVERGED || st == SIZING_DISCHARGE_FAIL;
	if (st == SIZING_RUNAWAY) {
		/* Nothing physical to record beyond the history. */
		record_run(p, &last, &ls, out);
		snprintf(out->termination, sizeof out->termination,
		    "mass runaway above %.0f kg: every added kilogram demands more "
		    "than a kilogram of subsystem mass", SIZING_RUNAWAY_KG);
		return st;
	}
	/* The final evaluation at the fixed point keeps the full trace (the
	 * loop's confirming evaluation when it made one: the same). */
	if (!fin_done)
		evaluate(p, &ls, m_star, c_star, FINAL_STEPS, out, &fin);
	record_fixed_point(p, st, &fin, &ls, m_star, c_star, out);
	return st;
}

bool
sizing_endurance_at_mass(const struct sizing_params *p_in, double mass_kg,
                         double v_forward_ms, struct sizing_endurance *out)
{
	memset(out, 0, sizeof *out);
	struct sizing_params p = *p_in;
	p.v_auto = !(v_forward_ms > 0.0);
	p.v_forward_ms = v_forward_ms;
	struct loop_state ls = { p.cells_fixed > 0 ? p.cells_fixed : p.cells_lo,
		0.02 * p.wheelbase_m, 1.0, NULL };
	struct eval e;
	/* Twice: the second pass sees the arm the first one sized (rotor-arm
	 * interference). */
	for (int k = 0; k < 2; k++) {
		evaluate_masses(&p, &ls, mass_kg, p.capacity_locked_ah, NULL, &e);
		ls.arm_width_m = e.arm.d_out_m;
		ls.cells = e.cells;
	}
	struct discharge_pack pk;
	pack_of(&p, &e, &pk);
	struct mission_power hv, fw;
	mission_power(&e.model, mass_kg, 0.0, 0.0, &hv);
	out->forward_speed_ms = p.v_auto ? e.v_min_power_ms : v_forward_ms;
	mission_power(&e.model, mass_kg, 0.0, out->forward_speed_ms, &fw);
	out->hover_power_w = hv.electrical_w;
	out->forward_power_w = fw.electrical_w;
	out->prop_diameter_m = e.model.rotor.diameter_m;
	out->hover_s = discharge_power_endurance_s(&pk, hv.electrical_w, p.ambient_c,
	    BATT_SOC_MIN, FINAL_STEPS);
	out->forward_s = discharge_power_endurance_s(&pk, fw.electrical_w,
	    p.ambient_c, BATT_SOC_MIN, FINAL_STEPS);
	return out->hover_s > 0.0 && isfinite(out->hover_s) && isfinite(out->forward_s);
}

/* Open loop: f at a given M, the capacity re-targeted at that mass until
 * the mission's charge and the capacity agree (the masses then no longer
 * change with it).  No fixed point in M is sought. */
#define OPEN_LOOP_MAX_ITER 60
bool
sizing_at_mass(const struct sizing_params *p, double mass_kg,
               struct sizing_open *out)
{
	memset(out, 0, sizeof *out);
	struct loop_state ls = { p->cells_fixed > 0 ? p->cells_fixed : p->cells_lo,
		0.02 * p->wheelbase_m, 1.0, NULL };
	if (p->parts.active && p->parts.cells > 0)
		ls.cells = p->parts.cells;
	double c = p->capacity_locked ? p->capacity_locked_ah
	    : battery_fixed(p) ? p->parts.capacity_ah
	    : seed_capacity_ah(p, &ls, mass_kg);
	struct eval e;
	bool settled = false;
	for (int k = 0; k < OPEN_LOOP_MAX_ITER && !settled; k++) {
		evaluate(p, &ls, mass_kg, c, LOOP_STEPS, NULL, &e);
		ls.arm_width_m = e.arm.d_out_m;
		ls.cells = e.cells;
		if (capacity_given(p) || (e.power_binds && e.c_target_ah <= e.capacity_ah)) {
			settled = k > 0; /* one more pass with this arm width */
			continue;
		}
		settled = fabs(e.c_target_ah - e.capacity_ah) <= 1e-4 * e.capacity_ah;
		c = e.c_target_ah;
	}
	out->mass = e.mass;
	out->capacity_ah = e.capacity_ah;
	out->cells = e.cells;
	out->flown = e.dis.end == DIS_COMPLETED;
	out->settled = settled;
	out->dry_kg = e.mass.total_kg - e.mass.payload_kg - e.mass.battery_kg;
	return settled && out->flown && isfinite(e.mass.total_kg);
}
