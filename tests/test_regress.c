/* test_regress.c — replays every input in tests/regress/ (see its README):
 * inputs that once crashed, hung, leaked or broke a promise of a reader or
 * of the solve.  Under `make asan` a crash, leak or UB here fails the run.
 * Run from the repository root (as `make test` does).
 */
#include "test_util.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/catalog.h"
#include "cli/cli.h"
#include "input/cohort.h"
#include "core/diag.h"
#include "input/catalog_io.h"
#include "output/fsout.h"
#include "input/mission_io.h"
#include "solve_check.h"
#include "util/file.h"
#include "util/xalloc.h"

#define REGRESS_DIR "tests/regress"

/* Calls fn(path, bytes, n) for every file of REGRESS_DIR named prefix*;
 * returns how many there were. */
static int
each_input(const char *prefix,
           void (*fn)(const char *path, const unsigned char *b, size_t n))
{
	DIR *d = opendir(REGRESS_DIR);
	assert_non_null(d);
	int count = 0;
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		if (strncmp(e->d_name, prefix, strlen(prefix)) != 0)
			continue;
		char path[512], msg[512];
		snprintf(path, sizeof path, "%s/%s", REGRESS_DIR, e->d_name);
		unsigned char *b = NULL;
		size_t n = 0;
		if (file_read(path, 16u << 20, &b, &n, msg, sizeof msg) != 0) {
			print_error("%s\n", msg);
			fail();
		}
		fn(path, b, n);
		free(b);
		count++;
	}
	closedir(d);
	return count;
}

static void
replay_mission(const char *path, const unsigned char *b, size_t n)
{
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	mission_io_parse(path, (const char *)b, n, catalog_default_chemistries,
	    dg, &s);
	diag_free(dg);
}

static void
regress_mission_inputs_should_parse_or_be_rejected_cleanly(void **state)
{
	(void)state;
	printf("regress: %d mission inputs\n", each_input("mission-", replay_mission));
}

static void
replay_cohort(const char *path, const unsigned char *b, size_t n)
{
	struct cohort c;
	cohort_parse(path, (const char *)b, n, &c);
	for (size_t i = 0; i < c.n_rows; i++)
		assert_true(c.rows[i].takeoff_mass_kg > 0);
	cohort_free(&c);
}

static void
regress_cohort_inputs_should_parse_or_be_rejected_cleanly(void **state)
{
	(void)state;
	printf("regress: %d cohort inputs\n", each_input("cohort-", replay_cohort));
}

static void
copy_file(const char *from, const char *to)
{
	unsigned char *b = NULL;
	size_t n = 0;
	char msg[512];
	assert_int_equal(file_read(from, 16u << 20, &b, &n, msg, sizeof msg), 0);
	FILE *f = fopen(to, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(b, 1, n, f), n);
	fclose(f);
	free(b);
}

static void
replay_catalog(const char *path, const unsigned char *b, size_t n)
{
	static const char *const files[4] = { "motors.json", "propellers.json",
		"batteries.json", "escs.json" };
	char dir[] = "/tmp/aeroeval-regress-XXXXXX", p[128], q[128];
	assert_non_null(mkdtemp(dir));
	for (int k = 0; k < 4; k++) {
		snprintf(p, sizeof p, "data/catalog/%s", files[k]);
		snprintf(q, sizeof q, "%s/%s", dir, files[k]);
		copy_file(p, q);
	}
	if (n > 0) {
		snprintf(q, sizeof q, "%s/%s", dir, files[b[0] % 4]);
		FILE *f = fopen(q, "wb");
		assert_non_null(f);
		assert_int_equal(fwrite(b + 1, 1, n - 1, f), n - 1);
		fclose(f);
	}
	struct diag *dg = diag_alloc(NULL);
	struct catalog *c = catalog_io_load(dir, NULL, dg, NULL);
	int n_err = diag_n_errors(dg);
	diag_free(dg);
	if ((c == NULL) != (n_err > 0)) {
		print_error("%s: catalog_io_load returned %p with %d errors\n", path,
		    (void *)c, n_err);
		fail();
	}
	catalog_free(c);
	for (int k = 0; k < 4; k++) {
		snprintf(q, sizeof q, "%s/%s", dir, files[k]);
		unlink(q);
	}
	rmdir(dir);
}

static void
regress_catalog_inputs_should_load_or_be_rejected_cleanly(void **state)
{
	(void)state;
	printf("regress: %d catalogue inputs\n", each_input("catalog-", replay_catalog));
}

static struct cli_env *env;
static struct solve_result *res;

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
	printf("regress: %d solve inputs\n", each_input("solve-", replay_solve));
	cli_env_free(env);
	free(env);
	free(res);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(regress_mission_inputs_should_parse_or_be_rejected_cleanly),
		cmocka_unit_test(regress_cohort_inputs_should_parse_or_be_rejected_cleanly),
		cmocka_unit_test(regress_catalog_inputs_should_load_or_be_rejected_cleanly),
		cmocka_unit_test(regress_solve_inputs_should_give_finite_consistent_results),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
