/* test_checks.c — the one table of checks (result/checks.h): every row is
 * complete and its code unique, a failed check becomes exactly one
 * violation in the table's words, and the examples' designs of record are
 * held to the checks a chief engineer reads first (arm tilt and stiffness,
 * the power path at full throttle, the pack's voltage in a burst), each
 * against a stated limit, as are their continuous references.
 */
#include "test_util.h"
#include "cli/cli.h"
#include "result/checks.h"
#include "diag/diag.h"
#include "engine/engine.h"
#include "input/mission_io.h"
#include "util/xalloc.h"

#include <stdlib.h>
#include <string.h>

static void
checks_table_should_be_complete_and_its_codes_unique(void **state)
{
	(void)state;
	for (int i = 0; i < CK_COUNT; i++) {
		const struct check_def *d = &check_table[i];
		assert_non_null(d->code);
		assert_non_null(d->stage);
		assert_non_null(d->name);
		assert_non_null(d->unit);
		assert_non_null(d->why);
		assert_non_null(d->fix[0]);
		assert_true(strlen(check_cond_text(d->cond)) > 0);
		for (int j = 0; j < i; j++)
			assert_string_not_equal(d->code, check_table[j].code);
	}
	assert_true(CK_COUNT <= RES_MAX_CHECKS);
}

static void
checks_apply_should_make_one_violation_per_failed_check(void **state)
{
	(void)state;
	struct solve_result *r = xcalloc(1, sizeof *r);
	struct res_run *o = &r->closed;
	struct check_values v;
	checks_init(&v);
	checks_set(&v, CK_CONNECTOR_FULL, 142.8, 60.0);
	snprintf(v.basis[CK_CONNECTOR_FULL], RES_BASIS, "Amass XT60, 60 A per pack");
	checks_set(&v, CK_POWER_MODULE_FULL, 50.0, 60.0);
	checks_set(&v, CK_ARM_TILT, 1.0, 1.0);          /* at its limit: passes */
	checks_set(&v, CK_RESERVE, 16.6, 16.7);
	v.pass_within_tol[CK_RESERVE] = true;            /* integrated to tolerance */
	checks_set(&v, CK_ARM_MODE_REV, 25.0, 23.7);    /* below the band's edge: */
	v.side[CK_ARM_MODE_REV] = +1;                    /* an upper limit, fails */
	checks_apply(&v, "closed", o, r);

	assert_int_equal(o->n_checks, 5);
	assert_false(o->feasible);
	/* Table order: the reserve first. */
	assert_string_equal(o->checks[0].code, "RESERVE");
	assert_true(o->checks[0].pass);
	const struct res_check *c = checks_find(o, "CONNECTOR_CURRENT_FULL");
	assert_non_null(c);
	assert_false(c->pass);
	assert_true(c->upper);
	assert_string_equal(c->condition, "full-throttle burst, 10 s");
	assert_string_equal(c->basis, "Amass XT60, 60 A per pack");
	assert_rel(c->margin, (60.0 - 142.8) / 60.0, 1e-12);
	assert_true(checks_find(o, "ARM_TILT")->pass);
	assert_true(checks_find(o, "POWER_MODULE_CURRENT_FULL")->pass);
	const struct res_check *m = checks_find(o, "ARM_RESONANCE_REV");
	assert_true(m->upper);
	assert_false(m->pass);
	assert_null(checks_find(o, "THRUST"));

	assert_int_equal(r->n_violations, 2);
	const struct res_violation *x = &r->violations[0];
	assert_string_equal(x->code, "CONNECTOR_CURRENT_FULL");
	assert_string_equal(x->run, "closed");
	assert_non_null(strstr(x->message, "142.8 A"));
	assert_non_null(strstr(x->message, "at most 60 A"));
	assert_non_null(strstr(x->message, "Amass XT60"));
	assert_true(x->n_fixes >= 1);
	assert_string_equal(r->violations[1].code, "ARM_RESONANCE_REV");
	free(r);
}

static void
checks_fix_should_expand_its_numbers(void **state)
{
	(void)state;
	struct solve_result *r = xcalloc(1, sizeof *r);
	struct check_values v;
	checks_init(&v);
	checks_set(&v, CK_POWER_MODULE_FULL, 87.9, 60.0);
	checks_apply(&v, "closed", &r->closed, r);
	assert_int_equal(r->n_violations, 1);
	assert_string_equal(r->violations[0].fixes[0], "A power module rated above 87.9 A");
	free(r);
}

/* The codes every design of record is held to, whatever its parts. */
static const char *const record_codes[] = {
	"RESERVE", "THRUST", "BATTERY_CURRENT", "BATTERY_BURST",
	"CONNECTOR_CURRENT_FULL", "HARNESS_CURRENT_FULL",
	"VOLTAGE_FULL_THROTTLE", "ARM_STRENGTH", "ARM_TILT", "ARM_TORSION",
	"ARM_MODE_CONTROL", "ARM_RESONANCE_REV", "ARM_RESONANCE", "TIP_MACH",
};

static void
check_example(struct cli_env *env, const char *path)
{
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	assert_int_equal(mission_io_load(path, env->model.chem_names, dg, &s), 0);
	diag_free(dg);
	struct solve_result *r = xcalloc(1, sizeof *r);
	assert_int_equal(engine_solve(&s, &env->model, env->cat, r), 0);
	assert_true(r->parts_selected);
	for (size_t i = 0; i < sizeof record_codes / sizeof record_codes[0]; i++) {
		const struct res_check *c = checks_find(&r->closed, record_codes[i]);
		if (c == NULL)
			fail_msg("%s: the design of record has no %s check", path,
			    record_codes[i]);
		assert_true(c->limit > 0.0);
		assert_non_null(c->condition);
	}
	/* A rated power module carries the full-throttle current too (a
	 * class that buys a distribution allowance has no rating to hold). */
	if (r->power_path.power_module.present
	    && r->power_path.power_module.continuous_a > 0.0)
		assert_non_null(checks_find(&r->closed, "POWER_MODULE_CURRENT_FULL"));
	/* The continuous reference is held to the same structure checks. */
	assert_non_null(checks_find(&r->custom, "ARM_TILT"));
	assert_non_null(checks_find(&r->custom, "ARM_RESONANCE_REV"));
	/* A failed check is a violation of the same code, and a passing
	 * design has none. */
	for (int i = 0; i < r->closed.n_checks; i++) {
		const struct res_check *c = &r->closed.checks[i];
		bool found = false;
		for (int k = 0; k < r->n_violations; k++)
			found |= strcmp(r->violations[k].code, c->code) == 0
			    && strcmp(r->violations[k].run, "closed") == 0;
		assert_true(found == !c->pass);
	}
	free(r);
}

static void
checks_examples_should_hold_the_record_to_the_power_path_and_the_arm(void **state)
{
	(void)state;
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	check_example(&env, "examples/sar_imaging_quad.json");
	check_example(&env, "examples/agri_spray_octo.json");
	check_example(&env, "examples/fpv_racing_quad.json");
	cli_env_free(&env);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(checks_table_should_be_complete_and_its_codes_unique),
		cmocka_unit_test(checks_apply_should_make_one_violation_per_failed_check),
		cmocka_unit_test(checks_fix_should_expand_its_numbers),
		cmocka_unit_test(checks_examples_should_hold_the_record_to_the_power_path_and_the_arm),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
