/* test_jsonw.c — the one JSON writer: its layout, exact numbers, string
 * escapes, cJSON trees, and faults named by their JSON path. */
#include "test_util.h"
#include "util/jsonw.h"

#include <stdlib.h>
#include <string.h>

static void
jsonw_should_lay_out_objects_arrays_and_scalars(void **state)
{
	(void)state;
	struct jsonw w;
	struct jsonw_faults f;
	jsonw_init(&w);
	jsonw_object(&w, NULL);
	jsonw_string(&w, "name", "quad");
	jsonw_int(&w, "n", -42);
	jsonw_bool(&w, "ok", true);
	jsonw_null(&w, "none");
	jsonw_object(&w, "empty");
	jsonw_end(&w);
	jsonw_array(&w, "list");
	jsonw_number(&w, NULL, 2.385);
	jsonw_array(&w, NULL);
	jsonw_end(&w);
	jsonw_end(&w);
	jsonw_array_packed(&w, "packed");
	for (int i = 0; i < 12; i++)
		jsonw_int(&w, NULL, i);
	jsonw_end(&w);
	jsonw_end(&w);
	char *text = jsonw_finish(&w, &f);
	assert_string_equal(text,
	    "{\n"
	    "  \"name\": \"quad\",\n"
	    "  \"n\": -42,\n"
	    "  \"ok\": true,\n"
	    "  \"none\": null,\n"
	    "  \"empty\": {},\n"
	    "  \"list\": [\n"
	    "    2.385,\n"
	    "    []\n"
	    "  ],\n"
	    "  \"packed\": [\n"
	    "    0, 1, 2, 3, 4, 5, 6, 7, 8, 9,\n"
	    "    10, 11\n"
	    "  ]\n"
	    "}\n");
	assert_int_equal(f.n_invalid, 0);
	assert_string_equal(f.first_path, "");
	free(text);
}

/* Every double comes back exactly, in its shortest form: what cJSON's
 * printer gets wrong (0.1 + 0.2, 2^53, DBL_MAX) included. */
static void
jsonw_should_print_every_number_exactly(void **state)
{
	(void)state;
	const double x[] = { 0.1 + 0.2, 9007199254740992.0, 1.7976931348623157e308,
	                     5e-324, 1.0 / 3.0, 1e-9, 3e9, -0.0, 76.000000001 };
	struct jsonw w;
	jsonw_init(&w);
	jsonw_array(&w, NULL);
	for (size_t i = 0; i < sizeof x / sizeof x[0]; i++)
		jsonw_number(&w, NULL, x[i]);
	jsonw_end(&w);
	char *text = jsonw_finish(&w, NULL);
	assert_string_equal(text, "[\n  0.30000000000000004,\n  9007199254740992,\n"
	                          "  1.7976931348623157e+308,\n  4.94065645841247e-324,\n"
	                          "  0.3333333333333333,\n  1e-09,\n  3000000000,\n  0,\n"
	                          "  76.000000001\n]\n");
	char *p = text + 1;
	for (size_t i = 0; i < sizeof x / sizeof x[0]; i++) {
		char *end;
		double y = strtod(p, &end);
		assert_true(y == x[i]);
		p = end + 1;
	}
	free(text);
}

static void
jsonw_should_escape_strings_and_mend_invalid_utf8(void **state)
{
	(void)state;
	struct jsonw w;
	jsonw_init(&w);
	jsonw_object(&w, NULL);
	jsonw_string(&w, "q\"k", "a\"b\\c\n\t\x01/\x7f");
	jsonw_string(&w, "utf8", "\xc2\xb0 \xe2\x82\xac \xf0\x9f\x98\x80");
	jsonw_string(&w, "bad", "caf\xe9!\xc0\xaf");
	jsonw_string_n(&w, "cut", "abcdef", 3);
	jsonw_string(&w, "null", NULL);
	jsonw_end(&w);
	char *text = jsonw_finish(&w, NULL);
	assert_string_equal(text,
	    "{\n"
	    "  \"q\\\"k\": \"a\\\"b\\\\c\\n\\t\\u0001/\x7f\",\n"
	    "  \"utf8\": \"\xc2\xb0 \xe2\x82\xac \xf0\x9f\x98\x80\",\n"
	    "  \"bad\": \"caf\xef\xbf\xbd!\xef\xbf\xbd\xef\xbf\xbd\",\n"
	    "  \"cut\": \"abc\",\n"
	    "  \"null\": \"\"\n"
	    "}\n");
	free(text);
}

/* A cJSON tree prints as the streamed calls would print it. */
static void
jsonw_should_print_a_cjson_tree(void **state)
{
	(void)state;
	cJSON *root = cJSON_CreateObject();
	cJSON_AddNumberToObject(root, "x", 0.1 + 0.2);
	cJSON *a = cJSON_AddArrayToObject(root, "a");
	cJSON_AddItemToArray(a, cJSON_CreateString("s"));
	cJSON_AddItemToArray(a, cJSON_CreateFalse());
	cJSON_AddItemToArray(a, cJSON_CreateNull());
	cJSON *o = cJSON_AddObjectToObject(root, "o");
	cJSON_AddNumberToObject(o, "n", 7);
	cJSON_AddObjectToObject(root, "e");
	struct jsonw_faults f;
	char *text = jsonw_print(root, &f);
	assert_string_equal(text,
	    "{\n"
	    "  \"x\": 0.30000000000000004,\n"
	    "  \"a\": [\n"
	    "    \"s\",\n"
	    "    false,\n"
	    "    null\n"
	    "  ],\n"
	    "  \"o\": {\n"
	    "    \"n\": 7\n"
	    "  },\n"
	    "  \"e\": {}\n"
	    "}\n");
	assert_int_equal(f.n_invalid, 0);
	free(text);
	cJSON_Delete(root);
}

/* NaN, Infinity and raw text never appear: null, counted, the first named. */
static void
jsonw_should_write_null_for_what_json_cannot_hold_and_name_it(void **state)
{
	(void)state;
	cJSON *root = cJSON_CreateObject();
	cJSON *runs = cJSON_AddArrayToObject(root, "runs");
	cJSON_AddItemToArray(runs, cJSON_CreateObject());
	cJSON *r1 = cJSON_CreateObject();
	cJSON_AddItemToArray(runs, r1);
	cJSON_AddNumberToObject(r1, "power_w", NAN);
	cJSON_AddItemToObject(root, "raw", cJSON_CreateRaw("1e999"));
	cJSON_AddNumberToObject(root, "inf", INFINITY);
	struct jsonw_faults f;
	char *text = jsonw_print(root, &f);
	assert_non_null(strstr(text, "\"power_w\": null"));
	assert_non_null(strstr(text, "\"raw\": null"));
	assert_non_null(strstr(text, "\"inf\": null"));
	assert_int_equal(f.n_invalid, 3);
	assert_string_equal(f.first_path, "runs[1].power_w");
	free(text);
	cJSON_Delete(root);

	struct jsonw w;
	jsonw_init(&w);
	jsonw_array(&w, NULL);
	jsonw_number(&w, NULL, 1);
	jsonw_null(&w, NULL);
	jsonw_fault(&w, NULL);   /* the element just written */
	jsonw_end(&w);
	text = jsonw_finish(&w, &f);
	assert_int_equal(f.n_invalid, 1);
	assert_string_equal(f.first_path, "[1]");
	free(text);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(jsonw_should_lay_out_objects_arrays_and_scalars),
		cmocka_unit_test(jsonw_should_print_every_number_exactly),
		cmocka_unit_test(jsonw_should_escape_strings_and_mend_invalid_utf8),
		cmocka_unit_test(jsonw_should_print_a_cjson_tree),
		cmocka_unit_test(jsonw_should_write_null_for_what_json_cannot_hold_and_name_it),
	};
	return cmocka_run_group_tests_name("jsonw", tests, NULL, NULL);
}
