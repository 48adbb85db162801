/* jsonw.h — the one JSON writer: every JSON file aeroeval writes
 * (result.json, index.json, vehicle_components.json, calibration.json,
 * the schema, validate --json, the sensitivity table, the missions
 * validate writes) is text from here.
 *
 * The text is deterministic: members in the order written, 2-space
 * indentation, LF line ends, one final newline.  Numbers print as the
 * shortest of %.15g/%.16g/%.17g that strtod() reads back to the same
 * double (numfmt.h), so a reader recovers every value exactly; cJSON's own
 * printer rounds (it prints 0.1 + 0.2 as 0.3 and 2^53 off by two).
 * Strings are escaped per RFC 8259; valid UTF-8 passes through, an invalid
 * byte becomes U+FFFD.  NaN and Infinity never appear: a non-finite number
 * is written as null and counted as a fault, with the JSON path of the
 * first one, so a caller can refuse to publish the text.
 *
 * Two ways in: a writer that streams values (jsonw_object(), jsonw_number(),
 * ..., jsonw_finish()), and jsonw_print() of a cJSON tree a caller built,
 * whose numbers get the same exact printing.
 *
 * Who may include it: every layer but physics.
 */
#ifndef AEROEVAL_JSONW_H
#define AEROEVAL_JSONW_H

#include <stdbool.h>
#include <stddef.h>

#include <cjson/cJSON.h>

#define JSONW_MAX_DEPTH 32   /* nested objects and arrays */
#define JSONW_PATH_MAX 160   /* bytes of a fault's path */

/* What the writer found wrong in what it was given. */
struct jsonw_faults {
	int n_invalid;                    /* values written as null for being
	                                     non-finite or out of range */
	char first_path[JSONW_PATH_MAX];  /* JSON path of the first, e.g.
	                                     "custom.phases[2].power_w"; "" if none */
};

/* One open object or array (the writer's own). */
struct jsonw_frame {
	bool array;          /* array (else object) */
	bool packed;         /* scalars written JSONW_PACK to a line */
	int n;               /* members written so far */
	size_t path_len;     /* length of the path before this container's step */
};

/* A writer: a plain value (jsonw_init()); its fields are its own. */
struct jsonw {
	char *buf;                        /* the text, NUL-terminated */
	size_t len, cap;
	int depth;                        /* open containers */
	struct jsonw_frame st[JSONW_MAX_DEPTH];
	char path[JSONW_PATH_MAX];        /* ".custom.phases[2]" of the open container */
	size_t path_len;
	struct jsonw_faults faults;
};

/* Scalars per line in a packed array. */
#define JSONW_PACK 10

/* Starts an empty text. */
void jsonw_init(struct jsonw *w);

/* In every call below, key names the member inside an object and must be
 * NULL inside an array and for the top-level value. */

/* Opens an object or an array; jsonw_end() closes the innermost.  A packed
 * array holds plain numbers or strings, JSONW_PACK to a line. */
void jsonw_object(struct jsonw *w, const char *key);
void jsonw_array(struct jsonw *w, const char *key);
void jsonw_array_packed(struct jsonw *w, const char *key);
void jsonw_end(struct jsonw *w);

/* A string: s (NULL writes ""), or at most max bytes of s stopping at a
 * NUL (for a char array that might lack one). */
void jsonw_string(struct jsonw *w, const char *key, const char *s);
void jsonw_string_n(struct jsonw *w, const char *key, const char *s, size_t max);

/* A number (exactly; non-finite: null and a fault), an integer, a boolean,
 * null. */
void jsonw_number(struct jsonw *w, const char *key, double x);
void jsonw_int(struct jsonw *w, const char *key, long long v);
void jsonw_bool(struct jsonw *w, const char *key, bool b);
void jsonw_null(struct jsonw *w, const char *key);

/* The cJSON value item (a tree) at key.  A cJSON_Raw or invalid node is
 * a fault, written as null. */
void jsonw_tree(struct jsonw *w, const char *key, const cJSON *item);

/* Records a fault of the caller's own (an enum or count out of range) at
 * key of the open object, or at the array element last begun; writes
 * nothing. */
void jsonw_fault(struct jsonw *w, const char *key);

/* Ends the text with its newline and returns it; faults (may be NULL)
 * receives what was found wrong.  Every container must be closed.
 * Ownership: the caller frees the text with free(); w is spent. */
char *jsonw_finish(struct jsonw *w, struct jsonw_faults *faults);

/* jsonw_tree() of root as a whole file, then jsonw_finish().  Never NULL
 * (allocation failure exits, xalloc.h).  Ownership: free(). */
char *jsonw_print(const cJSON *root, struct jsonw_faults *faults);

#endif
