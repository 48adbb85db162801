/* structure.c — CFRP arm sizing and resonance (see structure.h). */
#include "physics/structure.h"

#include "util/units.h"

double
structure_sigma_allow_pa(void)
{
	return STRUCT_SIGMA_ULT_PA * STRUCT_FATIGUE / STRUCT_FOS;
}

bool
structure_cg_thrust_n(double mass_kg, int n_rotors, double arm_length_m,
                      double cg_shift_m, double *thrust_n)
{
	double d_y = arm_length_m * cos(M_PI / (double)n_rotors);
	double nominal = mass_kg * G0_M_S2 / (double)n_rotors;
	if (cg_shift_m >= d_y) {
		*thrust_n = nominal;
		return false;
	}
	*thrust_n = nominal * (1.0 + cg_shift_m / d_y);
	return true;
}

double
structure_min_fraction(double wheelbase_m)
{
	double f = 0.05 + 0.05 * wheelbase_m;
	if (f > 0.20)
		f = 0.20;
	return f < 0.06 ? 0.06 : f;
}

double
structure_natural_freq_hz(double i_x_m4, double length_m, double tip_mass_kg,
                          double mu_kg_m)
{
	double l3 = length_m * length_m * length_m;
	double m_eff = tip_mass_kg + 0.24 * mu_kg_m * length_m;
	if (!(m_eff > 0.0) || !(l3 > 0.0))
		return 0.0;
	return sqrt(3.0 * STRUCT_E_CF_PA * i_x_m4 / (l3 * m_eff)) / (2.0 * M_PI);
}

/* Fill the section properties of a tube of outer diameter d with the wall
 * from alpha_w, floored at the minimum wall. */
static void
tube_section(double d_out, double alpha_w, double length_m,
             struct structure_arm *a)
{
	double wall = 0.5 * d_out * (1.0 - alpha_w);
	a->wall_floor_binds = wall < STRUCT_MIN_WALL_M;
	if (a->wall_floor_binds)
		wall = STRUCT_MIN_WALL_M;
	if (wall > 0.5 * d_out)
		wall = 0.5 * d_out; /* a solid rod at worst */
	a->d_out_m = d_out;
	a->wall_m = wall;
	a->d_in_m = d_out - 2.0 * wall;
	double d4 = d_out * d_out * d_out * d_out;
	double i4 = a->d_in_m * a->d_in_m * a->d_in_m * a->d_in_m;
	a->area_m2 = 0.25 * M_PI * (d_out * d_out - a->d_in_m * a->d_in_m);
	a->i_x_m4 = M_PI * (d4 - i4) / 64.0;
	a->mass_kg = STRUCT_RHO_CF_KG_M3 * a->area_m2 * length_m;
	a->stress_pa = a->i_x_m4 > 0.0
	    ? a->root_moment_nm * 0.5 * d_out / a->i_x_m4 : 0.0;
}

void
structure_size_arm(double force_n, double length_m, double alpha_w,
                   double tip_mass_kg, struct structure_arm *out)
{
	out->length_m = length_m;
	out->root_moment_nm = force_n * length_m;
	/* Paper eq. (dout).  With the wall floor the same diameter has a
	 * thicker wall and so a lower stress: the strength sizing stays valid. */
	double a4 = alpha_w * alpha_w * alpha_w * alpha_w;
	double d = cbrt(32.0 * out->root_moment_nm
	    / (M_PI * (1.0 - a4) * structure_sigma_allow_pa()));
	tube_section(d, alpha_w, length_m, out);
	out->f_nat_hz = structure_natural_freq_hz(out->i_x_m4, length_m,
	    tip_mass_kg, STRUCT_RHO_CF_KG_M3 * out->area_m2);
}

double
structure_resonance_margin(double f_nat_hz, double f_bpf_low_hz,
                           double f_bpf_peak_hz)
{
	/* No arm, or no blade-pass band (a rotor that cannot reach hover):
	 * nothing is known to be clear of resonance. */
	if (!(f_nat_hz > 0.0) || !(f_bpf_low_hz > 0.0) || !(f_bpf_peak_hz > 0.0))
		return -1.0;
	double stiff = f_nat_hz / (STRUCT_RESONANCE_MARGIN * f_bpf_peak_hz) - 1.0;
	double soft = (f_bpf_low_hz / STRUCT_RESONANCE_MARGIN) / f_nat_hz - 1.0;
	return stiff > soft ? stiff : soft;
}
