/* test_therm.c — the transient pack thermal model (paper §VI-G, eq.
 * hacool) and the winding resistance R_m(T) (paper §V-D).  Hand values in
 * the comments.
 */
#include "test_util.h"
#include "physics/therm.h"

static void
therm_hac_should_be_h_times_6_dm2_times_mass_ratio_to_two_thirds(void **state)
{
	(void)state;
	/* 838.5 g pack, h = 12: 12 · 0.06 · (838.5/2400)^(2/3) = 0.72 · 0.349375^(2/3)
	 *   = 0.72 · 0.496052775 = 0.357157998 W/K */
	assert_rel(therm_hac_w_k(0.8385, THERM_H_DEFAULT), 0.357157998, 1e-8);
	/* The 2400 g reference pack has 6 dm² of surface: 12 · 0.06 = 0.72 W/K */
	assert_rel(therm_hac_w_k(2.4, 12.0), 0.72, 1e-12);
	assert_rel(THERM_H_DEFAULT, 12.0, 0.0);
}

static void
therm_hac_should_be_scale_invariant_with_mass_to_two_thirds(void **state)
{
	(void)state;
	/* hA(8 m) / hA(m) = 8^(2/3) = 4 exactly, whatever m. */
	assert_rel(therm_hac_w_k(8.0 * 0.2385, 12.0) / therm_hac_w_k(0.2385, 12.0), 4.0, 1e-12);
	assert_rel(therm_hac_w_k(8.0 * 3.85, 12.0) / therm_hac_w_k(3.85, 12.0), 4.0, 1e-12);
	assert_rel(therm_hac_w_k(0.0, 12.0), 0.0, 0.0);
}

static void
therm_racing_cooling_should_use_h_120(void **state)
{
	(void)state;
	assert_rel(THERM_H_RACING, 120.0, 0.0);
	/* 120 · 0.06 · 0.496052775 = 3.57157998 W/K: ten times the default */
	assert_rel(therm_hac_w_k(0.8385, THERM_H_RACING), 3.57157998, 1e-8);
}

static void
therm_step_should_be_the_exact_exponential_solution(void **state)
{
	(void)state;
	/* 838.5 g pack at 31.5 °C in 23.85 °C air, 18.5 W of heat, 73.5 s:
	 * C_th = 0.8385 · 795 = 666.6075 J/K, hA = 0.357157998 W/K
	 * T_ss = 23.85 + 18.5/0.357157998 = 75.6478041 °C
	 * T = T_ss + (31.5 - T_ss) exp(-0.357157998 · 73.5 / 666.6075)
	 *   = 75.6478041 - 44.1478041 · exp(-0.0393801643)
	 *   = 75.6478041 - 44.1478041 · 0.961385093 = 33.2047606 °C */
	double hac = therm_hac_w_k(0.8385, 12.0);
	assert_rel(therm_step_c(31.5, 23.85, 18.5, hac, 0.8385, 73.5), 33.2047606, 1e-8);
	assert_rel(THERM_CP_J_KGK, 795.0, 0.0);
}

static void
therm_step_should_compose_like_the_exact_solution(void **state)
{
	(void)state;
	/* Two steps of dt/2 equal one step of dt: the exponential solution is
	 * exact, so the result does not depend on the step. */
	double hac = therm_hac_w_k(0.8385, 12.0);
	double one = therm_step_c(31.5, 23.85, 18.5, hac, 0.8385, 73.5);
	double half = therm_step_c(31.5, 23.85, 18.5, hac, 0.8385, 36.75);
	double two = therm_step_c(half, 23.85, 18.5, hac, 0.8385, 36.75);
	assert_rel(two, one, 1e-12);
}

static void
therm_step_should_settle_at_the_steady_state_for_a_huge_step(void **state)
{
	(void)state;
	double hac = therm_hac_w_k(0.8385, 12.0);
	/* T_ss = 23.85 + 18.5 / 0.357157998 = 75.64780406 °C, stable for any dt */
	assert_rel(therm_step_c(31.5, 23.85, 18.5, hac, 0.8385, 1e9), 75.64780406, 1e-9);
}

static void
therm_step_without_cooling_should_be_adiabatic(void **state)
{
	(void)state;
	/* hA = 0: T = 31.5 + 18.5 · 7.35 / 666.6075 = 31.5 + 0.203980 = 31.703980 °C */
	assert_rel(therm_step_c(31.5, 23.85, 18.5, 0.0, 0.8385, 7.35), 31.70398, 1e-7);
}

static void
therm_step_apply_should_equal_therm_step_c_step_after_step(void **state)
{
	(void)state;
	/* One decay factor for a run of steps of the same dt, as a discharge
	 * phase uses it: each step equals therm_step_c to the last bit, with
	 * cooling and without. */
	const double hacs[] = { therm_hac_w_k(0.8385, 12.0), 0.0 };
	for (size_t k = 0; k < 2; k++) {
		struct therm_step ts;
		therm_step_init(hacs[k], 0.8385, 7.35, &ts);
		double a = 31.5, b = 31.5;
		for (int i = 0; i < 5; i++) {
			double heat_w = 18.5 + 2.385 * i;
			a = therm_step_apply(&ts, a, 23.85, heat_w);
			b = therm_step_c(b, 23.85, heat_w, hacs[k], 0.8385, 7.35);
			assert_true(a == b);
		}
	}
}

static void
therm_winding_resistance_should_rise_with_alpha_cu(void **state)
{
	(void)state;
	/* 0.0385 Ω at 78.5 °C: 0.0385 (1 + 0.00393 · 53.5) = 0.0385 · 1.210255
	 *   = 0.0465948175 Ω */
	assert_rel(therm_winding_resistance_ohm(0.0385, 78.5), 0.0465948175, 1e-10);
	assert_rel(therm_winding_resistance_ohm(0.0385, 25.0), 0.0385, 1e-15);
	assert_rel(THERM_ALPHA_CU_PER_K, 0.00393, 0.0);
}

static void
therm_runaway_limit_should_be_60_c(void **state)
{
	(void)state;
	assert_rel(THERM_RUNAWAY_C, 60.0, 0.0);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(therm_hac_should_be_h_times_6_dm2_times_mass_ratio_to_two_thirds),
		cmocka_unit_test(therm_hac_should_be_scale_invariant_with_mass_to_two_thirds),
		cmocka_unit_test(therm_racing_cooling_should_use_h_120),
		cmocka_unit_test(therm_step_should_be_the_exact_exponential_solution),
		cmocka_unit_test(therm_step_should_compose_like_the_exact_solution),
		cmocka_unit_test(therm_step_should_settle_at_the_steady_state_for_a_huge_step),
		cmocka_unit_test(therm_step_without_cooling_should_be_adiabatic),
		cmocka_unit_test(therm_step_apply_should_equal_therm_step_c_step_after_step),
		cmocka_unit_test(therm_winding_resistance_should_rise_with_alpha_cu),
		cmocka_unit_test(therm_runaway_limit_should_be_60_c),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
