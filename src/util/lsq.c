/* lsq.c — Levenberg-Marquardt with a numerical Jacobian, Tikhonov prior
 * and clamped bounds (see lsq.h).  Marquardt's scaling: the damped normal
 * equations are (J'J + lambda diag(J'J)) delta = -J'r. */
#include "util/lsq.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/xalloc.h"

/* Damping limits: below LAMBDA_MIN the step is plain Gauss-Newton already;
 * above LAMBDA_MAX no step of any length lowers the cost, so the point is
 * a minimum to working precision. */
#define LAMBDA_MIN 1e-12
#define LAMBDA_MAX 1e16
/* Smallest magnitude the finite-difference step is scaled by, so a
 * parameter at 0 still gets a usable step. */
#define FD_SCALE_MIN 1e-3

void
lsq_options_default(struct lsq_options *opt)
{
	memset(opt, 0, sizeof *opt);
	opt->max_iter = 200;
	opt->epsrel_step = 1e-10;
	opt->epsrel_cost = 1e-14;
	opt->fd_step_rel = 1e-7;
	opt->lambda_init = 1e-3;
}

/* Everything one call needs, passed to the helpers instead of globals. */
struct work {
	lsq_residual_fn f;
	void *ctx;
	size_t m;                 /* callback residuals */
	size_t p;                 /* parameters */
	size_t n_res;             /* m, plus p when the prior is on */
	const struct lsq_options *opt;
	double sqrt_mu;           /* weight of the prior residuals */
};

static void
clamp(const struct work *w, double *theta)
{
	for (size_t j = 0; j < w->p; j++) {
		if (w->opt->theta_lo != NULL && theta[j] < w->opt->theta_lo[j])
			theta[j] = w->opt->theta_lo[j];
		if (w->opt->theta_hi != NULL && theta[j] > w->opt->theta_hi[j])
			theta[j] = w->opt->theta_hi[j];
	}
}

/* Residuals at theta into r[0..n_res) and their sum of squares into
 * *cost (and the data part into *cost_data).  -1 when the model is not
 * defined there. */
static int
evaluate(const struct work *w, const double *theta, double *r, double *cost,
         double *cost_data)
{
	if (w->f(theta, r, w->m, w->ctx) != 0)
		return -1;
	double sd = 0, sp = 0;
	for (size_t i = 0; i < w->m; i++) {
		if (!isfinite(r[i]))
			return -1;
		sd += r[i] * r[i];
	}
	if (w->n_res > w->m) {
		for (size_t j = 0; j < w->p; j++) {
			if (!(theta[j] > 0))
				return -1;
			double e = w->sqrt_mu * (log(theta[j]) - log(w->opt->prior[j]));
			r[w->m + j] = e;
			sp += e * e;
		}
	}
	if (!isfinite(sd + sp))
		return -1;
	*cost = sd + sp;
	if (cost_data != NULL)
		*cost_data = sd;
	return 0;
}

/* Forward-difference Jacobian of the callback into J (n_res x p, row-major)
 * at theta with residuals r; the prior rows are exact.  tmp holds n_res
 * doubles.  -1 when the callback fails at a perturbed point. */
static int
jacobian(const struct work *w, const double *theta, const double *r,
         double *J, double *tmp)
{
	double t[LSQ_MAX_PARAMS];
	memcpy(t, theta, w->p * sizeof *t);
	for (size_t j = 0; j < w->p; j++) {
		double scale = fabs(theta[j]) > FD_SCALE_MIN ? fabs(theta[j]) : FD_SCALE_MIN;
		double h = w->opt->fd_step_rel * scale;
		/* Step backward where forward would cross the upper bound. */
		if (w->opt->theta_hi != NULL && theta[j] + h > w->opt->theta_hi[j])
			h = -h;
		t[j] = theta[j] + h;
		h = t[j] - theta[j]; /* the step actually representable */
		int rc = w->f(t, tmp, w->m, w->ctx);
		t[j] = theta[j];
		if (rc != 0)
			return -1;
		for (size_t i = 0; i < w->m; i++) {
			if (!isfinite(tmp[i]))
				return -1;
			J[i * w->p + j] = (tmp[i] - r[i]) / h;
		}
	}
	for (size_t k = w->m; k < w->n_res; k++)
		for (size_t j = 0; j < w->p; j++)
			J[k * w->p + j] = (k - w->m == j) ? w->sqrt_mu / theta[j] : 0.0;
	return 0;
}

/* Solves (A + lambda D) x = b for symmetric A (p x p) by Cholesky, with
 * D = diag(A) (1 where that is 0).  -1 if the damped matrix is not
 * positive definite to working precision (the caller raises lambda). */
static int
solve_damped(size_t p, const double *A, const double *b, double lambda, double *x)
{
	double L[LSQ_MAX_PARAMS * LSQ_MAX_PARAMS];
	for (size_t i = 0; i < p; i++) {
		for (size_t j = 0; j <= i; j++) {
			double s = A[i * p + j];
			if (i == j)
				s += lambda * (A[i * p + i] > 0 ? A[i * p + i] : 1.0);
			for (size_t k = 0; k < j; k++)
				s -= L[i * p + k] * L[j * p + k];
			if (i == j) {
				if (!(s > 0))
					return -1;
				L[i * p + i] = sqrt(s);
			} else {
				L[i * p + j] = s / L[j * p + j];
			}
		}
	}
	double y[LSQ_MAX_PARAMS];
	for (size_t i = 0; i < p; i++) {
		double s = b[i];
		for (size_t k = 0; k < i; k++)
			s -= L[i * p + k] * y[k];
		y[i] = s / L[i * p + i];
	}
	for (size_t i = p; i-- > 0; ) {
		double s = y[i];
		for (size_t k = i + 1; k < p; k++)
			s -= L[k * p + i] * x[k];
		x[i] = s / L[i * p + i];
	}
	return 0;
}

static int
options_ok(size_t m, size_t p, const double *theta, const struct lsq_options *o)
{
	if (p < 1 || p > LSQ_MAX_PARAMS || m < 1 || o->max_iter < 1)
		return 0;
	if (!(o->fd_step_rel > 0) || !(o->lambda_init > 0) || !(o->mu >= 0) ||
	    !isfinite(o->mu) || !(o->epsrel_step >= 0) || !(o->epsrel_cost >= 0))
		return 0;
	for (size_t j = 0; j < p; j++) {
		if (!isfinite(theta[j]))
			return 0;
		if (o->theta_lo != NULL && o->theta_hi != NULL && !(o->theta_lo[j] <= o->theta_hi[j]))
			return 0;
		if (o->mu > 0 && (o->prior == NULL || !(o->prior[j] > 0) || !isfinite(o->prior[j])))
			return 0;
	}
	return 1;
}

int
lsq_minimize(lsq_residual_fn f, void *ctx, size_t m, size_t p,
             double *theta, const struct lsq_options *opt,
             struct lsq_result *res)
{
	struct lsq_result dummy;
	if (res == NULL)
		res = &dummy;
	memset(res, 0, sizeof *res);
	if (f == NULL || opt == NULL || !options_ok(m, p, theta, opt))
		return LSQ_EINVAL;

	struct work w = { f, ctx, m, p, m, opt, sqrt(opt->mu) };
	if (opt->mu > 0)
		w.n_res = m + p;

	double th[LSQ_MAX_PARAMS], tt[LSQ_MAX_PARAMS];
	memcpy(th, theta, p * sizeof *th);
	clamp(&w, th);
	if (opt->mu > 0)
		for (size_t j = 0; j < p; j++)
			if (!(th[j] > 0))
				return LSQ_EINVAL;

	/* One block: r, trial r, J, scratch. */
	double *r = xmalloc(w.n_res * (p + 3) * sizeof *r);
	double *rt = r + w.n_res;
	double *tmp = rt + w.n_res;
	double *J = tmp + w.n_res;
	double cost, cost_data, cost_t, cost_data_t;
	int status = LSQ_MAXITER;

	if (evaluate(&w, th, r, &cost, &cost_data) < 0) {
		status = LSQ_EBADFUNC;
		goto out;
	}
	res->cost_initial = cost;
	double lambda = opt->lambda_init;

	while (res->n_iter < opt->max_iter && status == LSQ_MAXITER) {
		if (cost == 0) { /* an exact fit: nothing left to lower */
			status = LSQ_OK;
			break;
		}
		if (jacobian(&w, th, r, J, tmp) < 0) {
			status = LSQ_EBADFUNC;
			break;
		}
		res->n_iter++;
		double A[LSQ_MAX_PARAMS * LSQ_MAX_PARAMS], g[LSQ_MAX_PARAMS], d[LSQ_MAX_PARAMS];
		for (size_t a = 0; a < p; a++) {
			g[a] = 0;
			for (size_t i = 0; i < w.n_res; i++)
				g[a] -= J[i * p + a] * r[i];
			for (size_t b = 0; b <= a; b++) {
				double s = 0;
				for (size_t i = 0; i < w.n_res; i++)
					s += J[i * p + a] * J[i * p + b];
				A[a * p + b] = A[b * p + a] = s;
			}
		}
		/* A parameter held at a bound by the descent direction is frozen
		 * for this step (its row and column become the identity), so
		 * the others get a true Gauss-Newton step instead of one bent
		 * by clamping afterwards. */
		for (size_t j = 0; j < p; j++) {
			int at_hi = opt->theta_hi != NULL && th[j] >= opt->theta_hi[j] && g[j] > 0;
			int at_lo = opt->theta_lo != NULL && th[j] <= opt->theta_lo[j] && g[j] < 0;
			if (!at_hi && !at_lo)
				continue;
			for (size_t b = 0; b < p; b++)
				A[j * p + b] = A[b * p + j] = 0;
			A[j * p + j] = 1;
			g[j] = 0;
		}
		/* Raise the damping until a step lowers the cost. */
		for (;;) {
			if (lambda > LAMBDA_MAX) {
				status = LSQ_OK; /* no descent left: a minimum */
				break;
			}
			if (solve_damped(p, A, g, lambda, d) < 0) {
				lambda *= 10;
				continue;
			}
			double step2 = 0, norm2 = 0;
			for (size_t j = 0; j < p; j++)
				tt[j] = th[j] + d[j];
			clamp(&w, tt);
			for (size_t j = 0; j < p; j++) {
				step2 += (tt[j] - th[j]) * (tt[j] - th[j]);
				norm2 += th[j] * th[j];
			}
			if (evaluate(&w, tt, rt, &cost_t, &cost_data_t) < 0 || !(cost_t < cost)) {
				/* A step too small to move theta cannot improve. */
				if (sqrt(step2) <= opt->epsrel_step * (sqrt(norm2) + opt->epsrel_step)) {
					status = LSQ_OK;
					break;
				}
				lambda *= 10;
				continue;
			}
			int small_step = sqrt(step2) <= opt->epsrel_step * (sqrt(norm2) + opt->epsrel_step);
			int small_gain = cost - cost_t <= opt->epsrel_cost * cost;
			memcpy(th, tt, p * sizeof *th);
			memcpy(r, rt, w.n_res * sizeof *r);
			cost = cost_t;
			cost_data = cost_data_t;
			lambda = lambda / 10 > LAMBDA_MIN ? lambda / 10 : LAMBDA_MIN;
			if (small_step || small_gain)
				status = LSQ_OK;
			break;
		}
	}
	memcpy(theta, th, p * sizeof *th);
	res->cost_final = cost;
	res->cost_data_final = cost_data;
	res->converged = status == LSQ_OK;
out:
	free(r);
	return status;
}
