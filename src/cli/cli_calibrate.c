/* cli_calibrate.c — `aeroeval calibrate` (see cli_calibrate.h). */
#include "cli/cli_calibrate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/batch.h"
#include "cli/cli.h"
#include "fs/fsout.h"
#include "input/cohort.h"
#include "input/model_io.h"
#include "study/calibrate.h"
#include "util/xalloc.h"

#define CALIBRATE_USAGE "usage: aeroeval calibrate [--write FILE] COHORT.csv\n"

/* Progress of `calibrate` on stderr, at most once a second (in a test
 * build AEROEVAL_PROGRESS_S overrides the interval; tests use 0): redrawn
 * in place on a terminal, one line each time otherwise (a log). */
struct progress_line {
	double t0, last;    /* start, last line (batch_now_s) */
	double every_s;     /* the interval */
	int tty;            /* stderr is a terminal */
	int shown;          /* a line is on screen (tty) */
};

static void
progress_init(struct progress_line *pl)
{
	pl->t0 = pl->last = batch_now_s();
	pl->every_s = 1.0;
#ifdef AEROEVAL_TEST_HOOKS
	const char *env = getenv("AEROEVAL_PROGRESS_S");
	char *end;
	if (env != NULL) {
		double s = strtod(env, &end);
		if (*end == '\0' && s >= 0.0)
			pl->every_s = s;
	}
#endif
	pl->tty = isatty(STDERR_FILENO);
	pl->shown = 0;
}

static void
show_progress(void *ctx, size_t stage, size_t row, size_t n_rows, size_t n_solves)
{
	struct progress_line *pl = ctx;
	double now = batch_now_s();
	if (now - pl->last < pl->every_s)
		return;
	pl->last = now;
	if (stage == 0)
		fprintf(stderr, "%scalibrate: fit on %zu rows, %zu sized, %zu solves, %.0f s%s",
		        pl->tty ? "\r\033[K" : "", n_rows, row, n_solves, now - pl->t0,
		        pl->tty ? "" : "\n");
	else
		fprintf(stderr, "%scalibrate: leave-one-out %zu of %zu, %zu solves, %.0f s%s",
		        pl->tty ? "\r\033[K" : "", stage, n_rows + 1, n_solves,
		        now - pl->t0, pl->tty ? "" : "\n");
	pl->shown = pl->tty;
}

int
cli_calibrate(int argc, char **argv)
{
	const char *write = NULL, *path = NULL;
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "--write") == 0 && i + 1 < argc)
			write = argv[++i];
		else if (argv[i][0] == '-' || path != NULL) {
			fputs(CALIBRATE_USAGE, stderr);
			return 2;
		} else
			path = argv[i];
	}
	if (path == NULL) {
		fputs(CALIBRATE_USAGE, stderr);
		return 2;
	}
	struct cli_env *env = xcalloc(1, sizeof *env);
	struct cohort c;
	memset(&c, 0, sizeof c);
	int rc = cli_cohort_load(path, env, &c);
	struct calibrate_result cr;
	memset(&cr, 0, sizeof cr);
	if (rc == 0) {
		struct progress_line pl;
		progress_init(&pl);
		struct calibrate_progress pg = { show_progress, &pl };
		int st = calibrate_fit(&c, &env->model, true, &pg, &cr);
		if (pl.shown)
			fputs("\r\033[K", stderr);
		if (st == -1) {
			fprintf(stderr, "%s: error: no row gives a converged mission to fit on\n", path);
			rc = 2;
		} else if (st != 0) {
			fprintf(stderr, "%s: internal error: the minimiser failed (status %d)\n",
			    path, cr.lsq_status);
			rc = 3;
		}
	}
	if (rc == 0) {
		double before[CAL_N_PARAMS];
		calibrate_theta(&cr.before, before);
		printf("Calibration on %s: %zu of %zu rows (the validate rule; rows it skips "
		    "are left out): %zu in the forward check, %zu with a published dry mass\n",
		    path, cr.n_rows, c.n_rows, cr.n_forward, cr.n_dry);
		printf("%-40s %10s %10s %10s %5s\n", "coefficient", "prior", "before", "after", "rows");
		for (int j = 0; j < CAL_N_PARAMS; j++) {
			if (j == 0)
				printf("The power chain, fitted on the forward check's endurance:\n");
			else if (j == CAL_FIRST_MASS)
				printf("The mass laws, fitted on the dry mass at the real takeoff mass:\n");
			printf("  %-38s %10.4g %10.4g %10.4g %5zu%s\n", calibrate_param_name(j),
			    calibrate_prior[j], before[j], cr.theta[j], cr.n_per_param[j],
			    calibrate_lo[j] == calibrate_hi[j] ? "  held"
			    : cr.n_per_param[j] < CALIBRATE_MIN_ROWS ? "  prior (too few rows)"
			    : cr.at_bound[j] ? "  AT ITS BOUND" : "");
		}
		printf("small-platform wiring coefficient: %.4g -> %.4g kg/(A m)\n",
		    cr.before.wire_coef_small, cr.after.wire_coef_small);
		printf("Forward check, in sample: endurance MAPE %.1f %% at the priors, "
		    "%.1f %% fitted\n", cr.forward_before_pct, cr.forward_after_pct);
		printf("Dry mass at the real mass, in sample: MAPE %.1f %% at the priors, "
		    "%.1f %% fitted (%zu LM iterations, %zu evaluations, mu %.2g)\n",
		    cr.dry_before_pct, cr.dry_after_pct, cr.n_iter, cr.n_evals, CALIBRATE_MU);
		printf("Closed loop, in sample: MTOW MAPE %.1f %% over %zu of %zu rows sized\n",
		    cr.mtow_mape_pct, cr.n_sized, cr.n_sizable);
		const struct model_spread *sp[] = { &cr.after.forward, &cr.after.dry };
		static const char *const sp_name[] = { "forward-check endurance",
			"dry mass at the real mass" };
		for (int i = 0; i < 2; i++)
			if (sp[i]->n > 0)
				printf("Leave-one-out, %s: MAPE %.1f %% over %d figures; %.0f %% "
				    "interval x%.3f to x%.3f, %.0f %% of the figures inside\n",
				    sp_name[i], sp[i]->mape_pct, sp[i]->n, 100.0 * CALIBRATE_LEVEL,
				    exp(sp[i]->log_lo), exp(sp[i]->log_hi), 100.0 * sp[i]->coverage);
		for (int b = 0; b < MODEL_BASIS_MAX; b++) {
		const struct model_accuracy *a = &cr.after.accuracy[b];
		printf("Leave-one-out, %s: MTOW MAPE %.1f %% over %d rows sized, battery "
		    "mass MAPE %.1f %% over %d rows\n", b == MODEL_PACK_LOCKED
		    ? "published packs locked" : "batteries sized from the endurance",
		    a->loo_mape_pct, a->n_rows, a->loo_battery_mape_pct, a->n_battery);
		if (a->valid) {
			printf("%.0f %% prediction interval on the takeoff mass (split conformal): "
			    "x%.3f to x%.3f pooled (%d rows)", 100.0 * a->level,
			    exp(a->pooled.log_lo), exp(a->pooled.log_hi), a->pooled.n);
			for (int k = 0; k < AF_CLASS_MAX; k++)
				if (a->cls[k].n > 0)
					printf("; %s x%.3f to x%.3f (%d rows)", spec_enum_airframe[k],
					    exp(a->cls[k].log_lo), exp(a->cls[k].log_hi), a->cls[k].n);
			printf("; %.0f %% of the rows inside\n", 100.0 * a->coverage);
			printf("Each design's own interval (its loop gain and mass shares, "
			    "the other rows' spreads): %.0f %% of %d rows inside, median width "
			    "x%.2f end to end\n", 100.0 * a->design_coverage, a->design_rows,
			    a->design_width);
		} else {
			printf("Too few rows sized for a %.0f %% interval\n", 100.0 * a->level);
		}
		}
		if (write != NULL) {
			char *txt = model_io_calibration_json(&cr.after);
			char err[512];
			if (fsout_write_atomic(write, txt, strlen(txt), err, sizeof err) != 0) {
				fprintf(stderr, "error: %s\n", err);
				rc = 2;
			} else {
				printf("wrote %s\n", write);
			}
			free(txt);
		}
		if (rc == 0)
			rc = cli_cohort_rejected(path, &c);
	}
	calibrate_result_free(&cr);
	cohort_free(&c);
	cli_env_free(env);
	free(env);
	return rc;
}
