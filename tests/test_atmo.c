/* test_atmo.c — the ISA atmosphere against paper §IV-B, eq. (trop).
 *
 * Constants of the hand computations (paper): P0 = 101325 Pa,
 * T0 = 288.15 K, L = 0.0065 K/m, g = 9.80665 m/s², R = 287.058 J/(kg K),
 * exponent g/(R L) = 9.80665 / (287.058 · 0.0065) = 5.2557858851.
 * Standard day: the ambient temperature is the ISA temperature.
 */
#include "test_util.h"
#include "physics/atmo.h"
#include "util/units.h"

static void
standard_day(double h_m, struct atmo_state *a)
{
	atmo_at(h_m, atmo_isa_temp_k(h_m), a);
}

static void
atmo_should_give_isa_sea_level(void **state)
{
	(void)state;
	struct atmo_state a;
	standard_day(0.0, &a);
	assert_rel(a.temp_k, 288.15, 1e-12);
	assert_rel(a.pressure_pa, 101325.0, 1e-12);
	/* ρ = 101325 / (287.058 · 288.15) = 101325 / 82715.7627 = 1.2249781262 */
	assert_rel(a.rho_kg_m3, 1.2249781262, 1e-9);
	/* a = sqrt(1.4 · 287.058 · 288.15) = sqrt(115802.102) = 340.297029 m/s */
	assert_rel(a.sound_m_s, 340.297029, 1e-8);
}

static void
atmo_should_match_isa_at_5000_m(void **state)
{
	(void)state;
	struct atmo_state a;
	standard_day(5000.0, &a);
	/* T = 288.15 - 0.0065 · 5000 = 288.15 - 32.5 = 255.65 K */
	assert_rel(a.temp_k, 255.65, 1e-12);
	assert_rel(a.isa_temp_k, 255.65, 1e-12);
	/* P = 101325 · (1 - 32.5/288.15)^5.2557858851
	 *   = 101325 · 0.887211522^5.2557858851 = 101325 · 0.5331408 = 54020.495 Pa */
	assert_rel(a.pressure_pa, 54020.4954, 1e-8);
	/* ρ = 54020.4954 / (287.058 · 255.65) = 54020.4954 / 73386.3777 = 0.73611067 */
	assert_rel(a.rho_kg_m3, 0.73611067, 1e-7);
}

static void
atmo_should_match_isa_at_the_11000_m_tropopause(void **state)
{
	(void)state;
	struct atmo_state a;
	standard_day(11000.0, &a);
	/* T = 288.15 - 0.0065 · 11000 = 288.15 - 71.5 = 216.65 K */
	assert_rel(a.temp_k, 216.65, 1e-12);
	/* P = 101325 · (216.65/288.15)^5.2557858851 = 101325 · 0.2233669 = 22632.646 Pa */
	assert_rel(a.pressure_pa, 22632.6464, 1e-8);
	/* ρ = 22632.6464 / (287.058 · 216.65) = 22632.6464 / 62191.1157 = 0.36392089 */
	assert_rel(a.rho_kg_m3, 0.36392089, 1e-7);
}

static void
atmo_should_be_isothermal_exponential_at_15000_m(void **state)
{
	(void)state;
	struct atmo_state a;
	standard_day(15000.0, &a);
	assert_rel(a.temp_k, 216.65, 1e-12);
	/* P = P11 exp(-g (h - 11000) / (R T11))
	 *   = 22632.6464 · exp(-9.80665 · 4000 / (287.058 · 216.65))
	 *   = 22632.6464 · exp(-0.6307428) = 22632.6464 · 0.5321963 = 12045.011 Pa */
	assert_rel(a.pressure_pa, 12045.0112, 1e-8);
	/* ρ = 12045.0112 / 62191.1157 = 0.19367736 */
	assert_rel(a.rho_kg_m3, 0.19367736, 1e-7);
}

static void
atmo_density_should_use_the_ambient_temperature_not_isa(void **state)
{
	(void)state;
	struct atmo_state a;
	/* A hot day at 2385 m: 35.7 °C = 308.85 K, ISA there is 272.6475 K. */
	atmo_at(2385.0, 308.85, &a);
	/* P = 101325 · (1 - 0.0065 · 2385 / 288.15)^5.2557858851
	 *   = 101325 · 0.9461998959^5.2557858851 = 75768.3545 Pa (ISA, unchanged) */
	assert_rel(a.pressure_pa, 75768.3545, 1e-8);
	assert_rel(a.isa_temp_k, 272.6475, 1e-12);
	assert_rel(a.temp_k, 308.85, 1e-12);
	/* ρ = 75768.3545 / (287.058 · 308.85) = 75768.3545 / 88657.8633 = 0.85461517 */
	assert_rel(a.rho_kg_m3, 0.85461517, 1e-7);
	/* a = sqrt(1.4 · 287.058 · 308.85) = 352.30812 m/s */
	assert_rel(a.sound_m_s, 352.30812, 1e-7);
	/* Thinner than the standard day at the same altitude. */
	struct atmo_state s;
	standard_day(2385.0, &s);
	assert_true(a.rho_kg_m3 < s.rho_kg_m3);
}

static void
atmo_should_clamp_altitude_to_0_and_20_km(void **state)
{
	(void)state;
	assert_rel(atmo_isa_pressure_pa(-385.0), 101325.0, 1e-12);
	assert_rel(atmo_isa_pressure_pa(23850.0), atmo_isa_pressure_pa(20000.0), 1e-12);
	assert_rel(atmo_isa_temp_k(23850.0), 216.65, 1e-12);
}

static void
atmo_pressure_should_be_continuous_at_the_tropopause(void **state)
{
	(void)state;
	double below = atmo_isa_pressure_pa(11000.0 - 1e-6);
	double above = atmo_isa_pressure_pa(11000.0 + 1e-6);
	assert_rel(above, below, 1e-9);
}

static void
atmo_viscosity_should_follow_sutherland(void **state)
{
	(void)state;
	struct atmo_state a;
	standard_day(0.0, &a);
	/* μ = 1.716e-5 (288.15/273.15)^1.5 (273.15 + 110.4)/(288.15 + 110.4)
	 *   = 1.716e-5 · 1.0834930 · 0.9623636 = 1.7892976e-5 Pa s */
	assert_rel(a.mu_pa_s, 1.7892976e-5, 1e-7);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(atmo_should_give_isa_sea_level),
		cmocka_unit_test(atmo_should_match_isa_at_5000_m),
		cmocka_unit_test(atmo_should_match_isa_at_the_11000_m_tropopause),
		cmocka_unit_test(atmo_should_be_isothermal_exponential_at_15000_m),
		cmocka_unit_test(atmo_density_should_use_the_ambient_temperature_not_isa),
		cmocka_unit_test(atmo_should_clamp_altitude_to_0_and_20_km),
		cmocka_unit_test(atmo_pressure_should_be_continuous_at_the_tropopause),
		cmocka_unit_test(atmo_viscosity_should_follow_sutherland),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
