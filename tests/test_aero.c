/* test_aero.c — rotor aerodynamics against paper §IV (overlap, downwash,
 * momentum theory, Glauert, eq. cdre, installed FoM, interference, profile
 * power).  Every expected value is worked by hand from the paper's
 * equations; the arithmetic is in the comment next to it.
 *
 * Common rotor of the hand cases: D = 0.2385 m,
 * A = π D²/4 = π · 0.05688225 / 4 = 0.04467521468 m², ρ = 1.1895 kg/m³,
 * T = 7.385 N, so T/(2 ρ A) = 7.385 / 0.10628133 = 69.48473563 m²/s²
 * and v_h = sqrt(69.48473563) = 8.335750454 m/s.
 */
#include "test_util.h"
#include "physics/aero.h"
#include "physics/atmo.h"
#include "util/units.h"

#define D_HAND   0.2385
#define A_HAND   0.04467521468
#define RHO_HAND 1.1895
#define T_HAND   7.385
#define VH2_HAND 69.48473563
#define VH_HAND  8.335750454

/* ---- eq. (overlap) -------------------------------------------------------- */

static void
aero_overlap_limit_should_be_0_672_w_for_a_quad(void **state)
{
	(void)state;
	/* D ≤ 0.95 · 1.235 · sin(π/4) = 0.95 · 1.235 · 0.70710678 = 0.82961303 m
	 * (0.67175 W, the paper's 0.672 W) */
	assert_rel(aero_overlap_limit_m(1.235, 4, AERO_TIP_CLEARANCE), 0.82961303, 1e-8);
	assert_rel(aero_overlap_limit_m(1.0, 4, AERO_TIP_CLEARANCE), 0.672, 1e-3);
}

static void
aero_overlap_limit_should_be_0_475_w_for_a_hex(void **state)
{
	(void)state;
	/* 0.95 · 1.235 · sin(π/6) = 0.95 · 1.235 · 0.5 = 0.586625 m */
	assert_rel(aero_overlap_limit_m(1.235, 6, AERO_TIP_CLEARANCE), 0.586625, 1e-12);
	assert_rel(aero_overlap_limit_m(1.0, 6, AERO_TIP_CLEARANCE), 0.475, 1e-3);
}

static void
aero_overlap_limit_should_be_0_364_w_for_an_octo(void **state)
{
	(void)state;
	/* 0.95 · 1.235 · sin(π/8) = 0.95 · 1.235 · 0.38268343 = 0.44898334 m */
	assert_rel(aero_overlap_limit_m(1.235, 8, AERO_TIP_CLEARANCE), 0.44898334, 1e-8);
	/* 0.95 · 0.38268343 = 0.36354926, which the paper rounds to 0.364 */
	assert_rel(aero_overlap_limit_m(1.0, 8, AERO_TIP_CLEARANCE), 0.364, 2e-3);
}

static void
aero_overlap_limit_of_a_coaxial_x8_should_use_four_arms(void **state)
{
	(void)state;
	/* Coaxial: N_arms = N_r / 2 = 4, so the X8 gets the quad limit 0.82961303 m,
	 * not the octo's 0.44898334 m. */
	int n_rotors = 8;
	assert_rel(aero_overlap_limit_m(1.235, n_rotors / 2, AERO_TIP_CLEARANCE),
	    0.82961303, 1e-8);
	assert_rel(AERO_TIP_CLEARANCE, 0.05, 0.0);
}

/* ---- momentum theory ---------------------------------------------------- */

static void
aero_hover_induced_velocity_should_be_sqrt_t_over_2_rho_a(void **state)
{
	(void)state;
	/* v_i = sqrt(7.385 / (2 · 1.1895 · 0.04467521468)) = sqrt(69.48473563)
	 *     = 8.335750454 m/s */
	assert_rel(aero_hover_induced_ms(T_HAND, RHO_HAND, A_HAND), VH_HAND, 1e-9);
	assert_rel(aero_hover_induced_ms(0.0, RHO_HAND, A_HAND), 0.0, 0.0);
}

static void
aero_climb_induced_velocity_should_solve_momentum_in_axial_climb(void **state)
{
	(void)state;
	/* v_i = -Vc/2 + sqrt((Vc/2)² + v_h²), Vc = 2.85:
	 *     = -1.425 + sqrt(2.030625 + 69.48473563) = -1.425 + sqrt(71.51536063)
	 *     = -1.425 + 8.456675507 = 7.031675507 m/s */
	double v = aero_climb_induced_ms(T_HAND, RHO_HAND, A_HAND, 2.85);
	assert_rel(v, 7.031675507, 1e-9);
	/* It satisfies T = 2 ρ A (Vc + v) v. */
	assert_rel(2.0 * RHO_HAND * A_HAND * (2.85 + v) * v, T_HAND, 1e-12);
}

static void
aero_glauert_should_solve_the_implicit_relation_to_1e_10(void **state)
{
	(void)state;
	int iter = -1;
	double v_inf = 8.35;
	double v = aero_glauert_induced_ms(T_HAND, RHO_HAND, A_HAND, v_inf, &iter);
	/* v sqrt(V² + v²) = T/(2 ρ A): residual relative to the right side. */
	double resid = v * sqrt(v_inf * v_inf + v * v) - VH2_HAND;
	assert_true(fabs(resid) <= 1e-10 * VH2_HAND);
	/* By hand: v⁴ + V² v² - v_h⁴ = 0, a quadratic in v²:
	 * v² = (-V² + sqrt(V⁴ + 4 v_h⁴)) / 2
	 *    = (-69.7225 + sqrt(4861.2270 + 19312.3335)) / 2
	 *    = (-69.7225 + 155.4784) / 2 = 42.8779...; v = 6.548151234 m/s */
	assert_rel(v, 6.548151234, 1e-9);
	assert_true(iter >= 1 && iter <= 60);
}

static void
aero_glauert_should_reduce_to_hover_at_zero_speed(void **state)
{
	(void)state;
	double v = aero_glauert_induced_ms(T_HAND, RHO_HAND, A_HAND, 0.0, NULL);
	assert_rel(v, VH_HAND, 1e-9);
}

static void
aero_glauert_should_stay_finite_and_positive_at_high_speed(void **state)
{
	(void)state;
	/* V = 238.5 m/s ≫ v_h: v ≈ v_h²/V = 69.48473563 / 238.5 = 0.29134 m/s */
	double v = aero_glauert_induced_ms(T_HAND, RHO_HAND, A_HAND, 238.5, NULL);
	assert_true(isfinite(v) && v > 0.0);
	assert_rel(v, 0.29134, 1e-4);
}

/* ---- eq. (cdre) ---------------------------------------------------------- */

static void
aero_cd0_should_use_the_square_root_branch_below_1e5(void **state)
{
	(void)state;
	/* 0.012 (1e5 / 62385)^0.5 = 0.012 · 1.602949427^0.5 = 0.012 · 1.266076391
	 *   = 0.0151929167 */
	assert_rel(aero_cd0(62385.0), 0.0151929167, 1e-9);
}

static void
aero_cd0_should_use_the_fifth_root_branch_above_1e5(void **state)
{
	(void)state;
	/* 0.012 (1e5 / 238500)^0.2 = 0.012 · 0.419287212^0.2 = 0.012 · 0.840431503
	 *   = 0.010085178 */
	assert_rel(aero_cd0(238500.0), 0.010085178, 1e-8);
}

static void
aero_cd0_should_be_continuous_at_1e5(void **state)
{
	(void)state;
	/* Both branches give 0.012 · 1 = 0.012 at Re = 1e5. */
	assert_rel(aero_cd0(1e5), 0.012, 1e-15);
	assert_rel(aero_cd0(1e5 * (1.0 - 1e-9)), 0.012, 1e-9);
	assert_rel(aero_cd0(1e5 * (1.0 + 1e-9)), 0.012, 1e-9);
}

/* ---- installed figure of merit --------------------------------------- */

static void
aero_fom_installed_should_divide_by_kappa_and_apply_the_reynolds_fit(void **state)
{
	(void)state;
	/* 0.72 / 1.25 · (1 - exp(-38500/20000)) = 0.576 · (1 - exp(-1.925))
	 *   = 0.576 · (1 - 0.145875756) = 0.576 · 0.854124244 = 0.491975564 */
	assert_rel(aero_fom_installed(0.72, 1.25, false, 38500.0, 0.0), 0.491975564, 1e-9);
	assert_rel(aero_fom_installed(0.72, 1.25, false, 38500.0, AERO_RE_REF),
	    0.491975564, 1e-9);
	/* A calibrated reference: 0.576 (1 - exp(-38500/38500)) = 0.576 ·
	 * 0.632120559 = 0.364101442 */
	assert_rel(aero_fom_installed(0.72, 1.25, false, 38500.0, 38500.0),
	    0.364101442, 1e-9);
}

static void
aero_fom_isolated_mode_should_skip_kappa(void **state)
{
	(void)state;
	/* 0.72 · 0.854124244 = 0.614969455 */
	assert_rel(aero_fom_installed(0.72, 1.25, true, 38500.0, 0.0), 0.614969455, 1e-9);
}

static void
aero_fom_should_be_floored_at_0_10(void **state)
{
	(void)state;
	/* 0.576 · (1 - exp(-5000/20000)) = 0.576 · 0.221199217 = 0.127411 > 0.10:
	 * the paper's 0.38 floor would hide a tiny rotor's losses */
	assert_rel(aero_fom_installed(0.72, 1.25, false, 5000.0, 0.0), 0.127410749, 1e-8);
	/* 0.576 · (1 - exp(-2000/20000)) = 0.576 · 0.095162582 = 0.0548 < 0.10 */
	assert_rel(aero_fom_installed(0.72, 1.25, false, 2000.0, 0.0), 0.10, 1e-15);
	assert_rel(AERO_FOM_FLOOR, 0.10, 0.0);
	assert_rel(AERO_RE_REF, 20000.0, 0.0);
}

/* ---- interference ------------------------------------------------------ */

static void
aero_interference_should_be_1_plus_c_wa_over_dp(void **state)
{
	(void)state;
	/* offset c = 0.6: 1 + 0.6 · 0.0185 / 0.2385 = 1 + 0.046540881 = 1.046540881 */
	assert_rel(aero_interference(0.6, 0.0185, D_HAND), 1.046540881, 1e-9);
	/* under-rotor c = 1.5: 1 + 1.5 · 0.0185 / 0.2385 = 1.116352201 */
	assert_rel(aero_interference(1.5, 0.0185, D_HAND), 1.116352201, 1e-9);
	/* folding c = 0: exactly 1 */
	assert_rel(aero_interference(0.0, 0.0185, D_HAND), 1.0, 0.0);
}

static void
aero_interference_should_be_capped_at_1_15(void **state)
{
	(void)state;
	/* 1 + 1.5 · 0.03 / 0.2385 = 1.188679 > 1.15 → 1.15 */
	assert_rel(aero_interference(1.5, 0.03, D_HAND), 1.15, 1e-15);
}

/* ---- profile power, downwash, drag ------------------------------------- */

static void
aero_profile_power_should_be_sigma_cd0_rho_a_vtip3_over_8(void **state)
{
	(void)state;
	/* σ = 0.28/π = 0.089126768; V_tip³ = 123.5³ = 1883652.875
	 * P_o = 0.089126768 · 0.0143 · 1.1895 · 0.04467521468 · 1883652.875 / 8
	 *     = 15.94726373 W */
	assert_rel(aero_profile_power_w(0.0143, RHO_HAND, A_HAND, 123.5),
	    15.94726373, 1e-9);
}

static void
aero_downwash_should_be_twice_the_fleet_induced_velocity(void **state)
{
	(void)state;
	/* 2 sqrt(12.35 · 9.80665 / (2 · 1.1895 · 6 · 0.04467521468))
	 *   = 2 sqrt(121.1121275 / 0.637694014) = 2 sqrt(189.9220077) = 27.56243877 m/s */
	assert_rel(aero_downwash_ms(12.35, RHO_HAND, 6, A_HAND), 27.56243877, 1e-9);
}

static void
aero_drag_and_reference_area_should_follow_the_paper(void **state)
{
	(void)state;
	/* S_ref = 0.012 · 8.385^(2/3) + 0.02 = 0.012 · 4.1273254 + 0.02 = 0.069527905 m² */
	double s = aero_ref_area_m2(0.012, 8.385, 0.02);
	assert_rel(s, 0.069527905, 1e-8);
	/* F = ½ · 1.1895 · 13.85² · 1.0 · 0.069533284 = 0.59475 · 191.8225 · 0.069527905
	 *   = 7.9321906 N */
	assert_rel(aero_drag_n(RHO_HAND, 13.85, 1.0, s), 7.9321906, 1e-7);
}

static void
aero_rps_should_invert_the_thrust_coefficient_law(void **state)
{
	(void)state;
	/* n = sqrt(T / (C_t ρ D⁴)) = sqrt(7.385 / (0.12 · 1.1895 · 0.0032355904))
	 *   = sqrt(7.385 / 0.000461848) = sqrt(15990.10) = 126.451981 rev/s */
	assert_rel(aero_rps_for_thrust(T_HAND, 0.12, RHO_HAND, D_HAND), 126.451981, 1e-8);
}

static void
aero_hover_shaft_power_should_be_ideal_power_over_fom(void **state)
{
	(void)state;
	/* At V = 0 the profile/induced split must give back the paper's
	 * P = T v_h / FoM = 7.385 · 8.335750454 / 0.62 = 99.2895437 W. */
	struct atmo_state air;
	atmo_at(0.0, 288.15, &air);
	air.rho_kg_m3 = RHO_HAND;
	struct aero_rotor r = { D_HAND, 0.12, 0.62, 2 };
	struct aero_point pt;
	aero_rotor_power(&r, &air, T_HAND, 0.0, 0.0, 0.0, &pt);
	assert_rel(pt.induced_ms, VH_HAND, 1e-9);
	assert_rel(pt.p_shaft_w, 99.2895437, 1e-8);
	assert_rel(pt.p_induced_w + pt.p_profile_w, pt.p_shaft_w, 1e-12);
	assert_rel(pt.tip_speed_ms, M_PI * D_HAND * pt.rps, 1e-12);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(aero_overlap_limit_should_be_0_672_w_for_a_quad),
		cmocka_unit_test(aero_overlap_limit_should_be_0_475_w_for_a_hex),
		cmocka_unit_test(aero_overlap_limit_should_be_0_364_w_for_an_octo),
		cmocka_unit_test(aero_overlap_limit_of_a_coaxial_x8_should_use_four_arms),
		cmocka_unit_test(aero_hover_induced_velocity_should_be_sqrt_t_over_2_rho_a),
		cmocka_unit_test(aero_climb_induced_velocity_should_solve_momentum_in_axial_climb),
		cmocka_unit_test(aero_glauert_should_solve_the_implicit_relation_to_1e_10),
		cmocka_unit_test(aero_glauert_should_reduce_to_hover_at_zero_speed),
		cmocka_unit_test(aero_glauert_should_stay_finite_and_positive_at_high_speed),
		cmocka_unit_test(aero_cd0_should_use_the_square_root_branch_below_1e5),
		cmocka_unit_test(aero_cd0_should_use_the_fifth_root_branch_above_1e5),
		cmocka_unit_test(aero_cd0_should_be_continuous_at_1e5),
		cmocka_unit_test(aero_fom_installed_should_divide_by_kappa_and_apply_the_reynolds_fit),
		cmocka_unit_test(aero_fom_isolated_mode_should_skip_kappa),
		cmocka_unit_test(aero_fom_should_be_floored_at_0_10),
		cmocka_unit_test(aero_interference_should_be_1_plus_c_wa_over_dp),
		cmocka_unit_test(aero_interference_should_be_capped_at_1_15),
		cmocka_unit_test(aero_profile_power_should_be_sigma_cd0_rho_a_vtip3_over_8),
		cmocka_unit_test(aero_downwash_should_be_twice_the_fleet_induced_velocity),
		cmocka_unit_test(aero_drag_and_reference_area_should_follow_the_paper),
		cmocka_unit_test(aero_rps_should_invert_the_thrust_coefficient_law),
		cmocka_unit_test(aero_hover_shaft_power_should_be_ideal_power_over_fom),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
