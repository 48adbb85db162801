/* cli.h — what every command shares: finding data/, loading the reference
 * tables and the parts catalogue once, the template, the cohort of
 * validate and calibrate, and the mission front end.
 * CLI layer: may use everything below it.
 */
#ifndef AEROEVAL_CLI_H
#define AEROEVAL_CLI_H

#include <stdio.h>

#include "spec/model.h"

struct catalog;

/* Loaded once per process and shared (read-only) by every mission. */
struct cli_env {
	char data_dir[4096];        /* reference tables */
	char db_dir[4200];          /* parts catalogue */
	struct model_data model;    /* chemistries, roles, classes, calibration */
	struct catalog *cat;        /* parts, or NULL when not loaded */
	char catalogue_sha256[65];  /* of the catalogue files read (catalog_io.h),
	                               "" when not loaded */
};

/* Where data/ is: $AEROEVAL_DATA, else next to the program (build tree or
 * installed share/aeroeval), else ./data.  Writes into out. */
void cli_data_dir(char *out, size_t n);

/* Load the reference tables and, when want_catalog, the catalogue from
 * db_dir (NULL = data/catalog; "" is refused).  Errors go to err; returns
 * 0 or 2. */
int cli_env_load(struct cli_env *env, const char *db_dir, int want_catalog,
                 FILE *err);

void cli_env_free(struct cli_env *env);

struct sha256_ctx;

/* Adds the regular file at path to c as its length (8 bytes, little
 * endian) followed by every one of its bytes, streamed: no size limit.
 * Returns 0; -1 when it cannot be opened or is not a regular file
 * (nothing added); -2 when a read fails or the file changes size while it
 * is read (c then holds part of it and must be discarded).  On failure err
 * holds "PATH: why". */
int cli_hash_file(struct sha256_ctx *c, const char *path, char *err, size_t errlen);

/* The output folder an option of command cmd names (build and sensitivity
 * -o, validate --missions): not "" (which once wrote /NAME/), not the root
 * however spelled, not an existing file.  Kept without trailing slashes
 * in out.  Returns 0, or 2 after one message on err. */
int cli_out_dir(const char *cmd, const char *opt, const char *value, char *out, size_t n,
                FILE *err);

/* The close_stdout habit (coreutils): flushes and closes standard output
 * and returns the exit status the program ends with: status as it is, or
 * at least 2 after one message on stderr when a write to stdout failed
 * (a full disk, /dev/full, a closed pipe's EPIPE), so a truncated
 * result.json or table is never an exit 0.  A stdout closed before the
 * program ran (>&-) is no error while nothing was written to it. */
int cli_close_stdout(int status);

struct template;

/* The dossier template: the built-in one when path is NULL, else the file,
 * its fonts and logo checked now (pdf/assets.h), before any mission is
 * solved.  Errors go to err; NULL when there was any.  Free with
 * template_free(). */
struct template *cli_template_load(const char *path, FILE *err);

struct cohort;

/* For `validate` and `calibrate`: loads the reference tables into env and
 * the cohort at path into c, printing every cohort problem on stderr.
 * Returns 0, or the exit status to give up with (2 when no row is usable). */
int cli_cohort_load(const char *path, struct cli_env *env, struct cohort *c);

/* A cohort with rejected rows (their error lines printed by
 * cli_cohort_load()) still gets its report, over the rows that were read,
 * but the run ends with exit status 2 like any other input error: a script
 * must not take statistics over a part of its cohort for the whole.
 * Prints why on stderr and returns 2, or returns 0 when no row was
 * rejected. */
int cli_cohort_rejected(const char *path, const struct cohort *c);

#endif
