/* mission_io.h — mission files: JSON text <-> struct mission_spec.
 *
 * The parser is strict and reports every problem of a file in one pass
 * through a struct diag (STYLE rules 9-10): malformed JSON, trailing text,
 * unknown keys (with a suggestion), duplicate keys, wrong types, non-integral
 * integers, values out of the table's range, infinities, unknown enum
 * spellings or chemistries, over-long or non-UTF-8 strings, impossible dates.
 * Each diagnostic carries file:line:col of the offending key or value.
 *
 * Files written for the paper's public engine (flat fields plus locks{},
 * payload_role{}, structural_overrides{}, aerodynamic_overrides{}) parse
 * unchanged.  "$schema" is allowed in every object, "name" in every group
 * (ignored there).  report.date may be "" (= not given).
 *
 * Who may include it: the input and command layers.
 */
#ifndef AEROEVAL_MISSION_IO_H
#define AEROEVAL_MISSION_IO_H

#include <stddef.h>

#include <cjson/cJSON.h>

#include "diag/diag.h"
#include "spec/spec.h"
#include "input/json_in.h"

/* Parse the mission text buf[0..len) (need not be NUL-terminated) named file
 * in diagnostics.  *out starts from spec_defaults(); each field present and
 * valid is stored and its out->given[id] set; an invalid field keeps its
 * default.  known_chemistries is a NULL-terminated list of the names
 * battery_chemistry may take; NULL skips that check.
 * Returns the number of errors reported into dg by this call (0 = valid). */
int mission_io_parse(const char *file, const char *buf, size_t len,
                     const char *const *known_chemistries, struct diag *dg,
                     struct mission_spec *out);

/* The same, then the mission as a whole: each essential it misses
 * (spec.h, spec_essentials: payload_kg, max_diameter_m, a mission time
 * above 0, unless requirements{} derives them) is one "missing field"
 * error at its top-level object ("file:1:1: error: payload_kg: missing
 * field; a mission gives payload_kg, or requirements.payload_preset to
 * derive it"), reported when the fields themselves are valid.  What
 * `check`, `solve` and `build` read a mission file with. */
int mission_io_parse_mission(const char *file, const char *buf, size_t len,
                             const char *const *known_chemistries, struct diag *dg,
                             struct mission_spec *out);

/* A mission file above this size is refused (PRODUCT: > 4 MiB). */
#define MISSION_IO_MAX_BYTES JSON_IN_MISSION_MAX

/* A mission file of more JSON values than this is refused before its tree
 * is built ("too many entries"), which bounds the memory of a parse to
 * about 40 MB whatever the file holds; a mission has about 100 values, the
 * hostile tests' 150 000 unknown keys fit. */
#define MISSION_IO_MAX_VALUES (1 << 18)

/* Read the file at path and parse it as mission_io_parse_mission.  An
 * unreadable file (also a
 * directory, FIFO or device, or one above MISSION_IO_MAX_BYTES) is one
 * error ("path: error: cannot read file: reason"), *out then holds the
 * defaults. */
int mission_io_load(const char *path, const char *const *known_chemistries,
                    struct diag *dg, struct mission_spec *out);

/* The mission as JSON, nested as in a mission file, with every field of the
 * table (defaults included); enums by spelling, v_forward_ms as "auto" when
 * v_forward_auto.  Parsing its printout (jsonw_print(), which prints every
 * number exactly) gives the same values back.
 * Ownership: cJSON_Delete(). */
cJSON *mission_io_to_json(const struct mission_spec *s);

#endif /* AEROEVAL_MISSION_IO_H */
