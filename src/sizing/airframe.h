/* airframe.h — the masses of everything but propulsion, battery and
 * payload: arm tubes, centre frame, body and landing gear, body shell,
 * power harness, avionics and role hardware.
 *
 * One model for both designs: the continuous mass loop (sizing.c) and the
 * aircraft closed on real parts (the parts search) call it with the loads
 * of their own propulsion, so the structure of the design of record is
 * sized for the real motors' thrust and the real pack's current.
 *
 * Sizing layer; no I/O.
 */
#ifndef AEROEVAL_AIRFRAME_H
#define AEROEVAL_AIRFRAME_H

#include <stdbool.h>

#include "physics/structure.h"
#include "sizing/params.h"

/* The loads and parts the airframe carries. */
struct airframe_loads {
	double mass_kg;              /* takeoff mass flown */
	double peak_thrust_n;        /* one rotor at full throttle */
	double tip_mass_kg;          /* motor + propeller of one rotor */
	double peak_current_a;       /* battery current at full throttle */
	double peak_torque_nm;       /* one motor's reaction torque at full throttle */
	double prop_diameter_m;      /* for the rate-loop bandwidth the arm's mode clears */
};

/* What it gives.  The mass items go to struct res_mass as arm_kg,
 * frame_kg, other_kg (body, landing gear, shell), wiring_kg,
 * avionics_kg and role_aux_kg. */
struct airframe_masses {
	struct structure_arm arm;    /* one arm tube as sized */
	bool cg_ok;                  /* the payload CG offset is inside the arms */
	bool min_fraction_binds;     /* the minimum structural fraction set it */
	double arm_kg;               /* all arm tubes */
	double frame_kg;             /* centre plates and spar joints */
	double other_kg;             /* body, landing gear, mounts and shell */
	double shell_kg;             /* the equipment's body share, in other_kg */
	double frame_total_kg;       /* arm + frame + body before the shell */
	double wiring_kg;            /* power harness */
	double avionics_kg;          /* flight controller, GNSS, radios */
	double role_aux_kg;          /* role hardware */
};

/* The airframe of the mission p carrying these loads:
 * airframe_structure() then airframe_harness(). */
void airframe_masses(const struct sizing_params *p,
                     const struct airframe_loads *in,
                     struct airframe_masses *out);

/* Everything of airframe_masses() but the harness (wiring_kg 0); it does
 * not read in->peak_current_a: a design that tries several battery buses
 * on the same propulsion sizes it once. */
void airframe_structure(const struct sizing_params *p,
                        const struct airframe_loads *in,
                        struct airframe_masses *out);

/* The harness of an airframe_structure() result for the battery current
 * at full throttle, into out->wiring_kg. */
void airframe_harness(const struct sizing_params *p, double peak_current_a,
                      struct airframe_masses *out);

/* Equipment: avionics, body shell, landing gear, gimbal, sensors and
 * mounts, everything the physics above does not size, as one law of the
 * design mass calibrated on the cohort (data/calibration.json):
 * e_class (M_design / 1 kg)^exponent, kg.  No floor: it vanishes with the
 * aircraft.  The class's avionics_share of it is shown as avionics, the
 * rest as body (a display split: both are dead mass at the centre). */
double airframe_equipment_kg(const struct sizing_params *p, double design_mass_kg);

/* The arm's figures into run (both designs). */
struct res_run;
void airframe_record_arm(const struct structure_arm *arm, double prop_diameter_m,
                         struct res_run *run);

/* The light-configuration scale S_scale of paper §VI-E at M_ref. */
double airframe_s_scale(double m_ref_kg);

#endif
