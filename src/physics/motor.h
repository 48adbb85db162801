/* motor.h — a brushless motor on a real propeller: the DC-equivalent model.
 *
 * The design of record flies on real parts, so its operating points come
 * from the motor's own constants, not from a drive efficiency.  The model is
 * the one eCalc users know: speed constant KV, winding resistance R and
 * no-load current I0.  With K = 60 / (2π KV) (N m/A, and V s/rad):
 *
 *     torque      Q = K (I - I0)
 *     voltage     V = K ω + I R(T)          R(T) = R25 (1 + α_Cu (T - 25))
 *     input       P_in = V I,  shaft P = Q ω,  η = P / P_in
 *     losses      copper I² R, no-load (iron and friction) K ω I0
 *
 * I0 is taken as constant over speed (the datasheet value), as eCalc does.
 * The winding temperature follows the losses through a thermal resistance
 * and capacity estimated from the motor's mass (datasheets rarely publish
 * them): see motor.c.  Where the catalogue lacks R or I0, estimates fitted
 * to the catalogue's motors stand in (motor_estimate_*); the result says
 * which.
 *
 * Physics layer: pure functions over value structs, SI units.
 */
#ifndef AEROEVAL_MOTOR_H
#define AEROEVAL_MOTOR_H

#include <stdbool.h>

#define MOTOR_CP_J_KGK       450.0  /* heat capacity of copper, iron and
                                       aluminium in a motor, J/(kg K) */
#define MOTOR_RTH_REF_K_W    3.0    /* winding-to-air thermal resistance of a
                                       100 g motor in its own propwash, K/W */
#define MOTOR_RTH_REF_KG     0.1
#define MOTOR_WINDING_MAX_C  150.0  /* winding limit kept in flight: class H
                                       enamel takes 180 °C, the high-grade
                                       (SH) neodymium magnets of UAV motors
                                       150 °C before they demagnetise */

/* A motor's constants (one motor). */
struct motor_model {
	double kv_rpm_per_v;      /* speed constant */
	double resistance_ohm;    /* winding resistance at 25 °C */
	double no_load_current_a; /* I0 */
	double mass_kg;           /* for the thermal estimate */
};

/* One operating point of one motor. */
struct motor_point {
	double rps;               /* rotor speed, rev/s */
	double torque_nm;         /* shaft torque */
	double current_a;         /* motor current */
	double voltage_v;         /* voltage at the motor terminals */
	double power_in_w;        /* V I */
	double power_shaft_w;     /* Q ω */
	double efficiency;        /* P / P_in, in (0, 1] */
	double copper_loss_w;     /* I² R(T) */
	double no_load_loss_w;    /* K ω I0 */
};

/* Torque constant K of a KV (rpm/V), N m/A = V s/rad. */
double motor_k_nm_a(double kv_rpm_per_v);

/* The point where the motor, at winding temperature temp_c, delivers
 * shaft_w of shaft power at rps.  rps > 0. */
void motor_at_shaft(const struct motor_model *m, double temp_c, double shaft_w,
                    double rps, struct motor_point *out);

/* The speed at which the motor on terminal voltage v_v turns a propeller
 * whose torque is kq · n² (n in rev/s, kq = C_P ρ D⁵ / 2π), and the point
 * there.  Returns false when the voltage does not overcome the no-load
 * current (no positive speed). */
bool motor_at_voltage(const struct motor_model *m, double temp_c, double v_v,
                      double kq_nm_s2, struct motor_point *out);

/* The point of the motor on terminal voltage v_v turning at rps: the
 * current the voltage drives past the back-EMF, I = (V - 2π K n) / R(T),
 * and the torque it gives.  For a load whose torque is not quadratic in n
 * (a propeller at an advance ratio: prop.h): the caller balances the
 * torques. */
void motor_at_voltage_rps(const struct motor_model *m, double temp_c, double v_v,
                          double rps, struct motor_point *out);

/* Winding-to-air thermal resistance and heat capacity of a motor of mass
 * mass_kg: surface ∝ m^(2/3), so R_th = 3 K/W × (m / 0.1 kg)^(-2/3). */
double motor_thermal_resistance_k_w(double mass_kg);
double motor_thermal_capacity_j_k(double mass_kg);

/* Winding temperature after dt_s with losses loss_w from temp_c in air at
 * ambient_c (exact solution of C dT/dt = P - (T - T_a)/R_th). */
double motor_temp_step_c(double mass_kg, double temp_c, double ambient_c,
                         double loss_w, double dt_s);

/* motor_temp_step_c() in two parts, for a search that steps one motor
 * many times: the decay exp(-dt / (R_th C_th)) of a motor of mass_kg over
 * dt_s, then the step from it and the motor's R_th.  The same numbers. */
double motor_temp_decay(double mass_kg, double dt_s);
double motor_temp_step_from(double rth_k_w, double decay, double temp_c,
                            double ambient_c, double loss_w);

/* Estimates where the catalogue lacks a value: log-linear least squares
 * over the catalogue's motors with KV, mass, R and I0 published (motor.c
 * gives the fit and its scatter). */
double motor_estimate_resistance_ohm(double kv_rpm_per_v, double mass_kg);
double motor_estimate_no_load_a(double kv_rpm_per_v, double mass_kg);
/* The same from the stator's diameter and height (mm): tighter, used
 * wherever the catalogue names the stator. */
double motor_estimate_resistance_stator_ohm(double kv_rpm_per_v, double d_mm,
                                            double h_mm);
double motor_estimate_no_load_stator_a(double kv_rpm_per_v, double d_mm,
                                       double h_mm);

#endif
