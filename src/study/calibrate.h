/* calibrate.h — fit the paper's three calibrated coefficient groups to a
 * cohort (paper §VII-A): the per-class structural multiplier λ (five
 * values), the battery packaging base and the wiring coefficient.
 *
 * Seven parameters theta (enum calibrate_param).  The wiring parameter is
 * C_wire of ordinary platforms; the racing/small-platform C_wire moves with
 * it (their ratio in the starting calibration is kept).  The fit minimises
 *	sum_rows ln(pred_i / actual_i)^2 + mu sum_j ln(theta_j / prior_j)^2
 * (lsq.h) over the rows the validation rule (validate.h) turns into
 * missions that converge at the starting coefficients.  Every residual
 * evaluation re-solves every row with the trial coefficients.  A trial
 * point where a row stops converging is rejected.  A class absent from the
 * cohort has no data residual and so stays at its prior.
 *
 * Engine layer (no printing, no JSON).  Reentrant.
 */
#ifndef AEROEVAL_CALIBRATE_H
#define AEROEVAL_CALIBRATE_H

#include <stddef.h>

#include "input/cohort.h"
#include "core/model.h"

enum calibrate_param {
	CAL_LAMBDA_MICRO,        /* λ MicroAIO */
	CAL_LAMBDA_CONSUMER,     /* λ ConsumerFolding */
	CAL_LAMBDA_ENT_QUAD,     /* λ EnterpriseRugged quad */
	CAL_LAMBDA_ENT_MULTI,    /* λ EnterpriseRugged hex/octo */
	CAL_LAMBDA_AGRI,         /* λ Agricultural */
	CAL_PACKAGING_BASE,      /* LiPo packaging base */
	CAL_WIRE_COEF,           /* C_wire, kg/(A m) */
	CAL_N_PARAMS
};

/* Name of a parameter ("lambda MicroAIO", ...). */
const char *calibrate_param_name(enum calibrate_param p);

/* The paper's values (priors and the default start), the bounds. */
extern const double calibrate_prior[CAL_N_PARAMS];
extern const double calibrate_lo[CAL_N_PARAMS];
extern const double calibrate_hi[CAL_N_PARAMS];

/* A coefficient informed by fewer rows keeps its prior: one aircraft
 * cannot tell a class's structural multiplier from its own quirks. */
#define CALIBRATE_MIN_ROWS 3
#define CALIBRATE_MU 0.1  /* Tikhonov weight: mild (a 10 % move costs about
                             as much as a 3 % error on one row) */

/* theta <-> calibration.  calibrate_apply keeps the small-platform wiring
 * coefficient in the ratio `base` had; base supplies that ratio. */
void calibrate_theta(const struct model_calibration *cal, double theta[CAL_N_PARAMS]);
void calibrate_apply(const double theta[CAL_N_PARAMS], const struct model_calibration *base,
                     struct model_calibration *out);

struct calibrate_result {
	struct model_calibration before;  /* md->cal */
	struct model_calibration after;   /* the fit */
	double theta[CAL_N_PARAMS];       /* the fit as parameters */
	size_t n_rows;                    /* rows in the fit */
	size_t n_per_param[CAL_N_PARAMS]; /* rows informing each λ (0 for base, wire: all) */
	double mape_before_pct;           /* over the fitted rows */
	double mape_after_pct;
	int lsq_status;                   /* enum lsq_status */
	size_t n_iter;
	size_t n_solves;                  /* engine solves spent */
};

/* Progress of a fit, for a command that shows it (a large cohort takes
 * minutes: every step of the minimiser re-solves every row).  fn is called
 * after each solve with the pass over the rows it belongs to (0: the first
 * pass that picks the rows that converge), the row within the pass, the
 * rows in the pass and the solves so far.  This layer prints nothing: the
 * command decides how often to show it. */
struct calibrate_progress {
	void (*fn)(void *ctx, size_t pass, size_t row, size_t n_rows, size_t n_solves);
	void *ctx;
};

/* Fits on cohort c starting from md->cal, with priors calibrate_prior,
 * reporting progress through progress (may be NULL).  Returns 0 with *out
 * filled, -1 when no row of c yields a converged mission (out->n_rows 0),
 * -2 when the minimiser failed (bad start). */
int calibrate_fit(const struct cohort *c, const struct model_data *md,
                  const struct calibrate_progress *progress,
                  struct calibrate_result *out);

/* The fit on explicit missions (the rows validate_mission_from_row built)
 * and their actual masses, with Tikhonov weight mu (calibrate_fit uses
 * CALIBRATE_MU); the engine of calibrate_fit, exposed for tests that build
 * missions directly.  Starts from md->cal.  Rows whose mission does not
 * converge at the start are left out (n_rows counts the rest). */
int calibrate_fit_missions(const struct mission_spec *specs, const double *actual_kg,
                           size_t n, const struct model_data *md, double mu,
                           struct calibrate_result *out);

#endif
