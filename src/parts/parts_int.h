/* parts_int.h — what the parts search's files share (parts.h says how the
 * search goes).  Who may include it: src/parts only. */
#ifndef AEROEVAL_PARTS_INT_H
#define AEROEVAL_PARTS_INT_H

#include <stdbool.h>

#include "catalog/catalog.h"
#include "spec/model.h"
#include "result/result.h"
#include "parts/parts.h"
#include "physics/motor.h"
#include "physics/prop.h"
#include "sizing/perf.h"
#include "sizing/sizing.h"

#define PARTS_MAX_CELLS     18    /* the highest bus searched: the agricultural
                                     class's 18S (75.6 V LiPo) */
#define PARTS_KIT_ITEMS     7     /* items of a class's avionics kit (kit.c) */
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
#define PARTS_TW_TOL        0.98  /* the ranking's screens keep options whose
                                     estimated T/W is up to 2 % short: their
                                     closing may reach it */
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
	                              relaxed (the ranking's screens let
	                              options PARTS_TW_TOL short through) */
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
	const struct catalog_avionics *plug; /* the catalogue's row of its own
	                                        plug family, or NULL, ... */
	const char *plug_name;               /* ... found for this connector
	                                        text by parts_kit_init() (NULL:
	                                        not looked up; kit.c) */
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
	struct parts_kit_kind plugs;       /* every connector row, usable or
	                                      not: a plug's rating bounds its
	                                      pack even where the catalogue has
	                                      no mass for its mate */
	/* The lightest part of each item of the class's kit whose choice
	 * hangs on the bus alone (every need but a current rating), and in
	 * the last slot the Remote ID module: by item and bus, the same for
	 * every closing, so parts_kit_init() picks them once (NULL: none
	 * fits; kit.c). */
	const struct catalog_avionics *kit_by_bus[PARTS_KIT_ITEMS + 1]
	                                         [PARTS_MAX_CELLS + 1];
	int kit_by_bus_class;              /* the airframe class they are for */
	/* The lightest transmitter and camera that work together, when the
	 * ESC board carries none (the same for every closing; kit.c). */
	const struct catalog_avionics *video_tx, *video_cam;
	bool *esc_offered;                 /* by catalogue ESC: usable and past
	                                      the screens (parts_escs_init()) */
	const struct catalog_frame **kit_frames; /* the frame kits offered */
	int n_kit_frames;
	int n_census[PARTS_REASON_MAX];
	int n_examined;
	bool exhaustive;                   /* no shortcut taken (test builds:
	                                      AEROEVAL_TEST_EXHAUSTIVE) */
};

/* What a kit is sized for (parts_kit_pick()): the currents of the
 * closing and its takeoff mass. */
struct parts_load {
	double sustained_a;                /* battery: the highest current of a
	                                      phase the mission flies */
	double full_a;                     /* battery at full throttle: every
	                                      motor and the auxiliaries */
	double motor_full_a;               /* one motor at full throttle */
	double mass_kg;                    /* takeoff mass without the kit's
	                                      own Remote ID module */
};

/* One run of the power harness (harness.c): n_runs alike, each a pair of
 * conductors (plus and minus) of `parallel` copper wires of one gauge,
 * carrying current_a over length_m. */
struct parts_run {
	const char *awg;                   /* "8", "2/0"; NULL: no such run */
	double area_mm2;                   /* one wire's copper */
	int parallel;                      /* wires in parallel per conductor */
	double ampacity_a;                 /* a conductor's chassis-wiring
	                                      ampacity (all its wires) */
	double current_a;                  /* what one run carries */
	double length_m;
	int n_runs;
	double kg;                         /* all n_runs, both conductors */
};

/* The parts around the propulsion (kit.c): the frame kit, the avionics
 * set of the airframe class, the battery connectors, the power harness
 * and the allowances with a stated basis. */
#define PARTS_KIT_MAX 10
struct parts_kit {
	const struct catalog_frame *frame; /* NULL: custom arms and centre */
	const struct catalog_avionics *part[PARTS_KIT_MAX]; /* the set found */
	int n_part;
	const char *allowance_what[PARTS_KIT_MAX]; /* what the class carries
	                                      that no catalogue part supplies */
	const char *allowance_basis[PARTS_KIT_MAX]; /* how its mass was set;
	                                      NULL: the class note's group */
	double allowance_kg[PARTS_KIT_MAX];
	int n_allowance;
	double avionics_kg;                /* parts + allowances */
	const struct catalog_avionics *power_module; /* the rated power module
	                                      or distribution board; NULL */
	bool power_module_item;            /* the class carries one (a part or
	                                      an allowance) */
	const struct catalog_avionics *connector; /* one per pack; NULL when
	                                      none carries the pack's share */
	int n_connectors;
	double connector_kg;               /* all of them */
	bool connector_mates;              /* of the pack's own plug's family */
	const struct catalog_avionics *plug; /* the catalogue's row of the
	                                      pack's own plug when the pair
	                                      bought is another (its rating
	                                      still bounds the pack); NULL */
	int n_on_esc;                      /* class items the ESC board carries
	                                      (an all-in-one board's flight
	                                      controller, receiver, ...) */
	bool camera_on_vtx;                /* the video transmitter bought
	                                      carries its camera */
	bool remote_id_required;           /* EU C1 and up, US Part 89 */
	bool remote_id_missing;            /* required, and neither a kit part
	                                      does it nor the catalogue sells
	                                      a module that fits */
	struct parts_load load;            /* what it was sized for */
	struct parts_run harness_main;     /* packs to distribution */
	struct parts_run harness_pack;     /* each pack's lead (several packs) */
	struct parts_run harness_arm;      /* each rotor's run (ESCs on arms) */
	double harness_kg;                 /* the three runs' copper */
	int n_motor_screws;                /* screws holding the motors */
	int n_arm_screws;                  /* ... and custom arms (none with a
	                                      frame kit: parts_kit_screws()) */
	const char *fastener_size;         /* "M3 x 8" */
	double fastener_unit_kg;           /* one screw */
	double role_supplied_kg;           /* role hardware the class items
	                                      supply (kept out of the role's
	                                      allowance) */
	const char *role_supplied_what;    /* their words, NULL none */
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

/* closure.c */
void parts_packs_init(struct parts_ctx *x);
void parts_packs_free(struct parts_ctx *x);
/* Screens every catalogue ESC once per search (x->esc_offered). */
void parts_escs_init(struct parts_ctx *x);
void parts_escs_free(struct parts_ctx *x);
bool parts_pick_esc(const struct parts_ctx *x, const struct parts_option *o,
                    const struct catalog_esc **esc, int *n);
bool parts_close(const struct parts_ctx *x, const struct parts_option *o,
                 const struct parts_pack *pk, const struct catalog_esc *esc,
                 int n_esc, struct parts_closed *out);
/* The performance figures beyond the mission (sizing/perf.h) of a closing
 * parts_close() made: the design of record's.  False if not finite. */
bool parts_close_figures(const struct parts_ctx *x, struct parts_closed *cl);
/* The pack arrangements of a bus of cells (*n of them, by mass), NULL
 * when it has none. */
const struct parts_pack *parts_packs_on(const struct parts_ctx *x, int cells,
                                        int *n);
void parts_record_checks(const struct parts_ctx *x, const struct parts_closed *c,
                         struct solve_result *r);

/* compat.c: do two parts work together?  Each rule returns NULL when
 * they do, else the reason written into why (size n). */

/* A part's current ratings: continuous, and a burst with how long it
 * holds (0: not published). */
struct compat_rating {
	double continuous_a, burst_a, burst_s;
};
/* The reason a rule fails: fmt formatted into why (size n) and why
 * returned, or, why NULL (the caller wants only the answer), a constant
 * non-NULL text and nothing formatted. */
const char *compat_reason(char *why, size_t n, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The rating that holds for a burst of need_s (compat.c says when the
 * burst rating does). */
double compat_rating_for(const struct compat_rating *r, double need_s);
/* sustained_a within the continuous rating, full_a within the rating for
 * a full-throttle burst of need_s.  Every compat_* rule returns NULL when
 * the parts work together, else the reason in why (why NULL: only the
 * answer, nothing formatted). */
const char *compat_rated(const struct compat_rating *r, double sustained_a,
                         double full_a, double need_s, char *why, size_t n);
/* camera with a transmitter of system vtx_system (vtx_has_camera: an air
 * unit that carries its camera; then camera must be NULL). */
const char *compat_video(const struct catalog_avionics *camera,
                         const char *vtx_system, bool vtx_has_camera,
                         char *why, size_t n);
/* Connector a on a pack whose plug is pack_connector ("XT60", "smart",
 * "" unknown), carrying the pack's share of the currents. */
const char *compat_connector(const char *pack_connector,
                             const struct catalog_avionics *a,
                             double sustained_a, double full_a, double need_s,
                             char *why, size_t n);
/* The family of a connector's name, upper case, letters and digits up to
 * the first blank, "(" or "/", without AMASS's -M/-F half suffix
 * ("XT90-S (mated pair)" and "xt90s" read "XT90S", "XT60-M" "XT60"). */
void compat_connector_family(const char *name, char *out, size_t n);
/* Is connector a one half of its pair ("XT60-M"), not a mated pair?  A
 * half mates with a pack's own plug; a pack fitted with another plug
 * needs the whole pair. */
bool compat_connector_half(const struct catalog_avionics *a);
/* Does a pack's plug text ("XT60", "AS150/XT150") name a's family? */
bool compat_mates(const char *pack_connector, const struct catalog_avionics *a);
/* ESC e driving motor m (NULL: not checked) on `cells`, each channel
 * carrying sustained_a and full_a (times margin). */
const char *compat_esc(const struct catalog_esc *e, const struct catalog_motor *m,
                       int cells, double sustained_a, double full_a,
                       double margin, double need_s, char *why, size_t n);
/* n_boards of e on one aircraft whose class takes (class_takes_it) or
 * not the flight controller an all-in-one board carries. */
const char *compat_board_fc(const struct catalog_esc *e, int n_boards,
                            bool class_takes_it, char *why, size_t n);
/* Does an aircraft of mass_kg need Remote ID (EU C1 and up, US Part 89)? */
bool compat_remote_id_required(double mass_kg);
/* Does part a do kind, as its own kind or one it carries? */
bool compat_does(const struct catalog_avionics *a, const char *kind);

/* harness.c: the power harness in copper. */

/* A run of n_runs pairs of conductors carrying current_a each over
 * length_m, in the lightest gauge whose chassis-wiring ampacity carries
 * it (harness.c cites the table), wires in parallel beyond the largest. */
void parts_harness_run(double current_a, double length_m, int n_runs,
                       struct parts_run *out);
/* The kit's three runs and their mass, for option o on pack pk with ESC
 * esc, sized for the kit's load (kit->load). */
void parts_harness(const struct parts_ctx *x, const struct parts_pack *pk,
                   const struct catalog_esc *esc, struct parts_kit *kit);

/* kit.c */
/* Indexes the catalogue's avionics by kind into x (parts_kit_free). */
void parts_kit_init(struct parts_ctx *x);
void parts_kit_free(struct parts_ctx *x);
/* The kit of option o on pack pk with ESC esc (NULL: the motors' own, an
 * integrated system's), sized for load. */
void parts_kit_pick(const struct parts_ctx *x, const struct parts_option *o,
                    const struct parts_pack *pk, const struct catalog_esc *esc,
                    const struct parts_load *load, struct parts_kit *kit);
/* Would the kit be the same one: the same parts, connectors and masses? */
bool parts_kit_same(const struct parts_kit *a, const struct parts_kit *b);
/* Can pack pk join the harness with each pack carrying its share of
 * sustained_a and full_a: through its own plug when the catalogue sells
 * its mate, else through a catalogue connector that carries it, the
 * plug's own rating carrying it wherever the catalogue has one?  NULL
 * when it can, else why (why NULL: only the answer). */
const char *parts_kit_plug(const struct parts_ctx *x, const struct parts_pack *pk,
                           double sustained_a, double full_a, char *why,
                           size_t n);
/* The screws the kit holds its motors (and custom arms) with, and
 * their mass. */
int parts_kit_screws(const struct parts_kit *kit);
double parts_kit_fastener_kg(const struct parts_kit *kit);
/* Does the airframe class fly the flight controller an all-in-one ESC
 * board carries (its need is any controller, not a redundant one)? */
bool parts_kit_takes_board_fc(const struct parts_ctx *x);
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
