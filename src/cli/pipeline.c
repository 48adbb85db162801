/* pipeline.c — compile one mission (see pipeline.h). */
#include "cli/pipeline.h"

#include <stdlib.h>
#include <string.h>

#include "formats/ardupilot.h"
#include "formats/bom_csv.h"
#include "diag/diag.h"
#include "engine/engine.h"
#include "fs/fsfolder.h"
#include "fs/fsout.h"
#include "formats/index.h"
#include "input/mission_io.h"
#include "pdf/report.h"
#include "study/sens.h"
#include "study/sens_report.h"
#include "template/template.h"
#include "formats/result_json.h"
#include "util/sha256.h"
#include "util/file.h"
#include "util/strbuf.h"
#include "util/text.h"
#include "util/xalloc.h"

int
pipeline_name(const char *path, char *out, size_t n)
{
	return fsout_safe_name(path, out, n);
}

int
pipeline_name_checked(const char *path, char *out, size_t n, FILE *err)
{
	int nr = pipeline_name(path, out, n);
	if (nr == -2)
		fprintf(err, "%s: error: the file name is too long to name an output "
		    "folder (at most %d characters before \".json\")\n", path, FSOUT_NAME_MAX);
	else if (nr == -3) {
		char list[128];
		text_join(index_file_names, list, sizeof list);
		fprintf(err, "%s: error: the file name would name the output folder after one "
		    "of the table's files beside it (%s); rename the mission\n", path, list);
	}
	else if (nr != 0)
		fprintf(err, "%s: error: the file name cannot name an output folder "
		    "(use letters, digits, '.', '_' and '-', not first a '.')\n", path);
	return nr;
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
	int n_err = mission_io_parse_mission(path, (const char *)buf, n,
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
		fprintf(err, "%s: internal error: %s\n", path, r->internal_error);
		return PIPE_INTERNAL;
	}
	return r->feasible ? PIPE_FEASIBLE : PIPE_INFEASIBLE;
}

/* The files of DIR/<name>/: the outputs in the order they are written,
 * the stamp that vouches for them, then the sensitivity study's files
 * (pipeline_add()).  Not every set has every output: no dossier without a
 * template, no ArduPilot hand-off for a design that is not buildable
 * (formats/ardupilot.h). */
enum pipeline_output { OUT_BOM, OUT_TOTALS, OUT_RESULT, OUT_DOSSIER, OUT_COMPONENTS,
	OUT_PARAMS, OUT_QGC_PARAMS, N_OUTPUTS };
static const char *const pipeline_files[] = { "bom.csv", "bom_totals.csv", "result.json",
	"dossier.pdf", "vehicle_components.json", "ardupilot.param", "qgroundcontrol.params",
	PIPELINE_STAMP, PIPELINE_SENS_JSON, PIPELINE_SENS_PDF, NULL };
_Static_assert(sizeof pipeline_files / sizeof pipeline_files[0] == N_OUTPUTS + 4,
               "one name per output, the stamp, the study's two, NULL");

/* One set of outputs; data[i] is NULL for an output not in the set. */
struct out_set {
	const void *data[N_OUTPUTS];
	size_t len[N_OUTPUTS];
};

/* The stamp's text: the fingerprint of the inputs, the verdict and the
 * SHA-256 of every output in the set, so "up to date" can prove the files
 * are the ones this stamp was written with, and that none is missing or
 * extra. */
static void
stamp_text(struct strbuf *sb, const char *fp, int infeasible,
           char hex[N_OUTPUTS][SHA256_HEX_LEN], const bool present[N_OUTPUTS])
{
	strbuf_reset(sb);
	strbuf_printf(sb, "%sfingerprint %s\nstatus %s\n", PIPELINE_STAMP_MAGIC, fp,
	    infeasible ? "infeasible" : "feasible");
	for (int i = 0; i < N_OUTPUTS; i++)
		if (present[i])
			strbuf_printf(sb, "sha256 %s %s\n", hex[i], pipeline_files[i]);
}

int
pipeline_current(const struct pipeline_opts *o, const char *name, const char *fp)
{
	struct fsfolder f;
	char msg[512], stamp[4096], hex[N_OUTPUTS][SHA256_HEX_LEN];
	bool present[N_OUTPUTS];
	size_t n = 0;
	int rc = -1;
	if (fsfolder_open(&f, o->out_dir, name, pipeline_files, FSFOLDER_NOWAIT, 0.0,
	    msg, sizeof msg) != 0)
		goto done;
	fsfolder_clean(&f, FSFOLDER_STALE_S);
	if (!fsfolder_exists(&f)
	    || fsfolder_read(&f, PIPELINE_STAMP, stamp, sizeof stamp, &n) != 0)
		goto done;
	/* The outputs found are hashed; the stamp must list exactly those. */
	for (int i = 0; i < N_OUTPUTS; i++)
		present[i] = fsfolder_hash(&f, pipeline_files[i], hex[i]) == 0;
	if (!present[OUT_BOM] || !present[OUT_TOTALS] || !present[OUT_RESULT]
	    || present[OUT_DOSSIER] != (o->tpl != NULL))
		goto done;
	struct strbuf want = STRBUF_INIT;
	for (int inf = 0; inf < 2 && rc < 0; inf++) {
		stamp_text(&want, fp, inf, hex, present);
		if (want.len == n && memcmp(want.data, stamp, n) == 0)
			rc = inf;
	}
	strbuf_free(&want);
done:
	fsfolder_close(&f);
	return rc;
}

void
pipeline_clean(const struct pipeline_opts *o, const char *name)
{
	struct fsfolder f;
	char msg[512];
	if (fsfolder_open(&f, o->out_dir, name, pipeline_files, FSFOLDER_NOWAIT, 0.0,
	    msg, sizeof msg) == 0)
		fsfolder_clean(&f, FSFOLDER_STALE_S);
	fsfolder_close(&f);
}

/* True when file is the name of one of the n files of x. */
static bool
is_among(const char *file, const struct pipeline_extra *x, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (strcmp(x[i].file, file) == 0)
			return true;
	return false;
}

/* Writes the n files of x as one new set of out_dir/name (fsfolder.h), each
 * synced but the stamp (a stamp lost in a power cut costs a recompile
 * only); with keep, the folder's other files are carried over as they
 * are.  A file-system problem is one line on err and -1, with the folder
 * as it was. */
static int
replace_set(const struct pipeline_opts *o, const char *name,
            const struct pipeline_extra *x, size_t n, bool keep, FILE *err)
{
	struct fsfolder f;
	char msg[5000];
	int bad = fsfolder_open(&f, o->out_dir, name, pipeline_files, 0, o->lock_wait_s,
	    msg, sizeof msg) != 0;
	if (!bad) {
		fsfolder_clean(&f, FSFOLDER_STALE_S);
		bad = fsfolder_begin(&f, msg, sizeof msg) != 0;
	}
	for (size_t i = 0; keep && !bad && pipeline_files[i] != NULL; i++)
		if (!is_among(pipeline_files[i], x, n))
			bad = fsfolder_carry(&f, pipeline_files[i], msg, sizeof msg) != 0;
	for (size_t i = 0; !bad && i < n; i++)
		bad = fsfolder_put(&f, x[i].file, x[i].data, x[i].n,
		    strcmp(x[i].file, PIPELINE_STAMP) != 0, msg, sizeof msg) != 0;
	if (!bad)
		bad = fsfolder_commit(&f, msg, sizeof msg) != 0;
	fsfolder_close(&f);
	if (bad)
		fprintf(err, "%s\n", msg);
	return bad ? -1 : 0;
}

/* Writes the rendered outputs and the stamp as one new set of out_dir/name;
 * a file-system problem is PIPE_UNWRITTEN, with the folder as it was. */
static enum pipeline_status
write_set(const struct pipeline_opts *o, const char *name, const char *fp,
          int infeasible, const struct out_set *set, FILE *err)
{
	char hex[N_OUTPUTS][SHA256_HEX_LEN];
	bool present[N_OUTPUTS];
	struct pipeline_extra x[N_OUTPUTS + 1];
	size_t n = 0;
	for (int i = 0; i < N_OUTPUTS; i++) {
		present[i] = set->data[i] != NULL;
		if (!present[i])
			continue;
		sha256_hex(set->data[i], set->len[i], hex[i]);
		x[n++] = (struct pipeline_extra){ pipeline_files[i], set->data[i], set->len[i] };
	}
	struct strbuf sb = STRBUF_INIT;
	if (fp != NULL && fp[0] != '\0') {
		stamp_text(&sb, fp, infeasible, hex, present);
		x[n++] = (struct pipeline_extra){ PIPELINE_STAMP, sb.data, sb.len };
	}
	int bad = replace_set(o, name, x, n, false, err);
	strbuf_free(&sb);
	if (bad)
		return PIPE_UNWRITTEN;
	return infeasible ? PIPE_INFEASIBLE : PIPE_FEASIBLE;
}

enum pipeline_status
pipeline_add(const struct pipeline_opts *o, const char *name,
             const struct pipeline_extra *x, size_t n_x, FILE *err)
{
	/* The folder's other files as they are: a build's outputs keep the
	 * stamp that vouches for them, so the mission stays up to date. */
	return replace_set(o, name, x, n_x, true, err) != 0 ? PIPE_UNWRITTEN : PIPE_FEASIBLE;
}

/* The dossier's trade-study section (report_section_fn). */
static int
sensitivity_section(struct doc *d, const struct template *t, const void *arg)
{
	return sens_report_section(d, t, arg);
}

enum pipeline_status
pipeline_build(const struct cli_env *env, const struct pipeline_opts *o,
               const char *path, const char *fp, FILE *err)
{
	char name[256], msg[512];
	if (pipeline_name_checked(path, name, sizeof name, err) != 0)
		return PIPE_REJECTED;
	struct solve_result *r = xmalloc(sizeof *r);
	unsigned char *bytes = NULL;
	size_t n_bytes = 0;
	enum pipeline_status st = pipeline_solve(env, path, r, err, &bytes, &n_bytes);
	if (st == PIPE_REJECTED || st == PIPE_INTERNAL)
		goto done;

	/* Render everything in memory first: a render failure writes nothing. */
	struct result_json_faults jf;
	int csv_bad = 0, totals_bad = 0;
	char *json = result_json_render_checked(r, AEROEVAL_VERSION, &jf);
	char *csv = bom_csv_render_checked(r, env->cat, &csv_bad);
	char *totals = bom_csv_totals(r, &totals_bad);
	unsigned char *pdf = NULL;
	size_t n_pdf = 0;
	if (jf.n_invalid > 0 || csv_bad > 0 || totals_bad > 0) {
		fprintf(err, "%s: internal error: non-finite value at %s\n", path,
		    jf.n_invalid > 0 ? jf.first_path : csv_bad > 0 ? "bom.csv" : "bom_totals.csv");
		st = PIPE_INTERNAL;
		goto written;
	}
	if (o->tpl != NULL) {
		/* The dossier date: report.date, else SOURCE_DATE_EPOCH, else
		 * none ("undated") — never a file time or the wall clock. */
		char date[16];
		if (fsout_resolve_date(r->mission.report.date, date, msg, sizeof msg) < 0) {
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
			sens != NULL ? sensitivity_section : NULL, sens, o->dossier_text };
		int rr = report_render(&in, &pdf, &n_pdf, msg, sizeof msg);
		free(sens);
		if (rr != 0) {
			fprintf(err, "%s: internal error: dossier: %s\n", path, msg);
			st = PIPE_INTERNAL;
			goto written;
		}
	}
	/* The autopilot hand-off, for a design of record that can be built. */
	struct ardupilot_design ap;
	char *components = NULL, *params = NULL, *qgc = NULL;
	if (ardupilot_derive(r, &env->model, env->cat, &ap, msg, sizeof msg) == 0) {
		components = ardupilot_components(r, &ap, name, AEROEVAL_VERSION);
		params = ardupilot_params(&ap, name, AEROEVAL_VERSION);
		qgc = ardupilot_params_qgc(&ap, name, AEROEVAL_VERSION);
	}
	struct out_set set = { { csv, totals, json, pdf, components, params, qgc }, { 0 } };
	for (int i = 0; i < N_OUTPUTS; i++)
		set.len[i] = i == OUT_DOSSIER ? n_pdf : set.data[i] ? strlen((const char *)set.data[i]) : 0;
	st = write_set(o, name, fp, st == PIPE_INFEASIBLE, &set, err);
	free(components);
	free(params);
	free(qgc);
written:
	free(pdf);
	free(json);
	free(csv);
	free(totals);
done:
	free(bytes);
	free(r);
	return st;
}
