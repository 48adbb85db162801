/* test_motor.c — the DC-equivalent brushless motor and the static
 * propeller (physics/motor.h, physics/prop.h).  Hand values in the
 * comments; "high entropy" inputs. */
#include "test_util.h"

#include "physics/motor.h"
#include "physics/prop.h"

/* A 385 KV, 185 g motor with R = 83.5 mOhm and I0 = 0.65 A. */
static const struct motor_model m385 = { 385.0, 0.0835, 0.65, 0.185 };

static void
motor_k_should_be_60_over_2_pi_kv(void **state)
{
	(void)state;
	/* 60 / (2π · 385) = 0.024803367754581 N m/A */
	assert_rel(motor_k_nm_a(385.0), 0.024803367754581, 1e-12);
}

static void
motor_at_shaft_should_match_the_hand_computation(void **state)
{
	(void)state;
	/* 238.5 W at 95.5 rev/s (ω = 600.04 rad/s), 25 °C:
	 *   Q = 238.5 / ω = 0.397470721753 N m
	 *   I = Q / K + I0 = 16.025 + 0.65 = 16.674869109948 A
	 *   V = K ω + I R = 14.883 + 1.392 = 16.275468453798 V
	 *   P_in = 271.391306170 W, η = 238.5 / 271.391 = 0.878804864
	 *   copper I² R = 23.217280196 W, no-load K ω I0 = 9.674025974 W */
	struct motor_point p;
	motor_at_shaft(&m385, 25.0, 238.5, 95.5, &p);
	assert_rel(p.torque_nm, 0.397470721753, 1e-10);
	assert_rel(p.current_a, 16.674869109948, 1e-10);
	assert_rel(p.voltage_v, 16.275468453798, 1e-10);
	assert_rel(p.power_in_w, 271.391306170155, 1e-10);
	assert_rel(p.power_shaft_w, 238.5, 1e-12);
	assert_rel(p.efficiency, 0.878804864333, 1e-10);
	assert_rel(p.copper_loss_w, 23.217280196129, 1e-10);
	assert_rel(p.no_load_loss_w, 9.674025974026, 1e-10);
	/* The losses are the difference between input and shaft power. */
	assert_rel(p.power_in_w - p.power_shaft_w,
	    p.copper_loss_w + p.no_load_loss_w, 1e-12);
}

static void
motor_efficiency_should_fall_as_the_winding_heats(void **state)
{
	(void)state;
	/* At 85 °C R = 0.0835 (1 + 0.00393 · 60) = 0.1031893 Ω, the same current
	 * needs V = 16.603784954 V: η = 238.5 / (16.6038 · 16.6749) = 0.861427734 */
	struct motor_point cold, hot;
	motor_at_shaft(&m385, 25.0, 238.5, 95.5, &cold);
	motor_at_shaft(&m385, 85.0, 238.5, 95.5, &hot);
	assert_rel(hot.voltage_v, 16.603784954164, 1e-10);
	assert_rel(hot.efficiency, 0.861427733856, 1e-10);
	assert_true(hot.efficiency < cold.efficiency);
}

static void
motor_at_voltage_should_balance_motor_and_propeller_torque(void **state)
{
	(void)state;
	/* 22.85 V on a 15 in propeller (D = 0.381 m, C_P = 0.0485) at
	 * ρ = 1.1685: kq = C_P ρ D⁵ / 2π = 7.241282077e-5 N m s².
	 *   kq n² + (2π K² / R) n - K (V / R - I0) = 0
	 *   n = 122.716348134 rev/s, I = (V - 2π K n) / R = 44.615261278 A,
	 *   torque 1.090486544 N m on both sides. */
	double kq = 0.0485 * 1.1685 * pow(0.381, 5.0) / (2.0 * M_PI);
	struct prop_coeffs pc = { 0.11, 0.0485, true };
	assert_rel(prop_kq_nm_s2(&pc, 1.1685, 0.381), kq, 1e-12);
	assert_rel(kq, 7.241282077455e-05, 1e-10);
	struct motor_point p;
	assert_true(motor_at_voltage(&m385, 25.0, 22.85, kq, &p));
	assert_rel(p.rps, 122.716348134226, 1e-10);
	assert_rel(p.current_a, 44.615261278372, 1e-10);
	assert_rel(p.torque_nm, 1.090486543914, 1e-10);
	assert_rel(p.voltage_v, 22.85, 1e-12);
	assert_true(p.efficiency > 0.0 && p.efficiency <= 1.0);
	/* The same motor held at that speed on that voltage: the same point. */
	struct motor_point q;
	motor_at_voltage_rps(&m385, 25.0, 22.85, 122.716348134226, &q);
	assert_rel(q.current_a, 44.615261278372, 1e-10);
	assert_rel(q.torque_nm, 1.090486543914, 1e-10);
	/* Faster, it draws less (the back-EMF): at 130.5 rev/s
	 * I = (22.85 - 2π · 0.024803367755 · 130.5) / 0.0835 = 30.087876 A. */
	motor_at_voltage_rps(&m385, 25.0, 22.85, 130.5, &q);
	assert_rel(q.current_a, (22.85 - 2.0 * M_PI * 0.024803367754581 * 130.5)
	    / 0.0835, 1e-12);
	assert_rel(q.current_a, 30.087876, 1e-6);
}

static void
motor_at_voltage_should_refuse_a_voltage_below_the_no_load_drop(void **state)
{
	(void)state;
	/* V / R < I0: no torque at any speed. */
	struct motor_point p;
	assert_false(motor_at_voltage(&m385, 25.0, 0.05, 1e-5, &p));
}

static void
motor_winding_should_follow_its_losses_through_the_estimated_thermal_path(void **state)
{
	(void)state;
	/* 185 g: R_th = 3 (1.85)^(-2/3) = 1.990704367 K/W, C = 0.185 · 450 =
	 * 83.25 J/K.  From 60 °C in 20 °C air with 35.5 W for 120 s:
	 *   T_ss = 20 + 35.5 · 1.9907 = 90.670 °C,
	 *   T = T_ss + (60 - T_ss) exp(-120 / (1.9907 · 83.25)) = 75.802187166 °C */
	assert_rel(motor_thermal_resistance_k_w(0.185), 1.990704366798, 1e-10);
	assert_rel(motor_thermal_capacity_j_k(0.185), 83.25, 1e-12);
	assert_rel(motor_temp_step_c(0.185, 60.0, 20.0, 35.5, 120.0),
	    75.802187166474, 1e-10);
	/* A heavier motor sheds heat more easily. */
	assert_true(motor_thermal_resistance_k_w(0.8) < motor_thermal_resistance_k_w(0.185));
}

static void
motor_estimates_should_follow_the_catalogue_fit(void **state)
{
	(void)state;
	/* R = 1e-3 exp(16.974 - 1.065 ln 385 - 1.221 ln 185) = 0.070791673 Ω,
	 * I0 = exp(-9.121 + 0.735 ln 385 + 0.881 ln 185) = 0.863956665 A
	 * (the catalogue's MN4014 KV400, 148 g, publishes 0.102 Ω, 0.6 A). */
	assert_rel(motor_estimate_resistance_ohm(385.0, 0.185), 7.079167340879e-02, 1e-9);
	assert_rel(motor_estimate_no_load_a(385.0, 0.185), 8.639566652432e-01, 1e-9);
	/* A faster motor of the same mass has fewer turns: less R, more I0. */
	assert_true(motor_estimate_resistance_ohm(900.0, 0.185)
	    < motor_estimate_resistance_ohm(385.0, 0.185));
	assert_true(motor_estimate_no_load_a(900.0, 0.185)
	    > motor_estimate_no_load_a(385.0, 0.185));
}

static void
motor_stator_estimates_should_follow_their_fit(void **state)
{
	(void)state;
	/* A 2207 of 1750 KV: R = 1e-3 exp(29.286 - 1.719 ln 1750
	 * - 3.210 ln 22 - 1.108 ln 7) = 0.0791444 Ω, I0 = exp(-23.432
	 * + 1.655 ln 1750 + 2.991 ln 22 + 0.878 ln 7) = 0.887201 A (the
	 * catalogue's XING2 2207 1855 KV publishes 50 mΩ; the mass law says
	 * 112 mΩ for it). */
	assert_rel(motor_estimate_resistance_stator_ohm(1750.0, 22.0, 7.0),
	    7.914443034780e-02, 1e-9);
	assert_rel(motor_estimate_no_load_stator_a(1750.0, 22.0, 7.0),
	    8.872009293956e-01, 1e-9);
	/* A wider or taller stator of the same KV: more copper, less R. */
	assert_true(motor_estimate_resistance_stator_ohm(1750.0, 23.0, 7.0)
	    < motor_estimate_resistance_stator_ohm(1750.0, 22.0, 7.0));
	assert_true(motor_estimate_resistance_stator_ohm(1750.0, 22.0, 8.0)
	    < motor_estimate_resistance_stator_ohm(1750.0, 22.0, 7.0));
}

static void
prop_estimate_should_follow_the_catalogue_fit(void **state)
{
	(void)state;
	/* P/D = 0.45: C_T = 0.142 · 0.45^0.472 = 0.097410248,
	 * C_P = 0.0727 · 0.45^0.972 = 0.033454687, FoM = C_T^1.5 / (C_P
	 * sqrt(π/2)) = 0.725086908; three blades: × 1.5^0.8, × 1.5. */
	struct prop_coeffs c, c3;
	prop_estimate(0.45, 2, &c);
	assert_false(c.measured);
	assert_rel(c.ct, 0.097410248416, 1e-10);
	assert_rel(c.cp, 0.033454687250, 1e-10);
	assert_rel(prop_fom(&c), 0.725086907809, 1e-10);
	prop_estimate(0.45, 3, &c3);
	assert_rel(c3.ct, 0.134734141085, 1e-10);
	assert_rel(c3.cp, 0.050182030875, 1e-10);
	/* More pitch: more thrust and more power per revolution. */
	struct prop_coeffs hi;
	prop_estimate(0.65, 2, &hi);
	assert_true(hi.ct > c.ct && hi.cp > c.cp);
}

static void
prop_thrust_and_power_should_scale_with_n_and_d(void **state)
{
	(void)state;
	/* C_T 0.1185, C_P 0.0485 at 85.5 rev/s, D = 0.254 m, ρ = 1.1685:
	 *   T = 0.1185 · 1.1685 · 85.5² · 0.254⁴ = 4.213220251 N
	 *   P = 0.0485 · 1.1685 · 85.5³ · 0.254⁵ = 37.448754883 W */
	struct prop_coeffs c = { 0.1185, 0.0485, true };
	assert_rel(prop_thrust_n(&c, 1.1685, 85.5, 0.254), 4.213220251387, 1e-10);
	assert_rel(prop_power_w(&c, 1.1685, 85.5, 0.254), 37.448754883286, 1e-10);
	/* Momentum theory: P ≥ T^1.5 / sqrt(2 ρ A) exactly when FoM ≤ 1. */
	double a = M_PI * 0.254 * 0.254 / 4.0;
	double ideal = pow(4.213220251387, 1.5) / sqrt(2.0 * 1.1685 * a);
	assert_rel(ideal / 37.448754883286, prop_fom(&c), 1e-10);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(motor_k_should_be_60_over_2_pi_kv),
		cmocka_unit_test(motor_at_shaft_should_match_the_hand_computation),
		cmocka_unit_test(motor_efficiency_should_fall_as_the_winding_heats),
		cmocka_unit_test(motor_at_voltage_should_balance_motor_and_propeller_torque),
		cmocka_unit_test(motor_at_voltage_should_refuse_a_voltage_below_the_no_load_drop),
		cmocka_unit_test(motor_winding_should_follow_its_losses_through_the_estimated_thermal_path),
		cmocka_unit_test(motor_estimates_should_follow_the_catalogue_fit),
		cmocka_unit_test(motor_stator_estimates_should_follow_their_fit),
		cmocka_unit_test(prop_estimate_should_follow_the_catalogue_fit),
		cmocka_unit_test(prop_thrust_and_power_should_scale_with_n_and_d),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
