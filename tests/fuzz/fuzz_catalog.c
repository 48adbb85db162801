/* fuzz_catalog.c — libFuzzer harness: a supplier's catalogue file.
 *
 * catalog_io_load() reads files, so the first input byte picks which of the
 * four catalogue files the rest of the input replaces, in a scratch copy of
 * the shipped catalogue (data/catalog, or $AEROEVAL_DATA/catalog) cut to
 * its first three entries per file.  The
 * loader must report or accept, never crash, leak or hit UB; an accepted
 * catalogue must answer every accessor and finder.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cjson/cJSON.h>

#include "catalog/catalog.h"
#include "diag/diag.h"
#include "input/catalog_io.h"
#include "util/file.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *const files[4] = { "motors.json", "propellers.json",
	"batteries.json", "escs.json" };
static const char *const keys[4] = { "motors", "propellers", "batteries",
	"escs" };
static char dirs[4][64]; /* dirs[k]: the shipped files, files[k] fuzzed */

/* Writes the shipped file `from` to `to` with only its first few entries:
 * the three files not being fuzzed then load fast (a full shipped file
 * costs more to parse than most fuzz inputs). */
static void
copy_trimmed(const char *from, const char *to, const char *key)
{
	unsigned char *text = NULL;
	size_t n = 0;
	char msg[512];
	if (file_read(from, 16u << 20, &text, &n, msg, sizeof msg) != 0) {
		fprintf(stderr, "fuzz_catalog: %s\n", msg);
		exit(1);
	}
	cJSON *root = cJSON_Parse((const char *)text);
	free(text);
	cJSON *list = cJSON_GetObjectItemCaseSensitive(root, key);
	while (cJSON_GetArraySize(list) > 3)
		cJSON_DeleteItemFromArray(list, 3);
	char *out = cJSON_Print(root);
	FILE *f = fopen(to, "wb");
	if (out == NULL || f == NULL) {
		fprintf(stderr, "fuzz_catalog: cannot write %s\n", to);
		exit(1);
	}
	fputs(out, f);
	fclose(f);
	free(out);
	cJSON_Delete(root);
}

/* Removes the scratch catalogues at exit. */
static void
remove_dirs(void)
{
	char path[128];
	for (int k = 0; k < 4; k++) {
		if (dirs[k][0] == '\0')
			continue;
		for (int f = 0; f < 4; f++) {
			snprintf(path, sizeof path, "%s/%s", dirs[k], files[f]);
			unlink(path);
		}
		rmdir(dirs[k]);
	}
}

int
LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	const char *data = getenv("AEROEVAL_DATA");
	char src[4200], from[4400], to[128];
	snprintf(src, sizeof src, "%s/catalog", data && *data ? data : "data");
	atexit(remove_dirs);
	for (int k = 0; k < 4; k++) {
		snprintf(dirs[k], sizeof dirs[k], "/tmp/aeroeval-fuzzcat-XXXXXX");
		if (mkdtemp(dirs[k]) == NULL) {
			perror("mkdtemp");
			exit(1);
		}
		for (int f = 0; f < 4; f++) {
			snprintf(from, sizeof from, "%s/%s", src, files[f]);
			snprintf(to, sizeof to, "%s/%s", dirs[k], files[f]);
			copy_trimmed(from, to, keys[f]);
		}
	}
	return 0;
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (size < 1)
		return 0;
	int k = data[0] % 4;
	char path[128];
	snprintf(path, sizeof path, "%s/%s", dirs[k], files[k]);
	FILE *f = fopen(path, "wb");
	if (f == NULL)
		abort();
	if (size > 1 && fwrite(data + 1, 1, size - 1, f) != size - 1)
		abort();
	fclose(f);

	struct diag *dg = diag_alloc(NULL);
	struct catalog *c = catalog_io_load(dirs[k], NULL, dg, NULL);
	int n_err = diag_n_errors(dg);
	diag_free(dg);
	if ((c == NULL) != (n_err > 0))
		abort(); /* NULL exactly when an error was reported */
	if (c == NULL)
		return 0;
	for (size_t i = 0; i < catalog_n_motors(c); i++)
		if (catalog_find_motor(c, catalog_motor(c, i)->id) == NULL)
			abort();
	for (size_t i = 0; i < catalog_n_props(c); i++)
		if (catalog_find_prop(c, catalog_prop(c, i)->id) == NULL)
			abort();
	for (size_t i = 0; i < catalog_n_batteries(c); i++)
		if (catalog_find_battery(c, catalog_battery(c, i)->id) == NULL)
			abort();
	for (size_t i = 0; i < catalog_n_escs(c); i++)
		if (catalog_find_esc(c, catalog_esc(c, i)->id) == NULL)
			abort();
	if (catalog_motor(c, catalog_n_motors(c)) != NULL)
		abort();
	catalog_free(c);
	return 0;
}
