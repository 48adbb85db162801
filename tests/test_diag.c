/* test_diag.c — diagnostics: line format, counting, buffering, exit status. */
#include "test_util.h"
#include "diag/diag.h"

#include <string.h>

static void
diag_report_should_print_file_line_col_path_and_detail(void **state)
{
	(void)state;
	struct diag *dg = diag_alloc(NULL);
	struct diag_loc loc = { "m/agri.json", 14, 5 };
	diag_report(dg, DIAG_RANGE, &loc, "payload_role.spray_rate_kg_per_s",
	            ": %s (allowed %s)", "-0.2", "0 to 20 kg/s");
	assert_string_equal(diag_text(dg),
		"m/agri.json:14:5: error: payload_role.spray_rate_kg_per_s: out of range: "
		"-0.2 (allowed 0 to 20 kg/s)\n");
	assert_int_equal(diag_n_errors(dg), 1);
	diag_free(dg);
}

static void
diag_report_should_leave_out_missing_position_and_path(void **state)
{
	(void)state;
	struct diag *dg = diag_alloc(NULL);
	struct diag_loc file_only = { "x.json", 0, 0 };
	struct diag_loc pos = { "x.json", 3, 7 };
	diag_report(dg, DIAG_IO, &file_only, NULL, ": %s", "No such file or directory");
	diag_report(dg, DIAG_SYNTAX, &pos, "", NULL);
	diag_report(dg, DIAG_INTERNAL, NULL, NULL, NULL);
	assert_string_equal(diag_text(dg),
		"x.json: error: cannot read file: No such file or directory\n"
		"x.json:3:7: error: malformed JSON\n"
		"error: internal error\n");
	diag_free(dg);
}

static void
diag_notes_should_not_count_as_errors_nor_raise_status(void **state)
{
	(void)state;
	struct diag *dg = diag_alloc(NULL);
	struct diag_loc loc = { "a.json", 2, 3 };
	diag_report(dg, DIAG_FIRST_HERE, &loc, "payload_kg", NULL);
	assert_string_equal(diag_text(dg), "a.json:2:3: note: payload_kg: first given here\n");
	assert_int_equal(diag_n_errors(dg), 0);
	assert_int_equal(diag_exit_status(dg), 0);
	assert_int_equal(diag_kind_severity(DIAG_FIRST_HERE), DIAG_NOTE);
	assert_string_equal(diag_severity_name(DIAG_NOTE), "note");
	diag_free(dg);
}

static void
diag_exit_status_should_be_the_worst_seen(void **state)
{
	(void)state;
	struct diag *dg = diag_alloc(NULL);
	assert_int_equal(diag_exit_status(dg), 0);
	diag_raise_status(dg, 1);
	assert_int_equal(diag_exit_status(dg), 1);
	diag_report(dg, DIAG_TYPE, NULL, "x", NULL);
	assert_int_equal(diag_exit_status(dg), 2);
	diag_report(dg, DIAG_INTERNAL, NULL, NULL, NULL);
	assert_int_equal(diag_exit_status(dg), 3);
	diag_raise_status(dg, 1);
	diag_report(dg, DIAG_TYPE, NULL, "x", NULL);
	assert_int_equal(diag_exit_status(dg), 3);
	assert_int_equal(diag_n_errors(dg), 3);
	diag_free(dg);
}

static void
diag_flush_should_write_everything_once_and_clear(void **state)
{
	(void)state;
	FILE *fp = tmpfile();
	assert_non_null(fp);
	struct diag *dg = diag_alloc(fp);
	struct diag_loc loc = { "f.json", 1, 1 };
	/* Enough lines to force the buffer to grow several times. */
	for (int i = 0; i < 200; i++)
		diag_report(dg, DIAG_UNKNOWN, &loc, "some_long_field_name_number", "; line %d", i);
	size_t want = strlen(diag_text(dg));
	diag_flush(dg);
	assert_string_equal(diag_text(dg), "");
	assert_int_equal(diag_n_errors(dg), 200);
	assert_int_equal(ftell(fp), (long)want);
	rewind(fp);
	char line[128];
	assert_non_null(fgets(line, sizeof line, fp));
	assert_string_equal(line, "f.json:1:1: error: some_long_field_name_number: unknown field; line 0\n");
	fseek(fp, 0, SEEK_END);
	diag_flush(dg); /* nothing buffered: writes nothing */
	assert_int_equal(ftell(fp), (long)want);
	diag_free(dg);
	fclose(fp);
	diag_free(NULL);
}

static void
diag_quote_should_escape_and_truncate(void **state)
{
	(void)state;
	char out[64];
	diag_quote("ab\"c\\", 5, 40, out, sizeof out);
	assert_string_equal(out, "\"ab\\\"c\\\\\"");
	diag_quote("x\ny\xff", 4, 40, out, sizeof out);
	assert_string_equal(out, "\"x\\x0ay\\xff\"");
	diag_quote("h\xc3\xa9llo world", 12, 4, out, sizeof out);
	assert_string_equal(out, "\"h\xc3\xa9ll...\"");
	diag_quote("abcdefghijklmnopqrstuvwxyz", 26, 100, out, 12);
	assert_true(strlen(out) < 12);
	assert_int_equal(out[strlen(out) - 1], '"');
}

static void
diag_report_should_escape_unprintable_paths(void **state)
{
	(void)state;
	struct diag *dg = diag_alloc(NULL);
	diag_report(dg, DIAG_UNKNOWN, NULL, "bad\tkey\xfe", NULL);
	assert_string_equal(diag_text(dg), "error: bad\\x09key\\xfe: unknown field\n");
	diag_free(dg);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(diag_report_should_print_file_line_col_path_and_detail),
		cmocka_unit_test(diag_report_should_leave_out_missing_position_and_path),
		cmocka_unit_test(diag_notes_should_not_count_as_errors_nor_raise_status),
		cmocka_unit_test(diag_exit_status_should_be_the_worst_seen),
		cmocka_unit_test(diag_flush_should_write_everything_once_and_clear),
		cmocka_unit_test(diag_quote_should_escape_and_truncate),
		cmocka_unit_test(diag_report_should_escape_unprintable_paths),
	};
	return cmocka_run_group_tests_name("diag", tests, NULL, NULL);
}
