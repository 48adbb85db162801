/* index.c — index.csv and index.json (see index.h). */
#include "formats/index.h"

#include <math.h>

#include <cjson/cJSON.h>

#include "util/csv.h"
#include "util/jsonw.h"
#include "util/numfmt.h"
#include "util/strbuf.h"
#include "util/text.h"

const char *const index_file_names[] = { "index.csv", "index.json", "overview.pdf", NULL };

/* ---- index.csv ------------------------------------------------------------- */

/* The mission as asked, then the design of record. */
static const char *const csv_header[] = {
	"name", "status",
	"role", "rotors", "coaxial", "wheelbase_m", "airframe_class", "battery_chemistry",
	"altitude_m", "ambient_temp_c", "t_hover_s", "t_forward_s", "t_climb_s",
	"payload_kg", "max_payload_kg",
	"takeoff_mass_kg", "mtow_interval_level", "mtow_lo_kg", "mtow_hi_kg",
	"flight_time_s", "hover_endurance_s", "cost_usd", "unpriced_lines", "cells",
	"capacity_mah", "motor", "propeller", "battery", "tightest_check", "tightest_margin",
	NULL
};

/* Text from outside the program (names, catalogue texts): neutralised
 * when it starts like a formula (text_is_formula()). */
static void
text(struct csv_out *o, const char *s)
{
	if (!text_is_formula(s)) {
		csv_out_field(o, s);
		return;
	}
	struct strbuf q = STRBUF_INIT;
	strbuf_append_char(&q, '\'');
	strbuf_append_str(&q, s);
	csv_out_field(o, strbuf_str(&q));
	strbuf_free(&q);
}

/* The mission's inputs of a row (all empty when it has none). */
static void
inputs_csv(struct csv_out *o, const struct table_row *w)
{
	bool in = w->has_inputs;
	text(o, in ? w->role : "");
	csv_out_num(o, in, w->rotors, 0);
	csv_out_field(o, !in ? "" : w->coaxial ? "true" : "false");
	csv_out_num(o, in, w->wheelbase_m, 3);
	text(o, in ? w->airframe_class : "");
	text(o, in ? w->chemistry : "");
	csv_out_num(o, in, w->altitude_m, 0);
	csv_out_num(o, in, w->ambient_temp_c, 2);
	csv_out_num(o, in, w->t_hover_s, 0);
	csv_out_num(o, in, w->t_forward_s, 0);
	csv_out_num(o, in, w->t_climb_s, 0);
	csv_out_num(o, true, w->payload_kg, 3);
	csv_out_num(o, in, w->max_payload_kg, 3);
}

char *
index_csv(const struct table_rows *s)
{
	struct strbuf sb = STRBUF_INIT;
	struct csv_out o = { &sb, 0 };
	for (size_t i = 0; csv_header[i] != NULL; i++)
		csv_out_field(&o, csv_header[i]);
	csv_out_end(&o);
	for (size_t i = 0; i < s->n; i++) {
		const struct table_row *w = &s->rows[i];
		bool real = w->status != TABLE_ROW_NOT_BUILDABLE;
		text(&o, w->name);
		csv_out_field(&o, table_row_status_name(w->status));
		inputs_csv(&o, w);
		csv_out_num(&o, true, w->takeoff_mass_kg, 3);
		csv_out_num(&o, w->has_interval && w->interval_level > 0.0, w->interval_level, 2);
		csv_out_num(&o, w->has_interval, w->mtow_lo_kg, 3);
		csv_out_num(&o, w->has_interval, w->mtow_hi_kg, 3);
		csv_out_num(&o, w->has_flight_time, w->flight_time_s, 0);
		csv_out_num(&o, w->has_endurance, w->hover_endurance_s, 0);
		csv_out_num(&o, w->has_cost, w->cost_usd, 2);
		csv_out_num(&o, real, w->unpriced_lines, 0);
		csv_out_num(&o, w->cells > 0, w->cells, 0);
		csv_out_num(&o, w->capacity_mah > 0.0, w->capacity_mah, 0);
		text(&o, w->motor);
		text(&o, w->propeller);
		text(&o, w->battery);
		text(&o, w->tightest);
		csv_out_num(&o, w->tightest[0] != '\0', w->tightest_margin, 3);
		csv_out_end(&o);
	}
	return strbuf_take(&sb, NULL);
}

/* ---- index.json ------------------------------------------------------------ */

/* x (printed exactly by jsonw), or null when unknown or not finite. */
static void
add_num(cJSON *o, const char *key, bool known, double x)
{
	if (known && isfinite(x))
		cJSON_AddNumberToObject(o, key, x);
	else
		cJSON_AddNullToObject(o, key);
}

static void
add_text(cJSON *o, const char *key, const char *s)
{
	if (s[0] != '\0')
		cJSON_AddStringToObject(o, key, s);
	else
		cJSON_AddNullToObject(o, key);
}

static cJSON *
row_json(const struct table_row *w)
{
	bool real = w->status != TABLE_ROW_NOT_BUILDABLE;
	cJSON *o = cJSON_CreateObject();
	cJSON_AddStringToObject(o, "name", w->name);
	cJSON_AddStringToObject(o, "status", table_row_status_name(w->status));
	bool in = w->has_inputs;
	add_text(o, "role", in ? w->role : "");
	add_num(o, "rotors", in, w->rotors);
	if (in)
		cJSON_AddBoolToObject(o, "coaxial", w->coaxial);
	else
		cJSON_AddNullToObject(o, "coaxial");
	add_num(o, "wheelbase_m", in, w->wheelbase_m);
	add_text(o, "airframe_class", in ? w->airframe_class : "");
	add_text(o, "battery_chemistry", in ? w->chemistry : "");
	add_num(o, "altitude_m", in, w->altitude_m);
	add_num(o, "ambient_temp_c", in, w->ambient_temp_c);
	add_num(o, "t_hover_s", in, w->t_hover_s);
	add_num(o, "t_forward_s", in, w->t_forward_s);
	add_num(o, "t_climb_s", in, w->t_climb_s);
	add_num(o, "payload_kg", true, w->payload_kg);
	add_num(o, "max_payload_kg", in, w->max_payload_kg);
	add_num(o, "takeoff_mass_kg", true, w->takeoff_mass_kg);
	if (w->has_interval) {
		cJSON *iv = cJSON_AddObjectToObject(o, "mtow_interval");
		add_num(iv, "level", w->interval_level > 0.0, w->interval_level);
		add_num(iv, "lo_kg", true, w->mtow_lo_kg);
		add_num(iv, "hi_kg", true, w->mtow_hi_kg);
	} else {
		cJSON_AddNullToObject(o, "mtow_interval");
	}
	add_num(o, "flight_time_s", w->has_flight_time, w->flight_time_s);
	add_num(o, "hover_endurance_s", w->has_endurance, w->hover_endurance_s);
	add_num(o, "cost_usd", w->has_cost, w->cost_usd);
	add_num(o, "unpriced_lines", real, w->unpriced_lines);
	add_num(o, "cell_count", w->cells > 0, w->cells);
	add_num(o, "battery_capacity_mah", w->capacity_mah > 0.0, w->capacity_mah);
	add_text(o, "motor", w->motor);
	add_text(o, "propeller", w->propeller);
	add_text(o, "battery", w->battery);
	if (w->tightest[0] != '\0') {
		cJSON *t = cJSON_AddObjectToObject(o, "tightest_check");
		cJSON_AddStringToObject(t, "name", w->tightest);
		add_num(t, "margin", true, w->tightest_margin);
	} else {
		cJSON_AddNullToObject(o, "tightest_check");
	}
	return o;
}

char *
index_json(const struct table_rows *s, const char *aeroeval_version)
{
	size_t count[TABLE_ROW_STATUS_MAX];
	table_row_count(s, count);
	cJSON *root = cJSON_CreateObject();
	cJSON_AddStringToObject(root, "aeroeval_version", aeroeval_version);
	cJSON *c = cJSON_AddObjectToObject(root, "counts");
	add_num(c, "feasible", true, (double)count[TABLE_ROW_FEASIBLE]);
	add_num(c, "infeasible", true, (double)count[TABLE_ROW_INFEASIBLE]);
	add_num(c, "not_buildable", true, (double)count[TABLE_ROW_NOT_BUILDABLE]);
	cJSON *arr = cJSON_AddArrayToObject(root, "missions");
	for (size_t i = 0; i < s->n; i++)
		cJSON_AddItemToArray(arr, row_json(&s->rows[i]));
	char *text = jsonw_print(root, NULL);
	cJSON_Delete(root);
	return text;
}
