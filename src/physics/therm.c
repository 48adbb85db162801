/* therm.c — transient battery thermal model (see therm.h). */
#include "physics/therm.h"

#include <math.h>

/* Reference pack of eq. (hacool): 2400 g with 6 dm² of surface.  The paper
 * prints "h · 6 (M/2400)^(2/3)" without the area's unit; a 2.4 kg cube of
 * pack density (about 2200 kg/m³) has 6.4 dm² of surface, so the 6 is in
 * dm².  Read as m² it would cool a pack a hundred times better than its
 * surface can: 72 W/K for 2.4 kg, a flat temperature trace whatever the
 * losses. */
#define HAC_REF_MASS_G 2400.0
#define HAC_REF_AREA_M2 0.06

double
therm_hac_w_k(double battery_mass_kg, double h_w_m2k)
{
	double m_g = battery_mass_kg * 1000.0;
	if (m_g < 0.0)
		m_g = 0.0;
	return h_w_m2k * HAC_REF_AREA_M2 * pow(m_g / HAC_REF_MASS_G, 2.0 / 3.0);
}

void
therm_step_init(double hac_w_k, double battery_mass_kg, double dt_s,
                struct therm_step *out)
{
	out->c_th_j_k = battery_mass_kg * THERM_CP_J_KGK;
	out->hac_w_k = hac_w_k;
	out->dt_s = dt_s;
	out->decay = out->c_th_j_k > 0.0 && hac_w_k > 0.0
	    ? exp(-hac_w_k * dt_s / out->c_th_j_k) : 0.0;
}

double
therm_step_apply(const struct therm_step *ts, double temp_c, double ambient_c,
                 double heat_w)
{
	if (!(ts->c_th_j_k > 0.0))
		return temp_c;
	if (!(ts->hac_w_k > 0.0))
		return temp_c + heat_w * ts->dt_s / ts->c_th_j_k;
	double t_ss = ambient_c + heat_w / ts->hac_w_k;
	return t_ss + (temp_c - t_ss) * ts->decay;
}

double
therm_step_c(double temp_c, double ambient_c, double heat_w, double hac_w_k,
             double battery_mass_kg, double dt_s)
{
	struct therm_step ts;
	therm_step_init(hac_w_k, battery_mass_kg, dt_s, &ts);
	return therm_step_apply(&ts, temp_c, ambient_c, heat_w);
}

double
therm_winding_resistance_ohm(double r_nom_ohm, double temp_c)
{
	return r_nom_ohm * (1.0 + THERM_ALPHA_CU_PER_K * (temp_c - 25.0));
}
