/* checks.h — the one table of checks every design is held to.
 *
 * The continuous design (sizing/feasibility.c) and the design of record on
 * catalogue parts (parts/closure.c) are judged by the same checks: each is a
 * row of check_table[] with its stable code, its name, its unit, the side
 * of the limit that passes, the condition it is evaluated at (hover, the
 * mission's peak, a full-throttle burst, ...), why it matters and what
 * fixes it.  A design fills a struct check_values with the values and
 * limits it knows; checks_apply() turns them into the run's checks table
 * and one violation per failed check, with the same words for both.
 * Who may include it: the engine's layers and the report.
 */
#ifndef AEROEVAL_CHECKS_H
#define AEROEVAL_CHECKS_H

#include <stdbool.h>

#include "result/result.h"

/* Where a check is evaluated. */
enum check_cond {
	COND_DESIGN,     /* a geometric or static property */
	COND_HOVER,      /* hovering at takeoff mass */
	COND_MISSION,    /* the mission's most demanding sustained phase */
	COND_FULL,       /* a full-throttle burst (PERF_FULL_THROTTLE_S) */
	COND_DESIGN_LOAD,/* the arm's design load (max of load factor × CG thrust, full thrust) */
	COND_LANDING,    /* at touchdown */
	COND_FLIGHT,     /* over the whole flight */
	COND_COUNT
};

/* The checks, in the order the checks table lists them. */
enum check_id {
	/* The mission. */
	CK_RESERVE, CK_THRUST, CK_THROTTLE, CK_CLIMB_SPEED, CK_FORWARD_PITCH,
	CK_FORWARD_SPEED, CK_DOWNWASH,
	/* The power path, pack to motor. */
	CK_BATTERY_CONTINUOUS, CK_BATTERY_BURST, CK_BATTERY_POWER,
	CK_CONNECTOR_MISSION, CK_CONNECTOR_FULL, CK_POWER_MODULE_MISSION,
	CK_POWER_MODULE_FULL, CK_HARNESS_FULL, CK_ESC_CURRENT,
	CK_MOTOR_CURRENT_MISSION, CK_MOTOR_CURRENT_FULL, CK_MOTOR_POWER,
	CK_VOLTAGE_MISSION, CK_VOLTAGE_FULL,
	/* Heat. */
	CK_BATTERY_TEMP, CK_WINDING_HOVER, CK_WINDING_FULL,
	/* The rotor. */
	CK_PROP_OVERLAP, CK_TIP_MACH, CK_PROP_RPM,
	/* The structure. */
	CK_ARM_SAFETY, CK_ARM_TILT, CK_ARM_TORSION, CK_ARM_MODE_CONTROL,
	CK_ARM_MODE_REV, CK_ARM_MODE_BLADE_PASS, CK_FRAME_MTOW, CK_CG_OFFSET,
	CK_COUNT
};

/* One row of the table: what the check is, in the client's words. */
struct check_def {
	const char *code;      /* stable machine code, "CONNECTOR_CURRENT_FULL" */
	const char *stage;     /* "discharge", "parts", "structure", ... */
	const char *name;      /* "Battery connector current" */
	const char *unit;      /* "A" */
	bool upper;            /* value <= limit passes (else value >= limit),
	                          unless check_values.side says otherwise */
	enum check_cond cond;
	const char *why;       /* one sentence: what goes wrong past the limit */
	const char *fix[RES_MAX_FIXES]; /* "{value}" and "{limit}" expand */
};

extern const struct check_def check_table[CK_COUNT];

/* How a condition reads in the checks table ("full-throttle burst, 10 s"). */
const char *check_cond_text(enum check_cond cond);

/* What one design knows: a check is evaluated when on[id]. */
struct check_values {
	bool on[CK_COUNT];
	double value[CK_COUNT];
	double limit[CK_COUNT];
	signed char side[CK_COUNT];  /* 0: the table's; +1 value <= limit;
	                                -1 value >= limit (a band's near edge) */
	bool sized[CK_COUNT];        /* the design is sized to it */
	bool pass_within_tol[CK_COUNT]; /* passes though a hair beyond (the
	                                reserve, integrated to its tolerance) */
	bool advisory[CK_COUNT];     /* a failure is reported, not a rejection */
	bool terse;                  /* values only: no basis text is
	                                written (a trial closing's) */
	/* Last, and strings only (checks_init() clears their first bytes): */
	char basis[CK_COUNT][RES_BASIS]; /* what sets the limit, "2 × XT60, 60 A" */
	char note[CK_COUNT][RES_TEXT];   /* a clause added to a failure */
};

/* Start with every check off. */
void checks_init(struct check_values *v);

/* Write what sets check id's limit ("2 × XT60, 60 A"), unless v->terse. */
void checks_basis(struct check_values *v, enum check_id id, const char *fmt,
                  ...) __attribute__((format(printf, 3, 4)));

/* Turn a check on with its value and limit. */
void checks_set(struct check_values *v, enum check_id id, double value,
                double limit);

/* The run's checks table, in table order, and one violation per failed
 * check (run: a string literal, "custom", "closed", ...).  Sets o->feasible
 * when every check passes but the advisory ones (other violations are the
 * caller's). */
void checks_apply(const struct check_values *v, const char *run,
                  struct res_run *o, struct solve_result *r);

/* The check of this code in a run's table, or NULL. */
const struct res_check *checks_find(const struct res_run *o, const char *code);

#endif
