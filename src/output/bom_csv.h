/* bom_csv.h — bom.csv, the bill of materials as a spreadsheet (README.md).
 *
 * Who may include it: the output layer and the command drivers.  It reads a
 * const struct solve_result and returns text; it writes no file.
 *
 * Format (RFC 4180): CRLF after every record, including the last; a field is
 * quoted when it contains a comma, a double quote, CR or LF, and an inner
 * quote is doubled.  Header:
 *   item,qty,category,manufacturer,part_number,description,unit_mass_g,
 *   total_mass_g,unit_price_usd,total_price_usd,catalogue_id
 * then one record per res_bom_line, masses in grams with one decimal, prices
 * in USD with two; an unknown price (0 in the struct) is an empty cell, in
 * both price columns.  Last, the total record: category "total", total_mass_g
 * = bom_mass_kg, total_price_usd = bom_price_usd (which the engine keeps as
 * the sum of the known prices).  When some prices are unknown the total
 * record's description says how many, e.g.
 *   ,,total,,,2 of 7 prices unknown: total is the sum of the known prices,,1234.5,,98.40,
 * When no parts were selected (!parts_selected) there is no BOM: the file is
 * the header and the total record ",,total,,,no parts selected,,0.0,,0.00,".
 * Numbers never print as "-0.0"; a non-finite number is an engine bug and
 * leaves its cell empty (counted by bom_csv_render_checked).
 */
#ifndef AEROEVAL_BOM_CSV_H
#define AEROEVAL_BOM_CSV_H

#include "core/result.h"

/* Renders bom.csv.  Ownership: the caller frees the text with free().
 * *n_invalid (if not NULL) receives the number of non-finite values that were
 * left as empty cells; the caller must treat > 0 as an internal error. */
char *bom_csv_render_checked(const struct solve_result *r, int *n_invalid);

/* Same, asserting (debug builds) that every number is finite. */
char *bom_csv_render(const struct solve_result *r);

/* BOM lines whose unit price is unknown (0); 0 when !parts_selected.
 * result.json reports the same count. */
int bom_csv_missing_prices(const struct solve_result *r);

#endif
