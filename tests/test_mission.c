/* test_mission.c — the three-phase power model (paper §IV-C..F): per-phase
 * thrust, body drag on S_ref with the forward-only multiplier, body pitch,
 * eq. (powerbudget), the coaxial induced factor and the speed sweep.  Hand
 * values in the comments.
 *
 * Hand aircraft: 4.385 kg quad, ISA sea level (ρ = 1.2249781262), rotors
 * D = 0.3385 m (A = π · 0.3385²/4 = 0.0899926887 m²), installed FoM 0.585,
 * η = 0.85, aux 22.5 W, 22.2 V bus, f_scale 0.012, ΔA 0.02 m², forward
 * multiplier 1.5, C_d,h 1.0, C_d,v 1.2.
 * S_ref = 0.012 · 4.385^(2/3) + 0.02 = 0.012 · 2.6790433 + 0.02 = 0.0521485195 m².
 */
#include "test_util.h"
#include "test_fixtures.h"
#include "physics/mission.h"
#include "physics/prop.h"
#include "util/stats.h"
#include "util/units.h"


static void
mission_hover_power_should_follow_the_power_budget(void **state)
{
	(void)state;
	struct mission_model m;
	struct mission_power p;
	fixture_hand_model(&m, false);
	mission_power(&m, 4.385, 0.0, 0.0, &p);
	/* T = 4.385 · 9.80665 / 4 = 10.7505400625 N */
	assert_rel(p.thrust_per_rotor_n, 10.7505400625, 1e-12);
	/* v_h = sqrt(10.7505400625 / (2 · 1.2249781262 · 0.0899926887)) = 6.982844365 m/s
	 * shaft per rotor = T v_h / FoM = 10.7505400625 · 6.982844365 / 0.585 = 128.3236720 W */
	assert_rel(p.rotor.induced_ms, 6.982844365, 1e-9);
	assert_rel(p.rotor.p_shaft_w, 128.323672, 1e-8);
	assert_rel(p.shaft_w, 4.0 * 128.323672, 1e-8);
	/* switching: ½ · 24000 · 3.75e-9 · 22.2² · 4 ESCs = 4.5e-5 · 492.84 · 4 = 0.0887112 W */
	assert_rel(p.switching_w, 0.0887112, 1e-9);
	/* P_e = 513.294688 / 0.85 + 0.0887112 + 22.5 = 603.876104 + 22.588711 = 626.4648146 W */
	assert_rel(p.electrical_w, 626.4648146, 1e-9);
	assert_rel(p.drag_n, 0.0, 0.0);
	assert_rel(p.pitch_deg, 0.0, 0.0);
}

static void
mission_climb_thrust_should_add_the_vertical_drag(void **state)
{
	(void)state;
	struct mission_model m;
	struct mission_power p;
	fixture_hand_model(&m, false);
	mission_power(&m, 4.385, 2.85, 0.0, &p);
	/* F_d,v = ½ · 1.2249781262 · 2.85² · 1.2 · 0.0521485195 (no forward multiplier)
	 *       = 0.311323058 N;  T = (43.00216025 + 0.311323058) / 4 = 10.82837083 N */
	assert_rel(p.drag_n, 0.311323058, 1e-8);
	assert_rel(p.thrust_per_rotor_n, 10.82837083, 1e-9);
	assert_rel(p.pitch_deg, 0.0, 0.0);
	/* the climb work T V_c is in the shaft power */
	assert_true(p.rotor.p_induced_w > p.thrust_per_rotor_n * 2.85);
}

static void
mission_forward_flight_should_pitch_and_tilt_the_thrust(void **state)
{
	(void)state;
	struct mission_model m;
	struct mission_power p;
	fixture_hand_model(&m, false);
	mission_power(&m, 4.385, 0.0, 13.85, &p);
	/* F_d = ½ · 1.2249781262 · 13.85² · 1.0 · (1.5 · 0.0521485195) = 9.190330453 N */
	assert_rel(p.drag_n, 9.190330453, 1e-9);
	/* θ = atan(9.190330453 / 43.00216025) = 12.06364721° */
	assert_rel(p.pitch_deg, 12.06364721, 1e-9);
	/* T = sqrt(43.00216025² + 9.190330453²) / 4 = 10.99331604 N */
	assert_rel(p.thrust_per_rotor_n, 10.99331604, 1e-9);
	/* each rotor carries a quarter of F_d V = 9.190330453 · 13.85 / 4 = 31.82151919 W */
	assert_rel(p.rotor.p_parasite_w, 31.82151919, 1e-9);
	assert_true(p.rotor.glauert_iter >= 1);
}

static void
mission_coaxial_should_raise_induced_power_by_1_22(void **state)
{
	(void)state;
	struct mission_model m;
	struct mission_power single, coax;
	fixture_hand_model(&m, false);
	mission_power(&m, 4.385, 0.0, 0.0, &single);
	fixture_hand_model(&m, true);
	mission_power(&m, 4.385, 0.0, 0.0, &coax);
	assert_rel(coax.rotor.p_induced_w, 1.22 * single.rotor.p_induced_w, 1e-12);
	assert_rel(coax.rotor.p_profile_w, single.rotor.p_profile_w, 1e-12);
	assert_rel(coax.rotor.p_shaft_w - single.rotor.p_shaft_w,
	    0.22 * single.rotor.p_induced_w, 1e-9);
}

static void
mission_sweep_should_cover_1_to_30_m_s_in_half_steps(void **state)
{
	(void)state;
	struct mission_model m;
	double v[64], pw[64], v_min, v_max;
	fixture_hand_model(&m, false);
	/* generous thrust limit: only the pitch limit clips */
	int n = mission_speed_sweep(&m, 4.385, 1e3, v, pw, 64, &v_min, &v_max);
	/* (30 - 1) / 0.5 + 1 = 59 points */
	assert_int_equal(n, 59);
	assert_rel(v[0], 1.0, 0.0);
	assert_rel(v[58], 30.0, 0.0);
	/* v_min is the argmin of the sampled power */
	int best = 0;
	for (int i = 1; i < n; i++)
		if (pw[i] < pw[best])
			best = i;
	assert_rel(v_min, v[best], 0.0);
	assert_true(v_min > 1.0 && v_min < 30.0);
	/* The 35° pitch limit ends the usable range: F_d grows with V², so
	 * at 25 m/s F_d = 9.190330453 (25/13.85)² = 29.9441 N, θ = atan(29.9441 /
	 * 43.0022) = 34.85° (within), at 25.5 m/s F_d = 31.1527 N, θ = 35.92°
	 * (beyond).  Between them, to the millimetre per second: F_d = W tan 35°
	 * = 43.00216025 · 0.7002075382 = 30.1104 N at V = 13.85 sqrt(30.1104 /
	 * 9.190330453) = 25.06933 m/s → v_max = 25.069 m/s, the pitch's. */
	assert_rel(v_max, 25.069, 1e-12);
	assert_rel(mission_pitch_limit_speed_ms(&m, 4.385), 25.0693306, 1e-8);
	assert_int_equal(mission_top_speed_limit(&m, 4.385, v_max),
	    MISSION_LIMIT_PITCH);
}

static void
mission_max_climb_should_stop_where_the_climb_drag_meets_the_thrust(void **state)
{
	(void)state;
	struct mission_model m;
	fixture_hand_model(&m, false);
	/* 4 T = W + ½ ρ V² C_d A: with T at 11.0 N, V² = (44 - 43.00216025)
	 * / (½ · 1.2249781262 · 1.2 · 0.0521485195), V = 5.10234260 m/s. */
	assert_rel(mission_max_climb_ms(&m, 4.385, 11.0, 20.0), 5.10234260, 1e-3);
	/* Within the limit: the climb asked; not even a hover: none. */
	assert_rel(mission_max_climb_ms(&m, 4.385, 11.0, 3.0), 3.0, 0.0);
	assert_rel(mission_max_climb_ms(&m, 4.385, 10.0, 3.0), 0.0, 0.0);
	/* The speed returned is within the limit, a step above it is not. */
	double v = mission_max_climb_ms(&m, 4.385, 11.0, 20.0);
	struct mission_power p;
	mission_power(&m, 4.385, v, 0.0, &p);
	assert_false(mission_beyond_limits(&m, &p, 11.0));
	mission_power(&m, 4.385, v + 0.01, 0.0, &p);
	assert_true(mission_beyond_limits(&m, &p, 11.0));
}

static void
mission_sweep_should_stop_v_max_at_the_thrust_limit(void **state)
{
	(void)state;
	struct mission_model m;
	double v[64], pw[64], v_min, v_max;
	fixture_hand_model(&m, false);
	/* Thrust per rotor 10.99331604 N at 13.85 m/s; with a limit of 11.0 N
	 * (and no propeller pitch: the same full thrust at every speed) the
	 * drag may reach sqrt(44² - 43.00216025²) = 9.317409 N, at V = 13.85
	 * sqrt(9.317409 / 9.190330453) = 13.945430 m/s → 13.945 on the
	 * millimetre lattice, between the grid's 13.5 and 14.0. */
	(void)mission_speed_sweep(&m, 4.385, 11.0, v, pw, 64, &v_min, &v_max);
	assert_rel(v_max, 13.945, 1e-12);
	assert_true(v_min <= v_max);
	assert_int_equal(mission_top_speed_limit(&m, 4.385, v_max),
	    MISSION_LIMIT_THRUST);
}

/* The envelope with the propeller's C_T(J): P/D 0.5, J0 = 1.15 · 0.5 =
 * 0.575, full thrust 16 N per rotor at rest, reached at n = sqrt(16 /
 * (0.12 · 1.2249781262 · 0.3385⁴)) = 91.05166 rev/s (zero thrust at
 * J0 n D = 17.72207 m/s).  At 5 m/s of inflow J = 5 / (91.05166 · 0.3385)
 * = 0.162228, x = 0.282136, C_T / C_T0 = 1 - 0.35 x - 0.65 x² = 0.849513:
 * 13.59221 N.  The top climb, where 4 · 16 · C_T(J)/C_T0 = W + ½ ρ V²
 * C_d,v S_ref: 7.98901 m/s (by hand, bisection), against 12.5 m/s or more
 * with the static 16 N at every speed. */
static void
mission_envelope_should_lose_thrust_with_the_inflow(void **state)
{
	(void)state;
	struct mission_model m;
	fixture_hand_model(&m, false);
	m.prop_j0 = 0.575;
	assert_rel(mission_thrust_available_n(&m, 16.0, 0.0), 16.0, 0.0);
	assert_rel(mission_thrust_available_n(&m, 16.0, 5.0), 13.59221, 1e-6);
	assert_true(fabs(mission_thrust_available_n(&m, 16.0, 17.72207)) < 1e-4);
	assert_rel(mission_max_climb_ms(&m, 4.385, 16.0, 30.0), 7.98901, 1e-4);
	/* Without the pitch: the static thrust at every climb rate. */
	m.prop_j0 = 0.0;
	assert_true(mission_max_climb_ms(&m, 4.385, 16.0, 30.0) > 12.5);
	/* In level flight the disk tilts by the pitch: its inflow is
	 * V sin θ, sin θ = F_d / |T| (13.85 m/s: 9.190330453 / 43.97326 · 13.85). */
	struct mission_power p;
	mission_power(&m, 4.385, 0.0, 13.85, &p);
	assert_rel(p.axial_ms, 13.85 * 9.190330453 / (4.0 * 10.99331604), 1e-8);
	mission_power(&m, 4.385, 2.85, 0.0, &p);
	assert_rel(p.axial_ms, 2.85, 0.0);
}

/* A slippery body: every grid speed is within the limits, and the top
 * speed is searched past the grid's end (30 m/s), to the pitch limit's
 * speed when the thrust lasts (C_d,h 0.6: 25.0693306 / sqrt(0.6) =
 * 32.364367 m/s → 32.364), else to where the thrust left at the inflow
 * ends; never the grid's end itself. */
static void
mission_top_speed_past_the_grid_should_be_searched_to_a_physical_limit(void **state)
{
	(void)state;
	struct mission_model m;
	double v[64], pw[64], v_min, v_max, s_min, s_max;
	fixture_hand_model(&m, false);
	m.cd_h = 0.6;
	(void)mission_speed_sweep(&m, 4.385, 1e3, v, pw, 64, &v_min, &v_max);
	assert_rel(v_max, 32.364, 1e-12);
	assert_int_equal(mission_top_speed_limit(&m, 4.385, v_max),
	    MISSION_LIMIT_PITCH);
	mission_speed_search(&m, 4.385, 1e3, &s_min, &s_max);
	assert_true(s_max == v_max && s_min == v_min);
	/* Thrust that lasts past the grid but not to the pitch limit. */
	m.prop_j0 = 0.575;
	double t_max_n = 30.0;
	(void)mission_speed_sweep(&m, 4.385, t_max_n, v, pw, 64, &v_min, &v_max);
	assert_true(v_max > MISSION_SWEEP_V1_MS && v_max < 32.364);
	assert_int_equal(mission_top_speed_limit(&m, 4.385, v_max),
	    MISSION_LIMIT_THRUST);
	struct mission_power p;
	mission_power(&m, 4.385, 0.0, v_max, &p);
	assert_false(mission_beyond_limits(&m, &p, t_max_n));
	mission_power(&m, 4.385, 0.0, v_max + 0.001, &p);
	assert_true(mission_beyond_limits(&m, &p, t_max_n));
	mission_speed_search(&m, 4.385, t_max_n, &s_min, &s_max);
	assert_true(s_max == v_max && s_min == v_min);
	struct mission_speed_hint h = { true, 59, 10, 30500 };
	mission_speed_search_hinted(&m, 4.385, t_max_n, &s_min, &s_max, &h);
	assert_true(s_max == v_max);
	assert_true(h.k_max == lround(v_max * MISSION_SPEED_RES_PER_MS));
}

/* A thrust limit a hair above hover: the sweep's first speed (1 m/s) is
 * already past it, and the top speed lies below the grid, bisected.  By
 * hand: 4 L = W (1 + 1e-7), D = W sqrt((1 + 1e-7)² - 1) = 0.0192313 N,
 * v = 13.85 sqrt(D / 9.190330453) = 0.633556 m/s.  Below hover: 0. */
static void
mission_top_speed_below_the_first_grid_point_should_be_bisected(void **state)
{
	(void)state;
	struct mission_model m;
	double v[64], pw[64], v_min, v_max, s_min, s_max;
	fixture_hand_model(&m, false);
	double w_n = 4.385 * G0_M_S2, limit_n = 0.25 * w_n * (1.0 + 1e-7);
	(void)mission_speed_sweep(&m, 4.385, limit_n, v, pw, 64, &v_min, &v_max);
	mission_speed_search(&m, 4.385, limit_n, &s_min, &s_max);
	assert_rel(v_max, 0.633556, 0.01);
	assert_rel(s_max, v_max, 0.0);
	struct mission_power p;
	mission_power(&m, 4.385, 0.0, v_max, &p);
	assert_false(mission_beyond_limits(&m, &p, limit_n));
	mission_power(&m, 4.385, 0.0, v_max + 0.01, &p);
	assert_true(mission_beyond_limits(&m, &p, limit_n));
	/* A requested 5 m/s is flown at that top speed, within full thrust. */
	assert_rel(mission_forward_flown_ms(&m, 4.385, limit_n, 5.0, 0.0), v_max, 0.0);
	(void)mission_speed_sweep(&m, 4.385, 0.24 * w_n, v, pw, 64, &v_min, &v_max);
	assert_rel(v_max, 0.0, 0.0);
}

/* The bisection search lands on the sweep's speeds: 5000 random aircraft
 * from a 5-inch racer to a 30 kg sprayer, sea level to 5000 m, some of
 * them clipped by the thrust limit at every speed. */
static void
mission_search_should_find_the_sweeps_speeds_on_random_aircraft(void **state)
{
	(void)state;
	struct stats_rng g;
	stats_rng_seed(&g, 20261201);
	for (int k = 0; k < 5000; k++) {
		struct mission_model m;
		fixture_hand_model(&m, stats_rng_uniform(&g, 0.0, 1.0) < 0.2);
		atmo_at(stats_rng_uniform(&g, 0.0, 5000.0),
		    c_to_k(stats_rng_uniform(&g, -20.0, 45.0)), &m.air);
		m.rotor.diameter_m = stats_rng_uniform(&g, 0.12, 1.0);
		m.rotor.ct = stats_rng_uniform(&g, 0.08, 0.16);
		m.rotor.fom = stats_rng_uniform(&g, 0.45, 0.75);
		m.rotor.n_blades = stats_rng_uniform(&g, 0.0, 1.0) < 0.7 ? 2 : 3;
		m.n_rotors = (int)stats_rng_uniform(&g, 3.0, 8.99);
		m.f_scale = stats_rng_uniform(&g, 0.005, 0.03);
		m.added_drag_m2 = stats_rng_uniform(&g, 0.0, 0.1);
		m.fwd_drag_mult = stats_rng_uniform(&g, 1.0, 2.0);
		m.cd_h = stats_rng_uniform(&g, 0.6, 1.4);
		m.aux_w = stats_rng_uniform(&g, 0.0, 300.0);
		double mass_kg = stats_rng_uniform(&g, 0.3, 40.0);
		double hover_n = mass_kg * G0_M_S2 / (double)m.n_rotors;
		double t_max_n = hover_n * stats_rng_uniform(&g, 0.9, 4.0);
		double v[64], pw[64], v_min, v_max, s_min, s_max;
		(void)mission_speed_sweep(&m, mass_kg, t_max_n, v, pw, 64, &v_min,
		    &v_max);
		mission_speed_search(&m, mass_kg, t_max_n, &s_min, &s_max);
		assert_true(s_min == v_min);
		assert_true(s_max == v_max);
		/* From any hint, near or far, even off the grid: the same. */
		struct mission_speed_hint h = { true, (int)stats_rng_uniform(&g, -3.0, 65.0),
		    (int)stats_rng_uniform(&g, -3.0, 65.0),
		    (long)stats_rng_uniform(&g, 0.0, 60000.0) };
		mission_speed_search_hinted(&m, mass_kg, t_max_n, &s_min, &s_max, &h);
		assert_true(s_min == v_min);
		assert_true(s_max == v_max);
		/* ... and the hint it leaves, at a mass 1 % up: the sweep's. */
		double v_min2, v_max2;
		(void)mission_speed_sweep(&m, 1.01 * mass_kg, t_max_n, v, pw, 64,
		    &v_min2, &v_max2);
		mission_speed_search_hinted(&m, 1.01 * mass_kg, t_max_n, &s_min,
		    &s_max, &h);
		assert_true(s_min == v_min2);
		assert_true(s_max == v_max2);
	}
}

/* The hint a search leaves names the grid points of its answers: the
 * minimum-power speed and the first speed past the limits. */
static void
mission_search_hint_should_name_the_grid_points_of_its_answers(void **state)
{
	(void)state;
	struct mission_model m;
	fixture_hand_model(&m, false);
	double mass_kg = 4.0;
	double t_max_n = 2.0 * mass_kg * G0_M_S2 / (double)m.n_rotors;
	struct mission_speed_hint h = { false, 0, 0, 0 };
	double s_min, s_max;
	mission_speed_search_hinted(&m, mass_kg, t_max_n, &s_min, &s_max, &h);
	assert_true(h.set);
	assert_true(h.i_min > 0 && h.i_min < h.n_ok - 1);
	assert_true(s_min == MISSION_SWEEP_V0_MS + MISSION_SWEEP_STEP_MS * h.i_min);
	/* The top speed lies between the last grid speed within the limits
	 * and the first past them, on the millimetre lattice. */
	assert_true(s_max >= MISSION_SWEEP_V0_MS
	    + MISSION_SWEEP_STEP_MS * (h.n_ok - 1));
	assert_true(s_max < MISSION_SWEEP_V0_MS + MISSION_SWEEP_STEP_MS * h.n_ok);
	assert_true(s_max == (double)h.k_max / MISSION_SPEED_RES_PER_MS);
	/* Searched again from it: the same answers and the same hint. */
	struct mission_speed_hint h2 = h;
	double s_min2, s_max2;
	mission_speed_search_hinted(&m, mass_kg, t_max_n, &s_min2, &s_max2, &h2);
	assert_true(s_min2 == s_min && s_max2 == s_max);
	assert_int_equal(h2.n_ok, h.n_ok);
	assert_int_equal(h2.i_min, h.i_min);
	assert_true(h2.k_max == h.k_max);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(mission_hover_power_should_follow_the_power_budget),
		cmocka_unit_test(mission_climb_thrust_should_add_the_vertical_drag),
		cmocka_unit_test(mission_forward_flight_should_pitch_and_tilt_the_thrust),
		cmocka_unit_test(mission_coaxial_should_raise_induced_power_by_1_22),
		cmocka_unit_test(mission_sweep_should_cover_1_to_30_m_s_in_half_steps),
		cmocka_unit_test(mission_max_climb_should_stop_where_the_climb_drag_meets_the_thrust),
		cmocka_unit_test(mission_sweep_should_stop_v_max_at_the_thrust_limit),
		cmocka_unit_test(mission_envelope_should_lose_thrust_with_the_inflow),
		cmocka_unit_test(mission_top_speed_past_the_grid_should_be_searched_to_a_physical_limit),
		cmocka_unit_test(mission_top_speed_below_the_first_grid_point_should_be_bisected),
		cmocka_unit_test(mission_search_should_find_the_sweeps_speeds_on_random_aircraft),
		cmocka_unit_test(mission_search_hint_should_name_the_grid_points_of_its_answers),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
