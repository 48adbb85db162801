/* test_schema.c — suggestions, `aeroeval schema` text and the JSON Schema,
 * all checked against the field table. */
#include "test_util.h"
#include "cli/cli.h"
#include "input/schema.h"
#include "util/jsonw.h"
#include "input/mission_io.h"

#include <stdlib.h>
#include <string.h>

/* The chemistry names of data/chemistries.json, as `aeroeval schema`
 * loads them (run from the repository root). */
static const char *const *
chemistries(void)
{
	static struct cli_env env;
	static bool loaded;
	if (!loaded) {
		assert_int_equal(cli_env_load(&env, NULL, 0, stderr), 0);
		loaded = true;
	}
	return env.model.chem_names;
}

static void
expect_suggestion(const char *path, const char *want)
{
	char got[128];
	bool found = spec_suggest(path, got, sizeof got);
	if (want == NULL) {
		if (found)
			fail_msg("%s: unexpected suggestion %s", path, got);
		assert_string_equal(got, "");
		return;
	}
	if (!found)
		fail_msg("%s: no suggestion, want %s", path, want);
	assert_string_equal(got, want);
}

static void
spec_suggest_should_find_the_closest_valid_path(void **state)
{
	(void)state;
	expect_suggestion("payload_kgs", "payload_kg");
	expect_suggestion("Payload_KG", "payload_kg");
	expect_suggestion("numrotors", "num_rotors");
	expect_suggestion("t_hvoer_s", "t_hover_s");              /* swap */
	expect_suggestion("aux_power_w", "payload_role.aux_power_w"); /* across groups */
	expect_suggestion("locks.aux_power_w", "payload_role.aux_power_w");
	expect_suggestion("locks.locked_kvv", "locks.locked_kv");
	expect_suggestion("payload_role.aux_power", "payload_role.aux_power_w");
	expect_suggestion("lock", "locks");
	expect_suggestion("Requirements", "requirements");
	expect_suggestion("xyz", NULL);
	expect_suggestion("payload_kg", NULL);                     /* itself */
	expect_suggestion("a_key_that_is_far_longer_than_anything_the_table_knows_about_at_all_really", NULL);
}

static void
spec_is_group_should_know_the_group_objects(void **state)
{
	(void)state;
	const char *groups[] = { "report", "locks", "payload_role", "structural_overrides",
	                         "aerodynamic_overrides", "requirements" };
	for (size_t i = 0; i < sizeof groups / sizeof groups[0]; i++)
		assert_true(spec_is_group(groups[i]));
	assert_false(spec_is_group("payload_kg"));
	assert_false(spec_is_group("lock"));
	assert_false(spec_is_group(""));
}

static void
spec_range_text_should_mark_an_exclusive_minimum(void **state)
{
	(void)state;
	char buf[96];
	spec_range_text(spec_field_by_path("payload_kg"), buf, sizeof buf);
	assert_string_equal(buf, "0 to 500 kg");
	spec_range_text(spec_field_by_path("max_diameter_m"), buf, sizeof buf);
	assert_string_equal(buf, "above 0.03 up to 5 m");
	spec_range_text(spec_field_by_path("num_rotors"), buf, sizeof buf);
	assert_string_equal(buf, "3 to 16");
}

/* The schema node of a field path inside the JSON Schema. */
static const cJSON *
schema_node(const cJSON *root, const char *path)
{
	const cJSON *props = cJSON_GetObjectItemCaseSensitive(root, "properties");
	const char *dot = strchr(path, '.');
	if (dot != NULL) {
		char group[64];
		snprintf(group, sizeof group, "%.*s", (int)(dot - path), path);
		const cJSON *g = cJSON_GetObjectItemCaseSensitive(props, group);
		assert_true(cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(g, "additionalProperties")));
		props = cJSON_GetObjectItemCaseSensitive(g, "properties");
		path = dot + 1;
	}
	return cJSON_GetObjectItemCaseSensitive(props, path);
}

static void
schema_json_should_list_exactly_the_table_fields(void **state)
{
	(void)state;
	cJSON *root = schema_json_schema(chemistries());
	struct mission_spec def;
	spec_defaults(&def);
	cJSON *defaults = mission_io_to_json(&def);

	assert_string_equal(cJSON_GetObjectItemCaseSensitive(root, "$schema")->valuestring,
	                    "https://json-schema.org/draft/2020-12/schema");
	assert_true(cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(root, "additionalProperties")));
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		const cJSON *n = schema_node(root, f->path);
		if (n == NULL)
			fail_msg("%s missing from the JSON Schema", f->path);
		const cJSON *num = n;
		if (f->type == SPEC_SPEED) {
			const cJSON *any = cJSON_GetObjectItemCaseSensitive(n, "anyOf");
			num = cJSON_GetArrayItem(any, 0);
			assert_string_equal(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(any, 1),
			                                                      "const")->valuestring, "auto");
		}
		const char *type = cJSON_GetObjectItemCaseSensitive(num, "type")->valuestring;
		switch (f->type) {
		case SPEC_NUM:
		case SPEC_INT:
		case SPEC_SPEED:
			assert_string_equal(type, f->type == SPEC_INT ? "integer" : "number");
			assert_rel(cJSON_GetObjectItemCaseSensitive(num, "maximum")->valuedouble, f->max, 0);
			if (f->flags & SPEC_F_MIN_EXCL) {
				assert_rel(cJSON_GetObjectItemCaseSensitive(num, "exclusiveMinimum")->valuedouble,
				           f->min, 0);
				assert_null(cJSON_GetObjectItemCaseSensitive(num, "minimum"));
			} else {
				assert_rel(cJSON_GetObjectItemCaseSensitive(num, "minimum")->valuedouble, f->min, 0);
			}
			break;
		case SPEC_BOOL:
			assert_string_equal(type, "boolean");
			break;
		case SPEC_ENUM: {
			assert_string_equal(type, "string");
			const cJSON *e = cJSON_GetObjectItemCaseSensitive(n, "enum");
			int k = 0;
			for (; f->enums[k] != NULL; k++)
				assert_string_equal(cJSON_GetArrayItem(e, k)->valuestring, f->enums[k]);
			assert_int_equal(cJSON_GetArraySize(e), k);
			break;
		}
		case SPEC_STR:
		case SPEC_DATE:
			assert_string_equal(type, "string");
			assert_int_equal(cJSON_GetObjectItemCaseSensitive(n, "maxLength")->valueint,
			                 SPEC_STR_MAX - 1);
			break;
		}
		/* The default is what the parser applies. */
		const cJSON *d = cJSON_GetObjectItemCaseSensitive(n, "default");
		const char *dot = strchr(f->path, '.');
		const cJSON *want = defaults;
		if (dot != NULL) {
			char group[64];
			snprintf(group, sizeof group, "%.*s", (int)(dot - f->path), f->path);
			want = cJSON_GetObjectItemCaseSensitive(defaults, group);
		}
		want = cJSON_GetObjectItemCaseSensitive(want, dot != NULL ? dot + 1 : f->path);
		assert_true(cJSON_Compare(d, want, 1));
		assert_non_null(strstr(cJSON_GetObjectItemCaseSensitive(n, "description")->valuestring,
		                       f->help));
	}
	/* Nothing else: count the properties, less "$schema" everywhere and the
	 * ignored "name" of each group. */
	size_t n = 0;
	const cJSON *props = cJSON_GetObjectItemCaseSensitive(root, "properties");
	for (const cJSON *c = props->child; c != NULL; c = c->next) {
		if (strcmp(c->string, "$schema") == 0)
			continue;
		if (!spec_is_group(c->string)) {
			n++;
			continue;
		}
		const cJSON *gp = cJSON_GetObjectItemCaseSensitive(c, "properties");
		for (const cJSON *g = gp->child; g != NULL; g = g->next)
			if (strcmp(g->string, "$schema") != 0 && strcmp(g->string, "name") != 0)
				n++;
	}
	assert_int_equal(n, SPEC_N_FIELDS);
	assert_string_equal(cJSON_GetObjectItemCaseSensitive(schema_node(root, "battery_chemistry"),
	                                                     "default")->valuestring, "LiHV");
	cJSON_Delete(defaults);
	cJSON_Delete(root);
}

/* The closed sets are enums, battery_chemistry's from data/chemistries.json;
 * what every mission gives is the "allOf" of the essentials, each an
 * "anyOf" of its fields and the requirements field that derives it. */
static void
schema_json_should_state_the_essentials_and_the_chemistries(void **state)
{
	(void)state;
	cJSON *root = schema_json_schema(chemistries());
	const cJSON *e = cJSON_GetObjectItemCaseSensitive(schema_node(root, "battery_chemistry"),
	                                                  "enum");
	int k = 0;
	for (const char *const *c = chemistries(); *c != NULL; c++, k++)
		assert_string_equal(cJSON_GetArrayItem(e, k)->valuestring, *c);
	assert_int_equal(cJSON_GetArraySize(e), k);
	assert_true(k >= 12);
	const cJSON *all = cJSON_GetObjectItemCaseSensitive(root, "allOf");
	assert_int_equal(cJSON_GetArraySize(all), SPEC_N_ESSENTIALS);
	for (int i = 0; i < SPEC_N_ESSENTIALS; i++) {
		const struct spec_essential *es = &spec_essentials[i];
		const cJSON *any = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(all, i), "anyOf");
		int n = 0;
		while (n < SPEC_ESSENTIAL_FIELDS && es->any_of[n] != SPEC_N_FIELDS) {
			const cJSON *req = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(any, n),
			                                                    "required");
			assert_string_equal(cJSON_GetArrayItem(req, 0)->valuestring,
			                    spec_fields[es->any_of[n]].path);
			n++;
		}
		assert_int_equal(cJSON_GetArraySize(any), n + (es->derived_by != SPEC_N_FIELDS));
	}
	/* Without a chemistry list the set stays open. */
	cJSON *open = schema_json_schema(NULL);
	assert_null(cJSON_GetObjectItemCaseSensitive(schema_node(open, "battery_chemistry"), "enum"));
	cJSON_Delete(open);
	cJSON_Delete(root);
}

/* Read a whole file into a NUL-terminated string, or NULL. */
static char *
slurp(const char *path)
{
	FILE *fp = fopen(path, "rb");
	if (fp == NULL)
		return NULL;
	fseek(fp, 0, SEEK_END);
	long n = ftell(fp);
	rewind(fp);
	char *s = malloc((size_t)n + 1);
	size_t got = fread(s, 1, (size_t)n, fp);
	s[got] = '\0';
	fclose(fp);
	return s;
}

static void
schema_committed_file_should_equal_the_generated_schema(void **state)
{
	(void)state;
	/* Tests run from the repository root (tests/run_all.sh). */
	char *committed = slurp("data/mission.schema.json");
	if (committed == NULL)
		fail_msg("cannot read data/mission.schema.json (run from the repository root)");
	cJSON *root = schema_json_schema(chemistries());
	char *text = jsonw_print(root, NULL);
	assert_string_equal(committed, text);
	free(text);
	free(committed);
	cJSON_Delete(root);
}

static void
schema_text_should_list_every_field_with_its_range(void **state)
{
	(void)state;
	FILE *fp = tmpfile();
	schema_print_text(fp);
	fputc('\0', fp);
	long n = ftell(fp);
	rewind(fp);
	char *text = malloc((size_t)n);
	assert_int_equal(fread(text, 1, (size_t)n, fp), (size_t)n);
	fclose(fp);
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		char want[128];
		snprintf(want, sizeof want, "\n  %s  (", spec_fields[i].path);
		if (strstr(text, want) == NULL)
			fail_msg("%s missing from `aeroeval schema`", spec_fields[i].path);
		assert_non_null(strstr(text, spec_fields[i].help));
	}
	assert_non_null(strstr(text, "default 1 kg (when absent, derived by the engine); "
	                             "allowed 0 to 500 kg\n"));
	assert_non_null(strstr(text, "allowed above 0.03 up to 5 m"));
	assert_non_null(strstr(text, "allowed: offset, folding, under_rotor"));
	assert_non_null(strstr(text, "  battery_chemistry  (string)\n      default LiHV"));
	/* Each group heading once, the top level first. */
	const char *top = strstr(text, "\ntop level\n");
	assert_non_null(top);
	assert_null(strstr(top + 1, "\ntop level\n"));
	assert_true(top < strstr(text, "\nlocks { ... }"));
	free(text);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(spec_suggest_should_find_the_closest_valid_path),
		cmocka_unit_test(spec_is_group_should_know_the_group_objects),
		cmocka_unit_test(spec_range_text_should_mark_an_exclusive_minimum),
		cmocka_unit_test(schema_json_should_list_exactly_the_table_fields),
		cmocka_unit_test(schema_json_should_state_the_essentials_and_the_chemistries),
		cmocka_unit_test(schema_committed_file_should_equal_the_generated_schema),
		cmocka_unit_test(schema_text_should_list_every_field_with_its_range),
	};
	return cmocka_run_group_tests_name("schema", tests, NULL, NULL);
}
