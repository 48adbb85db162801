/* atmo.c — ISA atmosphere (see atmo.h). */
#include "physics/atmo.h"

#include "util/units.h"

/* Sutherland's law constants for air. */
#define SUTH_MU0_PA_S  1.716e-5  /* reference viscosity at 273.15 K, Pa s */
#define SUTH_T0_K      273.15    /* reference temperature, K */
#define SUTH_S_K       110.4     /* Sutherland temperature, K */

static double
clamp_altitude(double h_m)
{
	if (!(h_m > 0.0))
		return 0.0;
	return h_m > ISA_HMAX_M ? ISA_HMAX_M : h_m;
}

double
atmo_isa_temp_k(double altitude_m)
{
	double h = clamp_altitude(altitude_m);
	if (h <= ISA_H11_M)
		return ISA_T0_K - ISA_LAPSE_K_M * h;
	return ISA_T11_K;
}

double
atmo_isa_pressure_pa(double altitude_m)
{
	double h = clamp_altitude(altitude_m);
	/* Paper eq. (trop): exponent g / (R L) ≈ 5.256. */
	double expo = G0_M_S2 / (R_AIR_J_KGK * ISA_LAPSE_K_M);
	if (h <= ISA_H11_M)
		return ISA_P0_PA * pow(1.0 - ISA_LAPSE_K_M * h / ISA_T0_K, expo);
	double p11 = ISA_P0_PA * pow(1.0 - ISA_LAPSE_K_M * ISA_H11_M / ISA_T0_K, expo);
	return p11 * exp(-G0_M_S2 * (h - ISA_H11_M) / (R_AIR_J_KGK * ISA_T11_K));
}

void
atmo_at(double altitude_m, double temp_k, struct atmo_state *out)
{
	out->altitude_m = clamp_altitude(altitude_m);
	out->pressure_pa = atmo_isa_pressure_pa(out->altitude_m);
	out->isa_temp_k = atmo_isa_temp_k(out->altitude_m);
	out->temp_k = temp_k;
	out->rho_kg_m3 = out->pressure_pa / (R_AIR_J_KGK * temp_k);
	out->sound_m_s = sqrt(GAMMA_AIR * R_AIR_J_KGK * temp_k);
	out->mu_pa_s = SUTH_MU0_PA_S * pow(temp_k / SUTH_T0_K, 1.5)
	    * (SUTH_T0_K + SUTH_S_K) / (temp_k + SUTH_S_K);
}
