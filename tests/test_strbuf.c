/* test_strbuf.c — the growable byte buffer. */
#include "test_util.h"
#include "strbuf.h"
#include "stats.h"

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

/* str_format() against snprintf() for one value in each float format, in
 * a buffer big enough and in a short one (truncation, return value).  The
 * formats come from a table, so the compiler cannot check them here. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
static void
check_fixed(double x)
{
	static const char *const fmts[] = { "%.0f", "%.1f", "%.2f", "%.3f", "%+.1f",
		"a %.2f b %s c %d%%" };
	for (size_t i = 0; i < sizeof fmts / sizeof fmts[0]; i++) {
		char a[128], b[128];
		for (size_t n = 1; n <= sizeof a; n += sizeof a - 1) {
			memset(a, 'x', sizeof a);
			memset(b, 'x', sizeof b);
			size_t m = n == 1 ? 7 : n;  /* short: 7 bytes */
			int ra = snprintf(a, m, fmts[i], x, "word", -12);
			int rb = str_format(b, m, fmts[i], x, "word", -12);
			if (ra != rb || memcmp(a, b, sizeof a) != 0)
				fail_msg("%s of %.17g: snprintf \"%s\" (%d), str_format \"%s\" (%d)",
				    fmts[i], x, a, ra, b, rb);
		}
	}
}
#pragma GCC diagnostic pop

static void
str_format_should_write_what_snprintf_writes(void **state)
{
	(void)state;
	/* Ties and near ties, exact and not: 2.5, 0.125, 1.005 ... */
	static const double edge[] = { 0.0, -0.0, 0.5, 1.5, 2.5, -2.5, 0.125,
		0.375, -0.125, 1.005, 2.675, 0.045, 1e11 + 0.5, 999999.9995,
		0.05, 0.15, 0.25, 0.35, 9.9995, 99.995, 1e12, -1e12, 1e15, 1e300,
		-1e300, DBL_MIN, -DBL_MIN, 5e-324, DBL_MAX, -0.4, -0.04, -0.0004,
		0.49999999999999994, 4503599627370495.5, 123456.789 };
	for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++)
		check_fixed(edge[i]);
	check_fixed(NAN);
	check_fixed(INFINITY);
	check_fixed(-INFINITY);
	struct stats_rng r;
	stats_rng_seed(&r, 20261202u);
	for (int i = 0; i < 40000; i++) {
		/* Any magnitude a message prints, both signs ... */
		double x = stats_rng_uniform(&r, -1.0, 1.0)
		    * pow(10.0, stats_rng_uniform(&r, -5.0, 13.0));
		check_fixed(x);
		/* ... and the ulps around a decimal tie. */
		int d = (int)stats_rng_below(&r, 4u);
		double tie = (floor(stats_rng_uniform(&r, 0.0, 1e6)) + 0.5)
		    / pow(10.0, d);
		double y = tie;
		for (int k = 0; k < 3; k++)
			y = nextafter(y, 0.0);
		for (int k = 0; k < 7; k++, y = nextafter(y, INFINITY))
			check_fixed(i % 2 ? -y : y);
	}
}

static void
str_format_should_hand_other_formats_to_vsnprintf(void **state)
{
	(void)state;
	char a[64], b[64];
	assert_int_equal(str_format(b, sizeof b, "%.3g|%5.1f|%x|%s", 0.000123456,
	    3.14159, 255u, "end"), snprintf(a, sizeof a, "%.3g|%5.1f|%x|%s",
	    0.000123456, 3.14159, 255u, "end"));
	assert_string_equal(a, b);
	assert_int_equal(str_format(b, sizeof b, "%d %d %d", INT_MIN, INT_MAX, 0),
	    snprintf(a, sizeof a, "%d %d %d", INT_MIN, INT_MAX, 0));
	assert_string_equal(a, b);
	/* A NULL string is the C library's business. */
	const char *volatile none = NULL;
	assert_int_equal(str_format(b, sizeof b, "[%s]", none),
	    snprintf(a, sizeof a, "[%s]", none));
	assert_string_equal(a, b);
	/* Nothing fits but the terminator; nothing at all. */
	assert_int_equal(str_format(b, 1, "%.1f", 12.25), 4);
	assert_string_equal(b, "");
	assert_int_equal(str_format(NULL, 0, "%s-%d", "ab", 7), 4);
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
		cmocka_unit_test(str_format_should_write_what_snprintf_writes),
		cmocka_unit_test(str_format_should_hand_other_formats_to_vsnprintf),
	};
	return cmocka_run_group_tests_name("strbuf", tests, NULL, NULL);
}
