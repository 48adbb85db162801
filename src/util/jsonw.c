/* jsonw.c — the one JSON writer (see jsonw.h).
 *
 * A growing buffer, a stack of open containers and the JSON path of the
 * innermost one, kept only so that a fault can be named.
 */
#include "util/jsonw.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/numfmt.h"
#include "util/text.h"
#include "util/xalloc.h"

/* ---- output bytes ---------------------------------------------------------- */

static void
put(struct jsonw *w, const char *s, size_t n)
{
	if (w->len + n + 1 > w->cap) {
		size_t cap = w->cap ? w->cap : 4096;
		while (w->len + n + 1 > cap)
			cap *= 2;
		w->buf = xrealloc(w->buf, cap);
		w->cap = cap;
	}
	memcpy(w->buf + w->len, s, n);
	w->len += n;
	w->buf[w->len] = '\0';
}

static void
puts_(struct jsonw *w, const char *s)
{
	put(w, s, strlen(s));
}

static void
newline(struct jsonw *w, int depth)
{
	static const char spaces[] =
		"                                                                ";
	_Static_assert(sizeof spaces - 1 == 2 * JSONW_MAX_DEPTH, "indent table");
	put(w, "\n", 1);
	put(w, spaces, (size_t)(2 * depth));
}

/* ---- paths and faults ------------------------------------------------------ */

/* Appends to w->path the step to the value now being written: ".key" in
 * an object, "[i]" in an array.  Cut short silently: it is for a message. */
static void
path_step(struct jsonw *w, const char *key)
{
	char step[80];
	if (key)
		snprintf(step, sizeof step, ".%s", key);
	else
		snprintf(step, sizeof step, "[%d]", w->st[w->depth - 1].n - 1);
	size_t room = sizeof w->path - 1 - w->path_len;
	size_t n = strlen(step);
	if (n > room)
		n = room;
	memcpy(w->path + w->path_len, step, n);
	w->path_len += n;
	w->path[w->path_len] = '\0';
}

void
jsonw_fault(struct jsonw *w, const char *key)
{
	if (w->faults.n_invalid++ > 0)
		return;
	size_t keep = w->path_len;
	if (w->depth > 0)
		path_step(w, key);
	const char *p = w->path[0] == '.' ? w->path + 1 : w->path;
	snprintf(w->faults.first_path, sizeof w->faults.first_path, "%s", p);
	w->path_len = keep;
	w->path[keep] = '\0';
}

/* ---- structure ------------------------------------------------------------- */

static void string_text(struct jsonw *w, const char *s, size_t max);

/* Separator, line break and key before a value. */
static void
begin(struct jsonw *w, const char *key)
{
	if (w->depth == 0)
		return;
	struct jsonw_frame *f = &w->st[w->depth - 1];
	assert(f->array == (key == NULL));
	if (f->n > 0)
		put(w, ",", 1);
	if (f->packed && f->n % JSONW_PACK != 0)
		put(w, " ", 1);
	else
		newline(w, w->depth);
	f->n++;
	if (key) {
		string_text(w, key, strlen(key));
		put(w, ": ", 2);
	}
}

static void
open_container(struct jsonw *w, const char *key, bool array, bool packed)
{
	assert(w->depth < JSONW_MAX_DEPTH);
	begin(w, key);
	size_t before = w->path_len;
	if (w->depth > 0)
		path_step(w, key);
	w->st[w->depth++] = (struct jsonw_frame){ array, packed, 0, before };
	put(w, array ? "[" : "{", 1);
}

void
jsonw_init(struct jsonw *w)
{
	memset(w, 0, sizeof *w);
}

void
jsonw_object(struct jsonw *w, const char *key)
{
	open_container(w, key, false, false);
}

void
jsonw_array(struct jsonw *w, const char *key)
{
	open_container(w, key, true, false);
}

void
jsonw_array_packed(struct jsonw *w, const char *key)
{
	open_container(w, key, true, true);
}

void
jsonw_end(struct jsonw *w)
{
	assert(w->depth > 0);
	struct jsonw_frame *f = &w->st[--w->depth];
	if (f->n > 0)
		newline(w, w->depth);
	put(w, f->array ? "]" : "}", 1);
	w->path_len = f->path_len;
	w->path[w->path_len] = '\0';
}

/* ---- scalars --------------------------------------------------------------- */

/* s (at most max bytes, stopping at a NUL) as a JSON string. */
static void
string_text(struct jsonw *w, const char *s, size_t max)
{
	const unsigned char *p = (const unsigned char *)s;
	size_t n = strnlen(s, max);
	put(w, "\"", 1);
	for (size_t i = 0; i < n;) {
		/* A run of printable ASCII needs no escape: one copy for it. */
		size_t run = i;
		while (run < n && p[run] >= 0x20 && p[run] < 0x80 && p[run] != '"' && p[run] != '\\')
			run++;
		if (run > i) {
			put(w, s + i, run - i);
			i = run;
			continue;
		}
		unsigned c = p[i];
		char esc[8];
		if (c == '"' || c == '\\') {
			esc[0] = '\\';
			esc[1] = (char)c;
			put(w, esc, 2);
			i++;
			continue;
		}
		if (c < 0x20) {
			switch (c) {
			case '\b': puts_(w, "\\b"); break;
			case '\f': puts_(w, "\\f"); break;
			case '\n': puts_(w, "\\n"); break;
			case '\r': puts_(w, "\\r"); break;
			case '\t': puts_(w, "\\t"); break;
			default:
				snprintf(esc, sizeof esc, "\\u%04x", c);
				puts_(w, esc);
			}
			i++;
			continue;
		}
		/* UTF-8 passes through whole; a byte that starts no valid
		 * sequence becomes U+FFFD. */
		size_t len = text_utf8_seq(s + i, n - i);
		if (len > 0) {
			put(w, s + i, len);
			i += len;
		} else {
			puts_(w, "\xEF\xBF\xBD");
			i++;
		}
	}
	put(w, "\"", 1);
}

void
jsonw_string_n(struct jsonw *w, const char *key, const char *s, size_t max)
{
	begin(w, key);
	string_text(w, s, max);
}

void
jsonw_string(struct jsonw *w, const char *key, const char *s)
{
	jsonw_string_n(w, key, s != NULL ? s : "", s != NULL ? strlen(s) : 0);
}

void
jsonw_null(struct jsonw *w, const char *key)
{
	begin(w, key);
	puts_(w, "null");
}

void
jsonw_bool(struct jsonw *w, const char *key, bool b)
{
	begin(w, key);
	puts_(w, b ? "true" : "false");
}

void
jsonw_int(struct jsonw *w, const char *key, long long v)
{
	char t[24];
	begin(w, key);
	snprintf(t, sizeof t, "%lld", v);
	puts_(w, t);
}

void
jsonw_number(struct jsonw *w, const char *key, double x)
{
	char t[NUMFMT_SHORTEST_LEN];
	begin(w, key);
	if (!isfinite(x)) {
		jsonw_fault(w, key);
		puts_(w, "null");
		return;
	}
	numfmt_shortest(t, x);
	puts_(w, t);
}

/* ---- trees and the whole text ---------------------------------------------- */

void
jsonw_tree(struct jsonw *w, const char *key, const cJSON *item)
{
	const cJSON *c;
	switch (item->type & 0xff) {
	case cJSON_Object:
		jsonw_object(w, key);
		cJSON_ArrayForEach(c, item)
			jsonw_tree(w, c->string, c);
		jsonw_end(w);
		break;
	case cJSON_Array:
		jsonw_array(w, key);
		cJSON_ArrayForEach(c, item)
			jsonw_tree(w, NULL, c);
		jsonw_end(w);
		break;
	case cJSON_String:
		jsonw_string(w, key, item->valuestring);
		break;
	case cJSON_Number:
		jsonw_number(w, key, item->valuedouble);
		break;
	case cJSON_True:
	case cJSON_False:
		jsonw_bool(w, key, cJSON_IsTrue(item));
		break;
	case cJSON_NULL:
		jsonw_null(w, key);
		break;
	default:
		/* cJSON_Raw: text nobody checked has no place in an output. */
		jsonw_null(w, key);
		jsonw_fault(w, key);
		break;
	}
}

char *
jsonw_finish(struct jsonw *w, struct jsonw_faults *faults)
{
	assert(w->depth == 0);
	put(w, "\n", 1);
	if (faults != NULL)
		*faults = w->faults;
	return w->buf;
}

char *
jsonw_print(const cJSON *root, struct jsonw_faults *faults)
{
	struct jsonw w;
	jsonw_init(&w);
	jsonw_tree(&w, NULL, root);
	return jsonw_finish(&w, faults);
}
