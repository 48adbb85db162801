/* model_io.h — load the reference tables of data/ into struct model_data.
 *
 * Strict like the mission reader: every problem is printed as
 * `file: error: entry.field: message` and loading fails; nothing is guessed.
 * IO layer (uses cJSON); the engine only sees struct model_data.
 */
#ifndef AEROEVAL_MODEL_IO_H
#define AEROEVAL_MODEL_IO_H

#include <stdio.h>

#include "core/model.h"

/* Load chemistries.json, roles.json, airframes.json, calibration.json and
 * requirements.json from dir into *out.  Returns the number of errors
 * (0 = success); each error is printed on err. */
int model_io_load(const char *dir, struct model_data *out, FILE *err);

/* Load only calibration.json from path into *cal (same error rules). */
int model_io_load_calibration(const char *path, struct model_calibration *cal,
                              FILE *err);

/* Serialise a calibration as data/calibration.json text; caller frees. */
char *model_io_calibration_json(const struct model_calibration *cal);

#endif
