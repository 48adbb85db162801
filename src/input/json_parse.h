/* json_parse.h — the JSON parser under json_in: one pass over the text
 * builds the cJSON tree the loaders walk and records, in each node, where
 * its key and value stand.
 *
 * cJSON's own parser keeps no source positions, so every reader used to
 * parse each file twice: cJSON for the tree, then a scanner for the
 * positions.  This parser builds ordinary cJSON nodes (walk them with the
 * cJSON_* accessors) inside a struct json_node that also holds the node's
 * line and column, so a diagnostic finds its position in O(1):
 * json_node_of(item).  The nodes and their strings live in blocks the
 * document owns; never cJSON_Delete() them, free the document.
 *
 * The syntax is JSON's (RFC 8259), at most JSON_PARSE_MAX_DEPTH nested
 * arrays and objects, a leading UTF-8 byte-order mark skipped.  Two things
 * strict JSON rejects are let through, so that the reader can report them
 * with their position and go on to report the rest of the file: raw
 * control characters inside strings, and numbers that C's strtod() reads
 * but JSON does not spell so ("012", "1.", "-.5").  Each is a "problem"
 * (json_doc_problem_at()) and marks its node JSON_PARSE_BAD.  Keys and
 * strings that spell \u0000 end there as C strings; their node is flagged.
 * Invalid UTF-8 is kept as it is (the reader checks each string it uses).
 *
 * Numbers are read exactly: the nearest double, as strtod() gives.
 * Lines and columns are 1-based; columns count characters, not bytes.
 *
 * Who may include it: the input layer's JSON reader (json_in.c) and its
 * tests.
 */
#ifndef AEROEVAL_JSON_PARSE_H
#define AEROEVAL_JSON_PARSE_H

#include <stddef.h>
#include <stdint.h>

#include <cjson/cJSON.h>

/* Nesting limit; the same as cJSON's CJSON_NESTING_LIMIT. */
#define JSON_PARSE_MAX_DEPTH 1000

/* Node flags. */
#define JSON_PARSE_KEY_NUL 0x1u   /* the member's key spells \u0000 */
#define JSON_PARSE_VAL_NUL 0x2u   /* the string value spells \u0000 */
#define JSON_PARSE_BAD     0x4u   /* a problem (below) lies in key or value */

/* One value of the document.  `item` comes first, so a `const cJSON *`
 * of the tree converts back to its node (json_node_of()). */
struct json_node {
	cJSON item;         /* the value as cJSON represents it */
	int key_line;       /* the key's opening quote; 0 for array */
	int key_col;        /*   elements and the root               */
	int val_line;       /* the value's first character */
	int val_col;
	uint32_t val_off;   /* byte offset of the value in the text */
	uint32_t val_end;   /* byte offset just past the value */
	unsigned char flags; /* JSON_PARSE_* */
};

/* A lexical problem the parser let through (see above). */
enum json_problem_kind {
	JSON_PROBLEM_CONTROL,  /* a raw control character inside a string */
	JSON_PROBLEM_NUMBER    /* a number not spelled as JSON spells one */
};

struct json_problem {
	enum json_problem_kind kind;
	const struct json_node *node;  /* whose key or value holds it */
	int line, col;      /* CONTROL: the character; NUMBER: the number */
	unsigned char byte; /* CONTROL: the character */
};

struct json_doc;

/* Parses text[0..len) (need not be NUL-terminated; an embedded NUL is
 * not the end).  The first value is parsed; what follows it is left to the
 * caller (json_doc_end()).  Returns NULL when the text is not JSON, with
 * *err_off the offset where reading stopped (len: at the end); text of
 * 4 GiB or more is refused at offset 0.  Ownership: json_doc_free(); the
 * text need not outlive the document. */
struct json_doc *json_parse(const char *text, size_t len, size_t *err_off);

/* Frees the document and every node and string of it (NULL: no-op). */
void json_doc_free(struct json_doc *d);

/* The first value (never NULL) and the offset just past it. */
const cJSON *json_doc_root(const struct json_doc *d);
size_t json_doc_end(const struct json_doc *d);

/* The problems, in document order. */
size_t json_doc_n_problems(const struct json_doc *d);
const struct json_problem *json_doc_problem_at(const struct json_doc *d, size_t i);

/* The node of item, a value of a document from json_parse(). */
static inline const struct json_node *
json_node_of(const cJSON *item)
{
	return (const struct json_node *)(const void *)item;
}

#endif /* AEROEVAL_JSON_PARSE_H */
