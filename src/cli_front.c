/* cli_front.c — `aeroeval check` and `aeroeval schema` (see cli_front.h). */
#include "cli_front.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "diag.h"
#include "mission_io.h"
#include "schema.h"
#include "xalloc.h"

/* Where the chemistry profiles live, relative to the working directory. */
#define CLI_CHEMISTRIES_PATH "data/chemistries.json"

/* The chemistry names of data/chemistries.json
 * ({"chemistries":[{"name":"LiPo",...},...]}), NULL-terminated, or NULL
 * when the file is missing, unreadable or names nothing: then
 * battery_chemistry is not checked against it (the engine's own loader
 * reports a broken file).
 * Stands in until the data layer's chemistry loader is merged.
 * Ownership: free with cli_free_names(). */
static char **
cli_chemistry_names(void)
{
	FILE *fp = fopen(CLI_CHEMISTRIES_PATH, "rb");
	if (fp == NULL)
		return NULL;
	size_t len = 0, cap = 8192;
	char *buf = xmalloc(cap);
	size_t got;
	while ((got = fread(buf + len, 1, cap - len - 1, fp)) > 0) {
		len += got;
		if (len + 1 == cap)
			buf = xrealloc(buf, cap *= 2);
	}
	fclose(fp);
	buf[len] = '\0';

	char **names = NULL;
	cJSON *root = cJSON_ParseWithLengthOpts(buf, len + 1, NULL, 1);
	const cJSON *list = cJSON_GetObjectItemCaseSensitive(root, "chemistries");
	if (cJSON_IsArray(list)) {
		size_t n = 0;
		names = xcalloc((size_t)cJSON_GetArraySize(list) + 1, sizeof *names);
		for (const cJSON *c = list->child; c != NULL; c = c->next) {
			const cJSON *nm = cJSON_GetObjectItemCaseSensitive(c, "name");
			if (cJSON_IsString(nm))
				names[n++] = xstrdup(nm->valuestring);
		}
		if (n == 0) {
			/* No usable names: better no check than rejecting all. */
			free(names);
			names = NULL;
		}
	}
	cJSON_Delete(root);
	free(buf);
	return names;
}

static void
cli_free_names(char **names)
{
	if (names == NULL)
		return;
	for (size_t i = 0; names[i] != NULL; i++)
		free(names[i]);
	free(names);
}

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

	char **chems = cli_chemistry_names();
	int status = 0;
	for (int i = 1; i < argc; i++) {
		struct diag *dg = diag_alloc(stderr);
		struct mission_spec spec;
		mission_io_load(argv[i], (const char *const *)chems, dg, &spec);
		diag_flush(dg);
		if (diag_exit_status(dg) > status)
			status = diag_exit_status(dg);
		diag_free(dg);
	}
	cli_free_names(chems);
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
	cJSON *s = schema_json_schema();
	char *text = cJSON_Print(s);
	cJSON_Delete(s);
	if (text == NULL) {
		fprintf(stderr, "aeroeval: internal error: cannot print the schema\n");
		return 3;
	}
	printf("%s\n", text);
	free(text);
	return 0;
}
