/* cli_front.c — `aeroeval check` and `aeroeval schema` (see cli_front.h). */
#include "cli/cli_front.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "cli/cli.h"
#include "diag/diag.h"
#include "input/mission_io.h"
#include "input/schema.h"
#include "util/jsonw.h"
#include "util/xalloc.h"

int
cli_check(int argc, char **argv)
{
	if (argc < 2) {
		fprintf(stderr, "usage: aeroeval check MISSION.json...\n");
		return 2;
	}
	for (int i = 1; i < argc; i++) {
		if (argv[i][0] == '-' && argv[i][1] != '\0') {
			fprintf(stderr, "aeroeval check: unknown option %s\n"
			        "usage: aeroeval check MISSION.json...\n", argv[i]);
			return 2;
		}
	}

	/* The same reference data as every other command (data/ found next
	 * to the program, or $AEROEVAL_DATA): battery_chemistry is checked
	 * against the loaded profiles. */
	struct cli_env *env = xcalloc(1, sizeof *env);
	int status = cli_env_load(env, NULL, 0, stderr);
	for (int i = 1; env->model.n_chem > 0 && i < argc; i++) {
		struct diag *dg = diag_alloc(stderr);
		struct mission_spec spec;
		mission_io_load(argv[i], env->model.chem_names, dg, &spec);
		diag_flush(dg);
		if (diag_exit_status(dg) > status)
			status = diag_exit_status(dg);
		diag_free(dg);
	}
	cli_env_free(env);
	free(env);
	return status;
}

int
cli_schema(int argc, char **argv)
{
	bool json = false;
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "--json") == 0) {
			json = true;
		} else {
			fprintf(stderr, "usage: aeroeval schema [--json]\n");
			return 2;
		}
	}
	if (!json) {
		schema_print_text(stdout);
		return 0;
	}
	/* battery_chemistry's enum: the profiles of data/chemistries.json. */
	struct cli_env *env = xcalloc(1, sizeof *env);
	int status = cli_env_load(env, NULL, 0, stderr);
	if (status != 0) {
		cli_env_free(env);
		free(env);
		return status;
	}
	cJSON *s = schema_json_schema(env->model.chem_names);
	char *text = jsonw_print(s, NULL);
	cJSON_Delete(s);
	cli_env_free(env);
	free(env);
	fputs(text, stdout);
	free(text);
	return 0;
}
