/* sens.h — the 14-parameter sensitivity suite (paper §VII-E) and the
 * shedding comparison of §VII-D.
 *
 * Each parameter is swept over a range around the mission's own value; every
 * point is a full engine_solve() of a copy of the mission with that one field
 * changed (and its given[] flag set, so no derived default overwrites it).
 * At every point the suite keeps the custom run's MTOW, its hover endurance
 * (the paper's "hover flight time") and its approved mission time.  At the
 * mission's value it takes central finite differences in the paper's units
 * (kg/kg, kg/in, min/1000 m, ...), and where a sweep leaves the feasible,
 * converged region it reports where.
 *
 * A point is "good" when the engine returned 0, the custom run ran, its mass
 * loop converged and every check passed.  The crossing of a sweep is where
 * it first stops being good walking away from the mission's value: linear
 * interpolation to zero of the margin of the check that fails worst at the
 * first bad point, between the last good point and that one, when both
 * carry it (an infeasible but converged design); else the midpoint of the
 * two (runaway, gate, no convergence: nothing continuous to interpolate).
 *
 * Role-specific parameters (drop mass, drop time ratio: delivery; spray rate:
 * agriculture) are evaluated on a copy of the mission with that role when the
 * mission's role differs; the curve says so (role_substituted).
 *
 * Engine layer plus plain C: no JSON, PDF or cairo here (sens_report.h and
 * cli_sens.c write the outputs).  Reentrant: everything is in the arguments.
 */
#ifndef AEROEVAL_SENS_H
#define AEROEVAL_SENS_H

#include <stdbool.h>

#include "spec/model.h"
#include "spec/spec.h"

#define SENS_MAX_POINTS 31     /* points of one sweep (the suite uses 11-15) */
#define SENS_MAX_CHECKS 24     /* checks kept per point (= RES_MAX_CHECKS) */

/* The 14 parameters, in the paper's table order. */
enum sens_param {
	SENS_PAYLOAD,        /* payload_kg, kg */
	SENS_DIAM_LIMIT,     /* prop-diameter limit (via max_diameter_m), in */
	SENS_V_FORWARD,      /* v_forward_ms, m/s */
	SENS_V_CLIMB,        /* v_climb_ms, m/s */
	SENS_ALTITUDE,       /* altitude_m, m (ambient follows ISA unless given) */
	SENS_AMBIENT,        /* ambient_temp_c, degC */
	SENS_AUX_POWER,      /* payload_role.aux_power_w, W */
	SENS_DRAG_AREA,      /* payload_role.added_drag_m2, m^2 */
	SENS_CG_SHIFT,       /* payload_role.cg_shift_m, m */
	SENS_BATT_LOCK,      /* locks.locked_capacity_mah (battery locked), mAh */
	SENS_PROP_LOCK,      /* locks.locked_diameter_in (prop locked), in */
	SENS_DROP_MASS,      /* payload_role.delivery_drop_mass_kg, kg */
	SENS_DROP_RATIO,     /* payload_role.delivery_drop_time_ratio, - */
	SENS_SPRAY_RATE,     /* payload_role.spray_rate_kg_per_s, kg/s */
	SENS_N_PARAMS
};

/* What stopped a point from being good (or SENS_OK). */
enum sens_status {
	SENS_OK,             /* converged, feasible, finite */
	SENS_INFEASIBLE,     /* converged, but a check failed */
	SENS_NOT_CONVERGED,  /* the mass loop hit its iteration limit */
	SENS_RUNAWAY,        /* mass above the runaway bound, or the mission
	                        could not be flown at the converged mass */
	SENS_GATE,           /* rejected before the mass loop */
	SENS_ERROR           /* non-finite number caught by the engine */
};

/* Static description of one parameter. */
struct sens_param_info {
	const char *key;         /* JSON key: "payload", "forward_speed", ... */
	const char *label;       /* "Payload mass" */
	const char *unit;        /* unit of the swept value x: "kg", "in", "m/s" */
	double step;             /* the paper's reporting step in x units
	                            (1 kg, 1000 m, 10 degC, 0.1 m^2, 0.05 m ...) */
	const char *step_text;   /* that step as the paper prints it: "1000 m" */
	int role;                /* enum role_type the parameter needs, or -1 */
};

/* One solved point of a sweep. */
struct sens_point {
	double x;                /* parameter value, in the info's unit */
	enum sens_status status;
	double mtow_kg;          /* custom-run takeoff mass (0 if it did not run) */
	double hover_endurance_s;/* hover-only endurance to the reserve */
	double flight_time_s;    /* approved mission time */
	double margin;           /* worst check margin (< 0: a check failed) */
	bool has_margin;         /* margin is meaningful (the run converged) */
	int n_checks;            /* the custom run's checks with a limit */
	char check_name[SENS_MAX_CHECKS][64];
	double check_margin[SENS_MAX_CHECKS];
	char reason[48];         /* first violation code at this point, "" if good */
};

/* One sweep and its derivatives. */
struct sens_curve {
	enum sens_param id;
	bool role_substituted;   /* evaluated with info.role instead of the mission's */
	double x0;               /* the mission's value */
	struct sens_point nominal;
	int n;
	struct sens_point pt[SENS_MAX_POINTS]; /* ascending x */

	/* Finite differences at x0 from two extra solves x0 ± h (h = the grid
	 * step; one-sided when a side is outside the allowed range or not good).
	 * An infeasible but converged nominal still gets derivatives, from
	 * converged neighbours; a nominal that did not converge gets none. */
	double h;                /* step used, x units */
	int fd_kind;             /* 0 central, +1 forward, -1 backward, 2 none */
	bool has_fd_lo, has_fd_hi;      /* x0 - h, x0 + h inside the bounds */
	struct sens_point fd_lo, fd_hi; /* the two solves */
	double d_mtow;           /* kg per info.step */
	double d_hover_min;      /* min of hover endurance per info.step */
	double d_flight_min;     /* min of approved flight time per info.step */

	/* Leaving the good region, below and above x0. */
	bool cross_lo, cross_hi;
	double x_cross_lo, x_cross_hi;
	char why_lo[48], why_hi[48];

	/* Tornado: MTOW at the outermost good points of the contiguous good
	 * run around x0 (equal to the nominal when none). */
	double x_good_lo, x_good_hi;
	double mtow_good_lo_kg, mtow_good_hi_kg;
};

struct sens_result {
	char mission[SPEC_STR_MAX];   /* mission name */
	int role;                     /* the mission's resolved role */
	struct sens_point nominal;    /* the mission as given */
	int n_solves;                 /* engine solves performed */
	double seconds;               /* wall time of the suite (0 if not timed) */
	struct sens_curve c[SENS_N_PARAMS];
};

/* The table of parameters, indexed by enum sens_param. */
extern const struct sens_param_info sens_params[SENS_N_PARAMS];

/* Spelling of a status: "ok", "infeasible", "not_converged", "runaway",
 * "gate", "error". */
const char *sens_status_name(enum sens_status s);

/* Runs the whole suite on spec (as parsed: given[] as in the file).
 * Returns 0, or 1 when the nominal point itself is not good (the sweeps are
 * still run and reported). */
int sens_run(const struct mission_spec *spec, const struct model_data *md,
             struct sens_result *out);

/* One sweep of parameter id over [lo, hi] in n points (2..SENS_MAX_POINTS),
 * plus its derivatives and crossings; lo == hi == 0 means the suite's own
 * range.  *n_solves is increased by the solves made (may be NULL). */
void sens_sweep(const struct mission_spec *spec, const struct model_data *md,
                enum sens_param id, double lo, double hi, int n,
                struct sens_curve *c, int *n_solves);

/* Solves spec with parameter id set to x (role substituted if needed) and
 * fills *pt.  Exposed for tests: a derivative must agree with two of these. */
void sens_eval(const struct mission_spec *spec, const struct model_data *md,
               enum sens_param id, double x, struct sens_point *pt);

/* The mission's value of parameter id (after the engine resolves defaults;
 * for the locks: the nominal design's capacity / propeller). */
double sens_nominal_x(const struct mission_spec *spec,
                      const struct model_data *md, enum sens_param id);

/* ---- the shedding study (paper §VII-D) ---------------------------------- */

struct sens_shedding {
	bool ok;                       /* both runs ran and converged */
	double mtow_static_kg, mtow_dynamic_kg;
	double energy_static_wh, energy_dynamic_wh;
	double frame_static_kg, frame_dynamic_kg; /* frame + arms + other */
	double avg_mass_dynamic_kg;    /* time-mean aircraft mass, dynamic run */
	double energy_saving;          /* 1 - E_dyn / E_static */
	double frame_saving;           /* 1 - frame_dyn / frame_static */
	double avg_mass_reduction;     /* 1 - avg_mass_dyn / MTOW_static */
};

/* Compares the custom runs of a static and a dynamic sizing.  With
 * stat == NULL the static case is dyn with payload_role.mass_shedding off. */
void sens_shedding(const struct mission_spec *stat,
                   const struct mission_spec *dyn,
                   const struct model_data *md, struct sens_shedding *out);

#endif
