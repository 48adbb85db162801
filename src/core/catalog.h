/* catalog.h — the real-parts catalogue: motors, propellers, batteries, ESCs.
 *
 * The optimizer maps its continuous sizing optimum onto orderable parts; this
 * module loads and validates the four catalogue files of a directory
 * (data/catalog/ by default, or a company catalogue given with --db DIR):
 *
 *     DIR/motors.json      {"motors":     [ {...}, ... ]}
 *     DIR/propellers.json  {"propellers": [ ... ]}
 *     DIR/batteries.json   {"batteries":  [ ... ]}
 *     DIR/escs.json        {"escs":       [ ... ]}
 *
 * Every key of an entry must be present (JSON null = "not published / not
 * found"); only integrated motor systems add `integrated_prop_in`.
 * data/catalog/README.md lists the keys.  Values are converted to SI on
 * load, except where a part is specified in other units by convention
 * (propeller inches, KV, mAh-derived Ah, Wh), and those keep the unit in the
 * field name.  An unknown number is stored as 0; an entry with any unknown
 * field that the optimizer needs has `usable` false and must be skipped.
 *
 * For the I/O and optimizer layers; physics modules never include this.
 */
#ifndef AEROEVAL_CATALOG_H
#define AEROEVAL_CATALOG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#define CATALOG_ID_MAX 64          /* buffer sizes, NUL included */
#define CATALOG_NAME_MAX 128
#define CATALOG_SOURCE_MAX 2048
#define CATALOG_UNCERTAIN_MAX 256

/* Fields every entry carries.  They are repeated in each struct (not nested)
 * so that callers read m->id, m->mass_kg alike for every category. */
#define CATALOG_COMMON_FIELDS                                                  \
	char id[CATALOG_ID_MAX];           /* stable lowercase slug, unique    \
	                                      across all four files */           \
	char manufacturer[CATALOG_NAME_MAX];                                     \
	char part_number[CATALOG_NAME_MAX]; /* model as sold */                 \
	char source[CATALOG_SOURCE_MAX];   /* where the numbers were read */    \
	char confidence[8];                /* "high", "medium" or "low" */      \
	char uncertain[CATALOG_UNCERTAIN_MAX]; /* JSON names of doubtful      \
	                                      fields, comma-separated, or "" */  \
	double price_usd;                  /* old store snapshot; 0 unknown */  \
	char price_date[12];               /* "YYYY-MM" of the snapshot, or "" */ \
	bool usable                        /* every field the optimizer needs  \
	                                      is known */

struct catalog_motor {
	CATALOG_COMMON_FIELDS;
	double kv_rpm_per_v;       /* speed constant (needed) */
	double mass_kg;            /* incl. cable; for an integrated system
	                              motor + ESC + propeller (needed) */
	double max_current_a;      /* maker's maximum; T-Motor: 180 s peak (needed) */
	double max_power_w;        /* maker's maximum input power */
	int cells_min, cells_max;  /* recommended LiPo series count; 0 unknown */
	double prop_min_in;        /* recommended propeller diameter range */
	double prop_max_in;
	double resistance_ohm;     /* winding resistance as published */
	double no_load_current_a;  /* I0; 0 unknown */
	bool integrated;           /* motor + ESC + prop sold as one system */
	double integrated_prop_in; /* its propeller diameter; 0 if !integrated */
	double integrated_pitch_in; /* its pitch; 0 unknown */
	double integrated_esc_current_a; /* its ESC's continuous rating; 0 unknown */
};

struct catalog_prop {
	CATALOG_COMMON_FIELDS;
	double diameter_in;        /* (needed) */
	double diameter_m;         /* = diameter_in * 0.0254 */
	double pitch_in;           /* (needed) */
	double pitch_m;
	int blades;                /* 0 unknown */
	char material[16];         /* plastic, carbon, wood, composite, "" unknown */
	double mass_kg;            /* one complete propeller (needed) */
	double max_rpm;            /* maker's limit; 0 unknown */
	int folding;               /* 1 folding, 0 fixed, -1 unknown */
	char part_number_ccw[CATALOG_NAME_MAX]; /* the counter-rotating SKU, or "" */
	double ct_static;          /* static C_T, n-based; 0 unknown */
	double cp_static;          /* static C_P; 0 unknown */
};

struct catalog_battery {
	CATALOG_COMMON_FIELDS;
	char chemistry[24];        /* one of the known chemistries (needed) */
	int cells_series;          /* (needed); 1 for a single cell */
	double capacity_ah;        /* (needed) */
	double mass_kg;            /* (needed) */
	double continuous_c;       /* maker's continuous C rate (needed) */
	double burst_c;            /* 0 unknown */
	double nominal_voltage_v;
	double energy_wh;
};

struct catalog_esc {
	CATALOG_COMMON_FIELDS;
	double continuous_current_a; /* per channel (needed) */
	double burst_current_a;
	int cells_min, cells_max;
	double mass_kg;            /* the whole board, all channels (needed) */
	int channels;              /* 1 single ESC, 4 for a 4-in-1 board (needed) */
};

struct catalog;                /* opaque: the loaded catalogue */

/* Loads DIR/motors.json, DIR/propellers.json, DIR/batteries.json and
 * DIR/escs.json (dir must not be NULL; a trailing '/' is fine) and validates
 * every entry.  known_chemistries is a
 * NULL-terminated list of accepted battery chemistry names; NULL means the
 * built-in list (catalog_default_chemistries).
 *
 * Every error of every file is printed to err (NULL: not printed), one line
 * each in compiler style, naming file, entry and field:
 *     DIR/motors.json: error: motors[12] "tmotor-x".mass_g: must be > 0 (got -3)
 *     DIR/escs.json:4:17: error: malformed JSON near "..."
 * and counted in *n_errors (may be NULL).  Returns NULL if there was any
 * error, else a catalogue the caller frees with catalog_free(). */
struct catalog *catalog_load(const char *dir, const char *const *known_chemistries,
                             FILE *err, int *n_errors);

/* The catalogue's fingerprint (result.json's catalogue_sha256): the
 * lowercase hex SHA-256 over the four files in the order above, each as
 * its name, a NUL, its length as 8 bytes little-endian, then its bytes --
 * the very bytes that were parsed.  Lives as long as c. */
const char *catalog_sha256(const struct catalog *c);

/* Frees a catalogue; NULL is a no-op.  Pointers into it die with it. */
void catalog_free(struct catalog *c);

/* The built-in NULL-terminated chemistry list (the mission schema's names). */
extern const char *const catalog_default_chemistries[];

/* Entries in file order.  The accessors return NULL if i >= the count; the
 * finders return NULL if no entry has that id.  Unusable entries are included:
 * check `usable`. */
size_t catalog_n_motors(const struct catalog *c);
size_t catalog_n_props(const struct catalog *c);
size_t catalog_n_batteries(const struct catalog *c);
size_t catalog_n_escs(const struct catalog *c);

const struct catalog_motor *catalog_motor(const struct catalog *c, size_t i);
const struct catalog_prop *catalog_prop(const struct catalog *c, size_t i);
const struct catalog_battery *catalog_battery(const struct catalog *c, size_t i);
const struct catalog_esc *catalog_esc(const struct catalog *c, size_t i);

/* The catalogue's propeller indices (catalog_prop()), catalog_n_props()
 * of them, by diameter; equal diameters in file order. */
const size_t *catalog_props_by_diameter(const struct catalog *c);

const struct catalog_motor *catalog_find_motor(const struct catalog *c, const char *id);
const struct catalog_prop *catalog_find_prop(const struct catalog *c, const char *id);
const struct catalog_battery *catalog_find_battery(const struct catalog *c, const char *id);
const struct catalog_esc *catalog_find_esc(const struct catalog *c, const char *id);

#endif
