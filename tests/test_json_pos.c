/* test_json_pos.c — the position index, its lexical notes, and offset
 * conversion. */
#include "test_util.h"
#include "input/json_pos.h"
#include "util/text.h"

#include <string.h>

/* Entry i in document order (pre-order), which must exist. */
static const struct json_pos_entry *
at(const struct json_pos *jp, size_t i)
{
	const struct json_pos_entry *e = json_pos_entry_at(jp, i);
	if (e == NULL)
		fail_msg("no entry %zu", i);
	return e;
}

static void
json_pos_should_index_keys_and_values_of_nested_objects(void **state)
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
	struct json_pos *jp = json_pos_alloc(t, strlen(t));
	const struct json_pos_entry *e = at(jp, 0);      /* the root */
	assert_int_equal(e->val_line, 1);
	assert_int_equal(e->val_col, 1);
	assert_int_equal(e->key_line, 0);
	e = at(jp, 1);                                   /* payload_kg */
	assert_int_equal(e->key_line, 2);
	assert_int_equal(e->key_col, 3);
	assert_int_equal(e->val_line, 2);
	assert_int_equal(e->val_col, 17);
	assert_int_equal(e->val_end - e->val_off, 5);
	assert_memory_equal(t + e->val_off, "2.385", 5);
	e = at(jp, 4);                                   /* locks.locked_kv */
	assert_int_equal(e->key_line, 5);
	assert_int_equal(e->key_col, 5);
	assert_int_equal(e->val_line, 5);
	assert_int_equal(e->val_col, 24);
	e = at(jp, 2);                                   /* locks */
	assert_int_equal(e->val_line, 3);
	assert_int_equal(e->val_col, 12);
	assert_int_equal(t[e->val_end - 1], '}');
	assert_int_equal(json_pos_count(jp), 5);
	assert_null(json_pos_entry_at(jp, 5));
	assert_true(json_pos_complete(jp));
	assert_int_equal(json_pos_n_problems(jp), 0);
	assert_int_equal(json_pos_all_flags(jp), 0);
	json_pos_free(jp);
}

static void
json_pos_should_index_array_elements_in_document_order(void **state)
{
	(void)state;
	const char *t = "{\"a\": [10, {\"b\": [true, null]}, \"s\", [], {}, -1e3]}";
	struct json_pos *jp = json_pos_alloc(t, strlen(t));
	/* root, a, a[0], a[1], a[1].b, b[0], b[1], a[2], a[3], a[4], a[5] */
	assert_int_equal(json_pos_count(jp), 11);
	assert_int_equal(at(jp, 2)->val_col, 8);
	assert_int_equal(at(jp, 6)->val_col, 25);
	assert_int_equal(at(jp, 7)->val_col, 33);
	const struct json_pos_entry *e = at(jp, 10);
	assert_int_equal(e->val_col, 46);
	assert_memory_equal(t + e->val_off, "-1e3", e->val_end - e->val_off);
	assert_int_equal(at(jp, 8)->key_line, 0);
	json_pos_free(jp);
}

static void
json_pos_should_count_characters_not_bytes(void **state)
{
	(void)state;
	/* "é" and "°" are two bytes each, "€" three: one column each. */
	const char *t = "{\"t\": \"\xc3\xa9\xc2\xb0\xe2\x82\xac\", \"x\": 1}";
	struct json_pos *jp = json_pos_alloc(t, strlen(t));
	assert_int_equal(at(jp, 2)->key_col, 14);
	assert_int_equal(at(jp, 2)->val_col, 19);
	int line, col;
	text_line_col(t, strlen(t), (size_t)(strstr(t, "1}") - t), &line, &col);
	assert_int_equal(line, 1);
	assert_int_equal(col, 19);
	json_pos_free(jp);
}

static void
json_pos_should_keep_every_duplicate_in_order(void **state)
{
	(void)state;
	const char *t = "{\"k\": 1,\n \"k\": 2,\n  \"k\": 3}";
	struct json_pos *jp = json_pos_alloc(t, strlen(t));
	assert_int_equal(json_pos_count(jp), 4);
	assert_int_equal(at(jp, 1)->key_line, 1);
	assert_int_equal(at(jp, 2)->key_line, 2);
	assert_int_equal(at(jp, 2)->key_col, 2);
	assert_int_equal(at(jp, 3)->key_col, 3);
	json_pos_free(jp);
}

static void
json_pos_should_step_over_escapes_in_keys_and_strings(void **state)
{
	(void)state;
	const char *t = "{\"a\\u00e9\\\"b\\n\": 1, \"\\ud83d\\ude00\": 2, \"q\": \"x\\\"}y\"}";
	struct json_pos *jp = json_pos_alloc(t, strlen(t));
	assert_int_equal(json_pos_count(jp), 4);
	assert_true(json_pos_complete(jp));
	const struct json_pos_entry *e = at(jp, 3);
	assert_int_equal(e->val_end - e->val_off, 7); /* "x\"}y" */
	json_pos_free(jp);
}

static void
json_pos_should_skip_a_byte_order_mark(void **state)
{
	(void)state;
	const char *t = "\xef\xbb\xbf{\"a\": 1}";
	struct json_pos *jp = json_pos_alloc(t, strlen(t));
	assert_int_equal(at(jp, 0)->val_col, 1);
	assert_int_equal(at(jp, 1)->key_col, 2);
	int line, col;
	text_line_col(t, strlen(t), 4, &line, &col);
	assert_int_equal(col, 2);
	json_pos_free(jp);
}

static void
json_pos_should_stop_quietly_on_malformed_text(void **state)
{
	(void)state;
	const char *bad[] = { "", "{", "{\"a\" 1}", "{\"a\": [1 2]}", "{\"a\":", "[\"\\x\"]", "{\"a\": \"unterminated" };
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		struct json_pos *jp = json_pos_alloc(bad[i], strlen(bad[i]));
		assert_non_null(jp);
		assert_false(json_pos_complete(jp));
		json_pos_free(jp);
	}
	/* The part before the error is indexed. */
	const char *t = "{\"a\": 1, \"b\": [2, }";
	struct json_pos *jp = json_pos_alloc(t, strlen(t));
	assert_true(json_pos_count(jp) >= 4);   /* root, a, b, b[0] */
	assert_int_equal(at(jp, 3)->val_col, 16);
	assert_false(json_pos_complete(jp));
	json_pos_free(jp);
	json_pos_free(NULL);
}

static void
json_pos_should_note_control_characters_and_non_json_numbers(void **state)
{
	(void)state;
	const char *t = "{\"a\tb\": 1,\n \"n\": [012, 1., -0, 2.385e-3, -.5],\n \"s\": \"x\ny\"}";
	struct json_pos *jp = json_pos_alloc(t, strlen(t));
	assert_true(json_pos_complete(jp));
	assert_int_equal(json_pos_n_problems(jp), 5);
	const struct json_pos_problem *p = json_pos_problem_at(jp, 0);
	assert_int_equal(p->kind, JSON_POS_CONTROL);  /* the TAB in a key */
	assert_int_equal(p->entry, 1);
	assert_int_equal(p->line, 1);
	assert_int_equal(p->col, 4);
	assert_int_equal(p->byte, '\t');
	assert_true(at(jp, 1)->flags & JSON_POS_BAD);
	p = json_pos_problem_at(jp, 1);
	assert_int_equal(p->kind, JSON_POS_NUMBER);   /* 012 */
	assert_int_equal(p->entry, 3);
	assert_int_equal(p->line, 2);
	assert_int_equal(p->col, 8);
	assert_int_equal(json_pos_problem_at(jp, 2)->entry, 4);   /* 1. */
	assert_int_equal(json_pos_problem_at(jp, 3)->entry, 7);   /* -.5 */
	assert_false(at(jp, 5)->flags & JSON_POS_BAD);            /* -0 is JSON */
	assert_false(at(jp, 6)->flags & JSON_POS_BAD);            /* 2.385e-3 too */
	p = json_pos_problem_at(jp, 4);
	assert_int_equal(p->kind, JSON_POS_CONTROL);  /* the newline in "x\ny" */
	assert_int_equal(p->line, 3);
	assert_int_equal(p->col, 9);
	assert_null(json_pos_problem_at(jp, 5));
	json_pos_free(jp);
}

static void
json_pos_should_flag_an_escaped_nul_in_keys_and_strings(void **state)
{
	(void)state;
	const char *t = "{\"k\\u0000x\": 1, \"s\": \"a\\u0000\", \"t\": \"a\\\\u0000\"}";
	struct json_pos *jp = json_pos_alloc(t, strlen(t));
	assert_int_equal(at(jp, 1)->flags, JSON_POS_KEY_NUL);
	assert_int_equal(at(jp, 2)->flags, JSON_POS_VAL_NUL);
	assert_int_equal(at(jp, 3)->flags, 0);   /* an escaped backslash, then text */
	assert_int_equal(json_pos_all_flags(jp), JSON_POS_KEY_NUL | JSON_POS_VAL_NUL);
	assert_int_equal(json_pos_n_problems(jp), 0);
	json_pos_free(jp);
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
		cmocka_unit_test(json_pos_should_index_keys_and_values_of_nested_objects),
		cmocka_unit_test(json_pos_should_index_array_elements_in_document_order),
		cmocka_unit_test(json_pos_should_count_characters_not_bytes),
		cmocka_unit_test(json_pos_should_keep_every_duplicate_in_order),
		cmocka_unit_test(json_pos_should_step_over_escapes_in_keys_and_strings),
		cmocka_unit_test(json_pos_should_skip_a_byte_order_mark),
		cmocka_unit_test(json_pos_should_stop_quietly_on_malformed_text),
		cmocka_unit_test(json_pos_should_note_control_characters_and_non_json_numbers),
		cmocka_unit_test(json_pos_should_flag_an_escaped_nul_in_keys_and_strings),
		cmocka_unit_test(text_line_col_should_follow_newlines_and_clamp),
		cmocka_unit_test(text_utf8_seq_should_reject_invalid_sequences),
	};
	return cmocka_run_group_tests_name("json_pos", tests, NULL, NULL);
}
