/* batt.c — battery electrochemistry (see batt.h). */
#include "physics/batt.h"

#include <math.h>

/* Packaging terms of paper §VI-D. */

double
batt_b_eff(double b, double c_rate)
{
	if (c_rate > 1.0)
		return b * (1.0 + BATT_C_RATE_B_SLOPE * log(c_rate));
	return b;
}

double
batt_ocv_cell(const struct batt_chem *c, double soc, double c_rate)
{
	if (!(soc >= BATT_SOC_MIN))
		soc = BATT_SOC_MIN;
	if (soc > 1.0)
		soc = 1.0;
	double b = batt_b_eff(c->b, c_rate);
	return c->v_exp + (c->v_full - c->v_exp) * exp(-b * (1.0 - soc))
	    - c->k * (1.0 / soc - 1.0);
}

void
batt_r_sys_init(const struct batt_chem *c, int cells, double capacity_ah,
                int cycles, int n_rotors, struct batt_r_sys *out)
{
	double cap = capacity_ah > 1e-6 ? capacity_ah : 1e-6;
	out->r_cells_ohm = 1e-3 * c->r_cell_mohm * (double)cells
	    * (BATT_REF_CAPACITY_AH / cap);
	out->f_aging = 1.0 + BATT_AGING_PER_CYCLE * (double)cycles;
	out->r_esc_ohm = BATT_RDS_ON_OHM / (double)n_rotors;
}

double
batt_r_sys_at(const struct batt_r_sys *rs, double temp_c)
{
	/* The products in eq. (rsys) order, so that the split changes no bit. */
	double f_temp = exp(-BATT_TEMP_COEF_PER_K * (temp_c - 25.0));
	return rs->r_cells_ohm * f_temp * rs->f_aging + rs->r_esc_ohm;
}

double
batt_r_sys_ohm(const struct batt_chem *c, int cells, double capacity_ah,
               double temp_c, int cycles, int n_rotors)
{
	struct batt_r_sys rs;
	batt_r_sys_init(c, cells, capacity_ah, cycles, n_rotors, &rs);
	return batt_r_sys_at(&rs, temp_c);
}

double
batt_rated_cell_ohm(const struct batt_chem *c, double capacity_ah,
                    double continuous_c)
{
	double cap = c->pouch ? BATT_C_CREDIBLE_LIPO : BATT_C_CREDIBLE_LI_ION;
	double rate = continuous_c < cap ? continuous_c : cap;
	return BATT_RATED_SAG_V / (rate * capacity_ah);
}

enum batt_status
batt_current_a(double v_oc, double r_ohm, double power_w, double *current_a)
{
	/* The guard comes first: an overflowing power must never reach the
	 * discriminant as Inf/NaN (paper §VI-F). */
	if (!isfinite(power_w) || power_w > BATT_POWER_GUARD_W)
		return BATT_OVERFLOW;
	if (power_w <= 0.0) {
		*current_a = 0.0;
		return BATT_OK;
	}
	double disc = v_oc * v_oc - 4.0 * r_ohm * power_w;
	if (disc < 0.0)
		return BATT_COLLAPSE;
	/* The smaller root written without cancellation, exact also for
	 * R -> 0 where it tends to P / V. */
	*current_a = 2.0 * power_w / (v_oc + sqrt(disc));
	return BATT_OK;
}

double
batt_pack_wh_kg(const struct batt_chem *c, double pack_wh, int cells)
{
	/* Below 1 Wh the catalogue has no packs: the law is held there. */
	double e = pack_wh > 1.0 ? pack_wh : 1.0;
	double s = cells > 0 ? (double)cells : 1.0;
	return c->pack_wh_kg_100 * pow(e / 100.0, c->pack_exponent)
	    * pow(s / BATT_PACK_REF_CELLS, -c->pack_series_exponent);
}

double
batt_pack_mass_kg(const struct batt_chem *c, double energy_wh, int n_packs,
                  int cells, double e_override_wh_kg)
{
	if (e_override_wh_kg > 0.0)
		return energy_wh / e_override_wh_kg;
	int n = n_packs > 0 ? n_packs : 1;
	return energy_wh / batt_pack_wh_kg(c, energy_wh / (double)n, cells);
}

double
batt_pack_energy_wh(const struct batt_chem *c, double mass_kg, int n_packs,
                    int cells, double e_override_wh_kg)
{
	if (e_override_wh_kg > 0.0)
		return mass_kg * e_override_wh_kg;
	/* m = E / (e_S (E / (100 n))^b) solved for E, e_S the law's value at
	 * 100 Wh for these cells; the floor of batt_pack_wh_kg() (1 Wh per
	 * pack) holds below. */
	double n = (double)(n_packs > 0 ? n_packs : 1);
	double b = c->pack_exponent;
	double e_s = batt_pack_wh_kg(c, 100.0, cells);
	double e_wh = pow(mass_kg * e_s / pow(100.0 * n, b), 1.0 / (1.0 - b));
	if (e_wh / n < 1.0)
		e_wh = mass_kg * batt_pack_wh_kg(c, 1.0, cells);
	return e_wh;
}
