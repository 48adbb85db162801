/* duty.c — a role's duty cycle laid out as segments (see duty.h). */
#include "physics/duty.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "util/strbuf.h"

_Static_assert(MODEL_DUTY_SOURCE == RES_DUTY_SOURCE,
    "a profile's source text must fit the result's");

/* Start a group; its index. */
static int
add_group(struct duty_plan *pl, const char *name, int phase, double fraction)
{
	if (pl->n_group >= DUTY_MAX_GROUP)
		return DUTY_MAX_GROUP - 1; /* unreachable: the asserts of duty.h */
	struct duty_group *g = &pl->group[pl->n_group];
	str_copy(g->name, sizeof g->name, name);
	g->phase = phase;
	g->count = 0;
	g->dur_s = 0.0;
	g->fraction = fraction;
	return pl->n_group++;
}

/* Append a segment of group g at the plan's end, dur_s long, with the
 * payload payload0_kg at its start; a pointer to it (its law and speeds
 * are the caller's to set), or NULL when it has no time or no room. */
static struct duty_segment *
add_seg(struct duty_plan *pl, int g, enum duty_law law, double dur_s,
        double payload0_kg)
{
	if (!(dur_s > 0.0) || pl->n_seg >= DUTY_MAX_SEG)
		return NULL;
	struct duty_segment *s = &pl->seg[pl->n_seg++];
	memset(s, 0, sizeof *s);
	s->group = g;
	s->phase = pl->group[g].phase;
	s->law = law;
	s->t0_s = pl->total_s;
	s->dur_s = dur_s;
	s->payload0_kg = payload0_kg;
	s->payload_min_kg = payload0_kg;
	pl->total_s += dur_s;
	pl->phase_s[s->phase] += dur_s;
	pl->group[g].dur_s += dur_s;
	return s;
}

static void
plan_init(struct duty_plan *pl, enum duty_kind kind)
{
	memset(pl, 0, offsetof(struct duty_plan, seg));
	pl->kind = kind;
	pl->drop_time_s = -1.0;
}

double
duty_payload_at(const struct duty_segment *s, double a_s)
{
	double p = s->payload0_kg - s->shed_kg_s * (a_s > 0.0 ? a_s : 0.0);
	return p > s->payload_min_kg ? p : s->payload_min_kg;
}

double
duty_payload_mean(const struct duty_segment *s, double a_s, double b_s)
{
	if (!(b_s > a_s) || !(s->shed_kg_s > 0.0))
		return duty_payload_at(s, a_s);
	/* The tank runs dry at t_dry: a ramp before it, flat after. */
	double t_dry = (s->payload0_kg - s->payload_min_kg) / s->shed_kg_s;
	double area = 0.0;
	double ramp_b = b_s < t_dry ? b_s : t_dry;
	if (ramp_b > a_s)
		area += (ramp_b - a_s) * (s->payload0_kg
		    - 0.5 * s->shed_kg_s * (a_s + ramp_b));
	double flat_a = a_s > t_dry ? a_s : t_dry;
	if (b_s > flat_a)
		area += (b_s - flat_a) * s->payload_min_kg;
	return area / (b_s - a_s);
}

double
duty_phase_mean_payload(const struct duty_plan *pl, int phase)
{
	double area = 0.0, span = 0.0, last = 0.0;
	bool any = false;
	for (int i = 0; i < pl->n_seg; i++) {
		const struct duty_segment *s = &pl->seg[i];
		if (s->phase != phase)
			continue;
		area += s->dur_s * duty_payload_mean(s, 0.0, s->dur_s);
		span += s->dur_s;
		last = s->payload0_kg;
		any = true;
	}
	if (!any)
		return pl->n_seg > 0 ? pl->seg[0].payload0_kg : 0.0;
	return span > 0.0 ? area / span : last;
}

double
duty_lap_mean_fraction(const struct model_duty *d)
{
	if (d == NULL || d->kind != DUTY_RACE)
		return 0.0;
	double f = 0.0;
	for (int i = 0; i < d->n_lap; i++)
		f += d->lap[i].share * d->lap[i].power_fraction;
	return f;
}

/* ---- the paper's three phases ---------------------------------------------- */

static const char *const phase_group_name[PHASE_MAX] = { "climb",
	"forward flight", "hover" };

void
duty_plan_phases(const double *duration_s, double v_climb_ms, double v_fwd_ms,
                 const struct role_shedding *sh, struct duty_plan *pl)
{
	plan_init(pl, DUTY_PHASES);
	int g[PHASE_MAX];
	for (int ph = 0; ph < PHASE_MAX; ph++)
		g[ph] = add_group(pl, phase_group_name[ph], ph, 0.0);
	double t = 0.0;
	double drop = sh->kind == SHED_DROP ? sh->drop_time_s : -1.0;
	for (int ph = 0; ph < PHASE_MAX; ph++) {
		double dur = duration_s[ph];
		if (!(dur > 0.0))
			continue;
		pl->group[g[ph]].count = 1;
		/* A drop inside the phase splits it: each piece flies one mass. */
		double cut[2] = { dur, 0.0 };
		if (drop > t && drop < t + dur) {
			cut[0] = drop - t;
			cut[1] = t + dur - drop;
			pl->drop_time_s = drop;
			pl->drop_mass_kg = sh->drop_mass_kg;
		} else if (drop >= 0.0 && drop <= t && pl->drop_time_s < 0.0) {
			pl->drop_time_s = drop;
			pl->drop_mass_kg = sh->drop_mass_kg;
		}
		for (int k = 0; k < 2; k++) {
			double t0 = pl->total_s;
			struct duty_segment *s = add_seg(pl, g[ph], DUTY_LAW_FLIGHT,
			    cut[k], role_payload_at(sh, t0));
			if (s == NULL)
				continue;
			s->whole_phase = true;
			s->v_climb_ms = ph == PHASE_CLIMB ? v_climb_ms : 0.0;
			s->v_fwd_ms = ph == PHASE_FORWARD ? v_fwd_ms : 0.0;
			if (sh->kind == SHED_SPRAY) {
				s->shed_kg_s = sh->spray_rate_kg_s;
				s->payload_min_kg = sh->payload0_kg - sh->spray_mass_kg;
				if (s->payload_min_kg > s->payload0_kg)
					s->payload_min_kg = s->payload0_kg;
			}
		}
		t += dur;
	}
	if (sh->kind == SHED_SPRAY) {
		pl->spray_rate_kg_s = sh->spray_rate_kg_s;
		pl->spray_s = pl->total_s;
	}
}

/* The legacy shedding of a phases profile: a drop at r_drop × t_total, a
 * spray from takeoff at the given rate (default: the whole payload over
 * the mission). */
static void
build_phases(const struct duty_input *in, struct duty_plan *pl)
{
	double total = 0.0;
	for (int i = 0; i < PHASE_MAX; i++)
		total += in->duration_s[i] > 0.0 ? in->duration_s[i] : 0.0;
	struct role_shedding sh;
	memset(&sh, 0, sizeof sh);
	sh.kind = in->shed;
	sh.payload0_kg = in->payload_kg;
	sh.drop_mass_kg = in->drop_mass_kg < in->payload_kg ? in->drop_mass_kg
	    : in->payload_kg;
	sh.drop_time_s = in->drop_ratio * total;
	sh.spray_mass_kg = in->payload_kg;
	sh.spray_rate_kg_s = in->spray_rate_kg_s > 0.0 ? in->spray_rate_kg_s
	    : (total > 0.0 ? in->payload_kg / total : 0.0);
	duty_plan_phases(in->duration_s, in->v_climb_ms, in->v_fwd_ms, &sh, pl);
}

/* A phase flown as the paper flies it, in a profile's own group. */
static void
flight_phase(struct duty_plan *pl, const char *name, int phase, double dur_s,
             double v_climb_ms, double v_fwd_ms, double payload_kg)
{
	if (!(dur_s > 0.0))
		return;
	int g = add_group(pl, name, phase, 0.0);
	struct duty_segment *s = add_seg(pl, g, DUTY_LAW_FLIGHT, dur_s, payload_kg);
	if (s == NULL)
		return;
	s->whole_phase = true;
	s->v_climb_ms = v_climb_ms;
	s->v_fwd_ms = v_fwd_ms;
	pl->group[g].count = 1;
}

/* ---- race ------------------------------------------------------------------ */

/* The forward time is the race: a whole number of laps, each the role's
 * lap time to within half a lap, each piece of a lap its share of it. */
static void
build_race(const struct duty_input *in, struct duty_plan *pl)
{
	const struct model_duty *d = in->duty;
	const double *dur = in->duration_s;
	double pay = in->payload_kg;
	plan_init(pl, DUTY_RACE);
	flight_phase(pl, "launch climb", PHASE_CLIMB, dur[PHASE_CLIMB],
	    in->v_climb_ms, 0.0, pay);
	double race_s = dur[PHASE_FORWARD];
	if (race_s > 0.0 && d->n_lap > 0 && d->lap_s > 0.0) {
		double n = floor(race_s / d->lap_s + 0.5);
		int laps = n < 1.0 ? 1 : n > 1e6 ? 1000000 : (int)n;
		int flown = laps < DUTY_MAX_LAPS ? laps : DUTY_MAX_LAPS;
		double lap_flown = race_s / (double)flown;
		int g0 = pl->n_group;
		double peak = 0.0;
		for (int k = 0; k < d->n_lap; k++) {
			add_group(pl, d->lap[k].name, PHASE_FORWARD,
			    d->lap[k].power_fraction);
			pl->group[g0 + k].count = laps;
			if (d->lap[k].power_fraction > peak)
				peak = d->lap[k].power_fraction;
		}
		for (int j = 0; j < flown; j++)
			for (int k = 0; k < d->n_lap; k++) {
				struct duty_segment *s = add_seg(pl, g0 + k,
				    DUTY_LAW_THROTTLE, d->lap[k].share * lap_flown, pay);
				if (s == NULL)
					continue;
				s->fraction = d->lap[k].power_fraction;
				s->v_fwd_ms = in->v_fwd_ms;
			}
		pl->n_laps = laps;
		pl->lap_s = race_s / (double)laps;
		pl->lap_mean_fraction = duty_lap_mean_fraction(d);
		pl->lap_peak_fraction = peak;
	}
	flight_phase(pl, "hover", PHASE_HOVER, dur[PHASE_HOVER], 0.0, 0.0, pay);
}

/* ---- spray sorties --------------------------------------------------------- */

/* The forward distance v × t is a transit to the field, passes of the
 * swath length across it and the transit back; a turn at each swath end
 * adds its time (the forward time is the time at the spraying speed).  The
 * tank is shed on the passes only. */
static void
build_spray(const struct duty_input *in, struct duty_plan *pl)
{
	const struct model_duty *d = in->duty;
	const double *dur = in->duration_s;
	double v = in->v_fwd_ms;
	double dist = v * dur[PHASE_FORWARD];
	if (!(dist > 0.0) || !(d->swath_length_m > 0.0) || !(d->turn_accel_m_s2 > 0.0)) {
		/* No forward flight to spray along: the paper's phases, the
		 * tank sprayed from takeoff. */
		build_phases(in, pl);
		return;
	}
	plan_init(pl, DUTY_SPRAY);
	double pay = in->payload_kg;
	flight_phase(pl, "climb", PHASE_CLIMB, dur[PHASE_CLIMB], in->v_climb_ms,
	    0.0, pay);
	/* At most a quarter of the distance each way is transit: a sortie
	 * sprays at least half of what it flies. */
	double tr = d->transit_m < 0.25 * dist ? d->transit_m : 0.25 * dist;
	double spray_m = dist - 2.0 * tr;
	double np = ceil(spray_m / d->swath_length_m - 1e-9);
	int passes = np < 1.0 ? 1 : np > 1e6 ? 1000000 : (int)np;
	int turns = passes - 1;
	double turn_s = 2.0 * v / d->turn_accel_m_s2 + d->turn_yaw_s;
	pl->n_passes = passes;
	pl->n_turns = turns;
	pl->swath_length_m = d->swath_length_m;
	pl->pass_m = spray_m / (double)passes;
	pl->turn_s = turn_s;
	pl->transit_m = tr;
	pl->spray_s = spray_m / v;
	bool sheds = in->shed != SHED_NONE;
	double rate = !sheds ? 0.0 : in->spray_rate_kg_s > 0.0 ? in->spray_rate_kg_s
	    : pay / pl->spray_s;
	pl->spray_rate_kg_s = rate;
	double floor_kg = sheds ? 0.0 : pay;

	int g_out = add_group(pl, "transit to the field", PHASE_FORWARD, 0.0);
	int g_pass = add_group(pl, "spraying pass", PHASE_FORWARD, 0.0);
	int g_turn = turns > 0 ? add_group(pl, "swath-end turn", PHASE_FORWARD, 0.0)
	    : -1;
	int g_back = add_group(pl, "transit back", PHASE_FORWARD, 0.0);
	pl->group[g_out].count = tr > 0.0;
	pl->group[g_pass].count = passes;
	if (g_turn >= 0)
		pl->group[g_turn].count = turns;
	pl->group[g_back].count = tr > 0.0;

	struct duty_segment *s = add_seg(pl, g_out, DUTY_LAW_FLIGHT, tr / v, pay);
	if (s != NULL)
		s->v_fwd_ms = v;
	int flown = passes < DUTY_MAX_PASSES ? passes : DUTY_MAX_PASSES;
	double pass_s = pl->spray_s / (double)flown;
	double turn_flown_s = flown > 1 ? turn_s * (double)turns / (double)(flown - 1)
	    : 0.0;
	double yaw_flown_s = flown > 1 ? d->turn_yaw_s * (double)turns
	    / (double)(flown - 1) : 0.0;
	for (int k = 0; k < flown; k++) {
		s = add_seg(pl, g_pass, DUTY_LAW_FLIGHT, pass_s, pay);
		if (s != NULL) {
			s->v_fwd_ms = v;
			s->shed_kg_s = rate;
			s->payload_min_kg = floor_kg;
			pay = duty_payload_at(s, pass_s);
		}
		if (k + 1 < flown && g_turn >= 0) {
			s = add_seg(pl, g_turn, DUTY_LAW_TURN, turn_flown_s, pay);
			if (s != NULL) {
				s->v_fwd_ms = v;
				s->accel_m_s2 = d->turn_accel_m_s2;
				s->yaw_s = yaw_flown_s;
			}
		}
	}
	s = add_seg(pl, g_back, DUTY_LAW_FLIGHT, tr / v, pay);
	if (s != NULL)
		s->v_fwd_ms = v;
	flight_phase(pl, "hover", PHASE_HOVER, dur[PHASE_HOVER], 0.0, 0.0, pay);
}

/* ---- out and back ---------------------------------------------------------- */

/* The out-leg (the drop ratio's share of the forward time) with the
 * parcel, the hover over the drop point, the release at its end, and the
 * return leg without the parcel. */
static void
build_out_and_back(const struct duty_input *in, struct duty_plan *pl)
{
	const double *dur = in->duration_s;
	plan_init(pl, DUTY_OUT_AND_BACK);
	double pay = in->payload_kg;
	double r = in->drop_ratio < 0.0 ? 0.0 : in->drop_ratio > 1.0 ? 1.0
	    : in->drop_ratio;
	flight_phase(pl, "climb", PHASE_CLIMB, dur[PHASE_CLIMB], in->v_climb_ms,
	    0.0, pay);
	flight_phase(pl, "out-leg with the parcel", PHASE_FORWARD,
	    r * dur[PHASE_FORWARD], 0.0, in->v_fwd_ms, pay);
	flight_phase(pl, "hover over the drop point", PHASE_HOVER,
	    dur[PHASE_HOVER], 0.0, 0.0, pay);
	if (in->shed != SHED_NONE) {
		double drop = in->drop_mass_kg < pay ? in->drop_mass_kg : pay;
		pl->drop_time_s = pl->total_s;
		pl->drop_mass_kg = drop;
		pay -= drop;
	}
	flight_phase(pl, in->shed != SHED_NONE ? "return leg, parcel released"
	    : "return leg", PHASE_FORWARD, (1.0 - r) * dur[PHASE_FORWARD], 0.0,
	    in->v_fwd_ms, pay);
}

void
duty_plan_build(const struct duty_input *in, struct duty_plan *out)
{
	enum duty_kind k = in->duty != NULL ? in->duty->kind : DUTY_PHASES;
	switch (k) {
	case DUTY_RACE:
		build_race(in, out);
		break;
	case DUTY_SPRAY:
		build_spray(in, out);
		break;
	case DUTY_OUT_AND_BACK:
		build_out_and_back(in, out);
		break;
	case DUTY_PHASES:
	case DUTY_KIND_MAX:
	default:
		build_phases(in, out);
		break;
	}
}
