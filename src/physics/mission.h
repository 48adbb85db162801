/* mission.h — three-phase mission power model (hover, climb, forward).
 *
 * Paper §IV-C..F: per-phase thrust (hover M g / N, climb (M g + F_dv) / N,
 * forward sqrt((M g)² + F_d²) / N with body pitch atan(F_d / M g)), parasite
 * drag on S_ref = f_scale M^(2/3) + ΔA (the role's forward multiplier in
 * forward flight only), rotor power from aero.h, electrical power
 * P_mech / η + ESC switching loss + auxiliary power (eq. powerbudget), and
 * the auto-velocity sweep 1–30 m/s in 0.5 m/s steps.
 *
 * The envelope: full thrust falls with the axial inflow through the disk
 * (the climb rate, or the forward speed times the sine of the pitch), as
 * the propeller's C_T(J) does (prop.h), when the model knows the
 * propeller's zero-thrust advance ratio (prop_j0).  The top speed is
 * where the thrust that is left no longer carries weight and drag, or the
 * pitch reaches MISSION_PITCH_MAX_DEG: searched on the sweep's grid, then
 * to the millimetre per second between grid points, and past the grid's
 * end when the aircraft is still within its limits there.
 *
 * The continuous design uses the paper's drive efficiency η.  A design on
 * real parts gives the model its motor (real_drive): each rotor's
 * electrical power is then the motor's input at the rotor's speed and
 * shaft power (motor.h), so efficiency, current and voltage are the
 * motor's own at every operating point.
 */
#ifndef AEROEVAL_MISSION_H
#define AEROEVAL_MISSION_H

#include <stdbool.h>

#include "physics/aero.h"
#include "physics/atmo.h"
#include "physics/motor.h"

#define MISSION_SWEEP_V0_MS   1.0
#define MISSION_SWEEP_V1_MS   30.0
#define MISSION_SWEEP_STEP_MS 0.5
#define MISSION_SWEEP_MAX_POINTS 64 /* grid speeds, with room to spare */
#define MISSION_F_PWM_HZ      24000.0 /* ESC PWM frequency, Hz */
#define MISSION_C_OSS_F       3.75e-9 /* MOSFET output capacitance, mid of 2.5-5 nF */
#define MISSION_COAX_INDUCED  1.22    /* coaxial-pair induced-power factor (Leishman) */
#define MISSION_PITCH_MAX_DEG 35.0    /* steepest body pitch accepted in cruise */
#define MISSION_SPEED_RES_PER_MS 1000.0 /* top speeds to 1 mm/s: the lattice
                                          k / 1000 m/s, so every search path
                                          lands on the same number */
#define MISSION_SPEED_CAP_MS  200.0   /* a search bound, reached only by a
                                         body without drag (no pitch limit):
                                         then reported as the bound */

/* What ends the forward-speed envelope. */
enum mission_limit {
	MISSION_LIMIT_NONE = 0,   /* not searched */
	MISSION_LIMIT_THRUST,     /* full thrust at the inflow against weight
	                             and drag */
	MISSION_LIMIT_PITCH,      /* the MISSION_PITCH_MAX_DEG pitch limit */
	MISSION_LIMIT_BOUND       /* MISSION_SPEED_CAP_MS, not a physical limit */
};

/* Everything the power of a phase depends on besides mass and speed. */
struct mission_model {
	struct atmo_state air;      /* the air */
	struct aero_rotor rotor;    /* one rotor */
	int n_rotors;               /* N_r */
	bool coaxial;               /* stacked pairs: induced factor */
	double f_scale;             /* S_ref scale, m²/kg^(2/3) */
	double added_drag_m2;       /* ΔA */
	double fwd_drag_mult;       /* role forward-flight multiplier */
	double cd_h;                /* body Cd, forward */
	double cd_v;                /* body Cd, climb */
	double wake_share;          /* forward flight: the share of the hover
	                               induced power the relief of Glauert's
	                               isolated rotor does not bring (rear
	                               rotors in the front rotors' wake) */
	double eta_drive;           /* motor + ESC efficiency */
	double aux_w;               /* auxiliary load, W */
	double bus_voltage_v;       /* for the switching loss */
	bool real_drive;            /* electrical power from `motor`, not η */
	struct motor_model motor;   /* the real motor (real_drive) */
	double motor_temp_c;        /* its winding temperature */
	double prop_j0;             /* zero-thrust advance ratio of the rotor's
	                               propeller (prop_j0()): full thrust falls
	                               with the inflow as C_T(J) does, at the
	                               full-throttle speed of static thrust;
	                               0: the same full thrust at every speed */
};

struct mission_power {
	double thrust_per_rotor_n;
	double drag_n;              /* body drag in this phase */
	double pitch_deg;           /* body pitch */
	double axial_ms;            /* inflow along the rotor axis: the climb
	                               rate, or the forward speed times the
	                               sine of the pitch */
	struct aero_point rotor;    /* one rotor's operating point */
	double shaft_w;             /* all rotors */
	double switching_w;         /* ESC switching loss, all ESCs */
	double electrical_w;        /* at the battery: shaft/η (or the motors'
	                               input) + switching + aux */
	struct motor_point motor;   /* one motor's point (real_drive only) */
};

/* Power of one phase at mass_kg: v_climb_ms > 0 for climb, v_fwd_ms > 0 for
 * forward flight, both 0 for hover. */
void mission_power(const struct mission_model *m, double mass_kg,
                   double v_climb_ms, double v_fwd_ms, struct mission_power *out);

/* Full-throttle static power when each rotor gives thrust_per_rotor_n. */
void mission_peak_power(const struct mission_model *m, double thrust_per_rotor_n,
                        struct mission_power *out);

/* Full thrust per rotor at an axial inflow of v_axial_ms, for a rotor
 * whose static full thrust is max_thrust_per_rotor_n: C_T(J) / C_T0 of it
 * at J = v / (n D), n the speed of static full thrust (a motor held at its
 * speed; a real motor unloads and speeds up a little: perf.c solves it).
 * max_thrust_per_rotor_n itself when m->prop_j0 is 0. */
double mission_thrust_available_n(const struct mission_model *m,
                                  double max_thrust_per_rotor_n,
                                  double v_axial_ms);

/* Is this operating point past the full thrust left at its inflow
 * (mission_thrust_available_n()) or the pitch limit MISSION_PITCH_MAX_DEG
 * (the speed sweep's limits)? */
bool mission_beyond_limits(const struct mission_model *m,
                           const struct mission_power *p,
                           double max_thrust_per_rotor_n);

/* The forward speed at which the body pitch reaches MISSION_PITCH_MAX_DEG
 * at mass_kg (drag = weight · tan 35°); MISSION_SPEED_CAP_MS for a body
 * without drag. */
double mission_pitch_limit_speed_ms(const struct mission_model *m,
                                    double mass_kg);

/* Which limit ends the envelope at top speed v_max_ms (a search's): the
 * pitch when the next millimetre per second is past MISSION_PITCH_MAX_DEG,
 * else the thrust. */
enum mission_limit mission_top_speed_limit(const struct mission_model *m,
                                           double mass_kg, double v_max_ms);

/* The forward speed flown when v_fwd_ms is asked: itself when it stays
 * within max_thrust_per_rotor_n and the pitch limit, else the top speed
 * within them: v_max_ms when the caller has it (> 0), else searched as
 * mission_speed_search() does.  No phase then runs above full throttle. */
double mission_forward_flown_ms(const struct mission_model *m, double mass_kg,
                                double max_thrust_per_rotor_n, double v_fwd_ms,
                                double v_max_ms);

/* The fastest vertical climb, up to v_hi_ms, whose thrust stays within
 * the full thrust left at that climb rate (mission_thrust_available_n(),
 * bisection to 1 mm/s); v_hi_ms itself when that is within it, 0 when not
 * even a hover is. */
double mission_max_climb_ms(const struct mission_model *m, double mass_kg,
                            double max_thrust_per_rotor_n, double v_hi_ms);

/* Sweep forward speed; fills up to max_points (v, electrical power) pairs and
 * returns the count.  *v_min_power_ms gets the minimum-power speed, and
 * *v_max_ms the highest speed whose thrust stays within the full thrust
 * left at its inflow and whose pitch stays under MISSION_PITCH_MAX_DEG, to
 * 1 mm/s on the lattice MISSION_SPEED_RES_PER_MS: between the last grid
 * speed within them and the first past them, or beyond the sweep's end
 * (up to the pitch-limit speed) when every grid speed is within them. */
int mission_speed_sweep(const struct mission_model *m, double mass_kg,
                        double max_thrust_per_rotor_n, double *v_ms,
                        double *power_w, int max_points,
                        double *v_min_power_ms, double *v_max_ms);

/* mission_speed_sweep()'s *v_min_power_ms and *v_max_ms without the curve,
 * by bisection on the same grid: about 18 operating points instead of 59.
 * Equal to the sweep's whenever the power has a single minimum over the
 * speeds within the limits (tests/test_mission.c checks it on random
 * aircraft). */
void mission_speed_search(const struct mission_model *m, double mass_kg,
                          double max_thrust_per_rotor_n,
                          double *v_min_power_ms, double *v_max_ms);

/* Where a speed search ended on the grid: the count of speeds within the
 * limits (a prefix) and the index of the power's first minimum.  A mass
 * loop's next search, at a mass close by, ends at the same points. */
struct mission_speed_hint {
	bool set;
	int n_ok;
	int i_min;
	long k_max;       /* the top speed on the lattice (v = k / 1000 m/s);
	                     0: none yet */
};

/* mission_speed_search() that first verifies the points *hint names (two
 * or three operating points each, against the bisection's ~9) and
 * bisects only where they fail; the result is the bisection's whenever
 * its tests are monotone on the grid, as mission_speed_search() assumes.
 * *hint gets this search's points. */
void mission_speed_search_hinted(const struct mission_model *m, double mass_kg,
                                 double max_thrust_per_rotor_n,
                                 double *v_min_power_ms, double *v_max_ms,
                                 struct mission_speed_hint *hint);

#endif
