/* test_discharge.c — the time-step discharge simulation (paper Module 4,
 * §VI-B..G): the first step worked by hand (OCV, R_sys, quadratic current,
 * SOC and exact thermal step), energy bookkeeping, every early stop
 * (voltage collapse, power overflow, thermal runaway, depletion or the
 * voltage floor), and monotonic responses (ambient → peak temperature,
 * mass → hover endurance).
 *
 * Hand aircraft: 4.385 kg quad at ISA sea level, D = 0.3385 m rotors at
 * installed FoM 0.585, η 0.85, aux 22.5 W — hover electrical power
 * 626.4648146 W (worked in test_mission.c).  Hand pack: LiPo 6S 5.385 Ah,
 * 0.8385 kg, new, 4 ESCs, h = 12 W/(m² K).
 */
#include "test_util.h"
#include "test_fixtures.h"
#include "physics/discharge.h"

#include <math.h>
#include <string.h>

#define HOVER_W 626.4648146



static void
hand_pack(struct discharge_pack *p, const struct batt_chem *c)
{
	p->chem = c;
	p->cells = 6;
	p->capacity_ah = 5.385;
	p->mass_kg = 0.8385;
	p->cycles = 0;
	p->n_rotors = 4;
	p->h_conv_w_m2k = 12.0;
	p->r_cells_ohm = 0.0;
}

/* Hover only, 600 s, at 15 °C, no shedding. */
static void
hover_mission(struct discharge_mission *d, const struct mission_model *m,
              double hover_s)
{
	memset(d, 0, sizeof *d);
	d->model = m;
	d->dry_mass_kg = 4.385;
	d->shed.kind = SHED_NONE;
	d->duration_s[PHASE_HOVER] = hover_s;
	d->ambient_c = 15.0;
}

static void
discharge_first_step_should_match_the_hand_computation(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out out;
	struct res_sample tr[80];
	int n = 0;
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	hover_mission(&d, &m, 600.0);
	discharge_run(&pk, &d, 60, tr, 80, &n, &out);
	assert_int_equal(out.end, DIS_COMPLETED);
	/* 60 steps of dt = 10 s, plus the t = 0 sample */
	assert_int_equal(n, 61);
	/* t = 0: full pack, V_oc = 6 · 4.2 = 25.2 V */
	assert_rel(tr[0].t_s, 0.0, 0.0);
	assert_rel(tr[0].v_oc_v, 25.2, 1e-12);
	assert_rel(tr[0].power_w, HOVER_W, 1e-9);
	/* Heun's step from t = 0, predictor first.
	 * R_sys at 15 °C: 1e-3 · 5 · 6 · (5/5.385) · exp(-0.013 · (15 - 25)) + 0.002/4
	 *   = 0.03 · 0.928505107 · 1.138828383 + 0.0005 = 0.032222239 Ω
	 * I0 = 2 · 626.4648146 / (25.2 + sqrt(635.04 - 4 · 0.032222239 · 626.4648146))
	 *    = 25.704556702 A, V_term0 = 25.2 - I0 · R_sys = 24.371741628 V
	 * Heat in the cells only: I0² (R_sys - R_ds,on/N_r) = 20.959652162 W; hA =
	 * 0.357157998 W/K, C_th = 666.6075 J/K, so the predicted end is
	 *   T1 = 15 + 58.684628 (1 - exp(-0.357157998 · 10 / 666.6075)) = 15.313581876 °C
	 *   SOC1 = 1 - I0 · 10 / (3600 · 5.385) = 0.986740660 */
	assert_rel(tr[0].current_a, 25.7045567, 1e-8);
	assert_rel(tr[0].v_term_v, 24.37174163, 1e-9);
	/* The corrector at the predicted end, B_eff at C = I0 / 5.385 = 4.773362433:
	 *   B_eff = 5.5 (1 + 0.18 ln 4.773362433) = 7.047420459
	 *   V_oc1 = 6 (3.9 + 0.3 exp(-7.047420459 · 0.013259340) - 0.046 (1/0.986740660 - 1))
	 *         = 25.035711246 V
	 *   R_sys1 = 0.03 · 0.928505107 · exp(-0.013 · (15.313581876 - 25)) + 0.0005
	 *          = 0.032093185 Ω
	 *   I1 = 25.881531625 A, V_term1 = 24.205090474 V, heat 21.162810928 W */
	assert_rel(tr[1].t_s, 10.0, 1e-12);
	assert_rel(tr[1].v_oc_v, 25.03571125, 1e-9);
	assert_rel(tr[1].current_a, 25.88153163, 1e-8);
	assert_rel(tr[1].v_term_v, 24.20509047, 1e-9);
	/* The step moves on the means: I = (I0 + I1) / 2 = 25.793044163 A,
	 *   SOC = 1 - 25.793044163 · 10 / (3600 · 5.385) = 0.986695015
	 *   T = 15 + (20.959652162 + 21.162810928) / 2 / 0.357157998
	 *       · (1 - exp(-0.357157998 · 10 / 666.6075)) = 15.315101627 °C */
	assert_rel(tr[1].soc, 0.98669502, 1e-8);
	assert_rel(tr[1].temp_c, 15.3151016, 1e-8);
}

static void
discharge_energy_should_add_up_over_the_phases(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out out;
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	hover_mission(&d, &m, 385.0);
	d.duration_s[PHASE_CLIMB] = 23.85;
	d.speed_ms[PHASE_CLIMB] = 2.85;
	d.duration_s[PHASE_FORWARD] = 238.5;
	d.speed_ms[PHASE_FORWARD] = 13.85;
	discharge_run(&pk, &d, 200, NULL, 0, NULL, &out);
	assert_int_equal(out.end, DIS_COMPLETED);
	assert_rel(out.t_end_s, 23.85 + 238.5 + 385.0, 1e-9);
	double sum = 0.0;
	for (int i = 0; i < PHASE_MAX; i++) {
		assert_true(out.phase_energy_wh[i] > 0.0);
		sum += out.phase_energy_wh[i];
	}
	assert_rel(sum, out.wh_used, 1e-12);
	/* Coulomb counting: ΔSOC · C = Ah drawn */
	assert_rel((1.0 - out.end_soc) * 5.385, out.ah_used, 1e-9);
	/* Hover energy ≈ 626.4648146 W · 385 s / 3600 = 66.9969 Wh */
	assert_rel(out.phase_energy_wh[PHASE_HOVER], 66.99693, 1e-6);
	assert_true(out.peak_temp_c > 15.0 && out.peak_temp_c < 60.0);
	assert_true(out.min_v_term_v > 6.0 * 3.3);
}

static void
discharge_should_stop_on_voltage_collapse(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out out;
	c.r_cell_mohm = 500.0; /* R_sys ≈ 3.2 Ω: V²/(4R) = 635.04/12.9 ≈ 49 W < 626 W */
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	hover_mission(&d, &m, 600.0);
	discharge_run(&pk, &d, 60, NULL, 0, NULL, &out);
	assert_int_equal(out.end, DIS_COLLAPSE);
	assert_rel(out.t_end_s, 0.0, 0.0);
}

static void
discharge_should_stop_on_power_overflow(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out out;
	fixture_hand_model(&m, false);
	m.aux_w = 2e7; /* above the 1e7 W guard */
	hand_pack(&pk, &c);
	hover_mission(&d, &m, 600.0);
	discharge_run(&pk, &d, 60, NULL, 0, NULL, &out);
	assert_int_equal(out.end, DIS_OVERFLOW);
	assert_true(isfinite(out.wh_used) && isfinite(out.peak_temp_c));
}

static void
discharge_should_stop_on_thermal_runaway_above_60_c(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out out;
	struct res_sample tr[200];
	int n = 0;
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	/* 0.1 kg of thermal mass (C_th = 79.5 J/K) in still air (h = 1:
	 * hA = 0.06 (100/2400)^(2/3) = 0.0072 W/K) heated by ≈ 21 W: it warms by
	 * ≈ 0.26 K/s, from 45 °C past 60 °C in about a minute. */
	pk.mass_kg = 0.1;
	pk.h_conv_w_m2k = 1.0;
	hover_mission(&d, &m, 600.0);
	d.ambient_c = 45.0;
	discharge_run(&pk, &d, 120, tr, 200, &n, &out);
	assert_int_equal(out.end, DIS_THERMAL);
	assert_true(out.peak_temp_c > 60.0);
	assert_true(out.t_end_s < 600.0);
	assert_true(tr[n - 1].temp_c > 60.0);
	for (int i = 0; i < n - 1; i++)
		assert_true(tr[i].temp_c <= 60.0);
}

static void
discharge_should_stop_when_the_pack_runs_out(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out out;
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	/* 5.385 Ah at ≈ 26 A lasts ≈ 12 min; ask for 30 min */
	hover_mission(&d, &m, 1800.0);
	discharge_run(&pk, &d, 300, NULL, 0, NULL, &out);
	assert_true(out.end == DIS_DEPLETED || out.end == DIS_VOLTAGE_FLOOR);
	assert_true(out.t_end_s > 300.0 && out.t_end_s < 1800.0);
	assert_true(isfinite(out.min_v_term_v) && out.min_v_term_v > 0.0);
}

static void
discharge_peak_temperature_should_rise_with_ambient(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out cold, hot;
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	hover_mission(&d, &m, 600.0);
	d.ambient_c = 5.0;
	discharge_run(&pk, &d, 120, NULL, 0, NULL, &cold);
	d.ambient_c = 38.5;
	discharge_run(&pk, &d, 120, NULL, 0, NULL, &hot);
	assert_int_equal(cold.end, DIS_COMPLETED);
	assert_int_equal(hot.end, DIS_COMPLETED);
	assert_true(hot.peak_temp_c > cold.peak_temp_c);
}

static void
discharge_hover_endurance_should_fall_with_mass(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	double light = discharge_hover_endurance_s(&pk, &m, 4.385, 15.0, 1.0 / 6.0);
	double heavy = discharge_hover_endurance_s(&pk, &m, 5.385, 15.0, 1.0 / 6.0);
	assert_true(light > heavy && heavy > 0.0);
	/* Nominal estimate: 5.385 Ah · 5/6 · 22.2 V · 3600 / 626.4648 W = 572.6 s;
	 * the simulated pack sits above nominal voltage most of the way, so it
	 * lasts a little longer, within 15 %. */
	assert_rel(light, 572.6, 0.15);
}

/* Heun's step is second order: halving the step quarters the error in
 * the charge drawn (against 1920 steps, converged to 1e-9 here), and the
 * 30 steps of a loop flight are within 3e-5 of it. */
static void
discharge_should_converge_at_second_order(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out out;
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	hover_mission(&d, &m, 520.0);
	d.ambient_c = 25.0;
	discharge_run(&pk, &d, 1920, NULL, 0, NULL, &out);
	assert_int_equal(out.end, DIS_COMPLETED);
	double ref_ah = out.ah_used;
	double err[3];
	for (int k = 0; k < 3; k++) {
		discharge_run(&pk, &d, 15 << k, NULL, 0, NULL, &out);
		assert_int_equal(out.end, DIS_COMPLETED);
		err[k] = fabs(out.ah_used - ref_ah) / ref_ah;
	}
	assert_true(err[1] < 3e-5);
	for (int k = 0; k < 2; k++) {
		double order = log2(err[k] / err[k + 1]);
		if (order < 1.6 || order > 2.4)
			print_error("order %g from %g to %g\n", order, err[k], err[k + 1]);
		assert_true(order >= 1.6 && order <= 2.4);
	}
}

/* A drop inside a step: the step draws each mass's power for its share of
 * the step, so the energy is exactly the two constant powers' (the drop at
 * 305 s falls mid-way through the 31st of 60 steps of 10 s). */
static void
discharge_drop_should_split_the_step_that_holds_it(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out out;
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	hover_mission(&d, &m, 600.0);
	d.dry_mass_kg = 3.385;
	d.shed = (struct role_shedding){ SHED_DROP, 1.0, 1.0, 305.0, 0.0, 0.0 };
	discharge_run(&pk, &d, 60, NULL, 0, NULL, &out);
	assert_int_equal(out.end, DIS_COMPLETED);
	struct mission_power full, empty;
	mission_power(&m, 4.385, 0.0, 0.0, &full);
	mission_power(&m, 3.385, 0.0, 0.0, &empty);
	double want_wh = (full.electrical_w * 305.0 + empty.electrical_w * 295.0) / 3600.0;
	assert_rel(out.wh_used, want_wh, 1e-12);
}

/* A sprayer's power follows its falling mass: interpolated between exact
 * values every few steps (a parabola through three), each step's power is
 * within 1e-6 of the exact power at that step's mid-step mass (30 times
 * below the time step's own 3e-5), at the 60 steps of a final flight, on
 * every phase and across the step where the tank runs dry (the mass stops
 * falling at 700 s).  The tank here is a quarter of the takeoff mass. */
static void
discharge_spray_power_should_follow_the_mass(void **state)
{
	(void)state;
	struct batt_chem c = fixture_lipo();
	struct mission_model m;
	struct discharge_pack pk;
	struct discharge_mission d;
	struct discharge_out out;
	static struct res_sample tr[256];
	int n = 0;
	fixture_hand_model(&m, false);
	hand_pack(&pk, &c);
	pk.capacity_ah = 12.0;
	pk.mass_kg = 1.9;
	hover_mission(&d, &m, 500.0);
	d.dry_mass_kg = 3.385;
	d.duration_s[PHASE_CLIMB] = 40.0;
	d.speed_ms[PHASE_CLIMB] = 2.0;
	d.duration_s[PHASE_FORWARD] = 400.0;
	d.speed_ms[PHASE_FORWARD] = 8.0;
	d.shed = (struct role_shedding){ SHED_SPRAY, 1.0, 0.0, 0.0, 1.0 / 700.0, 1.0 };
	discharge_run(&pk, &d, 60, tr, 256, &n, &out);
	assert_int_equal(out.end, DIS_COMPLETED);
	assert_true(n >= 60);
	int exact_after_dry = 0;
	for (int k = 1; k < n; k++) {
		struct mission_power pw;
		double v_climb = tr[k].phase == PHASE_CLIMB ? 2.0 : 0.0;
		double v_fwd = tr[k].phase == PHASE_FORWARD ? 8.0 : 0.0;
		mission_power(&m, tr[k].mass_kg, v_climb, v_fwd, &pw);
		assert_rel(tr[k].power_w, pw.electrical_w, 1e-6);
		exact_after_dry += tr[k].mass_kg == d.dry_mass_kg;
	}
	assert_true(exact_after_dry > 10); /* the tank ran dry mid-mission */
	assert_true(tr[1].mass_kg > tr[n - 1].mass_kg);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(discharge_first_step_should_match_the_hand_computation),
		cmocka_unit_test(discharge_energy_should_add_up_over_the_phases),
		cmocka_unit_test(discharge_should_stop_on_voltage_collapse),
		cmocka_unit_test(discharge_should_stop_on_power_overflow),
		cmocka_unit_test(discharge_should_stop_on_thermal_runaway_above_60_c),
		cmocka_unit_test(discharge_should_stop_when_the_pack_runs_out),
		cmocka_unit_test(discharge_peak_temperature_should_rise_with_ambient),
		cmocka_unit_test(discharge_hover_endurance_should_fall_with_mass),
		cmocka_unit_test(discharge_spray_power_should_follow_the_mass),
		cmocka_unit_test(discharge_should_converge_at_second_order),
		cmocka_unit_test(discharge_drop_should_split_the_step_that_holds_it),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
