/* structure.c — CFRP arm sizing and resonance (see structure.h). */
#include "physics/structure.h"

#include <math.h>
#include <string.h>

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

const char *const structure_sized_by_text[3] = {
	"strength", "stiffness (motor tilt)", "stiffness (first mode)"
};

double
structure_tau_allow_pa(void)
{
	return STRUCT_TAU_ULT_PA * STRUCT_FATIGUE / STRUCT_FOS;
}

double
structure_gyro_filter_hz(double prop_diameter_m)
{
	double d_in = prop_diameter_m / 0.0254;
	if (!(d_in > 0.0))
		return 0.0;
	return 289.22 * pow(d_in, -0.838);
}

/* The tube of outer diameter d with its section, stress, mass and mode. */
static void
arm_at(const struct structure_arm_loads *in, double d_out,
       struct structure_arm *a)
{
	a->length_m = in->length_m;
	a->root_moment_nm = in->design_force_n * in->length_m;
	tube_section(d_out, in->alpha_w, in->length_m, a);
	a->f_nat_hz = structure_natural_freq_hz(a->i_x_m4, in->length_m,
	    in->tip_mass_kg, STRUCT_RHO_CF_KG_M3 * a->area_m2);
}

/* Tip slope (rad) under force_n at the tip: F L² / 2EI. */
static double
tip_slope_rad(const struct structure_arm *a, double force_n)
{
	double ei = STRUCT_E_CF_PA * a->i_x_m4;
	return ei > 0.0 ? force_n * a->length_m * a->length_m / (2.0 * ei) : 0.0;
}

static void structure_size_for(const struct structure_arm_loads *in,
                               struct structure_arm *out);

void
structure_size_arm(const struct structure_arm_loads *in,
                   struct structure_arm *out)
{
	memset(out, 0, sizeof *out);
	/* A tube its stiffness sizes is best wide and thin (I ~ d³ t for the
	 * mass ~ d t): where the tilt or the mode governs, the wall is thinned
	 * to STRUCT_STIFF_ALPHA_W of the diameter, if the strength holds. */
	struct structure_arm_loads thin = *in;
	if (thin.alpha_w < STRUCT_STIFF_ALPHA_W)
		thin.alpha_w = STRUCT_STIFF_ALPHA_W;
	structure_size_for(in, out);
	/* A tube the strength sizes keeps its wall: the thin one is not
	 * needed to say so. */
	if (out->sized_by == ARM_BY_STRENGTH)
		return;
	struct structure_arm t;
	structure_size_for(&thin, &t);
	if (t.sized_by != ARM_BY_STRENGTH
	    && t.stress_pa <= structure_sigma_allow_pa() && t.mass_kg < out->mass_kg)
		*out = t;
}

/* structure_size_arm() at the wall ratio in->alpha_w. */
static void
structure_size_for(const struct structure_arm_loads *in,
                   struct structure_arm *out)
{
	memset(out, 0, sizeof *out);
	double k4 = 1.0 - pow(in->alpha_w, 4.0);
	/* Paper eq. (dout).  With the wall floor the same diameter has a
	 * thicker wall and so a lower stress: the strength sizing stays valid. */
	double d = cbrt(32.0 * in->design_force_n * in->length_m
	    / (M_PI * k4 * structure_sigma_allow_pa()));
	out->sized_by = ARM_BY_STRENGTH;
	/* Stiffness: I >= F L² / (2 E θ_max), I = π d⁴ k4 / 64. */
	double theta = STRUCT_TILT_MAX_DEG * M_PI / 180.0;
	double i_tilt = in->full_force_n * in->length_m * in->length_m
	    / (2.0 * STRUCT_E_CF_PA * theta);
	double d_tilt = pow(64.0 * i_tilt / (M_PI * k4), 0.25);
	if (d_tilt > d) {
		d = d_tilt;
		out->sized_by = ARM_BY_TILT;
	}
	arm_at(in, d, out);
	/* The mode floor.  With the wall at α_w, I = π k4 d⁴/64 and the tube's
	 * mass per length μ = ρ π (1 - α²) d²/4, so eq. (fnat) at f is a
	 * quadratic in x = d²:  (3πE k4/64) x² - (ω² L⁴ 0.24 ρ π (1-α²)/4) x
	 * - ω² L³ m_tip = 0, ω = 2πf.  Where the wall floor binds (a thicker
	 * wall than α_w gives, only in the smallest tubes) the root is
	 * stiffer than needed: a few bisection steps bring it down. */
	if (in->mode_floor_hz > 0.0 && out->f_nat_hz < in->mode_floor_hz) {
		double w2 = pow(2.0 * M_PI * in->mode_floor_hz, 2.0);
		double l = in->length_m;
		double qa = 3.0 * M_PI * STRUCT_E_CF_PA * k4 / 64.0;
		double qb = w2 * l * l * l * l * 0.24 * STRUCT_RHO_CF_KG_M3 * M_PI
		    * (1.0 - in->alpha_w * in->alpha_w) / 4.0;
		double qc = w2 * l * l * l * in->tip_mass_kg;
		double d_mode = sqrt((qb + sqrt(qb * qb + 4.0 * qa * qc)) / (2.0 * qa));
		struct structure_arm t;
		arm_at(in, d_mode, &t);
		if (t.wall_floor_binds) {
			double lo = d, hi = d_mode;
			for (int k = 0; k < 30; k++) {
				double mid = 0.5 * (lo + hi);
				arm_at(in, mid, &t);
				if (t.f_nat_hz >= in->mode_floor_hz)
					hi = mid;
				else
					lo = mid;
			}
			d_mode = hi;
		}
		if (d_mode > d) {
			arm_at(in, d_mode, out);
			out->sized_by = ARM_BY_MODE;
		}
	}
	double sigma_fat = STRUCT_SIGMA_ULT_PA * STRUCT_FATIGUE;
	out->safety_factor = out->stress_pa > 0.0 ? sigma_fat / out->stress_pa : 0.0;
	double slope = tip_slope_rad(out, in->full_force_n);
	out->tilt_full_deg = slope * 180.0 / M_PI;
	out->deflection_full_m = 2.0 / 3.0 * slope * in->length_m; /* F L³ / 3EI */
	/* Torsion of a tube: τ = Q r / J, J = 2 I. */
	out->torsion_pa = out->i_x_m4 > 0.0
	    ? in->full_torque_nm * 0.5 * out->d_out_m / (2.0 * out->i_x_m4) : 0.0;
}

double
structure_rate_bandwidth_hz(double prop_diameter_m)
{
	return 0.5 * structure_gyro_filter_hz(prop_diameter_m);
}

bool
structure_band_clear(double f_nat_hz, double lo_hz, double hi_hz,
                     double margin, double *edge_hz, bool *above)
{
	double lo = lo_hz / margin, hi = hi_hz * margin;
	/* The side it is on: nearer the edge it can reach with less change. */
	*above = f_nat_hz >= sqrt(lo * hi);
	*edge_hz = *above ? hi : lo;
	return *above ? f_nat_hz >= hi : f_nat_hz <= lo;
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
