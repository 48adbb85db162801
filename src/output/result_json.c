/* result_json.c — result.json writer (see result_json.h for the format).
 *
 * The text is produced by a small streaming writer of our own rather than
 * cJSON_Print: cJSON prints numbers with %1.15g and a relative-epsilon
 * re-parse test, so 0.1+0.2 comes out as 0.3 and 2^53 is off by two
 * (STACK.md §7); result.json must give back every double exactly.  The
 * writer also tracks the JSON path of the value being written, so an
 * invalid value can be named in the internal-error message.
 */
#include "output/result_json.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output/bom_csv.h"
#include "util/numfmt.h"
#include "util/xalloc.h"

#define JW_MAX_DEPTH 12   /* deepest nesting written is 5 (top.run.phases[i].x) */
#define JW_PACK      10   /* plain numbers per line in a packed array */

/* One open object or array. */
struct jw_frame {
	bool array;       /* array (else object) */
	bool packed;      /* scalar array written JW_PACK values to a line */
	int n;            /* members written so far */
	size_t path_len;  /* length of jw.path before this container's step */
};

/* The writer: output text, open containers, current path, faults. */
struct jw {
	char *buf;                        /* output, NUL-terminated */
	size_t len;                       /* bytes used */
	size_t cap;                       /* bytes allocated */
	int depth;                        /* open containers */
	struct jw_frame st[JW_MAX_DEPTH];
	char path[RESULT_JSON_PATH_MAX];  /* ".custom.phases[2]" of the open container */
	size_t path_len;
	struct result_json_faults faults;
};

/* ---- output bytes ---------------------------------------------------------- */

static void
jw_put(struct jw *w, const char *s, size_t n)
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
jw_puts(struct jw *w, const char *s)
{
	jw_put(w, s, strlen(s));
}

static void
jw_newline(struct jw *w, int depth)
{
	static const char spaces[] = "                        "; /* 2 x JW_MAX_DEPTH */
	_Static_assert(sizeof spaces - 1 == 2 * JW_MAX_DEPTH, "indent table");
	jw_put(w, "\n", 1);
	jw_put(w, spaces, (size_t)(2 * depth));
}

/* ---- paths and faults ------------------------------------------------------ */

/* Appends to w->path the step that leads to the value now being written:
 * ".key" inside an object, "[i]" inside an array.  Truncates silently: the
 * path is only for a message. */
static void
jw_path_step(struct jw *w, const char *key)
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

/* Records an invalid value at key, or at the array element just begun
 * (call after jw_begin so the index is right). */
static void
jw_fault(struct jw *w, const char *key)
{
	if (w->faults.n_invalid++ > 0)
		return;
	size_t keep = w->path_len;
	if (w->depth > 0)
		jw_path_step(w, key);
	const char *p = w->path[0] == '.' ? w->path + 1 : w->path;
	snprintf(w->faults.first_path, sizeof w->faults.first_path, "%s", p);
	w->path_len = keep;
	w->path[keep] = '\0';
}

/* ---- structure ------------------------------------------------------------- */

static void jw_string(struct jw *w, const char *s, size_t max);

/* Separator, line break and key before a value; key is NULL in an array. */
static void
jw_begin(struct jw *w, const char *key)
{
	if (w->depth == 0)
		return;
	struct jw_frame *f = &w->st[w->depth - 1];
	assert(f->array == (key == NULL));
	if (f->n > 0)
		jw_put(w, ",", 1);
	if (f->packed && f->n % JW_PACK != 0)
		jw_put(w, " ", 1);
	else
		jw_newline(w, w->depth);
	f->n++;
	if (key) {
		jw_string(w, key, strlen(key));
		jw_put(w, ": ", 2);
	}
}

static void
jw_open(struct jw *w, const char *key, bool array, bool packed)
{
	assert(w->depth < JW_MAX_DEPTH);
	jw_begin(w, key);
	size_t before = w->path_len;
	if (w->depth > 0)
		jw_path_step(w, key);
	w->st[w->depth++] = (struct jw_frame){ array, packed, 0, before };
	jw_put(w, array ? "[" : "{", 1);
}

static void
jw_obj(struct jw *w, const char *key)
{
	jw_open(w, key, false, false);
}

static void
jw_arr(struct jw *w, const char *key)
{
	jw_open(w, key, true, false);
}

/* An array of plain numbers or strings, packed JW_PACK to a line. */
static void
jw_arr_packed(struct jw *w, const char *key)
{
	jw_open(w, key, true, true);
}

static void
jw_close(struct jw *w)
{
	assert(w->depth > 0);
	struct jw_frame *f = &w->st[--w->depth];
	if (f->n > 0)
		jw_newline(w, w->depth);
	jw_put(w, f->array ? "]" : "}", 1);
	w->path_len = f->path_len;
	w->path[w->path_len] = '\0';
}

/* ---- scalars --------------------------------------------------------------- */

/* Writes s (at most max bytes, stopping at NUL) as a JSON string. */
static void
jw_string(struct jw *w, const char *s, size_t max)
{
	const unsigned char *p = (const unsigned char *)s;
	size_t n = strnlen(s, max);
	jw_put(w, "\"", 1);
	for (size_t i = 0; i < n;) {
		/* A run of printable ASCII needs no escape: one copy for it. */
		size_t run = i;
		while (run < n && p[run] >= 0x20 && p[run] < 0x80 && p[run] != '"' && p[run] != '\\')
			run++;
		if (run > i) {
			jw_put(w, s + i, run - i);
			i = run;
			continue;
		}
		unsigned c = p[i];
		char esc[8];
		if (c == '"' || c == '\\') {
			esc[0] = '\\';
			esc[1] = (char)c;
			jw_put(w, esc, 2);
			i++;
			continue;
		}
		if (c < 0x20) {
			switch (c) {
			case '\b': jw_puts(w, "\\b"); break;
			case '\f': jw_puts(w, "\\f"); break;
			case '\n': jw_puts(w, "\\n"); break;
			case '\r': jw_puts(w, "\\r"); break;
			case '\t': jw_puts(w, "\\t"); break;
			default:
				snprintf(esc, sizeof esc, "\\u%04x", c);
				jw_puts(w, esc);
			}
			i++;
			continue;
		}
		/* UTF-8: the length of a well-formed sequence (RFC 3629 table,
		 * no overlongs, no surrogates, nothing above U+10FFFF). */
		size_t len = 0;
		unsigned lo = 0x80, hi = 0xBF;
		if (c < 0x80)
			len = 1;
		else if (c >= 0xC2 && c <= 0xDF)
			len = 2;
		else if (c >= 0xE0 && c <= 0xEF) {
			len = 3;
			if (c == 0xE0)
				lo = 0xA0;
			if (c == 0xED)
				hi = 0x9F;
		} else if (c >= 0xF0 && c <= 0xF4) {
			len = 4;
			if (c == 0xF0)
				lo = 0x90;
			if (c == 0xF4)
				hi = 0x8F;
		}
		bool ok = len > 0 && i + len <= n;
		for (size_t k = 1; ok && k < len; k++) {
			unsigned b = p[i + k];
			unsigned l = k == 1 ? lo : 0x80, h = k == 1 ? hi : 0xBF;
			ok = b >= l && b <= h;
		}
		if (ok) {
			jw_put(w, s + i, len);
			i += len;
		} else {
			jw_puts(w, "\xEF\xBF\xBD"); /* U+FFFD for the one bad byte */
			i++;
		}
	}
	jw_put(w, "\"", 1);
}

static void
jw_str(struct jw *w, const char *key, const char *s, size_t max)
{
	jw_begin(w, key);
	jw_string(w, s, max);
}

/* A char-array member: bounded by its size, so a missing NUL cannot
 * overrun.  A pointer member (a string literal) is no array: JW_STR on one
 * fails to compile, and it goes through jw_lit(). */
#define JW_IS_ARRAY(a) \
	(!__builtin_types_compatible_p(__typeof__(a), __typeof__(&(a)[0])))
#define JW_STR(w, key, arr) \
	jw_str((w), (key), (arr), sizeof(arr) * sizeof(char[JW_IS_ARRAY(arr) ? 1 : -1]))

/* A string literal's text (NULL: empty). */
static void
jw_lit(struct jw *w, const char *key, const char *s)
{
	jw_str(w, key, s != NULL ? s : "", s != NULL ? strlen(s) + 1 : 1);
}

static void
jw_null(struct jw *w, const char *key)
{
	jw_begin(w, key);
	jw_puts(w, "null");
}

static void
jw_bool(struct jw *w, const char *key, bool b)
{
	jw_begin(w, key);
	jw_puts(w, b ? "true" : "false");
}

static void
jw_int(struct jw *w, const char *key, int v)
{
	char t[16];
	jw_begin(w, key);
	snprintf(t, sizeof t, "%d", v);
	jw_puts(w, t);
}

static void
jw_num(struct jw *w, const char *key, double x)
{
	char t[NUMFMT_SHORTEST_LEN];
	jw_begin(w, key);
	if (!isfinite(x)) {
		jw_fault(w, key);
		jw_puts(w, "null");
		return;
	}
	numfmt_shortest(t, x);
	jw_puts(w, t);
}

/* A price: 0 means unknown and is written as null. */
static void
jw_price(struct jw *w, const char *key, double usd)
{
	if (usd == 0.0)
		jw_null(w, key);
	else
		jw_num(w, key, usd);
}

/* An enum value spelled from a NULL-terminated table; out of range is a fault. */
static void
jw_enum(struct jw *w, const char *key, int v, const char *const *names)
{
	int n = 0;
	while (names[n])
		n++;
	jw_begin(w, key);
	if (v < 0 || v >= n) {
		jw_fault(w, key);
		jw_puts(w, "null");
		return;
	}
	jw_string(w, names[v], strlen(names[v]));
}

static void
jw_phase(struct jw *w, const char *key, int phase)
{
	jw_begin(w, key);
	if (phase < 0 || phase >= PHASE_MAX) {
		jw_fault(w, key);
		jw_puts(w, "null");
		return;
	}
	jw_string(w, res_phase_name[phase], strlen(res_phase_name[phase]));
}

/* A count from the struct, clamped to 0..max; outside is a fault. */
static int
jw_count(struct jw *w, const char *key, int n, int max)
{
	if (n >= 0 && n <= max)
		return n;
	jw_fault(w, key);
	return n < 0 ? 0 : max;
}

static void
jw_num_array(struct jw *w, const char *key, const double *x, int n)
{
	jw_arr_packed(w, key);
	for (int i = 0; i < n; i++)
		jw_num(w, NULL, x[i]);
	jw_close(w);
}

/* ---- mission --------------------------------------------------------------- */

/* One mission field under its leaf name (the part after the last dot). */
static void
put_field(struct jw *w, const struct mission_spec *s,
          const struct spec_field_info *f)
{
	const char *dot = strrchr(f->path, '.');
	const char *key = dot ? dot + 1 : f->path;
	const void *p = spec_member_const(s, f);
	switch (f->type) {
	case SPEC_NUM:
		jw_num(w, key, *(const double *)p);
		break;
	case SPEC_SPEED:
		/* The only speed field is v_forward_ms; "auto" is kept as given. */
		assert(f->id == SPECF_V_FORWARD_MS);
		if (s->v_forward_auto)
			jw_str(w, key, "auto", 4);
		else
			jw_num(w, key, *(const double *)p);
		break;
	case SPEC_INT:
		jw_int(w, key, *(const int *)p);
		break;
	case SPEC_BOOL:
		jw_bool(w, key, *(const bool *)p);
		break;
	case SPEC_ENUM:
		jw_enum(w, key, *(const int *)p, f->enums);
		break;
	case SPEC_STR:
	case SPEC_DATE:
		jw_str(w, key, (const char *)p, SPEC_STR_MAX);
		break;
	}
}

/* The fully resolved mission, every field of spec_fields[] nested by its
 * dotted path (one level: "locks.locked_kv" goes into "locks"), groups in
 * the order of their first field, then "defaulted": the paths the file did
 * not set. */
static void
put_mission(struct jw *w, const struct mission_spec *s)
{
	bool done[SPEC_N_FIELDS] = { false };
	jw_obj(w, "mission");
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		if (done[i])
			continue;
		const char *path = spec_fields[i].path;
		const char *dot = strchr(path, '.');
		if (!dot) {
			put_field(w, s, &spec_fields[i]);
			continue;
		}
		assert(strchr(dot + 1, '.') == NULL); /* one level of nesting */
		size_t glen = (size_t)(dot - path);
		char group[64];
		snprintf(group, sizeof group, "%.*s", (int)glen, path);
		jw_obj(w, group);
		for (size_t j = i; j < SPEC_N_FIELDS; j++) {
			const char *pj = spec_fields[j].path;
			if (strncmp(pj, path, glen + 1) == 0) {
				put_field(w, s, &spec_fields[j]);
				done[j] = true;
			}
		}
		jw_close(w);
	}
	jw_arr(w, "defaulted");
	for (size_t i = 0; i < SPEC_N_FIELDS; i++)
		if (!s->given[i])
			jw_str(w, NULL, spec_fields[i].path, strlen(spec_fields[i].path));
	jw_close(w);
	jw_close(w);
}

/* ---- runs ------------------------------------------------------------------ */

/* Total and breakdown, as members of the open object. */
static void
put_mass(struct jw *w, const struct res_mass *m)
{
	jw_num(w, "total_mass_kg", m->total_kg);
	jw_num(w, "payload_kg", m->payload_kg);
	jw_num(w, "battery_mass_kg", m->battery_kg);
	jw_num(w, "frame_mass_kg", m->frame_kg);
	jw_num(w, "arm_mass_kg", m->arm_kg);
	jw_num(w, "motor_mass_kg", m->motor_kg);
	jw_num(w, "prop_mass_kg", m->prop_kg);
	jw_num(w, "esc_mass_kg", m->esc_kg);
	jw_num(w, "wiring_mass_kg", m->wiring_kg);
	jw_num(w, "avionics_mass_kg", m->avionics_kg);
	jw_num(w, "role_aux_mass_kg", m->role_aux_kg);
	jw_num(w, "other_mass_kg", m->other_kg);
}

static void
put_optimum(struct jw *w, const char *key, const struct res_optimum *o)
{
	jw_obj(w, key);
	jw_num(w, "prop_diameter_in", o->prop_diameter_in);
	jw_num(w, "prop_pitch_in", o->prop_pitch_in);
	jw_num(w, "motor_kv", o->motor_kv);
	jw_num(w, "motor_mass_kg", o->motor_mass_kg);
	jw_num(w, "motor_peak_current_a", o->motor_peak_current_a);
	jw_num(w, "motor_peak_power_w", o->motor_peak_power_w);
	jw_close(w);
}

static void
put_phases(struct jw *w, const struct res_run *run)
{
	jw_arr(w, "phases");
	for (int i = 0; i < PHASE_MAX; i++) {
		const struct res_phase *p = &run->phase[i];
		jw_obj(w, NULL);
		jw_str(w, "phase", res_phase_name[i], strlen(res_phase_name[i]));
		jw_num(w, "duration_s", p->duration_s);
		jw_num(w, "power_w", p->power_w);
		jw_num(w, "current_a", p->current_a);
		jw_num(w, "energy_wh", p->energy_wh);
		jw_num(w, "speed_ms", p->speed_ms);
		jw_num(w, "thrust_per_rotor_n", p->thrust_per_rotor_n);
		jw_num(w, "shaft_power_w", p->shaft_power_w);
		jw_num(w, "rpm", p->rpm);
		jw_num(w, "throttle", p->throttle);
		jw_num(w, "pitch_deg", p->pitch_deg);
		jw_num(w, "tip_mach", p->tip_mach);
		jw_close(w);
	}
	jw_close(w);
}

/* One column of the discharge trace: the double at byte offset `off` of
 * every sample. */
static void
put_trace_column(struct jw *w, const char *key, const struct res_sample *t,
                 int n, size_t off)
{
	jw_arr_packed(w, key);
	for (int i = 0; i < n; i++)
		jw_num(w, NULL, *(const double *)((const char *)&t[i] + off));
	jw_close(w);
}

/* The discharge trace as columns (not a list of objects: 9 x 600 values). */
static void
put_time_series(struct jw *w, const struct res_run *run)
{
	int n = jw_count(w, "time_series", run->n_trace, RES_MAX_TRACE);
	const struct res_sample *t = run->trace;
	jw_obj(w, "time_series");
	jw_int(w, "n", n);
	put_trace_column(w, "t_s", t, n, offsetof(struct res_sample, t_s));
	put_trace_column(w, "soc", t, n, offsetof(struct res_sample, soc));
	put_trace_column(w, "v_oc_v", t, n, offsetof(struct res_sample, v_oc_v));
	put_trace_column(w, "v_term_v", t, n, offsetof(struct res_sample, v_term_v));
	put_trace_column(w, "current_a", t, n, offsetof(struct res_sample, current_a));
	put_trace_column(w, "power_w", t, n, offsetof(struct res_sample, power_w));
	put_trace_column(w, "temp_c", t, n, offsetof(struct res_sample, temp_c));
	put_trace_column(w, "mass_kg", t, n, offsetof(struct res_sample, mass_kg));
	jw_arr_packed(w, "phase");
	for (int i = 0; i < n; i++)
		jw_phase(w, NULL, t[i].phase);
	jw_close(w);
	jw_close(w);
}

static void
put_checks(struct jw *w, const struct res_run *run)
{
	int n = jw_count(w, "checks", run->n_checks, RES_MAX_CHECKS);
	jw_arr(w, "checks");
	for (int i = 0; i < n; i++) {
		const struct res_check *c = &run->checks[i];
		jw_obj(w, NULL);
		jw_lit(w, "code", c->code);
		jw_lit(w, "name", c->name);
		jw_lit(w, "condition", c->condition);
		jw_str(w, "basis", c->basis, sizeof c->basis);
		jw_lit(w, "unit", c->unit);
		jw_num(w, "value", c->value);
		jw_num(w, "limit", c->limit);
		jw_str(w, "kind", c->upper ? "max" : "min", 3);
		jw_num(w, "margin", c->margin);
		jw_bool(w, "pass", c->pass);
		jw_bool(w, "sized_to_limit", c->sized);
		jw_close(w);
	}
	jw_close(w);
}

static void put_selected(struct jw *w, const struct solve_result *r);
static void put_bom(struct jw *w, const struct solve_result *r);

/* One sized run; {"ran": false} when the gate stopped it.  parts is the
 * result whose real-parts selection this run's design is (the custom and
 * BOM-closed runs), or NULL for a run that is not mapped to parts (the
 * baseline): its "selected" and "bom" are then null. */
static void put_run_fields(struct jw *w, const struct res_run *run,
                           const struct solve_result *parts, const char *prop_key);

static void
put_run(struct jw *w, const char *key, const struct res_run *run,
        const struct solve_result *parts)
{
	jw_obj(w, key);
	put_run_fields(w, run, parts, "continuous_optimum");
	jw_close(w);
}

/* The fields of one run, into the object open in w; prop_key names its
 * propeller-and-motor block. */
static void
put_run_fields(struct jw *w, const struct res_run *run,
               const struct solve_result *parts, const char *prop_key)
{
	jw_bool(w, "ran", run->ran);
	if (!run->ran)
		return;
	jw_bool(w, "feasible", run->feasible);
	jw_bool(w, "converged", run->converged);
	jw_int(w, "iterations", run->iterations);
	JW_STR(w, "termination", run->termination);

	put_mass(w, &run->mass);
	int nh = jw_count(w, "convergence_history", run->n_history, RES_MAX_HISTORY);
	jw_num_array(w, "convergence_history", run->history_kg, nh);
	jw_num(w, "lipschitz_estimate", run->lipschitz);
	jw_num(w, "time_scale", run->time_scale);
	jw_num(w, "thrust_margin", run->thrust_margin);
	jw_num(w, "aux_power_w", run->aux_power_w);

	JW_STR(w, "chemistry", run->chemistry);
	jw_int(w, "cell_count", run->cell_count);
	jw_int(w, "pack_count", run->pack_count);
	jw_num(w, "battery_capacity_mah", run->capacity_mah);
	jw_num(w, "energy_wh", run->energy_wh);
	jw_num(w, "packaging_factor", run->packaging_factor);
	jw_bool(w, "battery_power_binds", run->battery_power_binds);
	jw_num(w, "nominal_voltage_v", run->nominal_voltage_v);

	put_phases(w, run);
	jw_num(w, "approved_hover_time_s", run->approved_time_s[PHASE_HOVER]);
	jw_num(w, "approved_climb_time_s", run->approved_time_s[PHASE_CLIMB]);
	jw_num(w, "approved_forward_time_s", run->approved_time_s[PHASE_FORWARD]);
	jw_num(w, "flight_time_s", run->flight_time_s);
	jw_num(w, "hover_endurance_s", run->hover_endurance_s);
	jw_num(w, "hover_power_w", run->hover_power_w);
	jw_num(w, "marketing_endurance_s", run->marketing_endurance_s);
	jw_num(w, "optimal_speed_ms", run->optimal_speed_ms);
	jw_num(w, "v_min_power_ms", run->v_min_power_ms);
	jw_num(w, "v_max_ms", run->v_max_ms);
	int ns = jw_count(w, "speed_sweep", run->n_sweep, RES_MAX_SWEEP);
	jw_obj(w, "speed_sweep");
	jw_num_array(w, "v_ms", run->sweep_v_ms, ns);
	jw_num_array(w, "power_w", run->sweep_power_w, ns);
	jw_close(w);

	jw_num(w, "thrust_to_weight_ratio", run->thrust_to_weight);
	jw_num(w, "hover_throttle", run->hover_throttle);
	jw_num(w, "forward_pitch_deg", run->forward_pitch_deg);
	jw_num(w, "disk_loading_n_m2", run->disk_loading_n_m2);
	jw_num(w, "downwash_ms", run->downwash_ms);
	jw_num(w, "fom_installed", run->fom_installed);
	jw_num(w, "interference", run->interference);
	jw_num(w, "installation_kappa", run->kappa);
	jw_num(w, "reynolds_tip", run->reynolds_tip);
	jw_num(w, "rpm_hover", run->rpm_hover);
	jw_num(w, "rpm_peak", run->rpm_peak);
	jw_num(w, "tip_mach_peak", run->tip_mach_peak);
	jw_num(w, "overlap_limit_in", run->overlap_limit_in);
	jw_num(w, "peak_power_w", run->peak_power_w);
	jw_num(w, "peak_current_a", run->peak_current_a);
	jw_num(w, "peak_c_rate", run->peak_c_rate);
	/* The run's own propeller and motor: for the baseline and the custom
	 * run their continuous optimum (PRODUCT.md §4), for the design of
	 * record its propulsion (real parts; the continuous optimum it was
	 * aimed at is the top-level "continuous_optimum"). */
	put_optimum(w, prop_key, &run->opt);

	jw_num(w, "arm_length_m", run->arm_length_m);
	jw_num(w, "arm_outer_diameter_mm", run->arm_outer_diameter_mm);
	jw_num(w, "arm_wall_thickness_mm", run->arm_wall_thickness_mm);
	jw_num(w, "arm_stress_mpa", run->arm_stress_mpa);
	jw_num(w, "arm_stress_allow_mpa", run->arm_stress_allow_mpa);
	jw_num(w, "arm_natural_frequency_hz", run->arm_natural_frequency_hz);
	jw_num(w, "blade_pass_frequency_hz", run->blade_pass_frequency_hz);
	jw_num(w, "blade_pass_low_hz", run->blade_pass_low_hz);
	jw_num(w, "resonance_margin", run->resonance_margin);
	jw_num(w, "arm_tip_mass_kg", run->arm_tip_mass_kg);
	jw_bool(w, "arm_wall_floor_binds", run->arm_wall_floor_binds);
	jw_bool(w, "min_fraction_binds", run->min_fraction_binds);

	jw_num(w, "max_battery_temp_c", run->max_battery_temp_c);
	jw_num(w, "thermal_margin_c", run->thermal_margin_c);
	jw_num(w, "min_terminal_voltage_v", run->min_terminal_voltage_v);
	jw_num(w, "voltage_floor_v", run->voltage_floor_v);
	jw_num(w, "end_soc", run->end_soc);
	jw_num(w, "winding_temp_c", run->winding_temp_c);
	jw_num(w, "motor_winding_resistance_ohm", run->motor_winding_resistance_ohm);
	jw_num(w, "motor_copper_loss_w", run->motor_copper_loss_w);
	put_time_series(w, run);

	int ne = jw_count(w, "endurance_explorer", run->n_endurance, RES_MAX_ENDURANCE);
	jw_obj(w, "endurance_explorer");
	jw_num_array(w, "scale", run->endurance_scale, ne);
	jw_num_array(w, "time_s", run->endurance_time_s, ne);
	jw_num_array(w, "mass_kg", run->endurance_mass_kg, ne);
	jw_num(w, "inflection_scale", run->endurance_inflection_scale);
	jw_close(w);

	put_checks(w, run);
	if (parts != NULL) {
		put_selected(w, parts);
		put_bom(w, parts);
	} else {
		jw_null(w, "selected");
		jw_null(w, "bom");
	}
}

/* One operating point of the real drive. */
static void
put_op(struct jw *w, int id, const struct res_op *op)
{
	jw_obj(w, NULL);
	jw_lit(w, "point", res_op_name[id]);
	jw_bool(w, "reachable", op->valid);
	jw_num(w, "thrust_n", op->thrust_n);
	jw_num(w, "rpm", op->rpm);
	jw_num(w, "throttle", op->throttle < 1.0 ? op->throttle : 1.0);
	jw_num(w, "motor_current_a", op->motor_current_a);
	jw_num(w, "motor_voltage_v", op->motor_voltage_v);
	jw_num(w, "motor_input_power_w", op->power_in_w);
	jw_num(w, "shaft_power_w", op->power_shaft_w);
	jw_num(w, "motor_efficiency", op->motor_efficiency);
	jw_num(w, "grams_per_watt", op->g_per_w);
	jw_num(w, "winding_temp_c", op->winding_temp_c);
	jw_num(w, "tip_mach", op->tip_mach);
	jw_num(w, "battery_current_a", op->battery_current_a);
	jw_num(w, "battery_voltage_v", op->bus_voltage_v);
	jw_num(w, "c_load", op->c_load);
	jw_num(w, "electrical_power_w", op->electrical_w);
	jw_close(w);
}

/* What the design on real parts can do: its operating points and figures. */
static void
put_perf(struct jw *w, const struct res_perf *pf)
{
	jw_arr(w, "operating_points");
	for (int i = 0; i < OP_MAX; i++)
		put_op(w, i, &pf->op[i]);
	jw_close(w);
	jw_obj(w, "performance");
	jw_num(w, "hover_time_s", pf->hover_time_s);
	jw_num(w, "mixed_time_s", pf->mixed_time_s);
	jw_num(w, "full_throttle_time_s", pf->full_throttle_time_s);
	jw_num(w, "max_speed_ms", pf->max_speed_ms);
	jw_num(w, "max_climb_ms", pf->max_climb_ms);
	jw_num(w, "max_tilt_deg", pf->max_tilt_deg);
	jw_num(w, "spare_payload_kg", pf->spare_payload_kg);
	jw_num(w, "throttle_needed", pf->throttle_needed);
	jw_num(w, "landing_soc", pf->landing_soc);
	if (pf->motor_out_rotors > 0) {
		jw_obj(w, "motor_out");
		jw_int(w, "rotors_counted", pf->motor_out_rotors);
		jw_num(w, "thrust_over_weight", pf->motor_out_ratio);
		jw_bool(w, "holds_altitude", pf->motor_out_holds);
		jw_close(w);
	} else {
		jw_null(w, "motor_out");
	}
	jw_num(w, "motor_resistance_ohm", pf->motor_resistance_ohm);
	jw_num(w, "motor_no_load_current_a", pf->motor_no_load_a);
	jw_bool(w, "motor_constants_estimated", pf->motor_r_estimated);
	jw_num(w, "prop_ct", pf->prop_ct);
	jw_num(w, "prop_cp", pf->prop_cp);
	jw_bool(w, "prop_coefficients_published", pf->prop_coeffs_measured);
	jw_num(w, "prop_fom_isolated", pf->prop_fom);
	jw_close(w);
}

/* The design of record: the aircraft every summary describes. */
static void
put_record(struct jw *w, const struct solve_result *r)
{
	bool buildable;
	const struct res_run *o = res_record(r, &buildable);
	jw_obj(w, "design_of_record");
	jw_lit(w, "basis", buildable ? "real_parts" : "continuous");
	jw_bool(w, "buildable", buildable);
	put_run_fields(w, o, buildable ? r : NULL, "propulsion");
	if (o->perf.valid)
		put_perf(w, &o->perf);
	/* What the bill of materials costs, as far as its prices are known. */
	if (r->parts_selected) {
		char text[96];
		jw_obj(w, "bom_price");
		jw_num(w, "at_least_usd", r->bom_price_usd);
		jw_int(w, "lines", r->bom_parts_lines);
		jw_int(w, "unpriced_lines", r->bom_parts_lines - r->bom_priced_lines);
		/* (both over the parts' lines, the payload's aside) */
		res_price_text(r, text, sizeof text);
		JW_STR(w, "text", text);
		jw_close(w);
	} else {
		jw_null(w, "bom_price");
	}
	jw_close(w);
}

/* ---- parts and BOM --------------------------------------------------------- */

static void
put_part(struct jw *w, const char *key, const struct res_part *p,
         const struct solve_result *r)
{
	if (!p->chosen) {
		jw_null(w, key);
		return;
	}
	jw_obj(w, key);
	JW_STR(w, "catalogue_id", p->id);
	JW_STR(w, "manufacturer", p->manufacturer);
	JW_STR(w, "part_number", p->part_number);
	JW_STR(w, "description", p->description);
	jw_int(w, "qty", p->qty);
	jw_num(w, "unit_mass_kg", p->unit_mass_kg);
	jw_price(w, "unit_price_usd", p->unit_price_usd);
	jw_num(w, "j_score", p->j_score);
	if (p == &r->battery) {
		jw_int(w, "series_packs", r->battery_series_packs);
		jw_int(w, "parallel_packs", r->battery_parallel_packs);
	}
	jw_close(w);
}

static void
put_selected(struct jw *w, const struct solve_result *r)
{
	if (!r->parts_selected) {
		jw_null(w, "selected");
		return;
	}
	jw_obj(w, "selected");
	put_part(w, "motor", &r->motor, r);
	put_part(w, "prop", &r->prop, r);
	put_part(w, "battery", &r->battery, r);
	put_part(w, "esc", &r->esc, r);
	jw_close(w);
}

/* The BOM as in bom.csv, masses in kg; empty with zero totals when no parts
 * were selected (bom.csv does the same). */
static void
put_bom(struct jw *w, const struct solve_result *r)
{
	int n = r->parts_selected ? jw_count(w, "bom", r->n_bom, RES_MAX_BOM) : 0;
	jw_obj(w, "bom");
	jw_arr(w, "lines");
	for (int i = 0; i < n; i++) {
		const struct res_bom_line *b = &r->bom[i];
		jw_obj(w, NULL);
		jw_int(w, "item", b->item);
		jw_int(w, "qty", b->qty);
		JW_STR(w, "category", b->category);
		JW_STR(w, "manufacturer", b->manufacturer);
		jw_lit(w, "part_number", bom_csv_part_number(r, b));
		JW_STR(w, "description", b->description);
		jw_num(w, "unit_mass_kg", b->unit_mass_kg);
		jw_num(w, "total_mass_kg", b->total_mass_kg);
		jw_price(w, "unit_price_usd", b->unit_price_usd);
		jw_price(w, "total_price_usd", b->unit_price_usd == 0.0 ? 0.0 : b->total_price_usd);
		JW_STR(w, "catalogue_id", b->catalogue_id);
		JW_STR(w, "price_date", b->price_date);
		JW_STR(w, "source", b->source_url);
		jw_close(w);
	}
	jw_close(w);
	jw_num(w, "total_mass_kg", r->parts_selected ? r->bom_mass_kg : 0.0);
	jw_num(w, "total_price_usd", r->parts_selected ? r->bom_price_usd : 0.0);
	/* Lines to buy (the payload's aside) and of those the unpriced. */
	jw_int(w, "lines_to_buy", r->parts_selected ? r->bom_parts_lines : 0);
	jw_int(w, "unpriced_lines", bom_csv_missing_prices(r));
	jw_close(w);
}

static void
put_candidates(struct jw *w, const struct solve_result *r)
{
	int n = jw_count(w, "candidates", r->n_candidates, RES_MAX_CANDIDATES);
	jw_arr(w, "candidates");
	for (int i = 0; i < n; i++) {
		const struct res_candidate *c = &r->candidates[i];
		jw_obj(w, NULL);
		JW_STR(w, "catalogue_id", c->id);
		jw_num(w, "kv", c->kv);
		jw_num(w, "mass_kg", c->mass_kg);
		jw_num(w, "j_score", c->j_score);
		jw_bool(w, "feasible", c->feasible);
		jw_close(w);
	}
	jw_close(w);
}

/* The prediction interval on the takeoff mass of record and the accuracy
 * behind it (null when the calibration carries none). */
static void
put_accuracy(struct jw *w, const struct solve_result *r)
{
	const struct res_interval *iv = &r->mtow_interval;
	const struct res_design_intervals *di = &r->intervals;
	if (iv->valid) {
		jw_obj(w, "mtow_interval");
		jw_num(w, "level", iv->level);
		jw_num(w, "lo_kg", iv->lo_kg);
		jw_num(w, "hi_kg", iv->hi_kg);
		jw_lit(w, "basis", di->from_parts ? "estimated_lines" : "loop_gain");
		if (di->from_parts)
			jw_num(w, "estimated_kg", di->estimated_kg);
		else
			jw_num(w, "loop_gain", di->loop_gain);
		jw_close(w);
	} else {
		jw_null(w, "mtow_interval");
	}
	if (di->power_valid) {
		jw_obj(w, "hover_power_interval");
		jw_num(w, "level", iv->level);
		jw_num(w, "hover_power_w", di->hover_power_w);
		jw_num(w, "lo_w", di->hover_power_lo_w);
		jw_num(w, "hi_w", di->hover_power_hi_w);
		jw_close(w);
		jw_obj(w, "hover_endurance_interval");
		jw_num(w, "level", iv->level);
		jw_num(w, "hover_endurance_s", di->endurance_s);
		jw_num(w, "lo_s", di->endurance_lo_s);
		jw_num(w, "hi_s", di->endurance_hi_s);
		jw_close(w);
	} else {
		jw_null(w, "hover_power_interval");
		jw_null(w, "hover_endurance_interval");
	}
	const struct res_accuracy *a = &r->accuracy;
	if (!a->valid) {
		jw_null(w, "accuracy");
		return;
	}
	jw_obj(w, "accuracy");
	jw_lit(w, "basis", a->pack_locked ? "pack_locked" : "from_endurance");
	jw_int(w, "cohort_rows", a->n_rows);
	jw_num(w, "loo_mtow_mape", a->mape);
	jw_num(w, "loo_battery_mape", a->battery_mape);
	jw_num(w, "interval_ratio_lo", a->ratio_lo);
	jw_num(w, "interval_ratio_hi", a->ratio_hi);
	jw_int(w, "interval_rows", a->interval_rows);
	jw_num(w, "coverage", a->coverage);
	jw_num(w, "design_interval_coverage", a->design_coverage);
	jw_close(w);
}

/* A mission beyond reach: what is reachable instead (null otherwise). */
static void
put_ceiling(struct jw *w, const struct solve_result *r)
{
	const struct res_ceiling *c = &r->ceiling;
	if (!c->valid) {
		jw_null(w, "ceiling");
		return;
	}
	jw_obj(w, "ceiling");
	jw_lit(w, "binds_code", c->binds_code);
	JW_STR(w, "binds", c->binds);
	jw_bool(w, "endurance_found", c->endurance_found);
	jw_num(w, "time_scale", c->time_scale);
	jw_num(w, "flight_time_s", c->flight_time_s);
	jw_num(w, "hover_endurance_s", c->hover_endurance_s);
	jw_num(w, "mass_kg", c->mass_kg);
	jw_bool(w, "payload_found", c->payload_found);
	jw_num(w, "max_payload_kg", c->max_payload_kg);
	jw_num(w, "mass_at_max_payload_kg", c->mass_at_payload_kg);
	jw_bool(w, "custom_is_ceiling_design", c->shown);
	jw_close(w);
}

/* A number that may not apply (NAN): null then. */
static void
jw_num_or_null(struct jw *w, const char *key, double x)
{
	if (isnan(x))
		jw_null(w, key);
	else
		jw_num(w, key, x);
}

/* The figures of the design of record the dossier's cover and summary,
 * bom_totals.csv and index.csv print (res_figures()): one number each. */
static void
put_key_figures(struct jw *w, const struct solve_result *r)
{
	struct res_figures f;
	res_figures(r, &f);
	jw_obj(w, "key_figures");
	jw_num(w, "takeoff_mass_kg", f.takeoff_mass_kg);
	jw_bool(w, "sheds_payload", f.sheds);
	jw_num(w, "hover_power_at_takeoff_mass_w", f.hover_power_w);
	jw_num_or_null(w, "hover_power_after_shedding_w", f.hover_power_shed_w);
	jw_num_or_null(w, "hover_battery_current_at_takeoff_mass_a", f.hover_current_a);
	jw_num(w, "aux_power_w", f.aux_power_w);
	jw_num(w, "hover_endurance_s", f.hover_endurance_s);
	jw_num(w, "flight_time_s", f.flight_time_s);
	jw_num(w, "landing_soc", f.landing_soc);
	jw_num(w, "bom_mass_kg", f.bom_mass_kg);
	jw_num(w, "bom_price_usd", f.bom_price_usd);
	jw_int(w, "bom_lines", f.bom_lines);
	jw_int(w, "bom_unpriced_lines", f.unpriced_lines);
	jw_close(w);
}

/* ---- top level ------------------------------------------------------------- */

static void
put_violations(struct jw *w, const struct solve_result *r)
{
	int n = jw_count(w, "violations", r->n_violations, RES_MAX_VIOLATIONS);
	jw_arr(w, "violations");
	for (int i = 0; i < n; i++) {
		const struct res_violation *v = &r->violations[i];
		jw_obj(w, NULL);
		jw_lit(w, "run", v->run);
		jw_lit(w, "stage", v->stage);
		jw_lit(w, "code", v->code);
		JW_STR(w, "message", v->message);
		int nf = jw_count(w, "suggested_fixes", v->n_fixes, RES_MAX_FIXES);
		jw_arr(w, "suggested_fixes");
		for (int k = 0; k < nf; k++)
			JW_STR(w, NULL, v->fixes[k]);
		jw_close(w);
		jw_close(w);
	}
	jw_close(w);
}

char *
result_json_render_checked(const struct solve_result *r,
                           const char *aeroeval_version,
                           struct result_json_faults *faults)
{
	struct jw w;
	memset(&w, 0, sizeof w);

	jw_obj(&w, NULL);
	jw_str(&w, "aeroeval_version", aeroeval_version, strlen(aeroeval_version));
	JW_STR(&w, "input_sha256", r->input_sha256);
	JW_STR(&w, "catalogue_sha256", r->catalogue_sha256);
	jw_str(&w, "status", r->feasible ? "feasible" : "infeasible",
	       r->feasible ? 8 : 10);
	struct res_figures fig;
	res_figures(r, &fig);
	jw_bool(&w, "buildable", fig.buildable);
	jw_num(&w, "takeoff_mass_kg", fig.takeoff_mass_kg);
	jw_obj(&w, "regulatory_class");
	jw_lit(&w, "eu_open_category", res_eu_class(fig.takeoff_mass_kg));
	jw_bool(&w, "us_part_107_small_uas", fig.takeoff_mass_kg < RES_US_107_KG);
	jw_close(&w);
	put_key_figures(&w, r);
	put_accuracy(&w, r);
	put_ceiling(&w, r);
	put_violations(&w, r);
	int nr = jw_count(&w, "rationale", r->n_rationale, RES_MAX_RATIONALE);
	jw_arr(&w, "rationale");
	for (int i = 0; i < nr; i++)
		JW_STR(&w, NULL, r->rationale[i]);
	jw_close(&w);

	put_mission(&w, &r->mission);
	put_run(&w, "baseline", &r->baseline, NULL);
	put_run(&w, "custom", &r->custom, r);
	jw_obj(&w, "role_overhead");
	put_mass(&w, &r->role_overhead);
	jw_close(&w);
	if (r->custom.ran)
		put_optimum(&w, "continuous_optimum", &r->custom.opt);
	else
		jw_null(&w, "continuous_optimum");
	put_record(&w, r);
	put_selected(&w, r);
	put_bom(&w, r);
	put_candidates(&w, r);
	jw_close(&w);
	jw_put(&w, "\n", 1);
	assert(w.depth == 0);

	if (faults)
		*faults = w.faults;
	return w.buf;
}

char *
result_json_render(const struct solve_result *r, const char *aeroeval_version)
{
	struct result_json_faults f;
	char *text = result_json_render_checked(r, aeroeval_version, &f);
	if (f.n_invalid > 0)
		fprintf(stderr, "aeroeval: internal error: result.json: %d invalid "
		        "value(s), first at %s\n", f.n_invalid, f.first_path);
	assert(f.n_invalid == 0 && "result.json: non-finite or out-of-range value");
	return text;
}
