/* parts_int.h — what the parts search's files share (parts.h says how the
 * search goes).  Who may include it: src/parts only. */
#ifndef AEROEVAL_PARTS_INT_H
#define AEROEVAL_PARTS_INT_H

#include <stdbool.h>

#include "core/catalog.h"
#include "core/model.h"
#include "core/result.h"
#include "parts/parts.h"
#include "physics/motor.h"
#include "physics/prop.h"
#include "sizing/perf.h"
#include "sizing/sizing.h"

#define PARTS_MAX_CELLS     18    /* the highest bus searched: the agricultural
                                     class's 18S (75.6 V LiPo) */
#define PARTS_MAX_SERIES    4     /* catalogue packs in series ... */
#define PARTS_BANK_PARALLEL 4     /* ... and in parallel, ... */
#define PARTS_MAX_PARALLEL  6     /* ... six when no closing passes with four
                                     (DJI's M600 flies six 6S packs in
                                     parallel), ... */
#define PARTS_MAX_PACKS     12    /* ... at most two such banks in all */
#define PARTS_KEEP          32    /* ranked options closed that reach the
                                     continuous design's T/W ... */
#define PARTS_KEEP_SHORT    8     /* ... and that may fall short of it once
                                     their own estimated mass is aboard */
#define PARTS_KEEP_MARGINAL 8     /* ... and within the motor's ratings only
                                     on the most-sagged bus (rank.c) */
#define PARTS_CELL_PACK_FACTOR 1.12 /* a pack built from single cells: the
                                     cells plus 12 % of holder, nickel strip,
                                     wiring and wrap (catalogue README) */
#define PARTS_PACK_TRIES    6     /* battery arrangements tried per option */
#define PARTS_PACK_STEP     1.15  /* each next one holds at least 15 % more */
#define PARTS_ROUNDS        3     /* rankings: at the continuous mass, then at
                                     the mass the closest closing reached ... */
#define PARTS_ROUND_MIN_GROWTH 0.03 /* ... when that is 3 % heavier or more,
                                     or trusting lighter closings: */
#define PARTS_LIGHTEST      0.8   /* ... an option's J estimate down to 80 % of
                                     the continuous mass */
#define PARTS_RANGE_TOL_IN  0.5   /* slack on a maker's recommended propeller range */
#define PARTS_LOADED_BUS    0.95  /* loaded pack voltage / nominal, for ranking */
#define PARTS_CURRENT_MARGIN 1.1  /* ESC rating over the motor's full-throttle current */
#define PARTS_TW_TOL        0.98  /* real T/W may fall 2 % short of the continuous one */
#define PARTS_TW_SPARE      1.05  /* ranking: thrust to spare for the mass estimate */
#define PARTS_MAX_SAG       0.15  /* battery pick: pack sag at full throttle, of
                                     V_oc (high-discharge packs at their rated
                                     current); the record's own full-throttle
                                     point on the sagging pack sets its T/W */
#define PARTS_STIFF_SAG     0.08  /* ... then stiffer packs, when none of those
                                     closes every check */
#define PARTS_UNRATED_ESC_CELLS 6 /* bus limit of an ESC with no published range */
#define PARTS_STACK_MAX_WHEELBASE_M 0.35 /* 4-in-1 boards only on small frames */

/* Why an option was set aside; the census counts them. */
enum parts_reason {
	PARTS_OK,
	PARTS_MOTOR_CELLS,     /* bus outside the motor's cell range */
	PARTS_PROP_OVERLAP,    /* diameter above the overlap limit */
	PARTS_PROP_RANGE,      /* outside the motor's recommended propellers */
	PARTS_THRUST,          /* cannot lift the design at the required T/W */
	PARTS_MOTOR_CURRENT,   /* full-throttle current above the motor's rating */
	PARTS_MOTOR_POWER,     /* full-throttle input above the motor's rating */
	PARTS_TIP_MACH,        /* tip Mach above 0.75 at full throttle */
	PARTS_PROP_RPM,        /* full throttle above the propeller's rpm limit */
	PARTS_NO_ESC,          /* no ESC set carries it on this bus */
	PARTS_NO_BATTERY,      /* no pack arrangement builds the bus */
	PARTS_LOCK,            /* excluded by a lock */
	PARTS_IMPLAUSIBLE,     /* its catalogue entry fails a screen (screen.h) */
	PARTS_DOWNWASH,        /* its wake above the role's downwash limit */
	PARTS_DOUBTFUL,        /* a number it is sized on is listed uncertain */
	PARTS_WINDING,         /* winding above its limit in hover or after the
	                          full-throttle burst */
	PARTS_REASON_MAX
};
extern const char *const parts_reason_text[PARTS_REASON_MAX];

/* The continuous optimum the search aims at, and what it must reach. */
struct parts_aim {
	double mass_kg;            /* M*: continuous takeoff mass */
	double lightest;           /* the lightest closing the ranking trusts
	                              its J to estimate, of M*: 1 at first */
	double drive_kg;           /* its motors + propellers + ESCs */
	double battery_kg;         /* its battery */
	double energy_wh;          /* its battery's nominal energy */
	double hover_power_w;      /* its hover electrical power */
	double growth;             /* 1 / (1 - L): mass growth per added kg */
	double tw_required;        /* T/W the design of record must reach with
	                              the largest payload aboard: the role's
	                              or the mission's requirement, never
	                              relaxed (less PARTS_TW_TOL) */
	double extra_payload_kg;   /* the largest payload over the mission's */
	double downwash_cap_ms;    /* the role's downwash limit; 0 none */
	double prop_diameter_in;   /* D* */
	double prop_pitch_in;      /* p* */
	double motor_kv;           /* KV* at the continuous bus */
	int cells;                 /* S* */
	double overlap_limit_in;   /* the largest propeller the wheelbase takes */
	double install_factor;     /* installed over isolated rotor power */
};

/* One bus × motor × propeller option, flown at full throttle. */
struct parts_option {
	int cells;
	const struct catalog_motor *motor;
	const struct catalog_prop *prop;   /* NULL: an integrated system */
	struct perf_craft craft;           /* drive filled; battery later */
	double full_thrust_n;              /* one rotor at full throttle */
	double full_current_a;             /* one motor at full throttle */
	double full_power_w;               /* one motor's input there */
	double hover_power_w;              /* the aircraft at M*, drive only */
	double d4_m4;                      /* the propeller's diameter^4 */
	double full_winding_c;             /* winding after the full-throttle
	                                      burst from its hover temperature */
	double sagged_current_a;           /* full throttle on the most-sagged
	                                      bus a kept pack may give: the */
	double sagged_power_w;             /* least current and input a real
	                                      pack can bring (the ratings' prune) */
	double sagged_winding_c;           /* ... and the winding there */
	double j;                          /* estimated mass penalty, % */
	bool parity;                       /* reaches tw_required at its
	                                      estimated mass */
	bool marginal;                     /* within the motor's ratings only
	                                      on the most-sagged bus */
};

/* A battery built from catalogue packs. */
struct parts_pack {
	const struct catalog_battery *b;
	int series, parallel;
	double mass_kg, capacity_ah, energy_wh;
	double max_continuous_a, max_burst_a;
	const struct batt_chem *chem;
};

/* The catalogue's usable avionics parts of one kind, in catalogue order
 * (kit.c): a kit looks through its kind's few parts, not all of them. */
#define PARTS_KIT_KINDS 24
struct parts_kit_kind {
	const char *kind;
	const struct catalog_avionics **items;
	int n;
};

/* The search's lists, built once per solve. */
struct parts_ctx {
	const struct mission_spec *spec;
	const struct sizing_params *p;     /* the custom run's parameters */
	const struct model_data *md;
	const struct catalog *cat;
	struct parts_aim aim;
	const struct catalog_motor *lock_motor;
	const struct catalog_prop *lock_prop;
	const struct catalog_battery *lock_battery;
	const struct catalog_esc *lock_esc;
	int cells_lo, cells_hi;            /* buses searched */
	int max_parallel;                  /* packs in parallel the pick takes */
	struct parts_pack *packs;          /* every arrangement, by bus then mass */
	int n_packs;
	struct parts_kit_kind kit_kinds[PARTS_KIT_KINDS];
	int n_kit_kinds;
	const struct catalog_frame **kit_frames; /* the frame kits offered */
	int n_kit_frames;
	int n_census[PARTS_REASON_MAX];
	int n_examined;
};

/* The parts around the propulsion (kit.c): the frame kit, the avionics
 * set of the airframe class and the battery connectors. */
#define PARTS_KIT_MAX 8
struct parts_kit {
	const struct catalog_frame *frame; /* NULL: custom arms and centre */
	const struct catalog_avionics *part[PARTS_KIT_MAX]; /* the set found */
	int n_part;
	const char *allowance_what[PARTS_KIT_MAX]; /* what the class carries
	                                      that no catalogue part supplies */
	double allowance_kg[PARTS_KIT_MAX];
	int n_allowance;
	double avionics_kg;                /* parts + allowances */
	const struct catalog_avionics *connector; /* one pair per pack; NULL
	                                      when none carries the current */
	int n_connectors;
	double connector_kg;               /* all pairs */
	bool connector_mates;              /* of the pack's own plug's family */
	int n_on_esc;                      /* class items the ESC board carries
	                                      (an all-in-one board's flight
	                                      controller, receiver, ...) */
	double sized_for_a;                /* the sustained battery current the
	                                      power module and connectors carry */
};

/* One closing: an option with its ESC set and battery, flown. */
struct parts_closed {
	struct parts_option o;
	const struct catalog_esc *esc;     /* NULL: integrated */
	int n_esc;
	struct parts_pack pack;
	struct parts_kit kit;
	struct solve_result *r;            /* its run in r->closed, violations */
	int failed;                        /* failed checks */
	bool finite;
	bool ran_away;                     /* its mass loop grew past
	                                      SIZING_RUNAWAY_KG: not finite, and
	                                      no defect either */
};

/* rank.c */

/* The currents a motor may carry (rank.c says why): through the phases of
 * the mission, and in a full-throttle burst (0: not checked). */
struct parts_motor_limits {
	double sustained_a;
	double full_a;
	const char *sustained_text;        /* which rating, for the checks */
	const char *full_text;
};
void parts_motor_limits(const struct catalog_motor *m,
                        struct parts_motor_limits *l);
/* An integrated system's published maximum thrust per rotor on `cells`
 * in the mission's air, N; 0 for a plain motor or none published. */
double parts_published_thrust_n(const struct parts_ctx *x,
                                const struct catalog_motor *m, int cells);
void parts_aim_from(const struct sizing_params *p, const struct res_run *custom,
                    struct parts_aim *aim);
/* The aim moved to `grown` times its mass: hover power, energy and
 * battery with it, as M^1.5 (induced power at a fixed disk area). */
void parts_aim_regrow(struct parts_aim *aim, double grown);
int parts_rank(struct parts_ctx *x, struct parts_option *best, int max_best,
               struct res_candidate *cand, int *n_cand);

/* close.c */
void parts_packs_init(struct parts_ctx *x);
void parts_packs_free(struct parts_ctx *x);
bool parts_pick_esc(const struct parts_ctx *x, const struct parts_option *o,
                    const struct catalog_esc **esc, int *n);
bool parts_close(const struct parts_ctx *x, const struct parts_option *o,
                 const struct parts_pack *pk, const struct catalog_esc *esc,
                 int n_esc, struct parts_closed *out);
/* The performance figures beyond the mission (sizing/perf.h) of a closing
 * parts_close() made: the design of record's.  False if not finite. */
bool parts_close_figures(const struct parts_ctx *x, struct parts_closed *cl);
const struct parts_pack *parts_packs_for(const struct parts_ctx *x,
                                         const struct parts_option *o,
                                         int *n);
void parts_record_checks(const struct parts_ctx *x, const struct parts_closed *c,
                         struct solve_result *r);

/* kit.c */
/* Indexes the catalogue's avionics by kind into x (parts_kit_free). */
void parts_kit_init(struct parts_ctx *x);
void parts_kit_free(struct parts_ctx *x);
/* The kit of option o on pack pk with ESC esc (NULL: the motors' own, an
 * integrated system's), sized for sustained_a. */
void parts_kit_pick(const struct parts_ctx *x, const struct parts_option *o,
                    const struct parts_pack *pk, const struct catalog_esc *esc,
                    double sustained_a, struct parts_kit *kit);
/* Does frame kit f fit (kit.c says when)?  custom_kg: the custom arms and
 * centre frame it would replace. */
bool parts_kit_frame_fits(const struct parts_ctx *x,
                          const struct catalog_frame *f, double prop_in,
                          double mass_kg, double arm_od_m, double custom_kg);
/* The lightest kit that fits, or NULL. */
const struct catalog_frame *parts_kit_frame(const struct parts_ctx *x,
                                            double prop_in, double mass_kg,
                                            double arm_od_m, double custom_kg);

/* bom.c */
void parts_fill(const struct parts_ctx *x, const struct parts_closed *c,
                struct solve_result *r);
void parts_explain(const struct parts_ctx *x, const struct parts_closed *c,
                   int n_closed, int n_better_failed, struct solve_result *r);

#endif
