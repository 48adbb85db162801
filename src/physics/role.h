/* role.h — payload mass over the mission: the path-dependent shedding of
 * paper §VI-H.  Delivery drops drop_mass_kg at r_drop · t_total; agriculture
 * sprays continuously at spray_rate_kg_s (M_fluid / t_mission when not given)
 * until the tank is empty.
 */
#ifndef AEROEVAL_ROLE_H
#define AEROEVAL_ROLE_H

#include "spec/model.h"

struct role_shedding {
	enum shed_kind kind;     /* none, drop, spray */
	double payload0_kg;      /* payload at takeoff */
	double drop_mass_kg;     /* released at the drop (delivery) */
	double drop_time_s;      /* r_drop · t_total (delivery) */
	double spray_rate_kg_s;  /* ṁ (agriculture) */
	double spray_mass_kg;    /* liquid that can be sprayed */
};

/* Payload mass carried at time t_s. */
double role_payload_at(const struct role_shedding *s, double t_s);

/* The payload's time average over [t0_s, t1_s] (exact: a drop is a step,
 * a spray a ramp): the mass a phase's table is evaluated at. */
double role_payload_mean(const struct role_shedding *s, double t0_s,
                         double t1_s);

#endif
