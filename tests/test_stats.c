/* test_stats.c — accuracy statistics, worked by hand on a 4-row cohort. */
#include "test_util.h"
#include "util/stats.h"

#include <stdlib.h>
#include <string.h>

/* The 4-row cohort (actual a, predicted p, kg) and its hand computation.
 *
 *  row  class             a      p      p - a    APE % = 100|p-a|/a      k = a/p
 *  1    ConsumerFolding   1.282  1.150  -0.132   13.2/1.282 = 10.29641   1.282/1.150 = 1.114783
 *  2    MicroAIO          0.580  0.640  +0.060    6.0/0.580 = 10.34483   0.580/0.640 = 0.906250
 *  3    EnterpriseRugged  2.385  2.100  -0.285   28.5/2.385 = 11.94969   2.385/2.100 = 1.135714
 *  4    EnterpriseRugged  5.831  6.400  +0.569   56.9/5.831 =  9.75819   5.831/6.400 = 0.911094
 *
 *  MAPE   = (10.29641 + 10.34483 + 11.94969 + 9.75819) / 4 = 42.34912 / 4 = 10.58728 %
 *  median = sorted APE 9.75819, 10.29641, 10.34483, 11.94969 -> (10.29641 + 10.34483) / 2
 *         = 10.32062 %
 *  RMSE   = sqrt((0.017424 + 0.0036 + 0.081225 + 0.323761) / 4) = sqrt(0.42601 / 4)
 *         = sqrt(0.1065025) = 0.3263472 kg
 *  k mean = (1.114783 + 0.906250 + 1.135714 + 0.911094) / 4 = 4.067841 / 4 = 1.016960
 *  k sd   = sqrt((0.0095692 + 0.0122567 + 0.0141025 + 0.0112077) / 3) = sqrt(0.0471362 / 3)
 *         = sqrt(0.0157121) = 0.125348
 *  groups = ConsumerFolding 10.29641 (1 row); EnterpriseRugged (11.94969 + 9.75819) / 2
 *         = 10.85394 (2 rows); MicroAIO 10.34483 (1 row)
 */
static const double A[4] = { 1.282, 0.580, 2.385, 5.831 };
static const double P[4] = { 1.150, 0.640, 2.100, 6.400 };
static const char *const CLS[4] = {
	"ConsumerFolding", "MicroAIO", "EnterpriseRugged", "EnterpriseRugged",
};

/* The hand values above carry 6-7 significant digits. */
#define HAND_TOL 2e-6

static void
stats_summary_should_match_the_hand_computation(void **state)
{
	(void)state;
	struct stats_summary s;
	assert_int_equal(stats_summarize(A, P, 4, &s), 0);
	assert_int_equal(s.n, 4);
	assert_rel(s.mape_pct, 10.58728, HAND_TOL);
	assert_rel(s.median_ape_pct, 10.32062, HAND_TOL);
	assert_rel(s.rmse_kg, 0.3263472, HAND_TOL);
	assert_rel(s.k_mean, 1.016960, HAND_TOL);
	assert_rel(s.k_sd, 0.125348, 1e-5);
}

static void
stats_summary_should_take_the_middle_value_for_odd_n(void **state)
{
	(void)state;
	struct stats_summary s;
	/* Rows 1-3: APE 10.29641, 10.34483, 11.94969 -> median 10.34483. */
	assert_int_equal(stats_summarize(A, P, 3, &s), 0);
	assert_rel(s.median_ape_pct, 10.34483, HAND_TOL);
	assert_rel(s.mape_pct, (10.29641 + 10.34483 + 11.94969) / 3, HAND_TOL);
}

static void
stats_summary_should_handle_zero_and_one_row_without_nan(void **state)
{
	(void)state;
	struct stats_summary s;
	assert_int_equal(stats_summarize(A, P, 0, &s), 0);
	assert_int_equal(s.n, 0);
	assert_true(s.mape_pct == 0 && s.median_ape_pct == 0 && s.rmse_kg == 0);
	assert_true(s.k_mean == 0 && s.k_sd == 0);

	assert_int_equal(stats_summarize(A + 2, P + 2, 1, &s), 0);
	assert_rel(s.mape_pct, 11.94969, HAND_TOL);
	assert_rel(s.median_ape_pct, 11.94969, HAND_TOL);
	assert_rel(s.rmse_kg, 0.285, 1e-12);
	assert_rel(s.k_mean, 1.135714, HAND_TOL);
	assert_true(s.k_sd == 0);
}

static void
stats_should_refuse_non_positive_and_non_finite_values(void **state)
{
	(void)state;
	const double bad_a[][2] = { { 1.2, 0.0 }, { 1.2, -0.5 }, { 1.2, NAN }, { INFINITY, 1 } };
	const double good[2] = { 1.1, 0.9 };
	for (size_t i = 0; i < 4; i++) {
		struct stats_summary s;
		double lo = 7, hi = 7, e[2] = { 7, 7 };
		struct stats_group *g = (struct stats_group *)&s;
		size_t ng = 7;
		static const char *const keys[2] = { "a", "b" };
		assert_int_equal(stats_summarize(bad_a[i], good, 2, &s), -1);
		assert_true(s.mape_pct == 0 && s.n == 0);
		assert_int_equal(stats_summarize(good, bad_a[i], 2, &s), -1);
		assert_int_equal(stats_bootstrap_mape_ci(good, bad_a[i], 2, 100, 1, &lo, &hi), -1);
		assert_true(lo == 0 && hi == 0);
		assert_int_equal(stats_signed_errors(bad_a[i], good, 2, e, NULL), -1);
		assert_true(e[0] == 0 && e[1] == 0);
		assert_int_equal(stats_group_mape(keys, good, bad_a[i], 2, &g, &ng), -1);
		assert_null(g);
		assert_int_equal(ng, 0);
	}
}

static void
stats_signed_errors_should_be_predicted_minus_actual(void **state)
{
	(void)state;
	double kg[4], pct[4];
	assert_int_equal(stats_signed_errors(A, P, 4, kg, pct), 0);
	assert_rel(kg[0], -0.132, 1e-12);
	assert_rel(kg[1], 0.060, 1e-12);
	assert_rel(kg[2], -0.285, 1e-12);
	assert_rel(kg[3], 0.569, 1e-12);
	assert_rel(pct[0], -10.29641, HAND_TOL);
	assert_rel(pct[1], 10.34483, HAND_TOL);
	assert_rel(pct[2], -11.94969, HAND_TOL);
	assert_rel(pct[3], 9.75819, HAND_TOL);
	assert_int_equal(stats_signed_errors(A, P, 4, NULL, pct), 0);
	assert_int_equal(stats_signed_errors(A, P, 0, NULL, NULL), 0);
}

static void
stats_group_mape_should_group_by_key_in_sorted_order(void **state)
{
	(void)state;
	struct stats_group *g;
	size_t ng;
	assert_int_equal(stats_group_mape(CLS, A, P, 4, &g, &ng), 0);
	assert_int_equal(ng, 3);
	assert_string_equal(g[0].key, "ConsumerFolding");
	assert_int_equal(g[0].n, 1);
	assert_rel(g[0].mape_pct, 10.29641, HAND_TOL);
	assert_string_equal(g[1].key, "EnterpriseRugged");
	assert_int_equal(g[1].n, 2);
	assert_rel(g[1].mape_pct, 10.85394, HAND_TOL);
	assert_string_equal(g[2].key, "MicroAIO");
	assert_int_equal(g[2].n, 1);
	assert_rel(g[2].mape_pct, 10.34483, HAND_TOL);
	assert_ptr_equal(g[1].key, CLS[2]); /* borrowed, not copied */
	free(g);

	assert_int_equal(stats_group_mape(CLS, A, P, 0, &g, &ng), 0);
	assert_null(g);
	assert_int_equal(ng, 0);
}

static void
stats_quantile_should_interpolate_between_order_statistics(void **state)
{
	(void)state;
	const double x[4] = { 9.75819, 10.29641, 10.34483, 11.94969 };
	/* h = 3 p.  p = 0.025: h = 0.075 -> 9.75819 + 0.075 * 0.53822. */
	assert_rel(stats_quantile_sorted(x, 4, 0.025), 9.75819 + 0.075 * 0.53822, 1e-12);
	/* p = 0.975: h = 2.925 -> 10.34483 + 0.925 * 1.60486. */
	assert_rel(stats_quantile_sorted(x, 4, 0.975), 10.34483 + 0.925 * 1.60486, 1e-12);
	assert_rel(stats_quantile_sorted(x, 4, 0.5), (10.29641 + 10.34483) / 2, 1e-12);
	assert_rel(stats_quantile_sorted(x, 4, 0), 9.75819, 0);
	assert_rel(stats_quantile_sorted(x, 4, 1), 11.94969, 0);
	assert_rel(stats_quantile_sorted(x, 4, 1.7), 11.94969, 0);
	assert_rel(stats_quantile_sorted(x, 4, NAN), 9.75819, 0);
	assert_rel(stats_quantile_sorted(x, 1, 0.3), 9.75819, 0);
	assert_true(stats_quantile_sorted(x, 0, 0.5) == 0);
}

static void
stats_rng_should_follow_the_published_xoshiro_sequence(void **state)
{
	(void)state;
	/* splitmix64 from 0 gives 0xe220a8397b1dcdaf first (Vigna's reference
	 * splitmix64.c); xoshiro256** from that state gives 0x99ec5f36cb75f2b4. */
	struct stats_rng r;
	stats_rng_seed(&r, 0);
	assert_true(r.s[0] == 0xe220a8397b1dcdafu);
	assert_true(stats_rng_next(&r) == 0x99ec5f36cb75f2b4u);
	assert_true(stats_rng_next(&r) == 0xbf6e1f784956452au);
}

static void
stats_rng_below_should_be_bounded_and_roughly_uniform(void **state)
{
	(void)state;
	struct stats_rng r;
	size_t hist[7] = { 0 };
	stats_rng_seed(&r, 20261122);
	for (int i = 0; i < 70000; i++) {
		uint64_t v = stats_rng_below(&r, 7);
		assert_true(v < 7);
		hist[v]++;
	}
	/* Expected 10000 each, sd about 93: 500 is more than 5 sd. */
	for (int i = 0; i < 7; i++)
		assert_true(hist[i] > 9500 && hist[i] < 10500);
	assert_true(stats_rng_below(&r, 0) == 0);
	assert_true(stats_rng_below(&r, 1) == 0);
}

/* The top 53 bits over 2^53: a draw whose bits are known maps to its
 * value exactly, and draws fill [lo, hi) evenly. */
static void
stats_rng_uniform_should_scale_the_top_53_bits_into_the_range(void **state)
{
	(void)state;
	struct stats_rng r, copy;
	stats_rng_seed(&r, 20261202);
	copy = r;
	uint64_t bits = stats_rng_next(&copy) >> 11;
	assert_true(stats_rng_uniform(&r, -2.0, 6.0)
	    == -2.0 + 8.0 * ((double)bits / 9007199254740992.0));
	size_t hist[8] = { 0 };
	for (int i = 0; i < 80000; i++) {
		double v = stats_rng_uniform(&r, -2.0, 6.0);
		assert_true(v >= -2.0 && v < 6.0);
		hist[(int)(v + 2.0)]++;
	}
	/* Expected 10000 each, sd about 94: 500 is more than 5 sd. */
	for (int i = 0; i < 8; i++)
		assert_true(hist[i] > 9500 && hist[i] < 10500);
}

static void
stats_bootstrap_should_bracket_the_mape_and_repeat_from_its_seed(void **state)
{
	(void)state;
	double lo, hi, lo2, hi2;
	assert_int_equal(stats_bootstrap_mape_ci(A, P, 4, 4000, 42, &lo, &hi), 0);
	/* A resample's MAPE lies between the smallest and the largest APE. */
	assert_true(lo >= 9.75819 - 1e-5 && hi <= 11.94969 + 1e-5);
	assert_true(lo < 10.58728 && 10.58728 < hi);
	/* With four rows the extremes are reachable (all four draws of one
	 * row: 4 * 0.25^4 = 1.6 % of resamples), so the 2.5 % quantile sits
	 * just above 9.76 %, within the two smallest APEs. */
	assert_true(lo < 10.29641 && hi > 10.34483);
	assert_int_equal(stats_bootstrap_mape_ci(A, P, 4, 4000, 42, &lo2, &hi2), 0);
	assert_true(lo == lo2 && hi == hi2);

	/* Four rows give only 35 distinct resample MAPEs, so nearby seeds
	 * often agree.  Twelve rows with spread-out errors do not. */
	double a12[12], p12[12];
	for (int i = 0; i < 12; i++) {
		a12[i] = 0.615 + 0.437 * i;
		p12[i] = a12[i] * (1.0 + 0.0173 * ((i * 7) % 13 - 6));
	}
	assert_int_equal(stats_bootstrap_mape_ci(a12, p12, 12, 2000, 42, &lo, &hi), 0);
	assert_int_equal(stats_bootstrap_mape_ci(a12, p12, 12, 2000, 43, &lo2, &hi2), 0);
	assert_true(lo != lo2 || hi != hi2);
	assert_true(lo < hi);
}

static void
stats_bootstrap_should_collapse_for_tiny_inputs(void **state)
{
	(void)state;
	double lo = 7, hi = 7;
	assert_int_equal(stats_bootstrap_mape_ci(A, P, 0, 1000, 1, &lo, &hi), 0);
	assert_true(lo == 0 && hi == 0);
	assert_int_equal(stats_bootstrap_mape_ci(A + 1, P + 1, 1, 1000, 1, &lo, &hi), 0);
	assert_rel(lo, 10.34483, HAND_TOL);
	assert_rel(hi, 10.34483, HAND_TOL);
	assert_int_equal(stats_bootstrap_mape_ci(A, P, 4, 0, 1, &lo, &hi), 0);
	assert_rel(lo, 10.58728, HAND_TOL);
	assert_rel(hi, 10.58728, HAND_TOL);
	/* Equal APEs: every resample has the same MAPE (20 %). */
	const double a2[3] = { 1.0, 2.5, 4.0 }, p2[3] = { 1.2, 2.0, 4.8 };
	assert_int_equal(stats_bootstrap_mape_ci(a2, p2, 3, 500, 9, &lo, &hi), 0);
	assert_rel(lo, 20.0, 1e-12);
	assert_rel(hi, 20.0, 1e-12);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(stats_summary_should_match_the_hand_computation),
		cmocka_unit_test(stats_summary_should_take_the_middle_value_for_odd_n),
		cmocka_unit_test(stats_summary_should_handle_zero_and_one_row_without_nan),
		cmocka_unit_test(stats_should_refuse_non_positive_and_non_finite_values),
		cmocka_unit_test(stats_signed_errors_should_be_predicted_minus_actual),
		cmocka_unit_test(stats_group_mape_should_group_by_key_in_sorted_order),
		cmocka_unit_test(stats_quantile_should_interpolate_between_order_statistics),
		cmocka_unit_test(stats_rng_should_follow_the_published_xoshiro_sequence),
		cmocka_unit_test(stats_rng_below_should_be_bounded_and_roughly_uniform),
		cmocka_unit_test(stats_rng_uniform_should_scale_the_top_53_bits_into_the_range),
		cmocka_unit_test(stats_bootstrap_should_bracket_the_mape_and_repeat_from_its_seed),
		cmocka_unit_test(stats_bootstrap_should_collapse_for_tiny_inputs),
	};
	return cmocka_run_group_tests_name("stats", tests, NULL, NULL);
}
