/* catalog_snap.h — the shipped catalogue, loaded and checked once at build
 * time and kept as a snapshot inside the program.
 *
 * Reading 1.4 MiB of catalogue JSON, checking every field and hashing every
 * byte costs about 270 M instructions, 70 % of a whole `aeroeval solve`.
 * `make` therefore loads data/catalog once with catalog_io_load(), hashes it,
 * and writes what it loaded as a flat snapshot (the entry structs with
 * their text pointers turned into offsets, then the text) that the program
 * carries in its read-only data.  At start-up the snapshot is used only
 * when every file it was made from is still the regular file of the same
 * size and modification time (the test make and git use); otherwise the
 * JSON is read as before.  Either way the catalogue, and so every output,
 * is the same: the snapshot holds the structs catalog_io_load() filled.
 *
 * A snapshot is valid only for the program it was built with (the struct
 * layout is copied as is); its header records the entry sizes as a guard.
 *
 * Who may include it: the command layer (and tests).
 */
#ifndef AEROEVAL_CATALOG_SNAP_H
#define AEROEVAL_CATALOG_SNAP_H

#include <stddef.h>
#include <stdio.h>

#include "core/catalog.h"

/* Writes the snapshot of c, loaded from DATA_DIR/catalog with the
 * chemistries of DATA_DIR/chemistries.json, whose catalogue SHA-256 (hex)
 * is sha256_hex, to out.  Returns 0, or -1 when a file it depends on cannot
 * be stat()ed or the write fails (err then says why). */
int catalog_snap_write(const struct catalog *c, const char *sha256_hex,
                       const char *data_dir, FILE *out, char *err, size_t errlen);

/* The catalogue held by the n bytes at blob, when the snapshot is intact
 * and every file under data_dir it was made from is unchanged; its SHA-256
 * is copied into sha256_hex.  NULL otherwise: read the JSON instead.  Free
 * with catalog_free(); its text points into blob, which must outlive it. */
struct catalog *catalog_snap_read(const unsigned char *blob, size_t n,
                                  const char *data_dir, char sha256_hex[65]);

/* The bytes before the first entry (for tests that damage a snapshot). */
size_t catalog_snap_header_bytes(void);

#endif
