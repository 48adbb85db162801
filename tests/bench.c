/* bench.c — the inputs `make bench` measures with, made deterministically.
 *
 * usage: build/bench missions SEED N DIR
 *   Writes N varied missions DIR/m0000.json ... from a pseudo-random
 *   sequence seeded by SEED (the same files for the same SEED on every
 *   machine): payload 0.2-25 kg (log-uniform), wheelbase 0.25-2 m, 4, 6 or
 *   8 rotors, every payload role, altitude 0-3000 m, hover 60-900 s,
 *   forward flight 0-1200 s at 5-18 m/s, one of three chemistries.  Many
 *   are infeasible (a 25 kg payload on a 0.25 m frame): an infeasible
 *   design still gets its whole dossier, so it costs what a feasible one
 *   does.
 *
 * usage: build/bench catalog SRC DST FACTOR
 *   Writes into DST every .json catalogue file of SRC with each entry of its
 *   top-level array repeated FACTOR times, the copies' ids suffixed -x2,
 *   -x3, ... (ids must stay unique): a catalogue FACTOR times the size,
 *   for measuring how the solve scales with it (`aeroeval solve --db DST`).
 *   Every other field is kept, so the copies are valid entries.
 */
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "util/file.h"

/* xorshift64: a fixed sequence for a fixed seed, whatever the libc. */
static uint64_t
next_u64(uint64_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 7;
	*s ^= *s << 17;
	return *s;
}

/* Uniform in [lo, hi], rounded to 3 decimals so the files read well. */
static double
uniform(uint64_t *s, double lo, double hi)
{
	double u = (double)(next_u64(s) >> 11) * 0x1p-53;
	return (double)(long long)((lo + u * (hi - lo)) * 1000.0 + 0.5) / 1000.0;
}

static int
write_json(const char *path, const cJSON *root)
{
	char *text = cJSON_Print(root);
	FILE *f = fopen(path, "w");
	int rc = text != NULL && f != NULL && fputs(text, f) >= 0 ? 0 : -1;
	if (f != NULL && fclose(f) != 0)
		rc = -1;
	free(text);
	if (rc != 0)
		fprintf(stderr, "bench: cannot write %s\n", path);
	return rc;
}

static int
make_missions(uint64_t seed, int n, const char *dir)
{
	static const char *const roles[] = { "none", "imaging", "delivery",
		"agriculture", "racing", "inspection", "mapping" };
	static const char *const chems[] = { "LiPo", "Li-ion NMC", "LiHV" };
	static const int rotors[] = { 4, 6, 8 };
	uint64_t s = seed * 0x9E3779B97F4A7C15u + 1;
	for (int i = 0; i < n; i++) {
		char name[64], path[4200];
		snprintf(name, sizeof name, "bench mission %04d", i);
		cJSON *m = cJSON_CreateObject();
		cJSON *rep = cJSON_AddObjectToObject(m, "report");
		cJSON_AddStringToObject(rep, "title", name);
		cJSON_AddStringToObject(rep, "date", "2026-11-22");
		/* log-uniform 0.2 .. 25 kg: as many small aircraft as big ones */
		double payload = 0.2 * pow(125.0, uniform(&s, 0.0, 1.0));
		cJSON_AddNumberToObject(m, "payload_kg", round(payload * 1000.0) / 1000.0);
		cJSON_AddNumberToObject(m, "max_diameter_m", uniform(&s, 0.25, 2.0));
		cJSON_AddNumberToObject(m, "num_rotors", rotors[next_u64(&s) % 3]);
		cJSON_AddNumberToObject(m, "altitude_m", uniform(&s, 0.0, 3000.0));
		cJSON_AddNumberToObject(m, "t_hover_s", uniform(&s, 60.0, 900.0));
		cJSON_AddNumberToObject(m, "t_climb_s", uniform(&s, 20.0, 90.0));
		cJSON_AddNumberToObject(m, "t_forward_s", uniform(&s, 0.0, 1200.0));
		cJSON_AddNumberToObject(m, "v_forward_ms", uniform(&s, 5.0, 18.0));
		cJSON_AddStringToObject(m, "battery_chemistry", chems[next_u64(&s) % 3]);
		cJSON *role = cJSON_AddObjectToObject(m, "payload_role");
		cJSON_AddStringToObject(role, "type", roles[next_u64(&s) % 7]);
		snprintf(path, sizeof path, "%s/m%04d.json", dir, i);
		int rc = write_json(path, m);
		cJSON_Delete(m);
		if (rc != 0)
			return 1;
	}
	return 0;
}

/* SRC/FILE's top-level arrays, each entry repeated factor times. */
static int
grow_file(const char *src, const char *dst, const char *file, int factor)
{
	char in[4200], out[4200], err[256];
	unsigned char *buf = NULL;
	size_t n = 0;
	snprintf(in, sizeof in, "%s/%s", src, file);
	snprintf(out, sizeof out, "%s/%s", dst, file);
	if (file_read(in, 64u << 20, &buf, &n, err, sizeof err) != 0) {
		fprintf(stderr, "bench: %s\n", err);
		return 1;
	}
	cJSON *root = cJSON_ParseWithLength((const char *)buf, n);
	free(buf);
	if (root == NULL) {
		fprintf(stderr, "bench: %s is not JSON\n", in);
		return 1;
	}
	cJSON *arr;
	cJSON_ArrayForEach(arr, root) {
		if (!cJSON_IsArray(arr))
			continue;
		int n0 = cJSON_GetArraySize(arr);
		for (int k = 2; k <= factor; k++)
			for (int i = 0; i < n0; i++) {
				cJSON *e = cJSON_Duplicate(cJSON_GetArrayItem(arr, i), 1);
				cJSON *id = cJSON_GetObjectItemCaseSensitive(e, "id");
				if (cJSON_IsString(id)) {
					char nid[256];
					snprintf(nid, sizeof nid, "%s-x%d", id->valuestring, k);
					cJSON_SetValuestring(id, nid);
				}
				cJSON_AddItemToArray(arr, e);
			}
	}
	int rc = write_json(out, root);
	cJSON_Delete(root);
	return rc;
}

static int
grow_catalog(const char *src, const char *dst, int factor)
{
	DIR *d = opendir(src);
	if (d == NULL) {
		fprintf(stderr, "bench: cannot open %s\n", src);
		return 1;
	}
	int rc = 0;
	struct dirent *de;
	while (rc == 0 && (de = readdir(d)) != NULL) {
		size_t len = strlen(de->d_name);
		if (len > 5 && strcmp(de->d_name + len - 5, ".json") == 0)
			rc = grow_file(src, dst, de->d_name, factor);
	}
	closedir(d);
	return rc;
}

int
main(int argc, char **argv)
{
	if (argc == 5 && strcmp(argv[1], "missions") == 0)
		return make_missions(strtoull(argv[2], NULL, 10), atoi(argv[3]), argv[4]);
	if (argc == 5 && strcmp(argv[1], "catalog") == 0 && atoi(argv[4]) >= 1)
		return grow_catalog(argv[2], argv[3], atoi(argv[4]));
	fprintf(stderr, "usage: bench missions SEED N DIR\n"
	                "       bench catalog SRC DST FACTOR\n");
	return 2;
}
