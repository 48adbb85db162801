/* test_duty.c — the roles' duty cycles (physics/duty.h, data/roles.json):
 * the plans laid out by hand-worked rules (whole laps of the lap's
 * pieces, turns from the forward distance and the swath length, the drop
 * after the out-leg and the hover, the bounds on long missions), energy =
 * ∫P dt over a plan, and the examples flown with the shipped data: the
 * FPV quad races and heats its pack, lands on the reserve with a battery
 * sized by the race's energy, the sprayer turns at its swath ends and
 * sheds its tank while it sprays, the delivery quad releases its parcel
 * at the drop point after the out-leg; and a property: a longer race
 * never makes the aircraft lighter.  Tests run from the repository root.
 */
#include "test_util.h"
#include "test_missions.h"
#include "test_fixtures.h"
#include "cli/cli.h"
#include "diag/diag.h"
#include "engine/engine.h"
#include "input/mission_io.h"
#include "physics/discharge.h"
#include "physics/duty.h"
#include "sizing/sizing.h"
#include "util/units.h"
#include "util/xalloc.h"

#include <stdlib.h>
#include <string.h>

/* ---- plans ----------------------------------------------------------------- */

/* A race profile: 14.85 s laps of a burst, a run and a corner. */
static void
race_duty(struct model_duty *d)
{
	memset(d, 0, sizeof *d);
	d->kind = DUTY_RACE;
	d->lap_s = 14.85;
	d->n_lap = 3;
	d->lap[0] = (struct model_lap_piece){ "burst", 0.125, 1.0 };
	d->lap[1] = (struct model_lap_piece){ "run", 0.475, 0.2 };
	d->lap[2] = (struct model_lap_piece){ "corner", 0.4, 0.05 };
}

/* The mission a plan is built from: the phases' times and speeds. */
static void
mission_in(struct duty_input *in, const struct model_duty *d, double t_climb_s,
           double t_fwd_s, double t_hover_s, double v_climb_ms, double v_fwd_ms,
           double payload_kg)
{
	memset(in, 0, sizeof *in);
	in->duty = d;
	in->duration_s[PHASE_CLIMB] = t_climb_s;
	in->duration_s[PHASE_FORWARD] = t_fwd_s;
	in->duration_s[PHASE_HOVER] = t_hover_s;
	in->v_climb_ms = v_climb_ms;
	in->v_fwd_ms = v_fwd_ms;
	in->payload_kg = payload_kg;
}

static void
duty_race_should_fly_whole_laps_of_its_pieces(void **state)
{
	(void)state;
	struct model_duty d;
	race_duty(&d);
	struct duty_input in;
	mission_in(&in, &d, 8.5, 128.5, 23.85, 6.0, 18.5, 0.0385);
	static struct duty_plan pl;
	duty_plan_build(&in, &pl);
	assert_int_equal(pl.kind, DUTY_RACE);
	/* 128.5 / 14.85 = 8.653: 9 laps of 128.5 / 9 = 14.2778 s */
	assert_int_equal(pl.n_laps, 9);
	assert_rel(pl.lap_s, 128.5 / 9.0, 1e-12);
	/* launch climb, 9 × 3 pieces, hover */
	assert_int_equal(pl.n_seg, 1 + 27 + 1);
	assert_rel(pl.total_s, 8.5 + 128.5 + 23.85, 1e-12);
	assert_rel(pl.phase_s[PHASE_FORWARD], 128.5, 1e-12);
	/* mean 0.125 + 0.475 · 0.2 + 0.4 · 0.05 = 0.24, peak 1 */
	assert_rel(pl.lap_mean_fraction, 0.24, 1e-12);
	assert_rel(pl.lap_peak_fraction, 1.0, 0.0);
	/* Each piece's time is its share of the race, counted once per lap. */
	for (int g = 1; g <= 3; g++) {
		assert_int_equal(pl.group[g].count, 9);
		assert_rel(pl.group[g].dur_s, d.lap[g - 1].share * 128.5, 1e-12);
	}
	for (int i = 1; i <= 27; i++) {
		assert_int_equal(pl.seg[i].law, DUTY_LAW_THROTTLE);
		assert_int_equal(pl.seg[i].phase, PHASE_FORWARD);
	}
}

static void
duty_long_race_should_fly_a_bounded_plan_of_the_same_times(void **state)
{
	(void)state;
	struct model_duty d;
	race_duty(&d);
	struct duty_input in;
	mission_in(&in, &d, 0.0, 3600.0, 0.0, 0.0, 0.0, 0.0);
	static struct duty_plan pl;
	duty_plan_build(&in, &pl);
	/* 3600 / 14.85 = 242.4: 242 laps, flown as 24 of 150 s */
	assert_int_equal(pl.n_laps, 242);
	assert_int_equal(pl.n_seg, DUTY_MAX_LAPS * 3);
	assert_true(pl.n_seg <= DUTY_MAX_SEG);
	for (int g = 0; g < 3; g++)
		assert_rel(pl.group[g].dur_s, d.lap[g].share * 3600.0, 1e-12);
	assert_rel(pl.total_s, 3600.0, 1e-12);
}

/* A spray profile as data/roles.json states it. */
static void
spray_duty(struct model_duty *d)
{
	memset(d, 0, sizeof *d);
	d->kind = DUTY_SPRAY;
	d->swath_length_m = 125.0;
	d->turn_accel_m_s2 = 2.5;
	d->turn_yaw_s = 3.0;
	d->transit_m = 50.0;
}

static void
duty_spray_turns_should_follow_the_swath_rule(void **state)
{
	(void)state;
	struct model_duty d;
	spray_duty(&d);
	static const double t_fwd[] = { 10.0, 60.0, 238.5, 480.0, 600.0, 5000.0 };
	for (size_t k = 0; k < sizeof t_fwd / sizeof t_fwd[0]; k++) {
		struct duty_input in;
		mission_in(&in, &d, 20.0, t_fwd[k], 60.0, 2.0, 5.85, 20.0);
		in.shed = SHED_SPRAY;
		static struct duty_plan pl;
		duty_plan_build(&in, &pl);
		double dist = 5.85 * t_fwd[k];
		double tr = dist / 4.0 < 50.0 ? dist / 4.0 : 50.0;
		int passes = (int)ceil((dist - 2.0 * tr) / 125.0 - 1e-9);
		if (passes < 1)
			passes = 1;
		assert_int_equal(pl.n_passes, passes);
		assert_int_equal(pl.n_turns, passes - 1);
		double turn_s = 2.0 * 5.85 / 2.5 + 3.0;
		assert_rel(pl.turn_s, turn_s, 1e-12);
		/* the turns add their time to the forward time */
		assert_rel(pl.phase_s[PHASE_FORWARD], t_fwd[k]
		    + (double)(passes - 1) * turn_s, 1e-12);
		assert_true(pl.n_seg <= DUTY_MAX_SEG);
		/* The tank is shed on the passes only, and empties on the last. */
		double sprayed = 0.0, pay = 20.0;
		for (int i = 0; i < pl.n_seg; i++) {
			const struct duty_segment *s = &pl.seg[i];
			assert_rel(s->payload0_kg, pay, 1e-9);
			bool pass = strcmp(pl.group[s->group].name, "spraying pass") == 0;
			assert_true(pass == (s->shed_kg_s > 0.0));
			if (strcmp(pl.group[s->group].name, "swath-end turn") == 0)
				assert_int_equal(s->law, DUTY_LAW_TURN);
			double end = duty_payload_at(s, s->dur_s);
			sprayed += s->payload0_kg - end;
			pay = end;
		}
		assert_rel(sprayed, 20.0, 1e-9);
		assert_rel(pl.spray_s, (dist - 2.0 * tr) / 5.85, 1e-12);
	}
}

static void
duty_out_and_back_should_release_after_the_out_leg_and_the_hover(void **state)
{
	(void)state;
	struct model_duty d;
	memset(&d, 0, sizeof d);
	d.kind = DUTY_OUT_AND_BACK;
	struct duty_input in;
	mission_in(&in, &d, 38.5, 1238.5, 123.85, 3.0, 13.85, 3.85);
	in.shed = SHED_DROP;
	in.drop_mass_kg = 2.385;
	in.drop_ratio = 0.385;
	static struct duty_plan pl;
	duty_plan_build(&in, &pl);
	assert_int_equal(pl.n_seg, 4);
	/* climb, out-leg 0.385 · 1238.5 = 476.8225 s, hover, return */
	assert_rel(pl.seg[1].dur_s, 476.8225, 1e-12);
	assert_rel(pl.drop_time_s, 38.5 + 476.8225 + 123.85, 1e-12);
	assert_int_equal(pl.seg[2].phase, PHASE_HOVER);
	for (int i = 0; i < 3; i++)
		assert_rel(pl.seg[i].payload0_kg, 3.85, 0.0);
	assert_rel(pl.seg[3].payload0_kg, 3.85 - 2.385, 1e-12);
	assert_rel(pl.seg[3].dur_s, 1238.5 - 476.8225, 1e-12);
	assert_rel(pl.phase_s[PHASE_FORWARD], 1238.5, 1e-12);
}

/* ---- a plan flown ---------------------------------------------------------- */

/* Energy = ∫P dt over a race: with a pack that does not sag below what
 * full throttle asks, each piece draws its fraction of full throttle (or
 * the hover power), and the energy drawn is their sum over time. */
static void
discharge_race_energy_should_be_the_pieces_power_over_time(void **state)
{
	(void)state;
	struct batt_chem chem = fixture_lipo();
	struct mission_model m;
	fixture_hand_model(&m, false);
	struct model_duty d;
	race_duty(&d);
	struct duty_input in;
	mission_in(&in, &d, 0.0, 120.0, 0.0, 0.0, 0.0, 0.0);
	static struct duty_plan pl;
	duty_plan_build(&in, &pl);
	/* A 20 Ah pack: full throttle never sags below the cut-off. */
	struct discharge_pack pk = { &chem, 6, 20.0, 2.0, 0, 4, 120.0, 0.0 };
	struct discharge_mission dm;
	memset(&dm, 0, sizeof dm);
	dm.model = &m;
	dm.dry_mass_kg = 4.385;
	dm.plan = &pl;
	dm.full_throttle_w = 4985.0;
	dm.full_throttle_shaft_w = 3988.0;
	/* full throttle given down to the cut-off: the pack never limits it */
	dm.full_throttle_v = 6.0 * chem.v_cutoff;
	dm.ambient_c = 15.0;
	struct discharge_out out;
	discharge_run(&pk, &dm, 60, NULL, 0, NULL, &out);
	assert_int_equal(out.end, DIS_COMPLETED);
	struct mission_power hv;
	mission_power(&m, 4.385, 0.0, 0.0, &hv);
	double want = 0.0;
	for (int k = 0; k < 3; k++) {
		double p = d.lap[k].power_fraction * 4985.0;
		double e = (p > hv.electrical_w ? p : hv.electrical_w)
		    * d.lap[k].share * 120.0 / S_PER_H;
		assert_rel(out.group_energy_wh[k], e, 1e-9);
		want += e;
	}
	/* the corner flies at the hover power, the burst at full throttle */
	assert_true(hv.electrical_w > 0.05 * 4985.0);
	assert_rel(out.wh_used, want, 1e-9);
	assert_rel(out.phase_energy_wh[PHASE_FORWARD], want, 1e-9);
	assert_rel(out.peak_power_w, 4985.0, 1e-12);
}

/* ---- the examples ---------------------------------------------------------- */

struct fixture {
	struct cli_env env;
	struct solve_result *r;
};

static int
setup(void **state)
{
	struct fixture *f = xcalloc(1, sizeof *f);
	if (cli_env_load(&f->env, NULL, 1, stderr) != 0) {
		free(f);
		return -1;
	}
	f->r = xcalloc(1, sizeof *f->r);
	*state = f;
	return 0;
}

static int
teardown(void **state)
{
	struct fixture *f = *state;
	cli_env_free(&f->env);
	free(f->r);
	free(f);
	return 0;
}

static void
load(const struct fixture *f, const char *path, struct mission_spec *s)
{
	struct diag *dg = diag_alloc(NULL);
	assert_int_equal(mission_io_load(path, f->env.model.chem_names, dg, s), 0);
	diag_free(dg);
}

/* The example solved with the catalogue; its design of record. */
static const struct res_run *
solve_example(struct fixture *f, const char *path, struct mission_spec *s)
{
	load(f, path, s);
	memset(f->r, 0, sizeof *f->r);
	/* 0: every invariant held, energy = ∫P dt among them */
	assert_int_equal(engine_solve(s, &f->env.model, f->env.cat, f->r), 0);
	bool buildable = false;
	const struct res_run *o = res_record(f->r, &buildable);
	assert_true(buildable);
	return o;
}

static void
fpv_design_of_record_should_race_and_heat_its_pack(void **state)
{
	struct fixture *f = *state;
	struct mission_spec s;
	const struct res_run *o = solve_example(f, "examples/fpv_racing_quad.json", &s);
	const struct res_duty *d = &o->duty;
	assert_int_equal(d->kind, DUTY_RACE);
	/* 120 s of forward flight: 8 laps of 15 s */
	assert_int_equal(d->n_laps, 8);
	assert_rel(d->race_s, 120.0, 1e-9);
	/* The race's mean current empties the usable charge in minutes: a
	 * large fraction of the capacity per hour (C/12 at least). */
	double usable_ah = (1.0 - o->reserve_soc) * o->capacity_mah / 1000.0;
	assert_true(d->race_mean_current_a > 0.0);
	double to_reserve_s = usable_ah / d->race_mean_current_a * S_PER_H;
	print_message("race: %.1f A mean on %.0f mAh: the reserve in %.0f s; "
	    "pack %.1f °C in %.1f °C air; lands at %.3f\n", d->race_mean_current_a,
	    o->capacity_mah, to_reserve_s, o->max_battery_temp_c, s.ambient_temp_c,
	    o->end_soc);
	assert_true(to_reserve_s < 300.0);
	/* its bursts are full throttle, its mean near the evidence's top */
	assert_rel(d->peak_power_w, d->full_throttle_power_w, 1e-6);
	assert_true(d->lap_mean_fraction > 0.15 && d->lap_mean_fraction < 0.3);
	/* The pack heats: flown as 120 s of cruise it rose 0.6 K; the race
	 * puts it well above the air (5 K at least; how far turns on the
	 * pack's resistance, a 120 C pack heats least). */
	assert_true(o->max_battery_temp_c >= s.ambient_temp_c + 5.0);
	/* and lands with its reserve */
	assert_true(o->end_soc >= o->reserve_soc - SIZING_RESERVE_TOL);
}

/* A battery free of the power floors, sized by the race's energy alone:
 * the FPV mission's custom aircraft on a LiPo whose cells could deliver
 * any power lands on the reserve after its race. */
static void
fpv_race_should_land_on_the_reserve_with_a_battery_sized_by_its_energy(void **state)
{
	struct fixture *f = *state;
	struct mission_spec s;
	load(f, "examples/fpv_racing_quad.json", &s);
	engine_resolve(&s, &f->env.model, NULL);
	struct sizing_params p;
	engine_params(&s, &f->env.model, false, &p);
	struct batt_chem free_power = *p.chem;
	free_power.p_spec_w_kg = 1e9;
	p.chem = &free_power;
	struct res_run *o = xcalloc(1, sizeof *o);
	assert_int_equal(sizing_run(&p, o), SIZING_CONVERGED);
	assert_false(o->battery_power_binds);
	assert_int_equal(o->duty.kind, DUTY_RACE);
	print_message("free battery: %.0f mAh, lands at %.4f (reserve %.4f)\n",
	    o->capacity_mah, o->end_soc, o->reserve_soc);
	assert_true(fabs(o->end_soc - o->reserve_soc) <= 0.005);
	free(o);
}

static void
agriculture_should_turn_at_its_swath_ends_and_shed_while_spraying(void **state)
{
	struct fixture *f = *state;
	struct mission_spec s;
	const struct res_run *o = solve_example(f, "examples/agri_spray_octo.json", &s);
	const struct res_duty *d = &o->duty;
	assert_int_equal(d->kind, DUTY_SPRAY);
	/* the rule: passes = ⌈(v t - 2 · transit) / swath⌉, a turn between two */
	double v = o->phase[PHASE_FORWARD].speed_ms;
	double dist = v * s.t_forward_s;
	int passes = (int)ceil((dist - 2.0 * d->transit_m) / d->swath_length_m - 1e-9);
	assert_true(d->n_turns > 0);
	assert_int_equal(d->n_passes, passes);
	assert_int_equal(d->n_turns, passes - 1);
	assert_rel(o->flight_time_s, s.t_climb_s + s.t_forward_s + s.t_hover_s
	    + (double)d->n_turns * d->turn_s, 1e-9);
	/* The whole tank is shed, while spraying only: full through the climb
	 * and the transit, empty from the last pass on. */
	assert_rel(d->tank_shed_kg, s.payload_kg, 1e-9);
	assert_rel(d->landing_payload_kg, 0.0, 0.0);
	double m0 = o->trace[0].mass_kg;
	double t_full = s.t_climb_s + d->transit_m / v;
	double t_empty = o->flight_time_s - s.t_hover_s - d->transit_m / v;
	int during = 0;
	for (int i = 1; i < o->n_trace; i++) {
		const struct res_sample *t = &o->trace[i];
		assert_true(t->mass_kg <= o->trace[i - 1].mass_kg);
		if (t->t_s <= t_full + 1e-9)
			assert_rel(t->mass_kg, m0, 1e-12);
		else if (t->t_s >= t_empty + 1e-6)
			assert_rel(t->mass_kg, m0 - s.payload_kg, 1e-9);
		else
			during++;
	}
	assert_true(during > d->n_passes / 2);
}

static void
delivery_should_release_its_parcel_at_the_drop_point_after_the_out_leg(void **state)
{
	struct fixture *f = *state;
	struct mission_spec s;
	const struct res_run *o = solve_example(f, "examples/delivery_drop_3p5kg.json", &s);
	const struct res_duty *d = &o->duty;
	assert_int_equal(d->kind, DUTY_OUT_AND_BACK);
	double r = s.payload_role.delivery_drop_time_ratio;
	double t_drop = s.t_climb_s + r * s.t_forward_s + s.t_hover_s;
	assert_rel(d->drop_time_s, t_drop, 1e-12);
	assert_rel(d->drop_mass_kg, s.payload_role.delivery_drop_mass_kg, 1e-12);
	double m0 = o->trace[0].mass_kg;
	int before = 0, after = 0;
	for (int i = 0; i < o->n_trace; i++) {
		const struct res_sample *t = &o->trace[i];
		if (t->t_s <= t_drop + 1e-6) {
			assert_rel(t->mass_kg, m0, 1e-12);
			/* out-leg, then the hover over the drop point */
			if (t->t_s > s.t_climb_s + r * s.t_forward_s + 1e-6)
				assert_int_equal(t->phase, PHASE_HOVER);
			before++;
		} else {
			assert_rel(t->mass_kg, m0 - d->drop_mass_kg, 1e-9);
			assert_int_equal(t->phase, PHASE_FORWARD);
			after++;
		}
	}
	assert_true(before > 10 && after > 10);
}

/* A longer race never makes the aircraft lighter: the FPV mission's
 * continuous design over races of 60 to 330 s. */
static void
longer_race_should_never_lighten_the_aircraft(void **state)
{
	struct fixture *f = *state;
	struct mission_spec s;
	load(f, "examples/fpv_racing_quad.json", &s);
	double prev = 0.0;
	int sized = 0;
	for (double t = 60.0; t <= 330.0; t += 22.5) {
		struct mission_spec q = s;
		SET(&q, T_FORWARD_S, t_forward_s, t);
		memset(f->r, 0, sizeof *f->r);
		f->r->skip_ceiling = true;
		assert_int_equal(engine_solve(&q, &f->env.model, NULL, f->r), 0);
		const struct res_run *o = &f->r->custom;
		if (!(o->ran && o->converged && o->feasible))
			break;
		print_message("race %.1f s: %.4f kg\n", t, o->mass.total_kg);
		assert_true(o->mass.total_kg >= prev * (1.0 - 0.005));
		prev = o->mass.total_kg;
		sized++;
	}
	assert_true(sized >= 8);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(duty_race_should_fly_whole_laps_of_its_pieces),
		cmocka_unit_test(duty_long_race_should_fly_a_bounded_plan_of_the_same_times),
		cmocka_unit_test(duty_spray_turns_should_follow_the_swath_rule),
		cmocka_unit_test(duty_out_and_back_should_release_after_the_out_leg_and_the_hover),
		cmocka_unit_test(discharge_race_energy_should_be_the_pieces_power_over_time),
		cmocka_unit_test(fpv_design_of_record_should_race_and_heat_its_pack),
		cmocka_unit_test(fpv_race_should_land_on_the_reserve_with_a_battery_sized_by_its_energy),
		cmocka_unit_test(agriculture_should_turn_at_its_swath_ends_and_shed_while_spraying),
		cmocka_unit_test(delivery_should_release_its_parcel_at_the_drop_point_after_the_out_leg),
		cmocka_unit_test(longer_race_should_never_lighten_the_aircraft),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
