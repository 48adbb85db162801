/* schema.h — the mission contract as documentation: `aeroeval schema`, the
 * JSON Schema for editors.
 *
 * Everything here is derived from the field table in spec.h (STYLE rule 11):
 * paths, groups, types, units, ranges, spellings and meanings; defaults come
 * from spec_defaults().  Nothing restates a default or a range.
 *
 * Who may include it: the input and command layers.
 */
#ifndef AEROEVAL_SCHEMA_H
#define AEROEVAL_SCHEMA_H

#include <stdio.h>

#include <cjson/cJSON.h>

#include "spec/spec.h"




/* `aeroeval schema`: every field, grouped by object, with its type, unit,
 * default, allowed range or values and meaning, for a terminal. */
void schema_print_text(FILE *out);

/* The JSON Schema (draft 2020-12) of mission files: types, enums, ranges,
 * defaults, descriptions, additionalProperties false, "$schema" allowed in
 * every object and "name" in every group; battery_chemistry an enum of
 * chemistries (NULL-terminated, the names of data/chemistries.json; NULL
 * leaves it open); and "allOf" the essentials every mission gives
 * (spec_essentials), each an "anyOf" of its fields and the requirements
 * field that derives it.  data/mission.schema.json is jsonw_print() of
 * this with the shipped chemistries (util/jsonw.h).  Ownership: cJSON_Delete(). */
cJSON *schema_json_schema(const char *const *chemistries);

#endif /* AEROEVAL_SCHEMA_H */
