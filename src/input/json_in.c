/* json_in.c — the one JSON reader (see json_in.h).
 *
 * cJSON builds the tree; json_pos scans the same text for positions and
 * lexical problems.  The two meet lazily: the first time a position (or an
 * entry's flags) is asked for, one depth-first walk of the tree pairs node
 * i with entry i in a pointer-keyed hash table.  A file that reads cleanly
 * never builds that table.
 */
#include "input/json_in.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input/json_pos.h"
#include "util/file.h"
#include "util/hash.h"
#include "util/text.h"
#include "util/xalloc.h"

struct json_in {
	char *text;              /* the file's bytes, NUL added */
	size_t len;              /* bytes, without the NUL */
	cJSON *root;             /* the tree */
	struct json_pos *jp;     /* positions, problems, flags */
	const char *file;        /* name in messages (the caller's) */
	struct diag *dg;         /* where messages go */
	struct ptrmap *node;     /* tree node -> entry index; NULL until needed */
	bool node_ok;            /* node is built and complete */
	struct ptrmap *indexed;  /* objects whose repeated keys are known */
	struct ptrmap *repeat;   /* a repeated member -> the first of its key */
	size_t key_probes;       /* probes of the per-object key tables */
	int n_errors;            /* errors reported through ji */
	int n_shown;             /* lines shown */
	int n_errors_shown;      /* errors among them */
	int n_hidden;            /* errors counted, not shown */
	bool last_shown;         /* the last error was shown (for its notes) */
};

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
	struct json_in *ji = json_in_parse(path, (const char *)buf, n, dg);
	free(buf);
	return ji;
}

/* ---- positions ----------------------------------------------------------- */

/* Number node i of the tree in document order (pre-order). */
static void
ji_number(struct ptrmap *m, const cJSON *node, size_t *i)
{
	ptrmap_put(m, node, (*i)++, NULL);
	for (const cJSON *c = node->child; c != NULL; c = c->next)
		ji_number(m, c, i);
}

/* The entry of item, or NULL when positions are unknown. */
static const struct json_pos_entry *
ji_entry(struct json_in *ji, const cJSON *item)
{
	if (ji->node == NULL) {
		size_t n = 0;
		ji->node = ptrmap_alloc(json_pos_count(ji->jp));
		ji_number(ji->node, ji->root, &n);
		/* The pairing holds only when both saw the same values. */
		ji->node_ok = json_pos_complete(ji->jp) && n == json_pos_count(ji->jp);
	}
	size_t i;
	if (!ji->node_ok || item == NULL || !ptrmap_get(ji->node, item, &i))
		return NULL;
	return json_pos_entry_at(ji->jp, i);
}

/* The entry's flags; no table is built for a file without any flag. */
static unsigned
ji_flags(struct json_in *ji, const cJSON *item)
{
	if (json_pos_all_flags(ji->jp) == 0)
		return 0;
	const struct json_pos_entry *e = ji_entry(ji, item);
	return e != NULL ? e->flags : 0;
}

struct diag_loc
json_in_loc(struct json_in *ji, const cJSON *item, enum json_in_at at)
{
	struct diag_loc loc = { ji->file, 0, 0 };
	const struct json_pos_entry *e = at != JSON_IN_FILE ? ji_entry(ji, item) : NULL;
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
	const struct json_pos_entry *e = ji_entry(ji, item);
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

void
json_in_path(char *buf, size_t n, const char *parent, const char *key)
{
	if (parent == NULL || parent[0] == '\0')
		snprintf(buf, n, "%s", key);
	else
		snprintf(buf, n, "%s.%s", parent, key);
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

/* The lexical problems json_pos found, in document order. */
static void
ji_report_problems(struct json_in *ji)
{
	for (size_t i = 0; i < json_pos_n_problems(ji->jp); i++) {
		const struct json_pos_problem *p = json_pos_problem_at(ji->jp, i);
		struct diag_loc loc = { ji->file, p->line, p->col };
		if (p->kind == JSON_POS_CONTROL) {
			ji_report_at(ji, DIAG_SYNTAX, &loc, NULL, " near byte 0x%02x (control "
			             "characters in strings must be escaped)", p->byte);
		} else {
			const struct json_pos_entry *e = json_pos_entry_at(ji->jp, p->entry);
			char q[96];
			diag_quote(ji->text + e->val_off, e->val_end - e->val_off, 32, q, sizeof q);
			ji_report_at(ji, DIAG_SYNTAX, &loc, NULL, " near %s (not a JSON number)", q);
		}
	}
}

struct json_in *
json_in_parse(const char *file, const char *buf, size_t len, struct diag *dg)
{
	struct diag_loc loc = { file, 0, 0 };
	const char *end = NULL;
	char near[96];

	/* cJSON wants a NUL inside the length it is given (STACK.md §7). */
	char *text = xmalloc(len + 1);
	memcpy(text, buf, len);
	text[len] = '\0';
	cJSON *root = cJSON_ParseWithLengthOpts(text, len + 1, &end, 0);
	if (root == NULL) {
		size_t off = end != NULL ? (size_t)(end - text) : 0;
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
	ji->root = root;
	ji->file = file;
	ji->dg = dg;

	/* cJSON stops after the value when not asked to require the end; what
	 * follows must be whitespace only.  Checked here rather than by cJSON
	 * so the message can say what is wrong. */
	size_t off = (size_t)(end - text);
	while (off < len && strchr(" \t\r\n", text[off]) != NULL && text[off] != '\0')
		off++;
	if (off < len) {
		text_line_col(text, len, off, &loc.line, &loc.col);
		diag_quote(text + off, len - off, 16, near, sizeof near);
		ji_report_at(ji, DIAG_TRAILING, &loc, NULL, " near %s", near);
	}

	ji->jp = json_pos_alloc(text, len);
	ji_report_problems(ji);
	if (!cJSON_IsObject(root)) {
		json_in_report(ji, DIAG_TOP_LEVEL, root, JSON_IN_VALUE, NULL, ", got %s",
		               json_in_type_name(root));
		json_in_free(ji);
		return NULL;
	}
	return ji;
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
	ptrmap_free(ji->node);
	ptrmap_free(ji->indexed);
	ptrmap_free(ji->repeat);
	json_pos_free(ji->jp);
	cJSON_Delete(ji->root);
	free(ji->text);
	free(ji);
}

const cJSON *
json_in_root(const struct json_in *ji)
{
	return ji->root;
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
	return (ji->node ? ptrmap_probes(ji->node) : 0) +
	       (ji->indexed ? ptrmap_probes(ji->indexed) : 0) +
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
	unsigned flags = ji_flags(ji, item);
	if (flags & JSON_POS_BAD)
		return false;
	if (flags & JSON_POS_KEY_NUL) {
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

int
json_in_check_keys(struct json_in *ji, const cJSON *obj, const char *path,
                   const char *const *allowed, unsigned flags)
{
	int before = ji->n_errors;
	char sub[512];
	ji_index_members(ji, obj);
	for (const cJSON *c = obj->child; c != NULL; c = c->next) {
		/* The member's path is written only for a message: a clean key
		 * (the rule, thousands of times in a catalogue) needs none. */
		size_t first;
		bool clean = !(ji_flags(ji, c) & (JSON_POS_BAD | JSON_POS_KEY_NUL))
		    && !ptrmap_get(ji->repeat, c, &first);
		if (!clean) {
			json_in_path(sub, sizeof sub, path, c->string);
			if (!json_in_member(ji, obj, c, sub))
				continue;
		}
		if ((flags & JSON_IN_COMMENTS) && c->string[0] == '_')
			continue;
		bool known = false;
		for (size_t i = 0; !known && allowed[i] != NULL; i++)
			known = strcmp(c->string, allowed[i]) == 0;
		if (known)
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
	unsigned ef = ji_flags(ji, item);
	if (ef & JSON_POS_BAD)
		return false;
	if (ef & JSON_POS_VAL_NUL) {
		json_in_report(ji, DIAG_NUL_IN_STRING, item, JSON_IN_VALUE, path, " (\\u0000)");
		return false;
	}
	const char *s = item->valuestring;
	size_t len = strlen(s);
	for (size_t i = 0; i < len;) {
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
	if (ji_flags(ji, item) & JSON_POS_BAD)
		return false;
	if (isfinite(item->valuedouble))
		return true;
	char src[64];
	json_in_source(ji, item, src, sizeof src);
	json_in_report(ji, DIAG_OVERFLOW, item, JSON_IN_VALUE, path, ": %s", src);
	return false;
}
