/* test_strbuf.c — the growable byte buffer. */
#include "test_util.h"
#include "util/strbuf.h"
#include "util/stats.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void
strbuf_empty_should_read_as_empty_string(void **state)
{
	(void)state;
	struct strbuf sb = STRBUF_INIT;
	assert_string_equal(strbuf_str(&sb), "");
	assert_int_equal(sb.len, 0);
	size_t n = 99;
	char *p = strbuf_take(&sb, &n);
	assert_non_null(p);
	assert_string_equal(p, "");
	assert_int_equal(n, 0);
	free(p);
	strbuf_free(&sb);
	strbuf_free(NULL);
}

static void
strbuf_appends_should_concatenate_in_order(void **state)
{
	(void)state;
	struct strbuf sb;
	strbuf_init(&sb);
	strbuf_append_str(&sb, "rotor");
	strbuf_append_char(&sb, '_');
	strbuf_append(&sb, "count=4xyz", 7);
	assert_string_equal(strbuf_str(&sb), "rotor_count=4");
	assert_int_equal(sb.len, 13);
	strbuf_free(&sb);
}

static void
strbuf_append_should_keep_embedded_nul_bytes(void **state)
{
	(void)state;
	struct strbuf sb = STRBUF_INIT;
	strbuf_append(&sb, "a\0b", 3);
	assert_int_equal(sb.len, 3);
	assert_memory_equal(sb.data, "a\0b", 4); /* and the terminating NUL */
	strbuf_free(&sb);
}

static void
strbuf_printf_should_grow_past_the_first_allocation(void **state)
{
	(void)state;
	struct strbuf sb = STRBUF_INIT;
	strbuf_printf(&sb, "%s=%.3f;", "mass_kg", 2.385);
	assert_string_equal(strbuf_str(&sb), "mass_kg=2.385;");
	/* 1000 formatted appends of 7 bytes: crosses several doublings and a
	 * second vsnprintf pass whenever one append straddles the capacity. */
	for (int i = 0; i < 1000; i++)
		strbuf_printf(&sb, "%06d|", i);
	assert_int_equal(sb.len, 14 + 7000);
	assert_memory_equal(sb.data + 14 + 7 * 617, "000617|", 7);
	assert_int_equal(sb.data[sb.len], '\0');
	/* One append longer than twice the capacity. */
	char big[5000];
	memset(big, 'q', sizeof big - 1);
	big[sizeof big - 1] = '\0';
	strbuf_reset(&sb);
	strbuf_printf(&sb, "<%s>", big);
	assert_int_equal(sb.len, 5001);
	assert_int_equal(sb.data[5000], '>');
	strbuf_free(&sb);
}

static void
strbuf_reset_should_empty_but_keep_capacity(void **state)
{
	(void)state;
	struct strbuf sb = STRBUF_INIT;
	strbuf_append_str(&sb, "battery_mass_kg");
	size_t cap = sb.cap;
	strbuf_reset(&sb);
	assert_int_equal(sb.len, 0);
	assert_int_equal(sb.cap, cap);
	assert_string_equal(strbuf_str(&sb), "");
	strbuf_free(&sb);
}

static void
strbuf_take_should_hand_over_and_leave_empty(void **state)
{
	(void)state;
	struct strbuf sb = STRBUF_INIT;
	strbuf_printf(&sb, "%d,%d", 27, 4);
	size_t n = 0;
	char *p = strbuf_take(&sb, &n);
	assert_string_equal(p, "27,4");
	assert_int_equal(n, 4);
	assert_null(sb.data);
	assert_int_equal(sb.len, 0);
	strbuf_append_str(&sb, "again");
	assert_string_equal(strbuf_str(&sb), "again");
	free(p);
	strbuf_free(&sb);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(strbuf_empty_should_read_as_empty_string),
		cmocka_unit_test(strbuf_appends_should_concatenate_in_order),
		cmocka_unit_test(strbuf_append_should_keep_embedded_nul_bytes),
		cmocka_unit_test(strbuf_printf_should_grow_past_the_first_allocation),
		cmocka_unit_test(strbuf_reset_should_empty_but_keep_capacity),
		cmocka_unit_test(strbuf_take_should_hand_over_and_leave_empty),
	};
	return cmocka_run_group_tests_name("strbuf", tests, NULL, NULL);
}
