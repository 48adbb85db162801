/* test_structure.c — CFRP arm sizing and resonance against paper §V:
 * eq. (sigallow), eq. (dout) with the minimum wall, eq. (fnat), the
 * resonance margin on both sides of the blade-pass band, the CG-offset
 * thrust and its rejection, and the minimum structural fraction; beyond
 * the paper, the stiffness sizing (motor tilt F L²/2EI <= 1°), the mode
 * floor, torsion and the band clearance.  Hand values in the comments.
 */
#include "test_util.h"
#include "physics/structure.h"
#include "util/units.h"

/* An arm sized for strength alone (no full-thrust tilt, no mode floor). */
static void
strength_arm(double force_n, double length_m, double alpha_w,
             double tip_mass_kg, struct structure_arm *a)
{
	struct structure_arm_loads in = { force_n, 0.0, 0.0, tip_mass_kg,
		length_m, alpha_w, 0.0 };
	structure_size_arm(&in, a);
}

static void
structure_sigma_allow_should_be_192_mpa(void **state)
{
	(void)state;
	/* 720 MPa · 0.40 / 1.5 = 288 / 1.5 = 192 MPa */
	assert_rel(structure_sigma_allow_pa(), 192e6, 1e-15);
}

static void
structure_arm_d_out_should_follow_eq_dout(void **state)
{
	(void)state;
	struct structure_arm a;
	/* F = 23.85 N at L = 0.3385 m: M_b = 8.073225 N m.  α_w = 0.9:
	 * 1 - α⁴ = 1 - 0.6561 = 0.3439
	 * d = cbrt(32 · 8.073225 / (π · 0.3439 · 192e6)) = cbrt(258.3432 / 2.07435593e8)
	 *   = cbrt(1.24541404e-6) = 0.01075898377 m */
	strength_arm(23.85, 0.3385, 0.9, 0.1385, &a);
	assert_rel(a.root_moment_nm, 8.073225, 1e-12);
	assert_rel(a.d_out_m, 0.01075898377, 1e-9);
	/* wall = d (1 - α)/2 = 0.000537949 m > 0.5 mm: the floor does not bind */
	assert_false(a.wall_floor_binds);
	assert_rel(a.wall_m, 0.000537949, 1e-6);
	assert_rel(a.d_in_m, 0.9 * 0.01075898377, 1e-9);
	/* Strength-sized: the root stress is exactly σ_all. */
	assert_rel(a.stress_pa, 192e6, 1e-9);
	/* mass = 1600 · π/4 (d² - d_in²) · L = 1600 · 1.72737e-5 · 0.3385 = 0.00935545 kg */
	assert_rel(a.mass_kg, 0.00935545, 1e-5);
}

static void
structure_arm_wall_should_be_floored_at_0_5_mm(void **state)
{
	(void)state;
	struct structure_arm a;
	/* F = 2.385 N at L = 0.1185 m: M_b = 0.28262250 N m,
	 * d = cbrt(32 · 0.2826225 / (π · 0.3439 · 192e6)) = 0.00351958246 m,
	 * its α-wall 0.000175979 m < 0.5 mm → wall = 0.5 mm, d_in = 2.51958 mm */
	strength_arm(2.385, 0.1185, 0.9, 0.03, &a);
	assert_rel(a.d_out_m, 0.00351958246, 1e-9);
	assert_true(a.wall_floor_binds);
	assert_rel(a.wall_m, STRUCT_MIN_WALL_M, 1e-15);
	assert_rel(STRUCT_MIN_WALL_M, 0.0005, 0.0);
	assert_rel(a.d_in_m, 0.00251958246, 1e-9);
	/* The thicker wall lowers the stress below σ_all:
	 * I = π (d⁴ - d_in⁴)/64 = 5.554155e-12 m⁴, σ = M d/(2 I) = 89.5468 MPa */
	assert_rel(a.i_x_m4, 5.554155e-12, 1e-6);
	assert_rel(a.stress_pa, 89.5468e6, 1e-5);
	assert_true(a.stress_pa < structure_sigma_allow_pa());
}

static void
structure_natural_frequency_should_follow_eq_fnat(void **state)
{
	(void)state;
	/* Tube 16.0 / 14.4 mm, L = 0.3385 m, tip mass 0.1385 kg:
	 * I = π (0.016⁴ - 0.0144⁴)/64 = 1.10632316e-9 m⁴
	 * A = π/4 (0.016² - 0.0144²) = 3.82017667e-5 m², μ = 1600 A = 0.0611228267 kg/m
	 * m_eff = 0.1385 + 0.24 · 0.0611228267 · 0.3385 = 0.143465618 kg
	 * f = sqrt(3 · 70e9 · 1.10632316e-9 / (0.0387860916 · 0.143465618)) / 2π
	 *   = sqrt(232.327864 / 0.00556446) / 2π = sqrt(41752.1) / 2π = 32.5206228 Hz */
	double d = 0.016, di = 0.0144;
	double i_x = M_PI * (d * d * d * d - di * di * di * di) / 64.0;
	double area = 0.25 * M_PI * (d * d - di * di);
	assert_rel(i_x, 1.10632316e-9, 1e-8);
	assert_rel(structure_natural_freq_hz(i_x, 0.3385, 0.1385, 1600.0 * area),
	    32.5206228, 1e-8);
}

static void
structure_sized_arm_should_report_its_own_natural_frequency(void **state)
{
	(void)state;
	struct structure_arm a;
	strength_arm(23.85, 0.3385, 0.9, 0.1385, &a);
	double want = structure_natural_freq_hz(a.i_x_m4, a.length_m, 0.1385,
	    STRUCT_RHO_CF_KG_M3 * a.area_m2);
	assert_rel(a.f_nat_hz, want, 1e-12);
	assert_true(a.f_nat_hz > 0.0);
}

static void
structure_resonance_margin_should_pass_a_stiff_arm(void **state)
{
	(void)state;
	/* f_nat 385 Hz, band 150–200 Hz: 385 / (1.5 · 200) - 1 = 0.283333 */
	assert_rel(structure_resonance_margin(385.0, 150.0, 200.0), 0.2833333333, 1e-9);
}

static void
structure_resonance_margin_should_pass_a_soft_arm(void **state)
{
	(void)state;
	/* f_nat 62.5 Hz, band 123.85–412 Hz: (123.85 / 1.5) / 62.5 - 1
	 *   = 82.566667 / 62.5 - 1 = 0.3210667 */
	assert_rel(structure_resonance_margin(62.5, 123.85, 412.0), 0.3210666667, 1e-9);
}

static void
structure_resonance_margin_should_fail_a_mode_inside_the_band(void **state)
{
	(void)state;
	/* 250 Hz in 123.85–412 Hz: stiff 250/618 - 1 = -0.595469,
	 * soft 82.566667/250 - 1 = -0.669733: the better side is still < 0 */
	double m = structure_resonance_margin(250.0, 123.85, 412.0);
	assert_true(m < 0.0);
	assert_rel(m, -0.5954692557, 1e-9);
	/* Exactly 1.5 × the peak passes with margin 0. */
	assert_rel(structure_resonance_margin(618.0, 123.85, 412.0), 0.0, 1e-12);
	assert_true(structure_resonance_margin(618.0, 123.85, 412.0) >= -1e-15);
	assert_true(structure_resonance_margin(0.0, 123.85, 412.0) < 0.0);
	/* A rotor that never reaches hover has no band: a finite failure. */
	assert_rel(structure_resonance_margin(250.0, 0.0, 0.0), -1.0, 1e-15);
	assert_rel(structure_resonance_margin(250.0, 123.85, 0.0), -1.0, 1e-15);
}

static void
structure_cg_thrust_should_load_the_worst_motor(void **state)
{
	(void)state;
	double t = 0.0;
	/* 4.385 kg quad, L_arm 0.4125 m, x_cg 0.0385 m:
	 * d_y = 0.4125 cos(π/4) = 0.291681547 m
	 * T = 4.385 · 9.80665 / 4 · (1 + 0.0385 / 0.291681547)
	 *   = 10.75054006 · 1.131993266 = 12.16953895 N */
	assert_true(structure_cg_thrust_n(4.385, 4, 0.4125, 0.0385, &t));
	assert_rel(t, 12.16953895, 1e-9);
	/* No offset: the share M g / N */
	assert_true(structure_cg_thrust_n(4.385, 4, 0.4125, 0.0, &t));
	assert_rel(t, 10.75054006, 1e-9);
}

static void
structure_cg_thrust_should_reject_an_offset_at_or_beyond_d_y(void **state)
{
	(void)state;
	double t = 0.0;
	double d_y = 0.4125 * cos(M_PI / 4.0);
	assert_false(structure_cg_thrust_n(4.385, 4, 0.4125, d_y, &t));
	assert_false(structure_cg_thrust_n(4.385, 4, 0.4125, 0.385, &t));
	assert_true(isfinite(t));
	assert_true(structure_cg_thrust_n(4.385, 4, 0.4125, 0.99 * d_y, &t));
}

static void
structure_min_fraction_should_stay_between_0_06_and_0_20(void **state)
{
	(void)state;
	/* 0.05 + 0.05 · 1.385 = 0.11925 (inside the bounds) */
	assert_rel(structure_min_fraction(1.385), 0.11925, 1e-12);
	/* 0.05 + 0.05 · 0.1185 = 0.055925 < 0.06 → 0.06 */
	assert_rel(structure_min_fraction(0.1185), 0.06, 1e-15);
	/* 0.05 + 0.05 · 3.85 = 0.2425 > 0.20 → 0.20 */
	assert_rel(structure_min_fraction(3.85), 0.20, 1e-15);
	/* the corners: W = 0.2 → 0.06, W = 3.0 → 0.20 */
	assert_rel(structure_min_fraction(0.2), 0.06, 1e-12);
	assert_rel(structure_min_fraction(3.0), 0.20, 1e-12);
}

static void
structure_arm_should_be_stiff_enough_for_one_degree_of_tilt(void **state)
{
	(void)state;
	/* 41 N of full thrust at the tip of a 0.5 m arm (design load 20 N):
	 * I >= F L² / (2 E θ) = 41 · 0.25 / (2 · 70e9 · 0.01745329) = 4.19487e-9 m⁴.
	 * Stiffness sizes it, so the wall thins to D/40 (α 0.95):
	 * d = (64 I / (π (1 - 0.95⁴)))^¼ = 0.0260528 m, wall 0.651 mm
	 * (at α 0.9 it would be 0.0223269 m and 1.12 mm, 39 % heavier). */
	struct structure_arm_loads in = { 20.0, 41.0, 2.0, 0.3, 0.5, 0.9, 0.0 };
	struct structure_arm a;
	structure_size_arm(&in, &a);
	assert_int_equal(a.sized_by, ARM_BY_TILT);
	assert_rel(a.d_out_m, 0.0260528249, 1e-8);
	assert_rel(a.wall_m, 0.000651320622, 1e-7);
	assert_rel(a.i_x_m4, 4.19486957e-9, 1e-8);
	assert_rel(a.tilt_full_deg, 1.0, 1e-9);
	/* δ = F L³ / 3EI = (2/3) θ L = (2/3) · 0.01745329 · 0.5 = 5.8178 mm */
	assert_rel(a.deflection_full_m, 0.00581776417, 1e-8);
	/* τ = Q r / 2I = 2 · 0.0130264 / (2 · 4.19487e-9) = 3.10532 MPa */
	assert_rel(a.torsion_pa, 3.10532002e6, 1e-7);
	/* The stress at the design load is far below σ_all: a real margin. */
	assert_true(a.safety_factor > 1.5);
	assert_rel(a.safety_factor, 288e6 / a.stress_pa, 1e-12);
	/* The thick-walled tube of the same stiffness is heavier. */
	struct structure_arm_loads thick = in;
	thick.alpha_w = 0.97;  /* a mission's thinner wall is kept */
	struct structure_arm b;
	structure_size_arm(&thick, &b);
	assert_true(b.mass_kg < a.mass_kg);
}

static void
structure_arm_mode_should_meet_its_floor(void **state)
{
	(void)state;
	/* The 0.5 m arm above with a 0.3 kg tip has its mode near 36 Hz;
	 * asked for 60 Hz, the tube grows until the mode is 60 Hz. */
	struct structure_arm_loads in = { 20.0, 41.0, 2.0, 0.3, 0.5, 0.9, 60.0 };
	struct structure_arm a;
	structure_size_arm(&in, &a);
	assert_int_equal(a.sized_by, ARM_BY_MODE);
	assert_rel(a.f_nat_hz, 60.0, 1e-9);
	assert_true(a.tilt_full_deg < 1.0);
	/* A floor it already clears changes nothing. */
	in.mode_floor_hz = 10.0;
	structure_size_arm(&in, &a);
	assert_int_equal(a.sized_by, ARM_BY_TILT);
}

static void
structure_tau_allow_and_gyro_filter_should_follow_their_sources(void **state)
{
	(void)state;
	/* 68 MPa · 0.40 / 1.5 = 18.1333 MPa */
	assert_rel(structure_tau_allow_pa(), 18.1333333e6, 1e-8);
	/* 289.22 · 10^-0.838 = 41.998 Hz; 24 in: 20.166 Hz; 30 in: 16.726 Hz */
	assert_rel(structure_gyro_filter_hz(10.0 * 0.0254), 41.9979722, 1e-8);
	assert_rel(structure_gyro_filter_hz(24.0 * 0.0254), 20.1656071, 1e-8);
	assert_rel(structure_gyro_filter_hz(30.0 * 0.0254), 16.7263319, 1e-8);
	assert_rel(structure_gyro_filter_hz(0.0), 0.0, 0.0);
	/* The rate loop: half the gyro filter, 21.0 Hz at 10 in. */
	assert_rel(structure_rate_bandwidth_hz(10.0 * 0.0254), 20.9989861, 1e-8);
}

static void
structure_band_clear_should_judge_the_near_edge(void **state)
{
	(void)state;
	double edge;
	bool above;
	/* Band 27.3–38 Hz ± 15 %: 23.739–43.7 Hz. */
	assert_false(structure_band_clear(25.0, 27.3, 38.0, 1.15, &edge, &above));
	assert_false(above);
	assert_rel(edge, 27.3 / 1.15, 1e-12);
	assert_true(structure_band_clear(23.0, 27.3, 38.0, 1.15, &edge, &above));
	assert_true(structure_band_clear(44.0, 27.3, 38.0, 1.15, &edge, &above));
	assert_true(above);
	assert_rel(edge, 43.7, 1e-12);
	assert_false(structure_band_clear(40.0, 27.3, 38.0, 1.15, &edge, &above));
	assert_true(above);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(structure_sigma_allow_should_be_192_mpa),
		cmocka_unit_test(structure_arm_d_out_should_follow_eq_dout),
		cmocka_unit_test(structure_arm_wall_should_be_floored_at_0_5_mm),
		cmocka_unit_test(structure_natural_frequency_should_follow_eq_fnat),
		cmocka_unit_test(structure_sized_arm_should_report_its_own_natural_frequency),
		cmocka_unit_test(structure_resonance_margin_should_pass_a_stiff_arm),
		cmocka_unit_test(structure_resonance_margin_should_pass_a_soft_arm),
		cmocka_unit_test(structure_resonance_margin_should_fail_a_mode_inside_the_band),
		cmocka_unit_test(structure_cg_thrust_should_load_the_worst_motor),
		cmocka_unit_test(structure_cg_thrust_should_reject_an_offset_at_or_beyond_d_y),
		cmocka_unit_test(structure_min_fraction_should_stay_between_0_06_and_0_20),
		cmocka_unit_test(structure_arm_should_be_stiff_enough_for_one_degree_of_tilt),
		cmocka_unit_test(structure_arm_mode_should_meet_its_floor),
		cmocka_unit_test(structure_tau_allow_and_gyro_filter_should_follow_their_sources),
		cmocka_unit_test(structure_band_clear_should_judge_the_near_edge),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
