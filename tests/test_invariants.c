/* test_invariants.c — the physics every printed number must obey
 * (engine/invariants.h): a result that breaks one is an internal error
 * naming it; the examples' results break none. */
#include "test_util.h"

#include "engine/invariants.h"
#include "util/xalloc.h"

/* A small consistent design of record: 1.385 kg, a hover-only mission of
 * 600 s at 150 W (25 Wh) and 6.25 A (1.0417 Ah) from a 5 Ah pack. */
static struct solve_result *
consistent(void)
{
	struct solve_result *r = xcalloc(1, sizeof *r);
	struct res_run *o = &r->closed;
	o->ran = true;
	o->feasible = true;
	o->mass.payload_kg = 0.385;
	o->mass.battery_kg = 0.5;
	o->mass.motor_kg = 0.3;
	o->mass.frame_kg = 0.2;
	o->mass.total_kg = 1.385;
	o->fom_installed = 0.55;
	o->capacity_mah = 5000.0;
	o->reserve_soc = 1.0 / 6.0;
	o->end_soc = 1.0 - 6.25 * 600.0 / 3600.0 / 5.0;
	snprintf(o->termination, sizeof o->termination, "mission completed");
	struct res_phase *h = &o->phase[PHASE_HOVER];
	h->duration_s = 600.0;
	h->power_w = 150.0;
	h->shaft_power_w = 112.5;
	h->current_a = 6.25;
	h->energy_wh = 25.0;
	h->throttle = 0.55;
	o->perf.valid = true;
	struct res_op *op = &o->perf.op[OP_HOVER];
	op->valid = true;
	op->power_in_w = 35.0;
	op->power_shaft_w = 28.1;
	op->motor_efficiency = 28.1 / 35.0;
	op->throttle = 0.55;
	r->parts_selected = true;
	r->bom_mass_kg = 1.0;
	return r;
}

static void
invariants_should_pass_a_consistent_design(void **state)
{
	(void)state;
	char msg[256] = "";
	struct solve_result *r = consistent();
	assert_int_equal(invariants_check(r, msg, sizeof msg), 0);
	free(r);
}

/* Break one thing, expect exit 3 and a message with `word` in it. */
static void
expect_broken(void (*breaker)(struct solve_result *), const char *word)
{
	char msg[256] = "";
	struct solve_result *r = consistent();
	breaker(r);
	assert_int_equal(invariants_check(r, msg, sizeof msg), 3);
	if (strstr(msg, word) == NULL)
		fail_msg("message \"%s\" lacks \"%s\"", msg, word);
	free(r);
}

static void eff_above_one(struct solve_result *r) { r->closed.perf.op[OP_HOVER].motor_efficiency = 1.02; }
static void shaft_above_input(struct solve_result *r) { r->closed.perf.op[OP_HOVER].power_shaft_w = 36.0; }
static void op_throttle(struct solve_result *r) { r->closed.perf.op[OP_HOVER].throttle = 1.2; }
static void phase_shaft(struct solve_result *r) { r->closed.phase[PHASE_HOVER].shaft_power_w = 151.0; }
static void phase_energy(struct solve_result *r) { r->closed.phase[PHASE_HOVER].energy_wh = 25.2; }
static void phase_charge(struct solve_result *r) { r->closed.end_soc += 0.01; }
static void mass_sum(struct solve_result *r) { r->closed.mass.total_kg = 1.386; }
static void bom_total(struct solve_result *r) { r->bom_mass_kg = 1.0015; }
static void below_reserve(struct solve_result *r) { r->closed.end_soc = 0.16; r->closed.phase[PHASE_HOVER].current_a = 25.2; }
static void fom(struct solve_result *r) { r->closed.fom_installed = 1.05; }

static void
invariants_should_refuse_an_efficiency_above_one(void **state)
{
	(void)state;
	expect_broken(eff_above_one, "efficiency");
	expect_broken(fom, "figure of merit");
}

static void
invariants_should_refuse_more_shaft_than_electrical_power(void **state)
{
	(void)state;
	expect_broken(shaft_above_input, "shaft power");
	expect_broken(phase_shaft, "shaft power");
}

static void
invariants_should_refuse_a_throttle_above_full(void **state)
{
	(void)state;
	expect_broken(op_throttle, "throttle");
}

static void
invariants_should_hold_energy_and_charge_to_half_a_percent(void **state)
{
	(void)state;
	/* 25.2 Wh against 150 W × 600 s = 25 Wh: 0.8 % off. */
	expect_broken(phase_energy, "energy");
	/* 1 % more state of charge left than the 1.0417 Ah drawn allow. */
	expect_broken(phase_charge, "Ah");
}

static void
invariants_should_hold_the_masses_and_the_bill(void **state)
{
	(void)state;
	expect_broken(mass_sum, "sum");
	/* 1.0015 + 0.385 = 1.3865 kg against 1.385: 1.5 g over the 1 g. */
	expect_broken(bom_total, "bill of materials");
}

static void
invariants_should_refuse_a_feasible_design_below_its_reserve(void **state)
{
	(void)state;
	expect_broken(below_reserve, "reserve");
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(invariants_should_pass_a_consistent_design),
		cmocka_unit_test(invariants_should_refuse_an_efficiency_above_one),
		cmocka_unit_test(invariants_should_refuse_more_shaft_than_electrical_power),
		cmocka_unit_test(invariants_should_refuse_a_throttle_above_full),
		cmocka_unit_test(invariants_should_hold_energy_and_charge_to_half_a_percent),
		cmocka_unit_test(invariants_should_hold_the_masses_and_the_bill),
		cmocka_unit_test(invariants_should_refuse_a_feasible_design_below_its_reserve),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
