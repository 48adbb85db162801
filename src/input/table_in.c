/* table_in.c — a design-space row from result.json (see table_in.h). */
#include "input/table_in.h"

#include <math.h>
#include <string.h>

#include "input/json_in.h"
#include "util/strbuf.h"

/* The member key of obj, or NULL (keys are case-sensitive: STYLE rule 9). */
static const cJSON *
member(const cJSON *obj, const char *key)
{
	return cJSON_IsObject(obj) ? cJSON_GetObjectItemCaseSensitive(obj, key) : NULL;
}

/* A finite number at obj.key into *out; false when absent or not one. */
static bool
get_num(const cJSON *obj, const char *key, double *out)
{
	const cJSON *v = member(obj, key);
	if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble))
		return false;
	*out = v->valuedouble;
	return true;
}

static const char *
get_str(const cJSON *obj, const char *key)
{
	const cJSON *v = member(obj, key);
	return cJSON_IsString(v) ? v->valuestring : NULL;
}

/* A required member: present with one of the types in mask, else an error
 * naming it. */
static const cJSON *
need(struct json_in *ji, const cJSON *obj, const char *path, const char *key,
     int mask, const char *expected)
{
	char p[96];
	json_in_path(p, sizeof p, path, key);
	const cJSON *v = member(obj, key);
	if (v == NULL) {
		json_in_report(ji, DIAG_MISSING, NULL, JSON_IN_FILE, p,
		               " (not a result.json of this aeroeval?)");
		return NULL;
	}
	return json_in_expect(ji, v, p, mask, expected) ? v : NULL;
}

/* "maker part" of a selected part (selected.<key>), or "". */
static void
part_text(const cJSON *selected, const char *key, char *out, size_t n)
{
	const cJSON *p = member(selected, key);
	const char *maker = get_str(p, "manufacturer"), *part = get_str(p, "part_number");
	out[0] = '\0';
	if (part == NULL)
		return;
	struct strbuf sb = STRBUF_INIT;
	if (maker != NULL && maker[0] != '\0')
		strbuf_printf(&sb, "%s ", maker);
	strbuf_append_str(&sb, part);
	str_copy(out, n, strbuf_str(&sb));
	strbuf_free(&sb);
}

/* The check that binds: the worst failing one, else the passing one with
 * the least margin; checks the design is sized to by construction (arm
 * stress, propeller diameter, mission energy) are skipped, as in
 * res_tightest_check(), since their zero margin says nothing. */
static void
tightest(const cJSON *checks, struct table_row *row)
{
	const cJSON *best = NULL;
	double best_margin = 0.0;
	bool best_fails = false;
	const cJSON *c;
	cJSON_ArrayForEach(c, checks) {
		double margin;
		const cJSON *pass = member(c, "pass"), *sized = member(c, "sized_to_limit");
		if (get_str(c, "name") == NULL || !get_num(c, "margin", &margin)
		    || !cJSON_IsBool(pass) || cJSON_IsTrue(sized))
			continue;
		bool fails = cJSON_IsFalse(pass);
		if (best == NULL || (fails && !best_fails)
		    || (fails == best_fails && margin < best_margin)) {
			best = c;
			best_margin = margin;
			best_fails = fails;
		}
	}
	if (best != NULL) {
		str_copy(row->tightest, sizeof row->tightest, get_str(best, "name"));
		row->tightest_margin = best_margin;
	}
}

/* The 90 % (or other) prediction interval on the takeoff mass, when the
 * file has one: "mtow_interval": {"level", "lo_kg", "hi_kg"} at the top
 * (the names of struct res_interval); an object without both bounds, or
 * null, counts as absent. */
static void
interval(const cJSON *root, struct table_row *row)
{
	const cJSON *iv = member(root, "mtow_interval");
	double lo, hi, level = 0.0;
	if (!get_num(iv, "lo_kg", &lo) || !get_num(iv, "hi_kg", &hi))
		return;
	get_num(iv, "level", &level);
	row->has_interval = true;
	row->mtow_lo_kg = lo;
	row->mtow_hi_kg = hi;
	row->interval_level = level;
}

/* The mission's inputs the table shows beside the results, from the fully
 * defaulted "mission" every result.json carries; all or none. */
static void
inputs(const cJSON *mission, struct table_row *row)
{
	const char *role = get_str(member(mission, "payload_role"), "type");
	const char *cls = get_str(mission, "airframe_class");
	const char *chem = get_str(mission, "battery_chemistry");
	const cJSON *coax = member(mission, "coaxial_layout");
	double rotors, max_payload;
	bool ok = role && cls && chem && cJSON_IsBool(coax)
	    && get_num(mission, "num_rotors", &rotors) && rotors >= 1.0 && rotors < 1000.0
	    && get_num(mission, "max_diameter_m", &row->wheelbase_m)
	    && get_num(mission, "altitude_m", &row->altitude_m)
	    && get_num(mission, "ambient_temp_c", &row->ambient_temp_c)
	    && get_num(mission, "t_hover_s", &row->t_hover_s)
	    && get_num(mission, "t_forward_s", &row->t_forward_s)
	    && get_num(mission, "t_climb_s", &row->t_climb_s)
	    && get_num(mission, "max_payload_kg", &max_payload);
	if (!ok)
		return;
	row->has_inputs = true;
	str_copy(row->role, sizeof row->role, role);
	str_copy(row->airframe_class, sizeof row->airframe_class, cls);
	str_copy(row->chemistry, sizeof row->chemistry, chem);
	row->rotors = (int)rotors;
	row->coaxial = cJSON_IsTrue(coax);
	row->max_payload_kg = fmax(max_payload, row->payload_kg);
}

int
table_in_parse(const char *file, const char *buf, size_t n, const char *name,
                 struct table_row *row, struct diag *dg)
{
	struct json_in *ji = json_in_parse(file, buf, n, dg);
	if (ji == NULL)
		return -1;
	const cJSON *root = json_in_root(ji);
	memset(row, 0, sizeof *row);
	str_copy(row->name, sizeof row->name, name);

	const cJSON *status = need(ji, root, "", "status", cJSON_String, "a string");
	const cJSON *buildable = need(ji, root, "", "buildable", cJSON_True | cJSON_False,
	                              "true or false");
	const cJSON *mtow = need(ji, root, "", "takeoff_mass_kg", cJSON_Number, "a number");
	const cJSON *dor = need(ji, root, "", "design_of_record", cJSON_Object, "an object");
	const cJSON *mission = need(ji, root, "", "mission", cJSON_Object, "an object");
	const cJSON *payload = mission != NULL
	    ? need(ji, mission, "mission", "payload_kg", cJSON_Number, "a number") : NULL;
	bool ok = status && buildable && mtow && dor && payload
	    && json_in_check_number(ji, mtow, "takeoff_mass_kg")
	    && json_in_check_number(ji, payload, "mission.payload_kg");
	if (ok && strcmp(status->valuestring, "feasible") != 0
	    && strcmp(status->valuestring, "infeasible") != 0) {
		json_in_report(ji, DIAG_BAD_ENUM, status, JSON_IN_VALUE, "status",
		               " (allowed: feasible, infeasible)");
		ok = false;
	}
	if (!ok) {
		json_in_free(ji);
		return -1;
	}

	bool real = cJSON_IsTrue(buildable);
	row->status = !real ? TABLE_ROW_NOT_BUILDABLE
	    : strcmp(status->valuestring, "feasible") == 0 ? TABLE_ROW_FEASIBLE
	    : TABLE_ROW_INFEASIBLE;
	row->takeoff_mass_kg = mtow->valuedouble;
	row->payload_kg = payload->valuedouble;
	inputs(mission, row);
	interval(root, row);
	/* The record's figures as the dossier prints them ("key_figures",
	 * result/result.h res_figures()); a result.json written before that
	 * block existed gives them from the record's own fields. */
	const cJSON *kf = member(root, "key_figures");
	row->has_flight_time = get_num(kf, "flight_time_s", &row->flight_time_s)
	    || get_num(dor, "flight_time_s", &row->flight_time_s);
	double t;
	if (get_num(kf, "hover_endurance_s", &t) && t > 0.0) {
		row->has_endurance = true;
		row->hover_endurance_s = t;
	} else if (real && get_num(member(dor, "performance"), "hover_time_s", &t)) {
		row->has_endurance = true;
		row->hover_endurance_s = t;
	} else if (get_num(dor, "hover_endurance_s", &t) && t > 0.0) {
		row->has_endurance = true;
		row->hover_endurance_s = t;
	}
	double cells = 0.0;
	if (get_num(dor, "cell_count", &cells) && cells >= 1.0 && cells < 1000.0)
		row->cells = (int)cells;
	get_num(dor, "battery_capacity_mah", &row->capacity_mah);
	if (real) {
		const cJSON *bom = member(root, "bom"), *selected = member(root, "selected");
		double missing = 0.0;
		row->has_cost = get_num(bom, "total_price_usd", &row->cost_usd);
		if ((get_num(kf, "bom_unpriced_lines", &missing)
		     || get_num(bom, "prices_missing", &missing)) && missing >= 0.0 && missing < 1e6)
			row->unpriced_lines = (int)missing;
		part_text(selected, "motor", row->motor, sizeof row->motor);
		part_text(selected, "prop", row->propeller, sizeof row->propeller);
		part_text(selected, "battery", row->battery, sizeof row->battery);
	}
	tightest(member(dor, "checks"), row);
	json_in_free(ji);
	return 0;
}
