/* role.c — payload mass over the mission (see role.h). */
#include "physics/role.h"

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
