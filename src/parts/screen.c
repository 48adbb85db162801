/* screen.c — physical plausibility of catalogue entries (see screen.h). */
#include "parts/screen.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "physics/motor.h"
#include "physics/prop.h"
#include "sizing/sizing.h"
#include "util/units.h"

#define LIPO_MAX_CELL_V  4.35   /* the highest charge voltage of a hobby cell */
#define PROP_TREND_K     0.33   /* kg / m^2.2: the catalogue's glass-filled
                                   nylon two-blade trend (engine.c) */

/* Is ratio outside 1/factor .. factor? */
static bool
off_trend(double ratio, double factor)
{
	return !(ratio >= 1.0 / factor && ratio <= factor);
}

void
screen_motor_estimates(const struct catalog_motor *m, double *r_ohm,
                       double *i0_a)
{
	double d_mm, h_mm;
	if (catalog_motor_stator_mm(m, &d_mm, &h_mm)) {
		*r_ohm = motor_estimate_resistance_stator_ohm(m->kv_rpm_per_v,
		    d_mm, h_mm);
		*i0_a = motor_estimate_no_load_stator_a(m->kv_rpm_per_v, d_mm, h_mm);
	} else {
		*r_ohm = motor_estimate_resistance_ohm(m->kv_rpm_per_v, m->mass_kg);
		*i0_a = motor_estimate_no_load_a(m->kv_rpm_per_v, m->mass_kg);
	}
}

const char *
screen_motor(const struct catalog_motor *m, char *why, size_t n)
{
	if (m->integrated || !(m->mass_kg > 0.0) || !(m->kv_rpm_per_v > 0.0))
		return NULL;
	if (m->max_power_w > 0.0 && m->cells_max > 0 && m->max_current_a > 0.0) {
		double vi = SCREEN_VI_SLACK * m->max_current_a * LIPO_MAX_CELL_V
		    * (double)m->cells_max;
		if (m->max_power_w > vi) {
			snprintf(why, n, "max_power_w: %.0f W, more than %.0f A at %dS "
			    "can carry (%.0f W)", m->max_power_w, m->max_current_a,
			    m->cells_max, vi);
			return why;
		}
	}
	if (m->max_power_w > 0.0 && m->max_current_a > 0.0) {
		double omega = 2.0 * M_PI * m->kv_rpm_per_v / S_PER_MIN
		    * m->max_power_w / m->max_current_a;
		double ratio = m->mass_kg / sizing_motor_kg(m->max_power_w, omega);
		/* Racing motors run far lighter than the law, by design. */
		if (m->kv_rpm_per_v < 1500.0 && off_trend(ratio, SCREEN_TREND_FACTOR)) {
			snprintf(why, n, "mass_g: %.0f g is %.2f x the catalogue's trend "
			    "for %.0f W", m->mass_kg * 1000.0, ratio, m->max_power_w);
			return why;
		}
	}
	double est_r_ohm, est_i0_a;
	screen_motor_estimates(m, &est_r_ohm, &est_i0_a);
	if (m->resistance_ohm > 0.0) {
		double est = est_r_ohm;
		if (off_trend(m->resistance_ohm / est, SCREEN_RI_FACTOR)) {
			snprintf(why, n, "resistance_mohm: %.1f mOhm is %.2f x the "
			    "catalogue's trend for its KV and size",
			    m->resistance_ohm * 1000.0, m->resistance_ohm / est);
			return why;
		}
	}
	if (m->no_load_current_a > 0.0) {
		double est = est_i0_a;
		if (off_trend(m->no_load_current_a / est, SCREEN_RI_FACTOR)) {
			snprintf(why, n, "no_load_current_a: %.2f A is %.2f x the "
			    "catalogue's trend for its KV and size",
			    m->no_load_current_a, m->no_load_current_a / est);
			return why;
		}
	}
	return NULL;
}

const char *
screen_prop(const struct catalog_prop *p, char *why, size_t n)
{
	if (!(p->mass_kg > 0.0) || !(p->diameter_in > 0.0))
		return NULL;
	double blades = p->blades > 0 ? (double)p->blades : 2.0;
	double trend = PROP_TREND_K * pow(in_to_m(p->diameter_in), 2.2) * blades / 2.0;
	if (off_trend(p->mass_kg / trend, SCREEN_TREND_FACTOR)) {
		snprintf(why, n, "mass_g: %.1f g is %.2f x the catalogue's trend for "
		    "%.1f in", p->mass_kg * 1000.0, p->mass_kg / trend, p->diameter_in);
		return why;
	}
	if (p->ct_static > 0.0 && p->cp_static > 0.0) {
		struct prop_coeffs c = { p->ct_static, p->cp_static, true };
		if (prop_fom(&c) > SCREEN_FOM_MAX) {
			snprintf(why, n, "cp_static: C_T %.3f and C_P %.4f make a figure "
			    "of merit of %.2f, above %.2f", p->ct_static, p->cp_static,
			    prop_fom(&c), SCREEN_FOM_MAX);
			return why;
		}
	}
	return NULL;
}

const char *
screen_battery(const struct catalog_battery *b, char *why, size_t n)
{
	if (!(b->mass_kg > 0.0) || !(b->capacity_ah > 0.0) || b->cells_series < 1)
		return NULL;
	double v_cell = b->nominal_voltage_v > 0.0
	    ? b->nominal_voltage_v / (double)b->cells_series : 3.7;
	double wh = b->energy_wh > 0.0 ? b->energy_wh
	    : (double)b->cells_series * v_cell * b->capacity_ah;
	double wh_kg = wh / b->mass_kg;
	double max = strncmp(b->chemistry, "LiPo", 4) == 0
	    || strcmp(b->chemistry, "LiHV") == 0 ? SCREEN_PACK_MAX_LIPO
	    : SCREEN_PACK_MAX_LIION;
	if (wh_kg < SCREEN_PACK_MIN_WH_KG || wh_kg > max) {
		snprintf(why, n, "mass_g: %.0f Wh in %.0f g is %.0f Wh/kg, outside "
		    "%.0f-%.0f", wh, b->mass_kg * 1000.0, wh_kg, SCREEN_PACK_MIN_WH_KG,
		    max);
		return why;
	}
	if (b->continuous_c * wh_kg > SCREEN_PACK_MAX_W_KG) {
		snprintf(why, n, "continuous_c: %.0fC at %.0f Wh/kg is %.1f kW/kg "
		    "sustained, above %.0f", b->continuous_c, wh_kg,
		    b->continuous_c * wh_kg / 1000.0, SCREEN_PACK_MAX_W_KG / 1000.0);
		return why;
	}
	return NULL;
}

const char *
screen_esc(const struct catalog_esc *e, char *why, size_t n)
{
	if (!(e->mass_kg > 0.0) || !(e->continuous_current_a > 0.0))
		return NULL;
	double channels = e->channels > 0 ? (double)e->channels : 1.0;
	double a_g = e->continuous_current_a * channels / (e->mass_kg * 1000.0);
	double limit = channels > 1.0 ? SCREEN_STACK_MAX_A_G : SCREEN_ESC_MAX_A_G;
	if (a_g > limit) {
		snprintf(why, n, "mass_g: %.1f g for %.0f x %.0f A (%.1f A/g, at most "
		    "%.0f)", e->mass_kg * 1000.0, channels, e->continuous_current_a,
		    a_g, limit);
		return why;
	}
	return NULL;
}

bool
screen_uncertain(const char *uncertain, const char *key)
{
	return catalog_list_names(uncertain, key);
}

/* The first of keys (NULL-terminated) that the list uncertain names, or
 * NULL. */
static const char *
doubted(const char *uncertain, const char *const *keys, char *why, size_t n)
{
	for (const char *const *k = keys; *k != NULL; k++)
		if (screen_uncertain(uncertain, *k)) {
			snprintf(why, n, "%s: listed as uncertain in the catalogue", *k);
			return why;
		}
	return NULL;
}

const char *
screen_doubt_motor(const struct catalog_motor *m, char *why, size_t n)
{
	static const char *const plain[] = { "kv_rpm_per_v", "mass_g",
		"max_current_a", NULL };
	static const char *const integrated[] = { "kv_rpm_per_v", "mass_g",
		"max_current_a", "integrated_prop_in", "max_thrust_g", NULL };
	return doubted(m->uncertain, m->integrated ? integrated : plain, why, n);
}

const char *
screen_doubt_prop(const struct catalog_prop *p, char *why, size_t n)
{
	static const char *const keys[] = { "diameter_in", "pitch_in", "mass_g",
		NULL };
	return doubted(p->uncertain, keys, why, n);
}

const char *
screen_doubt_battery(const struct catalog_battery *b, char *why, size_t n)
{
	/* The chemistry is not among them: a pack sold as "Li-ion" has its
	 * NCA/NMC profile marked uncertain, but its family (voltages,
	 * energy) is known and its capacity and mass are the maker's. */
	static const char *const keys[] = { "cells_series", "capacity_mah",
		"mass_g", "continuous_c", NULL };
	return doubted(b->uncertain, keys, why, n);
}

const char *
screen_doubt_esc(const struct catalog_esc *e, char *why, size_t n)
{
	static const char *const keys[] = { "continuous_current_a", "mass_g",
		"channels", NULL };
	return doubted(e->uncertain, keys, why, n);
}

const char *
screen_doubt_frame(const struct catalog_frame *f, char *why, size_t n)
{
	static const char *const keys[] = { "rotor_count", "wheelbase_mm",
		"mass_g", "includes", "max_prop_in", "max_takeoff_kg", NULL };
	return doubted(f->uncertain, keys, why, n);
}
