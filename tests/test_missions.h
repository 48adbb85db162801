/* test_missions.h — building mission specs in tests as the parser would
 * (each field set and marked given), for test_engine.c and test_sizing.c. */
#ifndef AEROEVAL_TEST_MISSIONS_H
#define AEROEVAL_TEST_MISSIONS_H

#include "spec/spec.h"

/* Set a mission field and mark it given, as the parser would. */
#define SET(s, id, member, value) \
	do { (s)->member = (value); (s)->given[SPECF_##id] = true; } while (0)

/* The fields every test mission names: the aircraft and its profile. */
struct test_profile {
	double payload_kg;
	double wheelbase_m;
	int n_rotors;
	int airframe_class;       /* enum airframe_class */
	double t_hover_s, t_climb_s, t_forward_s;
	double v_climb_ms, v_forward_ms;
	int role;                 /* enum role_type */
};

/* Defaults, then every field of *pr, each marked given. */
static inline void
test_mission(struct mission_spec *s, const struct test_profile *pr)
{
	spec_defaults(s);
	SET(s, PAYLOAD_KG, payload_kg, pr->payload_kg);
	SET(s, MAX_DIAMETER_M, max_diameter_m, pr->wheelbase_m);
	SET(s, NUM_ROTORS, num_rotors, pr->n_rotors);
	SET(s, AIRFRAME_CLASS, airframe_class, pr->airframe_class);
	SET(s, T_HOVER_S, t_hover_s, pr->t_hover_s);
	SET(s, T_CLIMB_S, t_climb_s, pr->t_climb_s);
	SET(s, T_FORWARD_S, t_forward_s, pr->t_forward_s);
	SET(s, V_CLIMB_MS, v_climb_ms, pr->v_climb_ms);
	SET(s, V_FORWARD_MS, v_forward_ms, pr->v_forward_ms);
	SET(s, ROLE_TYPE, payload_role.type, pr->role);
}

#endif
