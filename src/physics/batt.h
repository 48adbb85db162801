/* batt.h — battery electrochemistry: Tremblay–Dessaint OCV with C-rate
 * scaling, dynamic system resistance, current from the power balance with
 * voltage-collapse detection, and the per-configuration packaging factor.
 *
 * Paper §VI-A..E, eqs. (voc), (rsys), (batmass).  Physics layer: pure
 * functions over value structs, SI units (ohm, A, V, Ah where noted).
 */
#ifndef AEROEVAL_BATT_H
#define AEROEVAL_BATT_H

#include <stdbool.h>

#include "spec/model.h"

#define BATT_SOC_MIN          0.02    /* SOC clamp against the K/SOC pole, - */
#define BATT_C_RATE_B_SLOPE   0.18    /* B_eff = B (1 + 0.18 ln C), - */
#define BATT_TEMP_COEF_PER_K  0.013   /* f_temp = exp(-0.013 (T - 25)), 1/K */
#define BATT_AGING_PER_CYCLE  0.00125 /* k_ag, mid of the paper's 0.001-0.0015 */
#define BATT_REF_CAPACITY_AH  5.0     /* C_ref of eq. (rsys): R_i is quoted for a 5 Ah cell */
#define BATT_RDS_ON_OHM       0.002   /* ESC MOSFET on-resistance per ESC, ohm */
#define BATT_POWER_GUARD_W    1e7     /* power-overflow guard, W */

/* Current solution status. */
enum batt_status {
	BATT_OK,            /* a real current exists */
	BATT_COLLAPSE,      /* negative discriminant: voltage collapse */
	BATT_OVERFLOW       /* power not finite or above the guard */
};

/* Exponential-zone constant scaled by C-rate (only above 1C). */
double batt_b_eff(double b, double c_rate);

/* Open-circuit cell voltage at soc (clamped) and c_rate, eq. (voc). */
double batt_ocv_cell(const struct batt_chem *c, double soc, double c_rate);

/* System resistance of a pack of `cells` in series and total capacity_ah
 * at temp_c after `cycles`, plus the ESC on-resistance shared by n_rotors
 * ESCs, eq. (rsys), ohm. */
double batt_r_sys_ohm(const struct batt_chem *c, int cells, double capacity_ah,
                      double temp_c, int cycles, int n_rotors);

/* The same split into what a pack fixes and what its temperature changes,
 * for a time-step simulation that evaluates it every step:
 * batt_r_sys_at(&rs, T) after batt_r_sys_init() equals batt_r_sys_ohm()
 * to the last bit. */
struct batt_r_sys {
	double r_cells_ohm;    /* 1e-3 R_i N (C_ref / C): the cells at 25 °C, new */
	double f_aging;        /* 1 + k_ag · cycles */
	double r_esc_ohm;      /* R_ds,on / N_r: the ESC MOSFETs */
};
void batt_r_sys_init(const struct batt_chem *c, int cells, double capacity_ah,
                     int cycles, int n_rotors, struct batt_r_sys *out);
double batt_r_sys_at(const struct batt_r_sys *rs, double temp_c);

/* The cell resistance of a real pack from its maker's continuous rating:
 * makers rate the continuous current at about BATT_RATED_SAG_V of sag per
 * cell, so R_cell = sag / (C · Ah).  The C figure counted is capped by
 * chemistry (BATT_C_CREDIBLE_*): label ratings of high-C hobby packs run
 * far beyond what their cells deliver continuously.  Ohm per cell at 25 °C,
 * new.  The chemistry profile's R_i (eq. rsys) serves the continuous
 * design, which has no rating to go on. */
#define BATT_RATED_SAG_V        0.6   /* sag per cell at the rated current, V */
#define BATT_C_CREDIBLE_LIPO    100.0 /* LiPo/LiHV continuous C counted at most */
#define BATT_C_CREDIBLE_LI_ION  15.0  /* cylindrical Li-ion */
double batt_rated_cell_ohm(const struct batt_chem *c, double capacity_ah,
                           double continuous_c);

/* Current drawn for power_w from a source v_oc behind r_ohm:
 * I = (V - sqrt(V² - 4 R P)) / (2 R), computed as 2P / (V + sqrt(...)) so
 * that it stays exact as R -> 0.  Returns the status; *current_a is
 * set only when BATT_OK. */
enum batt_status batt_current_a(double v_oc, double r_ohm, double power_w,
                                double *current_a);

/* Pack-level specific energy (the whole pack: cells, wiring, case, BMS)
 * of one pack of `cells` in series storing pack_wh, Wh/kg:
 * e_100 (pack_wh / 100 Wh)^b (cells / 6)^-s, the chemistry's fit to the
 * catalogue's real packs (data/chemistries.json).  Larger packs carry
 * less case and wiring per watt-hour; at a given energy more series cells
 * means smaller cells, each with its own tabs, leads and separator. */
#define BATT_PACK_REF_CELLS 6.0
double batt_pack_wh_kg(const struct batt_chem *c, double pack_wh, int cells);

/* Mass of n_packs equal packs of `cells` in series storing energy_wh in
 * all, kg; a positive e_override_wh_kg (the mission's
 * battery_specific_energy_wh_kg) is the pack-level specific energy as
 * given. */
double batt_pack_mass_kg(const struct batt_chem *c, double energy_wh, int n_packs,
                         int cells, double e_override_wh_kg);

/* The inverse: the energy that n_packs packs of mass_kg in all store, Wh. */
double batt_pack_energy_wh(const struct batt_chem *c, double mass_kg, int n_packs,
                           int cells, double e_override_wh_kg);

#endif
