/* test_mission_io.c — the strict mission parser, its diagnostics and the
 * printers. */
#include "test_util.h"
#include "input/mission_io.h"

#include <stdlib.h>
#include <string.h>

static const char *const chems[] = { "LiPo", "LiIon", "LiHV", NULL };

/* Parse text as "m.json" and check the exact diagnostics and error count. */
static void
expect(const char *text, const char *want_diag, int want_errors)
{
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	int n = mission_io_parse("m.json", text, strlen(text), chems, dg, &s);
	assert_string_equal(diag_text(dg), want_diag);
	assert_int_equal(n, want_errors);
	assert_int_equal(diag_n_errors(dg), want_errors);
	diag_free(dg);
}

/* Parse text that must be valid. */
static void
parse_ok(const char *text, struct mission_spec *s)
{
	struct diag *dg = diag_alloc(NULL);
	int n = mission_io_parse("m.json", text, strlen(text), chems, dg, s);
	assert_string_equal(diag_text(dg), "");
	assert_int_equal(n, 0);
	diag_free(dg);
}

/* ---- valid input --------------------------------------------------------- */

static void
mission_io_should_apply_every_default_when_absent(void **state)
{
	(void)state;
	struct mission_spec s, d;
	parse_ok("{}", &s);
	spec_defaults(&d);
	assert_memory_equal(&s, &d, sizeof s);
	for (size_t i = 0; i < SPEC_N_FIELDS; i++)
		assert_false(s.given[i]);
	assert_string_equal(s.battery_chemistry, "LiHV");
	assert_false(s.v_forward_auto);
}

static void
mission_io_should_store_each_type_in_its_member(void **state)
{
	(void)state;
	struct mission_spec s;
	parse_ok("{\n"
	         "  \"$schema\": \"../data/mission.schema.json\",\n"
	         "  \"name\": \"agri \xc3\xa9t\xc3\xa9\",\n"
	         "  \"report\": {\"title\": \"Sprayer\", \"date\": \"2024-02-29\", \"name\": 7},\n"
	         "  \"payload_kg\": 2.385,\n"
	         "  \"num_rotors\": 6,\n"
	         "  \"coaxial_layout\": true,\n"
	         "  \"airframe_class\": \"Agricultural\",\n"
	         "  \"v_forward_ms\": 12.5,\n"
	         "  \"battery_chemistry\": \"LiHV\",\n"
	         "  \"locks\": {\"$schema\": 1, \"is_motor_locked\": true, \"locked_kv\": 920},\n"
	         "  \"payload_role\": {\"type\": \"agriculture\", \"spray_rate_kg_per_s\": 0.0125},\n"
	         "  \"structural_overrides\": {\"num_blades\": 3, \"arm_config\": \"under_rotor\"},\n"
	         "  \"aerodynamic_overrides\": {\"figure_of_merit_mode\": \"isolated\"},\n"
	         "  \"evaluate_marketing_limits\": true,\n"
	         "  \"requirements\": {\"transport\": \"car_trunk\", \"priority\": \"min_mass\"}\n"
	         "}\n", &s);
	assert_string_equal(s.name, "agri \xc3\xa9t\xc3\xa9");
	assert_string_equal(s.report.title, "Sprayer");
	assert_string_equal(s.report.date, "2024-02-29");
	assert_rel(s.payload_kg, 2.385, 0);
	assert_int_equal(s.num_rotors, 6);
	assert_true(s.coaxial_layout);
	assert_int_equal(s.airframe_class, AF_AGRICULTURAL);
	assert_rel(s.v_forward_ms, 12.5, 0);
	assert_false(s.v_forward_auto);
	assert_string_equal(s.battery_chemistry, "LiHV");
	assert_true(s.locks.is_motor_locked);
	assert_rel(s.locks.locked_kv, 920, 0);
	assert_int_equal(s.payload_role.type, ROLE_AGRICULTURE);
	assert_rel(s.payload_role.spray_rate_kg_per_s, 0.0125, 0);
	assert_int_equal(s.structural_overrides.num_blades, 3);
	assert_int_equal(s.structural_overrides.arm_config, ARM_UNDER_ROTOR);
	assert_int_equal(s.aerodynamic_overrides.figure_of_merit_mode, FOM_ISOLATED);
	assert_true(s.evaluate_marketing_limits);
	assert_int_equal(s.requirements.transport, TRANSPORT_CAR_TRUNK);
	assert_int_equal(s.requirements.priority, PRIORITY_MIN_MASS);
	assert_true(s.given[SPECF_PAYLOAD_KG]);
	assert_true(s.given[SPECF_LOCK_KV]);
	assert_false(s.given[SPECF_T_HOVER_S]);
	assert_false(s.given[SPECF_LOCK_PROP]);
	/* Untouched neighbours keep their defaults. */
	assert_rel(s.t_hover_s, 600, 0);
	assert_rel(s.locks.locked_pitch_in, 4.5, 0);
}

static void
mission_io_should_accept_auto_forward_speed(void **state)
{
	(void)state;
	struct mission_spec s;
	parse_ok("{\"v_forward_ms\": \"auto\"}", &s);
	assert_true(s.v_forward_auto);
	assert_true(s.given[SPECF_V_FORWARD_MS]);
	assert_rel(s.v_forward_ms, 10, 0); /* the table default stays */
	parse_ok("{\"v_forward_ms\": 7}", &s);
	assert_false(s.v_forward_auto);
	assert_rel(s.v_forward_ms, 7, 0);
}

/* A valid, non-default number for field f with 6 significant digits, as a
 * user would type it (cJSON prints 15 digits, so 17-digit values would not
 * survive a print and re-parse). */
static double
sample_number(const struct spec_field_info *f)
{
	char buf[32];
	snprintf(buf, sizeof buf, "%.6g", f->min + 0.37 * (f->max - f->min));
	return strtod(buf, NULL);
}

/* A valid, non-default JSON value for field f, written to buf. */
static void
sample_value(const struct spec_field_info *f, char *buf, size_t n)
{
	switch (f->type) {
	case SPEC_NUM:
		snprintf(buf, n, "%.17g", sample_number(f));
		break;
	case SPEC_INT:
		snprintf(buf, n, "%d", (int)f->max);
		break;
	case SPEC_BOOL:
		snprintf(buf, n, "%s", f->def != 0 ? "false" : "true");
		break;
	case SPEC_STR:
		if (f->id == SPECF_BATTERY_CHEMISTRY)
			snprintf(buf, n, "\"LiIon\"");
		else
			snprintf(buf, n, "\"s%d\"", (int)f->id);
		break;
	case SPEC_ENUM: {
		size_t last = 0;
		while (f->enums[last + 1] != NULL)
			last++;
		snprintf(buf, n, "\"%s\"", f->enums[last]);
		break;
	}
	case SPEC_SPEED:
		snprintf(buf, n, "\"auto\"");
		break;
	case SPEC_DATE:
		snprintf(buf, n, "\"2000-02-29\"");
		break;
	}
}

static void
mission_io_should_parse_every_field_of_the_table(void **state)
{
	(void)state;
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		char val[64], text[256];
		const char *dot = strchr(f->path, '.');
		sample_value(f, val, sizeof val);
		if (dot != NULL)
			snprintf(text, sizeof text, "{\"%.*s\": {\"%s\": %s}}",
			         (int)(dot - f->path), f->path, dot + 1, val);
		else
			snprintf(text, sizeof text, "{\"%s\": %s}", f->path, val);

		struct mission_spec s, d;
		parse_ok(text, &s);
		spec_defaults(&d);
		for (size_t j = 0; j < SPEC_N_FIELDS; j++)
			assert_int_equal(s.given[j], j == i);
		const void *p = spec_member(&s, f);
		switch (f->type) {
		case SPEC_NUM:
			assert_rel(*(const double *)p, sample_number(f), 0);
			break;
		case SPEC_INT:
			assert_int_equal(*(const int *)p, (int)f->max);
			break;
		case SPEC_BOOL:
			assert_int_equal(*(const bool *)p, f->def == 0);
			break;
		case SPEC_STR:
		case SPEC_DATE:
		case SPEC_ENUM:
			break; /* compared through the printer below */
		case SPEC_SPEED:
			assert_true(s.v_forward_auto);
			break;
		}
		char got[160], want[160];
		spec_format_value(&s, f, got, sizeof got);
		spec_format_value(&d, f, want, sizeof want);
		if (strcmp(got, want) == 0)
			fail_msg("%s: parsed value equals the default %s", f->path, got);
	}
}

static void
mission_io_should_parse_a_paper_engine_file_unchanged(void **state)
{
	(void)state;
	struct mission_spec s;
	parse_ok("{\n"
	         "  \"payload_kg\": 1.2, \"max_diameter_m\": 0.65, \"num_rotors\": 4,\n"
	         "  \"coaxial_layout\": false, \"airframe_class\": \"ConsumerFolding\",\n"
	         "  \"fixed_airframe_mass_kg\": 0, \"t_hover_s\": 900, \"t_climb_s\": 60,\n"
	         "  \"t_forward_s\": 600, \"v_climb_ms\": 3, \"v_forward_ms\": 12,\n"
	         "  \"baseline_v_forward_ms\": 12, \"baseline_t_forward_s\": 600,\n"
	         "  \"altitude_m\": 500, \"ambient_temp_c\": 25, \"battery_chemistry\": \"LiIon\",\n"
	         "  \"nominal_cell_count\": 6, \"battery_pack_count\": 2, \"battery_cycle_count\": 50,\n"
	         "  \"battery_specific_energy_wh_kg\": 0,\n"
	         "  \"locks\": {\"is_battery_locked\": false, \"locked_capacity_mah\": 10000,\n"
	         "    \"locked_cell_count\": 6, \"is_voltage_locked\": true, \"locked_series_cells\": 6,\n"
	         "    \"is_prop_locked\": false, \"locked_diameter_in\": 15, \"locked_pitch_in\": 5.5,\n"
	         "    \"is_motor_locked\": false, \"locked_kv\": 400, \"auto_reduce_flight_time\": true},\n"
	         "  \"payload_role\": {\"type\": \"imaging\", \"aux_power_w\": 15, \"added_drag_m2\": 0.01,\n"
	         "    \"cg_shift_m\": 0.02, \"delivery_drop_mass_kg\": 0, \"delivery_drop_time_ratio\": 0.5,\n"
	         "    \"spray_rate_kg_per_s\": 0, \"racing_load_factor\": 10, \"ag_max_downwash_ms\": 8,\n"
	         "    \"thrust_margin_override\": 0.4, \"drag_area_multiplier\": 1,\n"
	         "    \"integration_overhead_kg\": 0.1},\n"
	         "  \"structural_overrides\": {\"geometry_constant\": 1.5, \"wall_thickness_ratio\": 0.9,\n"
	         "    \"body_mass_multiplier\": 0.5, \"num_blades\": 2, \"arm_config\": \"folding\"},\n"
	         "  \"aerodynamic_overrides\": {\"figure_of_merit\": 0, \"figure_of_merit_isolated\": 0.75,\n"
	         "    \"figure_of_merit_mode\": \"installed\", \"propulsive_efficiency\": 0.85,\n"
	         "    \"cd_horizontal\": 1, \"cd_vertical\": 1.2, \"area_scaling_factor\": 0,\n"
	         "    \"aero_body_class\": \"commercial_compact\", \"assumed_ct\": 0.12,\n"
	         "    \"propeller_class\": \"auto\"},\n"
	         "  \"evaluate_marketing_limits\": false\n"
	         "}\n", &s);
	assert_true(s.locks.is_voltage_locked);
	assert_int_equal(s.locks.locked_series_cells, 6);
	assert_int_equal(s.structural_overrides.arm_config, ARM_FOLDING);
	assert_int_equal(s.aerodynamic_overrides.aero_body_class, BODY_COMMERCIAL_COMPACT);
	assert_rel(s.payload_role.aux_power_w, 15, 0);
	assert_int_equal(s.battery_pack_count, 2);
}

static void
mission_io_should_accept_an_empty_date_and_a_bom(void **state)
{
	(void)state;
	struct mission_spec s;
	parse_ok("{\"report\": {\"date\": \"\"}}", &s);
	assert_string_equal(s.report.date, "");
	parse_ok("\xef\xbb\xbf{\"payload_kg\": 3}", &s);
	assert_rel(s.payload_kg, 3, 0);
}

static void
mission_io_should_skip_the_chemistry_check_without_a_list(void **state)
{
	(void)state;
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	const char *t = "{\"battery_chemistry\": \"Unobtainium\"}";
	assert_int_equal(mission_io_parse("m.json", t, strlen(t), NULL, dg, &s), 0);
	assert_string_equal(s.battery_chemistry, "Unobtainium");
	diag_free(dg);
}

/* ---- one test per error kind --------------------------------------------- */

static void
mission_io_should_report_unknown_keys_with_a_suggestion(void **state)
{
	(void)state;
	expect("{\n  \"payload_kgs\": 2,\n  \"Payload_KG\": 1,\n  \"aux_power_w\": 3,\n"
	       "  \"locks\": {\"locked_kvv\": 900, \"zzzz\": 1, \"locked_kv.x\": 2},\n"
	       "  \"lock\": {}, \"locks.locked_kv\": 3\n}",
	       "m.json:2:3: error: payload_kgs: unknown field; did you mean \"payload_kg\"?\n"
	       "m.json:3:3: error: Payload_KG: unknown field; did you mean \"payload_kg\"?\n"
	       "m.json:4:3: error: aux_power_w: unknown field; did you mean \"payload_role.aux_power_w\"?\n"
	       "m.json:5:13: error: locks.locked_kvv: unknown field; did you mean \"locks.locked_kv\"?\n"
	       "m.json:5:32: error: locks.zzzz: unknown field\n"
	       "m.json:5:43: error: locks.locked_kv.x: unknown field; did you mean \"locks.locked_kv\"?\n"
	       "m.json:6:3: error: lock: unknown field; did you mean \"locks\"?\n"
	       "m.json:6:15: error: locks.locked_kv: unknown field\n",
	       8);
}

static void
mission_io_should_report_wrong_types(void **state)
{
	(void)state;
	expect("{\"payload_kg\": \"2\", \"num_rotors\": true, \"coaxial_layout\": 1,\n"
	       " \"name\": 5, \"airframe_class\": 2, \"v_forward_ms\": \"fast\",\n"
	       " \"report\": {\"date\": 20240101}, \"t_hover_s\": null, \"t_climb_s\": [1],\n"
	       " \"$schema\": {}}",
	       "m.json:1:16: error: payload_kg: wrong type: expected a number, got a string\n"
	       "m.json:1:35: error: num_rotors: wrong type: expected an integer, got a boolean\n"
	       "m.json:1:59: error: coaxial_layout: wrong type: expected a boolean, got a number\n"
	       "m.json:2:10: error: name: wrong type: expected a string, got a number\n"
	       "m.json:2:31: error: airframe_class: wrong type: expected a string, got a number\n"
	       "m.json:2:50: error: v_forward_ms: wrong type: expected a number or \"auto\", got \"fast\"\n"
	       "m.json:3:21: error: report.date: wrong type: expected a date string \"YYYY-MM-DD\", got a number\n"
	       "m.json:3:45: error: t_hover_s: wrong type: expected a number, got null\n"
	       "m.json:3:64: error: t_climb_s: wrong type: expected a number, got an array\n"
	       "m.json:4:13: error: $schema: wrong type: expected a string, got an object\n",
	       10);
}

static void
mission_io_should_report_values_out_of_range(void **state)
{
	(void)state;
	expect("{\"payload_kg\": -0.2,\n \"altitude_m\": 20000.5,\n \"num_rotors\": 2,\n"
	       " \"ambient_temp_c\": -40, \"locks\": {\"locked_kv\": 1e5}}",
	       "m.json:1:16: error: payload_kg: out of range: -0.2 (allowed 0 to 500 kg)\n"
	       "m.json:2:16: error: altitude_m: out of range: 20000.5 (allowed 0 to 20000 m)\n"
	       "m.json:3:16: error: num_rotors: out of range: 2 (allowed 3 to 16)\n"
	       "m.json:4:48: error: locks.locked_kv: out of range: 1e5 (allowed 10 to 60000 rpm/V)\n",
	       4);
}

static void
mission_io_should_respect_an_exclusive_minimum(void **state)
{
	(void)state;
	struct mission_spec s;
	expect("{\"max_diameter_m\": 0.03}",
	       "m.json:1:20: error: max_diameter_m: out of range: 0.03 "
	       "(allowed above 0.03 up to 5 m)\n", 1);
	parse_ok("{\"max_diameter_m\": 0.0300001}", &s);
	assert_rel(s.max_diameter_m, 0.0300001, 0);
	parse_ok("{\"payload_kg\": 0, \"max_diameter_m\": 5}", &s); /* inclusive ends */
}

static void
mission_io_should_reject_non_integral_integers(void **state)
{
	(void)state;
	struct mission_spec s;
	expect("{\"num_rotors\": 4.5, \"structural_overrides\": {\"num_blades\": 2.0000001}}",
	       "m.json:1:16: error: num_rotors: must be an integer (got 4.5)\n"
	       "m.json:1:60: error: structural_overrides.num_blades: must be an integer (got 2.0000001)\n",
	       2);
	parse_ok("{\"num_rotors\": 6.0, \"battery_pack_count\": 2e0}", &s);
	assert_int_equal(s.num_rotors, 6);
	assert_int_equal(s.battery_pack_count, 2);
}

static void
mission_io_should_report_duplicate_keys_at_the_second(void **state)
{
	(void)state;
	struct mission_spec s;
	const char *t = "{\"payload_kg\": 1,\n  \"locks\": {\"locked_kv\": 500, \"locked_kv\": 600},\n"
	                "  \"payload_kg\": 2}";
	expect(t,
	       "m.json:2:31: error: locks.locked_kv: duplicate field (first given at 2:13)\n"
	       "m.json:2:13: note: locks.locked_kv: first given here\n"
	       "m.json:3:3: error: payload_kg: duplicate field (first given at 1:2)\n"
	       "m.json:1:2: note: payload_kg: first given here\n",
	       2);
	struct diag *dg = diag_alloc(NULL);
	mission_io_parse("m.json", t, strlen(t), chems, dg, &s);
	assert_rel(s.payload_kg, 1, 0); /* the first one is kept */
	assert_rel(s.locks.locked_kv, 500, 0);
	diag_free(dg);
}

static void
mission_io_should_list_allowed_spellings_of_a_bad_enum(void **state)
{
	(void)state;
	expect("{\"payload_role\": {\"type\": \"Mapping\"},\n"
	       " \"structural_overrides\": {\"arm_config\": \"x-frame\"}}",
	       "m.json:1:27: error: payload_role.type: unknown value \"Mapping\" (allowed: none, "
	       "imaging, delivery, agriculture, racing, inspection, mapping); did you mean \"mapping\"?\n"
	       "m.json:2:41: error: structural_overrides.arm_config: unknown value \"x-frame\" "
	       "(allowed: offset, folding, under_rotor)\n",
	       2);
}

static void
mission_io_should_reject_an_unknown_chemistry(void **state)
{
	(void)state;
	expect("{\"battery_chemistry\": \"lipo\"}",
	       "m.json:1:23: error: battery_chemistry: unknown battery chemistry \"lipo\" "
	       "(known: LiPo, LiIon, LiHV)\n", 1);
}

static void
mission_io_should_reject_too_long_strings(void **state)
{
	(void)state;
	char text[400], want[200];
	char longest[SPEC_STR_MAX];
	memset(longest, 'x', SPEC_STR_MAX - 1);
	longest[SPEC_STR_MAX - 1] = '\0';
	struct mission_spec s;
	snprintf(text, sizeof text, "{\"name\": \"%s\"}", longest);
	parse_ok(text, &s); /* 127 bytes fit */
	assert_int_equal(strlen(s.name), SPEC_STR_MAX - 1);
	snprintf(text, sizeof text, "{\"name\": \"%sy\"}", longest);
	snprintf(want, sizeof want,
	         "m.json:1:10: error: name: string too long: %d bytes (at most %d)\n",
	         SPEC_STR_MAX, SPEC_STR_MAX - 1);
	expect(text, want, 1);
}

static void
mission_io_should_reject_invalid_utf8(void **state)
{
	(void)state;
	expect("{\"report\": {\"client\": \"Caf\xc3\"}, \"name\": \"ok\xed\xa0\x80\"}",
	       "m.json:1:23: error: report.client: string is not valid UTF-8 (byte 0xc3 at offset 3)\n"
	       "m.json:1:40: error: name: string is not valid UTF-8 (byte 0xed at offset 2)\n",
	       2);
}

static void
mission_io_should_reject_impossible_dates(void **state)
{
	(void)state;
	struct mission_spec s;
	const char *bad[] = { "2023-02-29", "2024-13-01", "2024-04-31", "24-01-01",
	                      "2024/01/01", "2024-1-01", "0000-01-01", "1900-02-29", "today" };
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		char text[96], want[200];
		snprintf(text, sizeof text, "{\"report\": {\"date\": \"%s\"}}", bad[i]);
		snprintf(want, sizeof want, "m.json:1:21: error: report.date: invalid date \"%s\" "
		         "(expected a calendar date YYYY-MM-DD)\n", bad[i]);
		expect(text, want, 1);
	}
	parse_ok("{\"report\": {\"date\": \"2000-02-29\"}}", &s);
	parse_ok("{\"report\": {\"date\": \"2026-12-31\"}}", &s);
}

static void
mission_io_should_reject_numbers_that_overflow(void **state)
{
	(void)state;
	expect("{\"t_hover_s\": 1e400, \"altitude_m\": -2E+999}",
	       "m.json:1:15: error: t_hover_s: number out of range of a double: 1e400\n"
	       "m.json:1:36: error: altitude_m: number out of range of a double: -2E+999\n", 2);
}

static void
mission_io_should_report_syntax_errors_near_their_position(void **state)
{
	(void)state;
	expect("{\n  \"payload_kg\": 1\n  \"t_hover_s\": 2\n}",
	       "m.json:3:3: error: malformed JSON near \"\\\"t_hover_s\\\": 2\\x0a}\"\n", 1);
	expect("{\"coaxial_layout\": tru}",
	       "m.json:1:20: error: malformed JSON near \"tru}\"\n", 1);
	/* Where a key is expected after the comma. */
	expect("{\"payload_kg\": 1,}",
	       "m.json:1:18: error: malformed JSON near \"}\"\n", 1);
	expect("{\"payload_kg\": 1",
	       "m.json:1:17: error: malformed JSON near the end of the file\n", 1);
	expect("", "m.json:1:1: error: malformed JSON near the end of the file\n", 1);
	/* A key must be in double quotes. */
	expect("{'a': 1}", "m.json:1:2: error: malformed JSON near \"'a': 1}\"\n", 1);
	expect("{\"name\": \"\xc3\xa9\xc3\xa9\", // note\n}",
	       "m.json:1:16: error: malformed JSON near \"// note\\x0a}\"\n", 1); /* columns count characters */
}

static void
mission_io_should_reject_numbers_cjson_tolerates(void **state)
{
	(void)state;
	struct mission_spec s;
	expect("{\"num_rotors\": 012, \"payload_kg\": 1.,\n \"t_hover_s\": -00}",
	       "m.json:1:16: error: malformed JSON near \"012\" (not a JSON number)\n"
	       "m.json:1:35: error: malformed JSON near \"1.\" (not a JSON number)\n"
	       "m.json:2:15: error: malformed JSON near \"-00\" (not a JSON number)\n", 3);
	parse_ok("{\"payload_kg\": 0.5, \"t_hover_s\": 1.2E+3, \"ambient_temp_c\": -0, "
	         "\"altitude_m\": 1e-2}", &s);
	assert_rel(s.t_hover_s, 1200, 0);
	assert_rel(s.altitude_m, 0.01, 0);
}

static void
mission_io_should_reject_raw_control_characters_in_strings(void **state)
{
	(void)state;
	struct mission_spec s;
	expect("{\"name\": \"a\tb\",\n \"report\": {\"title\": \"two\nlines\"}}",
	       "m.json:1:12: error: malformed JSON near byte 0x09 (control characters in "
	       "strings must be escaped)\n"
	       "m.json:2:26: error: malformed JSON near byte 0x0a (control characters in "
	       "strings must be escaped)\n", 2);
	/* Escaped, the JSON is good, but the text holds a control character
	 * all the same (issue 36). */
	expect("{\"name\": \"a\\tb\"}",
	       "m.json:1:10: error: name: string contains a control character (U+0009 at offset 1)\n", 1);
	expect("{\"report\": {\"title\": \"ab\\u0000cd\"}}",
	       "m.json:1:22: error: report.title: string contains a NUL character (\\u0000)\n", 1);
	parse_ok("{\"name\": \"x\\\\u0000\"}", &s); /* an escaped backslash, then text */
	assert_string_equal(s.name, "x\\u0000");
}

static void
mission_io_should_report_trailing_garbage_and_keep_checking(void **state)
{
	(void)state;
	expect("{\"payload_kg\": -1}\n  xyz",
	       "m.json:2:3: error: unexpected text after the JSON value near \"xyz\"\n"
	       "m.json:1:16: error: payload_kg: out of range: -1 (allowed 0 to 500 kg)\n", 2);
	expect("{} {}", "m.json:1:4: error: unexpected text after the JSON value near \"{}\"\n", 1);
	/* An embedded NUL is not the end of the file. */
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	assert_int_equal(mission_io_parse("m.json", "{}\0{}", 5, chems, dg, &s), 1);
	assert_string_equal(diag_text(dg),
	                    "m.json:1:3: error: unexpected text after the JSON value near \"\\x00{}\"\n");
	diag_free(dg);
}

static void
mission_io_should_reject_a_group_that_is_not_an_object(void **state)
{
	(void)state;
	expect("{\"locks\": [1], \"payload_role\": \"imaging\", \"report\": null}",
	       "m.json:1:11: error: locks: wrong type: expected an object, got an array\n"
	       "m.json:1:32: error: payload_role: wrong type: expected an object, got a string\n"
	       "m.json:1:53: error: report: wrong type: expected an object, got null\n", 3);
}

static void
mission_io_should_reject_a_top_level_that_is_not_an_object(void **state)
{
	(void)state;
	expect("  [{\"payload_kg\": 1}]",
	       "m.json:1:3: error: the top level must be an object, got an array\n", 1);
	expect("\n42", "m.json:2:1: error: the top level must be an object, got a number\n", 1);
}

static void
mission_io_should_report_every_error_of_a_file_in_one_pass(void **state)
{
	(void)state;
	expect("{\n"
	       "  \"payload_kgs\": 2,\n"
	       "  \"num_rotors\": \"four\",\n"
	       "  \"payload_kg\": -3,\n"
	       "  \"payload_role\": {\"type\": \"spraying\", \"spray_rate_kg_per_s\": -0.2},\n"
	       "  \"report\": {\"date\": \"2026-02-30\"}\n"
	       "}\n",
	       "m.json:2:3: error: payload_kgs: unknown field; did you mean \"payload_kg\"?\n"
	       "m.json:3:17: error: num_rotors: wrong type: expected an integer, got a string\n"
	       "m.json:4:17: error: payload_kg: out of range: -3 (allowed 0 to 500 kg)\n"
	       "m.json:5:28: error: payload_role.type: unknown value \"spraying\" (allowed: none, "
	       "imaging, delivery, agriculture, racing, inspection, mapping)\n"
	       "m.json:5:63: error: payload_role.spray_rate_kg_per_s: out of range: -0.2 "
	       "(allowed 0 to 20 kg/s)\n"
	       "m.json:6:22: error: report.date: invalid date \"2026-02-30\" "
	       "(expected a calendar date YYYY-MM-DD)\n",
	       6);
}

static void
mission_io_should_refuse_control_characters_in_text(void **state)
{
	(void)state;
	/* Issue 36: an ESC, a line break or a bidirectional override reached
	 * the dossier raw; the cohort reader already refused them. */
	expect("{\"name\": \"red\\u001b[31m\",\n"
	       " \"report\": {\"title\": \"a\\r\\nb\", \"client\": \"x\xe2\x80\xaegnp.exe\",\n"
	       " \"author\": \"c1\xc2\x85\", \"checked_by\": \"\\u2067iso\"}}",
	       "m.json:1:10: error: name: string contains a control character (U+001B at offset 3)\n"
	       "m.json:2:22: error: report.title: string contains a control character (U+000D at offset 1)\n"
	       "m.json:2:42: error: report.client: string contains a control character (U+202E at offset 1)\n"
	       "m.json:3:12: error: report.author: string contains a control character (U+0085 at offset 2)\n"
	       "m.json:3:33: error: report.checked_by: string contains a control character (U+2067 at offset 0)\n",
	       5);
	/* Letters of every script stay, joiners included. */
	struct mission_spec sp;
	parse_ok("{\"name\": \"\xd7\xa9\xd7\x9c\xd7\x95\xd7\x9d \xe2\x80\x8d caf\xc3\xa9\"}", &sp);
}

static void
mission_io_should_refuse_too_many_values_before_building_a_tree(void **state)
{
	(void)state;
	/* A 3.8 MB array took 278 MB: counted, refused, never parsed. */
	size_t n = 2 * (size_t)MISSION_IO_MAX_VALUES + 16;
	char *text = malloc(n + 1);
	assert_non_null(text);
	size_t k = 0;
	text[k++] = '[';
	while (k + 3 < n) {
		text[k++] = '0';
		text[k++] = ',';
	}
	text[k++] = '0';
	text[k++] = ']';
	text[k] = '\0';
	char want[160];
	snprintf(want, sizeof want, "m.json: error: too many entries: more than %d JSON values "
	    "(a mission has about 100)\n", MISSION_IO_MAX_VALUES);
	expect(text, want, 1);
	free(text);
	/* Keys are no values, and strings hold no structure: 140 000 members
	 * (280 000 strings, a million brackets and commas inside them) are
	 * read, and each unknown key reported. */
	int n_keys = 140000;
	text = malloc((size_t)n_keys * 32);
	assert_non_null(text);
	k = 0;
	text[k++] = '{';
	for (int i = 0; i < n_keys; i++)
		k += (size_t)sprintf(text + k, "%s\"k%d\": \"[,{:\\\"\"", i ? "," : "", i);
	text[k++] = '}';
	text[k] = '\0';
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec sp;
	assert_int_equal(mission_io_parse("m.json", text, k, chems, dg, &sp), n_keys);
	diag_free(dg);
	free(text);
}

static void
mission_io_load_should_report_an_unreadable_file(void **state)
{
	(void)state;
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	assert_int_equal(mission_io_load("no/such/mission.json", chems, dg, &s), 1);
	assert_string_equal(diag_text(dg),
	                    "no/such/mission.json: error: cannot read file: No such file or directory\n");
	assert_int_equal(diag_exit_status(dg), 2);
	assert_int_equal(s.num_rotors, 4);
	diag_free(dg);
}

static void
mission_io_load_should_read_a_file(void **state)
{
	(void)state;
	char path[] = "/tmp/aeroeval_mio_XXXXXX";
	int fd = mkstemp(path);
	assert_true(fd >= 0);
	FILE *fp = fdopen(fd, "w");
	/* Larger than the first read buffer, to exercise the growth. */
	fputs("{\"name\": \"big\",", fp);
	for (int i = 0; i < 2000; i++)
		fputs("      ", fp);
	fputs("\n \"num_rotors\": 1}", fp);
	fclose(fp);
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	assert_int_equal(mission_io_load(path, chems, dg, &s), 1);
	char want[256];
	snprintf(want, sizeof want, "%s:2:16: error: num_rotors: out of range: 1 (allowed 3 to 16)\n", path);
	assert_string_equal(diag_text(dg), want);
	assert_string_equal(s.name, "big");
	remove(path);
	diag_free(dg);
}

/* ---- printing ------------------------------------------------------------ */

/* The values of two specs agree (given[] aside). */
static void
assert_same_values(const struct mission_spec *a, const struct mission_spec *b)
{
	struct mission_spec x = *a, y = *b;
	memset(x.given, 0, sizeof x.given);
	memset(y.given, 0, sizeof y.given);
	assert_memory_equal(&x, &y, sizeof x);
}

static void
mission_io_to_json_should_round_trip(void **state)
{
	(void)state;
	struct mission_spec a, b, d;
	/* Every field at a non-default value, then the defaults. */
	char text[8192] = "{";
	size_t o = 1;
	const char *open_group = "";
	size_t glen = 0;
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		char val[64];
		const char *dot = strchr(f->path, '.');
		sample_value(f, val, sizeof val);
		size_t fg = dot != NULL ? (size_t)(dot - f->path) : 0;
		bool same = fg == glen && strncmp(f->path, open_group, glen) == 0;
		if (!same && glen > 0)
			o += (size_t)snprintf(text + o, sizeof text - o, "}");
		if (o > 1)
			o += (size_t)snprintf(text + o, sizeof text - o, ",");
		if (!same && fg > 0)
			o += (size_t)snprintf(text + o, sizeof text - o, "\"%.*s\":{", (int)fg, f->path);
		o += (size_t)snprintf(text + o, sizeof text - o, "\"%s\":%s",
		                      dot != NULL ? dot + 1 : f->path, val);
		open_group = f->path;
		glen = fg;
	}
	snprintf(text + o, sizeof text - o, "%s}", glen > 0 ? "}" : "");
	/* Within a group the comma goes after the previous member. */
	parse_ok(text, &a);
	spec_defaults(&d);
	struct mission_spec *cases[] = { &a, &d };
	for (size_t c = 0; c < 2; c++) {
		cJSON *j = mission_io_to_json(cases[c]);
		char *printed = cJSON_Print(j);
		cJSON_Delete(j);
		parse_ok(printed, &b);
		for (size_t i = 0; i < SPEC_N_FIELDS; i++)
			assert_true(b.given[i]);
		assert_same_values(cases[c], &b);
		free(printed);
	}
	assert_true(a.v_forward_auto);
}

static void
mission_io_to_json_should_nest_groups_and_print_auto(void **state)
{
	(void)state;
	struct mission_spec s;
	parse_ok("{\"v_forward_ms\": \"auto\", \"locks\": {\"locked_kv\": 700}}", &s);
	cJSON *j = mission_io_to_json(&s);
	assert_string_equal(cJSON_GetObjectItemCaseSensitive(j, "v_forward_ms")->valuestring, "auto");
	cJSON *locks = cJSON_GetObjectItemCaseSensitive(j, "locks");
	assert_true(cJSON_IsObject(locks));
	assert_rel(cJSON_GetObjectItemCaseSensitive(locks, "locked_kv")->valuedouble, 700, 0);
	assert_string_equal(cJSON_GetObjectItemCaseSensitive(j, "airframe_class")->valuestring,
	                    "EnterpriseRugged");
	assert_null(cJSON_GetObjectItemCaseSensitive(j, "locked_kv"));
	int n = 0;
	for (cJSON *c = j->child; c != NULL; c = c->next)
		n += cJSON_IsObject(c) ? cJSON_GetArraySize(c) : 1;
	assert_int_equal(n, SPEC_N_FIELDS);
	cJSON_Delete(j);
}

static void
spec_format_value_should_give_text_with_unit(void **state)
{
	(void)state;
	struct mission_spec s;
	char buf[64];
	parse_ok("{\"payload_kg\": 2.385, \"v_forward_ms\": \"auto\"}", &s);
	spec_format_value(&s, spec_field_by_path("payload_kg"), buf, sizeof buf);
	assert_string_equal(buf, "2.385 kg");
	spec_format_value(&s, spec_field_by_path("v_forward_ms"), buf, sizeof buf);
	assert_string_equal(buf, "auto");
	spec_format_value(&s, spec_field_by_path("nominal_cell_count"), buf, sizeof buf);
	assert_string_equal(buf, "0 cells");
	spec_format_value(&s, spec_field_by_path("structural_overrides.wall_thickness_ratio"),
	                        buf, sizeof buf);
	assert_string_equal(buf, "0.9");
	spec_format_value(&s, spec_field_by_path("coaxial_layout"), buf, sizeof buf);
	assert_string_equal(buf, "false");
	spec_format_value(&s, spec_field_by_path("airframe_class"), buf, sizeof buf);
	assert_string_equal(buf, "EnterpriseRugged");
	spec_format_value(&s, spec_field_by_path("report.title"), buf, sizeof buf);
	assert_string_equal(buf, "(none)");
	spec_format_value(&s, spec_field_by_path("battery_chemistry"), buf, sizeof buf);
	assert_string_equal(buf, "LiHV");
	spec_format_value(&s, spec_field_by_path("ambient_temp_c"), buf, 4);
	assert_string_equal(buf, "15 ");
}

/* ---- the essentials ------------------------------------------------------ */

/* mission_io_parse_mission's diagnostics for text ("m.json"). */
static const char *
essentials(const char *text, int want_errors)
{
	static char out[2048];
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	assert_int_equal(mission_io_parse_mission("m.json", text, strlen(text), chems, dg, &s),
	                 want_errors);
	snprintf(out, sizeof out, "%s", diag_text(dg));
	diag_free(dg);
	return out;
}

static void
mission_without_its_essentials_should_be_refused_at_its_object(void **state)
{
	(void)state;
	/* `check {}`: each essential, at the object's brace. */
	assert_string_equal(essentials("{}", 3),
	    "m.json:1:1: error: payload_kg: missing field; a mission gives payload_kg, or "
	    "requirements.payload_preset to derive it\n"
	    "m.json:1:1: error: max_diameter_m: missing field; a mission gives max_diameter_m, "
	    "or requirements.transport to derive it\n"
	    "m.json:1:1: error: t_hover_s: missing field; a mission needs a mission time: one "
	    "of t_hover_s, t_forward_s, t_climb_s above 0\n");
	assert_non_null(strstr(essentials("\n  {\"payload_kg\": 1, \"max_diameter_m\": 1}", 1),
	                       "m.json:2:3: error: t_hover_s: missing field"));
	/* Any one mission time above 0; a time of 0 is no mission. */
	assert_string_equal(essentials("{\"payload_kg\": 1, \"max_diameter_m\": 1, "
	                               "\"t_climb_s\": 30}", 0), "");
	assert_non_null(strstr(essentials("{\"payload_kg\": 1, \"max_diameter_m\": 1, "
	                                  "\"t_hover_s\": 0}", 1), "t_hover_s: missing field"));
	/* requirements{} derives payload and wheelbase; "none" derives nothing. */
	assert_string_equal(essentials("{\"requirements\": {\"payload_preset\": \"dslr_camera\", "
	                               "\"transport\": \"backpack\"}, \"t_forward_s\": 600}", 0), "");
	assert_non_null(strstr(essentials("{\"requirements\": {\"payload_preset\": \"none\", "
	                                  "\"transport\": \"backpack\"}, \"t_hover_s\": 60}", 1),
	                       "payload_kg: missing field"));
	/* A mission already wrong gets its own errors only. */
	assert_null(strstr(essentials("{\"payload_kgs\": 1}", 1), "missing field"));
	/* mission_io_parse itself reads fields only: {} is valid there. */
	struct mission_spec s;
	parse_ok("{}", &s);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(mission_io_should_apply_every_default_when_absent),
		cmocka_unit_test(mission_io_should_store_each_type_in_its_member),
		cmocka_unit_test(mission_io_should_accept_auto_forward_speed),
		cmocka_unit_test(mission_io_should_parse_every_field_of_the_table),
		cmocka_unit_test(mission_io_should_parse_a_paper_engine_file_unchanged),
		cmocka_unit_test(mission_io_should_accept_an_empty_date_and_a_bom),
		cmocka_unit_test(mission_io_should_skip_the_chemistry_check_without_a_list),
		cmocka_unit_test(mission_io_should_report_unknown_keys_with_a_suggestion),
		cmocka_unit_test(mission_io_should_report_wrong_types),
		cmocka_unit_test(mission_io_should_report_values_out_of_range),
		cmocka_unit_test(mission_io_should_respect_an_exclusive_minimum),
		cmocka_unit_test(mission_io_should_reject_non_integral_integers),
		cmocka_unit_test(mission_io_should_report_duplicate_keys_at_the_second),
		cmocka_unit_test(mission_io_should_list_allowed_spellings_of_a_bad_enum),
		cmocka_unit_test(mission_io_should_reject_an_unknown_chemistry),
		cmocka_unit_test(mission_io_should_reject_too_long_strings),
		cmocka_unit_test(mission_io_should_reject_invalid_utf8),
		cmocka_unit_test(mission_io_should_reject_impossible_dates),
		cmocka_unit_test(mission_io_should_reject_numbers_that_overflow),
		cmocka_unit_test(mission_io_should_report_syntax_errors_near_their_position),
		cmocka_unit_test(mission_io_should_reject_numbers_cjson_tolerates),
		cmocka_unit_test(mission_io_should_reject_raw_control_characters_in_strings),
		cmocka_unit_test(mission_io_should_report_trailing_garbage_and_keep_checking),
		cmocka_unit_test(mission_io_should_reject_a_group_that_is_not_an_object),
		cmocka_unit_test(mission_io_should_reject_a_top_level_that_is_not_an_object),
		cmocka_unit_test(mission_io_should_report_every_error_of_a_file_in_one_pass),
		cmocka_unit_test(mission_io_should_refuse_control_characters_in_text),
		cmocka_unit_test(mission_io_should_refuse_too_many_values_before_building_a_tree),
		cmocka_unit_test(mission_without_its_essentials_should_be_refused_at_its_object),
		cmocka_unit_test(mission_io_load_should_report_an_unreadable_file),
		cmocka_unit_test(mission_io_load_should_read_a_file),
		cmocka_unit_test(mission_io_to_json_should_round_trip),
		cmocka_unit_test(mission_io_to_json_should_nest_groups_and_print_auto),
		cmocka_unit_test(spec_format_value_should_give_text_with_unit),
	};
	return cmocka_run_group_tests_name("mission_io", tests, NULL, NULL);
}
