/* mission.c — three-phase mission power model (see mission.h). */
#include "physics/mission.h"

#include <stddef.h>
#include <string.h>

#include "physics/prop.h"
#include "util/units.h"

static void
finish(const struct mission_model *m, struct mission_power *out)
{
	out->shaft_w = out->rotor.p_shaft_w * (double)m->n_rotors;
	/* Paper eq. (powerbudget): ½ f_pwm C_oss V² per ESC. */
	out->switching_w = 0.5 * MISSION_F_PWM_HZ * MISSION_C_OSS_F
	    * m->bus_voltage_v * m->bus_voltage_v * (double)m->n_rotors;
	double drive_w;
	if (m->real_drive) {
		motor_at_shaft(&m->motor, m->motor_temp_c, out->rotor.p_shaft_w,
		    out->rotor.rps, &out->motor);
		drive_w = out->motor.power_in_w * (double)m->n_rotors;
	} else {
		memset(&out->motor, 0, sizeof out->motor);
		drive_w = out->shaft_w / m->eta_drive;
	}
	out->electrical_w = drive_w + out->switching_w + m->aux_w;
}

/* Coaxial pairs: the lower rotor works in the upper one's wake. */
static void
apply_coaxial(const struct mission_model *m, struct aero_point *p)
{
	if (!m->coaxial)
		return;
	double extra = (MISSION_COAX_INDUCED - 1.0) * p->p_induced_w;
	p->p_induced_w += extra;
	p->p_shaft_w += extra;
}

/* Forward flight: Glauert's isolated rotor sheds induced power as the flow
 * through it grows; a multirotor keeps the share m->wake_share of that
 * relief back (its rear rotors fly in the front rotors' wake, the body in
 * the wash).  The relief is measured against hover at the same thrust. */
static void
apply_wake(const struct mission_model *m, double thrust_per_rotor_n,
           struct aero_point *p)
{
	struct aero_point hover;
	aero_rotor_power(&m->rotor, &m->air, thrust_per_rotor_n, 0.0, 0.0, 0.0,
	    &hover);
	double relief = hover.p_induced_w - p->p_induced_w;
	if (!(relief > 0.0))
		return;
	double extra = m->wake_share * relief;
	p->p_induced_w += extra;
	p->p_shaft_w += extra;
}

/* Drag reference area in forward flight at mass_kg, m² (a pow: the speed
 * sweep computes it once for all its speeds). */
static double
forward_ref_area_m2(const struct mission_model *m, double mass_kg)
{
	/* Mapping LiDAR's multiplier acts in forward flight only. */
	return aero_ref_area_m2(m->f_scale, mass_kg, m->added_drag_m2)
	    * m->fwd_drag_mult;
}

/* mission_power with the forward reference area s_fwd_m2 already known
 * (read only when v_fwd_ms > 0). */
static void
phase_power(const struct mission_model *m, double mass_kg, double v_climb_ms,
            double v_fwd_ms, double s_fwd_m2, struct mission_power *out)
{
	double weight_n = mass_kg * G0_M_S2;
	double n = (double)m->n_rotors;
	double rho = m->air.rho_kg_m3;
	double parasite_w = 0.0;

	out->pitch_deg = 0.0;
	out->drag_n = 0.0;
	out->axial_ms = 0.0;
	if (v_fwd_ms > 0.0) {
		out->drag_n = aero_drag_n(rho, v_fwd_ms, m->cd_h, s_fwd_m2);
		out->pitch_deg = atan(out->drag_n / weight_n) * 180.0 / M_PI;
		double total_n = sqrt(weight_n * weight_n
		    + out->drag_n * out->drag_n);
		out->thrust_per_rotor_n = total_n / n;
		/* The disk tilts by the pitch: sin θ = F_d / |T|. */
		out->axial_ms = v_fwd_ms * out->drag_n / total_n;
		parasite_w = out->drag_n * v_fwd_ms / n;
	} else if (v_climb_ms > 0.0) {
		double s_ref = aero_ref_area_m2(m->f_scale, mass_kg, m->added_drag_m2);
		out->drag_n = aero_drag_n(rho, v_climb_ms, m->cd_v, s_ref);
		out->thrust_per_rotor_n = (weight_n + out->drag_n) / n;
		out->axial_ms = v_climb_ms;
	} else {
		out->thrust_per_rotor_n = weight_n / n;
	}
	aero_rotor_power(&m->rotor, &m->air, out->thrust_per_rotor_n,
	    v_climb_ms > 0.0 && v_fwd_ms <= 0.0 ? v_climb_ms : 0.0,
	    v_fwd_ms > 0.0 ? v_fwd_ms : 0.0, parasite_w, &out->rotor);
	if (v_fwd_ms > 0.0 && m->wake_share > 0.0)
		apply_wake(m, out->thrust_per_rotor_n, &out->rotor);
	apply_coaxial(m, &out->rotor);
	finish(m, out);
}

void
mission_power(const struct mission_model *m, double mass_kg, double v_climb_ms,
              double v_fwd_ms, struct mission_power *out)
{
	double s_fwd_m2 = v_fwd_ms > 0.0 ? forward_ref_area_m2(m, mass_kg) : 0.0;
	phase_power(m, mass_kg, v_climb_ms, v_fwd_ms, s_fwd_m2, out);
}

void
mission_peak_power(const struct mission_model *m, double thrust_per_rotor_n,
                   struct mission_power *out)
{
	out->thrust_per_rotor_n = thrust_per_rotor_n;
	out->drag_n = 0.0;
	out->pitch_deg = 0.0;
	out->axial_ms = 0.0;
	aero_rotor_power(&m->rotor, &m->air, thrust_per_rotor_n, 0.0, 0.0, 0.0,
	    &out->rotor);
	apply_coaxial(m, &out->rotor);
	finish(m, out);
}

double
mission_forward_flown_ms(const struct mission_model *m, double mass_kg,
                         double max_thrust_per_rotor_n, double v_fwd_ms,
                         double v_max_ms)
{
	if (v_max_ms > 0.0 && v_fwd_ms <= v_max_ms)
		return v_fwd_ms;
	struct mission_power p;
	mission_power(m, mass_kg, 0.0, v_fwd_ms, &p);
	if (!mission_beyond_limits(m, &p, max_thrust_per_rotor_n))
		return v_fwd_ms;
	if (!(v_max_ms > 0.0)) {
		double v_min_ms;
		mission_speed_search(m, mass_kg, max_thrust_per_rotor_n, &v_min_ms,
		    &v_max_ms);
	}
	return fmin(v_fwd_ms, v_max_ms);
}

/* The top climb (climb) or forward speed in [0, hi_ms] whose point stays
 * within the limits, for a speed hi_ms is past them: thrust (and pitch)
 * grow with the speed's drag while the full thrust left at the inflow
 * falls, so bisect to 1 mm/s keeping the low end within them; 0 when
 * hover itself is not. */
static double
top_speed_within(const struct mission_model *m, double mass_kg,
                 double s_fwd_m2, double max_thrust_per_rotor_n,
                 double hi_ms, bool climb)
{
	struct mission_power p;
	phase_power(m, mass_kg, 0.0, 0.0, 0.0, &p);
	if (mission_beyond_limits(m, &p, max_thrust_per_rotor_n))
		return 0.0;
	double lo = 0.0, hi = hi_ms;
	for (int i = 0; i < 64 && hi - lo > 1e-3; i++) {
		double mid = 0.5 * (lo + hi);
		phase_power(m, mass_kg, climb ? mid : 0.0, climb ? 0.0 : mid,
		    climb ? 0.0 : s_fwd_m2, &p);
		if (mission_beyond_limits(m, &p, max_thrust_per_rotor_n))
			hi = mid;
		else
			lo = mid;
	}
	return lo;
}

double
mission_max_climb_ms(const struct mission_model *m, double mass_kg,
                     double max_thrust_per_rotor_n, double v_hi_ms)
{
	struct mission_power p;
	mission_power(m, mass_kg, v_hi_ms, 0.0, &p);
	if (!mission_beyond_limits(m, &p, max_thrust_per_rotor_n))
		return v_hi_ms;
	return top_speed_within(m, mass_kg, 0.0, max_thrust_per_rotor_n, v_hi_ms,
	    true);
}

/* The sweep's grid: speed i of 0..mission_sweep_last(). */
static int
sweep_last(void)
{
	return (int)((MISSION_SWEEP_V1_MS - MISSION_SWEEP_V0_MS)
	    / MISSION_SWEEP_STEP_MS + 0.5);
}

static double
sweep_speed_ms(int i)
{
	return MISSION_SWEEP_V0_MS + MISSION_SWEEP_STEP_MS * (double)i;
}

double
mission_thrust_available_n(const struct mission_model *m,
                           double max_thrust_per_rotor_n, double v_axial_ms)
{
	if (!(m->prop_j0 > 0.0) || !(v_axial_ms > 0.0))
		return max_thrust_per_rotor_n;
	double d = m->rotor.diameter_m;
	double rps = aero_rps_for_thrust(max_thrust_per_rotor_n, m->rotor.ct,
	    m->air.rho_kg_m3, d);
	return max_thrust_per_rotor_n * prop_ct_ratio(prop_advance_ratio(
	    v_axial_ms, rps, d), m->prop_j0);
}

bool
mission_beyond_limits(const struct mission_model *m,
                      const struct mission_power *p,
                      double max_thrust_per_rotor_n)
{
	return p->thrust_per_rotor_n > mission_thrust_available_n(m,
	    max_thrust_per_rotor_n, p->axial_ms)
	    || p->pitch_deg > MISSION_PITCH_MAX_DEG;
}

double
mission_pitch_limit_speed_ms(const struct mission_model *m, double mass_kg)
{
	/* ½ ρ V² C_d S = W tan θ_max. */
	double cds = m->cd_h * forward_ref_area_m2(m, mass_kg);
	if (!(cds > 0.0))
		return MISSION_SPEED_CAP_MS;
	double v = sqrt(2.0 * mass_kg * G0_M_S2
	    * tan(MISSION_PITCH_MAX_DEG * M_PI / 180.0)
	    / (m->air.rho_kg_m3 * cds));
	return v < MISSION_SPEED_CAP_MS ? v : MISSION_SPEED_CAP_MS;
}

enum mission_limit
mission_top_speed_limit(const struct mission_model *m, double mass_kg,
                        double v_max_ms)
{
	if (v_max_ms >= MISSION_SPEED_CAP_MS)
		return MISSION_LIMIT_BOUND;
	struct mission_power p;
	mission_power(m, mass_kg, 0.0, v_max_ms + 1.0 / MISSION_SPEED_RES_PER_MS,
	    &p);
	return p.pitch_deg > MISSION_PITCH_MAX_DEG ? MISSION_LIMIT_PITCH
	    : MISSION_LIMIT_THRUST;
}

/* Speed k of the top-speed lattice. */
static double
lattice_ms(long k)
{
	return (double)k / MISSION_SPEED_RES_PER_MS;
}

/* Is forward speed k of the lattice within the limits? */
static bool
lattice_within(const struct mission_model *m, double mass_kg, double s_fwd_m2,
               double max_thrust_per_rotor_n, long k)
{
	struct mission_power p;
	phase_power(m, mass_kg, 0.0, lattice_ms(k), s_fwd_m2, &p);
	return !mission_beyond_limits(m, &p, max_thrust_per_rotor_n);
}

/* The highest lattice speed within the limits in [lo, hi), lo within and
 * hi past them (thrust and pitch needs only grow with the speed, the
 * thrust left only falls).  A guess in (lo, hi) (a previous search's
 * answer, at a mass close by) grows a bracket from it in steps of 1, 2,
 * 4, ... lattice points first; the answer is the same either way. */
static long
lattice_top(const struct mission_model *m, double mass_kg, double s_fwd_m2,
            double max_thrust_per_rotor_n, long lo, long hi, long guess)
{
	if (guess > lo && guess < hi) {
		long step = 1;
		if (lattice_within(m, mass_kg, s_fwd_m2, max_thrust_per_rotor_n,
		    guess)) {
			lo = guess;
			while (lo + step < hi && lattice_within(m, mass_kg, s_fwd_m2,
			    max_thrust_per_rotor_n, lo + step)) {
				lo += step;
				step *= 2;
			}
			if (lo + step < hi)
				hi = lo + step;
		} else {
			hi = guess;
			while (hi - step > lo && !lattice_within(m, mass_kg, s_fwd_m2,
			    max_thrust_per_rotor_n, hi - step)) {
				hi -= step;
				step *= 2;
			}
			if (hi - step > lo)
				lo = hi - step;
		}
	}
	while (hi - lo > 1) {
		long mid = lo + (hi - lo) / 2;
		if (lattice_within(m, mass_kg, s_fwd_m2, max_thrust_per_rotor_n, mid))
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

/* The top speed, the sweep's grid searched: n_ok grid speeds (a prefix)
 * within the limits.  None: bisected below the first.  Some: on the
 * lattice between the last within and the first past them.  All: on the
 * lattice between the grid's end and the pitch-limit speed, past which
 * the pitch alone is beyond its limit (MISSION_SPEED_CAP_MS for a body
 * without drag, reported as that bound).  *k_guess: a previous answer on
 * the lattice (0 none), and this one. */
static double
top_speed(const struct mission_model *m, double mass_kg, double s_fwd_m2,
          double max_thrust_per_rotor_n, int n_ok, long *k_guess)
{
	if (n_ok == 0) {
		*k_guess = 0;
		return top_speed_within(m, mass_kg, s_fwd_m2, max_thrust_per_rotor_n,
		    MISSION_SWEEP_V0_MS, false);
	}
	long lo = lround(sweep_speed_ms(n_ok - 1) * MISSION_SPEED_RES_PER_MS);
	long hi;
	if (n_ok <= sweep_last()) {
		hi = lround(sweep_speed_ms(n_ok) * MISSION_SPEED_RES_PER_MS);
	} else {
		long kp = (long)floor(mission_pitch_limit_speed_ms(m, mass_kg)
		    * MISSION_SPEED_RES_PER_MS);
		if (kp <= lo) {
			*k_guess = lo;
			return lattice_ms(lo);
		}
		/* At the pitch limit and within thrust: the pitch binds. */
		if (lattice_within(m, mass_kg, s_fwd_m2, max_thrust_per_rotor_n, kp)) {
			*k_guess = kp;
			return lattice_ms(kp);
		}
		hi = kp;
	}
	*k_guess = lattice_top(m, mass_kg, s_fwd_m2, max_thrust_per_rotor_n, lo, hi,
	    *k_guess);
	return lattice_ms(*k_guess);
}

int
mission_speed_sweep(const struct mission_model *m, double mass_kg,
                    double max_thrust_per_rotor_n, double *v_ms,
                    double *power_w, int max_points, double *v_min_power_ms,
                    double *v_max_ms)
{
	int n = 0;
	double best = 0.0;
	int n_ok = -1;
	*v_min_power_ms = MISSION_SWEEP_V0_MS;
	int steps = sweep_last();
	double s_fwd_m2 = forward_ref_area_m2(m, mass_kg); /* the same at every speed */
	for (int i = 0; i <= steps; i++) {
		double v = sweep_speed_ms(i);
		struct mission_power p;
		phase_power(m, mass_kg, 0.0, v, s_fwd_m2, &p);
		if (n < max_points) {
			v_ms[n] = v;
			power_w[n] = p.electrical_w;
			n++;
		}
		bool over = mission_beyond_limits(m, &p, max_thrust_per_rotor_n);
		if (over && n_ok < 0)
			n_ok = i;
		if (!over && (i == 0 || p.electrical_w < best)) {
			best = p.electrical_w;
			*v_min_power_ms = v;
		}
	}
	long k = 0;
	*v_max_ms = top_speed(m, mass_kg, s_fwd_m2, max_thrust_per_rotor_n,
	    n_ok < 0 ? steps + 1 : n_ok, &k);
	return n;
}

/* The speed search's memo: each grid speed's power and limit flag,
 * computed on first use. */
struct sweep_memo {
	const struct mission_model *m;
	double mass_kg, s_fwd_m2, max_thrust_n;
	double power_w[MISSION_SWEEP_MAX_POINTS];
	signed char over[MISSION_SWEEP_MAX_POINTS]; /* -1: not computed */
};

static void
memo_at(struct sweep_memo *s, int i)
{
	if (s->over[i] >= 0)
		return;
	struct mission_power p;
	phase_power(s->m, s->mass_kg, 0.0, sweep_speed_ms(i), s->s_fwd_m2, &p);
	s->power_w[i] = p.electrical_w;
	s->over[i] = mission_beyond_limits(s->m, &p, s->max_thrust_n);
}

/* The tests the search bisects on, each monotone in i on the grid: past
 * the limits (thrust and pitch grow with speed, drag ~ V²), and the power
 * no longer falling to the next speed (it falls, then rises). */
static bool
over_at(struct sweep_memo *s, int i)
{
	memo_at(s, i);
	return s->over[i] != 0;
}

static bool
rises_at(struct sweep_memo *s, int i)
{
	memo_at(s, i);
	memo_at(s, i + 1);
	return !(s->power_w[i + 1] < s->power_w[i]);
}

/* The first i in [lo, hi) where the monotone test holds, hi if none.  With
 * a hint in [lo, hi] the bracket grows from it in steps of 1, 2, 4, ...
 * (the answer a few points off costs a few tests), then bisects; without
 * one (hint < 0) it bisects [lo, hi].  The same answer either way. */
static int
first_true(struct sweep_memo *s, bool (*test)(struct sweep_memo *, int),
           int lo, int hi, int hint)
{
	if (hint >= lo && hint <= hi) {
		if (hint == hi || test(s, hint)) {
			/* The answer is at or below the hint. */
			int top = hint, step = 1;
			while (top - step >= lo && test(s, top - step)) {
				top -= step;
				step *= 2;
			}
			hi = top;
			lo = top - step >= lo ? top - step + 1 : lo;
		} else {
			/* Above it. */
			int bottom = hint, step = 1;
			while (bottom + step < hi && !test(s, bottom + step)) {
				bottom += step;
				step *= 2;
			}
			lo = bottom + 1;
			hi = bottom + step < hi ? bottom + step : hi;
		}
	}
	while (lo < hi) {
		int mid = lo + (hi - lo) / 2;
		if (test(s, mid))
			hi = mid;
		else
			lo = mid + 1;
	}
	return lo;
}

void
mission_speed_search_hinted(const struct mission_model *m, double mass_kg,
                            double max_thrust_per_rotor_n,
                            double *v_min_power_ms, double *v_max_ms,
                            struct mission_speed_hint *hint)
{
	struct sweep_memo s = { m, mass_kg, forward_ref_area_m2(m, mass_kg),
	    max_thrust_per_rotor_n, { 0.0 }, { 0 } };
	int last = sweep_last();
	if (last >= MISSION_SWEEP_MAX_POINTS) {
		/* A grid finer than the memo holds: sweep it all. */
		(void)mission_speed_sweep(m, mass_kg, max_thrust_per_rotor_n, NULL,
		    NULL, 0, v_min_power_ms, v_max_ms);
		if (hint != NULL)
			hint->set = false;
		return;
	}
	for (int i = 0; i <= last; i++)
		s.over[i] = -1;
	bool hinted = hint != NULL && hint->set;
	/* The speeds within the limits are a prefix 0..n_ok-1. */
	int n_ok = first_true(&s, over_at, 0, last + 1, hinted ? hint->n_ok : -1);
	long k_max = hinted ? hint->k_max : 0;
	*v_max_ms = top_speed(m, mass_kg, s.s_fwd_m2, max_thrust_per_rotor_n, n_ok,
	    &k_max);
	*v_min_power_ms = MISSION_SWEEP_V0_MS;
	int i_min = 0;
	if (n_ok > 0) {
		/* The first minimum: the first i whose successor is not lower. */
		i_min = first_true(&s, rises_at, 0, n_ok - 1,
		    hinted ? hint->i_min : -1);
		*v_min_power_ms = sweep_speed_ms(i_min);
	}
	if (hint != NULL)
		*hint = (struct mission_speed_hint){ true, n_ok, i_min, k_max };
}

void
mission_speed_search(const struct mission_model *m, double mass_kg,
                     double max_thrust_per_rotor_n, double *v_min_power_ms,
                     double *v_max_ms)
{
	mission_speed_search_hinted(m, mass_kg, max_thrust_per_rotor_n,
	    v_min_power_ms, v_max_ms, NULL);
}
