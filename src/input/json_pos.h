/* json_pos.h — source positions and lexical checks for JSON text.
 *
 * cJSON keeps no source positions (STACK.md §7), so this is a small scanner
 * of our own over the same buffer.  It records one entry per JSON value in
 * document order (pre-order: the root, then each member or element before
 * the values inside it), which is exactly the order of a depth-first walk of
 * the tree cJSON builds from the same text: entry i belongs to the i-th node
 * of that walk (json_in pairs them).  An entry is small and holds no path,
 * so the index stays linear in the size of the file.
 *
 * While it scans, it also notes what cJSON lets through but strict JSON does
 * not: raw control characters inside strings and numbers such as "012" or
 * "1." (both "problems", with their position), and keys or strings that
 * spell the escape \u0000, at which cJSON's C strings silently end.
 *
 * Columns count characters, not bytes: UTF-8 continuation bytes do not
 * advance the column.  Lines and columns are 1-based.
 *
 * Who may include it: the input layer (json_in).
 */
#ifndef AEROEVAL_JSON_POS_H
#define AEROEVAL_JSON_POS_H

#include <stddef.h>
#include <stdint.h>

/* Entry flags. */
#define JSON_POS_KEY_NUL 0x1u    /* the member's key spells \u0000 */
#define JSON_POS_VAL_NUL 0x2u    /* the string value spells \u0000 */
#define JSON_POS_BAD     0x4u    /* a problem (below) lies in key or value */

struct json_pos_entry {
	int key_line;      /* position of the key's opening quote; 0 for */
	int key_col;       /*   array elements and the root              */
	int val_line;      /* position of the value's first character */
	int val_col;
	uint32_t val_off;  /* byte offset of the value in the buffer */
	uint32_t val_end;  /* byte offset just past the value */
	uint8_t flags;     /* JSON_POS_* */
};

/* A lexical problem strict JSON rejects and cJSON accepts. */
enum json_pos_problem_kind {
	JSON_POS_CONTROL,  /* a raw control character inside a string */
	JSON_POS_NUMBER    /* a number not spelled as JSON spells one */
};

struct json_pos_problem {
	enum json_pos_problem_kind kind;
	size_t entry;      /* the entry whose key or value holds it */
	int line, col;     /* CONTROL: the character; NUMBER: the number */
	unsigned char byte; /* CONTROL: the character */
};

struct json_pos;

/* Scan buf[0..len) (need not be NUL-terminated) and index it.  Meant for
 * text that cJSON accepted; on malformed text it indexes what it could read
 * before the error and stops (json_pos_complete() is then false).  A
 * leading UTF-8 byte-order mark is skipped, as cJSON does.  Text of 4 GiB
 * or more is not indexed.  Ownership: free with json_pos_free(). */
struct json_pos *json_pos_alloc(const char *buf, size_t len);
void json_pos_free(struct json_pos *jp);   /* NULL is a no-op */

/* Number of entries, and entry i in document order (NULL past the end). */
size_t json_pos_count(const struct json_pos *jp);
const struct json_pos_entry *json_pos_entry_at(const struct json_pos *jp,
                                               size_t i);

/* True when the whole first value was scanned without a malformed spot. */
int json_pos_complete(const struct json_pos *jp);

/* The lexical problems, in document order (at most one per string or
 * number), and the OR of every entry's flags. */
size_t json_pos_n_problems(const struct json_pos *jp);
const struct json_pos_problem *json_pos_problem_at(const struct json_pos *jp,
                                                   size_t i);
unsigned json_pos_all_flags(const struct json_pos *jp);

#endif /* AEROEVAL_JSON_POS_H */
