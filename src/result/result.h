/* result.h — everything a solve produces, as plain values.
 *
 * The engine fills a struct solve_result; result.json, bom.csv and the
 * dossier only read it (const).  Units are SI unless the member name says
 * otherwise (capacity_mah, temp_c, *_deg, *_in, *_mm, *_rpm).  Every double
 * here is finite: the engine checks before it stores.
 * Who may include it: everyone (no I/O library types).
 */
#ifndef AEROEVAL_RESULT_H
#define AEROEVAL_RESULT_H

#include <stdbool.h>

#include "spec/spec.h"

#define RES_MAX_HISTORY    256  /* mass-loop iterations kept */
#define RES_MAX_TRACE      80   /* discharge samples kept (FINAL_STEPS + 13) */
#define RES_MAX_SWEEP      64   /* power-vs-speed points (1..30 m/s by 0.5) */
#define RES_MAX_ENDURANCE  32   /* endurance-explorer points */
#define RES_MAX_CHECKS     40   /* every row of result/checks.h */
#define RES_MAX_VIOLATIONS 24
#define RES_MAX_FIXES      3
#define RES_MAX_RATIONALE  48
#define RES_MAX_BOM        32
#define RES_MAX_CANDIDATES 512  /* motors scored for the crosshair figure */
#define RES_ID_MAX         128  /* a catalogue id, NUL included (CATALOG_ID_MAX) */
#define RES_TEXT           256
#define RES_BASIS          96   /* what sets a check's limit, "2 × XT60, 60 A" */

/* Mission phases, in the order they are flown. */
enum res_phase_id { PHASE_CLIMB, PHASE_FORWARD, PHASE_HOVER, PHASE_MAX };
extern const char *const res_phase_name[PHASE_MAX]; /* "climb", "forward", "hover" */

/* What ends a flight envelope figure (top speed, maximum climb). */
enum res_limit {
	RES_LIMIT_NONE,           /* not worked out */
	RES_LIMIT_INFLOW,         /* the propeller's full thrust at the inflow
	                             through its disk no longer carries weight
	                             and drag (prop.h, C_T(J)) */
	RES_LIMIT_PITCH,          /* the 35° body-pitch limit */
	RES_LIMIT_BOUND,          /* the search's bound, not a physical limit */
	RES_LIMIT_MAX
};
/* "none", "propeller_inflow", "pitch_limit", "search_bound" */
extern const char *const res_limit_name[RES_LIMIT_MAX];

/* Mass breakdown; the items sum to total_kg. */
struct res_mass {
	double payload_kg;      /* payload at takeoff */
	double battery_kg;      /* packs incl. packaging */
	double frame_kg;        /* centre plates, spar joints (C_body share) */
	double arm_kg;          /* arm tubes */
	double motor_kg;        /* all motors */
	double prop_kg;         /* all propellers */
	double esc_kg;          /* all ESCs */
	double wiring_kg;       /* power harness */
	double avionics_kg;     /* FC, GNSS, radios */
	double role_aux_kg;     /* role hardware (mounts, pump, release) */
	double other_kg;        /* body shell, landing gear, mounts (γ share) */
	double total_kg;        /* takeoff mass */
};

/* One flight phase at the converged design (takeoff mass). */
struct res_phase {
	double duration_s;        /* approved duration */
	double speed_ms;          /* climb or forward speed, 0 in hover */
	double thrust_per_rotor_n;
	double shaft_power_w;     /* all rotors */
	double power_w;           /* electrical at the battery, incl. aux */
	double current_a;         /* mean battery current */
	double energy_wh;         /* drawn from the battery in this phase */
	double rpm;               /* rotor speed */
	double throttle;          /* rpm / rpm at full throttle */
	double pitch_deg;         /* body pitch (forward) */
	double tip_mach;          /* rotor tip Mach */
};

/* The duty cycle a run flew (physics/duty.h): its segments grouped by
 * kind, and what the role's profile made of the mission. */
#define RES_MAX_DUTY_GROUPS 10
#define RES_DUTY_NAME       40
#define RES_DUTY_SOURCE     640   /* MODEL_DUTY_SOURCE */

struct res_duty_group {
	char name[RES_DUTY_NAME]; /* "spraying pass" */
	int phase;                /* enum res_phase_id its time counts in */
	int count;                /* how many the mission flew */
	double duration_s;        /* their time together */
	double fraction;          /* race pieces: of the full-throttle power */
	double power_w;           /* mean battery power (energy / time) */
	double current_a;         /* mean battery current */
	double energy_wh;         /* drawn from the battery */
};

struct res_duty {
	int kind;                 /* enum duty_kind (spec/model.h) */
	char source[RES_DUTY_SOURCE]; /* where the profile's numbers come from */
	int n_groups;
	struct res_duty_group group[RES_MAX_DUTY_GROUPS];
	double full_throttle_power_w; /* the design's, at the battery */
	double mean_power_w;      /* the flight's energy over its time */
	double peak_power_w;      /* the highest power a step drew */
	/* race */
	int n_laps;
	double lap_s;
	double race_s;            /* the laps' time */
	double race_mean_power_w; /* their energy over their time */
	double race_mean_current_a;
	double lap_mean_fraction; /* of the full-throttle power, as flown */
	double lap_peak_fraction;
	/* spray sorties */
	int n_passes, n_turns;
	double swath_length_m, pass_m, turn_s, transit_m;
	double spray_s, spray_rate_kg_s, tank_shed_kg;
	/* out and back */
	double drop_time_s;       /* < 0: no release */
	double drop_mass_kg;
	double landing_payload_kg;/* payload at touchdown */
};

/* One sample of the discharge simulation. */
struct res_sample {
	double t_s;          /* time since takeoff */
	double soc;          /* state of charge, 0..1 */
	double v_oc_v;       /* pack open-circuit voltage */
	double v_term_v;     /* pack terminal voltage */
	double current_a;    /* battery current */
	double power_w;      /* battery power */
	double temp_c;       /* pack temperature */
	double mass_kg;      /* aircraft mass (falls with drop/spray) */
	int phase;           /* enum res_phase_id */
};

/* One constraint of the checks table.  The text fields of checks and
 * violations point to string literals (the one table of checks,
 * result/checks.c): static, so results copy freely, and a trial closing
 * writes no text. */
struct res_check {
	const char *code;    /* "THERMAL_RUNAWAY" (result/checks.h) */
	const char *name;    /* "Battery peak temperature" */
	const char *unit;    /* "°C" */
	const char *condition; /* "full-throttle burst, 10 s" */
	char basis[RES_BASIS]; /* what sets the limit, "" when the name says it */
	double value;        /* achieved */
	double limit;        /* allowed */
	bool upper;          /* true: value <= limit passes; false: value >= limit */
	double margin;       /* (limit - value)/limit or (value - limit)/limit */
	bool pass;
	bool sized;          /* the design is sized to this limit by construction */
	bool advisory;       /* judged, but a failure does not reject the design
	                        (the continuous reference's resonances) */
};

struct res_violation {
	const char *run;                    /* "baseline", "custom", "closed" */
	const char *stage;                  /* "feasibility", "mass_loop", "discharge", "parts" */
	const char *code;                   /* stable machine code, e.g. "PROP_OVERLAP" */
	char message[RES_TEXT];             /* plain sentence with numbers */
	char fixes[RES_MAX_FIXES][RES_TEXT];/* suggested fixes */
	int n_fixes;
};

/* Continuous optimum the parts search aims at. */
struct res_optimum {
	double prop_diameter_in;
	double prop_pitch_in;
	double motor_kv;          /* rpm/V */
	double motor_mass_kg;     /* one motor, scaling law */
	double motor_peak_current_a;
	double motor_peak_power_w;
};

/* Where a run's mass loop closed: enough to evaluate its design again. */
struct res_fixed_point {
	double mass_kg;           /* M* */
	double capacity_ah;       /* C* */
	double arm_width_m;       /* the arm diameter the rotors saw */
	double time_scale;        /* γ the loop flew */
	int cells;                /* series cells */
};

/* Operating points of a design on real parts, in the layout eCalc users
 * know: hover and climb and cruise at the mission's takeoff mass, full
 * throttle at the nominal pack voltage. */
enum res_op_id { OP_HOVER, OP_CLIMB, OP_CRUISE, OP_FULL, OP_MAX };
extern const char *const res_op_name[OP_MAX]; /* "hover", "climb", "cruise", "full throttle" */

/* One operating point (per motor unless said otherwise). */
struct res_op {
	bool valid;
	double thrust_n;          /* one rotor */
	double rpm;
	double throttle;          /* motor voltage / available bus voltage, 0..1 */
	double motor_current_a;
	double motor_voltage_v;   /* at the motor terminals */
	double power_in_w;        /* electrical, one motor */
	double power_shaft_w;     /* one motor */
	double motor_efficiency;  /* shaft / electrical, (0, 1] */
	double g_per_w;           /* thrust in grams per electrical watt */
	double winding_temp_c;    /* estimated (motor.h) */
	double tip_mach;
	double battery_current_a; /* whole aircraft */
	double bus_voltage_v;     /* pack terminal voltage under this load */
	double c_load;            /* battery current over capacity, 1/h */
	double electrical_w;      /* whole aircraft at the pack */
};

/* What a design on real parts can do beyond its mission. */
struct res_perf {
	bool valid;               /* computed (the design flies on real parts) */
	struct res_op op[OP_MAX];
	double hover_time_s;      /* hover at takeoff mass down to the reserve */
	double mixed_time_s;      /* the mission's phase mix down to the reserve */
	double full_throttle_time_s; /* full throttle down to the reserve */
	double max_speed_ms;      /* level flight within the full thrust at its
	                             inflow and 35° pitch */
	enum res_limit max_speed_limit; /* which of them ends it */
	double max_climb_ms;      /* vertical, at full throttle, the motor and
	                             propeller at the climb's inflow */
	enum res_limit max_climb_limit; /* what ends it */
	double max_climb_rpm;     /* the rotor's speed at full throttle in
	                             that climb (above the static full-throttle
	                             rpm: the propeller unloads) */
	double max_tilt_deg;      /* bank holding altitude at full throttle */
	double spare_payload_kg;  /* more payload before T/W falls below the target */
	double throttle_needed;   /* the highest throttle the mission needs
	                             (above 1: out of reach) */
	double sustained_motor_current_a; /* the highest motor current of a
	                             phase the mission flies (hover, climb,
	                             cruise), for the continuous rating */
	int motor_out_rotors;     /* rotors counted with one out (0: a quad) */
	double motor_out_ratio;   /* their full thrust over the weight */
	bool motor_out_holds;     /* >= 1: it holds altitude and lands */
	double motor_resistance_ohm; /* R used (published or estimated) */
	double motor_no_load_a;   /* I0 used */
	bool motor_r_estimated;   /* R or I0 came from motor.h's fit */
	double prop_ct, prop_cp;  /* static coefficients used */
	double prop_fom;          /* the propeller's own static figure of merit,
	                             before κ and k_int (fom_installed after) */
	bool prop_coeffs_measured;/* published, not prop.h's fit */
	double landing_soc;       /* state of charge at touchdown */
};

/* One sized run (baseline, custom, or the BOM-closed custom design). */
struct res_run {
	bool ran;                 /* false if the gate stopped it before the loop */
	bool feasible;            /* every check passed */
	bool converged;           /* mass loop met the 1 g tolerance */
	double prop_frac;         /* an unlocked propeller's diameter over the
	                             largest the wheelbase admits (engine.c) */
	/* Why the rotor is not the largest the wheelbase admits, when it is
	 * not (engine.c): the same mission on the largest rotor. */
	struct res_largest_rotor {
		bool tried;           /* the search flew it */
		bool passes;          /* ... and it met every requirement */
		double mass_kg;       /* its takeoff mass (when it passes) */
		double motor_kg;      /* its motors */
		double battery_kg;    /* its battery */
		char fails[RES_TEXT]; /* the first check it failed, else "" */
	} largest;
	char termination[RES_TEXT]; /* why the discharge ended / the loop stopped */
	int iterations;
	double tolerance_kg;      /* the loop's convergence tolerance |ΔM| */
	int n_history;
	double history_kg[RES_MAX_HISTORY];   /* takeoff mass per iteration */
	double lipschitz;         /* dF/dM at the fixed point */
	double time_scale;        /* goal relaxation γ (1 = as requested) */
	double thrust_margin;     /* the thrust requirement: T/W = 1 / (1 - margin)²
	                             with the largest payload aboard */
	double aux_power_w;       /* auxiliary power flown (sizing_aux_w()) */
	struct res_fixed_point fixed;

	struct res_mass mass;

	/* battery */
	char chemistry[32];
	int cell_count;           /* series cells */
	int pack_count;           /* packs in parallel */
	double capacity_mah;      /* total at the terminals */
	double energy_wh;         /* nominal stored energy */
	double packaging_factor;  /* η_pkg */
	bool battery_power_binds; /* sized by power (sustained or burst), not energy */
	double nominal_voltage_v;

	/* mission */
	struct res_phase phase[PHASE_MAX];
	struct res_duty duty;     /* the duty cycle flown (the profile's segments) */
	double approved_time_s[PHASE_MAX];
	double flight_time_s;     /* total approved mission time */
	double hover_endurance_s; /* hover-only endurance to the reserve */
	double hover_power_w;     /* electrical, hovering at the takeoff mass */
	double hover_power_shed_w; /* ... at the lightest mass flown (after a
	                             drop or the spray; = hover_power_w else) */
	double marketing_endurance_s; /* best case (0 unless requested) */
	double optimal_speed_ms;  /* forward speed used (auto: minimum power) */
	double v_min_power_ms;    /* minimum-power speed of the sweep */
	double v_max_ms;          /* highest forward speed the thrust margin allows */
	enum res_limit v_max_limit; /* what ends it: the thrust at the inflow,
	                             the pitch limit */
	double climb_limit_ms;    /* the fastest climb the thrust allows, flown
	                             instead of the mission's when that is
	                             beyond it; 0 when the mission's is within */
	int n_sweep;
	double sweep_v_ms[RES_MAX_SWEEP];
	double sweep_power_w[RES_MAX_SWEEP];

	/* propulsion and aero */
	double thrust_to_weight;
	double hover_throttle;
	double forward_pitch_deg;
	double disk_loading_n_m2;
	double downwash_ms;
	double fom_installed;
	double interference;      /* k_int */
	double kappa;             /* installation penalty κ the figure of merit
	                             was divided by (1: not applied, the FoM
	                             isolated or given by the mission) */
	double reynolds_tip;
	double rpm_hover;
	double rpm_peak;
	double tip_mach_peak;
	double overlap_limit_in;  /* largest propeller the wheelbase allows */
	double peak_power_w;      /* battery power at full throttle */
	double peak_current_a;    /* battery current at full throttle */
	double peak_c_rate;
	struct res_optimum opt;

	/* structure */
	double arm_length_m;
	double arm_outer_diameter_mm;
	double arm_wall_thickness_mm;
	double arm_stress_mpa;
	double arm_stress_allow_mpa;
	double arm_natural_frequency_hz;
	double blade_pass_frequency_hz; /* at full-throttle rpm */
	double blade_pass_low_hz;  /* at the lowest in-flight rpm (0.7 × hover) */
	double resonance_margin;   /* >= 0: mode clear of the band (structure.h) */
	double arm_tip_mass_kg;    /* motor(s) + propeller(s) at one arm tip */
	const char *arm_sized_by;  /* "strength", "stiffness (motor tilt)", ... */
	double arm_safety_factor;  /* fatigue strength / root stress at the design load */
	double arm_tilt_full_deg;  /* motor tilt from arm bending at full thrust */
	double arm_deflection_full_mm; /* arm tip deflection at full thrust */
	double arm_torsion_mpa;    /* shear stress from the full-throttle torque */
	double arm_torsion_allow_mpa;
	double rate_bandwidth_hz;  /* the rate loop's bandwidth for the propeller
	                              (structure.h) */
	double rev_band_low_hz;    /* once-per-revolution band of the steady flight: */
	double rev_band_high_hz;   /* hover at the lightest mass flown to the
	                              fastest sustained phase */
	bool arm_wall_floor_binds;
	bool min_fraction_binds;

	/* thermal and electrical */
	double max_battery_temp_c;
	double thermal_margin_c;  /* 60 - peak */
	double min_terminal_voltage_v;
	double voltage_floor_v;
	double end_soc;
	double reserve_soc;       /* SOC the 20 % capacity margin leaves (1 - 1/1.2) */
	double winding_temp_c;    /* motor winding at hover (ambient + 40 K, assumed) */
	double motor_winding_resistance_ohm; /* R_m(T) of the real motor, 0 = unknown */
	double motor_copper_loss_w; /* per motor at hover, 0 = unknown */
	int n_trace;
	struct res_sample trace[RES_MAX_TRACE];

	/* endurance explorer: flight time vs capacity scale */
	int n_endurance;
	double endurance_scale[RES_MAX_ENDURANCE];
	double endurance_time_s[RES_MAX_ENDURANCE];
	double endurance_mass_kg[RES_MAX_ENDURANCE];
	double endurance_inflection_scale; /* where d(time)/d(scale) falls below half its initial value */

	struct res_perf perf;     /* real-parts performance (the design of record) */

	int n_checks;
	struct res_check checks[RES_MAX_CHECKS];
};

/* One element of the design of record's power path as the parts kit
 * sized it (parts/kit.c, issue 33): its ratings, per unit, and the
 * currents through one unit, for the checks and the report to compare.
 * A rating of 0 is not published (an allowance, or a part without one). */
struct res_power_rating {
	bool present;             /* the aircraft has this element */
	char what[96];            /* the part or the run: "XT60-M (male half,
	                             harness side)", "2 x 8 AWG" */
	int count;                /* units sharing the current in parallel
	                             (pairs per pack x packs in parallel) */
	double sized_for_a;       /* the full-throttle current through one unit
	                             the kit was sized for */
	double full_a;            /* the full-throttle current through one unit
	                             as the record flies (its burst) */
	double sustained_a;       /* the highest sustained mission current
	                             through one unit */
	double continuous_a;      /* one unit's continuous rating (a wire's
	                             chassis-wiring ampacity) */
	double burst_a;           /* one unit's burst rating; 0 none */
	double burst_s;           /* how long that burst rating holds; 0 not
	                             published */
	double rated_full_a;      /* the rating that holds for the record's
	                             full-throttle burst: the burst rating when
	                             it holds at least burst_need_s, else the
	                             continuous one (parts/compat.c) */
};

/* The power path, pack to motor.  Full throttle is a burst of
 * burst_need_s; each element is rated per unit. */
struct res_power_path {
	double burst_need_s;      /* the full-throttle burst the ratings are
	                             read for (PERF_FULL_THROTTLE_S) */
	struct res_power_rating connector;    /* one per pack: the pack's share */
	struct res_power_rating power_module; /* the whole current (absent on
	                                         classes that buy none) */
	struct res_power_rating harness_main; /* packs to distribution: the
	                                         whole current */
	struct res_power_rating harness_pack; /* each pack's lead: its share */
	struct res_power_rating harness_arm;  /* each rotor's run along its
	                                         arm: one motor's current */
	struct res_power_rating esc;          /* one channel: one motor */
};

/* A catalogue part chosen by the optimizer. */
struct res_part {
	bool chosen;
	char id[RES_ID_MAX];
	char manufacturer[64];
	char part_number[128];
	char description[160];
	int qty;
	double unit_mass_kg;
	double unit_price_usd;    /* 0 = unknown */
	char price_date[12];      /* of the price snapshot, "" unknown */
	char source_url[160];     /* the maker's page the facts come from, or "" */
	double j_score;
};

/* One BOM line (catalogue or custom). */
struct res_bom_line {
	int item;
	int qty;
	char category[24];        /* motor, propeller, battery, esc, custom */
	char manufacturer[64];
	char part_number[128];
	char description[160];
	double unit_mass_kg;
	double total_mass_kg;
	double unit_price_usd;    /* 0 = unknown */
	double total_price_usd;
	char price_date[12];      /* of the price snapshot, "" unknown */
	char source_url[160];     /* the maker's page, "" for custom lines */
	char catalogue_id[RES_ID_MAX]; /* "" for custom lines */
};

/* A motor scored by the optimizer (crosshair figure). */
struct res_candidate {
	char id[RES_ID_MAX];
	double kv;
	double mass_kg;
	double j_score;           /* 1e9 when pruned */
	bool feasible;
};

/* The accuracy the model reached on its calibration cohort, as shipped in
 * data/calibration.json (calibrate.c), and the prediction interval it
 * puts on a takeoff mass: for the dossier's cover and its assumptions. */
struct res_accuracy {
	bool valid;               /* the calibration carries these figures */
	bool pack_locked;         /* measured with the packs locked (a mission
	                           * whose battery is locked), else sized from
	                           * the endurance */
	int n_rows;               /* cohort rows the figures come from */
	double mape;              /* leave-one-out takeoff-mass MAPE, fraction */
	double battery_mape;      /* leave-one-out battery-mass MAPE, fraction */
	double level;             /* the interval's nominal coverage, e.g. 0.90 */
	double ratio_lo, ratio_hi; /* actual/predicted bounds at that level, for
	                            * this mission's class */
	int interval_rows;        /* leave-one-out residuals behind them */
	double coverage;          /* the share of cohort rows inside (LOO) */
	double design_coverage;   /* ... of their own design intervals */
};

/* A prediction interval on a takeoff mass. */
struct res_interval {
	bool valid;
	double level;             /* nominal coverage */
	double lo_kg, hi_kg;
};

/* The intervals the design of record carries (engine.c, PRODUCT "The
 * prediction intervals on a design"), each at the calibration's level. */
struct res_design_intervals {
	bool from_parts;          /* the mass one from the estimated lines of
	                             the bill of materials; else the model's
	                             error through the loop gain */
	double estimated_kg;      /* the mass the model estimates (from_parts) */
	double loop_gain;         /* 1 / (1 - L) used (not from_parts) */
	bool power_valid;         /* hover power and endurance, from the
	                             forward check's spread */
	double hover_power_lo_w, hover_power_hi_w, hover_power_w;
	double endurance_lo_s, endurance_hi_s, endurance_s;
};

/* A mission beyond what its geometry and class can reach (engine.c): what
 * is reachable instead, and the limit that binds the mission as asked. */
struct res_ceiling {
	bool valid;               /* the mission as asked does not size */
	char binds_code[32];      /* its first violation's code ("MASS_RUNAWAY") */
	char binds[RES_TEXT];     /* ... and its message */
	double min_time_scale;    /* the shortest share of the mission tried */
	bool endurance_found;     /* a shorter flight sizes: */
	double time_scale;        /* the largest share of every phase that does */
	double flight_time_s;     /* that flight */
	double hover_endurance_s; /* its aircraft's hover endurance to reserve */
	double mass_kg;           /* its aircraft (r->custom when replaced) */
	bool payload_found;       /* a lighter payload flies the mission as asked: */
	double max_payload_kg;    /* the largest that does */
	double mass_at_payload_kg;/* its aircraft */
	bool shown;               /* r->custom holds the ceiling design */
};

struct solve_result {
	struct mission_spec mission;   /* fully resolved input */
	char input_sha256[65];
	char catalogue_sha256[65];

	struct res_run baseline;
	struct res_run custom;
	struct res_mass role_overhead; /* custom - baseline */

	bool parts_selected;           /* the optimizer ran and found parts */
	struct res_part motor, prop, battery, esc;
	int battery_series_packs;      /* catalogue packs in series */
	int battery_parallel_packs;    /* catalogue packs in parallel */
	struct res_power_path power_path; /* the design of record's connectors,
	                                  power module, harness and ESC: ratings
	                                  and currents (parts/bom.c fills it;
	                                  the full-throttle checks read it) */
	struct res_run closed;         /* custom run re-solved with real part masses */
	int n_bom;
	struct res_bom_line bom[RES_MAX_BOM];
	double bom_mass_kg;            /* the aircraft's parts (not the payload) */
	double bom_price_usd;          /* the priced lines' sum: a lower bound */
	int bom_parts_lines;           /* lines of parts (the payload line aside) */
	int bom_priced_lines;          /* of those, with a price */
	int n_candidates;
	struct res_candidate candidates[RES_MAX_CANDIDATES];

	bool feasible;
	/* violations keep run, stage and code only, no text, and the
	 * closed run no figure the search does not compare (perf_fly()'s
	 * trial): the parts search's trial closings, of which one is kept
	 * (and closed again) */
	bool terse;
	int n_violations;
	struct res_violation violations[RES_MAX_VIOLATIONS];
	int n_rationale;
	char rationale[RES_MAX_RATIONALE][RES_TEXT];
	char internal_error[RES_TEXT]; /* what broke when the solve returns 3 */
	struct res_accuracy accuracy;  /* of the model, from the calibration */
	struct res_interval mtow_interval; /* on the takeoff mass of record */
	struct res_design_intervals intervals; /* how, and the other two */
	struct res_ceiling ceiling;    /* when the mission is beyond reach */
	bool skip_ceiling;             /* input: set by a caller that only
	                                  classifies designs (the sensitivity
	                                  sweeps, validate, the property
	                                  tests): no ceiling search */
};

/* The tightest passing check of a run that is not at its limit by
 * construction (arm stress, propeller diameter, mission energy), or NULL:
 * what binds the design.  The rationale and the dossier cover both name it. */
const struct res_check *res_tightest_check(const struct res_run *run);

/* The lightest mass a run flies (its trace: a drop or a spray sheds
 * payload on the way); its takeoff mass when it sheds none. */
double res_lightest_mass_kg(const struct res_run *run);

/* Zero all of a run but its trace samples, which are most of its size
 * and of which only the first n_trace are ever read. */
void res_run_clear_untraced(struct res_run *run);

/* Append a plain-language sentence to the design rationale (r may be
 * NULL; a full list keeps its first RES_MAX_RATIONALE lines). */
void res_rationale(struct solve_result *r, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

/* The design of record (PRODUCT "The design of record"): the aircraft
 * the bill of materials builds when the parts search closed one (feasible
 * or not: its checks say), else the continuous custom design, which
 * *buildable (may be NULL) then says is not buildable. */
const struct res_run *res_record(const struct solve_result *r, bool *buildable);

/* The figures of the design of record that the cover, the summary,
 * result.json ("key_figures"), bom_totals.csv and index.csv all print:
 * one number each, computed once here from the record (res_record()), so
 * that no writer derives its own.  A figure that does not apply is NAN
 * (hover_power_shed_w when nothing is shed; hover_current_a of a
 * continuous design that sheds before it hovers). */
struct res_figures {
	bool buildable;           /* the record is the aircraft the BOM builds */
	double takeoff_mass_kg;   /* the record's takeoff mass (BOM + payload) */
	double payload_kg;        /* at takeoff */
	bool sheds;               /* payload leaves on the way (drop, spray) */
	double hover_power_w;     /* electrical, hovering at the takeoff mass */
	double hover_power_shed_w;/* ... in the mission's hover phase, after
	                             shedding (NAN when nothing is shed) */
	double hover_current_a;   /* battery current hovering at the takeoff
	                             mass (the operating point of the real
	                             drive, the pack at its nominal voltage) */
	double aux_power_w;       /* auxiliary load flown (avionics and role) */
	double hover_endurance_s; /* hover at takeoff mass down to the reserve */
	double flight_time_s;     /* the mission flown (after any relaxation) */
	double landing_soc;       /* state of charge at touchdown, 0..1 */
	double reserve_soc;       /* the reserve it must keep, 0..1 */
	double bom_mass_kg;       /* parts, the payload aside (0 without parts) */
	double bom_price_usd;     /* the priced lines' sum: a lower bound */
	int bom_lines;            /* lines to buy (the payload line aside) */
	int unpriced_lines;       /* of those, without a price */
};

/* Fills *f from r's design of record. */
void res_figures(const struct solve_result *r, struct res_figures *f);

/* A battery chemistry profile's name as a reader says it: "LiPo" as is,
 * "LiPo_agricultural" as "LiPo (agricultural grade)", "LiPo_highvoltage"
 * as "LiPo (high-voltage grade)"; into buf (size n), which is returned. */
const char *res_chemistry_text(const char *name, char *buf, size_t n);

/* EU open-category class limits by takeoff mass (Reg. (EU) 2019/945), kg,
 * and the US 14 CFR Part 107 small-UAS limit (55 lb). */
#define RES_EU_C0_KG  0.25
#define RES_EU_C1_KG  0.9
#define RES_EU_C2_KG  4.0
#define RES_EU_C3_KG  25.0
#define RES_US_107_KG 24.948

/* The EU open-category class a takeoff mass allows (informative: a class
 * mark also needs the manufacturer's conformity): "C0" below 250 g, "C1"
 * below 900 g, "C2" below 4 kg, "C3/C4" below 25 kg, else "specific". */
const char *res_eu_class(double mass_kg);

/* The bill of materials' price as a buyer reads it: "≥ 1234.56 USD, 3 of 17
 * lines unpriced" (the priced lines' sum is a lower bound), or "1234.56
 * USD" when every line has a price, or "unpriced" when none has; into buf
 * (size n, >= 64), which is returned.  The payload line is not a line to
 * buy.  Empty when no parts were selected. */
const char *res_price_text(const struct solve_result *r, char *buf, size_t n);

#endif
