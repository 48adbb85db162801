/* schema.c — documentation, JSON Schema and suggestions from the field
 * table (see schema.h). */
#include "input/schema.h"

#include <ctype.h>
#include <string.h>

#include "input/mission_io.h"
#include "util/text.h"







/* ---- aeroeval schema ----------------------------------------------------- */

static const char *
schema_type_name(enum spec_type t)
{
	switch (t) {
	case SPEC_NUM:
		return "number";
	case SPEC_INT:
		return "integer";
	case SPEC_BOOL:
		return "boolean";
	case SPEC_STR:
		return "string";
	case SPEC_ENUM:
		return "text, one of the allowed values";
	case SPEC_SPEED:
		return "number or \"auto\"";
	case SPEC_DATE:
		return "date \"YYYY-MM-DD\"";
	}
	return "value";
}

/* One field of `aeroeval schema`: path and type, default and allowed
 * values, meaning. */
static void
schema_print_field(FILE *out, const struct mission_spec *def,
                   const struct spec_field_info *f)
{
	char val[256], range[128];

	fprintf(out, "  %s  (%s%s%s)\n", f->path, schema_type_name(f->type),
	        f->unit[0] != '\0' ? ", " : "", f->unit);
	spec_format_value(def, f, val, sizeof val);
	fprintf(out, "      default %s%s", val,
	        (f->flags & SPEC_F_DERIVED) ? " (when absent, derived by the engine)" : "");
	switch (f->type) {
	case SPEC_NUM:
	case SPEC_INT:
	case SPEC_SPEED:
		spec_range_text(f, range, sizeof range);
		fprintf(out, "; allowed %s", range);
		break;
	case SPEC_ENUM:
		fprintf(out, "; allowed:");
		for (size_t k = 0; f->enums[k] != NULL; k++)
			fprintf(out, "%s %s", k > 0 ? "," : "", f->enums[k]);
		break;
	case SPEC_STR:
		fprintf(out, "; at most %d bytes of UTF-8", SPEC_STR_MAX - 1);
		break;
	case SPEC_DATE:
	case SPEC_BOOL:
		break;
	}
	if (f->flags & SPEC_F_ZERO_AUTO)
		fprintf(out, "; 0 = automatic");
	if (f->flags & SPEC_F_BEYOND)
		fprintf(out, "; aeroeval extension");
	fprintf(out, "\n      %s\n", f->help);
}

void
schema_print_text(FILE *out)
{
	struct mission_spec def;
	char group[TEXT_DISTANCE_MAX + 1], other[TEXT_DISTANCE_MAX + 1];

	spec_defaults(&def);
	fprintf(out,
	        "aeroeval %s mission file fields.  \"$schema\" is allowed in every object.\n"
	        "\nRequired: a mission gives\n", AEROEVAL_VERSION);
	for (int i = 0; i < SPEC_N_ESSENTIALS; i++) {
		const struct spec_essential *e = &spec_essentials[i];
		fprintf(out, "  - %s", e->any_of[1] == SPEC_N_FIELDS ? "" : "one of ");
		for (int k = 0; k < SPEC_ESSENTIAL_FIELDS && e->any_of[k] != SPEC_N_FIELDS; k++)
			fprintf(out, "%s%s", k == 0 ? "" : ", ", spec_fields[e->any_of[k]].path);
		if (e->positive)
			fprintf(out, " above 0");
		if (e->derived_by != SPEC_N_FIELDS)
			fprintf(out, ", or %s, which derives it", spec_fields[e->derived_by].path);
		fprintf(out, "\n");
	}
	fprintf(out, "Every other field is optional; an absent field takes its default.\n");
	/* Groups in the order they first appear in the table, each with all
	 * of its fields, so the top level is listed once. */
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		bool seen = false;
		spec_split(spec_fields[i].path, group, sizeof group);
		for (size_t j = 0; j < i && !seen; j++) {
			spec_split(spec_fields[j].path, other, sizeof other);
			seen = strcmp(group, other) == 0;
		}
		if (seen)
			continue;
		if (group[0] == '\0')
			fprintf(out, "\ntop level\n");
		else
			fprintf(out, "\n%s { ... }   (an object; \"name\" is allowed and ignored)\n",
			        group);
		for (size_t j = i; j < SPEC_N_FIELDS; j++) {
			spec_split(spec_fields[j].path, other, sizeof other);
			if (strcmp(group, other) == 0)
				schema_print_field(out, &def, &spec_fields[j]);
		}
	}
}

/* ---- JSON Schema --------------------------------------------------------- */

/* The schema of one field; defval is its default as mission_io_to_json
 * prints it (so the default comes from spec_defaults, not from here). */
static cJSON *
schema_field(const struct spec_field_info *f, const cJSON *defval,
             const char *const *chemistries)
{
	cJSON *o = cJSON_CreateObject();
	char desc[512];

	if (f->unit[0] != '\0')
		snprintf(desc, sizeof desc, "%s [%s]", f->help, f->unit);
	else
		snprintf(desc, sizeof desc, "%s", f->help);
	cJSON_AddStringToObject(o, "description", desc);

	cJSON *num = o;
	if (f->type == SPEC_SPEED) {
		cJSON *any = cJSON_AddArrayToObject(o, "anyOf");
		num = cJSON_CreateObject();
		cJSON_AddItemToArray(any, num);
		cJSON *au = cJSON_CreateObject();
		cJSON_AddStringToObject(au, "const", "auto");
		cJSON_AddItemToArray(any, au);
	}
	switch (f->type) {
	case SPEC_NUM:
	case SPEC_INT:
	case SPEC_SPEED:
		cJSON_AddStringToObject(num, "type", f->type == SPEC_INT ? "integer" : "number");
		cJSON_AddNumberToObject(num, (f->flags & SPEC_F_MIN_EXCL) ? "exclusiveMinimum"
		                                                         : "minimum", f->min);
		cJSON_AddNumberToObject(num, "maximum", f->max);
		break;
	case SPEC_BOOL:
		cJSON_AddStringToObject(o, "type", "boolean");
		break;
	case SPEC_ENUM: {
		cJSON_AddStringToObject(o, "type", "string");
		cJSON *e = cJSON_AddArrayToObject(o, "enum");
		for (size_t k = 0; f->enums[k] != NULL; k++)
			cJSON_AddItemToArray(e, cJSON_CreateString(f->enums[k]));
		break;
	}
	case SPEC_STR:
	case SPEC_DATE:
		cJSON_AddStringToObject(o, "type", "string");
		/* JSON Schema counts characters, we count bytes: the closest bound. */
		cJSON_AddNumberToObject(o, "maxLength", SPEC_STR_MAX - 1);
		if (f->type == SPEC_DATE)
			cJSON_AddStringToObject(o, "pattern", "^([0-9]{4}-[0-9]{2}-[0-9]{2})?$");
		/* The one closed set of text the table cannot spell: the
		 * chemistry profiles of data/chemistries.json. */
		if (f->id == SPECF_BATTERY_CHEMISTRY && chemistries != NULL) {
			cJSON *e = cJSON_AddArrayToObject(o, "enum");
			for (size_t k = 0; chemistries[k] != NULL; k++)
				cJSON_AddItemToArray(e, cJSON_CreateString(chemistries[k]));
		}
		break;
	}
	cJSON_AddItemToObject(o, "default", cJSON_Duplicate(defval, 1));
	return o;
}

/* A new object schema with "$schema" (and "name" in groups) allowed. */
static cJSON *
schema_object(const char *description, bool group, cJSON **props)
{
	cJSON *o = cJSON_CreateObject();
	cJSON_AddStringToObject(o, "description", description);
	cJSON_AddStringToObject(o, "type", "object");
	*props = cJSON_AddObjectToObject(o, "properties");
	cJSON *sch = cJSON_AddObjectToObject(*props, "$schema");
	cJSON_AddStringToObject(sch, "description", "URI of the mission JSON Schema, for editors");
	cJSON_AddStringToObject(sch, "type", "string");
	if (group) {
		cJSON *nm = cJSON_AddObjectToObject(*props, "name");
		cJSON_AddStringToObject(nm, "description", "A label for the group; ignored");
	}
	cJSON_AddFalseToObject(o, "additionalProperties");
	return o;
}

/* The schema a mission meets when one of its fields gives essential e
 * (a time above 0), or its requirements field is other than "none". */
static cJSON *
schema_essential(const struct spec_essential *e)
{
	char desc[320] = "Required: ";
	size_t n = strlen(desc);
	if (e->any_of[1] != SPEC_N_FIELDS)
		n += (size_t)snprintf(desc + n, sizeof desc - n, "one of ");
	for (int k = 0; k < SPEC_ESSENTIAL_FIELDS && e->any_of[k] != SPEC_N_FIELDS; k++)
		n += (size_t)snprintf(desc + n, sizeof desc - n, "%s%s", k == 0 ? "" : ", ",
		    spec_fields[e->any_of[k]].path);
	if (e->positive)
		n += (size_t)snprintf(desc + n, sizeof desc - n, " above 0");
	if (e->derived_by != SPEC_N_FIELDS)
		snprintf(desc + n, sizeof desc - n, ", or %s, which derives it",
		    spec_fields[e->derived_by].path);

	cJSON *o = cJSON_CreateObject();
	cJSON_AddStringToObject(o, "description", desc);
	cJSON *any = cJSON_AddArrayToObject(o, "anyOf");
	for (int k = 0; k < SPEC_ESSENTIAL_FIELDS && e->any_of[k] != SPEC_N_FIELDS; k++) {
		const char *path = spec_fields[e->any_of[k]].path;
		cJSON *alt = cJSON_CreateObject();
		cJSON_AddItemToArray(cJSON_AddArrayToObject(alt, "required"), cJSON_CreateString(path));
		if (e->positive) {
			cJSON *p = cJSON_AddObjectToObject(cJSON_AddObjectToObject(alt, "properties"), path);
			cJSON_AddNumberToObject(p, "exclusiveMinimum", 0);
		}
		cJSON_AddItemToArray(any, alt);
	}
	if (e->derived_by != SPEC_N_FIELDS) {
		/* {"required": ["requirements"], "properties": {"requirements":
		 *  {"required": [key], "properties": {key: {"not": {"const": "none"}}}}}} */
		char group[TEXT_DISTANCE_MAX + 1];
		const char *key = spec_split(spec_fields[e->derived_by].path, group, sizeof group);
		cJSON *alt = cJSON_CreateObject();
		cJSON_AddItemToArray(cJSON_AddArrayToObject(alt, "required"), cJSON_CreateString(group));
		cJSON *g = cJSON_AddObjectToObject(cJSON_AddObjectToObject(alt, "properties"), group);
		cJSON_AddItemToArray(cJSON_AddArrayToObject(g, "required"), cJSON_CreateString(key));
		cJSON *k = cJSON_AddObjectToObject(cJSON_AddObjectToObject(g, "properties"), key);
		cJSON_AddStringToObject(cJSON_AddObjectToObject(k, "not"), "const",
		    spec_fields[e->derived_by].enums[0]);
		cJSON_AddItemToArray(any, alt);
	}
	return o;
}

cJSON *
schema_json_schema(const char *const *chemistries)
{
	struct mission_spec def;
	char group[TEXT_DISTANCE_MAX + 1], desc[128];
	cJSON *props;

	spec_defaults(&def);
	cJSON *defaults = mission_io_to_json(&def);
	cJSON *root = cJSON_CreateObject();
	cJSON_AddStringToObject(root, "$schema", "https://json-schema.org/draft/2020-12/schema");
	cJSON_AddStringToObject(root, "title", "aeroeval mission file");
	cJSON *top = schema_object("A multirotor UAV design mission for aeroeval: a payload, a "
	                           "wheelbase and a mission time (allOf below); every other field "
	                           "is optional and has a default", false, &props);
	/* Merge the object schema into the root, after the title. */
	for (cJSON *c = top->child; c != NULL; c = top->child)
		cJSON_AddItemToObject(root, c->string,
		                      cJSON_DetachItemViaPointer(top, c));
	cJSON_Delete(top);
	props = cJSON_GetObjectItemCaseSensitive(root, "properties");

	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		const char *key = spec_split(f->path, group, sizeof group);
		cJSON *dst = props, *defobj = defaults;
		if (group[0] != '\0') {
			cJSON *g = cJSON_GetObjectItemCaseSensitive(props, group);
			if (g == NULL) {
				cJSON *gprops;
				snprintf(desc, sizeof desc, "The %s group", group);
				g = schema_object(desc, true, &gprops);
				cJSON_AddItemToObject(props, group, g);
			}
			dst = cJSON_GetObjectItemCaseSensitive(g, "properties");
			defobj = cJSON_GetObjectItemCaseSensitive(defaults, group);
		}
		cJSON_AddItemToObject(dst, key, schema_field(f,
		    cJSON_GetObjectItemCaseSensitive(defobj, key), chemistries));
	}
	cJSON_Delete(defaults);
	/* What every mission needs (spec_essentials), after the fields. */
	cJSON *all = cJSON_AddArrayToObject(root, "allOf");
	for (int i = 0; i < SPEC_N_ESSENTIALS; i++)
		cJSON_AddItemToArray(all, schema_essential(&spec_essentials[i]));
	return root;
}
