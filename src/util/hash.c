/* hash.c — open-addressing hash tables (see hash.h).
 *
 * Linear probing over a power-of-two array of slots, grown to twice its
 * size when half full, so a probe sequence stays short.  Nothing is ever
 * removed, which keeps probing free of tombstones.
 */
#include "util/hash.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "util/xalloc.h"

struct slot {
	const void *key;  /* NULL: empty slot */
	size_t val;
};

/* The shared table; the two public types differ only in how keys hash and
 * compare. */
struct table {
	struct slot *v;   /* cap slots */
	size_t cap;       /* a power of two */
	size_t n;         /* keys held */
	size_t probes;    /* slots looked at, ever (tests bound the work) */
	bool by_string;   /* keys are C strings (else pointer values) */
};

struct strmap { struct table t; };
struct ptrmap { struct table t; };

size_t
hash_fnv1a(const char *s)
{
	uint64_t h = 14695981039346656037u;
	for (; *s != '\0'; s++) {
		h ^= (unsigned char)*s;
		h *= 1099511628211u;
	}
	return (size_t)h;
}

/* A pointer's bits mixed (allocations share their low and high bits). */
static size_t
hash_ptr(const void *p)
{
	uint64_t x = (uint64_t)(uintptr_t)p;
	x ^= x >> 33;
	x *= 0xff51afd7ed558ccdu;
	x ^= x >> 33;
	return (size_t)x;
}

static size_t
table_hash(const struct table *t, const void *key)
{
	return t->by_string ? hash_fnv1a(key) : hash_ptr(key);
}

static bool
table_same(const struct table *t, const void *a, const void *b)
{
	return t->by_string ? strcmp(a, b) == 0 : a == b;
}

static void
table_init(struct table *t, size_t expected, bool by_string)
{
	t->cap = 16;
	while (t->cap < 2 * expected + 2)
		t->cap *= 2;
	t->v = xcalloc(t->cap, sizeof *t->v);
	t->n = 0;
	t->probes = 0;
	t->by_string = by_string;
}

/* The slot holding key, or the empty slot where it would go. */
static struct slot *
table_find(struct table *t, const void *key)
{
	size_t mask = t->cap - 1, i = table_hash(t, key) & mask;
	t->probes++;
	while (t->v[i].key != NULL && !table_same(t, t->v[i].key, key)) {
		i = (i + 1) & mask;
		t->probes++;
	}
	return &t->v[i];
}

static void
table_grow(struct table *t)
{
	struct slot *old = t->v;
	size_t old_cap = t->cap;
	t->cap *= 2;
	t->v = xcalloc(t->cap, sizeof *t->v);
	for (size_t i = 0; i < old_cap; i++)
		if (old[i].key != NULL)
			*table_find(t, old[i].key) = old[i];
	free(old);
}

static bool
table_put(struct table *t, const void *key, size_t val, size_t *old)
{
	struct slot *s = table_find(t, key);
	if (s->key != NULL) {
		if (old != NULL)
			*old = s->val;
		return false;
	}
	s->key = key;
	s->val = val;
	if (++t->n * 2 > t->cap)
		table_grow(t);
	return true;
}

static bool
table_get(struct table *t, const void *key, size_t *val)
{
	const struct slot *s = table_find(t, key);
	if (s->key == NULL)
		return false;
	if (val != NULL)
		*val = s->val;
	return true;
}

struct strmap *
strmap_alloc(size_t expected)
{
	struct strmap *m = xmalloc(sizeof *m);
	table_init(&m->t, expected, true);
	return m;
}

void
strmap_free(struct strmap *m)
{
	if (m == NULL)
		return;
	free(m->t.v);
	free(m);
}

bool
strmap_put(struct strmap *m, const char *key, size_t val, size_t *old)
{
	return table_put(&m->t, key, val, old);
}

bool
strmap_get(struct strmap *m, const char *key, size_t *val)
{
	return table_get(&m->t, key, val);
}

size_t
strmap_count(const struct strmap *m)
{
	return m->t.n;
}

struct ptrmap *
ptrmap_alloc(size_t expected)
{
	struct ptrmap *m = xmalloc(sizeof *m);
	table_init(&m->t, expected, false);
	return m;
}

void
ptrmap_free(struct ptrmap *m)
{
	if (m == NULL)
		return;
	free(m->t.v);
	free(m);
}

bool
ptrmap_put(struct ptrmap *m, const void *key, size_t val, size_t *old)
{
	return table_put(&m->t, key, val, old);
}

bool
ptrmap_get(struct ptrmap *m, const void *key, size_t *val)
{
	return table_get(&m->t, key, val);
}

size_t
strmap_probes(const struct strmap *m)
{
	return m->t.probes;
}

size_t
ptrmap_probes(const struct ptrmap *m)
{
	return m->t.probes;
}
