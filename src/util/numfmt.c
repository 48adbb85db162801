/* numfmt.c — shortest round-trip and sign-safe fixed formatting (numfmt.h). */
#include "util/numfmt.h"

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
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

/* ---- the exact integer path ---------------------------------------------
 *
 * For 2^-16 <= |x| < 2^52 (1.5e-5 to 4.5e15: nearly every number aeroeval prints) the three
 * candidates and their round-trip tests need no printf and no strtod: with
 * x = m * 2^-q (m the 53-bit significand, q > 0) and a power of ten 10^p
 * (p <= 22), P = m * 10^p is an exact 128-bit integer and x * 10^p = P / 2^q.
 * Its integer part W (17 to 19 digits) and its fraction (the low q bits of
 * P) give every digit of x exactly, so each candidate is rounded the way
 * printf rounds the exact binary value (half to even on an exact tie).
 * A candidate C (x * 10^p rounded to k digits) reads back as x exactly when
 * it lies within half a gap of x: |C * 2^q - P| < 10^p / 2, which is half an
 * ulp in these units; at the boundary strtod rounds to the even
 * significand; below a power of two the gap is half as wide.
 * Outside that range, or without a 128-bit integer type, printf decides. */

#ifdef __SIZEOF_INT128__
__extension__ typedef unsigned __int128 u128;

static const uint64_t pow10_u64[20] = {
	1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u, 10000000u,
	100000000u, 1000000000u, 10000000000u, 100000000000u,
	1000000000000u, 10000000000000u, 100000000000000u,
	1000000000000000u, 10000000000000000u, 100000000000000000u,
	1000000000000000000u, 10000000000000000000u,
};

static u128
pow10_u128(int p)
{
	return p < 20 ? pow10_u64[p] : (u128)pow10_u64[19] * pow10_u64[p - 19];
}

/* x * 10^p = P / 2^q exactly, split for rounding. */
struct scaled {
	u128 P;          /* m * 10^p */
	int q;           /* binary places of P: 1..127 */
	u128 frac;       /* P mod 2^q: the fraction of x * 10^p, times 2^q */
	uint64_t W;      /* floor(x * 10^p): 17 to 19 digits */
	int nd;          /* digits of W */
	int p;           /* the power of ten */
	uint64_t m;      /* significand (53 bits) */
	bool low_gap;    /* m is 2^52 above the smallest binade: the gap below
	                  * x is half the gap above */
};

/* Fills s for |x| (finite, nonzero); false when x is outside the range
 * this path handles. */
static bool
scale_exact(double ax, struct scaled *s)
{
	uint64_t bits;
	memcpy(&bits, &ax, sizeof bits);
	int be = (int)(bits >> 52);                /* sign is clear */
	uint64_t frac = bits & ((UINT64_C(1) << 52) - 1);
	int e = be - 1075;                         /* x = m * 2^e */
	if (be == 0 || e >= 0)
		return false;                      /* subnormal, or |x| >= 2^52 */
	/* ax is in [2^b, 2^(b+1)), so floor(log10 ax) is est or est + 1 and
	 * x * 10^(17 - est) lies in [1e17, 1e19). */
	int b = e + 52;
	int est = (int)floor(b * 0.30102999566398120);
	if (est < -5)
		return false;                      /* 10^p > 10^22: P needs > 128 bits */
	s->p = 17 - est;
	s->m = frac | (UINT64_C(1) << 52);
	s->q = -e;
	s->P = (u128)s->m * pow10_u128(s->p);
	s->frac = s->P & (((u128)1 << s->q) - 1);
	s->W = (uint64_t)(s->P >> s->q);
	s->nd = s->W >= pow10_u64[18] ? 19 : s->W >= pow10_u64[17] ? 18 : 17;
	s->low_gap = frac == 0 && be > 1;
	return true;
}

/* Rounds x * 10^p to k significant digits (15..17) as printf does: the
 * digits into q_out, the decimal exponent of the first digit into *e10,
 * and the candidate's value times 10^p into *cs. */
static void
round_exact(const struct scaled *s, int k, uint64_t *q_out, int *e10, uint64_t *cs)
{
	int drop = s->nd - k;                      /* 0..4 */
	uint64_t div = pow10_u64[drop];
	uint64_t Q = s->W / div, R = s->W % div;
	/* Compare the dropped part R + frac / 2^q with div / 2, doubled:
	 * 2R - div + frac / 2^(q-1). */
	int64_t c = 2 * (int64_t)R - (int64_t)div;
	u128 half = (u128)1 << (s->q - 1);
	int sign;
	if (c >= 1)
		sign = 1;
	else if (c == 0)
		sign = s->frac != 0;
	else if (c == -1)
		sign = s->frac > half ? 1 : s->frac == half ? 0 : -1;
	else
		sign = -1;
	if (sign > 0 || (sign == 0 && (Q & 1) != 0))
		Q++;
	int carry = 0;
	if (Q == pow10_u64[k]) {                   /* 9.99..9 -> 10.0..0 */
		Q = pow10_u64[k - 1];
		carry = 1;
	}
	*q_out = Q;
	*e10 = s->nd - 1 - s->p + carry;
	*cs = Q * pow10_u64[drop + carry];
}

/* True when the decimal cs / 10^p reads back (strtod) as x. */
static bool
reads_back(const struct scaled *s, uint64_t cs)
{
	u128 c = (u128)cs << s->q;
	bool below = c < s->P;
	u128 d = below ? s->P - c : c - s->P;
	u128 ten_p = pow10_u128(s->p);
	if (d >= ten_p)
		return false;
	u128 twice = below && s->low_gap ? 4 * d : 2 * d;
	return twice < ten_p || (twice == ten_p && (s->m & 1) == 0);
}

/* Writes digits of Q (exactly k of them) into d. */
static void
digits_of(uint64_t Q, int k, char *d)
{
	for (int i = k - 1; i >= 0; i--) {
		d[i] = (char)('0' + Q % 10);
		Q /= 10;
	}
}

/* The exact path; returns the length, or 0 when x is out of its range. */
static int
shortest_exact(char buf[NUMFMT_SHORTEST_LEN], double x)
{
	struct scaled s;
	if (!scale_exact(fabs(x), &s))
		return 0;
	for (int k = 15; k <= 17; k++) {
		uint64_t Q, cs;
		int e10;
		round_exact(&s, k, &Q, &e10, &cs);
		if (k == 17 || reads_back(&s, cs)) {
			char d[17];
			digits_of(Q, k, d);
			return g_text(buf, d, k, e10, x < 0);
		}
	}
	return 0; /* not reached: 17 digits always read back */
}
#else
static int
shortest_exact(char buf[NUMFMT_SHORTEST_LEN], double x)
{
	(void)buf;
	(void)x;
	return 0;
}
#endif

/* The printf path, for what the exact path leaves: the shortest of
 * %.15g, %.16g, %.17g that strtod() reads back as x, with one printf
 * instead of three: the digits of the shorter ones come from the 17
 * (g_at()).  And %.16g is tried first: the nearest 16-digit decimal is no
 * farther from x than the nearest 15-digit one (which is a 16-digit
 * decimal too), so when %.16g does not read back as x, neither does
 * %.15g -- unless x is a power of two, whose doubles below are twice as
 * dense as above: a 15-digit decimal above can then read back while a
 * nearer 16-digit one below does not. */
static int
shortest_printf(char buf[NUMFMT_SHORTEST_LEN], double x)
{
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
	int k = shortest_exact(buf, x);
	return k > 0 ? k : shortest_printf(buf, x);
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

const char *
numfmt_sig(char *buf, size_t n, double x, int sig)
{
	if (sig < 1)
		sig = 1;
	if (sig > 6)
		sig = 6;
	if (!isfinite(x)) {
		snprintf(buf, n, "\xe2\x80\x94");
		return buf;
	}
	int dec = x == 0.0 ? 0 : sig - 1 - (int)floor(log10(fabs(x)));
	if (dec < 0)
		dec = 0;
	if (numfmt_fixed(buf, n, x, dec) == 0 && n > 0)
		snprintf(buf, n, "\xe2\x80\x94");
	return buf;
}
