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

/*
 * The advance-ratio model (the constants in prop.h).  Source: the UIUC Propeller Database (Brandt,
 * Deters, Ananda, Dantsker and Selig, University of Illinois at
 * Urbana-Champaign, m-selig.ae.illinois.edu/props/propDB.html), wind-tunnel
 * runs J, C_T, C_P of two APC propellers (facts read from public copies of
 * the data files; the fit is ours):
 *
 *   APC 9x4.7 Slow Flyer (P/D 0.52), apcsf_9x4.7_kt1033_4008: C_T 0.0936
 *   at J 0.162, 0.0654 at 0.330, 0.0306 at 0.488, 0 at J 0.600; C_P 0.0465,
 *   0.0421, 0.0339, 0.0254 at the same J.  Zero thrust at J/(P/D) = 1.15.
 *   APC 10x7 Thin Electric (P/D 0.70), run at 4011 rpm: C_T 0.1389 at J
 *   0.144, 0.1039 at 0.361, 0.0724 at 0.539, 0.0326 at 0.718 (extrapolated
 *   to zero at J 0.83 to 0.85, J/(P/D) 1.19 to 1.21); C_P 0.0726, 0.0649,
 *   0.0546, 0.0374.
 *
 * A nominal pitch under-states the pitch the blade works at (its camber
 * and washout), so thrust vanishes a little beyond J = P/D: k = 1.15, the
 * measured crossing, the lower (conservative) of the two.  The thrust
 * curve steepens towards J0 (the 9x4.7's slope grows from -0.16 to -0.29
 * per unit J), which 1 - a x - (1 - a) x² with a = 0.35 follows: least
 * squares over each run's points at J0 = 1.15 P/D, C_T0 free, leave a
 * largest error of 0.0011 (9x4.7, C_T0 0.108) and 0.007 (10x7, C_T0
 * 0.150), 1 % and 5 % of the static value.  The power coefficient falls
 * to 0.54 (9x4.7) and about 0.3 to 0.45 (10x7, extrapolated) of its
 * static value at J0: 1 - b x² with b = 0.55 (the 9x4.7 fits best at
 * 0.45, the 10x7 at 0.65) is within about 10 % of every point of both.  Other
 * propeller families (multirotor blades of low P/D, three blades) have no
 * tunnel data here; the model is the same for them, its limit.  The
 * data suggest k grows as P/D falls (the APC 10x4.7 Slow Flyer, C_T
 * 0.018 at J 0.599, extrapolates to zero near 0.65: k about 1.4), so
 * 1.15 errs low, towards a slower envelope, for low-pitch blades.
 */

double
prop_j0(double pitch_over_diameter)
{
	return pitch_over_diameter > 0.0 ? PROP_J0_PER_PD * pitch_over_diameter
	    : 0.0;
}

double
prop_ct_ratio(double j, double j0)
{
	if (!(j0 > 0.0) || !(j > 0.0))
		return 1.0;
	double x = j / j0;
	return 1.0 - PROP_CT_LINEAR * x - (1.0 - PROP_CT_LINEAR) * x * x;
}

double
prop_cp_ratio(double j, double j0)
{
	if (!(j0 > 0.0) || !(j > 0.0))
		return 1.0;
	double x = j / j0;
	return 1.0 - PROP_CP_DROP * x * x;
}

double
prop_advance_ratio(double v_ms, double rps, double d_m)
{
	if (!(v_ms > 0.0) || !(rps > 0.0) || !(d_m > 0.0))
		return 0.0;
	return v_ms / (rps * d_m);
}

double
prop_zero_thrust_speed_ms(double j0, double rps, double d_m)
{
	return j0 * rps * d_m;
}
