/* numfmt.c — shortest round-trip and sign-safe fixed formatting (numfmt.h). */
#include "numfmt.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int
numfmt_shortest(char buf[NUMFMT_SHORTEST_LEN], double x)
{
	buf[0] = '\0';
	if (!isfinite(x))
		return 0;
	if (x == 0.0) /* also catches -0.0 */
		x = 0.0;
	/* 15 significant digits are enough for every decimal with <= 15 digits,
	 * 17 for every double (IEEE 754 binary64); try the short ones first so
	 * that 0.1 prints as "0.1" and not "0.10000000000000001". */
	int k = 0;
	for (int prec = 15; prec <= 17; prec++) {
		k = snprintf(buf, NUMFMT_SHORTEST_LEN, "%.*g", prec, x);
		if (strtod(buf, NULL) == x)
			break;
	}
	return k;
}

/* True when s (after an optional '-') has only zeros and a point: the text
 * of a value that rounded to zero. */
static int
is_zero_text(const char *s)
{
	if (*s == '-')
		s++;
	for (; *s != '\0'; s++)
		if (*s != '0' && *s != '.')
			return 0;
	return 1;
}

int
numfmt_fixed(char *buf, size_t n, double x, int decimals)
{
	if (n > 0)
		buf[0] = '\0';
	if (!isfinite(x) || n == 0)
		return 0;
	if (decimals < 0)
		decimals = 0;
	if (decimals > 17)
		decimals = 17;
	int k = snprintf(buf, n, "%.*f", decimals, x);
	if (k < 0 || (size_t)k >= n) {
		buf[0] = '\0';
		return 0;
	}
	/* -0.004 with 2 decimals prints "-0.00": drop the sign by shifting the
	 * text (including its NUL) one byte left. */
	if (buf[0] == '-' && is_zero_text(buf)) {
		memmove(buf, buf + 1, (size_t)k);
		k--;
	}
	return k;
}
