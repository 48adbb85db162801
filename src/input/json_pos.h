/* json_pos.h — source positions for JSON text: path -> line:col index.
 *
 * cJSON keeps no source positions (STACK.md §7), so this is a small scanner
 * of our own over the same buffer.  It records, for every object member and
 * array element, the position of its key and of its value under a path:
 * "locks.locked_kv", "a[3]", "" for the root value.  Duplicate keys get one
 * entry each, in document order (find them with nth).
 *
 * Columns count characters, not bytes: UTF-8 continuation bytes do not
 * advance the column.  Lines and columns are 1-based.
 *
 * Who may include it: the input layer (mission_io, catalogue loaders).
 */
#ifndef AEROEVAL_JSON_POS_H
#define AEROEVAL_JSON_POS_H

#include <stddef.h>

struct json_pos_entry {
	char *path;        /* "payload_role.type", "a[3]", "" for the root */
	int key_line;      /* position of the key's opening quote; 0 for */
	int key_col;       /*   array elements and the root              */
	int val_line;      /* position of the value's first character */
	int val_col;
	size_t val_off;    /* byte offset of the value in the buffer */
	size_t val_end;    /* byte offset just past the value */
};

struct json_pos;

/* Scan buf[0..len) (need not be NUL-terminated) and index it.  Meant for
 * text that cJSON accepted; on malformed text it indexes what it could read
 * before the error and stops.  A leading UTF-8 byte-order mark is skipped,
 * as cJSON does.  Ownership: free with json_pos_free(). */
struct json_pos *json_pos_alloc(const char *buf, size_t len);
void json_pos_free(struct json_pos *jp);   /* NULL is a no-op */

/* The nth (0-based) entry with exactly this path, or NULL. */
const struct json_pos_entry *json_pos_find(const struct json_pos *jp,
                                           const char *path, int nth);

/* Number of entries, and entry i in document order. */
size_t json_pos_count(const struct json_pos *jp);
const struct json_pos_entry *json_pos_entry_at(const struct json_pos *jp,
                                               size_t i);

#endif /* AEROEVAL_JSON_POS_H */
