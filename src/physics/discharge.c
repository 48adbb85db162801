/* discharge.c — time-step discharge simulation (see discharge.h). */
#include "physics/discharge.h"

#include <math.h>
#include <string.h>

#include "physics/therm.h"
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
 * instead of per step. */
struct step_ctx {
	const struct discharge_pack *p;
	double ambient_c;
	double dt_s;
	struct batt_r_sys rs;
	struct therm_step ts;
};

static void
step_init(const struct discharge_pack *p, double hac_w_k, double ambient_c,
          double dt_s, struct step_ctx *sc)
{
	sc->p = p;
	sc->ambient_c = ambient_c;
	sc->dt_s = dt_s;
	batt_r_sys_init(p->chem, p->cells, p->capacity_ah, p->cycles, p->n_rotors,
	    &sc->rs);
	if (p->r_cells_ohm > 0.0)
		sc->rs.r_cells_ohm = p->r_cells_ohm;
	therm_step_init(hac_w_k, p->mass_kg, dt_s, &sc->ts);
}

/* What one step gives: the mean current over it (the charge and the heat
 * it draws), and the values at its start and end (the trace, the peak
 * current and the lowest terminal voltage). */
struct step_out {
	double i_a;                  /* mean current over the step */
	double i0_a, v_oc0_v, v_term0_v; /* at its start */
	double i1_a, v_oc1_v, v_term1_v; /* at its end */
};

/* The pack's current, open-circuit and terminal voltage at (soc, temp_c)
 * with b_eff at c_rate, drawing power_w.  DIS_COMPLETED when the pack can
 * deliver it, else the end code. */
static inline enum discharge_end
pack_draw(const struct step_ctx *sc, double power_w, double soc, double temp_c,
          double c_rate, double *i_a, double *v_oc_v, double *v_term_v,
          double *r_sys_ohm)
{
	const struct discharge_pack *p = sc->p;
	double r_sys = batt_r_sys_at(&sc->rs, temp_c);
	double v_oc = (double)p->cells * batt_ocv_cell(p->chem, soc, c_rate);
	enum batt_status bs = batt_current_a(v_oc, r_sys, power_w, i_a);
	if (bs == BATT_OVERFLOW)
		return DIS_OVERFLOW;
	if (bs == BATT_COLLAPSE)
		return DIS_COLLAPSE;
	*v_oc_v = v_oc;
	*v_term_v = v_oc - *i_a * r_sys;
	*r_sys_ohm = r_sys;
	if (*v_term_v < (double)p->cells * p->chem->v_cutoff)
		return DIS_VOLTAGE_FLOOR;
	return DIS_COMPLETED;
}

/* One step: draw power_w for sc->dt_s, by Heun's predictor-corrector: the
 * start's current predicts the end of the step, and the mean of the
 * currents (and heats) at both ends moves the state.  It is second order:
 * 30 steps over a mission come within 3e-5 of the converged charge, where
 * explicit Euler needs thousands.  Returns DIS_COMPLETED when the step was
 * flown, else the end code (a limit reached at either end: the step is
 * then not flown). */
static inline enum discharge_end
step(const struct step_ctx *sc, double power_w, struct cell_state *st,
     struct step_out *so)
{
	const struct discharge_pack *p = sc->p;
	double dt_s = sc->dt_s;
	double r_esc = sc->rs.r_esc_ohm;
	double r0, r1;
	enum discharge_end e = pack_draw(sc, power_w, st->soc, st->temp_c,
	    st->c_rate, &so->i0_a, &so->v_oc0_v, &so->v_term0_v, &r0);
	if (e != DIS_COMPLETED) {
		/* The end is the start: nothing was flown. */
		so->i1_a = so->i0_a;
		so->v_oc1_v = so->v_oc0_v;
		so->v_term1_v = so->v_term0_v;
		return e;
	}
	double i0 = so->i0_a;
	/* Only the cells heat the pack; the MOSFET loss stays in the ESC. */
	double heat0_w = i0 * i0 * (r0 - r_esc);
	double temp_pred_c = therm_step_apply(&sc->ts, st->temp_c, sc->ambient_c,
	    heat0_w);
	double soc_pred = st->soc - i0 * dt_s / (S_PER_H * p->capacity_ah);
	e = pack_draw(sc, power_w, soc_pred, temp_pred_c, i0 / p->capacity_ah,
	    &so->i1_a, &so->v_oc1_v, &so->v_term1_v, &r1);
	if (e != DIS_COMPLETED)
		return e;
	double i1 = so->i1_a;
	double heat1_w = i1 * i1 * (r1 - r_esc);
	so->i_a = 0.5 * (i0 + i1);
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

/* The electrical power the mission draws at mass_kg in a phase flown at
 * these speeds. */
static double
electric_power_w(const struct discharge_mission *mis, double v_climb_ms,
                 double v_fwd_ms, double mass_kg)
{
	struct mission_power pw;
	mission_power(mis->model, mass_kg, v_climb_ms, v_fwd_ms, &pw);
	return pw.electrical_w;
}

/* The electrical power at one mass, remembered for the next call. */
struct power_memo {
	double mass_kg;        /* -1: none yet */
	double power_w;
};

static double
memo_power_w(const struct discharge_mission *mis, double v_climb_ms,
             double v_fwd_ms, struct power_memo *pm, double mass_kg)
{
	if (pm->mass_kg != mass_kg) {
		pm->mass_kg = mass_kg;
		pm->power_w = electric_power_w(mis, v_climb_ms, v_fwd_ms, mass_kg);
	}
	return pm->power_w;
}

void
discharge_run(const struct discharge_pack *pack,
              const struct discharge_mission *mis, int steps,
              struct res_sample *trace, int max_trace, int *n_trace,
              struct discharge_out *out)
{
	struct cell_state st = { 1.0, mis->ambient_c, 0.0 };
	/* The pack's convective conductance is constant: computed once, not
	 * per step (it costs a pow). */
	double hac = therm_hac_w_k(pack->mass_kg, pack->h_conv_w_m2k);
	double total_s = 0.0;
	int dummy = 0;
	if (n_trace == NULL)
		n_trace = &dummy;
	*n_trace = 0;
	memset(out, 0, sizeof *out);
	out->end = DIS_COMPLETED;
	out->peak_temp_c = st.temp_c;
	out->min_v_term_v = (double)pack->cells * pack->chem->v_full;
	for (int ph = 0; ph < PHASE_MAX; ph++)
		total_s += mis->duration_s[ph];

	double t = 0.0;
	bool first = true;
	for (int ph = 0; ph < PHASE_MAX && out->end == DIS_COMPLETED; ph++) {
		double dur = mis->duration_s[ph];
		if (!(dur > 0.0))
			continue;
		int n = total_s > 0.0 ? (int)((double)steps * dur / total_s) : 0;
		if (n < MIN_STEPS_PER_PHASE)
			n = MIN_STEPS_PER_PHASE;
		double dt = dur / (double)n;
		struct step_ctx sc;
		step_init(pack, hac, mis->ambient_c, dt, &sc);
		double v_climb = ph == PHASE_CLIMB ? mis->speed_ms[ph] : 0.0;
		double v_fwd = ph == PHASE_FORWARD ? mis->speed_ms[ph] : 0.0;
		double mass = mis->dry_mass_kg + role_payload_at(&mis->shed, t);
		struct power_memo pm = { -1.0, 0.0 };
		double power_w = memo_power_w(mis, v_climb, v_fwd, &pm, mass);
		double e_wh = 0.0, q_ah = 0.0, p_sum = 0.0;
		int flown = 0;
		for (int k = 0; k < n; k++) {
			if (mis->shed.kind == SHED_DROP) {
				/* The power is a pure function of the mass, which a
				 * drop changes at one instant: a step that holds the
				 * drop draws each mass's power for its share of the
				 * step (its energy is then exact), and between drops
				 * the power is reused. */
				double m0 = mis->dry_mass_kg + role_payload_at(&mis->shed, t);
				double m1 = mis->dry_mass_kg
				    + role_payload_at(&mis->shed, t + dt);
				mass = mis->dry_mass_kg
				    + role_payload_at(&mis->shed, t + 0.5 * dt);
				double p0 = memo_power_w(mis, v_climb, v_fwd, &pm, m0);
				power_w = p0;
				if (m1 != m0) {
					double before = (mis->shed.drop_time_s - t) / dt;
					before = before < 0.0 ? 0.0 : before > 1.0 ? 1.0 : before;
					double p1 = memo_power_w(mis, v_climb, v_fwd, &pm, m1);
					power_w = before * p0 + (1.0 - before) * p1;
				}
			} else if (mis->shed.kind == SHED_SPRAY) {
				/* The tank empties along the step: its mean mass over
				 * the step (the mid-step mass unless the tank runs dry
				 * within it).  The steps' means average to the phase's,
				 * so the phase's mean power is at least the power at its
				 * mean mass, the record's shaft power (power is convex
				 * in mass). */
				mass = mis->dry_mass_kg
				    + role_payload_mean(&mis->shed, t, t + dt);
				power_w = memo_power_w(mis, v_climb, v_fwd, &pm, mass);
			}
			struct step_out so;
			enum discharge_end e = step(&sc, power_w, &st, &so);
			if (e == DIS_OVERFLOW || e == DIS_COLLAPSE) {
				out->end = e;
				break;
			}
			if (first) {
				record(trace, max_trace, n_trace, 0.0, &(struct cell_state){ 1.0, mis->ambient_c, 0.0 },
				    so.v_oc0_v, so.v_term0_v, so.i0_a, power_w, mass, ph);
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
			e_wh += power_w * dt / S_PER_H;
			q_ah += so.i_a * dt / S_PER_H;
			p_sum += power_w;
			if (st.temp_c > out->peak_temp_c)
				out->peak_temp_c = st.temp_c;
			record(trace, max_trace, n_trace, t, &st, so.v_oc1_v, so.v_term1_v,
			    so.i1_a, power_w, mass, ph);
			if (e != DIS_COMPLETED) {
				out->end = e;
				break;
			}
		}
		out->phase_energy_wh[ph] = e_wh;
		out->wh_used += e_wh;
		out->ah_used += q_ah;
		if (flown > 0) {
			double span = dt * (double)flown;
			out->phase_mean_current_a[ph] = q_ah * S_PER_H / span;
			out->phase_mean_power_w[ph] = p_sum / (double)flown;
		}
	}
	out->t_end_s = t;
	out->end_soc = st.soc > 0.0 ? st.soc : 0.0;
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
	step_init(pack, therm_hac_w_k(pack->mass_kg, pack->h_conv_w_m2k), ambient_c,
	    dt, &sc);
	double t = 0.0;
	for (int k = 0; k < ENDURANCE_MAX_STEPS; k++) {
		struct step_out so;
		double soc0 = st.soc;
		enum discharge_end e = step(&sc, power_w, &st, &so);
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
