/* test_lsq.c — the Levenberg-Marquardt minimiser on a known model. */
#include "test_util.h"
#include "util/lsq.h"

#include <string.h>

/* Synthetic data from y = a x^b + c with a = 2.385, b = 1.37, c = 0.615 at
 * x = 0.5, 0.75, ..., 4.25 (16 points), noise-free: the true parameters
 * give residuals of zero, so the fit must recover them. */
#define N_PTS 16
static const double TRUE_A = 2.385, TRUE_B = 1.37, TRUE_C = 0.615;

struct data {
	double x[N_PTS], y[N_PTS];
	int n_calls;        /* callback calls, to check the work is bounded */
	double fail_below_c; /* the model "is not defined" for c below this */
};

/* The data set and default options every test starts from. */
static void
make_data(struct data *d, struct lsq_options *o)
{
	lsq_options_default(o);
	memset(d, 0, sizeof *d);
	d->fail_below_c = -1e300;
	for (int i = 0; i < N_PTS; i++) {
		d->x[i] = 0.5 + 0.25 * i;
		d->y[i] = TRUE_A * pow(d->x[i], TRUE_B) + TRUE_C;
	}
}

static int
power_model(const double *t, double *r, size_t m, void *ctx)
{
	struct data *d = ctx;
	d->n_calls++;
	if (t[2] < d->fail_below_c)
		return -1;
	for (size_t i = 0; i < m; i++)
		r[i] = t[0] * pow(d->x[i], t[1]) + t[2] - d->y[i];
	return 0;
}

static int
nan_model(const double *t, double *r, size_t m, void *ctx)
{
	(void)t;
	(void)ctx;
	for (size_t i = 0; i < m; i++)
		r[i] = NAN;
	return 0;
}

static void
lsq_should_recover_the_parameters_of_a_power_law(void **state)
{
	(void)state;
	struct data d;
	struct lsq_options o;
	struct lsq_result res;
	make_data(&d, &o);
	double th[3] = { 1.0, 1.0, 0.1 };
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, th, &o, &res), LSQ_OK);
	assert_true(res.converged);
	assert_rel(th[0], TRUE_A, 1e-6);
	assert_rel(th[1], TRUE_B, 1e-6);
	assert_rel(th[2], TRUE_C, 1e-5);
	assert_true(res.cost_initial > 100); /* far from the answer at the start */
	assert_true(res.cost_final < 1e-12);
	assert_true(res.n_iter >= 2 && res.n_iter < o.max_iter);
	assert_true(res.cost_data_final == res.cost_final); /* no prior */
}

static void
lsq_prior_should_pull_the_fit_toward_it(void **state)
{
	(void)state;
	struct data d;
	struct lsq_options o;
	struct lsq_result res;
	const double prior[3] = { 2.0, 1.0, 1.0 };
	make_data(&d, &o);
	o.mu = 2.5;
	o.prior = prior;
	double th[3] = { 1.0, 1.0, 0.1 };
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, th, &o, &res), LSQ_OK);

	/* The regularised optimum trades data misfit for prior distance: its
	 * prior penalty must be below that of the true parameters (else the
	 * truth, with zero misfit, would have a lower total cost), and its
	 * data misfit above zero. */
	double pen_fit = 0, pen_true = 0;
	const double truth[3] = { TRUE_A, TRUE_B, TRUE_C };
	for (int j = 0; j < 3; j++) {
		pen_fit += pow(log(th[j]) - log(prior[j]), 2);
		pen_true += pow(log(truth[j]) - log(prior[j]), 2);
	}
	assert_true(pen_fit < pen_true);
	assert_true(res.cost_data_final > 1e-6);
	assert_rel(res.cost_final, res.cost_data_final + o.mu * pen_fit, 1e-9);
	assert_true(res.cost_final < o.mu * pen_true); /* beats the truth */

	/* A very strong prior holds the parameters at the prior. */
	o.mu = 1e10;
	double th2[3] = { 1.0, 1.0, 0.1 };
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, th2, &o, &res), LSQ_OK);
	for (int j = 0; j < 3; j++)
		assert_rel(th2[j], prior[j], 1e-3);
}

static void
lsq_should_clamp_to_bounds(void **state)
{
	(void)state;
	struct data d;
	struct lsq_options o;
	struct lsq_result res;
	const double lo[3] = { 0.1, 0.5, -5 }, hi[3] = { 10, 1.2, 5 };
	make_data(&d, &o);
	o.theta_lo = lo;
	o.theta_hi = hi;
	double th[3] = { 20.0, 1.0, 0.1 }; /* a starts outside: clamped to 10 */
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, th, &o, &res), LSQ_OK);
	/* The exponent wants 1.37 but may not exceed 1.2. */
	assert_true(th[1] == 1.2);
	/* With b fixed, y = a z + c with z = x^1.2 is a straight line, so the
	 * constrained optimum is ordinary regression: a = cov(z, y) / var(z),
	 * c = mean(y) - a mean(z). */
	double mz = 0, my = 0, szz = 0, szy = 0;
	for (int i = 0; i < N_PTS; i++) {
		mz += pow(d.x[i], 1.2) / N_PTS;
		my += d.y[i] / N_PTS;
	}
	for (int i = 0; i < N_PTS; i++) {
		double z = pow(d.x[i], 1.2) - mz;
		szz += z * z;
		szy += z * (d.y[i] - my);
	}
	assert_rel(th[0], szy / szz, 1e-6);
	assert_rel(th[2], my - szy / szz * mz, 1e-5);
	assert_true(th[0] > TRUE_A); /* a steeper prefactor makes up for it */
	assert_true(res.cost_final > 0 && res.cost_final < res.cost_initial);
	for (int j = 0; j < 3; j++)
		assert_true(th[j] >= lo[j] && th[j] <= hi[j]);
}

static void
lsq_should_stop_at_max_iter_with_the_best_point(void **state)
{
	(void)state;
	struct data d;
	struct lsq_options o;
	struct lsq_result res;
	make_data(&d, &o);
	o.max_iter = 2;
	double th[3] = { 1.0, 1.0, 0.1 };
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, th, &o, &res), LSQ_MAXITER);
	assert_false(res.converged);
	assert_int_equal(res.n_iter, 2);
	assert_true(res.cost_final < res.cost_initial);
	/* Bounded work: 2 Jacobians of 3 columns plus a bounded number of
	 * trial points (damping 1e-3 .. 1e16 is at most 20 tries each). */
	assert_true(d.n_calls <= 1 + 2 * (3 + 20));
}

static void
lsq_should_reject_steps_where_the_model_fails(void **state)
{
	(void)state;
	/* The callback refuses c < 0.2; the answer (c = 0.615) is inside, so
	 * the solver must back off such steps and still get there. */
	struct data d;
	struct lsq_options o;
	make_data(&d, &o);
	d.fail_below_c = 0.2;
	double th[3] = { 1.0, 1.0, 0.3 };
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, th, &o, NULL), LSQ_OK);
	assert_rel(th[0], TRUE_A, 1e-6);
	assert_rel(th[2], TRUE_C, 1e-5);
}

static void
lsq_should_refuse_bad_arguments_and_bad_models(void **state)
{
	(void)state;
	struct data d;
	struct lsq_options o;
	struct lsq_result res;
	make_data(&d, &o);
	double th[3] = { 1.0, 1.0, 0.1 };
	const double start[3] = { 1.0, 1.0, 0.1 };
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 0, th, &o, &res), LSQ_EINVAL);
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, LSQ_MAX_PARAMS + 1, th, &o, &res),
	                 LSQ_EINVAL);
	assert_int_equal(lsq_minimize(power_model, &d, 0, 3, th, &o, &res), LSQ_EINVAL);
	o.mu = 1.0; /* a prior weight without a prior */
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, th, &o, &res), LSQ_EINVAL);
	const double prior[3] = { 2.0, 1.0, 1.0 };
	o.prior = prior;
	double neg[3] = { 1.0, 1.0, -0.1 }; /* log of a negative start */
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, neg, &o, &res), LSQ_EINVAL);
	lsq_options_default(&o);
	const double lo[3] = { 0, 2, 0 }, hi[3] = { 1, 1, 1 }; /* lo > hi */
	o.theta_lo = lo;
	o.theta_hi = hi;
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, th, &o, &res), LSQ_EINVAL);
	lsq_options_default(&o);
	assert_int_equal(lsq_minimize(nan_model, NULL, N_PTS, 3, th, &o, &res), LSQ_EBADFUNC);
	d.fail_below_c = 1.0;
	assert_int_equal(lsq_minimize(power_model, &d, N_PTS, 3, th, &o, &res), LSQ_EBADFUNC);
	assert_memory_equal(th, start, sizeof start); /* untouched */
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(lsq_should_recover_the_parameters_of_a_power_law),
		cmocka_unit_test(lsq_prior_should_pull_the_fit_toward_it),
		cmocka_unit_test(lsq_should_clamp_to_bounds),
		cmocka_unit_test(lsq_should_stop_at_max_iter_with_the_best_point),
		cmocka_unit_test(lsq_should_reject_steps_where_the_model_fails),
		cmocka_unit_test(lsq_should_refuse_bad_arguments_and_bad_models),
	};
	return cmocka_run_group_tests_name("lsq", tests, NULL, NULL);
}
