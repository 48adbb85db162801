/* invariants.h — the physics every printed number must obey.
 *
 * Checked on every solve before anything is written (PRODUCT "The design
 * of record"): on the design of record and on both continuous runs, every
 * efficiency in (0, 1]; shaft power at most the electrical power; a
 * reachable operating point at most full throttle; the energy of the phase
 * table the integral of their power over their time (0.5 %); the charge
 * drawn what the state of charge says (0.5 %); the mass breakdown summing
 * to the takeoff mass; the bill of materials plus the payload equal to the
 * takeoff mass of record (1 g); a feasible design landing at or above its
 * reserve.  A broken invariant is a defect of the engine, never a result:
 * the solve becomes an internal error (exit 3) that names it.
 *
 * Engine layer; no I/O.
 */
#ifndef AEROEVAL_INVARIANTS_H
#define AEROEVAL_INVARIANTS_H

#include <stddef.h>

#include "result/result.h"
#include "sizing/sizing.h"

#define INV_ENERGY_RELTOL 0.005   /* energy and charge balances */
#define INV_BOM_TOL_KG    0.001   /* BOM + payload against the takeoff mass */
#define INV_SUM_RELTOL    1e-9    /* mass items against their total */
#define INV_RESERVE_TOL   SIZING_RESERVE_TOL /* landing SOC under the
                                     reserve: the discharge's integration
                                     accuracy (a continuous design is sized
                                     to land on it exactly) */

/* 0 when every invariant holds, else 3 with the first broken one described
 * in msg (size n). */
int invariants_check(const struct solve_result *r, char *msg, size_t n);

#endif
