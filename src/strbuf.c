/* strbuf.c — growable byte buffer (see strbuf.h). */
#include "strbuf.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "xalloc.h"

void
strbuf_init(struct strbuf *sb)
{
	sb->data = NULL;
	sb->len = 0;
	sb->cap = 0;
}

void
strbuf_free(struct strbuf *sb)
{
	if (sb == NULL)
		return;
	free(sb->data);
	strbuf_init(sb);
}

void
strbuf_reset(struct strbuf *sb)
{
	sb->len = 0;
	if (sb->data != NULL)
		sb->data[0] = '\0';
}

/* Makes room for `extra` more bytes plus the NUL.  Doubling keeps appends
 * amortised O(1); the first allocation is small because most strings are. */
static void
reserve(struct strbuf *sb, size_t extra)
{
	size_t need = sb->len + extra + 1;
	if (need <= sb->cap)
		return;
	size_t cap = sb->cap ? sb->cap : 64;
	while (cap < need)
		cap *= 2;
	sb->data = xrealloc(sb->data, cap);
	sb->cap = cap;
	sb->data[sb->len] = '\0'; /* the first allocation holds garbage */
}

void
strbuf_append(struct strbuf *sb, const void *data, size_t n)
{
	reserve(sb, n);
	if (n > 0)
		memcpy(sb->data + sb->len, data, n);
	sb->len += n;
	sb->data[sb->len] = '\0';
}

void
strbuf_append_str(struct strbuf *sb, const char *s)
{
	strbuf_append(sb, s, strlen(s));
}

void
strbuf_append_char(struct strbuf *sb, char c)
{
	strbuf_append(sb, &c, 1);
}

void
strbuf_vprintf(struct strbuf *sb, const char *fmt, va_list ap)
{
	va_list ap2;
	va_copy(ap2, ap);
	/* Try in the space we have; a second pass is needed only when it did
	 * not fit, and then vsnprintf has told us exactly how much is needed. */
	reserve(sb, 0);
	size_t room = sb->cap - sb->len;
	int k = vsnprintf(sb->data + sb->len, room, fmt, ap);
	if (k < 0) {
		/* Only an invalid format can get here; keep the buffer intact. */
		sb->data[sb->len] = '\0';
		va_end(ap2);
		return;
	}
	if ((size_t)k >= room) {
		reserve(sb, (size_t)k);
		vsnprintf(sb->data + sb->len, (size_t)k + 1, fmt, ap2);
	}
	sb->len += (size_t)k;
	va_end(ap2);
}

void
strbuf_printf(struct strbuf *sb, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	strbuf_vprintf(sb, fmt, ap);
	va_end(ap);
}

const char *
strbuf_str(const struct strbuf *sb)
{
	return sb->data != NULL ? sb->data : "";
}

char *
strbuf_take(struct strbuf *sb, size_t *len)
{
	reserve(sb, 0);
	char *p = sb->data;
	if (len != NULL)
		*len = sb->len;
	strbuf_init(sb);
	return p;
}

void
str_copy(char *dst, size_t n, const char *src)
{
	size_t len = strlen(src);
	if (len >= n)
		len = n - 1;
	memcpy(dst, src, len);
	dst[len] = '\0';
}

/* ---- message formatting --------------------------------------------------- */

/* Where str_vformat() writes: dst[n], and how long the text would be. */
struct fmt_out {
	char *dst;
	size_t n;
	size_t len;
};

static void
out_bytes(struct fmt_out *o, const char *s, size_t k)
{
	size_t room = o->n > o->len + 1 ? o->n - o->len - 1 : 0;
	if (room > 0 && k > 0)
		memcpy(o->dst + o->len, s, k < room ? k : room);
	o->len += k;
}

/* x with `decimals` (0..3) digits after the point, as printf("%.*f") of
 * glibc writes it, into buf (32 bytes): the exact binary value rounded to
 * nearest, ties to even, and a '-' whenever the sign bit is set ("-0").
 * Returns the length, or 0 when that rounding is not certain here: not
 * finite, too large for the integer path, or within the product's
 * rounding error of a tie. */
static size_t
fixed_text(char *buf, double x, int decimals, bool plus)
{
	static const double scale[] = { 1.0, 10.0, 100.0, 1000.0 };
	double a = fabs(x);
	if (!(a < 1e12))
		return 0;
	double y = a * scale[decimals];
	double k = floor(y);
	/* y is a * 10^decimals within half an ulp; y - k is exact. */
	double frac = y - k;
	if (fabs(frac - 0.5) <= y * 0x1p-51 + 0x1p-1000)
		return 0;
	if (frac > 0.5)
		k += 1.0;
	unsigned long long q = (unsigned long long)k;
	char digit[24];
	int nd = 0;
	do {
		digit[nd++] = (char)('0' + (int)(q % 10u));
		q /= 10u;
	} while (q > 0u);
	while (nd < decimals + 1)
		digit[nd++] = '0';
	size_t len = 0;
	if (signbit(x))
		buf[len++] = '-';
	else if (plus)
		buf[len++] = '+';
	for (int i = nd - 1; i >= 0; i--) {
		buf[len++] = digit[i];
		if (i == decimals && decimals > 0)
			buf[len++] = '.';
	}
	return len;
}

int
str_vformat(char *dst, size_t n, const char *fmt, va_list ap)
{
	va_list again;
	va_copy(again, ap);
	struct fmt_out o = { dst, n, 0 };
	for (const char *f = fmt; *f != '\0'; f++) {
		const char *plain = f;
		while (*f != '\0' && *f != '%')
			f++;
		out_bytes(&o, plain, (size_t)(f - plain));
		if (*f == '\0')
			break;
		f++;
		char buf[32];
		if (*f == '%') {
			out_bytes(&o, "%", 1);
		} else if (*f == 's') {
			const char *s = va_arg(ap, const char *);
			if (s == NULL)
				goto slow;
			out_bytes(&o, s, strlen(s));
		} else if (*f == 'd') {
			long long v = va_arg(ap, int);
			unsigned long long u = v < 0 ? 0ull - (unsigned long long)v
			    : (unsigned long long)v;
			size_t k = sizeof buf;
			do {
				buf[--k] = (char)('0' + (int)(u % 10u));
				u /= 10u;
			} while (u > 0u);
			if (v < 0)
				buf[--k] = '-';
			out_bytes(&o, buf + k, sizeof buf - k);
		} else {
			bool plus = *f == '+';
			if (plus)
				f++;
			if (!(f[0] == '.' && f[1] >= '0' && f[1] <= '3' && f[2] == 'f'))
				goto slow;
			int decimals = f[1] - '0';
			f += 2;
			double x = va_arg(ap, double);
			size_t k = fixed_text(buf, x, decimals, plus);
			if (k == 0) {
				int w = snprintf(buf, sizeof buf, plus ? "%+.*f" : "%.*f",
				    decimals, x);
				if (w < 0 || (size_t)w >= sizeof buf)
					goto slow;
				k = (size_t)w;
			}
			out_bytes(&o, buf, k);
		}
	}
	if (n > 0)
		dst[o.len < n ? o.len : n - 1] = '\0';
	va_end(again);
	return (int)o.len;
slow:;
	int r = vsnprintf(dst, n, fmt, again);
	va_end(again);
	return r;
}

int
str_format(char *dst, size_t n, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	int r = str_vformat(dst, n, fmt, ap);
	va_end(ap);
	return r;
}
