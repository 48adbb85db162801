/* optim.c — discrete part selection and the BOM-closed design (see optim.h). */
#include "parts/optim.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics/aero.h"
#include "sizing/feasibility.h"
#include "sizing/sizing.h"
#include "util/strbuf.h"
#include "physics/therm.h"
#include "util/units.h"
#include "util/xalloc.h"

#define RANGE_TOL_IN     0.05  /* rounding slack on a recommended propeller range, in */
#define OVERLAP_TOL_IN   1e-9  /* the overlap limit is itself a rounded-free value */
/* An integrated system's mass covers its propeller and ESC; sizing.c reads a
 * zero part mass as "use the scaling law", so those parts get this token. */
#define INTEGRATED_PART_KG 1e-9
#define BATTERY_TRIES    4     /* closings per combination, with upsized battery or ESC */
#define UPSIZE_MIN       1.15  /* least capacity step after a failed discharge */
#define UPSIZE_MAX       3.0   /* largest capacity step */
#define FLOWN_TOL        0.999 /* mission flown: as in feasibility.c */
#define CHECK_RELTOL     1e-9  /* check comparison tolerance, relative */

const char *const optim_reason_text[OPTIM_REASON_MAX] = {
	"none",
	"motor cell range",
	"motor current",
	"motor power",
	"prop overlap",
	"recommended prop range",
	"tip Mach",
	"prop rpm limit",
	"hover rpm",
	"ESC current",
	"no pack for the bus",
};

/* ---- small helpers -------------------------------------------------------- */

/* Append a formatted piece to dst[n]. */
static void __attribute__((format(printf, 3, 4)))
append(char *dst, size_t n, const char *fmt, ...)
{
	size_t len = strlen(dst);
	if (len + 1 >= n)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(dst + len, n - len, fmt, ap);
	va_end(ap);
}

/* Chemistry family: the catalogue says "LiPo" where a mission names a
 * LiPo profile such as "LiPo_agricultural". */
static const char *
chem_family(const char *name)
{
	if (strcmp(name, "LiHV") == 0 || strcmp(name, "LiPo_highvoltage") == 0)
		return "LiHV";
	if (strncmp(name, "LiPo", 4) == 0)
		return "LiPo";
	if (strncmp(name, "Li-ion", 6) == 0)
		return "Li-ion";
	return name;
}

/* A value of the continuous design at its bus S*, moved to `cells` at
 * constant power (currents) or constant energy (capacity). */
static double
at_bus(const struct optim_target *t, double v_star, int cells)
{
	return v_star * (double)t->cells / (double)cells;
}

/* Full-throttle rotor speed under load, rev/min. */
static double
full_rpm(const struct optim_target *t, int cells, double kv)
{
	return kv * (double)cells * t->v_cell_nom_v * OPTIM_LOAD_RPM;
}

/* The per-motor current motor and ESC must carry: the full-throttle
 * current with the 10 % margin, of the target on `cells` ... */
static double
target_current_a(const struct optim_target *t, int cells)
{
	return OPTIM_CURRENT_MARGIN * at_bus(t, t->motor_peak_current_a, cells);
}

/* ... or of a closed real-parts design. */
static double
closed_current_a(const struct res_run *o)
{
	return OPTIM_CURRENT_MARGIN * o->opt.motor_peak_current_a;
}

static double
option_diameter_in(const struct catalog_motor *m, const struct catalog_prop *p)
{
	return p != NULL ? p->diameter_in : m->integrated_prop_in;
}

/* ---- J-score and limits --------------------------------------------------- */

/* Hover rotor speed of a propeller of diameter_in at the target's thrust
 * per rotor (T = C_t ρ n² D⁴), rev/s.  It depends on the propeller alone,
 * so the search computes it once per propeller, not per motor and bus. */
static double
hover_rps(const struct optim_target *t, double diameter_in)
{
	double thrust_n = t->mass_kg * G0_M_S2 / (double)t->n_rotors;
	return aero_rps_for_thrust(thrust_n, t->ct, t->rho_kg_m3, in_to_m(diameter_in));
}

/* θ_hvr: hover over full-throttle rotor speed. */
static double
hover_theta(double n_hover_rps, double n_max_rps)
{
	return n_max_rps > 0.0 ? n_hover_rps / n_max_rps : 1.0 / OPTIM_LOAD_RPM;
}

/* The terms of J (eq. J), each as its own function so that the search can
 * compute those of a propeller, and of a motor on one bus, once for every
 * pairing; j_sum() adds them in one fixed order, so a J is the same bits
 * however its terms were come by.  The max(0, x) are written out: fmax()
 * is a call, and this is the search's inner loop. */
static double
positive_part(double x)
{
	return x > 0.0 ? x : 0.0;
}

static double
j_diameter_term(const struct optim_target *t, double diameter_in)
{
	if (!(t->prop_diameter_in > 0.0))
		return 0.0;
	return OPTIM_W_DIAMETER * fabs(diameter_in - t->prop_diameter_in)
	    / t->prop_diameter_in;
}

static double
j_kv_term(const struct optim_target *t, int cells, double kv)
{
	double kv_t = at_bus(t, t->motor_kv, cells);
	return kv_t > 0.0 ? OPTIM_W_KV * fabs(kv - kv_t) / kv_t : 0.0;
}

static double
j_pitch_term(const struct optim_target *t, double pitch_in)
{
	if (!(pitch_in > 0.0 && t->prop_pitch_in > 0.0))
		return 0.0;
	return OPTIM_W_PITCH * fabs(pitch_in - t->prop_pitch_in) / t->prop_pitch_in;
}

/* Pen_a: hover throttle this motor really gives on this propeller against
 * the role's target. */
static double
j_throttle_term(const struct optim_target *t, double theta)
{
	return OPTIM_PEN_THROTTLE * positive_part(theta - t->hover_throttle);
}

/* Pen_m (ours): a motor heavier than the scaling law's (for an integrated
 * system, pitch_in 0, than the law's motor, propeller and ESC). */
static double
j_mass_term(const struct optim_target *t, bool pitched, double motor_mass_kg)
{
	double m_star = pitched ? t->motor_mass_kg : t->drive_mass_kg;
	if (!(m_star > 0.0))
		return 0.0;
	return OPTIM_W_MASS * positive_part(motor_mass_kg / m_star - 1.0);
}

/* Pen_θ: cruise body pitch above 20° (the same for every part). */
static double
j_cruise_term(const struct optim_target *t)
{
	return OPTIM_PEN_PITCH * positive_part(t->forward_pitch_deg - OPTIM_PITCH_FREE_DEG);
}

static double
j_sum(double diameter, double kv, double pitch, double throttle, double mass,
      double cruise)
{
	return diameter + kv + pitch + throttle + mass + cruise;
}

/* optim_j_score with θ_hvr already known. */
static double
j_score_at(const struct optim_target *t, int cells, double diameter_in,
           double pitch_in, double kv, double motor_mass_kg, double theta)
{
	return j_sum(j_diameter_term(t, diameter_in), j_kv_term(t, cells, kv),
	    j_pitch_term(t, pitch_in), j_throttle_term(t, theta),
	    j_mass_term(t, pitch_in > 0.0, motor_mass_kg), j_cruise_term(t));
}

double
optim_j_score(const struct optim_target *t, int cells, double diameter_in,
              double pitch_in, double kv, double motor_mass_kg,
              double *hover_throttle)
{
	double theta = hover_theta(hover_rps(t, diameter_in),
	    full_rpm(t, cells, kv) / S_PER_MIN);
	if (hover_throttle != NULL)
		*hover_throttle = theta;
	return j_score_at(t, cells, diameter_in, pitch_in, kv, motor_mass_kg, theta);
}

/* What the pair limits need of a propeller (or an integrated system's own),
 * fixed for one target: the search computes it once per propeller. */
struct prop_aim {
	double d_in;          /* diameter */
	double tip_m;         /* π D: tip speed per rev/s, m */
	double n_hover_rps;   /* hover_rps() */
};

static void
prop_aim_of(const struct optim_target *t, const struct catalog_motor *m,
            const struct catalog_prop *p, struct prop_aim *a)
{
	a->d_in = option_diameter_in(m, p);
	a->tip_m = M_PI * in_to_m(a->d_in);
	a->n_hover_rps = hover_rps(t, a->d_in);
}

/* The limits of the motor alone on `cells` (cell range, current, power)
 * when it must carry current_a (target_current_a() on that bus): bits
 * OPTIM_MOTOR_CELLS..OPTIM_MOTOR_POWER, the first three reasons.  The
 * ranking calls it once per motor and bus, with the bus's current
 * computed once. */
static inline unsigned
motor_mask_at(const struct optim_target *t, int cells, double current_a,
              const struct catalog_motor *m)
{
	unsigned mask = 0;
	if ((m->cells_min > 0 && cells < m->cells_min)
	    || (m->cells_max > 0 && cells > m->cells_max))
		mask |= 1u << OPTIM_MOTOR_CELLS;
	if (m->max_current_a < current_a)
		mask |= 1u << OPTIM_MOTOR_CURRENT;
	if (m->max_power_w > 0.0 && m->max_power_w < t->motor_peak_power_w)
		mask |= 1u << OPTIM_MOTOR_POWER;
	return mask;
}

static unsigned
motor_mask(const struct optim_target *t, int cells, const struct catalog_motor *m)
{
	return motor_mask_at(t, cells, target_current_a(t, cells), m);
}

/* A propeller too large for the wheelbase. */
static bool
over_overlap(const struct optim_target *t, double d_in)
{
	return d_in > t->overlap_limit_in + OVERLAP_TOL_IN;
}

/* A propeller below or above the motor's recommended range. */
static bool
below_range(const struct catalog_motor *m, double d_in)
{
	return m->prop_min_in > 0.0 && d_in < m->prop_min_in - RANGE_TOL_IN;
}

static bool
above_range(const struct catalog_motor *m, double d_in)
{
	return m->prop_max_in > 0.0 && d_in > m->prop_max_in + RANGE_TOL_IN;
}

/* Tip Mach number of propeller a at rpm (pair_mask() and mach_cut() must
 * agree to the bit). */
static double
tip_mach(const struct optim_target *t, const struct prop_aim *a, double rpm)
{
	return a->tip_m * rpm / S_PER_MIN / t->sound_m_s;
}

/* The limits of the motor on its propeller (p NULL: an integrated system),
 * bits OPTIM_PROP_OVERLAP..OPTIM_CANNOT_HOVER; rpm is the motor's
 * full_rpm() on the bus, *theta gets the hover throttle. */
static unsigned
pair_mask(const struct optim_target *t, const struct catalog_motor *m,
          const struct catalog_prop *p, const struct prop_aim *a, double rpm,
          double *theta)
{
	unsigned mask = 0;
	double d_in = a->d_in;
	if (over_overlap(t, d_in))
		mask |= 1u << OPTIM_PROP_OVERLAP;
	if (below_range(m, d_in) || above_range(m, d_in))
		mask |= 1u << OPTIM_PROP_RANGE;
	if (!(tip_mach(t, a, rpm) <= AERO_TIP_MACH_MAX))
		mask |= 1u << OPTIM_TIP_MACH;
	if (p != NULL && p->max_rpm > 0.0 && rpm > p->max_rpm)
		mask |= 1u << OPTIM_PROP_RPM;
	*theta = hover_theta(a->n_hover_rps, rpm / S_PER_MIN);
	if (!(*theta < 1.0))
		mask |= 1u << OPTIM_CANNOT_HOVER;
	return mask;
}

/* Every limit the option breaks, one bit per enum optim_reason. */
static unsigned
limit_mask(const struct optim_target *t, int cells, const struct catalog_motor *m,
           const struct catalog_prop *p)
{
	struct prop_aim a;
	prop_aim_of(t, m, p, &a);
	double theta;
	return motor_mask(t, cells, m)
	    | pair_mask(t, m, p, &a, full_rpm(t, cells, m->kv_rpm_per_v), &theta);
}

/* The limits a lock takes out of the search: a locked motor is never pruned
 * for its own ratings, a locked propeller never for its size, and a pair
 * limit binds unless both sides are locked. */
static unsigned
locked_mask(bool motor_locked, bool prop_locked)
{
	unsigned mask = 0;
	if (motor_locked)
		mask |= 1u << OPTIM_MOTOR_CELLS | 1u << OPTIM_MOTOR_CURRENT
		    | 1u << OPTIM_MOTOR_POWER;
	if (prop_locked)
		mask |= 1u << OPTIM_PROP_OVERLAP;
	if (motor_locked && prop_locked)
		mask |= 1u << OPTIM_PROP_RANGE | 1u << OPTIM_TIP_MACH
		    | 1u << OPTIM_PROP_RPM | 1u << OPTIM_CANNOT_HOVER;
	return mask;
}

/* The lowest reason bit set: masks hold only bits 1..OPTIM_REASON_MAX-1
 * (bit 0, OPTIM_OK, is never set), so that is the first in enum order. */
static enum optim_reason
first_reason(unsigned mask)
{
	return mask != 0 ? (enum optim_reason)__builtin_ctz(mask) : OPTIM_OK;
}

enum optim_reason
optim_limits(const struct optim_target *t, int cells,
             const struct catalog_motor *m, const struct catalog_prop *p)
{
	return first_reason(limit_mask(t, cells, m, p));
}

/* ---- ESC and battery ------------------------------------------------------ */

/* The highest bus an ESC takes: its published cell range, else 6S.  An ESC
 * rated above 6S says so (HV parts give 12S or 14S), and a 6S part on a
 * higher bus fails at power-up, so one whose range is not in the
 * catalogue is never put on more than 6S. */
static int
esc_max_cells(const struct catalog_esc *e)
{
	return e->cells_max > 0 ? e->cells_max : OPTIM_ESC_UNRATED_MAX_CELLS;
}

/* What an ESC must meet on `cells` whatever the motor: the frame size of a
 * stack board, the cell range, i_need_a per motor continuously. */
static bool
esc_carries(const struct optim_target *t, int cells, const struct catalog_esc *e,
            double i_need_a)
{
	if (e->channels > 1 && t->wheelbase_m > OPTIM_STACK_MAX_WHEELBASE_M)
		return false;
	if ((e->cells_min > 0 && cells < e->cells_min) || cells > esc_max_cells(e))
		return false;
	if (e->continuous_current_a < i_need_a)
		return false;
	return true;
}

/* ... for the target's current. */
static bool
esc_fits_bus(const struct optim_target *t, int cells, const struct catalog_esc *e)
{
	return esc_carries(t, cells, e, target_current_a(t, cells));
}

/* A full-stick punch can draw what the motor takes. */
static bool
esc_carries_burst(const struct catalog_motor *m, const struct catalog_esc *e)
{
	return !(e->burst_current_a > 0.0 && e->burst_current_a < m->max_current_a);
}

/* An ESC for motor m on `cells` carrying i_need_a per motor ... */
static bool
esc_fits_at(const struct optim_target *t, int cells, const struct catalog_motor *m,
            const struct catalog_esc *e, double i_need_a)
{
	return esc_carries(t, cells, e, i_need_a) && esc_carries_burst(m, e);
}

/* ... or the target's current. */
static bool
esc_fits(const struct optim_target *t, int cells, const struct catalog_motor *m,
         const struct catalog_esc *e)
{
	return esc_fits_at(t, cells, m, e, target_current_a(t, cells));
}

static int
esc_boards(const struct optim_target *t, const struct catalog_esc *e)
{
	int ch = e->channels > 0 ? e->channels : 1;
	return (t->n_rotors + ch - 1) / ch;
}

/* The lightest ESC set for motor m on `cells` that carries i_need_a per
 * motor and the motor's burst (a locked ESC is taken as is); false if
 * none. */
static bool
pick_esc_for(const struct optim_target *t, const struct catalog *cat,
             const char *lock, int cells, const struct catalog_motor *m,
             double i_need_a, const struct catalog_esc **out, int *n_boards)
{
	const struct catalog_esc *best = NULL;
	double best_kg = 0.0;
	for (size_t i = 0; i < catalog_n_escs(cat); i++) {
		const struct catalog_esc *e = catalog_esc(cat, i);
		if (!e->usable)
			continue;
		if (lock != NULL) {
			if (strcmp(e->id, lock) != 0)
				continue;
		} else if (!esc_fits_at(t, cells, m, e, i_need_a)) {
			continue;
		}
		double kg = (double)esc_boards(t, e) * e->mass_kg;
		if (best == NULL || kg < best_kg
		    || (kg == best_kg && strcmp(e->id, best->id) < 0)) {
			best = e;
			best_kg = kg;
		}
	}
	*out = best;
	*n_boards = best != NULL ? esc_boards(t, best) : 0;
	return best != NULL;
}

/* ... for the target's full-throttle current with the 10 % margin. */
static bool
pick_esc(const struct optim_target *t, const struct catalog *cat,
         const char *lock, int cells, const struct catalog_motor *m,
         const struct catalog_esc **out, int *n_boards)
{
	return pick_esc_for(t, cat, lock, cells, m, target_current_a(t, cells),
	    out, n_boards);
}

/* Packs needed in parallel for capacity and continuous current. */
static int
parallel_needed(const struct catalog_battery *b, double need_ah, double need_a)
{
	double by_energy = ceil(need_ah / b->capacity_ah - CHECK_RELTOL);
	double by_current = ceil(need_a / (b->capacity_ah * b->continuous_c) - CHECK_RELTOL);
	double n = fmax(1.0, fmax(by_energy, by_current));
	return n > 1000.0 ? 1000 : (int)n;
}

/* The packs a pick chooses from: the usable catalogue packs (the locked
 * one alone when one is locked), each with its chemistry family.  Built
 * once for a search's many picks. */
struct pack_list {
	const struct catalog_battery **b;
	const char **family;
	size_t n;
	bool locked;
};

static void
pack_list_init(const struct catalog *cat, const char *lock, struct pack_list *pl)
{
	size_t nb = catalog_n_batteries(cat);
	pl->b = xmalloc((nb > 0 ? nb : 1) * sizeof *pl->b);
	pl->family = xmalloc((nb > 0 ? nb : 1) * sizeof *pl->family);
	pl->n = 0;
	pl->locked = lock != NULL;
	for (size_t i = 0; i < nb; i++) {
		const struct catalog_battery *b = catalog_battery(cat, i);
		if (!b->usable || b->chemistry[0] == '\0' || b->cells_series < 1)
			continue;
		if (lock != NULL && strcmp(b->id, lock) != 0)
			continue;
		pl->family[pl->n] = chem_family(b->chemistry);
		pl->b[pl->n++] = b;
	}
}

static void
pack_list_free(struct pack_list *pl)
{
	free(pl->b);
	free(pl->family);
}

/* The lightest battery of the packs of pl that builds `cells` in series
 * and holds need_ah at need_a within the continuous C rating, of chemistry
 * family `keep` when given, else the mission's family when one exists.
 * Fills c->battery and the pack counts; false if none. */
static bool
pick_battery(const struct optim_target *t, const struct pack_list *pl,
             int cells, double need_ah, double need_a, const char *keep,
             struct optim_choice *c)
{
	const char *fam = keep != NULL ? keep : chem_family(t->chemistry);
	for (int pass = 0; pass < (keep != NULL ? 1 : 2); pass++) {
		const struct catalog_battery *best = NULL;
		int best_np = 0;
		double best_kg = 0.0;
		for (size_t i = 0; i < pl->n; i++) {
			const struct catalog_battery *b = pl->b[i];
			if (cells % b->cells_series != 0)
				continue;
			int ns = cells / b->cells_series;
			if (ns > OPTIM_MAX_SERIES && !pl->locked)
				continue;
			/* chem_family() returns one pointer per known family:
			 * equal pointers need no strcmp. */
			if (pass == 0 && pl->family[i] != fam
			    && strcmp(pl->family[i], fam) != 0)
				continue;
			int np = parallel_needed(b, need_ah, need_a);
			if (np > OPTIM_MAX_PARALLEL) {
				if (!pl->locked)
					continue;
				np = OPTIM_MAX_PARALLEL; /* honoured; the checks report it */
			}
			double kg = (double)(ns * np) * b->mass_kg;
			if (best == NULL || kg < best_kg
			    || (kg == best_kg && strcmp(b->id, best->id) < 0)) {
				best = b;
				best_np = np;
				best_kg = kg;
			}
		}
		if (best != NULL) {
			c->battery = best;
			c->series_packs = cells / best->cells_series;
			c->parallel_packs = best_np;
			return true;
		}
	}
	return false;
}

/* ---- the grid search ------------------------------------------------------ */

static const char *
prop_id(const struct optim_choice *c)
{
	return c->prop != NULL ? c->prop->id : "";
}

/* Total order: J, bus nearest S*, motor id, propeller id, bus. */
static int
choice_cmp(const struct optim_choice *a, const struct optim_choice *b, int s_star)
{
	if (a->j_score != b->j_score)
		return a->j_score < b->j_score ? -1 : 1;
	int da = abs(a->cells - s_star), db = abs(b->cells - s_star);
	if (da != db)
		return da < db ? -1 : 1;
	int k = strcmp(a->motor->id, b->motor->id);
	if (k != 0)
		return k;
	k = strcmp(prop_id(a), prop_id(b));
	if (k != 0)
		return k;
	return a->cells - b->cells;
}

/* Keep the best max choices, sorted. */
static void
keep_choice(struct optim_choice *v, int *n, int max, const struct optim_choice *c,
            int s_star)
{
	int pos = *n;
	while (pos > 0 && choice_cmp(c, &v[pos - 1], s_star) < 0)
		pos--;
	if (pos >= max)
		return;
	int last = *n < max ? *n : max - 1;
	for (int k = last; k > pos; k--)
		v[k] = v[k - 1];
	v[pos] = *c;
	if (*n < max)
		(*n)++;
}

/* What one bus offers to every motor on it. */
struct bus_offer {
	int cells;
	bool have_battery;
	struct optim_choice battery;   /* battery fields only */
};

/* A usable propeller and what the search needs of it, for one target. */
struct rank_prop {
	const struct catalog_prop *p;
	bool locked;                   /* the mission locks this propeller */
	bool lock_ok;                  /* no propeller lock, or this one */
	bool over;                     /* above the overlap limit */
	struct prop_aim aim;
	double j_diameter, j_pitch;    /* its J terms */
	bool pitched;                  /* pitch known: j_mass_term()'s index */
	double max_rpm;                /* p->max_rpm, 0 unknown */
};

/* What one motor on one bus brings to each of its options. */
struct motor_on_bus {
	double rpm;                    /* full_rpm() */
	double j_kv;                   /* its J terms */
	double j_mass[2];              /* [pitched]: see j_mass_term() */
};

/* Where a motor's recommended propeller range starts and ends in the
 * diameter-sorted propellers within the overlap limit (range_cut()). */
struct prop_span {
	bool done;
	size_t first, end;
};

/* An ESC set that suits the bus being ranked, the motor's burst aside. */
struct esc_offer {
	const struct catalog_esc *e;
	double kg;                     /* boards × board mass */
};

/* Shared state of one ranking. */
struct rank_ctx {
	const struct optim_target *t;
	const struct catalog *cat;
	const struct optim_locks *lk;
	struct optim_census *cs;
	struct optim_choice *choices;
	int max_choices, n_kept, n_found;
	struct res_candidate *cand;    /* NULL: not recorded */
	int slot;                      /* this motor's candidate, -1 none */
	const struct rank_prop *const *props; /* the usable propellers, in file order */
	size_t n_props;
	int n_lock_ok;                 /* of them, those a propeller lock admits */
	const struct rank_prop *const *fit; /* those within the overlap limit or
	                                  locked; by diameter when no propeller
	                                  is locked */
	size_t n_fit;
	int n_over;                    /* admitted, free and above the limit */
	const struct esc_offer *escs;  /* with no ESC locked: the sets that
	                                  suit this bus, lightest first */
	size_t n_escs;
	struct prop_span *spans;       /* per usable motor, in catalogue order */
	struct prop_span *span;        /* the motor being ranked */
	double j_cruise;               /* the J term common to every option */
};

/* The ESC set of one motor on one bus, picked when an option first needs
 * it (most motors fail a limit on every propeller and never do). */
struct esc_pick {
	bool done;
	const struct catalog_esc *esc;
	int n_esc;
};

/* pick_esc() for motor m on the bus being ranked.  The ESC must suit the
 * motor's own limits even when the motor is free, so it is picked per
 * motor; with no ESC locked, the first of the bus's sets (lightest, then
 * by id: pick_esc's order) that carries the motor's burst. */
static void
rank_pick_esc(struct rank_ctx *x, int cells, const struct catalog_motor *m,
              struct esc_pick *ep)
{
	ep->done = true;
	if (x->lk->esc != NULL) {
		pick_esc(x->t, x->cat, x->lk->esc, cells, m, &ep->esc, &ep->n_esc);
		return;
	}
	ep->esc = NULL;
	ep->n_esc = 0;
	for (size_t i = 0; i < x->n_escs; i++) {
		if (esc_carries_burst(m, x->escs[i].e)) {
			ep->esc = x->escs[i].e;
			ep->n_esc = esc_boards(x->t, ep->esc);
			return;
		}
	}
}

/* Count an option in the census; true if it failed `why` (not OPTIM_OK). */
static bool
option_fails(struct rank_ctx *x, bool eligible, enum optim_reason why)
{
	if (eligible)
		x->cs->n_examined++;
	if (why == OPTIM_OK)
		return false;
	if (eligible)
		x->cs->n_fail[why]++;
	return true;
}

/* Keep a complete option of J score j among the best choices, if it ranks
 * there; ep is its ESC set (NULL: an integrated system). */
static inline void
keep_option(struct rank_ctx *x, const struct bus_offer *bus,
            const struct catalog_motor *m, const struct catalog_prop *p,
            const struct esc_pick *ep, double j, double theta)
{
	/* A J above the last one kept cannot be kept (keep_choice() would
	 * compare it there and stop). */
	if (x->n_kept >= x->max_choices
	    && (x->max_choices <= 0 || j > x->choices[x->max_choices - 1].j_score))
		return;
	struct optim_choice c = bus->battery;
	c.cells = bus->cells;
	c.motor = m;
	c.prop = p;
	c.esc = ep != NULL ? ep->esc : NULL;
	c.n_esc = ep != NULL ? ep->n_esc : 0;
	c.j_score = j;
	c.hover_throttle = theta;
	keep_choice(x->choices, &x->n_kept, x->max_choices, &c, x->t->cells);
}

/* One motor + propeller option on one bus that passed every limit the
 * locks leave (and was counted by option_fails): score it, keep it.  rc is
 * the motor's candidate, NULL when none is recorded.  Inline: it is the
 * search's inner loop, and most options stop after the score. */
static inline __attribute__((always_inline)) void
rank_option(struct rank_ctx *x, const struct bus_offer *bus,
            const struct catalog_motor *m, const struct motor_on_bus *mb,
            struct res_candidate *rc, const struct catalog_prop *p,
            double j_diameter, double j_pitch, double theta, bool eligible,
            struct esc_pick *ep)
{
	const struct optim_target *t = x->t;
	/* j_score_at()'s sum, from the terms computed once each. */
	bool pitched = p != NULL && p->pitch_in > 0.0;
	double j = j_sum(j_diameter, mb->j_kv, j_pitch, j_throttle_term(t, theta),
	    mb->j_mass[pitched], x->j_cruise);
	if (rc != NULL && j < rc->j_score)
		rc->j_score = j;
	if (!m->integrated && !ep->done)
		rank_pick_esc(x, bus->cells, m, ep);
	if (!m->integrated && ep->esc == NULL) {
		if (eligible)
			x->cs->n_fail[OPTIM_NO_ESC]++;
		return;
	}
	if (!bus->have_battery) {
		if (eligible)
			x->cs->n_fail[OPTIM_NO_BATTERY]++;
		return;
	}
	if (rc != NULL)
		rc->feasible = true;
	if (!eligible)
		return;
	x->cs->n_feasible++;
	x->n_found++;
	keep_option(x, bus, m, p, m->integrated ? NULL : ep, j, theta);
}

static bool
is_lock(const char *lock, const char *id)
{
	return lock != NULL && strcmp(lock, id) == 0;
}

/* The motor limits come first in enum order, so a motor that breaks one
 * fails on it whatever the propeller (rank_motor relies on it); then the
 * overlap limit and the recommended range. */
_Static_assert(OPTIM_MOTOR_CELLS == 1 && OPTIM_MOTOR_CURRENT == 2
    && OPTIM_MOTOR_POWER == 3 && OPTIM_PROP_OVERLAP == 4
    && OPTIM_PROP_RANGE == 5,
    "motor limits, the overlap limit, then the range must be the first reasons");

/* In v[0..n) sorted by diameter, how many lead where below(m, d) holds
 * (it holds on a prefix); with below false, how many do not trail where
 * above(m, d) holds (it holds on a suffix). */
static size_t
range_cut(const struct catalog_motor *m, const struct rank_prop *const *v,
          size_t n, bool below)
{
	size_t lo = 0, hi = n;
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;
		double d = v[mid]->aim.d_in;
		if (below ? below_range(m, d) : !above_range(m, d))
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

/* In v[0..n) sorted by diameter, how many lead within the tip Mach limit
 * at full rpm (pair_mask()'s test; it fails on a suffix, the tip speed
 * growing with the diameter). */
static size_t
mach_cut(const struct optim_target *t, const struct rank_prop *const *v,
         size_t n, double rpm)
{
	size_t lo = 0, hi = n;
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;
		if (tip_mach(t, &v[mid]->aim, rpm) <= AERO_TIP_MACH_MAX)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

static void
motor_on_bus_of(const struct optim_target *t, int cells,
                const struct catalog_motor *m, struct motor_on_bus *mb)
{
	mb->rpm = full_rpm(t, cells, m->kv_rpm_per_v);
	mb->j_kv = j_kv_term(t, cells, m->kv_rpm_per_v);
	mb->j_mass[0] = j_mass_term(t, false, m->mass_kg);
	mb->j_mass[1] = j_mass_term(t, true, m->mass_kg);
}

/* Every option of one motor on one bus, whose own limits give `own`
 * (motor_mask()); motor_locked when the mission locks it.  An option that
 * is not eligible (another part is locked) is never counted; it only
 * matters when it passes and a candidate records it, so it is skipped when
 * there is none.  A free motor with its own propellers (not an integrated
 * system) that breaks one of its own limits never comes here:
 * rank_catalog() counts its options at once. */
static void
rank_motor(struct rank_ctx *x, const struct bus_offer *bus,
           const struct catalog_motor *m, unsigned own, bool motor_locked)
{
	const struct optim_target *t = x->t;
	const struct optim_locks *lk = x->lk;
	bool motor_ok = lk->motor == NULL || motor_locked;
	bool has_cand = x->cand != NULL && x->slot >= 0;
	struct res_candidate *rc = has_cand ? &x->cand[x->slot] : NULL;
	struct motor_on_bus mb;
	double theta;
	if (!m->integrated) {
		motor_on_bus_of(t, bus->cells, m, &mb);
		/* A free propeller above the overlap limit fails there on a
		 * motor that passes its own limits (the next reason in enum
		 * order): those options too are counted at once. */
		const struct rank_prop *const *v = x->props;
		size_t n = x->n_props;
		if (!motor_locked) {
			if (motor_ok) {
				x->cs->n_examined += x->n_over;
				x->cs->n_fail[OPTIM_PROP_OVERLAP] += x->n_over;
			}
			v = x->fit;
			n = x->n_fit;
		}
		if (!motor_locked && lk->prop == NULL) {
			/* With no propeller locked, those left are free, all
			 * admitted and sorted by diameter: the ones outside the
			 * motor's range (the next reason) lead and trail, and
			 * are counted at once.  The census, the candidates and
			 * the kept choices do not depend on the order. */
			struct prop_span *span = x->span;
			if (!span->done) {
				span->first = range_cut(m, v, n, true);
				span->end = range_cut(m, v, n, false);
				if (span->end < span->first)
					span->end = span->first; /* min > max: all fail */
				span->done = true;
			}
			size_t first = span->first, end = span->end;
			if (motor_ok) {
				int out = (int)(n - (end - first));
				x->cs->n_examined += out;
				x->cs->n_fail[OPTIM_PROP_RANGE] += out;
			}
			v += first;
			n = end - first;
			/* The tip Mach number grows with the diameter, so the
			 * ones above its limit (the next reason) trail. */
			size_t fast = mach_cut(t, v, n, mb.rpm);
			if (motor_ok) {
				int out = (int)(n - fast);
				x->cs->n_examined += out;
				x->cs->n_fail[OPTIM_TIP_MACH] += out;
			}
			n = fast;
			if (!motor_ok && !has_cand)
				return;
			/* What is left can fail only the propeller's rpm limit or
			 * hover (pair_mask()'s last two reasons, in its order).
			 * The rest is rank_option() with what does not depend on
			 * the propeller done once: the ESC set (picked when the
			 * first option passes: it depends on the motor and the bus
			 * only), the bus's battery, the candidate's best J and the
			 * census counts. */
			struct esc_pick ep = { false, NULL, 0 };
			double n_max_rps = mb.rpm / S_PER_MIN;
			double best_j = rc != NULL ? rc->j_score : 0.0;
			int n_rpm = 0, n_hover = 0, n_pass = 0;
			bool keeps = false;    /* ESC, battery and no lock elsewhere */
			for (size_t j = 0; j < n; j++) {
				const struct rank_prop *rp = v[j];
				if (rp->max_rpm > 0.0 && mb.rpm > rp->max_rpm) {
					n_rpm++;
					continue;
				}
				theta = hover_theta(rp->aim.n_hover_rps, n_max_rps);
				if (!(theta < 1.0)) {
					n_hover++;
					continue;
				}
				/* j_score_at()'s sum, from the terms computed once each. */
				double jj = j_sum(rp->j_diameter, mb.j_kv, rp->j_pitch,
				    j_throttle_term(t, theta), mb.j_mass[rp->pitched],
				    x->j_cruise);
				if (jj < best_j)
					best_j = jj;
				if (n_pass++ == 0) {
					rank_pick_esc(x, bus->cells, m, &ep);
					keeps = ep.esc != NULL && bus->have_battery && motor_ok;
				}
				if (keeps)
					keep_option(x, bus, m, rp->p, &ep, jj, theta);
			}
			if (rc != NULL)
				rc->j_score = best_j;
			enum optim_reason why = ep.esc == NULL ? OPTIM_NO_ESC
			    : !bus->have_battery ? OPTIM_NO_BATTERY : OPTIM_OK;
			if (n_pass > 0 && why == OPTIM_OK && rc != NULL)
				rc->feasible = true;
			if (motor_ok) {
				x->cs->n_examined += (int)n;
				x->cs->n_fail[OPTIM_PROP_RPM] += n_rpm;
				x->cs->n_fail[OPTIM_CANNOT_HOVER] += n_hover;
				if (why != OPTIM_OK)
					x->cs->n_fail[why] += n_pass;
				else {
					x->cs->n_feasible += n_pass;
					x->n_found += n_pass;
				}
			}
			return;
		}
		struct esc_pick ep = { false, NULL, 0 };
		for (size_t j = 0; j < n; j++) {
			const struct rank_prop *rp = v[j];
			bool eligible = motor_ok && rp->lock_ok;
			if (!eligible && !has_cand)
				continue;
			unsigned ignored = eligible ? locked_mask(motor_locked, rp->locked) : 0;
			unsigned mask = own | pair_mask(t, m, rp->p, &rp->aim, mb.rpm, &theta);
			if (!option_fails(x, eligible, first_reason(mask & ~ignored)))
				rank_option(x, bus, m, &mb, rc, rp->p, rp->j_diameter,
				    rp->j_pitch, theta, eligible, &ep);
		}
	} else {
		/* An integrated system brings its own propeller and ESC: a
		 * propeller or ESC lock rules it out. */
		bool eligible = motor_ok && lk->prop == NULL && lk->esc == NULL;
		if (!eligible && !has_cand)
			return;
		motor_on_bus_of(t, bus->cells, m, &mb);
		struct prop_aim a;
		prop_aim_of(t, m, NULL, &a);
		unsigned ignored = eligible ? locked_mask(motor_locked, motor_locked) : 0;
		unsigned mask = own | pair_mask(t, m, NULL, &a, mb.rpm, &theta);
		if (!option_fails(x, eligible, first_reason(mask & ~ignored)))
			rank_option(x, bus, m, &mb, rc, NULL, j_diameter_term(t, a.d_in),
			    0.0, theta, eligible, NULL);
	}
}

/* qsort order of ESC sets: pick_esc's, lightest, then by id. */
static int
esc_offer_cmp(const void *a, const void *b)
{
	const struct esc_offer *x = a, *y = b;
	if (x->kg != y->kg)
		return x->kg < y->kg ? -1 : 1;
	return strcmp(x->e->id, y->e->id);
}

/* The usable ESC sets in pick_esc's order (lightest, then by id; a set's
 * mass depends on the rotor count alone, not on the bus or the aim), built
 * once for a search's rankings; empty when an ESC is locked. */
struct esc_list {
	struct esc_offer *v;
	size_t n;
};

static void
esc_list_init(const struct optim_target *t, const struct catalog *cat,
              const char *lock, struct esc_list *el)
{
	size_t ne = catalog_n_escs(cat);
	el->v = xmalloc((ne > 0 ? ne : 1) * sizeof *el->v);
	el->n = 0;
	for (size_t i = 0; i < ne && lock == NULL; i++) {
		const struct catalog_esc *e = catalog_esc(cat, i);
		if (!e->usable)
			continue;
		el->v[el->n].e = e;
		el->v[el->n].kg = (double)esc_boards(t, e) * e->mass_kg;
		el->n++;
	}
	qsort(el->v, el->n, sizeof *el->v, esc_offer_cmp);
}

static void
esc_list_free(struct esc_list *el)
{
	free(el->v);
}

/* optim_rank() with the packs every bus picks from (those of the locks'
 * battery lock) and the ESC sets given: a search ranks with the one list
 * it also upsizes batteries from. */
static int
rank_catalog(const struct optim_target *t, const struct catalog *cat,
             const struct optim_locks *locks, const struct pack_list *packs,
             const struct esc_list *el, struct optim_choice *choices, int max_choices,
             struct optim_census *census, struct res_candidate *cand, int *n_cand)
{
	struct optim_census local;
	struct optim_locks none = { NULL, NULL, NULL, NULL };
	struct rank_ctx x;
	memset(&x, 0, sizeof x);
	x.t = t;
	x.cat = cat;
	x.lk = locks != NULL ? locks : &none;
	x.cs = census != NULL ? census : &local;
	memset(x.cs, 0, sizeof *x.cs);
	x.choices = choices;
	x.max_choices = max_choices;
	x.cand = cand;
	x.j_cruise = j_cruise_term(t);

	/* The usable motors, in catalogue order, looked up once for every
	 * bus; which one a lock names; and each one's candidate slot. */
	size_t nm = catalog_n_motors(cat);
	const struct catalog_motor **motors = xmalloc((nm > 0 ? nm : 1)
	    * sizeof *motors);
	size_t n_usable = 0, locked_at = nm;
	for (size_t i = 0; i < nm; i++) {
		const struct catalog_motor *m = catalog_motor(cat, i);
		if (!m->usable)
			continue;
		if (is_lock(x.lk->motor, m->id))
			locked_at = n_usable;
		motors[n_usable++] = m;
	}
	int *slot = xmalloc((n_usable > 0 ? n_usable : 1) * sizeof *slot);
	int n = 0;
	for (size_t u = 0; u < n_usable; u++) {
		const struct catalog_motor *m = motors[u];
		slot[u] = -1;
		if (cand == NULL || n >= RES_MAX_CANDIDATES)
			continue;
		slot[u] = n;
		struct res_candidate *c = &cand[n++];
		memset(c, 0, sizeof *c);
		str_copy(c->id, sizeof c->id, m->id);
		c->kv = m->kv_rpm_per_v;
		c->mass_kg = m->mass_kg;
		c->j_score = OPTIM_PRUNED;
		c->feasible = false;
	}
	if (n_cand != NULL)
		*n_cand = n;

	/* What each propeller brings is the same on every motor and bus. */
	size_t np = catalog_n_props(cat);
	struct rank_prop *props = xmalloc((np > 0 ? np : 1) * sizeof *props);
	const struct rank_prop **all = xmalloc((np > 0 ? np : 1) * sizeof *all);
	const struct rank_prop **fit = xmalloc((np > 0 ? np : 1) * sizeof *fit);
	for (size_t j = 0; j < np; j++) {
		const struct catalog_prop *p = catalog_prop(cat, j);
		if (!p->usable)
			continue;
		struct rank_prop *rp = &props[j];
		rp->p = p;
		rp->locked = is_lock(x.lk->prop, p->id);
		rp->lock_ok = x.lk->prop == NULL || rp->locked;
		prop_aim_of(t, NULL, p, &rp->aim);
		rp->over = over_overlap(t, rp->aim.d_in);
		rp->j_diameter = j_diameter_term(t, rp->aim.d_in);
		rp->j_pitch = j_pitch_term(t, p->pitch_in);
		rp->pitched = p->pitch_in > 0.0;
		rp->max_rpm = p->max_rpm;
		x.n_lock_ok += rp->lock_ok;
		all[x.n_props++] = rp;
		if (x.lk->prop != NULL && (!rp->over || rp->locked))
			fit[x.n_fit++] = rp;
		else if (rp->over && rp->lock_ok)
			x.n_over++;
	}
	if (x.lk->prop == NULL) {
		/* Free propellers: those within the limit by diameter. */
		const size_t *by_d = catalog_props_by_diameter(cat);
		for (size_t k = 0; k < np; k++) {
			const struct rank_prop *rp = &props[by_d[k]];
			if (catalog_prop(cat, by_d[k])->usable && !rp->over)
				fit[x.n_fit++] = rp;
		}
	}
	x.props = all;
	x.fit = fit;
	/* The search's ESC sets, filtered for each bus below. */
	const struct esc_offer *all_escs = el->v;
	size_t n_all_escs = el->n;
	struct esc_offer *escs = xmalloc((n_all_escs > 0 ? n_all_escs : 1)
	    * sizeof *escs);
	x.escs = escs;
	/* Each motor's recommended propeller range, cut once (it does not
	 * depend on the bus). */
	x.spans = xmalloc((n_usable > 0 ? n_usable : 1) * sizeof *x.spans);
	for (size_t u = 0; u < n_usable; u++)
		x.spans[u].done = false;
	bool count_free = x.lk->motor == NULL; /* a free motor's options count */

	for (int s = t->cells_lo; s <= t->cells_hi; s++) {
		struct bus_offer bus;
		memset(&bus, 0, sizeof bus);
		bus.cells = s;
		bus.have_battery = pick_battery(t, packs, s, at_bus(t, t->capacity_ah, s),
		    at_bus(t, t->bus_peak_current_a, s), NULL, &bus.battery);
		x.n_escs = 0;
		for (size_t i = 0; i < n_all_escs; i++)
			if (esc_fits_bus(t, s, all_escs[i].e))
				escs[x.n_escs++] = all_escs[i];
		double current_a = target_current_a(t, s);
		for (size_t u = 0; u < n_usable; u++) {
			const struct catalog_motor *m = motors[u];
			unsigned own = motor_mask_at(t, s, current_a, m);
			bool locked = u == locked_at;
			if (own != 0 && !m->integrated && !locked) {
				/* A free motor's own limits are never ignored: each
				 * of its options fails on the first of them and
				 * touches nothing but the census, so they are
				 * counted at once (most motors stop here). */
				if (count_free) {
					x.cs->n_examined += x.n_lock_ok;
					x.cs->n_fail[first_reason(own)] += x.n_lock_ok;
				}
				continue;
			}
			x.slot = slot[u];
			x.span = &x.spans[u];
			rank_motor(&x, &bus, m, own, locked);
		}
	}
	free(motors);
	free(x.spans);
	free(escs);
	free(fit);
	free(all);
	free(props);
	free(slot);
	return x.n_found;
}

int
optim_rank(const struct optim_target *t, const struct catalog *cat,
           const struct optim_locks *locks, struct optim_choice *choices,
           int max_choices, struct optim_census *census,
           struct res_candidate *cand, int *n_cand)
{
	struct pack_list packs;
	pack_list_init(cat, locks != NULL ? locks->battery : NULL, &packs);
	struct esc_list escs;
	esc_list_init(t, cat, locks != NULL ? locks->esc : NULL, &escs);
	int n = rank_catalog(t, cat, locks, &packs, &escs, choices, max_choices,
	    census, cand, n_cand);
	esc_list_free(&escs);
	pack_list_free(&packs);
	return n;
}

/* ---- closing the loop on real parts --------------------------------------- */

/* The continuous optimum of the custom run as the search's aim point. */
static void
make_target(const struct sizing_params *p, const struct res_run *o,
            struct optim_target *t)
{
	memset(t, 0, sizeof *t);
	t->prop_diameter_in = o->opt.prop_diameter_in;
	t->prop_pitch_in = o->opt.prop_pitch_in;
	t->motor_kv = o->opt.motor_kv;
	t->cells = o->cell_count > 0 ? o->cell_count : 1;
	t->motor_peak_current_a = o->opt.motor_peak_current_a;
	t->motor_peak_power_w = o->opt.motor_peak_power_w;
	t->bus_peak_current_a = o->peak_current_a;
	t->capacity_ah = mah_to_ah(o->capacity_mah);
	t->mass_kg = o->mass.total_kg;
	t->motor_mass_kg = o->opt.motor_mass_kg;
	t->drive_mass_kg = (o->mass.motor_kg + o->mass.prop_kg + o->mass.esc_kg)
	    / (double)p->n_rotors;
	t->n_rotors = p->n_rotors;
	t->hover_throttle = o->hover_throttle;
	t->forward_pitch_deg = p->duration_s[PHASE_FORWARD] > 0.0 ? o->forward_pitch_deg : 0.0;
	t->overlap_limit_in = o->overlap_limit_in;
	t->wheelbase_m = p->wheelbase_m;
	t->ct = p->ct;
	t->rho_kg_m3 = p->air.rho_kg_m3;
	t->sound_m_s = p->air.sound_m_s;
	t->v_cell_nom_v = p->chem->v_nom;
	str_copy(t->chemistry, sizeof t->chemistry, p->chem->name);
	/* The bus is the mission's when it fixes it (cells, KV or battery
	 * locked); else any count from S* up to the class maximum. */
	bool fixed = p->cells_fixed > 0 || p->kv_locked || p->capacity_locked;
	t->cells_lo = t->cells;
	t->cells_hi = fixed || p->cells_hi < t->cells ? t->cells : p->cells_hi;
	t->cells_floor = fixed || p->cells_lo > t->cells || p->cells_lo < 1
	    ? t->cells : p->cells_lo;
}

/* The custom-run parameters with the real parts in. */
static void
apply_parts(struct sizing_params *p, const struct model_data *md,
            const struct optim_target *t, const struct res_run *custom,
            const struct optim_choice *c)
{
	const struct catalog_motor *m = c->motor;
	const struct catalog_battery *b = c->battery;
	double d_in, pitch_in;
	p->parts.active = true;
	p->parts.motor_kg_each = m->mass_kg;
	if (m->integrated) {
		p->parts.prop_kg_each = INTEGRATED_PART_KG;
		p->parts.esc_kg_total = INTEGRATED_PART_KG;
		d_in = m->integrated_prop_in;
		pitch_in = t->prop_pitch_in; /* not published: the continuous pitch */
	} else {
		p->parts.prop_kg_each = c->prop->mass_kg;
		p->parts.esc_kg_total = (double)c->n_esc * c->esc->mass_kg;
		d_in = c->prop->diameter_in;
		pitch_in = c->prop->pitch_in;
		if (c->prop->blades > 0)
			p->n_blades = c->prop->blades;
	}
	p->parts.battery_kg = (double)(c->series_packs * c->parallel_packs) * b->mass_kg;
	p->parts.capacity_ah = (double)c->parallel_packs * b->capacity_ah;
	p->parts.cells = c->cells;
	p->parts.motor_kv = m->kv_rpm_per_v;
	p->parts.motor_resistance_ohm = m->resistance_ohm;
	p->prop_locked = true;
	p->prop_diameter_m = in_to_m(d_in);
	p->prop_pitch_m = in_to_m(pitch_in);
	p->kv_locked = true;
	p->kv = m->kv_rpm_per_v;
	p->cells_fixed = c->cells;
	p->pack_count = c->parallel_packs;
	/* Another chemistry family than the mission's: its own profile. */
	if (strcmp(chem_family(b->chemistry), chem_family(p->chem->name)) != 0) {
		const struct batt_chem *bc = model_chem(md, b->chemistry);
		if (bc != NULL)
			p->chem = bc;
	}
	/* The same mission as the continuous design flew, relaxation included:
	 * real parts never relax it further. */
	if (custom->time_scale > 0.0 && custom->time_scale < 1.0)
		for (int i = 0; i < PHASE_MAX; i++)
			p->duration_s[i] *= custom->time_scale;
	if (custom->thrust_margin > 0.0)
		p->thrust_margin = custom->thrust_margin;
	p->thrust_margin_floor = 0.0;
	p->allow_relax = false;
}

/* One row of the closed run's checks table (when there is room: the verdict
 * never depends on it).  Returns whether the value passes; a failure's name
 * goes to *first unless one is there already. */
static bool
parts_check(struct res_run *run, const char *name, const char *unit,
            double value, double limit, bool upper,
            const char **first)
{
	double scale = fabs(limit) > 1e-12 ? fabs(limit) : 1.0;
	double tol = CHECK_RELTOL * scale;
	bool pass = isfinite(value) && isfinite(limit)
	    && (upper ? value <= limit + tol : value >= limit - tol);
	if (!pass) {
		run->feasible = false;
		if (*first == NULL)
			*first = name;
	}
	if (run->n_checks >= RES_MAX_CHECKS)
		return pass;
	struct res_check *c = &run->checks[run->n_checks++];
	memset(c, 0, sizeof *c);
	c->name = name;
	c->unit = unit;
	c->value = isfinite(value) ? value : 0.0;
	c->limit = isfinite(limit) ? limit : 0.0;
	c->upper = upper;
	c->margin = upper ? (c->limit - c->value) / scale : (c->value - c->limit) / scale;
	c->pass = pass;
	return pass;
}

/* Closing context shared by every try. */
struct closer {
	const struct sizing_params *p0;  /* custom-run parameters */
	const struct model_data *md;
	const struct optim_target *t;
	const struct catalog *cat;
	const struct optim_locks *lk;
	const struct res_run *custom;
	const struct pack_list *packs;   /* what an upsized battery is picked from */
};

/* Full-throttle rotor speed of the real motor on the closed bus, rev/s. */
static double
closed_full_rps(const struct sizing_params *p, const struct optim_choice *c)
{
	return c->motor->kv_rpm_per_v * (double)c->cells * p->chem->v_nom
	    * OPTIM_LOAD_RPM / S_PER_MIN;
}

/* The limits only real parts have: rows of the closed run's checks table
 * and stage "parts" violations.  Returns the name of the first that fails,
 * or NULL. */
static const char *
parts_checks(const struct closer *k, const struct sizing_params *p,
             const struct optim_choice *c, struct res_run *o,
             struct solve_result *r)
{
	const struct res_run *custom = k->custom;
	const struct catalog_motor *m = c->motor;
	double d_m = p->prop_diameter_m;
	double n_max = closed_full_rps(p, c);
	double t_max_n = p->ct * p->air.rho_kg_m3 * n_max * n_max * pow(d_m, 4.0);
	double tw = (double)p->n_rotors * t_max_n / (o->mass.total_kg * G0_M_S2);
	char f1[RES_TEXT], f2[RES_TEXT], f3[RES_TEXT];
	const char *fx[4] = { f1, f2, f3, NULL };

	const char *first = NULL;
	bool text = !r->terse; /* a trial closing keeps the codes only */
	if (!parts_check(o, "Thrust-to-weight of the real motor and propeller", "",
	    tw, custom->thrust_to_weight, false, &first)) {
		/* Thrust goes with rpm², rpm with KV: the KV that would do. */
		if (text) {
			snprintf(f1, sizeof f1, "Add a motor of about %.0f KV for %dS to the catalogue (or use --db)",
			    tw > 0.0 ? m->kv_rpm_per_v * sqrt(custom->thrust_to_weight / tw) : 0.0,
			    c->cells);
			snprintf(f2, sizeof f2, "Lock a higher-KV motor with locks.motor_part");
			snprintf(f3, sizeof f3, "Lower the thrust margin (payload_role.thrust_margin_override)");
		}
		feasibility_violation(r, "closed", "parts", "PARTS_THRUST", fx,
		    "%s %s on %.1f in propellers at %dS reaches T/W %.2f at full "
		    "throttle; the role needs %.2f.", m->manufacturer, m->part_number,
		    m_to_in(d_m), c->cells, tw, custom->thrust_to_weight);
	}
	double i_m = closed_current_a(o);
	if (!parts_check(o, "Motor current at full throttle (× 1.1)", "A", i_m,
	    m->max_current_a, true, &first)) {
		if (text) {
			snprintf(f1, sizeof f1, "No catalogue motor carries %.0f A at %dS: add one to data/catalog/motors.json or use --db",
			    i_m, c->cells);
			snprintf(f2, sizeof f2, "Raise the bus voltage (nominal_cell_count) to lower the current");
		}
		fx[2] = NULL;
		feasibility_violation(r, "closed", "parts", "MOTOR_CURRENT", fx,
		    "%s %s is rated for %.0f A; the closed design draws %.0f A per "
		    "motor at full throttle (with 10 %% margin).", m->manufacturer,
		    m->part_number, m->max_current_a, i_m);
		fx[2] = f3;
	}
	if (m->max_power_w > 0.0) {
		if (!parts_check(o, "Motor power at full throttle", "W",
		    o->opt.motor_peak_power_w, m->max_power_w, true, &first)) {
			if (text) {
				snprintf(f1, sizeof f1, "No catalogue motor is rated for %.0f W: add one to data/catalog/motors.json or use --db",
				    o->opt.motor_peak_power_w);
				snprintf(f2, sizeof f2, "Lower the thrust margin or the payload");
			}
			fx[2] = NULL;
			feasibility_violation(r, "closed", "parts", "MOTOR_POWER", fx,
			    "%s %s is rated for %.0f W; the closed design needs %.0f W "
			    "per motor at full throttle.", m->manufacturer, m->part_number,
			    m->max_power_w, o->opt.motor_peak_power_w);
			fx[2] = f3;
		}
	}
	if (c->esc != NULL) {
		if (!parts_check(o, "ESC current at full throttle (× 1.1)", "A", i_m,
		    c->esc->continuous_current_a, true, &first)) {
			if (text) {
				snprintf(f1, sizeof f1, "No catalogue ESC carries %.0f A at %dS: add one to data/catalog/escs.json or use --db",
				    i_m, c->cells);
				snprintf(f2, sizeof f2, "Remove locks.esc_part to let the optimizer choose");
			}
			fx[2] = NULL;
			feasibility_violation(r, "closed", "parts", "ESC_CURRENT", fx,
			    "%s %s carries %.0f A continuous; the closed design needs "
			    "%.0f A per motor.", c->esc->manufacturer, c->esc->part_number,
			    c->esc->continuous_current_a, i_m);
			fx[2] = f3;
		}
	}
	const struct catalog_battery *b = c->battery;
	double i_max = (double)c->parallel_packs * b->capacity_ah * b->continuous_c;
	if (!parts_check(o, "Battery current within the continuous C rating", "A",
	    o->peak_current_a, i_max, true, &first)) {
		if (text) {
			snprintf(f1, sizeof f1, "Add packs in parallel or a higher-C pack to data/catalog/batteries.json");
			snprintf(f2, sizeof f2, "Remove locks.battery_part to let the optimizer choose");
		}
		fx[2] = NULL;
		feasibility_violation(r, "closed", "parts", "BATTERY_C_RATE", fx,
		    "%d × %s %s deliver %.0f A continuous (%.0fC); full throttle draws "
		    "%.0f A.", c->series_packs * c->parallel_packs, b->manufacturer,
		    b->part_number, i_max, b->continuous_c, o->peak_current_a);
		fx[2] = f3;
	}
	double mach = M_PI * d_m * n_max / p->air.sound_m_s;
	if (!parts_check(o, "Tip Mach at the real motor's full rpm", "", mach,
	    AERO_TIP_MACH_MAX, true, &first)) {
		if (text) {
			snprintf(f1, sizeof f1, "Use a lower-KV motor or a smaller propeller");
			snprintf(f2, sizeof f2, "Remove the motor or propeller lock");
		}
		fx[2] = NULL;
		feasibility_violation(r, "closed", "parts", "PARTS_TIP_MACH", fx,
		    "At full rpm (%.0f rpm) the %.1f in propeller tip reaches Mach "
		    "%.2f (limit %.2f).", n_max * S_PER_MIN, m_to_in(d_m), mach,
		    AERO_TIP_MACH_MAX);
	}
	return first;
}

/* Did the battery run short (so a larger one may close)?  Read from the
 * violations' machine codes; *step gets the capacity factor to try. */
static bool
battery_short(const struct solve_result *sr, double *step)
{
	static const char *const codes[] = { "MISSION_NOT_FLOWN", "VOLTAGE_FLOOR",
		"THERMAL_RUNAWAY", "BATTERY_POWER", "BATTERY_C_RATE", NULL };
	const struct res_run *o = &sr->closed;
	double need = 0.0;
	for (int i = 0; i < PHASE_MAX; i++)
		need += o->approved_time_s[i];
	double flown = o->n_trace > 0 ? o->trace[o->n_trace - 1].t_s : 0.0;
	*step = UPSIZE_MIN;
	if (flown < FLOWN_TOL * need)
		*step = flown > 0.0 ? fmin(UPSIZE_MAX, fmax(UPSIZE_MIN, 1.1 * need / flown))
		    : UPSIZE_MAX;
	for (int i = 0; i < sr->n_violations; i++)
		for (int k = 0; codes[k] != NULL; k++)
			if (strcmp(sr->violations[i].code, codes[k]) == 0)
				return true;
	return false;
}

/* Did the continuous design fail the check of this name? */
static bool
custom_failed(const struct res_run *custom, const char *name)
{
	bool old = false;
	for (int k = 0; k < custom->n_checks; k++)
		if (strcmp(custom->checks[k].name, name) == 0)
			old = !custom->checks[k].pass;
	return old;
}

/* A failed check of the closed run that the continuous design passed. */
static const char *
new_failure(const struct res_run *custom, const struct res_run *closed)
{
	for (int i = 0; i < closed->n_checks; i++)
		if (!closed->checks[i].pass
		    && !custom_failed(custom, closed->checks[i].name))
			return closed->checks[i].name;
	return NULL;
}

static int
n_failed(const struct res_run *o)
{
	int n = 0;
	for (int i = 0; i < o->n_checks; i++)
		n += !o->checks[i].pass;
	return n;
}

/* Is every number the closed run stores finite? */
static bool
closed_finite(const struct res_run *o)
{
	const double *d = (const double *)(const void *)&o->mass;
	for (size_t i = 0; i < sizeof o->mass / sizeof(double); i++)
		if (!isfinite(d[i]))
			return false;
	double v[] = { o->capacity_mah, o->energy_wh, o->max_battery_temp_c,
		o->min_terminal_voltage_v, o->peak_power_w, o->peak_current_a,
		o->lipschitz, o->hover_endurance_s };
	for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
		if (!isfinite(v[i]))
			return false;
	return true;
}

/* Swap two result buffers. */
static void
swap_results(struct solve_result **a, struct solve_result **b)
{
	struct solve_result *tmp = *a;
	*a = *b;
	*b = tmp;
}

/* The ESC of choice c runs short of the closed design o's full-throttle
 * current: the lightest set that carries it (and the motor's burst) goes
 * into up->esc.  False when the ESC suffices, is locked or none larger
 * exists. */
static bool
esc_upsized(const struct closer *k, const struct optim_choice *c,
            const struct res_run *o, struct optim_choice *up)
{
	double i_need = closed_current_a(o);
	if (c->esc == NULL || k->lk->esc != NULL
	    || c->esc->continuous_current_a >= i_need)
		return false;
	const struct catalog_esc *e;
	int n;
	if (!pick_esc_for(k->t, k->cat, NULL, c->cells, c->motor, i_need, &e, &n))
		return false;
	up->esc = e;
	up->n_esc = n;
	return true;
}

/* The closed run's checks into sr->closed and its violations into sr, as
 * they stand for loop status st; returns the first failed parts check's
 * name, or NULL. */
static const char *
check_closing(const struct closer *k, const struct sizing_params *p,
              enum sizing_status st, const struct optim_choice *c,
              struct solve_result *sr)
{
	sr->n_violations = 0;
	feasibility_checks(p, st, "closed", &sr->closed, sr);
	return parts_checks(k, p, c, &sr->closed, sr);
}

/* Re-solve the custom mission on choice c into (*srp)->closed (violations
 * into *srp), upsizing the battery while it runs short and the ESC while
 * it carries less than the closed design's current.  Returns the name
 * of the first check the real parts fail that the continuous design
 * passed, or NULL when they close as well as it did.  *finite is false if
 * a number came out non-finite; *stp gets the loop status of the attempt
 * kept.  *sparep is a second buffer: an upsized battery is tried in one
 * while the other keeps the attempt before, so that going back to it needs
 * no second solve (the buffers may swap). */
static const char *
close_choice(const struct closer *k, struct optim_choice *c,
             struct solve_result **srp, struct solve_result **sparep,
             bool *finite, enum sizing_status *stp)
{
	double need_ah = at_bus(k->t, k->t->capacity_ah, c->cells);
	double need_a = at_bus(k->t, k->t->bus_peak_current_a, c->cells);
	struct optim_choice prev = *c;
	int prev_failed = -1;
	bool prev_finite = true;
	enum sizing_status prev_st = SIZING_CONVERGED;
	const char *parts_fail = NULL, *prev_parts_fail = NULL;
	struct solve_result *sr = *srp;
	for (int attempt = 0;; attempt++) {
		struct sizing_params p = *k->p0;
		apply_parts(&p, k->md, k->t, k->custom, c);
		enum sizing_status st = sizing_run(&p, &sr->closed);
		*stp = st;
		/* It flew the continuous design's relaxed mission, if any. */
		if (k->custom->time_scale > 0.0 && k->custom->time_scale < 1.0)
			sr->closed.time_scale = k->custom->time_scale;
		*finite = closed_finite(&sr->closed);
		parts_fail = check_closing(k, &p, st, c, sr);
		int nf = n_failed(&sr->closed);
		if (prev_failed >= 0 && nf >= prev_failed) {
			/* A larger battery or ESC did not help: go back to the last one,
			 * whose solve the spare buffer still holds (solving it
			 * again would give the same). */
			*c = prev;
			swap_results(srp, sparep);
			sr = *srp;
			*finite = prev_finite;
			*stp = prev_st;
			parts_fail = prev_parts_fail;
			break;
		}
		if (!*finite || st == SIZING_RUNAWAY || attempt + 1 >= BATTERY_TRIES)
			break;
		/* A battery or an ESC sized for the continuous design may be
		 * short for the heavier real-parts one: try the next larger. */
		struct optim_choice up = *c;
		bool larger = false;
		double step;
		if (battery_short(sr, &step)) {
			need_ah = fmax(need_ah, sr->closed.capacity_mah / 1000.0) * step;
			need_a = fmax(need_a, sr->closed.peak_current_a) * step;
			/* The larger pack keeps the chemistry (and so the cell
			 * profile) of the one it replaces. */
			struct optim_choice b = *c;
			if (pick_battery(k->t, k->packs, c->cells, need_ah, need_a,
			    chem_family(c->battery->chemistry), &b)
			    && (b.battery != c->battery
			    || b.parallel_packs != c->parallel_packs)) {
				up = b;
				larger = true;
			}
		}
		larger = esc_upsized(k, c, &sr->closed, &up) || larger;
		if (!larger)
			break;
		prev = *c;
		prev_failed = nf;
		prev_finite = *finite;
		prev_st = st;
		prev_parts_fail = parts_fail;
		swap_results(srp, sparep);
		sr = *srp;
		*c = up;
	}
	const char *fail = new_failure(k->custom, &sr->closed);
	return fail != NULL ? fail : parts_fail;
}

/* ---- locks ---------------------------------------------------------------- */

static bool
lock_known(struct solve_result *r, const char *field, const char *id,
           const char *file, bool found, bool usable)
{
	char f1[RES_TEXT], f2[RES_TEXT], f3[RES_TEXT];
	const char *fx[4] = { f1, f2, f3, NULL };
	if (!found) {
		snprintf(f1, sizeof f1, "Check the id against data/catalog/%s (ids are lowercase slugs)", file);
		snprintf(f2, sizeof f2, "Use --db DIR for a catalogue that has it");
		snprintf(f3, sizeof f3, "Remove locks.%s to let the optimizer choose", field);
		feasibility_violation(r, "closed", "parts", "UNKNOWN_PART", fx,
		    "locks.%s names \"%s\", which is not in the parts catalogue.",
		    field, id);
		return false;
	}
	if (!usable) {
		snprintf(f1, sizeof f1, "Fill the missing fields of \"%s\" in data/catalog/%s", id, file);
		snprintf(f2, sizeof f2, "Remove locks.%s to let the optimizer choose", field);
		fx[2] = NULL;
		feasibility_violation(r, "closed", "parts", "UNUSABLE_PART", fx,
		    "locks.%s names \"%s\", whose catalogue entry lacks a value the "
		    "optimizer needs.", field, id);
		return false;
	}
	return true;
}

/* The mission's part locks; false (with violations) if one is unknown. */
static bool
read_locks(const struct spec_locks *sl, const struct catalog *cat,
           struct optim_locks *lk, struct solve_result *r)
{
	lk->motor = sl->motor_part[0] ? sl->motor_part : NULL;
	lk->prop = sl->prop_part[0] ? sl->prop_part : NULL;
	lk->battery = sl->battery_part[0] ? sl->battery_part : NULL;
	lk->esc = sl->esc_part[0] ? sl->esc_part : NULL;
	bool ok = true;
	if (lk->motor != NULL) {
		const struct catalog_motor *m = catalog_find_motor(cat, lk->motor);
		ok &= lock_known(r, "motor_part", lk->motor, "motors.json", m != NULL,
		    m != NULL && m->usable);
	}
	if (lk->prop != NULL) {
		const struct catalog_prop *p = catalog_find_prop(cat, lk->prop);
		ok &= lock_known(r, "prop_part", lk->prop, "propellers.json", p != NULL,
		    p != NULL && p->usable);
	}
	if (lk->battery != NULL) {
		const struct catalog_battery *b = catalog_find_battery(cat, lk->battery);
		ok &= lock_known(r, "battery_part", lk->battery, "batteries.json",
		    b != NULL, b != NULL && b->usable && b->chemistry[0] != '\0');
	}
	if (lk->esc != NULL) {
		const struct catalog_esc *e = catalog_find_esc(cat, lk->esc);
		ok &= lock_known(r, "esc_part", lk->esc, "escs.json", e != NULL,
		    e != NULL && e->usable);
	}
	return ok;
}

/* A locked part kept although it breaks a limit the search prunes by. */
static void
locked_limits(const struct optim_target *t, const struct optim_locks *lk,
              const struct optim_choice *c, struct solve_result *r)
{
	bool ml = is_lock(lk->motor, c->motor->id);
	bool pl = c->motor->integrated ? ml : c->prop != NULL && is_lock(lk->prop, c->prop->id);
	unsigned bad = limit_mask(t, c->cells, c->motor, c->prop) & locked_mask(ml, pl);
	for (int k = 1; k < OPTIM_REASON_MAX; k++) {
		if (!(bad & 1u << k))
			continue;
		const char *fx[] = { "Remove the part lock to let the optimizer choose",
			"Or change the mission so that the locked part fits", NULL };
		feasibility_violation(r, "closed", "parts", "LOCKED_PART_LIMIT", fx,
		    "The locked %s%s%s breaks a limit (%s) on %dS.", c->motor->id,
		    c->prop != NULL ? " + " : "", c->prop != NULL ? c->prop->id : "",
		    optim_reason_text[k], c->cells);
	}
	if (c->esc != NULL && is_lock(lk->esc, c->esc->id) && !esc_fits(t, c->cells, c->motor, c->esc)) {
		const char *fx[] = { "Remove locks.esc_part to let the optimizer choose", NULL };
		feasibility_violation(r, "closed", "parts", "LOCKED_PART_LIMIT", fx,
		    "The locked ESC %s does not carry %.0f A continuous (or the "
		    "motor's %.0f A burst) on %dS, or is not rated for %dS (up to "
		    "%dS%s).", c->esc->id,
		    target_current_a(t, c->cells), c->motor->max_current_a, c->cells,
		    c->cells, esc_max_cells(c->esc),
		    c->esc->cells_max > 0 ? "" : ": no published range, taken as 6S");
	}
}

/* ---- reporting ------------------------------------------------------------ */

/* One fix sentence for an elimination reason. */
static void
reason_fix(const struct optim_target *t, enum optim_reason why, char *out, size_t n)
{
	int s = t->cells_hi;
	double i_m = target_current_a(t, s);
	switch (why) {
	case OPTIM_MOTOR_CURRENT:
		snprintf(out, n, "No catalogue motor carries %.0f A at %dS; add one to "
		    "data/catalog/motors.json or use --db", i_m, s);
		break;
	case OPTIM_MOTOR_POWER:
		snprintf(out, n, "No catalogue motor is rated for %.0f W; add one to "
		    "data/catalog/motors.json or use --db", t->motor_peak_power_w);
		break;
	case OPTIM_MOTOR_CELLS:
		snprintf(out, n, "No fitting catalogue motor runs on %d-%dS; add one to "
		    "data/catalog/motors.json or use --db", t->cells_lo, s);
		break;
	case OPTIM_PROP_OVERLAP:
		snprintf(out, n, "No catalogue propeller near %.1f in fits the %.1f in "
		    "overlap limit; add one to data/catalog/propellers.json",
		    t->prop_diameter_in, t->overlap_limit_in);
		break;
	case OPTIM_PROP_RANGE:
		snprintf(out, n, "The motors that carry the current swing other propellers "
		    "than the catalogue's; add a motor for %.0f in propellers",
		    t->prop_diameter_in);
		break;
	case OPTIM_CANNOT_HOVER:
		snprintf(out, n, "No catalogue motor spins the propellers fast enough to "
		    "hover; add motors of %.0f KV or more at %dS",
		    at_bus(t, t->motor_kv, s) / OPTIM_LOAD_RPM, s);
		break;
	case OPTIM_TIP_MACH:
	case OPTIM_PROP_RPM:
		snprintf(out, n, "Motors fast enough spin the propellers past their limit; "
		    "add lower-KV motors near %.0f KV at %dS", t->motor_kv, t->cells);
		break;
	case OPTIM_NO_ESC:
		snprintf(out, n, "No catalogue ESC carries %.0f A at %dS; add one to "
		    "data/catalog/escs.json or use --db", i_m, s);
		break;
	case OPTIM_NO_BATTERY:
		snprintf(out, n, "No catalogue pack builds %d-%dS with %.0f mAh at %.0f A "
		    "(at most %d in parallel); add one to data/catalog/batteries.json "
		    "or use --db", t->cells_lo, s, t->capacity_ah * 1000.0
		    * (double)t->cells / (double)s, at_bus(t, t->bus_peak_current_a, s),
		    OPTIM_MAX_PARALLEL);
		break;
	case OPTIM_OK:
	case OPTIM_REASON_MAX:
	default:
		snprintf(out, n, "Add parts to the catalogue or use --db");
		break;
	}
}

/* No complete combination: say what eliminated everything, worst first. */
static void
report_none(const struct optim_target *t, const struct optim_census *cs,
            const struct catalog_motor *locked_motor, struct solve_result *r)
{
	char msg[RES_TEXT];
	int order[OPTIM_REASON_MAX], n = 0;
	for (int k = 1; k < OPTIM_REASON_MAX; k++)
		if (cs->n_fail[k] > 0)
			order[n++] = k;
	for (int a = 1; a < n; a++)   /* by count, then enum order */
		for (int b = a; b > 0 && cs->n_fail[order[b]] > cs->n_fail[order[b - 1]]; b--) {
			int tmp = order[b];
			order[b] = order[b - 1];
			order[b - 1] = tmp;
		}
	snprintf(msg, sizeof msg, "No catalogue combination fits");
	if (locked_motor != NULL) {
		/* The search never prunes a locked motor: say what it breaks. */
		unsigned own = limit_mask(t, t->cells_lo, locked_motor, NULL)
		    & locked_mask(true, false);
		if (own != 0)
			append(msg, sizeof msg, "; the locked %s breaks a limit (%s) at %dS",
			    locked_motor->id, optim_reason_text[first_reason(own)],
			    t->cells_lo);
	}
	append(msg, sizeof msg, "; %d options (bus %d-%dS x motor x prop) fail: ",
	    cs->n_examined, t->cells_lo, t->cells_hi);
	for (int k = 0; k < n; k++)
		append(msg, sizeof msg, "%s%s %d", k > 0 ? ", " : "",
		    optim_reason_text[order[k]], cs->n_fail[order[k]]);
	if (n == 0)
		append(msg, sizeof msg, "none is usable");
	append(msg, sizeof msg, ".");
	char f[RES_MAX_FIXES][RES_TEXT];
	const char *fx[RES_MAX_FIXES + 1] = { NULL };
	int nf = 0;
	for (int k = 0; k < n && nf < RES_MAX_FIXES - 1; k++) {
		reason_fix(t, (enum optim_reason)order[k], f[nf], sizeof f[nf]);
		fx[nf] = f[nf];
		nf++;
	}
	snprintf(f[nf], sizeof f[nf], "Or lock a part by id (locks.motor_part) to "
	    "see which of its limits binds");
	fx[nf] = f[nf];
	fx[nf + 1] = NULL;
	feasibility_violation(r, "closed", "parts", "NO_PARTS", fx, "%s", msg);
}

static void
part_common(struct res_part *rp, const char *id, const char *manufacturer,
            const char *part_number, double price_usd)
{
	memset(rp, 0, sizeof *rp);
	rp->chosen = true;
	str_copy(rp->id, sizeof rp->id, id);
	str_copy(rp->manufacturer, sizeof rp->manufacturer, manufacturer);
	str_copy(rp->part_number, sizeof rp->part_number, part_number);
	rp->unit_price_usd = price_usd > 0.0 ? price_usd : 0.0;
}

/* r->motor/prop/battery/esc from the chosen combination. */
static void
fill_parts(const struct optim_target *t, const struct optim_choice *c,
           struct solve_result *r)
{
	const struct catalog_motor *m = c->motor;
	struct res_part *rp = &r->motor;
	part_common(rp, m->id, m->manufacturer, m->part_number, m->price_usd);
	if (m->integrated)
		append(rp->description, sizeof rp->description, "integrated motor + "
		    "ESC + %.0f in propeller, ", m->integrated_prop_in);
	append(rp->description, sizeof rp->description, "%.0f KV, %.0f g, %.0f A max",
	    m->kv_rpm_per_v, m->mass_kg * 1000.0, m->max_current_a);
	if (m->max_power_w > 0.0)
		append(rp->description, sizeof rp->description, ", %.0f W max", m->max_power_w);
	if (m->cells_min > 0 && m->cells_max > 0)
		append(rp->description, sizeof rp->description, ", %d-%dS",
		    m->cells_min, m->cells_max);
	rp->qty = t->n_rotors;
	rp->unit_mass_kg = m->mass_kg;
	rp->j_score = c->j_score;

	memset(&r->prop, 0, sizeof r->prop);
	memset(&r->esc, 0, sizeof r->esc);
	if (c->prop != NULL) {
		const struct catalog_prop *p = c->prop;
		rp = &r->prop;
		part_common(rp, p->id, p->manufacturer, p->part_number, p->price_usd);
		append(rp->description, sizeof rp->description, "%.1f x %.1f in",
		    p->diameter_in, p->pitch_in);
		if (p->blades > 0)
			append(rp->description, sizeof rp->description, ", %d-blade", p->blades);
		if (p->material[0])
			append(rp->description, sizeof rp->description, ", %s", p->material);
		if (p->folding == 1)
			append(rp->description, sizeof rp->description, ", folding");
		rp->qty = t->n_rotors;
		rp->unit_mass_kg = p->mass_kg;
		rp->j_score = c->j_score;
	}
	if (c->esc != NULL) {
		const struct catalog_esc *e = c->esc;
		rp = &r->esc;
		part_common(rp, e->id, e->manufacturer, e->part_number, e->price_usd);
		append(rp->description, sizeof rp->description, "%.0f A continuous",
		    e->continuous_current_a);
		if (e->burst_current_a > 0.0)
			append(rp->description, sizeof rp->description, ", %.0f A burst",
			    e->burst_current_a);
		if (e->channels == 4)
			append(rp->description, sizeof rp->description, ", 4-in-1");
		if (e->cells_max > 0)
			append(rp->description, sizeof rp->description, ", up to %dS", e->cells_max);
		rp->qty = c->n_esc;
		rp->unit_mass_kg = e->mass_kg;
	}
	const struct catalog_battery *b = c->battery;
	rp = &r->battery;
	part_common(rp, b->id, b->manufacturer, b->part_number, b->price_usd);
	append(rp->description, sizeof rp->description, "%s %dS %.0f mAh, %.0fC "
	    "continuous", b->chemistry, b->cells_series, b->capacity_ah * 1000.0,
	    b->continuous_c);
	if (c->series_packs * c->parallel_packs > 1)
		append(rp->description, sizeof rp->description, "; %d in series x %d "
		    "in parallel for %dS %.0f mAh", c->series_packs, c->parallel_packs,
		    c->cells, b->capacity_ah * 1000.0 * (double)c->parallel_packs);
	rp->qty = c->series_packs * c->parallel_packs;
	rp->unit_mass_kg = b->mass_kg;
	r->battery_series_packs = c->series_packs;
	r->battery_parallel_packs = c->parallel_packs;
}

static void
bom_add(struct solve_result *r, int qty, const char *category,
        const char *manufacturer, const char *part_number, const char *description,
        double unit_kg, double unit_usd, const char *id)
{
	if (r->n_bom >= RES_MAX_BOM || qty <= 0)
		return;
	struct res_bom_line *b = &r->bom[r->n_bom];
	memset(b, 0, sizeof *b);
	b->item = ++r->n_bom;
	b->qty = qty;
	str_copy(b->category, sizeof b->category, category);
	str_copy(b->manufacturer, sizeof b->manufacturer, manufacturer);
	str_copy(b->part_number, sizeof b->part_number, part_number);
	str_copy(b->description, sizeof b->description, description);
	b->unit_mass_kg = unit_kg;
	b->total_mass_kg = unit_kg * (double)qty;
	b->unit_price_usd = unit_usd > 0.0 ? unit_usd : 0.0;
	b->total_price_usd = b->unit_price_usd * (double)qty;
	str_copy(b->catalogue_id, sizeof b->catalogue_id, id);
}

static void
bom_part(struct solve_result *r, const struct res_part *p, const char *category)
{
	if (p->chosen)
		bom_add(r, p->qty, category, p->manufacturer, p->part_number,
		    p->description, p->unit_mass_kg, p->unit_price_usd, p->id);
}

/* A sized part the catalogue cannot supply (mass from the closed run). */
static void
bom_custom(struct solve_result *r, int qty, const char *part_number,
           const char *description, double total_kg)
{
	if (total_kg > 0.0)
		bom_add(r, qty, "custom", "custom", part_number, description,
		    total_kg / (double)qty, 0.0, "");
}

/* The bill of materials: catalogue parts, then the sized custom parts; the
 * masses sum, with the payload, to the closed takeoff mass. */
static void
fill_bom(const struct sizing_params *p, struct solve_result *r)
{
	const struct res_run *o = &r->closed;
	const struct res_mass *m = &o->mass;
	char d[160];
	r->n_bom = 0;
	bom_part(r, &r->motor, "motor");
	bom_part(r, &r->prop, "propeller");
	bom_part(r, &r->battery, "battery");
	bom_part(r, &r->esc, "esc");
	int arms = p->coaxial ? p->n_rotors / 2 : p->n_rotors;
	snprintf(d, sizeof d, "CFRP arm tube OD %.1f x wall %.2f x length %.0f mm",
	    o->arm_outer_diameter_mm, o->arm_wall_thickness_mm,
	    o->arm_length_m * 1000.0);
	bom_custom(r, arms > 0 ? arms : 1, "Carbon arm", d, m->arm_kg);
	bom_custom(r, 1, "Centre frame", "Centre plates and spar joints", m->frame_kg);
	bom_custom(r, 1, "Body and landing gear", "Body shell, landing gear and mounts",
	    m->other_kg);
	snprintf(d, sizeof d, "Power harness for %.0f A peak: wiring, connectors, "
	    "distribution", o->peak_current_a);
	bom_custom(r, 1, "Power harness", d, m->wiring_kg);
	bom_custom(r, 1, "Avionics", "Flight controller, GNSS, radios", m->avionics_kg);
	bom_custom(r, 1, "Role hardware", "Payload mounts and role equipment "
	    "(release, pump, gimbal)", m->role_aux_kg);
	r->bom_mass_kg = 0.0;
	r->bom_price_usd = 0.0;
	for (int i = 0; i < r->n_bom; i++) {
		r->bom_mass_kg += r->bom[i].total_mass_kg;
		r->bom_price_usd += r->bom[i].total_price_usd;
	}
}

static void
explain(const struct optim_target *t, const struct optim_choice *c,
        struct solve_result *r, int n_found, int tried, const char *failed)
{
	struct solve_result *w = r;
	const struct catalog_motor *m = c->motor;
	if (c->prop != NULL)
		res_rationale(w, "Motor %s (%.0f KV) on %s propellers (%.1f x %.1f in): "
		    "J = %.1f, best of %d catalogue combinations, aiming at %.1f x %.1f in "
		    "and %.0f KV at %dS; hover throttle %.0f %% on the real motor.",
		    m->id, m->kv_rpm_per_v, c->prop->id, c->prop->diameter_in,
		    c->prop->pitch_in, c->j_score, n_found, t->prop_diameter_in,
		    t->prop_pitch_in, at_bus(t, t->motor_kv, c->cells), c->cells,
		    100.0 * c->hover_throttle);
	else
		res_rationale(w, "Integrated system %s (%.0f KV, %.0f in propeller, "
		    "ESC inside): J = %.1f, best of %d catalogue combinations; hover "
		    "throttle %.0f %%.", m->id, m->kv_rpm_per_v, m->integrated_prop_in,
		    c->j_score, n_found, 100.0 * c->hover_throttle);
	if (c->cells != t->cells)
		res_rationale(w, "Bus %dS instead of the continuous %dS: the real "
		    "parts match better there (same power, %.0f %% of the current).",
		    c->cells, t->cells, 100.0 * (double)t->cells / (double)c->cells);
	if (strcmp(chem_family(c->battery->chemistry), chem_family(t->chemistry)) != 0)
		res_rationale(w, "No catalogue pack of the mission's %s family fits "
		    "the bus; %s packs are used and the closed run flies their "
		    "chemistry profile.", t->chemistry, c->battery->chemistry);
	res_rationale(w, "Battery: %d x %s (%dS%dP) = %dS %.0f mAh, %.2f kg.",
	    c->series_packs * c->parallel_packs, c->battery->id, c->series_packs,
	    c->parallel_packs, c->cells, c->battery->capacity_ah * 1000.0
	    * (double)c->parallel_packs, (double)(c->series_packs * c->parallel_packs)
	    * c->battery->mass_kg);
	if (c->esc != NULL)
		res_rationale(w, "ESC: %d x %s, %.0f A continuous for the %.0f A "
		    "each motor draws at full throttle with 10 %% margin.", c->n_esc,
		    c->esc->id, c->esc->continuous_current_a,
		    closed_current_a(&r->closed));
	if (tried > 0)
		res_rationale(w, "%d better-scoring combination%s did not close the "
		    "mission on real parts.", tried, tried == 1 ? "" : "s");
	res_rationale(w, "BOM-closed design: MTOW %.3f kg against %.3f kg "
	    "continuous (%+.1f %%)%s%s.", r->closed.mass.total_kg,
	    r->custom.mass.total_kg, 100.0 * (r->closed.mass.total_kg
	    / r->custom.mass.total_kg - 1.0), failed ? "; it fails: " : "",
	    failed ? failed : "");
}

static void
append_violations(struct solve_result *r, const struct solve_result *src)
{
	for (int i = 0; i < src->n_violations && r->n_violations < RES_MAX_VIOLATIONS; i++)
		r->violations[r->n_violations++] = src->violations[i];
}

/* The closest closing so far: the fewest failed checks, and among equals
 * the first in search order. */
struct fallback {
	struct solve_result *r;
	struct optim_choice c;
	int round;                     /* the search round it was found in */
	int failed;                    /* its failed checks; -1: none yet */
	bool finite;
	enum sizing_status st;
	const char *fail;              /* its first new failure, or NULL */
};

/* The closing in *cur (choice c, search round `round`) becomes the
 * fallback if it fails fewer checks.  The next try rewrites all it reads
 * of its result, so the buffers swap instead of copying a whole result. */
static void
offer_fallback(struct fallback *fb, struct solve_result **cur,
               const struct optim_choice *c, int round, bool finite,
               enum sizing_status st, const char *fail)
{
	int failed = n_failed(&(*cur)->closed);
	if (fb->failed >= 0 && failed >= fb->failed)
		return;
	fb->c = *c;
	fb->round = round;
	fb->failed = failed;
	fb->finite = finite;
	fb->st = st;
	fb->fail = fail;
	struct solve_result *tmp = fb->r;
	fb->r = *cur;
	*cur = tmp;
}

int
optim_select(const struct mission_spec *spec, const struct sizing_params *p_custom,
             const struct model_data *md, const struct catalog *cat,
             struct solve_result *r)
{
	r->parts_selected = false;
	r->n_bom = 0;
	r->n_candidates = 0;
	r->bom_mass_kg = 0.0;
	r->bom_price_usd = 0.0;
	memset(&r->motor, 0, sizeof r->motor);
	memset(&r->prop, 0, sizeof r->prop);
	memset(&r->battery, 0, sizeof r->battery);
	memset(&r->esc, 0, sizeof r->esc);
	memset(&r->closed, 0, sizeof r->closed);
	if (!r->custom.ran || !r->custom.converged) {
		res_rationale(r, "No parts selected: the continuous design did not "
		    "converge.");
		return 0;
	}
	struct sizing_params p = *p_custom;
	struct optim_locks lk;
	if (!read_locks(&spec->locks, cat, &lk, r))
		return 0;
	struct optim_target t;
	make_target(&p, &r->custom, &t);

	struct optim_choice ch[OPTIM_MAX_TRIES];
	struct optim_census cs;
	/* The packs every ranking and every upsized battery pick from. */
	struct pack_list packs;
	pack_list_init(cat, lk.battery, &packs);
	/* And the ESC sets every ranking picks from, in pick order. */
	struct esc_list escs;
	esc_list_init(&t, cat, lk.esc, &escs);
	int n_found = rank_catalog(&t, cat, &lk, &packs, &escs, ch, OPTIM_MAX_TRIES, &cs,
	    r->candidates, &r->n_candidates);
	if (n_found == 0 && t.cells_floor < t.cells_lo) {
		/* Nothing from S* up: try the lower buses the packs give. */
		struct optim_target low = t;
		struct optim_census cs2;
		low.cells_lo = t.cells_floor;
		low.cells_hi = t.cells - 1;
		n_found = rank_catalog(&low, cat, &lk, &packs, &escs, ch, OPTIM_MAX_TRIES, &cs2,
		    r->candidates, &r->n_candidates);
		for (int i = 0; i < OPTIM_REASON_MAX; i++)
			cs.n_fail[i] += cs2.n_fail[i];
		cs.n_examined += cs2.n_examined;
		if (n_found > 0) {
			res_rationale(r, "No catalogue combination fits at %dS or more; "
			    "the bus goes down to %dS, above the harness current budget.",
			    t.cells, ch[0].cells);
			t.cells_lo = low.cells_lo;
			t.cells_hi = low.cells_hi;
		} else {
			t.cells_lo = t.cells_floor;
		}
	}
	if (n_found == 0) {
		esc_list_free(&escs);
		pack_list_free(&packs);
		report_none(&t, &cs, lk.motor ? catalog_find_motor(cat, lk.motor) : NULL, r);
		return 0;
	}

	/* Close the best combinations in J order until one closes as well as
	 * the continuous design; re-aim at the real-parts mass when none does;
	 * else keep the one with the fewest failed checks (the first in search
	 * order among equals) and report it. */
	struct optim_target tr = t;
	struct closer k = { &p, md, &tr, cat, &lk, &r->custom, &packs };
	/* Trial buffers: each try writes all it reads of its result (see
	 * close_choice()), and keeps its violations' codes only. */
	struct solve_result *cur = xmalloc(sizeof *cur);
	struct solve_result *spare = xmalloc(sizeof *spare);
	struct fallback fb = { xmalloc(sizeof *fb.r), ch[0], 0, -1, true,
		SIZING_CONVERGED, NULL };
	fb.r->terse = cur->terse = spare->terse = true;
	fb.r->n_violations = 0;
	struct res_candidate *round_cand = xmalloc((size_t)OPTIM_ROUNDS
	    * RES_MAX_CANDIDATES * sizeof *round_cand);
	int round_n_cand[OPTIM_ROUNDS] = { 0 };
	struct optim_target round_t[OPTIM_ROUNDS];  /* the aim of each round */
	struct optim_choice use_c = ch[0];
	struct optim_target use_t = t;  /* the aim it was found at */
	int use_round = 0;
	bool finite = true;
	enum sizing_status st = SIZING_CONVERGED, use_st = st;
	struct solve_result *use = NULL;
	int tried = 0;
	for (int round = 0; round < OPTIM_ROUNDS && use == NULL; round++) {
		/* A re-aimed round scores the candidates too: the crosshair
		 * figure shows those of the round the parts come from. */
		int n = round == 0 ? n_found
		    : rank_catalog(&tr, cat, &lk, &packs, &escs, ch, OPTIM_MAX_TRIES, NULL,
		        &round_cand[round * RES_MAX_CANDIDATES], &round_n_cand[round]);
		if (n == 0)
			break;
		round_t[round] = tr;
		int kept = n < OPTIM_MAX_TRIES ? n : OPTIM_MAX_TRIES;
		double heaviest = 0.0;
		for (int i = 0; i < kept; i++) {
			struct optim_choice c = ch[i];
			const char *fail = close_choice(&k, &c, &cur, &spare, &finite, &st);
			tried += fail != NULL || !finite;
			if (fail == NULL && finite) {
				use = cur;
				use_st = st;
				use_c = c;
				use_t = tr;
				use_round = round;
				break;
			}
			if (i == 0)
				heaviest = cur->closed.mass.total_kg;
			offer_fallback(&fb, &cur, &c, round, finite, st, fail);
		}
		/* Real parts heavier than the aim: thrust, current, power and
		 * energy grow about as M^1.5 on a given rotor. */
		double ratio = heaviest / tr.mass_kg;
		if (use != NULL || !(ratio > 1.0) || !isfinite(ratio))
			break;
		double g = pow(ratio, 1.5);
		tr.mass_kg *= ratio;
		tr.motor_peak_current_a *= g;
		tr.motor_peak_power_w *= g;
		tr.bus_peak_current_a *= g;
		tr.capacity_ah *= g;
	}
	char failed[RES_TEXT] = "";
	if (use == NULL) {
		use = fb.r;
		use_c = fb.c;
		use_round = fb.round;
		use_t = round_t[use_round];
		use_st = fb.st;
		finite = fb.finite;
		str_copy(failed, sizeof failed, fb.fail != NULL ? fb.fail : "a check");
	}
	/* The closing kept gets its checks again, with the violations' text
	 * (the same checks: the same run and parameters). */
	struct sizing_params pu = p;
	apply_parts(&pu, md, &use_t, &r->custom, &use_c);
	use->terse = false;
	check_closing(&k, &pu, use_st, &use_c, use);
	r->closed = use->closed;
	finite = finite && isfinite(r->closed.hover_endurance_s);
	append_violations(r, use);
	if (failed[0]) {
		const char *fx[] = {
			"Add parts near the continuous optimum to the catalogue, or use --db",
			"Lock parts by id (locks.motor_part, ...) to study one combination",
			"Relax the mission (payload, times, thrust margin)", NULL };
		feasibility_violation(r, "closed", "parts", "PARTS_DO_NOT_CLOSE", fx,
		    "None of %d catalogue combinations closes the mission on real "
		    "parts; the closest (%s%s%s, %d x %s) fails \"%s\".", tried,
		    use_c.motor->id, use_c.prop ? " + " : "", use_c.prop ? use_c.prop->id : "",
		    use_c.series_packs * use_c.parallel_packs, use_c.battery->id, failed);
	}
	locked_limits(&use_t, &lk, &use_c, r);
	esc_list_free(&escs);
	pack_list_free(&packs);
	free(fb.r);
	free(cur);
	free(spare);
	/* The crosshair figure scores every motor against the aim the chosen
	 * parts were found at (scored by that round's ranking). */
	if (use_round > 0) {
		r->n_candidates = round_n_cand[use_round];
		memcpy(r->candidates, &round_cand[use_round * RES_MAX_CANDIDATES],
		    (size_t)r->n_candidates * sizeof r->candidates[0]);
		res_rationale(r, "Real parts came out heavier than the continuous "
		    "design, so the search was re-aimed at %.2f kg (%d round%s).",
		    use_t.mass_kg, use_round, use_round == 1 ? "" : "s");
	}
	free(round_cand);

	fill_parts(&t, &use_c, r);
	struct sizing_params pc = p;
	apply_parts(&pc, md, &t, &r->custom, &use_c);
	fill_bom(&pc, r);
	r->parts_selected = true;
	explain(&t, &use_c, r, n_found, failed[0] ? 0 : tried, failed[0] ? failed : NULL);
	if (!finite || !isfinite(r->bom_mass_kg) || !isfinite(r->bom_price_usd)) {
		memset(&r->closed.mass, 0, sizeof r->closed.mass);
		return 3;
	}
	return 0;
}
