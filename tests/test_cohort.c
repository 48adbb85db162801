/* test_cohort.c — the cohort CSV reader (data/cohorts/README.md). */
#include "test_util.h"
#include "input/cohort.h"

#include <string.h>

#define FIX "tests/fixtures/cohort/"

static void
cohort_should_read_the_real_calibration_file_with_27_rows(void **state)
{
	(void)state;
	struct cohort c;
	assert_int_equal(cohort_load(FIX "calibration.csv", &c), 0);
	assert_int_equal(c.n_errors, 0);
	assert_int_equal(c.n_rows, 27);

	/* Row 1 (line 2): a racer with few facts. */
	const struct cohort_row *q = &c.rows[0];
	assert_string_equal(q->name, "Holybro QAV250");
	assert_int_equal(q->line, 2);
	assert_rel(q->takeoff_mass_kg, 0.58, 1e-15);
	assert_false(q->has_empty_mass_kg);
	assert_int_equal(q->rotor_count, 4);
	assert_true(q->has_coaxial);
	assert_false(q->coaxial);
	assert_rel(q->diagonal_wheelbase_mm, 250, 1e-15);
	assert_false(q->has_prop_pitch_in);
	assert_int_equal(q->airframe_class, AF_MICRO_AIO);
	assert_int_equal(q->role, ROLE_RACING);
	assert_int_equal(q->confidence, COHORT_CONF_LOW);
	assert_string_equal(q->battery_chemistry, "");

	/* Row 2: a doubled quote inside a quoted name. */
	assert_string_equal(c.rows[1].name, "Holybro QAV-R 5\"");

	/* Row 4 (line 5): the fullest row of the DIY group. */
	const struct cohort_row *iris = &c.rows[3];
	assert_string_equal(iris->name, "3DR Iris+");
	assert_rel(iris->empty_mass_kg, 1.282, 1e-15);
	assert_true(iris->has_payload_kg);
	assert_rel(iris->payload_kg, 0.0, 0);
	assert_rel(iris->prop_diameter_in, 9.5, 1e-15);
	assert_rel(iris->prop_pitch_in, 4.5, 1e-15);
	assert_string_equal(iris->battery_chemistry, "LiPo");
	assert_int_equal(iris->cell_count, 3);
	assert_rel(iris->battery_capacity_mah, 5100, 1e-15);
	assert_int_equal(iris->battery_pack_count, 1);
	assert_rel(iris->max_flight_time_min, 22, 1e-15);
	assert_int_equal(iris->airframe_class, AF_CONSUMER_FOLDING);
	assert_non_null(strstr(iris->notes, "550 mm motor-to-motor"));

	/* Every row is in the calibration cohort and has its actual mass. */
	for (size_t i = 0; i < c.n_rows; i++) {
		assert_string_equal(c.rows[i].cohort, "calibration");
		assert_true(c.rows[i].takeoff_mass_kg > 0);
		assert_true(c.rows[i].line >= 2);
	}
	cohort_free(&c);
}

static void
cohort_should_accept_any_column_order_and_ignore_unknown_columns(void **state)
{
	(void)state;
	/* BOM, CRLF, a quoted note with "" and a line break, an unknown
	 * "colour" column, columns in a made-up order, coaxial as true. */
	struct cohort c;
	assert_int_equal(cohort_load(FIX "reordered.csv", &c), 0);
	assert_int_equal(c.n_rows, 2);
	const struct cohort_row *a = &c.rows[0];
	assert_string_equal(a->name, "Alpha X8");
	assert_int_equal(a->line, 2);
	assert_rel(a->takeoff_mass_kg, 2.385, 1e-15);
	assert_int_equal(a->rotor_count, 8);
	assert_true(a->has_coaxial);
	assert_true(a->coaxial);
	assert_rel(a->battery_mass_kg, 0.365, 1e-15);
	assert_int_equal(a->airframe_class, AF_ENTERPRISE_RUGGED);
	assert_int_equal(a->role, ROLE_MAPPING);
	assert_int_equal(a->confidence, COHORT_CONF_HIGH);
	assert_string_equal(a->notes, "has \"quotes\", a comma\r\nand a line break");
	/* Columns absent from the header are unknown, not zero. */
	assert_string_equal(a->cohort, "");
	assert_false(a->has_empty_mass_kg);
	assert_false(a->has_cruise_speed_ms);

	/* The second record starts on line 4: the quoted break counts. */
	const struct cohort_row *b = &c.rows[1];
	assert_string_equal(b->name, "QAV250");
	assert_int_equal(b->line, 4);
	assert_false(b->has_role);
	assert_false(b->has_confidence);
	assert_false(b->has_battery_mass_kg);
	assert_rel(b->battery_mass_kg, 0.0, 0);
	assert_false(b->coaxial);
	assert_true(b->has_coaxial);
	assert_string_equal(b->notes, "");
	cohort_free(&c);
}

static void
cohort_should_report_bad_rows_by_line_and_keep_the_others(void **state)
{
	(void)state;
	struct cohort c;
	assert_int_equal(cohort_load(FIX "malformed.csv", &c), -1);
	static const char *const want[] = {
		FIX "malformed.csv:3: error: takeoff_mass_kg: not a number (got \"1.2x\")",
		FIX "malformed.csv:4: error: payload_kg: must be >= 0 (got -0.2)",
		FIX "malformed.csv:5: error: airframe_class: unknown airframe class \"Heavy\" "
		    "(MicroAIO, ConsumerFolding, EnterpriseRugged, Agricultural)",
		FIX "malformed.csv:6: error: row: 4 cells, but the header has 8",
		FIX "malformed.csv:8: error: row: quote inside unquoted field (field 1)",
		/* One row with five faults gets five messages. */
		FIX "malformed.csv:9: error: takeoff_mass_kg: must be > 0 (got 0)",
		FIX "malformed.csv:9: error: rotor_count: must be a whole number >= 1 (got \"4.5\")",
		FIX "malformed.csv:9: error: coaxial: must be 0, 1, true or false (got \"yes\")",
		FIX "malformed.csv:9: error: role: unknown role \"none\" (imaging, delivery, "
		    "agriculture, racing, inspection, mapping)",
		FIX "malformed.csv:9: error: confidence: unknown confidence \"sure\" (high, medium, low)",
	};
	assert_int_equal(c.n_errors, sizeof want / sizeof want[0]);
	for (size_t i = 0; i < c.n_errors; i++)
		assert_string_equal(c.errors[i], want[i]);
	assert_int_equal(c.n_rows, 3);
	assert_string_equal(c.rows[0].name, "Good One");
	assert_int_equal(c.rows[0].line, 2);
	assert_string_equal(c.rows[1].name, "Good Two");
	assert_int_equal(c.rows[1].line, 7);
	assert_false(c.rows[1].has_coaxial);
	assert_string_equal(c.rows[2].name, "Good Three");
	assert_int_equal(c.rows[2].line, 10);
	assert_int_equal(c.rows[2].airframe_class, AF_ENTERPRISE_RUGGED);
	assert_int_equal(c.rows[2].role, ROLE_INSPECTION);
	cohort_free(&c);
}

/* Parses a string, for the short cases below. */
static int
parse(const char *text, struct cohort *c)
{
	return cohort_parse("t.csv", text, strlen(text), c);
}

static void
cohort_should_require_name_and_takeoff_mass_columns(void **state)
{
	(void)state;
	struct cohort c;
	assert_int_equal(parse("name,empty_mass_kg\nX,1.5\n", &c), -1);
	assert_int_equal(c.n_errors, 1);
	assert_string_equal(c.errors[0],
	                    "t.csv:1: error: takeoff_mass_kg: required column missing from the header");
	assert_int_equal(c.n_rows, 0);
	cohort_free(&c);

	assert_int_equal(parse("takeoff_mass_kg\n1.5\n", &c), -1);
	assert_string_equal(c.errors[0], "t.csv:1: error: name: required column missing from the header");
	cohort_free(&c);

	assert_int_equal(parse("name,takeoff_mass_kg,name\nX,1,Y\n", &c), -1);
	assert_string_equal(c.errors[0], "t.csv:1: error: name: column appears twice");
	cohort_free(&c);

	assert_int_equal(parse("", &c), -1);
	assert_string_equal(c.errors[0], "t.csv:1: error: row: empty file, no header line");
	cohort_free(&c);

	assert_int_equal(parse("name,\"takeoff_mass_kg\n", &c), -1);
	assert_string_equal(c.errors[0],
	                    "t.csv:1: error: row: header: unterminated quoted field (field 2)");
	cohort_free(&c);
}

static void
cohort_should_treat_empty_cells_as_unknown_but_not_required_ones(void **state)
{
	(void)state;
	struct cohort c;
	assert_int_equal(parse("name,takeoff_mass_kg,hover_time_min,payload_kg\n"
	                       "A, 2.385 ,,\n"      /* blanks around a number are fine */
	                       ",1.1,18,0\n"        /* empty name */
	                       "C, ,18,0\n"         /* blank actual mass */
	                       "D,1e0,  ,-0\n", &c), -1);
	assert_int_equal(c.n_errors, 2);
	assert_string_equal(c.errors[0], "t.csv:3: error: name: empty, but required");
	assert_string_equal(c.errors[1], "t.csv:4: error: takeoff_mass_kg: empty, but required");
	assert_int_equal(c.n_rows, 2);
	assert_rel(c.rows[0].takeoff_mass_kg, 2.385, 1e-15);
	assert_false(c.rows[0].has_hover_time_min);
	assert_false(c.rows[0].has_payload_kg);
	assert_rel(c.rows[1].takeoff_mass_kg, 1.0, 1e-15);
	assert_true(c.rows[1].has_payload_kg);
	assert_false(signbit(c.rows[1].payload_kg)); /* -0 is stored as 0 */
	cohort_free(&c);
}

static void
cohort_should_refuse_numbers_strtod_would_bend(void **state)
{
	(void)state;
	static const char *const cells[] = { "nan", "inf", "0x1p1", "1e999", "1,5", "--1", "" };
	for (size_t i = 0; cells[i][0] != '\0'; i++) {
		char text[128];
		struct cohort c;
		snprintf(text, sizeof text, "name,takeoff_mass_kg\nA,\"%s\"\n", cells[i]);
		assert_int_equal(parse(text, &c), -1);
		assert_int_equal(c.n_rows, 0);
		assert_non_null(strstr(c.errors[0], "t.csv:2: error: takeoff_mass_kg: not a number"));
		cohort_free(&c);
	}
}

/* A Latin-1 name made `validate --json` print invalid JSON: such a row is
 * refused with the byte named, the others kept; line breaks stay allowed
 * in the free-text notes. */
static void
cohort_should_refuse_text_that_is_not_utf8_or_holds_control_characters(void **state)
{
	(void)state;
	struct cohort c;
	assert_int_equal(parse("name,takeoff_mass_kg,notes\nCaf\xe9 one,1.2,\n"
	                       "Tab\tbed,2.3,\nGood \xc3\xa9,3.4,\"two\nlines\"\n"
	                       "Evil\xe2\x80\xaegnp,4.5,\n", &c), -1);
	assert_int_equal(c.n_rows, 1);
	assert_string_equal(c.rows[0].name, "Good \xc3\xa9");
	assert_string_equal(c.rows[0].notes, "two\nlines");
	assert_int_equal(c.n_errors, 3);
	assert_string_equal(c.errors[0], "t.csv:2: error: name: not valid UTF-8 (byte 0xe9 at "
	                                 "offset 3); save the file as UTF-8");
	assert_string_equal(c.errors[1], "t.csv:3: error: name: control character 0x09 at offset 3");
	/* A bidirectional override, refused as in mission files (issue 36). */
	assert_string_equal(c.errors[2], "t.csv:6: error: name: control character U+202E at offset 4");
	cohort_free(&c);
}

static void
cohort_should_read_coaxial_spellings_and_counts(void **state)
{
	(void)state;
	struct cohort c;
	assert_int_equal(parse("coaxial,name,takeoff_mass_kg,cell_count,battery_pack_count\n"
	                       "TRUE,a,1,6,2\nFalse,b,1,12,1\n1,c,1,3,\n0,d,1,,\n", &c), 0);
	assert_int_equal(c.n_rows, 4);
	assert_true(c.rows[0].coaxial);
	assert_int_equal(c.rows[0].cell_count, 6);
	assert_int_equal(c.rows[0].battery_pack_count, 2);
	assert_false(c.rows[1].coaxial);
	assert_int_equal(c.rows[1].cell_count, 12);
	assert_true(c.rows[2].coaxial);
	assert_false(c.rows[2].has_battery_pack_count);
	assert_false(c.rows[3].coaxial);
	assert_true(c.rows[3].has_coaxial);
	assert_false(c.rows[3].has_cell_count);
	cohort_free(&c);

	assert_int_equal(parse("name,takeoff_mass_kg,cell_count\na,1,0\nb,1,-3\n", &c), -1);
	assert_int_equal(c.n_errors, 2);
	assert_int_equal(c.n_rows, 0);
	cohort_free(&c);
}

static void
cohort_load_should_report_an_unreadable_file(void **state)
{
	(void)state;
	struct cohort c;
	assert_int_equal(cohort_load(FIX "no-such-file.csv", &c), -1);
	assert_int_equal(c.n_errors, 1);
	assert_string_equal(c.errors[0], FIX "no-such-file.csv: error: cannot open: "
	                    "No such file or directory");
	cohort_free(&c);
	cohort_free(NULL);
	assert_string_equal(cohort_confidence_name(COHORT_CONF_MEDIUM), "medium");
	assert_string_equal(cohort_confidence_name(COHORT_CONF_MAX), "");
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(cohort_should_read_the_real_calibration_file_with_27_rows),
		cmocka_unit_test(cohort_should_accept_any_column_order_and_ignore_unknown_columns),
		cmocka_unit_test(cohort_should_report_bad_rows_by_line_and_keep_the_others),
		cmocka_unit_test(cohort_should_require_name_and_takeoff_mass_columns),
		cmocka_unit_test(cohort_should_treat_empty_cells_as_unknown_but_not_required_ones),
		cmocka_unit_test(cohort_should_refuse_numbers_strtod_would_bend),
		cmocka_unit_test(cohort_should_refuse_text_that_is_not_utf8_or_holds_control_characters),
		cmocka_unit_test(cohort_should_read_coaxial_spellings_and_counts),
		cmocka_unit_test(cohort_load_should_report_an_unreadable_file),
	};
	return cmocka_run_group_tests_name("cohort", tests, NULL, NULL);
}
