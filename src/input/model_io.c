/* model_io.c — strict loader for the reference tables (see model_io.h). */
#include "input/model_io.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "util/xalloc.h"

/* Reading context: the file being read and the entry being read, so every
 * message names file, entry and field. */
struct rd {
	const char *file;   /* path as given */
	char entry[96];     /* e.g. chemistries[3] "LiPo" */
	FILE *err;
	int n_err;
};

static void rd_error(struct rd *r, const char *field, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void
rd_error(struct rd *r, const char *field, const char *fmt, ...)
{
	va_list ap;
	bool has_field = field != NULL && *field != '\0';
	fprintf(r->err, "%s: error: %s%s%s%s", r->file, r->entry,
	    (*r->entry && has_field) ? "." : "", has_field ? field : "",
	    (*r->entry || has_field) ? ": " : "");
	va_start(ap, fmt);
	vfprintf(r->err, fmt, ap);
	va_end(ap);
	fputc('\n', r->err);
	r->n_err++;
}

/* Read a whole file and parse it strictly; NULL after reporting. */
static cJSON *
rd_parse(struct rd *r)
{
	FILE *f = fopen(r->file, "rb");
	if (f == NULL) {
		rd_error(r, NULL, "cannot open (%s)", strerror(errno));
		return NULL;
	}
	size_t cap = 4096, n = 0;
	char *buf = xmalloc(cap);
	size_t got;
	while ((got = fread(buf + n, 1, cap - n - 1, f)) > 0) {
		n += got;
		if (n + 1 >= cap) {
			cap *= 2;
			buf = xrealloc(buf, cap);
		}
	}
	fclose(f);
	buf[n] = '\0';
	const char *end = NULL;
	cJSON *root = cJSON_ParseWithLengthOpts(buf, n + 1, &end, 1);
	if (root == NULL) {
		size_t off = end ? (size_t)(end - buf) : 0, line = 1, col = 1;
		for (size_t i = 0; i < off && i < n; i++) {
			if (buf[i] == '\n') {
				line++;
				col = 1;
			} else if (((unsigned char)buf[i] & 0xC0) != 0x80) {
				col++;
			}
		}
		fprintf(r->err, "%s:%zu:%zu: error: malformed JSON near here\n",
		    r->file, line, col);
		r->n_err++;
	}
	free(buf);
	return root;
}

/* Unknown keys are typos: refuse them.  `allowed` is NULL-terminated. */
static void
rd_keys(struct rd *r, const cJSON *obj, const char *const *allowed)
{
	for (const cJSON *c = obj->child; c != NULL; c = c->next) {
		bool ok = c->string[0] == '_'; /* "_comment", "_note" */
		for (int i = 0; !ok && allowed[i] != NULL; i++)
			ok = strcmp(c->string, allowed[i]) == 0;
		if (!ok)
			rd_error(r, c->string, "unknown field");
	}
}

static double
rd_num(struct rd *r, const cJSON *obj, const char *key, double lo, double hi)
{
	const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
	if (v == NULL) {
		rd_error(r, key, "missing (a number in [%g, %g])", lo, hi);
		return lo;
	}
	if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble)) {
		rd_error(r, key, "must be a number");
		return lo;
	}
	if (v->valuedouble < lo || v->valuedouble > hi) {
		rd_error(r, key, "out of range (got %g, allowed [%g, %g])",
		    v->valuedouble, lo, hi);
		return lo;
	}
	return v->valuedouble;
}

static int
rd_int(struct rd *r, const cJSON *obj, const char *key, int lo, int hi)
{
	double d = rd_num(r, obj, key, lo, hi);
	if (d != floor(d)) {
		rd_error(r, key, "must be an integer (got %g)", d);
		return lo;
	}
	return (int)d;
}

static void
rd_str(struct rd *r, const cJSON *obj, const char *key, char *out, size_t n)
{
	const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
	out[0] = '\0';
	if (v == NULL) {
		rd_error(r, key, "missing (a string)");
		return;
	}
	if (!cJSON_IsString(v)) {
		rd_error(r, key, "must be a string");
		return;
	}
	if (strlen(v->valuestring) >= n) {
		rd_error(r, key, "too long (at most %zu bytes)", n - 1);
		return;
	}
	strcpy(out, v->valuestring);
}

static bool
rd_bool(struct rd *r, const cJSON *obj, const char *key)
{
	const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
	if (v == NULL || !cJSON_IsBool(v)) {
		rd_error(r, key, v == NULL ? "missing (true or false)" : "must be true or false");
		return false;
	}
	return cJSON_IsTrue(v);
}

/* An enum spelled by a string; -1 after reporting. */
static int
rd_enum(struct rd *r, const cJSON *obj, const char *key,
        const char *const *table)
{
	char s[64];
	rd_str(r, obj, key, s, sizeof s);
	if (s[0] == '\0')
		return -1;
	int i = spec_enum_index(table, s);
	if (i < 0)
		rd_error(r, key, "unknown value \"%s\"", s);
	return i;
}

/* The array `key` at the top of root, or NULL after reporting. */
static const cJSON *
rd_array(struct rd *r, const cJSON *root, const char *key)
{
	if (!cJSON_IsObject(root)) {
		rd_error(r, NULL, "top level must be an object");
		return NULL;
	}
	const cJSON *a = cJSON_GetObjectItemCaseSensitive(root, key);
	if (!cJSON_IsArray(a)) {
		rd_error(r, key, "missing array");
		return NULL;
	}
	return a;
}

static void
rd_entry(struct rd *r, const char *array, int i, const cJSON *item)
{
	const cJSON *nm = cJSON_GetObjectItemCaseSensitive(item, "name");
	if (cJSON_IsString(nm))
		snprintf(r->entry, sizeof r->entry, "%s[%d] \"%.40s\"", array, i,
		    nm->valuestring);
	else
		snprintf(r->entry, sizeof r->entry, "%s[%d]", array, i);
}

static void
path_join(char *out, size_t n, const char *dir, const char *file)
{
	snprintf(out, n, "%s/%s", dir, file);
}

static void
load_chemistries(struct rd *r, const cJSON *root, struct model_data *m)
{
	static const char *const keys[] = { "name", "specific_energy_wh_kg",
		"specific_power_w_kg", "r_cell_mohm", "v_full_v", "v_nominal_v",
		"v_exp_v", "b", "k_v", "v_cutoff_v", "packaging", "source", NULL };
	static const char *const pack[] = { "pouch", "cylindrical", NULL };
	const cJSON *a = rd_array(r, root, "chemistries");
	if (a == NULL)
		return;
	int i = 0;
	const cJSON *it;
	cJSON_ArrayForEach(it, a) {
		rd_entry(r, "chemistries", i, it);
		if (i >= MODEL_MAX_CHEM) {
			rd_error(r, NULL, "too many chemistries (at most %d)", MODEL_MAX_CHEM);
			break;
		}
		if (!cJSON_IsObject(it)) {
			rd_error(r, NULL, "must be an object");
			i++;
			continue;
		}
		struct batt_chem *c = &m->chem[i];
		rd_keys(r, it, keys);
		rd_str(r, it, "name", c->name, sizeof c->name);
		c->e_spec_wh_kg = rd_num(r, it, "specific_energy_wh_kg", 20, 1000);
		c->p_spec_w_kg = rd_num(r, it, "specific_power_w_kg", 50, 20000);
		c->r_cell_mohm = rd_num(r, it, "r_cell_mohm", 0.1, 500);
		c->v_full = rd_num(r, it, "v_full_v", 1, 6);
		c->v_nom = rd_num(r, it, "v_nominal_v", 1, 6);
		c->v_exp = rd_num(r, it, "v_exp_v", 1, 6);
		c->b = rd_num(r, it, "b", 0.1, 100);
		c->k = rd_num(r, it, "k_v", 0, 1);
		c->v_cutoff = rd_num(r, it, "v_cutoff_v", 0.5, 6);
		c->pouch = rd_enum(r, it, "packaging", pack) == 0;
		if (c->v_cutoff >= c->v_nom || c->v_nom >= c->v_full)
			rd_error(r, "v_cutoff_v", "voltages must satisfy cutoff < nominal < full");
		for (int j = 0; j < i; j++)
			if (strcmp(m->chem[j].name, c->name) == 0)
				rd_error(r, "name", "duplicate chemistry");
		m->chem_names[i] = m->chem[i].name;
		i++;
	}
	m->n_chem = i;
	m->chem_names[i] = NULL;
	if (i == 0) {
		r->entry[0] = '\0';
		rd_error(r, "chemistries", "empty");
	}
}

static void
load_roles(struct rd *r, const cJSON *root, struct model_data *m)
{
	static const char *const keys[] = { "name", "thrust_margin", "load_factor",
		"aux_power_w", "added_drag_m2", "forward_drag_multiplier",
		"integration_overhead_frac", "c_motor", "c_esc", "h_conv_w_m2k",
		"battery_burst_factor", "shedding", "note", NULL };
	static const char *const shed[] = { "none", "drop", "spray", NULL };
	bool seen[ROLE_MAX] = { false };
	const cJSON *a = rd_array(r, root, "roles");
	if (a == NULL)
		return;
	int i = 0;
	const cJSON *it;
	cJSON_ArrayForEach(it, a) {
		rd_entry(r, "roles", i++, it);
		if (!cJSON_IsObject(it)) {
			rd_error(r, NULL, "must be an object");
			continue;
		}
		rd_keys(r, it, keys);
		int k = rd_enum(r, it, "name", spec_enum_role);
		if (k < 0)
			continue;
		if (seen[k])
			rd_error(r, "name", "duplicate role");
		seen[k] = true;
		struct model_role *ro = &m->role[k];
		ro->thrust_margin = rd_num(r, it, "thrust_margin", 0.05, 0.8);
		ro->load_factor = rd_num(r, it, "load_factor", 1, 20);
		ro->aux_power_w = rd_num(r, it, "aux_power_w", 0, 5000);
		ro->added_drag_m2 = rd_num(r, it, "added_drag_m2", 0, 5);
		ro->forward_drag_multiplier = rd_num(r, it, "forward_drag_multiplier", 0.1, 10);
		ro->integration_frac = rd_num(r, it, "integration_overhead_frac", 0, 2);
		ro->c_motor = rd_num(r, it, "c_motor", 0.01, 10);
		ro->c_esc = rd_num(r, it, "c_esc", 0.01, 10);
		ro->h_conv_w_m2k = rd_num(r, it, "h_conv_w_m2k", 1, 1000);
		ro->burst_factor = rd_num(r, it, "battery_burst_factor", 1, 10);
		int s = rd_enum(r, it, "shedding", shed);
		ro->shedding = s < 0 ? SHED_NONE : (enum shed_kind)s;
	}
	r->entry[0] = '\0';
	for (int k = 0; k < ROLE_MAX; k++)
		if (!seen[k])
			rd_error(r, "roles", "role \"%s\" is missing", spec_enum_role[k]);
}

static void
load_classes(struct rd *r, const cJSON *root, struct model_data *m)
{
	static const char *const keys[] = { "name", "kappa", "gamma", "avionics_kg",
		"cells_min", "cells_max", "small_platform", "shell_kg_m2",
		"fairing_section_frac", "note", NULL };
	bool seen[AF_CLASS_MAX] = { false };
	const cJSON *a = rd_array(r, root, "classes");
	if (a == NULL)
		return;
	int i = 0;
	const cJSON *it;
	cJSON_ArrayForEach(it, a) {
		rd_entry(r, "classes", i++, it);
		if (!cJSON_IsObject(it)) {
			rd_error(r, NULL, "must be an object");
			continue;
		}
		rd_keys(r, it, keys);
		int k = rd_enum(r, it, "name", spec_enum_airframe);
		if (k < 0)
			continue;
		if (seen[k])
			rd_error(r, "name", "duplicate class");
		seen[k] = true;
		struct model_class *c = &m->cls[k];
		c->kappa = rd_num(r, it, "kappa", 1, 3);
		c->gamma = rd_num(r, it, "gamma", 0, 5);
		c->avionics_kg = rd_num(r, it, "avionics_kg", 0, 20);
		c->shell_kg_m2 = rd_num(r, it, "shell_kg_m2", 0, 50);
		c->fairing_section_frac = rd_num(r, it, "fairing_section_frac", 0, 0.5);
		c->cells_min = rd_int(r, it, "cells_min", 1, 24);
		c->cells_max = rd_int(r, it, "cells_max", 1, 24);
		c->small_platform = rd_bool(r, it, "small_platform");
		if (c->cells_min > c->cells_max)
			rd_error(r, "cells_min", "must not exceed cells_max");
	}
	r->entry[0] = '\0';
	for (int k = 0; k < AF_CLASS_MAX; k++)
		if (!seen[k])
			rd_error(r, "classes", "class \"%s\" is missing", spec_enum_airframe[k]);
}

static const char *const lambda_keys[LAMBDA_MAX + 1] = { "MicroAIO",
	"ConsumerFolding", "EnterpriseRugged_quad", "EnterpriseRugged_multi",
	"Agricultural", NULL };

static void
load_calibration(struct rd *r, const cJSON *root, struct model_calibration *cal)
{
	static const char *const keys[] = { "lambda_class", "battery_packaging_base",
		"wiring_coefficient_kg_per_a_m", "small_wiring_coefficient_kg_per_a_m", NULL };
	if (!cJSON_IsObject(root)) {
		rd_error(r, NULL, "top level must be an object");
		return;
	}
	rd_keys(r, root, keys);
	const cJSON *l = cJSON_GetObjectItemCaseSensitive(root, "lambda_class");
	if (!cJSON_IsObject(l)) {
		rd_error(r, "lambda_class", "missing object");
	} else {
		snprintf(r->entry, sizeof r->entry, "lambda_class");
		rd_keys(r, l, lambda_keys);
		for (int k = 0; k < LAMBDA_MAX; k++)
			cal->lambda[k] = rd_num(r, l, lambda_keys[k], 0.2, 5);
		r->entry[0] = '\0';
	}
	cal->packaging_base = rd_num(r, root, "battery_packaging_base", 0.8, 2);
	cal->wire_coef = rd_num(r, root, "wiring_coefficient_kg_per_a_m", 0, 0.1);
	cal->wire_coef_small = rd_num(r, root, "small_wiring_coefficient_kg_per_a_m", 0, 0.1);
}

static void
load_requirements(struct rd *r, const cJSON *root, struct model_data *m)
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
	if (!cJSON_IsObject(root)) {
		rd_error(r, NULL, "top level must be an object");
		return;
	}
	rd_keys(r, root, top);
	m->coaxial_disk_loading_n_m2 = rd_num(r, root, "coaxial_disk_loading_n_m2", 10, 5000);
	if ((a = rd_array(r, root, "payload_presets")) != NULL) {
		i = 0;
		cJSON_ArrayForEach(it, a) {
			rd_entry(r, "payload_presets", i++, it);
			rd_keys(r, it, pkeys);
			int k = rd_enum(r, it, "name", spec_enum_preset);
			if (k <= 0) {
				if (k == 0)
					rd_error(r, "name", "\"none\" is not a preset");
				continue;
			}
			struct model_preset *p = &m->preset[k];
			p->payload_kg = rd_num(r, it, "payload_kg", 0, 500);
			p->role = rd_enum(r, it, "role", spec_enum_role);
			rd_str(r, it, "label", p->label, sizeof p->label);
		}
	}
	if ((a = rd_array(r, root, "transports")) != NULL) {
		i = 0;
		cJSON_ArrayForEach(it, a) {
			rd_entry(r, "transports", i++, it);
			rd_keys(r, it, tkeys);
			int k = rd_enum(r, it, "name", spec_enum_transport);
			if (k <= 0)
				continue;
			struct model_transport *t = &m->transport[k];
			t->max_wheelbase_m = rd_num(r, it, "max_wheelbase_m", 0.05, 5);
			t->airframe_class = rd_enum(r, it, "airframe_class", spec_enum_airframe);
			rd_str(r, it, "label", t->label, sizeof t->label);
		}
	}
	if ((a = rd_array(r, root, "priorities")) != NULL) {
		i = 0;
		cJSON_ArrayForEach(it, a) {
			rd_entry(r, "priorities", i++, it);
			rd_keys(r, it, qkeys);
			int k = rd_enum(r, it, "name", spec_enum_priority);
			if (k <= 0)
				continue;
			struct model_priority *q = &m->priority[k];
			rd_str(r, it, "battery_chemistry", q->chemistry, sizeof q->chemistry);
			if (q->chemistry[0] && model_chem(m, q->chemistry) == NULL)
				rd_error(r, "battery_chemistry", "unknown chemistry \"%s\"", q->chemistry);
			q->v_auto = rd_enum(r, it, "v_forward", vf) == 1;
		}
	}
	r->entry[0] = '\0';
}

/* Read one file of dir with loader fn. */
static int
load_file(const char *dir, const char *name, FILE *err, struct model_data *m,
          void (*fn)(struct rd *, const cJSON *, struct model_data *))
{
	char path[4096];
	path_join(path, sizeof path, dir, name);
	struct rd r = { path, "", err, 0 };
	cJSON *root = rd_parse(&r);
	if (root != NULL)
		fn(&r, root, m);
	cJSON_Delete(root);
	return r.n_err;
}

static void
load_calibration_into_model(struct rd *r, const cJSON *root, struct model_data *m)
{
	load_calibration(r, root, &m->cal);
}

int
model_io_load(const char *dir, struct model_data *out, FILE *err)
{
	int n = 0;
	memset(out, 0, sizeof *out);
	n += load_file(dir, "chemistries.json", err, out, load_chemistries);
	n += load_file(dir, "roles.json", err, out, load_roles);
	n += load_file(dir, "airframes.json", err, out, load_classes);
	n += load_file(dir, "calibration.json", err, out, load_calibration_into_model);
	n += load_file(dir, "requirements.json", err, out, load_requirements);
	return n;
}

int
model_io_load_calibration(const char *path, struct model_calibration *cal,
                          FILE *err)
{
	struct rd r = { path, "", err, 0 };
	cJSON *root = rd_parse(&r);
	if (root != NULL)
		load_calibration(&r, root, cal);
	cJSON_Delete(root);
	return r.n_err;
}

char *
model_io_calibration_json(const struct model_calibration *cal)
{
	cJSON *root = cJSON_CreateObject();
	cJSON_AddStringToObject(root, "_comment",
	    "The three calibrated coefficients (paper Sec. VII-A), fitted by "
	    "`aeroeval calibrate` on the calibration cohort only, then frozen.");
	cJSON *l = cJSON_AddObjectToObject(root, "lambda_class");
	for (int k = 0; k < LAMBDA_MAX; k++)
		cJSON_AddNumberToObject(l, lambda_keys[k], cal->lambda[k]);
	cJSON_AddNumberToObject(root, "battery_packaging_base", cal->packaging_base);
	cJSON_AddNumberToObject(root, "wiring_coefficient_kg_per_a_m", cal->wire_coef);
	cJSON_AddNumberToObject(root, "small_wiring_coefficient_kg_per_a_m", cal->wire_coef_small);
	char *txt = cJSON_Print(root);
	cJSON_Delete(root);
	char *copy = xstrdup(txt);
	free(txt);
	return copy;
}
