/* test_util.h — shared helpers for the cmocka programs. */
#ifndef AEROEVAL_TEST_UTIL_H
#define AEROEVAL_TEST_UTIL_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

/* Relative comparison with a named tolerance; prints both values in full,
 * because cmocka's assert_float_equal prints only 6 decimals. */
#define assert_rel(got, want, reltol) \
	assert_rel_impl((got), (want), (reltol), #got, __FILE__, __LINE__)

static inline void
assert_rel_impl(double got, double want, double reltol, const char *expr,
                const char *file, int line)
{
	double scale = fabs(want) > 1e-300 ? fabs(want) : 1.0;
	if (!(fabs(got - want) <= reltol * scale)) {
		print_error("%s = %.12g, want %.12g (rel tol %g)\n", expr, got, want, reltol);
		_fail(file, line);
	}
}

#endif
