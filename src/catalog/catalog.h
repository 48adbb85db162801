/* catalog.h — the real-parts catalogue: motors, propellers, batteries,
 * ESCs, frame kits and avionics, as plain structs with accessors and
 * finders.
 *
 * The optimizer maps its continuous sizing optimum onto orderable parts
 * from here.  Loading and validating the catalogue files (format version 2,
 * data/catalog/README.md) is the input layer's job (input/catalog_io.h);
 * this module only holds what was loaded: the entries of each category in
 * file order, an id index, and the propellers ordered by diameter.
 *
 * Values are SI inside with the unit in every name (mass_kg,
 * resistance_ohm, no_load_current_a), except where a part is specified in
 * other units by convention (propeller inches, KV, C rates, Wh), and those
 * keep the unit in the name too.  An unknown number ("null" in the file) is
 * stored as 0, an unknown text as "" (never NULL), an unknown yes/no as -1
 * where it may be unknown.  An entry with any unknown field that the
 * optimizer needs has `usable` false and must be skipped.
 *
 * For the input layer (which fills it), the parts, engine, formats, PDF
 * and command layers; physics modules never include this.
 */
#ifndef AEROEVAL_CATALOG_H
#define AEROEVAL_CATALOG_H

#include <stdbool.h>
#include <stddef.h>

#define CATALOG_ID_MAX 128         /* bytes of an id, NUL included */
#define CATALOG_TEXT_MAX 4096      /* bytes of any other text, NUL included */

/* Fields every entry carries.  They are repeated in each struct (not nested)
 * so that callers read m->id, m->mass_kg alike for every category.  Text
 * points into the catalogue and lives as long as it. */
#define CATALOG_COMMON_FIELDS                                                  \
	const char *id;                    /* stable lowercase slug, unique    \
	                                      across all files */                \
	const char *manufacturer;          /* maker as sold */                  \
	const char *part_number;           /* model as sold */                  \
	const char *source;                /* where the numbers were read */    \
	const char *confidence;            /* "high", "medium" or "low" */      \
	const char *uncertain;             /* JSON names of doubtful fields,    \
	                                      comma-separated, or "" */          \
	double price_usd;                  /* one unit, a snapshot; 0 unknown */\
	const char *price_date;            /* "YYYY-MM" or "YYYY" of the price, \
	                                      "" when the price is unknown */    \
	bool usable                        /* every field the optimizer needs  \
	                                      is known */

struct catalog_motor {
	CATALOG_COMMON_FIELDS;
	double kv_rpm_per_v;       /* speed constant (needed) */
	double mass_kg;            /* incl. cable; for an integrated system
	                              motor + ESC + propeller (needed) */
	double max_current_a;      /* maker's maximum (needed) */
	const char *max_current_basis; /* "continuous", "peak_180s", "peak_60s",
	                              "peak_30s", "peak_10s", "peak_unspecified", "" */
	double max_power_w;        /* maker's maximum input power */
	int cells_min, cells_max;  /* recommended LiPo series count; 0 unknown */
	double prop_min_in;        /* recommended propeller diameter range */
	double prop_max_in;
	double resistance_ohm;     /* winding resistance as published */
	double no_load_current_a;  /* I0 */
	double no_load_voltage_v;  /* the voltage I0 was measured at */
	const char *stator;        /* "50x08" (diameter x height, mm), "" */
	bool integrated;           /* motor + ESC + prop sold as one system */
	double integrated_prop_in; /* its propeller diameter; 0 if !integrated */
	double integrated_pitch_in; /* its propeller pitch; 0 if !integrated */
	double integrated_esc_current_a; /* its ESC continuous rating */
	double max_thrust_n;       /* maker's maximum thrust per motor (from g) */
};

struct catalog_prop {
	CATALOG_COMMON_FIELDS;
	double diameter_in;        /* (needed) */
	double diameter_m;         /* = diameter_in * 0.0254 */
	double pitch_in;           /* (needed) */
	double pitch_m;
	int blades;                /* 0 unknown */
	const char *material;      /* plastic, carbon, wood, composite, "" */
	double mass_kg;            /* one complete propeller (needed) */
	double max_rpm;            /* maker's limit; 0 unknown */
	int folding;               /* 1 folding, 0 fixed, -1 unknown */
	double ct_static;          /* static C_T = T / (rho n^2 D^4); 0 unknown */
	double cp_static;          /* static C_P = P / (rho n^3 D^5); 0 unknown */
	const char *coeff_source;  /* where ct/cp come from, "" */
	const char *part_number_ccw; /* the counter-rotating SKU, "" */
};

struct catalog_battery {
	CATALOG_COMMON_FIELDS;
	const char *chemistry;     /* one of the known chemistries (needed) */
	int cells_series;          /* (needed); 1 for a single cell */
	int cells_parallel;        /* 0 unknown */
	double capacity_ah;        /* (needed) */
	double mass_kg;            /* (needed) */
	double continuous_c;       /* maker's continuous C rate (needed) */
	double burst_c;            /* 0 unknown */
	double nominal_voltage_v;
	double energy_wh;
	const char *connector;     /* "XT60", "AS150U", ..., "" */
	bool smart;                /* its own BMS / smart-battery interface */
};

struct catalog_esc {
	CATALOG_COMMON_FIELDS;
	double continuous_current_a; /* per channel (needed) */
	double burst_current_a;    /* per channel */
	double burst_s;            /* duration of the burst rating; 0 unknown */
	int cells_min, cells_max;
	double mass_kg;            /* the whole board, all channels (needed) */
	int channels;              /* 1 single ESC, 4 for a 4-in-1 board (needed) */
	const char *carries;       /* avionics kinds on the board besides the
	                              ESCs, comma-separated ("flight_controller,
	                              receiver" on an all-in-one board), "" */
	const char *video_system;  /* the video system of the transmitter it
	                              carries ("analog", ...: data/catalog/
	                              README.md), "" when it carries none */
};

struct catalog_frame {
	CATALOG_COMMON_FIELDS;
	int rotor_count;           /* motors it carries, coaxial X8 = 8 (needed) */
	bool coaxial;
	double wheelbase_m;        /* diagonal motor-to-motor (needed) */
	double mass_kg;            /* kit mass as published (needed) */
	const char *includes;      /* what the mass covers (needed) */
	double max_prop_in;        /* largest propeller allowed; 0 unknown */
	double arm_tube_od_m;      /* arm tube outer diameter; 0 unknown */
	int folding;               /* 1, 0, -1 unknown */
	double max_takeoff_kg;     /* maker's recommended maximum; 0 unknown */
	const char *frame_class;   /* the airframe class it fits best, "" */
};

struct catalog_avionics {
	CATALOG_COMMON_FIELDS;
	const char *kind;          /* "flight_controller", "gnss", ... (needed) */
	double mass_kg;            /* one unit (needed) */
	int cells_min, cells_max;  /* supply range in series cells; 0 unknown */
	double max_current_a;      /* its continuous current rating; 0 unknown */
	double burst_current_a;    /* its burst rating; 0 none published */
	double burst_s;            /* how long the burst rating holds; 0 not
	                              published (then it holds for no burst the
	                              parts search asks of it) */
	double power_w;            /* typical draw; 0 unknown */
	const char *video_system;  /* a camera's or video transmitter's system
	                              ("analog", "walksnail", ...: a camera and
	                              a transmitter work together only on the
	                              same one), "" for other kinds */
	const char *carries;       /* kinds it does besides its own, comma-
	                              separated ("camera_fpv" on an air unit
	                              with its camera, "remote_id" on a part
	                              that broadcasts Remote ID), "" */
	const char *description;   /* one plain phrase (needed) */
};

/* The categories, in the order their files are read. */
enum catalog_category {
	CATALOG_MOTOR,
	CATALOG_PROP,
	CATALOG_BATTERY,
	CATALOG_ESC,
	CATALOG_FRAME,
	CATALOG_AVIONICS,
	CATALOG_N_CATEGORIES
};

struct catalog;                /* opaque: the loaded catalogue */

/* ---- building (for the loader, input/catalog_io.c) ------------------------ */

/* An empty catalogue.  Ownership: catalog_free(). */
struct catalog *catalog_alloc(void);

/* A copy of s kept in the catalogue (never moved; freed with it). */
const char *catalog_intern(struct catalog *c, const char *s);

/* Hands c the malloc'd array of n entries of category k (structs of
 * catalog_entry_size(k) bytes, strings interned in c); c frees it. */
void catalog_adopt(struct catalog *c, enum catalog_category k, void *items, size_t n);

/* Indexes the ids and orders the propellers; once, after every adopt. */
void catalog_finish(struct catalog *c);

/* sizeof the entry struct of category k. */
size_t catalog_entry_size(enum catalog_category k);

/* The number of entries of category k, and entry i of it (NULL past the
 * end) as raw bytes, for code that handles every category alike (the
 * snapshot, input/catalog_snap.h). */
size_t catalog_count(const struct catalog *c, enum catalog_category k);
const void *catalog_item(const struct catalog *c, enum catalog_category k, size_t i);

/* Frees a catalogue; NULL is a no-op.  Pointers into it die with it. */
void catalog_free(struct catalog *c);

/* ---- reading ------------------------------------------------------------- */

/* The built-in NULL-terminated chemistry list (the mission schema's names). */
extern const char *const catalog_default_chemistries[];

/* Entries in file order.  The accessors return NULL if i >= the count; the
 * finders return NULL if no entry has that id.  Unusable entries are included:
 * check `usable`. */
size_t catalog_n_motors(const struct catalog *c);
size_t catalog_n_props(const struct catalog *c);
size_t catalog_n_batteries(const struct catalog *c);
size_t catalog_n_escs(const struct catalog *c);
size_t catalog_n_frames(const struct catalog *c);
size_t catalog_n_avionics(const struct catalog *c);

const struct catalog_motor *catalog_motor(const struct catalog *c, size_t i);

/* Does a catalogue list field ("uncertain", an ESC's "carries": items
 * joined by commas) name item exactly?  False for a NULL list. */
bool catalog_list_names(const char *list, const char *item);

/* The stator's diameter and height in mm from m->stator ("22x07"); false
 * when the catalogue gives none or a form this does not read. */
bool catalog_motor_stator_mm(const struct catalog_motor *m, double *d_mm,
                             double *h_mm);
const struct catalog_prop *catalog_prop(const struct catalog *c, size_t i);
const struct catalog_battery *catalog_battery(const struct catalog *c, size_t i);
const struct catalog_esc *catalog_esc(const struct catalog *c, size_t i);
const struct catalog_frame *catalog_frame(const struct catalog *c, size_t i);
const struct catalog_avionics *catalog_avionics(const struct catalog *c, size_t i);

/* The catalogue's propeller indices (catalog_prop()), catalog_n_props()
 * of them, by diameter; equal diameters in file order. */
const size_t *catalog_props_by_diameter(const struct catalog *c);

const struct catalog_motor *catalog_find_motor(const struct catalog *c, const char *id);
const struct catalog_prop *catalog_find_prop(const struct catalog *c, const char *id);
const struct catalog_battery *catalog_find_battery(const struct catalog *c, const char *id);
const struct catalog_esc *catalog_find_esc(const struct catalog *c, const char *id);
const struct catalog_frame *catalog_find_frame(const struct catalog *c, const char *id);
const struct catalog_avionics *catalog_find_avionics(const struct catalog *c, const char *id);

#endif
