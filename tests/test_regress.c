/* test_regress.c — replays every input in tests/regress/ (see its README):
 * missions that once broke a promise of the solve (an internal error, a
 * violation without a reason, a non-finite number).  Each is solved with
 * the shipped data and must pass solve_check(): finite numbers, and a
 * feasible result that passes every check or an infeasible one that says
 * why.  Under `make asan` a crash, leak or UB here fails the run.
 * Run from the repository root (as `make test` does).
 */
#include "test_util.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "solve_check.h"
#include "util/file.h"
#include "util/xalloc.h"

#define REGRESS_DIR "tests/regress"

static struct cli_env *env;
static struct solve_result *res;

/* Solves the mission file at path (its bytes b[0..n)); it must pass. */
static void
replay_solve(const char *path, const unsigned char *b, size_t n)
{
	char detail[RESULT_JSON_PATH_MAX];
	const char *why = solve_text(env, path, (const char *)b, n, stderr, res,
	    detail, sizeof detail);
	if (why != NULL) { /* solve- inputs are valid missions */
		print_error("%s: %s (%s)\n", path, why, detail);
		fail();
	}
}

static void
regress_solve_inputs_should_give_finite_consistent_results(void **state)
{
	(void)state;
	env = xcalloc(1, sizeof *env);
	res = xmalloc(sizeof *res);
	assert_int_equal(cli_env_load(env, NULL, 1, stderr), 0);
	DIR *d = opendir(REGRESS_DIR);
	assert_non_null(d);
	int count = 0;
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		if (strncmp(e->d_name, "solve-", 6) != 0)
			continue;
		char path[512], msg[512];
		snprintf(path, sizeof path, "%s/%s", REGRESS_DIR, e->d_name);
		unsigned char *b = NULL;
		size_t n = 0;
		if (file_read(path, 16u << 20, &b, &n, msg, sizeof msg) != 0) {
			print_error("%s\n", msg);
			fail();
		}
		replay_solve(path, b, n);
		free(b);
		count++;
	}
	closedir(d);
	printf("regress: %d solve inputs\n", count);
	assert_true(count >= 7);   /* the inputs of tests/regress/README.md */
	cli_env_free(env);
	free(env);
	free(res);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(regress_solve_inputs_should_give_finite_consistent_results),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
