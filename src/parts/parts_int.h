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

#define PARTS_MAX_CELLS     14    /* the highest bus searched (58.8 V LiPo) */
#define PARTS_MAX_SERIES    4     /* catalogue packs in series ... */
#define PARTS_MAX_PARALLEL  4     /* ... and in parallel */
#define PARTS_KEEP          32    /* ranked options closed */
#define PARTS_PACK_TRIES    5     /* battery arrangements tried per option */
#define PARTS_RANGE_TOL_IN  0.5   /* slack on a maker's recommended propeller range */
#define PARTS_LOADED_BUS    0.95  /* loaded pack voltage / nominal, for ranking */
#define PARTS_CURRENT_MARGIN 1.1  /* ESC rating over the motor's full-throttle current */
#define PARTS_TW_TOL        0.98  /* real T/W may fall 2 % short of the continuous one */
#define PARTS_TW_SPARE      1.05  /* ranking: thrust to spare for the mass estimate */
#define PARTS_TW_SHORTFALL_W 0.2  /* selection: a design 10 % short of the role's
                                     T/W goal counts 2 % heavier */
#define PARTS_MAX_SAG       0.10  /* battery pick: pack sag at full throttle, of V_oc */
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
	PARTS_REASON_MAX
};
extern const char *const parts_reason_text[PARTS_REASON_MAX];

/* The continuous optimum the search aims at, and what it must reach. */
struct parts_aim {
	double mass_kg;            /* M*: continuous takeoff mass */
	double drive_kg;           /* its motors + propellers + ESCs */
	double battery_kg;         /* its battery */
	double energy_wh;          /* its battery's nominal energy */
	double hover_power_w;      /* its hover electrical power */
	double growth;             /* 1 / (1 - L): mass growth per added kg */
	double tw_required;        /* T/W the real rotor must reach: the
	                              mission's own target, or for a role's
	                              default target (a goal) the relaxation
	                              floor of sizing.h */
	double tw_target;          /* T/W of the role's target, a goal */
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
	double j;                          /* estimated mass penalty, % */
};

/* A battery built from catalogue packs. */
struct parts_pack {
	const struct catalog_battery *b;
	int series, parallel;
	double mass_kg, capacity_ah, energy_wh;
	double max_continuous_a, max_burst_a;
	const struct batt_chem *chem;
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
	struct parts_pack *packs;          /* every arrangement, by bus then mass */
	int n_packs;
	int n_census[PARTS_REASON_MAX];
	int n_examined;
};

/* One closing: an option with its ESC set and battery, flown. */
struct parts_closed {
	struct parts_option o;
	const struct catalog_esc *esc;     /* NULL: integrated */
	int n_esc;
	struct parts_pack pack;
	struct solve_result *r;            /* its run in r->closed, violations */
	int failed;                        /* failed checks */
	bool finite;
};

/* rank.c */
void parts_aim_from(const struct sizing_params *p, const struct res_run *custom,
                    struct parts_aim *aim);
int parts_rank(struct parts_ctx *x, struct parts_option *best, int max_best,
               struct res_candidate *cand, int *n_cand);
bool parts_drive(const struct parts_ctx *x, const struct catalog_motor *m,
                 const struct catalog_prop *pr, int cells,
                 struct parts_option *o);

/* close.c */
void parts_packs_init(struct parts_ctx *x);
void parts_packs_free(struct parts_ctx *x);
bool parts_pick_esc(const struct parts_ctx *x, const struct parts_option *o,
                    const struct catalog_esc **esc, int *n);
bool parts_close(const struct parts_ctx *x, const struct parts_option *o,
                 const struct parts_pack *pk, const struct catalog_esc *esc,
                 int n_esc, bool full, struct parts_closed *out);
const struct parts_pack *parts_packs_for(const struct parts_ctx *x,
                                         const struct parts_option *o,
                                         int *n);
void parts_record_checks(const struct parts_ctx *x, const struct parts_closed *c,
                         struct solve_result *r);

/* bom.c */
void parts_fill(const struct parts_ctx *x, const struct parts_closed *c,
                struct solve_result *r);
void parts_explain(const struct parts_ctx *x, const struct parts_closed *c,
                   int n_closed, int n_better_failed, struct solve_result *r);

#endif
