/* calibrate.c — least-squares fit of λ per class, packaging base and wiring
 * coefficient on log error (see calibrate.h). */
#include "study/calibrate.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/engine.h"
#include "util/lsq.h"
#include "util/stats.h"
#include "study/validate.h"
#include "util/xalloc.h"

/* Paper eq. (lambda), §V-B packaging base, §V-C C_wire. */
const double calibrate_prior[CAL_N_PARAMS] = { 1.50, 1.08, 0.95, 0.80, 1.00, 1.04, 0.0015 };
const double calibrate_lo[CAL_N_PARAMS] = { 0.5, 0.5, 0.5, 0.5, 0.5, 1.0, 0.0005 };
const double calibrate_hi[CAL_N_PARAMS] = { 5.0, 5.0, 5.0, 5.0, 5.0, 1.3, 0.005 };

static const char *const param_name[CAL_N_PARAMS] = {
	"lambda MicroAIO", "lambda ConsumerFolding", "lambda EnterpriseRugged quad",
	"lambda EnterpriseRugged hex/octo", "lambda Agricultural",
	"battery packaging base", "wiring coefficient (kg/(A m))",
};

const char *
calibrate_param_name(enum calibrate_param p)
{
	return (unsigned)p < CAL_N_PARAMS ? param_name[p] : "";
}

void
calibrate_theta(const struct model_calibration *cal, double theta[CAL_N_PARAMS])
{
	theta[CAL_LAMBDA_MICRO] = cal->lambda[LAMBDA_MICRO];
	theta[CAL_LAMBDA_CONSUMER] = cal->lambda[LAMBDA_CONSUMER];
	theta[CAL_LAMBDA_ENT_QUAD] = cal->lambda[LAMBDA_ENTERPRISE_QUAD];
	theta[CAL_LAMBDA_ENT_MULTI] = cal->lambda[LAMBDA_ENTERPRISE_MULTI];
	theta[CAL_LAMBDA_AGRI] = cal->lambda[LAMBDA_AGRI];
	theta[CAL_PACKAGING_BASE] = cal->packaging_base;
	theta[CAL_WIRE_COEF] = cal->wire_coef;
}

void
calibrate_apply(const double theta[CAL_N_PARAMS], const struct model_calibration *base,
                struct model_calibration *out)
{
	double ratio = base->wire_coef > 0.0 ? base->wire_coef_small / base->wire_coef : 0.2;
	out->lambda[LAMBDA_MICRO] = theta[CAL_LAMBDA_MICRO];
	out->lambda[LAMBDA_CONSUMER] = theta[CAL_LAMBDA_CONSUMER];
	out->lambda[LAMBDA_ENTERPRISE_QUAD] = theta[CAL_LAMBDA_ENT_QUAD];
	out->lambda[LAMBDA_ENTERPRISE_MULTI] = theta[CAL_LAMBDA_ENT_MULTI];
	out->lambda[LAMBDA_AGRI] = theta[CAL_LAMBDA_AGRI];
	out->packaging_base = theta[CAL_PACKAGING_BASE];
	out->wire_coef = theta[CAL_WIRE_COEF];
	out->wire_coef_small = ratio * theta[CAL_WIRE_COEF];
}

/* What the residual callback needs: the missions, a private copy of the
 * tables whose calibration it rewrites, and one scratch result. */
struct fit_ctx {
	const struct mission_spec *specs;
	const double *actual_kg;
	size_t n;
	struct model_data md;          /* copy; .cal rewritten per evaluation */
	struct model_calibration base; /* starting calibration */
	struct solve_result *work;
	size_t n_solves;
	double full[CAL_N_PARAMS];     /* every coefficient; held ones fixed */
	int free_idx[CAL_N_PARAMS];    /* the fitted ones' places in full[] */
	size_t n_free;
	const struct calibrate_progress *progress; /* may be NULL */
	size_t pass;                   /* passes over the rows so far */
};

/* One solve done: row i of a pass over n rows. */
static void
tick(struct fit_ctx *cx, size_t i, size_t n)
{
	cx->n_solves++;
	if (cx->progress != NULL && cx->progress->fn != NULL)
		cx->progress->fn(cx->progress->ctx, cx->pass, i + 1, n, cx->n_solves);
}

/* The whole coefficient vector from the fitted subset. */
static void
expand(struct fit_ctx *cx, const double *theta_free, double *theta)
{
	memcpy(theta, cx->full, sizeof cx->full);
	for (size_t j = 0; j < cx->n_free; j++)
		theta[cx->free_idx[j]] = theta_free[j];
}

/* Predicts every row at theta into pred[]; -1 if a row fails to converge. */
static int
predict_all(struct fit_ctx *cx, const double *theta, double *pred)
{
	calibrate_apply(theta, &cx->base, &cx->md.cal);
	cx->pass++;
	for (size_t i = 0; i < cx->n; i++) {
		struct validate_row vr;
		memset(&vr, 0, sizeof vr);
		validate_solve_row(&cx->specs[i], &cx->md, cx->work, &vr);
		tick(cx, i, cx->n);
		if (vr.status != VALIDATE_ROW_OK)
			return -1;
		pred[i] = vr.predicted_kg;
	}
	return 0;
}

static int
residuals(const double *theta_free, double *r, size_t m, void *ctx)
{
	struct fit_ctx *cx = ctx;
	double theta[CAL_N_PARAMS];
	expand(cx, theta_free, theta);
	if (predict_all(cx, theta, r) != 0)
		return 1;
	for (size_t i = 0; i < m; i++)
		r[i] = log(r[i] / cx->actual_kg[i]);
	return 0;
}

static double
mape_of(const double *actual, const double *pred, size_t n)
{
	struct stats_summary s;
	return stats_summarize(actual, pred, n, &s) == 0 ? s.mape_pct : 0.0;
}

static int
fit_missions(const struct mission_spec *specs, const double *actual_kg, size_t n,
             const struct model_data *md, double mu,
             const struct calibrate_progress *progress, struct calibrate_result *out)
{
	memset(out, 0, sizeof *out);
	out->before = md->cal;
	out->after = md->cal;
	calibrate_theta(&md->cal, out->theta);

	struct fit_ctx *cx = xcalloc(1, sizeof *cx);
	cx->progress = progress;
	cx->md = *md;
	cx->base = md->cal;
	cx->work = xmalloc(sizeof *cx->work);
	size_t cap = n ? n : 1;
	struct mission_spec *keep = xmalloc(cap * sizeof *keep);
	double *act = xmalloc(cap * sizeof *act);
	double *pred = xmalloc(cap * sizeof *pred);

	/* Keep the rows that converge at the start: the fit needs a fixed set
	 * of residuals, and a row that cannot be sized says nothing about the
	 * coefficients. */
	size_t m = 0;
	for (size_t i = 0; i < n; i++) {
		struct validate_row vr;
		memset(&vr, 0, sizeof vr);
		validate_solve_row(&specs[i], &cx->md, cx->work, &vr);
		tick(cx, i, n);
		if (vr.status != VALIDATE_ROW_OK)
			continue;
		keep[m] = specs[i];
		act[m] = actual_kg[i];
		m++;
		enum model_lambda li = model_lambda_index(specs[i].airframe_class,
		    specs[i].num_rotors);
		out->n_per_param[li]++;
	}
	out->n_per_param[CAL_PACKAGING_BASE] = m;
	out->n_per_param[CAL_WIRE_COEF] = m;
	out->n_rows = m;
	int rc = 0;
	if (m == 0) {
		rc = -1;
		goto done;
	}
	cx->specs = keep;
	cx->actual_kg = act;
	cx->n = m;

	double theta[CAL_N_PARAMS];
	calibrate_theta(&md->cal, theta);
	if (predict_all(cx, theta, pred) == 0)
		out->mape_before_pct = mape_of(act, pred, m);

	/* Fit only what enough rows inform; the rest stays where it is. */
	double th_free[CAL_N_PARAMS], prior[CAL_N_PARAMS], lo[CAL_N_PARAMS], hi[CAL_N_PARAMS];
	memcpy(cx->full, theta, sizeof theta);
	for (int j = 0; j < CAL_N_PARAMS; j++) {
		if (out->n_per_param[j] < CALIBRATE_MIN_ROWS)
			continue;
		size_t k = cx->n_free++;
		cx->free_idx[k] = j;
		th_free[k] = theta[j];
		prior[k] = calibrate_prior[j];
		lo[k] = calibrate_lo[j];
		hi[k] = calibrate_hi[j];
	}
	if (cx->n_free == 0) {
		out->mape_after_pct = out->mape_before_pct;
		goto done;
	}

	struct lsq_options opt;
	lsq_options_default(&opt);
	opt.mu = mu;
	opt.prior = prior;
	opt.theta_lo = lo;
	opt.theta_hi = hi;
	opt.max_iter = 60;
	/* The mass loop stops at a 1 g step, so the prediction jumps by about
	 * 1e-5 of itself where the iteration count changes; a 0.1 % step moves
	 * ln(MTOW) by 1e-4 or more for every coefficient, well above that. */
	opt.fd_step_rel = 1e-3;
	opt.epsrel_cost = 1e-8;
	opt.epsrel_step = 1e-6;
	struct lsq_result lr;
	int st = lsq_minimize(residuals, cx, m, cx->n_free, th_free, &opt, &lr);
	out->lsq_status = st;
	out->n_iter = lr.n_iter;
	if (st != LSQ_OK && st != LSQ_MAXITER && st != LSQ_EBADFUNC) {
		rc = -2;
		goto done;
	}
	if (st == LSQ_EBADFUNC && lr.n_iter == 0) {
		rc = -2;
		goto done;
	}
	expand(cx, th_free, theta);
	memcpy(out->theta, theta, sizeof theta);
	calibrate_apply(theta, &md->cal, &out->after);
	if (predict_all(cx, theta, pred) == 0)
		out->mape_after_pct = mape_of(act, pred, m);
done:
	out->n_solves = cx->n_solves;
	free(keep);
	free(act);
	free(pred);
	free(cx->work);
	free(cx);
	return rc;
}

int
calibrate_fit_missions(const struct mission_spec *specs, const double *actual_kg,
                       size_t n, const struct model_data *md, double mu,
                       struct calibrate_result *out)
{
	return fit_missions(specs, actual_kg, n, md, mu, NULL, out);
}

int
calibrate_fit(const struct cohort *c, const struct model_data *md,
              const struct calibrate_progress *progress, struct calibrate_result *out)
{
	size_t cap = c->n_rows ? c->n_rows : 1;
	struct mission_spec *specs = xmalloc(cap * sizeof *specs);
	double *act = xmalloc(cap * sizeof *act);
	size_t n = 0;
	for (size_t i = 0; i < c->n_rows; i++) {
		unsigned notes;
		if (validate_mission_from_row(&c->rows[i], md, &specs[n], &notes)
		    != VALIDATE_SKIP_NONE)
			continue;
		act[n++] = c->rows[i].takeoff_mass_kg;
	}
	int rc = fit_missions(specs, act, n, md, CALIBRATE_MU, progress, out);
	free(specs);
	free(act);
	return rc;
}
