/* mission_io.c — strict mission-file parser and printer (see mission_io.h).
 *
 * cJSON judges the syntax and builds the tree; json_pos supplies the
 * positions cJSON does not keep; every check is driven by the row of the
 * field table (spec.h) that a key names, so ranges, types and spellings are
 * never restated here.
 */
#include "input/mission_io.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "input/json_pos.h"
#include "util/text.h"
#include "util/xalloc.h"

/* Longest path we build: a group name, a dot and a key (user keys may be
 * longer; they are cut, which only shortens a message). */
#define MIO_PATH_MAX 256

/* Everything one parse needs, passed instead of globals. */
struct mio {
	const char *file;                  /* name for diagnostics */
	const char *buf;                   /* the text */
	size_t len;                        /* its length */
	const struct json_pos *jp;         /* path -> positions */
	const char *const *chemistries;    /* known names, or NULL */
	struct diag *dg;                   /* where problems go */
	struct mission_spec *out;          /* the result */
};

/* ---- positions and wording ----------------------------------------------- */

/* Position of the key (key == true) or value of the nth item at path. */
static struct diag_loc
mio_loc(const struct mio *m, const char *path, int nth, bool key)
{
	struct diag_loc loc = { m->file, 0, 0 };
	const struct json_pos_entry *e = json_pos_find(m->jp, path, nth);
	if (e != NULL) {
		loc.line = key && e->key_line > 0 ? e->key_line : e->val_line;
		loc.col = key && e->key_line > 0 ? e->key_col : e->val_col;
	}
	return loc;
}

/* The source text of a value (a number literal, say) as printed in a
 * message, so "1e400" is quoted as the user wrote it. */
static void
mio_source(const struct mio *m, const char *path, int nth, char *buf, size_t n)
{
	const struct json_pos_entry *e = json_pos_find(m->jp, path, nth);
	size_t len = e != NULL ? e->val_end - e->val_off : 0;
	if (len >= n)
		len = n - 1;
	if (e != NULL)
		memcpy(buf, m->buf + e->val_off, len);
	buf[len] = '\0';
}

/* "a number", "an object", ... for "got ..." in type errors. */
static const char *
mio_type_name(const cJSON *item)
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

/* What a field of type t expects, for type errors. */
static const char *
mio_expected(enum spec_type t)
{
	switch (t) {
	case SPEC_NUM:
		return "a number";
	case SPEC_INT:
		return "an integer";
	case SPEC_BOOL:
		return "a boolean";
	case SPEC_STR:
	case SPEC_ENUM:
		return "a string";
	case SPEC_SPEED:
		return "a number or \"auto\"";
	case SPEC_DATE:
		return "a date string \"YYYY-MM-DD\"";
	}
	return "a value";
}

/* "a, b, c" from a NULL-terminated list. */
static void
mio_join(const char *const *list, char *buf, size_t n)
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

/* ---- value checks -------------------------------------------------------- */

/* True when s is a number as JSON spells it: -?(0|[1-9][0-9]*)(.[0-9]+)?
 * ([eE][+-]?[0-9]+)?.  cJSON also takes "012" and "1." (STACK.md §7); a
 * strict parser does not. */
static bool
mio_json_number_ok(const char *s)
{
	if (*s == '-')
		s++;
	if (*s == '0')
		s++;
	else if (*s >= '1' && *s <= '9')
		while (*s >= '0' && *s <= '9')
			s++;
	else
		return false;
	if (*s == '.') {
		if (!(*++s >= '0' && *s <= '9'))
			return false;
		while (*s >= '0' && *s <= '9')
			s++;
	}
	if (*s == 'e' || *s == 'E') {
		s++;
		if (*s == '+' || *s == '-')
			s++;
		if (!(*s >= '0' && *s <= '9'))
			return false;
		while (*s >= '0' && *s <= '9')
			s++;
	}
	return *s == '\0';
}

/* A finite number within the field's range, else a diagnostic. */
static bool
mio_check_number(const struct mio *m, const struct spec_field_info *f,
                 const cJSON *item, const char *path, int nth)
{
	struct diag_loc loc = mio_loc(m, path, nth, false);
	char src[64], range[128];
	double v = item->valuedouble;

	mio_source(m, path, nth, src, sizeof src);
	if (!mio_json_number_ok(src)) {
		char q[96];
		diag_quote(src, strlen(src), 32, q, sizeof q);
		diag_report(m->dg, DIAG_SYNTAX, &loc, NULL, " near %s (not a JSON number)", q);
		return false;
	}
	if (!isfinite(v)) {
		diag_report(m->dg, DIAG_OVERFLOW, &loc, path, ": %s", src);
		return false;
	}
	if (f->type == SPEC_INT && v != floor(v)) {
		diag_report(m->dg, DIAG_NOT_INTEGER, &loc, path, " (got %s)", src);
		return false;
	}
	bool low = (f->flags & SPEC_F_MIN_EXCL) ? !(v > f->min) : !(v >= f->min);
	if (low || !(v <= f->max)) {
		spec_range_text(f, range, sizeof range);
		diag_report(m->dg, DIAG_RANGE, &loc, path, ": %s (allowed %s)", src, range);
		return false;
	}
	return true;
}

/* A string that fits the struct and is valid UTF-8, else a diagnostic. */
static bool
mio_check_string(const struct mio *m, const char *s, const char *path, int nth)
{
	struct diag_loc loc = mio_loc(m, path, nth, false);
	size_t len = strlen(s);

	for (size_t i = 0; i < len;) {
		size_t seq = text_utf8_seq(s + i, len - i);
		if (seq == 0) {
			diag_report(m->dg, DIAG_BAD_UTF8, &loc, path,
			            " (byte 0x%02x at offset %zu)", (unsigned char)s[i], i);
			return false;
		}
		i += seq;
	}
	if (len >= SPEC_STR_MAX) {
		diag_report(m->dg, DIAG_TOO_LONG, &loc, path,
		            ": %zu bytes (at most %d)", len, SPEC_STR_MAX - 1);
		return false;
	}
	return true;
}

static bool
mio_leap(int y)
{
	return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

/* "YYYY-MM-DD" naming a real calendar day (year 1 to 9999). */
static bool
mio_date_ok(const char *s)
{
	static const int mdays[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
	if (strlen(s) != 10 || s[4] != '-' || s[7] != '-')
		return false;
	for (int i = 0; i < 10; i++)
		if (i != 4 && i != 7 && (s[i] < '0' || s[i] > '9'))
			return false;
	int y = atoi(s), mo = atoi(s + 5), d = atoi(s + 8);
	if (y < 1 || mo < 1 || mo > 12 || d < 1)
		return false;
	return d <= mdays[mo - 1] + (mo == 2 && mio_leap(y));
}

/* False (with a diagnostic) when the source text of the string value at
 * path holds what cJSON lets through or loses: an unescaped control
 * character (e.g. a literal TAB), or an escaped NUL (\u0000), at which
 * cJSON's C string silently ends. */
static bool
mio_string_source_ok(const struct mio *m, const char *path, int nth)
{
	const struct json_pos_entry *e = json_pos_find(m->jp, path, nth);
	if (e == NULL)
		return true;
	for (size_t i = e->val_off; i < e->val_end; i++) {
		unsigned char c = (unsigned char)m->buf[i];
		struct diag_loc loc = { m->file, 0, 0 };
		if (c < 0x20) {
			text_line_col(m->buf, m->len, i, &loc.line, &loc.col);
			diag_report(m->dg, DIAG_SYNTAX, &loc, NULL,
			            " near byte 0x%02x (control characters in strings "
			            "must be escaped)", c);
			return false;
		}
		if (c != '\\')
			continue;
		if (e->val_end - i >= 6 && memcmp(m->buf + i, "\\u0000", 6) == 0) {
			loc = mio_loc(m, path, nth, false);
			diag_report(m->dg, DIAG_NUL_IN_STRING, &loc, path, " (\\u0000)");
			return false;
		}
		i++; /* skip the escaped character, so JSON "\\u0000" stays text */
	}
	return true;
}

/* Check item against field f and store it in m->out.  Returns true when
 * the value was valid and stored. */
static bool
mio_field(struct mio *m, const struct spec_field_info *f, const cJSON *item,
          const char *path, int nth)
{
	struct diag_loc loc = mio_loc(m, path, nth, false);
	void *p = spec_member(m->out, f);
	char q[96], list[512];

	if (cJSON_IsString(item) && !mio_string_source_ok(m, path, nth))
		return false;

	/* The one type that accepts two JSON types. */
	if (f->type == SPEC_SPEED && cJSON_IsString(item)) {
		if (strcmp(item->valuestring, "auto") == 0) {
			m->out->v_forward_auto = true;
			return true;
		}
		diag_quote(item->valuestring, strlen(item->valuestring), 40, q, sizeof q);
		diag_report(m->dg, DIAG_TYPE, &loc, path, ": expected %s, got %s",
		            mio_expected(f->type), q);
		return false;
	}

	bool type_ok = false;
	switch (f->type) {
	case SPEC_NUM:
	case SPEC_INT:
	case SPEC_SPEED:
		type_ok = cJSON_IsNumber(item);
		break;
	case SPEC_BOOL:
		type_ok = cJSON_IsBool(item);
		break;
	case SPEC_STR:
	case SPEC_ENUM:
	case SPEC_DATE:
		type_ok = cJSON_IsString(item);
		break;
	}
	if (!type_ok) {
		diag_report(m->dg, DIAG_TYPE, &loc, path, ": expected %s, got %s",
		            mio_expected(f->type), mio_type_name(item));
		return false;
	}

	switch (f->type) {
	case SPEC_NUM:
	case SPEC_SPEED:
		if (!mio_check_number(m, f, item, path, nth))
			return false;
		*(double *)p = item->valuedouble;
		if (f->type == SPEC_SPEED)
			m->out->v_forward_auto = false;
		return true;
	case SPEC_INT:
		if (!mio_check_number(m, f, item, path, nth))
			return false;
		*(int *)p = (int)item->valuedouble; /* integral and in range */
		return true;
	case SPEC_BOOL:
		*(bool *)p = cJSON_IsTrue(item);
		return true;
	case SPEC_ENUM: {
		const char *s = item->valuestring;
		int v = spec_enum_index(f->enums, s);
		if (v < 0) {
			diag_quote(s, strlen(s), 40, q, sizeof q);
			mio_join(f->enums, list, sizeof list);
			const char *hint = NULL;
			for (size_t i = 0; f->enums[i] != NULL; i++)
				if (strcasecmp(f->enums[i], s) == 0)
					hint = f->enums[i];
			if (hint != NULL)
				diag_report(m->dg, DIAG_BAD_ENUM, &loc, path,
				            " %s (allowed: %s); did you mean \"%s\"?", q, list, hint);
			else
				diag_report(m->dg, DIAG_BAD_ENUM, &loc, path,
				            " %s (allowed: %s)", q, list);
			return false;
		}
		*(int *)p = v;
		return true;
	}
	case SPEC_STR:
	case SPEC_DATE: {
		const char *s = item->valuestring;
		if (!mio_check_string(m, s, path, nth))
			return false;
		if (f->type == SPEC_DATE && s[0] != '\0' && !mio_date_ok(s)) {
			diag_quote(s, strlen(s), 40, q, sizeof q);
			diag_report(m->dg, DIAG_BAD_DATE, &loc, path,
			            " %s (expected a calendar date YYYY-MM-DD)", q);
			return false;
		}
		if (f->id == SPECF_BATTERY_CHEMISTRY && m->chemistries != NULL &&
		    spec_enum_index(m->chemistries, s) < 0) {
			diag_quote(s, strlen(s), 40, q, sizeof q);
			mio_join(m->chemistries, list, sizeof list);
			diag_report(m->dg, DIAG_BAD_CHEMISTRY, &loc, path,
			            " %s (known: %s)", q, list);
			return false;
		}
		strcpy((char *)p, s); /* length checked above */
		return true;
	}
	}
	return false;
}

/* ---- objects ------------------------------------------------------------- */

/* How many earlier siblings of item carry the same key: the occurrence
 * index json_pos needs, and > 0 means item is a duplicate. */
static int
mio_nth(const cJSON *parent, const cJSON *item, const cJSON **first)
{
	int nth = 0;
	*first = NULL;
	for (const cJSON *c = parent->child; c != NULL && c != item; c = c->next) {
		if (strcmp(c->string, item->string) == 0) {
			if (nth == 0)
				*first = c;
			nth++;
		}
	}
	return nth;
}

/* "group.key", or "key" at the top level. */
static void
mio_path(const char *group, const char *key, char *buf, size_t n)
{
	if (group[0] != '\0')
		snprintf(buf, n, "%s.%s", group, key);
	else
		snprintf(buf, n, "%s", key);
}

static void mio_object(struct mio *m, const cJSON *obj, const char *group);

/* One member of an object at group ("" = top level). */
static void
mio_member(struct mio *m, const cJSON *parent, const cJSON *item,
           const char *group)
{
	char path[MIO_PATH_MAX], hint[MIO_PATH_MAX];
	const cJSON *first;
	int nth = mio_nth(parent, item, &first);
	const char *key = item->string;

	mio_path(group, key, path, sizeof path);
	if (nth > 0) {
		struct diag_loc loc = mio_loc(m, path, nth, true);
		struct diag_loc loc0 = mio_loc(m, path, 0, true);
		diag_report(m->dg, DIAG_DUPLICATE, &loc, path,
		            " (first given at %d:%d)", loc0.line, loc0.col);
		diag_report(m->dg, DIAG_FIRST_HERE, &loc0, path, NULL);
		return;
	}

	if (strcmp(key, "$schema") == 0 || (group[0] != '\0' && strcmp(key, "name") == 0)) {
		/* Editor and grouping conveniences; only the top-level $schema
		 * is looked at, and it must at least be a string. */
		if (group[0] == '\0' && !cJSON_IsString(item)) {
			struct diag_loc loc = mio_loc(m, path, 0, false);
			diag_report(m->dg, DIAG_TYPE, &loc, path, ": expected a string, got %s",
			            mio_type_name(item));
		}
		return;
	}

	if (group[0] == '\0' && spec_is_group(key)) {
		if (!cJSON_IsObject(item)) {
			struct diag_loc loc = mio_loc(m, path, 0, false);
			diag_report(m->dg, DIAG_TYPE, &loc, path, ": expected an object, got %s",
			            mio_type_name(item));
			return;
		}
		mio_object(m, item, key);
		return;
	}

	/* A dotted key would otherwise match a nested field's path. */
	const struct spec_field_info *f =
		strchr(key, '.') == NULL ? spec_field_by_path(path) : NULL;
	if (f == NULL) {
		struct diag_loc loc = mio_loc(m, path, 0, true);
		if (spec_suggest(path, hint, sizeof hint))
			diag_report(m->dg, DIAG_UNKNOWN, &loc, path, "; did you mean \"%s\"?", hint);
		else
			diag_report(m->dg, DIAG_UNKNOWN, &loc, path, NULL);
		return;
	}
	if (mio_field(m, f, item, path, 0))
		m->out->given[f->id] = true;
}

static void
mio_object(struct mio *m, const cJSON *obj, const char *group)
{
	for (const cJSON *c = obj->child; c != NULL; c = c->next)
		mio_member(m, obj, c, group);
}

/* ---- entry points -------------------------------------------------------- */

int
mission_io_parse(const char *file, const char *buf, size_t len,
                 const char *const *known_chemistries, struct diag *dg,
                 struct mission_spec *out)
{
	int errors_before = diag_n_errors(dg);
	struct mio m = { file, NULL, len, NULL, known_chemistries, dg, out };
	const char *end = NULL;
	char near[96];
	struct diag_loc loc = { file, 0, 0 };

	spec_defaults(out);

	/* cJSON wants a NUL inside the length it is given (STACK.md §7). */
	char *text = xmalloc(len + 1);
	memcpy(text, buf, len);
	text[len] = '\0';
	m.buf = text;

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
		return diag_n_errors(dg) - errors_before;
	}

	/* cJSON stops after the value when not asked to require the end; what
	 * follows must be whitespace only.  Checked here rather than by cJSON
	 * so the message can say what is wrong. */
	size_t off = (size_t)(end - text);
	while (off < len && strchr(" \t\r\n", text[off]) != NULL && text[off] != '\0')
		off++;
	if (off < len) {
		text_line_col(text, len, off, &loc.line, &loc.col);
		diag_quote(text + off, len - off, 16, near, sizeof near);
		diag_report(dg, DIAG_TRAILING, &loc, NULL, " near %s", near);
	}

	struct json_pos *jp = json_pos_alloc(text, len);
	m.jp = jp;
	if (!cJSON_IsObject(root)) {
		struct diag_loc rl = mio_loc(&m, "", 0, false);
		diag_report(dg, DIAG_TOP_LEVEL, &rl, NULL, ", got %s", mio_type_name(root));
	} else {
		mio_object(&m, root, "");
	}

	json_pos_free(jp);
	cJSON_Delete(root);
	free(text);
	return diag_n_errors(dg) - errors_before;
}

int
mission_io_load(const char *path, const char *const *known_chemistries,
                struct diag *dg, struct mission_spec *out)
{
	struct diag_loc loc = { path, 0, 0 };
	char reason[128];
	struct stat st;
	size_t len = 0, cap = 4096;
	char *buf;

	/* Regular files only (a FIFO would block, /dev/zero never ends), and at
	 * most MISSION_IO_MAX_BYTES, as the build reads them. */
	if (stat(path, &st) == 0 && (!S_ISREG(st.st_mode)
	    || (unsigned long long)st.st_size > MISSION_IO_MAX_BYTES)) {
		spec_defaults(out);
		if (!S_ISREG(st.st_mode))
			diag_report(dg, DIAG_IO, &loc, NULL, ": not a regular file");
		else
			diag_report(dg, DIAG_IO, &loc, NULL, ": file too large "
			    "(%lld bytes, limit %u)", (long long)st.st_size,
			    MISSION_IO_MAX_BYTES);
		return 1;
	}
	FILE *fp = fopen(path, "rb");
	if (fp == NULL) {
		int e = errno;
		spec_defaults(out);
		if (strerror_r(e, reason, sizeof reason) != 0)
			snprintf(reason, sizeof reason, "error %d", e);
		diag_report(dg, DIAG_IO, &loc, NULL, ": %s", reason);
		return 1;
	}
	buf = xmalloc(cap);
	for (;;) {
		size_t got = fread(buf + len, 1, cap - len, fp);
		len += got;
		if (got == 0)
			break;
		if (len > MISSION_IO_MAX_BYTES)
			break; /* grew while read: the parser sees a truncated file */
		if (len == cap)
			buf = xrealloc(buf, cap *= 2);
	}
	if (ferror(fp)) {
		int e = errno;
		fclose(fp);
		free(buf);
		spec_defaults(out);
		if (strerror_r(e, reason, sizeof reason) != 0)
			snprintf(reason, sizeof reason, "error %d", e);
		diag_report(dg, DIAG_IO, &loc, NULL, ": %s", reason);
		return 1;
	}
	fclose(fp);
	int n = mission_io_parse(path, buf, len, known_chemistries, dg, out);
	free(buf);
	return n;
}

/* ---- printing ------------------------------------------------------------ */

cJSON *
mission_io_to_json(const struct mission_spec *s)
{
	cJSON *root = cJSON_CreateObject();
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		const void *p = spec_member_const(s, f);
		const char *dot = strchr(f->path, '.');
		cJSON *obj = root, *v = NULL;

		if (dot != NULL) {
			char group[MIO_PATH_MAX];
			snprintf(group, sizeof group, "%.*s", (int)(dot - f->path), f->path);
			obj = cJSON_GetObjectItemCaseSensitive(root, group);
			if (obj == NULL)
				obj = cJSON_AddObjectToObject(root, group);
		}
		switch (f->type) {
		case SPEC_NUM:
			v = cJSON_CreateNumber(*(const double *)p);
			break;
		case SPEC_SPEED:
			v = s->v_forward_auto ? cJSON_CreateString("auto")
			                      : cJSON_CreateNumber(*(const double *)p);
			break;
		case SPEC_INT:
			v = cJSON_CreateNumber(*(const int *)p);
			break;
		case SPEC_BOOL:
			v = cJSON_CreateBool(*(const bool *)p);
			break;
		case SPEC_ENUM:
			v = cJSON_CreateString(f->enums[*(const int *)p]);
			break;
		case SPEC_STR:
		case SPEC_DATE:
			v = cJSON_CreateString((const char *)p);
			break;
		}
		cJSON_AddItemToObject(obj, dot != NULL ? dot + 1 : f->path, v);
	}
	return root;
}

