/* feasibility.h — the feasibility gate and the checks table.
 *
 * Paper §IV-A: cheap geometric and physical checks reject impossible
 * configurations before the mass loop (coaxial arm count, a locked propeller
 * that overlaps its neighbour, a CG outside the rotor polygon, no mission,
 * a locked battery that cannot hold even the mission's lower-bound energy).
 * After the loop, the design is held to the checks of result/checks.h: one
 * row each of the checks table (value, limit, margin, PASS/FAIL), and each
 * failure a violation with a plain message and suggested fixes.
 */
#ifndef AEROEVAL_FEASIBILITY_H
#define AEROEVAL_FEASIBILITY_H

#include <stdbool.h>

#include "result/result.h"
#include "sizing/sizing.h"

/* Pre-loop gate for one run.  Appends violations (run name `run`, a
 * string literal) to r and returns true when the run may go on. */
bool feasibility_gate(const struct sizing_params *p, const char *run,
                      struct solve_result *r);

/* Fill run->checks from a finished run and append a violation for each
 * failed check and for the loop status (run: a string literal, as the
 * violations keep it).  Sets run->feasible. */
void feasibility_checks(const struct sizing_params *p, enum sizing_status st,
                        const char *run, struct res_run *run_out,
                        struct solve_result *r);

/* The checks both designs are held to that their run's figures decide
 * (the mission, heat, voltage, rotor, arm and CG), into v; the caller adds
 * its own (result/checks.h) and applies them.  Sets o's once-per-revolution
 * band. */
struct check_values;
void feasibility_common_checks(const struct sizing_params *p, struct res_run *o,
                               struct check_values *v);

/* Append one violation; fixes is a NULL-terminated list (may be NULL).
 * run, stage and code are string literals (the violation keeps the
 * pointers, see result.h).  With r->terse, run, stage and code only
 * (fixes and fmt are not read, message is empty). */
void feasibility_violation(struct solve_result *r, const char *run,
                           const char *stage, const char *code,
                           const char *const *fixes, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));

/* A violation's fix text into f (RES_TEXT bytes), unless r keeps its
 * violations' codes only (a trial closing's, solve_result.terse): none of
 * its violations reads the text then. */
void feasibility_fix(const struct solve_result *r, char *f, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
