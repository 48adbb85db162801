/* parts.c — the parts search: rank, close, choose (see parts.h). */
#include "parts/parts.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parts/parts_int.h"
#include "physics/batt.h"
#include "physics/discharge.h"
#include "sizing/feasibility.h"
#include "util/strbuf.h"
#include "util/xalloc.h"

/* A locked part id that the catalogue lacks, or whose entry is unusable. */
static bool
lock_known(struct solve_result *r, const char *field, const char *id,
           const char *file, bool found, bool usable)
{
	char f1[RES_TEXT], f2[RES_TEXT], f3[RES_TEXT];
	const char *fx[4] = { f1, f2, f3, NULL };
	if (!found) {
		snprintf(f1, sizeof f1, "Check the id against data/catalog/%s (ids are lowercase slugs)", file);
		snprintf(f2, sizeof f2, "Use --db DIR for a catalogue that has it");
		snprintf(f3, sizeof f3, "Remove locks.%s to let the search choose", field);
		feasibility_violation(r, "closed", "parts", "UNKNOWN_PART", fx,
		    "locks.%s names \"%s\", which is not in the parts catalogue.",
		    field, id);
		return false;
	}
	if (!usable) {
		snprintf(f1, sizeof f1, "Fill the missing fields of \"%s\" in data/catalog/%s", id, file);
		snprintf(f2, sizeof f2, "Remove locks.%s to let the search choose", field);
		fx[2] = NULL;
		feasibility_violation(r, "closed", "parts", "UNUSABLE_PART", fx,
		    "locks.%s names \"%s\", whose catalogue entry lacks a value the "
		    "search needs.", field, id);
		return false;
	}
	return true;
}

/* The mission's part locks; false (with violations) if one is unknown. */
static bool
read_locks(struct parts_ctx *x, struct solve_result *r)
{
	const struct spec_locks *sl = &x->spec->locks;
	const struct catalog *cat = x->cat;
	bool ok = true;
	if (sl->motor_part[0]) {
		x->lock_motor = catalog_find_motor(cat, sl->motor_part);
		ok &= lock_known(r, "motor_part", sl->motor_part, "motors.json",
		    x->lock_motor != NULL, x->lock_motor && x->lock_motor->usable);
	}
	if (sl->prop_part[0]) {
		x->lock_prop = catalog_find_prop(cat, sl->prop_part);
		ok &= lock_known(r, "prop_part", sl->prop_part, "propellers.json",
		    x->lock_prop != NULL, x->lock_prop && x->lock_prop->usable);
	}
	if (sl->battery_part[0]) {
		x->lock_battery = catalog_find_battery(cat, sl->battery_part);
		ok &= lock_known(r, "battery_part", sl->battery_part, "batteries.json",
		    x->lock_battery != NULL, x->lock_battery && x->lock_battery->usable);
	}
	if (sl->esc_part[0]) {
		x->lock_esc = catalog_find_esc(cat, sl->esc_part);
		ok &= lock_known(r, "esc_part", sl->esc_part, "escs.json",
		    x->lock_esc != NULL, x->lock_esc && x->lock_esc->usable);
	}
	return ok;
}

/* No option survived the ranking: say what set them aside, most first. */
static void
report_none(const struct parts_ctx *x, struct solve_result *r)
{
	char msg[RES_TEXT];
	int order[PARTS_REASON_MAX], n = 0;
	for (int k = 1; k < PARTS_REASON_MAX; k++)
		if (x->n_census[k] > 0)
			order[n++] = k;
	for (int a = 1; a < n; a++)
		for (int b = a; b > 0 && x->n_census[order[b]] > x->n_census[order[b - 1]]; b--) {
			int tmp = order[b];
			order[b] = order[b - 1];
			order[b - 1] = tmp;
		}
	size_t len = (size_t)snprintf(msg, sizeof msg, "No catalogue combination "
	    "fits at %d-%dS; of %d options: ", x->cells_lo, x->cells_hi,
	    x->n_examined);
	/* Whole reasons only, the commonest first, as many as the text holds. */
	for (int k = 0; k < n; k++) {
		char item[96];
		size_t add = (size_t)snprintf(item, sizeof item, "%s%s %d", k > 0 ? ", " : "",
		    parts_reason_text[order[k]], x->n_census[order[k]]);
		if (len + add + 2 > sizeof msg)
			break;
		memcpy(msg + len, item, add + 1);
		len += add;
	}
	snprintf(msg + len, sizeof msg - len, ".");
	const char *fx[] = {
		"Add parts near the continuous optimum to the catalogue, or use --db",
		"Lock a part by id (locks.motor_part) to see which of its limits binds",
		"Relax the mission (payload, times, thrust margin)", NULL };
	feasibility_violation(r, "closed", "parts", "NO_PARTS", fx, "%s", msg);
}

/* Does closing c reach the required T/W with the largest payload aboard? */
static bool
at_parity(const struct parts_ctx *x, const struct parts_closed *c)
{
	const struct res_run *o = &c->r->closed;
	return o->thrust_to_weight * o->mass.total_kg
	    >= x->aim.tw_required * (o->mass.total_kg + x->aim.extra_payload_kg);
}

/* Is closing a better than b?  Passing every check first (or the fewest
 * failed), then reaching the required T/W, then the lighter. */
static bool
better(const struct parts_ctx *x, const struct parts_closed *a,
       const struct parts_closed *b)
{
	if (b->r == NULL)
		return true;
	if (!a->finite || !b->finite)
		return a->finite;
	if (a->failed != b->failed)
		return a->failed < b->failed;
	if (at_parity(x, a) != at_parity(x, b))
		return at_parity(x, a);
	double ma = a->r->closed.mass.total_kg, mb = b->r->closed.mass.total_kg;
	if (ma != mb)
		return ma < mb;
	return strcmp(a->o.motor->id, b->o.motor->id) < 0;
}

/* The lightest arrangement of the bus heavier than above_kg, of at most
 * x->max_parallel packs in parallel, that holds need_wh and carries the
 * option's currents: hover within the continuous rating, full throttle
 * within the burst rating and with the pack's sag at most max_sag of its
 * voltage (else the thrust the ranking counted on is not there), and
 * through a plug that carries each pack's share of them (kit.c).  -1 when
 * none does. */
static int
pick_pack(const struct parts_ctx *x, const struct parts_option *o,
          const struct parts_pack *pk, int n, double need_wh, double max_sag,
          double above_kg)
{
	double v = (double)o->cells * x->p->chem->v_nom;
	double i_full = (double)x->p->n_rotors * o->full_current_a;
	double i_hover = o->hover_power_w / v;
	int best = -1;
	for (int i = 0; i < n; i++) {
		const struct parts_pack *q = &pk[i];
		if (!(q->energy_wh >= need_wh && q->max_burst_a >= i_full
		    && q->max_continuous_a >= i_hover && q->mass_kg > above_kg
		    && q->parallel <= x->max_parallel
		    && (best < 0 || q->mass_kg < pk[best].mass_kg)))
			continue;
		double r_pack = (double)o->cells * batt_rated_cell_ohm(q->chem,
		    q->capacity_ah, q->b->continuous_c);
		if (r_pack * i_full <= max_sag * v
		    && parts_kit_plug(x, q, i_hover, i_full, NULL, 0) == NULL) {
			best = i;
			/* The packs of a bus come by mass (parts_packs_init()):
			 * none after the first that fits is strictly lighter. */
			if (!x->exhaustive)
				break;
		}
	}
	return best;
}

static void
swap_closed(struct parts_closed *a, struct parts_closed *b)
{
	struct parts_closed t = *a;
	*a = *b;
	*b = t;
}

/* What a closing on one pack says about the next pack to try. */
struct pack_try {
	double end_soc, reserve_soc;
	bool completed;                /* the discharge flew the whole mission */
	bool pack_failed;              /* it failed, and only on checks another
	                                  pack of the bus may pass (pack_check) */
};

/* The checks a closing's pack decides with the drive unchanged: its plug,
 * its ratings and heat, and its sag (the voltage floor, and the thrust at
 * full throttle, which goes as the loaded bus voltage squared). */
static bool
pack_check(const char *code)
{
	static const char *const codes[] = { "CONNECTOR_CURRENT",
	    "CONNECTOR_CURRENT_FULL", "VOLTAGE_FLOOR", "VOLTAGE_FULL_THROTTLE",
	    "BATTERY_CURRENT", "BATTERY_BURST", "BATTERY_POWER", "THERMAL_RUNAWAY",
	    "THRUST" };
	for (size_t i = 0; i < sizeof codes / sizeof codes[0]; i++)
		if (strcmp(code, codes[i]) == 0)
			return true;
	return false;
}

/* A closing made: parts_close() reads the option, the pack, the ESCs and
 * the aim and nothing else that changes during a search, so the same
 * closing closes the same.  The rounds and the wider-bank search rank the
 * same options again and try the same packs (on the FPV racer 70 % of the
 * closings were repeats): a repeat is answered from here.  It cannot
 * displace the pick: better() is a fixed order (the T/W requirement does
 * not change with the aim), the closing was compared with the pick of its
 * time and the pick has only got better since. */
struct seen {
	const struct catalog_motor *motor;
	const struct catalog_prop *prop;
	int cells;
	const struct catalog_esc *esc;
	int n_esc;
	struct parts_aim aim;
	struct pack_try t;
	bool passed;
	int next;                      /* the next closing on its pack, or -1 */
};

/* A ranking made: parts_rank() reads the aim and nothing else that
 * changes during a search (not the bank's width), so the wider-bank
 * search, which ranks again at the aims the first one ranked at, is
 * answered from here: the options, the census and the candidates. */
#define PARTS_RANKED (PARTS_KEEP + PARTS_KEEP_SHORT + PARTS_KEEP_MARGINAL)
struct ranked {
	struct parts_aim aim;
	struct parts_option best[PARTS_RANKED];
	int n_best;
	int n_census[PARTS_REASON_MAX];
	int n_examined;
	struct res_candidate cand[RES_MAX_CANDIDATES];
	int n_cand;
};

/* One search's trial buffers, its best closing, the closings made and its
 * tallies. */
struct search {
	struct parts_closed cur, pick;
	struct solve_result *spare;
	int n_closed, n_ranked;
	struct seen *seen;
	int n_seen, cap_seen;
	int *seen_by_pack;             /* first closing on x->packs[i], or -1 */
	struct ranked *ranked;         /* the rankings made, n_ranked_at of */
	int n_ranked_at;               /* at most 2 PARTS_ROUNDS */
	bool exhaustive;               /* every closing made again (test builds:
	                                  AEROEVAL_TEST_EXHAUSTIVE) */
};

/* Every field of the aim, compared: a field added to struct parts_aim
 * must be added here too, or a closing at another aim would be taken for
 * this one (the assert trips on a new field). */
_Static_assert(sizeof(struct parts_aim) == 16 * sizeof(double),
    "aim_same() must compare every field of struct parts_aim");
static bool
aim_same(const struct parts_aim *a, const struct parts_aim *b)
{
	return a->mass_kg == b->mass_kg && a->lightest == b->lightest
	    && a->drive_kg == b->drive_kg && a->battery_kg == b->battery_kg
	    && a->energy_wh == b->energy_wh && a->hover_power_w == b->hover_power_w
	    && a->growth == b->growth && a->tw_required == b->tw_required
	    && a->extra_payload_kg == b->extra_payload_kg
	    && a->downwash_cap_ms == b->downwash_cap_ms
	    && a->prop_diameter_in == b->prop_diameter_in
	    && a->prop_pitch_in == b->prop_pitch_in && a->motor_kv == b->motor_kv
	    && a->cells == b->cells && a->overlap_limit_in == b->overlap_limit_in
	    && a->install_factor == b->install_factor;
}

/* The closing of o on x->packs[k] with esc at the aim, if made. */
static const struct seen *
seen_find(const struct parts_ctx *x, const struct search *s,
          const struct parts_option *o, int k, const struct catalog_esc *esc,
          int n_esc)
{
	for (int i = s->seen_by_pack[k]; i >= 0; i = s->seen[i].next) {
		const struct seen *e = &s->seen[i];
		if (e->motor == o->motor && e->prop == o->prop && e->cells == o->cells
		    && e->esc == esc && e->n_esc == n_esc && aim_same(&e->aim, &x->aim))
			return e;
	}
	return NULL;
}

static void
seen_add(const struct parts_ctx *x, struct search *s,
         const struct parts_option *o, int k, const struct catalog_esc *esc,
         int n_esc, const struct pack_try *t, bool passed)
{
	if (s->n_seen == s->cap_seen) {
		s->cap_seen = s->cap_seen > 0 ? 2 * s->cap_seen : 64;
		s->seen = xrealloc(s->seen, (size_t)s->cap_seen * sizeof *s->seen);
	}
	struct seen *e = &s->seen[s->n_seen];
	*e = (struct seen){ o->motor, o->prop, o->cells, esc, n_esc, x->aim, *t,
		passed, s->seen_by_pack[k] };
	s->seen_by_pack[k] = s->n_seen++;
}

/* parts_rank() at x->aim into best (r's candidates), or the ranking made
 * at the same aim before; returns the options ranked. */
static int
rank_at_aim(struct parts_ctx *x, struct search *s, struct parts_option *best,
            struct solve_result *r)
{
	for (int i = 0; i < s->n_ranked_at && !s->exhaustive; i++) {
		const struct ranked *e = &s->ranked[i];
		if (!aim_same(&e->aim, &x->aim))
			continue;
		memcpy(best, e->best, (size_t)e->n_best * sizeof *best);
		memcpy(x->n_census, e->n_census, sizeof x->n_census);
		x->n_examined = e->n_examined;
		memcpy(r->candidates, e->cand, (size_t)e->n_cand * sizeof *e->cand);
		r->n_candidates = e->n_cand;
		return e->n_best;
	}
	int n_best = parts_rank(x, best, PARTS_RANKED, r->candidates,
	    &r->n_candidates);
	if (s->n_ranked_at < 2 * PARTS_ROUNDS) {
		struct ranked *e = &s->ranked[s->n_ranked_at++];
		e->aim = x->aim;
		memcpy(e->best, best, (size_t)n_best * sizeof *best);
		e->n_best = n_best;
		memcpy(e->n_census, x->n_census, sizeof e->n_census);
		e->n_examined = x->n_examined;
		memcpy(e->cand, r->candidates, (size_t)r->n_candidates * sizeof *e->cand);
		e->n_cand = r->n_candidates;
	}
	return n_best;
}

/* Close option o on pack pk, keep it in s->pick when better; true when it
 * passes every check. */
static bool
close_on(const struct parts_ctx *x, const struct parts_option *o,
         const struct parts_pack *pk, const struct catalog_esc *esc,
         int n_esc, struct search *s, struct pack_try *t)
{
	int k = (int)(pk - x->packs);
	const struct seen *e = s->exhaustive ? NULL
	    : seen_find(x, s, o, k, esc, n_esc);
	if (e != NULL) {
		*t = e->t;
		return e->passed;
	}
	struct parts_closed *cur = &s->cur, *pick = &s->pick;
	parts_close(x, o, pk, esc, n_esc, cur);
	bool passed = cur->finite && cur->failed == 0;
	t->end_soc = cur->r->closed.end_soc;
	t->reserve_soc = cur->r->closed.reserve_soc;
	t->completed = strcmp(cur->r->closed.termination,
	    discharge_end_text[DIS_COMPLETED]) == 0;
	t->pack_failed = !passed && cur->finite;
	for (int i = 0; i < cur->r->n_violations && t->pack_failed; i++)
		t->pack_failed = pack_check(cur->r->violations[i].code);
	seen_add(x, s, o, k, esc, n_esc, t, passed);
	if (better(x, cur, pick)) {
		if (pick->r == NULL) {
			pick->r = s->spare;
			s->spare = NULL;
		}
		swap_closed(cur, pick);
	}
	return passed;
}

/* Close option o on the lightest fitting pack, then, while the pack lands
 * below the reserve, on larger ones. */
static int
close_option(const struct parts_ctx *x, const struct parts_option *o,
             const struct catalog_esc *esc, int n_esc, struct search *s)
{
	int n_pk, n_closed = 0;
	const struct parts_pack *pk = parts_packs_on(x, o->cells, &n_pk);
	if (pk == NULL)
		return 0;
	/* Packs allowed to sag more first (lighter); when none of those
	 * closes every check (a sagging pack costs thrust and voltage), stiffer
	 * ones. */
	static const double max_sag[] = { PARTS_MAX_SAG, PARTS_STIFF_SAG };
	for (size_t tier = 0; tier < sizeof max_sag / sizeof max_sag[0]; tier++) {
		/* The continuous design's energy, scaled by this option's hover
		 * power, a little below: the real design may well be lighter. */
		double need = x->aim.hover_power_w > 0.0 ? 0.85 * x->aim.energy_wh
		    * o->hover_power_w / x->aim.hover_power_w : 0.0;
		int last = -1;
		double above_kg = 0.0;
		bool passed = false;
		for (int k = 0; k < PARTS_PACK_TRIES; k++) {
			int at = pick_pack(x, o, pk, n_pk, need, max_sag[tier], above_kg);
			if (at < 0 || at == last)
				break;
			last = at;
			struct pack_try t;
			passed |= close_on(x, o, &pk[at], esc, n_esc, s, &t);
			n_closed++;
			double used = 1.0 - t.end_soc;
			/* The pack a mission flown whole asks for by its charge
			 * alone: this pack's energy times the charge it drew over
			 * the charge it may draw. */
			int fit = t.completed && used > 0.0 ? pick_pack(x, o, pk, n_pk,
			    pk[at].energy_wh * used / (1.0 - t.reserve_soc),
			    max_sag[tier], 0.0) : -1;
			/* Enough charge, but its plug, sag or ratings fail: that
			 * pack, when it is lighter (less mass to lift may pass the
			 * thrust check), then the next heavier pack of the same
			 * need. */
			if (t.end_soc >= t.reserve_soc && t.pack_failed) {
				if (fit >= 0 && pk[fit].mass_kg < pk[at].mass_kg) {
					passed |= close_on(x, o, &pk[fit], esc, n_esc, s,
					    &t);
					n_closed++;
				}
				above_kg = pk[at].mass_kg;
				continue;
			}
			if (t.end_soc >= t.reserve_soc || !(used > 0.0))
				break;
			/* Short of the reserve: the next pack holds at least
			 * PARTS_PACK_STEP more (it carries its own mass, and a
			 * mission cut short at the voltage floor drew less than it
			 * needed).  The pack its charge asks for is tried too,
			 * when that is a smaller step. */
			need = pk[at].energy_wh * PARTS_PACK_STEP;
			if (fit >= 0 && fit != at
			    && fit != pick_pack(x, o, pk, n_pk, need, max_sag[tier], 0.0)) {
				passed |= close_on(x, o, &pk[fit], esc, n_esc, s, &t);
				n_closed++;
			}
		}
		if (passed)
			break;
	}
	return n_closed;
}

/* Rank and close at the continuous design's mass; when no closing passes
 * every check and the closest came out heavier, or landed short of the
 * reserve (the battery it lacks, grown as the loop grows it), rank again at
 * that mass (the parts a heavier aircraft needs), as the continuous loop
 * would.  The best closing is kept in s->pick, across calls. */
static void
search_rounds(struct parts_ctx *x, struct solve_result *r, struct search *s)
{
	for (int round = 0; round < PARTS_ROUNDS; round++) {
		if (round > 0 && s->pick.r != NULL && s->pick.failed == 0)
			break;
		double grown = 1.0;
		if (round > 0 && s->pick.r != NULL) {
			const struct res_run *cl = &s->pick.r->closed;
			grown = cl->mass.total_kg / x->aim.mass_kg;
			/* Short of the reserve: the energy it lacks, carried as
			 * battery the loop grows around (aim.growth). */
			if (cl->end_soc < cl->reserve_soc && cl->mass.total_kg > 0.0) {
				double lack = (1.0 - cl->end_soc) / (1.0 - cl->reserve_soc) - 1.0;
				grown = fmax(grown, cl->mass.total_kg / x->aim.mass_kg
				    * (1.0 + x->aim.growth * lack * cl->mass.battery_kg
				    / cl->mass.total_kg));
			}
		}
		if (round > 0 && grown > 1.0 + PARTS_ROUND_MIN_GROWTH) {
			parts_aim_regrow(&x->aim, grown);
		} else if (round > 0) {
			/* Nothing ranked, or the closest closing is not heavier:
			 * the real parts may close lighter than the continuous
			 * design (its laws fit the catalogue's median part, the
			 * search finds the lightest), so the ranking may trust
			 * an option's lighter estimate, once. */
			if (x->aim.lightest < 1.0)
				break;
			x->aim.lightest = PARTS_LIGHTEST;
		}
		/* The census the report gives is the last ranking's. */
		memset(x->n_census, 0, sizeof x->n_census);
		x->n_examined = 0;
		struct parts_option best[PARTS_RANKED];
		int n_best = rank_at_aim(x, s, best, r);
		s->n_ranked += n_best;
		/* Each on the lightest pack arrangement that fits it; the best
		 * closing is kept. */
		for (int i = 0; i < n_best; i++) {
			const struct catalog_esc *esc;
			int n_esc;
			if (!parts_pick_esc(x, &best[i], &esc, &n_esc)) {
				x->n_census[PARTS_NO_ESC]++;
				continue;
			}
			s->n_closed += close_option(x, &best[i], esc, n_esc, s);
		}
		if (s->pick.r != NULL && !s->pick.finite)
			break;
	}
}

/* Frees the lists parts_packs_init(), parts_escs_init() and
 * parts_kit_init() built. */
static void
ctx_free(struct parts_ctx *x)
{
	parts_packs_free(x);
	parts_escs_free(x);
	parts_kit_free(x);
}

int
parts_select(const struct mission_spec *spec, const struct sizing_params *p,
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
	struct parts_ctx x;
	memset(&x, 0, sizeof x);
	x.spec = spec;
	x.p = p;
	x.md = md;
	x.cat = cat;
	parts_aim_from(p, &r->custom, &x.aim);
	if (!read_locks(&x, r))
		return 0;
	if (p->cells_fixed > 0) {
		x.cells_lo = x.cells_hi = p->cells_fixed;
	} else {
		x.cells_lo = p->cells_lo > 1 ? p->cells_lo : 1;
		x.cells_hi = p->cells_hi < PARTS_MAX_CELLS ? p->cells_hi : PARTS_MAX_CELLS;
	}
	parts_packs_init(&x);
	parts_escs_init(&x);
	parts_kit_init(&x);

	/* The trial buffers keep their violations' codes only.  Banks of at
	 * most PARTS_BANK_PARALLEL packs in parallel first; wider ones (more
	 * packs to wire, charge and swap: a builder's last resort) only when
	 * no closing on those passes every check. */
	struct search s = { 0 };
	s.cur.r = xmalloc(sizeof *s.cur.r);
	s.spare = xmalloc(sizeof *s.spare);
	s.cur.r->terse = s.spare->terse = true;
	s.seen_by_pack = xmalloc((size_t)(x.n_packs > 0 ? x.n_packs : 1)
	    * sizeof *s.seen_by_pack);
	for (int i = 0; i < x.n_packs; i++)
		s.seen_by_pack[i] = -1;
	s.ranked = xmalloc(2 * PARTS_ROUNDS * sizeof *s.ranked);
#ifdef AEROEVAL_TEST_HOOKS
	s.exhaustive = getenv("AEROEVAL_TEST_EXHAUSTIVE") != NULL;
#endif
	x.exhaustive = s.exhaustive;
	const struct parts_aim aim = x.aim;
	x.max_parallel = PARTS_BANK_PARALLEL;
	search_rounds(&x, r, &s);
	if (s.pick.r != NULL && s.pick.finite && s.pick.failed > 0) {
		x.aim = aim;
		x.max_parallel = PARTS_MAX_PARALLEL;
		search_rounds(&x, r, &s);
	}
	free(s.spare);
	free(s.cur.r);
	free(s.seen);
	free(s.seen_by_pack);
	free(s.ranked);
	struct parts_closed pick = s.pick;
	int n_closed = s.n_closed, n_ranked = s.n_ranked;
	if (n_ranked == 0 || pick.r == NULL || !pick.finite) {
		/* Closings whose mass ran away are a verdict on the parts, not
		 * a defect: said as one.  A closing that is no number is. */
		bool ran_away = pick.r != NULL && pick.ran_away;
		bool defect = pick.r != NULL && !pick.ran_away;
		free(pick.r);
		ctx_free(&x);
		if (ran_away) {
			const char *fx[] = {
				"Add lighter or stronger parts near the continuous optimum, or use --db",
				"Relax the mission (payload, times, thrust margin)", NULL };
			feasibility_violation(r, "closed", "parts", "PARTS_RUNAWAY", fx,
			    "Every closing on catalogue parts ran away: with the real "
			    "parts the takeoff mass grows past %.0f kg.", SIZING_RUNAWAY_KG);
		} else {
			report_none(&x, r);
		}
		return defect ? 3 : 0;
	}

	/* The design of record, closed again with its violations' texts. */
	struct parts_closed rec = pick;
	rec.r = xcalloc(1, sizeof *rec.r);
	parts_close(&x, &pick.o, &pick.pack, pick.esc, pick.n_esc, &rec);
	rec.finite = rec.finite && parts_close_figures(&x, &rec);
	r->closed = rec.r->closed;
	for (int i = 0; i < rec.r->n_violations && r->n_violations < RES_MAX_VIOLATIONS; i++)
		r->violations[r->n_violations++] = rec.r->violations[i];
	if (rec.failed > 0) {
		const char *fx[] = {
			"Add parts near the continuous optimum to the catalogue, or use --db",
			"Lock parts by id (locks.motor_part, ...) to study one combination",
			"Relax the mission (payload, times, thrust margin)", NULL };
		feasibility_violation(r, "closed", "parts", "PARTS_DO_NOT_CLOSE", fx,
		    "None of the %d combinations of catalogue parts sized and flown "
		    "passes every check; the closest (%s %s%s%s%s%s, %d x %s %s) fails "
		    "%d.", n_closed, rec.o.motor->manufacturer, rec.o.motor->part_number,
		    rec.o.prop ? " + " : "", rec.o.prop ? rec.o.prop->manufacturer : "",
		    rec.o.prop ? " " : "", rec.o.prop ? rec.o.prop->part_number : "",
		    rec.pack.series * rec.pack.parallel, rec.pack.b->manufacturer,
		    rec.pack.b->part_number, rec.failed);
	}
	parts_fill(&x, &rec, r);
	parts_explain(&x, &rec, n_closed, 0, r);
	r->parts_selected = true;
	bool finite = rec.finite && isfinite(r->bom_mass_kg);
	free(rec.r);
	free(pick.r);
	ctx_free(&x);
	return finite ? 0 : 3;
}
