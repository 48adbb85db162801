/* test_optim.c — the discrete optimizer: J-score, limits, locks, the
 * BOM-closed design and its bill of materials.
 *
 * The ranking tests use a hand-made aim point and the small fixture
 * catalogue tests/fixtures/optim/basic, where each "trap" motor or part is
 * better by J than the right answer but breaks exactly one limit.  The
 * whole-solve tests run every example with the shipped catalogue (run from
 * the repository root).
 */
#include "test_util.h"

#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/catalog.h"
#include "cli/cli.h"
#include "core/diag.h"
#include "input/catalog_io.h"
#include "engine/engine.h"
#include "input/mission_io.h"
#include "parts/optim.h"
#include "physics/aero.h"
#include "util/stats.h"
#include "output/result_json.h"
#include "util/units.h"
#include "util/xalloc.h"

#define FIXTURE_DIR "tests/fixtures/optim/basic"
#define EXAMPLE_DIR "examples"
#define MAX_EXAMPLES 32
#define BOM_TOL_KG 0.001   /* the BOM sums to the closed MTOW within 1 g */

/* Aim point of the fixture tests: a 2 kg quad, 15 x 5 in, 400 KV at 4S.
 * Hover: T = 2 g / 4 = 4.903 N, n = sqrt(T / (C_t ρ D⁴)) = 2615 rpm on a
 * 15 in rotor (C_t 0.1, ρ 1.225).  Full rpm of 410 KV at 4S:
 * 410 × 4 × 3.7 × 0.85 = 5158 rpm, so θ_hvr = 0.507 < θ_role = 0.6. */
static void
fixture_target(struct optim_target *t)
{
	memset(t, 0, sizeof *t);
	t->prop_diameter_in = 15.0;
	t->prop_pitch_in = 5.0;
	t->motor_kv = 400.0;
	t->cells = 4;
	t->motor_peak_current_a = 15.0;
	t->motor_peak_power_w = 250.0;
	t->bus_peak_current_a = 60.0;
	t->capacity_ah = 5.0;
	t->mass_kg = 2.0;
	t->motor_mass_kg = 0.1;
	t->drive_mass_kg = 0.15;
	t->n_rotors = 4;
	t->hover_throttle = 0.6;
	t->forward_pitch_deg = 10.0;
	t->overlap_limit_in = 16.0;
	t->ct = 0.1;
	t->rho_kg_m3 = 1.225;
	t->sound_m_s = 340.3;
	t->v_cell_nom_v = 3.7;
	t->cells_lo = t->cells_hi = t->cells_floor = 4;
	snprintf(t->chemistry, sizeof t->chemistry, "LiPo");
}

static int
setup_fixture(void **state)
{
	struct diag *dg = diag_alloc(stderr);
	*state = catalog_io_load(FIXTURE_DIR, NULL, dg);
	diag_flush(dg);
	diag_free(dg);
	return *state != NULL ? 0 : -1;
}

static int
teardown_fixture(void **state)
{
	catalog_free(*state);
	return 0;
}

/* Rank with the default target, or t if given; returns the best choice. */
static struct optim_choice
best_of(const struct catalog *cat, const struct optim_target *t,
        const struct optim_locks *lk, struct optim_census *cs)
{
	struct optim_choice ch[4];
	int n = optim_rank(t, cat, lk, ch, 4, cs, NULL, NULL);
	assert_true(n > 0);
	return ch[0];
}

static void
assert_pack(const struct optim_choice *c, const char *id, int series, int parallel)
{
	assert_string_equal(c->battery->id, id);
	assert_int_equal(c->series_packs, series);
	assert_int_equal(c->parallel_packs, parallel);
}

/* ---- J-score ------------------------------------------------------------- */

static void
optim_j_score_should_match_the_hand_worked_value(void **state)
{
	(void)state;
	struct optim_target t;
	fixture_target(&t);
	double theta;
	/* 10 × 10/400 + 50 × 0.2/5 = 0.25 + 2.0; no throttle or pitch penalty. */
	double j = optim_j_score(&t, 4, 15.0, 5.2, 410.0, 0.1, &theta);
	assert_rel(j, 2.25, 1e-12);
	assert_rel(theta, 2615.0 / 5157.8, 1e-3);
}

static void
optim_j_score_should_penalise_hover_throttle_pitch_and_mass(void **state)
{
	(void)state;
	struct optim_target t;
	fixture_target(&t);
	double theta;
	/* 300 KV: full rpm 3774, θ = 0.693: Pen_a = 1000 × 0.093. */
	double j = optim_j_score(&t, 4, 15.0, 5.0, 300.0, 0.1, &theta);
	assert_rel(theta, 2615.0 / 3774.0, 1e-3);
	assert_rel(j, 2.5 + 1000.0 * (2615.0 / 3774.0 - 0.6), 2e-3);
	/* Pen_θ = 10 per degree above 20°; Pen_m = 10 per unit over m*. */
	t.forward_pitch_deg = 23.5;
	assert_rel(optim_j_score(&t, 4, 15.0, 5.2, 410.0, 0.1, NULL), 2.25 + 35.0, 1e-12);
	t.forward_pitch_deg = 10.0;
	assert_rel(optim_j_score(&t, 4, 15.0, 5.2, 410.0, 0.15, NULL), 2.25 + 5.0, 1e-12);
	/* At 8S the KV target halves: 205 KV is on target. */
	assert_rel(optim_j_score(&t, 8, 15.0, 5.2, 200.0, 0.1, NULL), 2.0, 1e-12);
}

/* ---- ranking on the fixture catalogue ------------------------------------ */

static void
optim_rank_should_pick_the_hand_checked_parts(void **state)
{
	const struct catalog *cat = *state;
	struct optim_target t;
	fixture_target(&t);
	struct optim_census cs;
	struct optim_choice c = best_of(cat, &t, NULL, &cs);
	assert_string_equal(c.motor->id, "fx-good");
	assert_string_equal(c.prop->id, "fx-p15x52");
	assert_rel(c.j_score, 2.25, 1e-12);
	/* The 4-in-1 board is the lightest that carries 1.1 × 15 A. */
	assert_string_equal(c.esc->id, "fx-esc-4in1-25a");
	assert_int_equal(c.n_esc, 1);
	/* 5.2 Ah at 30C: one pack holds 5 Ah and delivers 156 A >= 60 A. */
	assert_pack(&c, "fx-b4s-5200-30c", 1, 1);
	assert_int_equal(c.cells, 4);
	/* 6 usable motors x 4 propellers on one bus. */
	assert_int_equal(cs.n_examined, 24);
}

static void
optim_rank_should_prune_each_motor_limit(void **state)
{
	const struct catalog *cat = *state;
	struct optim_target t;
	fixture_target(&t);
	struct optim_census cs;
	struct optim_choice c = best_of(cat, &t, NULL, &cs);
	/* Each trap would score 0.25 better than fx-good on KV. */
	assert_string_equal(c.motor->id, "fx-good");
	assert_int_equal(cs.n_fail[OPTIM_MOTOR_CURRENT], 4);  /* 12 A < 16.5 A */
	assert_int_equal(cs.n_fail[OPTIM_MOTOR_POWER], 4);    /* 200 W < 250 W */
	assert_int_equal(cs.n_fail[OPTIM_MOTOR_CELLS], 4);    /* 6-12S, bus 4S */
	assert_true(cs.n_fail[OPTIM_PROP_RANGE] >= 3);       /* 18-22 in */
	const struct catalog_motor *trap = catalog_find_motor(cat, "fx-trap-current");
	assert_int_equal(optim_limits(&t, 4, trap, catalog_find_prop(cat, "fx-p15x52")),
	    OPTIM_MOTOR_CURRENT);
	trap = catalog_find_motor(cat, "fx-trap-range");
	assert_int_equal(optim_limits(&t, 4, trap, catalog_find_prop(cat, "fx-p15x52")),
	    OPTIM_PROP_RANGE);
	/* Raising the need above fx-good's 20 A leaves nothing. */
	t.motor_peak_current_a = 19.0;
	assert_int_equal(optim_rank(&t, cat, NULL, NULL, 0, &cs, NULL, NULL), 0);
	assert_true(cs.n_fail[OPTIM_MOTOR_CURRENT] > 0);
	/* A power need above 300 W likewise. */
	fixture_target(&t);
	t.motor_peak_power_w = 320.0;
	assert_int_equal(optim_rank(&t, cat, NULL, NULL, 0, &cs, NULL, NULL), 0);
	assert_true(cs.n_fail[OPTIM_MOTOR_POWER] > 0);
}

static void
optim_rank_should_prune_overlap_tip_mach_and_prop_rpm(void **state)
{
	const struct catalog *cat = *state;
	struct optim_target t;
	fixture_target(&t);
	struct optim_census cs;
	struct optim_choice c = best_of(cat, &t, NULL, &cs);
	/* 17 in > 16 in overlap limit; 5158 rpm > the slow prop's 4000. */
	assert_true(cs.n_fail[OPTIM_PROP_OVERLAP] > 0);
	assert_true(cs.n_fail[OPTIM_PROP_RPM] > 0);
	assert_string_equal(c.prop->id, "fx-p15x52");
	assert_int_equal(optim_limits(&t, 4, catalog_find_motor(cat, "fx-good"),
	    catalog_find_prop(cat, "fx-p17x6")), OPTIM_PROP_OVERLAP);
	assert_int_equal(optim_limits(&t, 4, catalog_find_motor(cat, "fx-good"),
	    catalog_find_prop(cat, "fx-p15x5-slow")), OPTIM_PROP_RPM);

	/* A 14 in overlap limit leaves only the 13 in propeller. */
	t.overlap_limit_in = 14.0;
	c = best_of(cat, &t, NULL, &cs);
	assert_string_equal(c.prop->id, "fx-p13x45");

	/* Speed of sound 130 m/s: the 15 in tip runs at π 0.381 m × 86 rev/s
	 * = 103 m/s, Mach 0.79 > 0.75; the 13 in one at Mach 0.69. */
	fixture_target(&t);
	t.sound_m_s = 130.0;
	c = best_of(cat, &t, NULL, &cs);
	assert_true(cs.n_fail[OPTIM_TIP_MACH] > 0);
	assert_string_equal(c.prop->id, "fx-p13x45");
}

static void
optim_rank_should_respect_the_battery_c_rate_and_chemistry(void **state)
{
	const struct catalog *cat = *state;
	struct optim_target t;
	fixture_target(&t);
	/* At 40 A the 10C pack (50 A) is enough and the lightest. */
	t.bus_peak_current_a = 40.0;
	struct optim_choice c = best_of(cat, &t, NULL, NULL);
	assert_string_equal(c.battery->id, "fx-b4s-5000-10c");
	/* At 60 A it would need two in parallel (900 g): the 30C pack wins. */
	t.bus_peak_current_a = 60.0;
	c = best_of(cat, &t, NULL, NULL);
	assert_string_equal(c.battery->id, "fx-b4s-5200-30c");
	/* The lighter LiHV pack is taken only for a LiHV mission. */
	snprintf(t.chemistry, sizeof t.chemistry, "LiPo_highvoltage");
	c = best_of(cat, &t, NULL, NULL);
	assert_string_equal(c.battery->id, "fx-b4s-lihv-6000");
	/* 9 Ah: two packs in parallel either way; two 10C packs (900 g,
	 * 100 A) are lighter than two 30C ones (1040 g). */
	fixture_target(&t);
	t.capacity_ah = 9.0;
	c = best_of(cat, &t, NULL, NULL);
	assert_pack(&c, "fx-b4s-5000-10c", 1, 2);
}

static void
optim_rank_should_build_the_bus_from_smaller_packs(void **state)
{
	const struct catalog *cat = *state;
	struct optim_target t;
	fixture_target(&t);
	/* A 6S bus only the 2S packs build (3 in series); fx-trap-cells now
	 * fits its 6-12S range and the KV target is 400 × 4/6 = 267. */
	t.cells = 6;
	t.cells_lo = t.cells_hi = t.cells_floor = 6;
	t.motor_kv = 400.0;
	struct optim_choice c = best_of(cat, &t, NULL, NULL);
	assert_pack(&c, "fx-b2s-2700-40c", 3, 2); /* 5 Ah: two 2.7 Ah strings */
}

static void
optim_rank_should_honour_a_motor_lock_even_past_its_limit(void **state)
{
	const struct catalog *cat = *state;
	struct optim_target t;
	fixture_target(&t);
	struct optim_locks lk = { "fx-trap-current", NULL, NULL, NULL };
	struct optim_choice c = best_of(cat, &t, &lk, NULL);
	assert_string_equal(c.motor->id, "fx-trap-current");
	struct optim_locks lp = { NULL, "fx-p13x45", NULL, NULL };
	c = best_of(cat, &t, &lp, NULL);
	assert_string_equal(c.prop->id, "fx-p13x45");
	assert_string_equal(c.motor->id, "fx-good");
}

static void
optim_rank_should_score_every_usable_motor_for_the_crosshair(void **state)
{
	const struct catalog *cat = *state;
	struct optim_target t;
	fixture_target(&t);
	struct res_candidate cand[RES_MAX_CANDIDATES];
	int n = 0;
	struct optim_choice ch[1];
	optim_rank(&t, cat, NULL, ch, 1, NULL, cand, &n);
	assert_int_equal(n, 6); /* fx-unusable is left out */
	for (int i = 0; i < n; i++) {
		bool trap = strncmp(cand[i].id, "fx-trap", 7) == 0;
		assert_int_equal(cand[i].feasible, !trap);
		if (trap)
			assert_true(cand[i].j_score == OPTIM_PRUNED);
		else
			assert_true(cand[i].j_score < 200.0);
	}
	assert_string_equal(cand[0].id, "fx-good");
	assert_rel(cand[0].kv, 410.0, 1e-12);
	assert_rel(cand[0].mass_kg, 0.1, 1e-12);
	assert_rel(cand[0].j_score, 2.25, 1e-12);
}

/* ---- whole solves with the shipped catalogue ----------------------------- */

struct env_state {
	struct cli_env env;
};

static int
setup_env(void **state)
{
	struct env_state *s = xcalloc(1, sizeof *s);
	if (cli_env_load(&s->env, NULL, 1, stderr) != 0) {
		free(s);
		return -1;
	}
	*state = s;
	return 0;
}

static int
teardown_env(void **state)
{
	struct env_state *s = *state;
	cli_env_free(&s->env);
	free(s);
	return 0;
}

static void
load_mission(const struct env_state *s, const char *path, struct mission_spec *m)
{
	struct diag *dg = diag_alloc(NULL);
	int n_err = mission_io_load(path, s->env.model.chem_names, dg, m);
	if (n_err != 0)
		print_error("%s", diag_text(dg));
	diag_free(dg);
	assert_int_equal(n_err, 0);
}

static struct solve_result *
solve(const struct env_state *s, const struct mission_spec *m)
{
	struct solve_result *r = xcalloc(1, sizeof *r);
	assert_int_equal(engine_solve(m, &s->env.model, s->env.cat, r), 0);
	return r;
}

/* ---- the ranking against a plain scan ------------------------------------ */

#define SCAN_TARGETS 120

/* A random but plausible aim point: a multirotor of 0.3-60 kg whose rotor,
 * KV, currents and powers hang together roughly as a sized design's do, so
 * that every limit, and every shortcut the ranking takes past them, is
 * met on some targets and missed on others. */
static void
random_target(struct stats_rng *g, struct optim_target *t)
{
	static const int rotors[] = { 4, 6, 8 };
	static const char *const chem[] = { "LiPo", "LiHV", "Li-ion_standard" };
	memset(t, 0, sizeof *t);
	t->mass_kg = 0.3 * pow(200.0, stats_rng_uniform(g, 0.0, 1.0));
	t->n_rotors = rotors[stats_rng_below(g, 3)];
	t->prop_diameter_in = 10.0 * pow(t->mass_kg / 2.0, 0.4)
	    * stats_rng_uniform(g, 0.6, 1.5);
	t->prop_pitch_in = t->prop_diameter_in * stats_rng_uniform(g, 0.25, 0.6);
	t->overlap_limit_in = t->prop_diameter_in * stats_rng_uniform(g, 0.95, 1.3);
	t->wheelbase_m = in_to_m(t->prop_diameter_in) * stats_rng_uniform(g, 1.8, 3.0);
	t->cells = 2 + (int)stats_rng_below(g, 13);
	t->cells_lo = t->cells_floor = t->cells;
	t->cells_hi = t->cells + (int)stats_rng_below(g, 5);
	t->v_cell_nom_v = stats_rng_uniform(g, 3.6, 3.85);
	t->ct = stats_rng_uniform(g, 0.08, 0.12);
	t->rho_kg_m3 = stats_rng_uniform(g, 0.8, 1.3);
	t->sound_m_s = stats_rng_uniform(g, 325.0, 345.0);
	t->hover_throttle = stats_rng_uniform(g, 0.45, 0.7);
	t->forward_pitch_deg = stats_rng_uniform(g, 5.0, 25.0);
	double thrust_n = t->mass_kg * G0_M_S2 / (double)t->n_rotors;
	double n_hover = aero_rps_for_thrust(thrust_n, t->ct, t->rho_kg_m3,
	    in_to_m(t->prop_diameter_in));
	t->motor_kv = n_hover * 60.0 / (t->hover_throttle * (double)t->cells
	    * t->v_cell_nom_v * OPTIM_LOAD_RPM) * stats_rng_uniform(g, 0.7, 1.4);
	t->motor_peak_power_w = 250.0 * t->mass_kg / (double)t->n_rotors
	    * stats_rng_uniform(g, 0.5, 2.0);
	t->motor_peak_current_a = t->motor_peak_power_w
	    / ((double)t->cells * t->v_cell_nom_v);
	t->bus_peak_current_a = t->motor_peak_current_a * (double)t->n_rotors;
	t->capacity_ah = t->mass_kg * stats_rng_uniform(g, 0.5, 3.0) * 4.0
	    / (double)t->cells;
	t->motor_mass_kg = 0.03 * t->mass_kg / (double)t->n_rotors
	    * stats_rng_uniform(g, 0.6, 1.6);
	t->drive_mass_kg = 1.5 * t->motor_mass_kg;
	snprintf(t->chemistry, sizeof t->chemistry, "%s", chem[stats_rng_below(g, 3)]);
}

/* The ranking takes many shortcuts: a motor that breaks its own limits is
 * counted for all its propellers at once, the propellers outside its range
 * or above the tip Mach limit are cut from the diameter-sorted list, and
 * what does not depend on the propeller is done once per motor and bus.
 * Scanning every bus × motor × propeller option with optim_limits() and
 * optim_j_score() must give the same census, the same best J for every
 * motor (bit for bit), and kept choices that are the best-scoring
 * complete options in order. */
static void
optim_rank_should_agree_with_a_plain_scan_of_every_option(void **state)
{
	const struct env_state *s = *state;
	const struct catalog *cat = s->env.cat;
	struct stats_rng g;
	stats_rng_seed(&g, 20261202);
	size_t nm = catalog_n_motors(cat), np = catalog_n_props(cat);
	struct res_candidate *cand = xmalloc(RES_MAX_CANDIDATES * sizeof *cand);
	double *best = xmalloc(nm * sizeof *best);
	int n_passing_targets = 0, n_feasible_targets = 0;
	for (int k = 0; k < SCAN_TARGETS; k++) {
		struct optim_target t;
		random_target(&g, &t);
		struct optim_census cs;
		struct optim_choice ch[8];
		int n_cand = 0;
		int n_found = optim_rank(&t, cat, NULL, ch, 8, &cs, cand, &n_cand);

		struct optim_census ref;
		memset(&ref, 0, sizeof ref);
		int n_pass = 0;
		for (size_t i = 0; i < nm; i++)
			best[i] = OPTIM_PRUNED;
		for (int cells = t.cells_lo; cells <= t.cells_hi; cells++) {
			for (size_t i = 0; i < nm; i++) {
				const struct catalog_motor *m = catalog_motor(cat, i);
				if (!m->usable)
					continue;
				for (size_t j = 0; j < (m->integrated ? 1 : np); j++) {
					const struct catalog_prop *p = m->integrated ? NULL
					    : catalog_prop(cat, j);
					if (p != NULL && !p->usable)
						continue;
					ref.n_examined++;
					enum optim_reason why = optim_limits(&t, cells, m, p);
					if (why != OPTIM_OK) {
						ref.n_fail[why]++;
						continue;
					}
					n_pass++;
					double theta;
					double jj = optim_j_score(&t, cells,
					    p != NULL ? p->diameter_in : m->integrated_prop_in,
					    p != NULL ? p->pitch_in : 0.0, m->kv_rpm_per_v,
					    m->mass_kg, &theta);
					if (jj < best[i])
						best[i] = jj;
				}
			}
		}
		assert_int_equal(cs.n_examined, ref.n_examined);
		for (int why = OPTIM_OK + 1; why < OPTIM_REASON_MAX; why++)
			if (why != OPTIM_NO_ESC && why != OPTIM_NO_BATTERY)
				assert_int_equal(cs.n_fail[why], ref.n_fail[why]);
		/* Each option passing the limits lacks an ESC or a battery, or
		 * is complete. */
		assert_int_equal(cs.n_fail[OPTIM_NO_ESC] + cs.n_fail[OPTIM_NO_BATTERY]
		    + cs.n_feasible, n_pass);
		assert_int_equal(n_found, cs.n_feasible);
		/* Every usable motor's candidate, in catalogue order. */
		int c = 0;
		for (size_t i = 0; i < nm && c < n_cand; i++) {
			const struct catalog_motor *m = catalog_motor(cat, i);
			if (!m->usable)
				continue;
			assert_string_equal(cand[c].id, m->id);
			assert_true(cand[c].j_score == best[i]);
			if (cand[c].feasible)
				assert_true(best[i] < OPTIM_PRUNED);
			c++;
		}
		/* The kept choices: options within the limits, each with its
		 * own parts' J, in order.  (A candidate's best J may be an option
		 * that lacks an ESC or a battery, so it bounds nothing here.) */
		int kept = n_found < 8 ? n_found : 8;
		for (int i = 0; i < kept; i++) {
			double theta;
			double jj = optim_j_score(&t, ch[i].cells,
			    ch[i].prop != NULL ? ch[i].prop->diameter_in
			        : ch[i].motor->integrated_prop_in,
			    ch[i].prop != NULL ? ch[i].prop->pitch_in : 0.0,
			    ch[i].motor->kv_rpm_per_v, ch[i].motor->mass_kg, &theta);
			assert_true(jj == ch[i].j_score);
			assert_true(theta == ch[i].hover_throttle);
			assert_int_equal(optim_limits(&t, ch[i].cells, ch[i].motor,
			    ch[i].prop), OPTIM_OK);
			if (i > 0)
				assert_true(ch[i - 1].j_score <= ch[i].j_score);
		}
		n_passing_targets += n_pass > 0;
		n_feasible_targets += n_found > 0;
	}
	/* The targets reach the shortcuts' far side, not only their cuts. */
	assert_true(n_passing_targets >= SCAN_TARGETS / 4);
	assert_true(n_feasible_targets >= SCAN_TARGETS / 8);
	free(best);
	free(cand);
}

static int
cmp_str(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The example files, sorted; returns how many. */
static int
examples(char **out, int max)
{
	DIR *d = opendir(EXAMPLE_DIR);
	assert_non_null(d);
	int n = 0;
	struct dirent *e;
	while ((e = readdir(d)) != NULL && n < max) {
		size_t len = strlen(e->d_name);
		if (len > 5 && strcmp(e->d_name + len - 5, ".json") == 0) {
			out[n] = xmalloc(len + sizeof EXAMPLE_DIR + 1);
			sprintf(out[n], "%s/%s", EXAMPLE_DIR, e->d_name);
			n++;
		}
	}
	closedir(d);
	qsort(out, (size_t)n, sizeof *out, cmp_str);
	return n;
}

static bool
has_violation(const struct solve_result *r, const char *code)
{
	for (int i = 0; i < r->n_violations; i++)
		if (strcmp(r->violations[i].code, code) == 0)
			return true;
	return false;
}

static void
optim_select_should_close_every_example_with_a_bom_that_sums(void **state)
{
	const struct env_state *s = *state;
	char *files[MAX_EXAMPLES];
	int n = examples(files, MAX_EXAMPLES);
	assert_true(n >= 6);
	int no_parts = 0;
	for (int i = 0; i < n; i++) {
		struct mission_spec m;
		load_mission(s, files[i], &m);
		struct solve_result *r = solve(s, &m);
		/* A design no catalogue combination fits says so, with the
		 * census of why, and is infeasible; every other one closes. */
		if (!r->parts_selected) {
			print_message("%s: no parts selected (NO_PARTS)\n", files[i]);
			assert_true(has_violation(r, "NO_PARTS"));
			assert_false(r->feasible);
			no_parts++;
			free(r);
			free(files[i]);
			continue;
		}
		assert_true(r->closed.ran);
		double sum = 0.0, price = 0.0;
		for (int k = 0; k < r->n_bom; k++) {
			assert_int_equal(r->bom[k].item, k + 1);
			assert_rel(r->bom[k].total_mass_kg,
			    r->bom[k].unit_mass_kg * r->bom[k].qty, 1e-12);
			sum += r->bom[k].total_mass_kg;
			price += r->bom[k].total_price_usd;
		}
		assert_rel(r->bom_mass_kg, sum, 1e-12);
		assert_rel(r->bom_price_usd + 1.0, price + 1.0, 1e-12);
		double mtow = r->bom_mass_kg + r->closed.mass.payload_kg;
		if (fabs(mtow - r->closed.mass.total_kg) > BOM_TOL_KG)
			print_error("%s: BOM + payload %.4f kg, closed MTOW %.4f kg\n",
			    files[i], mtow, r->closed.mass.total_kg);
		assert_true(fabs(mtow - r->closed.mass.total_kg) <= BOM_TOL_KG);
		/* The catalogue lines carry what the closed run flew. */
		assert_rel(r->motor.unit_mass_kg * r->motor.qty, r->closed.mass.motor_kg, 1e-9);
		assert_rel(r->battery.unit_mass_kg * r->battery.qty, r->closed.mass.battery_kg, 1e-9);
		assert_int_equal(r->battery.qty, r->battery_series_packs * r->battery_parallel_packs);
		assert_true(r->n_candidates > 0);
		/* The ESC is rated for the bus: its published cell range, or 6S
		 * when the catalogue gives none. */
		if (r->esc.id[0] != '\0') {
			const struct catalog_esc *e = catalog_find_esc(s->env.cat, r->esc.id);
			assert_non_null(e);
			int cells = r->closed.cell_count;
			assert_true(cells <= (e->cells_max > 0 ? e->cells_max
			    : OPTIM_ESC_UNRATED_MAX_CELLS));
			assert_true(e->cells_min <= 0 || cells >= e->cells_min);
		}
		/* Infeasible real parts are always said so, never silent. */
		if (!r->closed.feasible)
			assert_false(r->feasible);
		free(r);
		free(files[i]);
	}
	/* Only the backpack Mission-Workspace example is allowed to miss. */
	assert_true(no_parts <= 1);
}

static void
optim_select_should_be_deterministic(void **state)
{
	const struct env_state *s = *state;
	struct mission_spec m;
	load_mission(s, EXAMPLE_DIR "/sar_imaging_quad.json", &m);
	struct solve_result *a = solve(s, &m);
	struct solve_result *b = solve(s, &m);
	assert_true(a->parts_selected);
	assert_string_equal(a->motor.id, b->motor.id);
	assert_string_equal(a->prop.id, b->prop.id);
	assert_string_equal(a->battery.id, b->battery.id);
	assert_string_equal(a->esc.id, b->esc.id);
	assert_true(a->motor.j_score == b->motor.j_score);
	assert_true(a->closed.mass.total_kg == b->closed.mass.total_kg);
	assert_int_equal(a->n_bom, b->n_bom);
	assert_memory_equal(a->bom, b->bom, sizeof a->bom[0] * (size_t)a->n_bom);
	assert_int_equal(a->n_candidates, b->n_candidates);
	assert_memory_equal(a->candidates, b->candidates,
	    sizeof a->candidates[0] * (size_t)a->n_candidates);
	assert_int_equal(a->n_violations, b->n_violations);
	free(a);
	free(b);
}

/* The SAR example with part locks ("" = free) and, when cells > 0, a fixed
 * bus, solved with the shipped catalogue. */
static struct solve_result *
solve_sar_locked(const struct env_state *s, const char *motor, const char *prop,
                 const char *battery, int cells)
{
	struct mission_spec m;
	load_mission(s, EXAMPLE_DIR "/sar_imaging_quad.json", &m);
	snprintf(m.locks.motor_part, sizeof m.locks.motor_part, "%s", motor);
	snprintf(m.locks.prop_part, sizeof m.locks.prop_part, "%s", prop);
	snprintf(m.locks.battery_part, sizeof m.locks.battery_part, "%s", battery);
	if (cells > 0) {
		m.nominal_cell_count = cells;
		m.given[SPECF_NOMINAL_CELL_COUNT] = true;
	}
	return solve(s, &m);
}

/* The ESC the ranking picks carries the continuous design's current; the
 * real-parts design of the delivery quad draws more, so the closing
 * upsizes the ESC (as it does a short battery) instead of giving up the
 * best-scoring motor and propeller: the parts kept are the best J of the
 * search, and their ESC carries the closed design's current with margin. */
static void
optim_select_should_upsize_an_esc_the_closed_design_outgrows(void **state)
{
	const struct env_state *s = *state;
	struct mission_spec m;
	load_mission(s, EXAMPLE_DIR "/delivery_quad.json", &m);
	struct solve_result *r = solve(s, &m);
	assert_true(r->parts_selected);
	assert_true(r->feasible);
	double best_j = 1e300;
	for (int i = 0; i < r->n_candidates; i++)
		if (r->candidates[i].feasible && r->candidates[i].j_score < best_j)
			best_j = r->candidates[i].j_score;
	assert_rel(r->motor.j_score, best_j, 1e-12);
	const struct catalog_esc *e = catalog_find_esc(s->env.cat, r->esc.id);
	assert_non_null(e);
	double i_need = OPTIM_CURRENT_MARGIN * r->closed.opt.motor_peak_current_a;
	assert_true(e->continuous_current_a >= i_need);
	/* the ESC set the ranking would pick for the continuous current is
	 * lighter and too small for the closed design */
	bool smaller_exists = false;
	for (size_t i = 0; i < catalog_n_escs(s->env.cat); i++) {
		const struct catalog_esc *x = catalog_esc(s->env.cat, i);
		smaller_exists |= x->usable && x->mass_kg < e->mass_kg
		    && x->continuous_current_a < i_need
		    && x->continuous_current_a >= OPTIM_CURRENT_MARGIN
		        * r->custom.opt.motor_peak_current_a
		        * (double)r->custom.cell_count / (double)r->closed.cell_count;
	}
	assert_true(smaller_exists);
	bool said = false;
	for (int i = 0; i < r->n_rationale; i++)
		said |= strncmp(r->rationale[i], "ESC: ", 5) == 0;
	assert_true(said);
	free(r);
}

static void
optim_select_should_honour_a_motor_lock_by_id(void **state)
{
	struct solve_result *r = solve_sar_locked(*state, "tmotor-u8-ii-kv100", "", "", 0);
	assert_true(r->parts_selected);
	assert_string_equal(r->motor.id, "tmotor-u8-ii-kv100");
	assert_int_equal(r->motor.qty, 4);
	assert_rel(r->closed.mass.motor_kg, 4 * 0.272, 1e-9);
	free(r);
}

static void
optim_select_should_report_an_unknown_part_id(void **state)
{
	struct solve_result *r = solve_sar_locked(*state, "", "no-such-prop-27x9", "", 0);
	assert_false(r->parts_selected);
	assert_false(r->feasible);
	assert_true(has_violation(r, "UNKNOWN_PART"));
	for (int i = 0; i < r->n_violations; i++)
		if (strcmp(r->violations[i].code, "UNKNOWN_PART") == 0) {
			assert_string_equal(r->violations[i].stage, "parts");
			assert_non_null(strstr(r->violations[i].message, "no-such-prop-27x9"));
			assert_true(r->violations[i].n_fixes > 0);
		}
	assert_int_equal(r->n_bom, 0);
	free(r);
}

static void
optim_select_should_explain_when_nothing_fits(void **state)
{
	/* A 3S-only battery lock on a 6S-and-up motor: no bus works. */
	struct solve_result *r = solve_sar_locked(*state, "tmotor-u8-ii-kv100", "",
	    "turnigy-graphene-5000mah-3s-75c", 3);
	assert_false(r->parts_selected);
	assert_true(has_violation(r, "NO_PARTS"));
	assert_false(r->feasible);
	free(r);
}

static void
optim_select_should_let_an_integrated_system_replace_motor_prop_and_esc(void **state)
{
	const struct env_state *s = *state;
	struct mission_spec m;
	load_mission(s, EXAMPLE_DIR "/agri_spray_octo.json", &m);
	snprintf(m.locks.motor_part, sizeof m.locks.motor_part,
	    "hobbywing-xrotor-x8-g2-integrated-system");
	m.nominal_cell_count = 12;
	m.given[SPECF_NOMINAL_CELL_COUNT] = true;
	struct solve_result *r = solve(s, &m);
	assert_true(r->parts_selected);
	assert_string_equal(r->motor.id, "hobbywing-xrotor-x8-g2-integrated-system");
	assert_int_equal(r->motor.qty, 8);
	assert_false(r->prop.chosen);
	assert_false(r->esc.chosen);
	for (int i = 0; i < r->n_bom; i++) {
		assert_string_not_equal(r->bom[i].category, "propeller");
		assert_string_not_equal(r->bom[i].category, "esc");
	}
	assert_true(fabs(r->bom_mass_kg + r->closed.mass.payload_kg
	    - r->closed.mass.total_kg) <= BOM_TOL_KG);
	/* 80 A and 920 W cannot lift this octocopter: said, not hidden. */
	assert_true(has_violation(r, "LOCKED_PART_LIMIT"));
	assert_true(has_violation(r, "MOTOR_CURRENT"));
	assert_false(r->feasible);
	free(r);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(optim_j_score_should_match_the_hand_worked_value,
		    setup_fixture, teardown_fixture),
		cmocka_unit_test_setup_teardown(optim_j_score_should_penalise_hover_throttle_pitch_and_mass,
		    setup_fixture, teardown_fixture),
		cmocka_unit_test_setup_teardown(optim_rank_should_pick_the_hand_checked_parts,
		    setup_fixture, teardown_fixture),
		cmocka_unit_test_setup_teardown(optim_rank_should_prune_each_motor_limit,
		    setup_fixture, teardown_fixture),
		cmocka_unit_test_setup_teardown(optim_rank_should_prune_overlap_tip_mach_and_prop_rpm,
		    setup_fixture, teardown_fixture),
		cmocka_unit_test_setup_teardown(optim_rank_should_respect_the_battery_c_rate_and_chemistry,
		    setup_fixture, teardown_fixture),
		cmocka_unit_test_setup_teardown(optim_rank_should_build_the_bus_from_smaller_packs,
		    setup_fixture, teardown_fixture),
		cmocka_unit_test_setup_teardown(optim_rank_should_honour_a_motor_lock_even_past_its_limit,
		    setup_fixture, teardown_fixture),
		cmocka_unit_test_setup_teardown(optim_rank_should_score_every_usable_motor_for_the_crosshair,
		    setup_fixture, teardown_fixture),
		cmocka_unit_test_setup_teardown(optim_rank_should_agree_with_a_plain_scan_of_every_option,
		    setup_env, teardown_env),
		cmocka_unit_test_setup_teardown(optim_select_should_close_every_example_with_a_bom_that_sums,
		    setup_env, teardown_env),
		cmocka_unit_test_setup_teardown(optim_select_should_be_deterministic,
		    setup_env, teardown_env),
		cmocka_unit_test_setup_teardown(optim_select_should_upsize_an_esc_the_closed_design_outgrows,
		    setup_env, teardown_env),
		cmocka_unit_test_setup_teardown(optim_select_should_honour_a_motor_lock_by_id,
		    setup_env, teardown_env),
		cmocka_unit_test_setup_teardown(optim_select_should_report_an_unknown_part_id,
		    setup_env, teardown_env),
		cmocka_unit_test_setup_teardown(optim_select_should_explain_when_nothing_fits,
		    setup_env, teardown_env),
		cmocka_unit_test_setup_teardown(optim_select_should_let_an_integrated_system_replace_motor_prop_and_esc,
		    setup_env, teardown_env),
	};
	return cmocka_run_group_tests_name("optim", tests, NULL, NULL);
}
