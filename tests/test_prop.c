/* test_prop.c — the propeller's advance-ratio model (physics/prop.h):
 * C_T(J) and C_P(J) from the static coefficients and the pitch over
 * diameter.  Hand values in the comments; "high entropy" inputs.  The
 * static coefficients themselves are tested in test_motor.c. */
#include "test_util.h"

#include "physics/prop.h"

/* A propeller of P/D 0.4385: J0 = 1.15 · 0.4385 = 0.504275. */
#define PD   0.4385
#define J0   0.504275

static void
prop_j0_should_be_k_times_the_pitch_over_diameter(void **state)
{
	(void)state;
	assert_rel(prop_j0(PD), J0, 1e-12);
	/* No pitch known: no zero-thrust advance ratio, and no decline. */
	assert_rel(prop_j0(0.0), 0.0, 0.0);
	assert_rel(prop_j0(-0.3), 0.0, 0.0);
	assert_rel(prop_ct_ratio(0.2385, 0.0), 1.0, 0.0);
	assert_rel(prop_cp_ratio(0.2385, 0.0), 1.0, 0.0);
}

/* C_T(0) = C_T0, C_T(J0) = 0, and at J = 0.2385: x = 0.2385 / 0.504275 =
 * 0.472956224, C_T/C_T0 = 1 - 0.35 x - 0.65 x² = 1 - 0.165534678
 * - 0.145396934 = 0.689068388. */
static void
prop_thrust_should_fall_from_static_to_zero_at_j0(void **state)
{
	(void)state;
	assert_rel(prop_ct_ratio(0.0, J0), 1.0, 0.0);
	assert_true(fabs(prop_ct_ratio(J0, J0)) < 1e-15);
	assert_rel(prop_ct_ratio(0.2385, J0), 0.689068388, 1e-8);
	/* A descent is not modelled: static. */
	assert_rel(prop_ct_ratio(-0.1, J0), 1.0, 0.0);
	/* Past J0 the propeller windmills: negative thrust. */
	assert_true(prop_ct_ratio(1.1 * J0, J0) < 0.0);
}

/* Monotone decline over [0, J0], and steeper towards J0 (the slope
 * -0.35 - 1.3 x, from -0.35 / J0 at rest to -1.65 / J0 at J0). */
static void
prop_thrust_should_decline_monotonically_and_steepen(void **state)
{
	(void)state;
	double prev = prop_ct_ratio(0.0, J0), prev_drop = 0.0;
	for (int i = 1; i <= 200; i++) {
		double j = J0 * (double)i / 200.0;
		double ct = prop_ct_ratio(j, J0);
		double drop = prev - ct;
		assert_true(drop > 0.0);
		assert_true(drop > prev_drop);
		prev = ct;
		prev_drop = drop;
	}
	assert_rel(prop_ct_ratio(J0 * 1e-6, J0), 1.0 - 0.35e-6, 1e-9);
}

/* C_P(0) = C_P0, C_P(J0) = (1 - 0.55) C_P0 = 0.45 C_P0, and at J = 0.2385
 * 1 - 0.55 · 0.223687 = 0.876971825; it declines monotonically, stays
 * positive to J0, and above the thrust's ratio (a propeller unloads its
 * motor more slowly than it loses thrust), so the propulsive efficiency
 * J C_T / C_P rises from 0 at rest and falls back to 0 at J0. */
static void
prop_power_should_fall_more_slowly_than_thrust(void **state)
{
	(void)state;
	assert_rel(prop_cp_ratio(0.0, J0), 1.0, 0.0);
	assert_rel(prop_cp_ratio(J0, J0), 0.45, 1e-12);
	assert_rel(prop_cp_ratio(0.2385, J0), 0.876971825, 1e-8);
	double prev = 1.0, eta_max = 0.0;
	for (int i = 1; i <= 200; i++) {
		double j = J0 * (double)i / 200.0;
		double cp = prop_cp_ratio(j, J0);
		double ct = prop_ct_ratio(j, J0);
		assert_true(cp < prev);
		assert_true(cp > 0.0);
		assert_true(cp >= ct);
		double eta = j * ct / cp;
		if (eta > eta_max)
			eta_max = eta;
		prev = cp;
	}
	assert_true(eta_max > 0.0);
	assert_true(fabs(J0 * prop_ct_ratio(J0, J0) / prop_cp_ratio(J0, J0)) < 1e-14);
}

/* J = V / (n D): 12.85 m/s at 58.5 rev/s on 0.6604 m is 0.332613749; the
 * zero-thrust speed J0 n D = 0.504275 · 58.5 · 0.6604 = 19.4818578 m/s. */
static void
prop_advance_ratio_should_be_the_advance_per_turn_over_diameter(void **state)
{
	(void)state;
	assert_rel(prop_advance_ratio(12.85, 58.5, 0.6604), 0.332613749, 1e-8);
	assert_rel(prop_advance_ratio(0.0, 58.5, 0.6604), 0.0, 0.0);
	assert_rel(prop_advance_ratio(12.85, 0.0, 0.6604), 0.0, 0.0);
	assert_rel(prop_zero_thrust_speed_ms(J0, 58.5, 0.6604), 19.4818578, 1e-8);
	assert_true(fabs(prop_ct_ratio(prop_advance_ratio(19.4818578, 58.5,
	    0.6604), J0)) < 1e-8);
}

/* The model against its source: the UIUC Propeller Database's APC 9x4.7
 * Slow Flyer run (apcsf_9x4.7_kt1033_4008, P/D 0.5222: J0 = 0.600556),
 * with the run's least-squares static values C_T0 0.1078, C_P0 0.0507
 * (prop.c).  Its measured zero thrust is at J 0.600. */
static void
prop_model_should_follow_the_uiuc_9x4_7_run(void **state)
{
	(void)state;
	static const double run[][3] = {   /* J, C_T, C_P measured */
		{ 0.162, 0.0936, 0.0465 },
		{ 0.330, 0.0654, 0.0421 },
		{ 0.488, 0.0306, 0.0339 },
		{ 0.600, 0.0000, 0.0254 },
	};
	double j0 = prop_j0(4.7 / 9.0);
	assert_rel(j0, 0.6005556, 1e-6);
	for (size_t i = 0; i < sizeof run / sizeof run[0]; i++) {
		double ct = 0.1078 * prop_ct_ratio(run[i][0], j0);
		double cp = 0.0507 * prop_cp_ratio(run[i][0], j0);
		assert_true(fabs(ct - run[i][1]) < 0.0012);
		assert_true(fabs(cp - run[i][2]) < 0.11 * run[i][2]);
	}
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(prop_j0_should_be_k_times_the_pitch_over_diameter),
		cmocka_unit_test(prop_thrust_should_fall_from_static_to_zero_at_j0),
		cmocka_unit_test(prop_thrust_should_decline_monotonically_and_steepen),
		cmocka_unit_test(prop_power_should_fall_more_slowly_than_thrust),
		cmocka_unit_test(prop_advance_ratio_should_be_the_advance_per_turn_over_diameter),
		cmocka_unit_test(prop_model_should_follow_the_uiuc_9x4_7_run),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
