/* result_json.h — result.json, the machine-readable record of one solve
 * (README.md).
 *
 * Who may include it: the command drivers.  It reads a const struct
 * solve_result and returns text; it writes no file (the caller does,
 * atomically).
 *
 * The text is deterministic: fixed key order, 2-space indentation, LF line
 * ends, one final newline, numbers printed as the shortest of %.15g/%.16g/
 * %.17g that strtod() reads back to the same double (so a reader recovers
 * every value exactly and two runs give identical bytes), integers as
 * integers, and -0 as 0.  Arrays of plain numbers (and the phase column of
 * the time series) are packed ten to a line to keep the file small.
 * Strings are escaped per RFC 8259; valid UTF-8 passes through, an invalid
 * byte becomes U+FFFD.
 *
 * NaN and Infinity never appear.  A non-finite double (or an enum or count
 * outside its range) is a programming error in the engine: it is written as
 * null and counted, so the caller can fail with exit status 3 and name the
 * first offending JSON path.
 *
 * Layout (top level, in order): aeroeval_version, input_sha256,
 * catalogue_sha256, status, violations, rationale, mission, baseline, custom,
 * role_overhead, continuous_optimum, selected, bom_closed, bom, candidates.
 * A run that did not run is {"ran": false}; bom_closed and selected are null
 * when no parts were selected; an unknown price (0 in the struct) is null.
 */
#ifndef AEROEVAL_RESULT_JSON_H
#define AEROEVAL_RESULT_JSON_H

#include "result/result.h"

#define RESULT_JSON_PATH_MAX 160

/* What render found wrong in the result it was given. */
struct result_json_faults {
	int n_invalid;                          /* values written as null for being
	                                           non-finite or out of range */
	char first_path[RESULT_JSON_PATH_MAX];  /* JSON path of the first one, e.g.
	                                           "custom.phases[2].power_w"; "" if none */
};

/* Renders result.json for r.  Ownership: the caller frees the text with
 * free().  Never returns NULL (allocation failure exits, see xalloc.h).
 * aeroeval_version must not be NULL (the program passes AEROEVAL_VERSION).
 * faults receives the count and first path of invalid values; the caller must
 * treat n_invalid > 0 as an internal error and not publish the text.  Use
 * this one in the program. */
char *result_json_render_checked(const struct solve_result *r,
                                 const char *aeroeval_version,
                                 struct result_json_faults *faults);

/* Same, for callers that cannot handle faults: an invalid value trips an
 * assert in a debug build (after naming its path on stderr) and is written
 * as null in an NDEBUG build. */
char *result_json_render(const struct solve_result *r,
                         const char *aeroeval_version);

#endif
