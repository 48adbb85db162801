/* solve_check.h — what every solve must satisfy, whatever the mission:
 * shared by the random-mission sweep (test_sweep.c), the regression replay
 * (test_regress.c) and the whole-solve fuzzer (fuzz/fuzz_solve.c).
 *
 * solve_check() renders result.json and bom.csv (checked) and returns NULL
 * when
 *  - engine_solve() returned 0 (no non-finite value caught inside),
 *  - result.json and bom.csv render without a non-finite or out-of-range
 *    value,
 *  - a feasible result ran the custom design and passed every custom check,
 *  - an infeasible result carries at least one violation, and every
 *    violation has a non-empty message;
 * else a static sentence naming the first broken promise, with the JSON
 * path, check name or violation code concerned in detail[0..n) ("" if none).
 */
#ifndef AEROEVAL_SOLVE_CHECK_H
#define AEROEVAL_SOLVE_CHECK_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/bom_csv.h"
#include "cli/cli.h"
#include "diag/diag.h"
#include "engine/engine.h"
#include "input/mission_io.h"
#include "result/result.h"
#include "formats/result_json.h"

static const char *
solve_check(int engine_rc, const struct solve_result *r, char *detail, size_t n)
{
	snprintf(detail, n, "%s", "");
	if (engine_rc != 0) {
		snprintf(detail, n, "%.150s", r->internal_error);
		return "engine_solve reported an internal error";
	}
	struct result_json_faults jf;
	char *json = result_json_render_checked(r, "check", &jf);
	free(json);
	if (jf.n_invalid != 0) {
		snprintf(detail, n, "%s", jf.first_path);
		return "result.json holds a non-finite or out-of-range value";
	}
	int csv_bad = 0;
	free(bom_csv_render_checked(r, NULL, &csv_bad));
	if (csv_bad != 0)
		return "bom.csv holds a non-finite value";
	for (int i = 0; i < r->n_violations; i++)
		if (r->violations[i].message[0] == '\0') {
			snprintf(detail, n, "%s", r->violations[i].code);
			return "a violation has an empty message";
		}
	if (r->feasible) {
		if (!r->custom.ran)
			return "feasible but the custom run did not run";
		/* An advisory check (the reference's resonances) may fail. */
		for (int i = 0; i < r->custom.n_checks; i++)
			if (!r->custom.checks[i].pass && !r->custom.checks[i].advisory) {
				snprintf(detail, n, "%s", r->custom.checks[i].name);
				return "feasible but a custom check fails";
			}
	} else if (r->n_violations < 1) {
		return "infeasible without any violation";
	}
	return NULL;
}

/* What solve_text() returns for a mission the reader rejects. */
static const char solve_rejected[] = "the mission was rejected";

/* Parse text[0..len) as the mission file `file` (diagnostics to diag_out,
 * NULL: kept quiet), solve it into *r with env's data and check it as
 * above (the explorer included, as the outputs ask for it).  Returns
 * NULL, solve_rejected, or solve_check()'s sentence. */
static const char *
solve_text(const struct cli_env *env, const char *file, const char *text,
           size_t len, FILE *diag_out, struct solve_result *r, char *detail,
           size_t n)
{
	struct diag *dg = diag_alloc(diag_out);
	struct mission_spec spec;
	int n_err = mission_io_parse(file, text, len, env->model.chem_names, dg,
	    &spec);
	diag_flush(dg);
	diag_free(dg);
	snprintf(detail, n, "%s", "");
	if (n_err != 0)
		return solve_rejected;
	memset(r, 0, sizeof *r);
	int rc = engine_solve(&spec, &env->model, env->cat, r);
	engine_explore(r, &env->model); /* as the outputs do */
	return solve_check(rc, r, detail, n);
}

#endif
