/* strbuf.c — growable byte buffer (see strbuf.h). */
#include "util/strbuf.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/xalloc.h"

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
