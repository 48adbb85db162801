/* duty.h — a role's duty cycle: its mission laid out as segments.
 *
 * The paper flies every mission as three phases (climb, forward, hover).
 * A role flies its mission its own way (data/roles.json "duty";
 * docs/model.md, "Duty cycles"):
 *   - phases: the paper's climb, forward flight and hover;
 *   - race: the forward time is a race, laps of full-throttle bursts,
 *     high-speed runs and corners, each piece drawing a fraction of the
 *     design's full-throttle battery power;
 *   - spray sorties: the forward distance is a transit to the field,
 *     spraying passes of the role's swath length with a turn at each swath
 *     end (brake, yaw, accelerate) and the transit back; the tank is shed
 *     while, and only while, the aircraft sprays;
 *   - out and back: the out-leg with the parcel, a hover over the drop
 *     point, the release, and the return leg without it.
 * duty_plan_build() lays the mission out as segments, each accounted to
 * the phase whose time it flies; the discharge (discharge.h) flies them
 * one after another, so energy = ∫P dt over the very segments the dossier
 * lists.  The plan is bounded (DUTY_MAX_SEG): a race of more than
 * DUTY_MAX_LAPS laps is flown as DUTY_MAX_LAPS longer laps, and more than
 * DUTY_MAX_PASSES passes as that many longer passes with the turns' time
 * shared among them (same times, same powers, same energy; only the
 * ripple of the pack's temperature is coarser).  Pure: no allocation.
 */
#ifndef AEROEVAL_DUTY_H
#define AEROEVAL_DUTY_H

#include <stdbool.h>

#include "spec/model.h"
#include "result/result.h"
#include "physics/role.h"

#define DUTY_MAX_LAPS   24   /* laps flown one by one */
#define DUTY_MAX_PASSES 24   /* spraying passes flown one by one */
#define DUTY_MAX_SEG    (DUTY_MAX_LAPS * MODEL_MAX_LAP + 8)
#define DUTY_MAX_GROUP  RES_MAX_DUTY_GROUPS
_Static_assert(MODEL_MAX_LAP + 3 <= DUTY_MAX_GROUP, "a race's groups must fit");
_Static_assert(2 * DUTY_MAX_PASSES + 6 <= DUTY_MAX_SEG, "a sortie must fit");

/* How a segment's battery power follows from the aircraft. */
enum duty_law {
	DUTY_LAW_FLIGHT,    /* mission_power() at the segment's speeds */
	DUTY_LAW_THROTTLE,  /* fraction × the full-throttle battery power, and
	                       never below the hover power at the mass */
	DUTY_LAW_TURN       /* a swath end: brake, yaw, accelerate */
};

/* One kind of segment, as the dossier lists it. */
struct duty_group {
	char name[RES_DUTY_NAME];  /* "spraying pass" */
	int phase;                 /* enum res_phase_id its time counts in */
	int count;                 /* how many the mission flies */
	double dur_s;              /* their time together */
	double fraction;           /* DUTY_LAW_THROTTLE: of full throttle */
};

struct duty_segment {
	int group;                 /* index into duty_plan.group */
	int phase;                 /* enum res_phase_id */
	enum duty_law law;
	double t0_s;               /* start, since takeoff */
	double dur_s;
	double v_climb_ms;         /* climb rate (DUTY_LAW_FLIGHT) */
	double v_fwd_ms;           /* forward speed (flight, turn) */
	double fraction;           /* DUTY_LAW_THROTTLE */
	double accel_m_s2;         /* DUTY_LAW_TURN: braking = acceleration */
	double yaw_s;              /* DUTY_LAW_TURN: of dur_s, the yaw */
	double payload0_kg;        /* payload at the segment's start */
	double shed_kg_s;          /* shed while it flies (spraying) */
	double payload_min_kg;     /* the payload with the tank empty */
	bool whole_phase;          /* a whole phase of the paper's mission,
	                              flown in at least 4 steps */
};

struct duty_plan {
	enum duty_kind kind;       /* the profile flown */
	int n_seg;
	int n_group;
	struct duty_group group[DUTY_MAX_GROUP];
	double total_s;            /* the flight */
	double phase_s[PHASE_MAX]; /* time accounted in each phase */
	/* What the profile made of the mission. */
	int n_laps;                /* race: laps (the race / the lap, rounded) */
	double lap_s;              /* race: one lap as flown */
	double lap_mean_fraction;  /* race: a lap's mean over full throttle */
	double lap_peak_fraction;  /* race: its highest piece */
	int n_passes, n_turns;     /* spray: passes, and a turn between two */
	double swath_length_m;     /* spray: the role's pass length */
	double pass_m;             /* spray: one pass as flown */
	double turn_s;             /* spray: one turn */
	double transit_m;          /* spray: each way */
	double spray_s;            /* spray: time spraying */
	double spray_rate_kg_s;    /* spray: tank shed rate */
	double drop_time_s;        /* delivery: the release; < 0: none */
	double drop_mass_kg;       /* delivery: released */
	/* Last: only seg[0 .. n_seg) is ever written or read, so a new plan
	 * clears what comes before it, not its 150 slots (the solve builds
	 * a plan per flight it flies). */
	struct duty_segment seg[DUTY_MAX_SEG];
};

/* What a plan is built from: the role's profile and the mission. */
struct duty_input {
	const struct model_duty *duty;   /* NULL: the paper's three phases */
	double duration_s[PHASE_MAX];    /* the phases' times (goal relaxation
	                                    applied) */
	double v_climb_ms, v_fwd_ms;     /* as flown */
	double payload_kg;               /* at takeoff */
	enum shed_kind shed;             /* SHED_NONE: sized static */
	double drop_mass_kg;             /* delivery: released */
	double drop_ratio;               /* delivery: the out-leg's share of the
	                                    forward time (phases: the drop's
	                                    share of the whole mission) */
	double spray_rate_kg_s;          /* > 0 given; 0: the tank empties at
	                                    the end of the last pass */
};

/* Lay out the mission of in as out's segments. */
void duty_plan_build(const struct duty_input *in, struct duty_plan *out);

/* The paper's three phases with a legacy shedding (a drop at
 * sh->drop_time_s, or a spray from takeoff): the plan of a phases profile,
 * and of a discharge given phases rather than a plan. */
void duty_plan_phases(const double *duration_s, double v_climb_ms,
                      double v_fwd_ms, const struct role_shedding *sh,
                      struct duty_plan *out);

/* The payload at a segment's time a_s (since its start), and its mean
 * over [a_s, b_s] (exact: the tank empties linearly, then stays empty). */
double duty_payload_at(const struct duty_segment *s, double a_s);
double duty_payload_mean(const struct duty_segment *s, double a_s, double b_s);

/* The payload's time average over the segments of one phase. */
double duty_phase_mean_payload(const struct duty_plan *pl, int phase);

/* A race lap's mean power over the full-throttle power, before the hover
 * floor (0 for a profile without laps). */
double duty_lap_mean_fraction(const struct model_duty *d);

#endif
