/* atmo.h — ISA atmosphere: troposphere and isothermal stratosphere to 20 km.
 *
 * Paper §IV-B, eq. (trop).  Pressure follows the ISA with height; density is
 * taken at the *ambient* temperature the mission states (ρ = P / (R T_amb)),
 * so a hot day at sea level is thinner air than ISA.  Physics layer: pure
 * functions, no I/O.
 */
#ifndef AEROEVAL_ATMO_H
#define AEROEVAL_ATMO_H

struct atmo_state {
	double altitude_m;     /* geopotential altitude, m (clamped to 0..20 km) */
	double pressure_pa;    /* ISA static pressure, Pa */
	double isa_temp_k;     /* ISA temperature at this altitude, K */
	double temp_k;         /* ambient temperature used, K */
	double rho_kg_m3;      /* density P / (R T_amb), kg / m^3 */
	double sound_m_s;      /* speed of sound sqrt(γ R T_amb), m / s */
	double mu_pa_s;        /* dynamic viscosity (Sutherland), Pa s */
};

/* ISA temperature at altitude_m, K. */
double atmo_isa_temp_k(double altitude_m);

/* ISA pressure at altitude_m, Pa. */
double atmo_isa_pressure_pa(double altitude_m);

/* The air at altitude_m with ambient temperature temp_k (pass
 * atmo_isa_temp_k(h) for the standard day). */
void atmo_at(double altitude_m, double temp_k, struct atmo_state *out);

#endif
