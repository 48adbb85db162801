/* model_io.h — load the reference tables of data/ into struct model_data.
 *
 * Strict like the mission reader (it reads through json_in): every problem
 * is reported into a struct diag as `file:line:col: error: entry.field:
 * message` (e.g. `data/roles.json:12:24: error: roles[3].load_factor: out
 * of range: 40 (allowed 1 to 20)`) and loading fails; nothing is guessed.
 * IO layer (uses cJSON); the engine only sees struct model_data.
 */
#ifndef AEROEVAL_MODEL_IO_H
#define AEROEVAL_MODEL_IO_H

#include "diag/diag.h"
#include "spec/model.h"

/* Load chemistries.json, roles.json, airframes.json, calibration.json and
 * requirements.json from dir into *out.  Returns the number of errors
 * (0 = success), each reported into dg. */
int model_io_load(const char *dir, struct model_data *out, struct diag *dg);

/* Load only calibration.json from path into *cal (same error rules). */
int model_io_load_calibration(const char *path, struct model_calibration *cal,
                              struct diag *dg);

/* Serialise a calibration as data/calibration.json text; caller frees. */
char *model_io_calibration_json(const struct model_calibration *cal);

#endif
