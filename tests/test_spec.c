/* test_spec.c — the mission field table and its defaults. */
#include "test_util.h"
#include "spec/spec.h"

#include <string.h>

static void
spec_table_ids_should_match_positions(void **state)
{
	(void)state;
	for (size_t i = 0; i < SPEC_N_FIELDS; i++)
		assert_int_equal(spec_fields[i].id, i);
}

static void
spec_defaults_should_match_the_paper(void **state)
{
	(void)state;
	struct mission_spec s;
	spec_defaults(&s);
	assert_string_equal(s.battery_chemistry, "LiHV");  /* not the paper's LiPo: docs/model.md */
	assert_int_equal(s.num_rotors, 4);
	assert_rel(s.structural_overrides.wall_thickness_ratio, 0.90, 1e-12);
	assert_rel(s.structural_overrides.geometry_constant, 1.5, 1e-12);
	assert_rel(s.aerodynamic_overrides.assumed_ct, 0.12, 1e-12);
	/* The paper's 8 m/s rules out every production sprayer; aeroeval's
	 * default is the wake of the heaviest of them (spec.h). */
	assert_rel(s.payload_role.ag_max_downwash_ms, 17.0, 1e-12);
	/* No payload beyond the mission's unless the mission says so. */
	assert_rel(s.max_payload_kg, 0.0, 0.0);
	assert_int_equal(s.payload_role.type, ROLE_NONE);
	assert_false(s.given[SPECF_PAYLOAD_KG]);
}

static void
spec_paths_should_be_unique_and_found(void **state)
{
	(void)state;
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		assert_ptr_equal(spec_field_by_path(spec_fields[i].path), &spec_fields[i]);
		if (spec_fields[i].type == SPEC_ENUM)
			assert_non_null(spec_fields[i].enums);
	}
	assert_null(spec_field_by_path("payload_kgs"));
	assert_int_equal(spec_enum_index(spec_enum_role, "mapping"), ROLE_MAPPING);
	assert_int_equal(spec_enum_index(spec_enum_role, "Mapping"), -1);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(spec_table_ids_should_match_positions),
		cmocka_unit_test(spec_defaults_should_match_the_paper),
		cmocka_unit_test(spec_paths_should_be_unique_and_found),
	};
	return cmocka_run_group_tests_name("spec", tests, NULL, NULL);
}
