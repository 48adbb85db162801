/* role.c — payload mass over the mission (see role.h). */
#include "physics/role.h"

#include <math.h>

double
role_payload_at(const struct role_shedding *s, double t_s)
{
	switch (s->kind) {
	case SHED_DROP:
		return t_s >= s->drop_time_s ? s->payload0_kg - s->drop_mass_kg
		    : s->payload0_kg;
	case SHED_SPRAY: {
		double sprayed = s->spray_rate_kg_s * (t_s > 0.0 ? t_s : 0.0);
		if (sprayed > s->spray_mass_kg)
			sprayed = s->spray_mass_kg;
		return s->payload0_kg - sprayed;
	}
	case SHED_NONE:
	default:
		return s->payload0_kg;
	}
}

/* ∫ min(r t, cap) dt over [a, b], a <= b, t >= 0. */
static double
sprayed_integral(double rate, double cap, double a, double b)
{
	double t_empty = rate > 0.0 ? cap / rate : INFINITY;
	double lin_b = b < t_empty ? b : t_empty;
	double area = 0.0;
	if (lin_b > a)
		area += 0.5 * rate * (lin_b * lin_b - a * a);
	double flat_a = a > t_empty ? a : t_empty;
	if (b > flat_a)
		area += cap * (b - flat_a);
	return area;
}

double
role_payload_mean(const struct role_shedding *s, double t0_s, double t1_s)
{
	if (!(t1_s > t0_s))
		return role_payload_at(s, t0_s);
	double span = t1_s - t0_s;
	switch (s->kind) {
	case SHED_DROP: {
		double before = s->drop_time_s - t0_s;
		before = before < 0.0 ? 0.0 : before > span ? span : before;
		return s->payload0_kg - s->drop_mass_kg * (span - before) / span;
	}
	case SHED_SPRAY: {
		double a = t0_s > 0.0 ? t0_s : 0.0, b = t1_s > 0.0 ? t1_s : 0.0;
		return s->payload0_kg - sprayed_integral(s->spray_rate_kg_s,
		    s->spray_mass_kg, a, b) / span;
	}
	case SHED_NONE:
	default:
		return s->payload0_kg;
	}
}
