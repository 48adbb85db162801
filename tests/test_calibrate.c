/* test_calibrate.c — the coefficient fit of `aeroeval calibrate`. */
#include "test_util.h"
#include "study/calibrate.h"

#include <stdlib.h>
#include <string.h>

#include "util/lsq.h"
#include "input/cohort.h"
#include "core/diag.h"
#include "input/model_io.h"
#include "study/validate.h"

static struct model_data md;

static int
setup(void **state)
{
	(void)state;
	struct diag *dg = diag_alloc(stderr);
	int n_err = model_io_load("data", &md, dg);
	diag_flush(dg);
	diag_free(dg);
	return n_err == 0 ? 0 : -1;
}

static void
theta_should_round_trip_and_keep_the_small_wiring_ratio(void **state)
{
	(void)state;
	double th[CAL_N_PARAMS];
	calibrate_theta(&md.cal, th);
	struct model_calibration out;
	calibrate_apply(th, &md.cal, &out);
	for (int i = 0; i < LAMBDA_MAX; i++)
		assert_rel(out.lambda[i], md.cal.lambda[i], 1e-15);
	assert_rel(out.packaging_base, md.cal.packaging_base, 1e-15);
	assert_rel(out.wire_coef_small, md.cal.wire_coef_small, 1e-12);
	th[CAL_WIRE_COEF] *= 2;
	calibrate_apply(th, &md.cal, &out);
	assert_rel(out.wire_coef, 2 * md.cal.wire_coef, 1e-15);
	assert_rel(out.wire_coef_small, 2 * md.cal.wire_coef_small, 1e-12);
	/* The prior is the paper's: eq. (lambda), packaging base, C_wire. */
	const double paper[CAL_N_PARAMS] = { 1.50, 1.08, 0.95, 0.80, 1.00, 1.04, 0.0015 };
	for (int j = 0; j < CAL_N_PARAMS; j++)
		assert_rel(calibrate_prior[j], paper[j], 1e-15);
}

/* What a progress callback saw. */
struct seen {
	size_t calls, last_solves, max_pass, first_pass_rows;
};

static void
count_progress(void *ctx, size_t pass, size_t row, size_t n_rows, size_t n_solves)
{
	struct seen *s = ctx;
	assert_true(row >= 1 && row <= n_rows);
	assert_int_equal(n_solves, s->last_solves + 1);   /* one call per solve */
	if (pass == 0)
		s->first_pass_rows = n_rows;
	if (pass > s->max_pass)
		s->max_pass = pass;
	s->calls++;
	s->last_solves = n_solves;
}

/* data/calibration.json is the frozen fit: calibrating the calibration
 * cohort again from the paper's values lands on the shipped numbers, and
 * the classes with fewer than CALIBRATE_MIN_ROWS rows keep the paper's. */
static void
shipped_calibration_should_be_the_fit_on_the_calibration_cohort(void **state)
{
	(void)state;
	struct cohort c;
	assert_int_equal(cohort_load("tests/fixtures/cohort/calibration.csv", &c), 0);
	struct model_data start = md;
	calibrate_apply(calibrate_prior, &md.cal, &start.cal);
	struct calibrate_result r;
	struct seen seen = { 0 };
	struct calibrate_progress pg = { count_progress, &seen };
	assert_int_equal(calibrate_fit(&c, &start, &pg, &r), 0);
	/* Progress came once per solve, through the first pass and the fit. */
	assert_int_equal(seen.calls, r.n_solves);
	assert_true(seen.first_pass_rows >= r.n_rows);
	assert_true(seen.max_pass > r.n_iter);
	double shipped[CAL_N_PARAMS];
	calibrate_theta(&md.cal, shipped);
	for (int j = 0; j < CAL_N_PARAMS; j++) {
		assert_rel(r.theta[j], shipped[j], 1e-3);
		if (r.n_per_param[j] < CALIBRATE_MIN_ROWS)
			assert_rel(r.theta[j], calibrate_prior[j], 1e-12);
	}
	assert_true(r.mape_after_pct < r.mape_before_pct);
	cohort_free(&c);
}

/* A mission like one the rule would build. */
static void
mission(struct mission_spec *s, int cls, int rotors, double wheelbase_m,
        double payload_kg, double hover_min, int role)
{
	spec_defaults(s);
	s->airframe_class = cls;
	s->num_rotors = rotors;
	s->max_diameter_m = wheelbase_m;
	s->payload_kg = payload_kg;
	s->t_hover_s = 60 * hover_min;
	s->t_climb_s = 0;
	s->payload_role.type = role;
	s->given[SPECF_AIRFRAME_CLASS] = s->given[SPECF_NUM_ROTORS] = true;
	s->given[SPECF_MAX_DIAMETER_M] = s->given[SPECF_PAYLOAD_KG] = true;
	s->given[SPECF_T_HOVER_S] = s->given[SPECF_T_CLIMB_S] = true;
	s->given[SPECF_ROLE_TYPE] = true;
}

enum { N_SYN = 8 };

static void
synthetic(struct mission_spec *s)
{
	mission(&s[0], AF_CONSUMER_FOLDING, 4, 0.30, 0.2, 20, ROLE_IMAGING);
	mission(&s[1], AF_CONSUMER_FOLDING, 4, 0.45, 0.6, 12, ROLE_IMAGING);
	mission(&s[2], AF_CONSUMER_FOLDING, 4, 0.50, 1.0, 12, ROLE_IMAGING);
	mission(&s[3], AF_CONSUMER_FOLDING, 6, 0.50, 0.5, 12, ROLE_IMAGING);
	mission(&s[4], AF_ENTERPRISE_RUGGED, 4, 0.90, 2.0, 15, ROLE_INSPECTION);
	mission(&s[5], AF_ENTERPRISE_RUGGED, 6, 1.00, 5.0, 20, ROLE_MAPPING);
	mission(&s[6], AF_ENTERPRISE_RUGGED, 8, 1.20, 5.0, 15, ROLE_IMAGING);
	mission(&s[7], AF_MICRO_AIO, 4, 0.25, 0.15, 8, ROLE_IMAGING);
}

/* actual[i] = scale x the prediction of mission i with tables m. */
static void
predict(const struct mission_spec *s, const struct model_data *m, double scale,
        double *actual)
{
	struct solve_result *work = malloc(sizeof *work);
	for (int i = 0; i < N_SYN; i++) {
		struct validate_row vr;
		memset(&vr, 0, sizeof vr);
		validate_solve_row(&s[i], m, work, &vr);
		if (vr.status != VALIDATE_ROW_OK)
			print_error("row %d: %s, %g kg: %s\n", i, validate_status_text(vr.status),
			    vr.predicted_kg, work->custom.termination);
		assert_int_equal(vr.status, VALIDATE_ROW_OK);
		actual[i] = scale * vr.predicted_kg;
	}
	free(work);
}

/* Predictions made with known coefficients serve as the "actual" masses;
 * the fit, started from the paper's values, must find them again. */
static void
fit_should_recover_known_coefficients_from_a_synthetic_cohort(void **state)
{
	(void)state;
	struct mission_spec s[N_SYN];
	synthetic(s);
	struct model_data truth = md;
	truth.cal.lambda[LAMBDA_CONSUMER] = 1.2;
	truth.cal.packaging_base = 1.06;
	double actual[N_SYN];
	predict(s, &truth, 1.0, actual);

	struct calibrate_result r;
	/* A negligible prior, so the data alone decide. */
	assert_int_equal(calibrate_fit_missions(s, actual, N_SYN, &md, 1e-6, &r), 0);
	assert_int_equal(r.n_rows, N_SYN);
	assert_true(r.lsq_status == LSQ_OK || r.lsq_status == LSQ_MAXITER);
	assert_rel(r.theta[CAL_LAMBDA_CONSUMER], 1.2, 0.03);
	assert_rel(r.theta[CAL_PACKAGING_BASE], 1.06, 0.01);
	assert_rel(r.after.lambda[LAMBDA_CONSUMER], 1.2, 0.03);
	assert_true(r.mape_before_pct > 1.0);
	assert_true(r.mape_after_pct < 0.2);
	assert_int_equal(r.n_per_param[CAL_LAMBDA_CONSUMER], 4);
	assert_int_equal(r.n_per_param[CAL_LAMBDA_ENT_QUAD], 1);
	assert_int_equal(r.n_per_param[CAL_LAMBDA_ENT_MULTI], 2);
	assert_int_equal(r.n_per_param[CAL_LAMBDA_AGRI], 0);
	/* One and two rows are too few (CALIBRATE_MIN_ROWS): held exactly. */
	assert_true(r.theta[CAL_LAMBDA_ENT_QUAD] == md.cal.lambda[LAMBDA_ENTERPRISE_QUAD]);
	assert_true(r.theta[CAL_LAMBDA_ENT_MULTI] == md.cal.lambda[LAMBDA_ENTERPRISE_MULTI]);
	assert_true(r.theta[CAL_LAMBDA_MICRO] == md.cal.lambda[LAMBDA_MICRO]);
	/* No Agricultural row: its lambda has no data and stays put. */
	assert_rel(r.theta[CAL_LAMBDA_AGRI], calibrate_prior[CAL_LAMBDA_AGRI], 1e-9);
}

/* With the production prior weight, a class absent from the cohort keeps
 * the paper's value, and every coefficient stays inside its bounds. */
static void
fit_should_keep_absent_classes_at_the_prior_and_respect_bounds(void **state)
{
	(void)state;
	struct mission_spec s[N_SYN];
	synthetic(s);
	/* Everything three times heavier than the model: the fit must stop at
	 * the bounds, not beyond. */
	double actual[N_SYN];
	predict(s, &md, 3.0, actual);
	struct calibrate_result r;
	assert_int_equal(calibrate_fit_missions(s, actual, N_SYN, &md, CALIBRATE_MU, &r), 0);
	assert_rel(r.theta[CAL_LAMBDA_AGRI], 1.0, 1e-9);
	for (int j = 0; j < CAL_N_PARAMS; j++) {
		assert_true(r.theta[j] >= calibrate_lo[j]);
		assert_true(r.theta[j] <= calibrate_hi[j]);
	}
	assert_true(r.mape_after_pct < r.mape_before_pct);
}

static void
fit_should_refuse_a_cohort_without_usable_rows(void **state)
{
	(void)state;
	struct cohort c;
	memset(&c, 0, sizeof c);
	struct calibrate_result r;
	assert_int_equal(calibrate_fit(&c, &md, NULL, &r), -1);
	assert_int_equal(r.n_rows, 0);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(theta_should_round_trip_and_keep_the_small_wiring_ratio),
		cmocka_unit_test(shipped_calibration_should_be_the_fit_on_the_calibration_cohort),
		cmocka_unit_test(fit_should_recover_known_coefficients_from_a_synthetic_cohort),
		cmocka_unit_test(fit_should_keep_absent_classes_at_the_prior_and_respect_bounds),
		cmocka_unit_test(fit_should_refuse_a_cohort_without_usable_rows),
	};
	return cmocka_run_group_tests(tests, setup, NULL);
}
