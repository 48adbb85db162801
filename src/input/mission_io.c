/* mission_io.c — strict mission-file parser and printer (see mission_io.h).
 *
 * json_in reads the file (syntax, positions, repeated keys, string and
 * number hygiene); every check here is driven by the row of the field table
 * (spec.h) that a key names, so ranges, types and spellings are never
 * restated here.
 */
#include "input/mission_io.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <stdint.h>

#include "input/json_in.h"
#include "util/text.h"
#include "util/xalloc.h"

/* Longest path we build: a group name, a dot and a key (user keys may be
 * longer; they are cut, which only shortens a message). */
#define MIO_PATH_MAX 256

/* Everything one parse needs, passed instead of globals. */
struct mio {
	struct json_in *ji;                /* the file, positions, diagnostics */
	const char *const *chemistries;    /* known names, or NULL */
	struct mission_spec *out;          /* the result */
};

/* ---- wording ------------------------------------------------------------- */

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

/* ---- value checks -------------------------------------------------------- */

/* A finite number within the field's range, else a diagnostic.  The value
 * is quoted as the user wrote it ("1e400", not "inf"). */
static bool
mio_check_number(struct mio *m, const struct spec_field_info *f,
                 const cJSON *item, const char *path)
{
	char src[64], range[128];
	double v = item->valuedouble;

	if (!json_in_check_number(m->ji, item, path))
		return false;
	json_in_source(m->ji, item, src, sizeof src);
	if (f->type == SPEC_INT && v != floor(v)) {
		json_in_report(m->ji, DIAG_NOT_INTEGER, item, JSON_IN_VALUE, path,
		               " (got %s)", src);
		return false;
	}
	bool low = (f->flags & SPEC_F_MIN_EXCL) ? !(v > f->min) : !(v >= f->min);
	if (low || !(v <= f->max)) {
		spec_range_text(f, range, sizeof range);
		json_in_report(m->ji, DIAG_RANGE, item, JSON_IN_VALUE, path,
		               ": %s (allowed %s)", src, range);
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

/* Text fields reach the dossier, result.json, the index and file
 * metadata: no control character (an ESC or CR/LF once reached the
 * dossier raw) and no bidirectional control (text_is_control()), as the
 * cohort reader refuses them.  s is valid UTF-8 (checked before). */
static bool
mio_check_text(struct mio *m, const cJSON *item, const char *path)
{
	const char *s = item->valuestring;
	size_t len = strlen(s);
	for (size_t i = 0, seq; i < len; i += seq) {
		seq = text_utf8_seq(s + i, len - i);
		unsigned long cp = text_utf8_cp(s + i, seq);
		if (text_is_control(cp)) {
			json_in_report(m->ji, DIAG_CONTROL_CHAR, item, JSON_IN_VALUE, path,
			               " (U+%04lX at offset %zu)", cp, i);
			return false;
		}
	}
	return true;
}

/* Check item against field f and store it in m->out.  Returns true when
 * the value was valid and stored. */
static bool
mio_field(struct mio *m, const struct spec_field_info *f, const cJSON *item,
          const char *path)
{
	void *p = spec_member(m->out, f);
	char q[96], list[512];

	/* \u0000 (where cJSON's C string ends) and invalid UTF-8, whatever
	 * type the field wants. */
	if (cJSON_IsString(item) && !json_in_check_string(m->ji, item, path, SIZE_MAX, 0))
		return false;

	/* The one type that accepts two JSON types. */
	if (f->type == SPEC_SPEED && cJSON_IsString(item)) {
		if (strcmp(item->valuestring, "auto") == 0) {
			m->out->v_forward_auto = true;
			return true;
		}
		diag_quote(item->valuestring, strlen(item->valuestring), 40, q, sizeof q);
		json_in_report(m->ji, DIAG_TYPE, item, JSON_IN_VALUE, path,
		               ": expected %s, got %s", mio_expected(f->type), q);
		return false;
	}

	int mask = 0;
	switch (f->type) {
	case SPEC_NUM:
	case SPEC_INT:
	case SPEC_SPEED:
		mask = cJSON_Number;
		break;
	case SPEC_BOOL:
		mask = cJSON_True | cJSON_False;
		break;
	case SPEC_STR:
	case SPEC_ENUM:
	case SPEC_DATE:
		mask = cJSON_String;
		break;
	}
	if (!json_in_expect(m->ji, item, path, mask, mio_expected(f->type)))
		return false;

	switch (f->type) {
	case SPEC_NUM:
	case SPEC_SPEED:
		if (!mio_check_number(m, f, item, path))
			return false;
		*(double *)p = item->valuedouble;
		if (f->type == SPEC_SPEED)
			m->out->v_forward_auto = false;
		return true;
	case SPEC_INT:
		if (!mio_check_number(m, f, item, path))
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
			text_join(f->enums, list, sizeof list);
			const char *hint = NULL;
			for (size_t i = 0; f->enums[i] != NULL; i++)
				if (strcasecmp(f->enums[i], s) == 0)
					hint = f->enums[i];
			if (hint != NULL)
				json_in_report(m->ji, DIAG_BAD_ENUM, item, JSON_IN_VALUE, path,
				               " %s (allowed: %s); did you mean \"%s\"?", q, list, hint);
			else
				json_in_report(m->ji, DIAG_BAD_ENUM, item, JSON_IN_VALUE, path,
				               " %s (allowed: %s)", q, list);
			return false;
		}
		*(int *)p = v;
		return true;
	}
	case SPEC_STR:
	case SPEC_DATE: {
		const char *s = item->valuestring;
		if (!json_in_check_string(m->ji, item, path, SPEC_STR_MAX - 1, 0)
		    || !mio_check_text(m, item, path))
			return false;
		if (f->type == SPEC_DATE && s[0] != '\0' && !mio_date_ok(s)) {
			diag_quote(s, strlen(s), 40, q, sizeof q);
			json_in_report(m->ji, DIAG_BAD_DATE, item, JSON_IN_VALUE, path,
			               " %s (expected a calendar date YYYY-MM-DD)", q);
			return false;
		}
		if (f->id == SPECF_BATTERY_CHEMISTRY && m->chemistries != NULL &&
		    spec_enum_index(m->chemistries, s) < 0) {
			diag_quote(s, strlen(s), 40, q, sizeof q);
			text_join(m->chemistries, list, sizeof list);
			json_in_report(m->ji, DIAG_BAD_CHEMISTRY, item, JSON_IN_VALUE, path,
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

static void mio_object(struct mio *m, const cJSON *obj, const char *group);

/* One member of an object at group ("" = top level). */
static void
mio_member(struct mio *m, const cJSON *parent, const cJSON *item,
           const char *group)
{
	char path[MIO_PATH_MAX], hint[MIO_PATH_MAX];
	const char *key = item->string;

	json_in_path(path, sizeof path, group, key);
	if (!json_in_member(m->ji, parent, item, path))
		return;   /* a repeated key (reported) or a bad value */

	if (strcmp(key, "$schema") == 0 || (group[0] != '\0' && strcmp(key, "name") == 0)) {
		/* Editor and grouping conveniences; only the top-level $schema
		 * is looked at, and it must at least be a string. */
		if (group[0] == '\0')
			json_in_expect(m->ji, item, path, cJSON_String, "a string");
		return;
	}

	if (group[0] == '\0' && spec_is_group(key)) {
		if (json_in_expect(m->ji, item, path, cJSON_Object, "an object"))
			mio_object(m, item, key);
		return;
	}

	/* A dotted key would otherwise match a nested field's path. */
	const struct spec_field_info *f =
		strchr(key, '.') == NULL ? spec_field_by_path(path) : NULL;
	if (f == NULL) {
		/* The suggestion costs a search of the table: only for lines
		 * that will be shown (a file of 10^5 unknown keys stays fast). */
		if (json_in_showing(m->ji) && spec_suggest(path, hint, sizeof hint))
			json_in_report(m->ji, DIAG_UNKNOWN, item, JSON_IN_KEY, path,
			               "; did you mean \"%s\"?", hint);
		else
			json_in_report(m->ji, DIAG_UNKNOWN, item, JSON_IN_KEY, path, NULL);
		return;
	}
	if (mio_field(m, f, item, path))
		m->out->given[f->id] = true;
}

static void
mio_object(struct mio *m, const cJSON *obj, const char *group)
{
	for (const cJSON *c = obj->child; c != NULL; c = c->next)
		mio_member(m, obj, c, group);
}

/* ---- the essentials ------------------------------------------------------ */

/* Each essential (spec.h) the mission misses, as a "missing field" error at
 * its top-level object, naming what meets it. */
static void
mio_essentials(struct mio *m)
{
	for (int i = 0; i < SPEC_N_ESSENTIALS; i++) {
		const struct spec_essential *e = &spec_essentials[i];
		if (spec_essential_met(m->out, e))
			continue;
		char fields[256] = "";
		for (int k = 0; k < SPEC_ESSENTIAL_FIELDS && e->any_of[k] != SPEC_N_FIELDS; k++)
			snprintf(fields + strlen(fields), sizeof fields - strlen(fields), "%s%s",
			    k == 0 ? "" : ", ", spec_fields[e->any_of[k]].path);
		const char *path = spec_fields[e->any_of[0]].path;
		if (e->derived_by != SPEC_N_FIELDS)
			json_in_report(m->ji, DIAG_MISSING, json_in_root(m->ji), JSON_IN_VALUE, path,
			    "; a mission gives %s, or %s to derive it", fields,
			    spec_fields[e->derived_by].path);
		else
			json_in_report(m->ji, DIAG_MISSING, json_in_root(m->ji), JSON_IN_VALUE, path,
			    "; a mission needs %s: one of %s above 0", e->what, fields);
	}
}

/* ---- entry points -------------------------------------------------------- */

static bool
mio_blank(char c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/* The JSON values in b[0..n), counted up to just past cap without building
 * anything: each '{' and '[', each number or literal, each string that is
 * not a key (a key is a string followed by ':').  Exact for valid JSON; on
 * malformed text only an estimate, which is all the cap needs. */
static size_t
mio_count_values(const char *b, size_t n, size_t cap)
{
	size_t k = 0;
	for (size_t i = 0; i < n && k <= cap;) {
		char c = b[i];
		if (c == '"') {
			for (i++; i < n && b[i] != '"'; i++)
				i += b[i] == '\\';  /* an escape takes the next byte with it */
			size_t t = ++i;
			while (t < n && mio_blank(b[t]))
				t++;
			k += t >= n || b[t] != ':';
		} else if (c == '{' || c == '[' || c == '-' || (c >= '0' && c <= '9')
		    || c == 't' || c == 'f' || c == 'n') {
			k++;
			i++;
			if (c == '{' || c == '[')
				continue;
			while (i < n && ((b[i] >= '0' && b[i] <= '9') || (b[i] >= 'a' && b[i] <= 'z')
			    || (b[i] >= 'A' && b[i] <= 'Z') || b[i] == '.' || b[i] == '+' || b[i] == '-'))
				i++;
		} else {
			i++;
		}
	}
	return k;
}

static int
mio_parse(const char *file, const char *buf, size_t len,
          const char *const *known_chemistries, bool complete, struct diag *dg,
          struct mission_spec *out)
{
	int errors_before = diag_n_errors(dg);
	spec_defaults(out);
	/* The tree and its positions cost about 140 bytes per value, so a
	 * 3.8 MB array of zeros took 278 MB before any check could refuse it.
	 * Counting first bounds the memory of any mission file. */
	size_t n_values = mio_count_values(buf, len, MISSION_IO_MAX_VALUES);
	if (n_values > MISSION_IO_MAX_VALUES) {
		struct diag_loc loc = { file, 0, 0 };
		diag_report(dg, DIAG_TOO_MANY, &loc, NULL, ": more than %d JSON values "
		            "(a mission has about 100)", MISSION_IO_MAX_VALUES);
		return diag_n_errors(dg) - errors_before;
	}
	struct json_in *ji = json_in_parse(file, buf, len, dg);
	if (ji != NULL) {
		struct mio m = { ji, known_chemistries, out };
		mio_object(&m, json_in_root(ji), "");
		/* A mission that is wrong already needs no more errors. */
		if (complete && diag_n_errors(dg) == errors_before)
			mio_essentials(&m);
		json_in_free(ji);
	}
	return diag_n_errors(dg) - errors_before;
}

int
mission_io_parse(const char *file, const char *buf, size_t len,
                 const char *const *known_chemistries, struct diag *dg,
                 struct mission_spec *out)
{
	return mio_parse(file, buf, len, known_chemistries, false, dg, out);
}

int
mission_io_parse_mission(const char *file, const char *buf, size_t len,
                         const char *const *known_chemistries, struct diag *dg,
                         struct mission_spec *out)
{
	return mio_parse(file, buf, len, known_chemistries, true, dg, out);
}

int
mission_io_load(const char *path, const char *const *known_chemistries,
                struct diag *dg, struct mission_spec *out)
{
	unsigned char *buf;
	size_t len;
	/* Regular files only (a FIFO would block, /dev/zero never ends), and at
	 * most MISSION_IO_MAX_BYTES, as the build reads them. */
	if (json_in_read(path, MISSION_IO_MAX_BYTES, dg, &buf, &len) != 0) {
		spec_defaults(out);
		return 1;
	}
	int n = mission_io_parse_mission(path, (const char *)buf, len, known_chemistries, dg,
	    out);
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

