/* model_io.c — strict loader for the reference tables (see model_io.h),
 * reading through json_in. */
#include "input/model_io.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input/json_in.h"
#include "util/jsonw.h"
#include "util/text.h"
#include "util/xalloc.h"

/* Reading context: the file, and the entry being read (its path and
 * object), so every message names file:line:col, entry and field. */
struct rd {
	struct json_in *ji;   /* the file */
	char entry[64];       /* "chemistries[3]", "" at the top level */
	const cJSON *obj;     /* the object the keys below are looked up in */
};

/* "entry.key" (or "key") into buf. */
static const char *
rd_path(const struct rd *r, const char *key, char *buf, size_t n)
{
	json_in_path(buf, n, r->entry, key);
	return buf;
}

/* The value of key in the current object, or NULL after reporting it
 * missing (with what it should be). */
static const cJSON *
rd_get(struct rd *r, const char *key, const char *what)
{
	char path[128];
	const cJSON *v = cJSON_GetObjectItemCaseSensitive(r->obj, key);
	if (v == NULL)
		json_in_report(r->ji, DIAG_MISSING, r->obj, JSON_IN_VALUE,
		               rd_path(r, key, path, sizeof path), " (%s)", what);
	return v;
}

/* A number in [lo, hi]; lo after reporting when missing or invalid. */
static double
rd_num(struct rd *r, const char *key, double lo, double hi)
{
	char path[128], what[80], src[64];
	snprintf(what, sizeof what, "a number from %g to %g", lo, hi);
	const cJSON *v = rd_get(r, key, what);
	rd_path(r, key, path, sizeof path);
	if (v == NULL || !json_in_expect(r->ji, v, path, cJSON_Number, "a number") ||
	    !json_in_check_number(r->ji, v, path))
		return lo;
	if (v->valuedouble < lo || v->valuedouble > hi) {
		json_in_source(r->ji, v, src, sizeof src);
		json_in_report(r->ji, DIAG_RANGE, v, JSON_IN_VALUE, path,
		               ": %s (allowed %g to %g)", src, lo, hi);
		return lo;
	}
	return v->valuedouble;
}

static int
rd_int(struct rd *r, const char *key, int lo, int hi)
{
	char path[128];
	double d = rd_num(r, key, lo, hi);
	if (d != floor(d)) {
		json_in_report(r->ji, DIAG_NOT_INTEGER, cJSON_GetObjectItemCaseSensitive(r->obj, key),
		               JSON_IN_VALUE, rd_path(r, key, path, sizeof path), " (got %g)", d);
		return lo;
	}
	return (int)d;
}

/* A string of at most n - 1 bytes into out ("" after reporting). */
static void
rd_str(struct rd *r, const char *key, char *out, size_t n)
{
	char path[128];
	const cJSON *v = rd_get(r, key, "a string");
	out[0] = '\0';
	rd_path(r, key, path, sizeof path);
	if (v == NULL || !json_in_expect(r->ji, v, path, cJSON_String, "a string") ||
	    !json_in_check_string(r->ji, v, path, n - 1, JSON_IN_NO_CONTROL))
		return;
	strcpy(out, v->valuestring);
}

static bool
rd_bool(struct rd *r, const char *key)
{
	char path[128];
	const cJSON *v = rd_get(r, key, "true or false");
	rd_path(r, key, path, sizeof path);
	return v != NULL && json_in_expect(r->ji, v, path, cJSON_True | cJSON_False,
	                                   "true or false") && cJSON_IsTrue(v);
}

/* An enum spelled by a string; -1 after reporting. */
static int
rd_enum(struct rd *r, const char *key, const char *const *table)
{
	char s[64], path[128], list[512], q[96];
	rd_str(r, key, s, sizeof s);
	if (s[0] == '\0')
		return -1;
	int i = spec_enum_index(table, s);
	if (i < 0) {
		diag_quote(s, strlen(s), 40, q, sizeof q);
		text_join(table, list, sizeof list);
		json_in_report(r->ji, DIAG_BAD_ENUM, cJSON_GetObjectItemCaseSensitive(r->obj, key),
		               JSON_IN_VALUE, rd_path(r, key, path, sizeof path),
		               " %s (allowed: %s)", q, list);
	}
	return i;
}

/* The array `key` of the root object, or NULL after reporting. */
static const cJSON *
rd_array(struct rd *r, const char *key)
{
	r->entry[0] = '\0';
	r->obj = json_in_root(r->ji);
	const cJSON *a = rd_get(r, key, "an array");
	if (a == NULL || !json_in_expect(r->ji, a, key, cJSON_Array, "an array"))
		return NULL;
	return a;
}

/* Enter element i of array `array`: NULL after reporting when it is not an
 * object; else its keys are checked against keys (NULL-terminated). */
static const cJSON *
rd_entry(struct rd *r, const char *array, int i, const cJSON *item,
         const char *const *keys)
{
	json_in_path_index(r->entry, sizeof r->entry, array, (size_t)i);
	r->obj = item;
	if (!json_in_expect(r->ji, item, r->entry, cJSON_Object, "an object"))
		return NULL;
	json_in_check_keys(r->ji, item, r->entry, keys, JSON_IN_COMMENTS);
	return item;
}

/* An error about the entry itself (no single field). */
static void
rd_error(struct rd *r, enum diag_kind kind, const char *key, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));

static void
rd_error(struct rd *r, enum diag_kind kind, const char *key, const char *fmt, ...)
{
	char path[128];
	const cJSON *at = key != NULL ? cJSON_GetObjectItemCaseSensitive(r->obj, key) : NULL;
	va_list ap;
	va_start(ap, fmt);
	json_in_vreport(r->ji, kind, at != NULL ? at : r->obj, JSON_IN_VALUE,
	                key != NULL ? rd_path(r, key, path, sizeof path) : r->entry, fmt, ap);
	va_end(ap);
}

static void
path_join(char *out, size_t n, const char *dir, const char *file)
{
	snprintf(out, n, "%s/%s", dir, file);
}

static void
load_chemistries(struct rd *r, struct model_data *m)
{
	static const char *const keys[] = { "name", "specific_energy_wh_kg",
		"specific_power_w_kg", "r_cell_mohm", "v_full_v", "v_nominal_v",
		"v_exp_v", "b", "k_v", "v_cutoff_v", "packaging", "source",
		"pack_specific_energy_wh_kg_at_100wh_6s", "pack_energy_exponent",
		"pack_series_exponent",
		"pack_source", NULL };
	static const char *const pack[] = { "pouch", "cylindrical", NULL };
	const cJSON *a = rd_array(r, "chemistries");
	if (a == NULL)
		return;
	int i = 0;
	const cJSON *it;
	cJSON_ArrayForEach(it, a) {
		if (i >= MODEL_MAX_CHEM) {
			json_in_report(r->ji, DIAG_TOO_MANY, it, JSON_IN_VALUE, "chemistries",
			               " (at most %d chemistries)", MODEL_MAX_CHEM);
			break;
		}
		if (rd_entry(r, "chemistries", i, it, keys) == NULL) {
			i++;
			continue;
		}
		struct batt_chem *c = &m->chem[i];
		rd_str(r, "name", c->name, sizeof c->name);
		c->e_spec_wh_kg = rd_num(r, "specific_energy_wh_kg", 20, 1000);
		c->p_spec_w_kg = rd_num(r, "specific_power_w_kg", 50, 20000);
		c->r_cell_mohm = rd_num(r, "r_cell_mohm", 0.1, 500);
		c->v_full = rd_num(r, "v_full_v", 1, 6);
		c->v_nom = rd_num(r, "v_nominal_v", 1, 6);
		c->v_exp = rd_num(r, "v_exp_v", 1, 6);
		c->b = rd_num(r, "b", 0.1, 100);
		c->k = rd_num(r, "k_v", 0, 1);
		c->v_cutoff = rd_num(r, "v_cutoff_v", 0.5, 6);
		c->pouch = rd_enum(r, "packaging", pack) == 0;
		c->pack_wh_kg_100 = rd_num(r, "pack_specific_energy_wh_kg_at_100wh_6s", 20, 1000);
		c->pack_exponent = rd_num(r, "pack_energy_exponent", 0, 0.5);
		c->pack_series_exponent = rd_num(r, "pack_series_exponent", 0, 0.5);
		if (c->v_cutoff >= c->v_nom || c->v_nom >= c->v_full)
			rd_error(r, DIAG_INCONSISTENT, "v_cutoff_v",
			         ": the voltages must satisfy cutoff < nominal < full");
		/* At most MODEL_MAX_CHEM names: a scan of the earlier ones. */
		for (int j = 0; j < i && c->name[0] != '\0'; j++)
			if (strcmp(m->chem[j].name, c->name) == 0)
				rd_error(r, DIAG_DUPLICATE_ID, "name", " \"%s\" (first given by "
				         "chemistries[%d])", c->name, j);
		m->chem_names[i] = m->chem[i].name;
		i++;
	}
	m->n_chem = i;
	m->chem_names[i] = NULL;
	if (i == 0)
		json_in_report(r->ji, DIAG_MISSING_ENTRY, a, JSON_IN_VALUE, "chemistries",
		               " (at least one chemistry)");
}

/* Every value of `names` (ROLE_MAX or AF_CLASS_MAX of them) has an entry. */
static void
rd_all_present(struct rd *r, const char *array, const bool *seen,
               const char *const *names, int n)
{
	const cJSON *a = cJSON_GetObjectItemCaseSensitive(json_in_root(r->ji), array);
	for (int k = 0; k < n; k++)
		if (!seen[k])
			json_in_report(r->ji, DIAG_MISSING_ENTRY, a, JSON_IN_VALUE, array,
			               " \"%s\"", names[k]);
}

/* Keys of a duty profile that only some profiles read: present where the
 * profile does not read it is an error (the numbers would be ignored). */
static void
duty_unread(struct rd *r, const char *const *keys, enum duty_kind kind)
{
	for (int i = 0; keys[i] != NULL; i++)
		if (cJSON_GetObjectItemCaseSensitive(r->obj, keys[i]) != NULL)
			rd_error(r, DIAG_INCONSISTENT, keys[i], ": not read by the "
			         "\"%s\" profile", duty_kind_name[kind]);
}

/* The laps of a race: pieces whose shares sum to 1. */
static void
load_lap(struct rd *r, struct model_duty *d)
{
	static const char *const keys[] = { "name", "share", "power_fraction",
		"note", NULL };
	char path[64];
	const cJSON *a = rd_get(r, "lap", "an array of lap pieces");
	rd_path(r, "lap", path, sizeof path);
	if (a == NULL || !json_in_expect(r->ji, a, path, cJSON_Array, "an array"))
		return;
	struct rd sub = *r;
	double sum = 0.0;
	int i = 0;
	const cJSON *it;
	cJSON_ArrayForEach(it, a) {
		if (i >= MODEL_MAX_LAP) {
			json_in_report(r->ji, DIAG_TOO_MANY, it, JSON_IN_VALUE, path,
			               " (at most %d lap pieces)", MODEL_MAX_LAP);
			break;
		}
		if (rd_entry(&sub, path, i, it, keys) == NULL) {
			i++;
			continue;
		}
		struct model_lap_piece *pc = &d->lap[i];
		rd_str(&sub, "name", pc->name, sizeof pc->name);
		pc->share = rd_num(&sub, "share", 0.001, 1);
		pc->power_fraction = rd_num(&sub, "power_fraction", 0.001, 1);
		sum += pc->share;
		i++;
	}
	d->n_lap = i;
	if (i == 0)
		json_in_report(r->ji, DIAG_MISSING_ENTRY, a, JSON_IN_VALUE, path,
		               " (at least one lap piece)");
	else if (fabs(sum - 1.0) > 1e-6)
		rd_error(r, DIAG_INCONSISTENT, "lap", ": the pieces' shares sum to "
		         "%g, not 1", sum);
}

/* A role's duty profile: the object "duty" of its entry. */
static void
load_duty(struct rd *r, struct model_duty *d)
{
	static const char *const keys[] = { "profile", "source", "lap_s", "lap",
		"swath_length_m", "turn_accel_m_s2", "turn_yaw_s", "transit_m",
		"note", NULL };
	static const char *const race_keys[] = { "lap_s", "lap", NULL };
	static const char *const spray_keys[] = { "swath_length_m",
		"turn_accel_m_s2", "turn_yaw_s", "transit_m", NULL };
	char path[64];
	memset(d, 0, sizeof *d);
	const cJSON *o = rd_get(r, "duty", "an object: the role's duty profile");
	rd_path(r, "duty", path, sizeof path);
	if (o == NULL || !json_in_expect(r->ji, o, path, cJSON_Object, "an object"))
		return;
	struct rd sub = *r;
	snprintf(sub.entry, sizeof sub.entry, "%s", path);
	sub.obj = o;
	json_in_check_keys(r->ji, o, sub.entry, keys, JSON_IN_COMMENTS);
	int k = rd_enum(&sub, "profile", duty_kind_name);
	d->kind = k < 0 ? DUTY_PHASES : (enum duty_kind)k;
	rd_str(&sub, "source", d->source, sizeof d->source);
	if (d->kind == DUTY_RACE) {
		d->lap_s = rd_num(&sub, "lap_s", 1, 600);
		load_lap(&sub, d);
	} else {
		duty_unread(&sub, race_keys, d->kind);
	}
	if (d->kind == DUTY_SPRAY) {
		d->swath_length_m = rd_num(&sub, "swath_length_m", 1, 5000);
		d->turn_accel_m_s2 = rd_num(&sub, "turn_accel_m_s2", 0.1, 20);
		d->turn_yaw_s = rd_num(&sub, "turn_yaw_s", 0, 60);
		d->transit_m = rd_num(&sub, "transit_m", 0, 10000);
	} else {
		duty_unread(&sub, spray_keys, d->kind);
	}
}

static void
load_roles(struct rd *r, struct model_data *m)
{
	static const char *const keys[] = { "name", "thrust_to_weight",
		"thrust_to_weight_source", "load_factor", "aux_power_w",
		"aux_reference_mass_kg", "added_drag_m2", "forward_drag_multiplier",
		"integration_overhead_frac", "c_motor", "c_esc", "h_conv_w_m2k",
		"battery_burst_factor", "shedding", "duty", "note", NULL };
	static const char *const shed[] = { "none", "drop", "spray", NULL };
	bool seen[ROLE_MAX] = { false };
	const cJSON *a = rd_array(r, "roles");
	if (a == NULL)
		return;
	int i = 0;
	const cJSON *it;
	cJSON_ArrayForEach(it, a) {
		if (rd_entry(r, "roles", i++, it, keys) == NULL)
			continue;
		int k = rd_enum(r, "name", spec_enum_role);
		if (k < 0)
			continue;
		if (seen[k])
			rd_error(r, DIAG_DUPLICATE_ID, "name", " \"%s\" (a role is given once)",
			         spec_enum_role[k]);
		seen[k] = true;
		struct model_role *ro = &m->role[k];
		/* The requirement is stored as the T/W real aircraft of the role
		 * fly; the engine works in the paper's thrust margin,
		 * T/W = 1 / (1 - margin)². */
		double tw = rd_num(r, "thrust_to_weight", 1.2, 25);
		ro->thrust_margin = 1.0 - 1.0 / sqrt(tw);
		ro->load_factor = rd_num(r, "load_factor", 1, 20);
		ro->aux_power_w = rd_num(r, "aux_power_w", 0, 5000);
		ro->aux_ref_kg = rd_num(r, "aux_reference_mass_kg", 0.01, 1000);
		ro->added_drag_m2 = rd_num(r, "added_drag_m2", 0, 5);
		ro->forward_drag_multiplier = rd_num(r, "forward_drag_multiplier", 0.1, 10);
		ro->integration_frac = rd_num(r, "integration_overhead_frac", 0, 2);
		ro->c_motor = rd_num(r, "c_motor", 0.01, 10);
		ro->c_esc = rd_num(r, "c_esc", 0.01, 10);
		ro->h_conv_w_m2k = rd_num(r, "h_conv_w_m2k", 1, 1000);
		ro->burst_factor = rd_num(r, "battery_burst_factor", 1, 10);
		int sh = rd_enum(r, "shedding", shed);
		ro->shedding = sh < 0 ? SHED_NONE : (enum shed_kind)sh;
		load_duty(r, &ro->duty);
	}
	rd_all_present(r, "roles", seen, spec_enum_role, ROLE_MAX);
}

static void
load_classes(struct rd *r, struct model_data *m)
{
	static const char *const keys[] = { "name", "gamma", "avionics_share",
		"cells_min", "cells_max", "small_platform", "note", NULL };
	bool seen[AF_CLASS_MAX] = { false };
	const cJSON *a = rd_array(r, "classes");
	if (a == NULL)
		return;
	int i = 0;
	const cJSON *it;
	cJSON_ArrayForEach(it, a) {
		if (rd_entry(r, "classes", i++, it, keys) == NULL)
			continue;
		int k = rd_enum(r, "name", spec_enum_airframe);
		if (k < 0)
			continue;
		if (seen[k])
			rd_error(r, DIAG_DUPLICATE_ID, "name", " \"%s\" (a class is given once)",
			         spec_enum_airframe[k]);
		seen[k] = true;
		struct model_class *c = &m->cls[k];
		c->gamma = rd_num(r, "gamma", 0, 5);
		c->avionics_share = rd_num(r, "avionics_share", 0, 1);
		c->cells_min = rd_int(r, "cells_min", 1, 24);
		c->cells_max = rd_int(r, "cells_max", 1, 24);
		c->small_platform = rd_bool(r, "small_platform");
		if (c->cells_min > c->cells_max)
			rd_error(r, DIAG_INCONSISTENT, "cells_min", ": %d > cells_max %d",
			         c->cells_min, c->cells_max);
	}
	rd_all_present(r, "classes", seen, spec_enum_airframe, AF_CLASS_MAX);
}

static const char *const lambda_keys[LAMBDA_MAX + 1] = { "MicroAIO",
	"ConsumerFolding", "EnterpriseRugged_quad", "EnterpriseRugged_multi",
	"Agricultural", NULL };

/* Enter the object at key of the current one (reported when it is not an
 * object), checking its keys; false when absent or not an object. */
static bool
rd_enter(struct rd *r, const char *key, const char *const *keys, bool required)
{
	const cJSON *o = cJSON_GetObjectItemCaseSensitive(r->obj, key);
	if (o == NULL && !required)
		return false;
	if (o == NULL)
		o = rd_get(r, key, "an object");
	char path[64];
	json_in_path(path, sizeof path, r->entry, key);
	if (o == NULL || !json_in_expect(r->ji, o, path, cJSON_Object, "an object"))
		return false;
	snprintf(r->entry, sizeof r->entry, "%s", path);
	r->obj = o;
	json_in_check_keys(r->ji, o, path, keys, JSON_IN_COMMENTS);
	return true;
}

static void
load_interval(struct rd *r, struct model_interval *iv)
{
	iv->n = rd_int(r, "n", 1, 1000000);
	iv->log_lo = rd_num(r, "log_lo", -5, 0);
	iv->log_hi = rd_num(r, "log_hi", 0, 5);
}

static const char *const accuracy_keys[MODEL_BASIS_MAX] = {
	"accuracy_from_endurance", "accuracy_pack_locked",
};

/* An optional accuracy block that `calibrate --write` adds. */
static void
load_accuracy(struct rd *r, const char *key, struct model_accuracy *a)
{
	static const char *const keys[] = { "cohort_rows", "loo_mtow_mape_pct",
		"battery_rows", "loo_battery_mape_pct", "level", "coverage", "pooled",
		"by_class", "design_rows", "design_coverage", "design_width", NULL };
	static const char *const iv_keys[] = { "n", "log_lo", "log_hi", NULL };
	const cJSON *root = r->obj;
	if (!rd_enter(r, key, keys, false))
		return;
	const cJSON *acc = r->obj;
	a->valid = true;
	a->n_rows = rd_int(r, "cohort_rows", 1, 1000000);
	a->loo_mape_pct = rd_num(r, "loo_mtow_mape_pct", 0, 1000);
	a->n_battery = rd_int(r, "battery_rows", 0, 1000000);
	a->loo_battery_mape_pct = rd_num(r, "loo_battery_mape_pct", 0, 1000);
	a->level = rd_num(r, "level", 0.5, 0.99);
	a->coverage = rd_num(r, "coverage", 0, 1);
	a->design_rows = rd_int(r, "design_rows", 0, 1000000);
	a->design_coverage = rd_num(r, "design_coverage", 0, 1);
	a->design_width = rd_num(r, "design_width", 0, 1e6);
	if (rd_enter(r, "pooled", iv_keys, true))
		load_interval(r, &a->pooled);
	snprintf(r->entry, sizeof r->entry, "%s", key);
	r->obj = acc;
	if (rd_enter(r, "by_class", spec_enum_airframe, false)) {
		const cJSON *bc = r->obj;
		for (int k = 0; k < AF_CLASS_MAX; k++) {
			snprintf(r->entry, sizeof r->entry, "%s.by_class", key);
			r->obj = bc;
			if (rd_enter(r, spec_enum_airframe[k], iv_keys, false))
				load_interval(r, &a->cls[k]);
		}
	}
	r->entry[0] = '\0';
	r->obj = root;
}

/* An optional spread block ("forward_check", "dry_mass") that
 * `calibrate --write` adds. */
static void
load_spread(struct rd *r, const char *key, struct model_spread *sp)
{
	static const char *const keys[] = { "rows", "loo_mape_pct", "level",
		"log_lo", "log_hi", "coverage", NULL };
	const cJSON *root = r->obj;
	if (rd_enter(r, key, keys, false)) {
		sp->valid = true;
		sp->n = rd_int(r, "rows", 1, 1000000);
		sp->mape_pct = rd_num(r, "loo_mape_pct", 0, 1000);
		sp->level = rd_num(r, "level", 0.5, 0.99);
		sp->log_lo = rd_num(r, "log_lo", -5, 0);
		sp->log_hi = rd_num(r, "log_hi", 0, 5);
		sp->coverage = rd_num(r, "coverage", 0, 1);
	}
	r->entry[0] = '\0';
	r->obj = root;
}

static void
load_calibration(struct rd *r, struct model_calibration *cal)
{
	static const char *const keys[] = { "lambda_class",
		"wiring_coefficient_kg_per_a_m", "small_wiring_coefficient_kg_per_a_m",
		"equipment_kg_at_1kg", "equipment_exponent", "kappa", "drive_efficiency",
		"reynolds_reference", "aux_power_scale", "drag_area_scale", "forward_wake_share",
		"accuracy_from_endurance", "accuracy_pack_locked", "forward_check",
		"dry_mass", NULL };
	const cJSON *root = json_in_root(r->ji);
	memset(cal, 0, sizeof *cal);
	r->entry[0] = '\0';
	r->obj = root;
	json_in_check_keys(r->ji, root, "", keys, JSON_IN_COMMENTS);
	if (rd_enter(r, "lambda_class", lambda_keys, true))
		for (int k = 0; k < LAMBDA_MAX; k++)
			cal->lambda[k] = rd_num(r, lambda_keys[k], 0.2, 5);
	r->entry[0] = '\0';
	r->obj = root;
	if (rd_enter(r, "equipment_kg_at_1kg", spec_enum_airframe, true))
		for (int k = 0; k < AF_CLASS_MAX; k++)
			cal->equip_kg[k] = rd_num(r, spec_enum_airframe[k], 0, 2);
	r->entry[0] = '\0';
	r->obj = root;
	cal->equip_exponent = rd_num(r, "equipment_exponent", 0.3, 1.5);
	cal->kappa = rd_num(r, "kappa", 1, 3);
	cal->eta_drive = rd_num(r, "drive_efficiency", 0.3, 1);
	cal->re_ref = rd_num(r, "reynolds_reference", 1000, 1e7);
	cal->aux_scale = rd_num(r, "aux_power_scale", 0.05, 20);
	cal->drag_scale = rd_num(r, "drag_area_scale", 0.05, 20);
	cal->wake_share = rd_num(r, "forward_wake_share", 0, 1);
	cal->wire_coef = rd_num(r, "wiring_coefficient_kg_per_a_m", 0, 0.1);
	cal->wire_coef_small = rd_num(r, "small_wiring_coefficient_kg_per_a_m", 0, 0.1);
	for (int b = 0; b < MODEL_BASIS_MAX; b++)
		load_accuracy(r, accuracy_keys[b], &cal->accuracy[b]);
	load_spread(r, "forward_check", &cal->forward);
	load_spread(r, "dry_mass", &cal->dry);
}

static void
load_requirements(struct rd *r, struct model_data *m)
{
	static const char *const top[] = { "payload_presets", "transports",
		"coaxial_disk_loading_n_m2", "priorities", NULL };
	static const char *const pkeys[] = { "name", "payload_kg", "role", "label", NULL };
	static const char *const tkeys[] = { "name", "max_wheelbase_m",
		"airframe_class", "label", NULL };
	static const char *const qkeys[] = { "name", "battery_chemistry", "v_forward", NULL };
	static const char *const vf[] = { "keep", "auto", NULL };
	const cJSON *a, *it;
	int i;
	r->entry[0] = '\0';
	r->obj = json_in_root(r->ji);
	json_in_check_keys(r->ji, r->obj, "", top, JSON_IN_COMMENTS);
	m->coaxial_disk_loading_n_m2 = rd_num(r, "coaxial_disk_loading_n_m2", 10, 5000);
	if ((a = rd_array(r, "payload_presets")) != NULL) {
		i = 0;
		cJSON_ArrayForEach(it, a) {
			if (rd_entry(r, "payload_presets", i++, it, pkeys) == NULL)
				continue;
			int k = rd_enum(r, "name", spec_enum_preset);
			if (k <= 0) {
				if (k == 0)
					rd_error(r, DIAG_BAD_ENUM, "name", " \"none\" (not a preset)");
				continue;
			}
			struct model_preset *p = &m->preset[k];
			p->payload_kg = rd_num(r, "payload_kg", 0, 500);
			p->role = rd_enum(r, "role", spec_enum_role);
			rd_str(r, "label", p->label, sizeof p->label);
		}
	}
	if ((a = rd_array(r, "transports")) != NULL) {
		i = 0;
		cJSON_ArrayForEach(it, a) {
			if (rd_entry(r, "transports", i++, it, tkeys) == NULL)
				continue;
			int k = rd_enum(r, "name", spec_enum_transport);
			if (k <= 0)
				continue;
			struct model_transport *t = &m->transport[k];
			t->max_wheelbase_m = rd_num(r, "max_wheelbase_m", 0.05, 5);
			t->airframe_class = rd_enum(r, "airframe_class", spec_enum_airframe);
			rd_str(r, "label", t->label, sizeof t->label);
		}
	}
	if ((a = rd_array(r, "priorities")) != NULL) {
		i = 0;
		cJSON_ArrayForEach(it, a) {
			if (rd_entry(r, "priorities", i++, it, qkeys) == NULL)
				continue;
			int k = rd_enum(r, "name", spec_enum_priority);
			if (k <= 0)
				continue;
			struct model_priority *q = &m->priority[k];
			rd_str(r, "battery_chemistry", q->chemistry, sizeof q->chemistry);
			if (q->chemistry[0] && model_chem(m, q->chemistry) == NULL)
				rd_error(r, DIAG_BAD_CHEMISTRY, "battery_chemistry", " \"%s\"",
				         q->chemistry);
			q->v_auto = rd_enum(r, "v_forward", vf) == 1;
		}
	}
}

static void
load_calibration_into_model(struct rd *r, struct model_data *m)
{
	load_calibration(r, &m->cal);
}

/* Read one file of dir with loader fn; returns the errors reported. */
static int
load_file(const char *dir, const char *name, struct diag *dg, struct model_data *m,
          void (*fn)(struct rd *, struct model_data *))
{
	char path[4096];
	int before = diag_n_errors(dg);
	path_join(path, sizeof path, dir, name);
	struct rd r = { .ji = json_in_load(path, JSON_IN_DATA_MAX, dg) };
	if (r.ji != NULL)
		fn(&r, m);
	json_in_free(r.ji);
	return diag_n_errors(dg) - before;
}

int
model_io_load(const char *dir, struct model_data *out, struct diag *dg)
{
	int n = 0;
	memset(out, 0, sizeof *out);
	n += load_file(dir, "chemistries.json", dg, out, load_chemistries);
	n += load_file(dir, "roles.json", dg, out, load_roles);
	n += load_file(dir, "airframes.json", dg, out, load_classes);
	n += load_file(dir, "calibration.json", dg, out, load_calibration_into_model);
	n += load_file(dir, "requirements.json", dg, out, load_requirements);
	return n;
}

int
model_io_load_calibration(const char *path, struct model_calibration *cal,
                          struct diag *dg)
{
	int before = diag_n_errors(dg);
	struct rd r = { .ji = json_in_load(path, JSON_IN_DATA_MAX, dg) };
	if (r.ji != NULL)
		load_calibration(&r, cal);
	json_in_free(r.ji);
	return diag_n_errors(dg) - before;
}

static void
add_interval(cJSON *parent, const char *key, const struct model_interval *iv)
{
	cJSON *o = cJSON_AddObjectToObject(parent, key);
	cJSON_AddNumberToObject(o, "n", iv->n);
	cJSON_AddNumberToObject(o, "log_lo", iv->log_lo);
	cJSON_AddNumberToObject(o, "log_hi", iv->log_hi);
}

char *
model_io_calibration_json(const struct model_calibration *cal)
{
	cJSON *root = cJSON_CreateObject();
	cJSON_AddStringToObject(root, "_comment",
	    "The calibrated coefficients, fitted by `aeroeval calibrate --write` "
	    "on the calibration cohort only, then frozen: the structural "
	    "multiplier lambda and the installed-FoM penalty kappa per class "
	    "(paper eq. lambda, Table classes), the wiring "
	    "coefficient (paper Sec. V-C) and the equipment law "
	    "e_class (M_design / 1 kg)^exponent (docs/model.md).  The accuracy "
	    "blocks are the leave-one-out error on that cohort, sized from the "
	    "endurance or with the published pack locked, and the "
	    "split-conformal interval on ln(actual / predicted) built from it.");
	cJSON *l = cJSON_AddObjectToObject(root, "lambda_class");
	for (int k = 0; k < LAMBDA_MAX; k++)
		cJSON_AddNumberToObject(l, lambda_keys[k], cal->lambda[k]);
	cJSON_AddNumberToObject(root, "wiring_coefficient_kg_per_a_m", cal->wire_coef);
	cJSON_AddNumberToObject(root, "small_wiring_coefficient_kg_per_a_m", cal->wire_coef_small);
	cJSON *e = cJSON_AddObjectToObject(root, "equipment_kg_at_1kg");
	for (int k = 0; k < AF_CLASS_MAX; k++)
		cJSON_AddNumberToObject(e, spec_enum_airframe[k], cal->equip_kg[k]);
	cJSON_AddNumberToObject(root, "equipment_exponent", cal->equip_exponent);
	cJSON_AddNumberToObject(root, "kappa", cal->kappa);
	cJSON_AddNumberToObject(root, "drive_efficiency", cal->eta_drive);
	cJSON_AddNumberToObject(root, "reynolds_reference", cal->re_ref);
	cJSON_AddNumberToObject(root, "aux_power_scale", cal->aux_scale);
	cJSON_AddNumberToObject(root, "drag_area_scale", cal->drag_scale);
	cJSON_AddNumberToObject(root, "forward_wake_share", cal->wake_share);
	for (int b = 0; b < MODEL_BASIS_MAX; b++) {
		const struct model_accuracy *a = &cal->accuracy[b];
		if (!a->valid)
			continue;
		cJSON *o = cJSON_AddObjectToObject(root, accuracy_keys[b]);
		cJSON_AddNumberToObject(o, "cohort_rows", a->n_rows);
		cJSON_AddNumberToObject(o, "loo_mtow_mape_pct", a->loo_mape_pct);
		cJSON_AddNumberToObject(o, "battery_rows", a->n_battery);
		cJSON_AddNumberToObject(o, "loo_battery_mape_pct", a->loo_battery_mape_pct);
		cJSON_AddNumberToObject(o, "level", a->level);
		cJSON_AddNumberToObject(o, "coverage", a->coverage);
		cJSON_AddNumberToObject(o, "design_rows", a->design_rows);
		cJSON_AddNumberToObject(o, "design_coverage", a->design_coverage);
		cJSON_AddNumberToObject(o, "design_width", a->design_width);
		add_interval(o, "pooled", &a->pooled);
		cJSON *bc = cJSON_AddObjectToObject(o, "by_class");
		for (int k = 0; k < AF_CLASS_MAX; k++)
			if (a->cls[k].n > 0)
				add_interval(bc, spec_enum_airframe[k], &a->cls[k]);
	}
	const struct model_spread *sp[] = { &cal->forward, &cal->dry };
	static const char *const sp_key[] = { "forward_check", "dry_mass" };
	for (int i = 0; i < 2; i++) {
		if (!sp[i]->valid)
			continue;
		cJSON *o = cJSON_AddObjectToObject(root, sp_key[i]);
		cJSON_AddNumberToObject(o, "rows", sp[i]->n);
		cJSON_AddNumberToObject(o, "loo_mape_pct", sp[i]->mape_pct);
		cJSON_AddNumberToObject(o, "level", sp[i]->level);
		cJSON_AddNumberToObject(o, "log_lo", sp[i]->log_lo);
		cJSON_AddNumberToObject(o, "log_hi", sp[i]->log_hi);
		cJSON_AddNumberToObject(o, "coverage", sp[i]->coverage);
	}
	char *txt = jsonw_print(root, NULL);
	cJSON_Delete(root);
	return txt;
}
