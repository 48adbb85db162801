/* json_pos.c — a position-recording JSON scanner (see json_pos.h).
 *
 * It does not build values, only paths and positions.  It trusts cJSON to
 * have judged the syntax; where the text is malformed it simply stops.
 */
#include "input/json_pos.h"

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/text.h"
#include "util/xalloc.h"

/* Same limit as CJSON_NESTING_LIMIT: anything deeper was rejected anyway. */
#define JSON_POS_MAX_DEPTH 1000

struct json_pos {
	struct json_pos_entry *v;  /* entries in document order */
	size_t n;                  /* entries used */
	size_t cap;                /* entries allocated */
};

/* A growable NUL-terminated string (the current path, a decoded key). */
struct jp_str {
	char *s;
	size_t len;
	size_t cap;
};

struct jp_scan {
	const char *b;         /* the text */
	size_t len;            /* its length in bytes */
	size_t pos;            /* next byte to read */
	int line, col;         /* position of b[pos] */
	int depth;             /* open objects and arrays */
	bool failed;           /* malformed text met: stop */
	struct jp_str path;    /* path of the value being scanned */
	struct jp_str key;     /* scratch: the last decoded key */
	struct json_pos *jp;   /* the index being built */
};

static void
jp_str_put(struct jp_str *t, const char *s, size_t n)
{
	if (t->len + n + 1 > t->cap) {
		while (t->len + n + 1 > t->cap)
			t->cap = t->cap ? 2 * t->cap : 64;
		t->s = xrealloc(t->s, t->cap);
	}
	memcpy(t->s + t->len, s, n);
	t->len += n;
	t->s[t->len] = '\0';
}

static void
jp_str_truncate(struct jp_str *t, size_t len)
{
	t->len = len;
	if (t->s != NULL)
		t->s[len] = '\0';
}




/* Consume one byte, keeping line:col of the next one. */
static void
jp_adv(struct jp_scan *s)
{
	unsigned char ch = (unsigned char)s->b[s->pos++];
	if (ch == '\n') {
		s->line++;
		s->col = 1;
	} else if ((ch & 0xc0) != 0x80) {
		s->col++;
	}
}

static bool
jp_at(const struct jp_scan *s, char c)
{
	return s->pos < s->len && s->b[s->pos] == c;
}

static void
jp_skip_ws(struct jp_scan *s)
{
	while (s->pos < s->len && strchr(" \t\r\n", s->b[s->pos]) != NULL &&
	       s->b[s->pos] != '\0')
		jp_adv(s);
}

static int
jp_hex4(const char *p)
{
	int v = 0;
	for (int i = 0; i < 4; i++) {
		char c = p[i];
		v <<= 4;
		if (c >= '0' && c <= '9')
			v |= c - '0';
		else if (c >= 'a' && c <= 'f')
			v |= c - 'a' + 10;
		else if (c >= 'A' && c <= 'F')
			v |= c - 'A' + 10;
		else
			return -1;
	}
	return v;
}

/* Append code point cp to t as UTF-8. */
static void
jp_put_utf8(struct jp_str *t, unsigned long cp)
{
	char o[4];
	size_t n;
	if (cp < 0x80) {
		o[0] = (char)cp;
		n = 1;
	} else if (cp < 0x800) {
		o[0] = (char)(0xc0 | (cp >> 6));
		o[1] = (char)(0x80 | (cp & 0x3f));
		n = 2;
	} else if (cp < 0x10000) {
		o[0] = (char)(0xe0 | (cp >> 12));
		o[1] = (char)(0x80 | ((cp >> 6) & 0x3f));
		o[2] = (char)(0x80 | (cp & 0x3f));
		n = 3;
	} else {
		o[0] = (char)(0xf0 | (cp >> 18));
		o[1] = (char)(0x80 | ((cp >> 12) & 0x3f));
		o[2] = (char)(0x80 | ((cp >> 6) & 0x3f));
		o[3] = (char)(0x80 | (cp & 0x3f));
		n = 4;
	}
	jp_str_put(t, o, n);
}

/* Scan a string at s->pos (the opening quote).  When out is not NULL the
 * decoded text goes there, decoded as cJSON decodes it, so that a key's
 * path matches the cJSON item's ->string. */
static void
jp_string(struct jp_scan *s, struct jp_str *out)
{
	if (out != NULL)
		jp_str_truncate(out, 0);
	jp_adv(s); /* '"' */
	while (s->pos < s->len && s->b[s->pos] != '"') {
		char c = s->b[s->pos];
		if (c != '\\') {
			if (out != NULL)
				jp_str_put(out, &c, 1);
			jp_adv(s);
			continue;
		}
		jp_adv(s);
		if (s->pos >= s->len)
			break;
		c = s->b[s->pos];
		if (c == 'u') {
			int hi = s->pos + 5 <= s->len ? jp_hex4(s->b + s->pos + 1) : -1;
			if (hi < 0) {
				s->failed = true;
				return;
			}
			for (int i = 0; i < 5; i++)
				jp_adv(s);
			unsigned long cp = (unsigned long)hi;
			if (hi >= 0xd800 && hi <= 0xdbff && s->pos + 6 <= s->len &&
			    s->b[s->pos] == '\\' && s->b[s->pos + 1] == 'u') {
				int lo = jp_hex4(s->b + s->pos + 2);
				if (lo >= 0xdc00 && lo <= 0xdfff) {
					cp = 0x10000 + (((unsigned long)hi - 0xd800) << 10) +
					     ((unsigned long)lo - 0xdc00);
					for (int i = 0; i < 6; i++)
						jp_adv(s);
				}
			}
			if (out != NULL)
				jp_put_utf8(out, cp);
			continue;
		}
		const char *esc = strchr("\"\"\\\\//b\bf\fn\nr\rt\t", c);
		if (esc == NULL || c == '\0') {
			s->failed = true;
			return;
		}
		if (out != NULL)
			jp_str_put(out, esc + 1, 1);
		jp_adv(s);
	}
	if (!jp_at(s, '"')) {
		s->failed = true;
		return;
	}
	jp_adv(s);
}

static size_t
jp_add_entry(struct jp_scan *s, int key_line, int key_col)
{
	struct json_pos *jp = s->jp;
	if (jp->n == jp->cap) {
		jp->cap = jp->cap ? 2 * jp->cap : 32;
		jp->v = xrealloc(jp->v, jp->cap * sizeof *jp->v);
	}
	struct json_pos_entry *e = &jp->v[jp->n];
	e->path = xstrdup(s->path.s != NULL ? s->path.s : "");
	e->key_line = key_line;
	e->key_col = key_col;
	e->val_line = s->line;
	e->val_col = s->col;
	e->val_off = s->pos;
	e->val_end = s->pos;
	return jp->n++;
}

static void jp_value(struct jp_scan *s, int key_line, int key_col);

/* After a member or element: consume a comma and return true (another one
 * follows), or consume the closing bracket and return false.  Anything else
 * is malformed: mark it and return false. */
static bool
jp_next(struct jp_scan *s, char close)
{
	jp_skip_ws(s);
	if (jp_at(s, ',')) {
		jp_adv(s);
		jp_skip_ws(s);
		return true;
	}
	if (jp_at(s, close))
		jp_adv(s);
	else
		s->failed = true;
	return false;
}

static void
jp_object(struct jp_scan *s)
{
	size_t base = s->path.len;
	jp_adv(s); /* '{' */
	jp_skip_ws(s);
	if (jp_at(s, '}')) {
		jp_adv(s);
		return;
	}
	while (!s->failed) {
		if (!jp_at(s, '"')) {
			s->failed = true;
			return;
		}
		int kl = s->line, kc = s->col;
		jp_string(s, &s->key);
		jp_skip_ws(s);
		if (s->failed || !jp_at(s, ':')) {
			s->failed = true;
			return;
		}
		jp_adv(s);
		jp_skip_ws(s);
		if (base > 0)
			jp_str_put(&s->path, ".", 1);
		jp_str_put(&s->path, s->key.s != NULL ? s->key.s : "", s->key.len);
		jp_value(s, kl, kc);
		jp_str_truncate(&s->path, base);
		if (!jp_next(s, '}'))
			return;
	}
}

static void
jp_array(struct jp_scan *s)
{
	size_t base = s->path.len;
	jp_adv(s); /* '[' */
	jp_skip_ws(s);
	if (jp_at(s, ']')) {
		jp_adv(s);
		return;
	}
	for (size_t i = 0; !s->failed; i++) {
		char idx[32];
		int n = snprintf(idx, sizeof idx, "[%zu]", i);
		jp_str_put(&s->path, idx, (size_t)n);
		jp_value(s, 0, 0);
		jp_str_truncate(&s->path, base);
		if (!jp_next(s, ']'))
			return;
	}
}

static void
jp_value(struct jp_scan *s, int key_line, int key_col)
{
	if (s->pos >= s->len) {
		s->failed = true;
		return;
	}
	size_t i = jp_add_entry(s, key_line, key_col);
	char c = s->b[s->pos];
	if (c == '{' || c == '[') {
		if (++s->depth > JSON_POS_MAX_DEPTH) {
			s->failed = true;
			return;
		}
		if (c == '{')
			jp_object(s);
		else
			jp_array(s);
		s->depth--;
	} else if (c == '"') {
		jp_string(s, NULL);
	} else {
		/* number or literal: up to the next delimiter */
		while (s->pos < s->len && strchr(",]} \t\r\n", s->b[s->pos]) == NULL)
			jp_adv(s);
		if (s->pos < s->len && s->b[s->pos] == '\0')
			s->failed = true;
	}
	s->jp->v[i].val_end = s->pos;
}

struct json_pos *
json_pos_alloc(const char *buf, size_t len)
{
	struct jp_scan s = { .b = buf, .len = len, .line = 1, .col = 1 };
	s.jp = xcalloc(1, sizeof *s.jp);
	s.pos = text_bom(buf, len);
	jp_str_put(&s.path, "", 0);
	jp_skip_ws(&s);
	jp_value(&s, 0, 0);
	free(s.path.s);
	free(s.key.s);
	return s.jp;
}

void
json_pos_free(struct json_pos *jp)
{
	if (jp == NULL)
		return;
	for (size_t i = 0; i < jp->n; i++)
		free(jp->v[i].path);
	free(jp->v);
	free(jp);
}

const struct json_pos_entry *
json_pos_find(const struct json_pos *jp, const char *path, int nth)
{
	for (size_t i = 0; i < jp->n; i++)
		if (strcmp(jp->v[i].path, path) == 0 && nth-- == 0)
			return &jp->v[i];
	return NULL;
}

size_t
json_pos_count(const struct json_pos *jp)
{
	return jp->n;
}

const struct json_pos_entry *
json_pos_entry_at(const struct json_pos *jp, size_t i)
{
	return i < jp->n ? &jp->v[i] : NULL;
}
