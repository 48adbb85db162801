/* test_numfmt.c — shortest round-trip and fixed-point number text. */
#include "test_util.h"
#include "util/numfmt.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void
numfmt_shortest_should_prefer_fifteen_digits(void **state)
{
	(void)state;
	char b[NUMFMT_SHORTEST_LEN];
	assert_int_equal(numfmt_shortest(b, 0.1), 3);
	assert_string_equal(b, "0.1");
	numfmt_shortest(b, 2.385);
	assert_string_equal(b, "2.385");
	numfmt_shortest(b, -1282.0);
	assert_string_equal(b, "-1282");
	numfmt_shortest(b, 1e-5);
	assert_string_equal(b, "1e-05");
	numfmt_shortest(b, 6.02214076e23);
	assert_string_equal(b, "6.02214076e+23");
}

static void
numfmt_shortest_should_use_more_digits_only_when_needed(void **state)
{
	(void)state;
	char b[NUMFMT_SHORTEST_LEN];
	/* 0.1 + 0.2 = 0.30000000000000004 needs all 17 digits. */
	numfmt_shortest(b, 0.1 + 0.2);
	assert_string_equal(b, "0.30000000000000004");
	/* 1/3 needs 16 digits: %.15g "0.333333333333333" is another double. */
	numfmt_shortest(b, 1.0 / 3.0);
	assert_string_equal(b, "0.3333333333333333");
	/* DBL_MAX and the smallest subnormal round-trip too. */
	numfmt_shortest(b, 1.7976931348623157e308);
	assert_true(strtod(b, NULL) == 1.7976931348623157e308);
	numfmt_shortest(b, 4.9406564584124654e-324);
	assert_true(strtod(b, NULL) == 4.9406564584124654e-324);
}

static void
numfmt_shortest_should_round_trip_many_values(void **state)
{
	(void)state;
	char b[NUMFMT_SHORTEST_LEN];
	/* A deterministic walk over many magnitudes and mantissas. */
	double x = 0.7390851332151607;
	for (int i = 0; i < 20000; i++) {
		x = x * 1.6180339887498949 + 0.318309886183790671;
		if (x > 1e12)
			x *= 3.14159e-17;
		int k = numfmt_shortest(b, x);
		assert_true(k > 0 && k < NUMFMT_SHORTEST_LEN);
		assert_true(strtod(b, NULL) == x);
	}
}

static void
numfmt_shortest_should_refuse_non_finite_and_unsign_zero(void **state)
{
	(void)state;
	char b[NUMFMT_SHORTEST_LEN] = "junk";
	assert_int_equal(numfmt_shortest(b, NAN), 0);
	assert_string_equal(b, "");
	assert_int_equal(numfmt_shortest(b, INFINITY), 0);
	assert_int_equal(numfmt_shortest(b, -INFINITY), 0);
	assert_string_equal(b, "");
	assert_int_equal(numfmt_shortest(b, -0.0), 1);
	assert_string_equal(b, "0");
}

static void
numfmt_fixed_should_round_to_the_given_decimals(void **state)
{
	(void)state;
	char b[32];
	assert_int_equal(numfmt_fixed(b, sizeof b, 2.385, 1), 3);
	assert_string_equal(b, "2.4");
	numfmt_fixed(b, sizeof b, -17.3456, 2);
	assert_string_equal(b, "-17.35");
	numfmt_fixed(b, sizeof b, 1282.49, 0);
	assert_string_equal(b, "1282");
	numfmt_fixed(b, sizeof b, 0.5, -3); /* clamped to 0 decimals */
	assert_string_equal(b, "0");
}

static void
numfmt_fixed_should_never_print_negative_zero(void **state)
{
	(void)state;
	char b[32];
	numfmt_fixed(b, sizeof b, -0.004, 2);
	assert_string_equal(b, "0.00");
	numfmt_fixed(b, sizeof b, -0.0, 3);
	assert_string_equal(b, "0.000");
	assert_int_equal(numfmt_fixed(b, sizeof b, -0.4, 0), 1);
	assert_string_equal(b, "0");
	numfmt_fixed(b, sizeof b, -0.006, 2); /* rounds away from zero: keeps sign */
	assert_string_equal(b, "-0.01");
}

static void
numfmt_fixed_should_refuse_non_finite_and_short_buffers(void **state)
{
	(void)state;
	char b[8] = "junk";
	assert_int_equal(numfmt_fixed(b, sizeof b, NAN, 2), 0);
	assert_string_equal(b, "");
	assert_int_equal(numfmt_fixed(b, sizeof b, -INFINITY, 2), 0);
	assert_int_equal(numfmt_fixed(b, sizeof b, 12345.678, 3), 0); /* 9 bytes */
	assert_string_equal(b, "");
	assert_int_equal(numfmt_fixed(b, 0, 1.5, 1), 0);
}

/* The definition numfmt_shortest() must match: try %.15g, %.16g, %.17g
 * in turn, keep the first that strtod() reads back. */
static void
shortest_by_definition(char out[NUMFMT_SHORTEST_LEN], double x)
{
	if (x == 0.0) {
		strcpy(out, "0");
		return;
	}
	for (int prec = 15; prec <= 17; prec++) {
		snprintf(out, NUMFMT_SHORTEST_LEN, "%.*g", prec, x);
		if (strtod(out, NULL) == x)
			return;
	}
}

static uint64_t
xorshift(uint64_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 7;
	*s ^= *s << 17;
	return *s;
}

/* numfmt_shortest() takes its shorter forms from one printf's 17 digits:
 * the same text as the definition on 300 000 doubles of every kind --
 * any bit pattern (subnormals included), short decimals, 17-digit
 * decimals, powers of two and their neighbours (where the doubles are
 * denser below than above). */
static void
numfmt_shortest_should_print_what_the_definition_prints(void **state)
{
	(void)state;
	uint64_t g = 88172645463325252u;
	char want[NUMFMT_SHORTEST_LEN], got[NUMFMT_SHORTEST_LEN];
	int n_checked = 0;
	for (int i = 0; i < 300000; i++) {
		uint64_t u = xorshift(&g);
		double x;
		switch (i % 5) {
		case 0:
			memcpy(&x, &u, sizeof x);
			break;
		case 1:
			x = (double)(int64_t)(u % 2000000001u)
			    / pow(10.0, (double)(xorshift(&g) % 20));
			break;
		case 2:
			x = ldexp(1.0, (int)(xorshift(&g) % 2098) - 1074);
			break;
		case 3:
			x = nextafter(ldexp(1.0, (int)(xorshift(&g) % 200) - 100),
			    (u & 1) ? 0.0 : INFINITY);
			break;
		default:
			x = (double)(int64_t)(u % 100000000000000000u)
			    * pow(10.0, (double)((int)(xorshift(&g) % 30) - 25));
			break;
		}
		if (u & 2)
			x = -x;
		if (!isfinite(x))
			continue;
		shortest_by_definition(want, x);
		int k = numfmt_shortest(got, x);
		assert_string_equal(got, want);
		assert_int_equal(k, (int)strlen(want));
		n_checked++;
	}
	assert_true(n_checked > 299000);
}

/* The exact integer path (2^-16 <= |x| < 2^52) against the definition:
 * random significands in every binade it covers, exact ties at the 15th,
 * 16th and 17th digit (n + 0.5, n + 0.25, n + 0.75, where printf rounds the
 * exact value half to even), powers of two and their neighbours (narrower
 * gap below), and the ends of the range. */
static void
numfmt_shortest_should_match_the_definition_on_the_exact_path(void **state)
{
	(void)state;
	uint64_t g = 0x9E3779B97F4A7C15u;
	char want[NUMFMT_SHORTEST_LEN], got[NUMFMT_SHORTEST_LEN];
	static const double frac[] = { 0.5, 0.25, 0.75, 0.125, 0.375 };
	for (int i = 0; i < 200000; i++) {
		uint64_t u = xorshift(&g);
		double x;
		int b = (int)(xorshift(&g) % 69) - 17;   /* binades 2^-17 .. 2^51 */
		switch (i % 4) {
		case 0:
			x = ldexp(1.0 + (double)(u >> 12) * 0x1p-52, b);
			break;
		case 1: /* n + a binary fraction: decimal ties at 15..17 digits */
			x = (double)(int64_t)(u % 4000000000000000u + 100000000000000u)
			    + frac[i % 5];
			break;
		case 2:
			x = ldexp(1.0, b);
			if (u & 4)
				x = nextafter(x, (u & 8) ? 0.0 : INFINITY);
			break;
		default: /* short decimals, as most outputs are */
			x = (double)(int64_t)(u % 100000000u) / pow(10.0, (double)(i % 12));
			break;
		}
		if (u & 2)
			x = -x;
		if (x == 0.0)
			continue;
		shortest_by_definition(want, x);
		int k = numfmt_shortest(got, x);
		assert_string_equal(got, want);
		assert_int_equal(k, (int)strlen(want));
	}
	static const double ends[] = { 0x1p-16, 0x1.fffffffffffffp-17, 0x1p52,
		0x1.fffffffffffffp51, 1e-5, 1.5e-5, 4503599627370495.5, 9.5, 0.5 };
	for (size_t i = 0; i < sizeof ends / sizeof ends[0]; i++) {
		shortest_by_definition(want, ends[i]);
		numfmt_shortest(got, ends[i]);
		assert_string_equal(got, want);
	}
}

/* Sentences for people: three significant digits, never an exponent
 * (the rationale once printed "1.97e+03 W"). */
static void
numfmt_sig_should_never_print_an_exponent(void **state)
{
	(void)state;
	char b[32];
	assert_string_equal(numfmt_sig(b, sizeof b, 1974.3, 3), "1974");
	assert_string_equal(numfmt_sig(b, sizeof b, 2072.0, 3), "2072");
	assert_string_equal(numfmt_sig(b, sizeof b, 13.24, 3), "13.2");
	assert_string_equal(numfmt_sig(b, sizeof b, 0.05876, 3), "0.0588");
	assert_string_equal(numfmt_sig(b, sizeof b, 3107448.2, 3), "3107448");
	assert_string_equal(numfmt_sig(b, sizeof b, -0.0001, 1), "-0.0001");
	assert_string_equal(numfmt_sig(b, sizeof b, 0.0, 3), "0");
	assert_string_equal(numfmt_sig(b, sizeof b, NAN, 3), "\xe2\x80\x94");
	assert_null(strchr(numfmt_sig(b, sizeof b, 1.8e3, 2), 'e'));
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(numfmt_shortest_should_prefer_fifteen_digits),
		cmocka_unit_test(numfmt_shortest_should_use_more_digits_only_when_needed),
		cmocka_unit_test(numfmt_shortest_should_round_trip_many_values),
		cmocka_unit_test(numfmt_shortest_should_print_what_the_definition_prints),
		cmocka_unit_test(numfmt_shortest_should_match_the_definition_on_the_exact_path),
		cmocka_unit_test(numfmt_shortest_should_refuse_non_finite_and_unsign_zero),
		cmocka_unit_test(numfmt_fixed_should_round_to_the_given_decimals),
		cmocka_unit_test(numfmt_fixed_should_never_print_negative_zero),
		cmocka_unit_test(numfmt_fixed_should_refuse_non_finite_and_short_buffers),
		cmocka_unit_test(numfmt_sig_should_never_print_an_exponent),
	};
	return cmocka_run_group_tests_name("numfmt", tests, NULL, NULL);
}
