/* discharge.c — time-step discharge simulation (see discharge.h). */
#include "physics/discharge.h"

#include <math.h>
#include <string.h>

#include "physics/therm.h"
#include "util/strbuf.h"
#include "util/units.h"

#define MIN_STEPS_PER_PHASE 4
#define ENDURANCE_STEPS     60    /* steps of an endurance run */
#define ENDURANCE_MAX_STEPS 4000  /* hard bound, whatever the estimate */

const char *const discharge_end_text[DIS_END_MAX] = {
	"mission completed",
	"battery depleted before the end of the mission",
	"terminal voltage fell below the cut-off",
	"voltage collapse: the pack cannot deliver the power",
	"power overflow: the demand is not physical",
	"thermal runaway: pack above 60 °C",
};

/* Battery state carried between steps. */
struct cell_state {
	double soc;
	double temp_c;
	double c_rate;          /* of the previous step, for B_eff */
};

/* What every step of one time step dt_s shares: the pack's fixed part of
 * R_sys and the thermal decay over dt_s, computed once (each costs an exp)
 * instead of per step: step_init() the pack's, step_dt() the decay's. */
struct step_ctx {
	const struct discharge_pack *p;
	double ambient_c;
	double dt_s;
	struct batt_r_sys rs;
	struct therm_step ts;
};

static void
step_init(const struct discharge_pack *p, double ambient_c, struct step_ctx *sc)
{
	sc->p = p;
	sc->ambient_c = ambient_c;
	batt_r_sys_init(p->chem, p->cells, p->capacity_ah, p->cycles, p->n_rotors,
	    &sc->rs);
	if (p->r_cells_ohm > 0.0)
		sc->rs.r_cells_ohm = p->r_cells_ohm;
}

static void
step_dt(double hac_w_k, double dt_s, struct step_ctx *sc)
{
	sc->dt_s = dt_s;
	therm_step_init(hac_w_k, sc->p->mass_kg, dt_s, &sc->ts);
}

/* What one step gives: the mean current over it (the charge and the heat
 * it draws), and the values at its start and end (the trace, the peak
 * current and the lowest terminal voltage). */
struct step_out {
	double i_a;                  /* mean current over the step */
	double p_w;                  /* mean battery power over the step */
	double i0_a, v_oc0_v, v_term0_v, p0_w; /* at its start */
	double i1_a, v_oc1_v, v_term1_v, p1_w; /* at its end */
};

/* What a step asks of the pack: a power, and for a piece of a race the
 * full-throttle point it is a fraction of. */
struct demand {
	double power_w;              /* asked */
	double full_w;               /* > 0: full throttle gives full_w ... */
	double full_v;               /* ... at this terminal voltage */
};

/* The power the pack's terminal voltage v_term allows at full throttle:
 * the rotors turn with the voltage and their power goes as the speed
 * cubed, P = P_full (V / V_full)³. */
static inline double
full_at(const struct demand *d, double v_term)
{
	double x = v_term / d->full_v;
	return d->full_w * x * x * x;
}

/* The pack's current, open-circuit and terminal voltage at (soc, temp_c)
 * with b_eff at c_rate, drawing the demand d, and the power it draws
 * (*p_w: the demand, or for a race's piece what full throttle gives on
 * the sagging pack when that is less: a punch-out on a tired pack is
 * weaker, not an end of the race).  DIS_COMPLETED when the pack can
 * deliver it, else the end code. */
static inline enum discharge_end
pack_draw(const struct step_ctx *sc, const struct demand *d, double soc,
          double temp_c, double c_rate, double *i_a, double *v_oc_v,
          double *v_term_v, double *r_sys_ohm, double *p_w)
{
	const struct discharge_pack *p = sc->p;
	double r_sys = batt_r_sys_at(&sc->rs, temp_c);
	double v_oc = (double)p->cells * batt_ocv_cell(p->chem, soc, c_rate);
	enum batt_status bs = batt_current_a(v_oc, r_sys, d->power_w, i_a);
	if (bs == BATT_OVERFLOW)
		return DIS_OVERFLOW;
	double power = d->power_w;
	double v_term = bs == BATT_OK ? v_oc - *i_a * r_sys : 0.0;
	if (d->full_w > 0.0 && d->full_v > 0.0
	    && (bs == BATT_COLLAPSE || full_at(d, v_term) < power)) {
		/* Full throttle on the sagging pack: V solves
		 * P_full (V / V_f)³ = V (V_oc - V) / R, i.e.
		 * P_full R V² + V_f³ V - V_f³ V_oc = 0. */
		double vf3 = d->full_v * d->full_v * d->full_v;
		double a = d->full_w * r_sys;
		v_term = a > 0.0 ? 2.0 * vf3 * v_oc / (vf3 + sqrt(vf3 * vf3
		    + 4.0 * a * vf3 * v_oc)) : v_oc;
		power = full_at(d, v_term);
		*i_a = v_term > 0.0 ? power / v_term : 0.0;
		bs = v_term > 0.0 ? BATT_OK : BATT_COLLAPSE;
	}
	double v_cut = (double)p->cells * p->chem->v_cutoff;
	if (d->full_w > 0.0 && v_oc > v_cut && (bs == BATT_COLLAPSE || v_term < v_cut)) {
		/* A race's piece is flown down to the cut-off, not past it: the
		 * throttle gives what the pack delivers there (the pilot, or the
		 * ESC's low-voltage limit, holds it back). */
		v_term = v_cut;
		power = v_cut * (v_oc - v_cut) / r_sys;
		*i_a = power / v_cut;
		bs = BATT_OK;
	}
	if (bs == BATT_COLLAPSE)
		return DIS_COLLAPSE;
	*v_oc_v = v_oc;
	*v_term_v = v_term;
	*r_sys_ohm = r_sys;
	*p_w = power;
	if (*v_term_v < (double)p->cells * p->chem->v_cutoff)
		return DIS_VOLTAGE_FLOOR;
	return DIS_COMPLETED;
}

/* One step: draw the demand d for sc->dt_s, by Heun's predictor-corrector:
 * the start's current predicts the end of the step, and the mean of the
 * currents (and heats, and powers) at both ends moves the state.  It is
 * second order: 30 steps over a mission come within 3e-5 of the converged
 * charge, where explicit Euler needs thousands.  Returns DIS_COMPLETED
 * when the step was flown, else the end code (a limit reached at either
 * end: the step is then not flown). */
static inline enum discharge_end
step(const struct step_ctx *sc, const struct demand *d, struct cell_state *st,
     struct step_out *so)
{
	const struct discharge_pack *p = sc->p;
	double dt_s = sc->dt_s;
	double r_esc = sc->rs.r_esc_ohm;
	double r0, r1;
	enum discharge_end e = pack_draw(sc, d, st->soc, st->temp_c,
	    st->c_rate, &so->i0_a, &so->v_oc0_v, &so->v_term0_v, &r0, &so->p0_w);
	if (e != DIS_COMPLETED) {
		/* The end is the start: nothing was flown. */
		so->i1_a = so->i0_a;
		so->v_oc1_v = so->v_oc0_v;
		so->v_term1_v = so->v_term0_v;
		so->p1_w = so->p0_w;
		return e;
	}
	double i0 = so->i0_a;
	/* Only the cells heat the pack; the MOSFET loss stays in the ESC. */
	double heat0_w = i0 * i0 * (r0 - r_esc);
	double temp_pred_c = therm_step_apply(&sc->ts, st->temp_c, sc->ambient_c,
	    heat0_w);
	double soc_pred = st->soc - i0 * dt_s / (S_PER_H * p->capacity_ah);
	e = pack_draw(sc, d, soc_pred, temp_pred_c, i0 / p->capacity_ah,
	    &so->i1_a, &so->v_oc1_v, &so->v_term1_v, &r1, &so->p1_w);
	if (e != DIS_COMPLETED)
		return e;
	double i1 = so->i1_a;
	double heat1_w = i1 * i1 * (r1 - r_esc);
	so->i_a = 0.5 * (i0 + i1);
	/* A constant demand is drawn exactly (the same bits as asked). */
	so->p_w = so->p0_w == so->p1_w ? so->p0_w : 0.5 * (so->p0_w + so->p1_w);
	st->temp_c = therm_step_apply(&sc->ts, st->temp_c, sc->ambient_c,
	    0.5 * (heat0_w + heat1_w));
	st->soc -= so->i_a * dt_s / (S_PER_H * p->capacity_ah);
	st->c_rate = i1 / p->capacity_ah;
	if (st->temp_c > THERM_RUNAWAY_C)
		return DIS_THERMAL;
	if (st->soc <= BATT_SOC_MIN)
		return DIS_DEPLETED;
	return DIS_COMPLETED;
}

static void
record(struct res_sample *trace, int max_trace, int *n_trace, double t,
       const struct cell_state *st, double v_oc, double v_term, double i,
       double power_w, double mass_kg, int phase)
{
	if (trace == NULL || *n_trace >= max_trace)
		return;
	struct res_sample *s = &trace[(*n_trace)++];
	s->t_s = t;
	s->soc = st->soc > 0.0 ? st->soc : 0.0;
	s->v_oc_v = v_oc;
	s->v_term_v = v_term;
	s->current_a = i;
	s->power_w = power_w;
	s->temp_c = st->temp_c;
	s->mass_kg = mass_kg;
	s->phase = phase;
}

/* A segment's battery and shaft power at one mass. */
struct seg_power {
	double power_w;        /* at the battery */
	double shaft_w;        /* all rotors */
};

/* The hover power at one mass, remembered for the next call: every
 * piece of a race and every turn of a survey asks it, whatever its own
 * fraction or speeds. */
struct hover_memo {
	double mass_kg;        /* -1: none yet */
	struct mission_power mp;
};

static const struct mission_power *
hover_at(const struct mission_model *m, struct hover_memo *hm, double mass_kg)
{
	if (hm->mass_kg != mass_kg) {
		hm->mass_kg = mass_kg;
		mission_power(m, mass_kg, 0.0, 0.0, &hm->mp);
	}
	return &hm->mp;
}

/* The power segment s draws at mass_kg (duty.h's laws). */
static void
segment_power(const struct discharge_mission *mis,
              const struct duty_segment *s, double mass_kg,
              struct hover_memo *hm, struct seg_power *out)
{
	const struct mission_model *m = mis->model;
	struct mission_power mp;
	switch (s->law) {
	case DUTY_LAW_THROTTLE: {
		/* A fraction of full throttle, and never less than the hover
		 * power: a racer that drew less would be sinking. */
		const struct mission_power *hv = hover_at(m, hm, mass_kg);
		double p = s->fraction * mis->full_throttle_w;
		if (p > hv->electrical_w) {
			out->power_w = p;
			out->shaft_w = s->fraction * mis->full_throttle_shaft_w;
			if (out->shaft_w < hv->shaft_w)
				out->shaft_w = hv->shaft_w;
			if (out->shaft_w > out->power_w)
				out->shaft_w = out->power_w;
		} else {
			out->power_w = hv->electrical_w;
			out->shaft_w = hv->shaft_w;
		}
		return;
	}
	case DUTY_LAW_TURN: {
		/* Brake from v at a, yaw hovering, accelerate back to v at a.
		 * Braking and accelerating tilt the thrust: the rotors carry
		 * the weight and m a, M sqrt(1 + (a/g)²) in all; accelerating
		 * also gives the aircraft its kinetic energy, m a v̄ with v̄ =
		 * v / 2, through the drive's efficiency at that point.  Braking
		 * recovers none of it (no regeneration). */
		double a = s->accel_m_s2, v = s->v_fwd_ms;
		double t_b = 0.5 * (s->dur_s - s->yaw_s);
		if (t_b < 0.0)
			t_b = 0.0;
		const struct mission_power *hv = hover_at(m, hm, mass_kg);
		struct mission_power tilt;
		mission_power(m, mass_kg * sqrt(1.0 + (a / G0_M_S2) * (a / G0_M_S2)),
		    0.0, 0.0, &tilt);
		double drive_w = tilt.electrical_w - tilt.switching_w - m->aux_w;
		double eta = drive_w > 0.0 && tilt.shaft_w > 0.0
		    ? tilt.shaft_w / drive_w : 1.0;
		if (eta > 1.0)
			eta = 1.0;
		double kin_w = mass_kg * a * 0.5 * v;
		double e_j = tilt.electrical_w * 2.0 * t_b + hv->electrical_w * s->yaw_s
		    + kin_w / eta * t_b;
		double es_j = tilt.shaft_w * 2.0 * t_b + hv->shaft_w * s->yaw_s
		    + kin_w * t_b;
		out->power_w = s->dur_s > 0.0 ? e_j / s->dur_s : hv->electrical_w;
		out->shaft_w = s->dur_s > 0.0 ? es_j / s->dur_s : hv->shaft_w;
		return;
	}
	case DUTY_LAW_FLIGHT:
	default:
		mission_power(m, mass_kg, s->v_climb_ms, s->v_fwd_ms, &mp);
		out->power_w = mp.electrical_w;
		out->shaft_w = mp.shaft_w;
		return;
	}
}

/* The power at one mass, remembered for the next call.  segment_power()
 * is a pure function of the mass and of the few fields of the segment its
 * law reads, so the memo holds across segments that share them: a race's
 * laps repeat the same pieces, a survey its passes and turns. */
struct power_memo {
	double mass_kg;        /* -1: none yet */
	const struct duty_segment *s; /* the segment it was worked out for */
	struct seg_power p;
	struct hover_memo hover;
};

/* The same bits: a signed zero is not taken for the other. */
static bool
same_bits(double a, double b)
{
	return memcmp(&a, &b, sizeof a) == 0;
}

/* Does segment_power() give a at every mass what it gives b?  The fields
 * its law reads hold the same bits. */
static bool
same_law(const struct duty_segment *a, const struct duty_segment *b)
{
	if (a->law != b->law)
		return false;
	switch (a->law) {
	case DUTY_LAW_THROTTLE:
		return same_bits(a->fraction, b->fraction);
	case DUTY_LAW_TURN:
		return same_bits(a->accel_m_s2, b->accel_m_s2)
		    && same_bits(a->v_fwd_ms, b->v_fwd_ms)
		    && same_bits(a->dur_s, b->dur_s) && same_bits(a->yaw_s, b->yaw_s);
	case DUTY_LAW_FLIGHT:
	default:
		return same_bits(a->v_climb_ms, b->v_climb_ms)
		    && same_bits(a->v_fwd_ms, b->v_fwd_ms);
	}
}

static const struct seg_power *
memo_power(const struct discharge_mission *mis, const struct duty_segment *s,
           struct power_memo *pm, double mass_kg)
{
	if (pm->mass_kg != mass_kg || pm->s == NULL
	    || (pm->s != s && !same_law(pm->s, s))) {
		pm->mass_kg = mass_kg;
		segment_power(mis, s, mass_kg, &pm->hover, &pm->p);
	}
	pm->s = s;
	return &pm->p;
}

/* The plan a discharge flies: its own, or the three phases of the legacy
 * fields in *buf. */
static const struct duty_plan *
mission_plan(const struct discharge_mission *mis, struct duty_plan *buf)
{
	if (mis->plan != NULL)
		return mis->plan;
	duty_plan_phases(mis->duration_s, mis->speed_ms[PHASE_CLIMB],
	    mis->speed_ms[PHASE_FORWARD], &mis->shed, buf);
	return buf;
}

/* Steps of segment s: its share of `steps` (at least 4 for a whole phase
 * of the paper's mission, at least one for a piece of a profile). */
static int
segment_steps(const struct duty_segment *s, int steps, double total_s)
{
	int n = total_s > 0.0 ? (int)((double)steps * s->dur_s / total_s) : 0;
	int lo = s->whole_phase ? MIN_STEPS_PER_PHASE : 1;
	return n < lo ? lo : n;
}

double
discharge_plan_energy_wh(const struct discharge_mission *mis)
{
	struct duty_plan buf;
	const struct duty_plan *pl = mission_plan(mis, &buf);
	struct hover_memo hm = { .mass_kg = -1.0 };
	double wh = 0.0;
	for (int i = 0; i < pl->n_seg; i++) {
		const struct duty_segment *s = &pl->seg[i];
		struct seg_power sp;
		segment_power(mis, s, mis->dry_mass_kg
		    + duty_payload_mean(s, 0.0, s->dur_s), &hm, &sp);
		wh += sp.power_w * s->dur_s / S_PER_H;
	}
	return wh;
}

void
discharge_run(const struct discharge_pack *pack,
              const struct discharge_mission *mis, int steps,
              struct res_sample *trace, int max_trace, int *n_trace,
              struct discharge_out *out)
{
	struct duty_plan buf;
	const struct duty_plan *pl = mission_plan(mis, &buf);
	struct cell_state st = { 1.0, mis->ambient_c, 0.0 };
	/* The pack's convective conductance is constant: computed once, not
	 * per step (it costs a pow). */
	double hac = therm_hac_w_k(pack->mass_kg, pack->h_conv_w_m2k);
	double total_s = pl->total_s;
	int dummy = 0;
	if (n_trace == NULL)
		n_trace = &dummy;
	*n_trace = 0;
	memset(out, 0, sizeof *out);
	out->end = DIS_COMPLETED;
	out->peak_temp_c = st.temp_c;
	out->min_v_term_v = (double)pack->cells * pack->chem->v_full;
	out->end_payload_kg = pl->n_seg > 0 ? pl->seg[0].payload0_kg : 0.0;

	/* A plan of more steps than the trace holds is recorded every
	 * stride-th step, and always at its last. */
	int n_steps = 0;
	for (int i = 0; i < pl->n_seg; i++)
		n_steps += segment_steps(&pl->seg[i], steps, total_s);
	int stride = 1;
	if (trace != NULL && max_trace > 1 && n_steps + 1 > max_trace)
		stride = (n_steps + max_trace - 2) / (max_trace - 1);

	double t = 0.0;
	double ph_e[PHASE_MAX] = { 0 }, ph_es[PHASE_MAX] = { 0 };
	double ph_q[PHASE_MAX] = { 0 }, ph_t[PHASE_MAX] = { 0 };
	bool first = true;
	int k_all = 0;
	/* The pack's part of the steps is the same in every segment. */
	struct step_ctx sc;
	step_init(pack, mis->ambient_c, &sc);
	struct power_memo pm = { .mass_kg = -1.0, .hover.mass_kg = -1.0 };
	for (int i = 0; i < pl->n_seg && out->end == DIS_COMPLETED; i++) {
		const struct duty_segment *sg = &pl->seg[i];
		int n = segment_steps(sg, steps, total_s);
		double dt = sg->dur_s / (double)n;
		/* The thermal decay over dt: the same as the last segment's
		 * when their steps are (it costs an exp). */
		if (i == 0 || !same_bits(sc.dt_s, dt))
			step_dt(hac, dt, &sc);
		double e_wh = 0.0, es_wh = 0.0, q_ah = 0.0;
		int flown = 0;
		for (int k = 0; k < n; k++) {
			/* The payload's mean over the step: a tank emptying along
			 * it (the mid-step mass until it runs dry within it).  The
			 * steps' means average to the segment's, so its mean power
			 * is at least the power at its mean mass (power is convex
			 * in mass). */
			double tau = (double)k * dt;
			double payload = duty_payload_mean(sg, tau, tau + dt);
			double mass = mis->dry_mass_kg + payload;
			const struct seg_power *sp = memo_power(mis, sg, &pm, mass);
			struct demand dmd = { sp->power_w, 0.0, 0.0 };
			if (sg->law == DUTY_LAW_THROTTLE) {
				dmd.full_w = mis->full_throttle_w;
				dmd.full_v = mis->full_throttle_v;
			}
			struct step_out so;
			enum discharge_end e = step(&sc, &dmd, &st, &so);
			/* What the pack gave: the demand, or less at full throttle
			 * on a sagging pack (the shaft power in proportion). */
			double power_w = e == DIS_COMPLETED || e == DIS_DEPLETED
			    || e == DIS_THERMAL ? so.p_w : so.p0_w;
			double shaft_w = sp->power_w > 0.0 && power_w < sp->power_w
			    ? sp->shaft_w * power_w / sp->power_w : sp->shaft_w;
			if (e == DIS_OVERFLOW || e == DIS_COLLAPSE) {
				out->end = e;
				break;
			}
			if (first) {
				record(trace, max_trace, n_trace, 0.0, &(struct cell_state){ 1.0, mis->ambient_c, 0.0 },
				    so.v_oc0_v, so.v_term0_v, so.i0_a, so.p0_w, mass, sg->phase);
				first = false;
			}
			/* Both ends of the step count for the extremes: the end
			 * of the last step is the mission's lowest voltage. */
			double i_hi = so.i1_a > so.i0_a ? so.i1_a : so.i0_a;
			double v_lo = so.v_term1_v < so.v_term0_v ? so.v_term1_v : so.v_term0_v;
			if (i_hi > out->peak_current_a)
				out->peak_current_a = i_hi;
			if (v_lo < out->min_v_term_v)
				out->min_v_term_v = v_lo;
			if (e == DIS_VOLTAGE_FLOOR) {
				/* Not flown: the floor came within the step. */
				out->end = e;
				break;
			}
			t += dt;
			flown++;
			k_all++;
			e_wh += power_w * dt / S_PER_H;
			es_wh += shaft_w * dt / S_PER_H;
			q_ah += so.i_a * dt / S_PER_H;
			if (power_w > out->peak_power_w)
				out->peak_power_w = power_w;
			out->end_payload_kg = duty_payload_at(sg, tau + dt);
			if (st.temp_c > out->peak_temp_c)
				out->peak_temp_c = st.temp_c;
			bool last = (i + 1 == pl->n_seg && k + 1 == n) || e != DIS_COMPLETED;
			if (k_all % stride == 0 || last)
				record(trace, max_trace, n_trace, t, &st, so.v_oc1_v,
				    so.v_term1_v, so.i1_a, power_w, mass, sg->phase);
			if (e != DIS_COMPLETED) {
				out->end = e;
				break;
			}
		}
		int ph = sg->phase;
		ph_e[ph] += e_wh;
		ph_es[ph] += es_wh;
		ph_q[ph] += q_ah;
		ph_t[ph] += dt * (double)flown;
		if (sg->group >= 0 && sg->group < DUTY_MAX_GROUP) {
			out->group_energy_wh[sg->group] += e_wh;
			out->group_ah[sg->group] += q_ah;
			out->group_time_s[sg->group] += dt * (double)flown;
		}
		out->wh_used += e_wh;
		out->ah_used += q_ah;
	}
	for (int ph = 0; ph < PHASE_MAX; ph++) {
		out->phase_energy_wh[ph] = ph_e[ph];
		if (ph_t[ph] > 0.0) {
			out->phase_mean_current_a[ph] = ph_q[ph] * S_PER_H / ph_t[ph];
			out->phase_mean_power_w[ph] = ph_e[ph] * S_PER_H / ph_t[ph];
			out->phase_mean_shaft_w[ph] = ph_es[ph] * S_PER_H / ph_t[ph];
		}
	}
	out->t_end_s = t;
	out->end_soc = st.soc > 0.0 ? st.soc : 0.0;
}

void
discharge_duty_record(const struct duty_plan *pl, const struct discharge_out *out,
                      double full_throttle_w, const char *source,
                      struct res_duty *rec)
{
	memset(rec, 0, sizeof *rec);
	rec->kind = (int)pl->kind;
	if (source != NULL)
		str_copy(rec->source, sizeof rec->source, source);
	rec->full_throttle_power_w = full_throttle_w;
	rec->mean_power_w = out->t_end_s > 0.0
	    ? out->wh_used * S_PER_H / out->t_end_s : 0.0;
	rec->peak_power_w = out->peak_power_w;
	rec->n_groups = pl->n_group < RES_MAX_DUTY_GROUPS ? pl->n_group
	    : RES_MAX_DUTY_GROUPS;
	double race_e = 0.0, race_q = 0.0;
	for (int g = 0; g < rec->n_groups; g++) {
		const struct duty_group *dg = &pl->group[g];
		struct res_duty_group *r = &rec->group[g];
		str_copy(r->name, sizeof r->name, dg->name);
		r->phase = dg->phase;
		r->count = dg->count;
		r->duration_s = out->group_time_s[g];
		r->fraction = dg->fraction;
		r->energy_wh = out->group_energy_wh[g];
		if (r->duration_s > 0.0) {
			r->power_w = r->energy_wh * S_PER_H / r->duration_s;
			r->current_a = out->group_ah[g] * S_PER_H / r->duration_s;
		}
		if (pl->kind == DUTY_RACE && dg->fraction > 0.0) {
			rec->race_s += r->duration_s;
			race_e += r->energy_wh;
			race_q += out->group_ah[g];
		}
	}
	rec->n_laps = pl->n_laps;
	rec->lap_s = pl->lap_s;
	if (rec->race_s > 0.0) {
		rec->race_mean_power_w = race_e * S_PER_H / rec->race_s;
		rec->race_mean_current_a = race_q * S_PER_H / rec->race_s;
	}
	/* As flown: the hover floor may lift a corner above its fraction. */
	rec->lap_mean_fraction = full_throttle_w > 0.0
	    ? rec->race_mean_power_w / full_throttle_w : 0.0;
	rec->lap_peak_fraction = pl->lap_peak_fraction;
	rec->n_passes = pl->n_passes;
	rec->n_turns = pl->n_turns;
	rec->swath_length_m = pl->swath_length_m;
	rec->pass_m = pl->pass_m;
	rec->turn_s = pl->turn_s;
	rec->transit_m = pl->transit_m;
	rec->spray_s = pl->spray_s;
	rec->spray_rate_kg_s = pl->spray_rate_kg_s;
	double p0 = pl->n_seg > 0 ? pl->seg[0].payload0_kg : 0.0;
	rec->landing_payload_kg = out->end_payload_kg;
	rec->tank_shed_kg = pl->kind == DUTY_SPRAY || pl->spray_rate_kg_s > 0.0
	    ? p0 - out->end_payload_kg : 0.0;
	rec->drop_time_s = pl->drop_time_s;
	rec->drop_mass_kg = pl->drop_mass_kg;
}

double
discharge_hover_endurance_s(const struct discharge_pack *pack,
                            const struct mission_model *model, double mass_kg,
                            double ambient_c, double reserve_soc)
{
	return discharge_hover_endurance_steps_s(pack, model, mass_kg, ambient_c,
	    reserve_soc, ENDURANCE_STEPS);
}

double
discharge_hover_endurance_steps_s(const struct discharge_pack *pack,
                                  const struct mission_model *model,
                                  double mass_kg, double ambient_c,
                                  double reserve_soc, int steps)
{
	struct mission_power pw;
	mission_power(model, mass_kg, 0.0, 0.0, &pw);
	return discharge_power_endurance_s(pack, pw.electrical_w, ambient_c,
	    reserve_soc, steps);
}

double
discharge_power_endurance_s(const struct discharge_pack *pack, double power_w,
                            double ambient_c, double reserve_soc, int steps)
{
	double v_nom = (double)pack->cells * pack->chem->v_nom;
	if (!(power_w > 0.0) || !(v_nom > 0.0))
		return 0.0;
	/* First estimate from nominal energy sets the step. */
	double est_s = pack->capacity_ah * (1.0 - reserve_soc) * v_nom
	    * S_PER_H / power_w;
	double dt = est_s / (double)(steps > 0 ? steps : ENDURANCE_STEPS);
	if (!(dt > 0.0))
		return 0.0;
	struct cell_state st = { 1.0, ambient_c, 0.0 };
	struct step_ctx sc;
	step_init(pack, ambient_c, &sc);
	step_dt(therm_hac_w_k(pack->mass_kg, pack->h_conv_w_m2k), dt, &sc);
	double t = 0.0;
	for (int k = 0; k < ENDURANCE_MAX_STEPS; k++) {
		struct step_out so;
		double soc0 = st.soc;
		struct demand dmd = { power_w, 0.0, 0.0 };
		enum discharge_end e = step(&sc, &dmd, &st, &so);
		if (e == DIS_OVERFLOW || e == DIS_COLLAPSE || e == DIS_VOLTAGE_FLOOR)
			return t;
		if (st.soc <= reserve_soc) {
			/* Interpolate the crossing inside the step. */
			double frac = (soc0 - reserve_soc) / (soc0 - st.soc);
			return t + dt * frac;
		}
		t += dt;
		if (e != DIS_COMPLETED)
			return t;
	}
	return t;
}
