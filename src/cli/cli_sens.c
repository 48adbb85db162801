/* cli_sens.c — `aeroeval sensitivity` (see cli_sens.h). */
#include "cli/cli_sens.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "cli/cli.h"
#include "cli/pipeline.h"
#include "diag/diag.h"
#include "pdf/doc.h"
#include "fs/fsout.h"
#include "input/mission_io.h"
#include "study/sens.h"
#include "study/sens_report.h"
#include "template/template.h"
#include "util/file.h"
#include "util/xalloc.h"

#define SENS_USAGE \
	"usage: aeroeval sensitivity [-o DIR] [--template FILE] [--tsv] MISSION.json\n" \
	"       aeroeval sensitivity --compare-shedding [STATIC.json] DYNAMIC.json\n" \
	"       aeroeval sensitivity --case-row RESULT.json\n"

#define RESULT_MAX_BYTES (64u << 20) /* a result.json is a few hundred kB */
#define SENS_LOCK_WAIT_S 30.0  /* a build writing the same mission, as build waits */

/* Loads a mission; diagnostics on stderr.  0 or 2. */
static int
load_mission(const char *path, const struct cli_env *env, struct mission_spec *s)
{
	struct diag *dg = diag_alloc(stderr);
	int n_err = mission_io_load(path, env->model.chem_names, dg, s);
	diag_flush(dg);
	diag_free(dg);
	return n_err > 0 ? 2 : 0;
}

/* The study of the mission at path: the table on stdout, then
 * sensitivity.json and sensitivity.pdf into DIR/<name>/ beside the
 * mission's build outputs, through the same file-system layer as `build`
 * (pipeline_add()): the same refusals, one set swapped in whole, and a
 * folder `build` still calls its own. */
static int
run_suite(const struct cli_env *env, const char *path, const char *dir_opt,
          const char *tpl_path, int tsv)
{
	struct mission_spec spec;
	if (load_mission(path, env, &spec) != 0)
		return 2;
	char dir[4096], name[256], err[512], date[11];
	if (cli_out_dir("sensitivity", "-o", dir_opt != NULL ? dir_opt : "out", dir,
	    sizeof dir, stderr) != 0 || pipeline_name_checked(path, name, sizeof name, stderr) != 0)
		return 2;
	if (fsout_resolve_date(spec.report.date, date, err, sizeof err) < 0) {
		fprintf(stderr, "%s: error: %s\n", path, err);
		return 2;
	}
	struct template *tpl = cli_template_load(tpl_path, stderr);
	if (tpl == NULL)
		return 2;

	struct sens_result *s = xmalloc(sizeof *s);
	int nominal_bad = sens_run(&spec, &env->model, s);
	if (tsv)
		sens_report_tsv(stdout, s);
	else
		sens_report_text(stdout, s);
	fflush(stdout);
	fprintf(stderr, "sensitivity: %d solves in %.3f s (%.2f ms per solve)\n",
	    s->n_solves, s->seconds, 1e3 * s->seconds / (double)s->n_solves);

	/* A file-system problem is exit 2, like bad input (README.md);
	 * only a failed render is an internal error. */
	int rc = nominal_bad ? 1 : 0, bad = 0;
	char *json = sens_report_json(s, AEROEVAL_VERSION);
	unsigned char *pdf = NULL;
	size_t n = 0;
	if (sens_report_pdf(s, tpl, date, &pdf, &n, err, sizeof err) != 0) {
		fprintf(stderr, "aeroeval: internal error: %s\n", err);
		bad = 3;
	} else if (fsout_mkdirs(dir, err, sizeof err) != 0) {
		fprintf(stderr, "aeroeval: error: %s\n", err);
		bad = 2;
	} else {
		struct pipeline_opts po = { dir, tpl, SENS_LOCK_WAIT_S, NULL };
		struct pipeline_extra x[] = { { PIPELINE_SENS_JSON, json, strlen(json) },
			{ PIPELINE_SENS_PDF, pdf, n } };
		if (pipeline_add(&po, name, x, 2, stderr) != PIPE_FEASIBLE)
			bad = 2;
	}
	free(json);
	free(pdf);
	if (bad == 0)
		fprintf(stderr, "sensitivity: wrote %s/%s/%s and %s\n", dir, name,
		    PIPELINE_SENS_JSON, PIPELINE_SENS_PDF);
	else
		rc = bad;
	free(s);
	template_free(tpl);
	doc_global_cleanup();
	return rc;
}

static int
compare_shedding(const struct cli_env *env, const char *stat_path,
                 const char *dyn_path)
{
	struct mission_spec st, dy;
	if ((stat_path != NULL && load_mission(stat_path, env, &st) != 0)
	    || load_mission(dyn_path, env, &dy) != 0)
		return 2;
	struct sens_shedding sh;
	sens_shedding(stat_path ? &st : NULL, &dy, &env->model, &sh);
	if (!sh.ok) {
		fprintf(stderr, "sensitivity: a shedding run did not converge\n");
		return 1;
	}
	printf("mtow_static_kg=%.3f\nmtow_dynamic_kg=%.3f\n", sh.mtow_static_kg,
	    sh.mtow_dynamic_kg);
	printf("energy_static_wh=%.1f\nenergy_dynamic_wh=%.1f\nenergy_saving_pct=%.1f\n",
	    sh.energy_static_wh, sh.energy_dynamic_wh, 100.0 * sh.energy_saving);
	printf("structure_static_kg=%.3f\nstructure_dynamic_kg=%.3f\n"
	    "structure_saving_pct=%.1f\n", sh.frame_static_kg, sh.frame_dynamic_kg,
	    100.0 * sh.frame_saving);
	printf("avg_mass_dynamic_kg=%.3f\navg_mass_reduction_pct=%.1f\n",
	    sh.avg_mass_dynamic_kg, 100.0 * sh.avg_mass_reduction);
	return 0;
}

/* A number at a path of nested objects, or NAN. */
static double
num_at(const cJSON *o, const char *const *keys)
{
	for (; *keys != NULL && o != NULL; keys++)
		o = cJSON_GetObjectItemCaseSensitive(o, *keys);
	return cJSON_IsNumber(o) ? o->valuedouble : NAN;
}

static int
case_row(const char *path)
{
	unsigned char *buf = NULL;
	size_t n = 0;
	char err[512];
	if (file_read(path, RESULT_MAX_BYTES, &buf, &n, err, sizeof err) != 0) {
		fprintf(stderr, "aeroeval: error: %s\n", err);
		return 2;
	}
	cJSON *root = cJSON_ParseWithLength((const char *)buf, n);
	free(buf);
	if (root == NULL) {
		fprintf(stderr, "%s: error: not a result.json\n", path);
		return 2;
	}
	static const char *const k_mtow[] = { "custom", "total_mass_kg", NULL };
	static const char *const k_d[] = { "continuous_optimum", "prop_diameter_in", NULL };
	static const char *const k_p[] = { "continuous_optimum", "prop_pitch_in", NULL };
	static const char *const k_kv[] = { "continuous_optimum", "motor_kv", NULL };
	static const char *const k_s[] = { "custom", "cell_count", NULL };
	static const char *const k_c[] = { "custom", "battery_capacity_mah", NULL };
	static const char *const k_it[] = { "custom", "iterations", NULL };
	const cJSON *cu = cJSON_GetObjectItemCaseSensitive(root, "custom");
	const cJSON *conv = cJSON_GetObjectItemCaseSensitive(cu, "converged");
	const cJSON *status = cJSON_GetObjectItemCaseSensitive(root, "status");
	double v[] = { num_at(root, k_mtow), num_at(root, k_d), num_at(root, k_p),
		num_at(root, k_kv), num_at(root, k_s), num_at(root, k_c),
		num_at(root, k_it) };
	int rc = 0;
	for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
		if (!isfinite(v[i]))
			rc = 2;
	if (rc == 0)
		printf("mtow_kg=%.2f prop=%.1fx%.1f kv=%.0f battery=%.0fS_%.0fmAh "
		    "iterations=%.0f converged=%s status=%s\n", v[0], v[1], v[2], v[3],
		    v[4], v[5], v[6], cJSON_IsTrue(conv) ? "yes" : "no",
		    cJSON_IsString(status) ? status->valuestring : "?");
	else
		fprintf(stderr, "%s: error: result.json lacks a custom run\n", path);
	cJSON_Delete(root);
	return rc;
}

int
cli_sensitivity(int argc, char **argv)
{
	const char *dir = NULL, *tpl = NULL, *files[2] = { NULL, NULL };
	int n_files = 0, shedding = 0, row = 0, tsv = 0;
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
			dir = argv[++i];
		else if (strcmp(argv[i], "--template") == 0 && i + 1 < argc)
			tpl = argv[++i];
		else if (strcmp(argv[i], "--compare-shedding") == 0)
			shedding = 1;
		else if (strcmp(argv[i], "--case-row") == 0)
			row = 1;
		else if (strcmp(argv[i], "--tsv") == 0)
			tsv = 1;
		else if (argv[i][0] == '-' || n_files == 2) {
			fputs(SENS_USAGE, stderr);
			return 2;
		} else
			files[n_files++] = argv[i];
	}
	if (n_files == 0 || (n_files == 2 && !shedding) || (shedding && row)) {
		fputs(SENS_USAGE, stderr);
		return 2;
	}
	if (row)
		return case_row(files[0]);
	struct cli_env *env = xcalloc(1, sizeof *env);
	int rc = cli_env_load(env, NULL, 0, stderr);
	if (rc == 0) {
		if (shedding)
			rc = compare_shedding(env, n_files == 2 ? files[0] : NULL,
			    files[n_files - 1]);
		else
			rc = run_suite(env, files[0], dir, tpl, tsv);
	}
	cli_env_free(env);
	free(env);
	return rc;
}
