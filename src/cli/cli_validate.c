/* cli_validate.c — `aeroeval validate` (see cli_validate.h). */
#include "cli/cli_validate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "cli/cli.h"
#include "input/cohort.h"
#include "pdf/doc.h"
#include "fs/fsfolder.h"
#include "fs/fsout.h"
#include "input/mission_io.h"
#include "study/validate.h"
#include "study/valreport.h"
#include "util/jsonw.h"
#include "util/text.h"
#include "util/xalloc.h"

#define VALIDATE_USAGE "usage: aeroeval validate [--pack] [--report FILE.pdf] [--json] [--missions DIR] COHORT.csv\n"

/* Why a row was skipped, naming the fact when one was out of range. */
static void
skip_line(const struct validate_row *vr, char *buf, size_t n)
{
	if (vr->skip == VALIDATE_SKIP_RANGE)
		validate_fact_text(&vr->fact, buf, n);
	else
		snprintf(buf, n, "%s", validate_skip_text(vr->skip));
}

/* The notes of a row as "a; b; c" into buf. */
static void
notes_line(unsigned notes, char *buf, size_t n)
{
	buf[0] = '\0';
	size_t used = 0;
	for (int i = 0; i < VALIDATE_NOTE_COUNT; i++) {
		if (!(notes & (1u << i)))
			continue;
		int w = snprintf(buf + used, n - used, "%s%s", used ? "; " : "",
		    validate_note_text(1u << i));
		if (w < 0 || (size_t)w >= n - used)
			return;
		used += (size_t)w;
	}
}

static void
print_table(FILE *out, const struct cohort *c, const struct validate_report *v)
{
	fprintf(out, "%-28s %-16s %9s %9s %8s %6s %9s  %s\n", "platform", "class",
	    "actual", "predicted", "error", "k", "battery", "status");
	for (size_t i = 0; i < v->n_rows; i++) {
		const struct validate_row *vr = &v->rows[i];
		const struct cohort_row *row = &c->rows[i];
		if (vr->status != VALIDATE_ROW_OK)
			continue;
		char batt[16] = "-";
		if (vr->has_battery)
			snprintf(batt, sizeof batt, "%+.1f %%", vr->battery_err_pct);
		fprintf(out, "%-28.28s %-16s %7.3f kg %7.3f kg %+7.1f%% %6.2f %9s  %s\n",
		    row->name, validate_class_key(row), vr->actual_kg, vr->predicted_kg,
		    vr->err_pct, vr->k, batt, vr->feasible ? "ok" : "ok (infeasible)");
	}
	fprintf(out, "\nMTOW over %zu of %zu rows: MAPE %.1f %% (95 %% CI %.1f-%.1f %%, "
	    "bootstrap %d resamples, seed %u), median APE %.1f %%, RMSE %.3f kg, "
	    "k %.2f +- %.2f\n", v->n_ok, v->n_rows, v->mtow.mape_pct, v->ci_lo_pct,
	    v->ci_hi_pct, VALIDATE_BOOT_RESAMPLES, VALIDATE_BOOT_SEED,
	    v->mtow.median_ape_pct, v->mtow.rmse_kg, v->mtow.k_mean, v->mtow.k_sd);
	for (size_t g = 0; g < v->n_classes; g++)
		fprintf(out, "  %-16s n=%-3zu MAPE %.1f %%\n", v->by_class[g].key,
		    v->by_class[g].n, v->by_class[g].mape_pct);
	if (v->battery.n > 0)
		fprintf(out, "Battery mass over %zu rows: MAPE %.1f %%\n", v->battery.n,
		    v->battery.mape_pct);
	if (v->n_open > 0)
		fprintf(out, "Open loop, the model evaluated at each aircraft's real mass: "
		    "dry mass (all but battery and payload) mean error %.1f %% and battery "
		    "%.1f %% over %zu rows with a published battery mass\n",
		    v->open_dry_mape_pct, v->open_battery_mape_pct, v->n_open);
	if (v->n_forward_rows > 0) {
		fprintf(out, "Forward check, each aircraft flown at its real mass on its published "
		    "pack to an empty pack: endurance MAPE %.1f %% over %zu published times of "
		    "%zu rows\n", v->forward_mape_pct, v->n_forward_figures, v->n_forward_rows);
		for (size_t i = 0; i < v->n_rows; i++) {
			const struct validate_forward *f = &v->rows[i].forward;
			if (!f->valid)
				continue;
			fprintf(out, "  %-28.28s", c->rows[i].name);
			if (f->hover_pub_s > 0.0)
				fprintf(out, "  hover %5.1f of %5.1f min (%+5.1f %%)",
				    f->hover_model_s / 60.0, f->hover_pub_s / 60.0,
				    100.0 * (f->hover_model_s / f->hover_pub_s - 1.0));
			if (f->max_pub_s > 0.0)
				fprintf(out, "  level at %4.1f m/s %5.1f of %5.1f min (%+5.1f %%)",
				    f->speed_ms, f->max_model_s / 60.0, f->max_pub_s / 60.0,
				    100.0 * (f->max_model_s / f->max_pub_s - 1.0));
			fputc('\n', out);
		}
	}
	if (v->has_interval)
		fprintf(out, "Inside the shipped %.0f %% prediction interval: %zu of %zu rows\n",
		    100.0 * v->interval_level, v->n_inside, v->n_ok);
	else
		fprintf(out, "The shipped calibration carries no prediction interval for this rule\n");
	int header = 0;
	for (size_t i = 0; i < v->n_rows; i++) {
		const struct validate_row *vr = &v->rows[i];
		if (vr->status == VALIDATE_ROW_OK)
			continue;
		if (!header++)
			fprintf(out, "\nNot in the statistics:\n");
		char why[256];
		skip_line(vr, why, sizeof why);
		if (vr->status == VALIDATE_ROW_SKIPPED)
			fprintf(out, "  %-28.28s skipped: %s\n", c->rows[i].name, why);
		else if (vr->status == VALIDATE_ROW_NOT_CONVERGED)
			fprintf(out, "  %-28.28s not converged (last mass %.3f kg)\n",
			    c->rows[i].name, vr->predicted_kg);
		else
			fprintf(out, "  %-28.28s not run (rejected by the feasibility gate)\n",
			    c->rows[i].name);
	}
	header = 0;
	for (size_t i = 0; i < v->n_rows; i++) {
		const struct validate_row *vr = &v->rows[i];
		if (vr->status == VALIDATE_ROW_SKIPPED || vr->notes == 0)
			continue;
		if (!header++)
			fprintf(out, "\nStand-ins the rule used:\n");
		char buf[512];
		notes_line(vr->notes, buf, sizeof buf);
		fprintf(out, "  %-28.28s %s\n", c->rows[i].name, buf);
	}

	header = 0;
	for (size_t i = 0; i < v->n_rows; i++) {
		const struct validate_row *vr = &v->rows[i];
		if (vr->status != VALIDATE_ROW_OK || !(vr->slope_at_real >= 1.0))
			continue;
		if (!header++)
			fprintf(out, "\nNot a contraction at the real mass (the loop's slope there is "
			    "1 or more: the real aircraft is no fixed point the loop can reach; "
			    "docs/validation.md):\n");
		fprintf(out, "  %-28.28s slope %.2f, predicted %+.1f%%\n", c->rows[i].name,
		    vr->slope_at_real, vr->err_pct);
	}
}

/* Every row ran into a skip, a loop that did not converge or the gate:
 * say so with the count of each, rather than print a MAPE of no row. */
static void
no_row_validated(const char *path, const struct validate_report *v)
{
	size_t n_skip[VALIDATE_SKIP_MAX] = { 0 }, n_status[VALIDATE_ROW_STATUS_MAX] = { 0 };
	for (size_t i = 0; i < v->n_rows; i++) {
		n_status[v->rows[i].status]++;
		if (v->rows[i].status == VALIDATE_ROW_SKIPPED)
			n_skip[v->rows[i].skip]++;
	}
	fprintf(stderr, "%s: error: no row could be validated (%zu rows", path, v->n_rows);
	for (int k = 1; k < VALIDATE_SKIP_MAX; k++)
		if (n_skip[k] > 0)
			fprintf(stderr, "; %zu skipped: %s", n_skip[k],
			        validate_skip_text((enum validate_skip)k));
	if (n_status[VALIDATE_ROW_NOT_CONVERGED] > 0)
		fprintf(stderr, "; %zu did not converge", n_status[VALIDATE_ROW_NOT_CONVERGED]);
	if (n_status[VALIDATE_ROW_NOT_RUN] > 0)
		fprintf(stderr, "; %zu rejected by the feasibility gate",
		        n_status[VALIDATE_ROW_NOT_RUN]);
	fprintf(stderr, ")\n");
}

static cJSON *
summary_json(const struct stats_summary *s)
{
	cJSON *o = cJSON_CreateObject();
	cJSON_AddNumberToObject(o, "n", (double)s->n);
	cJSON_AddNumberToObject(o, "mape_pct", s->mape_pct);
	cJSON_AddNumberToObject(o, "median_ape_pct", s->median_ape_pct);
	cJSON_AddNumberToObject(o, "rmse_kg", s->rmse_kg);
	cJSON_AddNumberToObject(o, "k_mean", s->k_mean);
	cJSON_AddNumberToObject(o, "k_sd", s->k_sd);
	return o;
}

static char *
report_json(const char *path, const struct cohort *c, const struct validate_report *v)
{
	cJSON *root = cJSON_CreateObject();
	char *path_utf8 = text_utf8_copy(path);   /* a file name need not be UTF-8 */
	cJSON_AddStringToObject(root, "cohort", path_utf8);
	free(path_utf8);
	/* "n_rows": "rows" is the array of rows below (it was both). */
	cJSON_AddNumberToObject(root, "n_rows", (double)v->n_rows);
	cJSON *mt = summary_json(&v->mtow);
	cJSON_AddNumberToObject(mt, "ci95_lo_pct", v->ci_lo_pct);
	cJSON_AddNumberToObject(mt, "ci95_hi_pct", v->ci_hi_pct);
	cJSON_AddNumberToObject(mt, "bootstrap_resamples", VALIDATE_BOOT_RESAMPLES);
	cJSON_AddNumberToObject(mt, "bootstrap_seed", VALIDATE_BOOT_SEED);
	cJSON_AddItemToObject(root, "mtow", mt);
	cJSON_AddItemToObject(root, "battery_mass", summary_json(&v->battery));
	cJSON_AddStringToObject(root, "rule", v->rule == VALIDATE_PACK_LOCKED
	    ? "pack_locked" : "from_endurance");
	cJSON *fc = cJSON_AddObjectToObject(root, "forward_check");
	cJSON_AddNumberToObject(fc, "rows", (double)v->n_forward_rows);
	cJSON_AddNumberToObject(fc, "figures", (double)v->n_forward_figures);
	cJSON_AddNumberToObject(fc, "mape_pct", v->forward_mape_pct);
	cJSON *ol = cJSON_AddObjectToObject(root, "open_loop");
	cJSON_AddNumberToObject(ol, "n", (double)v->n_open);
	cJSON_AddNumberToObject(ol, "dry_mape_pct", v->open_dry_mape_pct);
	cJSON_AddNumberToObject(ol, "battery_mape_pct", v->open_battery_mape_pct);
	if (v->has_interval) {
		cJSON *iv = cJSON_AddObjectToObject(root, "interval");
		cJSON_AddNumberToObject(iv, "level", v->interval_level);
		cJSON_AddNumberToObject(iv, "n_inside", (double)v->n_inside);
		cJSON_AddNumberToObject(iv, "n", (double)v->n_ok);
	}
	cJSON *cl = cJSON_AddArrayToObject(root, "by_class");
	for (size_t g = 0; g < v->n_classes; g++) {
		cJSON *o = cJSON_CreateObject();
		cJSON_AddStringToObject(o, "class", v->by_class[g].key);
		cJSON_AddNumberToObject(o, "n", (double)v->by_class[g].n);
		cJSON_AddNumberToObject(o, "mape_pct", v->by_class[g].mape_pct);
		cJSON_AddItemToArray(cl, o);
	}
	cJSON *rows = cJSON_AddArrayToObject(root, "rows");
	for (size_t i = 0; i < v->n_rows; i++) {
		const struct validate_row *vr = &v->rows[i];
		const struct cohort_row *row = &c->rows[i];
		cJSON *o = cJSON_CreateObject();
		cJSON_AddStringToObject(o, "name", row->name);
		cJSON_AddNumberToObject(o, "line", (double)row->line);
		cJSON_AddStringToObject(o, "class", validate_class_key(row));
		cJSON_AddStringToObject(o, "status", validate_status_text(vr->status));
		if (vr->status == VALIDATE_ROW_SKIPPED) {
			char why[256];
			skip_line(vr, why, sizeof why);
			cJSON_AddStringToObject(o, "skip_reason", why);
		}
		cJSON_AddNumberToObject(o, "actual_kg", vr->actual_kg);
		if (vr->status == VALIDATE_ROW_OK || vr->status == VALIDATE_ROW_NOT_CONVERGED)
			cJSON_AddNumberToObject(o, "predicted_kg", vr->predicted_kg);
		if (vr->status == VALIDATE_ROW_OK) {
			cJSON_AddNumberToObject(o, "error_pct", vr->err_pct);
			cJSON_AddNumberToObject(o, "k", vr->k);
			cJSON_AddBoolToObject(o, "feasible", vr->feasible);
			cJSON_AddNumberToObject(o, "cells", vr->cells);
			cJSON_AddNumberToObject(o, "capacity_mah", vr->capacity_mah);
			cJSON_AddNumberToObject(o, "thrust_to_weight", vr->thrust_to_weight);
			cJSON_AddNumberToObject(o, "slope_at_real_mass", vr->slope_at_real);
		}
		if (vr->has_battery) {
			cJSON_AddNumberToObject(o, "battery_actual_kg", vr->battery_actual_kg);
			cJSON_AddNumberToObject(o, "battery_predicted_kg", vr->battery_pred_kg);
			cJSON_AddNumberToObject(o, "battery_error_pct", vr->battery_err_pct);
		}
		const struct validate_forward *f = &vr->forward;
		if (f->valid) {
			cJSON *fo = cJSON_AddObjectToObject(o, "forward_check");
			if (f->hover_pub_s > 0.0) {
				cJSON_AddNumberToObject(fo, "hover_published_s", f->hover_pub_s);
				cJSON_AddNumberToObject(fo, "hover_model_s", f->hover_model_s);
				cJSON_AddNumberToObject(fo, "hover_error_pct",
				    100.0 * (f->hover_model_s / f->hover_pub_s - 1.0));
			}
			if (f->max_pub_s > 0.0) {
				cJSON_AddNumberToObject(fo, "max_flight_published_s", f->max_pub_s);
				cJSON_AddNumberToObject(fo, "max_flight_model_s", f->max_model_s);
				cJSON_AddNumberToObject(fo, "max_flight_speed_ms", f->speed_ms);
				cJSON_AddNumberToObject(fo, "max_flight_error_pct",
				    100.0 * (f->max_model_s / f->max_pub_s - 1.0));
			}
		}
		cJSON *nt = cJSON_AddArrayToObject(o, "rule_notes");
		for (int b = 0; b < VALIDATE_NOTE_COUNT; b++)
			if (vr->notes & (1u << b))
				cJSON_AddItemToArray(nt, cJSON_CreateString(validate_note_text(1u << b)));
		cJSON_AddItemToArray(rows, o);
	}
	char *txt = jsonw_print(root, NULL);
	cJSON_Delete(root);
	return txt;
}

/* "07-DJI-FlameWheel-F550": row number, then the name with every byte
 * outside [A-Za-z0-9._-] turned into '-', so names never leave DIR. */
static void
mission_file_name(size_t i, const char *name, char *out, size_t n)
{
	int w = snprintf(out, n, "%02zu-", i + 1);
	size_t k = w > 0 ? (size_t)w : 0;
	for (const char *p = name; *p && k + 6 < n; p++) {
		char ch = *p;
		int ok = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') ||
		    (ch >= '0' && ch <= '9') || ch == '.' || ch == '_' || ch == '-';
		if (!ok)
			ch = '-';
		if (ch == '-' && k > 0 && out[k - 1] == '-')
			continue;
		out[k++] = ch;
	}
	while (k > 0 && out[k - 1] == '-')
		k--;
	snprintf(out + k, n - k, ".json");
}

/* mission_io_to_json writes every field, defaults included; a reader would
 * take them all as given and skip the role and class defaults the engine
 * derives for fields the rule left open.  Keep only what the rule set, so
 * the written file solves exactly like the rule's mission. */
static void
prune_to_given(cJSON *root, const struct mission_spec *s)
{
	for (int i = 0; i < SPEC_N_FIELDS; i++) {
		if (s->given[i])
			continue;
		char path[128];
		snprintf(path, sizeof path, "%s", spec_fields[i].path);
		cJSON *obj = root;
		char *key = path, *dot;
		while (obj != NULL && (dot = strchr(key, '.')) != NULL) {
			*dot = '\0';
			obj = cJSON_GetObjectItemCaseSensitive(obj, key);
			key = dot + 1;
		}
		if (obj != NULL)
			cJSON_DeleteItemFromObjectCaseSensitive(obj, key);
	}
	/* Drop the groups left empty. */
	cJSON *it = root->child;
	while (it != NULL) {
		cJSON *next = it->next;
		if (cJSON_IsObject(it) && it->child == NULL)
			cJSON_Delete(cJSON_DetachItemViaPointer(root, it));
		it = next;
	}
}

/* The lock of --missions DIR is waited for this long (another validate). */
#define MISSIONS_LOCK_WAIT_S 30.0

/* --missions DIR: the rows' missions as DIR/NN-NAME.json, DIR being a folder
 * of their own replaced as a whole through the file-system layer (fsfolder.h),
 * as `build` replaces a mission's folder: not "" or the root, no link at
 * DIR, nothing in it but missions an earlier run wrote ("*.json"), one new
 * set swapped in.  Returns 0, or -1 after one message. */
static int
write_missions(const char *dir_opt, const struct cohort *c, const struct validate_report *v)
{
	char dir[4096], parent[4096], err[5000];
	if (cli_out_dir("validate", "--missions", dir_opt, dir, sizeof dir, stderr) != 0)
		return -1;
	const char *slash = strrchr(dir, '/');
	const char *base = slash != NULL ? slash + 1 : dir;
	if (slash == NULL)
		snprintf(parent, sizeof parent, ".");
	else
		snprintf(parent, sizeof parent, "%.*s", slash == dir ? 1 : (int)(slash - dir), dir);
	if (fsout_mkdirs(parent, err, sizeof err) != 0) {
		fprintf(stderr, "aeroeval: error: %s\n", err);
		return -1;
	}
	static const char *const mission_files[] = { "*.json", NULL };
	struct fsfolder f;
	int bad = fsfolder_open(&f, parent, base, mission_files, 0, MISSIONS_LOCK_WAIT_S,
	    err, sizeof err) != 0;
	if (!bad) {
		fsfolder_clean(&f, FSFOLDER_STALE_S);
		bad = fsfolder_begin(&f, err, sizeof err) != 0;
	}
	for (size_t i = 0; !bad && i < v->n_rows; i++) {
		if (v->rows[i].status == VALIDATE_ROW_SKIPPED)
			continue;
		char file[160];
		mission_file_name(i, c->rows[i].name, file, sizeof file);
		cJSON *j = mission_io_to_json(&v->rows[i].spec);
		prune_to_given(j, &v->rows[i].spec);
		char *txt = jsonw_print(j, NULL);
		cJSON_Delete(j);
		bad = fsfolder_put(&f, file, txt, strlen(txt), 1, err, sizeof err) != 0;
		free(txt);
	}
	if (!bad)
		bad = fsfolder_commit(&f, err, sizeof err) != 0;
	fsfolder_close(&f);
	if (bad) {
		fprintf(stderr, "%s\n", err);
		return -1;
	}
	return 0;
}

static int
write_report(const char *pdf_path, const char *cohort_path, const struct cohort *c,
             const struct validate_report *v, const struct model_calibration *cal)
{
	char date[11], err[512];
	if (fsout_resolve_date("", date, err, sizeof err) < 0) {
		fprintf(stderr, "error: %s\n", err);
		return -1;
	}
	unsigned char *pdf = NULL;
	size_t n = 0;
	if (valreport_render(c, v, cal, cohort_path, date, &pdf, &n, err, sizeof err) != 0) {
		fprintf(stderr, "error: %s: %s\n", pdf_path, err);
		return -1;
	}
	int rc = fsout_write_atomic(pdf_path, pdf, n, err, sizeof err);
	free(pdf);
	doc_global_cleanup();
	if (rc != 0) {
		fprintf(stderr, "error: %s\n", err);
		return -1;
	}
	return 0;
}

int
cli_validate(int argc, char **argv)
{
	const char *report = NULL, *missions = NULL, *path = NULL;
	int json = 0;
	enum validate_rule rule = VALIDATE_FROM_ENDURANCE;
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "--report") == 0 && i + 1 < argc)
			report = argv[++i];
		else if (strcmp(argv[i], "--missions") == 0 && i + 1 < argc)
			missions = argv[++i];
		else if (strcmp(argv[i], "--json") == 0)
			json = 1;
		else if (strcmp(argv[i], "--pack") == 0)
			rule = VALIDATE_PACK_LOCKED;
		else if (argv[i][0] == '-' || path != NULL) {
			fputs(VALIDATE_USAGE, stderr);
			return 2;
		} else
			path = argv[i];
	}
	if (path == NULL) {
		fputs(VALIDATE_USAGE, stderr);
		return 2;
	}
	struct cli_env *env = xcalloc(1, sizeof *env);
	struct cohort c;
	memset(&c, 0, sizeof c);
	int rc = cli_cohort_load(path, env, &c);
	struct validate_report v;
	memset(&v, 0, sizeof v);
	if (rc == 0 && validate_cohort(&c, &env->model, rule, &v) != 0) {
		fprintf(stderr, "%s: internal error: statistics refused the predictions\n", path);
		rc = 3;
	}
	if (rc == 0 && v.n_ok == 0) {
		no_row_validated(path, &v);
		rc = 2;
	}
	if (rc == 0) {
		if (json) {
			char *txt = report_json(path, &c, &v);
			printf("%s\n", txt);
			free(txt);
		} else {
			print_table(stdout, &c, &v);
		}
		if (missions != NULL && write_missions(missions, &c, &v) != 0)
			rc = 2;
		if (report != NULL && write_report(report, path, &c, &v, &env->model.cal) != 0)
			rc = 2;
		if (rc == 0)
			rc = cli_cohort_rejected(path, &c);
	}
	validate_report_free(&v);
	cohort_free(&c);
	cli_env_free(env);
	free(env);
	return rc;
}
