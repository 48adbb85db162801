/* result_json.c — result.json writer (see result_json.h for the format).
 *
 * The text comes from the one JSON writer (util/jsonw.h), which prints
 * every double exactly and names the JSON path of the first invalid value
 * for the internal-error message; this file decides what goes where.
 */
#include "formats/result_json.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "spec/model.h"
#include "formats/bom_csv.h"
#include "util/jsonw.h"

/* A char-array member: bounded by its size, so a missing NUL cannot
 * overrun.  A pointer member (a string literal) is no array: JW_STR on one
 * fails to compile, and it goes through jsonw_string(). */
#define JW_IS_ARRAY(a) \
	(!__builtin_types_compatible_p(__typeof__(a), __typeof__(&(a)[0])))
#define JW_STR(w, key, arr) \
	jsonw_string_n((w), (key), (arr), sizeof(arr) * sizeof(char[JW_IS_ARRAY(arr) ? 1 : -1]))

/* A price: 0 means unknown and is written as null. */
static void
jw_price(struct jsonw *w, const char *key, double usd)
{
	if (usd == 0.0)
		jsonw_null(w, key);
	else
		jsonw_number(w, key, usd);
}

/* An enum value spelled from a NULL-terminated table; out of range is a fault. */
static void
jw_enum(struct jsonw *w, const char *key, int v, const char *const *names)
{
	int n = 0;
	while (names[n])
		n++;
	if (v < 0 || v >= n) {
		jsonw_null(w, key);
		jsonw_fault(w, key);
		return;
	}
	jsonw_string(w, key, names[v]);
}

static void
jw_phase(struct jsonw *w, const char *key, int phase)
{
	if (phase < 0 || phase >= PHASE_MAX) {
		jsonw_null(w, key);
		jsonw_fault(w, key);
		return;
	}
	jsonw_string(w, key, res_phase_name[phase]);
}

/* A count from the struct, clamped to 0..max; outside is a fault. */
static int
jw_count(struct jsonw *w, const char *key, int n, int max)
{
	if (n >= 0 && n <= max)
		return n;
	jsonw_fault(w, key);
	return n < 0 ? 0 : max;
}

static void
jw_num_array(struct jsonw *w, const char *key, const double *x, int n)
{
	jsonw_array_packed(w, key);
	for (int i = 0; i < n; i++)
		jsonw_number(w, NULL, x[i]);
	jsonw_end(w);
}

/* ---- mission --------------------------------------------------------------- */

/* One mission field under its leaf name (the part after the last dot). */
static void
put_field(struct jsonw *w, const struct mission_spec *s,
          const struct spec_field_info *f)
{
	const char *dot = strrchr(f->path, '.');
	const char *key = dot ? dot + 1 : f->path;
	const void *p = spec_member_const(s, f);
	switch (f->type) {
	case SPEC_NUM:
		jsonw_number(w, key, *(const double *)p);
		break;
	case SPEC_SPEED:
		/* The only speed field is v_forward_ms; "auto" is kept as given. */
		assert(f->id == SPECF_V_FORWARD_MS);
		if (s->v_forward_auto)
			jsonw_string(w, key, "auto");
		else
			jsonw_number(w, key, *(const double *)p);
		break;
	case SPEC_INT:
		jsonw_int(w, key, *(const int *)p);
		break;
	case SPEC_BOOL:
		jsonw_bool(w, key, *(const bool *)p);
		break;
	case SPEC_ENUM:
		jw_enum(w, key, *(const int *)p, f->enums);
		break;
	case SPEC_STR:
	case SPEC_DATE:
		jsonw_string_n(w, key, (const char *)p, SPEC_STR_MAX);
		break;
	}
}

/* The fully resolved mission, every field of spec_fields[] nested by its
 * dotted path (one level: "locks.locked_kv" goes into "locks"), groups in
 * the order of their first field, then "defaulted": the paths the file did
 * not set. */
static void
put_mission(struct jsonw *w, const struct mission_spec *s)
{
	bool done[SPEC_N_FIELDS] = { false };
	jsonw_object(w, "mission");
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
		jsonw_object(w, group);
		for (size_t j = i; j < SPEC_N_FIELDS; j++) {
			const char *pj = spec_fields[j].path;
			if (strncmp(pj, path, glen + 1) == 0) {
				put_field(w, s, &spec_fields[j]);
				done[j] = true;
			}
		}
		jsonw_end(w);
	}
	jsonw_array(w, "defaulted");
	for (size_t i = 0; i < SPEC_N_FIELDS; i++)
		if (!s->given[i])
			jsonw_string(w, NULL, spec_fields[i].path);
	jsonw_end(w);
	jsonw_end(w);
}

/* ---- runs ------------------------------------------------------------------ */

/* Total and breakdown, as members of the open object. */
static void
put_mass(struct jsonw *w, const struct res_mass *m)
{
	jsonw_number(w, "total_mass_kg", m->total_kg);
	jsonw_number(w, "payload_kg", m->payload_kg);
	jsonw_number(w, "battery_mass_kg", m->battery_kg);
	jsonw_number(w, "frame_mass_kg", m->frame_kg);
	jsonw_number(w, "arm_mass_kg", m->arm_kg);
	jsonw_number(w, "motor_mass_kg", m->motor_kg);
	jsonw_number(w, "prop_mass_kg", m->prop_kg);
	jsonw_number(w, "esc_mass_kg", m->esc_kg);
	jsonw_number(w, "wiring_mass_kg", m->wiring_kg);
	jsonw_number(w, "avionics_mass_kg", m->avionics_kg);
	jsonw_number(w, "role_aux_mass_kg", m->role_aux_kg);
	jsonw_number(w, "other_mass_kg", m->other_kg);
}

static void
put_optimum(struct jsonw *w, const char *key, const struct res_optimum *o)
{
	jsonw_object(w, key);
	jsonw_number(w, "prop_diameter_in", o->prop_diameter_in);
	jsonw_number(w, "prop_pitch_in", o->prop_pitch_in);
	jsonw_number(w, "motor_kv", o->motor_kv);
	jsonw_number(w, "motor_mass_kg", o->motor_mass_kg);
	jsonw_number(w, "motor_peak_current_a", o->motor_peak_current_a);
	jsonw_number(w, "motor_peak_power_w", o->motor_peak_power_w);
	jsonw_end(w);
}

static void
put_phases(struct jsonw *w, const struct res_run *run)
{
	jsonw_array(w, "phases");
	for (int i = 0; i < PHASE_MAX; i++) {
		const struct res_phase *p = &run->phase[i];
		jsonw_object(w, NULL);
		jsonw_string(w, "phase", res_phase_name[i]);
		jsonw_number(w, "duration_s", p->duration_s);
		jsonw_number(w, "power_w", p->power_w);
		jsonw_number(w, "current_a", p->current_a);
		jsonw_number(w, "energy_wh", p->energy_wh);
		jsonw_number(w, "speed_ms", p->speed_ms);
		jsonw_number(w, "thrust_per_rotor_n", p->thrust_per_rotor_n);
		jsonw_number(w, "shaft_power_w", p->shaft_power_w);
		jsonw_number(w, "rpm", p->rpm);
		jsonw_number(w, "throttle", p->throttle);
		jsonw_number(w, "pitch_deg", p->pitch_deg);
		jsonw_number(w, "tip_mach", p->tip_mach);
		jsonw_end(w);
	}
	jsonw_end(w);
}

/* What the run flew: its role's duty profile, segment by kind, and what
 * the profile made of the mission (physics/duty.h). */
static void
put_duty(struct jsonw *w, const struct res_run *run)
{
	const struct res_duty *d = &run->duty;
	int kind = d->kind >= 0 && d->kind < DUTY_KIND_MAX ? d->kind : DUTY_PHASES;
	jsonw_object(w, "duty_profile");
	jsonw_string(w, "profile", duty_kind_name[kind]);
	JW_STR(w, "source", d->source);
	jsonw_number(w, "full_throttle_power_w", d->full_throttle_power_w);
	jsonw_number(w, "mean_power_w", d->mean_power_w);
	jsonw_number(w, "peak_power_w", d->peak_power_w);
	int n = jw_count(w, "segments", d->n_groups, RES_MAX_DUTY_GROUPS);
	jsonw_array(w, "segments");
	for (int i = 0; i < n; i++) {
		const struct res_duty_group *g = &d->group[i];
		jsonw_object(w, NULL);
		JW_STR(w, "segment", g->name);
		jw_phase(w, "phase", g->phase);
		jsonw_int(w, "count", g->count);
		jsonw_number(w, "duration_s", g->duration_s);
		jsonw_number(w, "power_w", g->power_w);
		jsonw_number(w, "current_a", g->current_a);
		jsonw_number(w, "energy_wh", g->energy_wh);
		if (g->fraction > 0.0)
			jsonw_number(w, "fraction_of_full_throttle", g->fraction);
		else
			jsonw_null(w, "fraction_of_full_throttle");
		jsonw_end(w);
	}
	jsonw_end(w);
	if (kind == DUTY_RACE) {
		jsonw_object(w, "race");
		jsonw_int(w, "laps", d->n_laps);
		jsonw_number(w, "lap_s", d->lap_s);
		jsonw_number(w, "race_s", d->race_s);
		jsonw_number(w, "mean_power_w", d->race_mean_power_w);
		jsonw_number(w, "mean_current_a", d->race_mean_current_a);
		jsonw_number(w, "mean_fraction_of_full_throttle", d->lap_mean_fraction);
		jsonw_number(w, "peak_fraction_of_full_throttle", d->lap_peak_fraction);
		jsonw_end(w);
	} else {
		jsonw_null(w, "race");
	}
	if (kind == DUTY_SPRAY) {
		jsonw_object(w, "spray");
		jsonw_number(w, "swath_length_m", d->swath_length_m);
		jsonw_int(w, "passes", d->n_passes);
		jsonw_int(w, "turns", d->n_turns);
		jsonw_number(w, "pass_m", d->pass_m);
		jsonw_number(w, "turn_s", d->turn_s);
		jsonw_number(w, "transit_m", d->transit_m);
		jsonw_number(w, "spraying_s", d->spray_s);
		jsonw_number(w, "spray_rate_kg_s", d->spray_rate_kg_s);
		jsonw_number(w, "tank_shed_kg", d->tank_shed_kg);
		jsonw_end(w);
	} else {
		jsonw_null(w, "spray");
	}
	if (d->drop_time_s >= 0.0 && d->drop_mass_kg > 0.0) {
		jsonw_object(w, "drop");
		jsonw_number(w, "time_s", d->drop_time_s);
		jsonw_number(w, "mass_kg", d->drop_mass_kg);
		jsonw_end(w);
	} else {
		jsonw_null(w, "drop");
	}
	jsonw_number(w, "landing_payload_kg", d->landing_payload_kg);
	jsonw_end(w);
}

/* One column of the discharge trace: the double at byte offset `off` of
 * every sample. */
static void
put_trace_column(struct jsonw *w, const char *key, const struct res_sample *t,
                 int n, size_t off)
{
	jsonw_array_packed(w, key);
	for (int i = 0; i < n; i++)
		jsonw_number(w, NULL, *(const double *)((const char *)&t[i] + off));
	jsonw_end(w);
}

/* The discharge trace as columns (not a list of objects: 9 x 600 values). */
static void
put_time_series(struct jsonw *w, const struct res_run *run)
{
	int n = jw_count(w, "time_series", run->n_trace, RES_MAX_TRACE);
	const struct res_sample *t = run->trace;
	jsonw_object(w, "time_series");
	jsonw_int(w, "n", n);
	put_trace_column(w, "t_s", t, n, offsetof(struct res_sample, t_s));
	put_trace_column(w, "soc", t, n, offsetof(struct res_sample, soc));
	put_trace_column(w, "v_oc_v", t, n, offsetof(struct res_sample, v_oc_v));
	put_trace_column(w, "v_term_v", t, n, offsetof(struct res_sample, v_term_v));
	put_trace_column(w, "current_a", t, n, offsetof(struct res_sample, current_a));
	put_trace_column(w, "power_w", t, n, offsetof(struct res_sample, power_w));
	put_trace_column(w, "temp_c", t, n, offsetof(struct res_sample, temp_c));
	put_trace_column(w, "mass_kg", t, n, offsetof(struct res_sample, mass_kg));
	jsonw_array_packed(w, "phase");
	for (int i = 0; i < n; i++)
		jw_phase(w, NULL, t[i].phase);
	jsonw_end(w);
	jsonw_end(w);
}

static void
put_checks(struct jsonw *w, const struct res_run *run)
{
	int n = jw_count(w, "checks", run->n_checks, RES_MAX_CHECKS);
	jsonw_array(w, "checks");
	for (int i = 0; i < n; i++) {
		const struct res_check *c = &run->checks[i];
		jsonw_object(w, NULL);
		jsonw_string(w, "code", c->code);
		jsonw_string(w, "name", c->name);
		jsonw_string(w, "condition", c->condition);
		jsonw_string_n(w, "basis", c->basis, sizeof c->basis);
		jsonw_string(w, "unit", c->unit);
		jsonw_number(w, "value", c->value);
		jsonw_number(w, "limit", c->limit);
		jsonw_string_n(w, "kind", c->upper ? "max" : "min", 3);
		jsonw_number(w, "margin", c->margin);
		jsonw_bool(w, "pass", c->pass);
		jsonw_bool(w, "sized_to_limit", c->sized);
		jsonw_end(w);
	}
	jsonw_end(w);
}

static void put_selected(struct jsonw *w, const struct solve_result *r);
static void put_bom(struct jsonw *w, const struct solve_result *r);

/* One sized run; {"ran": false} when the gate stopped it.  parts is the
 * result whose real-parts selection this run's design is (the custom and
 * BOM-closed runs), or NULL for a run that is not mapped to parts (the
 * baseline): its "selected" and "bom" are then null. */
static void put_run_fields(struct jsonw *w, const struct res_run *run,
                           const struct solve_result *parts, const char *prop_key);

static void
put_run(struct jsonw *w, const char *key, const struct res_run *run,
        const struct solve_result *parts)
{
	jsonw_object(w, key);
	put_run_fields(w, run, parts, "continuous_optimum");
	jsonw_end(w);
}

/* The fields of one run, into the object open in w; prop_key names its
 * propeller-and-motor block. */
static void
put_run_fields(struct jsonw *w, const struct res_run *run,
               const struct solve_result *parts, const char *prop_key)
{
	jsonw_bool(w, "ran", run->ran);
	if (!run->ran)
		return;
	jsonw_bool(w, "feasible", run->feasible);
	jsonw_bool(w, "converged", run->converged);
	jsonw_int(w, "iterations", run->iterations);
	JW_STR(w, "termination", run->termination);

	put_mass(w, &run->mass);
	int nh = jw_count(w, "convergence_history", run->n_history, RES_MAX_HISTORY);
	jw_num_array(w, "convergence_history", run->history_kg, nh);
	jsonw_number(w, "lipschitz_estimate", run->lipschitz);
	jsonw_number(w, "time_scale", run->time_scale);
	jsonw_number(w, "thrust_margin", run->thrust_margin);
	jsonw_number(w, "aux_power_w", run->aux_power_w);

	JW_STR(w, "chemistry", run->chemistry);
	jsonw_int(w, "cell_count", run->cell_count);
	jsonw_int(w, "pack_count", run->pack_count);
	jsonw_number(w, "battery_capacity_mah", run->capacity_mah);
	jsonw_number(w, "energy_wh", run->energy_wh);
	jsonw_number(w, "packaging_factor", run->packaging_factor);
	jsonw_bool(w, "battery_power_binds", run->battery_power_binds);
	jsonw_number(w, "nominal_voltage_v", run->nominal_voltage_v);

	put_phases(w, run);
	put_duty(w, run);
	jsonw_number(w, "approved_hover_time_s", run->approved_time_s[PHASE_HOVER]);
	jsonw_number(w, "approved_climb_time_s", run->approved_time_s[PHASE_CLIMB]);
	jsonw_number(w, "approved_forward_time_s", run->approved_time_s[PHASE_FORWARD]);
	jsonw_number(w, "flight_time_s", run->flight_time_s);
	jsonw_number(w, "hover_endurance_s", run->hover_endurance_s);
	jsonw_number(w, "hover_power_w", run->hover_power_w);
	jsonw_number(w, "hover_power_after_shedding_w", run->hover_power_shed_w);
	jsonw_number(w, "marketing_endurance_s", run->marketing_endurance_s);
	jsonw_number(w, "optimal_speed_ms", run->optimal_speed_ms);
	jsonw_number(w, "v_min_power_ms", run->v_min_power_ms);
	jsonw_number(w, "v_max_ms", run->v_max_ms);
	jsonw_string(w, "v_max_limited_by", res_limit_name[run->v_max_limit]);
	int ns = jw_count(w, "speed_sweep", run->n_sweep, RES_MAX_SWEEP);
	jsonw_object(w, "speed_sweep");
	jw_num_array(w, "v_ms", run->sweep_v_ms, ns);
	jw_num_array(w, "power_w", run->sweep_power_w, ns);
	jsonw_end(w);

	jsonw_number(w, "thrust_to_weight_ratio", run->thrust_to_weight);
	jsonw_number(w, "hover_throttle", run->hover_throttle);
	jsonw_number(w, "forward_pitch_deg", run->forward_pitch_deg);
	jsonw_number(w, "disk_loading_n_m2", run->disk_loading_n_m2);
	jsonw_number(w, "downwash_ms", run->downwash_ms);
	jsonw_number(w, "fom_installed", run->fom_installed);
	jsonw_number(w, "interference", run->interference);
	jsonw_number(w, "installation_kappa", run->kappa);
	jsonw_number(w, "reynolds_tip", run->reynolds_tip);
	jsonw_number(w, "rpm_hover", run->rpm_hover);
	jsonw_number(w, "rpm_peak", run->rpm_peak);
	jsonw_number(w, "tip_mach_peak", run->tip_mach_peak);
	jsonw_number(w, "overlap_limit_in", run->overlap_limit_in);
	jsonw_number(w, "peak_power_w", run->peak_power_w);
	jsonw_number(w, "peak_current_a", run->peak_current_a);
	jsonw_number(w, "peak_c_rate", run->peak_c_rate);
	/* The run's own propeller and motor: for the baseline and the custom
	 * run their continuous optimum, for the design of
	 * record its propulsion (real parts; the continuous optimum it was
	 * aimed at is the top-level "continuous_optimum"). */
	put_optimum(w, prop_key, &run->opt);

	jsonw_number(w, "arm_length_m", run->arm_length_m);
	jsonw_number(w, "arm_outer_diameter_mm", run->arm_outer_diameter_mm);
	jsonw_number(w, "arm_wall_thickness_mm", run->arm_wall_thickness_mm);
	jsonw_number(w, "arm_stress_mpa", run->arm_stress_mpa);
	jsonw_number(w, "arm_stress_allow_mpa", run->arm_stress_allow_mpa);
	jsonw_number(w, "arm_natural_frequency_hz", run->arm_natural_frequency_hz);
	jsonw_number(w, "blade_pass_frequency_hz", run->blade_pass_frequency_hz);
	jsonw_number(w, "blade_pass_low_hz", run->blade_pass_low_hz);
	jsonw_number(w, "resonance_margin", run->resonance_margin);
	jsonw_number(w, "arm_tip_mass_kg", run->arm_tip_mass_kg);
	jsonw_bool(w, "arm_wall_floor_binds", run->arm_wall_floor_binds);
	jsonw_bool(w, "min_fraction_binds", run->min_fraction_binds);

	jsonw_number(w, "max_battery_temp_c", run->max_battery_temp_c);
	jsonw_number(w, "thermal_margin_c", run->thermal_margin_c);
	jsonw_number(w, "min_terminal_voltage_v", run->min_terminal_voltage_v);
	jsonw_number(w, "voltage_floor_v", run->voltage_floor_v);
	jsonw_number(w, "end_soc", run->end_soc);
	jsonw_number(w, "winding_temp_c", run->winding_temp_c);
	jsonw_number(w, "motor_winding_resistance_ohm", run->motor_winding_resistance_ohm);
	jsonw_number(w, "motor_copper_loss_w", run->motor_copper_loss_w);
	put_time_series(w, run);

	int ne = jw_count(w, "endurance_explorer", run->n_endurance, RES_MAX_ENDURANCE);
	jsonw_object(w, "endurance_explorer");
	jw_num_array(w, "scale", run->endurance_scale, ne);
	jw_num_array(w, "time_s", run->endurance_time_s, ne);
	jw_num_array(w, "mass_kg", run->endurance_mass_kg, ne);
	jsonw_number(w, "inflection_scale", run->endurance_inflection_scale);
	jsonw_end(w);

	put_checks(w, run);
	if (parts != NULL) {
		put_selected(w, parts);
		put_bom(w, parts);
	} else {
		jsonw_null(w, "selected");
		jsonw_null(w, "bom");
	}
}

/* One operating point of the real drive. */
static void
put_op(struct jsonw *w, int id, const struct res_op *op)
{
	jsonw_object(w, NULL);
	jsonw_string(w, "point", res_op_name[id]);
	jsonw_bool(w, "reachable", op->valid);
	jsonw_number(w, "thrust_n", op->thrust_n);
	jsonw_number(w, "rpm", op->rpm);
	jsonw_number(w, "throttle", op->throttle < 1.0 ? op->throttle : 1.0);
	jsonw_number(w, "motor_current_a", op->motor_current_a);
	jsonw_number(w, "motor_voltage_v", op->motor_voltage_v);
	jsonw_number(w, "motor_input_power_w", op->power_in_w);
	jsonw_number(w, "shaft_power_w", op->power_shaft_w);
	jsonw_number(w, "motor_efficiency", op->motor_efficiency);
	jsonw_number(w, "grams_per_watt", op->g_per_w);
	jsonw_number(w, "winding_temp_c", op->winding_temp_c);
	jsonw_number(w, "tip_mach", op->tip_mach);
	jsonw_number(w, "battery_current_a", op->battery_current_a);
	jsonw_number(w, "battery_voltage_v", op->bus_voltage_v);
	jsonw_number(w, "c_load", op->c_load);
	jsonw_number(w, "electrical_power_w", op->electrical_w);
	jsonw_end(w);
}

/* What the design on real parts can do: its operating points and figures. */
static void
put_perf(struct jsonw *w, const struct res_perf *pf)
{
	jsonw_array(w, "operating_points");
	for (int i = 0; i < OP_MAX; i++)
		put_op(w, i, &pf->op[i]);
	jsonw_end(w);
	jsonw_object(w, "performance");
	jsonw_number(w, "hover_time_s", pf->hover_time_s);
	jsonw_number(w, "mixed_time_s", pf->mixed_time_s);
	jsonw_number(w, "full_throttle_time_s", pf->full_throttle_time_s);
	jsonw_number(w, "max_speed_ms", pf->max_speed_ms);
	jsonw_string(w, "max_speed_limited_by", res_limit_name[pf->max_speed_limit]);
	jsonw_number(w, "max_climb_ms", pf->max_climb_ms);
	jsonw_string(w, "max_climb_limited_by", res_limit_name[pf->max_climb_limit]);
	jsonw_number(w, "max_climb_rpm", pf->max_climb_rpm);
	jsonw_number(w, "max_tilt_deg", pf->max_tilt_deg);
	jsonw_number(w, "spare_payload_kg", pf->spare_payload_kg);
	jsonw_number(w, "throttle_needed", pf->throttle_needed);
	jsonw_number(w, "landing_soc", pf->landing_soc);
	if (pf->motor_out_rotors > 0) {
		jsonw_object(w, "motor_out");
		jsonw_int(w, "rotors_counted", pf->motor_out_rotors);
		jsonw_number(w, "thrust_over_weight", pf->motor_out_ratio);
		jsonw_bool(w, "holds_altitude", pf->motor_out_holds);
		jsonw_end(w);
	} else {
		jsonw_null(w, "motor_out");
	}
	jsonw_number(w, "motor_resistance_ohm", pf->motor_resistance_ohm);
	jsonw_number(w, "motor_no_load_current_a", pf->motor_no_load_a);
	jsonw_bool(w, "motor_constants_estimated", pf->motor_r_estimated);
	jsonw_number(w, "prop_ct", pf->prop_ct);
	jsonw_number(w, "prop_cp", pf->prop_cp);
	jsonw_bool(w, "prop_coefficients_published", pf->prop_coeffs_measured);
	jsonw_number(w, "prop_fom_isolated", pf->prop_fom);
	jsonw_end(w);
}

/* The design of record: the aircraft every summary describes. */
static void
put_record(struct jsonw *w, const struct solve_result *r)
{
	bool buildable;
	const struct res_run *o = res_record(r, &buildable);
	jsonw_object(w, "design_of_record");
	jsonw_string(w, "basis", buildable ? "real_parts" : "continuous");
	jsonw_bool(w, "buildable", buildable);
	put_run_fields(w, o, buildable ? r : NULL, "propulsion");
	if (o->perf.valid)
		put_perf(w, &o->perf);
	/* What the bill of materials costs, as far as its prices are known. */
	if (r->parts_selected) {
		char text[96];
		jsonw_object(w, "bom_price");
		jsonw_number(w, "at_least_usd", r->bom_price_usd);
		jsonw_int(w, "lines", r->bom_parts_lines);
		jsonw_int(w, "unpriced_lines", r->bom_parts_lines - r->bom_priced_lines);
		/* (both over the parts' lines, the payload's aside) */
		res_price_text(r, text, sizeof text);
		JW_STR(w, "text", text);
		jsonw_end(w);
	} else {
		jsonw_null(w, "bom_price");
	}
	jsonw_end(w);
}

/* ---- parts and BOM --------------------------------------------------------- */

static void
put_part(struct jsonw *w, const char *key, const struct res_part *p,
         const struct solve_result *r)
{
	if (!p->chosen) {
		jsonw_null(w, key);
		return;
	}
	jsonw_object(w, key);
	JW_STR(w, "catalogue_id", p->id);
	JW_STR(w, "manufacturer", p->manufacturer);
	JW_STR(w, "part_number", p->part_number);
	JW_STR(w, "description", p->description);
	jsonw_int(w, "qty", p->qty);
	jsonw_number(w, "unit_mass_kg", p->unit_mass_kg);
	jw_price(w, "unit_price_usd", p->unit_price_usd);
	jsonw_number(w, "j_score", p->j_score);
	if (p == &r->battery) {
		jsonw_int(w, "series_packs", r->battery_series_packs);
		jsonw_int(w, "parallel_packs", r->battery_parallel_packs);
	}
	jsonw_end(w);
}

static void
put_selected(struct jsonw *w, const struct solve_result *r)
{
	if (!r->parts_selected) {
		jsonw_null(w, "selected");
		return;
	}
	jsonw_object(w, "selected");
	put_part(w, "motor", &r->motor, r);
	put_part(w, "prop", &r->prop, r);
	put_part(w, "battery", &r->battery, r);
	put_part(w, "esc", &r->esc, r);
	jsonw_end(w);
}

/* The BOM as in bom.csv, masses in kg; empty with zero totals when no parts
 * were selected (bom.csv does the same). */
static void
put_bom(struct jsonw *w, const struct solve_result *r)
{
	int n = r->parts_selected ? jw_count(w, "bom", r->n_bom, RES_MAX_BOM) : 0;
	jsonw_object(w, "bom");
	jsonw_array(w, "lines");
	for (int i = 0; i < n; i++) {
		const struct res_bom_line *b = &r->bom[i];
		jsonw_object(w, NULL);
		jsonw_int(w, "item", b->item);
		jsonw_int(w, "qty", b->qty);
		JW_STR(w, "category", b->category);
		JW_STR(w, "manufacturer", b->manufacturer);
		jsonw_string(w, "part_number", bom_csv_part_number(r, b));
		JW_STR(w, "description", b->description);
		jsonw_number(w, "unit_mass_kg", b->unit_mass_kg);
		jsonw_number(w, "total_mass_kg", b->total_mass_kg);
		jw_price(w, "unit_price_usd", b->unit_price_usd);
		jw_price(w, "total_price_usd", b->unit_price_usd == 0.0 ? 0.0 : b->total_price_usd);
		JW_STR(w, "catalogue_id", b->catalogue_id);
		JW_STR(w, "price_date", b->price_date);
		JW_STR(w, "source", b->source_url);
		jsonw_end(w);
	}
	jsonw_end(w);
	jsonw_number(w, "total_mass_kg", r->parts_selected ? r->bom_mass_kg : 0.0);
	jsonw_number(w, "total_price_usd", r->parts_selected ? r->bom_price_usd : 0.0);
	/* Lines to buy (the payload's aside) and of those the unpriced. */
	jsonw_int(w, "lines_to_buy", r->parts_selected ? r->bom_parts_lines : 0);
	jsonw_int(w, "unpriced_lines", bom_csv_missing_prices(r));
	jsonw_end(w);
}

static void
put_candidates(struct jsonw *w, const struct solve_result *r)
{
	int n = jw_count(w, "candidates", r->n_candidates, RES_MAX_CANDIDATES);
	jsonw_array(w, "candidates");
	for (int i = 0; i < n; i++) {
		const struct res_candidate *c = &r->candidates[i];
		jsonw_object(w, NULL);
		JW_STR(w, "catalogue_id", c->id);
		jsonw_number(w, "kv", c->kv);
		jsonw_number(w, "mass_kg", c->mass_kg);
		jsonw_number(w, "j_score", c->j_score);
		jsonw_bool(w, "feasible", c->feasible);
		jsonw_end(w);
	}
	jsonw_end(w);
}

/* The prediction interval on the takeoff mass of record and the accuracy
 * behind it (null when the calibration carries none). */
static void
put_accuracy(struct jsonw *w, const struct solve_result *r)
{
	const struct res_interval *iv = &r->mtow_interval;
	const struct res_design_intervals *di = &r->intervals;
	if (iv->valid) {
		jsonw_object(w, "mtow_interval");
		jsonw_number(w, "level", iv->level);
		jsonw_number(w, "lo_kg", iv->lo_kg);
		jsonw_number(w, "hi_kg", iv->hi_kg);
		jsonw_string(w, "basis", di->from_parts ? "estimated_lines" : "loop_gain");
		if (di->from_parts)
			jsonw_number(w, "estimated_kg", di->estimated_kg);
		else
			jsonw_number(w, "loop_gain", di->loop_gain);
		jsonw_end(w);
	} else {
		jsonw_null(w, "mtow_interval");
	}
	if (di->power_valid) {
		jsonw_object(w, "hover_power_interval");
		jsonw_number(w, "level", iv->level);
		jsonw_number(w, "hover_power_w", di->hover_power_w);
		jsonw_number(w, "lo_w", di->hover_power_lo_w);
		jsonw_number(w, "hi_w", di->hover_power_hi_w);
		jsonw_end(w);
		jsonw_object(w, "hover_endurance_interval");
		jsonw_number(w, "level", iv->level);
		jsonw_number(w, "hover_endurance_s", di->endurance_s);
		jsonw_number(w, "lo_s", di->endurance_lo_s);
		jsonw_number(w, "hi_s", di->endurance_hi_s);
		jsonw_end(w);
	} else {
		jsonw_null(w, "hover_power_interval");
		jsonw_null(w, "hover_endurance_interval");
	}
	const struct res_accuracy *a = &r->accuracy;
	if (!a->valid) {
		jsonw_null(w, "accuracy");
		return;
	}
	jsonw_object(w, "accuracy");
	jsonw_string(w, "basis", a->pack_locked ? "pack_locked" : "from_endurance");
	jsonw_int(w, "cohort_rows", a->n_rows);
	jsonw_number(w, "loo_mtow_mape", a->mape);
	jsonw_number(w, "loo_battery_mape", a->battery_mape);
	jsonw_number(w, "interval_ratio_lo", a->ratio_lo);
	jsonw_number(w, "interval_ratio_hi", a->ratio_hi);
	jsonw_int(w, "interval_rows", a->interval_rows);
	jsonw_number(w, "coverage", a->coverage);
	jsonw_number(w, "design_interval_coverage", a->design_coverage);
	jsonw_end(w);
}

/* A mission beyond reach: what is reachable instead (null otherwise). */
static void
put_ceiling(struct jsonw *w, const struct solve_result *r)
{
	const struct res_ceiling *c = &r->ceiling;
	if (!c->valid) {
		jsonw_null(w, "ceiling");
		return;
	}
	jsonw_object(w, "ceiling");
	jsonw_string(w, "binds_code", c->binds_code);
	JW_STR(w, "binds", c->binds);
	jsonw_bool(w, "endurance_found", c->endurance_found);
	jsonw_number(w, "time_scale", c->time_scale);
	jsonw_number(w, "flight_time_s", c->flight_time_s);
	jsonw_number(w, "hover_endurance_s", c->hover_endurance_s);
	jsonw_number(w, "mass_kg", c->mass_kg);
	jsonw_bool(w, "payload_found", c->payload_found);
	jsonw_number(w, "max_payload_kg", c->max_payload_kg);
	jsonw_number(w, "mass_at_max_payload_kg", c->mass_at_payload_kg);
	jsonw_bool(w, "custom_is_ceiling_design", c->shown);
	jsonw_end(w);
}

/* A number that may not apply (NAN): null then. */
static void
jw_num_or_null(struct jsonw *w, const char *key, double x)
{
	if (isnan(x))
		jsonw_null(w, key);
	else
		jsonw_number(w, key, x);
}

/* The figures of the design of record the dossier's cover and summary,
 * bom_totals.csv and index.csv print (res_figures()): one number each. */
static void
put_key_figures(struct jsonw *w, const struct solve_result *r)
{
	struct res_figures f;
	res_figures(r, &f);
	jsonw_object(w, "key_figures");
	jsonw_number(w, "takeoff_mass_kg", f.takeoff_mass_kg);
	jsonw_bool(w, "sheds_payload", f.sheds);
	jsonw_number(w, "hover_power_at_takeoff_mass_w", f.hover_power_w);
	jw_num_or_null(w, "hover_power_after_shedding_w", f.hover_power_shed_w);
	jw_num_or_null(w, "hover_battery_current_at_takeoff_mass_a", f.hover_current_a);
	jsonw_number(w, "aux_power_w", f.aux_power_w);
	jsonw_number(w, "hover_endurance_s", f.hover_endurance_s);
	jsonw_number(w, "flight_time_s", f.flight_time_s);
	jsonw_number(w, "landing_soc", f.landing_soc);
	jsonw_number(w, "bom_mass_kg", f.bom_mass_kg);
	jsonw_number(w, "bom_price_usd", f.bom_price_usd);
	jsonw_int(w, "bom_lines", f.bom_lines);
	jsonw_int(w, "bom_unpriced_lines", f.unpriced_lines);
	jsonw_end(w);
}

/* ---- top level ------------------------------------------------------------- */

static void
put_violations(struct jsonw *w, const struct solve_result *r)
{
	int n = jw_count(w, "violations", r->n_violations, RES_MAX_VIOLATIONS);
	jsonw_array(w, "violations");
	for (int i = 0; i < n; i++) {
		const struct res_violation *v = &r->violations[i];
		jsonw_object(w, NULL);
		jsonw_string(w, "run", v->run);
		jsonw_string(w, "stage", v->stage);
		jsonw_string(w, "code", v->code);
		JW_STR(w, "message", v->message);
		int nf = jw_count(w, "suggested_fixes", v->n_fixes, RES_MAX_FIXES);
		jsonw_array(w, "suggested_fixes");
		for (int k = 0; k < nf; k++)
			JW_STR(w, NULL, v->fixes[k]);
		jsonw_end(w);
		jsonw_end(w);
	}
	jsonw_end(w);
}

char *
result_json_render_checked(const struct solve_result *r,
                           const char *aeroeval_version,
                           struct result_json_faults *faults)
{
	struct jsonw w;
	jsonw_init(&w);

	jsonw_object(&w, NULL);
	jsonw_string(&w, "aeroeval_version", aeroeval_version);
	JW_STR(&w, "input_sha256", r->input_sha256);
	JW_STR(&w, "catalogue_sha256", r->catalogue_sha256);
	jsonw_string(&w, "status", r->feasible ? "feasible" : "infeasible");
	struct res_figures fig;
	res_figures(r, &fig);
	jsonw_bool(&w, "buildable", fig.buildable);
	jsonw_number(&w, "takeoff_mass_kg", fig.takeoff_mass_kg);
	jsonw_object(&w, "regulatory_class");
	jsonw_string(&w, "eu_open_category", res_eu_class(fig.takeoff_mass_kg));
	jsonw_bool(&w, "us_part_107_small_uas", fig.takeoff_mass_kg < RES_US_107_KG);
	jsonw_end(&w);
	put_key_figures(&w, r);
	put_accuracy(&w, r);
	put_ceiling(&w, r);
	put_violations(&w, r);
	int nr = jw_count(&w, "rationale", r->n_rationale, RES_MAX_RATIONALE);
	jsonw_array(&w, "rationale");
	for (int i = 0; i < nr; i++)
		JW_STR(&w, NULL, r->rationale[i]);
	jsonw_end(&w);

	put_mission(&w, &r->mission);
	put_run(&w, "baseline", &r->baseline, NULL);
	put_run(&w, "custom", &r->custom, r);
	jsonw_object(&w, "role_overhead");
	put_mass(&w, &r->role_overhead);
	jsonw_end(&w);
	if (r->custom.ran)
		put_optimum(&w, "continuous_optimum", &r->custom.opt);
	else
		jsonw_null(&w, "continuous_optimum");
	put_record(&w, r);
	put_selected(&w, r);
	put_bom(&w, r);
	put_candidates(&w, r);
	jsonw_end(&w);

	struct jsonw_faults f;
	char *text = jsonw_finish(&w, &f);
	if (faults) {
		faults->n_invalid = f.n_invalid;
		snprintf(faults->first_path, sizeof faults->first_path, "%s", f.first_path);
	}
	return text;
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
