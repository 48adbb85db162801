/* test_json_parse.c — the one-pass parser: the tree it builds, where each
 * value stands, what it lets through as a problem, where it stops on
 * malformed text, numbers read exactly; and the text helpers it uses. */
#include "test_util.h"
#include "input/json_parse.h"
#include "util/text.h"

#include <string.h>

/* Parses t, which must be JSON. */
static struct json_doc *
parse(const char *t)
{
	size_t err = 0;
	struct json_doc *d = json_parse(t, strlen(t), &err);
	if (d == NULL)
		fail_msg("not parsed, stopped at %zu: %s", err, t);
	return d;
}

/* The node at a member path of plain keys and [i] indices, e.g. "a[1].b". */
static const struct json_node *
node_at(const struct json_doc *d, const char *path)
{
	const cJSON *at = json_doc_root(d);
	char key[64];
	while (at != NULL && *path != '\0') {
		if (*path == '[') {
			char *end;
			long i = strtol(path + 1, &end, 10);
			at = cJSON_GetArrayItem(at, (int)i);
			path = end + 1;
		} else {
			path += *path == '.';
			size_t k = strcspn(path, ".[");
			memcpy(key, path, k);
			key[k] = '\0';
			at = cJSON_GetObjectItemCaseSensitive(at, key);
			path += k;
		}
	}
	if (at == NULL)
		fail_msg("no value at %s", path);
	return json_node_of(at);
}

static void
json_parse_should_build_the_tree_cjson_builds(void **state)
{
	(void)state;
	const char *t = "{\"a\": [10, {\"b\": [true, null]}, \"s\", [], {}, -1e3],"
	                " \"f\": false, \"big\": 1e300, \"neg\": -3e10}";
	struct json_doc *d = parse(t);
	const cJSON *root = json_doc_root(d);
	assert_true(cJSON_IsObject(root));
	const cJSON *a = cJSON_GetObjectItemCaseSensitive(root, "a");
	assert_int_equal(cJSON_GetArraySize(a), 6);
	assert_ptr_equal(a->child->prev, cJSON_GetArrayItem(a, 5));   /* cJSON's rule */
	assert_null(cJSON_GetArrayItem(a, 5)->next);
	assert_ptr_equal(cJSON_GetArrayItem(a, 2)->prev, cJSON_GetArrayItem(a, 1));
	assert_int_equal(cJSON_GetArrayItem(a, 0)->valueint, 10);
	assert_rel(cJSON_GetArrayItem(a, 5)->valuedouble, -1000, 0);
	const cJSON *b = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(a, 1), "b");
	assert_true(cJSON_IsTrue(cJSON_GetArrayItem(b, 0)));
	assert_true(cJSON_IsNull(cJSON_GetArrayItem(b, 1)));
	assert_string_equal(cJSON_GetArrayItem(a, 2)->valuestring, "s");
	assert_true(cJSON_IsArray(cJSON_GetArrayItem(a, 3)));
	assert_null(cJSON_GetArrayItem(a, 3)->child);
	assert_true(cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(root, "f")));
	assert_int_equal(cJSON_GetObjectItemCaseSensitive(root, "big")->valueint, INT32_MAX);
	assert_int_equal(cJSON_GetObjectItemCaseSensitive(root, "neg")->valueint, INT32_MIN);
	assert_string_equal(cJSON_GetObjectItemCaseSensitive(root, "neg")->string, "neg");
	assert_int_equal(json_doc_end(d), strlen(t));
	json_doc_free(d);
	json_doc_free(NULL);
}

static void
json_parse_should_place_keys_and_values_of_nested_objects(void **state)
{
	(void)state;
	const char *t =
		"{\n"
		"  \"payload_kg\": 2.385,\n"
		"  \"locks\": {\n"
		"    \"is_motor_locked\": true,\n"
		"    \"locked_kv\":       920\n"
		"  }\n"
		"}\n";
	struct json_doc *d = parse(t);
	const struct json_node *e = json_node_of(json_doc_root(d));
	assert_int_equal(e->val_line, 1);
	assert_int_equal(e->val_col, 1);
	assert_int_equal(e->key_line, 0);
	e = node_at(d, "payload_kg");
	assert_int_equal(e->key_line, 2);
	assert_int_equal(e->key_col, 3);
	assert_int_equal(e->val_line, 2);
	assert_int_equal(e->val_col, 17);
	assert_int_equal(e->val_end - e->val_off, 5);
	assert_memory_equal(t + e->val_off, "2.385", 5);
	e = node_at(d, "locks.locked_kv");
	assert_int_equal(e->key_line, 5);
	assert_int_equal(e->key_col, 5);
	assert_int_equal(e->val_line, 5);
	assert_int_equal(e->val_col, 24);
	e = node_at(d, "locks");
	assert_int_equal(e->val_line, 3);
	assert_int_equal(e->val_col, 12);
	assert_int_equal(t[e->val_end - 1], '}');
	assert_int_equal(json_doc_end(d), strlen(t) - 1);   /* before the newline */
	assert_int_equal(json_doc_n_problems(d), 0);
	json_doc_free(d);
}

static void
json_parse_should_place_array_elements(void **state)
{
	(void)state;
	const char *t = "{\"a\": [10, {\"b\": [true, null]}, \"s\", [], {}, -1e3]}";
	struct json_doc *d = parse(t);
	assert_int_equal(node_at(d, "a[0]")->val_col, 8);
	assert_int_equal(node_at(d, "a[1].b[1]")->val_col, 25);
	assert_int_equal(node_at(d, "a[2]")->val_col, 33);
	const struct json_node *e = node_at(d, "a[5]");
	assert_int_equal(e->val_col, 46);
	assert_memory_equal(t + e->val_off, "-1e3", e->val_end - e->val_off);
	assert_int_equal(node_at(d, "a[3]")->key_line, 0);
	json_doc_free(d);
}

static void
json_parse_should_count_characters_not_bytes(void **state)
{
	(void)state;
	/* "é" and "°" are two bytes each, "€" three: one column each. */
	const char *t = "{\"t\": \"\xc3\xa9\xc2\xb0\xe2\x82\xac\", \"x\": 1,\n \"\xc3\xa9\": 2}";
	struct json_doc *d = parse(t);
	assert_string_equal(node_at(d, "t")->item.valuestring, "\xc3\xa9\xc2\xb0\xe2\x82\xac");
	assert_int_equal(node_at(d, "x")->key_col, 14);
	assert_int_equal(node_at(d, "x")->val_col, 19);
	int line, col;
	text_line_col(t, strlen(t), (size_t)(strstr(t, "1,") - t), &line, &col);
	assert_int_equal(line, 1);
	assert_int_equal(col, 19);
	const struct json_node *e = json_node_of(json_doc_root(d)->child->next->next);
	assert_int_equal(e->key_line, 2);    /* a new line starts counting again */
	assert_int_equal(e->val_col, 7);
	json_doc_free(d);
}

static void
json_parse_should_keep_every_duplicate_in_order(void **state)
{
	(void)state;
	const char *t = "{\"k\": 1,\n \"k\": 2,\n  \"k\": 3}";
	struct json_doc *d = parse(t);
	const cJSON *k = json_doc_root(d)->child;
	assert_null(k->next->next->next);
	assert_int_equal(json_node_of(k)->key_line, 1);
	assert_int_equal(json_node_of(k->next)->key_line, 2);
	assert_int_equal(json_node_of(k->next)->key_col, 2);
	assert_int_equal(json_node_of(k->next->next)->key_col, 3);
	assert_int_equal(cJSON_GetObjectItemCaseSensitive(json_doc_root(d), "k")->valueint, 1);
	json_doc_free(d);
}

static void
json_parse_should_unescape_keys_and_strings(void **state)
{
	(void)state;
	const char *t = "{\"a\\u00e9\\\"b\\n\": 1, \"\\ud83d\\ude00\": 2, \"q\": \"x\\\"}y\","
	                " \"e\": \"\\/\\\\\\b\\f\\r\\t\\u20AC\"}";
	struct json_doc *d = parse(t);
	const cJSON *c = json_doc_root(d)->child;
	assert_string_equal(c->string, "a\xc3\xa9\"b\n");
	assert_string_equal(c->next->string, "\xf0\x9f\x98\x80");
	const struct json_node *e = node_at(d, "q");
	assert_string_equal(e->item.valuestring, "x\"}y");
	assert_int_equal(e->val_end - e->val_off, 7); /* "x\"}y" */
	assert_string_equal(node_at(d, "e")->item.valuestring, "/\\\b\f\r\t\xe2\x82\xac");
	json_doc_free(d);
}

static void
json_parse_should_skip_a_byte_order_mark(void **state)
{
	(void)state;
	const char *t = "\xef\xbb\xbf{\"a\": 1}";
	struct json_doc *d = parse(t);
	assert_int_equal(json_node_of(json_doc_root(d))->val_col, 1);
	assert_int_equal(node_at(d, "a")->key_col, 2);
	int line, col;
	text_line_col(t, strlen(t), 4, &line, &col);
	assert_int_equal(col, 2);
	json_doc_free(d);
}

/* Malformed text: no document, and the offset where reading stopped. */
static void
json_parse_should_stop_at_the_first_malformed_spot(void **state)
{
	(void)state;
	static const struct { const char *text; size_t off; } bad[] = {
		{ "", 0 },                         /* nothing: the end */
		{ " \n ", 3 },
		{ "{", 1 },
		{ "{\"a\" 1}", 5 },                /* the colon is missing */
		{ "{\"a\": [1 2]}", 9 },           /* a comma is missing */
		{ "{\"a\": 1,}", 8 },              /* a key is expected */
		{ "[1, 2,]", 6 },
		{ "{'a': 1}", 1 },
		{ "{\"a\":", 5 },
		{ "[\"\\x\"]", 2 },                /* the bad escape */
		{ "[\"\\u12G4\"]", 2 },
		{ "[\"\\udc00\"]", 2 },            /* a lone low surrogate */
		{ "[\"\\ud83dx\"]", 2 },           /* a high one without its low half */
		{ "{\"a\": \"unterminated", 6 },   /* the opening quote */
		{ "[tru]", 1 },
		{ "[nul, 1]", 1 },
		{ "[1.2.3]", 4 },
		{ "[-]", 1 },
		{ "[.5]", 1 },
		{ "[+1]", 1 },
		{ "[0x10]", 2 },
		{ "[1e]", 2 },
		{ "[NaN]", 1 },
		{ "[1] // c", 3 },                 /* fine: the caller judges the rest */
		{ "\x0c{}", 0 },                   /* only space, tab, CR and LF are space */
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		size_t off = 99;
		struct json_doc *d = json_parse(bad[i].text, strlen(bad[i].text), &off);
		if (i == 23) {
			assert_non_null(d);
			assert_int_equal(json_doc_end(d), bad[i].off);
			json_doc_free(d);
			continue;
		}
		if (d != NULL || off != bad[i].off)
			fail_msg("%s: got %s at %zu, want a stop at %zu", bad[i].text,
			         d != NULL ? "a document" : "a stop", off, bad[i].off);
	}
}

static void
json_parse_should_limit_nesting_as_cjson_does(void **state)
{
	(void)state;
	char t[2 * (JSON_PARSE_MAX_DEPTH + 1) + 1];
	size_t n = 0, err;
	for (int i = 0; i < JSON_PARSE_MAX_DEPTH; i++)
		t[n++] = '[';
	for (int i = 0; i < JSON_PARSE_MAX_DEPTH; i++)
		t[n++] = ']';
	struct json_doc *d = json_parse(t, n, &err);
	assert_non_null(d);
	json_doc_free(d);
	memmove(t + 1, t, n);
	t[0] = '[';
	t[n + 1] = ']';
	assert_null(json_parse(t, n + 2, &err));
	assert_int_equal(err, JSON_PARSE_MAX_DEPTH);
}

static void
json_parse_should_note_control_characters_and_non_json_numbers(void **state)
{
	(void)state;
	const char *t = "{\"a\tb\": 1,\n \"n\": [012, 1., -0, 2.385e-3, -.5],\n \"s\": \"x\ny\",\n \"z\": 2}";
	struct json_doc *d = parse(t);
	assert_int_equal(json_doc_n_problems(d), 5);
	const struct json_problem *p = json_doc_problem_at(d, 0);
	assert_int_equal(p->kind, JSON_PROBLEM_CONTROL);  /* the TAB in a key */
	assert_ptr_equal(p->node, json_node_of(json_doc_root(d)->child));
	assert_int_equal(p->line, 1);
	assert_int_equal(p->col, 4);
	assert_int_equal(p->byte, '\t');
	assert_true(p->node->flags & JSON_PARSE_BAD);
	p = json_doc_problem_at(d, 1);
	assert_int_equal(p->kind, JSON_PROBLEM_NUMBER);   /* 012, read as 12 */
	assert_ptr_equal(p->node, node_at(d, "n[0]"));
	assert_rel(p->node->item.valuedouble, 12, 0);
	assert_int_equal(p->line, 2);
	assert_int_equal(p->col, 8);
	assert_ptr_equal(json_doc_problem_at(d, 2)->node, node_at(d, "n[1]"));   /* 1. */
	assert_ptr_equal(json_doc_problem_at(d, 3)->node, node_at(d, "n[4]"));   /* -.5 */
	assert_rel(node_at(d, "n[4]")->item.valuedouble, -0.5, 0);
	assert_false(node_at(d, "n[2]")->flags & JSON_PARSE_BAD);   /* -0 is JSON */
	assert_true(signbit(node_at(d, "n[2]")->item.valuedouble));
	assert_false(node_at(d, "n[3]")->flags & JSON_PARSE_BAD);   /* 2.385e-3 too */
	p = json_doc_problem_at(d, 4);
	assert_int_equal(p->kind, JSON_PROBLEM_CONTROL);  /* the newline in "x\ny" */
	assert_int_equal(p->line, 3);
	assert_int_equal(p->col, 9);
	assert_null(json_doc_problem_at(d, 5));
	/* The raw newline starts a line: "z" is on line 5. */
	assert_int_equal(node_at(d, "z")->key_line, 5);
	assert_int_equal(node_at(d, "z")->key_col, 2);
	json_doc_free(d);
}

static void
json_parse_should_flag_an_escaped_nul_in_keys_and_strings(void **state)
{
	(void)state;
	const char *t = "{\"k\\u0000x\": 1, \"s\": \"a\\u0000\", \"t\": \"a\\\\u0000\"}";
	struct json_doc *d = parse(t);
	const cJSON *c = json_doc_root(d)->child;
	assert_int_equal(json_node_of(c)->flags, JSON_PARSE_KEY_NUL);
	assert_string_equal(c->string, "k");    /* a C string ends at the NUL */
	assert_int_equal(json_node_of(c->next)->flags, JSON_PARSE_VAL_NUL);
	assert_int_equal(json_node_of(c->next->next)->flags, 0);   /* an escaped backslash */
	assert_string_equal(c->next->next->valuestring, "a\\u0000");
	assert_int_equal(json_doc_n_problems(d), 0);
	json_doc_free(d);
}

/* Every number reads as strtod() reads it: the fast path (up to 15
 * digits, a power of ten up to 22) and the rest.  A fixed generator makes
 * 200 000 numbers of every shape JSON allows. */
static void
json_parse_should_read_numbers_exactly_as_strtod(void **state)
{
	(void)state;
	static const char *const fixed[] = {
		"0", "-0", "0.1", "0.30000000000000004", "9007199254740993", "1e23",
		"2.2250738585072014e-308", "4.9e-324", "1.7976931348623157e308", "1e400",
		"-1e400", "1e-400", "123456789012345678901234567890", "0.000001234",
		"1E+2", "3.14159265358979323846264338327950288", "5e-324", "1e22", "1e-22",
		"999999999999999", "9999999999999999", "0.1e-5", "100e-2",
	};
	char t[96];
	uint64_t r = 88172645463325252u;
	for (size_t k = 0; k < 200000 + sizeof fixed / sizeof fixed[0]; k++) {
		const char *num = NULL;
		char gen[64];
		if (k < sizeof fixed / sizeof fixed[0]) {
			num = fixed[k];
		} else {
			/* xorshift64: -? then "0.000ddd" or "ddd.ddd" or "ddd", e±x sometimes */
			r ^= r << 13, r ^= r >> 7, r ^= r << 17;
			int nd = 1 + (int)(r % 20), point = (int)((r >> 8) % (unsigned)nd);
			size_t n = 0;
			if (r & 0x100000)
				gen[n++] = '-';
			if (r & 0x400000) {
				gen[n++] = '0';
				gen[n++] = '.';
				for (int z = (int)((r >> 40) % 8); z > 0; z--)
					gen[n++] = '0';
				point = 0;
			}
			uint64_t q = r;
			for (int i = 0; i < nd; i++) {
				if (point > 0 && i == point)
					gen[n++] = '.';
				q = q * 6364136223846793005u + 1442695040888963407u;
				int digit = (int)((q >> 59) % 10);
				gen[n++] = (char)('0' + (i == 0 && digit == 0 && !(r & 0x400000) ? 7 : digit));
			}
			if (r & 0x200000)
				n += (size_t)snprintf(gen + n, sizeof gen - n, "e%d",
				                      (int)((r >> 24) % 700) - 350);
			gen[n] = '\0';
			num = gen;
		}
		snprintf(t, sizeof t, "[%s]", num);
		size_t err;
		struct json_doc *d = json_parse(t, strlen(t), &err);
		if (d == NULL)
			fail_msg("%s: not parsed", t);
		double got = json_doc_root(d)->child->valuedouble, want = strtod(num, NULL);
		bool bad = json_doc_n_problems(d) > 0;
		json_doc_free(d);
		if (bad)
			fail_msg("%s: a problem noted", t);
		if (memcmp(&got, &want, sizeof got) != 0)
			fail_msg("%s: read %.17g, strtod gives %.17g", num, got, want);
	}
}

static void
text_line_col_should_follow_newlines_and_clamp(void **state)
{
	(void)state;
	const char *t = "ab\ncd\n\nxyz";
	int line, col;
	text_line_col(t, strlen(t), 0, &line, &col);
	assert_int_equal(line, 1);
	assert_int_equal(col, 1);
	text_line_col(t, strlen(t), 4, &line, &col);
	assert_int_equal(line, 2);
	assert_int_equal(col, 2);
	text_line_col(t, strlen(t), 9, &line, &col);
	assert_int_equal(line, 4);
	assert_int_equal(col, 3);
	text_line_col(t, strlen(t), 999, &line, &col);
	assert_int_equal(line, 4);
	assert_int_equal(col, 4);
}

static void
text_utf8_seq_should_reject_invalid_sequences(void **state)
{
	(void)state;
	assert_int_equal(text_utf8_seq("a", 1), 1);
	assert_int_equal(text_utf8_seq("\xc3\xa9", 2), 2);
	assert_int_equal(text_utf8_seq("\xe2\x82\xac", 3), 3);
	assert_int_equal(text_utf8_seq("\xf0\x9f\x98\x80", 4), 4);
	assert_int_equal(text_utf8_seq("\xc3\xa9", 1), 0);       /* cut short */
	assert_int_equal(text_utf8_seq("\x80", 1), 0);           /* lone continuation */
	assert_int_equal(text_utf8_seq("\xc0\xaf", 2), 0);       /* overlong '/' */
	assert_int_equal(text_utf8_seq("\xe0\x80\xaf", 3), 0);   /* overlong */
	assert_int_equal(text_utf8_seq("\xed\xa0\x80", 3), 0);   /* surrogate */
	assert_int_equal(text_utf8_seq("\xf4\x90\x80\x80", 4), 0); /* > U+10FFFF */
	assert_int_equal(text_utf8_seq("\xff", 1), 0);
	assert_int_equal(text_utf8_seq("\xc3(", 2), 0);
	assert_int_equal(text_utf8_seq("", 0), 0);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(json_parse_should_build_the_tree_cjson_builds),
		cmocka_unit_test(json_parse_should_place_keys_and_values_of_nested_objects),
		cmocka_unit_test(json_parse_should_place_array_elements),
		cmocka_unit_test(json_parse_should_count_characters_not_bytes),
		cmocka_unit_test(json_parse_should_keep_every_duplicate_in_order),
		cmocka_unit_test(json_parse_should_unescape_keys_and_strings),
		cmocka_unit_test(json_parse_should_skip_a_byte_order_mark),
		cmocka_unit_test(json_parse_should_stop_at_the_first_malformed_spot),
		cmocka_unit_test(json_parse_should_limit_nesting_as_cjson_does),
		cmocka_unit_test(json_parse_should_note_control_characters_and_non_json_numbers),
		cmocka_unit_test(json_parse_should_flag_an_escaped_nul_in_keys_and_strings),
		cmocka_unit_test(json_parse_should_read_numbers_exactly_as_strtod),
		cmocka_unit_test(text_line_col_should_follow_newlines_and_clamp),
		cmocka_unit_test(text_utf8_seq_should_reject_invalid_sequences),
	};
	return cmocka_run_group_tests_name("json_parse", tests, NULL, NULL);
}
