/* sizing.h — the Banach fixed-point mass loop (paper §II-D, Module 3).
 *
 * M = f(M) = payload + battery(M) + frame(M) + propulsion(M) + ...  Each
 * iteration evaluates every subsystem at the current takeoff mass, flies the
 * mission in the discharge simulation to find the capacity it really needs,
 * and under-relaxes that capacity (α = 0.5, 20 % margin) with a ratchet
 * above the largest capacity that already failed.  The loop stops at a 1 g
 * change, on a runaway above 150 kg, or at max_iter.  Everything it needs is
 * in struct sizing_params, already resolved from the mission, the role and
 * the class by engine.c; this module makes no decision about defaults.
 */
#ifndef AEROEVAL_SIZING_H
#define AEROEVAL_SIZING_H

#include <stdbool.h>

#include "physics/atmo.h"
#include "physics/batt.h"
#include "physics/duty.h"
#include "physics/mission.h"
#include "physics/role.h"
#include "spec/model.h"
#include "result/result.h"
#include "sizing/params.h"

#define SIZING_TOL_KG        0.001  /* convergence |M(k+1) - M(k)|, kg */
#define SIZING_MAX_ITER      200    /* bounded iteration count */
#define SIZING_RELAX_ALPHA   0.5    /* capacity under-relaxation α */
#define SIZING_CAP_MARGIN    1.2    /* capacity = 1.2 × charge the mission used */
#define SIZING_RATCHET       1.05   /* capacity >= 1.05 × largest failed one */
#define SIZING_RESERVE_TOL   0.002  /* a sized battery lands on its reserve to
                                       the discharge's integration accuracy */
#define SIZING_RUNAWAY_KG    150.0  /* runaway-divergence flag, kg */
#define SIZING_GAMMA_MIN     0.05   /* goal relaxation floor */
#define SIZING_SEED_FRACTION 0.60   /* M(0) = payload / 0.60 (eq. altcorrect) */
/* Steps of a final, recorded flight: twice the loop's, so a limit the
 * loop's steps hide shows; each phase's count rounds down and is floored
 * at 4, so the trace holds at most SIZING_FINAL_STEPS + 13 samples. */
#define SIZING_FINAL_STEPS   60
_Static_assert(SIZING_FINAL_STEPS + 13 <= RES_MAX_TRACE, "trace buffer too small");

/* Continuous component laws, fitted to the published specifications of
 * the parts catalogue (component facts, not aircraft facts; least squares
 * in log space; docs/model.md).  Motor mass follows the maximum power and
 * the speed it is delivered at (an electric motor's size is set by its
 * torque, P / ω): over the 153 single-channel motors below 1500 KV with a
 * published mass, maximum power, current and KV (ω_max = KV × P_max /
 * I_max), m = 0.0961 P^0.762 ω^-0.667 (kg, W, rad/s), log-sd 0.28 — close
 * to m ∝ torque^0.7.  The catalogue's 57 racing motors (KV >= 1500) weigh
 * 0.54 of the law (median), the racing factor C_motor of data/roles.json.
 * ESC mass is linear in current (FETs and copper in parallel): the median
 * of the 101 single ESCs with a plausible mass per amp, 1.10 g/A. */
#define SIZING_MOTOR_K          0.0961  /* kg / (W^0.762 (rad/s)^-0.667) */
#define SIZING_MOTOR_EXP_P      0.762   /* motor mass ~ P_max^0.762 */
#define SIZING_MOTOR_EXP_W      0.667   /* ... × ω_max^-0.667 */
#define SIZING_MOTOR_MIN_KG     0.008   /* paper's floor on total motor mass */
#define SIZING_ESC_KG_PER_A     0.00110 /* ESC mass per amp of rating, kg/A */
#define SIZING_ESC_MIN_A        15.0    /* paper: I_ESC,rotor >= 15 A */
#define SIZING_ESC_RATING       1.2     /* ESC rating over the peak current */
#define SIZING_PROP_EXPONENT    2.2    /* blade mass ~ D^2.2 */
#define SIZING_CURRENT_BUDGET_A 60.0   /* bus current budget at 1 kg, A (× sqrt(M)) */
#define SIZING_LOW_FLIGHT_RPM   0.7    /* lowest in-flight rpm / hover rpm (descent) */
#define SIZING_WINDING_RISE_K   40.0   /* winding above ambient at hover, K (assumed) */
#define SIZING_BURST_ORDINARY   2.0    /* an ordinary pack's 10 s burst over its
                                          continuous power (data/roles.json) */

/* What the loop stopped on. */
enum sizing_status {
	SIZING_CONVERGED,     /* fixed point found, mission flown */
	SIZING_RUNAWAY,       /* mass above 150 kg: L >= 1 in practice */
	SIZING_MAX_ITERATIONS,/* no convergence in max_iter */
	SIZING_DISCHARGE_FAIL,/* converged mass but the mission cannot be flown */
	SIZING_GATE           /* rejected before the loop (CG, geometry) */
};


/* Size one run.  Fills *out completely (history, masses, phases, trace,
 * sweep, checks are left to feasibility.c) and returns the status.  The
 * thrust target (p->thrust_margin) is a requirement: it is never lowered.
 * If the run fails and p->allow_relax (the mission's own opt-in), the
 * mission times are scaled down by the largest γ >= 0.05 that closes;
 * out->time_scale records it. */
enum sizing_status sizing_run(const struct sizing_params *p, struct res_run *out);

/* The phase durations of p after goal relaxation γ (d: PHASE_MAX), and
 * their sum. */
void sizing_durations(const struct sizing_params *p, double gamma_time,
                      double *d);
double sizing_total_duration(const struct sizing_params *p, double gamma_time);

/* The mission of p at goal relaxation γ laid out by its role's duty
 * profile (physics/duty.h), flown at these climb and forward speeds: what
 * the continuous design and the real-parts flight both fly. */
void sizing_plan(const struct sizing_params *p, double gamma_time,
                 double v_climb_ms, double v_fwd_ms, struct duty_plan *out);

/* State of charge left by the 20 % capacity margin (1 - 1/1.2). */
double sizing_reserve_soc(void);

/* The endurance explorer of run, a converged or capacity-limited
 * sizing_run() of p (run->fixed set): hover endurance and takeoff mass at
 * RES_MAX_ENDURANCE capacity scales from 0.25 to 3, the mass loop re-closed
 * at each locked capacity, into run->endurance_*.  An analysis of the
 * design, not part of it: the outputs that show it ask for it. */
void sizing_explore(const struct sizing_params *p, struct res_run *run);

/* The map f evaluated once at a given takeoff mass (open loop), with the
 * battery the mission needs at that mass: how the model's parts compare
 * with a real aircraft's when both fly at its real mass. */
struct sizing_open {
	struct res_mass mass;        /* every item of f(M); total_kg = f(M) */
	double dry_kg;               /* f(M) less payload and battery */
	double capacity_ah;          /* the battery's capacity */
	int cells;                   /* its series cells */
	bool flown;                  /* the mission flew on it */
	bool settled;                /* capacity and charge agree */
	double prop_frac;            /* the propeller's share of the largest
	                                the wheelbase admits (engine_at_mass) */
};

/* Fills *out at mass_kg; true when the capacity settled and the mission
 * flew (bounded: at most 60 evaluations). */
bool sizing_at_mass(const struct sizing_params *p, double mass_kg,
                    struct sizing_open *out);

/* The forward check: the endurance of an aircraft p describes, its
 * battery locked (a published pack), at its takeoff mass mass_kg, flown
 * as makers quote it: to an empty pack (BATT_SOC_MIN), without the
 * mission's reserve, in hover and in level flight at v_forward_ms (0: the
 * minimum-power speed).  False when the pack cannot carry the aircraft at
 * all (voltage collapse at the first step). */
struct sizing_endurance {
	double hover_s;              /* hover to empty */
	double forward_s;            /* level flight to empty */
	double forward_speed_ms;     /* at this speed */
	double hover_power_w;        /* electrical, at mass_kg */
	double forward_power_w;
	double prop_diameter_m;      /* the rotor flown */
};
bool sizing_endurance_at_mass(const struct sizing_params *p, double mass_kg,
                              double v_forward_ms, struct sizing_endurance *out);

/* The altitude-corrected seed of eq. (altcorrect), kg. */
double sizing_seed_kg(double payload_kg, double rho_kg_m3);

/* Auxiliary power at a design mass: the role's default (paper Table
 * roles) describes the gimbal, sensors and links of the paper's case-study
 * aircraft of that role (p->aux_ref_kg: data/roles.json); the equipment
 * those loads power grows as M^(2/3) (airframe.h), so a role default
 * scales with it (a 249 g camera drone draws a few watts, not the 22.5 W
 * of a 5.6 kg one).  A value the mission gave is used as is. */
double sizing_aux_w(const struct sizing_params *p, double design_mass_kg);

/* The mission model's air, layout, drag and auxiliary load for p at a
 * design mass: what the continuous design and the real-parts flight share
 * (each sets its own rotor and drive). */
void sizing_mission_model(const struct sizing_params *p, double design_mass_kg,
                          struct mission_model *m);

/* Continuous motor mass law (see the constants above), kg per motor. */
double sizing_motor_kg(double power_max_w, double omega_max_rad_s);

/* Propeller pitch for hover inflow: blade angle at 75 % radius =
 * inflow angle + 4° incidence, m. */
double sizing_pitch_m(double diameter_m, double induced_ms, double rps);

/* The result's name for a mission-model envelope limit. */
enum res_limit sizing_limit(enum mission_limit l);


#endif
