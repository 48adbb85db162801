/* test_json_in.c — the one JSON reader: files it refuses at once, the
 * positions and paths it gives, key and value checks, the cap on shown
 * lines, and linear work on hostile sizes (counted in hash probes). */
#include "test_util.h"
#include "input/json_in.h"
#include "util/strbuf.h"

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *const motor_keys[] = { "id", "mass_g", "kv_rpm_per_v", NULL };

/* Lines in text. */
static int
count_lines(const char *text)
{
	int n = 0;
	for (; *text != '\0'; text++)
		n += *text == '\n';
	return n;
}

/* Parse text as "t.json"; the diagnostics stay in *dg. */
static struct json_in *
parse(const char *text, struct diag **dg)
{
	*dg = diag_alloc(NULL);
	return json_in_parse("t.json", text, strlen(text), *dg);
}

/* ---- files refused at once ----------------------------------------------- */

static void
json_in_should_refuse_a_fifo_without_waiting(void **state)
{
	(void)state;
	char dir[] = "/tmp/aeroeval-json-in-XXXXXX", path[64];
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof path, "%s/motors.json", dir);
	assert_int_equal(mkfifo(path, 0600), 0);
	struct diag *dg = diag_alloc(NULL);
	alarm(10);   /* a reader that waited for a writer would be killed here */
	assert_null(json_in_load(path, JSON_IN_CATALOG_MAX, dg));
	alarm(0);
	char want[128];
	snprintf(want, sizeof want, "%s: error: cannot read file: not a regular file\n", path);
	assert_string_equal(diag_text(dg), want);
	assert_int_equal(diag_exit_status(dg), 2);
	diag_free(dg);
	unlink(path);
	rmdir(dir);
}

static void
json_in_should_refuse_a_directory_a_device_and_a_missing_file(void **state)
{
	(void)state;
	static const struct { const char *path, *want; } cases[] = {
		{ "tests", "tests: error: cannot read file: not a regular file\n" },
		{ "/dev/zero", "/dev/zero: error: cannot read file: not a regular file\n" },
		{ "no/such.json", "no/such.json: error: cannot read file: No such file or directory\n" },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct diag *dg = diag_alloc(NULL);
		assert_null(json_in_load(cases[i].path, JSON_IN_TEMPLATE_MAX, dg));
		assert_string_equal(diag_text(dg), cases[i].want);
		assert_int_equal(diag_exit_status(dg), 2);
		diag_free(dg);
	}
}

static void
json_in_should_refuse_a_file_above_its_cap(void **state)
{
	(void)state;
	char path[] = "/tmp/aeroeval-json-in-XXXXXX";
	int fd = mkstemp(path);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, "{\"a\": 1}     ", 13), 13);
	close(fd);
	struct diag *dg = diag_alloc(NULL);
	assert_null(json_in_load(path, 12, dg));
	assert_non_null(strstr(diag_text(dg), ": error: cannot read file: file too large (13 bytes, limit 12)"));
	diag_free(dg);
	dg = diag_alloc(NULL);
	struct json_in *ji = json_in_load(path, 13, dg);
	assert_non_null(ji);
	assert_string_equal(json_in_file(ji), path);
	json_in_free(ji);
	assert_string_equal(diag_text(dg), "");
	diag_free(dg);
	unlink(path);
}

/* ---- the file as a whole ------------------------------------------------- */

static void
json_in_should_refuse_malformed_text_trailing_text_and_a_non_object(void **state)
{
	(void)state;
	static const struct { const char *text, *want; } cases[] = {
		{ "{\n  \"a\": 1\n  \"b\": 2\n}", "t.json:3:3: error: malformed JSON near \"\\\"b\\\": 2\\x0a}\"\n" },
		{ "", "t.json:1:1: error: malformed JSON near the end of the file\n" },
		{ "[1, 2]", "t.json:1:1: error: the top level must be an object, got an array\n" },
		{ "\"x\"} {", "t.json:1:4: error: unexpected text after the JSON value near \"} {\"\n"
		           "t.json:1:1: error: the top level must be an object, got a string\n" },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct diag *dg;
		assert_null(parse(cases[i].text, &dg));
		assert_string_equal(diag_text(dg), cases[i].want);
		diag_free(dg);
	}
	/* Trailing text after an object is an error, the tree is still read. */
	struct diag *dg;
	struct json_in *ji = parse("{\"a\": 1} x", &dg);
	assert_non_null(ji);
	assert_int_equal(json_in_n_errors(ji), 1);
	json_in_free(ji);
	diag_free(dg);
}

static void
json_in_should_report_every_lexical_problem_and_skip_its_value(void **state)
{
	(void)state;
	struct diag *dg;
	struct json_in *ji = parse("{\"a\": 012,\n \"b\": \"x\ty\", \"c\": 1.5}", &dg);
	assert_non_null(ji);
	assert_string_equal(diag_text(dg),
	    "t.json:1:7: error: malformed JSON near \"012\" (not a JSON number)\n"
	    "t.json:2:9: error: malformed JSON near byte 0x09 (control characters in "
	    "strings must be escaped)\n");
	const cJSON *root = json_in_root(ji);
	const cJSON *a = cJSON_GetObjectItemCaseSensitive(root, "a");
	const cJSON *c = cJSON_GetObjectItemCaseSensitive(root, "c");
	assert_false(json_in_member(ji, root, a, "a"));   /* quietly: reported above */
	assert_false(json_in_check_number(ji, a, "a"));
	assert_true(json_in_member(ji, root, c, "c"));
	assert_true(json_in_check_number(ji, c, "c"));
	assert_int_equal(count_lines(diag_text(dg)), 2);
	json_in_free(ji);
	diag_free(dg);
}

static void
json_in_should_find_any_path_and_its_position(void **state)
{
	(void)state;
	struct diag *dg;
	struct json_in *ji = parse("{\"motors\": [\n  {\"id\": \"m-1\"},\n"
	                           "  {\"id\": \"m-2\", \"mass_g\": -3}\n]}", &dg);
	const cJSON *m = json_in_find(ji, "motors[1].mass_g");
	assert_non_null(m);
	assert_rel(m->valuedouble, -3, 0);
	struct diag_loc loc = json_in_loc(ji, m, JSON_IN_VALUE);
	assert_int_equal(loc.line, 3);
	assert_int_equal(loc.col, 27);
	loc = json_in_loc(ji, m, JSON_IN_KEY);
	assert_int_equal(loc.col, 17);
	loc = json_in_loc(ji, json_in_find(ji, "motors[0]"), JSON_IN_KEY);
	assert_int_equal(loc.line, 2);    /* an element has no key: its value */
	assert_int_equal(loc.col, 3);
	assert_ptr_equal(json_in_find(ji, ""), json_in_root(ji));
	assert_null(json_in_find(ji, "motors[2]"));
	assert_null(json_in_find(ji, "motors.id"));
	assert_null(json_in_find(ji, "motors[1].mass_g.x"));
	char src[8];
	json_in_source(ji, m, src, sizeof src);
	assert_string_equal(src, "-3");
	json_in_report(ji, DIAG_RANGE, m, JSON_IN_VALUE, "motors[1].mass_g",
	               ": %s (allowed above 0 g)", src);
	assert_string_equal(diag_text(dg),
	    "t.json:3:27: error: motors[1].mass_g: out of range: -3 (allowed above 0 g)\n");
	json_in_free(ji);
	diag_free(dg);
}

/* ---- keys ---------------------------------------------------------------- */

static void
json_in_should_check_keys_against_a_list_with_a_suggestion(void **state)
{
	(void)state;
	struct diag *dg;
	struct json_in *ji = parse("{\"id\": \"a\", \"mas_g\": 1, \"_note\": 0,\n"
	                           " \"id\": \"b\", \"zzz\": 2, \"kv\\u0000\": 3}", &dg);
	assert_int_equal(json_in_check_keys(ji, json_in_root(ji), "motors[0]", motor_keys,
	                                    JSON_IN_COMMENTS), 4);
	assert_string_equal(diag_text(dg),
	    "t.json:1:13: error: motors[0].mas_g: unknown field; did you mean \"mass_g\"?\n"
	    "t.json:2:2: error: motors[0].id: duplicate field (first given at 1:2)\n"
	    "t.json:1:2: note: motors[0].id: first given here\n"
	    "t.json:2:13: error: motors[0].zzz: unknown field\n"
	    "t.json:2:23: error: motors[0].kv: string contains a NUL character (\\u0000 in the key)\n");
	/* Without JSON_IN_COMMENTS "_note" is unknown too. */
	assert_int_equal(json_in_check_keys(ji, json_in_root(ji), "", motor_keys, 0), 5);
	json_in_free(ji);
	diag_free(dg);
}

/* 150 000 unknown keys: every one reported (and counted), the first lines
 * shown, and the work linear (an index of every key, not a scan of the
 * ones before it, which took over a minute). */
static void
json_in_should_check_150000_unknown_keys_in_linear_work(void **state)
{
	(void)state;
	enum { N = 150000 };
	struct strbuf sb = STRBUF_INIT;
	strbuf_append_str(&sb, "{");
	for (int i = 0; i < N; i++)
		strbuf_printf(&sb, "%s\"unknown_%d\": %d", i ? ", " : "", i, i);
	strbuf_append_str(&sb, "}");
	struct diag *dg = diag_alloc(NULL);
	struct json_in *ji = json_in_parse("big.json", sb.data, sb.len, dg);
	assert_non_null(ji);
	assert_int_equal(json_in_check_keys(ji, json_in_root(ji), "", motor_keys, 0), N);
	assert_true(json_in_probes(ji) < 10 * (size_t)N);
	json_in_free(ji);
	assert_int_equal(diag_n_errors(dg), N);
	assert_int_equal(count_lines(diag_text(dg)), JSON_IN_MAX_SHOWN + 1);
	char want[96];
	snprintf(want, sizeof want, "big.json: note: more errors not shown: %d (%d shown above)\n",
	         N - JSON_IN_MAX_SHOWN, JSON_IN_MAX_SHOWN);
	assert_non_null(strstr(diag_text(dg), want));
	diag_free(dg);
	strbuf_free(&sb);
}

/* 100 000 repeats of one key: at most the cap of lines plus the summary
 * (it used to print 199 998 lines), and still every error counted. */
static void
json_in_should_cap_100000_duplicate_keys_at_the_shown_lines(void **state)
{
	(void)state;
	enum { N = 100000 };
	struct strbuf sb = STRBUF_INIT;
	strbuf_append_str(&sb, "{");
	for (int i = 0; i < N; i++)
		strbuf_printf(&sb, "%s\"id\": %d", i ? ",\n" : "", i);
	strbuf_append_str(&sb, "}");
	struct diag *dg = diag_alloc(NULL);
	struct json_in *ji = json_in_parse("dup.json", sb.data, sb.len, dg);
	assert_int_equal(json_in_check_keys(ji, json_in_root(ji), "", motor_keys, 0), N - 1);
	assert_true(json_in_probes(ji) < 10 * (size_t)N);
	json_in_free(ji);
	const char *text = diag_text(dg);
	assert_true(count_lines(text) <= JSON_IN_MAX_SHOWN + 1);
	assert_memory_equal(text, "dup.json:2:1: error: id: duplicate field (first given at 1:2)\n"
	                          "dup.json:1:2: note: id: first given here\n", 102);
	assert_non_null(strstr(text, "dup.json: note: more errors not shown: "));
	assert_int_equal(diag_n_errors(dg), N - 1);
	assert_int_equal(diag_exit_status(dg), 2);
	diag_free(dg);
	strbuf_free(&sb);
}

/* ---- values -------------------------------------------------------------- */

static void
json_in_should_check_strings_for_nul_utf8_control_characters_formulas_and_length(void **state)
{
	(void)state;
	struct diag *dg;
	struct json_in *ji = parse("{\"a\": \"x\\u0000y\", \"b\": \"caf\xe9\", \"c\": \"two\\nlines\",\n"
	                           " \"d\": \"=HYPERLINK(\\\"http://x\\\")\", \"e\": \"-12\", \"f\": \"abcdef\",\n"
	                           " \"g\": \"Caf\xc3\xa9 12-6S\"}", &dg);
	const cJSON *root = json_in_root(ji);
	unsigned all = JSON_IN_NO_CONTROL | JSON_IN_NO_FORMULA;
	static const char *const keys[] = { "a", "b", "c", "d", "e", "f" };
	for (size_t i = 0; i < 6; i++)
		assert_false(json_in_check_string(ji, json_in_find(ji, keys[i]), keys[i], 5, all));
	assert_true(json_in_check_string(ji, json_in_find(ji, "g"), "g", 64, all));
	assert_true(json_in_check_string(ji, json_in_find(ji, "c"), "c", 64, 0));
	assert_string_equal(diag_text(dg),
	    "t.json:1:7: error: a: string contains a NUL character (\\u0000)\n"
	    "t.json:1:24: error: b: string is not valid UTF-8 (byte 0xe9 at offset 3)\n"
	    "t.json:1:37: error: c: string contains a control character (byte 0x0a at offset 3)\n"
	    "t.json:2:7: error: d: string too long: 22 bytes (at most 5)\n"
	    "t.json:2:40: error: e: text starts like a spreadsheet formula: \"-12\" "
	    "(text may not start with =, +, - or @)\n"
	    "t.json:2:52: error: f: string too long: 6 bytes (at most 5)\n");
	(void)root;
	json_in_free(ji);
	diag_free(dg);
	ji = parse("{\"d\": \"=HYPERLINK(\\\"http://x\\\")\"}", &dg);
	assert_false(json_in_check_string(ji, json_in_find(ji, "d"), "d", 64, all));
	assert_non_null(strstr(diag_text(dg), "t.json:1:7: error: d: text starts like a spreadsheet "
	                                      "formula: \"=HYPERLINK(\\\"http://x\\\")\""));
	json_in_free(ji);
	diag_free(dg);
}

static void
json_in_should_check_types_and_finite_numbers(void **state)
{
	(void)state;
	struct diag *dg;
	struct json_in *ji = parse("{\"a\": 1e400, \"b\": -2.385, \"c\": null}", &dg);
	assert_false(json_in_check_number(ji, json_in_find(ji, "a"), "a"));
	assert_true(json_in_check_number(ji, json_in_find(ji, "b"), "b"));
	assert_true(json_in_expect(ji, json_in_find(ji, "b"), "b", cJSON_Number, "a number"));
	assert_false(json_in_expect(ji, json_in_find(ji, "c"), "c", cJSON_String, "a string"));
	assert_true(json_in_expect(ji, json_in_find(ji, "c"), "c", cJSON_String | cJSON_NULL, "x"));
	assert_string_equal(diag_text(dg),
	    "t.json:1:7: error: a: number out of range of a double: 1e400\n"
	    "t.json:1:32: error: c: wrong type: expected a string, got null\n");
	json_in_free(ji);
	diag_free(dg);
}

int
main(void)
{
	signal(SIGALRM, SIG_DFL);
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(json_in_should_refuse_a_fifo_without_waiting),
		cmocka_unit_test(json_in_should_refuse_a_directory_a_device_and_a_missing_file),
		cmocka_unit_test(json_in_should_refuse_a_file_above_its_cap),
		cmocka_unit_test(json_in_should_refuse_malformed_text_trailing_text_and_a_non_object),
		cmocka_unit_test(json_in_should_report_every_lexical_problem_and_skip_its_value),
		cmocka_unit_test(json_in_should_find_any_path_and_its_position),
		cmocka_unit_test(json_in_should_check_keys_against_a_list_with_a_suggestion),
		cmocka_unit_test(json_in_should_check_150000_unknown_keys_in_linear_work),
		cmocka_unit_test(json_in_should_cap_100000_duplicate_keys_at_the_shown_lines),
		cmocka_unit_test(json_in_should_check_strings_for_nul_utf8_control_characters_formulas_and_length),
		cmocka_unit_test(json_in_should_check_types_and_finite_numbers),
	};
	return cmocka_run_group_tests_name("json_in", tests, NULL, NULL);
}
