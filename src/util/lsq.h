/* lsq.h — a small Levenberg-Marquardt least-squares minimiser.
 *
 * For `calibrate`, which fits a handful of model coefficients (at most
 * LSQ_MAX_PARAMS) to a cohort.  It minimises
 *	cost(theta) = sum_i r_i(theta)^2 + mu sum_j (log theta_j - log prior_j)^2
 * where the r_i come from a user callback, the second (Tikhonov) term pulls
 * the fit toward a prior and is added as p extra residuals
 * sqrt(mu) (log theta_j - log prior_j).  The Jacobian of the callback is
 * taken by forward differences with a relative step; the prior term's is
 * exact.  Bounds are enforced by clamping every trial point.  Note the cost
 * has no factor 1/2.
 *
 * No mutable state outside the call; the workspace (m + p) * (p + 3)
 * doubles is allocated once per call with xmalloc and freed before return.
 */
#ifndef AEROEVAL_LSQ_H
#define AEROEVAL_LSQ_H

#include <stddef.h>

#define LSQ_MAX_PARAMS 16

/* Fills r[0..m) with the residuals at theta (model minus data, any sign
 * convention).  Returns 0 on success; non-zero means "the model is not
 * defined here" (a trial step there is rejected; at the starting point it
 * is an error).  Non-finite residuals are treated like a non-zero return. */
typedef int (*lsq_residual_fn)(const double *theta, double *r, size_t m, void *ctx);

struct lsq_options {
	size_t max_iter;        /* Jacobian evaluations allowed, >= 1 */
	double epsrel_step;     /* stop when |dtheta| <= epsrel_step (|theta| + epsrel_step) */
	double epsrel_cost;     /* stop when an accepted step lowers cost by <= epsrel_cost * cost */
	double fd_step_rel;     /* difference step h_j = fd_step_rel * max(|theta_j|, 1e-3), > 0 */
	double lambda_init;     /* initial Marquardt damping, > 0 */
	double mu;              /* Tikhonov weight, >= 0; 0 switches the prior off */
	const double *prior;    /* p values > 0; required when mu > 0, else ignored */
	const double *theta_lo; /* p lower bounds, or NULL for none */
	const double *theta_hi; /* p upper bounds, or NULL for none */
};

struct lsq_result {
	double cost_initial;    /* total cost at the (clamped) starting point */
	double cost_final;      /* total cost at the returned theta */
	double cost_data_final; /* sum r_i^2 alone at the returned theta */
	size_t n_iter;          /* Jacobian evaluations made */
	int converged;          /* 1 if a stopping test was met */
};

enum lsq_status {
	LSQ_OK = 0,        /* converged */
	LSQ_MAXITER = 1,   /* max_iter reached; theta is the best point found */
	LSQ_EINVAL = -1,   /* bad arguments; theta untouched */
	LSQ_EBADFUNC = -2  /* the callback failed at the starting point (theta
	                      untouched) or while differencing around an accepted
	                      point (theta = that point) */
};

/* Sensible defaults: max_iter 200, epsrel_step 1e-10, epsrel_cost 1e-14,
 * fd_step_rel 1e-7 (about sqrt of the double epsilon), lambda_init 1e-3,
 * mu 0, no prior, no bounds. */
void lsq_options_default(struct lsq_options *opt);

/* Minimises the cost above over theta[0..p), 1 <= p <= LSQ_MAX_PARAMS,
 * starting from theta (clamped into the bounds) and overwriting it with the
 * best point found.  m >= 1 residuals.  With mu > 0 every theta_j must stay
 * > 0 (the log): a start <= 0 is LSQ_EINVAL and trial points <= 0 are
 * rejected.  res (may be NULL) receives costs and the iteration count.
 * Returns an enum lsq_status; LSQ_OK and LSQ_MAXITER leave a usable theta. */
int lsq_minimize(lsq_residual_fn f, void *ctx, size_t m, size_t p,
                 double *theta, const struct lsq_options *opt,
                 struct lsq_result *res);

#endif
