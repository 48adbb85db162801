/* test_ardupilot.c — the autopilot hand-off: vehicle_components.json holds
 * every field the Methodic Configurator's schema requires, and its numbers
 * and the parameter file's are the bill of materials' and the design of
 * record's.
 *
 * The examples are solved for real (pipeline_solve): the SAR quad is
 * buildable and feasible; a design without parts gets no hand-off.
 */
#include "test_util.h"

#include <glob.h>

#include <cjson/cJSON.h>

#include "cli/cli.h"
#include "cli/pipeline.h"
#include "catalog/catalog.h"
#include "formats/ardupilot.h"
#include "formats/bom_csv.h"
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

/* The schema's required fields and types (the list above) in a
 * vehicle_components.json text. */
static void
assert_schema_shape(const char *json)
{
	cJSON *root = cJSON_Parse(json);
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
	/* connectionComponent: FC Connection {Type, Protocol} strings. */
	cJSON_ArrayForEach(c, comps) {
		const cJSON *fc = cJSON_GetObjectItemCaseSensitive(c, "FC Connection");
		if (fc != NULL) {
			assert_true(cJSON_IsString(get(fc, "Type")));
			assert_true(cJSON_IsString(get(fc, "Protocol")));
		}
	}
	cJSON_Delete(root);
}

static void
components_should_hold_every_field_the_schema_requires(void **state)
{
	struct fixture *fx = *state;
	assert_schema_shape(fx->components);
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

/* Every parameter line follows its own comment line "# NAME: how". */
static void
params_should_be_name_value_lines_each_after_its_derivation(void **state)
{
	struct fixture *fx = *state;
	int n = 0;
	char *copy = xstrdup(fx->params);
	const char *prev = "";
	for (char *l = strtok(copy, "\n"); l != NULL; prev = l, l = strtok(NULL, "\n")) {
		if (l[0] == '#')
			continue;
		char *comma = strchr(l, ',');
		assert_non_null(comma);
		assert_null(strchr(l, '#'));
		assert_null(strchr(l, ' '));
		*comma = '\0';
		assert_true(strlen(l) >= 1 && strlen(l) <= 16);
		assert_true(strspn(l, "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") == strlen(l));
		char want[32];
		snprintf(want, sizeof want, "# %s: ", l);
		assert_true(strncmp(prev, want, strlen(want)) == 0);
		assert_true(strlen(prev) > strlen(want) + 5);
		char *end;
		strtod(comma + 1, &end);
		assert_true(end > comma + 1 && *end == '\0');
		n++;
	}
	free(copy);
	assert_true(n >= 18);
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

/* ---- every example's files, read by the tools that load them ------------------
 *
 * Each loader below follows the parsing rules of one tool, as its source
 * reads (not its code):
 *   - Mission Planner, ExtLibs/Utilities/ParamFile.cs loadParamFile: a line
 *     starting with '#' is skipped; any other is split on ' ', ',' and '\t'
 *     with empty entries removed, and only a line of exactly two items is
 *     taken (name, double.Parse of the value; a bad number throws);
 *   - MAVProxy / pymavlink, mavparm.py MAVParmDict.load: the line is
 *     stripped; empty and '#' lines are skipped; commas become spaces, the
 *     line is split on white space and one of other than two words is an
 *     "Invalid line"; the value is float() (or 0x hex);
 *   - the ArduPilot Methodic Configurator, data_model_par_dict.py
 *     ParDict.load_param_file_into_dict: the file is read as UTF-8, each
 *     line stripped; empty and '#' lines skipped; a '#' starts a trailing
 *     comment; the line splits at its first ',' (else ' ', else tab); the
 *     name must match ^[A-Z][A-Z_0-9]*$ in at most 16 characters and appear
 *     once; the value is float(); anything else stops the load;
 *   - QGroundControl, ParameterEditorController::buildDiffFromFile (and
 *     ParameterManager::readParametersFromStream): a line not starting with
 *     '#' is split on '\t' and taken when it has five fields: vehicle id,
 *     component id, name, value, MAV_PARAM_TYPE.
 * A loader returns the names it loaded, in order, and fails the test on
 * what its tool rejects. */

#define MAX_LOADED 64

struct loaded {
	char name[MAX_LOADED][17];
	double value[MAX_LOADED];
	int n;
};

static void
loaded_add(struct loaded *ld, const char *name, size_t len, double v)
{
	assert_true(ld->n < MAX_LOADED && len <= 16);
	memcpy(ld->name[ld->n], name, len);
	ld->name[ld->n][len] = '\0';
	ld->value[ld->n++] = v;
}

/* A whole number text as C# double.Parse and Python float() take it. */
static double
number(const char *s, size_t len)
{
	char t[64], *end;
	assert_true(len > 0 && len < sizeof t);
	memcpy(t, s, len);
	t[len] = '\0';
	double v = strtod(t, &end);
	assert_true(*end == '\0');
	return v;
}

/* The lines of text, each without its line end, to fn. */
#define FOR_LINES(text, line, len) \
	for (const char *line = (text), *nl_; *line != '\0'; \
	     line = (nl_ = strchr(line, '\n')) ? nl_ + 1 : line + strlen(line)) \
		for (size_t len = strcspn(line, "\n"), once_ = 1; once_; once_ = 0)

static void
load_mission_planner(const char *text, struct loaded *ld)
{
	ld->n = 0;
	FOR_LINES(text, line, len) {
		if (len > 0 && line[len - 1] == '\r')
			len--;                         /* StreamReader.ReadLine */
		if (len > 0 && line[0] == '#')
			continue;
		const char *item[3];
		size_t item_len[3];
		int n = 0;
		for (size_t i = 0; i < len;) {
			size_t w = strcspn(line + i, " ,\t\n");
			if (w > len - i)
				w = len - i;
			if (w > 0) {
				if (n < 3) {
					item[n] = line + i;
					item_len[n] = w;
				}
				n++;
			}
			i += w + 1;
		}
		if (n != 2)
			continue;                      /* not loaded: the line is lost */
		loaded_add(ld, item[0], item_len[0], number(item[1], item_len[1]));
	}
}

static void
load_pymavlink(const char *text, struct loaded *ld)
{
	ld->n = 0;
	FOR_LINES(text, line, len) {
		char t[512];
		assert_true(len < sizeof t);
		memcpy(t, line, len);
		t[len] = '\0';
		char *a = t + strspn(t, " \t\r\v\f");      /* line.strip() */
		size_t n = strlen(a);
		while (n > 0 && strchr(" \t\r\v\f", a[n - 1]))
			a[--n] = '\0';
		if (n == 0 || a[0] == '#')
			continue;
		for (char *c = a; *c; c++)
			if (*c == ',')
				*c = ' ';
		char *w[3];
		int k = 0;
		for (char *tok = strtok(a, " \t"); tok != NULL; tok = strtok(NULL, " \t"))
			if (k < 3)
				w[k++] = tok;
			else
				k++;
		if (k != 2)
			fail_msg("pymavlink: Invalid line: %.*s", (int)len, line);
		loaded_add(ld, w[0], strlen(w[0]), number(w[1], strlen(w[1])));
	}
}

static void
load_methodic_configurator(const char *text, struct loaded *ld)
{
	ld->n = 0;
	assert_false((unsigned char)text[0] == 0xEF);   /* no byte order mark */
	FOR_LINES(text, line, len) {
		char t[512];
		assert_true(len < sizeof t);
		memcpy(t, line, len);
		t[len] = '\0';
		for (char *c = t; *c; c++)
			assert_true((unsigned char)*c < 0x80);  /* ASCII reads as UTF-8 */
		char *a = t + strspn(t, " \t\r");
		size_t n = strlen(a);
		while (n > 0 && strchr(" \t\r", a[n - 1]))
			a[--n] = '\0';
		if (n == 0 || a[0] == '#')
			continue;
		char *hash = strchr(a, '#');
		if (hash != NULL)
			*hash = '\0';
		char *sep = strchr(a, ',');
		if (sep == NULL)
			sep = strchr(a, ' ');
		if (sep == NULL)
			sep = strchr(a, '\t');
		if (sep == NULL)
			fail_msg("configurator: Missing parameter-value separator: %s", a);
		*sep = '\0';
		char *name = a, *value = sep + 1;
		while (*value == ' ' || *value == '\t')
			value++;
		size_t vl = strlen(value);
		while (vl > 0 && (value[vl - 1] == ' ' || value[vl - 1] == '\t'))
			value[--vl] = '\0';
		size_t nl = strlen(name);
		assert_true(nl >= 1 && nl <= 16);
		assert_true(name[0] >= 'A' && name[0] <= 'Z');
		assert_true(strspn(name, "ABCDEFGHIJKLMNOPQRSTUVWXYZ_0123456789") == nl);
		for (int i = 0; i < ld->n; i++)
			if (strcmp(ld->name[i], name) == 0)
				fail_msg("configurator: Duplicated parameter %s", name);
		loaded_add(ld, name, nl, number(value, vl));
	}
}

static void
load_qgroundcontrol(const char *text, struct loaded *ld)
{
	ld->n = 0;
	FOR_LINES(text, line, len) {
		if (len > 0 && line[0] == '#')
			continue;
		const char *f[6];
		size_t fl[6];
		int k = 0;
		for (size_t i = 0; i <= len && k < 6; k++) {
			size_t w = strcspn(line + i, "\t\n");
			if (w > len - i)
				w = len - i;
			f[k] = line + i;
			fl[k] = w;
			i += w + 1;
		}
		if (k != 5)
			continue;                      /* not a parameter line */
		assert_int_equal((int)number(f[0], fl[0]), 1);
		assert_int_equal((int)number(f[1], fl[1]), 1);
		int type = (int)number(f[4], fl[4]);
		assert_true(type == 2 || type == 6 || type == 9);   /* INT8, INT32, REAL32 */
		double v = number(f[3], fl[3]);
		if (type != 9)
			assert_true(v == floor(v));
		loaded_add(ld, f[2], fl[2], v);
	}
}

/* The NAME,VALUE lines of a .param text: what "every line" means. */
static void
param_lines(const char *text, struct loaded *ld)
{
	ld->n = 0;
	FOR_LINES(text, line, len) {
		if (len == 0 || line[0] == '#')
			continue;
		const char *comma = memchr(line, ',', len);
		assert_non_null(comma);
		loaded_add(ld, line, (size_t)(comma - line), number(comma + 1,
		    len - (size_t)(comma - line) - 1));
	}
}

static void
assert_same_load(const struct loaded *want, const struct loaded *got, const char *tool)
{
	if (got->n != want->n)
		fail_msg("%s loads %d of %d lines", tool, got->n, want->n);
	for (int i = 0; i < want->n; i++) {
		assert_string_equal(got->name[i], want->name[i]);
		assert_true(got->value[i] == want->value[i]);
	}
}

static int
index_of(const struct loaded *ld, const char *name)
{
	for (int i = 0; i < ld->n; i++)
		if (strcmp(ld->name[i], name) == 0)
			return i;
	return -1;
}

/* Enable parameters before what they enable; the notch within the gyro
 * loop (ArduPilot notches only below 0.48 x the gyro rate: 1 kHz, 2 kHz
 * with INS_GYRO_RATE 1), its harmonics too. */
static void
assert_enable_order_and_notch(const struct loaded *ld)
{
	int monitor = index_of(ld, "BATT_MONITOR"), enable = index_of(ld, "INS_HNTCH_ENABLE");
	int gyro = index_of(ld, "INS_GYRO_RATE");
	assert_true(enable >= 0);
	for (int i = 0; i < ld->n; i++) {
		if (strncmp(ld->name[i], "BATT_", 5) == 0 && i != monitor && monitor >= 0)
			assert_true(monitor < i);
		if (strncmp(ld->name[i], "INS_HNTCH_", 10) == 0 && i != enable) {
			assert_true(enable < i);
			assert_true(gyro < enable);
		}
	}
	double rate = gyro >= 0 && ld->value[gyro] == 1 ? 2000.0 : 1000.0;
	double f = ld->value[index_of(ld, "INS_HNTCH_FREQ")];
	int h = (int)ld->value[index_of(ld, "INS_HNTCH_HMNCS")];
	assert_true(f >= 10.0 && f <= 495.0);
	for (int k = 0; k < 8; k++)
		if (h & (1 << k))
			assert_true((k + 1) * f < 0.48 * rate);
}

/* A component's product is the BOM line with that maker and orderable part
 * number (bom_csv_part_number), and every BOM line of a part the
 * configurator knows is some component's product. */
static void
assert_components_are_the_bill(const struct solve_result *r, const char *json,
                               const struct catalog *cat)
{
	cJSON *root = cJSON_Parse(json);
	assert_non_null(root);
	const cJSON *comps = get(root, "Components");
	const cJSON *c;
	int matched = 0;
	cJSON_ArrayForEach(c, comps) {
		const cJSON *p = get(c, "Product");
		const char *maker = get(p, "Manufacturer")->valuestring;
		const char *model = get(p, "Model")->valuestring;
		if (maker[0] == '\0')
			continue;  /* not bought: custom frame, no monitor */
		bool found = false;
		for (int i = 0; i < r->n_bom && !found; i++)
			found = strcmp(r->bom[i].manufacturer, maker) == 0
			    && strcmp(bom_csv_part_number(r, &r->bom[i]), model) == 0;
		if (!found)
			fail_msg("%s \"%s %s\" is no line of the bill of materials", c->string, maker, model);
		matched++;
	}
	for (int i = 0; i < r->n_bom; i++) {
		const struct res_bom_line *b = &r->bom[i];
		const char *cat_name = b->category;
		bool known = strcmp(cat_name, "motor") == 0 || strcmp(cat_name, "propeller") == 0
		    || strcmp(cat_name, "battery") == 0 || strcmp(cat_name, "esc") == 0
		    || strcmp(cat_name, "frame") == 0;
		if (strcmp(cat_name, "avionics") == 0) {
			const struct catalog_avionics *a = catalog_find_avionics(cat, b->catalogue_id);
			assert_non_null(a);
			static const char *const kinds[] = { "flight_controller", "power_module", "pdb",
				"gnss", "receiver", "telemetry", NULL };
			for (int k = 0; kinds[k] != NULL; k++)
				known = known || strcmp(a->kind, kinds[k]) == 0;
		}
		/* The counter-rotating blades under the maker's own CCW part
		 * number are the propeller component's other half. */
		if (strcmp(cat_name, "propeller") == 0) {
			const struct catalog_prop *pr = catalog_find_prop(cat, b->catalogue_id);
			if (pr != NULL && strcmp(b->part_number, pr->part_number_ccw) == 0)
				continue;
		}
		if (!known)
			continue;
		bool found = false;
		cJSON_ArrayForEach(c, comps) {
			const cJSON *p = get(c, "Product");
			found = found || (strcmp(get(p, "Manufacturer")->valuestring, b->manufacturer) == 0
			    && strcmp(get(p, "Model")->valuestring, bom_csv_part_number(r, b)) == 0);
		}
		if (!found)
			fail_msg("BOM item %d (%s %s) is in no component", b->item, b->manufacturer,
			    b->part_number);
	}
	assert_true(matched >= 6);
	cJSON_Delete(root);
}

static void
every_example_handoff_should_load_in_full_in_every_tool(void **state)
{
	struct fixture *fx = *state;
	glob_t g;
	assert_int_equal(glob("examples/*.json", 0, NULL, &g), 0);
	int handoffs = 0, feasible = 0;
	for (size_t k = 0; k < g.gl_pathc; k++) {
		struct solve_result *r = solve(fx, g.gl_pathv[k]);
		feasible += r->parts_selected && r->closed.feasible;
		struct ardupilot_design d;
		char why[256];
		if (ardupilot_derive(r, &fx->env.model, fx->env.cat, &d, why, sizeof why) != 0) {
			free(r);
			continue;   /* the infeasible example: nothing buildable */
		}
		handoffs++;
		char *params = ardupilot_params(&d, "x", "9.8.7");
		char *qgc = ardupilot_params_qgc(&d, "x", "9.8.7");
		char *comps = ardupilot_components(r, &d, "x", "9.8.7");
		struct loaded want, got;
		param_lines(params, &want);
		assert_true(want.n >= 15);
		load_mission_planner(params, &got);
		assert_same_load(&want, &got, "Mission Planner");
		load_pymavlink(params, &got);
		assert_same_load(&want, &got, "pymavlink");
		load_methodic_configurator(params, &got);
		assert_same_load(&want, &got, "the Methodic Configurator");
		load_qgroundcontrol(qgc, &got);
		assert_same_load(&want, &got, "QGroundControl");
		/* The QGC file read by the others loads nothing (no line of two
		 * fields); the .param file read by QGC loads nothing either. */
		load_mission_planner(qgc, &got);
		assert_int_equal(got.n, 0);
		load_qgroundcontrol(params, &got);
		assert_int_equal(got.n, 0);
		assert_enable_order_and_notch(&want);
		/* BATT_MONITOR is the bought monitor's, and only then written. */
		assert_int_equal(index_of(&want, "BATT_MONITOR") >= 0, d.batt_monitor >= 0);
		assert_int_equal(d.batt_monitor >= 0, d.line[AP_ROLE_MONITOR] >= 0);
		assert_schema_shape(comps);
		assert_components_are_the_bill(r, comps, fx->env.cat);
		free(params);
		free(qgc);
		free(comps);
		free(r);
	}
	globfree(&g);
	/* Every aircraft that can be built gets its hand-offs. */
	assert_true(handoffs >= feasible && handoffs >= 8);
}

/* The monitor's interface sets BATT_MONITOR and its FC connection: the
 * SAR quad buys the analog PM02 V3, its full-throttle burst within the
 * module's 120 A: Analog Voltage and Current (4). */
static void
battery_monitor_should_be_the_bought_power_module(void **state)
{
	struct fixture *fx = *state;
	assert_int_equal(fx->d.batt_monitor, 4);
	assert_int_equal((int)param(fx->params, "BATT_MONITOR"), 4);
	assert_string_equal(fx->d.link[AP_ROLE_MONITOR].type, "Analog");
	cJSON *root = cJSON_Parse(fx->components);
	const cJSON *m = get(get(root, "Components"), "Battery Monitor");
	assert_string_equal(get(get(m, "FC Connection"), "Protocol")->valuestring,
	                    "Analog Voltage and Current");
	assert_string_equal(get(get(m, "Product"), "Model")->valuestring,
	                    fx->sar->bom[fx->d.line[AP_ROLE_MONITOR]].part_number);
	cJSON_Delete(root);
}

/* A rotor beyond a 1 kHz gyro loop: an H7 board's loop is raised to 2 kHz
 * (INS_GYRO_RATE 1, written before the notch); another board keeps 1 kHz
 * and the notch is held below 0.48 kHz, the blade-pass harmonic left out. */
static void
notch_should_stay_within_the_gyro_loop(void **state)
{
	struct fixture *fx = *state;
	struct solve_result *r = xmalloc(sizeof *r);
	memcpy(r, fx->sar, sizeof *r);
	r->closed.perf.op[OP_HOVER].rpm = 31000.0;    /* 516.7 Hz */
	struct ardupilot_design d;
	char why[256];
	assert_int_equal(ardupilot_derive(r, &fx->env.model, fx->env.cat, &d, why, sizeof why), 0);
	assert_string_equal(d.mcu, "STM32H7xx");   /* the Pixhawk 6C Mini */
	assert_true(d.gyro_rate_raised);
	assert_int_equal(d.gyro_rate_hz, 2000);
	char *t = ardupilot_params(&d, "x", "9.8.7");
	assert_int_equal((int)param(t, "INS_GYRO_RATE"), 1);
	assert_true(fabs(param(t, "INS_HNTCH_FREQ") - 495.0) < 1e-9);  /* the parameter's maximum */
	assert_true(strstr(t, "INS_GYRO_RATE") < strstr(t, "INS_HNTCH_ENABLE,"));
	free(t);
	/* The same rotor on an F4 board (the Mateksys F405-SE). */
	struct ardupilot_design d2;
	snprintf(r->bom[d.line[AP_ROLE_FC]].catalogue_id, sizeof r->bom[0].catalogue_id,
	         "matek-f405-se-fc");
	assert_int_equal(ardupilot_derive(r, &fx->env.model, fx->env.cat, &d2, why, sizeof why), 0);
	assert_string_equal(d2.mcu, "STM32F4xx");
	assert_false(d2.gyro_rate_raised);
	assert_true(d2.notch_held);
	assert_true(d2.notch_hz < 0.48 * 1000.0);
	assert_int_equal(d2.hmncs, 1);
	assert_int_equal(d2.blade_harmonic_dropped, 2);
	t = ardupilot_params(&d2, "x", "9.8.7");
	assert_false(has_param(t, "INS_GYRO_RATE"));
	assert_int_equal((int)param(t, "INS_HNTCH_HMNCS"), 1);
	free(t);
	free(r);
}

/* The loaders above are strict enough to see what issue 34 found: the old
 * "NAME,VALUE  # comment" lines load in the configurator only. */
static void
loaders_should_lose_trailing_comment_lines(void **state)
{
	(void)state;
	static const char old[] = "# header\nBATT_CAPACITY,14000  # pack\nFRAME_CLASS,1  # quad\n";
	struct loaded ld;
	load_mission_planner(old, &ld);
	assert_int_equal(ld.n, 0);
	load_methodic_configurator(old, &ld);
	assert_int_equal(ld.n, 2);
	load_qgroundcontrol(old, &ld);
	assert_int_equal(ld.n, 0);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(components_should_hold_every_field_the_schema_requires),
		cmocka_unit_test(components_numbers_should_be_the_bill_of_materials),
		cmocka_unit_test(params_should_be_name_value_lines_each_after_its_derivation),
		cmocka_unit_test(params_should_follow_the_pack_and_the_drive),
		cmocka_unit_test(design_that_is_not_buildable_should_get_no_handoff),
		cmocka_unit_test(chemistry_without_a_configurator_name_should_get_no_handoff),
		cmocka_unit_test(frame_class_should_follow_rotor_count_and_layout),
		cmocka_unit_test(handoff_should_be_the_same_bytes_every_time),
		cmocka_unit_test(every_example_handoff_should_load_in_full_in_every_tool),
		cmocka_unit_test(battery_monitor_should_be_the_bought_power_module),
		cmocka_unit_test(notch_should_stay_within_the_gyro_loop),
		cmocka_unit_test(loaders_should_lose_trailing_comment_lines),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
