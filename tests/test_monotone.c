/* test_monotone.c — the sized mass never falls when a requirement grows.
 *
 * The continuous design is the lightest aircraft that meets every
 * requirement of its mission (engine.c, sizing.c): the least fixed point of
 * the mass loop, minimised over the propeller share, the series count
 * inside the current budget, and every check passed.  An aircraft sized
 * for a harder mission also flies the easier one, so the easier one's
 * lightest aircraft is never heavier.  This test holds that property over
 * MONO_N seeded missions (payload 0-8 kg, wheelbase 0.3-1.6 m, 4, 6 or 8
 * rotors, three classes, the imaging role, goal relaxation off) and eight
 * requirements, each made harder in turn: hover time, forward time,
 * payload, the largest payload, altitude, ambient temperature, the T/W
 * requirement and the auxiliary power.  A harder mission's design may not
 * weigh more than MONO_TOL less, and a mission a harder one closes must
 * close too (feasibility never appears as a requirement grows).
 */
#include "test_util.h"
#include "test_missions.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "engine/engine.h"
#include "util/stats.h"
#include "util/xalloc.h"

#if defined(__SANITIZE_ADDRESS__)
#define MONO_N 150  /* the sanitizer pass runs ~3x slower; the full count
                       runs in the plain pass (make test runs both) */
#else
#define MONO_N 500
#endif
#define MONO_TOL 0.005   /* 0.5 %: the loop's own convergence is 1 g */
#define MONO_SEED 0x6d6f6e6fu

static struct cli_env *env;
static struct solve_result *res;

enum req { R_HOVER, R_FORWARD, R_PAYLOAD, R_MAX_PAYLOAD, R_ALTITUDE,
	R_AMBIENT, R_TW, R_AUX, R_MAX };
static const char *const req_name[R_MAX] = { "hover time", "forward time",
	"payload", "largest payload", "altitude", "ambient temperature",
	"T/W requirement", "auxiliary power" };

static int
setup(void **state)
{
	(void)state;
	env = xcalloc(1, sizeof *env);
	res = xmalloc(sizeof *res);
	return cli_env_load(env, NULL, 0, stderr) == 0 ? 0 : -1;
}

static int
teardown(void **state)
{
	(void)state;
	cli_env_free(env);
	free(env);
	free(res);
	return 0;
}

/* A seeded mission over the space. */
static void
draw(struct stats_rng *g, struct mission_spec *s)
{
	static const int rotors[] = { 4, 6, 8 };
	static const int classes[] = { AF_MICRO_AIO, AF_CONSUMER_FOLDING,
		AF_ENTERPRISE_RUGGED };
	int cls = classes[stats_rng_below(g, 3)];
	double payload = stats_rng_uniform(g, 0.0, 8.0);
	double wheelbase = stats_rng_uniform(g, 0.3, 1.6);
	if (cls == AF_MICRO_AIO) {
		payload = fmin(payload, 0.8);
		wheelbase = fmin(wheelbase, 0.5);
	}
	struct test_profile pr = { payload, wheelbase, rotors[stats_rng_below(g, 3)],
		cls, stats_rng_uniform(g, 300.0, 1800.0), 0.0,
		stats_rng_uniform(g, 0.0, 1.0) < 0.5 ? 0.0 : stats_rng_uniform(g, 60.0, 900.0),
		2.0, 10.0, ROLE_IMAGING };
	test_mission(s, &pr);
	SET(s, ALTITUDE_M, altitude_m, stats_rng_uniform(g, 0.0, 3000.0));
	SET(s, AMBIENT_TEMP_C, ambient_temp_c, stats_rng_uniform(g, -10.0, 35.0));
	SET(s, LOCK_AUTO_REDUCE, locks.auto_reduce_flight_time, false);
}

/* The mission one step harder in requirement q. */
static void
harder(struct mission_spec *s, enum req q)
{
	switch (q) {
	case R_HOVER:
		SET(s, T_HOVER_S, t_hover_s, 1.15 * s->t_hover_s + 30.0);
		break;
	case R_FORWARD:
		SET(s, T_FORWARD_S, t_forward_s, 1.2 * s->t_forward_s + 60.0);
		break;
	case R_PAYLOAD:
		SET(s, PAYLOAD_KG, payload_kg, 1.1 * s->payload_kg + 0.1);
		break;
	case R_MAX_PAYLOAD:
		SET(s, MAX_PAYLOAD_KG, max_payload_kg, 1.2 * s->payload_kg + 0.2);
		break;
	case R_ALTITUDE:
		SET(s, ALTITUDE_M, altitude_m, s->altitude_m + 500.0);
		break;
	case R_AMBIENT:
		SET(s, AMBIENT_TEMP_C, ambient_temp_c, s->ambient_temp_c + 8.0);
		break;
	case R_TW:
		/* T/W 2.5 (the imaging default) to 2.8, asked explicitly */
		SET(s, ROLE_THRUST_MARGIN, payload_role.thrust_margin_override,
		    1.0 - 1.0 / sqrt(2.8));
		break;
	case R_AUX:
		SET(s, ROLE_AUX_POWER_W, payload_role.aux_power_w, 30.0);
		break;
	default:
		break;
	}
}

/* The easier side of requirement q's pair: what the draw leaves open,
 * asked for explicitly where the harder side names a value. */
static void
easier(struct mission_spec *s, enum req q)
{
	if (q == R_TW)
		SET(s, ROLE_THRUST_MARGIN, payload_role.thrust_margin_override,
		    1.0 - 1.0 / sqrt(2.5));
	else if (q == R_AUX)
		SET(s, ROLE_AUX_POWER_W, payload_role.aux_power_w, 10.0);
}

/* Solve s (no catalogue: the continuous design); true when it sized:
 * converged, flown as asked, every check passed. */
static bool
sized(const struct mission_spec *s, double *mass_kg)
{
	memset(res, 0, sizeof *res);
	res->skip_ceiling = true;
	int rc = engine_solve(s, &env->model, NULL, res);
	assert_int_equal(rc, 0);
	const struct res_run *o = &res->custom;
	*mass_kg = o->mass.total_kg;
	return o->ran && o->converged && o->feasible && o->time_scale == 1.0;
}

static void
sized_mass_should_never_fall_when_a_requirement_grows(void **state)
{
	(void)state;
	struct stats_rng g;
	stats_rng_seed(&g, MONO_SEED);
	int pairs[R_MAX] = { 0 }, n_sized = 0;
	for (int i = 0; i < MONO_N; i++) {
		struct mission_spec base;
		draw(&g, &base);
		double m0;
		bool s0 = sized(&base, &m0);
		n_sized += s0;
		for (int q = 0; q < R_MAX; q++) {
			struct mission_spec a = base, b = base;
			double ma = m0, mb;
			bool sa = s0;
			/* The easier side is the drawn mission itself, but where the
			 * pair names its value. */
			if (q == R_TW || q == R_AUX) {
				easier(&a, (enum req)q);
				sa = sized(&a, &ma);
			}
			harder(&b, (enum req)q);
			bool sb = sized(&b, &mb);
			if (sb && !sa)
				fail_msg("%s: the easier mission does not size, the harder "
				    "one does (mission %d)", req_name[q], i);
			if (!sa || !sb)
				continue;
			pairs[q]++;
			if (mb < ma * (1.0 - MONO_TOL))
				fail_msg("%s: %.4f kg -> %.4f kg (mission %d)", req_name[q],
				    ma, mb, i);
		}
	}
	print_message("monotone: %d missions, %d sized; pairs compared:", MONO_N,
	    n_sized);
	for (int q = 0; q < R_MAX; q++)
		print_message(" %s %d%s", req_name[q], pairs[q], q + 1 < R_MAX ? "," : "\n");
	/* Enough designs size for the property to say something. */
	for (int q = 0; q < R_MAX; q++)
		assert_true(pairs[q] >= MONO_N / 4);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sized_mass_should_never_fall_when_a_requirement_grows),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
