/* hash.h — two small open-addressing hash tables with size_t values: one
 * keyed by C strings, one keyed by pointers.
 *
 * They exist so that every reader stays linear in the size of its input:
 * duplicate keys of a JSON object, duplicate catalogue ids, the position of
 * a parsed JSON value and catalogue look-ups by id are one probe each
 * instead of a scan over everything seen before.
 *
 * Keys are not copied: a string key must stay alive and unchanged as long
 * as the table holds it.  The tables grow by themselves (load <= 1/2).
 * Who may include it: everyone.
 */
#ifndef AEROEVAL_HASH_H
#define AEROEVAL_HASH_H

#include <stdbool.h>
#include <stddef.h>

struct strmap;
struct ptrmap;

/* A table sized for about `expected` keys (0 is fine).  Ownership: free
 * with strmap_free() / ptrmap_free(); NULL is a no-op there. */
struct strmap *strmap_alloc(size_t expected);
void strmap_free(struct strmap *m);

/* Adds key -> val unless key is already there.  Returns true when added;
 * false when present, with its value in *old (old may be NULL). */
bool strmap_put(struct strmap *m, const char *key, size_t val, size_t *old);

/* True with *val set (val may be NULL) when key is in the table.  (Not
 * const: a look-up counts its probes.) */
bool strmap_get(struct strmap *m, const char *key, size_t *val);

/* Keys held. */
size_t strmap_count(const struct strmap *m);

struct ptrmap *ptrmap_alloc(size_t expected);
void ptrmap_free(struct ptrmap *m);

/* As strmap_put / strmap_get, keyed by the pointer value (never NULL). */
bool ptrmap_put(struct ptrmap *m, const void *key, size_t val, size_t *old);
bool ptrmap_get(struct ptrmap *m, const void *key, size_t *val);

/* Slots looked at by every put and get so far: a probe sequence is short
 * (about 1.5 slots at the fill the tables keep), so tests can bound the
 * work a reader does by counting rather than timing. */
size_t strmap_probes(const struct strmap *m);
size_t ptrmap_probes(const struct ptrmap *m);

/* FNV-1a over the bytes of s, for callers that hash their own keys. */
size_t hash_fnv1a(const char *s);

#endif
