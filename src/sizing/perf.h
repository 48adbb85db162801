/* perf.h — a design on real parts, flown: the design of record's numbers.
 *
 * The continuous design (sizing.h) says what the physics asks for; the
 * aircraft the bill of materials builds is a set of real parts with their
 * own masses and constants.  perf_fly() flies that aircraft on the mission:
 * every operating point from the real propeller's thrust and power
 * coefficients and the real motor's KV, R and I0 (the rotor's installed
 * losses on top, as in the continuous model), each phase at its own mass
 * and thrust, the battery's voltage under each load, the mission's
 * discharge with the pack heated by its own I²R losses, the winding
 * temperature from the copper and iron losses, and the figures a
 * practitioner asks of a design: flight times, maximum speed and climb,
 * tilt, spare payload, a motor out.
 *
 * Sizing layer; no I/O.
 */
#ifndef AEROEVAL_PERF_H
#define AEROEVAL_PERF_H

#include <stdbool.h>

#include "result/result.h"
#include "physics/motor.h"
#include "physics/prop.h"
#include "physics/structure.h"
#include "sizing/sizing.h"

#define PERF_FULL_THROTTLE_S 10.0 /* a full-throttle burst (the 10 s the
                                     battery's burst rating is for), for
                                     the winding temperature it reaches
                                     from hover */

/* A concrete aircraft: its parts and what it weighs. */
struct perf_craft {
	struct motor_model motor;     /* R and I0 published or estimated */
	bool motor_r_estimated;       /* R or I0 came from motor.h's fit */
	double motor_max_current_a;   /* the maker's maximum */
	double motor_max_power_w;     /* the maker's maximum input; 0 unknown */
	double max_thrust_n;          /* an integrated system's published
	                                 maximum thrust per rotor at this bus
	                                 and air; 0: none (the model's) */
	struct prop_coeffs prop;      /* static C_T and C_P */
	double prop_diameter_m;
	double prop_pitch_m;
	int prop_blades;
	double prop_max_rpm;          /* the maker's limit; 0 unknown */
	double esc_current_a;         /* continuous rating per motor */
	int cells;                    /* series cells of the bus */
	double capacity_ah;           /* total at the terminals */
	double battery_kg;
	double battery_continuous_c;  /* the pack's continuous C rating */
	double battery_burst_c;       /* 0 unknown */
	struct structure_arm arm;     /* one arm tube as sized for it */
	struct res_mass mass;         /* takeoff, with the mission payload */
};

/* Fly craft c on the mission of p (the custom run's parameters) into run:
 * masses, battery, phases, trace, operating points, structure and thermal
 * fields (run->checks are left to the caller).  Flies the whole mission,
 * or with p->allow_relax the largest fraction of it (goal relaxation,
 * γ >= 0.05) that lands at the reserve.  A trial (a closing the parts
 * search only compares) leaves out what no check reads: the minimum-power
 * speed of a mission that flies at its own speed (run->v_min_power_ms),
 * and the top speed beyond the mission's own (run->v_max_ms is then a
 * lower bound at or above it).  Returns true when every number came out
 * finite. */
bool perf_fly(const struct sizing_params *p, const struct perf_craft *c,
              bool trial, struct res_run *run);

/* The performance figures beyond the mission (hover and full-throttle
 * endurance, the mission's mix to the reserve, maximum climb and tilt,
 * spare payload, one motor out) into run->perf, and the power-vs-speed
 * curve into run->sweep_v_ms/sweep_power_w, for a run perf_fly() has
 * flown with the same p and c.  No check reads them: the parts search
 * works them out for the design of record only, not for every closing it
 * tries (two discharge simulations each).  Returns true when they came
 * out finite. */
bool perf_figures(const struct sizing_params *p, const struct perf_craft *c,
                  struct res_run *run);

#endif
