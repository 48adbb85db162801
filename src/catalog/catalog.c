/* catalog.c — the loaded parts catalogue: storage, id index, accessors
 * (see catalog.h).  The files are read by input/catalog_io.c. */
#include "catalog/catalog.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/hash.h"
#include "util/xalloc.h"

const char *const catalog_default_chemistries[] = {
	"LiPo", "LiHV", "Li-ion NCA", "Li-ion NMC", "Solid State", "Li-S",
	"LiPo_standard", "LiPo_highvoltage", "LiPo_premium", "LiPo_consumer",
	"LiPo_enterprise", "LiPo_agricultural", NULL,
};

/* Text lives in blocks that never move, so entries can point into them. */
#define CATALOG_BLOCK 65536

struct text_block {
	struct text_block *next;
	size_t used, cap;
	char data[];
};

struct catalog {
	void *items[CATALOG_N_CATEGORIES];     /* arrays of the entry structs */
	size_t n[CATALOG_N_CATEGORIES];
	struct strmap *by_id[CATALOG_N_CATEGORIES]; /* id -> index */
	size_t *prop_order;                    /* propeller indices by diameter */
	struct text_block *text;               /* interned strings, newest first */
};

static const size_t entry_size[CATALOG_N_CATEGORIES] = {
	sizeof(struct catalog_motor), sizeof(struct catalog_prop),
	sizeof(struct catalog_battery), sizeof(struct catalog_esc),
	sizeof(struct catalog_frame), sizeof(struct catalog_avionics),
};

/* Every entry struct starts with CATALOG_COMMON_FIELDS, so the id is read
 * the same way in each. */
struct catalog_common { CATALOG_COMMON_FIELDS; };

size_t
catalog_entry_size(enum catalog_category k)
{
	return entry_size[k];
}

struct catalog *
catalog_alloc(void)
{
	return xcalloc(1, sizeof(struct catalog));
}

const char *
catalog_intern(struct catalog *c, const char *s)
{
	size_t n = strlen(s) + 1;
	struct text_block *b = c->text;
	if (n == 1)
		return "";
	if (b == NULL || b->cap - b->used < n) {
		size_t cap = n > CATALOG_BLOCK ? n : CATALOG_BLOCK;
		b = xmalloc(sizeof *b + cap);
		b->next = c->text;
		b->used = 0;
		b->cap = cap;
		c->text = b;
	}
	char *p = b->data + b->used;
	memcpy(p, s, n);
	b->used += n;
	return p;
}

void
catalog_adopt(struct catalog *c, enum catalog_category k, void *items, size_t n)
{
	free(c->items[k]);
	c->items[k] = items;
	c->n[k] = n;
}

static const void *
item_at(const struct catalog *c, enum catalog_category k, size_t i)
{
	if (c == NULL || i >= c->n[k])
		return NULL;
	return (const char *)c->items[k] + i * entry_size[k];
}

size_t
catalog_count(const struct catalog *c, enum catalog_category k)
{
	return c != NULL ? c->n[k] : 0;
}

const void *
catalog_item(const struct catalog *c, enum catalog_category k, size_t i)
{
	return item_at(c, k, i);
}

/* A propeller's sort key: diameter, then file order, a total order so
 * qsort's instability cannot show. */
struct prop_key {
	double diameter_in;
	size_t i;
};

static int
cmp_prop(const void *a, const void *b)
{
	const struct prop_key *x = a, *y = b;
	if (x->diameter_in != y->diameter_in)
		return x->diameter_in < y->diameter_in ? -1 : 1;
	return x->i < y->i ? -1 : x->i > y->i;
}

void
catalog_finish(struct catalog *c)
{
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		strmap_free(c->by_id[k]);
		c->by_id[k] = strmap_alloc(c->n[k]);
		for (size_t i = 0; i < c->n[k]; i++) {
			const struct catalog_common *e = item_at(c, (enum catalog_category)k, i);
			strmap_put(c->by_id[k], e->id, i, NULL);   /* the first wins */
		}
	}
	size_t n = c->n[CATALOG_PROP];
	const struct catalog_prop *v = c->items[CATALOG_PROP];
	struct prop_key *keys = xmalloc((n > 0 ? n : 1) * sizeof *keys);
	for (size_t i = 0; i < n; i++)
		keys[i] = (struct prop_key){ v[i].diameter_in, i };
	if (n > 1)
		qsort(keys, n, sizeof *keys, cmp_prop);
	free(c->prop_order);
	c->prop_order = xmalloc((n > 0 ? n : 1) * sizeof *c->prop_order);
	for (size_t i = 0; i < n; i++)
		c->prop_order[i] = keys[i].i;
	free(keys);
}

void
catalog_free(struct catalog *c)
{
	if (c == NULL)
		return;
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		free(c->items[k]);
		strmap_free(c->by_id[k]);
	}
	while (c->text != NULL) {
		struct text_block *next = c->text->next;
		free(c->text);
		c->text = next;
	}
	free(c->prop_order);
	free(c);
}

static const void *
item_by_id(const struct catalog *c, enum catalog_category k, const char *id)
{
	size_t i;
	if (c == NULL || id == NULL || c->by_id[k] == NULL ||
	    !strmap_get(c->by_id[k], id, &i))
		return NULL;
	return item_at(c, k, i);
}

size_t catalog_n_motors(const struct catalog *c) { return c != NULL ? c->n[CATALOG_MOTOR] : 0; }
size_t catalog_n_props(const struct catalog *c) { return c != NULL ? c->n[CATALOG_PROP] : 0; }
size_t catalog_n_batteries(const struct catalog *c) { return c != NULL ? c->n[CATALOG_BATTERY] : 0; }
size_t catalog_n_escs(const struct catalog *c) { return c != NULL ? c->n[CATALOG_ESC] : 0; }
size_t catalog_n_frames(const struct catalog *c) { return c != NULL ? c->n[CATALOG_FRAME] : 0; }
size_t catalog_n_avionics(const struct catalog *c) { return c != NULL ? c->n[CATALOG_AVIONICS] : 0; }

const struct catalog_motor *
catalog_motor(const struct catalog *c, size_t i) { return item_at(c, CATALOG_MOTOR, i); }
const struct catalog_prop *
catalog_prop(const struct catalog *c, size_t i) { return item_at(c, CATALOG_PROP, i); }
const struct catalog_battery *
catalog_battery(const struct catalog *c, size_t i) { return item_at(c, CATALOG_BATTERY, i); }
const struct catalog_esc *
catalog_esc(const struct catalog *c, size_t i) { return item_at(c, CATALOG_ESC, i); }
const struct catalog_frame *
catalog_frame(const struct catalog *c, size_t i) { return item_at(c, CATALOG_FRAME, i); }
const struct catalog_avionics *
catalog_avionics(const struct catalog *c, size_t i) { return item_at(c, CATALOG_AVIONICS, i); }

const size_t *
catalog_props_by_diameter(const struct catalog *c) { return c->prop_order; }

const struct catalog_motor *
catalog_find_motor(const struct catalog *c, const char *id) { return item_by_id(c, CATALOG_MOTOR, id); }
const struct catalog_prop *
catalog_find_prop(const struct catalog *c, const char *id) { return item_by_id(c, CATALOG_PROP, id); }
const struct catalog_battery *
catalog_find_battery(const struct catalog *c, const char *id) { return item_by_id(c, CATALOG_BATTERY, id); }
const struct catalog_esc *
catalog_find_esc(const struct catalog *c, const char *id) { return item_by_id(c, CATALOG_ESC, id); }
const struct catalog_frame *
catalog_find_frame(const struct catalog *c, const char *id) { return item_by_id(c, CATALOG_FRAME, id); }
const struct catalog_avionics *
catalog_find_avionics(const struct catalog *c, const char *id) { return item_by_id(c, CATALOG_AVIONICS, id); }

bool
catalog_motor_stator_mm(const struct catalog_motor *m, double *d_mm,
                        double *h_mm)
{
	char tail;
	if (m->stator == NULL
	    || sscanf(m->stator, "%lfx%lf%c", d_mm, h_mm, &tail) != 2)
		return false;
	return *d_mm > 0.0 && *h_mm > 0.0 && *d_mm < 1000.0 && *h_mm < 1000.0;
}

bool
catalog_list_names(const char *list, const char *item)
{
	size_t len = strlen(item);
	for (const char *u = list; u != NULL && *u != '\0'; ) {
		size_t ulen = strcspn(u, ",");
		if (ulen == len && strncmp(u, item, len) == 0)
			return true;
		u += ulen;
		if (*u == ',')
			u++;
	}
	return false;
}
