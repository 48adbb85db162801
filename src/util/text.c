/* text.c — UTF-8, positions in text and edit distance (see text.h). */
#include "util/text.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "util/xalloc.h"

size_t
text_utf8_seq(const char *s, size_t left)
{
	const unsigned char *u = (const unsigned char *)s;
	size_t n;
	unsigned long cp;

	if (left == 0)
		return 0;
	if (u[0] < 0x80)
		return 1;
	if (u[0] >= 0xc2 && u[0] <= 0xdf) {
		n = 2;
		cp = u[0] & 0x1fu;
	} else if (u[0] >= 0xe0 && u[0] <= 0xef) {
		n = 3;
		cp = u[0] & 0x0fu;
	} else if (u[0] >= 0xf0 && u[0] <= 0xf4) {
		n = 4;
		cp = u[0] & 0x07u;
	} else {
		return 0; /* continuation byte, 0xc0/0xc1 or 0xf5.. */
	}
	if (left < n)
		return 0;
	for (size_t i = 1; i < n; i++) {
		if ((u[i] & 0xc0) != 0x80)
			return 0;
		cp = (cp << 6) | (u[i] & 0x3fu);
	}
	if ((n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000))
		return 0; /* overlong */
	if ((cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff)
		return 0; /* surrogate or beyond Unicode */
	return n;
}

unsigned long
text_utf8_cp(const char *s, size_t seq)
{
	const unsigned char *u = (const unsigned char *)s;
	if (seq <= 1)
		return u[0];
	/* The lead byte keeps 7 - seq bits (5, 4 or 3), each continuation 6. */
	unsigned long cp = u[0] & (0x7fu >> seq);
	for (size_t i = 1; i < seq; i++)
		cp = (cp << 6) | (u[i] & 0x3fu);
	return cp;
}

int
text_is_control(unsigned long cp)
{
	return cp < 0x20 || (cp >= 0x7f && cp <= 0x9f) || cp == 0x061c
	    || cp == 0x200e || cp == 0x200f || (cp >= 0x202a && cp <= 0x202e)
	    || (cp >= 0x2066 && cp <= 0x2069);
}

int
text_hex_digit(unsigned char c)
{
	if (c >= '0' && c <= '9')
		return c - '0';
	if (c >= 'a' && c <= 'f')
		return c - 'a' + 10;
	if (c >= 'A' && c <= 'F')
		return c - 'A' + 10;
	return -1;
}

size_t
text_bom(const char *b, size_t len)
{
	return len >= 3 && memcmp(b, "\xef\xbb\xbf", 3) == 0 ? 3 : 0;
}

void
text_line_col(const char *buf, size_t len, size_t off, int *line, int *col)
{
	int l = 1, c = 1;
	if (off > len)
		off = len;
	for (size_t i = off >= text_bom(buf, len) ? text_bom(buf, len) : 0; i < off; i++) {
		unsigned char ch = (unsigned char)buf[i];
		if (ch == '\n') {
			l++;
			c = 1;
		} else if ((ch & 0xc0) != 0x80) {
			c++;
		}
	}
	*line = l;
	*col = c;
}

/* Edit distance between a and b ignoring case, where insertions,
 * deletions, substitutions and swaps of two neighbours cost 1 (optimal
 * string alignment).  Strings longer than TEXT_DISTANCE_MAX count as far. */
size_t
text_distance(const char *a, const char *b)
{
	size_t na = strlen(a), nb = strlen(b);
	size_t d[TEXT_DISTANCE_MAX + 1][TEXT_DISTANCE_MAX + 1];

	if (na > TEXT_DISTANCE_MAX || nb > TEXT_DISTANCE_MAX)
		return (size_t)-1 / 2;
	for (size_t i = 0; i <= na; i++)
		d[i][0] = i;
	for (size_t j = 0; j <= nb; j++)
		d[0][j] = j;
	for (size_t i = 1; i <= na; i++) {
		for (size_t j = 1; j <= nb; j++) {
			int ca = tolower((unsigned char)a[i - 1]);
			int cb = tolower((unsigned char)b[j - 1]);
			size_t best = d[i - 1][j - 1] + (ca != cb);
			if (d[i - 1][j] + 1 < best)
				best = d[i - 1][j] + 1;
			if (d[i][j - 1] + 1 < best)
				best = d[i][j - 1] + 1;
			if (i > 1 && j > 1 &&
			    ca == tolower((unsigned char)b[j - 2]) &&
			    tolower((unsigned char)a[i - 2]) == cb &&
			    d[i - 2][j - 2] + 1 < best)
				best = d[i - 2][j - 2] + 1;
			d[i][j] = best;
		}
	}
	return d[na][nb];
}

size_t
text_typo_limit(size_t len)
{
	return len / 3 > 3 ? 3 : (len / 3 < 1 ? 1 : len / 3);
}

const char *
text_nearest(const char *word, const char *const *list)
{
	size_t best_d = text_typo_limit(strlen(word)) + 1;
	const char *best = NULL;
	for (; *list != NULL; list++) {
		size_t d = text_distance(word, *list);
		if (d < best_d) {
			best_d = d;
			best = *list;
		}
	}
	return best;
}

void
text_join(const char *const *list, char *buf, size_t n)
{
	size_t o = 0;
	buf[0] = '\0';
	for (size_t i = 0; list[i] != NULL && o < n; i++) {
		int w = snprintf(buf + o, n - o, "%s%s", i > 0 ? ", " : "", list[i]);
		if (w < 0)
			break;
		o += (size_t)w;
	}
}

char *
text_utf8_copy(const char *s)
{
	size_t len = strlen(s), o = 0;
	char *out = xmalloc(3 * len + 1);   /* a bad byte becomes 3 bytes */
	for (size_t i = 0; i < len;) {
		size_t seq = text_utf8_seq(s + i, len - i);
		if (seq == 0) {
			memcpy(out + o, "\xef\xbf\xbd", 3);
			o += 3;
			i++;
			continue;
		}
		memcpy(out + o, s + i, seq);
		o += seq;
		i += seq;
	}
	out[o] = '\0';
	return out;
}

int
text_is_formula(const char *s)
{
	return s[0] != '\0' && strchr("=+-@", s[0]) != NULL;
}

void
text_errf(char *err, size_t errlen, const char *fmt, ...)
{
	if (err == NULL || errlen == 0)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(err, errlen, fmt, ap);
	va_end(ap);
}
