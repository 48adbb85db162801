/* calibrate.h — fit the calibrated coefficients to a cohort of real
 * aircraft, and measure what the fit is worth.
 *
 * Two separate fits, so that no coefficient absorbs another's error:
 *
 * 1. THE POWER CHAIN on the forward check alone.  For every row with a
 *    published takeoff mass, pack and flight time, the model flies that
 *    aircraft at that mass on that pack to an empty pack, as makers quote
 *    it (sizing_endurance_at_mass()): in hover against the published hover
 *    time, in level flight at the published cruise speed (else the
 *    minimum-power speed) against the published maximum flight time.
 *    The residuals ln(t_model / t_published) fit the installed-FoM penalty
 *    κ, the drive efficiency η (motor + ESC), the Reynolds reference of the
 *    FoM(Re) fit, a scale on the roles' auxiliary power and a scale on the
 *    body drag area, each inside physical bounds (calibrate.c).  No mass
 *    enters: the aircraft's real mass and real pack are given.
 * 2. THE MASS LAWS on the dry mass alone.  For every row with a published
 *    battery mass, the model's dry mass (everything but payload and
 *    battery) at the real takeoff mass, ln(dry_model / dry_real), fits the
 *    equipment law e_class (M_design / 1 kg)^β per class and the wiring
 *    coefficient C_wire, with the power chain of fit 1 held.  λ per class
 *    and β = 2/3 are held (docs/model.md).
 *
 * Racing rows are left out of the forward check: a racer's published
 * flight time is flown at race throttle, neither in hover nor at a stated
 * speed.  Both fits minimise their squares plus mu sum ln(theta/prior)^2
 * (lsq.h); a coefficient informed by fewer than CALIBRATE_MIN_ROWS rows
 * keeps its prior.
 *
 * What it is worth is measured out of sample: each row is left out in
 * turn, both fits redone on the others, and the row's forward check, dry
 * mass and closed-loop takeoff mass (from its endurance, and around its
 * published pack) predicted.  Those errors give the accuracy figures and
 * the split-conformal intervals (struct model_accuracy, model_spread) the
 * engine turns into each design's own intervals.
 *
 * Study layer (no printing, no JSON).  Reentrant.
 */
#ifndef AEROEVAL_CALIBRATE_H
#define AEROEVAL_CALIBRATE_H

#include <stdbool.h>
#include <stddef.h>

#include "input/cohort.h"
#include "spec/model.h"

enum calibrate_param {
	/* the power chain: fit 1 */
	CAL_KAPPA,               /* installed-FoM penalty κ */
	CAL_ETA_DRIVE,           /* motor + ESC efficiency */
	CAL_RE_REF,              /* Reynolds reference of FoM(Re) */
	CAL_AUX_SCALE,           /* on the roles' auxiliary power */
	CAL_DRAG_SCALE,          /* on the body drag area */
	CAL_WAKE_SHARE,          /* forward flight's induced relief, 1 - the
	                          * wake share (a positive prior, 1) */
	/* the mass laws: fit 2 */
	CAL_LAMBDA_MICRO,        /* λ MicroAIO (held) */
	CAL_LAMBDA_CONSUMER,     /* λ ConsumerFolding (held) */
	CAL_LAMBDA_ENT_QUAD,     /* λ EnterpriseRugged quad (held) */
	CAL_LAMBDA_ENT_MULTI,    /* λ EnterpriseRugged hex/octo (held) */
	CAL_LAMBDA_AGRI,         /* λ Agricultural (held) */
	CAL_EQUIP_MICRO,         /* equipment at 1 kg, MicroAIO, kg */
	CAL_EQUIP_CONSUMER,
	CAL_EQUIP_ENTERPRISE,
	CAL_EQUIP_AGRI,
	CAL_EQUIP_EXPONENT,      /* β (held) */
	CAL_WIRE_COEF,           /* C_wire, kg/(A m) */
	CAL_N_PARAMS
};
#define CAL_FIRST_MASS CAL_LAMBDA_MICRO /* params below it: the power chain */

/* Name of a parameter ("kappa", "lambda MicroAIO", ...). */
const char *calibrate_param_name(enum calibrate_param p);

/* Priors and bounds (calibrate.c says where each comes from). */
extern const double calibrate_prior[CAL_N_PARAMS];
extern const double calibrate_lo[CAL_N_PARAMS];
extern const double calibrate_hi[CAL_N_PARAMS];

/* A coefficient informed by fewer rows keeps its prior: two aircraft
 * cannot tell a class's coefficient from their own quirks. */
#define CALIBRATE_MIN_ROWS 3
#define CALIBRATE_PROP_PASSES 3 /* minimisations, each propeller choice held */
#define CALIBRATE_MU 0.05    /* Tikhonov weight: a 10 % move from the prior
                              * costs about as much as a 2 % error on one row */
#define CALIBRATE_LEVEL 0.90 /* nominal coverage of the intervals */
/* A class gets an interval of its own from this many leave-one-out
 * residuals: the smallest n for which the split-conformal bounds of a
 * 90 % two-sided interval are finite ((n + 1) 0.05 >= 1). */
#define CALIBRATE_CLASS_INTERVAL_MIN 19

/* theta <-> calibration.  calibrate_apply keeps the small-platform wiring
 * coefficient in the ratio `base` had and leaves base's accuracy out. */
void calibrate_theta(const struct model_calibration *cal, double theta[CAL_N_PARAMS]);
void calibrate_apply(const double theta[CAL_N_PARAMS], const struct model_calibration *base,
                     struct model_calibration *out);

/* One aircraft of a fit: the missions the validation rule built for it and
 * what is known of it. */
struct calibrate_row {
	struct mission_spec spec;      /* battery sized from the endurance */
	struct mission_spec pack_spec; /* the published pack locked, where given
	                                * (else the same as spec) */
	bool sized;              /* spec is a mission the loop may size */
	bool has_pack;           /* pack_spec locks the published pack */
	double actual_kg;        /* real takeoff mass */
	double battery_kg;       /* real battery mass, 0 when unknown */
	double hover_s;          /* published hover time, 0 when unknown */
	double max_flight_s;     /* published maximum flight time, 0 unknown */
	double cruise_ms;        /* its speed, 0 when unknown */
	bool racing;             /* flight times flown at race throttle */
};

/* The real dry mass of a row (takeoff - payload - battery), 0 when the
 * battery mass is unknown or leaves nothing. */
double calibrate_dry_kg(const struct calibrate_row *row);

/* Does the row take part in the forward check (a pack, a time, not a
 * racer)? */
bool calibrate_has_forward(const struct calibrate_row *row);

/* The forward check of row at calibration cal: ln(t_model / t_published)
 * for its hover time into r[0] and its maximum flight time into r[1],
 * each NAN when not published or not flown.  False when the model cannot
 * fly the aircraft on its pack. */
bool calibrate_forward(const struct calibrate_row *row, const struct model_data *md,
                       double r[2]);

/* Leave-one-out outcome of one row. */
struct calibrate_loo {
	bool sized[MODEL_BASIS_MAX];             /* the closed loop converged */
	double predicted_kg[MODEL_BASIS_MAX];    /* takeoff mass, the row left out */
	double battery_pred_kg[MODEL_BASIS_MAX]; /* its battery */
	double dry_pred_kg[MODEL_BASIS_MAX];     /* its dry mass */
	double lipschitz[MODEL_BASIS_MAX];       /* its loop's L */
	double forward[2];                       /* forward residuals, NAN if none */
	double dry;                              /* ln(dry_model / dry_real), NAN */
};

struct calibrate_result {
	struct model_calibration before;  /* the starting calibration */
	struct model_calibration after;   /* the fit, with its accuracy when measured */
	double theta[CAL_N_PARAMS];       /* the fit as parameters */
	size_t n_rows;                    /* rows in either fit */
	size_t n_forward;                 /* rows in the power-chain fit */
	size_t n_dry;                     /* rows in the mass-law fit */
	size_t n_per_param[CAL_N_PARAMS]; /* rows informing each coefficient */
	bool at_bound[CAL_N_PARAMS];      /* the fit pinned it at a bound */
	double forward_before_pct;        /* forward-check MAPE at the priors */
	double forward_after_pct;         /* ... and at the fit, in sample */
	double dry_before_pct;            /* dry-mass MAPE at the priors */
	double dry_after_pct;             /* ... and at the fit, in sample */
	double mtow_mape_pct;             /* closed loop, in sample, after (from
	                                   * the endurance) */
	size_t n_sized;                   /* rows the closed loop sized, after */
	size_t n_sizable;                 /* rows it was asked to size */
	int lsq_status;                   /* enum lsq_status of the worse fit */
	size_t n_iter;
	size_t n_evals;                   /* open-loop evaluations */
	size_t n_solves;                  /* closed-loop solves */
	struct calibrate_loo *loo;        /* n_rows entries when measured, else NULL */
	size_t *row_index;                /* the cohort row of each fitted row */
};

/* Progress: fn is called after each closed-loop solve and after each pass
 * of the minimiser, with the stage (0: the full fit, k >= 1: leave-one-out
 * fit k of n_rows), the rows done in that stage and the solves so far. */
struct calibrate_progress {
	void (*fn)(void *ctx, size_t stage, size_t done, size_t n_rows, size_t n_solves);
	void *ctx;
};

/* Builds the fit's row from cohort row cr by the validation rule; false
 * when the rule has no mission for it. */
bool calibrate_row_from_cohort(const struct cohort_row *cr,
                               const struct model_data *md,
                               struct calibrate_row *out);

/* Fits on cohort c starting from the priors calibrate_prior (md->cal is
 * the "before" of the report and lends its wiring ratio) and, when loo,
 * measures the leave-one-out accuracy into out->after.accuracy[],
 * .forward and .dry.
 * Returns 0 with *out filled, -1 when no row of c yields a usable mission
 * (out->n_rows 0), -2 when the minimiser failed.  Release with
 * calibrate_result_free(). */
int calibrate_fit(const struct cohort *c, const struct model_data *md, bool loo,
                  const struct calibrate_progress *progress,
                  struct calibrate_result *out);

/* The fit alone on explicit rows, with Tikhonov weight mu: the engine of
 * calibrate_fit, for tests that build missions directly. */
int calibrate_fit_rows(const struct calibrate_row *rows, size_t n,
                       const struct model_data *md, double mu,
                       struct calibrate_result *out);

void calibrate_result_free(struct calibrate_result *r);

/* Split-conformal bounds from n residuals (sorted in place): the
 * floor((n + 1) a/2)-th smallest and the ceil((n + 1)(1 - a/2))-th
 * smallest, a = 1 - level; false (bounds untouched) when n is too small
 * for them to exist. */
bool calibrate_conformal(double *resid, size_t n, double level,
                         double *lo, double *hi);

#endif
