/* feasibility.c — feasibility gate and checks table (see feasibility.h). */
#include "sizing/feasibility.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "result/checks.h"
#include "physics/aero.h"
#include "physics/mission.h"
#include "util/strbuf.h"
#include "physics/structure.h"
#include "physics/therm.h"
#include "util/units.h"

/* Fixes are formatted into this scratch before they are copied. */
#define FIX_LEN RES_TEXT

void
feasibility_violation(struct solve_result *r, const char *run,
                      const char *stage, const char *code,
                      const char *const *fixes, const char *fmt, ...)
{
	if (r->n_violations >= RES_MAX_VIOLATIONS)
		return;
	struct res_violation *v = &r->violations[r->n_violations++];
	/* Terse: the codes alone, the texts (most of its size) unwritten. */
	if (!r->terse)
		memset(v, 0, sizeof *v);
	v->run = run;
	v->stage = stage;
	v->code = code;
	v->message[0] = '\0';
	v->n_fixes = 0;
	if (r->terse)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(v->message, sizeof v->message, fmt, ap);
	va_end(ap);
	for (int i = 0; fixes != NULL && fixes[i] != NULL && i < RES_MAX_FIXES; i++) {
		str_copy(v->fixes[i], sizeof v->fixes[i], fixes[i]);
		v->n_fixes++;
	}
}

void
feasibility_fix(const struct solve_result *r, char *f, const char *fmt, ...)
{
	if (r->terse)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(f, RES_TEXT, fmt, ap);
	va_end(ap);
}

static double
mission_time_s(const struct sizing_params *p)
{
	double t = 0.0;
	for (int i = 0; i < PHASE_MAX; i++)
		t += p->duration_s[i];
	return t;
}

/* The payload CG limit d_y (m): the distance from the centre to the nearest
 * side of the rotor polygon, half the wheelbase times cos(pi / arms).  A
 * coaxial layout has n/2 arms only when its rotors pair up on 3 or more
 * arms; a layout that cannot (COAXIAL_LAYOUT says so) is judged flat, as
 * the fix "coaxial_layout false" would build it: 3 coaxial rotors once
 * gave one arm and a limit of -0.5 wheelbase. */
static double
cg_limit_m(const struct sizing_params *p)
{
	int pairs = p->n_rotors / 2;
	int arms = p->coaxial && p->n_rotors % 2 == 0 && pairs >= 3 ? pairs : p->n_rotors;
	return 0.5 * p->wheelbase_m * cos(M_PI / (double)arms);
}

bool
feasibility_gate(const struct sizing_params *p, const char *run,
                 struct solve_result *r)
{
	bool ok = true;
	char f1[FIX_LEN], f2[FIX_LEN], f3[FIX_LEN];
	const char *fx[4] = { f1, f2, f3, NULL };

	if (p->coaxial && (p->n_rotors % 2 != 0 || p->n_rotors < 6)) {
		feasibility_fix(r, f1, "Use an even rotor count of 6 or more (coaxial X8: num_rotors 8)");
		feasibility_fix(r, f2, "Set coaxial_layout to false");
		fx[2] = NULL;
		feasibility_violation(r, run, "feasibility", "COAXIAL_LAYOUT", fx,
		    "A coaxial layout stacks rotors in pairs on at least 3 arms; "
		    "%d rotors cannot be paired that way.", p->n_rotors);
		ok = false;
	}
	int arms = p->coaxial ? p->n_rotors / 2 : p->n_rotors;
	double limit = arms >= 2 ? aero_overlap_limit_m(p->wheelbase_m, arms,
	    AERO_TIP_CLEARANCE) : 0.0;
	if (p->prop_locked && p->prop_diameter_m > limit * (1.0 + AERO_OVERLAP_REL_TOL)) {
		double w_need = p->prop_diameter_m / ((1.0 - AERO_TIP_CLEARANCE)
		    * sin(M_PI / (double)arms));
		feasibility_fix(r, f1, "Increase max_diameter_m to at least %.3f m", w_need);
		feasibility_fix(r, f2, "Lock a propeller of at most %.1f in", m_to_in(limit));
		feasibility_fix(r, f3, "Use fewer rotors or a coaxial layout");
		fx[2] = f3;
		feasibility_violation(r, run, "feasibility", "PROP_OVERLAP", fx,
		    "The locked %.1f in propeller overlaps its neighbour: a %.0f mm "
		    "wheelbase with %d arms admits at most %.1f in (5 %% tip clearance).",
		    m_to_in(p->prop_diameter_m), p->wheelbase_m * 1000.0, arms,
		    m_to_in(limit));
		ok = false;
	}
	double d_y = cg_limit_m(p);
	if (p->cg_shift_m >= d_y) {
		feasibility_fix(r, f1, "Mount the payload within %.3f m of the centre", d_y);
		feasibility_fix(r, f2, "Increase max_diameter_m above %.3f m",
		    p->cg_shift_m * p->wheelbase_m / d_y);
		fx[2] = NULL;
		feasibility_violation(r, run, "feasibility", "CG_OFFSET", fx,
		    "The payload CG offset of %.3f m lies outside the rotor polygon "
		    "(d_y = %.3f m): the aircraft cannot be trimmed.", p->cg_shift_m, d_y);
		ok = false;
	}
	/* A locked battery that cannot hover even its own mass plus the
	 * payload for the mission with ideal rotors (FoM = 1, the largest
	 * propellers the wheelbase admits) can never close: say so now. */
	if (p->capacity_locked && !p->allow_relax && arms >= 2 && limit > 0.0) {
		double v_nom = (double)p->cells_fixed * p->chem->v_nom;
		double e_avail_wh = p->capacity_locked_ah * v_nom;
		double m_bat = e_avail_wh / fmax(p->chem->e_spec_wh_kg,
		    p->e_pack_override_wh_kg); /* bare cells: the lightest */
		double m_min = p->payload_kg + m_bat;
		double d = p->prop_locked ? p->prop_diameter_m : limit;
		double area = 0.25 * M_PI * d * d * (double)arms;
		double w = m_min * G0_M_S2;
		double p_ideal_w = w * sqrt(w / (2.0 * p->air.rho_kg_m3 * area));
		double e_min_wh = p_ideal_w * mission_time_s(p) / 3600.0;
		if (e_min_wh > e_avail_wh) {
			feasibility_fix(r, f1, "Increase locks.locked_capacity_mah above %.0f mAh",
			    1000.0 * e_min_wh / v_nom);
			feasibility_fix(r, f2, "Allow goal relaxation: locks.auto_reduce_flight_time = true");
			feasibility_fix(r, f3, "Shorten the mission");
			fx[2] = f3;
			feasibility_violation(r, run, "feasibility", "LOCKED_BATTERY_ENERGY", fx,
			    "The locked %.0f Wh battery cannot fly this mission even with "
			    "ideal rotors: hovering its own %.2f kg and the payload for "
			    "%.0f s needs at least %.0f Wh.", e_avail_wh, m_bat,
			    mission_time_s(p), e_min_wh);
			ok = false;
		}
	}
	if (!(mission_time_s(p) > 0.0)) {
		feasibility_fix(r, f1, "Give t_hover_s, t_climb_s or t_forward_s");
		fx[1] = NULL;
		feasibility_violation(r, run, "feasibility", "NO_MISSION", fx,
		    "The mission has no flight time: every phase duration is 0.");
		ok = false;
	}
	return ok;
}

/* The steady once-per-revolution band: hover at the lightest mass the
 * mission flies (rotor speed ~ sqrt(thrust)) to the fastest sustained
 * phase. */
static void
rev_band(struct res_run *o)
{
	double m_min = o->mass.total_kg;
	for (int i = 0; i < o->n_trace && i < RES_MAX_TRACE; i++)
		if (o->trace[i].mass_kg > 0.0 && o->trace[i].mass_kg < m_min)
			m_min = o->trace[i].mass_kg;
	double hover_hz = o->rpm_hover / S_PER_MIN;
	double lo = o->mass.total_kg > 0.0
	    ? hover_hz * sqrt(m_min / o->mass.total_kg) : hover_hz;
	double hi = hover_hz;
	for (int i = 0; i < PHASE_MAX; i++)
		if (o->phase[i].duration_s > 0.0 && o->phase[i].rpm / S_PER_MIN > hi)
			hi = o->phase[i].rpm / S_PER_MIN;
	o->rev_band_low_hz = lo;
	o->rev_band_high_hz = hi;
}

/* A mode clear of a band [lo, hi] ± margin: its value, its near edge. */
static void
band_check(struct check_values *v, enum check_id id, double f_hz, double lo,
           double hi, double margin, const char *what)
{
	if (!(f_hz > 0.0) || !(lo > 0.0) || !(hi >= lo))
		return;
	double edge;
	bool above;
	structure_band_clear(f_hz, lo, hi, margin, &edge, &above);
	checks_set(v, id, f_hz, edge);
	v->side[id] = above ? -1 : +1;
	checks_basis(v, id, "%s %.0f–%.0f Hz %s %.0f %%", what, lo, hi, "±",
	    100.0 * (margin - 1.0));
}

void
feasibility_common_checks(const struct sizing_params *p, struct res_run *o,
                          struct check_values *v)
{
	/* The mission, down to the reserve the 20 % capacity margin leaves
	 * (paper §II-D).  Integrated to SIZING_RESERVE_TOL: a locked copy of a
	 * sized battery passes as the sized one does. */
	double need = 0.0;
	for (int i = 0; i < PHASE_MAX; i++)
		need += o->approved_time_s[i];
	double flown = o->n_trace > 0 ? o->trace[o->n_trace - 1].t_s : 0.0;
	bool completed = flown >= need * 0.999;
	checks_set(v, CK_RESERVE, completed ? 100.0 * o->end_soc : 0.0,
	    100.0 * o->reserve_soc);
	v->pass_within_tol[CK_RESERVE] = completed
	    && o->end_soc >= o->reserve_soc - SIZING_RESERVE_TOL;
	if (!completed)
		snprintf(v->note[CK_RESERVE], sizeof v->note[CK_RESERVE],
		    "The flight ended after %.0f s of %.0f s: %.160s.", flown, need,
		    o->termination);

	/* A climb rate the thrust does not reach is flown at the fastest it
	 * does (climb_limit_ms). */
	if (p->duration_s[PHASE_CLIMB] > 0.0 && o->climb_limit_ms > 0.0)
		checks_set(v, CK_CLIMB_SPEED, p->v_climb_ms, o->climb_limit_ms);
	if (p->duration_s[PHASE_FORWARD] > 0.0) {
		checks_set(v, CK_FORWARD_PITCH, o->forward_pitch_deg,
		    MISSION_PITCH_MAX_DEG);
		/* A design whose loop ran away has no top speed to compare. */
		if (o->v_max_ms > 0.0)
			checks_set(v, CK_FORWARD_SPEED, o->optimal_speed_ms, o->v_max_ms);
	}
	if (p->downwash_cap_ms > 0.0)
		checks_set(v, CK_DOWNWASH, o->downwash_ms, p->downwash_cap_ms);

	checks_set(v, CK_VOLTAGE_MISSION, o->min_terminal_voltage_v,
	    o->voltage_floor_v);
	checks_set(v, CK_BATTERY_TEMP, o->max_battery_temp_c, THERM_RUNAWAY_C);
	checks_set(v, CK_PROP_OVERLAP, o->opt.prop_diameter_in,
	    o->overlap_limit_in * (1.0 + 1e-6)); /* a real part to 1 ppm */
	checks_set(v, CK_TIP_MACH, o->tip_mach_peak, AERO_TIP_MACH_MAX);

	/* The arm: strength at its design load, stiffness and torsion at
	 * full thrust, its first mode against the rate loop and the steady
	 * excitations. */
	if (o->arm_length_m > 0.0) {
		checks_set(v, CK_ARM_SAFETY, o->arm_safety_factor, STRUCT_FOS);
		v->sized[CK_ARM_SAFETY] = strcmp(o->arm_sized_by,
		    structure_sized_by_text[ARM_BY_STRENGTH]) == 0;
		checks_set(v, CK_ARM_TILT, o->arm_tilt_full_deg, STRUCT_TILT_MAX_DEG);
		v->sized[CK_ARM_TILT] = strcmp(o->arm_sized_by,
		    structure_sized_by_text[ARM_BY_TILT]) == 0;
		checks_basis(v, CK_ARM_TILT, "tip deflection %.1f mm",
		    o->arm_deflection_full_mm);
		checks_set(v, CK_ARM_TORSION, o->arm_torsion_mpa, o->arm_torsion_allow_mpa);
		if (o->rate_bandwidth_hz > 0.0) {
			checks_set(v, CK_ARM_MODE_CONTROL, o->arm_natural_frequency_hz,
			    o->rate_bandwidth_hz);
			v->sized[CK_ARM_MODE_CONTROL] = strcmp(o->arm_sized_by,
			    structure_sized_by_text[ARM_BY_MODE]) == 0;
		}
		rev_band(o);
		band_check(v, CK_ARM_MODE_REV, o->arm_natural_frequency_hz,
		    o->rev_band_low_hz, o->rev_band_high_hz, STRUCT_REV_MARGIN,
		    "rotor speed");
		band_check(v, CK_ARM_MODE_BLADE_PASS, o->arm_natural_frequency_hz,
		    o->blade_pass_low_hz, o->blade_pass_frequency_hz,
		    STRUCT_RESONANCE_MARGIN, "blade pass");
	}
	checks_set(v, CK_CG_OFFSET, p->cg_shift_m, cg_limit_m(p));
}

void
feasibility_checks(const struct sizing_params *p, enum sizing_status st,
                   const char *run, struct res_run *o, struct solve_result *r)
{
	char f1[FIX_LEN], f2[FIX_LEN], f3[FIX_LEN];
	const char *fx[4] = { f1, f2, f3, NULL };
	int n0 = r->n_violations;

	/* The loop itself: its status is a violation, not a check. */
	if (st == SIZING_RUNAWAY) {
		feasibility_fix(r, f1, "Reduce payload_kg or the mission times");
		feasibility_fix(r, f2, "Choose a higher specific-energy battery_chemistry");
		feasibility_fix(r, f3, "Allow a shorter flight: locks.auto_reduce_flight_time = true");
		feasibility_violation(r, run, "mass_loop", "MASS_RUNAWAY", fx,
		    "The takeoff mass grows without bound past %.0f kg: each added "
		    "kilogram needs more than a kilogram of battery, structure and "
		    "motors to carry it.", SIZING_RUNAWAY_KG);
	} else if (st == SIZING_MAX_ITERATIONS) {
		feasibility_fix(r, f1, "Shorten the mission or lighten the payload");
		feasibility_fix(r, f2, "Fix the cell count (nominal_cell_count)");
		fx[2] = NULL;
		feasibility_violation(r, run, "mass_loop", "NOT_CONVERGED", fx,
		    "The takeoff mass did not settle to 1 g in %d iterations.",
		    o->iterations);
		fx[2] = f3;
	}

	struct check_values v;
	checks_init(&v);
	feasibility_common_checks(p, o, &v);
	/* The continuous design is sized to its thrust requirement, and its
	 * battery to the cells' burst power. */
	double p_max = p->burst_factor * p->chem->p_spec_w_kg * o->mass.battery_kg
	    / (o->packaging_factor > 0.0 ? o->packaging_factor : 1.0);
	checks_set(&v, CK_BATTERY_POWER, o->peak_power_w, p_max);
	/* The role's T/W with the largest payload aboard, sized to it. */
	double theta = 1.0 - p->thrust_margin;
	double m_max = o->mass.total_kg + p->extra_payload_kg;
	if (theta > 0.0 && m_max > 0.0 && o->thrust_to_weight > 0.0) {
		checks_set(&v, CK_THRUST, o->thrust_to_weight * o->mass.total_kg / m_max,
		    1.0 / (theta * theta));
		v.sized[CK_THRUST] = true;
		/* Sized at the loop's last iterate, within its 1 g. */
		v.pass_within_tol[CK_THRUST] = v.value[CK_THRUST]
		    >= v.limit[CK_THRUST] * (1.0 - 1e-3);
	}
	v.sized[CK_BATTERY_POWER] = o->battery_power_binds;
	v.sized[CK_RESERVE] = !p->capacity_locked;
	v.sized[CK_PROP_OVERLAP] = !p->prop_locked
	    && !(p->prop_frac > 0.0 && p->prop_frac < 1.0);
	/* Where the arm's mode falls against the rotor's excitations turns on
	 * the rotor speed to a few per cent, and no tube moves it both ways
	 * (the tilt and the rate loop floor its stiffness): on the
	 * continuous reference they are reported, and the design of record,
	 * whose rotor is real, is held to them.  A requirement that grows
	 * cannot then let a lighter reference through (test_monotone). */
	v.advisory[CK_ARM_MODE_REV] = true;
	v.advisory[CK_ARM_MODE_BLADE_PASS] = true;
	/* A runaway's numbers are those of a mass that grew without bound:
	 * its violation says why, its checks add nothing. */
	if (st == SIZING_RUNAWAY)
		checks_init(&v);
	checks_apply(&v, run, o, r);
	o->feasible = o->feasible && r->n_violations == n0;
}
