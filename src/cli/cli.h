/* cli.h — what every command shares: finding data/, loading the reference
 * tables and the parts catalogue once, and the mission front end.
 * CLI layer: may use everything below it.
 */
#ifndef AEROEVAL_CLI_H
#define AEROEVAL_CLI_H

#include <stdio.h>

#include "core/model.h"

struct catalog;

/* Loaded once per process and shared (read-only) by every mission. */
struct cli_env {
	char data_dir[4096];        /* reference tables */
	char db_dir[4200];          /* parts catalogue */
	struct model_data model;    /* chemistries, roles, classes, calibration */
	struct catalog *cat;        /* parts, or NULL when not loaded */
	char catalogue_sha256[65];  /* of the four catalogue files, "" when not loaded */
};

/* Where data/ is: $AEROEVAL_DATA, else next to the program (build tree or
 * installed share/aeroeval), else ./data.  Writes into out. */
void cli_data_dir(char *out, size_t n);

/* Load the reference tables and, when want_catalog, the catalogue from
 * db_dir (NULL = data/catalog).  Errors go to err; returns 0 or 2. */
int cli_env_load(struct cli_env *env, const char *db_dir, int want_catalog,
                 FILE *err);

void cli_env_free(struct cli_env *env);

struct template;

/* The dossier template: the built-in one when path is NULL, else the file,
 * its fonts and logo checked now (output/assets.h), before any mission is
 * solved.  Errors go to err; NULL when there was any.  Free with
 * template_free(). */
struct template *cli_template_load(const char *path, FILE *err);

#endif
