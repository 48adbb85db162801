/* catalog_io.c — read and validate a catalogue directory (see catalog_io.h).
 *
 * One field table per category drives the key list, the type and range
 * checks, the unit conversion and the `usable` flag, so the six categories
 * share one parser; the few rules between fields are small functions
 * after it.  Errors accumulate (every error of every file is reported) and
 * the load fails at the end if there was any.
 */
#include "input/catalog_io.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "spec/spec.h"
#include "input/json_in.h"
#include "util/hash.h"
#include "util/sha256.h"
#include "util/units.h"
#include "util/text.h"
#include "util/xalloc.h"

#define G_TO_KG 1e-3
#define MOHM_TO_OHM 1e-3
#define MAH_TO_AH 1e-3
#define MM_TO_M 1e-3
#define GRAM_FORCE_N (G0_M_S2 * 1e-3)  /* thrust in grams -> newtons */
#define NUM_MAX 1e9       /* above any real part's number: keeps products finite */
#define INT_MAX_COUNT 1000 /* cells, blades, channels, rotors */

const char *const catalog_io_files[CATALOG_N_CATEGORIES] = {
	"motors.json", "propellers.json", "batteries.json", "escs.json",
	"frames.json", "avionics.json",
};

static const char *const array_keys[CATALOG_N_CATEGORIES] = {
	"motors", "propellers", "batteries", "escs", "frames", "avionics",
};

static const char *const confidences[] = { "high", "medium", "low", NULL };
static const char *const materials[] = { "plastic", "carbon", "wood", "composite", NULL };
static const char *const current_bases[] = { "continuous", "peak_180s", "peak_60s",
	"peak_30s", "peak_10s", "peak_unspecified", NULL };
static const char *const avionics_kinds[] = { "flight_controller", "gnss", "receiver",
	"telemetry", "power_module", "pdb", "bec", "connector", "series_lead", "video_tx",
	"camera_fpv", "gimbal_camera", "companion_computer", "lidar", "remote_id", NULL };
/* The video systems a camera and a transmitter may belong to; the parts
 * search pairs a camera only with a transmitter of the same system
 * (data/catalog/README.md says which parts are which). */
static const char *const video_systems[] = { "analog", "dji_hd", "dji_o3",
	"dji_o4", "walksnail", "walksnail_moonlight", "hdzero", NULL };

bool
catalog_io_required(enum catalog_category k)
{
	return k != CATALOG_FRAME && k != CATALOG_AVIONICS;
}

/* ---- field tables -------------------------------------------------------- */

enum kind {
	K_STR,            /* text, interned */
	K_NUM,            /* double, times scale */
	K_INT,            /* whole number 1..INT_MAX_COUNT into an int */
	K_BOOL,           /* true/false into a bool */
	K_TRIBOOL,        /* true/false/null into an int 1/0/-1 */
	K_LIST,           /* the `uncertain` array of key names */
};

enum check {
	C_NONE,           /* any text */
	C_POS,            /* number > 0 */
	C_ID,             /* lowercase slug */
	C_LIST,           /* one of field->list */
	C_CHEM,           /* one of the known chemistries */
	C_DATE,           /* "YYYY-MM" or "YYYY" */
};

struct field {
	const char *key;          /* JSON key */
	enum kind kind;
	size_t off;               /* offset of the destination in the struct */
	double scale;             /* K_NUM: file unit -> stored unit */
	const char *unit;         /* the file's unit, for messages */
	enum check check;
	const char *const *list;  /* C_LIST: the spellings */
	bool nullable;            /* null means "unknown" */
	bool needed;              /* must be known for the entry to be `usable` */
};

#define F(T, k, kind, m, sc, unit, chk, list, null, need) \
	{ k, kind, offsetof(T, m), sc, unit, chk, list, null, need }
#define COMMON(T)                                                            \
	F(T, "id", K_STR, id, 1, "", C_ID, NULL, false, false),                  \
	F(T, "manufacturer", K_STR, manufacturer, 1, "", C_NONE, NULL, false, false), \
	F(T, "part_number", K_STR, part_number, 1, "", C_NONE, NULL, false, false), \
	F(T, "price_usd", K_NUM, price_usd, 1, "USD", C_POS, NULL, true, false),  \
	F(T, "price_date", K_STR, price_date, 1, "", C_DATE, NULL, true, false),  \
	F(T, "source", K_STR, source, 1, "", C_NONE, NULL, false, false),         \
	F(T, "confidence", K_STR, confidence, 1, "", C_LIST, confidences, false, false), \
	F(T, "uncertain", K_LIST, uncertain, 1, "", C_NONE, NULL, false, false)
/* A number > 0 in the file's unit; need: the optimizer needs it. */
#define NUM(T, k, m, sc, unit, need) F(T, k, K_NUM, m, sc, unit, C_POS, NULL, true, need)
#define INT(T, k, m, need) F(T, k, K_INT, m, 1, "", C_POS, NULL, true, need)
#define TEXT(T, k, m, need) F(T, k, K_STR, m, 1, "", C_NONE, NULL, true, need)
#define ENUM(T, k, m, list, need) F(T, k, K_STR, m, 1, "", C_LIST, list, true, need)
#define BOOL(T, k, m) F(T, k, K_BOOL, m, 1, "", C_NONE, NULL, false, false)
#define TRIBOOL(T, k, m) F(T, k, K_TRIBOOL, m, 1, "", C_NONE, NULL, true, false)

#define M struct catalog_motor
static const struct field motor_fields[] = {
	COMMON(M),
	NUM(M, "kv_rpm_per_v", kv_rpm_per_v, 1, "rpm/V", true),
	NUM(M, "mass_g", mass_kg, G_TO_KG, "g", true),
	NUM(M, "max_current_a", max_current_a, 1, "A", true),
	ENUM(M, "max_current_basis", max_current_basis, current_bases, false),
	NUM(M, "max_power_w", max_power_w, 1, "W", false),
	INT(M, "cells_min", cells_min, false),
	INT(M, "cells_max", cells_max, false),
	NUM(M, "prop_min_in", prop_min_in, 1, "in", false),
	NUM(M, "prop_max_in", prop_max_in, 1, "in", false),
	NUM(M, "resistance_mohm", resistance_ohm, MOHM_TO_OHM, "mOhm", false),
	NUM(M, "no_load_current_a", no_load_current_a, 1, "A", false),
	NUM(M, "no_load_voltage_v", no_load_voltage_v, 1, "V", false),
	TEXT(M, "stator", stator, false),
	BOOL(M, "integrated", integrated),
	/* Null unless integrated; check_integrated() says so. */
	NUM(M, "integrated_prop_in", integrated_prop_in, 1, "in", false),
	NUM(M, "integrated_pitch_in", integrated_pitch_in, 1, "in", false),
	NUM(M, "integrated_esc_current_a", integrated_esc_current_a, 1, "A", false),
	NUM(M, "max_thrust_g", max_thrust_n, GRAM_FORCE_N, "g", false),
};
#undef M

#define P struct catalog_prop
static const struct field prop_fields[] = {
	COMMON(P),
	NUM(P, "diameter_in", diameter_in, 1, "in", true),
	NUM(P, "pitch_in", pitch_in, 1, "in", true),
	INT(P, "blades", blades, false),
	ENUM(P, "material", material, materials, false),
	NUM(P, "mass_g", mass_kg, G_TO_KG, "g", true),
	NUM(P, "max_rpm", max_rpm, 1, "rpm", false),
	TRIBOOL(P, "folding", folding),
	NUM(P, "ct_static", ct_static, 1, "", false),
	NUM(P, "cp_static", cp_static, 1, "", false),
	TEXT(P, "coeff_source", coeff_source, false),
	TEXT(P, "part_number_ccw", part_number_ccw, false),
};
#undef P

#define B struct catalog_battery
static const struct field battery_fields[] = {
	COMMON(B),
	F(B, "chemistry", K_STR, chemistry, 1, "", C_CHEM, NULL, true, true),
	INT(B, "cells_series", cells_series, true),
	INT(B, "cells_parallel", cells_parallel, false),
	NUM(B, "capacity_mah", capacity_ah, MAH_TO_AH, "mAh", true),
	NUM(B, "mass_g", mass_kg, G_TO_KG, "g", true),
	NUM(B, "continuous_c", continuous_c, 1, "C", true),
	NUM(B, "burst_c", burst_c, 1, "C", false),
	NUM(B, "nominal_voltage_v", nominal_voltage_v, 1, "V", false),
	NUM(B, "energy_wh", energy_wh, 1, "Wh", false),
	TEXT(B, "connector", connector, false),
	BOOL(B, "smart", smart),
};
#undef B

#define E struct catalog_esc
static const struct field esc_fields[] = {
	COMMON(E),
	NUM(E, "continuous_current_a", continuous_current_a, 1, "A", true),
	NUM(E, "burst_current_a", burst_current_a, 1, "A", false),
	NUM(E, "burst_seconds", burst_s, 1, "s", false),
	INT(E, "cells_min", cells_min, false),
	INT(E, "cells_max", cells_max, false),
	NUM(E, "mass_g", mass_kg, G_TO_KG, "g", true),
	INT(E, "channels", channels, true),
	TEXT(E, "carries", carries, false),
	ENUM(E, "video_system", video_system, video_systems, false),
};
#undef E

#define FR struct catalog_frame
static const struct field frame_fields[] = {
	COMMON(FR),
	INT(FR, "rotor_count", rotor_count, true),
	BOOL(FR, "coaxial", coaxial),
	NUM(FR, "wheelbase_mm", wheelbase_m, MM_TO_M, "mm", true),
	NUM(FR, "mass_g", mass_kg, G_TO_KG, "g", true),
	TEXT(FR, "includes", includes, true),
	NUM(FR, "max_prop_in", max_prop_in, 1, "in", false),
	NUM(FR, "arm_tube_od_mm", arm_tube_od_m, MM_TO_M, "mm", false),
	TRIBOOL(FR, "folding", folding),
	NUM(FR, "max_takeoff_kg", max_takeoff_kg, 1, "kg", false),
	ENUM(FR, "frame_class", frame_class, spec_enum_airframe, false),
};
#undef FR

#define AV struct catalog_avionics
static const struct field avionics_fields[] = {
	COMMON(AV),
	ENUM(AV, "kind", kind, avionics_kinds, true),
	NUM(AV, "mass_g", mass_kg, G_TO_KG, "g", true),
	INT(AV, "cells_min", cells_min, false),
	INT(AV, "cells_max", cells_max, false),
	NUM(AV, "max_current_a", max_current_a, 1, "A", false),
	NUM(AV, "burst_current_a", burst_current_a, 1, "A", false),
	NUM(AV, "burst_seconds", burst_s, 1, "s", false),
	NUM(AV, "power_w", power_w, 1, "W", false),
	ENUM(AV, "video_system", video_system, video_systems, false),
	TEXT(AV, "carries", carries, false),
	TEXT(AV, "description", description, true),
};
#undef AV

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))
#define MAX_FIELDS 32

/* Pairs whose known values must be in order: lo <= hi. */
struct order {
	const char *lo, *hi;
	const char *why;          /* said after the values */
};

static const struct order motor_orders[] = {
	{ "cells_min", "cells_max", "a range goes from low to high" },
	{ "prop_min_in", "prop_max_in", "a range goes from low to high" },
};
static const struct order battery_orders[] = {
	{ "continuous_c", "burst_c", "a burst rating is at least the continuous one" },
};
static const struct order esc_orders[] = {
	{ "cells_min", "cells_max", "a range goes from low to high" },
	{ "continuous_current_a", "burst_current_a", "a burst rating is at least the continuous one" },
};
static const struct order avionics_orders[] = {
	{ "cells_min", "cells_max", "a range goes from low to high" },
	{ "max_current_a", "burst_current_a", "a burst rating is at least the continuous one" },
};

struct category {
	const struct field *fields;
	size_t n_fields;
	const struct order *orders;
	size_t n_orders;
};

static const struct category categories[CATALOG_N_CATEGORIES] = {
	{ motor_fields, N_OF(motor_fields), motor_orders, N_OF(motor_orders) },
	{ prop_fields, N_OF(prop_fields), NULL, 0 },
	{ battery_fields, N_OF(battery_fields), battery_orders, N_OF(battery_orders) },
	{ esc_fields, N_OF(esc_fields), esc_orders, N_OF(esc_orders) },
	{ frame_fields, N_OF(frame_fields), NULL, 0 },
	{ avionics_fields, N_OF(avionics_fields), avionics_orders, N_OF(avionics_orders) },
};

_Static_assert(N_OF(motor_fields) < MAX_FIELDS && N_OF(prop_fields) < MAX_FIELDS &&
               N_OF(battery_fields) < MAX_FIELDS && N_OF(esc_fields) < MAX_FIELDS &&
               N_OF(frame_fields) < MAX_FIELDS && N_OF(avionics_fields) < MAX_FIELDS,
               "raise MAX_FIELDS");

size_t
catalog_io_text_fields(enum catalog_category k, size_t *offsets, size_t max)
{
	size_t n = 0;
	for (size_t i = 0; i < categories[k].n_fields; i++) {
		const struct field *f = &categories[k].fields[i];
		if ((f->kind == K_STR || f->kind == K_LIST) && n < max)
			offsets[n++] = f->off;
	}
	return n;
}

/* ---- the load ------------------------------------------------------------ */

/* Where an id was first given, for "duplicate id" messages. */
struct id_owner {
	enum catalog_category k;
	size_t i;                 /* entry index */
	const cJSON *item;        /* its id value */
};

/* Everything one load needs. */
struct load {
	struct catalog *c;
	struct diag *dg;
	const char *const *chems;
	struct json_in *ji[CATALOG_N_CATEGORIES];   /* kept to the end: positions */
	char *path[CATALOG_N_CATEGORIES];
	struct strmap *ids;       /* id -> index into owners */
	struct id_owner *owners;
	size_t n_owners, cap_owners;
};

/* The state of one entry while it is read. */
struct entry {
	struct load *ld;
	enum catalog_category k;
	struct json_in *ji;
	const cJSON *obj;
	char path[64];            /* "motors[12]" */
	char *base;               /* the struct being filled */
	const cJSON *item[MAX_FIELDS]; /* each field's value, NULL if absent */
	bool known[MAX_FIELDS];   /* valid and not null */
};

static const struct field *
field_of(enum catalog_category k, const char *key, size_t *index)
{
	const struct category *cat = &categories[k];
	for (size_t i = 0; i < cat->n_fields; i++)
		if (strcmp(cat->fields[i].key, key) == 0) {
			if (index != NULL)
				*index = i;
			return &cat->fields[i];
		}
	return NULL;
}

/* Reports at field f of the entry (its value, or the entry when absent). */
static void
entry_report(struct entry *e, enum diag_kind kind, const struct field *f,
             const cJSON *item, const char *fmt, ...)
	__attribute__((format(printf, 5, 6)));

static void
entry_report(struct entry *e, enum diag_kind kind, const struct field *f,
             const cJSON *item, const char *fmt, ...)
{
	char path[128];
	va_list ap;
	json_in_path(path, sizeof path, e->path, f->key);
	va_start(ap, fmt);
	json_in_vreport(e->ji, kind, item != NULL ? item : e->obj, JSON_IN_VALUE, path,
	                fmt, ap);
	va_end(ap);
}

/* ---- one value ------------------------------------------------------------ */

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

/* "YYYY-MM" (month 01-12) or "YYYY". */
static bool
is_price_date(const char *s)
{
	size_t n = strlen(s);
	if (n != 4 && n != 7)
		return false;
	for (size_t i = 0; i < n; i++)
		if (i != 4 && (s[i] < '0' || s[i] > '9'))
			return false;
	if (n == 4)
		return true;
	int month = (s[5] - '0') * 10 + (s[6] - '0');
	return s[4] == '-' && month >= 1 && month <= 12;
}

static bool
in_list(const char *s, const char *const *list)
{
	for (; *list != NULL; list++)
		if (strcmp(s, *list) == 0)
			return true;
	return false;
}

/* Every text of the catalogue: valid UTF-8, no control character, no NUL,
 * not starting like a spreadsheet formula (the BOM goes to a spreadsheet). */
static bool
check_text(struct entry *e, const cJSON *v, const char *path, size_t max)
{
	return json_in_check_string(e->ji, v, path, max,
	                            JSON_IN_NO_CONTROL | JSON_IN_NO_FORMULA);
}

/* s quoted for a message into q (96 bytes): only when one is written, not
 * for every string a catalogue holds. */
static const char *
quoted(const char *s, char q[96])
{
	diag_quote(s, strlen(s), 40, q, 96);
	return q;
}

static bool
store_string(struct entry *e, const struct field *f, const cJSON *v, const char *path)
{
	const char *s = v->valuestring;
	char q[96], list[512];
	if (!check_text(e, v, path, f->check == C_ID ? CATALOG_ID_MAX - 1 : CATALOG_TEXT_MAX - 1))
		return false;
	switch (f->check) {
	case C_ID:
		if (!is_slug(s)) {
			entry_report(e, DIAG_BAD_ID, f, v, ": %s (a lowercase slug of a-z, 0-9 and '-')", quoted(s, q));
			return false;
		}
		break;
	case C_LIST:
		if (!in_list(s, f->list)) {
			text_join(f->list, list, sizeof list);
			entry_report(e, DIAG_BAD_ENUM, f, v, " %s (allowed: %s)", quoted(s, q), list);
			return false;
		}
		break;
	case C_CHEM:
		if (!in_list(s, e->ld->chems)) {
			text_join(e->ld->chems, list, sizeof list);
			entry_report(e, DIAG_BAD_CHEMISTRY, f, v, " %s (known: %s)", quoted(s, q), list);
			return false;
		}
		break;
	case C_DATE:
		if (!is_price_date(s)) {
			entry_report(e, DIAG_BAD_DATE, f, v, " %s (expected \"YYYY-MM\" or \"YYYY\")", quoted(s, q));
			return false;
		}
		break;
	case C_NONE:
		if (s[0] == '\0') {
			entry_report(e, DIAG_TYPE, f, v, ": expected a non-empty string, got \"\"");
			return false;
		}
		break;
	case C_POS:
		break;
	}
	*(const char **)(e->base + f->off) = catalog_intern(e->ld->c, s);
	return true;
}

/* The `uncertain` list: strings naming keys of the entry's category. */
static bool
store_list(struct entry *e, const struct field *f, const cJSON *v, const char *path)
{
	char el_path[160], joined[CATALOG_TEXT_MAX], q[96];
	size_t used = 0, i = 0;
	bool ok = true;
	const cJSON *el;
	joined[0] = '\0';
	cJSON_ArrayForEach(el, v) {
		json_in_path_index(el_path, sizeof el_path, path, i++);
		if (!json_in_expect(e->ji, el, el_path, cJSON_String, "a key name") ||
		    !check_text(e, el, el_path, 64)) {
			ok = false;
			continue;
		}
		if (field_of(e->k, el->valuestring, NULL) == NULL) {
			diag_quote(el->valuestring, strlen(el->valuestring), 40, q, sizeof q);
			json_in_report(e->ji, DIAG_BAD_ENUM, el, JSON_IN_VALUE, el_path,
			               " %s (not a key of %s)", q, array_keys[e->k]);
			ok = false;
			continue;
		}
		size_t len = strlen(el->valuestring);
		if (used + len + 2 > sizeof joined)
			break;    /* only repeats can get here: the keys are few */
		if (used > 0)
			joined[used++] = ',';
		memcpy(joined + used, el->valuestring, len + 1);
		used += len;
	}
	*(const char **)(e->base + f->off) = catalog_intern(e->ld->c, joined);
	return ok;
}

/* A number of field f: finite, > 0 and not absurd, whole for counts. */
static bool
store_number(struct entry *e, const struct field *f, const cJSON *v, const char *path)
{
	char src[64];   /* the number as written, for a message only */
	double x = v->valuedouble;
	if (!json_in_check_number(e->ji, v, path))
		return false;
	const char *sp = f->unit[0] != '\0' ? " " : "";
	if (f->kind == K_INT) {
		if (x != floor(x)) {
			json_in_source(e->ji, v, src, sizeof src);
			entry_report(e, DIAG_NOT_INTEGER, f, v, " (got %s)", src);
			return false;
		}
		if (x < 1 || x > INT_MAX_COUNT) {
			json_in_source(e->ji, v, src, sizeof src);
			entry_report(e, DIAG_RANGE, f, v, ": %s (allowed 1 to %d)", src, INT_MAX_COUNT);
			return false;
		}
		*(int *)(e->base + f->off) = (int)x;
		return true;
	}
	if (!(x > 0) || x > NUM_MAX) {
		json_in_source(e->ji, v, src, sizeof src);
		if (!(x > 0))
			entry_report(e, DIAG_RANGE, f, v, ": %s (allowed above 0%s%s)", src, sp,
			             f->unit);
		else
			entry_report(e, DIAG_RANGE, f, v, ": %s (allowed above 0 up to %g%s%s)",
			             src, NUM_MAX, sp, f->unit);
		return false;
	}
	*(double *)(e->base + f->off) = x * f->scale;
	return true;
}

/* Checks and stores one value; true when it is valid and not null. */
static bool
store_value(struct entry *e, const struct field *f, const cJSON *v)
{
	static const char *const expected[] = {
		[K_STR] = "a string", [K_NUM] = "a number", [K_INT] = "a whole number",
		[K_BOOL] = "true or false", [K_TRIBOOL] = "true, false or null",
		[K_LIST] = "an array of key names",
	};
	static const int types[] = {
		[K_STR] = cJSON_String, [K_NUM] = cJSON_Number, [K_INT] = cJSON_Number,
		[K_BOOL] = cJSON_True | cJSON_False, [K_TRIBOOL] = cJSON_True | cJSON_False,
		[K_LIST] = cJSON_Array,
	};
	char path[128];
	json_in_path(path, sizeof path, e->path, f->key);
	if (cJSON_IsNull(v) && f->nullable) {
		if (f->kind == K_TRIBOOL)
			*(int *)(e->base + f->off) = -1;
		return false;
	}
	if (!json_in_expect(e->ji, v, path, types[f->kind], expected[f->kind]))
		return false;
	switch (f->kind) {
	case K_STR:
		return store_string(e, f, v, path);
	case K_LIST:
		return store_list(e, f, v, path);
	case K_BOOL:
		*(bool *)(e->base + f->off) = cJSON_IsTrue(v);
		return true;
	case K_TRIBOOL:
		*(int *)(e->base + f->off) = cJSON_IsTrue(v) ? 1 : 0;
		return true;
	case K_NUM:
	case K_INT:
		return store_number(e, f, v, path);
	}
	return false;
}

/* ---- rules between fields ---------------------------------------------- */

/* The index of key in the entry's table (the key exists: tables are ours). */
static size_t
slot(const struct entry *e, const char *key)
{
	size_t i = 0;
	field_of(e->k, key, &i);
	return i;
}

static void
check_orders(struct entry *e)
{
	const struct category *cat = &categories[e->k];
	char a[64], b[64];
	for (size_t i = 0; i < cat->n_orders; i++) {
		size_t lo = slot(e, cat->orders[i].lo), hi = slot(e, cat->orders[i].hi);
		if (!e->known[lo] || !e->known[hi])
			continue;
		if (!(e->item[lo]->valuedouble > e->item[hi]->valuedouble))
			continue;
		json_in_source(e->ji, e->item[lo], a, sizeof a);
		json_in_source(e->ji, e->item[hi], b, sizeof b);
		entry_report(e, DIAG_INCONSISTENT, &cat->fields[lo], e->item[lo],
		             ": %s > %s %s (%s)", a, cat->orders[i].hi, b, cat->orders[i].why);
	}
}

/* `what` is given exactly when `when` is (both valid and not null). */
static void
check_iff(struct entry *e, const char *what, const char *when, const char *why)
{
	size_t w = slot(e, what), c = slot(e, when);
	if (e->item[w] == NULL || e->item[c] == NULL)
		return;   /* missing: reported already */
	bool has_w = !cJSON_IsNull(e->item[w]), has_c = !cJSON_IsNull(e->item[c]);
	if (has_w == has_c)
		return;
	entry_report(e, DIAG_INCONSISTENT, &categories[e->k].fields[w], e->item[w],
	             ": %s while %s is %s (%s)", has_w ? "given" : "null", when,
	             has_c ? "given" : "null", why);
}

/* A doubtful field makes an entry medium or low confidence. */
static void
check_confidence(struct entry *e)
{
	size_t conf = slot(e, "confidence"), unc = slot(e, "uncertain");
	const char *level = *(const char **)(e->base + categories[e->k].fields[conf].off);
	const char *list = *(const char **)(e->base + categories[e->k].fields[unc].off);
	if (e->known[conf] && e->known[unc] && list[0] != '\0' && strcmp(level, "high") == 0)
		entry_report(e, DIAG_INCONSISTENT, &categories[e->k].fields[conf], e->item[conf],
		             ": \"high\" while uncertain lists %s (a doubtful field makes "
		             "it medium or low)", list);
}

/* An integrated system lists its propeller and ESC (null if unknown, which
 * makes the entry unusable: the optimizer cannot size around an unknown
 * rotor); a plain motor has null there.  Returns false if unusable. */
static bool
check_integrated(struct entry *e)
{
	static const char *const keys[] = { "integrated_prop_in", "integrated_pitch_in",
		"integrated_esc_current_a" };
	const struct catalog_motor *m = (const struct catalog_motor *)(const void *)e->base;
	for (size_t i = 0; i < N_OF(keys) && !m->integrated; i++) {
		size_t k = slot(e, keys[i]);
		if (e->item[k] != NULL && !cJSON_IsNull(e->item[k]))
			entry_report(e, DIAG_INCONSISTENT, &motor_fields[k], e->item[k],
			             ": given while integrated is false (null for a plain motor)");
	}
	return !m->integrated || e->known[slot(e, "integrated_prop_in")];
}

/* The text of field key once it is known valid, else NULL. */
static const char *
known_text(const struct entry *e, const char *key)
{
	size_t k = slot(e, key);
	return e->known[k] ? *(const char **)(e->base + categories[e->k].fields[k].off)
	    : NULL;
}

/* Every item of a `carries` list is an avionics kind: the parts search
 * reads it to buy nothing twice, so a misspelt kind would buy it again. */
static void
check_carries(struct entry *e)
{
	const char *list = known_text(e, "carries");
	size_t k = slot(e, "carries");
	char item[64], q[96], kinds[512];
	for (const char *p = list; p != NULL && *p != '\0'; ) {
		size_t n = strcspn(p, ",");
		snprintf(item, sizeof item, "%.*s", (int)n, p);
		if (!in_list(item, avionics_kinds)) {
			text_join(avionics_kinds, kinds, sizeof kinds);
			entry_report(e, DIAG_BAD_ENUM, &categories[e->k].fields[k], e->item[k],
			             " %s in the list (allowed: %s, joined by commas)",
			             quoted(item, q), kinds);
			return;
		}
		p += n + (p[n] == ',');
	}
}

/* A camera or video transmitter names its video system, and nothing else
 * does; an ESC board names the system of the transmitter it carries.
 * The parts search pairs a camera only with a transmitter of its own
 * system, so a camera without one could be paired with anything. */
static void
check_video_system(struct entry *e)
{
	size_t v = slot(e, "video_system");
	if (e->item[v] == NULL)
		return;   /* missing: reported already */
	bool want;
	if (e->k == CATALOG_AVIONICS) {
		const char *kind = known_text(e, "kind");
		if (kind == NULL)
			return;
		want = strcmp(kind, "camera_fpv") == 0 || strcmp(kind, "video_tx") == 0;
	} else {
		want = catalog_list_names(known_text(e, "carries"), "video_tx");
	}
	bool has = !cJSON_IsNull(e->item[v]);
	if (has == want)
		return;
	const char *what = e->k == CATALOG_AVIONICS ? "a camera or video transmitter"
	    : "a board that carries a video transmitter";
	entry_report(e, DIAG_INCONSISTENT, &categories[e->k].fields[v], e->item[v],
	             has ? ": given, but only %s has one" : ": null for %s (a camera "
	             "works only with a transmitter of its own system)", what);
}

static void
check_rules(struct entry *e)
{
	check_orders(e);
	check_iff(e, "price_date", "price_usd", "a price is dated, and a date needs a price");
	check_confidence(e);
	if (e->k == CATALOG_PROP) {
		check_iff(e, "cp_static", "ct_static", "the static coefficients come as a pair");
		check_iff(e, "coeff_source", "ct_static", "the coefficients name their source");
	}
	if (e->k == CATALOG_AVIONICS || e->k == CATALOG_ESC) {
		check_carries(e);
		check_video_system(e);
	}
	if (e->k == CATALOG_AVIONICS && e->item[slot(e, "burst_seconds")] != NULL
	    && !cJSON_IsNull(e->item[slot(e, "burst_seconds")]))
		check_iff(e, "burst_seconds", "burst_current_a",
		          "a duration belongs to a burst rating");
}

/* ---- one entry ------------------------------------------------------------ */

/* Ids are unique across every file: the BOM and mission locks name parts
 * by id alone.  One hash set, so 10^5 parts cost 10^5 probes. */
static void
check_id(struct entry *e, size_t i_entry)
{
	struct load *ld = e->ld;
	size_t k_id = slot(e, "id");
	if (!e->known[k_id])
		return;
	const char *id = *(const char **)(e->base + categories[e->k].fields[k_id].off);
	size_t first;
	if (strmap_put(ld->ids, id, ld->n_owners, &first)) {
		if (ld->n_owners == ld->cap_owners) {
			ld->cap_owners = ld->cap_owners ? 2 * ld->cap_owners : 256;
			ld->owners = xrealloc(ld->owners, ld->cap_owners * sizeof *ld->owners);
		}
		ld->owners[ld->n_owners++] = (struct id_owner){ e->k, i_entry, e->item[k_id] };
		return;
	}
	const struct id_owner *o = &ld->owners[first];
	char q[96], where[1200];
	diag_quote(id, strlen(id), 40, q, sizeof q);
	struct diag_loc at = json_in_showing(e->ji) ?
		json_in_loc(ld->ji[o->k], o->item, JSON_IN_VALUE) :
		(struct diag_loc){ ld->path[o->k], 0, 0 };
	if (at.line > 0)
		snprintf(where, sizeof where, "%s:%d:%d, %s[%zu]", at.file, at.line, at.col,
		         array_keys[o->k], o->i);
	else
		snprintf(where, sizeof where, "%s, %s[%zu]", at.file, array_keys[o->k], o->i);
	entry_report(e, DIAG_DUPLICATE_ID, &categories[e->k].fields[k_id], e->item[k_id],
	             " %s (first used at %s)", q, where);
}

static void
parse_entry(struct load *ld, enum catalog_category k, struct json_in *ji,
            const cJSON *obj, size_t index, char *base)
{
	const struct category *cat = &categories[k];
	const char *keys[MAX_FIELDS + 1];
	struct entry e = { .ld = ld, .k = k, .ji = ji, .obj = obj, .base = base };

	json_in_path_index(e.path, sizeof e.path, array_keys[k], index);
	for (size_t i = 0; i < cat->n_fields; i++) {
		const struct field *f = &cat->fields[i];
		if (f->kind == K_STR || f->kind == K_LIST)
			*(const char **)(base + f->off) = "";
		keys[i] = f->key;
	}
	keys[cat->n_fields] = NULL;
	if (!json_in_expect(ji, obj, e.path, cJSON_Object, "an object"))
		return;
	json_in_check_keys(ji, obj, e.path, keys, 0);

	/* Each field's value: the first member of its key (as
	 * cJSON_GetObjectItemCaseSensitive finds it), in one walk. */
	size_t guess = 0;
	for (const cJSON *c = obj->child; c != NULL; c = c->next) {
		size_t i = json_in_key_index(c->string, keys, cat->n_fields, &guess);
		if (i < cat->n_fields && e.item[i] == NULL)
			e.item[i] = c;
	}
	bool usable = true;
	for (size_t i = 0; i < cat->n_fields; i++) {
		const struct field *f = &cat->fields[i];
		if (e.item[i] == NULL)
			entry_report(&e, DIAG_MISSING, f, NULL, NULL);
		else
			e.known[i] = store_value(&e, f, e.item[i]);
		if (f->needed && !e.known[i])
			usable = false;
	}
	check_rules(&e);
	check_id(&e, index);
	if (k == CATALOG_MOTOR)
		usable &= check_integrated(&e);
	if (k == CATALOG_PROP) {
		struct catalog_prop *p = (struct catalog_prop *)(void *)base;
		p->diameter_m = p->diameter_in * M_PER_IN;
		p->pitch_m = p->pitch_in * M_PER_IN;
	}
	((struct catalog_motor *)(void *)base)->usable = usable;  /* common prefix */
}

/* ---- one file ------------------------------------------------------------- */

char *
catalog_io_path(const char *dir, enum catalog_category k)
{
	size_t dl = strlen(dir);
	char *path = xmalloc(dl + strlen(catalog_io_files[k]) + 2);
	sprintf(path, "%s%s%s", dir, dl > 0 && dir[dl - 1] == '/' ? "" : "/",
	        catalog_io_files[k]);
	return path;
}

bool
catalog_io_absent(const char *path, enum catalog_category k)
{
	struct stat st;
	return !catalog_io_required(k) && lstat(path, &st) != 0 && errno == ENOENT;
}

/* Reads category k's file into the catalogue; all errors go to ld->dg. */
static void
load_file(struct load *ld, const char *dir, enum catalog_category k)
{
	char *path = catalog_io_path(dir, k);
	ld->path[k] = path;
	if (catalog_io_absent(path, k))
		return;
	struct json_in *ji = json_in_load(path, JSON_IN_CATALOG_MAX, ld->dg);
	if (ji == NULL)
		return;
	ld->ji[k] = ji;
	const cJSON *root = json_in_root(ji);
	const char *const top[] = { array_keys[k], NULL };
	json_in_check_keys(ji, root, "", top, 0);
	const cJSON *arr = cJSON_GetObjectItemCaseSensitive(root, array_keys[k]);
	if (arr == NULL) {
		json_in_report(ji, DIAG_MISSING, NULL, JSON_IN_FILE, array_keys[k],
		               " (the file holds {\"%s\": [...]})", array_keys[k]);
		return;
	}
	if (!json_in_expect(ji, arr, array_keys[k], cJSON_Array, "an array"))
		return;
	size_t n = 0, size = catalog_entry_size(k);
	for (const cJSON *el = arr->child; el != NULL; el = el->next)
		n++;
	char *items = xcalloc(n > 0 ? n : 1, size);
	size_t i = 0;
	for (const cJSON *el = arr->child; el != NULL; el = el->next, i++)
		parse_entry(ld, k, ji, el, i, items + i * size);
	catalog_adopt(ld->c, k, items, n);
}

/* ---- public --------------------------------------------------------------- */

void
catalog_io_fingerprint(const char *const text[CATALOG_N_CATEGORIES],
                       const size_t len[CATALOG_N_CATEGORIES], char *hex)
{
	struct sha256_ctx c;
	unsigned char digest[SHA256_DIGEST_LEN];
	sha256_init(&c);
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		if (text[k] == NULL)
			continue;
		size_t n = len[k];
		unsigned char len8[8];
		for (int i = 0; i < 8; i++)
			len8[i] = (unsigned char)((uint64_t)n >> (8 * i));
		sha256_update(&c, catalog_io_files[k], strlen(catalog_io_files[k]) + 1);
		sha256_update(&c, len8, sizeof len8);
		sha256_update(&c, text[k], n);
	}
	sha256_final(&c, digest);
	sha256_to_hex(digest, hex);
}

/* The fingerprint of the files ld read into hex. */
static void
hash_files(const struct load *ld, char *hex)
{
	const char *text[CATALOG_N_CATEGORIES] = { NULL };
	size_t len[CATALOG_N_CATEGORIES] = { 0 };
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++)
		if (ld->ji[k] != NULL)
			text[k] = json_in_text(ld->ji[k], &len[k]);
	catalog_io_fingerprint(text, len, hex);
}

struct catalog *
catalog_io_load(const char *dir, const char *const *known_chemistries,
                struct diag *dg, char *sha256_hex)
{
	struct load ld = { .dg = dg, .chems = known_chemistries != NULL ?
	                   known_chemistries : catalog_default_chemistries };
	int before = diag_n_errors(dg);
	ld.c = catalog_alloc();
	ld.ids = strmap_alloc(1024);
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++)
		load_file(&ld, dir, (enum catalog_category)k);
	bool failed = diag_n_errors(dg) > before;
	if (!failed && sha256_hex != NULL)
		hash_files(&ld, sha256_hex);
	/* The files stay open to here: a duplicate id points at its first use
	 * in another file, and the fingerprint hashes their bytes. */
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		json_in_free(ld.ji[k]);
		free(ld.path[k]);
	}
	strmap_free(ld.ids);
	free(ld.owners);
	if (failed) {
		catalog_free(ld.c);
		return NULL;
	}
	catalog_finish(ld.c);
	return ld.c;
}
