/* bom_csv.h — bom.csv and bom_totals.csv, the bill of materials as a
 * procurement team orders from it.
 *
 * Who may include it: the formats, the dossier and the command drivers.
 * It reads a const struct solve_result (and the catalogue the parts came
 * from) and returns text; it writes no file.
 *
 * bom.csv (RFC 4180): CRLF after every record, including the last; a field
 * is quoted when it holds a comma, a double quote, CR or LF, and an inner
 * quote is doubled.  Header: the product's eleven bill columns, then the
 * procurement columns:
 *   item,qty,category,manufacturer,part_number,description,unit_mass_g,
 *   total_mass_g,unit_price_usd,total_price_usd,catalogue_id,
 *   currency,price_date,supplier_url,source,orderable,order_note
 * then one record per res_bom_line and nothing else: every record is a
 * line of the bill, so a spreadsheet's sort, filter or pivot and a CSV
 * reader (csv.DictReader, pandas, R) never take a total for a part.
 * Masses in grams with one decimal, prices in USD with two; an unknown
 * price (0 in the struct) leaves both price columns, currency and
 * price_date empty.  part_number is what the buyer orders (bom_csv_order):
 * the counter-rotating propeller line whose part number the parts search
 * made up ("<part number> (CCW)", the catalogue having no CCW part number)
 * carries the maker's one part number and says so in order_note.
 * supplier_url is the maker's page, source the catalogue's account of where
 * the facts were read (its `source` up to the caveats).  orderable is
 * "yes", "no" (a part sized by the design and made to its description, a
 * mass allowance of the airframe class, or the customer's payload: nothing
 * to order) or "confirm" (the catalogue doubts the part number itself:
 * order only after the maker confirms it); order_note says why.
 * When no parts were selected the file is the header alone.
 *
 * bom_totals.csv: the totals as their own one-record table,
 *   parts_mass_g,payload_mass_g,takeoff_mass_g,lines,priced_lines,
 *   unpriced_lines,known_price,currency,price_note
 * known_price is the sum of the known prices (a lower bound when some
 * lines are unpriced, as price_note says).
 *
 * Encoding: the text is ASCII whenever every name and description is (the
 * shipped catalogue is); otherwise it is UTF-8 with a byte order mark, the
 * signal Excel needs to decode it (without it Excel on Windows reads the
 * bytes as the ANSI code page).  Both open in Excel, LibreOffice and RFC
 * 4180 readers.  Numbers never print as "-0.0"; a non-finite number is an
 * engine bug and leaves its cell empty (counted in *n_invalid).
 */
#ifndef AEROEVAL_BOM_CSV_H
#define AEROEVAL_BOM_CSV_H

#include <stddef.h>

#include "catalog/catalog.h"
#include "result/result.h"

/* What a buyer does with one line. */
enum bom_orderable { BOM_ORDER_YES, BOM_ORDER_CONFIRM, BOM_ORDER_NO };

struct bom_order {
	enum bom_orderable orderable;
	const char *part_number;  /* as ordered: the line's, or the maker's one
	                             part number of a CW/CCW set (borrowed) */
	char note[256];           /* why not or how, "" for a plain part */
	char source[1024];        /* where the catalogue read the facts, "" */
};

/* How line b of r is ordered.  cat (may be NULL) gives the catalogue's
 * doubts about a part number and its source text. */
void bom_csv_order(const struct solve_result *r, const struct res_bom_line *b,
                   const struct catalog *cat, struct bom_order *o);

/* The part number to order for line b (bom_csv_order's, without the
 * catalogue): result.json, the dossier and vehicle_components.json name
 * the part bom.csv names. */
const char *bom_csv_part_number(const struct solve_result *r,
                                const struct res_bom_line *b);

/* Renders bom.csv.  Ownership: the caller frees the text with free().
 * *n_invalid (if not NULL) receives the number of non-finite values that were
 * left as empty cells; the caller must treat > 0 as an internal error. */
char *bom_csv_render_checked(const struct solve_result *r, const struct catalog *cat,
                             int *n_invalid);

/* Same, asserting (debug builds) that every number is finite. */
char *bom_csv_render(const struct solve_result *r, const struct catalog *cat);

/* Renders bom_totals.csv, with *n_invalid as above.  Ownership: free(). */
char *bom_csv_totals(const struct solve_result *r, int *n_invalid);

/* BOM lines whose unit price is unknown (0); 0 when !parts_selected.
 * result.json reports the same count. */
int bom_csv_missing_prices(const struct solve_result *r);

#endif
