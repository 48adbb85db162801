/* catalog.c — load and validate the real-parts catalogue (see catalog.h).
 *
 * One field table per category drives parsing, the type and range checks, the
 * unit conversion and the `usable` flag, so the four categories share one
 * parser.  Errors accumulate (every error of every file is reported) and the
 * load fails at the end if there was any.
 */
#include "core/catalog.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "util/sha256.h"
#include "util/xalloc.h"

#define G_TO_KG 1e-3
#define MOHM_TO_OHM 1e-3
#define MAH_TO_AH 1e-3
#define IN_TO_M 0.0254            /* exact, by definition of the inch */

const char *const catalog_default_chemistries[] = {
	"LiPo", "LiHV", "Li-ion NCA", "Li-ion NMC", "Solid State", "Li-S",
	"LiPo_standard", "LiPo_highvoltage", "LiPo_premium", "LiPo_consumer",
	"LiPo_enterprise", "LiPo_agricultural", NULL,
};

static const char *const materials[] = { "plastic", "carbon", "wood", "composite", NULL };
static const char *const confidences[] = { "high", "medium", "low", NULL };

/* ---- field tables -------------------------------------------------------- */

enum kind {
	K_STR,            /* string into a char[size] */
	K_NUM,            /* double, times scale */
	K_INT,            /* integral number into an int */
	K_BOOL,           /* true/false into a bool */
	K_TRIBOOL,        /* true/false/null into an int 1/0/-1 */
	K_LIST,           /* the `uncertain` array of field names */
	K_ANY,            /* accepted, not stored (format version 2 keys the
	                     engine does not read) */
};

enum check {
	C_NONE,
	C_POS,            /* number > 0 */
	C_ID,             /* lowercase slug */
	C_NONEMPTY,       /* non-empty string */
	C_CONF,           /* high/medium/low */
	C_CHEM,           /* one of the known chemistries */
	C_MATERIAL,       /* one of `materials` */
};

struct field {
	const char *key;  /* JSON key */
	enum kind kind;
	size_t off;       /* offset of the destination in the struct */
	size_t size;      /* K_STR: buffer size */
	double scale;     /* K_NUM: JSON unit -> stored unit */
	enum check check;
	bool nullable;    /* null means "unknown" */
	bool optional;    /* the key may be absent */
	bool needed;      /* must be known for the entry to be `usable` */
};

/* "hi must be >= lo" pairs, checked when both are known. */
struct order { const char *lo, *hi; };

#define STR(T, k, chk) { #k, K_STR, offsetof(T, k), sizeof(((T *)0)->k), 1, chk, false, false, false }
#define COMMON(T)                                                      \
	STR(T, id, C_ID), STR(T, manufacturer, C_NONEMPTY),                \
	STR(T, part_number, C_NONEMPTY), STR(T, source, C_NONEMPTY),       \
	STR(T, confidence, C_CONF),                                        \
	{ "uncertain", K_LIST, offsetof(T, uncertain), CATALOG_UNCERTAIN_MAX, 1, C_NONE, false, false, false }, \
	{ "price_usd", K_NUM, offsetof(T, price_usd), 0, 1, C_POS, true, false, false }, \
	{ "price_date", K_STR, offsetof(T, price_date), sizeof(((T *)0)->price_date), 1, C_NONE, true, true, false }
#define ANY(k) { k, K_ANY, 0, 0, 1, C_NONE, true, true, false }
/* A number field: JSON key, destination, scale, needed for `usable`. */
#define NUM(T, k, dst, sc, need) { k, K_NUM, offsetof(T, dst), 0, sc, C_POS, true, false, need }
#define INT(T, k, need) { #k, K_INT, offsetof(T, k), 0, 1, C_POS, true, false, need }

static const struct field motor_fields[] = {
	COMMON(struct catalog_motor),
	NUM(struct catalog_motor, "kv_rpm_per_v", kv_rpm_per_v, 1, true),
	NUM(struct catalog_motor, "mass_g", mass_kg, G_TO_KG, true),
	NUM(struct catalog_motor, "max_current_a", max_current_a, 1, true),
	NUM(struct catalog_motor, "max_power_w", max_power_w, 1, false),
	INT(struct catalog_motor, cells_min, false),
	INT(struct catalog_motor, cells_max, false),
	NUM(struct catalog_motor, "prop_min_in", prop_min_in, 1, false),
	NUM(struct catalog_motor, "prop_max_in", prop_max_in, 1, false),
	NUM(struct catalog_motor, "resistance_mohm", resistance_ohm, MOHM_TO_OHM, false),
	{ "integrated", K_BOOL, offsetof(struct catalog_motor, integrated), 0, 1, C_NONE, false, false, false },
	/* Present only for integrated systems; enforced in check_integrated(). */
	{ "integrated_prop_in", K_NUM, offsetof(struct catalog_motor, integrated_prop_in), 0, 1, C_POS, true, true, false },
	{ "no_load_current_a", K_NUM, offsetof(struct catalog_motor, no_load_current_a), 0, 1, C_POS, true, true, false },
	{ "integrated_pitch_in", K_NUM, offsetof(struct catalog_motor, integrated_pitch_in), 0, 1, C_POS, true, true, false },
	{ "integrated_esc_current_a", K_NUM, offsetof(struct catalog_motor, integrated_esc_current_a), 0, 1, C_POS, true, true, false },
	ANY("max_current_basis"), ANY("no_load_voltage_v"), ANY("stator"), ANY("max_thrust_g"),
};

static const struct field prop_fields[] = {
	COMMON(struct catalog_prop),
	NUM(struct catalog_prop, "diameter_in", diameter_in, 1, true),
	NUM(struct catalog_prop, "pitch_in", pitch_in, 1, true),
	INT(struct catalog_prop, blades, false),
	{ "material", K_STR, offsetof(struct catalog_prop, material), sizeof(((struct catalog_prop *)0)->material), 1, C_MATERIAL, true, false, false },
	NUM(struct catalog_prop, "mass_g", mass_kg, G_TO_KG, true),
	NUM(struct catalog_prop, "max_rpm", max_rpm, 1, false),
	{ "folding", K_TRIBOOL, offsetof(struct catalog_prop, folding), 0, 1, C_NONE, true, false, false },
	{ "ct_static", K_NUM, offsetof(struct catalog_prop, ct_static), 0, 1, C_POS, true, true, false },
	{ "cp_static", K_NUM, offsetof(struct catalog_prop, cp_static), 0, 1, C_POS, true, true, false },
	{ "part_number_ccw", K_STR, offsetof(struct catalog_prop, part_number_ccw), sizeof(((struct catalog_prop *)0)->part_number_ccw), 1, C_NONE, true, true, false },
	ANY("coeff_source"),
};

static const struct field battery_fields[] = {
	COMMON(struct catalog_battery),
	{ "chemistry", K_STR, offsetof(struct catalog_battery, chemistry), sizeof(((struct catalog_battery *)0)->chemistry), 1, C_CHEM, true, false, true },
	INT(struct catalog_battery, cells_series, true),
	NUM(struct catalog_battery, "capacity_mah", capacity_ah, MAH_TO_AH, true),
	NUM(struct catalog_battery, "mass_g", mass_kg, G_TO_KG, true),
	NUM(struct catalog_battery, "continuous_c", continuous_c, 1, true),
	NUM(struct catalog_battery, "burst_c", burst_c, 1, false),
	NUM(struct catalog_battery, "nominal_voltage_v", nominal_voltage_v, 1, false),
	NUM(struct catalog_battery, "energy_wh", energy_wh, 1, false),
	ANY("cells_parallel"), ANY("connector"), ANY("smart"),
};

static const struct field esc_fields[] = {
	COMMON(struct catalog_esc),
	NUM(struct catalog_esc, "continuous_current_a", continuous_current_a, 1, true),
	NUM(struct catalog_esc, "burst_current_a", burst_current_a, 1, false),
	INT(struct catalog_esc, cells_min, false),
	INT(struct catalog_esc, cells_max, false),
	NUM(struct catalog_esc, "mass_g", mass_kg, G_TO_KG, true),
	INT(struct catalog_esc, channels, true),
	ANY("burst_seconds"),
};

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))
#define MAX_FIELDS 32

static const struct order motor_orders[] = {
	{ "cells_min", "cells_max" }, { "prop_min_in", "prop_max_in" },
};
static const struct order battery_orders[] = { { "continuous_c", "burst_c" } };
static const struct order esc_orders[] = {
	{ "cells_min", "cells_max" }, { "continuous_current_a", "burst_current_a" },
};

enum cat { CAT_MOTOR, CAT_PROP, CAT_BATTERY, CAT_ESC, CAT_N };

struct category {
	const char *file;            /* file name in the catalogue directory */
	const char *key;             /* top-level array key */
	const struct field *fields;
	size_t n_fields;
	const struct order *orders;
	size_t n_orders;
	size_t size;                 /* sizeof the entry struct */
	size_t off_id, off_usable;
};

#define CATEGORY(file, key, T, f, o, no) \
	{ file, key, f, N_OF(f), o, no, sizeof(T), offsetof(T, id), offsetof(T, usable) }

static const struct category categories[CAT_N] = {
	CATEGORY("motors.json", "motors", struct catalog_motor, motor_fields, motor_orders, N_OF(motor_orders)),
	CATEGORY("propellers.json", "propellers", struct catalog_prop, prop_fields, NULL, 0),
	CATEGORY("batteries.json", "batteries", struct catalog_battery, battery_fields, battery_orders, N_OF(battery_orders)),
	CATEGORY("escs.json", "escs", struct catalog_esc, esc_fields, esc_orders, N_OF(esc_orders)),
};

_Static_assert(N_OF(motor_fields) <= MAX_FIELDS && N_OF(prop_fields) <= MAX_FIELDS &&
               N_OF(battery_fields) <= MAX_FIELDS && N_OF(esc_fields) <= MAX_FIELDS,
               "raise MAX_FIELDS");

struct catalog {
	void *items[CAT_N];          /* arrays of the entry structs */
	size_t n[CAT_N];
	size_t *prop_order;          /* propeller indices by diameter */
	char sha256[SHA256_HEX_LEN]; /* fingerprint of the bytes parsed */
};

/* ---- diagnostics --------------------------------------------------------- */

/* Where the parser is, for messages. */
struct ctx {
	FILE *err;
	int n_errors;
	const char *const *chems;
	const char *path;            /* current file */
	const struct category *cat;
	size_t index;                /* current entry */
	const char *entry_id;        /* its id if readable, else NULL */
	struct sha256_ctx sha;       /* over every file as read (catalog_sha256) */
};

static void report_file(struct ctx *cx, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
static void report(struct ctx *cx, const char *key, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

/* A whole-file error: "PATH: error: MESSAGE". */
static void
report_file(struct ctx *cx, const char *fmt, ...)
{
	va_list ap;
	cx->n_errors++;
	if (cx->err == NULL)
		return;
	fprintf(cx->err, "%s: error: ", cx->path);
	va_start(ap, fmt);
	vfprintf(cx->err, fmt, ap);
	va_end(ap);
	fputc('\n', cx->err);
}

/* An entry error: PATH: error: motors[3] "id".KEY: MESSAGE (key may be NULL). */
static void
report(struct ctx *cx, const char *key, const char *fmt, ...)
{
	va_list ap;
	cx->n_errors++;
	if (cx->err == NULL)
		return;
	fprintf(cx->err, "%s: error: %s[%zu]", cx->path, cx->cat->key, cx->index);
	if (cx->entry_id != NULL)
		fprintf(cx->err, " \"%s\"", cx->entry_id);
	if (key != NULL)
		fprintf(cx->err, ".%s", key);
	fputs(": ", cx->err);
	va_start(ap, fmt);
	vfprintf(cx->err, fmt, ap);
	va_end(ap);
	fputc('\n', cx->err);
}

/* ---- helpers -------------------------------------------------------------- */

static bool
in_list(const char *s, const char *const *list)
{
	for (; *list != NULL; list++)
		if (strcmp(s, *list) == 0)
			return true;
	return false;
}

/* The field named key, trying fields[hint] first: the entries of a file
 * list their keys in the table's order, so passing the index after the
 * last match finds most keys with one comparison instead of a scan. */
static const struct field *
find_field_from(const struct category *cat, const char *key, size_t hint)
{
	if (hint < cat->n_fields && strcmp(cat->fields[hint].key, key) == 0)
		return &cat->fields[hint];
	for (size_t i = 0; i < cat->n_fields; i++)
		if (strcmp(cat->fields[i].key, key) == 0)
			return &cat->fields[i];
	return NULL;
}

static const struct field *
find_field(const struct category *cat, const char *key)
{
	return find_field_from(cat, key, 0);
}

/* Levenshtein distance, capped: enough to suggest a key for a typo. */
static size_t
edit_distance(const char *a, const char *b)
{
	size_t la = strlen(a), lb = strlen(b);
	size_t row[64];
	if (la >= N_OF(row) || lb >= N_OF(row))
		return SIZE_MAX;
	for (size_t j = 0; j <= lb; j++)
		row[j] = j;
	for (size_t i = 1; i <= la; i++) {
		size_t diag = row[0];
		row[0] = i;
		for (size_t j = 1; j <= lb; j++) {
			size_t up = row[j];
			size_t best = diag + (a[i - 1] != b[j - 1]);
			if (up + 1 < best)
				best = up + 1;
			if (row[j - 1] + 1 < best)
				best = row[j - 1] + 1;
			row[j] = best;
			diag = up;
		}
	}
	return row[lb];
}

static bool
is_slug(const char *s)
{
	if (*s == '\0')
		return false;
	for (; *s != '\0'; s++)
		if (!((*s >= 'a' && *s <= 'z') || (*s >= '0' && *s <= '9') || *s == '-'))
			return false;
	return true;
}

static const char *
json_type_name(const cJSON *v)
{
	if (cJSON_IsString(v))
		return "a string";
	if (cJSON_IsNumber(v))
		return "a number";
	if (cJSON_IsBool(v))
		return "a boolean";
	if (cJSON_IsNull(v))
		return "null";
	if (cJSON_IsArray(v))
		return "an array";
	if (cJSON_IsObject(v))
		return "an object";
	return "invalid";
}

/* Reads a whole file into a NUL-terminated buffer; NULL (errno set) on failure. */
static char *
read_file(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	if (f == NULL)
		return NULL;
	size_t cap = 8192, n = 0;
	char *buf = xmalloc(cap);
	for (;;) {
		if (cap - n < 2) {
			cap *= 2;
			buf = xrealloc(buf, cap);
		}
		size_t got = fread(buf + n, 1, cap - n - 1, f);
		n += got;
		if (got == 0)
			break;
	}
	int failed = ferror(f);
	fclose(f);
	if (failed) {
		free(buf);
		errno = EIO;
		return NULL;
	}
	buf[n] = '\0';
	*len = n;
	return buf;
}

/* ---- one value ------------------------------------------------------------ */

/* Checks and stores one string value into dst[f->size]. */
static void
store_string(struct ctx *cx, const struct field *f, const char *s, char *dst)
{
	size_t len = strlen(s);
	if (len >= f->size) {
		report(cx, f->key, "too long (%zu chars, at most %zu)", len, f->size - 1);
		return;
	}
	switch (f->check) {
	case C_ID:
		if (!is_slug(s))
			report(cx, f->key, "must be a lowercase slug of a-z, 0-9 and '-' (got \"%s\")", s);
		break;
	case C_NONEMPTY:
		if (len == 0)
			report(cx, f->key, "must not be empty");
		break;
	case C_CONF:
		if (!in_list(s, confidences))
			report(cx, f->key, "must be \"high\", \"medium\" or \"low\" (got \"%s\")", s);
		break;
	case C_CHEM:
		if (!in_list(s, cx->chems))
			report(cx, f->key, "unknown chemistry \"%s\"", s);
		break;
	case C_MATERIAL:
		if (!in_list(s, materials))
			report(cx, f->key, "must be plastic, carbon, wood or composite (got \"%s\")", s);
		break;
	case C_NONE:
	case C_POS:
		break;
	}
	memcpy(dst, s, len + 1);
}

/* Stores the `uncertain` list: every element must name a field of the entry. */
static void
store_list(struct ctx *cx, const struct field *f, const cJSON *v, char *dst)
{
	size_t used = 0, i = 0;
	const cJSON *el;
	dst[0] = '\0';
	cJSON_ArrayForEach(el, v) {
		if (!cJSON_IsString(el)) {
			report(cx, f->key, "element %zu must be a string (got %s)", i, json_type_name(el));
		} else if (find_field(cx->cat, el->valuestring) == NULL) {
			report(cx, f->key, "element %zu names no field of %s (got \"%s\")",
			       i, cx->cat->key, el->valuestring);
		} else {
			size_t len = strlen(el->valuestring);
			if (used + len + 2 > f->size) {
				report(cx, f->key, "list too long");
				return;
			}
			if (used > 0)
				dst[used++] = ',';
			memcpy(dst + used, el->valuestring, len + 1);
			used += len;
		}
		i++;
	}
}

/* Checks and stores one value; returns true if it is known (not null). */
static bool
store_value(struct ctx *cx, const struct field *f, const cJSON *v, char *base)
{
	void *dst = base + f->off;
	if (cJSON_IsNull(v)) {
		if (!f->nullable)
			report(cx, f->key, "must not be null");
		if (f->kind == K_TRIBOOL)
			*(int *)dst = -1;
		return false;
	}
	switch (f->kind) {
	case K_STR:
		if (!cJSON_IsString(v)) {
			report(cx, f->key, "must be a string (got %s)", json_type_name(v));
			return false;
		}
		store_string(cx, f, v->valuestring, dst);
		return true;
	case K_LIST:
		if (!cJSON_IsArray(v)) {
			report(cx, f->key, "must be an array of field names (got %s)", json_type_name(v));
			return false;
		}
		store_list(cx, f, v, dst);
		return true;
	case K_BOOL:
	case K_TRIBOOL:
		if (!cJSON_IsBool(v)) {
			report(cx, f->key, "must be true or false (got %s)", json_type_name(v));
			return false;
		}
		if (f->kind == K_BOOL)
			*(bool *)dst = cJSON_IsTrue(v);
		else
			*(int *)dst = cJSON_IsTrue(v) ? 1 : 0;
		return true;
	case K_ANY:
		return true;
	case K_NUM:
	case K_INT:
		break;
	}
	if (!cJSON_IsNumber(v)) {
		report(cx, f->key, "must be a number (got %s)", json_type_name(v));
		return false;
	}
	double x = v->valuedouble;
	if (!isfinite(x)) {
		report(cx, f->key, "must be a finite number");
		return false;
	}
	if (f->check == C_POS && !(x > 0)) {
		report(cx, f->key, "must be > 0 (got %g)", x);
		return false;
	}
	if (f->kind == K_INT) {
		if (x != floor(x) || x > 1000) {
			report(cx, f->key, "must be a whole number up to 1000 (got %g)", x);
			return false;
		}
		*(int *)dst = (int)x;
	} else {
		*(double *)dst = x * f->scale;
	}
	return true;
}

/* The value of a known numeric field as written in the JSON (for messages). */
static double
raw_number(const struct field *f, const char *base)
{
	if (f->kind == K_INT)
		return *(const int *)(base + f->off);
	return *(const double *)(base + f->off) / f->scale;
}

/* ---- one entry ------------------------------------------------------------ */

static void
check_orders(struct ctx *cx, const char *base, const bool *known)
{
	const struct category *cat = cx->cat;
	for (size_t i = 0; i < cat->n_orders; i++) {
		const struct field *lo = find_field(cat, cat->orders[i].lo);
		const struct field *hi = find_field(cat, cat->orders[i].hi);
		if (!known[lo - cat->fields] || !known[hi - cat->fields])
			continue;
		double a = raw_number(lo, base), b = raw_number(hi, base);
		if (a > b)
			report(cx, lo->key, "must be <= %s (got %g > %g)", hi->key, a, b);
	}
}

/* An integrated system lists its propeller (null if unknown, which makes the
 * entry unusable: the optimizer cannot size around an unknown rotor); a plain
 * motor must not list one.  Returns false if the entry is unusable. */
static bool
check_integrated(struct ctx *cx, const struct catalog_motor *m, const bool *seen, const bool *known)
{
	const struct field *f = find_field(cx->cat, "integrated_prop_in");
	size_t i = (size_t)(f - cx->cat->fields);
	if (m->integrated && !seen[i])
		report(cx, f->key, "required when integrated is true (null if unknown)");
	if (!m->integrated && known[i])
		report(cx, f->key, "must be null unless integrated is true");
	return !m->integrated || known[i];
}

static void
parse_entry(struct ctx *cx, const cJSON *obj, char *base)
{
	const struct category *cat = cx->cat;
	bool seen[MAX_FIELDS] = { false }, known[MAX_FIELDS] = { false };
	const cJSON *id;

	cx->entry_id = NULL;
	if (!cJSON_IsObject(obj)) {
		report(cx, NULL, "must be an object (got %s)", json_type_name(obj));
		return;
	}
	id = cJSON_GetObjectItemCaseSensitive(obj, "id");
	if (cJSON_IsString(id))
		cx->entry_id = id->valuestring;
	size_t hint = 0;
	for (const cJSON *kv = obj->child; kv != NULL; kv = kv->next) {
		const struct field *f = find_field_from(cat, kv->string, hint);
		if (f == NULL) {
			const char *best = NULL;
			size_t best_d = 3;    /* suggest only close matches */
			for (size_t i = 0; i < cat->n_fields; i++) {
				size_t d = edit_distance(kv->string, cat->fields[i].key);
				if (d < best_d) {
					best_d = d;
					best = cat->fields[i].key;
				}
			}
			if (best != NULL)
				report(cx, kv->string, "unknown key (did you mean \"%s\"?)", best);
			else
				report(cx, kv->string, "unknown key");
			continue;
		}
		size_t i = (size_t)(f - cat->fields);
		hint = i + 1;
		if (seen[i]) {
			report(cx, f->key, "duplicate key");
			continue;
		}
		seen[i] = true;
		known[i] = store_value(cx, f, kv, base);
	}

	bool usable = true;
	for (size_t i = 0; i < cat->n_fields; i++) {
		const struct field *f = &cat->fields[i];
		if (!seen[i] && !f->optional)
			report(cx, f->key, "missing required key");
		if (f->needed && !known[i])
			usable = false;
	}
	check_orders(cx, base, known);
	if (cat == &categories[CAT_MOTOR])
		usable &= check_integrated(cx, (const struct catalog_motor *)(const void *)base, seen, known);
	if (cat == &categories[CAT_PROP]) {
		struct catalog_prop *p = (struct catalog_prop *)(void *)base;
		p->diameter_m = p->diameter_in * IN_TO_M;
		p->pitch_m = p->pitch_in * IN_TO_M;
	}
	*(bool *)(base + cat->off_usable) = usable;
}

/* ---- one file ------------------------------------------------------------- */

/* 1-based line and column (in characters, not bytes) of offset off. */
static void
line_col(const char *buf, size_t off, int *line, int *col)
{
	*line = 1;
	*col = 1;
	for (size_t i = 0; i < off; i++) {
		if (buf[i] == '\n') {
			(*line)++;
			*col = 1;
		} else if (((unsigned char)buf[i] & 0xC0) != 0x80) {
			(*col)++;
		}
	}
}

static void
report_syntax(struct ctx *cx, const char *buf, size_t n, const char *end)
{
	size_t off = end != NULL && end >= buf && end <= buf + n ? (size_t)(end - buf) : n;
	char near[21];
	size_t k = 0;
	int line, col;

	line_col(buf, off, &line, &col);
	for (size_t i = off; i < n && k + 1 < sizeof near && (unsigned char)buf[i] >= 0x20; i++)
		near[k++] = buf[i];
	near[k] = '\0';
	cx->n_errors++;
	if (cx->err != NULL)
		fprintf(cx->err, "%s:%d:%d: error: malformed JSON near '%s'\n", cx->path, line, col, near);
}

/* Parses one category file into c; all errors go through cx. */
static void
load_file(struct ctx *cx, const char *dir, struct catalog *c, enum cat k)
{
	const struct category *cat = &categories[k];
	size_t dl = strlen(dir);
	char *path = xmalloc(dl + strlen(cat->file) + 2);
	sprintf(path, "%s%s%s", dir, dl > 0 && dir[dl - 1] == '/' ? "" : "/", cat->file);
	cx->path = path;
	cx->cat = cat;

	size_t n = 0;
	char *buf = read_file(path, &n);
	if (buf == NULL) {
		report_file(cx, "cannot read %s file: %s", cat->key, strerror(errno));
		goto done;
	}
	/* The fingerprint covers each file as name, NUL, length (8 bytes,
	 * little-endian) and bytes, hashed from the very buffer parsed. */
	unsigned char len8[8];
	for (int b = 0; b < 8; b++)
		len8[b] = (unsigned char)((uint64_t)n >> (8 * b));
	sha256_update(&cx->sha, cat->file, strlen(cat->file) + 1);
	sha256_update(&cx->sha, len8, sizeof len8);
	sha256_update(&cx->sha, buf, n);
	const char *end = NULL;
	cJSON *root = cJSON_ParseWithLengthOpts(buf, n + 1, &end, 1);
	if (root == NULL) {
		report_syntax(cx, buf, n, end);
		goto done;
	}
	const cJSON *arr = NULL;
	if (!cJSON_IsObject(root)) {
		report_file(cx, "top level must be an object {\"%s\": [...]}", cat->key);
	} else {
		for (const cJSON *kv = root->child; kv != NULL; kv = kv->next)
			if (strcmp(kv->string, cat->key) != 0)
				report_file(cx, "unknown top-level key \"%s\" (expected only \"%s\")",
				            kv->string, cat->key);
		arr = cJSON_GetObjectItemCaseSensitive(root, cat->key);
		if (arr == NULL)
			report_file(cx, "missing top-level key \"%s\"", cat->key);
		else if (!cJSON_IsArray(arr)) {
			report_file(cx, "\"%s\" must be an array (got %s)", cat->key, json_type_name(arr));
			arr = NULL;
		}
	}
	if (arr != NULL) {
		size_t cnt = (size_t)cJSON_GetArraySize(arr), i = 0;
		char *items = xcalloc(cnt > 0 ? cnt : 1, cat->size);
		const cJSON *el;
		cJSON_ArrayForEach(el, arr) {
			cx->index = i;
			parse_entry(cx, el, items + i * cat->size);
			i++;
		}
		c->items[k] = items;
		c->n[k] = cnt;
	}
	cJSON_Delete(root);
done:
	free(buf);
	free(path);
	cx->path = NULL;
	cx->entry_id = NULL;
}

/* One catalogue entry's id, for finding duplicates. */
struct id_ref {
	const char *id;
	int k;               /* category */
	size_t i;            /* index in it */
};

/* By id, then by place (category, index): equal ids end up together with
 * the first-loaded one first. */
static int
cmp_id_ref(const void *pa, const void *pb)
{
	const struct id_ref *a = pa, *b = pb;
	int c = strcmp(a->id, b->id);
	if (c != 0)
		return c;
	if (a->k != b->k)
		return a->k < b->k ? -1 : 1;
	return (a->i > b->i) - (a->i < b->i);
}

/* Ids must be unique across all four files: the BOM and --db overrides name
 * parts by id alone.  Sorting the ids finds the repeats in n log n (a pairwise
 * scan grows with the square of the catalogue); each repeat is then reported,
 * in file order, against the entry that used the id first. */
static void
check_duplicates(struct ctx *cx, const char *dir, const struct catalog *c)
{
	size_t n = 0, base[CAT_N];
	for (int k = 0; k < CAT_N; k++) {
		base[k] = n;
		n += c->n[k];
	}
	if (n == 0)
		return;
	struct id_ref *v = xmalloc(n * sizeof *v);
	size_t m = 0;
	for (int k = 0; k < CAT_N; k++)
		for (size_t i = 0; i < c->n[k]; i++) {
			const char *id = (const char *)c->items[k] + i * categories[k].size
			                 + categories[k].off_id;
			if (*id != '\0')
				v[m++] = (struct id_ref){ id, k, i };
		}
	qsort(v, m, sizeof *v, cmp_id_ref);
	/* first[base[k] + i]: the sorted position of the id's first user, for
	 * a repeated entry; SIZE_MAX for every other. */
	size_t *first = xmalloc(n * sizeof *first);
	for (size_t j = 0; j < n; j++)
		first[j] = SIZE_MAX;
	for (size_t j = 1, head = 0; j < m; j++) {
		if (strcmp(v[j].id, v[head].id) != 0)
			head = j;
		else
			first[base[v[j].k] + v[j].i] = head;
	}
	size_t dl = strlen(dir);
	const char *sep = dl > 0 && dir[dl - 1] == '/' ? "" : "/";
	for (int k = 0; k < CAT_N; k++) {
		const struct category *cat = &categories[k];
		for (size_t i = 0; i < c->n[k]; i++) {
			size_t f = first[base[k] + i];
			if (f == SIZE_MAX)
				continue;
			const struct category *cat2 = &categories[v[f].k];
			char path[1024];
			snprintf(path, sizeof path, "%s%s%s", dir, sep, cat->file);
			cx->path = path;
			cx->cat = cat;
			cx->index = i;
			cx->entry_id = v[f].id;
			report(cx, "id", "duplicate id (first used by %s%s%s %s[%zu])",
			       dir, sep, cat2->file, cat2->key, v[f].i);
			cx->path = NULL;
		}
	}
	free(first);
	free(v);
}

/* The propellers by diameter, ties in file order (insertion sort: a
 * catalogue holds some dozens), once for every search that ranks them. */
static void
sort_props(struct catalog *c)
{
	size_t n = c->n[CAT_PROP];
	c->prop_order = xmalloc((n > 0 ? n : 1) * sizeof *c->prop_order);
	const struct catalog_prop *v = c->items[CAT_PROP];
	for (size_t i = 0; i < n; i++) {
		size_t j = i;
		while (j > 0 && v[c->prop_order[j - 1]].diameter_in > v[i].diameter_in) {
			c->prop_order[j] = c->prop_order[j - 1];
			j--;
		}
		c->prop_order[j] = i;
	}
}

/* ---- public --------------------------------------------------------------- */

struct catalog *
catalog_load(const char *dir, const char *const *known_chemistries, FILE *err, int *n_errors)
{
	struct ctx cx = { .err = err, .chems = known_chemistries != NULL ? known_chemistries
	                                                              : catalog_default_chemistries };
	struct catalog *c = xcalloc(1, sizeof *c);

	sha256_init(&cx.sha);
	for (int k = 0; k < CAT_N; k++)
		load_file(&cx, dir, c, (enum cat)k);
	check_duplicates(&cx, dir, c);
	if (n_errors != NULL)
		*n_errors = cx.n_errors;
	if (cx.n_errors > 0) {
		catalog_free(c);
		return NULL;
	}
	sort_props(c);
	unsigned char digest[SHA256_DIGEST_LEN];
	sha256_final(&cx.sha, digest);
	for (int i = 0; i < SHA256_DIGEST_LEN; i++) {
		c->sha256[2 * i] = "0123456789abcdef"[digest[i] >> 4];
		c->sha256[2 * i + 1] = "0123456789abcdef"[digest[i] & 15];
	}
	c->sha256[64] = '\0';
	return c;
}

const char *
catalog_sha256(const struct catalog *c)
{
	return c->sha256;
}

void
catalog_free(struct catalog *c)
{
	if (c == NULL)
		return;
	for (int k = 0; k < CAT_N; k++)
		free(c->items[k]);
	free(c->prop_order);
	free(c);
}

static const void *
item_at(const struct catalog *c, enum cat k, size_t i)
{
	if (c == NULL || i >= c->n[k])
		return NULL;
	return (const char *)c->items[k] + i * categories[k].size;
}

static const void *
item_by_id(const struct catalog *c, enum cat k, const char *id)
{
	for (size_t i = 0; c != NULL && id != NULL && i < c->n[k]; i++) {
		const char *p = item_at(c, k, i);
		if (strcmp(p + categories[k].off_id, id) == 0)
			return p;
	}
	return NULL;
}

size_t catalog_n_motors(const struct catalog *c) { return c != NULL ? c->n[CAT_MOTOR] : 0; }
size_t catalog_n_props(const struct catalog *c) { return c != NULL ? c->n[CAT_PROP] : 0; }
size_t catalog_n_batteries(const struct catalog *c) { return c != NULL ? c->n[CAT_BATTERY] : 0; }
size_t catalog_n_escs(const struct catalog *c) { return c != NULL ? c->n[CAT_ESC] : 0; }

const struct catalog_motor *
catalog_motor(const struct catalog *c, size_t i) { return item_at(c, CAT_MOTOR, i); }
const struct catalog_prop *
catalog_prop(const struct catalog *c, size_t i) { return item_at(c, CAT_PROP, i); }
const struct catalog_battery *
catalog_battery(const struct catalog *c, size_t i) { return item_at(c, CAT_BATTERY, i); }
const struct catalog_esc *
catalog_esc(const struct catalog *c, size_t i) { return item_at(c, CAT_ESC, i); }

const size_t *
catalog_props_by_diameter(const struct catalog *c) { return c->prop_order; }

const struct catalog_motor *
catalog_find_motor(const struct catalog *c, const char *id) { return item_by_id(c, CAT_MOTOR, id); }
const struct catalog_prop *
catalog_find_prop(const struct catalog *c, const char *id) { return item_by_id(c, CAT_PROP, id); }
const struct catalog_battery *
catalog_find_battery(const struct catalog *c, const char *id) { return item_by_id(c, CAT_BATTERY, id); }
const struct catalog_esc *
catalog_find_esc(const struct catalog *c, const char *id) { return item_by_id(c, CAT_ESC, id); }
