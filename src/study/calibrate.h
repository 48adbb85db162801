/* calibrate.h — fit the calibrated coefficients to a cohort of real
 * aircraft, and measure what the fit is worth.
 *
 * The coefficients (enum calibrate_param): the structural multiplier λ per
 * class (paper eq. lambda), the equipment law e_class (M_design / 1 kg)^β
 * (airframe.h: avionics, body shell, landing gear, gimbal and mounts), the
 * wiring coefficient C_wire (paper §V-C; the racing/small-platform one
 * keeps its ratio to it) and the installed-FoM penalty κ per class (paper
 * Table classes), which carries the power, and so the battery, chain.
 *
 * The fit is OPEN LOOP: the mass function f of the sizing loop is
 * evaluated once at each aircraft's real takeoff mass (sizing_at_mass()),
 * where the model's parts can be compared with the real ones without the
 * loop's amplification (near L = 1 a 3 % error in a mass fraction moves the
 * fixed point by 10 % or more).  The residuals of a row are
 *	ln(f(M) / M)                   the closure at the real mass M: M is a
 *	                               fixed point of the model when it is 0,
 *	ln(dry_model / dry_real)       where the row gives the battery mass
 *	ln(battery_model / battery_real)   (dry = takeoff - payload - battery),
 * and the fit minimises their squares plus mu sum ln(theta/prior)^2
 * (lsq.h).  A coefficient informed by fewer than CALIBRATE_MIN_ROWS rows
 * keeps its prior.  Rows whose loop is not a contraction at the role's
 * default thrust target (the engine relaxes it; sizing.h) are left out of
 * the fit and reported: the role's target does not describe them.
 *
 * What it is worth is measured CLOSED LOOP and out of sample: each row is
 * left out in turn, the coefficients refitted on the others, and the row
 * sized by the full mass loop (leave-one-out).  Those errors give the
 * accuracy figures and a split-conformal prediction interval on
 * ln(actual / predicted) (struct model_accuracy) that result.json and the
 * dossier put around every design's takeoff mass.
 *
 * Study layer (no printing, no JSON).  Reentrant.
 */
#ifndef AEROEVAL_CALIBRATE_H
#define AEROEVAL_CALIBRATE_H

#include <stdbool.h>
#include <stddef.h>

#include "input/cohort.h"
#include "core/model.h"

enum calibrate_param {
	CAL_LAMBDA_MICRO,        /* λ MicroAIO */
	CAL_LAMBDA_CONSUMER,     /* λ ConsumerFolding */
	CAL_LAMBDA_ENT_QUAD,     /* λ EnterpriseRugged quad */
	CAL_LAMBDA_ENT_MULTI,    /* λ EnterpriseRugged hex/octo */
	CAL_LAMBDA_AGRI,         /* λ Agricultural */
	CAL_EQUIP_MICRO,         /* equipment at 1 kg, MicroAIO, kg */
	CAL_EQUIP_CONSUMER,
	CAL_EQUIP_ENTERPRISE,
	CAL_EQUIP_AGRI,
	CAL_EQUIP_EXPONENT,      /* β */
	CAL_WIRE_COEF,           /* C_wire, kg/(A m) */
	CAL_KAPPA_MICRO,         /* κ MicroAIO: installed-FoM penalty */
	CAL_KAPPA_CONSUMER,
	CAL_KAPPA_ENTERPRISE,
	CAL_KAPPA_AGRI,
	CAL_N_PARAMS
};

/* Name of a parameter ("lambda MicroAIO", ...). */
const char *calibrate_param_name(enum calibrate_param p);

/* Priors (the paper's λ and C_wire; see calibrate.c for the equipment
 * law's) and bounds. */
extern const double calibrate_prior[CAL_N_PARAMS];
extern const double calibrate_lo[CAL_N_PARAMS];
extern const double calibrate_hi[CAL_N_PARAMS];

/* A coefficient informed by fewer rows keeps its prior: two aircraft
 * cannot tell a class's coefficient from their own quirks. */
#define CALIBRATE_MIN_ROWS 3
#define CALIBRATE_PROP_PASSES 3 /* minimisations, each propeller choice held */
#define CALIBRATE_MU 0.05    /* Tikhonov weight: a 10 % move from the prior
                              * costs about as much as a 2 % error on one row */
#define CALIBRATE_LEVEL 0.90 /* nominal coverage of the interval */
/* A class gets an interval of its own from this many leave-one-out
 * residuals: the smallest n for which the split-conformal bounds of a
 * 90 % two-sided interval are finite ((n + 1) 0.05 >= 1). */
#define CALIBRATE_CLASS_INTERVAL_MIN 19

/* theta <-> calibration.  calibrate_apply keeps the small-platform wiring
 * coefficient in the ratio `base` had and leaves base's accuracy out. */
void calibrate_theta(const struct model_calibration *cal, double theta[CAL_N_PARAMS]);
void calibrate_apply(const double theta[CAL_N_PARAMS], const struct model_calibration *base,
                     struct model_calibration *out);

/* One aircraft of a fit: the mission the validation rule built for it and
 * what is known of it. */
struct calibrate_row {
	struct mission_spec spec;      /* battery sized from the endurance */
	struct mission_spec pack_spec; /* the published pack locked, where given
	                                * (else the same as spec) */
	double actual_kg;        /* real takeoff mass */
	double battery_kg;       /* real battery mass, 0 when unknown */
};

/* The real dry mass of a row (takeoff - payload - battery), 0 when the
 * battery mass is unknown or leaves nothing. */
double calibrate_dry_kg(const struct calibrate_row *row);

/* Leave-one-out outcome of one row, for each battery basis
 * (enum model_basis: spec, pack_spec). */
struct calibrate_loo {
	bool sized[MODEL_BASIS_MAX];             /* the closed loop converged */
	double predicted_kg[MODEL_BASIS_MAX];    /* takeoff mass, the row left out */
	double battery_pred_kg[MODEL_BASIS_MAX]; /* its battery */
};

struct calibrate_result {
	struct model_calibration before;  /* the starting calibration */
	struct model_calibration after;   /* the fit, with its accuracy when measured */
	double theta[CAL_N_PARAMS];       /* the fit as parameters */
	size_t n_rows;                    /* rows in the fit */
	size_t n_relaxed;                 /* rows left out: not a contraction at the
	                                   * role's default thrust target */
	size_t n_per_param[CAL_N_PARAMS]; /* rows informing each coefficient */
	double open_before_pct;           /* open-loop mean |closure error| at the */
	double open_after_pct;            /* priors and at the fit, % */
	double mtow_mape_pct;             /* closed loop, in sample, after (from
	                                   * the endurance) */
	size_t n_sized;                   /* rows the closed loop sized, after */
	int lsq_status;                   /* enum lsq_status of the full fit */
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

/* Fits on cohort c starting from the priors calibrate_prior (md->cal is
 * the "before" of the report and lends its wiring ratio) and,
 * when loo, measures the leave-one-out accuracy of both battery bases into
 * out->after.accuracy[].
 * Returns 0 with *out filled, -1 when no row of c yields a usable mission
 * (out->n_rows 0), -2 when the minimiser failed.  Release with
 * calibrate_result_free(). */
int calibrate_fit(const struct cohort *c, const struct model_data *md, bool loo,
                  const struct calibrate_progress *progress,
                  struct calibrate_result *out);

/* The open-loop fit alone on explicit rows, with Tikhonov weight mu: the
 * engine of calibrate_fit, for tests that build missions directly. */
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
