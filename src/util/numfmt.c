/* numfmt.c — shortest round-trip and sign-safe fixed formatting (numfmt.h). */
#include "util/numfmt.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* x's 17 significant digits as printf rounds them: d[0..16] ('0'..'9'),
 * the decimal exponent *e10 and the sign *neg. */
static void
digits17(double x, char d[17], int *e10, bool *neg)
{
	char t[40]; /* at most "-d.dddddddddddddddde-308" */
	snprintf(t, sizeof t, "%.16e", x);
	const char *p = t;
	*neg = *p == '-';
	if (*neg)
		p++;
	d[0] = *p++;
	p++; /* the point */
	for (int i = 1; i < 17; i++)
		d[i] = *p++;
	*e10 = atoi(p + 1); /* past the 'e' */
}

/* Rounds the 17 digits d to k (15 or 16) into r, with exponent *e10.
 * Returns false on a possible tie: d's digits from k on are "5" or "50",
 * where the binary value alone decides (printf rounds the exact value,
 * not these digits).  Elsewhere rounding the digits gives printf's. */
static bool
round17(const char d[17], int k, char *r, int *e10)
{
	int tail = k == 16 ? d[16] - '0' : 10 * (d[15] - '0') + (d[16] - '0');
	int half = k == 16 ? 5 : 50;
	if (tail == half)
		return false;
	memcpy(r, d, (size_t)k);
	if (tail > half) {
		int i = k - 1;
		while (i >= 0 && r[i] == '9')
			r[i--] = '0';
		if (i >= 0) {
			r[i]++;
		} else {
			r[0] = '1'; /* 9.99..9 -> 10.0..0 */
			(*e10)++;
		}
	}
	return true;
}

/* What printf's %.{prec}g prints for the prec significant digits d with
 * decimal exponent e10: d.ddde±XX when e10 < -4 or e10 >= prec, else
 * fixed; trailing zeros and a bare point dropped.  Returns the length. */
static int
g_text(char *buf, const char *d, int prec, int e10, bool neg)
{
	int nd = prec;
	while (nd > 1 && d[nd - 1] == '0')
		nd--;
	char *o = buf;
	if (neg)
		*o++ = '-';
	if (e10 < -4 || e10 >= prec) {
		*o++ = d[0];
		if (nd > 1) {
			*o++ = '.';
			memcpy(o, d + 1, (size_t)(nd - 1));
			o += nd - 1;
		}
		int e = e10 < 0 ? -e10 : e10;
		*o++ = 'e';
		*o++ = e10 < 0 ? '-' : '+';
		if (e >= 100)
			*o++ = (char)('0' + e / 100);
		*o++ = (char)('0' + e / 10 % 10);
		*o++ = (char)('0' + e % 10);
	} else if (e10 < 0) {
		*o++ = '0';
		*o++ = '.';
		for (int i = 0; i < -e10 - 1; i++)
			*o++ = '0';
		memcpy(o, d, (size_t)nd);
		o += nd;
	} else {
		for (int i = 0; i <= e10; i++)
			*o++ = i < nd ? d[i] : '0';
		if (nd > e10 + 1) {
			*o++ = '.';
			memcpy(o, d + e10 + 1, (size_t)(nd - e10 - 1));
			o += nd - e10 - 1;
		}
	}
	*o = '\0';
	return (int)(o - buf);
}

/* %.{prec}g of x, from the 17 digits when that is safe, else by printf. */
static int
g_at(char buf[NUMFMT_SHORTEST_LEN], double x, const char d17[17], int e17,
     bool neg, int prec)
{
	if (prec == 17)
		return g_text(buf, d17, 17, e17, neg);
	char r[17];
	int e10 = e17;
	if (!round17(d17, prec, r, &e10))
		return snprintf(buf, NUMFMT_SHORTEST_LEN, "%.*g", prec, x);
	return g_text(buf, r, prec, e10, neg);
}

int
numfmt_shortest(char buf[NUMFMT_SHORTEST_LEN], double x)
{
	buf[0] = '\0';
	if (!isfinite(x))
		return 0;
	if (x == 0.0) { /* also catches -0.0 */
		buf[0] = '0';
		buf[1] = '\0';
		return 1;
	}
	/* The shortest of %.15g, %.16g, %.17g that strtod() reads back as x,
	 * with one printf instead of three: the digits of the shorter ones
	 * come from the 17 (g_at()).  And %.16g is tried first: the nearest
	 * 16-digit decimal is no farther from x than the nearest 15-digit one
	 * (which is a 16-digit decimal too), so when %.16g does not read back
	 * as x, neither does %.15g -- unless x is a power of two, whose
	 * doubles below are twice as dense as above: a 15-digit decimal above
	 * can then read back while a nearer 16-digit one below does not. */
	char d17[17];
	int e17;
	bool neg;
	digits17(x, d17, &e17, &neg);
	int exp2;
	bool pow2 = fabs(frexp(x, &exp2)) == 0.5;
	int k = g_at(buf, x, d17, e17, neg, 16);
	bool ok16 = strtod(buf, NULL) == x;
	if (!ok16 && !pow2)
		return g_at(buf, x, d17, e17, neg, 17);
	char b15[NUMFMT_SHORTEST_LEN];
	int k15 = g_at(b15, x, d17, e17, neg, 15);
	if (strtod(b15, NULL) == x) {
		memcpy(buf, b15, (size_t)k15 + 1);
		return k15;
	}
	return ok16 ? k : g_at(buf, x, d17, e17, neg, 17);
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
