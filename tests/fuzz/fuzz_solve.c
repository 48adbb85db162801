/* fuzz_solve.c — libFuzzer harness: a whole solve.
 *
 * Two ways in, chosen by the first byte:
 *  - text starting with '{' (or whitespace / a BOM) is a mission file, parsed
 *    as the program parses it;
 *  - anything else drives a mission generator: the bytes choose, field by
 *    field of the spec table, whether the field is given and which value in
 *    its documented range it takes (enums, chemistries and booleans too).
 *    The mission is written as JSON and parsed, so the engine only ever
 *    sees what a mission file could say.
 * A valid mission is solved with the shipped reference tables and
 * catalogue ($AEROEVAL_DATA, else ./data), and the result must pass
 * solve_check(): no non-finite value anywhere, consistent feasibility.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "../solve_check.h"
#include "spec/spec.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static struct cli_env env;         /* read-only after init */
static struct solve_result result; /* large: not on the stack */

int
LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	if (getenv("AEROEVAL_DATA") == NULL)
		setenv("AEROEVAL_DATA", "data", 1);
	if (cli_env_load(&env, NULL, 1, stderr) != 0) {
		fprintf(stderr, "fuzz_solve: cannot load the shipped data\n");
		exit(1);
	}
	return 0;
}

/* The input as a byte stream; past the end it reads zeros. */
struct bytes {
	const uint8_t *p;
	size_t n;
};

static unsigned
take(struct bytes *b)
{
	if (b->n == 0)
		return 0;
	b->n--;
	return *b->p++;
}

/* The object for a dotted path's group ("locks.x" -> root.locks). */
static cJSON *
group_of(cJSON *root, const char *path, const char **leaf)
{
	const char *dot = strchr(path, '.');
	if (dot == NULL) {
		*leaf = path;
		return root;
	}
	char g[64];
	snprintf(g, sizeof g, "%.*s", (int)(dot - path), path);
	*leaf = dot + 1;
	cJSON *o = cJSON_GetObjectItemCaseSensitive(root, g);
	if (o == NULL)
		o = cJSON_AddObjectToObject(root, g);
	return o;
}

static char *
generate(struct bytes *b)
{
	cJSON *root = cJSON_CreateObject();
	for (int i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		if (take(b) % 2 == 0 || f->type == SPEC_DATE)
			continue; /* not given: the default or the derived value */
		if (f->type == SPEC_STR && f->id != SPECF_BATTERY_CHEMISTRY)
			continue; /* names and part ids do not reach the physics */
		const char *leaf;
		cJSON *g = group_of(root, f->path, &leaf);
		unsigned v = take(b);
		double u = (double)(v << 8 | take(b)) / 65535.0;
		switch (f->type) {
		case SPEC_NUM:
		case SPEC_SPEED: {
			if (f->type == SPEC_SPEED && v % 8 == 0) {
				cJSON_AddStringToObject(g, leaf, "auto");
				break;
			}
			double x = f->min + u * (f->max - f->min);
			if ((f->flags & SPEC_F_MIN_EXCL) && x <= f->min)
				x = f->min + 1e-3 * (f->max - f->min);
			cJSON_AddNumberToObject(g, leaf, x);
			break;
		}
		case SPEC_INT:
			cJSON_AddNumberToObject(g, leaf,
			    f->min + (double)(v % (unsigned)(f->max - f->min + 1)));
			break;
		case SPEC_BOOL:
			cJSON_AddBoolToObject(g, leaf, v % 2);
			break;
		case SPEC_ENUM: {
			int n = 0;
			while (f->enums[n] != NULL)
				n++;
			cJSON_AddStringToObject(g, leaf, f->enums[v % (unsigned)n]);
			break;
		}
		case SPEC_STR:
			cJSON_AddStringToObject(g, leaf,
			    env.model.chem_names[v % (unsigned)env.model.n_chem]);
			break;
		default:
			break;
		}
	}
	char *text = cJSON_PrintUnformatted(root);
	cJSON_Delete(root);
	return text;
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (size == 0)
		return 0;
	char *text = NULL;
	const char *buf = (const char *)data;
	size_t len = size;
	if (strchr("{ \t\r\n\xef", data[0]) == NULL) {
		struct bytes b = { data, size };
		text = generate(&b);
		buf = text;
		len = strlen(text);
	}
	char detail[RESULT_JSON_PATH_MAX];
	const char *why = solve_text(&env, "fuzz.json", buf, len, NULL, &result,
	    detail, sizeof detail);
	if (why != NULL && why != solve_rejected) {
		fprintf(stderr, "fuzz_solve: %s (%s)\nmission: %.*s\n", why, detail,
		    (int)len, buf);
		abort();
	}
	free(text);
	return 0;
}
