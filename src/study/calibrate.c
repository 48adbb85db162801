/* calibrate.c — the power chain fitted on the forward check, the mass laws
 * on the dry mass, and their leave-one-out accuracy (see calibrate.h). */
#include "study/calibrate.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/engine.h"
#include "util/lsq.h"
#include "study/validate.h"
#include "util/xalloc.h"

/* Priors and bounds, each a physical statement:
 *  κ      the installed-FoM penalty: rotor-rotor and rotor-body
 *         interference and non-uniform inflow cost an installed rotor
 *         10-30 % of its isolated figure of merit (paper §IV-F gives
 *         1.20-1.46 per class; the rotor literature 1.1-1.3): prior 1.2,
 *         bounds 1.10-1.35;
 *  η      motor and ESC efficiency at flight throttle: brushless drives
 *         reach 0.80-0.90 at their best point and fall at part load and in
 *         small motors: prior 0.85 (the paper's propulsive efficiency),
 *         bounds 0.60-0.92;
 *  Re_ref the Bohorquez-Pines FoM(Re) fit's reference, 20 000 in the
 *         paper: a rotor at its tip Reynolds number Re has
 *         1 - exp(-Re/Re_ref) of its best FoM; low-Reynolds airfoil data
 *         put the knee between 10^4 and 2 x 10^5: bounds 10 000-200 000;
 *  aux    a scale on the roles' auxiliary power (the paper's ranges,
 *         scaled with the aircraft): prior 1, bounds 0.5-2;
 *  drag   a scale on the body drag area S_ref of the paper's body classes:
 *         prior 1, bounds 0.5-3 (a body with its arms, gear and gimbal
 *         can show a few times the area of a clean shape);
 *  relief the share of Glauert's forward-flight relief of induced power a
 *         multirotor gets (1 - the wake share of mission.h): 1 is the
 *         isolated rotor, the prior; bounds 0.1-1.
 * The mass laws: λ paper eq. (lambda) and the equipment exponent 2/3 (the
 * surface law of shells, gear and mounts) held; the equipment law a
 * quarter of a 1 kg aircraft; C_wire the paper's §V-C. */
const double calibrate_prior[CAL_N_PARAMS] = {
	1.20, 0.85, 20000.0, 1.0, 1.0, 1.0,
	1.50, 1.08, 0.95, 0.80, 1.00,
	0.25, 0.25, 0.25, 0.25, 2.0 / 3.0,
	0.0015,
};
const double calibrate_lo[CAL_N_PARAMS] = {
	1.10, 0.60, 10000.0, 0.5, 0.5, 0.1,
	1.50, 1.08, 0.95, 0.80, 1.00,
	0.01, 0.01, 0.01, 0.01, 2.0 / 3.0,
	0.0005,
};
const double calibrate_hi[CAL_N_PARAMS] = {
	1.35, 0.92, 200000.0, 2.0, 3.0, 1.0,
	1.50, 1.08, 0.95, 0.80, 1.00,
	1.0, 1.0, 1.0, 1.0, 2.0 / 3.0,
	0.005,
};

static const char *const param_name[CAL_N_PARAMS] = {
	"kappa", "drive efficiency", "Reynolds reference", "aux power scale",
	"drag area scale", "forward induced relief",
	"lambda MicroAIO", "lambda ConsumerFolding", "lambda EnterpriseRugged quad",
	"lambda EnterpriseRugged hex/octo", "lambda Agricultural",
	"equipment MicroAIO (kg at 1 kg)", "equipment ConsumerFolding (kg at 1 kg)",
	"equipment EnterpriseRugged (kg at 1 kg)", "equipment Agricultural (kg at 1 kg)",
	"equipment exponent", "wiring coefficient (kg/(A m))",
};

/* The per-class equipment parameters, in enum airframe_class order. */
static const int equip_param[AF_CLASS_MAX] = {
	CAL_EQUIP_MICRO, CAL_EQUIP_CONSUMER, CAL_EQUIP_ENTERPRISE, CAL_EQUIP_AGRI,
};

const char *
calibrate_param_name(enum calibrate_param p)
{
	return (unsigned)p < CAL_N_PARAMS ? param_name[p] : "";
}

void
calibrate_theta(const struct model_calibration *cal, double theta[CAL_N_PARAMS])
{
	theta[CAL_KAPPA] = cal->kappa;
	theta[CAL_ETA_DRIVE] = cal->eta_drive;
	theta[CAL_RE_REF] = cal->re_ref;
	theta[CAL_AUX_SCALE] = cal->aux_scale;
	theta[CAL_DRAG_SCALE] = cal->drag_scale;
	theta[CAL_WAKE_SHARE] = 1.0 - cal->wake_share;
	for (int k = 0; k < LAMBDA_MAX; k++)
		theta[CAL_LAMBDA_MICRO + k] = cal->lambda[k];
	for (int k = 0; k < AF_CLASS_MAX; k++)
		theta[equip_param[k]] = cal->equip_kg[k];
	theta[CAL_EQUIP_EXPONENT] = cal->equip_exponent;
	theta[CAL_WIRE_COEF] = cal->wire_coef;
}

void
calibrate_apply(const double theta[CAL_N_PARAMS], const struct model_calibration *base,
                struct model_calibration *out)
{
	double ratio = base->wire_coef > 0.0 ? base->wire_coef_small / base->wire_coef : 0.2;
	memset(out, 0, sizeof *out);
	out->kappa = theta[CAL_KAPPA];
	out->eta_drive = theta[CAL_ETA_DRIVE];
	out->re_ref = theta[CAL_RE_REF];
	out->aux_scale = theta[CAL_AUX_SCALE];
	out->drag_scale = theta[CAL_DRAG_SCALE];
	out->wake_share = 1.0 - theta[CAL_WAKE_SHARE];
	for (int k = 0; k < LAMBDA_MAX; k++)
		out->lambda[k] = theta[CAL_LAMBDA_MICRO + k];
	for (int k = 0; k < AF_CLASS_MAX; k++)
		out->equip_kg[k] = theta[equip_param[k]];
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

bool
calibrate_has_forward(const struct calibrate_row *row)
{
	return row->has_pack && !row->racing
	    && (row->hover_s > 0.0 || row->max_flight_s > 0.0);
}

bool
calibrate_forward(const struct calibrate_row *row, const struct model_data *md,
                  double r[2])
{
	r[0] = r[1] = NAN;
	struct cohort_row cr;
	memset(&cr, 0, sizeof cr);
	cr.takeoff_mass_kg = row->actual_kg;
	cr.has_hover_time_min = row->hover_s > 0.0;
	cr.hover_time_min = row->hover_s / 60.0;
	cr.has_max_flight_time_min = row->max_flight_s > 0.0;
	cr.max_flight_time_min = row->max_flight_s / 60.0;
	cr.has_cruise_speed_ms = row->cruise_ms > 0.0;
	cr.cruise_speed_ms = row->cruise_ms;
	cr.has_role = row->racing;
	cr.role = row->racing ? ROLE_RACING : ROLE_NONE;
	struct validate_forward f;
	validate_forward(&cr, &row->pack_spec, md, &f);
	if (!f.valid)
		return false;
	if (f.hover_pub_s > 0.0 && f.hover_model_s > 0.0)
		r[0] = log(f.hover_model_s / f.hover_pub_s);
	if (f.max_pub_s > 0.0 && f.max_model_s > 0.0)
		r[1] = log(f.max_model_s / f.max_pub_s);
	return true;
}

/* What the residual callbacks need: the rows, a private copy of the tables
 * whose calibration they rewrite, the fitted subset and which fit runs. */
struct fit_ctx {
	const struct calibrate_row *rows;
	size_t n_rows;
	const bool *left_out;          /* rows out of this fit, or NULL */
	bool *no_forward;              /* rows the model cannot fly at the priors */
	bool *no_dry;                  /* ... or size at their real mass */
	bool mass_fit;                 /* false: the power chain; true: the mass laws */
	struct model_data md;          /* copy; .cal rewritten per evaluation */
	struct model_calibration base; /* lends the wiring ratio */
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

/* The dry-mass residual of row idx at the tables' current calibration:
 * the model at the real takeoff mass, around the published pack where
 * given (the dry mass does not ask whether the pack flies the mission:
 * that is the forward check's question); false when the model has no
 * settled design there. */
static bool
dry_residual(struct fit_ctx *cx, size_t idx, double *r)
{
	const struct calibrate_row *row = &cx->rows[idx];
	double dry = calibrate_dry_kg(row);
	struct sizing_open o;
	cx->n_evals++;
	bool flown = engine_at_mass(row->has_pack ? &row->pack_spec : &row->spec,
	    &cx->md, row->actual_kg, cx->prop_frac[idx], &o);
	cx->prop_frac[idx] = o.prop_frac;
	if (!(flown || (row->has_pack && o.settled)) || !(o.dry_kg > 0.0) || !(dry > 0.0))
		return false;
	*r = log(o.dry_kg / dry);
	return isfinite(*r);
}

/* Does row i take part in the current fit, and with how many residuals
 * (the forward check's published times; the dry mass's one)? */
static size_t
n_residuals(const struct fit_ctx *cx, size_t i)
{
	const struct calibrate_row *row = &cx->rows[i];
	if (cx->left_out != NULL && cx->left_out[i])
		return 0;
	if (cx->mass_fit)
		return calibrate_dry_kg(row) > 0.0 && !cx->no_dry[i] ? 1 : 0;
	if (!calibrate_has_forward(row) || cx->no_forward[i])
		return 0;
	return (row->hover_s > 0.0) + (row->max_flight_s > 0.0);
}

/* The residuals of row i into r (n_residuals() of them); false when the
 * model cannot produce one. */
static bool
row_residuals(struct fit_ctx *cx, size_t i, double *r)
{
	if (cx->mass_fit)
		return dry_residual(cx, i, r);
	double f[2];
	cx->n_evals++;
	if (!calibrate_forward(&cx->rows[i], &cx->md, f))
		return false;
	size_t k = 0;
	for (int j = 0; j < 2; j++) {
		if (!((j == 0 ? cx->rows[i].hover_s : cx->rows[i].max_flight_s) > 0.0))
			continue;
		if (!isfinite(f[j]))
			return false;
		r[k++] = f[j];
	}
	return true;
}

static int
residuals(const double *theta_free, double *r, size_t m, void *ctx)
{
	struct fit_ctx *cx = ctx;
	double theta[CAL_N_PARAMS];
	expand(cx, theta_free, theta);
	calibrate_apply(theta, &cx->base, &cx->md.cal);
	size_t k = 0;
	for (size_t i = 0; i < cx->n_rows; i++) {
		size_t got = n_residuals(cx, i);
		if (got == 0)
			continue;
		if (k + got > m || !row_residuals(cx, i, r + k))
			return 1;
		k += got;
	}
	if (cx->progress != NULL && cx->progress->fn != NULL)
		cx->progress->fn(cx->progress->ctx, cx->stage, 0, cx->n_rows, cx->n_solves);
	return k == m ? 0 : 1;
}

/* Mean |e^r - 1| of the current fit's residuals at theta, %. */
static double
fit_error_pct(struct fit_ctx *cx, const double *theta)
{
	calibrate_apply(theta, &cx->base, &cx->md.cal);
	double sum = 0.0, r[2];
	size_t k = 0;
	for (size_t i = 0; i < cx->n_rows; i++) {
		size_t got = n_residuals(cx, i);
		if (got == 0 || !row_residuals(cx, i, r))
			continue;
		for (size_t j = 0; j < got; j++)
			sum += fabs(expm1(r[j]));
		k += got;
	}
	return k ? 100.0 * sum / (double)k : 0.0;
}

/* The rows informing each coefficient of the current fit: the power
 * chain's, every row of the forward check; a class's equipment, its own
 * rows; C_wire, every dry-mass row. */
static void
count_rows(const struct fit_ctx *cx, size_t count[CAL_N_PARAMS])
{
	memset(count, 0, CAL_N_PARAMS * sizeof count[0]);
	for (size_t i = 0; i < cx->n_rows; i++) {
		if (n_residuals(cx, i) == 0)
			continue;
		if (!cx->mass_fit) {
			for (int j = 0; j < CAL_FIRST_MASS; j++)
				count[j]++;
			continue;
		}
		const struct mission_spec *s = &cx->rows[i].spec;
		count[CAL_LAMBDA_MICRO + model_lambda_index(s->airframe_class, s->num_rotors)]++;
		count[equip_param[s->airframe_class]]++;
		count[CAL_EQUIP_EXPONENT]++;
		count[CAL_WIRE_COEF]++;
	}
}

/* Minimise the current fit (cx->mass_fit says which) over the
 * coefficients it owns that enough rows inform, from start; theta gets the
 * result.  Returns the lsq status. */
static int
minimise(struct fit_ctx *cx, const double *start, double mu, double *theta,
         size_t *n_iter)
{
	size_t count[CAL_N_PARAMS];
	count_rows(cx, count);
	double th[CAL_N_PARAMS], prior[CAL_N_PARAMS], lo[CAL_N_PARAMS], hi[CAL_N_PARAMS];
	memcpy(cx->full, start, sizeof cx->full);
	cx->n_free = 0;
	int first = cx->mass_fit ? CAL_FIRST_MASS : 0;
	int last = cx->mass_fit ? CAL_N_PARAMS : CAL_FIRST_MASS;
	for (int j = first; j < last; j++) {
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
	for (size_t i = 0; i < cx->n_rows; i++)
		m += n_residuals(cx, i);
	if (m == 0)
		return LSQ_OK;
	struct lsq_result lr;
	int st = lsq_minimize(residuals, cx, m, cx->n_free, th, &opt, &lr);
	*n_iter = lr.n_iter;
	if (st == LSQ_OK || st == LSQ_MAXITER || (st == LSQ_EBADFUNC && lr.n_iter > 0))
		expand(cx, th, theta);
	return st;
}

static bool
lsq_usable(int st, size_t n_iter)
{
	return st == LSQ_OK || st == LSQ_MAXITER || (st == LSQ_EBADFUNC && n_iter > 0);
}

/* Both fits from start into theta: the power chain first, then the mass
 * laws with it held; each row's propeller held through a minimisation of
 * the mass laws (a diameter switching between evaluations would put kinks
 * in the residuals), chosen again at the fitted coefficients, and the
 * minimisation repeated while a choice moves.  Returns the worse status. */
static int
fit_both(struct fit_ctx *cx, const double *start, double mu, double *theta,
         size_t *n_iter)
{
	size_t it = 0;
	cx->mass_fit = false;
	int st = minimise(cx, start, mu, theta, &it);
	*n_iter = it;
	if (!lsq_usable(st, it))
		return st;
	cx->mass_fit = true;
	for (size_t i = 0; i < cx->n_rows; i++)
		cx->prop_frac[i] = 0.0;
	double from[CAL_N_PARAMS];
	memcpy(from, theta, sizeof from);
	int st2 = minimise(cx, from, mu, theta, &it);
	*n_iter += it;
	for (int pass = 1; pass < CALIBRATE_PROP_PASSES && lsq_usable(st2, it); pass++) {
		double *held = xmalloc(cx->n_rows * sizeof *held);
		memcpy(held, cx->prop_frac, cx->n_rows * sizeof *held);
		for (size_t i = 0; i < cx->n_rows; i++)
			cx->prop_frac[i] = 0.0;
		fit_error_pct(cx, theta);
		bool moved = false;
		for (size_t i = 0; i < cx->n_rows; i++)
			moved |= n_residuals(cx, i) > 0 && cx->prop_frac[i] != held[i];
		free(held);
		if (!moved)
			break;
		memcpy(from, theta, sizeof from);
		st2 = minimise(cx, from, mu, theta, &it);
		*n_iter += it;
	}
	return lsq_usable(st2, it) ? st : st2;
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

/* Coverage, out of sample, of the split-conformal interval over res[0..n):
 * does each residual lie in the interval built from the others?  An
 * interval judged on the residuals it was built from would cover them by
 * construction.  keys (may be NULL) restrict "the others" to the same key
 * when own[key] says that key has an interval of its own. */
static double
loo_coverage(const double *res, size_t n, const int *keys, const bool *own)
{
	double *others = xmalloc((n ? n : 1) * sizeof *others);
	size_t inside = 0, judged = 0;
	for (size_t i = 0; i < n; i++) {
		bool by_key = keys != NULL && own[keys[i]];
		size_t m = 0;
		for (size_t j = 0; j < n; j++)
			if (j != i && (!by_key || keys[j] == keys[i]))
				others[m++] = res[j];
		double lo, hi;
		if (!calibrate_conformal(others, m, CALIBRATE_LEVEL, &lo, &hi))
			continue;
		inside += res[i] >= lo && res[i] <= hi;
		judged++;
	}
	free(others);
	return judged ? (double)inside / (double)judged : 0.0;
}

/* A spread from n leave-one-out residuals ln(model / published): MAPE,
 * the interval on ln(published / model) and its coverage. */
static void
spread_of(const double *resid, size_t n, struct model_spread *sp)
{
	memset(sp, 0, sizeof *sp);
	double *r = xmalloc((n ? n : 1) * sizeof *r);
	double ape = 0.0;
	for (size_t i = 0; i < n; i++) {
		ape += fabs(expm1(resid[i]));
		r[i] = -resid[i];
	}
	sp->n = (int)n;
	sp->level = CALIBRATE_LEVEL;
	sp->mape_pct = n ? 100.0 * ape / (double)n : 0.0;
	sp->coverage = loo_coverage(r, n, NULL, NULL);
	sp->valid = calibrate_conformal(r, n, CALIBRATE_LEVEL, &sp->log_lo, &sp->log_hi);
	free(r);
}

/* The accuracy figures, interval and coverage of one battery basis from
 * the leave-one-out predictions. */
static void
accuracy_of(const struct calibrate_row *rows, size_t n,
            const struct calibrate_loo *loo, int b, struct model_accuracy *a)
{
	double *res = xmalloc((n ? n : 1) * sizeof *res);
	double *res_cls = xmalloc((n ? n : 1) * sizeof *res_cls);
	int *cls = xmalloc((n ? n : 1) * sizeof *cls);
	memset(a, 0, sizeof *a);
	double ape = 0.0, bape = 0.0;
	size_t k = 0;
	for (size_t i = 0; i < n; i++) {
		const struct calibrate_row *row = &rows[i];
		if (!row->sized || !loo[i].sized[b] || !(loo[i].predicted_kg[b] > 0.0))
			continue;
		ape += fabs(loo[i].predicted_kg[b] / row->actual_kg - 1.0);
		cls[k] = row->spec.airframe_class;
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
	bool own[AF_CLASS_MAX] = { false };
	for (int c = 0; c < AF_CLASS_MAX; c++) {
		size_t kc = 0;
		for (size_t i = 0; i < k; i++)
			if (cls[i] == c)
				res_cls[kc++] = res[i];
		struct model_interval *iv = &a->cls[c];
		if (kc >= CALIBRATE_CLASS_INTERVAL_MIN
		    && calibrate_conformal(res_cls, kc, CALIBRATE_LEVEL, &iv->log_lo, &iv->log_hi)) {
			iv->n = (int)kc;
			own[c] = true;
		}
	}
	a->coverage = loo_coverage(res, k, cls, own);
	a->valid = calibrate_conformal(res, k, CALIBRATE_LEVEL, &a->pooled.log_lo,
	    &a->pooled.log_hi);
	a->pooled.n = (int)k;
	free(cls);
	free(res_cls);
	free(res);
}

/* The spread of the leave-one-out residuals in key (forward: both of a
 * row's figures; dry) of every row but `skip`, into sp. */
static void
spread_without(const struct calibrate_loo *loo, size_t n, size_t skip, bool forward,
               struct model_spread *sp)
{
	double *v = xmalloc((2 * n + 1) * sizeof *v);
	size_t k = 0;
	for (size_t i = 0; i < n; i++) {
		if (i == skip)
			continue;
		if (forward) {
			for (int j = 0; j < 2; j++)
				if (isfinite(loo[i].forward[j]))
					v[k++] = loo[i].forward[j];
		} else if (isfinite(loo[i].dry)) {
			v[k++] = loo[i].dry;
		}
	}
	spread_of(v, k, sp);
	free(v);
}

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The design intervals' coverage, out of sample: each sized row's own
 * interval (engine_loop_interval(), its loop gain and shares, the spreads
 * of the other rows) against its real takeoff mass, and their median
 * width hi / lo. */
static void
design_coverage(const struct calibrate_row *rows, size_t n,
                const struct calibrate_loo *loo, int b, struct model_accuracy *a)
{
	double *width = xmalloc((n ? n : 1) * sizeof *width);
	size_t judged = 0, inside = 0;
	for (size_t i = 0; i < n; i++) {
		const struct calibrate_loo *l = &loo[i];
		double m = l->predicted_kg[b];
		if (!rows[i].sized || !l->sized[b] || !(m > 0.0))
			continue;
		struct model_spread dry, fwd;
		spread_without(loo, n, i, false, &dry);
		spread_without(loo, n, i, true, &fwd);
		if (!dry.valid || !fwd.valid)
			continue;
		double lo, hi;
		engine_loop_interval(l->dry_pred_kg[b] / m, l->battery_pred_kg[b] / m,
		    l->lipschitz[b], &dry, &fwd, &lo, &hi);
		double r = log(rows[i].actual_kg / m);
		inside += r >= lo && r <= hi;
		width[judged++] = exp(hi - lo);
	}
	a->design_rows = (int)judged;
	a->design_coverage = judged ? (double)inside / (double)judged : 0.0;
	if (judged > 0) {
		qsort(width, judged, sizeof *width, cmp_double);
		a->design_width = judged % 2 ? width[judged / 2]
		    : 0.5 * (width[judged / 2 - 1] + width[judged / 2]);
	}
	free(width);
}

/* Leave each row out in turn, redo both fits on the rest, and predict the
 * row: its forward check, dry mass and closed-loop takeoff mass from its
 * endurance and around its published pack.  The accuracy into
 * out->after. */
static void
leave_one_out(struct fit_ctx *cx, const struct calibrate_row *rows, size_t n,
              double mu, struct calibrate_result *out)
{
	struct solve_result *work = xmalloc(sizeof *work);
	bool *left = xcalloc(n ? n : 1, sizeof *left);
	out->loo = xcalloc(n ? n : 1, sizeof *out->loo);
	cx->left_out = left;
	for (size_t i = 0; i < n; i++) {
		left[i] = true;
		cx->stage = i + 1;
		double th[CAL_N_PARAMS];
		size_t it;
		fit_both(cx, out->theta, mu, th, &it);
		left[i] = false;
		struct model_calibration cal;
		calibrate_apply(th, &cx->base, &cal);
		cx->md.cal = cal;
		struct calibrate_loo *l = &out->loo[i];
		const struct calibrate_row *row = &rows[i];
		l->forward[0] = l->forward[1] = l->dry = NAN;
		if (calibrate_has_forward(row))
			calibrate_forward(row, &cx->md, l->forward);
		double d;
		cx->prop_frac[i] = 0.0;
		if (calibrate_dry_kg(row) > 0.0 && dry_residual(cx, i, &d))
			l->dry = d;
		for (int b = 0; b < MODEL_BASIS_MAX && row->sized; b++) {
			struct validate_row vr;
			l->sized[b] = closed_loop(cx, b == MODEL_PACK_LOCKED ? &row->pack_spec
			    : &row->spec, &cal, work, &vr);
			l->predicted_kg[b] = vr.predicted_kg;
			l->battery_pred_kg[b] = vr.battery_pred_kg;
			l->dry_pred_kg[b] = vr.dry_pred_kg;
			l->lipschitz[b] = vr.lipschitz;
		}
	}
	cx->left_out = NULL;
	for (int b = 0; b < MODEL_BASIS_MAX; b++)
		accuracy_of(rows, n, out->loo, b, &out->after.accuracy[b]);
	double *fw = xmalloc((2 * n + 1) * sizeof *fw), *dr = xmalloc((n + 1) * sizeof *dr);
	size_t nf = 0, nd = 0;
	for (size_t i = 0; i < n; i++) {
		for (int j = 0; j < 2; j++)
			if (isfinite(out->loo[i].forward[j]))
				fw[nf++] = out->loo[i].forward[j];
		if (isfinite(out->loo[i].dry))
			dr[nd++] = out->loo[i].dry;
	}
	spread_of(fw, nf, &out->after.forward);
	spread_of(dr, nd, &out->after.dry);
	for (int b = 0; b < MODEL_BASIS_MAX; b++)
		design_coverage(rows, n, out->loo, b, &out->after.accuracy[b]);
	free(fw);
	free(dr);
	free(left);
	free(work);
}

/* The whole fit on rows[0..n): both fits, the closed loop in sample, then
 * (when loo) out of sample. */
static int
fit(const struct calibrate_row *rows, size_t n, const struct model_data *md,
    double mu, bool loo, const struct calibrate_progress *progress,
    struct calibrate_result *out)
{
	memset(out, 0, sizeof *out);
	out->before = md->cal;
	out->after = md->cal;
	calibrate_theta(&md->cal, out->theta);
	out->row_index = xmalloc((n ? n : 1) * sizeof *out->row_index);
	for (size_t i = 0; i < n; i++)
		out->row_index[i] = i;
	out->n_rows = n;
	if (n == 0)
		return -1;

	struct fit_ctx *cx = xcalloc(1, sizeof *cx);
	cx->rows = rows;
	cx->n_rows = n;
	/* The fit starts from the priors, whatever calibration md carries:
	 * it is a function of the cohort alone (md->cal only lends the
	 * small-platform wiring ratio and is reported as "before"). */
	struct model_calibration prior_cal;
	calibrate_apply(calibrate_prior, &md->cal, &prior_cal);
	cx->md = *md;
	cx->md.cal = prior_cal;
	cx->base = md->cal;
	cx->progress = progress;
	cx->prop_frac = xcalloc(n, sizeof *cx->prop_frac);
	struct solve_result *work = xmalloc(sizeof *work);
	int rc = 0;

	/* The rows the model can fly (forward check) or size (dry mass) at
	 * their real mass at the priors: a fixed set of residuals for the
	 * minimiser. */
	cx->no_forward = xcalloc(n, sizeof *cx->no_forward);
	cx->no_dry = xcalloc(n, sizeof *cx->no_dry);
	for (size_t i = 0; i < n; i++) {
		double r[2];
		cx->mass_fit = false;
		cx->no_forward[i] = n_residuals(cx, i) > 0 && !row_residuals(cx, i, r);
		cx->mass_fit = true;
		cx->no_dry[i] = n_residuals(cx, i) > 0 && !row_residuals(cx, i, r);
	}
	size_t count[CAL_N_PARAMS];
	cx->mass_fit = false;
	out->forward_before_pct = fit_error_pct(cx, calibrate_prior);
	count_rows(cx, count);
	for (size_t i = 0; i < n; i++)
		out->n_forward += n_residuals(cx, i) > 0;
	cx->mass_fit = true;
	out->dry_before_pct = fit_error_pct(cx, calibrate_prior);
	size_t count_mass[CAL_N_PARAMS];
	count_rows(cx, count_mass);
	for (size_t i = 0; i < n; i++)
		out->n_dry += n_residuals(cx, i) > 0;
	for (int j = 0; j < CAL_N_PARAMS; j++)
		out->n_per_param[j] = j < CAL_FIRST_MASS ? count[j] : count_mass[j];

	out->lsq_status = fit_both(cx, calibrate_prior, mu, out->theta, &out->n_iter);
	if (!lsq_usable(out->lsq_status, out->n_iter)) {
		rc = -2;
		goto done;
	}
	for (int j = 0; j < CAL_N_PARAMS; j++)
		out->at_bound[j] = calibrate_lo[j] < calibrate_hi[j]
		    && out->n_per_param[j] >= CALIBRATE_MIN_ROWS
		    && (out->theta[j] <= calibrate_lo[j] * (1.0 + 1e-6)
		        || out->theta[j] >= calibrate_hi[j] * (1.0 - 1e-6));
	calibrate_apply(out->theta, &md->cal, &out->after);
	cx->mass_fit = false;
	out->forward_after_pct = fit_error_pct(cx, out->theta);
	cx->mass_fit = true;
	out->dry_after_pct = fit_error_pct(cx, out->theta);

	/* Closed loop, in sample. */
	double ape = 0.0;
	for (size_t i = 0; i < n; i++) {
		if (!rows[i].sized)
			continue;
		out->n_sizable++;
		struct validate_row vr;
		if (closed_loop(cx, &rows[i].spec, &out->after, work, &vr)) {
			ape += fabs(vr.predicted_kg / rows[i].actual_kg - 1.0);
			out->n_sized++;
		}
		if (progress != NULL && progress->fn != NULL)
			progress->fn(progress->ctx, 0, i + 1, n, cx->n_solves);
	}
	out->mtow_mape_pct = out->n_sized ? 100.0 * ape / (double)out->n_sized : 0.0;
	if (loo)
		leave_one_out(cx, rows, n, mu, out);
done:
	free(work);
	out->n_evals = cx->n_evals;
	out->n_solves = cx->n_solves;
	free(cx->prop_frac);
	free(cx->no_forward);
	free(cx->no_dry);
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

bool
calibrate_row_from_cohort(const struct cohort_row *cr, const struct model_data *md,
                          struct calibrate_row *r)
{
	unsigned notes;
	memset(r, 0, sizeof *r);
	r->sized = validate_mission_explained(cr, md, VALIDATE_FROM_ENDURANCE,
	    &r->spec, &notes, NULL) == VALIDATE_SKIP_NONE;
	bool packed = validate_mission_explained(cr, md, VALIDATE_PACK_LOCKED,
	    &r->pack_spec, &notes, NULL) == VALIDATE_SKIP_NONE;
	if (!r->sized && !packed)
		return false;
	if (!r->sized)
		r->spec = r->pack_spec;
	if (!packed)
		r->pack_spec = r->spec;
	r->has_pack = packed && r->pack_spec.locks.is_battery_locked;
	r->actual_kg = cr->takeoff_mass_kg;
	r->battery_kg = cr->has_battery_mass_kg ? cr->battery_mass_kg : 0.0;
	r->hover_s = cr->has_hover_time_min ? 60.0 * cr->hover_time_min : 0.0;
	r->max_flight_s = cr->has_max_flight_time_min ? 60.0 * cr->max_flight_time_min : 0.0;
	r->cruise_ms = cr->has_cruise_speed_ms ? cr->cruise_speed_ms : 0.0;
	r->racing = cr->has_role && cr->role == ROLE_RACING;
	return true;
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
		if (!calibrate_row_from_cohort(&c->rows[i], md, &rows[n]))
			continue;
		/* A row in neither fit and not sizable says nothing. */
		if (!calibrate_has_forward(&rows[n]) && !(calibrate_dry_kg(&rows[n]) > 0.0)
		    && !rows[n].sized)
			continue;
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
