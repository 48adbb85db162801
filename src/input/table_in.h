/* table_in.h — one row of the design-space table from a result.json.
 *
 * Reads what the table shows (result/table_row.h) out of a result.json that
 * aeroeval wrote: the verdict, the takeoff mass of record and, when the
 * file carries one, its prediction interval, the payload, flight times,
 * cost, pack, parts and the tightest check of the design of record.
 * A field the table needs to place the row at all (status, buildable,
 * takeoff_mass_kg, mission.payload_kg, design_of_record) missing or of the
 * wrong type is an error; every other field may be absent (its cell stays
 * empty), so files of older and newer versions still give rows.
 *
 * Who may include it: the command layer.
 */
#ifndef AEROEVAL_TABLE_IN_H
#define AEROEVAL_TABLE_IN_H

#include <stddef.h>

#include "diag/diag.h"
#include "result/table_row.h"

/* Parses buf[0..n) (need not be NUL-terminated), named file in messages,
 * as the result.json of the mission called name (the folder name) into
 * *row.  Returns 0, or -1 after reporting through dg (row unspecified). */
int table_in_parse(const char *file, const char *buf, size_t n,
                     const char *name, struct table_row *row,
                     struct diag *dg);

#endif
