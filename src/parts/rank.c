/* rank.c — every bus × motor × propeller option, flown at full throttle
 * on its own constants and scored (see parts.h).
 *
 * J is the takeoff-mass penalty an option would bring over the continuous
 * design, in percent:
 *
 *     J = 100 · growth · (Δdrive + Δbattery) / M*
 *
 * Each term is a mass, so J weighs every mismatch by what it costs in
 * flight instead of by fixed weights on the diameter, KV, pitch and
 * throttle errors (the paper's 100, 10, 50 and 1000, under which a small,
 * fast FPV motor on a 7 in propeller outscored the right 13 in one):
 *
 *   Δdrive    the option's motors, propellers and ESCs against the
 *             continuous design's, weight 1 per kilogram: they are flown
 *             as they are.  The ESC is not chosen yet; it counts by the
 *             continuous design's own law, the catalogue's median 1.10 g
 *             per amp (sizing.h) times the role's c_esc (racing boards
 *             carry far more amps per gram), of its rating, 10 % over the
 *             motor's full-throttle current (closure.c's pick): so J
 *             compares like with like.  An integrated system's mass holds
 *             all three.
 *   Δbattery  the continuous battery scaled by the option's hover power
 *             over the continuous design's: the energy a mission needs
 *             follows the hover power, so a propeller smaller than the
 *             aim (induced power ~ 1/D) or a motor turning away from its
 *             efficient speed (copper loss ~ I²) costs battery here.
 *   growth    1 / (1 - L), L the continuous loop's Lipschitz constant
 *             (capped at 0.8): every kilogram added is carried by more
 *             battery, structure and thrust, as the loop carries it.
 *
 * Options that cannot lift the continuous design at the required T/W
 * (with the largest payload aboard), overrun a motor rating, break tip Mach or the propeller's rpm limit,
 * heat the winding past its limit (steady in hover, then the record's
 * full-throttle burst: most makers publish only a peak current, so the
 * winding's heat is the motor's real rating) or blow a wake above the
 * role's downwash limit are pruned before scoring.  The ratings (current,
 * power, winding) are pruned on the most-sagged bus a kept pack may give
 * (PARTS_MAX_SAG below nominal): the record flies full throttle on its
 * pack's own sag, which lowers the current, so an option over a rating on
 * the ranking's bus may still pass there.  The rest are kept by J in three
 * lists, all closed: those that reach the continuous design's own T/W at
 * their estimated mass, a few that may fall short of it there (the closing
 * checks the real T/W), and a few within the motor's
 * ratings only on the sagged bus (marginal: kept apart, so that they take
 * no place from the options the ranking's bus already admits).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parts/parts_int.h"
#include "parts/screen.h"
#include "physics/aero.h"
#include "physics/mission.h"
#include "util/units.h"
#include "util/xalloc.h"

#define MIN_DIAMETER_FRAC  0.55   /* smallest propeller searched, × D* */
#define KV_WINDOW_LO       0.6    /* KV searched around the KV the thrust */
#define KV_WINDOW_HI       2.5    /* ... needs on each bus and propeller */
#define LOADED_SPEED       0.85   /* loaded full-throttle speed / no-load */
#define RANK_WINDING_RISE_K 40.0  /* winding above ambient assumed for ranking */
#define LOCK_KV_TOL        0.05   /* a KV lock matches within 5 % */
#define LOCK_DIAMETER_TOL_IN 0.3  /* a propeller lock within 0.3 in */
#define LOCK_PITCH_TOL_IN  0.5
#define MAX_L              0.8    /* growth factor capped at 5 */
#define PRUNED_J           1e9
#define PARTS_DOWNWASH_SLACK 1.05 /* sqrt(1 / 0.9): a closing 10 % lighter */

const char *const parts_reason_text[PARTS_REASON_MAX] = {
	"none",
	"motor cell range",
	"propeller overlap",
	"recommended propeller range",
	"thrust at full throttle",
	"motor current",
	"motor power",
	"tip Mach",
	"propeller rpm limit",
	"no ESC for the current",
	"no pack for the bus",
	"lock",
	"implausible catalogue entry",
	"downwash",
	"doubtful catalogue value",
	"winding temperature",
};

void
parts_aim_from(const struct sizing_params *p, const struct res_run *custom,
               struct parts_aim *aim)
{
	memset(aim, 0, sizeof *aim);
	const struct res_mass *m = &custom->mass;
	aim->mass_kg = m->total_kg;
	aim->lightest = 1.0;
	aim->drive_kg = m->motor_kg + m->prop_kg + m->esc_kg;
	aim->battery_kg = m->battery_kg;
	aim->energy_wh = custom->energy_wh;
	aim->hover_power_w = custom->phase[PHASE_HOVER].shaft_power_w / p->eta_drive;
	/* A mission that drops or sprays its payload hovers lighter than it
	 * takes off; the options' hover is worked out at the takeoff mass
	 * (parts_drive), so the aim's is brought there too (P ~ M^1.5). */
	const struct res_phase *hv = &custom->phase[PHASE_HOVER];
	if (p->shed != SHED_NONE && hv->thrust_per_rotor_n > 0.0)
		aim->hover_power_w *= pow(m->total_kg * G0_M_S2
		    / ((double)p->n_rotors * hv->thrust_per_rotor_n), 1.5);
	double l = custom->lipschitz;
	l = l < 0.0 ? 0.0 : l > MAX_L ? MAX_L : l;
	aim->growth = 1.0 / (1.0 - l);
	/* The T/W requirement (the role's or the mission's) holds with the
	 * largest payload aboard; the continuous run flew exactly it. */
	aim->extra_payload_kg = p->extra_payload_kg;
	aim->tw_required = custom->thrust_to_weight * m->total_kg
	    / (m->total_kg + p->extra_payload_kg);
	aim->downwash_cap_ms = p->downwash_cap_ms;
	aim->prop_diameter_in = custom->opt.prop_diameter_in;
	aim->prop_pitch_in = custom->opt.prop_pitch_in;
	aim->motor_kv = custom->opt.motor_kv;
	aim->cells = custom->cell_count > 0 ? custom->cell_count : 1;
	aim->overlap_limit_in = custom->overlap_limit_in;
	/* The rotor's installed power over the propeller's own at the same
	 * thrust and speed: κ and the arm interference (perf.c's FoM), and the
	 * lower rotor's wake on a coaxial pair. */
	aim->install_factor = (p->fom_isolated_mode ? 1.0 : p->kappa)
	    * (custom->interference > 1.0 ? custom->interference : 1.0)
	    * (p->coaxial ? 1.0 + 0.5 * (MISSION_COAX_INDUCED - 1.0) : 1.0);
}

void
parts_aim_regrow(struct parts_aim *aim, double grown)
{
	double power = pow(grown, 1.5);
	aim->mass_kg *= grown;
	aim->hover_power_w *= power;
	aim->energy_wh *= power;
	aim->battery_kg *= power;
}

/* The propeller of an option: the catalogue's, or an integrated system's. */
static void
option_prop(const struct catalog_motor *m, const struct catalog_prop *pr,
            const struct parts_aim *aim, struct perf_craft *c)
{
	double d_in, pitch_in;
	int blades = 2;
	if (pr != NULL) {
		d_in = pr->diameter_in;
		pitch_in = pr->pitch_in;
		blades = pr->blades > 0 ? pr->blades : 2;
		c->prop_max_rpm = pr->max_rpm;
	} else {
		d_in = m->integrated_prop_in;
		pitch_in = m->integrated_pitch_in > 0.0 ? m->integrated_pitch_in
		    : aim->prop_pitch_in / aim->prop_diameter_in * d_in;
		c->prop_max_rpm = 0.0;
	}
	c->prop_diameter_m = in_to_m(d_in);
	c->prop_pitch_m = in_to_m(pitch_in);
	c->prop_blades = blades;
	/* Published coefficients, unless the catalogue doubts them. */
	if (pr != NULL && pr->ct_static > 0.0 && pr->cp_static > 0.0
	    && !screen_uncertain(pr->uncertain, "ct_static")
	    && !screen_uncertain(pr->uncertain, "cp_static")) {
		c->prop.ct = pr->ct_static;
		c->prop.cp = pr->cp_static;
		c->prop.measured = true;
	} else {
		prop_estimate(pitch_in / d_in, blades, &c->prop);
	}
}

double
parts_published_thrust_n(const struct parts_ctx *x,
                         const struct catalog_motor *m, int cells)
{
	if (!m->integrated || !(m->max_thrust_n > 0.0))
		return 0.0;
	/* Published at sea level on the system's highest rated bus (where
	 * the maker gives one): thrust at a given rpm follows the density,
	 * and the rpm the voltage, so thrust ~ ρ V² below that bus. */
	double scale = x->p->air.rho_kg_m3 / RHO_SL_KG_M3;
	if (m->cells_max > 0 && cells < m->cells_max) {
		double v = (double)cells / (double)m->cells_max;
		scale *= v * v;
	}
	return m->max_thrust_n * scale;
}

void
parts_motor_limits(const struct catalog_motor *m, struct parts_motor_limits *l)
{
	if (m->integrated) {
		/* The system's ESC's continuous rating holds the mission; full
		 * throttle is bounded by the published maximum thrust instead. */
		l->sustained_a = m->integrated_esc_current_a > 0.0
		    ? m->integrated_esc_current_a : m->max_current_a;
		l->full_a = 0.0;
		l->sustained_text = "continuous rating of its ESC";
		l->full_text = "";
	} else if (strcmp(m->max_current_basis, "continuous") == 0) {
		/* No peak published: the continuous rating bounds the burst too. */
		l->sustained_a = l->full_a = m->max_current_a;
		l->sustained_text = l->full_text = "continuous rating";
	} else {
		/* A peak rating (most makers publish no continuous one): it
		 * bounds every current; the heat of sustained flight is the
		 * winding-temperature check's. */
		l->sustained_a = l->full_a = m->max_current_a;
		l->sustained_text = "peak rating (no continuous rating published)";
		l->full_text = strncmp(m->max_current_basis, "peak_", 5) == 0
		    && strcmp(m->max_current_basis, "peak_unspecified") != 0
		    ? "peak rating" : "maximum (duration not published)";
	}
}

/* What a propeller brings to every motor it is tried on, worked out once
 * per bus and catalogue propeller (for an integrated system's own
 * propeller, per option): its craft fields (option_prop), D^4 and its
 * torque factor Q / n^2 before the installation. */
struct prop_pre {
	struct perf_craft craft;
	double d4_m4;
	double kq_nm_s2;
};

static void
prop_pre(const struct catalog_motor *m, const struct catalog_prop *pr,
         const struct parts_aim *aim, double rho, struct prop_pre *pp)
{
	memset(pp, 0, sizeof *pp);
	option_prop(m, pr, aim, &pp->craft);
	double d = pp->craft.prop_diameter_m;
	pp->d4_m4 = pow(d, 4.0);
	pp->kq_nm_s2 = prop_kq_nm_s2(&pp->craft.prop, rho, d);
}

/* What a motor brings to every propeller and bus it is tried on, worked
 * out once per solve: its winding resistance and no-load current
 * (published, else estimated), its thermal resistance, the decay of its
 * winding's temperature over the full-throttle burst and its current
 * ratings. */
struct motor_pre {
	double r_ohm, i0_a;
	bool estimated;
	double rth_k_w, decay_full;
	struct parts_motor_limits lim;
};

static void
motor_pre(const struct catalog_motor *m, struct motor_pre *mp)
{
	double est_r_ohm, est_i0_a;
	screen_motor_estimates(m, &est_r_ohm, &est_i0_a);
	mp->r_ohm = m->resistance_ohm > 0.0 ? m->resistance_ohm : est_r_ohm;
	mp->i0_a = m->no_load_current_a > 0.0 ? m->no_load_current_a : est_i0_a;
	mp->estimated = !(m->resistance_ohm > 0.0 && m->no_load_current_a > 0.0);
	mp->rth_k_w = motor_thermal_resistance_k_w(m->mass_kg);
	mp->decay_full = motor_temp_decay(m->mass_kg, PERF_FULL_THROTTLE_S);
	parts_motor_limits(m, &mp->lim);
}

/* The motor points of an option a ranking works out, each only when a
 * check first reads it (most options fail the thrust or a current rating
 * long before their hover is needed): the torque factor and winding
 * temperature they share, and full throttle on the ranking's bus. */
struct drive_pts {
	const struct motor_pre *mp;
	double kq, t_w;
	struct motor_point full;
	bool hover_done;
};

/* Motor m's model with its motor_pre mp's values. */
static struct motor_model
motor_of(const struct catalog_motor *m, const struct motor_pre *mp)
{
	return (struct motor_model){ .kv_rpm_per_v = m->kv_rpm_per_v,
		.resistance_ohm = mp->r_ohm, .no_load_current_a = mp->i0_a,
		.mass_kg = m->mass_kg };
}

/* Full throttle of motor mm on propeller pp (the ranking's bus of cells,
 * the ranking's winding temperature) into d.  False when the motor cannot
 * turn the propeller. */
static bool
full_point(const struct parts_ctx *x, const struct motor_model *mm,
           const struct prop_pre *pp, int cells, struct drive_pts *d)
{
	d->kq = x->aim.install_factor * pp->kq_nm_s2;
	d->t_w = x->p->ambient_c + RANK_WINDING_RISE_K;
	double v = (double)cells * x->p->chem->v_nom * PARTS_LOADED_BUS;
	return motor_at_voltage(mm, d->t_w, v, d->kq, &d->full);
}

/* Is full thrust short of lifting the design at the required T/W, with
 * the largest payload aboard and a little to spare, at mass_kg?  The
 * screen lets an option 2 % short through (the closing flies it on its
 * own masses); the record's check holds the requirement. */
static bool
thrust_short(const struct parts_ctx *x, double full_thrust_n, double mass_kg)
{
	const struct sizing_params *p = x->p;
	double thrust = (double)p->n_rotors * full_thrust_n;
	double need_per_kg_n = PARTS_TW_SPARE * PARTS_TW_TOL * x->aim.tw_required
	    * G0_M_S2;
	return thrust < need_per_kg_n * (mass_kg + p->extra_payload_kg);
}

/* Option m (with its motor_pre mp) on propeller pr (with its prop_pre
 * pp), or an integrated system (pr and pp NULL), on a bus of cells: its
 * full-throttle point, already in d when have_full.  False when the motor
 * cannot turn the propeller. */
static bool
drive_full(const struct parts_ctx *x, const struct catalog_motor *m,
           const struct motor_pre *mp, const struct catalog_prop *pr,
           const struct prop_pre *pp, int cells, bool have_full,
           struct parts_option *o, struct drive_pts *d)
{
	const struct sizing_params *p = x->p;
	const struct parts_aim *aim = &x->aim;
	memset(o, 0, sizeof *o);
	o->cells = cells;
	o->motor = m;
	o->prop = pr;
	struct perf_craft *c = &o->craft;
	c->motor = motor_of(m, mp);
	c->motor_r_estimated = mp->estimated;
	c->motor_max_current_a = m->max_current_a;
	c->motor_max_power_w = m->max_power_w;
	double rho = p->air.rho_kg_m3;
	struct prop_pre own;
	if (pp == NULL) {
		prop_pre(m, pr, aim, rho, &own);
		pp = &own;
	}
	c->prop_diameter_m = pp->craft.prop_diameter_m;
	c->prop_pitch_m = pp->craft.prop_pitch_m;
	c->prop_blades = pp->craft.prop_blades;
	c->prop_max_rpm = pp->craft.prop_max_rpm;
	c->prop = pp->craft.prop;
	o->d4_m4 = pp->d4_m4;
	c->cells = cells;

	d->mp = mp;
	d->hover_done = false;
	struct motor_point *full = &d->full;
	if (!have_full && !full_point(x, &c->motor, pp, cells, d))
		return false;
	o->full_thrust_n = prop_thrust_d4_n(&c->prop, rho, full->rps, o->d4_m4);
	o->full_current_a = full->current_a;
	o->full_power_w = full->power_in_w;
	/* An integrated system is flown up to the thrust its maker publishes
	 * and no further: where the model of its motor and propeller promises
	 * more, the point at that thrust (on the same rotor) is full throttle.
	 * Nor past its own ESC's continuous rating (the full-throttle burst
	 * lasts longer than the seconds a peak rating allows): the torque that
	 * current gives, K (I - I0), meets the rotor's kq n^2 at n_esc. */
	c->max_thrust_n = parts_published_thrust_n(x, m, cells);
	if (m->integrated && m->integrated_esc_current_a > mp->i0_a) {
		double n_esc = sqrt(motor_k_nm_a(m->kv_rpm_per_v)
		    * (m->integrated_esc_current_a - mp->i0_a) / d->kq);
		double t_esc = prop_thrust_d4_n(&c->prop, rho, n_esc, o->d4_m4);
		if (!(c->max_thrust_n > 0.0) || t_esc < c->max_thrust_n)
			c->max_thrust_n = t_esc;
	}
	if (c->max_thrust_n > 0.0 && o->full_thrust_n > c->max_thrust_n) {
		double n_c = sqrt(c->max_thrust_n / (c->prop.ct * rho * o->d4_m4));
		motor_at_shaft(&c->motor, d->t_w, d->kq * 2.0 * M_PI * n_c * n_c * n_c,
		    n_c, full);
		o->full_thrust_n = c->max_thrust_n;
		o->full_current_a = full->current_a;
		o->full_power_w = full->power_in_w;
	}
	/* Until drive_sag() finds a sagged point: the ranking bus's. */
	o->sagged_current_a = o->full_current_a;
	o->sagged_power_w = o->full_power_w;
	return true;
}

/* Full throttle on the most-sagged bus a kept pack may give.  The ratings
 * are pruned where a real pack is kindest to them: the record flies full
 * throttle on its pack's own sag (up to PARTS_MAX_SAG, closure.c), which
 * lowers the current; an option pruned at the ranking's bus would be lost
 * though the record would pass it.  An integrated system capped at its
 * published thrust draws that point's current on any bus.  False (the
 * ranking bus's values kept) where there is no such point. */
static bool
drive_sag(const struct parts_ctx *x, struct parts_option *o,
          const struct drive_pts *d, struct motor_point *sag)
{
	const struct perf_craft *c = &o->craft;
	if ((c->max_thrust_n > 0.0 && o->full_thrust_n >= c->max_thrust_n)
	    || !motor_at_voltage(&c->motor, d->t_w, (double)o->cells
	    * x->p->chem->v_nom * (1.0 - PARTS_MAX_SAG), d->kq, sag))
		return false;
	o->sagged_current_a = sag->current_a;
	o->sagged_power_w = sag->power_in_w;
	return true;
}

/* The hover of the continuous design's mass on this rotor, and the
 * winding as the record's checks heat it (perf.c): steady in hover, then
 * the full-throttle burst from there, on both buses (sag NULL: there is
 * no sagged point, the ranking bus's stands). */
static void
drive_hover(const struct parts_ctx *x, struct parts_option *o,
            struct drive_pts *d, const struct motor_point *sag)
{
	const struct sizing_params *p = x->p;
	const struct motor_pre *mp = d->mp;
	const struct perf_craft *c = &o->craft;
	double t_h = x->aim.mass_kg * G0_M_S2 / (double)p->n_rotors;
	double n_h = sqrt(t_h / (c->prop.ct * p->air.rho_kg_m3 * o->d4_m4));
	struct motor_point hov;
	motor_at_shaft(&c->motor, d->t_w, d->kq * 2.0 * M_PI * n_h * n_h * n_h,
	    n_h, &hov);
	o->hover_power_w = hov.power_in_w * (double)p->n_rotors;
	double hover_c = p->ambient_c + (hov.copper_loss_w + hov.no_load_loss_w)
	    * mp->rth_k_w;
	o->full_winding_c = fmax(hover_c, motor_temp_step_from(mp->rth_k_w,
	    mp->decay_full, hover_c, p->ambient_c,
	    d->full.copper_loss_w + d->full.no_load_loss_w));
	o->sagged_winding_c = sag == NULL ? o->full_winding_c
	    : fmax(hover_c, motor_temp_step_from(mp->rth_k_w, mp->decay_full,
	    hover_c, p->ambient_c, sag->copper_loss_w + sag->no_load_loss_w));
	d->hover_done = true;
}

static double
option_j(const struct parts_ctx *x, const struct parts_option *o)
{
	const struct parts_aim *aim = &x->aim;
	double n = (double)x->p->n_rotors;
	const struct catalog_motor *m = o->motor;
	double drive = n * m->mass_kg;
	if (o->prop != NULL)
		drive += n * (o->prop->mass_kg + SIZING_ESC_KG_PER_A * x->p->c_esc
		    * PARTS_CURRENT_MARGIN * o->full_current_a);
	double d_battery = aim->hover_power_w > 0.0
	    ? aim->battery_kg * (o->hover_power_w / aim->hover_power_w - 1.0) : 0.0;
	return 100.0 * aim->growth * (drive - aim->drive_kg + d_battery)
	    / aim->mass_kg;
}

/* The first reason the option fails a hard limit, or PARTS_OK; once it
 * passes, o->j is its score, o->parity says whether it reaches the
 * required T/W at its estimated mass and o->marginal whether it is within
 * the motor's ratings only on the most-sagged bus.  The checks run in one
 * fixed order (the census counts the first that fails); each motor point
 * is worked out when the first check that reads it comes. */
static enum parts_reason
option_limits(const struct parts_ctx *x, struct parts_option *o,
              struct drive_pts *d)
{
	const struct sizing_params *p = x->p;
	const struct perf_craft *c = &o->craft;
	const struct catalog_motor *m = o->motor;
	bool locked = x->lock_motor != NULL;
	struct motor_point sag;
	bool has_sag = false;
	/* The screen below trusts J only once aim.lightest is below 1 (at
	 * first the screen's mass is the continuous design's whatever J
	 * says): only then is the score needed before the checks. */
	if (x->aim.lightest < 1.0) {
		has_sag = drive_sag(x, o, d, &sag);
		drive_hover(x, o, d, has_sag ? &sag : NULL);
		o->j = option_j(x, o);
	}
	/* The thrust to lift the design at the required T/W with the largest
	 * payload aboard, with a little to spare, at the lightest mass the
	 * option may close at: its J estimate, trusted below the continuous
	 * design's only down to aim.lightest.  The closing finds the real
	 * mass, and checks the real T/W there. */
	double screen = d->hover_done
	    ? fmax(x->aim.lightest, fmin(1.0, 1.0 + o->j / 100.0)) : 1.0;
	double mass = x->aim.mass_kg * screen;
	if (thrust_short(x, o->full_thrust_n, mass))
		return PARTS_THRUST;
	/* The motor's ratings, pruned on the most-sagged bus. */
	if (!d->hover_done)
		has_sag = drive_sag(x, o, d, &sag);
	const struct parts_motor_limits *lim = &d->mp->lim;
	if (!locked && lim->full_a > 0.0 && o->sagged_current_a > lim->full_a)
		return PARTS_MOTOR_CURRENT;
	if (!locked && !m->integrated && m->max_power_w > 0.0
	    && o->sagged_power_w > m->max_power_w)
		return PARTS_MOTOR_POWER;
	double rps_full = sqrt(o->full_thrust_n / (c->prop.ct * p->air.rho_kg_m3
	    * o->d4_m4));
	if (M_PI * c->prop_diameter_m * rps_full / p->air.sound_m_s > AERO_TIP_MACH_MAX)
		return PARTS_TIP_MACH;
	if (c->prop_max_rpm > 0.0 && rps_full * S_PER_MIN > c->prop_max_rpm)
		return PARTS_PROP_RPM;
	if (!d->hover_done) {
		drive_hover(x, o, d, has_sag ? &sag : NULL);
		o->j = option_j(x, o);
	}
	/* An integrated system's losses are not modelled apart from its ESC
	 * and propeller (its mass holds all three): the record checks it. */
	if (!locked && !m->integrated && o->sagged_winding_c > MOTOR_WINDING_MAX_C)
		return PARTS_WINDING;
	/* The wake of the continuous design's mass on this rotor, with the
	 * slack of a design that closes up to 10 % lighter (the wake goes as
	 * the square root of the mass; the record checks its own). */
	int arms = p->coaxial ? p->n_rotors / 2 : p->n_rotors;
	double area = 0.25 * M_PI * c->prop_diameter_m * c->prop_diameter_m;
	if (x->aim.downwash_cap_ms > 0.0 && aero_downwash_ms(mass,
	    p->air.rho_kg_m3, arms, area) > PARTS_DOWNWASH_SLACK
	    * x->aim.downwash_cap_ms)
		return PARTS_DOWNWASH;
	/* Parity: the T/W is still reached at the option's own estimate. */
	double mass_est = x->aim.mass_kg
	    * fmax(1.0 + o->j / 100.0, x->aim.lightest);
	o->parity = !thrust_short(x, o->full_thrust_n, mass_est);
	/* Within the ratings on the ranking's bus too?  One within them only
	 * on the most-sagged bus is marginal (kept apart, see above). */
	bool cur_full = lim->full_a > 0.0 && o->full_current_a > lim->full_a;
	bool pow_full = !m->integrated && m->max_power_w > 0.0
	    && o->full_power_w > m->max_power_w;
	bool hot_full = !m->integrated && o->full_winding_c > MOTOR_WINDING_MAX_C;
	o->marginal = !locked && (cur_full || pow_full || hot_full);
	return PARTS_OK;
}

/* Keep o among the best max_best, best J first (ties: fewer cells nearer
 * the continuous bus, then ids: deterministic). */
static void
keep(struct parts_option *best, int *n, int max_best, const struct parts_option *o)
{
	/* One option per motor and bus (its best propeller): the closings then
	 * try different motors and buses, not variants of one. */
	for (int i = 0; i < *n; i++) {
		if (best[i].motor != o->motor || best[i].cells != o->cells)
			continue;
		if (best[i].j <= o->j)
			return;
		memmove(&best[i], &best[i + 1], (size_t)(*n - i - 1) * sizeof *best);
		(*n)--;
		break;
	}
	int at = *n;
	while (at > 0 && (best[at - 1].j > o->j || (best[at - 1].j == o->j
	    && strcmp(best[at - 1].motor->id, o->motor->id) > 0)))
		at--;
	if (at >= max_best)
		return;
	int last = *n < max_best ? *n : max_best - 1;
	memmove(&best[at + 1], &best[at], (size_t)(last - at) * sizeof *best);
	best[at] = *o;
	if (*n < max_best)
		(*n)++;
}

static bool
motor_on_bus(const struct catalog_motor *m, int cells)
{
	return !(m->cells_min > 0 && cells < m->cells_min)
	    && !(m->cells_max > 0 && cells > m->cells_max);
}

/* Has the bus of cells any pack arrangement?  A scan rather than
 * closure.c's parts_packs_on(): closure.c calls into this file, and no two
 * files may call each other (tests/check_layers.sh). */
static bool
bus_has_pack(const struct parts_ctx *x, int cells)
{
	for (int i = 0; i < x->n_packs; i++)
		if (x->packs[i].b->cells_series * x->packs[i].series == cells)
			return true;
	return false;
}

/* The mission's locks on values (paper §II-C) on a motor or propeller. */
static bool
motor_locked_out(const struct parts_ctx *x, const struct catalog_motor *m)
{
	if (x->lock_motor != NULL)
		return m != x->lock_motor;
	const struct spec_locks *lk = &x->spec->locks;
	return lk->is_motor_locked
	    && fabs(m->kv_rpm_per_v / lk->locked_kv - 1.0) > LOCK_KV_TOL;
}

static bool
prop_locked_out(const struct parts_ctx *x, const struct catalog_prop *pr)
{
	if (x->lock_prop != NULL)
		return pr != x->lock_prop;
	const struct spec_locks *lk = &x->spec->locks;
	return lk->is_prop_locked
	    && (fabs(pr->diameter_in - lk->locked_diameter_in) > LOCK_DIAMETER_TOL_IN
	    || fabs(pr->pitch_in - lk->locked_pitch_in) > LOCK_PITCH_TOL_IN);
}

/* The three lists of kept options (see the top of this file). */
struct kept {
	struct parts_option parity[PARTS_KEEP];
	int n_parity;
	struct parts_option short_of[PARTS_KEEP_SHORT];
	int n_short;
	struct parts_option marginal[PARTS_KEEP_MARGINAL];
	int n_marginal;
};

/* One option: flown, checked, scored; kept among the best. */
static void
try_option(struct parts_ctx *x, const struct catalog_motor *m,
           const struct motor_pre *mp, const struct catalog_prop *pr,
           const struct prop_pre *pp, int cells, struct kept *k,
           double *motor_best_j)
{
	struct parts_option o;
	struct drive_pts d;
	x->n_examined++;
	/* Most options cannot lift the design at full throttle: that is told
	 * before the option is filled in, where it can be (a catalogue
	 * propeller: no published thrust caps the point; and the screen's
	 * mass still the continuous design's, see option_limits()). */
	bool have_full = pp != NULL && x->aim.lightest >= 1.0;
	if (have_full) {
		struct motor_model mm = motor_of(m, mp);
		if (!full_point(x, &mm, pp, cells, &d)
		    || thrust_short(x, prop_thrust_d4_n(&pp->craft.prop,
		    x->p->air.rho_kg_m3, d.full.rps, pp->d4_m4), x->aim.mass_kg)) {
			x->n_census[PARTS_THRUST]++;
			return;
		}
	}
	if (!drive_full(x, m, mp, pr, pp, cells, have_full, &o, &d)) {
		x->n_census[PARTS_THRUST]++;
		return;
	}
	enum parts_reason why = option_limits(x, &o, &d);
	if (why != PARTS_OK) {
		x->n_census[why]++;
		return;
	}
	if (o.j < *motor_best_j)
		*motor_best_j = o.j;
	if (o.marginal)
		keep(k->marginal, &k->n_marginal, PARTS_KEEP_MARGINAL, &o);
	else if (o.parity)
		keep(k->parity, &k->n_parity, PARTS_KEEP, &o);
	else
		keep(k->short_of, &k->n_short, PARTS_KEEP_SHORT, &o);
}

/* The catalogue's usable motors by KV, for the KV window of a bus and
 * propeller. */
static int
cmp_kv(const void *a, const void *b)
{
	const struct catalog_motor *x = *(const struct catalog_motor *const *)a;
	const struct catalog_motor *y = *(const struct catalog_motor *const *)b;
	if (x->kv_rpm_per_v != y->kv_rpm_per_v)
		return x->kv_rpm_per_v < y->kv_rpm_per_v ? -1 : 1;
	return strcmp(x->id, y->id);
}

int
parts_rank(struct parts_ctx *x, struct parts_option *best, int max_best,
           struct res_candidate *cand, int *n_cand)
{
	const struct sizing_params *p = x->p;
	const struct catalog *cat = x->cat;
	size_t nm = catalog_n_motors(cat), np = catalog_n_props(cat);
	const struct catalog_motor **mv = xmalloc((nm ? nm : 1) * sizeof *mv);
	double *mj = xmalloc((nm ? nm : 1) * sizeof *mj);
	int n_m = 0;
	for (size_t i = 0; i < nm; i++) {
		const struct catalog_motor *m = catalog_motor(cat, i);
		if (!m->usable)
			continue;
		if (motor_locked_out(x, m)) {
			x->n_census[PARTS_LOCK]++;
			continue;
		}
		char why[256];
		if (m != x->lock_motor && screen_motor(m, why, sizeof why) != NULL) {
			x->n_census[PARTS_IMPLAUSIBLE]++;
			continue;
		}
		if (m != x->lock_motor && screen_doubt_motor(m, why, sizeof why) != NULL) {
			x->n_census[PARTS_DOUBTFUL]++;
			continue;
		}
		mv[n_m++] = m;
	}
	qsort(mv, (size_t)n_m, sizeof *mv, cmp_kv);
	struct motor_pre *mpre = xmalloc((n_m ? (size_t)n_m : 1) * sizeof *mpre);
	for (int i = 0; i < n_m; i++) {
		mj[i] = PRUNED_J;
		motor_pre(mv[i], &mpre[i]);
	}

	struct kept *kept = xcalloc(1, sizeof *kept);
	double rho = p->air.rho_kg_m3;
	double t_req = PARTS_TW_TOL * x->aim.tw_required
	    * (x->aim.mass_kg + p->extra_payload_kg)
	    * G0_M_S2 / (double)p->n_rotors;
	double d_min_in = MIN_DIAMETER_FRAC * x->aim.prop_diameter_in;
	for (int s = x->cells_lo; s <= x->cells_hi; s++) {
		if (!bus_has_pack(x, s)) {
			x->n_census[PARTS_NO_BATTERY]++;
			continue;
		}
		double v_bus = (double)s * p->chem->v_nom * PARTS_LOADED_BUS;
		/* Integrated systems bring their own propeller. */
		for (int i = 0; i < n_m; i++) {
			const struct catalog_motor *m = mv[i];
			if (!m->integrated)
				continue;
			if (!motor_on_bus(m, s)) {
				x->n_census[PARTS_MOTOR_CELLS]++;
				continue;
			}
			if (m->integrated_prop_in > x->aim.overlap_limit_in + 1e-6) {
				x->n_census[PARTS_PROP_OVERLAP]++;
				continue;
			}
			try_option(x, m, &mpre[i], NULL, NULL, s, kept, &mj[i]);
		}
		for (size_t k = 0; k < np; k++) {
			const struct catalog_prop *pr = catalog_prop(cat, k);
			if (!pr->usable || pr->diameter_in < d_min_in)
				continue;
			if (pr->diameter_in > x->aim.overlap_limit_in + 1e-6) {
				x->n_census[PARTS_PROP_OVERLAP]++;
				continue;
			}
			if (prop_locked_out(x, pr)) {
				x->n_census[PARTS_LOCK]++;
				continue;
			}
			char why[256];
			if (pr != x->lock_prop && screen_prop(pr, why, sizeof why) != NULL) {
				x->n_census[PARTS_IMPLAUSIBLE]++;
				continue;
			}
			if (pr != x->lock_prop && screen_doubt_prop(pr, why, sizeof why) != NULL) {
				x->n_census[PARTS_DOUBTFUL]++;
				continue;
			}
			/* The KV whose loaded full-throttle speed gives the thrust. */
			struct prop_pre pp;
			prop_pre(NULL, pr, &x->aim, rho, &pp);
			double n_req = sqrt(t_req / (pp.craft.prop.ct * rho * pp.d4_m4));
			double kv_req = S_PER_MIN * n_req / (v_bus * LOADED_SPEED);
			for (int i = 0; i < n_m; i++) {
				const struct catalog_motor *m = mv[i];
				if (m->integrated)
					continue;
				if (x->lock_motor == NULL
				    && m->kv_rpm_per_v < KV_WINDOW_LO * kv_req)
					continue;
				if (x->lock_motor == NULL
				    && m->kv_rpm_per_v > KV_WINDOW_HI * kv_req)
					break;
				if (!motor_on_bus(m, s)) {
					x->n_census[PARTS_MOTOR_CELLS]++;
					continue;
				}
				if ((m->prop_min_in > 0.0 && pr->diameter_in
				    < m->prop_min_in - PARTS_RANGE_TOL_IN)
				    || (m->prop_max_in > 0.0 && pr->diameter_in
				    > m->prop_max_in + PARTS_RANGE_TOL_IN)) {
					x->n_census[PARTS_PROP_RANGE]++;
					continue;
				}
				try_option(x, m, &mpre[i], pr, &pp, s, kept, &mj[i]);
			}
		}
	}
	/* One crosshair point per usable motor: its best J anywhere. */
	*n_cand = 0;
	for (int i = 0; i < n_m && *n_cand < RES_MAX_CANDIDATES; i++) {
		struct res_candidate *c = &cand[(*n_cand)++];
		memset(c, 0, sizeof *c);
		snprintf(c->id, sizeof c->id, "%s", mv[i]->id);
		c->kv = mv[i]->kv_rpm_per_v;
		c->mass_kg = mv[i]->mass_kg;
		c->j_score = mj[i];
		c->feasible = mj[i] < PRUNED_J;
	}
	free(mv);
	free(mj);
	free(mpre);
	/* The options that reach the required T/W first. */
	int n_best = 0;
	for (int i = 0; i < kept->n_parity && n_best < max_best; i++)
		best[n_best++] = kept->parity[i];
	for (int i = 0; i < kept->n_short && n_best < max_best; i++)
		best[n_best++] = kept->short_of[i];
	for (int i = 0; i < kept->n_marginal && n_best < max_best; i++)
		best[n_best++] = kept->marginal[i];
	free(kept);
	return n_best;
}
