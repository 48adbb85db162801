/* test_result_json.c — result.json: keys, exact numbers, faults, golden file.
 *
 * A synthetic solve_result is filled with high-entropy values (17
 * significant digits, many magnitudes), rendered, parsed back with cJSON and
 * compared with == : the writer promises that every double round-trips.
 * Run with AEROEVAL_UPDATE_GOLDEN=1 to rewrite the golden file after an
 * intended format change (then review the diff).
 */
#include "test_util.h"
#include "formats/result_json.h"
#include "util/xalloc.h"

#include <cjson/cJSON.h>
#include <fcntl.h>
#include <float.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define GOLDEN "tests/fixtures/outputs/result.json.expected"
#define VERSION "9.8.7-test"

/* ---- fixture --------------------------------------------------------------- */

/* Deterministic xorshift64*, so the fixture (and the golden file) never
 * changes between machines. */
struct rng {
	unsigned long long s;
};

static double
rnd(struct rng *g)
{
	g->s ^= g->s >> 12;
	g->s ^= g->s << 25;
	g->s ^= g->s >> 27;
	return (double)((g->s * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}

/* A value in [lo, hi) with all 53 bits random. */
static double
val(struct rng *g, double lo, double hi)
{
	return lo + (hi - lo) * rnd(g);
}

/* Scalar doubles of struct res_run and their result.json keys.  The test
 * fills every one and checks it comes back exactly. */
static const struct {
	const char *key;
	size_t off;
} run_doubles[] = {
#define RD(key, member) { key, offsetof(struct res_run, member) }
	RD("lipschitz_estimate", lipschitz),
	RD("time_scale", time_scale),
	RD("battery_capacity_mah", capacity_mah),
	RD("energy_wh", energy_wh),
	RD("packaging_factor", packaging_factor),
	RD("nominal_voltage_v", nominal_voltage_v),
	RD("approved_climb_time_s", approved_time_s[PHASE_CLIMB]),
	RD("approved_forward_time_s", approved_time_s[PHASE_FORWARD]),
	RD("approved_hover_time_s", approved_time_s[PHASE_HOVER]),
	RD("flight_time_s", flight_time_s),
	RD("hover_endurance_s", hover_endurance_s),
	RD("marketing_endurance_s", marketing_endurance_s),
	RD("optimal_speed_ms", optimal_speed_ms),
	RD("v_min_power_ms", v_min_power_ms),
	RD("v_max_ms", v_max_ms),
	RD("thrust_to_weight_ratio", thrust_to_weight),
	RD("hover_throttle", hover_throttle),
	RD("forward_pitch_deg", forward_pitch_deg),
	RD("disk_loading_n_m2", disk_loading_n_m2),
	RD("downwash_ms", downwash_ms),
	RD("fom_installed", fom_installed),
	RD("interference", interference),
	RD("reynolds_tip", reynolds_tip),
	RD("rpm_hover", rpm_hover),
	RD("rpm_peak", rpm_peak),
	RD("tip_mach_peak", tip_mach_peak),
	RD("overlap_limit_in", overlap_limit_in),
	RD("peak_power_w", peak_power_w),
	RD("peak_current_a", peak_current_a),
	RD("peak_c_rate", peak_c_rate),
	RD("arm_length_m", arm_length_m),
	RD("arm_outer_diameter_mm", arm_outer_diameter_mm),
	RD("arm_wall_thickness_mm", arm_wall_thickness_mm),
	RD("arm_stress_mpa", arm_stress_mpa),
	RD("arm_stress_allow_mpa", arm_stress_allow_mpa),
	RD("arm_natural_frequency_hz", arm_natural_frequency_hz),
	RD("blade_pass_frequency_hz", blade_pass_frequency_hz),
	RD("resonance_margin", resonance_margin),
	RD("max_battery_temp_c", max_battery_temp_c),
	RD("thermal_margin_c", thermal_margin_c),
	RD("min_terminal_voltage_v", min_terminal_voltage_v),
	RD("voltage_floor_v", voltage_floor_v),
	RD("end_soc", end_soc),
	RD("blade_pass_low_hz", blade_pass_low_hz),
	RD("arm_tip_mass_kg", arm_tip_mass_kg),
	RD("winding_temp_c", winding_temp_c),
	RD("motor_winding_resistance_ohm", motor_winding_resistance_ohm),
	RD("motor_copper_loss_w", motor_copper_loss_w),
	RD("hover_power_w", hover_power_w),
	RD("hover_power_after_shedding_w", hover_power_shed_w),
#undef RD
};
#define N_RUN_DOUBLES (sizeof run_doubles / sizeof run_doubles[0])

/* The mass items in result.json order after total_mass_kg. */
static const struct {
	const char *key;
	size_t off;
} mass_items[] = {
#define MI(key, member) { key, offsetof(struct res_mass, member) }
	MI("payload_kg", payload_kg),
	MI("battery_mass_kg", battery_kg),
	MI("frame_mass_kg", frame_kg),
	MI("arm_mass_kg", arm_kg),
	MI("motor_mass_kg", motor_kg),
	MI("prop_mass_kg", prop_kg),
	MI("esc_mass_kg", esc_kg),
	MI("wiring_mass_kg", wiring_kg),
	MI("avionics_mass_kg", avionics_kg),
	MI("role_aux_mass_kg", role_aux_kg),
	MI("other_mass_kg", other_kg),
#undef MI
};
#define N_MASS_ITEMS (sizeof mass_items / sizeof mass_items[0])

static double *
run_double(struct res_run *run, size_t off)
{
	return (double *)((char *)run + off);
}

static double *
mass_item(struct res_mass *m, size_t off)
{
	return (double *)((char *)m + off);
}

/* Sizes of the variable-length parts: small for the golden file. */
struct fixture_size {
	int history, trace, sweep, endurance, checks, candidates;
};

static const struct fixture_size SMALL = { 4, 5, 3, 3, 2, 2 };
static const struct fixture_size FULL = { RES_MAX_HISTORY, RES_MAX_TRACE,
	RES_MAX_SWEEP, RES_MAX_ENDURANCE, RES_MAX_CHECKS, RES_MAX_CANDIDATES };

static void
fill_mass(struct rng *g, struct res_mass *m)
{
	double sum = 0.0;
	for (size_t i = 0; i < N_MASS_ITEMS; i++) {
		double *x = mass_item(m, mass_items[i].off);
		*x = val(g, 0.0123, 2.97);
		sum += *x;
	}
	m->total_kg = sum;
}

static void
fill_run(struct rng *g, struct res_run *run, const struct fixture_size *sz)
{
	run->ran = true;
	run->feasible = rnd(g) < 0.5;
	run->converged = true;
	snprintf(run->termination, sizeof run->termination,
	         "reserve reached at SOC 0.2 (\"hover\" phase)");
	run->iterations = sz->history;
	run->n_history = sz->history;
	for (int i = 0; i < sz->history; i++)
		run->history_kg[i] = val(g, 1.0, 30.0);
	for (size_t i = 0; i < N_RUN_DOUBLES; i++)
		*run_double(run, run_doubles[i].off) = val(g, -3.7, 1234.5) * pow(10.0, (int)(i % 9) - 4);
	fill_mass(g, &run->mass);
	snprintf(run->chemistry, sizeof run->chemistry, "LiPo");
	run->cell_count = 6;
	run->pack_count = 2;
	for (int p = 0; p < PHASE_MAX; p++) {
		struct res_phase *ph = &run->phase[p];
		double *x = &ph->duration_s;
		/* struct res_phase is eleven doubles in a row */
		for (size_t k = 0; k < sizeof *ph / sizeof(double); k++)
			x[k] = val(g, 0.01, 3000.0);
	}
	run->n_sweep = sz->sweep;
	for (int i = 0; i < sz->sweep; i++) {
		run->sweep_v_ms[i] = 1.0 + 0.5 * i;
		run->sweep_power_w[i] = val(g, 100.0, 900.0);
	}
	run->opt = (struct res_optimum){ val(g, 5, 30), val(g, 2, 12), val(g, 100, 2000),
		val(g, 0.03, 0.4), val(g, 5, 60), val(g, 100, 2000) };
	run->arm_wall_floor_binds = false;
	run->min_fraction_binds = true;
	run->v_max_limit = RES_LIMIT_PITCH;
	run->n_trace = sz->trace;
	for (int i = 0; i < sz->trace; i++) {
		struct res_sample *s = &run->trace[i];
		*s = (struct res_sample){ 2.5 * i, val(g, 0, 1), val(g, 20, 25),
			val(g, 18, 25), val(g, 5, 80), val(g, 100, 2000),
			val(g, 15, 60), val(g, 2, 10), i * PHASE_MAX / sz->trace };
	}
	run->n_endurance = sz->endurance;
	for (int i = 0; i < sz->endurance; i++) {
		run->endurance_scale[i] = 0.25 * (i + 1);
		run->endurance_time_s[i] = val(g, 100, 3000);
		run->endurance_mass_kg[i] = val(g, 1, 20);
	}
	run->endurance_inflection_scale = val(g, 0.5, 3);
	run->n_checks = sz->checks;
	/* A check's name is static text (result.h). */
	static char names[RES_MAX_CHECKS][24];
	for (int i = 0; i < sz->checks; i++) {
		struct res_check *c = &run->checks[i];
		snprintf(names[i], sizeof names[i], "Check %d", i);
		c->name = names[i];
		c->unit = "\xc2\xb0" "C";
		c->value = val(g, 10, 70);
		c->limit = 60.0;
		c->upper = i % 2 == 0;
		c->margin = (c->limit - c->value) / c->limit;
		c->pass = c->margin >= 0;
	}
}

static void
fill_part(struct rng *g, struct res_part *p, const char *id, int qty)
{
	p->chosen = true;
	snprintf(p->id, sizeof p->id, "%s", id);
	snprintf(p->manufacturer, sizeof p->manufacturer, "T-Motor");
	snprintf(p->part_number, sizeof p->part_number, "%s-PN", id);
	snprintf(p->description, sizeof p->description, "%s, a \"good\" one", id);
	p->qty = qty;
	p->unit_mass_kg = val(g, 0.01, 1.5);
	p->unit_price_usd = val(g, 5, 300);
	p->j_score = val(g, 0, 2);
}

/* A fully populated result; the caller frees it. */
static struct solve_result *
fixture_new(const struct fixture_size *sz)
{
	struct rng g = { 0x9E3779B97F4A7C15ULL };
	struct solve_result *r = xcalloc(1, sizeof *r);
	spec_defaults(&r->mission);
	snprintf(r->mission.name, sizeof r->mission.name, "Survey \"north\" field");
	r->mission.payload_kg = 2.3456789012345678;
	r->mission.given[SPECF_NAME] = true;
	r->mission.given[SPECF_PAYLOAD_KG] = true;
	r->mission.v_forward_auto = true;
	r->mission.given[SPECF_V_FORWARD_MS] = true;
	r->mission.airframe_class = AF_AGRICULTURAL;
	r->mission.given[SPECF_AIRFRAME_CLASS] = true;
	r->mission.structural_overrides.arm_config = ARM_UNDER_ROTOR;
	r->mission.locks.locked_kv = 917.25;
	memset(r->input_sha256, 'a', 64);
	memset(r->catalogue_sha256, 'b', 64);

	fill_run(&g, &r->baseline, sz);
	fill_run(&g, &r->custom, sz);
	fill_run(&g, &r->closed, sz);
	double *b = &r->baseline.mass.payload_kg, *c = &r->custom.mass.payload_kg;
	double *o = &r->role_overhead.payload_kg;
	for (size_t k = 0; k < sizeof r->role_overhead / sizeof(double); k++)
		o[k] = c[k] - b[k];

	r->parts_selected = true;
	fill_part(&g, &r->motor, "tm-mn5008", 4);
	fill_part(&g, &r->prop, "tm-p18", 4);
	fill_part(&g, &r->battery, "tattu-16000-6s", 2);
	fill_part(&g, &r->esc, "tm-f55a", 4);
	r->battery_series_packs = 1;
	r->battery_parallel_packs = 2;
	const struct res_part *parts[] = { &r->motor, &r->prop, &r->battery, &r->esc };
	r->n_bom = 5;
	for (int i = 0; i < r->n_bom; i++) {
		struct res_bom_line *l = &r->bom[i];
		l->item = i + 1;
		if (i < 4) {
			const struct res_part *p = parts[i];
			l->qty = p->qty;
			snprintf(l->category, sizeof l->category, "%s",
			         (const char *[]){ "motor", "propeller", "battery", "esc" }[i]);
			snprintf(l->manufacturer, sizeof l->manufacturer, "%s", p->manufacturer);
			snprintf(l->part_number, sizeof l->part_number, "%s", p->part_number);
			snprintf(l->description, sizeof l->description, "%s", p->description);
			snprintf(l->catalogue_id, sizeof l->catalogue_id, "%s", p->id);
			l->unit_mass_kg = p->unit_mass_kg;
			l->unit_price_usd = p->unit_price_usd;
		} else {
			l->qty = 4;
			snprintf(l->category, sizeof l->category, "custom");
			snprintf(l->description, sizeof l->description,
			         "CFRP arm tube 22.0 x 20.0 mm, 0.412 m");
			l->unit_mass_kg = val(&g, 0.02, 0.2);
			l->unit_price_usd = 0.0; /* unknown */
		}
		l->total_mass_kg = l->qty * l->unit_mass_kg;
		l->total_price_usd = l->qty * l->unit_price_usd;
		r->bom_mass_kg += l->total_mass_kg;
		r->bom_price_usd += l->total_price_usd;
		r->bom_parts_lines++;
		r->bom_priced_lines += l->unit_price_usd > 0.0;
	}
	r->n_candidates = sz->candidates;
	for (int i = 0; i < sz->candidates; i++) {
		struct res_candidate *k = &r->candidates[i];
		snprintf(k->id, sizeof k->id, "motor-%03d", i);
		k->kv = val(&g, 100, 3000);
		k->mass_kg = val(&g, 0.02, 0.6);
		k->j_score = i % 5 == 4 ? 1e9 : val(&g, 0, 3);
		k->feasible = k->j_score < 1e9;
	}

	r->feasible = false;
	r->n_violations = 1;
	struct res_violation *v = &r->violations[0];
	v->run = "custom";
	v->stage = "discharge";
	v->code = "BATTERY_OVERTEMP";
	snprintf(v->message, sizeof v->message, "Pack reaches 63.2 \xc2\xb0" "C, above 60 \xc2\xb0" "C");
	v->n_fixes = 2;
	snprintf(v->fixes[0], sizeof v->fixes[0], "Add a second pack in parallel");
	snprintf(v->fixes[1], sizeof v->fixes[1], "Shorten t_hover_s");
	r->n_rationale = 2;
	snprintf(r->rationale[0], sizeof r->rationale[0], "6S chosen for the motor's KV range");
	snprintf(r->rationale[1], sizeof r->rationale[1], "Tab\there, backslash \\ and newline\nend");
	return r;
}

/* ---- helpers --------------------------------------------------------------- */

/* Renders r and parses it back; fails the test on any fault or syntax error. */
static cJSON *
render_parse(const struct solve_result *r, char **text_out)
{
	struct result_json_faults f;
	char *text = result_json_render_checked(r, VERSION, &f);
	assert_int_equal(f.n_invalid, 0);
	const char *end = NULL;
	cJSON *root = cJSON_ParseWithLengthOpts(text, strlen(text) + 1, &end, 1);
	if (!root)
		fail_msg("result.json does not parse near byte %td", end ? end - text : -1);
	if (text_out)
		*text_out = text;
	else
		free(text);
	return root;
}

static const cJSON *
get(const cJSON *obj, const char *key)
{
	const cJSON *it = cJSON_GetObjectItemCaseSensitive(obj, key);
	if (!it)
		fail_msg("missing key \"%s\"", key);
	return it;
}

static double
num(const cJSON *obj, const char *key)
{
	const cJSON *it = get(obj, key);
	if (!cJSON_IsNumber(it))
		fail_msg("\"%s\" is not a number", key);
	return it->valuedouble;
}

static const char *
str(const cJSON *obj, const char *key)
{
	const cJSON *it = get(obj, key);
	if (!cJSON_IsString(it))
		fail_msg("\"%s\" is not a string", key);
	return it->valuestring;
}

/* Exact double comparison with both values printed in full. */
#define assert_exact(got, want) do { \
	double g_ = (got), w_ = (want); \
	if (!(g_ == w_)) \
		fail_msg("%s = %.17g, want exactly %.17g", #got, g_, w_); \
} while (0)

static void
assert_array_exact(const cJSON *arr, const double *want, int n)
{
	assert_true(cJSON_IsArray(arr));
	assert_int_equal(cJSON_GetArraySize(arr), n);
	int i = 0;
	const cJSON *it;
	cJSON_ArrayForEach(it, arr) {
		assert_exact(it->valuedouble, want[i]);
		i++;
	}
}

/* ---- tests ----------------------------------------------------------------- */

static void
result_json_should_hold_every_product_key_per_run(void **state)
{
	(void)state;
	static const char *const top[] = {
		"aeroeval_version", "input_sha256", "catalogue_sha256", "status",
		"buildable", "takeoff_mass_kg", "regulatory_class", "key_figures", "mtow_interval",
		"hover_power_interval", "hover_endurance_interval", "accuracy", "ceiling",
		"violations", "rationale", "mission", "baseline", "custom",
		"role_overhead", "continuous_optimum", "design_of_record",
		"selected", "bom", "candidates"
	};
	/* The keys every run holds, which readers of result.json rely on. */
	static const char *const per_run[] = {
		"total_mass_kg", "payload_kg", "battery_mass_kg", "frame_mass_kg",
		"arm_mass_kg", "motor_mass_kg", "prop_mass_kg", "esc_mass_kg",
		"wiring_mass_kg", "avionics_mass_kg", "role_aux_mass_kg",
		"other_mass_kg", "converged", "iterations", "convergence_history",
		"lipschitz_estimate", "cell_count", "battery_capacity_mah",
		"energy_wh", "phases", "approved_hover_time_s",
		"approved_climb_time_s", "approved_forward_time_s",
		"thrust_to_weight_ratio", "hover_throttle", "forward_pitch_deg",
		"optimal_speed_ms", "disk_loading_n_m2", "downwash_ms",
		"arm_outer_diameter_mm", "arm_wall_thickness_mm",
		"arm_natural_frequency_hz", "blade_pass_frequency_hz",
		"resonance_margin", "max_battery_temp_c", "thermal_margin_c",
		"min_terminal_voltage_v", "time_series", "continuous_optimum",
		"feasible", "ran", "checks", "speed_sweep", "endurance_explorer",
		"selected", "bom", "v_max_limited_by"
	};
	static const char *const phase_keys[] = {
		"phase", "duration_s", "power_w", "current_a", "energy_wh"
	};
	static const char *const runs[] = { "baseline", "custom", "design_of_record" };
	struct solve_result *r = fixture_new(&SMALL);
	cJSON *root = render_parse(r, NULL);

	/* Top-level keys, in this order and no others. */
	const cJSON *it = root->child;
	for (size_t i = 0; i < sizeof top / sizeof top[0]; i++, it = it->next) {
		assert_non_null(it);
		assert_string_equal(it->string, top[i]);
	}
	assert_null(it);

	for (size_t k = 0; k < 3; k++) {
		const cJSON *run = get(root, runs[k]);
		/* The record names its propeller and motor "propulsion": real
		 * parts, not the continuous optimum of the top level. */
		for (size_t i = 0; i < sizeof per_run / sizeof per_run[0]; i++)
			get(run, k == 2 && strcmp(per_run[i], "continuous_optimum") == 0
			    ? "propulsion" : per_run[i]);
		const cJSON *phases = get(run, "phases");
		assert_int_equal(cJSON_GetArraySize(phases), PHASE_MAX);
		for (int p = 0; p < PHASE_MAX; p++) {
			const cJSON *ph = cJSON_GetArrayItem(phases, p);
			for (size_t i = 0; i < sizeof phase_keys / sizeof phase_keys[0]; i++)
				get(ph, phase_keys[i]);
			assert_string_equal(str(ph, "phase"), res_phase_name[p]);
		}
		/* What ends the top speed, next to it. */
		assert_string_equal(str(run, "v_max_limited_by"), "pitch_limit");
	}
	/* The baseline is not mapped to parts; the custom design's parts and
	 * BOM are the top level's. */
	assert_true(cJSON_IsNull(get(get(root, "baseline"), "selected")));
	assert_true(cJSON_IsNull(get(get(root, "baseline"), "bom")));
	assert_true(cJSON_Compare(get(get(root, "custom"), "selected"),
	    get(root, "selected"), 1));
	assert_true(cJSON_Compare(get(get(root, "custom"), "bom"),
	    get(root, "bom"), 1));
	const cJSON *opt = get(root, "continuous_optimum");
	assert_exact(num(opt, "prop_diameter_in"), r->custom.opt.prop_diameter_in);
	assert_exact(num(opt, "prop_pitch_in"), r->custom.opt.prop_pitch_in);
	assert_exact(num(opt, "motor_kv"), r->custom.opt.motor_kv);
	assert_string_equal(str(root, "status"), "infeasible");
	assert_string_equal(str(root, "aeroeval_version"), VERSION);

	cJSON_Delete(root);
	free(r);
}

static void
check_run_exact(const cJSON *jr, const struct res_run *run, const char *prop_key)
{
	for (size_t i = 0; i < N_RUN_DOUBLES; i++) {
		double want = *run_double((struct res_run *)run, run_doubles[i].off);
		if (num(jr, run_doubles[i].key) != want)
			fail_msg("%s = %.17g, want %.17g", run_doubles[i].key,
			         num(jr, run_doubles[i].key), want);
	}
	assert_exact(num(jr, "total_mass_kg"), run->mass.total_kg);
	for (size_t i = 0; i < N_MASS_ITEMS; i++)
		assert_exact(num(jr, mass_items[i].key),
		             *mass_item((struct res_mass *)&run->mass, mass_items[i].off));
	assert_array_exact(get(jr, "convergence_history"), run->history_kg, run->n_history);
	const cJSON *ph = get(jr, "phases");
	for (int p = 0; p < PHASE_MAX; p++) {
		const cJSON *o = cJSON_GetArrayItem(ph, p);
		const struct res_phase *w = &run->phase[p];
		assert_exact(num(o, "duration_s"), w->duration_s);
		assert_exact(num(o, "speed_ms"), w->speed_ms);
		assert_exact(num(o, "thrust_per_rotor_n"), w->thrust_per_rotor_n);
		assert_exact(num(o, "shaft_power_w"), w->shaft_power_w);
		assert_exact(num(o, "power_w"), w->power_w);
		assert_exact(num(o, "current_a"), w->current_a);
		assert_exact(num(o, "energy_wh"), w->energy_wh);
		assert_exact(num(o, "rpm"), w->rpm);
		assert_exact(num(o, "throttle"), w->throttle);
		assert_exact(num(o, "pitch_deg"), w->pitch_deg);
		assert_exact(num(o, "tip_mach"), w->tip_mach);
	}
	const cJSON *sw = get(jr, "speed_sweep");
	assert_array_exact(get(sw, "v_ms"), run->sweep_v_ms, run->n_sweep);
	assert_array_exact(get(sw, "power_w"), run->sweep_power_w, run->n_sweep);
	const cJSON *en = get(jr, "endurance_explorer");
	assert_array_exact(get(en, "scale"), run->endurance_scale, run->n_endurance);
	assert_array_exact(get(en, "time_s"), run->endurance_time_s, run->n_endurance);
	assert_array_exact(get(en, "mass_kg"), run->endurance_mass_kg, run->n_endurance);
	assert_exact(num(en, "inflection_scale"), run->endurance_inflection_scale);
	const cJSON *op = get(jr, prop_key);
	assert_exact(num(op, "motor_mass_kg"), run->opt.motor_mass_kg);
	assert_exact(num(op, "motor_peak_power_w"), run->opt.motor_peak_power_w);
	const cJSON *ts = get(jr, "time_series");
	double col[RES_MAX_TRACE];
	for (int i = 0; i < run->n_trace; i++)
		col[i] = run->trace[i].v_term_v;
	assert_array_exact(get(ts, "v_term_v"), col, run->n_trace);
	for (int i = 0; i < run->n_trace; i++)
		col[i] = run->trace[i].temp_c;
	assert_array_exact(get(ts, "temp_c"), col, run->n_trace);
	const cJSON *ch = get(jr, "checks");
	assert_int_equal(cJSON_GetArraySize(ch), run->n_checks);
	for (int i = 0; i < run->n_checks; i++) {
		const cJSON *o = cJSON_GetArrayItem(ch, i);
		assert_exact(num(o, "value"), run->checks[i].value);
		assert_exact(num(o, "margin"), run->checks[i].margin);
		assert_string_equal(str(o, "kind"), run->checks[i].upper ? "max" : "min");
		assert_string_equal(str(o, "unit"), "\xc2\xb0" "C");
		assert_true(cJSON_IsBool(get(o, "pass")));
	}
	assert_true(cJSON_IsTrue(get(jr, "min_fraction_binds")));
	assert_true(cJSON_IsFalse(get(jr, "arm_wall_floor_binds")));
	assert_int_equal((int)num(jr, "cell_count"), run->cell_count);
	assert_string_equal(str(jr, "termination"), run->termination);
}

static void
result_json_numbers_should_round_trip_exactly(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&FULL);
	cJSON *root = render_parse(r, NULL);
	check_run_exact(get(root, "baseline"), &r->baseline, "continuous_optimum");
	check_run_exact(get(root, "custom"), &r->custom, "continuous_optimum");
	check_run_exact(get(root, "design_of_record"), &r->closed, "propulsion");

	const cJSON *bat = get(get(root, "selected"), "battery");
	assert_exact(num(bat, "unit_mass_kg"), r->battery.unit_mass_kg);
	assert_exact(num(bat, "unit_price_usd"), r->battery.unit_price_usd);
	assert_exact(num(bat, "j_score"), r->battery.j_score);
	assert_int_equal((int)num(bat, "parallel_packs"), 2);
	assert_int_equal((int)num(bat, "series_packs"), 1);
	assert_string_equal(str(bat, "catalogue_id"), "tattu-16000-6s");

	const cJSON *bom = get(root, "bom");
	assert_exact(num(bom, "total_mass_kg"), r->bom_mass_kg);
	assert_exact(num(bom, "total_price_usd"), r->bom_price_usd);
	assert_int_equal((int)num(bom, "unpriced_lines"), 1);
	const cJSON *lines = get(bom, "lines");
	assert_int_equal(cJSON_GetArraySize(lines), r->n_bom);
	const cJSON *custom_line = cJSON_GetArrayItem(lines, 4);
	assert_true(cJSON_IsNull(get(custom_line, "unit_price_usd")));
	assert_true(cJSON_IsNull(get(custom_line, "total_price_usd")));
	assert_exact(num(custom_line, "total_mass_kg"), r->bom[4].total_mass_kg);

	const cJSON *cands = get(root, "candidates");
	assert_int_equal(cJSON_GetArraySize(cands), RES_MAX_CANDIDATES);
	for (int i = 0; i < RES_MAX_CANDIDATES; i++) {
		const cJSON *o = cJSON_GetArrayItem(cands, i);
		assert_exact(num(o, "kv"), r->candidates[i].kv);
		assert_exact(num(o, "j_score"), r->candidates[i].j_score);
	}
	const cJSON *ro = get(root, "role_overhead");
	assert_exact(num(ro, "battery_mass_kg"), r->role_overhead.battery_kg);
	assert_exact(num(get(root, "mission"), "payload_kg"), r->mission.payload_kg);
	cJSON_Delete(root);
	free(r);
}

static void
result_json_mass_breakdown_should_sum_to_total(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&SMALL);
	cJSON *root = render_parse(r, NULL);
	static const char *const runs[] = { "baseline", "custom", "design_of_record", "role_overhead" };
	for (size_t k = 0; k < 4; k++) {
		const cJSON *jr = get(root, runs[k]);
		double sum = 0.0;
		for (size_t i = 0; i < N_MASS_ITEMS; i++)
			sum += num(jr, mass_items[i].key);
		assert_rel(sum, num(jr, "total_mass_kg"), 1e-12);
	}
	cJSON_Delete(root);
	free(r);
}

static void
result_json_time_series_should_have_n_trace_entries(void **state)
{
	(void)state;
	static const char *const cols[] = {
		"t_s", "soc", "v_oc_v", "v_term_v", "current_a", "power_w",
		"temp_c", "mass_kg", "phase"
	};
	struct solve_result *r = fixture_new(&FULL);
	enum { N = 71 }; /* not a multiple of the packing width */
	_Static_assert(N < RES_MAX_TRACE, "N must fit the trace");
	r->custom.n_trace = N;
	cJSON *root = render_parse(r, NULL);
	const cJSON *ts = get(get(root, "custom"), "time_series");
	assert_int_equal((int)num(ts, "n"), N);
	for (size_t i = 0; i < sizeof cols / sizeof cols[0]; i++)
		assert_int_equal(cJSON_GetArraySize(get(ts, cols[i])), N);
	const cJSON *ph = get(ts, "phase");
	assert_string_equal(cJSON_GetArrayItem(ph, 0)->valuestring, "climb");
	assert_string_equal(cJSON_GetArrayItem(ph, N - 1)->valuestring, "hover");
	assert_exact(cJSON_GetArrayItem(get(ts, "soc"), N - 1)->valuedouble,
	             r->custom.trace[N - 1].soc);
	ts = get(get(root, "baseline"), "time_series");
	assert_int_equal(cJSON_GetArraySize(get(ts, "mass_kg")), RES_MAX_TRACE);
	cJSON_Delete(root);
	free(r);
}

/* Looks a dotted mission path up in the rendered mission object. */
static const cJSON *
mission_field(const cJSON *mission, const char *path)
{
	char group[64];
	const char *dot = strchr(path, '.');
	if (!dot)
		return get(mission, path);
	snprintf(group, sizeof group, "%.*s", (int)(dot - path), path);
	return get(get(mission, group), dot + 1);
}

static void
result_json_mission_should_spell_auto_enums_and_defaulted(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&SMALL);
	cJSON *root = render_parse(r, NULL);
	const cJSON *m = get(root, "mission");

	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		const cJSON *it = mission_field(m, f->path);
		switch (f->type) {
		case SPEC_NUM:
			assert_exact(it->valuedouble, *(const double *)spec_member_const(&r->mission, f));
			break;
		case SPEC_INT:
			assert_true(cJSON_IsNumber(it));
			assert_int_equal(it->valueint, *(const int *)spec_member_const(&r->mission, f));
			break;
		case SPEC_BOOL:
			assert_true(cJSON_IsBool(it));
			break;
		case SPEC_ENUM:
			assert_string_equal(it->valuestring,
			                    f->enums[*(const int *)spec_member_const(&r->mission, f)]);
			break;
		case SPEC_SPEED:
		case SPEC_STR:
		case SPEC_DATE:
			assert_true(cJSON_IsString(it));
			break;
		}
	}
	assert_string_equal(str(m, "v_forward_ms"), "auto");
	assert_string_equal(str(m, "airframe_class"), "Agricultural");
	assert_string_equal(str(get(m, "structural_overrides"), "arm_config"), "under_rotor");
	assert_string_equal(str(m, "name"), "Survey \"north\" field");
	assert_string_equal(str(m, "battery_chemistry"), "LiHV");
	assert_exact(num(get(m, "locks"), "locked_kv"), 917.25);

	/* defaulted: every path not given, in table order. */
	const cJSON *d = get(m, "defaulted");
	assert_int_equal(cJSON_GetArraySize(d), SPEC_N_FIELDS - 4);
	const cJSON *it = d->child;
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		if (r->mission.given[i])
			continue;
		assert_string_equal(it->valuestring, spec_fields[i].path);
		it = it->next;
	}

	/* A numeric speed is a number again. */
	cJSON_Delete(root);
	r->mission.v_forward_auto = false;
	r->mission.v_forward_ms = 12.75;
	root = render_parse(r, NULL);
	assert_exact(num(get(root, "mission"), "v_forward_ms"), 12.75);
	cJSON_Delete(root);
	free(r);
}

static void
result_json_should_report_non_finite_value_as_null_with_path(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&SMALL);
	struct result_json_faults f;

	r->custom.phase[PHASE_HOVER].power_w = NAN;
	r->baseline.trace[3].temp_c = INFINITY;
	r->bom[1].unit_mass_kg = -INFINITY;
	char *text = result_json_render_checked(r, VERSION, &f);
	/* The BOM line is written three times: in the custom run, in the
	 * BOM-closed run and at the top level. */
	assert_int_equal(f.n_invalid, 5);
	/* The first in document order: baseline comes before custom. */
	assert_string_equal(f.first_path, "baseline.time_series.temp_c[3]");
	/* Every value follows a space; keys such as "resonance_margin" and
	 * "inflection_scale" contain the letters. */
	assert_null(strstr(text, " nan"));
	assert_null(strstr(text, " -nan"));
	assert_null(strstr(text, " inf"));
	assert_null(strstr(text, " -inf"));
	cJSON *root = cJSON_Parse(text);
	assert_non_null(root);
	const cJSON *hover = cJSON_GetArrayItem(get(get(root, "custom"), "phases"), PHASE_HOVER);
	assert_true(cJSON_IsNull(get(hover, "power_w")));
	cJSON_Delete(root);
	free(text);

	/* Paths name object keys, enum values and counts too. */
	r->baseline.trace[3].temp_c = 20.0;
	r->bom[1].unit_mass_kg = 0.5;
	r->custom.phase[PHASE_HOVER].power_w = 250.0;
	r->mission.requirements.priority = PRIORITY_MAX;
	text = result_json_render_checked(r, VERSION, &f);
	assert_int_equal(f.n_invalid, 1);
	assert_string_equal(f.first_path, "mission.requirements.priority");
	free(text);
	r->mission.requirements.priority = PRIORITY_RANGE;
	r->custom.lipschitz = NAN;
	text = result_json_render_checked(r, VERSION, &f);
	assert_string_equal(f.first_path, "custom.lipschitz_estimate");
	free(text);
	r->custom.lipschitz = 0.25;
	r->closed.n_checks = RES_MAX_CHECKS + 1;
	r->custom.trace[0].phase = 7;
	text = result_json_render_checked(r, VERSION, &f);
	assert_int_equal(f.n_invalid, 2);
	assert_string_equal(f.first_path, "custom.time_series.phase[0]");
	free(text);
	free(r);
}

/* The unchecked render is for callers that cannot fail: in a debug build a
 * NaN must stop the program (after naming the path), not slip out as null.
 * Run in a child so the abort does not end the test program. */
static void
result_json_unchecked_render_should_abort_on_nan_in_debug(void **state)
{
	(void)state;
#ifdef NDEBUG
	skip();
#else
	struct solve_result *r = fixture_new(&SMALL);
	r->custom.energy_wh = NAN;
	fflush(NULL);
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		signal(SIGABRT, SIG_DFL);
		int devnull = open("/dev/null", O_WRONLY);
		if (devnull >= 0)
			dup2(devnull, STDERR_FILENO);
		free(result_json_render(r, VERSION));
		_exit(0);
	}
	int status = 0;
	assert_int_equal(waitpid(pid, &status, 0), pid);
	assert_true(WIFSIGNALED(status));
	assert_int_equal(WTERMSIG(status), SIGABRT);
	free(r);
#endif
}

static void
result_json_should_write_ran_false_run_and_null_parts(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&SMALL);
	r->custom.ran = false;
	r->parts_selected = false;
	char *text = NULL;
	cJSON *root = render_parse(r, &text);
	assert_non_null(strstr(text, "\"custom\": {\n    \"ran\": false\n  },\n"));
	const cJSON *custom = get(root, "custom");
	assert_int_equal(cJSON_GetArraySize(custom), 1);
	assert_true(cJSON_IsNull(get(root, "continuous_optimum")));
	assert_true(cJSON_IsNull(get(root, "selected")));
	/* Nothing to build: the record is the continuous design, not run. */
	const cJSON *rec = get(root, "design_of_record");
	assert_true(cJSON_IsFalse(get(rec, "buildable")));
	assert_true(cJSON_IsFalse(get(rec, "ran")));
	const cJSON *bom = get(root, "bom");
	assert_int_equal(cJSON_GetArraySize(get(bom, "lines")), 0);
	assert_exact(num(bom, "total_mass_kg"), 0.0);
	assert_true(cJSON_IsTrue(get(get(root, "baseline"), "ran")));
	cJSON_Delete(root);
	free(text);

	/* Parts selected but the closed run stopped at the gate. */
	r->parts_selected = true;
	r->closed.ran = false;
	r->esc.chosen = false;
	root = render_parse(r, NULL);
	assert_true(cJSON_IsFalse(get(get(root, "design_of_record"), "buildable")));
	assert_true(cJSON_IsNull(get(get(root, "selected"), "esc")));
	cJSON_Delete(root);
	free(r);
}

static void
result_json_renders_should_be_byte_identical(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&FULL);
	char *a = result_json_render(r, VERSION);
	struct solve_result *r2 = fixture_new(&FULL);
	char *b = result_json_render(r2, VERSION);
	assert_string_equal(a, b);
	size_t n = strlen(a);
	assert_true(n > 2 && a[n - 1] == '\n' && a[n - 2] == '}');
	assert_null(strchr(a, '\r'));
	free(a);
	free(b);
	free(r);
	free(r2);
}

/* Finds "key": in text and returns the number text after it (static). */
static const char *
number_text(const char *text, const char *key)
{
	static char out[40];
	char pat[64];
	snprintf(pat, sizeof pat, "\"%s\": ", key);
	const char *p = strstr(text, pat);
	assert_non_null(p);
	p += strlen(pat);
	size_t n = strcspn(p, ",\n");
	assert_true(n < sizeof out);
	memcpy(out, p, n);
	out[n] = '\0';
	return out;
}

static void
result_json_numbers_should_print_shortest_exact_form(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&SMALL);
	r->baseline.ran = false;  /* so the first match is custom's */
	struct {
		double x;
		const char *want;
	} cases[] = {
		{ 0.1, "0.1" },
		{ 0.1 + 0.2, "0.30000000000000004" },   /* cJSON prints 0.3 */
		{ 9007199254740992.0, "9007199254740992" },
		{ 1.0 / 3.0, "0.3333333333333333" },
		{ -0.0, "0" },
		{ 1e-9, "1e-09" },
		{ 600.0, "600" },
		{ DBL_MAX, "1.7976931348623157e+308" },
		{ 5e-324, "4.94065645841247e-324" },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		r->custom.lipschitz = cases[i].x;
		char *text = result_json_render(r, VERSION);
		const char *got = number_text(text, "lipschitz_estimate");
		if (strcmp(got, cases[i].want) != 0)
			fail_msg("%.17g printed as %s, want %s", cases[i].x, got, cases[i].want);
		assert_true(strtod(got, NULL) == cases[i].x);
		free(text);
	}
	free(r);
}

static void
result_json_should_escape_strings(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&SMALL);
	/* quote, backslash, controls, DEL, valid 2/3/4-byte UTF-8, then a stray
	 * continuation byte, an overlong '/', a surrogate and a cut sequence. */
	snprintf(r->mission.name, sizeof r->mission.name,
	         "a\"b\\c\x01\x1f\b\f\n\r\t\x7f \xc3\xa9\xe2\x82\xac\xf0\x9f\x9a\x81 "
	         "\x80|\xc0\xaf|\xed\xa0\x80|\xe2\x82");
	char *text = NULL;
	cJSON *root = render_parse(r, &text);
	assert_non_null(strstr(text,
	        "\"a\\\"b\\\\c\\u0001\\u001f\\b\\f\\n\\r\\t\x7f \xc3\xa9\xe2\x82\xac\xf0\x9f\x9a\x81 "
	        "\xef\xbf\xbd|\xef\xbf\xbd\xef\xbf\xbd|\xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd|"
	        "\xef\xbf\xbd\xef\xbf\xbd\""));
	assert_string_equal(str(get(root, "mission"), "name"),
	        "a\"b\\c\x01\x1f\b\f\n\r\t\x7f \xc3\xa9\xe2\x82\xac\xf0\x9f\x9a\x81 "
	        "\xef\xbf\xbd|\xef\xbf\xbd\xef\xbf\xbd|\xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd|"
	        "\xef\xbf\xbd\xef\xbf\xbd");
	cJSON_Delete(root);
	free(text);
	free(r);
}

/* The design of record's envelope figures carry what limits them, next to
 * each figure, by name; the climb also its rotor speed. */
static void
result_json_should_name_what_limits_the_envelope(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&SMALL);
	struct res_perf *pf = &r->closed.perf;
	pf->valid = true;
	pf->max_speed_ms = 23.857;
	pf->max_speed_limit = RES_LIMIT_INFLOW;
	pf->max_climb_ms = 11.285;
	pf->max_climb_limit = RES_LIMIT_INFLOW;
	pf->max_climb_rpm = 4385.25;
	cJSON *root = render_parse(r, NULL);
	const cJSON *perf = get(get(root, "design_of_record"), "performance");
	assert_exact(num(perf, "max_speed_ms"), 23.857);
	assert_string_equal(str(perf, "max_speed_limited_by"), "propeller_inflow");
	assert_exact(num(perf, "max_climb_ms"), 11.285);
	assert_string_equal(str(perf, "max_climb_limited_by"), "propeller_inflow");
	assert_exact(num(perf, "max_climb_rpm"), 4385.25);
	/* Each key follows its figure. */
	assert_string_equal(get(perf, "max_speed_ms")->next->string,
	    "max_speed_limited_by");
	assert_string_equal(get(perf, "max_climb_ms")->next->string,
	    "max_climb_limited_by");
	cJSON_Delete(root);
	pf->max_speed_limit = RES_LIMIT_PITCH;
	pf->max_climb_limit = RES_LIMIT_BOUND;
	root = render_parse(r, NULL);
	perf = get(get(root, "design_of_record"), "performance");
	assert_string_equal(str(perf, "max_speed_limited_by"), "pitch_limit");
	assert_string_equal(str(perf, "max_climb_limited_by"), "search_bound");
	cJSON_Delete(root);
	free(r);
}

/* Byte comparison with the golden file; AEROEVAL_UPDATE_GOLDEN=1 rewrites it. */
static void
result_json_should_match_golden_file(void **state)
{
	(void)state;
	struct solve_result *r = fixture_new(&SMALL);
	char *text = result_json_render(r, VERSION);
	assert_golden(GOLDEN, text);
	free(text);
	free(r);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(result_json_should_hold_every_product_key_per_run),
		cmocka_unit_test(result_json_numbers_should_round_trip_exactly),
		cmocka_unit_test(result_json_mass_breakdown_should_sum_to_total),
		cmocka_unit_test(result_json_time_series_should_have_n_trace_entries),
		cmocka_unit_test(result_json_mission_should_spell_auto_enums_and_defaulted),
		cmocka_unit_test(result_json_should_report_non_finite_value_as_null_with_path),
		cmocka_unit_test(result_json_unchecked_render_should_abort_on_nan_in_debug),
		cmocka_unit_test(result_json_should_write_ran_false_run_and_null_parts),
		cmocka_unit_test(result_json_renders_should_be_byte_identical),
		cmocka_unit_test(result_json_numbers_should_print_shortest_exact_form),
		cmocka_unit_test(result_json_should_escape_strings),
		cmocka_unit_test(result_json_should_name_what_limits_the_envelope),
		cmocka_unit_test(result_json_should_match_golden_file),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
