/* result.c — the few constants of the result contract (see result.h). */
#include "result.h"

/* Spellings of enum res_phase_id, as written to result.json, bom.csv and the
 * dossier; index = enum value. */
const char *const res_phase_name[PHASE_MAX] = { "climb", "forward", "hover" };
