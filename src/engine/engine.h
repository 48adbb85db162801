/* engine.h — one solve: mission in, struct solve_result out.
 *
 * Applies the requirements-first layer (paper §III-A Mission Workspace),
 * resolves every role- and class-derived default the mission left open,
 * runs the baseline (null role, hover throttle 0.60) and the custom run
 * through the feasibility gate and the mass loop, fills the checks and
 * violations, the role overhead, and the plain-language design rationale.
 * Parts selection (parts/parts.c) runs on top when a catalogue is given.
 *
 * Engine layer: no JSON, PDF or cairo.  Reentrant: everything it touches is
 * in its arguments, so missions can be solved in parallel.
 */
#ifndef AEROEVAL_ENGINE_H
#define AEROEVAL_ENGINE_H

#include "spec/model.h"
#include "result/result.h"
#include "sizing/sizing.h"
#include "spec/spec.h"

struct catalog;

/* Solve `spec` with the reference tables `md` and, when cat != NULL, pick
 * real parts from it.  Returns 0 when every run produced finite numbers
 * (feasible or not: see r->feasible), 3 on an internal error (a non-finite
 * value caught before it could reach an output). */
int engine_solve(const struct mission_spec *spec, const struct model_data *md,
                 const struct catalog *cat, struct solve_result *r);

/* The endurance explorer of r's custom run (sizing_explore()), for the
 * outputs that show it: result.json and the dossier.  Kept out of
 * engine_solve() because nothing the design is decided on reads it, and
 * the batch analyses (validate, sensitivity) solve hundreds of missions
 * without it. */
void engine_explore(struct solve_result *r, const struct model_data *md);

/* The custom run's map f evaluated once at mass_kg (sizing_at_mass()):
 * the open-loop comparison of validate and calibrate, which evaluate the
 * model at a real aircraft's real takeoff mass.  An unlocked propeller is
 * flown at share of the largest the wheelbase admits, or, with share 0,
 * at the share of those the closed loop tries whose f is
 * least (out->prop_frac says which). */
bool engine_at_mass(const struct mission_spec *spec, const struct model_data *md,
                    double mass_kg, double share, struct sizing_open *out);

/* The forward check of validate and calibrate (sizing_endurance_at_mass()):
 * the endurance of the aircraft spec describes, its pack locked, at
 * mass_kg; an unlocked propeller flown at share of the largest the
 * wheelbase admits (0 reads as 1). */
bool engine_endurance_at_mass(const struct mission_spec *spec,
                              const struct model_data *md, double mass_kg,
                              double share, double v_forward_ms,
                              struct sizing_endurance *out);

/* The interval on ln(real / model) of a continuous design's takeoff mass
 * (PRODUCT "The prediction intervals on a design"): the dry-mass model's
 * spread on its dry share and the forward check's on its battery share,
 * carried through the loop's gain 1 / (1 - L), L capped at ENGINE_MAX_L.
 * Shared by the engine and the calibration's coverage measure. */
#define ENGINE_MAX_L 0.9
void engine_loop_interval(double dry_share, double battery_share, double lipschitz,
                          const struct model_spread *dry,
                          const struct model_spread *fwd,
                          double *log_lo, double *log_hi);

/* Resolve the mission into the custom-run parameters (after the
 * requirements layer has been applied to *spec).  Exposed for the
 * sensitivity study and the tests. */
void engine_params(const struct mission_spec *spec, const struct model_data *md,
                   bool baseline, struct sizing_params *p);

/* Apply requirements{} and the role/class defaults to *spec in place,
 * appending one rationale line per decision to r (may be NULL). */
void engine_resolve(struct mission_spec *spec, const struct model_data *md,
                    struct solve_result *r);


#endif
