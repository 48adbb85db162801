/* bench.c — in-process solve time per mission (`make bench`, not a test).
 *
 * usage: build/bench [-n SOLVES] MISSION.json...   (from the repository root)
 * Loads the shipped data once, parses each mission once, then solves it
 * SOLVES times (default 200) and prints one table row per mission: the
 * median, the fastest and the slowest solve, the median of SOLVES solves
 * without the parts catalogue (the continuous design only: no parts
 * selection, no BOM-closed run), the endurance explorer that the outputs
 * ask for after the solve (engine_explore(), median of 20), and the time
 * to render result.json (median of 20), in microseconds.  Ends with the
 * medians over all missions and the peak resident memory of this process.
 *
 * usage: build/bench -c parts|noparts MISSION.json
 * One solve of the mission (with or without the parts catalogue) inside
 * counted_solve(), for `valgrind --tool=callgrind
 * --toggle-collect=counted_solve`: the instructions the calling thread
 * spends on it, which repeat (to within 0.2 %: whether the solve waits
 * for the baseline's thread) where wall times drift (bench.sh, part 5).  The solve is engine_solve_unhelped(): all of the parts search
 * on the calling thread, as without the helper, whose share varies.
 */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "cli/cli.h"
#include "core/diag.h"
#include "engine/engine.h"
#include "output/fsout.h"
#include "input/mission_io.h"
#include "output/result_json.h"
#include "util/xalloc.h"

#define RENDERS 20 /* result.json renders timed per mission */

static double
now_us(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec * 1e6 + (double)t.tv_nsec * 1e-3;
}

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static double
median(double *v, int n)
{
	qsort(v, (size_t)n, sizeof *v, cmp_double);
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* The solve callgrind counts (-c); not inlined, so that it has a name. */
void counted_solve(const struct mission_spec *spec, const struct cli_env *env,
                   const struct catalog *cat, struct solve_result *r);
__attribute__((noinline)) void
counted_solve(const struct mission_spec *spec, const struct cli_env *env,
              const struct catalog *cat, struct solve_result *r)
{
	engine_solve(spec, &env->model, cat, r);
}

/* -c MODE MISSION: one counted solve; 0 when it ran. */
static int
count_one(const char *mode, const char *path)
{
	bool parts = strcmp(mode, "parts") == 0;
	if (!parts && strcmp(mode, "noparts") != 0) {
		fprintf(stderr, "bench: -c takes parts or noparts\n");
		return 2;
	}
	struct cli_env *env = xcalloc(1, sizeof *env);
	if (cli_env_load(env, NULL, 1, stderr) != 0)
		return 2;
	struct diag *dg = diag_alloc(stderr);
	struct mission_spec spec;
	int n_err = mission_io_load(path, env->model.chem_names, dg, &spec);
	diag_flush(dg);
	diag_free(dg);
	if (n_err != 0)
		return 2;
	struct solve_result *r = xcalloc(1, sizeof *r);
	counted_solve(&spec, env, parts ? env->cat : NULL, r);
	free(r);
	cli_env_free(env);
	free(env);
	return 0;
}

int
main(int argc, char **argv)
{
	if (argc == 4 && strcmp(argv[1], "-c") == 0)
		return count_one(argv[2], argv[3]);
	int n_solves = 200, first = 1;
	if (argc > 2 && strcmp(argv[1], "-n") == 0) {
		n_solves = atoi(argv[2]);
		first = 3;
	}
	if (first >= argc || n_solves < 1) {
		fprintf(stderr, "usage: bench [-n SOLVES] MISSION.json...\n");
		return 2;
	}
	struct cli_env *env = xcalloc(1, sizeof *env);
	if (cli_env_load(env, NULL, 1, stderr) != 0)
		return 2;
	struct solve_result *r = xmalloc(sizeof *r);
	double *t = xmalloc((size_t)(n_solves > RENDERS ? n_solves : RENDERS) * sizeof *t);
	double *meds = xmalloc((size_t)argc * sizeof *meds);
	double *meds_noparts = xmalloc((size_t)argc * sizeof *meds_noparts);
	int n_meds = 0;

	printf("%-32s %10s %10s %10s %12s %11s %10s  %s\n", "mission", "median_us",
	    "min_us", "max_us", "noparts_us", "explore_us", "render_us", "status");
	for (int a = first; a < argc; a++) {
		struct diag *dg = diag_alloc(stderr);
		struct mission_spec spec;
		int n_err = mission_io_load(argv[a], env->model.chem_names, dg, &spec);
		diag_flush(dg);
		diag_free(dg);
		if (n_err != 0)
			continue;
		for (int i = 0; i < n_solves; i++) {
			double t0 = now_us();
			memset(r, 0, sizeof *r);
			engine_solve(&spec, &env->model, env->cat, r);
			t[i] = now_us() - t0;
		}
		qsort(t, (size_t)n_solves, sizeof *t, cmp_double);
		double lo = t[0], hi = t[n_solves - 1], med = median(t, n_solves);
		/* The same mission without a catalogue, before the render so
		 * that r holds the solve with parts when it is rendered. */
		for (int i = 0; i < n_solves; i++) {
			double t0 = now_us();
			memset(r, 0, sizeof *r);
			engine_solve(&spec, &env->model, NULL, r);
			t[i] = now_us() - t0;
		}
		double med_noparts = median(t, n_solves);
		memset(r, 0, sizeof *r);
		engine_solve(&spec, &env->model, env->cat, r);
		for (int i = 0; i < RENDERS; i++) {
			double t0 = now_us();
			engine_explore(r, &env->model);
			t[i] = now_us() - t0;
		}
		double med_explore = median(t, RENDERS);
		for (int i = 0; i < RENDERS; i++) {
			double t0 = now_us();
			struct result_json_faults jf;
			free(result_json_render_checked(r, "bench", &jf));
			t[i] = now_us() - t0;
		}
		const char *base = strrchr(argv[a], '/');
		printf("%-32s %10.0f %10.0f %10.0f %12.0f %11.0f %10.0f  %s\n",
		    base ? base + 1 : argv[a], med, lo, hi, med_noparts, med_explore,
		    median(t, RENDERS), r->feasible ? "feasible" : "infeasible");
		meds_noparts[n_meds] = med_noparts;
		meds[n_meds++] = med;
	}
	struct rusage ru;
	getrusage(RUSAGE_SELF, &ru);
	if (n_meds > 0)
		printf("%-32s %10.0f %10s %10s %12.0f\n", "median of the medians",
		    median(meds, n_meds), "", "", median(meds_noparts, n_meds));
	printf("peak RSS of the bench process: %ld KiB\n", ru.ru_maxrss);
	free(meds_noparts);
	free(meds);
	free(t);
	free(r);
	cli_env_free(env);
	free(env);
	return 0;
}
