/* schema.h — the mission contract as documentation: `aeroeval schema`, the
 * JSON Schema for editors, and "did you mean" suggestions.
 *
 * Everything here is derived from the field table in spec.h (STYLE rule 11):
 * paths, groups, types, units, ranges, spellings and meanings; defaults come
 * from spec_defaults().  Nothing restates a default or a range.
 *
 * Who may include it: the input and command layers.
 */
#ifndef AEROEVAL_SCHEMA_H
#define AEROEVAL_SCHEMA_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include <cjson/cJSON.h>

#include "spec.h"

/* True when name is a group object of the mission file ("locks",
 * "payload_role", ...): some field path starts with name + ".". */
bool schema_is_group(const char *name);

/* The valid path closest to path, for "unknown field" messages: a field
 * path or a group name.  Case is ignored, transpositions count as one edit,
 * and the key is also compared with the fields of other groups, so
 * "payload_kgs" -> "payload_kg", "Payload_KG" -> "payload_kg", top-level
 * "aux_power_w" -> "payload_role.aux_power_w", "lock" -> "locks".
 * Writes it to out (size n) and returns true; false (out = "") when nothing
 * is close enough or the closest is path itself. */
bool schema_suggest(const char *path, char *out, size_t n);

/* The allowed range of numeric field f as text: "0 to 500 kg", or
 * "above 0.05 up to 5 m" when the minimum is exclusive (SPEC_F_MIN_EXCL). */
void schema_range_text(const struct spec_field_info *f, char *buf, size_t n);

/* `aeroeval schema`: every field, grouped by object, with its type, unit,
 * default, allowed range or values and meaning, for a terminal. */
void schema_print_text(FILE *out);

/* The JSON Schema (draft 2020-12) of mission files: types, enums, ranges,
 * defaults, descriptions, additionalProperties false, "$schema" allowed in
 * every object and "name" in every group.  data/mission.schema.json is
 * cJSON_Print of this plus a newline.  Ownership: cJSON_Delete(). */
cJSON *schema_json_schema(void);

#endif /* AEROEVAL_SCHEMA_H */
