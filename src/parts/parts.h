/* parts.h — the parts search: the continuous optimum onto real parts, and
 * the aircraft those parts build (the design of record).
 *
 * Paper §VIII uses the continuous optimum as the aim of a search over the
 * parts catalogue.  aeroeval searches every admissible bus (series cell
 * count), every motor and propeller of the catalogue that can fly there,
 * and every arrangement of catalogue packs (series × parallel, any
 * chemistry unless the mission names one) that builds that bus:
 *
 *   rank   every bus × motor × propeller option is flown at full throttle
 *          on the motor's own constants (KV, R, I0) and the propeller's
 *          own coefficients; those that cannot lift the design, overrun a
 *          rating even on the most-sagged bus a pack may give (the winding
 *          temperature counted among the ratings), or break tip Mach are
 *          pruned; the rest are scored by J,
 *          the takeoff-mass penalty they would bring over the continuous
 *          design, in percent (parts/rank.c says how it is estimated and
 *          why that weighs diameter and KV as the physics does);
 *   close  the best options get an ESC set, a battery, a frame kit where
 *          one fits, the avionics set of the airframe class and the
 *          battery connectors (parts/kit.c) and are closed: the takeoff
 *          mass found again with the real parts' masses, the structure
 *          sized for the real motors' thrust, the mission flown on the real
 *          drive (sizing/perf.h) and every check applied, with the same
 *          requirements as the continuous design (its T/W, the reserve,
 *          the largest payload);
 *   choose the design of record is the lightest combination that passes
 *          every check and reaches the continuous design's T/W; when none
 *          reaches it, the lightest at or above the floor the continuous
 *          loop relaxes a role's default target to; when none passes, the
 *          search ranks again at the mass the closest closing reached, and
 *          else reports the one with the fewest failures as not buildable.
 *
 * Parts layer: no I/O.  Reentrant.
 */
#ifndef AEROEVAL_PARTS_H
#define AEROEVAL_PARTS_H

#include "catalog/catalog.h"
#include "spec/model.h"
#include "result/result.h"
#include "spec/spec.h"
#include "sizing/sizing.h"

/* Select parts for the converged custom run of r and build the design of
 * record into r->closed, with r->motor/prop/battery/esc, the bill of
 * materials, the crosshair candidates, rationale lines and "parts"
 * violations.  spec is the resolved mission (r->mission), p_custom the
 * custom run's parameters.  Returns 0, or 3 when a number came out
 * non-finite (an internal error). */
int parts_select(const struct mission_spec *spec,
                 const struct sizing_params *p_custom,
                 const struct model_data *md, const struct catalog *cat,
                 struct solve_result *r);

#endif
