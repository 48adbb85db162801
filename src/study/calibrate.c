/* calibrate.c — open-loop fit of the calibrated coefficients and their
 * leave-one-out accuracy (see calibrate.h). */
#include "study/calibrate.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/engine.h"
#include "util/lsq.h"
#include "study/validate.h"
#include "util/xalloc.h"

/* Priors: λ paper eq. (lambda), C_wire paper §V-C, κ paper Table classes;
 * the equipment law a quarter of a 1 kg aircraft.  Held (lo == hi): λ,
 * which the equipment law would otherwise trade against class by class,
 * and the equipment exponent 2/3, the surface law of shells, gear and
 * mounts: the fit, free, puts it near 1, where an endurance-sized loop
 * without payload loses its contraction (the equipment fraction no longer
 * falls with size) and a racer runs away (docs/model.md).  κ may go to
 * 2.5: the cohort puts it near 1.6 for every class (hover efficiency
 * below the paper's, the losses η_drive leaves out). */
const double calibrate_prior[CAL_N_PARAMS] = {
	1.50, 1.08, 0.95, 0.80, 1.00,
	0.25, 0.25, 0.25, 0.25, 2.0 / 3.0,
	0.0015,
	1.30, 1.20, 1.25, 1.46,
};
const double calibrate_lo[CAL_N_PARAMS] = {
	1.50, 1.08, 0.95, 0.80, 1.00,
	0.01, 0.01, 0.01, 0.01, 2.0 / 3.0,
	0.0005,
	1.0, 1.0, 1.0, 1.0,
};
const double calibrate_hi[CAL_N_PARAMS] = {
	1.50, 1.08, 0.95, 0.80, 1.00,
	1.0, 1.0, 1.0, 1.0, 2.0 / 3.0,
	0.005,
	2.5, 2.5, 2.5, 2.5,
};

static const char *const param_name[CAL_N_PARAMS] = {
	"lambda MicroAIO", "lambda ConsumerFolding", "lambda EnterpriseRugged quad",
	"lambda EnterpriseRugged hex/octo", "lambda Agricultural",
	"equipment MicroAIO (kg at 1 kg)", "equipment ConsumerFolding (kg at 1 kg)",
	"equipment EnterpriseRugged (kg at 1 kg)", "equipment Agricultural (kg at 1 kg)",
	"equipment exponent", "wiring coefficient (kg/(A m))",
	"kappa MicroAIO", "kappa ConsumerFolding", "kappa EnterpriseRugged",
	"kappa Agricultural",
};

/* The per-class parameters, in enum airframe_class order. */
static const int equip_param[AF_CLASS_MAX] = {
	CAL_EQUIP_MICRO, CAL_EQUIP_CONSUMER, CAL_EQUIP_ENTERPRISE, CAL_EQUIP_AGRI,
};
static const int kappa_param[AF_CLASS_MAX] = {
	CAL_KAPPA_MICRO, CAL_KAPPA_CONSUMER, CAL_KAPPA_ENTERPRISE, CAL_KAPPA_AGRI,
};

const char *
calibrate_param_name(enum calibrate_param p)
{
	return (unsigned)p < CAL_N_PARAMS ? param_name[p] : "";
}

void
calibrate_theta(const struct model_calibration *cal, double theta[CAL_N_PARAMS])
{
	for (int k = 0; k < LAMBDA_MAX; k++)
		theta[CAL_LAMBDA_MICRO + k] = cal->lambda[k];
	for (int k = 0; k < AF_CLASS_MAX; k++) {
		theta[equip_param[k]] = cal->equip_kg[k];
		theta[kappa_param[k]] = cal->kappa[k];
	}
	theta[CAL_EQUIP_EXPONENT] = cal->equip_exponent;
	theta[CAL_WIRE_COEF] = cal->wire_coef;
}

void
calibrate_apply(const double theta[CAL_N_PARAMS], const struct model_calibration *base,
                struct model_calibration *out)
{
	double ratio = base->wire_coef > 0.0 ? base->wire_coef_small / base->wire_coef : 0.2;
	memset(out, 0, sizeof *out);
	for (int k = 0; k < LAMBDA_MAX; k++)
		out->lambda[k] = theta[CAL_LAMBDA_MICRO + k];
	for (int k = 0; k < AF_CLASS_MAX; k++) {
		out->equip_kg[k] = theta[equip_param[k]];
		out->kappa[k] = theta[kappa_param[k]];
	}
	out->equip_exponent = theta[CAL_EQUIP_EXPONENT];
	out->wire_coef = theta[CAL_WIRE_COEF];
	out->wire_coef_small = ratio * theta[CAL_WIRE_COEF];
}

double
calibrate_dry_kg(const struct calibrate_row *row)
{
	if (!(row->battery_kg > 0.0))
		return 0.0;
	double dry = row->actual_kg - row->spec.payload_kg - row->battery_kg;
	return dry > 0.0 ? dry : 0.0;
}

/* What the residual callback needs: the rows in the fit, a private copy of
 * the tables whose calibration it rewrites, and the fitted subset. */
struct fit_ctx {
	const struct calibrate_row *rows;
	const size_t *use;             /* indices of the rows in the fit */
	size_t n;
	struct model_data md;          /* copy; .cal rewritten per evaluation */
	struct model_calibration base; /* starting calibration */
	double full[CAL_N_PARAMS];     /* every coefficient; held ones fixed */
	int free_idx[CAL_N_PARAMS];    /* the fitted ones' places in full[] */
	size_t n_free;
	size_t n_evals;
	const struct calibrate_progress *progress;
	size_t stage;
	size_t n_solves;
	double *prop_frac;             /* per row: its unlocked propeller's share
	                                  of the overlap limit, held through a
	                                  minimisation (0: chosen at the next
	                                  evaluation, engine_at_mass()) */
};

static void
expand(const struct fit_ctx *cx, const double *theta_free, double *theta)
{
	memcpy(theta, cx->full, sizeof cx->full);
	for (size_t j = 0; j < cx->n_free; j++)
		theta[cx->free_idx[j]] = theta_free[j];
}

/* Open-loop residuals of a row at the tables' current calibration: the
 * closure ln(f(M) / M) at its real mass M into r[0], and where its battery
 * mass is known the dry-mass and battery errors into r[1], r[2]; returns
 * how many (0 when the model cannot fly the mission at M). */
static int
open_residuals(struct fit_ctx *cx, size_t idx, double r[3])
{
	const struct calibrate_row *row = &cx->rows[idx];
	struct sizing_open o;
	cx->n_evals++;
	bool flown = engine_at_mass(&row->spec, &cx->md, row->actual_kg,
	    cx->prop_frac[idx], &o);
	cx->prop_frac[idx] = o.prop_frac;
	if (!flown || !(o.mass.total_kg > 0.0))
		return 0;
	r[0] = log(o.mass.total_kg / row->actual_kg);
	double dry = calibrate_dry_kg(row);
	if (!(dry > 0.0 && o.dry_kg > 0.0 && o.mass.battery_kg > 0.0))
		return isfinite(r[0]) ? 1 : 0;
	r[1] = log(o.dry_kg / dry);
	r[2] = log(o.mass.battery_kg / row->battery_kg);
	return isfinite(r[0]) && isfinite(r[1]) && isfinite(r[2]) ? 3 : 0;
}

/* Residuals a row contributes (open_residuals() at the start). */
static size_t
n_residuals(const struct calibrate_row *row)
{
	return calibrate_dry_kg(row) > 0.0 ? 3 : 1;
}

static int
residuals(const double *theta_free, double *r, size_t m, void *ctx)
{
	struct fit_ctx *cx = ctx;
	double theta[CAL_N_PARAMS];
	expand(cx, theta_free, theta);
	calibrate_apply(theta, &cx->base, &cx->md.cal);
	size_t k = 0;
	for (size_t i = 0; i < cx->n; i++) {
		const struct calibrate_row *row = &cx->rows[cx->use[i]];
		double ri[3];
		int got = open_residuals(cx, cx->use[i], ri);
		if (got == 0 || (size_t)got != n_residuals(row) || k + (size_t)got > m)
			return 1;
		for (int j = 0; j < got; j++)
			r[k++] = ri[j];
	}
	if (cx->progress != NULL && cx->progress->fn != NULL)
		cx->progress->fn(cx->progress->ctx, cx->stage, 0, cx->n, cx->n_solves);
	return k == m ? 0 : 1;
}

/* Mean |e^r - 1| of the closures ln(f(M) / M) at theta, %: how far the
 * real mass is from being a fixed point of the model. */
static double
open_error_pct(struct fit_ctx *cx, const double *theta)
{
	calibrate_apply(theta, &cx->base, &cx->md.cal);
	double sum = 0.0;
	size_t k = 0;
	for (size_t i = 0; i < cx->n; i++) {
		double r[3];
		if (open_residuals(cx, cx->use[i], r) > 0) {
			sum += fabs(expm1(r[0]));
			k++;
		}
	}
	return k ? 100.0 * sum / (double)k : 0.0;
}

/* The rows informing each coefficient: a class's λ and equipment its own
 * rows, the exponent and C_wire all of them. */
static void
count_rows(const struct calibrate_row *rows, const size_t *use, size_t n,
           size_t count[CAL_N_PARAMS])
{
	memset(count, 0, CAL_N_PARAMS * sizeof count[0]);
	for (size_t i = 0; i < n; i++) {
		const struct mission_spec *s = &rows[use[i]].spec;
		count[CAL_LAMBDA_MICRO + model_lambda_index(s->airframe_class, s->num_rotors)]++;
		count[equip_param[s->airframe_class]]++;
		count[kappa_param[s->airframe_class]]++;
	}
	count[CAL_EQUIP_EXPONENT] = n;
	count[CAL_WIRE_COEF] = n;
}

/* Minimise over the coefficients enough rows inform, from start; theta
 * gets the result.  Returns the lsq status. */
static int
minimise(struct fit_ctx *cx, const double *start, double mu, double *theta,
         size_t *n_iter)
{
	size_t count[CAL_N_PARAMS];
	count_rows(cx->rows, cx->use, cx->n, count);
	double th[CAL_N_PARAMS], prior[CAL_N_PARAMS], lo[CAL_N_PARAMS], hi[CAL_N_PARAMS];
	memcpy(cx->full, start, sizeof cx->full);
	cx->n_free = 0;
	for (int j = 0; j < CAL_N_PARAMS; j++) {
		if (count[j] < CALIBRATE_MIN_ROWS || calibrate_lo[j] == calibrate_hi[j])
			continue;
		size_t k = cx->n_free++;
		cx->free_idx[k] = j;
		th[k] = start[j];
		prior[k] = calibrate_prior[j];
		lo[k] = calibrate_lo[j];
		hi[k] = calibrate_hi[j];
	}
	memcpy(theta, start, CAL_N_PARAMS * sizeof theta[0]);
	*n_iter = 0;
	if (cx->n_free == 0)
		return LSQ_OK;
	struct lsq_options opt;
	lsq_options_default(&opt);
	opt.mu = mu;
	opt.prior = prior;
	opt.theta_lo = lo;
	opt.theta_hi = hi;
	opt.max_iter = 40;
	/* The open loop settles the capacity to 1e-4: a 0.1 % step moves
	 * every residual by more than that. */
	opt.fd_step_rel = 1e-3;
	opt.epsrel_cost = 1e-7;
	opt.epsrel_step = 1e-5;
	size_t m = 0;
	for (size_t i = 0; i < cx->n; i++)
		m += n_residuals(&cx->rows[cx->use[i]]);
	struct lsq_result lr;
	int st = lsq_minimize(residuals, cx, m, cx->n_free, th, &opt, &lr);
	*n_iter = lr.n_iter;
	if (st == LSQ_OK || st == LSQ_MAXITER || (st == LSQ_EBADFUNC && lr.n_iter > 0))
		expand(cx, th, theta);
	return st;
}

/* Size a mission by the full mass loop with calibration cal into *vr;
 * true when it converged (VALIDATE_ROW_OK). */
static bool
closed_loop(struct fit_ctx *cx, const struct mission_spec *spec,
            const struct model_calibration *cal, struct solve_result *work,
            struct validate_row *vr)
{
	cx->md.cal = *cal;
	memset(vr, 0, sizeof *vr);
	validate_solve_row(spec, &cx->md, work, vr);
	cx->n_solves++;
	return vr->status == VALIDATE_ROW_OK;
}

bool
calibrate_conformal(double *resid, size_t n, double level, double *lo, double *hi)
{
	/* The 1e-9 keeps an exact order (40 x 0.05 = 2) from rounding away. */
	double a = 1.0 - level;
	size_t k_lo = (size_t)floor((double)(n + 1) * a / 2.0 + 1e-9);
	size_t k_hi = (size_t)ceil((double)(n + 1) * (1.0 - a / 2.0) - 1e-9);
	if (n == 0 || k_lo < 1 || k_hi > n)
		return false;
	/* Insertion sort: a cohort is tens of rows. */
	for (size_t i = 1; i < n; i++)
		for (size_t j = i; j > 0 && resid[j] < resid[j - 1]; j--) {
			double t = resid[j];
			resid[j] = resid[j - 1];
			resid[j - 1] = t;
		}
	*lo = fmin(resid[k_lo - 1], 0.0);
	*hi = fmax(resid[k_hi - 1], 0.0);
	return true;
}

/* The accuracy figures, interval and coverage of one battery basis from
 * the leave-one-out predictions. */
static void
accuracy_of(const struct calibrate_row *rows, const size_t *use, size_t n,
            const struct calibrate_loo *loo, int b, struct model_accuracy *a)
{
	double *res = xmalloc((n ? n : 1) * sizeof *res);
	double *res_cls = xmalloc((n ? n : 1) * sizeof *res_cls);
	memset(a, 0, sizeof *a);
	double ape = 0.0, bape = 0.0;
	size_t k = 0;
	for (size_t i = 0; i < n; i++) {
		const struct calibrate_row *row = &rows[use[i]];
		if (!loo[i].sized[b] || !(loo[i].predicted_kg[b] > 0.0))
			continue;
		ape += fabs(loo[i].predicted_kg[b] / row->actual_kg - 1.0);
		res[k++] = log(row->actual_kg / loo[i].predicted_kg[b]);
		if (row->battery_kg > 0.0 && loo[i].battery_pred_kg[b] > 0.0) {
			bape += fabs(loo[i].battery_pred_kg[b] / row->battery_kg - 1.0);
			a->n_battery++;
		}
	}
	a->n_rows = (int)k;
	a->level = CALIBRATE_LEVEL;
	a->loo_mape_pct = k ? 100.0 * ape / (double)k : 0.0;
	a->loo_battery_mape_pct = a->n_battery ? 100.0 * bape / (double)a->n_battery : 0.0;
	a->valid = calibrate_conformal(res, k, CALIBRATE_LEVEL, &a->pooled.log_lo,
	    &a->pooled.log_hi);
	a->pooled.n = (int)k;
	for (int c = 0; c < AF_CLASS_MAX && a->valid; c++) {
		size_t kc = 0;
		for (size_t i = 0; i < n; i++) {
			const struct calibrate_row *row = &rows[use[i]];
			if (loo[i].sized[b] && loo[i].predicted_kg[b] > 0.0
			    && row->spec.airframe_class == c)
				res_cls[kc++] = log(row->actual_kg / loo[i].predicted_kg[b]);
		}
		struct model_interval *iv = &a->cls[c];
		if (kc >= CALIBRATE_CLASS_INTERVAL_MIN
		    && calibrate_conformal(res_cls, kc, CALIBRATE_LEVEL, &iv->log_lo, &iv->log_hi))
			iv->n = (int)kc;
	}
	/* Coverage, out of sample: does each row's error lie in the interval
	 * built from the other rows' errors (the same class rule)?  An
	 * interval judged on the residuals it was built from would cover them
	 * by construction. */
	size_t inside = 0, judged = 0;
	double *others = xmalloc((n ? n : 1) * sizeof *others);
	for (size_t i = 0; i < n && a->valid; i++) {
		const struct calibrate_row *row = &rows[use[i]];
		if (!loo[i].sized[b] || !(loo[i].predicted_kg[b] > 0.0))
			continue;
		int c = row->spec.airframe_class;
		bool own = a->cls[c].n > 0;
		size_t m = 0;
		for (size_t j = 0; j < n; j++) {
			const struct calibrate_row *o = &rows[use[j]];
			if (j == i || !loo[j].sized[b] || !(loo[j].predicted_kg[b] > 0.0)
			    || (own && o->spec.airframe_class != c))
				continue;
			others[m++] = log(o->actual_kg / loo[j].predicted_kg[b]);
		}
		double lo, hi;
		if (!calibrate_conformal(others, m, CALIBRATE_LEVEL, &lo, &hi))
			continue;
		double r = log(row->actual_kg / loo[i].predicted_kg[b]);
		inside += r >= lo && r <= hi;
		judged++;
	}
	free(others);
	k = judged;
	a->coverage = k ? (double)inside / (double)k : 0.0;
	free(res_cls);
	free(res);
}

/* Leave each row out in turn, refit on the rest and size it from its
 * endurance and around its published pack; the accuracy of each basis
 * into out->after.accuracy[]. */
static void
leave_one_out(struct fit_ctx *cx, const struct calibrate_row *rows, size_t n,
              const size_t *use, double mu, struct calibrate_result *out)
{
	struct solve_result *work = xmalloc(sizeof *work);
	size_t *rest = xmalloc((n ? n : 1) * sizeof *rest);
	out->loo = xcalloc(n ? n : 1, sizeof *out->loo);
	for (size_t i = 0; i < n; i++) {
		size_t m = 0;
		for (size_t j = 0; j < n; j++)
			if (j != i)
				rest[m++] = use[j];
		cx->use = rest;
		cx->n = m;
		cx->stage = i + 1;
		double th[CAL_N_PARAMS];
		size_t it;
		minimise(cx, out->theta, mu, th, &it);
		struct model_calibration cal;
		calibrate_apply(th, &cx->base, &cal);
		struct calibrate_loo *l = &out->loo[i];
		const struct calibrate_row *row = &rows[use[i]];
		for (int b = 0; b < MODEL_BASIS_MAX; b++) {
			struct validate_row vr;
			l->sized[b] = closed_loop(cx, b == MODEL_PACK_LOCKED ? &row->pack_spec
			    : &row->spec, &cal, work, &vr);
			l->predicted_kg[b] = vr.predicted_kg;
			l->battery_pred_kg[b] = vr.battery_pred_kg;
		}
	}
	cx->use = use;
	cx->n = n;
	for (int b = 0; b < MODEL_BASIS_MAX; b++)
		accuracy_of(rows, use, n, out->loo, b, &out->after.accuracy[b]);
	free(rest);
	free(work);
}

/* The whole fit on rows[0..n): open loop, then the closed loop in sample,
 * then (when loo) out of sample. */
static int
fit(const struct calibrate_row *rows, size_t n, const struct model_data *md,
    double mu, bool loo, const struct calibrate_progress *progress,
    struct calibrate_result *out)
{
	memset(out, 0, sizeof *out);
	out->before = md->cal;
	out->after = md->cal;
	calibrate_theta(&md->cal, out->theta);

	struct fit_ctx *cx = xcalloc(1, sizeof *cx);
	cx->rows = rows;
	/* The fit starts from the priors, whatever calibration md carries:
	 * it is a function of the cohort alone (md->cal only lends the
	 * small-platform wiring ratio and is reported as "before"). */
	struct model_calibration prior_cal;
	calibrate_apply(calibrate_prior, &md->cal, &prior_cal);
	cx->md = *md;
	cx->md.cal = prior_cal;
	cx->base = md->cal;
	cx->progress = progress;
	size_t *use = xmalloc((n ? n : 1) * sizeof *use);
	out->row_index = use;

	/* The rows the model can fly at their real mass: a fixed set of
	 * residuals for the minimiser. */
	size_t m = 0;
	struct solve_result *work = xmalloc(sizeof *work);
	cx->prop_frac = xcalloc(n ? n : 1, sizeof *cx->prop_frac);
	for (size_t i = 0; i < n; i++) {
		double r[3];
		if ((size_t)open_residuals(cx, i, r) != n_residuals(&rows[i]))
			continue;
		/* A row whose loop the engine had to relax at the role's default
		 * thrust target is no contraction there: reported, left out. */
		struct validate_row vr;
		closed_loop(cx, &rows[i].spec, &prior_cal, work, &vr);
		if (vr.thrust_relaxed) {
			out->n_relaxed++;
			continue;
		}
		use[m++] = i;
	}
	out->n_rows = m;
	count_rows(rows, use, m, out->n_per_param);
	int rc = 0;
	if (m == 0) {
		rc = -1;
		goto done;
	}
	cx->use = use;
	cx->n = m;
	out->open_before_pct = open_error_pct(cx, calibrate_prior);
	out->lsq_status = minimise(cx, calibrate_prior, mu, out->theta, &out->n_iter);
	/* Each row's propeller is held through a minimisation (a diameter
	 * switching between evaluations would put kinks in the residuals),
	 * then chosen again at the fitted coefficients; while a choice moves,
	 * minimise again from there. */
	for (int pass = 1; pass < CALIBRATE_PROP_PASSES
	    && (out->lsq_status == LSQ_OK || out->lsq_status == LSQ_MAXITER); pass++) {
		bool moved = false;
		double *held = xmalloc((n ? n : 1) * sizeof *held);
		memcpy(held, cx->prop_frac, (n ? n : 1) * sizeof *held);
		for (size_t i = 0; i < m; i++)
			cx->prop_frac[use[i]] = 0.0;
		open_error_pct(cx, out->theta);
		for (size_t i = 0; i < m; i++)
			moved |= cx->prop_frac[use[i]] != held[use[i]];
		free(held);
		if (!moved)
			break;
		double start[CAL_N_PARAMS];
		memcpy(start, out->theta, sizeof start);
		size_t n_iter = 0;
		out->lsq_status = minimise(cx, start, mu, out->theta, &n_iter);
		out->n_iter += n_iter;
	}
	if (out->lsq_status != LSQ_OK && out->lsq_status != LSQ_MAXITER
	    && !(out->lsq_status == LSQ_EBADFUNC && out->n_iter > 0)) {
		rc = -2;
		goto done;
	}
	calibrate_apply(out->theta, &md->cal, &out->after);
	out->open_after_pct = open_error_pct(cx, out->theta);

	/* Closed loop, in sample. */
	double ape = 0.0;
	for (size_t i = 0; i < m; i++) {
		struct validate_row vr;
		if (closed_loop(cx, &rows[use[i]].spec, &out->after, work, &vr)) {
			ape += fabs(vr.predicted_kg / rows[use[i]].actual_kg - 1.0);
			out->n_sized++;
		}
		if (progress != NULL && progress->fn != NULL)
			progress->fn(progress->ctx, 0, i + 1, m, cx->n_solves);
	}
	out->mtow_mape_pct = out->n_sized ? 100.0 * ape / (double)out->n_sized : 0.0;
	if (loo)
		leave_one_out(cx, rows, m, use, mu, out);
done:
	free(work);
	out->n_evals = cx->n_evals;
	out->n_solves = cx->n_solves;
	free(cx->prop_frac);
	free(cx);
	return rc;
}

int
calibrate_fit_rows(const struct calibrate_row *rows, size_t n,
                   const struct model_data *md, double mu,
                   struct calibrate_result *out)
{
	return fit(rows, n, md, mu, false, NULL, out);
}

int
calibrate_fit(const struct cohort *c, const struct model_data *md, bool loo,
              const struct calibrate_progress *progress, struct calibrate_result *out)
{
	size_t cap = c->n_rows ? c->n_rows : 1;
	struct calibrate_row *rows = xmalloc(cap * sizeof *rows);
	size_t *cohort_row = xmalloc(cap * sizeof *cohort_row);
	size_t n = 0;
	for (size_t i = 0; i < c->n_rows; i++) {
		unsigned notes;
		struct calibrate_row *r = &rows[n];
		if (validate_mission_explained(&c->rows[i], md, VALIDATE_FROM_ENDURANCE,
		    &r->spec, &notes, NULL) != VALIDATE_SKIP_NONE
		    || validate_mission_explained(&c->rows[i], md, VALIDATE_PACK_LOCKED,
		    &r->pack_spec, &notes, NULL) != VALIDATE_SKIP_NONE)
			continue;
		r->actual_kg = c->rows[i].takeoff_mass_kg;
		r->battery_kg = c->rows[i].has_battery_mass_kg ? c->rows[i].battery_mass_kg : 0.0;
		cohort_row[n++] = i;
	}
	int rc = fit(rows, n, md, CALIBRATE_MU, loo, progress, out);
	/* Fitted rows by their cohort row. */
	for (size_t i = 0; i < out->n_rows; i++)
		out->row_index[i] = cohort_row[out->row_index[i]];
	free(cohort_row);
	free(rows);
	return rc;
}

void
calibrate_result_free(struct calibrate_result *r)
{
	if (r == NULL)
		return;
	free(r->loo);
	free(r->row_index);
	r->loo = NULL;
	r->row_index = NULL;
}
