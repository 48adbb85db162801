/* role.c — payload mass over the mission (see role.h). */
#include "role.h"

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

double
role_payload_mean(const struct role_shedding *s, double t_total_s)
{
	if (!(t_total_s > 0.0))
		return s->payload0_kg;
	switch (s->kind) {
	case SHED_DROP: {
		double t = s->drop_time_s < t_total_s ? s->drop_time_s : t_total_s;
		return (s->payload0_kg * t + (s->payload0_kg - s->drop_mass_kg)
		    * (t_total_s - t)) / t_total_s;
	}
	case SHED_SPRAY: {
		/* Linear fall until the tank is empty, flat after. */
		double t_empty = s->spray_rate_kg_s > 0.0
		    ? s->spray_mass_kg / s->spray_rate_kg_s : t_total_s;
		if (t_empty > t_total_s)
			t_empty = t_total_s;
		double sprayed_end = s->spray_rate_kg_s * t_empty;
		double area = s->payload0_kg * t_total_s
		    - 0.5 * sprayed_end * t_empty - sprayed_end * (t_total_s - t_empty);
		return area / t_total_s;
	}
	case SHED_NONE:
	default:
		return s->payload0_kg;
	}
}
