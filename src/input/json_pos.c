/* json_pos.c — a position-recording JSON scanner (see json_pos.h).
 *
 * It does not build values, only positions and flags.  It trusts cJSON to
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
	struct json_pos_entry *v;      /* entries in document order */
	size_t n, cap;                 /* used, allocated */
	struct json_pos_problem *p;    /* lexical problems in document order */
	size_t n_p, cap_p;
	unsigned all_flags;            /* OR of the entries' flags */
	bool complete;                 /* the first value was scanned whole */
};

struct jp_scan {
	const char *b;         /* the text */
	size_t len;            /* its length in bytes */
	size_t pos;            /* next byte to read */
	int line, col;         /* position of b[pos] */
	int depth;             /* open objects and arrays */
	bool failed;           /* malformed text met: stop */
	struct json_pos *jp;   /* the index being built */
};

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

static bool
jp_is_ws(char c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

static void
jp_skip_ws(struct jp_scan *s)
{
	while (s->pos < s->len && jp_is_ws(s->b[s->pos]))
		jp_adv(s);
}

static bool
jp_is_hex(char c)
{
	return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

/* Record a problem of the entry with index `entry` (which may not exist
 * yet: a key is scanned before its value's entry is added). */
static void
jp_problem(struct jp_scan *s, enum json_pos_problem_kind kind, size_t entry,
           int line, int col, unsigned char byte)
{
	struct json_pos *jp = s->jp;
	if (jp->n_p == jp->cap_p) {
		jp->cap_p = jp->cap_p ? 2 * jp->cap_p : 8;
		jp->p = xrealloc(jp->p, jp->cap_p * sizeof *jp->p);
	}
	jp->p[jp->n_p++] = (struct json_pos_problem){ kind, entry, line, col, byte };
}

/* Scan a string at s->pos (the opening quote).  Returns JSON_POS_BAD when
 * it holds a raw control character (the first one is recorded as a problem
 * of entry `entry`), plus `nul_flag` when it spells \u0000. */
static unsigned
jp_string(struct jp_scan *s, size_t entry, unsigned nul_flag)
{
	unsigned flags = 0;
	jp_adv(s); /* '"' */
	while (s->pos < s->len && s->b[s->pos] != '"') {
		unsigned char c = (unsigned char)s->b[s->pos];
		if (c < 0x20 && !(flags & JSON_POS_BAD)) {
			jp_problem(s, JSON_POS_CONTROL, entry, s->line, s->col, c);
			flags |= JSON_POS_BAD;
		}
		if (c != '\\') {
			jp_adv(s);
			continue;
		}
		jp_adv(s);
		if (s->pos >= s->len)
			break;
		if (s->b[s->pos] == 'u') {
			if (s->pos + 5 > s->len) {
				s->failed = true;
				return flags;
			}
			for (int i = 1; i <= 4; i++)
				if (!jp_is_hex(s->b[s->pos + i])) {
					s->failed = true;
					return flags;
				}
			if (memcmp(s->b + s->pos, "u0000", 5) == 0)
				flags |= nul_flag;
			for (int i = 0; i < 5; i++)
				jp_adv(s);
			continue;
		}
		if (strchr("\"\\/bfnrt", s->b[s->pos]) == NULL || s->b[s->pos] == '\0') {
			s->failed = true;
			return flags;
		}
		jp_adv(s);
	}
	if (!jp_at(s, '"')) {
		s->failed = true;
		return flags;
	}
	jp_adv(s);
	return flags;
}

/* True when b[0..n) is a number as JSON spells it:
 * -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?.  cJSON also takes "012",
 * "1." and "-.5" (STACK.md §7); a strict reader does not. */
static bool
jp_number_ok(const char *b, size_t n)
{
	size_t i = 0;
#define DIGIT(k) ((k) < n && b[k] >= '0' && b[k] <= '9')
	if (i < n && b[i] == '-')
		i++;
	if (i < n && b[i] == '0')
		i++;
	else if (DIGIT(i) && b[i] != '0')
		while (DIGIT(i))
			i++;
	else
		return false;
	if (i < n && b[i] == '.') {
		i++;
		if (!DIGIT(i))
			return false;
		while (DIGIT(i))
			i++;
	}
	if (i < n && (b[i] == 'e' || b[i] == 'E')) {
		i++;
		if (i < n && (b[i] == '+' || b[i] == '-'))
			i++;
		if (!DIGIT(i))
			return false;
		while (DIGIT(i))
			i++;
	}
#undef DIGIT
	return i == n;
}

static size_t
jp_add_entry(struct jp_scan *s, int key_line, int key_col, unsigned key_flags)
{
	struct json_pos *jp = s->jp;
	if (jp->n == jp->cap) {
		jp->cap = jp->cap ? 2 * jp->cap : 32;
		jp->v = xrealloc(jp->v, jp->cap * sizeof *jp->v);
	}
	struct json_pos_entry *e = &jp->v[jp->n];
	e->key_line = key_line;
	e->key_col = key_col;
	e->val_line = s->line;
	e->val_col = s->col;
	e->val_off = (uint32_t)s->pos;
	e->val_end = (uint32_t)s->pos;
	e->flags = (uint8_t)key_flags;
	return jp->n++;
}

static void jp_value(struct jp_scan *s, int key_line, int key_col, unsigned key_flags);

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
		/* The key belongs to the entry its value is about to get. */
		unsigned kf = jp_string(s, s->jp->n, JSON_POS_KEY_NUL);
		jp_skip_ws(s);
		if (s->failed || !jp_at(s, ':')) {
			s->failed = true;
			return;
		}
		jp_adv(s);
		jp_skip_ws(s);
		jp_value(s, kl, kc, kf);
		if (!jp_next(s, '}'))
			return;
	}
}

static void
jp_array(struct jp_scan *s)
{
	jp_adv(s); /* '[' */
	jp_skip_ws(s);
	if (jp_at(s, ']')) {
		jp_adv(s);
		return;
	}
	while (!s->failed) {
		jp_value(s, 0, 0, 0);
		if (!jp_next(s, ']'))
			return;
	}
}

static void
jp_value(struct jp_scan *s, int key_line, int key_col, unsigned key_flags)
{
	if (s->pos >= s->len) {
		s->failed = true;
		return;
	}
	size_t i = jp_add_entry(s, key_line, key_col, key_flags);
	char c = s->b[s->pos];
	unsigned flags = 0;
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
		flags = jp_string(s, i, JSON_POS_VAL_NUL);
	} else {
		/* number or literal: up to the next delimiter */
		size_t start = s->pos;
		int line = s->line, col = s->col;
		while (s->pos < s->len && strchr(",]} \t\r\n", s->b[s->pos]) == NULL)
			jp_adv(s);
		if (s->pos < s->len && s->b[s->pos] == '\0')
			s->failed = true;
		if ((c == '-' || (c >= '0' && c <= '9')) &&
		    !jp_number_ok(s->b + start, s->pos - start)) {
			jp_problem(s, JSON_POS_NUMBER, i, line, col, 0);
			flags = JSON_POS_BAD;
		}
	}
	struct json_pos_entry *e = &s->jp->v[i];
	e->val_end = (uint32_t)s->pos;
	e->flags |= (uint8_t)flags;
	s->jp->all_flags |= e->flags;
}

struct json_pos *
json_pos_alloc(const char *buf, size_t len)
{
	struct jp_scan s = { .b = buf, .len = len, .line = 1, .col = 1 };
	s.jp = xcalloc(1, sizeof *s.jp);
	if (len >= UINT32_MAX)
		return s.jp;   /* offsets would not fit: no positions */
	s.pos = text_bom(buf, len);
	jp_skip_ws(&s);
	jp_value(&s, 0, 0, 0);
	s.jp->complete = !s.failed;
	return s.jp;
}

void
json_pos_free(struct json_pos *jp)
{
	if (jp == NULL)
		return;
	free(jp->v);
	free(jp->p);
	free(jp);
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

int
json_pos_complete(const struct json_pos *jp)
{
	return jp->complete;
}

size_t
json_pos_n_problems(const struct json_pos *jp)
{
	return jp->n_p;
}

const struct json_pos_problem *
json_pos_problem_at(const struct json_pos *jp, size_t i)
{
	return i < jp->n_p ? &jp->p[i] : NULL;
}

unsigned
json_pos_all_flags(const struct json_pos *jp)
{
	return jp->all_flags;
}
