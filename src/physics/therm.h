/* therm.h — transient battery thermal model and motor winding resistance.
 *
 * Paper §VI-G, eq. (hacool): C_th dT/dt = I² R - hA (T - T_a), with
 * C_th = M_bat C_p and the scale-invariant cooling hA = h A, A = 6 dm² ×
 * (M_bat/2400 g)^(2/3) (h = 12 W/m²K, 120 for racing; the paper's 6 is the
 * reference pack's surface in dm², see therm.c).  Thermal runaway is declared above 60 °C.
 * Paper §V-D: R_m(T) = R_nom (1 + α_Cu (T - 25)).
 */
#ifndef AEROEVAL_THERM_H
#define AEROEVAL_THERM_H

#define THERM_CP_J_KGK        795.0  /* pack specific heat, J/(kg K) */
#define THERM_H_DEFAULT       12.0   /* convective coefficient, W/(m² K) */
#define THERM_H_RACING        120.0  /* exposed high-speed airflow, W/(m² K) */
#define THERM_RUNAWAY_C       60.0   /* thermal-runaway termination, °C */
#define THERM_ALPHA_CU_PER_K  0.00393 /* copper resistance coefficient, 1/K */

/* Convective conductance hA_c of a pack of mass_kg, W/K. */
double therm_hac_w_k(double battery_mass_kg, double h_w_m2k);

/* Advance the pack temperature over dt_s with heat input heat_w, exactly
 * (exponential solution of the linear ODE, stable for any dt), °C. */
double therm_step_c(double temp_c, double ambient_c, double heat_w,
                    double hac_w_k, double battery_mass_kg, double dt_s);

/* The same for many steps of one dt_s: therm_step_init() computes the
 * decay factor exp(-hA dt / C_th) once, therm_step_apply() equals
 * therm_step_c() to the last bit. */
struct therm_step {
	double c_th_j_k;       /* M_bat C_p */
	double hac_w_k;        /* hA_c */
	double dt_s;
	double decay;          /* exp(-hA_c dt / C_th) */
};
void therm_step_init(double hac_w_k, double battery_mass_kg, double dt_s,
                     struct therm_step *out);
double therm_step_apply(const struct therm_step *ts, double temp_c,
                        double ambient_c, double heat_w);

/* Winding resistance at temp_c from its 25 °C value, ohm. */
double therm_winding_resistance_ohm(double r_nom_ohm, double temp_c);

#endif
