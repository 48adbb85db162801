/* json_in.c — the one JSON reader (see json_in.h).
 *
 * json_parse reads the text once into a tree of cJSON nodes that carry
 * their own positions and lexical flags; this file adds the checks and the
 * reporting.  Repeated keys are looked for only in the objects a loader
 * reads, one hash table per object.
 */
#include "input/json_in.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input/json_parse.h"
#include "util/file.h"
#include "util/hash.h"
#include "util/text.h"
#include "util/xalloc.h"

struct json_in {
	char *text;              /* the file's bytes, NUL added */
	size_t len;              /* bytes, without the NUL */
	struct json_doc *doc;    /* the tree, its positions and problems */
	const cJSON *root;       /* the tree's root */
	const char *file;        /* name in messages (the caller's) */
	struct diag *dg;         /* where messages go */
	struct ptrmap *indexed;  /* objects whose repeated keys are known */
	struct ptrmap *repeat;   /* a repeated member -> the first of its key */
	size_t key_probes;       /* probes of the per-object key tables */
	int n_errors;            /* errors reported through ji */
	int n_shown;             /* lines shown */
	int n_errors_shown;      /* errors among them */
	int n_hidden;            /* errors counted, not shown */
	bool last_shown;         /* the last error was shown (for its notes) */
};

static struct json_in *ji_parse_owned(const char *file, char *text, size_t len,
                                      struct diag *dg);

/* ---- reading ------------------------------------------------------------- */

/* The reason in file_read's message msg about path: its text starts
 * "PATH: " and may say "cannot open: "; a diagnostic says both already. */
static const char *
ji_read_reason(const char *path, const char *msg)
{
	size_t lp = strlen(path);
	if (strncmp(msg, path, lp) == 0 && strncmp(msg + lp, ": ", 2) == 0)
		msg += lp + 2;
	if (strncmp(msg, "cannot open: ", 13) == 0)
		msg += 13;
	return msg;
}

int
json_in_read(const char *path, size_t max_bytes, struct diag *dg,
             unsigned char **out, size_t *n)
{
	char msg[512];
	if (file_read(path, max_bytes, out, n, msg, sizeof msg) == 0)
		return 0;
	struct diag_loc loc = { path, 0, 0 };
	diag_report(dg, DIAG_IO, &loc, NULL, ": %s", ji_read_reason(path, msg));
	return -1;
}

int
json_in_read_named(struct json_in *ji, const cJSON *item, const char *jpath,
                   const char *path, size_t max_bytes, unsigned char **out, size_t *n)
{
	char msg[512];
	if (file_read(path, max_bytes, out, n, msg, sizeof msg) == 0)
		return 0;
	json_in_report(ji, DIAG_IO, item, JSON_IN_VALUE, jpath, ": %s: %s", path,
	               ji_read_reason(path, msg));
	return -1;
}

struct json_in *
json_in_load(const char *path, size_t max_bytes, struct diag *dg)
{
	unsigned char *buf;
	size_t n;
	if (json_in_read(path, max_bytes, dg, &buf, &n) != 0)
		return NULL;
	return ji_parse_owned(path, (char *)buf, n, dg);
}

/* ---- positions ----------------------------------------------------------- */

/* The node of item (a value of this tree), or NULL. */
static const struct json_node *
ji_node(const cJSON *item)
{
	return item != NULL ? json_node_of(item) : NULL;
}

/* The node's flags (JSON_PARSE_*). */
static unsigned
ji_flags(const cJSON *item)
{
	return item != NULL ? json_node_of(item)->flags : 0;
}

struct diag_loc
json_in_loc(struct json_in *ji, const cJSON *item, enum json_in_at at)
{
	struct diag_loc loc = { ji->file, 0, 0 };
	const struct json_node *e = at != JSON_IN_FILE ? ji_node(item) : NULL;
	if (e != NULL) {
		bool key = at == JSON_IN_KEY && e->key_line > 0;
		loc.line = key ? e->key_line : e->val_line;
		loc.col = key ? e->key_col : e->val_col;
	}
	return loc;
}

const cJSON *
json_in_find(const struct json_in *ji, const char *path)
{
	const cJSON *at = ji->root;
	char key[256];
	while (at != NULL && *path != '\0') {
		if (*path == '[') {
			char *end;
			unsigned long i = strtoul(path + 1, &end, 10);
			if (*end != ']' || i > INT32_MAX)
				return NULL;
			at = cJSON_IsArray(at) ? cJSON_GetArrayItem(at, (int)i) : NULL;
			path = end + 1;
		} else {
			if (*path == '.')
				path++;
			size_t k = strcspn(path, ".[");
			if (k >= sizeof key)
				return NULL;
			memcpy(key, path, k);
			key[k] = '\0';
			at = cJSON_IsObject(at) ? cJSON_GetObjectItemCaseSensitive(at, key) : NULL;
			path += k;
		}
	}
	return at;
}

void
json_in_source(struct json_in *ji, const cJSON *item, char *buf, size_t n)
{
	const struct json_node *e = ji_node(item);
	size_t k = e != NULL ? e->val_end - e->val_off : 0;
	if (k >= n)
		k = n - 1;
	if (e != NULL)
		memcpy(buf, ji->text + e->val_off, k);
	buf[k] = '\0';
}

/* ---- reporting ----------------------------------------------------------- */

bool
json_in_showing(const struct json_in *ji)
{
	return ji->n_shown < JSON_IN_MAX_SHOWN;
}

static void
ji_vreport(struct json_in *ji, enum diag_kind kind, const struct diag_loc *loc,
           const char *path, const char *fmt, va_list ap)
{
	bool error = diag_kind_severity(kind) == DIAG_ERROR;
	if (error)
		ji->n_errors++;
	if (error && !json_in_showing(ji)) {
		diag_count(ji->dg, kind);
		ji->n_hidden++;
		ji->last_shown = false;
		return;
	}
	if (!error && (!ji->last_shown || !json_in_showing(ji)))
		return;
	diag_vreport(ji->dg, kind, loc, path, fmt, ap);
	ji->n_shown++;
	if (error) {
		ji->n_errors_shown++;
		ji->last_shown = true;
	}
}

static void
ji_report_at(struct json_in *ji, enum diag_kind kind, const struct diag_loc *loc,
             const char *path, const char *fmt, ...)
	__attribute__((format(printf, 5, 6)));

static void
ji_report_at(struct json_in *ji, enum diag_kind kind, const struct diag_loc *loc,
             const char *path, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	ji_vreport(ji, kind, loc, path, fmt, ap);
	va_end(ap);
}

void
json_in_vreport(struct json_in *ji, enum diag_kind kind, const cJSON *item,
                enum json_in_at at, const char *path, const char *fmt, va_list ap)
{
	/* The position is looked up only for a line that will be shown. */
	struct diag_loc loc = { ji->file, 0, 0 };
	bool error = diag_kind_severity(kind) == DIAG_ERROR;
	if (json_in_showing(ji) && (error || ji->last_shown))
		loc = json_in_loc(ji, item, item != NULL ? at : JSON_IN_FILE);
	ji_vreport(ji, kind, &loc, path, fmt, ap);
}

void
json_in_report(struct json_in *ji, enum diag_kind kind, const cJSON *item,
               enum json_in_at at, const char *path, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	json_in_vreport(ji, kind, item, at, path, fmt, ap);
	va_end(ap);
}

/* Appends s to buf[*used..n - 1), cut short at the end. */
static void
ji_append(char *buf, size_t n, size_t *used, const char *s, size_t len)
{
	if (len > n - 1 - *used)
		len = n - 1 - *used;
	memcpy(buf + *used, s, len);
	*used += len;
}

void
json_in_path(char *buf, size_t n, const char *parent, const char *key)
{
	/* Copies, not snprintf: a loader writes one for every value it reads. */
	size_t used = 0;
	if (n == 0)
		return;
	if (parent != NULL && parent[0] != '\0') {
		ji_append(buf, n, &used, parent, strlen(parent));
		ji_append(buf, n, &used, ".", 1);
	}
	ji_append(buf, n, &used, key, strlen(key));
	buf[used] = '\0';
}

void
json_in_path_index(char *buf, size_t n, const char *parent, size_t i)
{
	snprintf(buf, n, "%s[%zu]", parent != NULL ? parent : "", i);
}

const char *
json_in_type_name(const cJSON *item)
{
	if (cJSON_IsNumber(item))
		return "a number";
	if (cJSON_IsString(item))
		return "a string";
	if (cJSON_IsBool(item))
		return "a boolean";
	if (cJSON_IsNull(item))
		return "null";
	if (cJSON_IsObject(item))
		return "an object";
	if (cJSON_IsArray(item))
		return "an array";
	return "an invalid value";
}

/* ---- parsing ------------------------------------------------------------- */

/* The lexical problems json_parse let through, in document order. */
static void
ji_report_problems(struct json_in *ji)
{
	for (size_t i = 0; i < json_doc_n_problems(ji->doc); i++) {
		const struct json_problem *p = json_doc_problem_at(ji->doc, i);
		struct diag_loc loc = { ji->file, p->line, p->col };
		if (p->kind == JSON_PROBLEM_CONTROL) {
			ji_report_at(ji, DIAG_SYNTAX, &loc, NULL, " near byte 0x%02x (control "
			             "characters in strings must be escaped)", p->byte);
		} else {
			const struct json_node *e = p->node;
			char q[96];
			diag_quote(ji->text + e->val_off, e->val_end - e->val_off, 32, q, sizeof q);
			ji_report_at(ji, DIAG_SYNTAX, &loc, NULL, " near %s (not a JSON number)", q);
		}
	}
}

/* json_in_parse() of text[0..len), a heap buffer with a NUL after it,
 * which the result owns (freed here on failure). */
static struct json_in *
ji_parse_owned(const char *file, char *text, size_t len, struct diag *dg)
{
	struct diag_loc loc = { file, 0, 0 };
	char near[96];
	size_t off;
	struct json_doc *doc = json_parse(text, len, &off);
	if (doc == NULL) {
		text_line_col(text, len, off, &loc.line, &loc.col);
		if (off >= len) {
			diag_report(dg, DIAG_SYNTAX, &loc, NULL, " near the end of the file");
		} else {
			diag_quote(text + off, len - off, 16, near, sizeof near);
			diag_report(dg, DIAG_SYNTAX, &loc, NULL, " near %s", near);
		}
		free(text);
		return NULL;
	}

	struct json_in *ji = xcalloc(1, sizeof *ji);
	ji->text = text;
	ji->len = len;
	ji->doc = doc;
	ji->root = json_doc_root(doc);
	ji->file = file;
	ji->dg = dg;

	/* What follows the value must be whitespace only. */
	off = json_doc_end(doc);
	while (off < len && strchr(" \t\r\n", text[off]) != NULL && text[off] != '\0')
		off++;
	if (off < len) {
		text_line_col(text, len, off, &loc.line, &loc.col);
		diag_quote(text + off, len - off, 16, near, sizeof near);
		ji_report_at(ji, DIAG_TRAILING, &loc, NULL, " near %s", near);
	}

	ji_report_problems(ji);
	if (!cJSON_IsObject(ji->root)) {
		json_in_report(ji, DIAG_TOP_LEVEL, ji->root, JSON_IN_VALUE, NULL, ", got %s",
		               json_in_type_name(ji->root));
		json_in_free(ji);
		return NULL;
	}
	return ji;
}

struct json_in *
json_in_parse(const char *file, const char *buf, size_t len, struct diag *dg)
{
	char *text = xmalloc(len + 1);
	memcpy(text, buf, len);
	text[len] = '\0';
	return ji_parse_owned(file, text, len, dg);
}

void
json_in_free(struct json_in *ji)
{
	if (ji == NULL)
		return;
	if (ji->n_hidden > 0) {
		struct diag_loc loc = { ji->file, 0, 0 };
		diag_report(ji->dg, DIAG_MORE, &loc, NULL, ": %d (%d shown above)",
		            ji->n_hidden, ji->n_errors_shown);
	}
	ptrmap_free(ji->indexed);
	ptrmap_free(ji->repeat);
	json_doc_free(ji->doc);
	free(ji->text);
	free(ji);
}

const cJSON *
json_in_root(const struct json_in *ji)
{
	return ji->root;
}

const char *
json_in_text(const struct json_in *ji, size_t *len)
{
	*len = ji->len;
	return ji->text;
}

const char *
json_in_file(const struct json_in *ji)
{
	return ji->file;
}

int
json_in_n_errors(const struct json_in *ji)
{
	return ji->n_errors;
}

size_t
json_in_probes(const struct json_in *ji)
{
	return (ji->indexed ? ptrmap_probes(ji->indexed) : 0) +
	       (ji->repeat ? ptrmap_probes(ji->repeat) : 0) + ji->key_probes;
}

/* ---- members ------------------------------------------------------------- */

/* Note every member of obj that repeats an earlier key, once per object:
 * one hash table over its keys, so 10^5 members cost 10^5 probes. */
static void
ji_index_members(struct json_in *ji, const cJSON *obj)
{
	if (ji->indexed == NULL) {
		ji->indexed = ptrmap_alloc(16);
		ji->repeat = ptrmap_alloc(16);
	}
	if (!ptrmap_put(ji->indexed, obj, 0, NULL))
		return;
	if (obj->child == NULL || obj->child->next == NULL)
		return;
	size_t n = 0;
	for (const cJSON *c = obj->child; c != NULL; c = c->next)
		n++;
	struct strmap *seen = strmap_alloc(n);
	for (const cJSON *c = obj->child; c != NULL; c = c->next) {
		size_t first;
		if (!strmap_put(seen, c->string, (size_t)(uintptr_t)c, &first))
			ptrmap_put(ji->repeat, c, first, NULL);
	}
	ji->key_probes += strmap_probes(seen);
	strmap_free(seen);
}

bool
json_in_member(struct json_in *ji, const cJSON *obj, const cJSON *item,
               const char *path)
{
	unsigned flags = ji_flags(item);
	if (flags & JSON_PARSE_BAD)
		return false;
	if (flags & JSON_PARSE_KEY_NUL) {
		json_in_report(ji, DIAG_NUL_IN_STRING, item, JSON_IN_KEY, path,
		               " (\\u0000 in the key)");
		return false;
	}
	ji_index_members(ji, obj);
	size_t first;
	if (!ptrmap_get(ji->repeat, item, &first))
		return true;
	if (json_in_showing(ji)) {
		const cJSON *f = (const cJSON *)(uintptr_t)first;
		struct diag_loc loc0 = json_in_loc(ji, f, JSON_IN_KEY);
		json_in_report(ji, DIAG_DUPLICATE, item, JSON_IN_KEY, path,
		               " (first given at %d:%d)", loc0.line, loc0.col);
		ji_report_at(ji, DIAG_FIRST_HERE, &loc0, path, NULL);
	} else {
		json_in_report(ji, DIAG_DUPLICATE, item, JSON_IN_KEY, path, NULL);
	}
	return false;
}

size_t
json_in_key_index(const char *key, const char *const *list, size_t n, size_t *guess)
{
	size_t i = *guess < n ? *guess : 0;
	for (size_t tried = 0; tried < n; tried++) {
		if (strcmp(key, list[i]) == 0) {
			*guess = i + 1;
			return i;
		}
		if (++i == n)
			i = 0;
	}
	return n;
}

int
json_in_check_keys(struct json_in *ji, const cJSON *obj, const char *path,
                   const char *const *allowed, unsigned flags)
{
	int before = ji->n_errors;
	char sub[512];
	size_t n_allowed = 0, guess = 0;
	while (allowed[n_allowed] != NULL)
		n_allowed++;
	ji_index_members(ji, obj);
	for (const cJSON *c = obj->child; c != NULL; c = c->next) {
		/* The member's path is written only for a message: a clean key
		 * (the rule, thousands of times in a catalogue) needs none. */
		size_t first;
		bool clean = !(ji_flags(c) & (JSON_PARSE_BAD | JSON_PARSE_KEY_NUL))
		    && !ptrmap_get(ji->repeat, c, &first);
		if (!clean) {
			json_in_path(sub, sizeof sub, path, c->string);
			if (!json_in_member(ji, obj, c, sub))
				continue;
		}
		if ((flags & JSON_IN_COMMENTS) && c->string[0] == '_')
			continue;
		if (json_in_key_index(c->string, allowed, n_allowed, &guess) < n_allowed)
			continue;
		json_in_path(sub, sizeof sub, path, c->string);
		const char *hint = json_in_showing(ji) ? text_nearest(c->string, allowed) : NULL;
		if (hint != NULL)
			json_in_report(ji, DIAG_UNKNOWN, c, JSON_IN_KEY, sub,
			               "; did you mean \"%s\"?", hint);
		else
			json_in_report(ji, DIAG_UNKNOWN, c, JSON_IN_KEY, sub, NULL);
	}
	return ji->n_errors - before;
}

/* ---- values -------------------------------------------------------------- */

bool
json_in_expect(struct json_in *ji, const cJSON *item, const char *path,
               int mask, const char *expected)
{
	if ((item->type & 0xff & mask) != 0)
		return true;
	json_in_report(ji, DIAG_TYPE, item, JSON_IN_VALUE, path, ": expected %s, got %s",
	               expected, json_in_type_name(item));
	return false;
}

bool
json_in_check_string(struct json_in *ji, const cJSON *item, const char *path,
                     size_t max_bytes, unsigned flags)
{
	unsigned ef = ji_flags(item);
	if (ef & JSON_PARSE_BAD)
		return false;
	if (ef & JSON_PARSE_VAL_NUL) {
		json_in_report(ji, DIAG_NUL_IN_STRING, item, JSON_IN_VALUE, path, " (\\u0000)");
		return false;
	}
	const char *s = item->valuestring;
	size_t len = strlen(s);
	for (size_t i = 0; i < len;) {
		if (s[i] >= 0x20 && s[i] < 0x7f) {
			i++;   /* printable ASCII: valid, and no control character */
			continue;
		}
		size_t seq = text_utf8_seq(s + i, len - i);
		if (seq == 0) {
			json_in_report(ji, DIAG_BAD_UTF8, item, JSON_IN_VALUE, path,
			               " (byte 0x%02x at offset %zu)", (unsigned char)s[i], i);
			return false;
		}
		unsigned char c = (unsigned char)s[i];
		if ((flags & JSON_IN_NO_CONTROL) && (c < 0x20 || c == 0x7f)) {
			json_in_report(ji, DIAG_CONTROL_CHAR, item, JSON_IN_VALUE, path,
			               " (byte 0x%02x at offset %zu)", (unsigned char)s[i], i);
			return false;
		}
		i += seq;
	}
	if (len > max_bytes) {
		json_in_report(ji, DIAG_TOO_LONG, item, JSON_IN_VALUE, path,
		               ": %zu bytes (at most %zu)", len, max_bytes);
		return false;
	}
	if ((flags & JSON_IN_NO_FORMULA) && text_is_formula(s)) {
		char q[96];
		diag_quote(s, len, 24, q, sizeof q);
		json_in_report(ji, DIAG_FORMULA, item, JSON_IN_VALUE, path,
		               ": %s (text may not start with =, +, - or @)", q);
		return false;
	}
	return true;
}

bool
json_in_check_number(struct json_in *ji, const cJSON *item, const char *path)
{
	if (ji_flags(item) & JSON_PARSE_BAD)
		return false;
	if (isfinite(item->valuedouble))
		return true;
	char src[64];
	json_in_source(ji, item, src, sizeof src);
	json_in_report(ji, DIAG_OVERFLOW, item, JSON_IN_VALUE, path, ": %s", src);
	return false;
}
