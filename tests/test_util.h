/* test_util.h — shared helpers for the cmocka programs. */
#ifndef AEROEVAL_TEST_UTIL_H
#define AEROEVAL_TEST_UTIL_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

/* Byte comparison of text with the golden file at path (relative to the
 * repository root); AEROEVAL_UPDATE_GOLDEN=1 rewrites the file first. */
static inline void
assert_golden(const char *path, const char *text)
{
	size_t n = strlen(text);
	if (getenv("AEROEVAL_UPDATE_GOLDEN")) {
		FILE *out = fopen(path, "wb");
		assert_non_null(out);
		assert_int_equal(fwrite(text, 1, n, out), n);
		assert_int_equal(fclose(out), 0);
	}
	FILE *in = fopen(path, "rb");
	if (!in)
		fail_msg("cannot open %s (run from the repository root)", path);
	char *want = malloc(n + 2);
	assert_non_null(want);
	size_t got = fread(want, 1, n + 1, in);
	fclose(in);
	if (got != n || memcmp(want, text, n) != 0) {
		size_t i = 0;
		while (i < n && i < got && want[i] == text[i])
			i++;
		free(want);
		fail_msg("%s differs from the render at byte %zu (lengths %zu and %zu)",
		         path, i, got, n);
	}
	free(want);
}

/* Copies the file src to dst; false when src cannot be opened. */
static inline bool
test_copy_file(const char *src, const char *dst)
{
	FILE *in = fopen(src, "rb");
	if (in == NULL)
		return false;
	FILE *out = fopen(dst, "wb");
	assert_non_null(out);
	char buf[4096];
	size_t n;
	while ((n = fread(buf, 1, sizeof buf, in)) > 0)
		assert_int_equal(fwrite(buf, 1, n, out), n);
	fclose(in);
	assert_int_equal(fclose(out), 0);
	return true;
}

#endif
