/* motor.c — the DC-equivalent brushless motor (see motor.h). */
#include "physics/motor.h"

#include <math.h>

#include "physics/therm.h"
#include "util/units.h"

/* Estimates fitted to the parts catalogue (data/catalog/motors.json, the
 * 248 motors with KV, mass, R and I0 published; least squares in log
 * space, residual standard deviation in log units):
 *     R  = exp(16.974) KV^-1.065 m^-1.221   mOhm, m in g   (sd 0.40)
 *     I0 = exp(-9.121) KV^0.735 m^0.881     A              (sd 0.43)
 * Component facts, not aircraft facts; a motor with published values
 * never uses them. */
#define R_FIT_LN_MOHM   16.974
#define R_FIT_EXP_KV    (-1.065)
#define R_FIT_EXP_MASS  (-1.221)
#define I0_FIT_LN_A     (-9.121)
#define I0_FIT_EXP_KV   0.735
#define I0_FIT_EXP_MASS 0.881

/* The same fits on the stator's diameter d and height h (mm) instead of
 * the mass, over the 123 (R) and 165 (I0) motors that publish them with
 * their stator (least squares in log space, 2026-12 catalogue):
 *     R  = exp(29.286) KV^-1.719 d^-3.210 h^-1.108   mOhm   (sd 0.27)
 *     I0 = exp(-23.432) KV^1.655 d^2.991 h^0.878     A      (sd 0.39)
 * Closer to the physics than the mass law (a winding's turns go as
 * 1 / (KV d h), its resistance as the turns squared over the slot area),
 * and tighter: the mass law holds a racing motor's rotor bell, magnets and
 * cooling fins against it, and overstates a modern 2207's R about 2x. */
#define RS_FIT_LN_MOHM  29.286
#define RS_FIT_EXP_KV   (-1.719)
#define RS_FIT_EXP_D    (-3.210)
#define RS_FIT_EXP_H    (-1.108)
#define I0S_FIT_LN_A    (-23.432)
#define I0S_FIT_EXP_KV  1.655
#define I0S_FIT_EXP_D   2.991
#define I0S_FIT_EXP_H   0.878

double
motor_k_nm_a(double kv_rpm_per_v)
{
	return S_PER_MIN / (2.0 * M_PI * kv_rpm_per_v);
}

/* Fill the electrical side of a point from its current and speed. */
static void
point_from(const struct motor_model *m, double r_ohm, double k, double i_a,
           double rps, struct motor_point *out)
{
	double omega = 2.0 * M_PI * rps;
	out->rps = rps;
	out->current_a = i_a;
	out->torque_nm = k * (i_a - m->no_load_current_a);
	out->voltage_v = k * omega + i_a * r_ohm;
	out->power_in_w = out->voltage_v * i_a;
	out->power_shaft_w = out->torque_nm * omega;
	out->copper_loss_w = i_a * i_a * r_ohm;
	out->no_load_loss_w = k * omega * m->no_load_current_a;
	out->efficiency = out->power_in_w > 0.0 && out->power_shaft_w > 0.0
	    ? out->power_shaft_w / out->power_in_w : 0.0;
}

void
motor_at_shaft(const struct motor_model *m, double temp_c, double shaft_w,
               double rps, struct motor_point *out)
{
	double k = motor_k_nm_a(m->kv_rpm_per_v);
	double r = therm_winding_resistance_ohm(m->resistance_ohm, temp_c);
	double torque = shaft_w / (2.0 * M_PI * rps);
	point_from(m, r, k, torque / k + m->no_load_current_a, rps, out);
}

bool
motor_at_voltage(const struct motor_model *m, double temp_c, double v_v,
                 double kq_nm_s2, struct motor_point *out)
{
	double k = motor_k_nm_a(m->kv_rpm_per_v);
	double r = therm_winding_resistance_ohm(m->resistance_ohm, temp_c);
	/* kq n² = K ((V - 2π K n) / R - I0): a quadratic in n. */
	double b = 2.0 * M_PI * k * k / r;
	double c = k * (v_v / r - m->no_load_current_a);
	if (!(c > 0.0) || !(kq_nm_s2 > 0.0) || !(r > 0.0))
		return false;
	/* The root in the form that keeps its digits when kq b is small. */
	double n = 2.0 * c / (b + sqrt(b * b + 4.0 * kq_nm_s2 * c));
	double i_a = (v_v - 2.0 * M_PI * k * n) / r;
	point_from(m, r, k, i_a, n, out);
	return true;
}

void
motor_at_voltage_rps(const struct motor_model *m, double temp_c, double v_v,
                     double rps, struct motor_point *out)
{
	double k = motor_k_nm_a(m->kv_rpm_per_v);
	double r = therm_winding_resistance_ohm(m->resistance_ohm, temp_c);
	point_from(m, r, k, (v_v - 2.0 * M_PI * k * rps) / r, rps, out);
}

double
motor_thermal_resistance_k_w(double mass_kg)
{
	return MOTOR_RTH_REF_K_W * pow(mass_kg / MOTOR_RTH_REF_KG, -2.0 / 3.0);
}

double
motor_thermal_capacity_j_k(double mass_kg)
{
	return mass_kg * MOTOR_CP_J_KGK;
}

double
motor_temp_step_c(double mass_kg, double temp_c, double ambient_c,
                  double loss_w, double dt_s)
{
	return motor_temp_step_from(motor_thermal_resistance_k_w(mass_kg),
	    motor_temp_decay(mass_kg, dt_s), temp_c, ambient_c, loss_w);
}

double
motor_temp_decay(double mass_kg, double dt_s)
{
	double rth = motor_thermal_resistance_k_w(mass_kg);
	double cth = motor_thermal_capacity_j_k(mass_kg);
	return exp(-dt_s / (rth * cth));
}

double
motor_temp_step_from(double rth_k_w, double decay, double temp_c,
                     double ambient_c, double loss_w)
{
	double t_ss = ambient_c + loss_w * rth_k_w;
	return t_ss + (temp_c - t_ss) * decay;
}

double
motor_estimate_resistance_ohm(double kv_rpm_per_v, double mass_kg)
{
	return 1e-3 * exp(R_FIT_LN_MOHM + R_FIT_EXP_KV * log(kv_rpm_per_v)
	    + R_FIT_EXP_MASS * log(1000.0 * mass_kg));
}

double
motor_estimate_no_load_a(double kv_rpm_per_v, double mass_kg)
{
	return exp(I0_FIT_LN_A + I0_FIT_EXP_KV * log(kv_rpm_per_v)
	    + I0_FIT_EXP_MASS * log(1000.0 * mass_kg));
}

double
motor_estimate_resistance_stator_ohm(double kv_rpm_per_v, double d_mm,
                                     double h_mm)
{
	return 1e-3 * exp(RS_FIT_LN_MOHM + RS_FIT_EXP_KV * log(kv_rpm_per_v)
	    + RS_FIT_EXP_D * log(d_mm) + RS_FIT_EXP_H * log(h_mm));
}

double
motor_estimate_no_load_stator_a(double kv_rpm_per_v, double d_mm, double h_mm)
{
	return exp(I0S_FIT_LN_A + I0S_FIT_EXP_KV * log(kv_rpm_per_v)
	    + I0S_FIT_EXP_D * log(d_mm) + I0S_FIT_EXP_H * log(h_mm));
}
