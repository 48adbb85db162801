/* test_calibrate.c — the coefficient fit of `aeroeval calibrate`. */
#include "test_util.h"
#include "study/calibrate.h"

#include <stdlib.h>
#include <string.h>

#include "util/lsq.h"
#include "input/cohort.h"
#include "diag/diag.h"
#include "input/model_io.h"
#include "study/validate.h"
#include "engine/engine.h"

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
	for (int k = 0; k < AF_CLASS_MAX; k++)
		assert_rel(out.equip_kg[k], md.cal.equip_kg[k], 1e-15);
	assert_rel(out.kappa, md.cal.kappa, 1e-15);
	assert_rel(out.eta_drive, md.cal.eta_drive, 1e-15);
	assert_rel(out.re_ref, md.cal.re_ref, 1e-15);
	assert_rel(out.aux_scale, md.cal.aux_scale, 1e-15);
	assert_rel(out.drag_scale, md.cal.drag_scale, 1e-15);
	assert_rel(out.wake_share, md.cal.wake_share, 1e-12);
	assert_rel(out.equip_exponent, md.cal.equip_exponent, 1e-15);
	assert_rel(out.wire_coef_small, md.cal.wire_coef_small, 1e-12);
	th[CAL_WIRE_COEF] *= 2;
	calibrate_apply(th, &md.cal, &out);
	assert_rel(out.wire_coef, 2 * md.cal.wire_coef, 1e-15);
	assert_rel(out.wire_coef_small, 2 * md.cal.wire_coef_small, 1e-12);
	/* The priors of the paper's coefficients are the paper's: eq.
	 * (lambda), §IV-F (κ 1.2, the consumer class's, inside the rotor
	 * literature's 1.1-1.3), the Reynolds fit's 20 000, §V-C (C_wire). */
	const double lambda[LAMBDA_MAX] = { 1.50, 1.08, 0.95, 0.80, 1.00 };
	for (int j = 0; j < LAMBDA_MAX; j++)
		assert_rel(calibrate_prior[CAL_LAMBDA_MICRO + j], lambda[j], 1e-15);
	assert_rel(calibrate_prior[CAL_KAPPA], 1.20, 1e-15);
	assert_true(calibrate_lo[CAL_KAPPA] >= 1.1 && calibrate_hi[CAL_KAPPA] <= 1.35);
	assert_true(calibrate_hi[CAL_ETA_DRIVE] < 1.0);
	assert_rel(calibrate_prior[CAL_RE_REF], 20000.0, 1e-15);
	assert_rel(calibrate_prior[CAL_WIRE_COEF], 0.0015, 1e-15);
}

/* Split conformal: with n residuals, the floor((n+1)·0.05)-th smallest and
 * the ceil((n+1)·0.95)-th smallest bound a 90 % interval. */
static void
conformal_should_pick_the_order_statistics_of_the_level(void **state)
{
	(void)state;
	double r[39];
	/* -0.38 .. +0.38 in steps of 0.02, shuffled by a stride. */
	for (int i = 0; i < 39; i++)
		r[(i * 7) % 39] = -0.38 + 0.02 * i;
	double lo, hi;
	/* n = 39: k_lo = floor(40 · 0.05) = 2, k_hi = ceil(40 · 0.95) = 38. */
	assert_true(calibrate_conformal(r, 39, 0.90, &lo, &hi));
	assert_rel(lo, -0.36, 1e-12);
	assert_rel(hi, 0.36, 1e-12);
	/* n = 19 is the smallest with finite bounds: the extremes. */
	for (int i = 0; i < 19; i++)
		r[i] = 0.01 * (double)(i + 1);
	assert_true(calibrate_conformal(r, 19, 0.90, &lo, &hi));
	assert_rel(hi, 0.19, 1e-12);
	assert_true(lo == 0.0);   /* the interval always holds the prediction */
	assert_false(calibrate_conformal(r, 18, 0.90, &lo, &hi));
	assert_false(calibrate_conformal(r, 0, 0.90, &lo, &hi));
}

/* What a progress callback saw. */
struct seen {
	size_t calls, last_solves, max_stage;
};

static void
count_progress(void *ctx, size_t stage, size_t done, size_t n_rows, size_t n_solves)
{
	struct seen *s = ctx;
	assert_true(done <= n_rows);
	assert_true(n_solves >= s->last_solves);
	if (stage > s->max_stage)
		s->max_stage = stage;
	s->calls++;
	s->last_solves = n_solves;
}

/* data/calibration.json is the frozen fit: calibrating the project's
 * calibration cohort again from the priors lands on the shipped numbers,
 * coefficients with fewer than CALIBRATE_MIN_ROWS rows (and the fixed
 * ones: λ, the equipment exponent) keep their priors, and the shipped file
 * carries the leave-one-out accuracy of both battery bases, the forward
 * check and the dry mass. */
static void
shipped_calibration_should_be_the_fit_on_the_calibration_cohort(void **state)
{
	(void)state;
	struct cohort c;
	assert_int_equal(cohort_load("data/cohorts/calibration.csv", &c), 0);
	struct model_data start = md;
	calibrate_apply(calibrate_prior, &md.cal, &start.cal);
	struct calibrate_result r;
	struct seen seen = { 0 };
	struct calibrate_progress pg = { count_progress, &seen };
	assert_int_equal(calibrate_fit(&c, &start, false, &pg, &r), 0);
	assert_true(seen.calls > r.n_iter);
	assert_int_equal(seen.max_stage, 0);   /* no leave-one-out asked */
	assert_null(r.loo);
	double shipped[CAL_N_PARAMS];
	calibrate_theta(&md.cal, shipped);
	for (int j = 0; j < CAL_N_PARAMS; j++) {
		assert_rel(r.theta[j], shipped[j], 1e-3);
		if (r.n_per_param[j] < CALIBRATE_MIN_ROWS || calibrate_lo[j] == calibrate_hi[j])
			assert_rel(r.theta[j], calibrate_prior[j], 1e-12);
	}
	assert_true(r.forward_after_pct < r.forward_before_pct);
	assert_true(r.dry_after_pct < r.dry_before_pct);
	assert_true(r.n_rows >= 30);
	assert_true(r.n_forward >= 30);
	assert_true(r.n_dry >= 20);
	const struct model_spread *sp[] = { &md.cal.forward, &md.cal.dry };
	for (int i = 0; i < 2; i++) {
		assert_true(sp[i]->valid);
		assert_true(sp[i]->n >= 19);
		assert_true(sp[i]->log_lo <= 0.0 && sp[i]->log_hi >= 0.0);
		assert_true(sp[i]->coverage >= CALIBRATE_LEVEL - 0.05);
	}
	for (int b = 0; b < MODEL_BASIS_MAX; b++) {
		const struct model_accuracy *a = &md.cal.accuracy[b];
		assert_true(a->valid);
		assert_true(a->n_rows >= 19 && (size_t)a->n_rows <= r.n_rows);
		assert_true(a->pooled.log_lo <= 0.0 && a->pooled.log_hi >= 0.0);
		assert_true(a->coverage >= a->level);
	}
	calibrate_result_free(&r);
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

/* Eight rows: "real" aircraft sized by tables truth, so each real mass is
 * a fixed point of truth, with their battery masses published. */
static void
synthetic(const struct model_data *truth, struct calibrate_row *rows)
{
	struct mission_spec s[N_SYN];
	mission(&s[0], AF_CONSUMER_FOLDING, 4, 0.30, 0.2, 20, ROLE_IMAGING);
	mission(&s[1], AF_CONSUMER_FOLDING, 4, 0.45, 0.6, 12, ROLE_IMAGING);
	mission(&s[2], AF_CONSUMER_FOLDING, 4, 0.50, 1.0, 12, ROLE_IMAGING);
	mission(&s[3], AF_CONSUMER_FOLDING, 6, 0.50, 0.5, 12, ROLE_IMAGING);
	mission(&s[4], AF_ENTERPRISE_RUGGED, 4, 0.90, 2.0, 15, ROLE_INSPECTION);
	mission(&s[5], AF_ENTERPRISE_RUGGED, 6, 1.00, 5.0, 20, ROLE_MAPPING);
	mission(&s[6], AF_ENTERPRISE_RUGGED, 8, 1.20, 5.0, 15, ROLE_IMAGING);
	mission(&s[7], AF_MICRO_AIO, 4, 0.25, 0.15, 8, ROLE_IMAGING);
	struct solve_result *work = malloc(sizeof *work);
	for (int i = 0; i < N_SYN; i++) {
		struct validate_row vr;
		memset(&vr, 0, sizeof vr);
		validate_solve_row(&s[i], truth, work, &vr);
		assert_int_equal(vr.status, VALIDATE_ROW_OK);
		memset(&rows[i], 0, sizeof rows[i]);
		rows[i].spec = s[i];
		rows[i].sized = true;
		rows[i].actual_kg = vr.predicted_kg;
		rows[i].battery_kg = vr.battery_pred_kg;
		/* Its pack published, and the endurance truth gives it to an
		 * empty pack in hover and at 8 m/s: the maker's figures. */
		struct mission_spec *ps = &rows[i].pack_spec;
		*ps = s[i];
		ps->locks.is_battery_locked = true;
		ps->locks.locked_cell_count = vr.cells;
		ps->locks.locked_capacity_mah = vr.capacity_mah;
		ps->given[SPECF_LOCK_BATTERY] = ps->given[SPECF_LOCK_CELL_COUNT] = true;
		ps->given[SPECF_LOCK_CAPACITY_MAH] = true;
		rows[i].has_pack = true;
		rows[i].cruise_ms = 8.0;
		struct sizing_endurance e;
		assert_true(engine_endurance_at_mass(ps, truth, vr.predicted_kg, 1.0,
		    rows[i].cruise_ms, &e));
		rows[i].hover_s = e.hover_s;
		rows[i].max_flight_s = e.forward_s;
	}
	free(work);
}

/* Rows sized with known coefficients serve as the real aircraft; the
 * open-loop fit, started from the priors, finds those coefficients again
 * (only the four consumer rows inform the consumer ones). */
static void
fit_should_recover_known_coefficients_from_a_synthetic_cohort(void **state)
{
	(void)state;
	struct model_data truth = md;
	calibrate_apply(calibrate_prior, &md.cal, &truth.cal);
	truth.cal.equip_kg[AF_CONSUMER_FOLDING] = 0.20;
	truth.cal.eta_drive = 0.78;
	truth.cal.drag_scale = 1.5;
	struct calibrate_row rows[N_SYN];
	synthetic(&truth, rows);

	struct model_data start = md;
	calibrate_apply(calibrate_prior, &md.cal, &start.cal);
	struct calibrate_result r;
	/* A negligible prior, so the data alone decide. */
	assert_int_equal(calibrate_fit_rows(rows, N_SYN, &start, 1e-8, &r), 0);
	assert_int_equal(r.n_rows, N_SYN);
	assert_rel(r.theta[CAL_EQUIP_CONSUMER], 0.20, 0.01);
	assert_rel(r.after.equip_kg[AF_CONSUMER_FOLDING], 0.20, 0.01);
	/* κ and η share the hover power (P = P_ideal / (FoM η)): the fit
	 * finds their product, and the forward check's residuals vanish. */
	assert_rel(r.theta[CAL_ETA_DRIVE] / r.theta[CAL_KAPPA], 0.78 / 1.20, 0.01);
	assert_true(r.forward_after_pct < 0.5);
	assert_true(r.forward_after_pct < 0.1 * r.forward_before_pct);
	assert_true(r.dry_after_pct < 0.1 * r.dry_before_pct);
	assert_int_equal(r.n_per_param[CAL_EQUIP_CONSUMER], 4);
	assert_int_equal(r.n_per_param[CAL_EQUIP_ENTERPRISE], 3);
	assert_int_equal(r.n_per_param[CAL_EQUIP_MICRO], 1);
	assert_int_equal(r.n_per_param[CAL_EQUIP_AGRI], 0);
	/* One row is too few: held exactly; no row: the prior. */
	assert_true(r.theta[CAL_EQUIP_MICRO] == start.cal.equip_kg[AF_MICRO_AIO]);
	assert_rel(r.theta[CAL_EQUIP_AGRI], calibrate_prior[CAL_EQUIP_AGRI], 1e-12);
	calibrate_result_free(&r);
}

/* With the production prior weight every coefficient stays in its bounds,
 * even when the "real" aircraft are three times the model's. */
static void
fit_should_respect_bounds(void **state)
{
	(void)state;
	struct model_data start = md;
	calibrate_apply(calibrate_prior, &md.cal, &start.cal);
	struct calibrate_row rows[N_SYN];
	synthetic(&start, rows);
	for (int i = 0; i < N_SYN; i++) {
		rows[i].actual_kg *= 3.0;
		rows[i].battery_kg = 0.0;
	}
	struct calibrate_result r;
	assert_int_equal(calibrate_fit_rows(rows, N_SYN, &start, CALIBRATE_MU, &r), 0);
	for (int j = 0; j < CAL_N_PARAMS; j++) {
		assert_true(r.theta[j] >= calibrate_lo[j]);
		assert_true(r.theta[j] <= calibrate_hi[j]);
	}
	assert_true(r.dry_after_pct <= r.dry_before_pct);
	calibrate_result_free(&r);
}

static void
fit_should_refuse_a_cohort_without_usable_rows(void **state)
{
	(void)state;
	struct cohort c;
	memset(&c, 0, sizeof c);
	struct calibrate_result r;
	assert_int_equal(calibrate_fit(&c, &md, false, NULL, &r), -1);
	assert_int_equal(r.n_rows, 0);
	calibrate_result_free(&r);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(theta_should_round_trip_and_keep_the_small_wiring_ratio),
		cmocka_unit_test(conformal_should_pick_the_order_statistics_of_the_level),
		cmocka_unit_test(shipped_calibration_should_be_the_fit_on_the_calibration_cohort),
		cmocka_unit_test(fit_should_recover_known_coefficients_from_a_synthetic_cohort),
		cmocka_unit_test(fit_should_respect_bounds),
		cmocka_unit_test(fit_should_refuse_a_cohort_without_usable_rows),
	};
	return cmocka_run_group_tests(tests, setup, NULL);
}
