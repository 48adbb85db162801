/* json_in.h — the one JSON reader: every JSON input of aeroeval (missions,
 * the parts catalogue, the reference tables in data/, dossier templates)
 * comes in through here.
 *
 * It reads a file through file_read() (regular files only, a size cap per
 * kind of file), parses it once (json_parse.h: a tree of cJSON nodes that
 * know where they stand in the text), and reports through diag_report()
 * in compiler form (file:line:col: error: path: message):
 *   - malformed JSON, text after the value, a top level that is not an
 *     object (the file is then refused: json_in_load() returns NULL);
 *   - what cJSON lets through but strict JSON does not: raw control
 *     characters in strings, numbers such as "012" or "1." (reported when
 *     the file is parsed; the values concerned are then skipped quietly);
 *   - for the loaders, per object and value: repeated keys (with a note at
 *     the first), unknown keys (with the nearest allowed one), keys and
 *     strings spelling \u0000, invalid UTF-8, control characters, text that
 *     starts like a spreadsheet formula, over-long text, infinite numbers,
 *     wrong types.
 * Any value of the tree has a position (json_in_loc), any path "a.b[3]"
 * names a value (json_in_find).
 *
 * Everything is linear in the size of the file: a position is read from
 * its node, repeated keys go through hash tables (util/hash.h), never a
 * scan of what came before.  Only the first JSON_IN_MAX_SHOWN lines of one file are shown;
 * the rest are counted (the exit status and error counts stay right) and
 * json_in_free() closes with one note saying how many were left out.
 *
 * Who may include it: the input layer (the loaders) and the command layer.
 */
#ifndef AEROEVAL_JSON_IN_H
#define AEROEVAL_JSON_IN_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>

#include <cjson/cJSON.h>

#include "diag/diag.h"

/* The size cap of each kind of file (bytes).  A catalogue file may be
 * large: a company list of 10^5 parts with their sources. */
#define JSON_IN_MISSION_MAX  ((size_t)4 << 20)
#define JSON_IN_CATALOG_MAX  ((size_t)256 << 20)
#define JSON_IN_DATA_MAX     ((size_t)4 << 20)
#define JSON_IN_TEMPLATE_MAX ((size_t)1 << 20)

/* Lines shown per file; the rest are counted. */
#define JSON_IN_MAX_SHOWN 50

struct json_in;

/* Read the regular file at path (at most max_bytes) into *out (NUL added
 * after the *n bytes; free() it).  A missing, unreadable or too large file,
 * a directory, FIFO or device is one DIAG_IO error "path: error: cannot
 * read file: reason"; returns -1 then, 0 on success. */
int json_in_read(const char *path, size_t max_bytes, struct diag *dg,
                 unsigned char **out, size_t *n);

/* json_in_read() then json_in_parse().  NULL after reporting when the file
 * cannot be read or parsed or its top level is not an object. */
struct json_in *json_in_load(const char *path, size_t max_bytes,
                             struct diag *dg);

/* Parse buf[0..len) (need not be NUL-terminated; an embedded NUL is not
 * the end; it is copied) named file in messages.  NULL after reporting as above.
 * Ownership: json_in_free(); file and dg must outlive the result. */
struct json_in *json_in_parse(const char *file, const char *buf, size_t len,
                              struct diag *dg);

/* Frees ji (NULL is a no-op), after the note about errors not shown. */
void json_in_free(struct json_in *ji);

/* The root object (never NULL), the file name, and the errors reported
 * through ji so far, shown or not. */
const cJSON *json_in_root(const struct json_in *ji);
const char *json_in_file(const struct json_in *ji);

/* The bytes read, exactly as they were (len of them, a NUL after): what a
 * fingerprint of the file must hash.  They live as long as ji. */
const char *json_in_text(const struct json_in *ji, size_t *len);
int json_in_n_errors(const struct json_in *ji);

/* Hash-table probes spent on repeated keys so far: tests bound the
 * reader's work by counting them (util/hash.h). */
size_t json_in_probes(const struct json_in *ji);

/* json_in_read() of a file that item (at jpath) of ji names, a font in a
 * template say: a failure is an error at item, "FILE:line:col: error:
 * jpath: cannot read file: path: reason". */
int json_in_read_named(struct json_in *ji, const cJSON *item, const char *jpath,
                       const char *path, size_t max_bytes, unsigned char **out,
                       size_t *n);

/* ---- positions ----------------------------------------------------------- */

enum json_in_at {
	JSON_IN_VALUE,  /* the value's first character */
	JSON_IN_KEY,    /* the member's key (the value for array elements) */
	JSON_IN_FILE    /* no position: the whole file */
};

/* Where item (a node of this tree) stands; line 0 when unknown. */
struct diag_loc json_in_loc(struct json_in *ji, const cJSON *item,
                            enum json_in_at at);

/* The value at path ("motors[12].mass_g", "" for the root), or NULL.  A
 * repeated key names its first occurrence. */
const cJSON *json_in_find(const struct json_in *ji, const char *path);

/* The source text of item's value, cut to n - 1 bytes, into buf. */
void json_in_source(struct json_in *ji, const cJSON *item, char *buf, size_t n);

/* ---- reporting ----------------------------------------------------------- */

/* True while a new error would still be shown: callers skip the work of a
 * detail (a "did you mean" search) that nobody would read. */
bool json_in_showing(const struct json_in *ji);

/* Report a diagnostic about item (NULL or JSON_IN_FILE: the whole file) at
 * path (may be NULL), through the cap: an error is shown while fewer than
 * JSON_IN_MAX_SHOWN lines were, else counted; a note is shown only after a
 * shown error. */
void json_in_report(struct json_in *ji, enum diag_kind kind, const cJSON *item,
                    enum json_in_at at, const char *path, const char *fmt, ...)
	__attribute__((format(printf, 6, 7)));

/* The same with a va_list (consumed), for a loader's own wrapper. */
void json_in_vreport(struct json_in *ji, enum diag_kind kind, const cJSON *item,
                     enum json_in_at at, const char *path, const char *fmt, va_list ap)
	__attribute__((format(printf, 6, 0)));

/* Paths: "parent.key" ("key" when parent is ""), "parent[i]". */
void json_in_path(char *buf, size_t n, const char *parent, const char *key);
void json_in_path_index(char *buf, size_t n, const char *parent, size_t i);

/* "a number", "a string", "an object", ... "null", for "got ..." texts. */
const char *json_in_type_name(const cJSON *item);

/* ---- members ------------------------------------------------------------- */

/* True when item, a member of object obj at path, may be read: false after
 * reporting when it repeats an earlier key of obj (error at it, note at the
 * first, which is the one that counts) or its key spells \u0000; false
 * quietly when a problem reported at parse time lies in it. */
bool json_in_member(struct json_in *ji, const cJSON *obj, const cJSON *item,
                    const char *path);

/* Key-list flags. */
#define JSON_IN_COMMENTS 0x1u   /* keys starting with '_' are comments */

/* The index of key in list[0..n), or n when it is not there.  The search
 * starts at *guess and wraps round; a hit leaves *guess just past it, so
 * keys met in the list's own order (as in a catalogue entry) cost one
 * comparison each. */
size_t json_in_key_index(const char *key, const char *const *list, size_t n,
                         size_t *guess);

/* json_in_member() for every member of obj (at path), and an error for each
 * key not in the NULL-terminated list allowed, with the nearest allowed key
 * as a suggestion.  Returns the number of errors it reported. */
int json_in_check_keys(struct json_in *ji, const cJSON *obj, const char *path,
                       const char *const *allowed, unsigned flags);

/* ---- values -------------------------------------------------------------- */

/* True when item has one of the cJSON types in mask (cJSON_Number, ...),
 * else a DIAG_TYPE error "expected <expected>, got <type>" and false. */
bool json_in_expect(struct json_in *ji, const cJSON *item, const char *path,
                    int mask, const char *expected);

/* String flags. */
#define JSON_IN_NO_CONTROL 0x2u /* no control character, escaped or not */
#define JSON_IN_NO_FORMULA 0x4u /* no leading = + - @ (CSV formula injection) */

/* The string item (a cJSON string) holds no \u0000 and valid UTF-8, at
 * most max_bytes bytes, and obeys flags; else false after an error. */
bool json_in_check_string(struct json_in *ji, const cJSON *item,
                          const char *path, size_t max_bytes, unsigned flags);

/* The number item (a cJSON number) is finite (1e400 is not); else false
 * after an error.  False quietly for a number reported at parse time. */
bool json_in_check_number(struct json_in *ji, const cJSON *item,
                          const char *path);

#endif /* AEROEVAL_JSON_IN_H */
