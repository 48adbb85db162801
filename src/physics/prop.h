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

#endif
