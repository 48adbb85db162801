/* batt.c — battery electrochemistry (see batt.h). */
#include "physics/batt.h"

#include <math.h>

/* Packaging terms of paper §VI-D. */
#define PKG_PER_CELL_ABOVE_6S    0.012 /* per series cell above 6S */
#define PKG_PER_EXTRA_PACK       0.06  /* per additional parallel pack */
#define PKG_SMALL_CELL_MAX       0.28  /* small-cell penalty at 0 mAh */
#define PKG_SMALL_CELL_REF_MAH   4000.0 /* penalty vanishes at this capacity */
#define PKG_SMALL_CELL_CONSUMER  0.5   /* penalty reduction, consumer/micro */
#define PKG_SMALL_FRAME          0.12  /* sub-250 mm frames */
#define PKG_SMALL_FRAME_W_M      0.25
#define PKG_ENTERPRISE_LOW_S     0.10  /* enterprise packs below 14S */
#define PKG_ENTERPRISE_HIGH_S    1.03  /* integrated enterprise packs >= 14S */
#define PKG_ENTERPRISE_S         14
#define PKG_CYLINDRICAL          1.15  /* Li-ion cells holders, exotic chemistries */

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
batt_packaging_factor(const struct batt_chem *c, double base, int cells,
                      double pack_capacity_mah, int n_packs,
                      double wheelbase_m, bool consumer_or_micro,
                      bool enterprise)
{
	if (!c->pouch)
		return PKG_CYLINDRICAL;
	if (enterprise && cells >= PKG_ENTERPRISE_S)
		return PKG_ENTERPRISE_HIGH_S;
	double eta = base;
	if (cells > 6)
		eta += PKG_PER_CELL_ABOVE_6S * (double)(cells - 6);
	if (n_packs > 1)
		eta += PKG_PER_EXTRA_PACK * (double)(n_packs - 1);
	if (pack_capacity_mah < PKG_SMALL_CELL_REF_MAH) {
		double pen = PKG_SMALL_CELL_MAX
		    * (1.0 - pack_capacity_mah / PKG_SMALL_CELL_REF_MAH);
		eta += consumer_or_micro ? PKG_SMALL_CELL_CONSUMER * pen : pen;
	}
	if (wheelbase_m < PKG_SMALL_FRAME_W_M)
		eta += PKG_SMALL_FRAME;
	if (enterprise)
		eta += PKG_ENTERPRISE_LOW_S;
	return eta;
}

double
batt_mass_kg(double energy_wh, double e_spec_wh_kg, double eta_pkg)
{
	return energy_wh / e_spec_wh_kg * eta_pkg;
}
