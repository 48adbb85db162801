/* test_validate.c — the cohort row -> mission rule, the per-row solve and
 * the statistics of `aeroeval validate`. */
#include "test_util.h"
#include "study/validate.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "input/mission_io.h"
#include "diag/diag.h"
#include "input/model_io.h"
#include "util/xalloc.h"

#define FIX "tests/fixtures/validate/"

static struct model_data md;

static int
setup(void **state)
{
	(void)state;
	struct diag *dg = diag_alloc(stderr);
	int n_err = model_io_load("data", &md, dg);
	diag_flush(dg);
	diag_free(dg);
	return n_err == 0 ? 0 : -1;
}

static void
load(const char *path, struct cohort *c)
{
	assert_int_equal(cohort_load(path, c), 0);
}

static void
rule_should_take_every_fact_of_a_full_row(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "rules.csv", &c);
	assert_int_equal(c.n_rows, 9);
	struct mission_spec s;
	unsigned notes = 99;
	assert_int_equal(validate_mission_from_row(&c.rows[0], &md, &s, &notes),
	    VALIDATE_SKIP_NONE);
	assert_int_equal(notes, 0);
	assert_rel(s.payload_kg, 0.5, 1e-15);
	assert_rel(s.max_diameter_m, 0.45, 1e-15);
	assert_int_equal(s.num_rotors, 4);
	assert_false(s.coaxial_layout);
	assert_int_equal(s.airframe_class, AF_ENTERPRISE_RUGGED);
	assert_int_equal(s.payload_role.type, ROLE_IMAGING);
	assert_true(s.locks.is_prop_locked);
	assert_rel(s.locks.locked_diameter_in, 10, 1e-15);
	assert_rel(s.locks.locked_pitch_in, 4.5, 1e-15);
	assert_string_equal(s.battery_chemistry, "LiPo");
	assert_int_equal(s.nominal_cell_count, 4);
	assert_int_equal(s.battery_pack_count, 1);
	/* 20 min to empty is 20 / 1.2 min to the engine's reserve. */
	assert_rel(s.t_hover_s, 1000.0, 1e-12);
	assert_rel(s.t_climb_s + 1.0, 1.0, 1e-15);
	assert_rel(s.t_forward_s + 1.0, 1.0, 1e-15);
	/* Capacity is sized, never locked. */
	assert_false(s.locks.is_battery_locked);
	assert_true(s.given[SPECF_PAYLOAD_KG] && s.given[SPECF_T_HOVER_S]);
	cohort_free(&c);
}

/* A published endurance is flown with the load on board: the shedding
 * roles shed nothing in a validation mission; the others keep the
 * default. */
static void
rule_should_turn_shedding_off_for_the_roles_that_shed(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "rules.csv", &c);
	struct mission_spec s;
	unsigned notes;
	struct cohort_row r = c.rows[0];
	const enum role_type shedding[] = { ROLE_DELIVERY, ROLE_AGRICULTURE };
	for (size_t i = 0; i < 2; i++) {
		r.role = shedding[i];
		assert_int_equal(validate_mission_from_row(&r, &md, &s, &notes),
		    VALIDATE_SKIP_NONE);
		assert_false(s.payload_role.mass_shedding);
		assert_true(s.given[SPECF_ROLE_MASS_SHEDDING]);
	}
	r.role = ROLE_IMAGING;
	assert_int_equal(validate_mission_from_row(&r, &md, &s, &notes),
	    VALIDATE_SKIP_NONE);
	assert_false(s.given[SPECF_ROLE_MASS_SHEDDING]);
	cohort_free(&c);
}

/* The pack rule locks a published pack (cells, capacity x packs) and
 * keeps the endurance as the mission; the default rule sizes it; a row
 * that names no pack is sized under both.  The largest payload becomes
 * the load case. */
static void
rule_should_lock_the_published_pack_only_under_the_pack_rule(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "rules.csv", &c);
	struct mission_spec s;
	unsigned notes;
	struct cohort_row r = c.rows[0];
	r.has_cell_count = r.has_battery_capacity_mah = r.has_battery_pack_count = true;
	r.cell_count = 6;
	r.battery_capacity_mah = 4500.0;
	r.battery_pack_count = 2;
	r.has_max_payload_kg = true;
	r.max_payload_kg = r.payload_kg + 1.25;
	assert_int_equal(validate_mission_explained(&r, &md, VALIDATE_PACK_LOCKED, &s,
	    &notes, NULL), VALIDATE_SKIP_NONE);
	assert_true(s.locks.is_battery_locked);
	assert_int_equal(s.locks.locked_cell_count, 6);
	assert_rel(s.locks.locked_capacity_mah, 9000.0, 1e-15);
	assert_true(notes & VALIDATE_NOTE_PACK_LOCKED);
	assert_true(s.t_hover_s > 0.0);
	assert_rel(s.max_payload_kg, r.payload_kg + 1.25, 1e-15);
	assert_int_equal(validate_mission_explained(&r, &md, VALIDATE_FROM_ENDURANCE, &s,
	    &notes, NULL), VALIDATE_SKIP_NONE);
	assert_false(s.locks.is_battery_locked);
	assert_false(notes & VALIDATE_NOTE_PACK_LOCKED);
	r.has_battery_capacity_mah = false;
	assert_int_equal(validate_mission_explained(&r, &md, VALIDATE_PACK_LOCKED, &s,
	    &notes, NULL), VALIDATE_SKIP_NONE);
	assert_false(s.locks.is_battery_locked);
	cohort_free(&c);
}

static void
rule_should_derive_the_wheelbase_from_the_overlap_limit(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "rules.csv", &c);
	struct mission_spec s;
	unsigned notes;

	/* Hexacopter, 10 in: W = D / (0.95 sin(pi/6)). */
	assert_int_equal(validate_mission_from_row(&c.rows[1], &md, &s, &notes),
	    VALIDATE_SKIP_NONE);
	assert_rel(s.max_diameter_m, 0.254 / (0.95 * 0.5), 1e-12);
	assert_true(s.locks.is_prop_locked);
	assert_rel(s.locks.locked_diameter_in, 10, 1e-15);
	assert_rel(s.locks.locked_pitch_in, 4.5, 1e-12); /* 0.45 D */
	assert_string_equal(s.battery_chemistry, "Li-ion NMC");
	assert_int_equal(s.battery_pack_count, 2);
	assert_int_equal(s.nominal_cell_count, 6);
	assert_int_equal(s.payload_role.type, ROLE_MAPPING);
	assert_rel(s.payload_kg + 1.0, 1.0, 1e-15);
	/* 25 min of advertised flight, flown level at the minimum-power speed
	 * (no cruise speed given), brought to the reserve. */
	assert_rel(s.t_forward_s, 25 * 60 / 1.2, 1e-12);
	assert_rel(s.t_hover_s + 1.0, 1.0, 1e-15);
	assert_true(s.v_forward_auto);
	assert_int_equal(notes, VALIDATE_NOTE_WHEELBASE_PROP | VALIDATE_NOTE_CHEM_FAMILY
	    | VALIDATE_NOTE_MAX_FLIGHT);

	/* Coaxial X8: four arms; "lipo" names the LiPo profile. */
	assert_int_equal(validate_mission_from_row(&c.rows[2], &md, &s, &notes),
	    VALIDATE_SKIP_NONE);
	assert_true(s.coaxial_layout);
	assert_int_equal(s.num_rotors, 8);
	assert_rel(s.max_diameter_m, 15 * 0.0254 / (0.95 * sin(M_PI / 4)), 1e-12);
	assert_string_equal(s.battery_chemistry, "LiPo");
	assert_rel(s.t_hover_s, 600, 1e-12);
	assert_rel(s.payload_kg, 1.0, 1e-15);
	assert_int_equal(notes, VALIDATE_NOTE_WHEELBASE_PROP);
	cohort_free(&c);
}

static void
rule_should_not_lock_a_propeller_the_wheelbase_cannot_hold(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "rules.csv", &c);
	struct mission_spec s;
	unsigned notes;
	/* 350 mm quad: the limit is 0.95 x 350 x sin 45° = 9.26 in < 9.4 in. */
	assert_int_equal(validate_mission_from_row(&c.rows[3], &md, &s, &notes),
	    VALIDATE_SKIP_NONE);
	assert_false(s.locks.is_prop_locked);
	assert_rel(s.max_diameter_m, 0.35, 1e-15);
	assert_string_equal(s.battery_chemistry, "LiHV");
	assert_false(s.coaxial_layout);
	assert_int_equal(s.payload_role.type, ROLE_NONE);
	assert_int_equal(notes, VALIDATE_NOTE_PROP_OVER | VALIDATE_NOTE_CHEM_DEFAULT
	    | VALIDATE_NOTE_COAX_DEFAULT | VALIDATE_NOTE_ROLE_DEFAULT
	    | VALIDATE_NOTE_MAX_FLIGHT);
	cohort_free(&c);
}

static void
rule_should_skip_rows_without_a_needed_fact(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "rules.csv", &c);
	struct mission_spec s;
	unsigned notes;
	assert_int_equal(validate_mission_from_row(&c.rows[4], &md, &s, &notes),
	    VALIDATE_SKIP_ROTORS);
	assert_int_equal(validate_mission_from_row(&c.rows[5], &md, &s, &notes),
	    VALIDATE_SKIP_CLASS);
	assert_int_equal(validate_mission_from_row(&c.rows[6], &md, &s, &notes),
	    VALIDATE_SKIP_WHEELBASE);
	assert_int_equal(validate_mission_from_row(&c.rows[7], &md, &s, &notes),
	    VALIDATE_SKIP_ENDURANCE);
	assert_int_equal(notes, 0);
	for (int k = VALIDATE_SKIP_PAYLOAD; k < VALIDATE_SKIP_MAX; k++)
		assert_true(strlen(validate_skip_text(k)) > 0);
	cohort_free(&c);
}

/* The rule reads no mass: two rows that differ only in takeoff, empty and
 * battery mass give byte-identical missions. */
static void
rule_should_never_read_the_masses_it_predicts(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "rules.csv", &c);
	struct mission_spec a, b;
	unsigned na, nb;
	assert_int_equal(validate_mission_from_row(&c.rows[0], &md, &a, &na), 0);
	assert_int_equal(validate_mission_from_row(&c.rows[8], &md, &b, &nb), 0);
	assert_true(c.rows[0].takeoff_mass_kg != c.rows[8].takeoff_mass_kg);
	cJSON *ja = mission_io_to_json(&a), *jb = mission_io_to_json(&b);
	char *ta = cJSON_Print(ja), *tb = cJSON_Print(jb);
	assert_string_equal(ta, tb);
	assert_int_equal(na, nb);
	assert_memory_equal(a.given, b.given, sizeof a.given);
	free(ta);
	free(tb);
	cJSON_Delete(ja);
	cJSON_Delete(jb);
	cohort_free(&c);
}

/* Statistics worked by hand: actual 1, 2, 4 kg, predicted 1.1, 1.8, 5 kg.
 * APE 10, 10, 25 % -> MAPE 15 %, median 10 %; RMSE sqrt((0.01 + 0.04 +
 * 1) / 3) = sqrt(0.35) kg; k = 1/1.1, 2/1.8, 0.8; Consumer rows 10 %,
 * Enterprise 25 %; battery 0.36 against 0.3 kg = 20 %. */
static void
summarize_should_match_a_hand_worked_cohort(void **state)
{
	(void)state;
	struct cohort_row rows[4];
	memset(rows, 0, sizeof rows);
	const double a[4] = { 1, 2, 4, 3 }, p[4] = { 1.1, 1.8, 5, 0 };
	const int cls[4] = { AF_CONSUMER_FOLDING, AF_CONSUMER_FOLDING,
		AF_ENTERPRISE_RUGGED, AF_MICRO_AIO };
	struct validate_report v;
	memset(&v, 0, sizeof v);
	v.n_rows = 4;
	v.rows = calloc(4, sizeof *v.rows);
	for (int i = 0; i < 4; i++) {
		rows[i].airframe_class = cls[i];
		rows[i].has_airframe_class = true;
		v.rows[i].actual_kg = a[i];
		v.rows[i].predicted_kg = p[i];
		v.rows[i].status = i < 3 ? VALIDATE_ROW_OK : VALIDATE_ROW_SKIPPED;
	}
	v.rows[0].has_battery = true;
	v.rows[0].battery_actual_kg = 0.3;
	v.rows[0].battery_pred_kg = 0.36;
	struct cohort c = { .rows = rows, .n_rows = 4 };
	assert_int_equal(validate_summarize(&c, &v), 0);
	assert_int_equal(v.n_ok, 3);
	assert_rel(v.mtow.mape_pct, 15.0, 1e-12);
	assert_rel(v.mtow.median_ape_pct, 10.0, 1e-12);
	assert_rel(v.mtow.rmse_kg, sqrt(0.35), 1e-12);
	double k[3] = { 1 / 1.1, 2 / 1.8, 0.8 };
	double km = (k[0] + k[1] + k[2]) / 3;
	double ks = sqrt(((k[0] - km) * (k[0] - km) + (k[1] - km) * (k[1] - km)
	    + (k[2] - km) * (k[2] - km)) / 2);
	assert_rel(v.mtow.k_mean, km, 1e-12);
	assert_rel(v.mtow.k_sd, ks, 1e-12);
	/* A bootstrap of three APEs 10, 10, 25 can only give means in [10, 25]. */
	assert_true(v.ci_lo_pct >= 10.0 - 1e-9 && v.ci_lo_pct <= 15.0);
	assert_true(v.ci_hi_pct >= 15.0 && v.ci_hi_pct <= 25.0 + 1e-9);
	assert_true(v.ci_hi_pct > v.ci_lo_pct);
	assert_int_equal(v.n_classes, 2);
	assert_string_equal(v.by_class[0].key, "ConsumerFolding");
	assert_int_equal(v.by_class[0].n, 2);
	assert_rel(v.by_class[0].mape_pct, 10.0, 1e-12);
	assert_string_equal(v.by_class[1].key, "EnterpriseRugged");
	assert_rel(v.by_class[1].mape_pct, 25.0, 1e-12);
	assert_int_equal(v.battery.n, 1);
	assert_rel(v.battery.mape_pct, 20.0, 1e-12);
	/* The same input gives the same CI (fixed seed). */
	double lo = v.ci_lo_pct, hi = v.ci_hi_pct;
	assert_int_equal(validate_summarize(&c, &v), 0);
	assert_true(lo == v.ci_lo_pct && hi == v.ci_hi_pct);
	validate_report_free(&v);
}

static void
cohort_should_solve_each_row_and_count_only_converged_rows(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "tiny.csv", &c);
	struct validate_report v;
	assert_int_equal(validate_cohort(&c, &md, VALIDATE_FROM_ENDURANCE, &v), 0);
	assert_int_equal(v.n_rows, 5);
	assert_int_equal(v.rows[4].status, VALIDATE_ROW_SKIPPED);
	assert_int_equal(v.rows[4].skip, VALIDATE_SKIP_ROTORS);
	size_t ok = 0;
	for (size_t i = 0; i < 4; i++) {
		const struct validate_row *vr = &v.rows[i];
		if (vr->status != VALIDATE_ROW_OK)
			continue;
		ok++;
		assert_true(vr->predicted_kg > 0 && isfinite(vr->predicted_kg));
		assert_rel(vr->k, vr->actual_kg / vr->predicted_kg, 1e-12);
		assert_rel(vr->err_pct, 100 * (vr->predicted_kg - vr->actual_kg)
		    / vr->actual_kg, 1e-12);
		assert_true(vr->predicted_kg > c.rows[i].payload_kg);
		/* The loop's slope at the real mass: positive and finite. */
		assert_true(vr->slope_at_real > 0.0 && isfinite(vr->slope_at_real));
		/* Inside the shipped interval exactly when the error is. */
		const struct model_interval *iv = model_interval_for(
		    &md.cal.accuracy[MODEL_FROM_ENDURANCE], vr->spec.airframe_class);
		double r = log(vr->actual_kg / vr->predicted_kg);
		assert_int_equal(vr->inside, r >= iv->log_lo && r <= iv->log_hi);
	}
	assert_true(ok >= 3);
	assert_true(v.has_interval);
	size_t inside = 0;
	for (size_t i = 0; i < v.n_rows; i++)
		inside += v.rows[i].status == VALIDATE_ROW_OK && v.rows[i].inside;
	assert_int_equal(v.n_inside, inside);
	assert_int_equal(v.n_ok, ok);
	/* Only the first row gives a battery mass. */
	assert_true(v.battery.n <= 1);
	assert_int_equal(v.rows[0].has_battery, v.rows[0].status == VALIDATE_ROW_OK);

	/* Solving twice gives the same numbers (no hidden state). */
	struct validate_report w;
	assert_int_equal(validate_cohort(&c, &md, VALIDATE_FROM_ENDURANCE, &w), 0);
	for (size_t i = 0; i < 5; i++)
		assert_true(v.rows[i].predicted_kg == w.rows[i].predicted_kg);
	assert_true(v.mtow.mape_pct == w.mtow.mape_pct);
	assert_true(v.ci_lo_pct == w.ci_lo_pct);
	validate_report_free(&v);
	validate_report_free(&w);
	cohort_free(&c);
}

/* A row whose fact the mission format cannot hold is skipped, and the
 * reason names the fact, the field and the contract's range. */
static void
rule_should_name_the_fact_outside_the_mission_range(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "rules.csv", &c);
	struct cohort_row r = c.rows[0];
	struct mission_spec s;
	struct validate_fact f;
	unsigned notes;
	char text[256];
	r.rotor_count = 2;
	assert_int_equal(validate_mission_explained(&r, &md, VALIDATE_FROM_ENDURANCE, &s, &notes, &f), VALIDATE_SKIP_RANGE);
	validate_fact_text(&f, text, sizeof text);
	assert_string_equal(text, "rotor_count 2 gives num_rotors 2, outside the mission "
	                          "contract's range (3 to 16)");
	r = c.rows[0];
	r.has_hover_time_min = true;
	r.hover_time_min = 1e6;
	assert_int_equal(validate_mission_explained(&r, &md, VALIDATE_FROM_ENDURANCE, &s, &notes, &f), VALIDATE_SKIP_RANGE);
	validate_fact_text(&f, text, sizeof text);
	assert_non_null(strstr(text, "hover_time_min 1e+06 gives t_hover_s 5e+07, outside the "
	                             "mission contract's range ("));
	cohort_free(&c);
}

/* A racer sized by the rule flies its role's T/W requirement (8): the
 * requirement is never relaxed to make a row close. */
static void
solve_row_should_fly_the_role_thrust_requirement(void **state)
{
	(void)state;
	struct cohort c;
	load(FIX "rules.csv", &c);
	struct cohort_row r = c.rows[0];
	r.role = ROLE_RACING;
	r.airframe_class = AF_MICRO_AIO;
	r.payload_kg = 0.03;
	r.diagonal_wheelbase_mm = 200.0;
	r.prop_diameter_in = 5.0;
	r.prop_pitch_in = 4.3;
	r.cell_count = 4;
	r.hover_time_min = 4.0;
	struct mission_spec s;
	unsigned notes;
	assert_int_equal(validate_mission_from_row(&r, &md, &s, &notes),
	    VALIDATE_SKIP_NONE);
	struct solve_result *work = xmalloc(sizeof *work);
	struct validate_row vr;
	memset(&vr, 0, sizeof vr);
	validate_solve_row(&s, &md, work, &vr);
	assert_int_equal(vr.status, VALIDATE_ROW_OK);
	double theta = 1.0 - md.role[ROLE_RACING].thrust_margin;
	assert_rel(vr.thrust_to_weight, 1.0 / (theta * theta), 1e-9);
	free(work);
	cohort_free(&c);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(rule_should_take_every_fact_of_a_full_row),
		cmocka_unit_test(rule_should_name_the_fact_outside_the_mission_range),
		cmocka_unit_test(rule_should_turn_shedding_off_for_the_roles_that_shed),
		cmocka_unit_test(rule_should_lock_the_published_pack_only_under_the_pack_rule),
		cmocka_unit_test(rule_should_derive_the_wheelbase_from_the_overlap_limit),
		cmocka_unit_test(rule_should_not_lock_a_propeller_the_wheelbase_cannot_hold),
		cmocka_unit_test(rule_should_skip_rows_without_a_needed_fact),
		cmocka_unit_test(rule_should_never_read_the_masses_it_predicts),
		cmocka_unit_test(summarize_should_match_a_hand_worked_cohort),
		cmocka_unit_test(cohort_should_solve_each_row_and_count_only_converged_rows),
		cmocka_unit_test(solve_row_should_fly_the_role_thrust_requirement),
	};
	return cmocka_run_group_tests(tests, setup, NULL);
}
