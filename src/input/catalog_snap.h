/* catalog_snap.h — the shipped catalogue, loaded and checked once at build
 * time and carried inside the program, used only for the very bytes it was
 * made from.
 *
 * Reading 1.5 MiB of catalogue JSON, checking every field and hashing every
 * byte is most of a one-shot `aeroeval solve`.  `make` therefore runs
 * catsnap (src/tools/catsnap.c), which loads data/catalog with
 * catalog_io_load() and writes a snapshot: the bytes of every catalogue
 * file it read, the chemistry names the batteries were checked against,
 * the catalogue's SHA-256, then the entry structs it filled (text pointers
 * turned into offsets) and their text.  The program carries the snapshot in
 * its read-only data.
 *
 * At start-up the catalogue files are read as always and compared, byte for
 * byte, with the bytes the snapshot holds; the snapshot is used only when
 * every file (and the absence of an absent optional one) and the chemistry
 * list are identical.  catalog_io_load() is a function of exactly those
 * inputs, so the snapshot then holds what it would return, and its
 * SHA-256 is the hash of what was read.  Any difference, however small and
 * whatever the files' times say, and the JSON is parsed instead.  No file
 * time or size is trusted; the snapshot records none, so two builds of one
 * commit carry the same bytes.
 *
 * A snapshot is valid only for the program it was built with (the entry
 * structs are copied as they are); its header records their sizes as a
 * guard.
 *
 * Who may include it: the command layer, the catsnap tool and tests.
 */
#ifndef AEROEVAL_CATALOG_SNAP_H
#define AEROEVAL_CATALOG_SNAP_H

#include <stddef.h>
#include <stdio.h>

#include "catalog/catalog.h"
#include "diag/diag.h"

/* Loads the catalogue folder dir with catalog_io_load() (every problem
 * reported into dg) and writes its snapshot to out.  Returns 0, or -1 when
 * the catalogue does not load, a file cannot be read again or the write
 * fails (err then says why, unless dg already did). */
int catalog_snap_write(const char *dir, const char *const *known_chemistries,
                       struct diag *dg, FILE *out, char *err, size_t errlen);

/* The catalogue of folder dir when the n-byte snapshot at blob is intact
 * and was made from exactly the bytes dir's files hold now and the same
 * chemistry list (NULL: catalog_default_chemistries); its SHA-256 (hex) is
 * copied into sha256_hex.  NULL otherwise, reporting nothing: read the JSON
 * then.  Free with catalog_free(); its text points into blob, which must
 * outlive it. */
struct catalog *catalog_snap_read(const unsigned char *blob, size_t n,
                                  const char *dir,
                                  const char *const *known_chemistries,
                                  char sha256_hex[65]);

#endif
