/* cli.c — shared command set-up (see cli.h). */
#include "cli/cli.h"

#include <stdlib.h>
#include <string.h>

#include "core/catalog.h"
#include "input/model_io.h"
#include "util/file.h"

void
cli_data_dir(char *out, size_t n)
{
	const char *env = getenv("AEROEVAL_DATA");
	if (env != NULL && *env != '\0')
		snprintf(out, n, "%s", env);
	else
		file_shipped_dir("data", "chemistries.json", out, n);
}

int
cli_env_load(struct cli_env *env, const char *db_dir, int want_catalog,
             FILE *err)
{
	memset(env, 0, sizeof *env);
	cli_data_dir(env->data_dir, sizeof env->data_dir);
	if (db_dir != NULL)
		snprintf(env->db_dir, sizeof env->db_dir, "%s", db_dir);
	else
		snprintf(env->db_dir, sizeof env->db_dir, "%s/catalog", env->data_dir);
	if (model_io_load(env->data_dir, &env->model, err) != 0)
		return 2;
	if (want_catalog) {
		int n_err = 0;
		env->cat = catalog_load(env->db_dir, env->model.chem_names, err, &n_err);
		if (env->cat == NULL)
			return 2;
		snprintf(env->catalogue_sha256, sizeof env->catalogue_sha256, "%s",
		         catalog_sha256(env->cat));
	}
	return 0;
}

void
cli_env_free(struct cli_env *env)
{
	catalog_free(env->cat);
	env->cat = NULL;
}
