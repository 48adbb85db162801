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
#include "core/model.h"
#include "core/result.h"

#define SIZING_TOL_KG        0.001  /* convergence |M(k+1) - M(k)|, kg */
#define SIZING_MAX_ITER      200    /* bounded iteration count */
#define SIZING_RELAX_ALPHA   0.5    /* capacity under-relaxation α */
#define SIZING_CAP_MARGIN    1.2    /* capacity = 1.2 × charge the mission used */
#define SIZING_RATCHET       1.05   /* capacity >= 1.05 × largest failed one */
#define SIZING_RUNAWAY_KG    150.0  /* runaway-divergence flag, kg */
#define SIZING_GAMMA_MIN     0.05   /* goal relaxation floor */
#define SIZING_MARGIN_BISECT 8      /* bisection steps of the thrust relaxation */
#define SIZING_RELAX_MAX_L   0.75   /* a relaxed thrust target keeps L below this */
#define SIZING_MIN_THRUST_MARGIN 0.3 /* relaxation floor: hover throttle 70 %,
                                      * T/W 2.0, the usual minimum for
                                      * attitude authority in gusts */
#define SIZING_SEED_FRACTION 0.60   /* M(0) = payload / 0.60 (eq. altcorrect) */

/* Continuous component laws.  The paper's motor and ESC laws
 * (0.00035 kg per N or A) are ten times lighter than any datasheet, so
 * aeroeval fits them to the published specifications of the parts
 * catalogue instead — component facts, not aircraft facts — by least
 * squares in log space.  Motor mass follows the maximum power and the
 * speed it is delivered at (an electric motor's size is set by its torque,
 * P / ω, so at equal power a faster motor is lighter).  Fit over the 97
 * single-channel non-racing motors (KV < 1500 rpm/V) with a published
 * mass, maximum power, maximum current and KV (ω_max = KV × P_max /
 * I_max): m = 0.00182 P^0.857 ω^-0.174 (kg, W, rad/s), log-sd 0.19 (power
 * alone: 0.20).  ESC mass is linear in current (FETs and copper in
 * parallel): the median mass per amp of the 17 single ESCs, 1.25 g/A (a
 * power-law fit, driven by the 200 A units, extrapolates unphysically
 * beyond them).  The paper's racing factors (C_motor 0.25, C_esc 0.10)
 * then scale them for racing hardware: the catalogue's 13 racing motors
 * (KV >= 1500) weigh 0.22 × the law (median; 0.17-0.40). */
#define SIZING_MOTOR_K          0.00182 /* kg / (W^0.857 (rad/s)^-0.174) */
#define SIZING_MOTOR_EXP_P      0.857   /* motor mass ~ P_max^0.857 */
#define SIZING_MOTOR_EXP_W      0.174   /* ... × ω_max^-0.174 */
#define SIZING_MOTOR_MIN_KG     0.008   /* paper's floor on total motor mass */
#define SIZING_ESC_KG_PER_A     0.00125 /* ESC mass per amp of rating, kg/A */
#define SIZING_ESC_MIN_A        15.0    /* paper: I_ESC,rotor >= 15 A */
#define SIZING_ESC_RATING       1.2     /* ESC rating over the peak current */
#define SIZING_PROP_EXPONENT    2.2    /* blade mass ~ D^2.2 */
#define SIZING_CURRENT_BUDGET_A 60.0   /* bus current budget at 1 kg, A (× sqrt(M)) */
/* Body shell (a mass term the paper leaves open): a minimum-gauge shell
 * enclosing the battery and the electronics.  Volume from the pack and
 * electronics densities at 50 % fill; surface of a box of that volume with
 * a 1.2 shape factor over a cube. */
#define SIZING_PACK_DENSITY_KG_M3 2200.0 /* LiPo/Li-ion pack incl. case */
#define SIZING_AVIONICS_DENSITY_KG_M3 1000.0 /* boards, modules, cables */
#define SIZING_BODY_FILL          0.5    /* fraction of the body that is equipment */
#define SIZING_BODY_SHAPE         1.2    /* body surface over a cube's */
#define SIZING_LOW_FLIGHT_RPM   0.7    /* lowest in-flight rpm / hover rpm (descent) */
#define SIZING_WINDING_RISE_K   40.0   /* winding above ambient at hover, K (assumed) */

/* What the loop stopped on. */
enum sizing_status {
	SIZING_CONVERGED,     /* fixed point found, mission flown */
	SIZING_RUNAWAY,       /* mass above 150 kg: L >= 1 in practice */
	SIZING_MAX_ITERATIONS,/* no convergence in max_iter */
	SIZING_DISCHARGE_FAIL,/* converged mass but the mission cannot be flown */
	SIZING_GATE           /* rejected before the loop (CG, geometry) */
};

/* Real parts fixed by the optimizer (BOM-closed run); 0 = scaling law. */
struct sizing_parts {
	bool active;
	double motor_kg_each;
	double prop_kg_each;
	double esc_kg_total;
	double battery_kg;        /* whole battery, catalogue packs */
	double capacity_ah;       /* its total capacity */
	int cells;                /* its series cells */
	double motor_kv;          /* selected motor KV (0 = unknown) */
	double motor_resistance_ohm; /* winding resistance (0 = unknown) */
};

struct sizing_params {
	/* geometry */
	double wheelbase_m;          /* W */
	int n_rotors;                /* N_r */
	bool coaxial;                /* stacked pairs on N_r/2 arms */
	int airframe_class;          /* enum airframe_class */
	/* air */
	struct atmo_state air;
	double ambient_c;
	/* mission as requested (goal relaxation scales the durations) */
	double duration_s[PHASE_MAX];
	double v_climb_ms;
	double v_forward_ms;
	bool v_auto;
	bool allow_relax;            /* locks.auto_reduce_flight_time */
	/* role */
	double thrust_margin;        /* hover throttle = 1 - margin */
	double thrust_margin_floor;  /* > 0: the margin is the role's default
	                              * target and may be relaxed down to this
	                              * value when the loop cannot close */
	double load_factor;
	double aux_w;
	double added_drag_m2;
	double fwd_drag_mult;
	double cg_shift_m;
	double role_aux_kg;
	double c_motor;
	double c_esc;
	double h_conv_w_m2k;
	double burst_factor;         /* 10 s burst / continuous battery power */
	bool small_platform;         /* racing/small wiring coefficient */
	enum shed_kind shed;
	double drop_mass_kg;
	double drop_ratio;
	double spray_rate_kg_s;      /* 0 = payload / mission time */
	double downwash_cap_ms;      /* agriculture downwash cap, 0 = none */
	double payload_kg;
	/* battery */
	const struct batt_chem *chem;
	double e_spec_wh_kg;         /* may override the chemistry */
	int cells_fixed;             /* 0 = auto */
	int cells_lo, cells_hi;      /* auto range (class table) */
	int pack_count;
	int cycles;
	bool capacity_locked;
	double capacity_locked_ah;
	/* propeller and motor */
	bool prop_locked;
	double prop_diameter_m;
	double prop_pitch_m;
	bool kv_locked;
	double kv;
	int n_blades;
	double prop_kg_per_m22;      /* blade mass coefficient, kg / m^2.2 */
	/* aerodynamics */
	double fom_override;         /* > 0: installed FoM used as is */
	double fom_isolated;
	bool fom_isolated_mode;
	double kappa;
	double interference_c;       /* 0.6 offset, 1.5 under-rotor, 0 folding */
	double eta_drive;
	double cd_h, cd_v;
	double f_scale;
	double ct;
	/* structure */
	double c_body;
	double alpha_w;
	double gamma;
	double lambda;
	double fixed_frame_kg;       /* > 0: frame mass given */
	double avionics_kg;
	double shell_kg_m2;          /* body-shell areal mass */
	double fairing_section_frac; /* arm fairing side over arm length; 0: none */
	/* calibration */
	double packaging_base;
	double wire_coef;
	bool consumer_or_micro;      /* packaging small-cell reduction */
	bool enterprise;             /* packaging enterprise terms */
	/* real parts for the BOM-closed run */
	struct sizing_parts parts;
	/* extras of the final evaluation */
	bool marketing;              /* evaluate_marketing_limits */
	/* numerics */
	int max_iter;
};

/* Size one run.  Fills *out completely (history, masses, phases, trace,
 * sweep, checks are left to feasibility.c) and returns the status.  If the
 * run fails and p->allow_relax, the mission times are scaled down by the
 * largest γ >= 0.05 that closes; out->time_scale records it.  If it still
 * fails and p->thrust_margin_floor > 0 (a role's default thrust target, not
 * one the mission asked for), the thrust margin is lowered to the largest
 * value in [floor, requested) whose loop closes with a Lipschitz constant
 * <= SIZING_RELAX_MAX_L (else to the floor, if that closes at all);
 * out->thrust_margin and out->thrust_margin_requested record both. */
enum sizing_status sizing_run(const struct sizing_params *p, struct res_run *out);

/* State of charge left by the 20 % capacity margin (1 - 1/1.2). */
double sizing_reserve_soc(void);

/* The endurance explorer of run, a converged or capacity-limited
 * sizing_run() of p (run->fixed set): hover endurance and takeoff mass at
 * RES_MAX_ENDURANCE capacity scales from 0.25 to 3, the mass loop re-closed
 * at each locked capacity, into run->endurance_*.  An analysis of the
 * design, not part of it: the outputs that show it ask for it. */
void sizing_explore(const struct sizing_params *p, struct res_run *run);

/* The altitude-corrected seed of eq. (altcorrect), kg. */
double sizing_seed_kg(double payload_kg, double rho_kg_m3);

/* Continuous motor mass law (see the constants above), kg per motor. */
double sizing_motor_kg(double power_max_w, double omega_max_rad_s);

/* Series cells for a peak battery power at mass_kg: the smallest count
 * keeping the peak current within 60 A × sqrt(M / 1 kg), clamped to
 * [lo, hi]. */
int sizing_auto_cells(double peak_power_w, double mass_kg, double v_nom_cell,
                      int lo, int hi);

/* Propeller pitch for hover inflow: blade angle at 75 % radius =
 * inflow angle + 4° incidence, m. */
double sizing_pitch_m(double diameter_m, double induced_ms, double rps);

/* Body-shell surface, m²: the box around the pack and the electronics
 * (see SIZING_BODY_*) plus, where the class moulds its arms
 * (fairing_section_frac c > 0), a hollow fairing of side c·L over each
 * arm of length L: 4c·L² per arm. */
double sizing_shell_area_m2(double battery_kg, double avionics_kg, int n_arms,
                            double arm_length_m, double fairing_section_frac);

#endif
