/* prop.h — a real propeller's static thrust and power coefficients.
 *
 *     T = C_T ρ n² D⁴      P = C_P ρ n³ D⁵      Q = P / (2π n)
 *
 * with n in rev/s.  The catalogue gives C_T and C_P where the maker or a
 * test publishes them (APC's static performance data for most); for the
 * other propellers prop_estimate() fits the published ones by pitch over
 * diameter.  The figure of merit of a static propeller follows from the two
 * coefficients, FoM = C_T^(3/2) / (C_P sqrt(π/2)) (momentum theory's ideal
 * power T^(3/2) / sqrt(2ρA) over P), and is what the mission model's rotor
 * uses for the real part (installed penalty and interference on top).
 *
 * Away from the static point the coefficients depend on the advance ratio
 * J = V_axial / (n D), the distance the propeller advances per revolution
 * over its diameter.  Thrust falls as J grows and vanishes at the
 * zero-thrust advance ratio J0, a little beyond the geometric pitch:
 *
 *     x = J / J0,   J0 = k P/D (k = 1.15)
 *     C_T(J) = C_T0 (1 - a x - (1 - a) x²)      a = 0.35
 *     C_P(J) = C_P0 (1 - b x²)                  b = 0.55
 *
 * fitted to the UIUC Propeller Database's wind-tunnel runs (prop.c gives
 * the data).  The catalogue publishes static coefficients only, so the
 * model stands for every propeller; J is the free-stream axial speed, as
 * in the tunnel (the induced velocity is inside the measured curves).
 *
 * Physics layer: pure functions, SI units.
 */
#ifndef AEROEVAL_PROP_H
#define AEROEVAL_PROP_H

#include <stdbool.h>

/* Static coefficients of one propeller. */
struct prop_coeffs {
	double ct;          /* C_T */
	double cp;          /* C_P */
	bool measured;      /* published (catalogue) or estimated here */
};

/* C_T and C_P of a propeller of this pitch over diameter and blade count
 * when nothing is published: fits to the catalogue's 151 two-blade
 * propellers with published static coefficients, scaled for more blades by
 * their solidity (prop.c). */
void prop_estimate(double pitch_over_diameter, int n_blades,
                   struct prop_coeffs *out);

/* Static figure of merit C_T^1.5 / (C_P sqrt(π/2)). */
double prop_fom(const struct prop_coeffs *c);

/* Thrust and power at n rev/s in air of density rho, diameter d_m. */
double prop_thrust_n(const struct prop_coeffs *c, double rho_kg_m3,
                     double rps, double d_m);
/* The same thrust from D^4 already worked out (d4_m4 = d_m^4): for a
 * search that tries one propeller at many speeds. */
double prop_thrust_d4_n(const struct prop_coeffs *c, double rho_kg_m3,
                        double rps, double d4_m4);
double prop_power_w(const struct prop_coeffs *c, double rho_kg_m3,
                    double rps, double d_m);

/* The torque factor kq with Q = kq n²: C_P ρ D⁵ / 2π. */
double prop_kq_nm_s2(const struct prop_coeffs *c, double rho_kg_m3, double d_m);

/* The advance-ratio model (see above; prop.c gives the data). */
#define PROP_J0_PER_PD   1.15  /* k: zero-thrust J over P/D, - */
#define PROP_CT_LINEAR   0.35  /* a: the linear share of the thrust decline */
#define PROP_CP_DROP     0.55  /* b: C_P falls to 1 - b of static at J0 */

/* Zero-thrust advance ratio J0 = k P/D of a propeller of this pitch over
 * diameter (k = PROP_J0_PER_PD); 0 when the ratio is not positive. */
double prop_j0(double pitch_over_diameter);

/* C_T(J) / C_T0 and C_P(J) / C_P0 at advance ratio j of a propeller whose
 * zero-thrust advance ratio is j0 > 0: 1 at J <= 0 (static; a descent is
 * not modelled), the thrust ratio falling monotonically to 0 at J0 and
 * negative beyond (windmilling), the power ratio falling from 1 to
 * 1 - b at J0.  With j0 <= 0 (no pitch known) both are 1. */
double prop_ct_ratio(double j, double j0);
double prop_cp_ratio(double j, double j0);

/* Advance ratio J = V / (n D) of axial speed v_ms at n rev/s; 0 for a
 * non-positive speed or rotation. */
double prop_advance_ratio(double v_ms, double rps, double d_m);

/* The axial speed at which the propeller turning at n rev/s gives no
 * thrust: J0 n D. */
double prop_zero_thrust_speed_ms(double j0, double rps, double d_m);

#endif
