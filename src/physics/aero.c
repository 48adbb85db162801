/* aero.c — rotor aerodynamics and body drag (see aero.h). */
#include "physics/aero.h"

#include "physics/atmo.h"
#include "util/units.h"

/* Newton–Raphson controls for Glauert's relation. */
#define GLAUERT_MAX_ITER 60
#define GLAUERT_EPSREL   1e-12

/* Forward-flight profile-power growth with advance ratio, (1 + K μ²). */
#define PROFILE_MU_K 4.65

double
aero_overlap_limit_m(double wheelbase_m, int n_arms, double clearance)
{
	/* Paper eq. (overlap): adjacent hubs are W sin(π/N) apart. */
	return (1.0 - clearance) * wheelbase_m * sin(M_PI / (double)n_arms);
}

double
aero_hover_induced_ms(double thrust_n, double rho_kg_m3, double area_m2)
{
	if (!(thrust_n > 0.0))
		return 0.0;
	return sqrt(thrust_n / (2.0 * rho_kg_m3 * area_m2));
}

double
aero_climb_induced_ms(double thrust_n, double rho_kg_m3, double area_m2,
                      double v_climb_ms)
{
	double vh = aero_hover_induced_ms(thrust_n, rho_kg_m3, area_m2);
	double half = 0.5 * v_climb_ms;
	/* Momentum theory in axial climb: v_i = -Vc/2 + sqrt((Vc/2)² + v_h²). */
	return -half + sqrt(half * half + vh * vh);
}

double
aero_glauert_induced_ms(double thrust_n, double rho_kg_m3, double area_m2,
                        double v_inf_ms, int *iter)
{
	double vh = aero_hover_induced_ms(thrust_n, rho_kg_m3, area_m2);
	double rhs = vh * vh; /* T / (2 ρ A) */
	double v2 = v_inf_ms * v_inf_ms;
	int k = 0;
	if (!(vh > 0.0)) {
		if (iter)
			*iter = 0;
		return 0.0;
	}
	/* Solve f(v) = v sqrt(V² + v²) - v_h² = 0.  f is increasing and convex
	 * for v > 0, so Newton from v_h (an upper bound) converges
	 * monotonically. */
	double v = vh;
	for (k = 1; k <= GLAUERT_MAX_ITER; k++) {
		double s = sqrt(v2 + v * v);
		double f = v * s - rhs;
		double df = s + v * v / s;
		double step = f / df;
		v -= step;
		if (v <= 0.0)
			v = 1e-9 * vh;
		if (fabs(step) <= GLAUERT_EPSREL * v)
			break;
	}
	if (iter)
		*iter = k > GLAUERT_MAX_ITER ? GLAUERT_MAX_ITER : k;
	return v;
}

double
aero_rps_for_thrust(double thrust_n, double ct, double rho_kg_m3,
                    double diameter_m)
{
	if (!(thrust_n > 0.0))
		return 0.0;
	double d2 = diameter_m * diameter_m;
	return sqrt(thrust_n / (ct * rho_kg_m3 * d2 * d2));
}

double
aero_cd0(double reynolds_tip)
{
	/* Paper eq. (cdre); below Re = 10⁵ the laminar-bubble growth is steeper. */
	double re = reynolds_tip > 1.0 ? reynolds_tip : 1.0;
	double ratio = 1e5 / re;
	if (re < 1e5)
		return 0.012 * pow(ratio, 0.5);
	return 0.012 * pow(ratio, 0.2);
}

double
aero_chord_m(double diameter_m, int n_blades)
{
	double radius = 0.5 * diameter_m;
	return AERO_SOLIDITY * M_PI * radius / (double)n_blades;
}

double
aero_tip_reynolds(const struct atmo_state *air, double v_tip_ms, double chord_m)
{
	return air->rho_kg_m3 * v_tip_ms * chord_m / air->mu_pa_s;
}

double
aero_profile_power_w(double cd0, double rho_kg_m3, double area_m2,
                     double v_tip_ms)
{
	return AERO_SOLIDITY * cd0 * rho_kg_m3 * area_m2
	    * v_tip_ms * v_tip_ms * v_tip_ms / 8.0;
}

double
aero_fom_installed(double fom_isolated, double kappa, bool isolated_mode,
                   double reynolds_tip, double re_ref)
{
	double fom_max = isolated_mode ? fom_isolated : fom_isolated / kappa;
	double re = reynolds_tip > 0.0 ? reynolds_tip : 0.0;
	double ref = re_ref > 0.0 ? re_ref : AERO_RE_REF;
	double fom = fom_max * (1.0 - exp(-re / ref));
	return fom < AERO_FOM_FLOOR ? AERO_FOM_FLOOR : fom;
}

double
aero_interference(double c_config, double arm_width_m, double diameter_m)
{
	double k = 1.0 + c_config * arm_width_m / diameter_m;
	return k > AERO_INTERFERENCE_CAP ? AERO_INTERFERENCE_CAP : k;
}

double
aero_ref_area_m2(double f_scale, double mass_kg, double added_area_m2)
{
	return f_scale * pow(mass_kg, 2.0 / 3.0) + added_area_m2;
}

double
aero_drag_n(double rho_kg_m3, double v_ms, double cd, double area_m2)
{
	return 0.5 * rho_kg_m3 * v_ms * v_ms * cd * area_m2;
}

void
aero_rotor_power(const struct aero_rotor *r, const struct atmo_state *air,
                 double thrust_n, double v_climb_ms, double v_fwd_ms,
                 double parasite_w, struct aero_point *out)
{
	double rho = air->rho_kg_m3;
	double area = 0.25 * M_PI * r->diameter_m * r->diameter_m;
	double vh = aero_hover_induced_ms(thrust_n, rho, area);

	out->thrust_n = thrust_n;
	out->rps = aero_rps_for_thrust(thrust_n, r->ct, rho, r->diameter_m);
	out->tip_speed_ms = M_PI * r->diameter_m * out->rps;
	out->tip_mach = out->tip_speed_ms / air->sound_m_s;
	out->reynolds_tip = aero_tip_reynolds(air, out->tip_speed_ms,
	    aero_chord_m(r->diameter_m, r->n_blades));
	out->glauert_iter = 0;

	/* Hover split of the FoM into profile and induced parts (see aero.h). */
	double p_ideal_hover = thrust_n * vh;
	double p_profile_hover = aero_profile_power_w(aero_cd0(out->reynolds_tip),
	    rho, area, out->tip_speed_ms);
	double k_induced = 1.0;
	if (p_ideal_hover > 0.0)
		k_induced = 1.0 / r->fom - p_profile_hover / p_ideal_hover;
	if (k_induced < 1.0)
		k_induced = 1.0; /* never better than ideal momentum theory */

	double mu = out->tip_speed_ms > 0.0 ? v_fwd_ms / out->tip_speed_ms : 0.0;
	if (v_fwd_ms > 0.0)
		out->induced_ms = aero_glauert_induced_ms(thrust_n, rho, area,
		    v_fwd_ms, &out->glauert_iter);
	else if (v_climb_ms > 0.0)
		out->induced_ms = aero_climb_induced_ms(thrust_n, rho, area, v_climb_ms);
	else
		out->induced_ms = vh;

	/* Paper: P_i = T (V_c + v_i).  Only the T v_i part carries the induced
	 * loss factor; the climb work T V_c is exact. */
	out->p_induced_w = k_induced * thrust_n * out->induced_ms
	    + thrust_n * (v_climb_ms > 0.0 ? v_climb_ms : 0.0);
	out->p_profile_w = p_profile_hover * (1.0 + PROFILE_MU_K * mu * mu);
	out->p_parasite_w = parasite_w;
	out->p_shaft_w = out->p_induced_w + out->p_profile_w + parasite_w;
}

double
aero_downwash_ms(double mass_kg, double rho_kg_m3, int n_rotors, double area_m2)
{
	/* Paper eq. (downwash): the far wake doubles the disk induced velocity. */
	return 2.0 * sqrt(mass_kg * G0_M_S2 / (2.0 * rho_kg_m3 * (double)n_rotors * area_m2));
}
