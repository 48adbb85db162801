/* test_role.c — payload shedding over the mission (paper §VI-H): the
 * delivery drop at t_drop = r_drop · t_total and the linear spray until the
 * tank is empty.
 * Hand values in the comments.
 */
#include "test_util.h"
#include "physics/role.h"

#include <string.h>

/* Delivery: 3.5 kg parcel of which 2.385 kg is dropped at r · t_total. */
static struct role_shedding
drop(double r_drop, double t_total_s)
{
	struct role_shedding s;
	memset(&s, 0, sizeof s);
	s.kind = SHED_DROP;
	s.payload0_kg = 3.5;
	s.drop_mass_kg = 2.385;
	s.drop_time_s = r_drop * t_total_s;
	return s;
}

/* Agriculture: 12.385 kg at takeoff, 10 kg of it sprayable at rate_kg_s. */
static struct role_shedding
spray(double rate_kg_s)
{
	struct role_shedding s;
	memset(&s, 0, sizeof s);
	s.kind = SHED_SPRAY;
	s.payload0_kg = 12.385;
	s.spray_mass_kg = 10.0;
	s.spray_rate_kg_s = rate_kg_s;
	return s;
}

static void
role_drop_should_release_the_mass_at_r_times_t_total(void **state)
{
	(void)state;
	/* t_drop = 0.5 · 1740 s = 870 s */
	struct role_shedding s = drop(0.5, 1740.0);
	assert_rel(role_payload_at(&s, 0.0), 3.5, 0.0);
	assert_rel(role_payload_at(&s, 869.9), 3.5, 0.0);
	/* after: 3.5 - 2.385 = 1.115 kg */
	assert_rel(role_payload_at(&s, 870.0), 1.115, 1e-12);
	assert_rel(role_payload_at(&s, 1740.0), 1.115, 1e-12);
}

static void
role_spray_should_fall_linearly_until_the_tank_is_empty(void **state)
{
	(void)state;
	/* ṁ = M_fluid / t_mission = 10 / 1385 = 0.007220217 kg/s */
	struct role_shedding s = spray(10.0 / 1385.0);
	/* t = 500 s: 12.385 - 0.007220217 · 500 = 12.385 - 3.610108 = 8.774892 kg */
	assert_rel(role_payload_at(&s, 500.0), 8.774891697, 1e-9);
	/* empty at 1385 s: 12.385 - 10 = 2.385 kg, and it stays there */
	assert_rel(role_payload_at(&s, 1385.0), 2.385, 1e-12);
	assert_rel(role_payload_at(&s, 2385.0), 2.385, 1e-12);
	assert_rel(role_payload_at(&s, -3.85), 12.385, 0.0);
}

static void
role_none_should_carry_the_payload_throughout(void **state)
{
	(void)state;
	struct role_shedding s;
	memset(&s, 0, sizeof s);
	s.kind = SHED_NONE;
	s.payload0_kg = 2.385;
	assert_rel(role_payload_at(&s, 1234.5), 2.385, 0.0);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(role_drop_should_release_the_mass_at_r_times_t_total),
		cmocka_unit_test(role_spray_should_fall_linearly_until_the_tank_is_empty),
		cmocka_unit_test(role_none_should_carry_the_payload_throughout),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
