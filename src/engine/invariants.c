/* invariants.c — the physics every printed number must obey (see
 * invariants.h). */
#include "engine/invariants.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "util/units.h"

/* The mission was flown to its end (the phase table then covers it). */
static bool
completed(const struct res_run *o)
{
	return strcmp(o->termination, "mission completed") == 0;
}

static bool
near(double a, double b, double reltol)
{
	double scale = fmax(fabs(a), fabs(b));
	return fabs(a - b) <= reltol * (scale > 0.0 ? scale : 1.0);
}

/* The checks of one run; false with msg set at the first broken one. */
static bool
run_holds(const char *name, const struct res_run *o, char *msg, size_t n)
{
	if (!o->ran)
		return true;
	const struct res_mass *m = &o->mass;
	double sum = m->payload_kg + m->battery_kg + m->frame_kg + m->arm_kg
	    + m->motor_kg + m->prop_kg + m->esc_kg + m->wiring_kg
	    + m->avionics_kg + m->role_aux_kg + m->other_kg;
	if (!near(sum, m->total_kg, INV_SUM_RELTOL)) {
		snprintf(msg, n, "%s: the mass items sum to %.6f kg, the takeoff "
		    "mass is %.6f kg", name, sum, m->total_kg);
		return false;
	}
	if (!(o->fom_installed > 0.0 && o->fom_installed <= 1.0)) {
		snprintf(msg, n, "%s: installed figure of merit %.4f outside (0, 1]",
		    name, o->fom_installed);
		return false;
	}
	double e_sum = 0.0, e_pt = 0.0, q_sum = 0.0;
	for (int i = 0; i < PHASE_MAX; i++) {
		const struct res_phase *ph = &o->phase[i];
		if (!(ph->duration_s > 0.0))
			continue;
		if (ph->shaft_power_w > ph->power_w * (1.0 + INV_SUM_RELTOL)) {
			snprintf(msg, n, "%s: %s shaft power %.1f W above its electrical "
			    "power %.1f W", name, res_phase_name[i], ph->shaft_power_w,
			    ph->power_w);
			return false;
		}
		if (ph->throttle > 1.0 + 1e-9) {
			snprintf(msg, n, "%s: %s throttle %.3f above full", name,
			    res_phase_name[i], ph->throttle);
			return false;
		}
		e_sum += ph->energy_wh;
		e_pt += ph->power_w * ph->duration_s / S_PER_H;
		q_sum += ph->current_a * ph->duration_s / S_PER_H;
	}
	if (completed(o) && e_sum > 0.0) {
		if (!near(e_sum, e_pt, INV_ENERGY_RELTOL)) {
			snprintf(msg, n, "%s: the phases' energy %.3f Wh is not their "
			    "power over their time (%.3f Wh)", name, e_sum, e_pt);
			return false;
		}
		double q_soc = o->capacity_mah / 1000.0 * (1.0 - o->end_soc);
		if (!near(q_sum, q_soc, INV_ENERGY_RELTOL)) {
			snprintf(msg, n, "%s: the phases drew %.4f Ah, the state of "
			    "charge says %.4f Ah", name, q_sum, q_soc);
			return false;
		}
	}
	if (o->perf.valid) {
		for (int i = 0; i < OP_MAX; i++) {
			const struct res_op *op = &o->perf.op[i];
			if (!op->valid)
				continue;
			if (!(op->motor_efficiency > 0.0 && op->motor_efficiency <= 1.0)) {
				snprintf(msg, n, "%s: %s motor efficiency %.4f outside (0, 1]",
				    name, res_op_name[i], op->motor_efficiency);
				return false;
			}
			if (op->power_shaft_w > op->power_in_w * (1.0 + INV_SUM_RELTOL)) {
				snprintf(msg, n, "%s: %s shaft power %.1f W above the motor's "
				    "input %.1f W", name, res_op_name[i], op->power_shaft_w,
				    op->power_in_w);
				return false;
			}
			if (!(op->throttle >= 0.0 && op->throttle <= 1.0 + 1e-9)) {
				snprintf(msg, n, "%s: %s throttle %.3f outside [0, 1]", name,
				    res_op_name[i], op->throttle);
				return false;
			}
		}
	}
	if (o->feasible && o->end_soc < o->reserve_soc - INV_RESERVE_TOL) {
		snprintf(msg, n, "%s: marked feasible but lands at %.1f %% state of "
		    "charge, below its %.1f %% reserve", name, 100.0 * o->end_soc,
		    100.0 * o->reserve_soc);
		return false;
	}
	return true;
}

int
invariants_check(const struct solve_result *r, char *msg, size_t n)
{
	if (!run_holds("baseline", &r->baseline, msg, n)
	    || !run_holds("custom", &r->custom, msg, n))
		return 3;
	if (!r->parts_selected)
		return 0;
	if (!run_holds("design of record", &r->closed, msg, n))
		return 3;
	double total = r->bom_mass_kg + r->closed.mass.payload_kg;
	if (fabs(total - r->closed.mass.total_kg) > INV_BOM_TOL_KG) {
		snprintf(msg, n, "design of record: the bill of materials (%.4f kg) "
		    "and the payload (%.4f kg) make %.4f kg, the takeoff mass is "
		    "%.4f kg", r->bom_mass_kg, r->closed.mass.payload_kg, total,
		    r->closed.mass.total_kg);
		return 3;
	}
	return 0;
}
