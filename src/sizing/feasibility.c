/* feasibility.c — feasibility gate and checks table (see feasibility.h). */
#include "sizing/feasibility.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "physics/aero.h"
#include "physics/mission.h"
#include "util/strbuf.h"
#include "physics/structure.h"
#include "physics/therm.h"
#include "util/units.h"

/* Fixes are formatted into this scratch before they are copied. */
#define FIX_LEN RES_TEXT
#define CHECK_RELTOL 1e-9 /* check comparison tolerance, relative */

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

struct res_check *
feasibility_add_check(struct res_run *run, const char *name, const char *unit,
                      double value, double limit, bool upper)
{
	if (run->n_checks >= RES_MAX_CHECKS)
		return NULL;
	struct res_check *c = &run->checks[run->n_checks++];
	memset(c, 0, sizeof *c);
	c->name = name;
	c->unit = unit;
	c->value = isfinite(value) ? value : 0.0;
	c->limit = limit;
	c->upper = upper;
	double scale = fabs(limit) > 1e-12 ? fabs(limit) : 1.0;
	c->margin = upper ? (limit - c->value) / scale : (c->value - limit) / scale;
	/* A quantity sized to its limit (the arm stress) must pass: compare
	 * with a relative tolerance far below any physical meaning. */
	double tol = CHECK_RELTOL * scale;
	c->pass = upper ? c->value <= limit + tol : c->value >= limit - tol;
	return c;
}

void
feasibility_checks(const struct sizing_params *p, enum sizing_status st,
                   const char *run, struct res_run *o, struct solve_result *r)
{
	char f1[FIX_LEN], f2[FIX_LEN], f3[FIX_LEN];
	const char *fx[4] = { f1, f2, f3, NULL };
	int n0 = r->n_violations;
	o->n_checks = 0;

	/* The loop itself. */
	double last_step = o->n_history >= 2
	    ? fabs(o->history_kg[o->n_history - 1] - o->history_kg[o->n_history - 2])
	    : 0.0;
	struct res_check *c = feasibility_add_check(o, "Mass loop step at exit", "kg",
	    last_step, SIZING_TOL_KG, true);
	if (c && st == SIZING_CONVERGED)
		c->pass = true;
	if (c)
		c->sized = true;
	if (st == SIZING_RUNAWAY) {
		feasibility_fix(r, f1, "Reduce payload_kg or the mission times");
		feasibility_fix(r, f2, "Choose a higher specific-energy battery_chemistry");
		feasibility_fix(r, f3, "Allow goal relaxation: locks.auto_reduce_flight_time = true");
		feasibility_violation(r, run, "mass_loop", "MASS_RUNAWAY", fx,
		    "The takeoff mass ran away above %.0f kg: each added kilogram "
		    "needs more than a kilogram of battery, structure and motors "
		    "(Lipschitz constant >= 1).", SIZING_RUNAWAY_KG);
	} else if (st == SIZING_MAX_ITERATIONS) {
		feasibility_fix(r, f1, "Shorten the mission or lighten the payload");
		feasibility_fix(r, f2, "Fix the cell count (nominal_cell_count) to stop cell-count cycling");
		fx[2] = NULL;
		feasibility_violation(r, run, "mass_loop", "NOT_CONVERGED", fx,
		    "The mass loop did not converge to 1 g in %d iterations.",
		    o->iterations);
		fx[2] = f3;
	}
	feasibility_add_check(o, "Mass-growth Lipschitz constant", "", o->lipschitz, 1.0, true);
	feasibility_add_check(o, "Takeoff mass", "kg", o->mass.total_kg, SIZING_RUNAWAY_KG, true);

	/* The mission, down to the reserve: the pack must land with the state
	 * of charge the 20 % capacity margin leaves (paper §II-D).  A free
	 * battery is sized to land on it exactly; sized or locked, the landing
	 * state of charge is known to the discharge's integration accuracy
	 * (SIZING_RESERVE_TOL), so a locked copy of a sized battery passes
	 * as the sized one does. */
	double need = 0.0, flown = 0.0;
	for (int i = 0; i < PHASE_MAX; i++)
		need += o->approved_time_s[i];
	flown = o->n_trace > 0 ? o->trace[o->n_trace - 1].t_s : 0.0;
	bool completed = flown >= need * 0.999;
	bool sized = !p->capacity_locked;
	c = feasibility_add_check(o, "State of charge at landing (reserve)", "%",
	    completed ? 100.0 * o->end_soc : 0.0, 100.0 * o->reserve_soc, false);
	if (c) {
		c->sized = sized;
		if (completed && o->end_soc >= o->reserve_soc - SIZING_RESERVE_TOL)
			c->pass = true;
	}
	if (c && !c->pass && st != SIZING_RUNAWAY) {
		if (p->capacity_locked) {
			feasibility_fix(r, f1, "Increase locks.locked_capacity_mah above %.0f mAh",
			    p->capacity_locked_ah * 1000.0 * (need > 0.0 && flown > 0.0 ? need / flown : 2.0) * SIZING_CAP_MARGIN);
			feasibility_fix(r, f2, "Allow goal relaxation: locks.auto_reduce_flight_time = true");
			feasibility_fix(r, f3, "Unlock the battery so the solver can size it");
		} else {
			feasibility_fix(r, f1, "Add series cells (nominal_cell_count) to lower the current");
			feasibility_fix(r, f2, "Shorten the mission or lighten the payload");
			feasibility_fix(r, f3, "Choose a lower-resistance battery_chemistry");
		}
		if (!completed)
			feasibility_violation(r, run, "discharge", "MISSION_NOT_FLOWN", fx,
			    "The discharge simulation stopped at %.0f s of %.0f s: %s.",
			    flown, need, o->termination);
		else
			feasibility_violation(r, run, "discharge", "RESERVE", fx,
			    "The pack lands at %.1f %% state of charge, below the "
			    "%.1f %% reserve.", 100.0 * o->end_soc,
			    100.0 * o->reserve_soc);
	}

	/* Propulsion geometry. */
	c = feasibility_add_check(o, "Propeller diameter (overlap limit)", "in",
	    o->opt.prop_diameter_in, o->overlap_limit_in + 1e-9, true);
	if (c)
		c->sized = !p->prop_locked && !(p->prop_frac > 0.0 && p->prop_frac < 1.0);
	c = feasibility_add_check(o, "Tip Mach number at full throttle", "", o->tip_mach_peak,
	    AERO_TIP_MACH_MAX, true);
	if (c && !c->pass) {
		feasibility_fix(r, f1, "Use a larger propeller (lower rpm for the same thrust)");
		feasibility_fix(r, f2, "Reduce the thrust margin (payload_role.thrust_margin_override)");
		feasibility_fix(r, f3, "Lower the operating altitude or raise the ambient temperature limit");
		feasibility_violation(r, run, "propulsion", "TIP_MACH", fx,
		    "The rotor tip reaches Mach %.2f at full throttle (limit %.2f): "
		    "noise, compressibility losses and blade loads rise sharply.",
		    o->tip_mach_peak, AERO_TIP_MACH_MAX);
	}

	/* Electrical and thermal. */
	c = feasibility_add_check(o, "Battery peak temperature", "°C", o->max_battery_temp_c,
	    THERM_RUNAWAY_C, true);
	if (c && !c->pass) {
		feasibility_fix(r, f1, "Add capacity or parallel packs to lower the C-rate");
		feasibility_fix(r, f2, "Choose a lower-resistance battery_chemistry (LiPo, LiHV)");
		feasibility_fix(r, f3, "Lower the ambient temperature limit of the mission");
		feasibility_violation(r, run, "discharge", "THERMAL_RUNAWAY", fx,
		    "The pack reaches %.1f °C, above the %.0f °C thermal-runaway limit.",
		    o->max_battery_temp_c, THERM_RUNAWAY_C);
	}
	c = feasibility_add_check(o, "Minimum terminal voltage", "V", o->min_terminal_voltage_v,
	    o->voltage_floor_v, false);
	if (c && !c->pass) {
		feasibility_fix(r, f1, "Add series cells (nominal_cell_count)");
		feasibility_fix(r, f2, "Add capacity to reduce the voltage sag");
		fx[2] = NULL;
		feasibility_violation(r, run, "discharge", "VOLTAGE_FLOOR", fx,
		    "The terminal voltage falls to %.2f V, below the %.2f V cut-off.",
		    o->min_terminal_voltage_v, o->voltage_floor_v);
		fx[2] = f3;
	}
	double p_max = p->burst_factor * p->chem->p_spec_w_kg * o->mass.battery_kg
	    / (o->packaging_factor > 0.0 ? o->packaging_factor : 1.0);
	c = feasibility_add_check(o, "Full-throttle battery power (burst capability)", "W",
	    o->peak_power_w, p_max, true);
	if (c)
		c->sized = o->battery_power_binds;
	if (c && !c->pass) {
		feasibility_fix(r, f1, "Unlock or enlarge the battery");
		feasibility_fix(r, f2, "Choose a higher-power chemistry such as LiPo or LiHV");
		feasibility_fix(r, f3, "Reduce the thrust margin");
		feasibility_violation(r, run, "discharge", "BATTERY_POWER", fx,
		    "Full throttle draws %.0f W, but %.2f kg of %s cells deliver at "
		    "most %.0f W in a 10 s burst (%.0f × their continuous specific "
		    "power).", o->peak_power_w, o->mass.battery_kg, p->chem->name,
		    p_max, p->burst_factor);
	}

	/* Structure. */
	c = feasibility_add_check(o, "Arm root bending stress", "MPa", o->arm_stress_mpa,
	    o->arm_stress_allow_mpa, true);
	if (c)
		c->sized = true;
	c = feasibility_add_check(o, "Arm mode clear of the blade-pass band", "",
	    o->resonance_margin, 0.0, false);
	if (c && !c->pass) {
		feasibility_fix(r, f1, "Stiffen the arm above %.0f Hz (larger tube diameter)",
		    STRUCT_RESONANCE_MARGIN * o->blade_pass_frequency_hz);
		feasibility_fix(r, f2, "Or soften it below %.0f Hz (soft-mounted arms)",
		    o->blade_pass_low_hz / STRUCT_RESONANCE_MARGIN);
		feasibility_fix(r, f3, "Change the blade count (structural_overrides.num_blades) to move the band");
		feasibility_violation(r, run, "structure", "ARM_RESONANCE", fx,
		    "The arm's first bending mode (%.0f Hz) lies inside the "
		    "in-flight blade-pass band (%.0f–%.0f Hz) without the 1.5 margin.",
		    o->arm_natural_frequency_hz, o->blade_pass_low_hz,
		    o->blade_pass_frequency_hz);
	}
	feasibility_add_check(o, "Payload CG offset", "m", p->cg_shift_m, cg_limit_m(p), true);

	/* Role-specific limits. */
	if (p->downwash_cap_ms > 0.0) {
		c = feasibility_add_check(o, "Downwash (crop and drift limit)", "m/s",
		    o->downwash_ms, p->downwash_cap_ms, true);
		if (c && !c->pass) {
			feasibility_fix(r, f1, "Increase max_diameter_m: larger rotors lower the downwash");
			feasibility_fix(r, f2, "Use more rotors (num_rotors)");
			feasibility_fix(r, f3, "Raise payload_role.ag_max_downwash_ms if the crop allows");
			feasibility_violation(r, run, "feasibility", "DOWNWASH", fx,
			    "The downwash of %.1f m/s exceeds the %.1f m/s cap against "
			    "crop damage and spray drift.", o->downwash_ms, p->downwash_cap_ms);
		}
	}
	/* A climb rate the thrust does not reach: the run flies the fastest
	 * climb it does reach (climb_limit_ms). */
	if (p->duration_s[PHASE_CLIMB] > 0.0 && o->climb_limit_ms > 0.0) {
		feasibility_add_check(o, "Climb speed within thrust", "m/s",
		    p->v_climb_ms, o->climb_limit_ms, true);
		const char *climb_fx[] = { f1, NULL };
		feasibility_fix(r, f1, "Reduce v_climb_ms to %.1f m/s or less, or raise "
		    "the thrust margin (payload_role.thrust_margin_override)",
		    o->climb_limit_ms);
		feasibility_violation(r, run, "mission", "CLIMB_SPEED", climb_fx,
		    "A %.1f m/s climb needs more thrust than full throttle gives; the "
		    "design climbs at %.1f m/s at most and flies its climb at that.",
		    p->v_climb_ms, o->climb_limit_ms);
	}
	if (p->duration_s[PHASE_FORWARD] > 0.0) {
		c = feasibility_add_check(o, "Forward body pitch", "°", o->forward_pitch_deg,
		    MISSION_PITCH_MAX_DEG, true);
		/* A design whose mass loop ran away has no top speed to compare
		 * with (v_max_ms 0): its runaway is the violation. */
		c = o->v_max_ms > 0.0 ? feasibility_add_check(o,
		    "Forward speed within thrust margin", "m/s", o->optimal_speed_ms,
		    o->v_max_ms, true) : NULL;
		if (c && !c->pass) {
			feasibility_fix(r, f1, "Reduce v_forward_ms to %.1f m/s or less", o->v_max_ms);
			feasibility_fix(r, f2, "Use \"auto\" for the minimum-power speed");
			feasibility_fix(r, f3, "Reduce the drag area (payload_role.added_drag_m2)");
			feasibility_violation(r, run, "mission", "FORWARD_SPEED", fx,
			    "At %.1f m/s the drag needs more thrust or pitch than the "
			    "design has; the model diverges beyond %.1f m/s.",
			    o->optimal_speed_ms, o->v_max_ms);
		}
	}
	o->feasible = r->n_violations == n0;
	for (int i = 0; i < o->n_checks; i++)
		if (!o->checks[i].pass)
			o->feasible = false;
	/* Some checks have no violation of their own (Lipschitz, bending stress,
	 * pitch...): an infeasible run must still say why. */
	bool unexplained = !o->feasible && r->n_violations == n0;
	for (int i = 0; unexplained && i < o->n_checks; i++)
		if (!o->checks[i].pass) {
			const struct res_check *k = &o->checks[i];
			fx[0] = NULL;
			feasibility_violation(r, run, "checks", "CHECK_FAILED", fx,
			    "%s is %.4g%s%s, beyond its limit of %.4g%s%s.", k->name,
			    k->value, k->unit[0] ? " " : "", k->unit, k->limit,
			    k->unit[0] ? " " : "", k->unit);
			fx[0] = f1;
		}
}
