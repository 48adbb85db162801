/* test_sweep.c — thousands of random but plausible missions through the
 * whole solve (issue 9).
 *
 * A fixed-seed generator (stats_rng) draws missions over every role,
 * airframe class and shipped chemistry, 3-16 rotors (coaxial when even),
 * locks (battery, voltage, propeller, KV), altitude 0-5000 m, ambient
 * -20..45 degC, payload 0-30 kg on a wheelbase that grows with the payload.
 * Each mission is written as JSON and parsed as a mission file is, solved
 * with the shipped data (run from the repository root, as `make test`
 * does), and must pass solve_check(): no NaN or Infinity anywhere in
 * result.json, a feasible result passes every custom check, an infeasible
 * one says why in at least one non-empty violation, and the violations
 * come run by run (baseline, custom, closed).
 *
 * On a sample, physics that must hold whatever the engine's details:
 * more payload never lowers the takeoff mass, 5000 m never needs less
 * mass than sea level, a warmer day never gives the same pack a cooler
 * peak — compared only between converged, feasible continuous designs
 * flown as requested (no goal relaxation), so a design that changed
 * regime is not compared.  The pairs are solved without the catalogue:
 * what they compare is the continuous design, which no parts search
 * changes.
 *
 * No hang: every solve must finish within SWEEP_MAX_SOLVE_S.
 *
 * The search's shortcuts give the exhaustive result on SWEEP_SAME_PARTS
 * (170; 3 under ASan) missions of the draw whose parts are searched and
 * SWEEP_SAME (30; 3 under ASan) beyond reach: 200 in all.
 *
 * Counts: SWEEP_N missions (1000) and SWEEP_PAIRS pairs per property (30),
 * each pair drawn until it settles: about 2100 solves, 200 of them
 * exhaustive.  Under ASan (make test runs both builds) 100 missions
 * and 8 pairs: there the sweep looks for memory errors and undefined
 * behaviour on the paths random missions take, which a tenth of the
 * missions reaches at a quarter of the cost.
 */
#include "test_util.h"


#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <time.h>

#include "cli/cli.h"
#include "solve_check.h"
#include "util/file.h"
#include "util/stats.h"
#include "util/xalloc.h"

#ifndef SWEEP_N /* -DSWEEP_N=... -DSWEEP_PAIRS=... for a longer run */
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SWEEP_N 100
#define SWEEP_PAIRS 8
#define SWEEP_MAX_SOLVE_S 10.0
#else
#define SWEEP_N 1000
#define SWEEP_PAIRS 30
#endif
#endif
/* Missions solved twice, with and without the search's shortcuts: this
 * many whose parts are searched (the parts search takes most of them),
 * and this many beyond reach. */
#ifndef SWEEP_SAME
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SWEEP_SAME_PARTS 3
#define SWEEP_SAME 3
#else
#define SWEEP_SAME_PARTS 170
#define SWEEP_SAME 30
#endif
#endif
#ifndef SWEEP_SAME_PARTS
#define SWEEP_SAME_PARTS SWEEP_SAME
#endif
#ifndef SWEEP_MAX_SOLVE_S
#define SWEEP_MAX_SOLVE_S 2.0 /* a solve slower than this is a hang (worst seen: 0.1 s) */
#endif
#define SWEEP_SEED 0x5eedae20u

/* What the generator chooses; rendered to mission JSON by mission_text(). */
struct sweep_mission {
	int role;              /* enum role_type */
	int cls;               /* enum airframe_class */
	double payload_kg;
	double wheelbase_m;
	int rotors;
	bool coaxial;
	int chem;              /* index into the model's chemistries */
	double altitude_m;
	double ambient_c;
	bool has_ambient;
	double t_hover_s, t_climb_s, t_forward_s;
	double v_forward_ms;   /* 0 = "auto" */
	bool lock_battery, lock_voltage, lock_prop, lock_kv;
	double lock_capacity_mah;
	int lock_cells;
	double lock_diameter_in, lock_pitch_in, lock_kv_value;
};

static struct cli_env *env;
/* The same data without the catalogue: the pairs compare continuous
 * designs, which never wait for a parts search. */
static struct cli_env *env_continuous;
static struct solve_result *res;

static bool
chance(struct stats_rng *g, double p)
{
	return stats_rng_uniform(g, 0, 1) < p;
}

static void
draw(struct stats_rng *g, struct sweep_mission *m)
{
	memset(m, 0, sizeof *m);
	m->role = (int)stats_rng_below(g, ROLE_MAX);
	switch (m->role) {
	case ROLE_RACING:
		m->cls = AF_MICRO_AIO;
		m->payload_kg = stats_rng_uniform(g, 0, 0.5);
		break;
	case ROLE_AGRICULTURE:
		m->cls = AF_AGRICULTURAL;
		m->payload_kg = stats_rng_uniform(g, 2, 30);
		break;
	default:
		m->cls = (int)stats_rng_below(g, AF_CLASS_MAX);
		m->payload_kg = m->cls == AF_MICRO_AIO ? stats_rng_uniform(g, 0, 0.8)
		    : m->cls == AF_CONSUMER_FOLDING ? stats_rng_uniform(g, 0, 3)
		    : stats_rng_uniform(g, 0, 30);
		break;
	}
	/* Wheelbase roughly as built: ~0.5 m at 1 kg, ~1.8 m at 20 kg. */
	m->wheelbase_m = (0.2 + 0.35 * sqrt(m->payload_kg))
	    * stats_rng_uniform(g, 0.8, 1.4);
	if (m->cls == AF_MICRO_AIO && m->wheelbase_m > 0.45)
		m->wheelbase_m = stats_rng_uniform(g, 0.15, 0.45);
	m->rotors = 3 + (int)stats_rng_below(g, 14);
	m->coaxial = m->rotors % 2 == 0 && m->rotors >= 6 && chance(g, 0.3);
	m->chem = (int)stats_rng_below(g, (uint64_t)env->model.n_chem);
	m->altitude_m = chance(g, 0.3) ? 0 : stats_rng_uniform(g, 0, 5000);
	m->has_ambient = chance(g, 0.8);
	m->ambient_c = stats_rng_uniform(g, -20, 45);
	m->t_hover_s = stats_rng_uniform(g, 60, 1500);
	m->t_climb_s = stats_rng_uniform(g, 0, 120);
	m->t_forward_s = chance(g, 0.5) ? 0 : stats_rng_uniform(g, 60, 1500);
	m->v_forward_ms = chance(g, 0.3) ? 0 : stats_rng_uniform(g, 4, 20);
	m->lock_voltage = chance(g, 0.15);
	m->lock_battery = chance(g, 0.1);
	m->lock_prop = chance(g, 0.1);
	m->lock_kv = chance(g, 0.1);
	m->lock_cells = 2 + (int)stats_rng_below(g, 13);
	m->lock_capacity_mah = stats_rng_uniform(g, 500, 4000) * (1 + m->payload_kg);
	/* a propeller that fits the wheelbase more often than not */
	m->lock_diameter_in = stats_rng_uniform(g, 0.3, 0.9) * m->wheelbase_m / 0.0254
	    * sin(M_PI / (m->coaxial ? m->rotors / 2 : m->rotors));
	m->lock_diameter_in = fmin(fmax(m->lock_diameter_in, 2), 60);
	m->lock_pitch_in = m->lock_diameter_in * stats_rng_uniform(g, 0.3, 0.6);
	m->lock_kv_value = stats_rng_uniform(g, 100,
	    m->cls == AF_MICRO_AIO ? 3000 : 1200);
}

/* The mission as a mission file would say it. */
static void
mission_text(const struct sweep_mission *m, char *buf, size_t n)
{
	char speed[32], ambient[48], locks[512];
	if (m->v_forward_ms > 0)
		snprintf(speed, sizeof speed, "%.6g", m->v_forward_ms);
	else
		snprintf(speed, sizeof speed, "\"auto\"");
	ambient[0] = '\0';
	if (m->has_ambient)
		snprintf(ambient, sizeof ambient, "\"ambient_temp_c\": %.6g,", m->ambient_c);
	snprintf(locks, sizeof locks,
	    "\"locks\": {\"is_battery_locked\": %s, \"locked_capacity_mah\": %.6g,"
	    " \"locked_cell_count\": %d, \"is_voltage_locked\": %s,"
	    " \"locked_series_cells\": %d, \"is_prop_locked\": %s,"
	    " \"locked_diameter_in\": %.6g, \"locked_pitch_in\": %.6g,"
	    " \"is_motor_locked\": %s, \"locked_kv\": %.6g}",
	    m->lock_battery ? "true" : "false", m->lock_capacity_mah, m->lock_cells,
	    m->lock_voltage ? "true" : "false", m->lock_cells,
	    m->lock_prop ? "true" : "false", m->lock_diameter_in, m->lock_pitch_in,
	    m->lock_kv ? "true" : "false", m->lock_kv_value);
	snprintf(buf, n,
	    "{\"payload_kg\": %.6g, \"max_diameter_m\": %.6g, \"num_rotors\": %d,"
	    " \"coaxial_layout\": %s, \"airframe_class\": \"%s\","
	    " \"t_hover_s\": %.6g, \"t_climb_s\": %.6g, \"t_forward_s\": %.6g,"
	    " \"v_forward_ms\": %s, \"altitude_m\": %.6g, %s"
	    " \"battery_chemistry\": \"%s\", %s,"
	    " \"payload_role\": {\"type\": \"%s\"}}",
	    m->payload_kg, m->wheelbase_m, m->rotors, m->coaxial ? "true" : "false",
	    spec_enum_airframe[m->cls], m->t_hover_s, m->t_climb_s, m->t_forward_s,
	    speed, m->altitude_m, ambient, env->model.chem_names[m->chem], locks,
	    spec_enum_role[m->role]);
}

/* Parse and solve; fails the test if the mission text is not valid or the
 * result breaks solve_check().  Returns the result (static storage). */
static const struct solve_result *
solve_in(const struct cli_env *e, const struct sweep_mission *m)
{
	char text[2048], detail[RESULT_JSON_PATH_MAX];
	mission_text(m, text, sizeof text);
	struct timespec t0, t1;
	clock_gettime(CLOCK_MONOTONIC, &t0);
	const char *why = solve_text(e, "sweep.json", text, strlen(text), stderr,
	    res, detail, sizeof detail);
	clock_gettime(CLOCK_MONOTONIC, &t1);
	double took_s = (double)(t1.tv_sec - t0.tv_sec)
	    + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
	if (why == NULL && took_s > SWEEP_MAX_SOLVE_S)
		why = "the solve took too long (a hang?)";
	if (why != NULL) {
		print_error("%s (%s)\nmission: %s\n", why, detail, text);
		fail();
	}
	return res;
}

static const struct solve_result *
solve(const struct sweep_mission *m)
{
	return solve_in(env, m);
}

/* A design worth comparing: converged, feasible, flown as requested. */
static bool
settled(const struct solve_result *r)
{
	return r->feasible && r->custom.ran && r->custom.converged
	    && r->custom.time_scale == 1.0;
}

static int
setup(void **state)
{
	(void)state;
	env = xcalloc(1, sizeof *env);
	env_continuous = xcalloc(1, sizeof *env_continuous);
	res = xmalloc(sizeof *res);
	return cli_env_load(env, NULL, 1, stderr) == 0
	    && cli_env_load(env_continuous, NULL, 0, stderr) == 0 ? 0 : -1;
}

static int
teardown(void **state)
{
	(void)state;
	cli_env_free(env);
	free(env);
	cli_env_free(env_continuous);
	free(env_continuous);
	free(res);
	return 0;
}

/* Where a run's violations come in the list: baseline, custom, closed. */
static int
run_rank(const char *run)
{
	return strcmp(run, "baseline") == 0 ? 0 : strcmp(run, "custom") == 0 ? 1 : 2;
}

/* The missions of the draw that take a shortcut of the search, with
 * their result.json, kept for sweep_shortcuts_should_give_the_exhaustive_
 * result (which solves them again without the shortcuts). */
struct kept {
	struct sweep_mission m;
	int i;                 /* its place in the draw */
	char *fast;            /* result.json with the shortcuts */
};
static struct kept kept[SWEEP_SAME_PARTS + SWEEP_SAME];
static int n_kept_parts, n_kept_ceiling;

/* Keeps mission m (drawn i-th, solved to r) when it takes a shortcut and
 * its kind still has room: its parts are searched, or it is beyond reach
 * and its ceiling's bisection moved (a longer flight or some payload
 * sizes). */
static void
keep_if_shortcut(const struct sweep_mission *m, int i, const struct solve_result *r)
{
	bool parts = r->parts_selected && n_kept_parts < SWEEP_SAME_PARTS;
	bool ceiling = r->ceiling.valid && n_kept_ceiling < SWEEP_SAME
	    && (r->ceiling.time_scale > r->ceiling.min_time_scale
	    || r->ceiling.max_payload_kg > 0.0);
	if (!parts && !ceiling)
		return;
	struct kept *k = &kept[n_kept_parts + n_kept_ceiling];
	n_kept_parts += parts;
	n_kept_ceiling += !parts;
	k->m = *m;
	k->i = i;
	k->fast = result_json_render(r, "sweep");
	assert_non_null(k->fast);
}

static void
sweep_random_missions_should_give_finite_consistent_results(void **state)
{
	(void)state;
	struct stats_rng g;
	stats_rng_seed(&g, SWEEP_SEED);
	int n_feasible = 0, n_converged = 0, n_parts = 0, n_both = 0;
	for (int i = 0; i < SWEEP_N; i++) {
		struct sweep_mission m;
		draw(&g, &m);
		const struct solve_result *r = solve(&m);
		n_feasible += r->feasible;
		n_converged += r->custom.ran && r->custom.converged;
		/* Its violations come run by run: baseline, custom, closed. */
		bool seen[3] = { false, false, false };
		for (int k = 0; k < r->n_violations; k++) {
			int at = run_rank(r->violations[k].run);
			for (int later = at + 1; later < 3; later++)
				assert_false(seen[later]);
			seen[at] = true;
		}
		n_both += seen[0] && seen[1];
		n_parts += r->parts_selected;
		keep_if_shortcut(&m, i, r);
	}
	printf("sweep: %d missions, %d feasible, %d converged, %d with parts, "
	    "%d with baseline and custom violations\n", SWEEP_N, n_feasible,
	    n_converged, n_parts, n_both);
	assert_true(n_both > SWEEP_N / 100);
	/* A sweep that is all infeasible would test little: keep it honest.
	 * The generator is deliberately harsh (tiny propellers on many
	 * rotors, 50-minute missions, Li-S packs): about a quarter of its
	 * missions run away physically, and about 11 % close feasibly (114
	 * of the 1000). */
	assert_true(n_feasible > SWEEP_N / 50);
}



/* Draws a mission (adjusted by `prepare`, may be NULL) that settles,
 * records what `measure` reads from it, lets `vary` change it (returns
 * false to skip the pair), solves again and requires `holds(before,
 * after)`; `what` names the quantity. */
static void
compare_pairs(uint64_t seed, const char *what,
              void (*prepare)(struct sweep_mission *),
              double (*measure)(const struct solve_result *),
              bool (*vary)(struct sweep_mission *),
              bool (*holds)(double before, double after))
{
	struct stats_rng g;
	stats_rng_seed(&g, seed);
	int compared = 0;
	for (int i = 0; i < SWEEP_PAIRS; i++) {
		/* Draw until both designs of the pair settle: a pair where the
		 * change pushes the design into a runaway says nothing about the
		 * direction of a settled design's change. */
		struct sweep_mission m;
		const struct solve_result *r = NULL;
		double before = 0.0;
		bool paired = false;
		for (int k = 0; k < 200 && !paired; k++) {
			draw(&g, &m);
			m.has_ambient = true;
			if (prepare != NULL)
				prepare(&m);
			r = solve_in(env_continuous, &m);
			if (!settled(r))
				continue;
			before = measure(r);
			if (!vary(&m))
				continue;
			r = solve_in(env_continuous, &m);
			paired = settled(r);
		}
		assert_true(paired);
		compared++;
		double after = measure(r);
		if (!holds(before, after)) {
			char text[2048];
			mission_text(&m, text, sizeof text);
			print_error("%s %.9g after the change, %.9g before: %s\n", what,
			    measure(r), before, text);
			fail();
		}
	}
	printf("sweep: %s pairs compared: %d\n", what, compared);
	assert_int_equal(compared, SWEEP_PAIRS);
}

static double
mtow_kg(const struct solve_result *r)
{
	return r->custom.mass.total_kg;
}

static double
peak_battery_c(const struct solve_result *r)
{
	return r->custom.max_battery_temp_c;
}

static bool
rises(double before, double after)
{
	return after > before;
}

static bool
does_not_fall(double before, double after)
{
	return after >= before * (1 - 1e-9);
}

static bool
more_payload(struct sweep_mission *m)
{
	m->payload_kg += 0.05 + 0.1 * m->payload_kg;
	return true;
}

static void
at_sea_level(struct sweep_mission *m)
{
	m->altitude_m = 0;
}

static bool
to_5000_m(struct sweep_mission *m)
{
	m->altitude_m = 5000;
	return true;
}

static bool
warmer_day(struct sweep_mission *m)
{
	m->ambient_c += 5;
	return m->ambient_c <= 45;
}

/* The pack held: its capacity and series count locked, so that the warmer
 * day flies the same pack.  A design sized afresh may answer a warmer day
 * with a larger pack that runs cooler (seen: 52.6 -> 60.0 Ah, 58.0 ->
 * 57.6 degC at +5 degC), which is the sizing meeting its limits, not the
 * physics the property is about. */
static void
same_pack(struct sweep_mission *m)
{
	m->lock_battery = true;
	m->lock_voltage = true;
}

static void
sweep_more_payload_should_raise_mtow(void **state)
{
	(void)state;
	compare_pairs(SWEEP_SEED + 1, "MTOW (payload up)", NULL, mtow_kg, more_payload,
	    rises);
}

static void
sweep_high_altitude_should_not_lower_mtow(void **state)
{
	(void)state;
	compare_pairs(SWEEP_SEED + 2, "MTOW (5000 m)", at_sea_level, mtow_kg, to_5000_m,
	    does_not_fall);
}

static void
sweep_warmer_day_should_raise_peak_battery_temperature(void **state)
{
	(void)state;
	compare_pairs(SWEEP_SEED + 3, "peak battery temperature (+5 degC, same pack)",
	    same_pack, peak_battery_c, warmer_day, rises);
}

/* The search's shortcuts (a closing already made is not made again; a
 * ranking at an aim already ranked at is not made again; a pack pick
 * stops at the first pack of its bus that fits; a ceiling's
 * bisection steps ask only whether some propeller share passes) give
 * what the exhaustive search gives (AEROEVAL_TEST_EXHAUSTIVE), result.json
 * byte for byte, on the missions of the draw that take them (kept by
 * sweep_random_missions_should_give_finite_consistent_results, which runs
 * first):
 * SWEEP_SAME_PARTS whose parts are searched and SWEEP_SAME beyond reach
 * whose ceiling's bisection moved.  Only these are solved again, so the
 * check costs their exhaustive solves alone. */
static void
sweep_shortcuts_should_give_the_exhaustive_result(void **state)
{
	(void)state;
	assert_int_equal(n_kept_parts, SWEEP_SAME_PARTS);
	assert_int_equal(n_kept_ceiling, SWEEP_SAME);
	for (int k = 0; k < n_kept_parts + n_kept_ceiling; k++) {
		setenv("AEROEVAL_TEST_EXHAUSTIVE", "1", 1);
		const struct solve_result *r = solve(&kept[k].m);
		unsetenv("AEROEVAL_TEST_EXHAUSTIVE");
		char *full = result_json_render(r, "sweep");
		assert_non_null(full);
		if (strcmp(kept[k].fast, full) != 0) {
			char text[2048];
			mission_text(&kept[k].m, text, sizeof text);
			print_error("mission %d of the draw differs with the "
			    "shortcuts:\n%s\n", kept[k].i, text);
			fail();
		}
		free(full);
		free(kept[k].fast);
		kept[k].fast = NULL;
	}
	printf("sweep: the same exhaustively: %d with parts, %d beyond reach\n",
	    n_kept_parts, n_kept_ceiling);
}

/* The FPV racer example's search fails every closing on its first banks of
 * packs and goes on to wider ones, ranking again at the aims it ranked at
 * before, which the search answers from the rankings it made: the same
 * result.json as the exhaustive search (where the random draws seldom
 * reach that far). */
static void
sweep_wider_bank_search_should_give_the_exhaustive_result(void **state)
{
	(void)state;
	const char *path = "examples/fpv_racing_quad.json";
	unsigned char *text;
	size_t len;
	char err[256], detail[RESULT_JSON_PATH_MAX];
	assert_int_equal(file_read(path, (size_t)1 << 20, &text, &len, err, sizeof err), 0);
	char *json[2];
	for (int exhaustive = 0; exhaustive < 2; exhaustive++) {
		if (exhaustive)
			setenv("AEROEVAL_TEST_EXHAUSTIVE", "1", 1);
		const char *why = solve_text(env, path, (const char *)text, len, stderr,
		    res, detail, sizeof detail);
		unsetenv("AEROEVAL_TEST_EXHAUSTIVE");
		if (why != NULL && why != solve_rejected)
			print_error("%s (%s)\n", why, detail);
		assert_null(why);
		assert_true(res->parts_selected);
		json[exhaustive] = result_json_render(res, "fpv_racing_quad");
		assert_non_null(json[exhaustive]);
	}
	assert_string_equal(json[0], json[1]);
	free(json[0]);
	free(json[1]);
	free(text);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sweep_random_missions_should_give_finite_consistent_results),
		cmocka_unit_test(sweep_shortcuts_should_give_the_exhaustive_result),
		cmocka_unit_test(sweep_wider_bank_search_should_give_the_exhaustive_result),
		cmocka_unit_test(sweep_more_payload_should_raise_mtow),
		cmocka_unit_test(sweep_high_altitude_should_not_lower_mtow),
		cmocka_unit_test(sweep_warmer_day_should_raise_peak_battery_temperature),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
