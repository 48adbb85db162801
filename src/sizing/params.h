/* params.h — everything a run of the engine needs, resolved from the
 * mission, the role and the class by the engine (engine.c): the one set of
 * parameters the continuous mass loop (sizing.h), the airframe model
 * (airframe.h) and the flight of a design on real parts (perf.h) read.
 * This module makes no decision about defaults.
 */
#ifndef AEROEVAL_PARAMS_H
#define AEROEVAL_PARAMS_H

#include <stdbool.h>

#include "spec/model.h"
#include "result/result.h"
#include "physics/atmo.h"

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
	double time_scale;           /* every phase flown at this share of its
	                                request (the engine's ceiling); 0 = 1 */
	/* role */
	double thrust_margin;        /* hover throttle = 1 - margin */
	double load_factor;
	double aux_w;                /* auxiliary power, W (the role's at
	                              * aux_ref_kg when aux_scaled) */
	double aux_ref_kg;           /* the role's reference aircraft */
	bool aux_scaled;             /* the role's default: scales with the
	                              * aircraft (sizing_aux_w()) */
	double added_drag_m2;
	double fwd_drag_mult;
	double cg_shift_m;
	double role_aux_kg;
	double c_motor;
	double c_esc;
	double h_conv_w_m2k;
	double burst_factor;         /* 10 s burst / continuous battery power */
	bool small_platform;         /* racing/small wiring coefficient */
	const struct model_duty *duty; /* the role's duty profile (NULL: the
	                              * paper's three phases) */
	enum shed_kind shed;
	double drop_mass_kg;
	double drop_ratio;
	double spray_rate_kg_s;      /* 0 = payload / mission time */
	double downwash_cap_ms;      /* agriculture downwash cap, 0 = none */
	double payload_kg;
	double extra_payload_kg;     /* max_payload_kg - payload_kg (>= 0): the
	                              * structure and motors carry it */
	/* battery */
	const struct batt_chem *chem;
	double e_pack_override_wh_kg; /* > 0: pack specific energy given by the mission */
	int cells_fixed;             /* 0 = auto */
	int cells_lo, cells_hi;      /* auto range (class table) */
	int pack_count;
	int cycles;
	bool capacity_locked;
	double capacity_locked_ah;
	/* propeller and motor */
	bool prop_locked;
	double prop_diameter_m;
	double prop_frac;          /* unlocked: the diameter flown over the largest
	                              the wheelbase admits (0 reads as 1) */
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
	double re_ref;               /* Reynolds reference of FoM(Re) */
	double interference_c;       /* 0.6 offset, 1.5 under-rotor, 0 folding */
	double eta_drive;
	double cd_h, cd_v;
	double wake_share;           /* forward flight's kept induced power */
	double f_scale;
	double ct;
	/* structure */
	double c_body;
	double alpha_w;
	double gamma;
	double lambda;
	double fixed_frame_kg;       /* > 0: frame mass given */
	double equip_kg;             /* equipment at 1 kg design mass (airframe.h) */
	double equip_exponent;
	double avionics_share;       /* of the equipment, shown as avionics */
	/* calibration */
	double wire_coef;
	/* real parts for the BOM-closed run */
	struct sizing_parts parts;
	/* extras of the final evaluation */
	bool marketing;              /* evaluate_marketing_limits */
	/* numerics */
	int max_iter;
};

#endif
