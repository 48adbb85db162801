/* index.c — index.csv and index.json (see index.h). */
#include "output/index.h"

#include <math.h>

#include <cjson/cJSON.h>

#include "util/csv.h"
#include "util/jsonw.h"
#include "util/numfmt.h"
#include "util/strbuf.h"
#include "util/text.h"

/* ---- index.csv ------------------------------------------------------------- */

static const char *const csv_header[] = {
	"name", "status", "takeoff_mass_kg", "mtow_interval_level", "mtow_lo_kg",
	"mtow_hi_kg", "payload_kg", "flight_time_s", "hover_endurance_s", "cost_usd",
	"prices_missing", "cells", "capacity_mah", "motor", "propeller", "battery",
	"tightest_check", "tightest_margin", NULL
};

/* A record being written: the text and whether a field came before. */
struct rec {
	struct strbuf *sb;
	int n;  /* fields written in this record */
};

static void
field(struct rec *r, const char *s)
{
	if (r->n++ > 0)
		strbuf_append_char(r->sb, ',');
	csv_write_field(r->sb, s);
}

/* Text from outside the program (names, catalogue texts): neutralised
 * when it starts like a formula (text_is_formula()). */
static void
text(struct rec *r, const char *s)
{
	if (!text_is_formula(s)) {
		field(r, s);
		return;
	}
	struct strbuf q = STRBUF_INIT;
	strbuf_append_char(&q, '\'');
	strbuf_append_str(&q, s);
	field(r, strbuf_str(&q));
	strbuf_free(&q);
}

/* A number with fixed decimals, or an empty cell when unknown. */
static void
num(struct rec *r, bool known, double x, int decimals)
{
	char t[64];
	if (!known || numfmt_fixed(t, sizeof t, x, decimals) == 0)
		t[0] = '\0';
	field(r, t);
}

static void
end(struct rec *r)
{
	strbuf_append(r->sb, "\r\n", 2);
	r->n = 0;
}

char *
index_csv(const struct summary *s)
{
	struct strbuf sb = STRBUF_INIT;
	struct rec r = { &sb, 0 };
	for (size_t i = 0; csv_header[i] != NULL; i++)
		field(&r, csv_header[i]);
	end(&r);
	for (size_t i = 0; i < s->n; i++) {
		const struct summary_row *w = &s->rows[i];
		bool real = w->status != SUMMARY_NOT_BUILDABLE;
		text(&r, w->name);
		field(&r, summary_status_name(w->status));
		num(&r, true, w->takeoff_mass_kg, 3);
		num(&r, w->has_interval && w->interval_level > 0.0, w->interval_level, 2);
		num(&r, w->has_interval, w->mtow_lo_kg, 3);
		num(&r, w->has_interval, w->mtow_hi_kg, 3);
		num(&r, true, w->payload_kg, 3);
		num(&r, w->has_flight_time, w->flight_time_s, 0);
		num(&r, w->has_endurance, w->hover_endurance_s, 0);
		num(&r, w->has_cost, w->cost_usd, 2);
		num(&r, real, w->prices_missing, 0);
		num(&r, w->cells > 0, w->cells, 0);
		num(&r, w->capacity_mah > 0.0, w->capacity_mah, 0);
		text(&r, w->motor);
		text(&r, w->propeller);
		text(&r, w->battery);
		text(&r, w->tightest);
		num(&r, w->tightest[0] != '\0', w->tightest_margin, 3);
		end(&r);
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
row_json(const struct summary_row *w)
{
	bool real = w->status != SUMMARY_NOT_BUILDABLE;
	cJSON *o = cJSON_CreateObject();
	cJSON_AddStringToObject(o, "name", w->name);
	cJSON_AddStringToObject(o, "status", summary_status_name(w->status));
	add_num(o, "takeoff_mass_kg", true, w->takeoff_mass_kg);
	if (w->has_interval) {
		cJSON *iv = cJSON_AddObjectToObject(o, "mtow_interval");
		add_num(iv, "level", w->interval_level > 0.0, w->interval_level);
		add_num(iv, "lo_kg", true, w->mtow_lo_kg);
		add_num(iv, "hi_kg", true, w->mtow_hi_kg);
	} else {
		cJSON_AddNullToObject(o, "mtow_interval");
	}
	add_num(o, "payload_kg", true, w->payload_kg);
	add_num(o, "flight_time_s", w->has_flight_time, w->flight_time_s);
	add_num(o, "hover_endurance_s", w->has_endurance, w->hover_endurance_s);
	add_num(o, "cost_usd", w->has_cost, w->cost_usd);
	add_num(o, "prices_missing", real, w->prices_missing);
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
index_json(const struct summary *s, const char *aeroeval_version)
{
	size_t count[SUMMARY_STATUS_MAX];
	summary_count(s, count);
	cJSON *root = cJSON_CreateObject();
	cJSON_AddStringToObject(root, "aeroeval_version", aeroeval_version);
	cJSON *c = cJSON_AddObjectToObject(root, "counts");
	add_num(c, "feasible", true, (double)count[SUMMARY_FEASIBLE]);
	add_num(c, "infeasible", true, (double)count[SUMMARY_INFEASIBLE]);
	add_num(c, "not_buildable", true, (double)count[SUMMARY_NOT_BUILDABLE]);
	cJSON *arr = cJSON_AddArrayToObject(root, "missions");
	for (size_t i = 0; i < s->n; i++)
		cJSON_AddItemToArray(arr, row_json(&s->rows[i]));
	char *text = jsonw_print(root, NULL);
	cJSON_Delete(root);
	return text;
}
