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
	double battery_kg;           /* the pack, for the body around it */
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
	double shell_kg;             /* the shell's share of other_kg */
	double frame_total_kg;       /* arm + frame + body before the shell */
	double wiring_kg;            /* power harness */
	double avionics_kg;          /* flight controller, GNSS, radios */
	double role_aux_kg;          /* role hardware */
};

/* The airframe of the mission p carrying these loads. */
void airframe_masses(const struct sizing_params *p,
                     const struct airframe_loads *in,
                     struct airframe_masses *out);

/* Body shell (a mass term the paper leaves open): a minimum-gauge shell
 * enclosing the battery and the electronics.  Volume from the pack and
 * electronics densities at 50 % fill; surface of a box of that volume with
 * a 1.2 shape factor over a cube. */
#define AIRFRAME_PACK_DENSITY_KG_M3 2200.0 /* LiPo/Li-ion pack incl. case */
#define AIRFRAME_AVIONICS_DENSITY_KG_M3 1000.0 /* boards, modules, cables */
#define AIRFRAME_BODY_FILL          0.5    /* fraction of the body that is equipment */
#define AIRFRAME_BODY_SHAPE         1.2    /* body surface over a cube's */

/* Surface of the body shell: a box around the pack and the electronics
 * (volume from their densities at the fill fraction, surface a shape
 * factor over a cube's) plus the moulded arm fairings of classes that have
 * them, 4 c L² per arm, m². */
double airframe_shell_area_m2(double battery_kg, double avionics_kg, int n_arms,
                              double arm_length_m, double fairing_section_frac);

/* The light-configuration scale S_scale of paper §VI-E at M_ref. */
double airframe_s_scale(double m_ref_kg);

#endif
