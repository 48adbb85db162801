/* strbuf.h — a growable byte buffer for building text (JSON, CSV, messages).
 *
 * Any module may include this.  A struct strbuf is a plain value: set it up
 * with strbuf_init() (or = STRBUF_INIT), release it with strbuf_free().  The
 * bytes are always NUL-terminated once anything has been appended, so
 * strbuf_str() is a valid C string; embedded NUL bytes are allowed (use len).
 * Growth goes through xrealloc, so an append never fails: out of memory exits
 * with status 3 (see xalloc.h).
 */
#ifndef AEROEVAL_STRBUF_H
#define AEROEVAL_STRBUF_H

#include <stdarg.h>
#include <stddef.h>

struct strbuf {
	char *data;  /* heap bytes, NUL-terminated after them; NULL until first use */
	size_t len;  /* bytes in use, not counting the terminating NUL */
	size_t cap;  /* bytes allocated (always > len once data != NULL) */
};

#define STRBUF_INIT { NULL, 0, 0 }

/* Makes sb an empty buffer.  Allocates nothing. */
void strbuf_init(struct strbuf *sb);

/* Releases the bytes and leaves sb empty (re-usable).  NULL is a no-op. */
void strbuf_free(struct strbuf *sb);

/* Empties sb but keeps its allocation, for re-use in a loop. */
void strbuf_reset(struct strbuf *sb);

/* Appends n bytes from data (which may contain NUL and may not alias sb). */
void strbuf_append(struct strbuf *sb, const void *data, size_t n);

/* Appends the C string s (without its NUL). */
void strbuf_append_str(struct strbuf *sb, const char *s);

/* Copies the C string src into dst[n] (n > 0), truncated to n - 1 bytes
 * as snprintf(dst, n, "%s", src) would, without parsing a format. */
void str_copy(char *dst, size_t n, const char *src);

/* Appends one byte. */
void strbuf_append_char(struct strbuf *sb, char c);

/* Appends printf-formatted text.  Uses the C locale's number format as long
 * as the program never calls setlocale (aeroeval does not). */
void strbuf_printf(struct strbuf *sb, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

/* Same as strbuf_printf with a va_list (consumed). */
void strbuf_vprintf(struct strbuf *sb, const char *fmt, va_list ap)
	__attribute__((format(printf, 2, 0)));

/* The contents as a C string; "" for an empty buffer.  Borrowed: valid until
 * the next change to sb. */
const char *strbuf_str(const struct strbuf *sb);

/* Hands the bytes to the caller and leaves sb empty.  The result is never
 * NULL, is NUL-terminated, and the caller frees it with free().  *len (if
 * len != NULL) receives the byte count without the NUL. */
char *strbuf_take(struct strbuf *sb, size_t *len);

#endif
