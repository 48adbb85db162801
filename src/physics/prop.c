/* prop.c — static propeller coefficients (see prop.h). */
#include "physics/prop.h"

#include <math.h>

#include "util/units.h"

/* Fits over the catalogue's two-blade propellers with published static
 * coefficients (151, mostly APC's own static data), least squares in log
 * space:  C_T = 0.142 (P/D)^0.472 (sd 0.20),  C_P = 0.0727 (P/D)^0.972
 * (sd 0.28).  Component facts. */
#define CT_FIT_K    0.142
#define CT_FIT_EXP  0.472
#define CP_FIT_K    0.0727
#define CP_FIT_EXP  0.972
/* More blades at the same diameter and pitch: more solidity.  Blade-element
 * theory puts both coefficients nearly in proportion to the solidity at
 * low thrust; induced losses rise with loading, so thrust grows less:
 * C_T ∝ (N_b/2)^0.8, C_P ∝ (N_b/2)^1 (an engineering estimate; the
 * catalogue has no multi-blade data to fit). */
#define CT_BLADE_EXP 0.8
#define CP_BLADE_EXP 1.0

void
prop_estimate(double pitch_over_diameter, int n_blades, struct prop_coeffs *out)
{
	double pd = pitch_over_diameter > 0.05 ? pitch_over_diameter : 0.05;
	double blades = n_blades >= 2 ? (double)n_blades / 2.0 : 1.0;
	out->ct = CT_FIT_K * pow(pd, CT_FIT_EXP) * pow(blades, CT_BLADE_EXP);
	out->cp = CP_FIT_K * pow(pd, CP_FIT_EXP) * pow(blades, CP_BLADE_EXP);
	out->measured = false;
}

double
prop_fom(const struct prop_coeffs *c)
{
	return pow(c->ct, 1.5) / (c->cp * sqrt(M_PI / 2.0));
}

double
prop_thrust_n(const struct prop_coeffs *c, double rho_kg_m3, double rps,
              double d_m)
{
	return prop_thrust_d4_n(c, rho_kg_m3, rps, pow(d_m, 4.0));
}

double
prop_thrust_d4_n(const struct prop_coeffs *c, double rho_kg_m3, double rps,
                 double d4_m4)
{
	return c->ct * rho_kg_m3 * rps * rps * d4_m4;
}

double
prop_power_w(const struct prop_coeffs *c, double rho_kg_m3, double rps,
             double d_m)
{
	return c->cp * rho_kg_m3 * rps * rps * rps * pow(d_m, 5.0);
}

double
prop_kq_nm_s2(const struct prop_coeffs *c, double rho_kg_m3, double d_m)
{
	return c->cp * rho_kg_m3 * pow(d_m, 5.0) / (2.0 * M_PI);
}
