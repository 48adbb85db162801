/* pipeline.c — compile one mission (see pipeline.h). */
#include "cli/pipeline.h"

#include <stdlib.h>
#include <string.h>

#include "output/bom_csv.h"
#include "core/diag.h"
#include "engine/engine.h"
#include "output/fsout.h"
#include "input/mission_io.h"
#include "output/report.h"
#include "study/sens.h"
#include "study/sens_report.h"
#include "core/template.h"
#include "output/result_json.h"
#include "util/sha256.h"
#include "util/xalloc.h"

int
pipeline_name(const char *path, char *out, size_t n)
{
	return fsout_safe_name(path, out, n);
}

enum pipeline_status
pipeline_solve(const struct cli_env *env, const char *path,
               struct solve_result *r, FILE *err, unsigned char **bytes,
               size_t *n_bytes)
{
	unsigned char *buf = NULL;
	size_t n = 0;
	struct diag *dg = diag_alloc(err);
	/* Read here rather than by mission_io_load: the bytes are hashed and
	 * attached to the dossier too. */
	if (json_in_read(path, MISSION_IO_MAX_BYTES, dg, &buf, &n) != 0) {
		diag_flush(dg);
		diag_free(dg);
		return PIPE_REJECTED;
	}
	struct mission_spec spec;
	int n_err = mission_io_parse(path, (const char *)buf, n,
	    env->model.chem_names, dg, &spec);
	diag_flush(dg);
	diag_free(dg);
	if (n_err > 0) {
		free(buf);
		return PIPE_REJECTED;
	}
	memset(r, 0, sizeof *r);
	int rc = engine_solve(&spec, &env->model, env->cat, r);
	engine_explore(r, &env->model);
	sha256_hex(buf, n, r->input_sha256);
	memcpy(r->catalogue_sha256, env->catalogue_sha256, sizeof r->catalogue_sha256);
	if (bytes != NULL) {
		*bytes = buf;
		*n_bytes = n;
	} else {
		free(buf);
	}
	if (rc != 0) {
		fprintf(err, "%s: internal error: a non-finite value reached the result\n", path);
		return PIPE_INTERNAL;
	}
	return r->feasible ? PIPE_FEASIBLE : PIPE_INFEASIBLE;
}

/* Write one output file atomically into dir. */
static int
put(const char *dir, const char *file, const void *data, size_t n, FILE *err)
{
	char path[4608], msg[512];
	snprintf(path, sizeof path, "%.4400s/%s", dir, file);
	if (fsout_write_atomic(path, data, n, msg, sizeof msg) != 0) {
		fprintf(err, "%s: error: %s\n", path, msg);
		return -1;
	}
	return 0;
}

/* The dossier's trade-study section (report_section_fn). */
static int
sensitivity_section(struct doc *d, const struct template *t, const void *arg)
{
	return sens_report_section(d, t, arg);
}

enum pipeline_status
pipeline_build(const struct cli_env *env, const struct pipeline_opts *o,
               const char *path, FILE *err)
{
	char name[256], dir[4400], msg[512];
	if (pipeline_name(path, name, sizeof name) != 0) {
		fprintf(err, "%s: error: the file name cannot name an output folder "
		    "(use letters, digits, '.', '_' and '-')\n", path);
		return PIPE_REJECTED;
	}
	struct solve_result *r = xmalloc(sizeof *r);
	unsigned char *bytes = NULL;
	size_t n_bytes = 0;
	enum pipeline_status st = pipeline_solve(env, path, r, err, &bytes, &n_bytes);
	if (st == PIPE_REJECTED || st == PIPE_INTERNAL)
		goto done;

	/* Render everything in memory first: a render failure writes nothing. */
	struct result_json_faults jf;
	int csv_bad = 0;
	char *json = result_json_render_checked(r, AEROEVAL_VERSION, &jf);
	char *csv = bom_csv_render_checked(r, &csv_bad);
	unsigned char *pdf = NULL;
	size_t n_pdf = 0;
	if (jf.n_invalid > 0 || csv_bad > 0) {
		fprintf(err, "%s: internal error: non-finite value at %s\n", path,
		    jf.n_invalid > 0 ? jf.first_path : "bom.csv");
		st = PIPE_INTERNAL;
		goto written;
	}
	if (o->tpl != NULL) {
		/* The dossier date: report.date, else SOURCE_DATE_EPOCH, else the
		 * mission file's mtime — never the wall clock. */
		char date[16];
		if (fsout_resolve_date(r->mission.report.date, path, date, msg,
		    sizeof msg) < 0) {
			fprintf(err, "%s: error: %s\n", path, msg);
			st = PIPE_REJECTED;
			goto written;
		}
		const char *base = strrchr(path, '/');
		/* The trade study only when the template asks for its section. */
		struct sens_result *sens = NULL;
		if (template_section_enabled(o->tpl, TEMPLATE_SEC_SENSITIVITY)) {
			sens = xmalloc(sizeof *sens);
			sens_run(&r->mission, &env->model, sens);
		}
		struct report_input in = { r, o->tpl, name, base ? base + 1 : path,
			bytes, n_bytes, date, AEROEVAL_VERSION, env->cat,
			sens != NULL ? sensitivity_section : NULL, sens };
		int rr = report_render(&in, &pdf, &n_pdf, msg, sizeof msg);
		free(sens);
		if (rr != 0) {
			fprintf(err, "%s: internal error: dossier: %s\n", path, msg);
			st = PIPE_INTERNAL;
			goto written;
		}
	}
	snprintf(dir, sizeof dir, "%s/%s", o->out_dir, name);
	if (fsout_mkdirs(dir, msg, sizeof msg) != 0) {
		fprintf(err, "%s: error: %s\n", dir, msg);
		st = PIPE_INTERNAL;
	} else if (put(dir, "bom.csv", csv, strlen(csv), err) != 0
	    || put(dir, "result.json", json, strlen(json), err) != 0
	    || (pdf != NULL && put(dir, "dossier.pdf", pdf, n_pdf, err) != 0)) {
		st = PIPE_INTERNAL;
	}
written:
	free(pdf);
	free(json);
	free(csv);
done:
	free(bytes);
	free(r);
	return st;
}
