/* optim.h — discrete part selection: the continuous optimum onto catalogue parts.
 *
 * Paper §VIII: the continuous optimum (propeller diameter and pitch, motor
 * KV) is the aim point of an exhaustive guided grid search over the parts
 * catalogue, scored by
 *
 *     J = 100 ΔD + 10 ΔKV + 50 Δp + Pen_a + Pen_θ (+ Pen_m)
 *
 * with relative deviations Δx = |x - x*| / x*, the hover-throttle penalty
 * Pen_a = 1000 max(0, θ_hvr - θ_role) and the cruise-pitch penalty
 * Pen_θ = 10 max(0, θ_cr - 20°).  Pen_m = 10 max(0, m/m* - 1) is ours, not
 * the paper's: without it J is blind to motor mass, and a 3.6 kg motor of
 * the right KV outscores a 0.3 kg one on a 5 kg aircraft whenever its KV is
 * a little closer (heavier parts then run the closed design away).  A combination that breaks a hard limit is
 * pruned (J = 1e9): propeller overlap, tip Mach 0.75 at full rpm, the
 * propeller's rpm limit, the motor's current (10 % margin), power, cell range
 * and recommended propeller range; a combination also needs an ESC and a
 * battery built from catalogue packs (series × parallel) for its bus.
 *
 * The bus is a search dimension: when the mission leaves the cell count
 * open, every count from the continuous design's up to the class maximum is
 * tried (more cells means less current, which is never worse for the
 * harness budget), with the KV target, currents and capacity rescaled at
 * constant power and energy; only when nothing fits there are the counts
 * below S* down to the class minimum tried (the harness then carries more
 * than its budget, which the closed run's wiring mass accounts for).  The
 * aim point stays the paper's.
 *
 * optim_select then closes the loop on real parts: the custom mission is
 * re-solved with the real masses (sizing_run with parts.active) into
 * r->closed, checked, and compared.  The best combinations are closed in J
 * order (a battery that runs short, or an ESC picked for the continuous
 * design's current that the heavier real-parts design exceeds, is upsized
 * from the catalogue and the design closed again); when
 * none closes and real parts came out heavier, the search is re-aimed at
 * that mass (thrust, currents and capacity scaled with M^1.5) and run
 * again, at most OPTIM_ROUNDS times.  A design the real parts cannot close
 * is infeasible with a violation, never silently relaxed.  It finally
 * writes the bill of materials.
 *
 * Engine layer (called by engine.c); no I/O.  Reentrant.
 */
#ifndef AEROEVAL_OPTIM_H
#define AEROEVAL_OPTIM_H

#include <stdbool.h>

#include "core/catalog.h"
#include "core/model.h"
#include "core/result.h"
#include "core/spec.h"
#include "sizing/sizing.h"

#define OPTIM_W_DIAMETER     100.0  /* w1, per unit relative diameter error */
#define OPTIM_W_KV           10.0   /* w2, per unit relative KV error */
#define OPTIM_W_PITCH        50.0   /* w3, per unit relative pitch error */
#define OPTIM_PEN_THROTTLE   1000.0 /* Pen_a per unit of hover throttle above the role's */
#define OPTIM_PEN_PITCH      10.0   /* Pen_θ per degree of cruise pitch above ... */
#define OPTIM_PITCH_FREE_DEG 20.0   /* ... this body pitch, ° */
#define OPTIM_W_MASS         10.0   /* Pen_m per unit of motor mass above the scaling law's */
#define OPTIM_PRUNED         1e9    /* J of a pruned branch */
#define OPTIM_LOAD_RPM       0.85   /* full-throttle rpm under load / (KV × V_bus) */
/* Multi-channel (4-in-1) ESC boards sit in the centre stack and run the
 * phase leads out to the motors: practice limits them to small frames
 * whose leads stay short. */
#define OPTIM_STACK_MAX_WHEELBASE_M 0.35
#define OPTIM_ESC_UNRATED_MAX_CELLS 6 /* bus limit of an ESC with no published cell range */
#define OPTIM_CURRENT_MARGIN 1.1    /* motor and ESC rating over the peak current */
#define OPTIM_MAX_SERIES     4      /* most catalogue packs in series ... */
#define OPTIM_MAX_PARALLEL   4      /* ... and in parallel (a locked pack may exceed) */
#define OPTIM_MAX_TRIES      8      /* best combinations closed per round */
#define OPTIM_ROUNDS         3      /* re-aimed searches at the real-parts mass */

/* Why an option was eliminated; the census counts them. */
enum optim_reason {
	OPTIM_OK,
	OPTIM_MOTOR_CELLS,     /* bus outside the motor's cell range */
	OPTIM_MOTOR_CURRENT,   /* max current < 1.1 × peak per motor */
	OPTIM_MOTOR_POWER,     /* max power < peak per motor */
	OPTIM_PROP_OVERLAP,    /* diameter above the overlap limit */
	OPTIM_PROP_RANGE,      /* outside the motor's recommended propellers */
	OPTIM_TIP_MACH,        /* tip Mach > 0.75 at full rpm */
	OPTIM_PROP_RPM,        /* full rpm above the propeller's limit */
	OPTIM_CANNOT_HOVER,    /* hover needs more than the full rpm (θ_hvr >= 1) */
	OPTIM_NO_ESC,          /* no ESC carries the current on this bus */
	OPTIM_NO_BATTERY,      /* no pack combination builds the bus */
	OPTIM_REASON_MAX
};

/* A short name for each reason ("motor current"). */
extern const char *const optim_reason_text[OPTIM_REASON_MAX];

/* The continuous optimum the search aims at, at its own bus (S*). */
struct optim_target {
	double prop_diameter_in;     /* D* */
	double prop_pitch_in;        /* p* */
	double motor_kv;             /* KV* at `cells`, rpm/V */
	int cells;                   /* S*, series cells of the continuous design */
	double motor_peak_current_a; /* per motor at S* */
	double motor_peak_power_w;   /* per motor, electrical */
	double bus_peak_current_a;   /* battery at full throttle at S* */
	double capacity_ah;          /* battery at S*, with the 20 % margin */
	double mass_kg;              /* takeoff mass of the continuous design */
	double motor_mass_kg;        /* m*: one motor by the scaling law */
	double drive_mass_kg;        /* motor + propeller + ESC share per rotor */
	int n_rotors;
	double hover_throttle;       /* θ_role (rpm fraction) */
	double forward_pitch_deg;    /* θ_cr */
	double overlap_limit_in;     /* largest propeller the wheelbase admits */
	double wheelbase_m;          /* W: a 4-in-1 stack board only fits small frames */
	double ct;                   /* thrust coefficient T = C_t ρ n² D⁴ */
	double rho_kg_m3;            /* air density of the mission */
	double sound_m_s;            /* speed of sound at the mission's ambient */
	double v_cell_nom_v;         /* nominal cell voltage of the mission chemistry */
	int cells_lo, cells_hi;      /* bus range searched */
	int cells_floor;             /* lowest bus of the class: searched below S*
	                                only when nothing fits from S* up */
	char chemistry[32];          /* mission chemistry profile name */
};

/* One complete combination. */
struct optim_choice {
	int cells;                              /* bus series cells */
	const struct catalog_motor *motor;
	const struct catalog_prop *prop;        /* NULL for an integrated system */
	const struct catalog_esc *esc;          /* NULL for an integrated system */
	int n_esc;                              /* ESC boards */
	const struct catalog_battery *battery;
	int series_packs, parallel_packs;
	double j_score;
	double hover_throttle;                  /* θ_hvr of this motor + propeller */
};

/* Options examined and eliminated. */
struct optim_census {
	int n_examined;                  /* bus × motor × propeller options */
	int n_fail[OPTIM_REASON_MAX];    /* eliminated, by first failing limit */
	int n_feasible;                  /* complete combinations */
};

/* The part ids a mission locks ("" = free). */
struct optim_locks {
	const char *motor, *prop, *battery, *esc;
};

/* J-score of one motor on one propeller at `cells` (prop pitch 0 = not
 * scored, as for an integrated system, whose mass is then compared with the
 * drive mass); *hover_throttle (may be NULL) gets θ_hvr.  No pruning here. */
double optim_j_score(const struct optim_target *t, int cells, double diameter_in,
                     double pitch_in, double kv, double motor_mass_kg,
                     double *hover_throttle);

/* Hard limits of a motor + propeller on `cells`: OPTIM_OK or the first
 * reason it fails, in enum order.  prop may be NULL for an integrated
 * motor. */
enum optim_reason optim_limits(const struct optim_target *t, int cells,
                               const struct catalog_motor *m,
                               const struct catalog_prop *p);

/* Score every usable motor × propeller × bus, honouring the locks (a locked
 * part is never pruned: its limits are the caller's to report).  Fills
 * choices[0..max_choices) best first (J, then closeness of the bus to S*,
 * then ids: deterministic), the census (may be NULL) and, when cand is not
 * NULL, one res_candidate per usable motor (up to RES_MAX_CANDIDATES; best J
 * over its options, OPTIM_PRUNED if all were pruned) with *n_cand.
 * Returns the number of complete combinations found (may exceed
 * max_choices). */
int optim_rank(const struct optim_target *t, const struct catalog *cat,
               const struct optim_locks *locks, struct optim_choice *choices,
               int max_choices, struct optim_census *census,
               struct res_candidate *cand, int *n_cand);

/* Parts selection on top of a converged custom run of r (spec: the
 * resolved mission, r->mission; p_custom: the parameters of its custom
 * run): ranks, closes the best combinations on real
 * parts until one closes without a failure the continuous design did not
 * have, fills r->motor/prop/battery/esc, r->closed, r->bom, r->candidates,
 * rationale lines and stage "parts" violations.  Unknown locked ids
 * (UNKNOWN_PART) or no complete combination leave parts_selected false.
 * Returns 0, or 3 if a non-finite number was caught. */
int optim_select(const struct mission_spec *spec,
                 const struct sizing_params *p_custom,
                 const struct model_data *md, const struct catalog *cat,
                 struct solve_result *r);

#endif
