/* catalog_io.h — read and validate a parts-catalogue directory (format
 * version 2, data/catalog/README.md) into a struct catalog (catalog/catalog.h).
 *
 *     DIR/motors.json      {"motors":     [ {...}, ... ]}   required
 *     DIR/propellers.json  {"propellers": [ ... ]}          required
 *     DIR/batteries.json   {"batteries":  [ ... ]}          required
 *     DIR/escs.json        {"escs":       [ ... ]}          required
 *     DIR/frames.json      {"frames":     [ ... ]}          optional
 *     DIR/avionics.json    {"avionics":   [ ... ]}          optional
 *
 * Every key of a category is present in every entry (null = "not published
 * / not found").  Each file is read through json_in, so every problem is a
 * diagnostic with file:line:col and the JSON path, e.g.
 *     data/catalog/motors.json:240:17: error: motors[12].mass_g: out of range: -3 (allowed above 0 g)
 * checked: types, numbers > 0 where physical, whole counts, known
 * spellings (chemistry, material, max_current_basis, kind, frame_class),
 * text (valid UTF-8, no control character, no NUL, no leading = + - @),
 * cells_min <= cells_max, burst >= continuous, ct/cp both or neither,
 * price_date iff price_usd, ids unique across every file (a hash set).
 *
 * Who may include it: the command layer (and tests).
 */
#ifndef AEROEVAL_CATALOG_IO_H
#define AEROEVAL_CATALOG_IO_H

#include <stdbool.h>

#include "catalog/catalog.h"
#include "diag/diag.h"

/* The file of each category in a catalogue directory, in load order. */
extern const char *const catalog_io_files[CATALOG_N_CATEGORIES];

/* True when the category's file must exist (false: absent = no entries). */
bool catalog_io_required(enum catalog_category k);

/* The path of category k's file in folder dir (a trailing '/' is fine);
 * free() it. */
char *catalog_io_path(const char *dir, enum catalog_category k);

/* True when path, category k's file, is optional and simply not there. */
bool catalog_io_absent(const char *path, enum catalog_category k);

/* The offsets of category k's text fields (every `const char *` of its
 * entry struct), written into offsets (room for max); returns how many.
 * The snapshot (input/catalog_snap.h) stores these as text offsets. */
size_t catalog_io_text_fields(enum catalog_category k, size_t *offsets, size_t max);

/* The catalogue fingerprint (see catalog_io_load()) of the files whose
 * bytes are text[k] (len[k] of them; NULL: absent), as 64 hex digits and a
 * NUL into hex. */
void catalog_io_fingerprint(const char *const text[CATALOG_N_CATEGORIES],
                            const size_t len[CATALOG_N_CATEGORIES], char *hex);

/* Loads the catalogue directory dir (a trailing '/' is fine).
 * known_chemistries is the NULL-terminated list of accepted battery
 * chemistries; NULL means catalog_default_chemistries.  Every problem of
 * every file is reported into dg (exit status 2).  Returns NULL if there
 * was any error, else a catalogue the caller frees with catalog_free().
 *
 * When sha256_hex is not NULL it receives the catalogue's fingerprint
 * (result.json's catalogue_sha256): the SHA-256, as 64 hex digits, of
 * each file read in the order of catalog_io_files (its name, a NUL, its
 * length as 8 bytes little-endian, its bytes), an absent optional file
 * adding nothing.  It hashes the very bytes parsed, so it names exactly
 * the catalogue that was used. */
struct catalog *catalog_io_load(const char *dir, const char *const *known_chemistries,
                                struct diag *dg, char *sha256_hex);

#endif
