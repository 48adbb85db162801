/* test_index.c — the design-space table: rows read from result.json
 * (input/table_in), rendered as index.csv and index.json (formats/index).
 *
 * The result.json files are the golden copies of the examples, so the rows
 * follow what the compiler writes now.
 */
#include "test_util.h"

#include <cjson/cJSON.h>

#include "diag/diag.h"
#include "result/table_row.h"
#include "input/table_in.h"
#include "formats/index.h"
#include "util/file.h"

#define HEADER "name,status,role,rotors,coaxial,wheelbase_m,airframe_class," \
	"battery_chemistry,altitude_m,ambient_temp_c,t_hover_s,t_forward_s,t_climb_s," \
	"payload_kg,max_payload_kg,takeoff_mass_kg,mtow_interval_level,mtow_lo_kg," \
	"mtow_hi_kg,flight_time_s,hover_endurance_s,cost_usd,unpriced_lines," \
	"cells,capacity_mah,motor,propeller,battery,tightest_check,tightest_margin\r\n"

/* Parses text as the result.json of name; returns parse's result, the
 * diagnostics in msg. */
static int
parse_text(const char *text, const char *name, struct table_row *row, char *msg,
           size_t n)
{
	struct diag *dg = diag_alloc(NULL);
	int rc = table_in_parse("t/result.json", text, strlen(text), name, row, dg);
	snprintf(msg, n, "%s", diag_text(dg));
	diag_free(dg);
	return rc;
}

static char *
golden(const char *example)
{
	char path[256], err[512];
	unsigned char *buf;
	size_t n;
	snprintf(path, sizeof path, "tests/golden/%s/result.json", example);
	if (file_read(path, (size_t)64 << 20, &buf, &n, err, sizeof err) != 0)
		fail_msg("%s", err);
	return (char *)buf;
}

static void
row_should_carry_the_design_of_record(void **state)
{
	(void)state;
	char *text = golden("sar_imaging_quad"), msg[512];
	struct table_row w;
	assert_int_equal(parse_text(text, "sar_imaging_quad", &w, msg, sizeof msg), 0);
	cJSON *root = cJSON_Parse(text);
	const cJSON *dor = cJSON_GetObjectItemCaseSensitive(root, "design_of_record");
	assert_string_equal(w.name, "sar_imaging_quad");
	assert_int_equal(w.status, TABLE_ROW_FEASIBLE);
	assert_rel(w.takeoff_mass_kg,
	           cJSON_GetObjectItemCaseSensitive(root, "takeoff_mass_kg")->valuedouble, 0);
	assert_int_equal(w.cells, cJSON_GetObjectItemCaseSensitive(dor, "cell_count")->valueint);
	assert_rel(w.capacity_mah,
	           cJSON_GetObjectItemCaseSensitive(dor, "battery_capacity_mah")->valuedouble, 0);
	assert_rel(w.payload_kg, 1.5, 0);
	assert_true(w.has_cost && w.has_endurance && w.has_flight_time);
	const cJSON *iv = cJSON_GetObjectItemCaseSensitive(root, "mtow_interval");
	assert_true(w.has_interval);
	assert_rel(w.mtow_lo_kg, cJSON_GetObjectItemCaseSensitive(iv, "lo_kg")->valuedouble, 0);
	assert_rel(w.mtow_hi_kg, cJSON_GetObjectItemCaseSensitive(iv, "hi_kg")->valuedouble, 0);
	const cJSON *sel = cJSON_GetObjectItemCaseSensitive(root, "selected");
	assert_non_null(sel);
	assert_true(w.motor[0] != '\0');
	assert_true(w.tightest[0] != '\0' && w.tightest_margin > 0.0);
	cJSON_Delete(root);
	free(text);

	text = golden("infeasible_compact_lifter");
	assert_int_equal(parse_text(text, "infeasible_compact_lifter", &w, msg, sizeof msg), 0);
	assert_int_equal(w.status, TABLE_ROW_NOT_BUILDABLE);
	assert_string_equal(w.motor, "");
	assert_false(w.has_cost);
	free(text);
}

/* The mission as asked stands beside the results: a study plots payload,
 * wheelbase or endurance asked against the takeoff mass straight from the
 * table, without the mission files. */
static void
row_should_carry_the_mission_inputs(void **state)
{
	(void)state;
	static const struct { const char *example, *csv; } cases[] = {
		{ "sar_imaging_quad", "sar_imaging_quad,feasible,imaging,4,false,1.000,"
		  "EnterpriseRugged,LiPo,1500,5.25,900,600,60,1.500,1.500," },
		{ "coaxial_inspection_quad", "coaxial_inspection_quad,feasible,inspection,8,true,"
		  "0.600,EnterpriseRugged,LiPo,0,15.00,900,240,60,1.200,1.200," },
		{ "workspace_backpack_inspection", "workspace_backpack_inspection,feasible,"
		  "inspection,4,false,0.450,ConsumerFolding,LiPo_premium,0,15.00,120,1200,45,"
		  "0.900,0.900," },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		char *text = golden(cases[i].example), msg[512];
		struct table_row w;
		assert_int_equal(parse_text(text, cases[i].example, &w, msg, sizeof msg), 0);
		assert_true(w.has_inputs);
		struct table_rows s = { 0 };
		table_row_add(&s, &w);
		char *csv = index_csv(&s);
		if (strstr(csv, cases[i].csv) == NULL)
			fail_msg("%s: want \"%s\" in\n%s", cases[i].example, cases[i].csv, csv);
		char *json = index_json(&s, "9.8.7");
		cJSON *root = cJSON_Parse(json);
		const cJSON *m = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(root, "missions"), 0);
		assert_int_equal(cJSON_GetObjectItemCaseSensitive(m, "rotors")->valueint, w.rotors);
		assert_true(cJSON_IsBool(cJSON_GetObjectItemCaseSensitive(m, "coaxial")));
		assert_rel(cJSON_GetObjectItemCaseSensitive(m, "t_hover_s")->valuedouble, w.t_hover_s, 0);
		assert_string_equal(cJSON_GetObjectItemCaseSensitive(m, "role")->valuestring, w.role);
		cJSON_Delete(root);
		free(json);
		free(csv);
		table_row_free(&s);
		free(text);
	}
}

static void
row_should_read_a_prediction_interval_when_there_is_one(void **state)
{
	(void)state;
	char *text = golden("lidar_mapping_quad"), msg[512];
	cJSON *root = cJSON_Parse(text);
	cJSON *iv = cJSON_CreateObject();
	cJSON_ReplaceItemInObjectCaseSensitive(root, "mtow_interval", iv);
	cJSON_AddNumberToObject(iv, "level", 0.9);
	cJSON_AddNumberToObject(iv, "lo_kg", 2.385);
	cJSON_AddNumberToObject(iv, "hi_kg", 3.615);
	char *with = cJSON_PrintUnformatted(root);
	struct table_row w;
	assert_int_equal(parse_text(with, "lidar", &w, msg, sizeof msg), 0);
	assert_true(w.has_interval);
	assert_rel(w.interval_level, 0.9, 0);
	assert_rel(w.mtow_lo_kg, 2.385, 0);
	assert_rel(w.mtow_hi_kg, 3.615, 0);
	struct table_rows s = { 0 };
	table_row_add(&s, &w);
	char *csv = index_csv(&s);
	assert_non_null(strstr(csv, ",0.90,2.385,3.615,"));
	free(csv);
	table_row_free(&s);
	cJSON_free(with);
	cJSON_Delete(root);
	free(text);
}

static void
result_without_what_a_row_needs_should_be_an_error_naming_it(void **state)
{
	(void)state;
	static const struct { const char *text, *want; } bad[] = {
		{ "{\"status\": \"feasible\"}", "buildable: missing field" },
		{ "{\"status\": \"odd\", \"buildable\": true, \"takeoff_mass_kg\": 2.385, "
		  "\"design_of_record\": {}, \"mission\": {\"payload_kg\": 1}}",
		  "status: unknown value" },
		{ "{\"status\": \"feasible\", \"buildable\": 1, \"takeoff_mass_kg\": 2.385, "
		  "\"design_of_record\": {}, \"mission\": {\"payload_kg\": 1}}",
		  "buildable: wrong type" },
		{ "{\"status\": \"feasible\", \"buildable\": true, \"takeoff_mass_kg\": 2.385, "
		  "\"design_of_record\": {}, \"mission\": {}}", "mission.payload_kg: missing field" },
		{ "{\"status\": ", "malformed JSON" },
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		struct table_row w;
		char msg[1024];
		assert_int_equal(parse_text(bad[i].text, "x", &w, msg, sizeof msg), -1);
		if (strstr(msg, bad[i].want) == NULL || strncmp(msg, "t/result.json", 13) != 0)
			fail_msg("case %zu: \"%s\" lacks \"%s\"", i, msg, bad[i].want);
	}
	/* The smallest file a row can come from: every other cell empty. */
	struct table_row w;
	char msg[512];
	assert_int_equal(parse_text("{\"status\": \"infeasible\", \"buildable\": true, "
	    "\"takeoff_mass_kg\": 2.385, \"design_of_record\": {}, "
	    "\"mission\": {\"payload_kg\": 0.5}}", "m", &w, msg, sizeof msg), 0);
	assert_int_equal(w.status, TABLE_ROW_INFEASIBLE);
	struct table_rows s = { 0 };
	table_row_add(&s, &w);
	char *csv = index_csv(&s);
	assert_string_equal(csv, HEADER "m,infeasible,,,,,,,,,,,,0.500,,2.385,,,,,,,0,,,,,,,\r\n");
	free(csv);
	table_row_free(&s);
}

/* A row with the given name and texts, everything else plain. */
static struct table_row
row(const char *name, const char *motor, enum table_row_status st)
{
	struct table_row w;
	memset(&w, 0, sizeof w);
	snprintf(w.name, sizeof w.name, "%s", name);
	snprintf(w.motor, sizeof w.motor, "%s", motor);
	w.status = st;
	w.takeoff_mass_kg = 2.385;
	w.payload_kg = 0.5;
	return w;
}

static void
csv_cells_should_never_start_like_a_formula(void **state)
{
	(void)state;
	struct table_rows s = { 0 };
	struct table_row w = row("-dash", "=HYPERLINK(\"x\")", TABLE_ROW_FEASIBLE);
	table_row_add(&s, &w);
	w = row("plus", "+1 motor, \"quoted\"", TABLE_ROW_FEASIBLE);
	snprintf(w.battery, sizeof w.battery, "@SUM(A1)");
	table_row_add(&s, &w);
	table_row_sort(&s);
	char *csv = index_csv(&s);
	assert_non_null(strstr(csv, "\r\n'-dash,feasible,"));
	assert_non_null(strstr(csv, ",\"'=HYPERLINK(\"\"x\"\")\","));
	assert_non_null(strstr(csv, ",\"'+1 motor, \"\"quoted\"\"\","));
	assert_non_null(strstr(csv, ",'@SUM(A1),"));
	/* index.json keeps the text as it is. */
	char *json = index_json(&s, "9.8.7");
	cJSON *root = cJSON_Parse(json);
	const cJSON *m = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(root, "missions"), 0);
	assert_string_equal(cJSON_GetObjectItemCaseSensitive(m, "name")->valuestring, "-dash");
	cJSON_Delete(root);
	free(json);
	free(csv);
	table_row_free(&s);
}

static void
table_should_be_the_same_bytes_whatever_order_the_rows_came_in(void **state)
{
	(void)state;
	struct table_rows a = { 0 }, b = { 0 };
	static const char *const names[] = { "zulu", "alpha", "mike", "Bravo", "alpha2" };
	for (int i = 0; i < 5; i++) {
		struct table_row w = row(names[i], "", (enum table_row_status)(i % 3));
		w.takeoff_mass_kg = 1.0 + 0.1 * i;
		table_row_add(&a, &w);
	}
	for (int i = 4; i >= 0; i--)
		table_row_add(&b, &a.rows[i]);
	table_row_sort(&a);
	table_row_sort(&b);
	char *ca = index_csv(&a), *cb = index_csv(&b);
	char *ja = index_json(&a, "9.8.7"), *jb = index_json(&b, "9.8.7");
	assert_string_equal(ca, cb);
	assert_string_equal(ja, jb);
	/* Byte order of names: "Bravo" < "alpha" < "alpha2" < "mike" < "zulu". */
	assert_string_equal(a.rows[0].name, "Bravo");
	assert_string_equal(a.rows[4].name, "zulu");
	cJSON *root = cJSON_Parse(ja);
	const cJSON *counts = cJSON_GetObjectItemCaseSensitive(root, "counts");
	assert_int_equal(cJSON_GetObjectItemCaseSensitive(counts, "feasible")->valueint, 2);
	assert_int_equal(cJSON_GetObjectItemCaseSensitive(counts, "infeasible")->valueint, 2);
	assert_int_equal(cJSON_GetObjectItemCaseSensitive(counts, "not_buildable")->valueint, 1);
	assert_int_equal(cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(root, "missions")), 5);
	cJSON_Delete(root);
	free(ca);
	free(cb);
	free(ja);
	free(jb);
	table_row_free(&a);
	table_row_free(&b);
	table_row_free(NULL);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(row_should_carry_the_design_of_record),
		cmocka_unit_test(row_should_read_a_prediction_interval_when_there_is_one),
		cmocka_unit_test(row_should_carry_the_mission_inputs),
		cmocka_unit_test(result_without_what_a_row_needs_should_be_an_error_naming_it),
		cmocka_unit_test(csv_cells_should_never_start_like_a_formula),
		cmocka_unit_test(table_should_be_the_same_bytes_whatever_order_the_rows_came_in),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
