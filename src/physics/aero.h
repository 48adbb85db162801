/* aero.h — rotor aerodynamics and body drag.
 *
 * Paper §IV: propeller-overlap limit (eq. overlap), actuator-disk downwash
 * (eq. downwash), momentum theory in hover and climb, Glauert's forward-flight
 * induced velocity solved by Newton–Raphson, profile power with the
 * Reynolds-dependent C_d0 (eq. cdre), installed figure of merit (class penalty
 * κ, Bohorquez–Pines Reynolds fit, floor 0.38), rotor–arm interference, and
 * the parasite drag of the body.  Physics layer: pure functions, SI units.
 *
 * How the figure of merit and profile power fit together: in hover the shaft
 * power is the ideal induced power divided by the installed FoM (paper).  The
 * FoM already contains the profile loss, so the hover shaft power is split
 * into a profile part P_o (from C_d0(Re)) and an induced part k_i T v_i with
 * k_i = 1/FoM - P_o/(T v_h).  In forward flight each part then scales with
 * its own physics: induced with Glauert's v_i, profile with (1 + 4.65 μ²),
 * plus the parasite power F_d V.  At V = 0 this is exactly the paper's hover
 * power, so nothing is double counted.
 */
#ifndef AEROEVAL_AERO_H
#define AEROEVAL_AERO_H

#include <stdbool.h>

struct atmo_state;

#define AERO_TIP_CLEARANCE   0.05   /* ε of eq. (overlap), - */
/* A propeller exactly at the overlap limit fits: a wheelbase derived from
 * the limit (or the limit from the wheelbase) may round either way by a
 * few ulps, so comparisons against the limit allow this relative slack. */
#define AERO_OVERLAP_REL_TOL 1e-9
#define AERO_TIP_MACH_MAX    0.75   /* tip-Mach pruning limit, - */
#define AERO_SOLIDITY        (0.28 / M_PI) /* σ of the profile-power formula, - */
#define AERO_FOM_FLOOR       0.10   /* minimum installed FoM, - */
#define AERO_RE_REF          20000.0 /* Re_ref of the FoM(Re) fit, - */
#define AERO_INTERFERENCE_CAP 1.15  /* cap of k_int, - */

/* Largest propeller diameter that fits W with n_arms arms (eq. overlap). */
double aero_overlap_limit_m(double wheelbase_m, int n_arms, double clearance);

/* Hover induced velocity v_i = sqrt(T / (2 ρ A)), m/s. */
double aero_hover_induced_ms(double thrust_n, double rho_kg_m3, double area_m2);

/* Momentum-theory induced velocity in axial climb at v_climb, m/s. */
double aero_climb_induced_ms(double thrust_n, double rho_kg_m3, double area_m2,
                             double v_climb_ms);

/* Glauert: v_i = T / (2 ρ A sqrt(V² + v_i²)) by Newton–Raphson.  *iter gets
 * the iterations used (may be NULL).  Always returns a finite positive value
 * for finite positive inputs. */
double aero_glauert_induced_ms(double thrust_n, double rho_kg_m3, double area_m2,
                               double v_inf_ms, int *iter);

/* Rotational speed giving thrust T: n = sqrt(T / (C_t ρ D⁴)), rev/s. */
double aero_rps_for_thrust(double thrust_n, double ct, double rho_kg_m3,
                           double diameter_m);

/* Reynolds-dependent blade drag coefficient (eq. cdre). */
double aero_cd0(double reynolds_tip);

/* Blade chord implied by the solidity σ: c = σ π R / N_b, m. */
double aero_chord_m(double diameter_m, int n_blades);

/* Tip Reynolds number ρ V_tip c / μ. */
double aero_tip_reynolds(const struct atmo_state *air, double v_tip_ms,
                         double chord_m);

/* Profile power P_o = σ C_d0 ρ A V_tip³ / 8, W. */
double aero_profile_power_w(double cd0, double rho_kg_m3, double area_m2,
                            double v_tip_ms);

/* Installed figure of merit: iso / κ (installed mode) or iso (isolated),
 * times the Reynolds fit 1 - exp(-Re/Re_ref) (re_ref <= 0: the paper's
 * AERO_RE_REF; the engine's is calibrated), floored at 0.38. */
double aero_fom_installed(double fom_isolated, double kappa, bool isolated_mode,
                          double reynolds_tip, double re_ref);

/* Rotor–arm interference k_int = 1 + c w_a / D_p, capped at 1.15. */
double aero_interference(double c_config, double arm_width_m, double diameter_m);

/* Reference area S_ref = f_scale M^(2/3) + ΔA, m². */
double aero_ref_area_m2(double f_scale, double mass_kg, double added_area_m2);

/* Drag ½ ρ V² C_d S, N. */
double aero_drag_n(double rho_kg_m3, double v_ms, double cd, double area_m2);

/* One rotor's operating point. */
struct aero_rotor {
	double diameter_m;   /* D_p */
	double ct;           /* thrust coefficient in T = C_t ρ n² D⁴ */
	double fom;          /* installed FoM incl. interference */
	int n_blades;        /* N_b */
};

struct aero_point {
	double thrust_n;        /* thrust of this rotor, N */
	double induced_ms;      /* induced velocity, m/s */
	double rps;             /* rotational speed, rev/s */
	double tip_speed_ms;    /* V_tip, m/s */
	double tip_mach;        /* V_tip / a */
	double reynolds_tip;    /* Re at the tip */
	double p_induced_w;     /* induced part of shaft power, W */
	double p_profile_w;     /* profile part, W */
	double p_parasite_w;    /* this rotor's share of F_d V, W */
	double p_shaft_w;       /* total shaft power, W */
	int glauert_iter;       /* Newton–Raphson iterations (forward) */
};

/* Shaft power of one rotor carrying thrust_n while the aircraft climbs at
 * v_climb_ms and flies forward at v_fwd_ms; parasite_w is this rotor's share
 * of the body drag power.  Hover is v_climb = v_fwd = 0. */
void aero_rotor_power(const struct aero_rotor *r, const struct atmo_state *air,
                      double thrust_n, double v_climb_ms, double v_fwd_ms,
                      double parasite_w, struct aero_point *out);

/* Downwash of the whole aircraft 2 sqrt(M g / (2 ρ N A)), m/s (eq. downwash). */
double aero_downwash_ms(double mass_kg, double rho_kg_m3, int n_rotors,
                        double area_m2);

#endif
