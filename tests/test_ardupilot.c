/* test_ardupilot.c — the autopilot hand-off: vehicle_components.json holds
 * every field the Methodic Configurator's schema requires, and its numbers
 * and the parameter file's are the bill of materials' and the design of
 * record's.
 *
 * The examples are solved for real (pipeline_solve): the SAR quad is
 * buildable and feasible; a design without parts gets no hand-off.
 */
#include "test_util.h"

#include <cjson/cJSON.h>

#include "cli/cli.h"
#include "cli/pipeline.h"
#include "core/catalog.h"
#include "output/ardupilot.h"
#include "util/xalloc.h"

/* ---- the schema's required fields, as test data ----------------------------
 *
 * From ardupilot_methodic_configurator/vehicle_components_schema.json in
 * https://github.com/ArduPilot/MethodicConfigurator (draft-07; read at
 * commit ea969fbb7f2e4f9930d4d535cd21ffc0abf6c6b6):
 *   - top level: "required": ["Format version", "Components"] and
 *     "additionalProperties": false over Format version, Components,
 *     Program version, Configuration template; the project's ARCHITECTURE.md
 *     (section 9) makes all four required, so all four are checked;
 *   - Components: "required": [Flight Controller, Frame, Battery Monitor,
 *     Battery, ESC, Motors], "additionalProperties": false over those, RC
 *     Controller, RC Transmitter, RC Receiver, Telemetry, Propellers and
 *     GNSS Receiver;
 *   - every component (baseComponent): "required": ["Product"]; product:
 *     "required": ["Manufacturer", "Model"], strings;
 *   - flightController: "required": ["Firmware"];
 *   - battery: "required": ["Specifications"], whose "required" is
 *     ["Number of cells", "Capacity mAh"], both "integer";
 *   - Format version "integer", Program version and Configuration template
 *     "string"; frame TOW min/max Kg and propeller Diameter_inches "number".
 */
static const char *const top_required[] = {
	"Format version", "Components", "Program version", "Configuration template", NULL
};
static const char *const top_allowed[] = {
	"Format version", "Components", "Program version", "Configuration template", NULL
};
static const char *const comp_required[] = {
	"Flight Controller", "Frame", "Battery Monitor", "Battery", "ESC", "Motors", NULL
};
static const char *const comp_allowed[] = {
	"Flight Controller", "Frame", "RC Controller", "RC Transmitter", "RC Receiver",
	"Telemetry", "Battery Monitor", "Battery", "ESC", "Motors", "Propellers",
	"GNSS Receiver", NULL
};
static const char *const product_required[] = { "Manufacturer", "Model", NULL };
static const char *const battery_spec_required[] = { "Number of cells", "Capacity mAh", NULL };

/* ---- fixture ------------------------------------------------------------------ */

struct fixture {
	struct cli_env env;
	struct solve_result *sar;     /* buildable, feasible */
	struct ardupilot_design d;    /* of sar */
	char *components;
	char *params;
};

static struct solve_result *
solve(struct fixture *fx, const char *path)
{
	struct solve_result *r = xmalloc(sizeof *r);
	enum pipeline_status st = pipeline_solve(&fx->env, path, r, stderr, NULL, NULL);
	assert_true(st == PIPE_FEASIBLE || st == PIPE_INFEASIBLE);
	return r;
}

static int
setup(void **state)
{
	struct fixture *fx = xcalloc(1, sizeof *fx);
	if (cli_env_load(&fx->env, NULL, 1, stderr) != 0)
		return -1;
	fx->sar = solve(fx, "examples/sar_imaging_quad.json");
	char why[256];
	if (ardupilot_derive(fx->sar, &fx->env.model, fx->env.cat, &fx->d, why, sizeof why) != 0)
		return -1;
	fx->components = ardupilot_components(fx->sar, &fx->d, "sar_imaging_quad", "9.8.7");
	fx->params = ardupilot_params(&fx->d, "sar_imaging_quad", "9.8.7");
	*state = fx;
	return 0;
}

static int
teardown(void **state)
{
	struct fixture *fx = *state;
	free(fx->components);
	free(fx->params);
	free(fx->sar);
	cli_env_free(&fx->env);
	free(fx);
	return 0;
}

static const cJSON *
get(const cJSON *o, const char *key)
{
	const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
	if (v == NULL)
		fail_msg("missing \"%s\"", key);
	return v;
}

static void
assert_required(const cJSON *o, const char *const *keys)
{
	for (size_t i = 0; keys[i] != NULL; i++)
		get(o, keys[i]);
}

static void
assert_only(const cJSON *o, const char *const *allowed)
{
	const cJSON *c;
	cJSON_ArrayForEach(c, o) {
		bool ok = false;
		for (size_t i = 0; allowed[i] != NULL; i++)
			ok = ok || strcmp(c->string, allowed[i]) == 0;
		if (!ok)
			fail_msg("\"%s\" is not allowed here (additionalProperties: false)", c->string);
	}
}

static bool
is_integer(const cJSON *v)
{
	return cJSON_IsNumber(v) && v->valuedouble == floor(v->valuedouble);
}

/* The BOM line of a category (the first). */
static const struct res_bom_line *
bom_line(const struct solve_result *r, const char *category)
{
	for (int i = 0; i < r->n_bom; i++)
		if (strcmp(r->bom[i].category, category) == 0)
			return &r->bom[i];
	fail_msg("no %s line in the BOM", category);
	return NULL;
}

/* ---- vehicle_components.json -------------------------------------------------- */

static void
components_should_hold_every_field_the_schema_requires(void **state)
{
	struct fixture *fx = *state;
	cJSON *root = cJSON_Parse(fx->components);
	assert_non_null(root);
	assert_required(root, top_required);
	assert_only(root, top_allowed);
	assert_true(is_integer(get(root, "Format version")));
	assert_int_equal(get(root, "Format version")->valueint, 1);
	assert_true(cJSON_IsString(get(root, "Program version")));
	assert_true(cJSON_IsString(get(root, "Configuration template")));
	const cJSON *comps = get(root, "Components");
	assert_required(comps, comp_required);
	assert_only(comps, comp_allowed);
	const cJSON *c;
	cJSON_ArrayForEach(c, comps) {
		const cJSON *product = get(c, "Product");
		assert_required(product, product_required);
		assert_true(cJSON_IsString(get(product, "Manufacturer")));
		assert_true(cJSON_IsString(get(product, "Model")));
	}
	get(get(comps, "Flight Controller"), "Firmware");
	const cJSON *spec = get(get(comps, "Battery"), "Specifications");
	assert_required(spec, battery_spec_required);
	assert_true(is_integer(get(spec, "Number of cells")));
	assert_true(is_integer(get(spec, "Capacity mAh")));
	const cJSON *frame = get(get(comps, "Frame"), "Specifications");
	assert_true(cJSON_IsNumber(get(frame, "TOW min Kg")));
	assert_true(cJSON_IsNumber(get(frame, "TOW max Kg")));
	assert_true(cJSON_IsNumber(get(get(get(comps, "Propellers"), "Specifications"),
	    "Diameter_inches")));
	cJSON_Delete(root);
}

static void
components_numbers_should_be_the_bill_of_materials(void **state)
{
	struct fixture *fx = *state;
	const struct solve_result *r = fx->sar;
	const struct catalog_battery *b = catalog_find_battery(fx->env.cat, r->battery.id);
	const struct catalog_motor *m = catalog_find_motor(fx->env.cat, r->motor.id);
	const struct catalog_prop *p = catalog_find_prop(fx->env.cat, r->prop.id);
	assert_non_null(b);
	assert_non_null(m);
	assert_non_null(p);
	cJSON *root = cJSON_Parse(fx->components);
	const cJSON *comps = get(root, "Components");

	/* The pack: cells and capacity of the packs in series and parallel,
	 * which are the design of record's. */
	const cJSON *spec = get(get(comps, "Battery"), "Specifications");
	assert_int_equal(get(spec, "Number of cells")->valueint,
	                 b->cells_series * r->battery_series_packs);
	assert_int_equal(get(spec, "Number of cells")->valueint, r->closed.cell_count);
	assert_rel(get(spec, "Capacity mAh")->valuedouble,
	           1000.0 * b->capacity_ah * r->battery_parallel_packs, 1e-9);
	assert_rel(get(spec, "Capacity mAh")->valuedouble, r->closed.capacity_mah, 1e-9);
	assert_string_equal(get(spec, "Chemistry")->valuestring, "Lipo");
	assert_rel(get(spec, "Volt per cell max")->valuedouble, 4.2, 1e-12);
	assert_string_equal(get(get(get(comps, "Battery"), "Product"), "Model")->valuestring,
	                    bom_line(r, "battery")->part_number);

	/* Motors and propellers: the BOM's parts, KV and pitch in the notes. */
	const cJSON *motors = get(comps, "Motors");
	assert_string_equal(get(get(motors, "Product"), "Model")->valuestring,
	                    bom_line(r, "motor")->part_number);
	assert_string_equal(get(get(motors, "Product"), "Manufacturer")->valuestring,
	                    bom_line(r, "motor")->manufacturer);
	char want[64];
	snprintf(want, sizeof want, "%.0f KV (rpm/V)", m->kv_rpm_per_v);
	assert_non_null(strstr(get(motors, "Notes")->valuestring, want));
	const cJSON *props = get(comps, "Propellers");
	assert_rel(get(get(props, "Specifications"), "Diameter_inches")->valuedouble,
	           p->diameter_in, 1e-12);
	snprintf(want, sizeof want, "pitch %.1f in", p->pitch_in);
	assert_non_null(strstr(get(props, "Notes")->valuestring, want));
	assert_string_equal(get(get(get(comps, "ESC"), "Product"), "Model")->valuestring,
	                    bom_line(r, "esc")->part_number);

	/* The frame: empty and full takeoff weight around the mass of record. */
	const cJSON *frame = get(get(comps, "Frame"), "Specifications");
	assert_rel(get(frame, "TOW max Kg")->valuedouble, r->closed.mass.total_kg, 1e-3);
	assert_rel(get(frame, "TOW min Kg")->valuedouble,
	           r->closed.mass.total_kg - r->mission.payload_kg, 1e-3);
	assert_string_equal(get(frame, "Frame class")->valuestring, "Quad");
	cJSON_Delete(root);
}

/* ---- the parameter file ----------------------------------------------------- */

/* The value of NAME in a .param text; fails when absent. */
static double
param(const char *text, const char *name)
{
	size_t n = strlen(name);
	for (const char *l = text; l != NULL && *l != '\0'; l = strchr(l, '\n'), l = l ? l + 1 : l)
		if (strncmp(l, name, n) == 0 && l[n] == ',')
			return strtod(l + n + 1, NULL);
	fail_msg("no %s in the parameter file", name);
	return 0.0;
}

static bool
has_param(const char *text, const char *name)
{
	char key[32];
	snprintf(key, sizeof key, "\n%s,", name);
	return strstr(text, key) != NULL;
}

static void
params_should_be_name_value_lines_each_with_its_derivation(void **state)
{
	struct fixture *fx = *state;
	char prev[32] = "";
	int n = 0;
	char *copy = xstrdup(fx->params);
	for (char *l = strtok(copy, "\n"); l != NULL; l = strtok(NULL, "\n")) {
		if (l[0] == '#')
			continue;
		/* NAME,VALUE  # comment: as the configurator's reader splits it. */
		char *comma = strchr(l, ','), *hash = strchr(l, '#');
		assert_non_null(comma);
		assert_non_null(hash);
		assert_true(comma < hash);
		assert_null(strchr(hash + 1, '#'));
		assert_true(strlen(hash + 1) > 5);
		*comma = '\0';
		assert_true(strlen(l) >= 1 && strlen(l) <= 16);
		assert_true(strspn(l, "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") == strlen(l));
		assert_true(strcmp(prev, l) < 0);  /* sorted, so no name twice */
		snprintf(prev, sizeof prev, "%s", l);
		char *end;
		strtod(comma + 1, &end);
		assert_true(end > comma + 1);
		n++;
	}
	free(copy);
	assert_true(n >= 15);
}

static void
params_should_follow_the_pack_and_the_drive(void **state)
{
	struct fixture *fx = *state;
	const char *t = fx->params;
	const struct res_run *rec = &fx->sar->closed;
	int cells = rec->cell_count;
	assert_rel(param(t, "BATT_CAPACITY"), rec->capacity_mah, 1e-9);
	assert_rel(param(t, "BATT_LOW_MAH"), rec->reserve_soc * rec->capacity_mah, 1e-3);
	assert_rel(param(t, "MOT_BAT_VOLT_MAX"), cells * 4.2, 1e-9);      /* LiPo full */
	assert_rel(param(t, "MOT_BAT_VOLT_MIN"), cells * 3.3, 1e-9);      /* LiPo cut-off */
	assert_rel(param(t, "BATT_ARM_VOLT"), cells * 3.8, 1e-9);
	assert_rel(param(t, "BATT_LOW_VOLT"), cells * 3.6, 1e-9);
	assert_rel(param(t, "BATT_CRT_VOLT"), cells * 3.3, 1e-9);
	assert_true(param(t, "MOT_BAT_VOLT_MAX") > param(t, "BATT_ARM_VOLT"));
	assert_true(param(t, "BATT_ARM_VOLT") > param(t, "BATT_LOW_VOLT"));
	assert_true(param(t, "BATT_LOW_VOLT") > param(t, "BATT_CRT_VOLT") - 1e-9);
	/* The notch: the hover rotor speed in Hz, half of it as bandwidth, the
	 * blade-pass frequency (2 blades: harmonic 2) in the harmonics. */
	double hz = rec->perf.op[OP_HOVER].rpm / 60.0;
	assert_true(fabs(param(t, "INS_HNTCH_FREQ") - hz) <= 0.05 + 1e-9);
	assert_true(fabs(param(t, "INS_HNTCH_BW") - hz / 2.0) <= 0.1);
	assert_int_equal((int)param(t, "INS_HNTCH_HMNCS"), 3);
	assert_int_equal((int)param(t, "INS_HNTCH_MODE"), 1);
	assert_rel(param(t, "INS_HNTCH_REF"), param(t, "MOT_THST_HOVER"), 1e-12);
	/* Hover thrust over full-throttle thrust of one rotor. */
	double thrust = rec->perf.op[OP_HOVER].thrust_n / rec->perf.op[OP_FULL].thrust_n;
	assert_true(fabs(param(t, "MOT_THST_HOVER") - thrust) <= 5e-4);
	assert_true(param(t, "MOT_THST_HOVER") >= 0.2 && param(t, "MOT_THST_HOVER") <= 0.8);
	assert_int_equal((int)param(t, "FRAME_CLASS"), 1);
	assert_int_equal((int)param(t, "FRAME_TYPE"), 1);
}

/* ---- what gets no hand-off, and the frame classes ------------------------------ */

static void
design_that_is_not_buildable_should_get_no_handoff(void **state)
{
	struct fixture *fx = *state;
	/* The SAR result with its parts taken away: no design of record. */
	struct solve_result *r = xmalloc(sizeof *r);
	memcpy(r, fx->sar, sizeof *r);
	r->parts_selected = false;
	struct ardupilot_design d;
	char why[256];
	assert_int_equal(ardupilot_derive(r, &fx->env.model, fx->env.cat, &d, why,
	                                  sizeof why), -1);
	assert_non_null(strstr(why, "not buildable"));
	free(r);
}

static void
chemistry_without_a_configurator_name_should_get_no_handoff(void **state)
{
	struct fixture *fx = *state;
	struct solve_result *r = xmalloc(sizeof *r);
	memcpy(r, fx->sar, sizeof *r);
	snprintf(r->closed.chemistry, sizeof r->closed.chemistry, "Li-S");
	struct ardupilot_design d;
	char why[256];
	assert_int_equal(ardupilot_derive(r, &fx->env.model, fx->env.cat, &d, why, sizeof why), -1);
	assert_non_null(strstr(why, "Li-S"));
	/* A LiPo charged above the configurator's LipoHV limit is held to it. */
	snprintf(r->closed.chemistry, sizeof r->closed.chemistry, "LiPo_premium");
	assert_int_equal(ardupilot_derive(r, &fx->env.model, fx->env.cat, &d, why, sizeof why), 0);
	assert_string_equal(d.chemistry, "LipoHV");
	assert_true(d.cell_max_clamped);
	assert_rel(d.cell_max_v, 4.35, 1e-12);
	free(r);
}

static void
frame_class_should_follow_rotor_count_and_layout(void **state)
{
	struct fixture *fx = *state;
	static const struct { int n; bool coax; int cls; int type; } cases[] = {
		{ 3, false, AP_FRAME_TRI, -1 }, { 4, false, AP_FRAME_QUAD, 1 },
		{ 6, false, AP_FRAME_HEXA, 1 }, { 8, false, AP_FRAME_OCTA, 1 },
		{ 10, false, AP_FRAME_DECA, 1 }, { 6, true, AP_FRAME_Y6, -1 },
		{ 8, true, AP_FRAME_OCTAQUAD, 1 }, { 12, true, AP_FRAME_DODECAHEXA, 1 },
		{ 5, false, AP_FRAME_UNDEFINED, -1 }, { 16, true, AP_FRAME_UNDEFINED, -1 },
	};
	struct solve_result *r = xmalloc(sizeof *r);
	memcpy(r, fx->sar, sizeof *r);
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct ardupilot_design d;
		char why[256];
		r->mission.num_rotors = cases[i].n;
		r->mission.coaxial_layout = cases[i].coax;
		assert_int_equal(ardupilot_derive(r, &fx->env.model, fx->env.cat, &d, why,
		                                  sizeof why), 0);
		assert_int_equal(d.frame_class, cases[i].cls);
		assert_int_equal(d.frame_type, cases[i].type);
		char *t = ardupilot_params(&d, "x", "9.8.7");
		assert_int_equal(has_param(t, "FRAME_CLASS"), cases[i].cls != AP_FRAME_UNDEFINED);
		assert_int_equal(has_param(t, "FRAME_TYPE"), cases[i].type >= 0);
		free(t);
	}
	free(r);
}

static void
handoff_should_be_the_same_bytes_every_time(void **state)
{
	struct fixture *fx = *state;
	char *c = ardupilot_components(fx->sar, &fx->d, "sar_imaging_quad", "9.8.7");
	char *p = ardupilot_params(&fx->d, "sar_imaging_quad", "9.8.7");
	assert_string_equal(c, fx->components);
	assert_string_equal(p, fx->params);
	free(c);
	free(p);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(components_should_hold_every_field_the_schema_requires),
		cmocka_unit_test(components_numbers_should_be_the_bill_of_materials),
		cmocka_unit_test(params_should_be_name_value_lines_each_with_its_derivation),
		cmocka_unit_test(params_should_follow_the_pack_and_the_drive),
		cmocka_unit_test(design_that_is_not_buildable_should_get_no_handoff),
		cmocka_unit_test(chemistry_without_a_configurator_name_should_get_no_handoff),
		cmocka_unit_test(frame_class_should_follow_rotor_count_and_layout),
		cmocka_unit_test(handoff_should_be_the_same_bytes_every_time),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
