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
 * usage: build/bench closure SEED|LO-HI N AEROEVAL [DB]
 *   The closure report: N plausible missions made from SEED, or from each
 *   seed LO to HI (a line per seed, then the whole sample) (payload
 *   0.2-25 kg log-uniform, wheelbase 0.25-2 m, 4, 4, 6 or 8 rotors, hover
 *   600-1800 s, altitude 0-4000 m, one of the roles imaging, delivery,
 *   inspection, mapping or none; every other field its default), each
 *   solved by `AEROEVAL solve [--db DB]`.  Prints how many size
 *   continuously, how many of those close on real parts (a design of
 *   record with no violation of its own), the closed-vs-continuous takeoff
 *   mass gap (median, median of its size, worst), the gap split by mass
 *   line (each line's median share of the continuous takeoff mass) and
 *   the failures by code.
 *   With CLOSURE_LIST=1 it also lists every mission that does not close.
 *   Deterministic: the same lines for the same SEED, binary and catalogue.
 *
 * usage: build/bench aircraft COHORT [DB]
 *   Closure on the missions real aircraft fly: each row of the cohort CSV
 *   made into its mission as `validate` makes it (the endurance rule) but
 *   with the propeller, bus, chemistry and pack count left to the search,
 *   then solved with the parts catalogue DB (default data/catalog).  A line per
 *   row (its real takeoff mass, the continuous design, the design of
 *   record and its verdict with the codes of what fails), then how many
 *   rows size continuously and how many of those close on real parts.
 *   With CLOSURE_LIST=1 it also prints what fails, for each open row.
 *
 * usage: build/bench catalog SRC DST FACTOR
 *   Writes into DST every .json catalogue file of SRC with each entry of its
 *   top-level array repeated FACTOR times, the copies' ids suffixed -x2,
 *   -x3, ... (ids must stay unique): a catalogue FACTOR times the size,
 *   for measuring how the solve scales with it (`aeroeval solve --db DST`).
 *   Every other field is kept, so the copies are valid entries.
 */
#include <dirent.h>
#include <unistd.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "cli/cli.h"
#include "result/result.h"
#include "engine/engine.h"
#include "input/cohort.h"
#include "study/validate.h"
#include "util/file.h"
#include "util/xalloc.h"

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

/* ---- closure report -------------------------------------------------- */

#define CLOSURE_MAX_CODES 32

/* The mass-breakdown lines of result.json the gap is split into, with the
 * names the report prints. */
static const char *const closure_part_key[] = {
	"motor_mass_kg", "prop_mass_kg", "battery_mass_kg", "esc_mass_kg",
	"wiring_mass_kg", "frame_mass_kg", "arm_mass_kg", "avionics_mass_kg",
	"other_mass_kg", "role_aux_mass_kg",
};
static const char *const closure_part_name[] = {
	"motors", "propellers", "battery", "ESCs", "harness and connectors",
	"frame", "arms", "avionics", "body and equipment", "role hardware",
};
#define CLOSURE_PARTS (sizeof closure_part_key / sizeof closure_part_key[0])

/* Continuous takeoff-mass bands the closure is also counted in, kg. */
static const double closure_band_kg[] = { 5.0, 20.0, 50.0 };
#define CLOSURE_BANDS (sizeof closure_band_kg / sizeof closure_band_kg[0] + 1)

struct closure {
	int n_missions, n_continuous, n_closed;
	int band_sized[CLOSURE_BANDS], band_closed[CLOSURE_BANDS];
	int n_feasible;               /* sized, and the continuous design passes
	                                 every check */
	int n_feasible_closed;        /* ... and closed */
	double *gap;                  /* closed / continuous - 1, per closure */
	double *part_gap[CLOSURE_PARTS]; /* each line's record - continuous,
	                                    over the continuous takeoff mass */
	char code[CLOSURE_MAX_CODES][48];
	int n_code[CLOSURE_MAX_CODES];
	int n_codes;
};

/* One plausible mission of the closure study, the i-th from s. */
static cJSON *
closure_mission(uint64_t *s)
{
	static const char *const roles[] = { "imaging", "delivery", "inspection",
		"mapping", "none" };
	static const int rotors[] = { 4, 4, 6, 8 };
	cJSON *m = cJSON_CreateObject();
	cJSON_AddNumberToObject(m, "payload_kg",
	    round(pow(10.0, uniform(s, -0.7, 1.4)) * 100.0) / 100.0);
	cJSON_AddNumberToObject(m, "max_diameter_m",
	    round(uniform(s, 0.25, 2.0) * 100.0) / 100.0);
	cJSON_AddNumberToObject(m, "num_rotors", rotors[next_u64(s) % 4]);
	cJSON_AddNumberToObject(m, "t_hover_s", round(uniform(s, 600.0, 1800.0)));
	cJSON_AddNumberToObject(m, "altitude_m", round(uniform(s, 0.0, 4000.0)));
	cJSON *role = cJSON_AddObjectToObject(m, "payload_role");
	cJSON_AddStringToObject(role, "type", roles[next_u64(s) % 5]);
	return m;
}

static void
closure_count(struct closure *c, const char *code)
{
	for (int i = 0; i < c->n_codes; i++)
		if (strcmp(c->code[i], code) == 0) {
			c->n_code[i]++;
			return;
		}
	if (c->n_codes < CLOSURE_MAX_CODES) {
		snprintf(c->code[c->n_codes], sizeof c->code[0], "%s", code);
		c->n_code[c->n_codes++] = 1;
	}
}

/* The solve's stdout, whole (caller frees), or NULL. */
static char *
closure_solve(const char *cmd)
{
	FILE *p = popen(cmd, "r");
	if (p == NULL)
		return NULL;
	size_t cap = 1u << 20, len = 0;
	char *buf = malloc(cap);
	size_t got;
	while (buf != NULL && (got = fread(buf + len, 1, cap - len - 1, p)) > 0) {
		len += got;
		if (len + 1 == cap) {
			char *more = realloc(buf, cap *= 2);
			if (more == NULL) {
				free(buf);
				buf = NULL;
			}
			buf = more;
		}
	}
	pclose(p);
	if (buf != NULL)
		buf[len] = '\0';
	return buf;
}

/* Record one solve's result.json (text) in c; name for the listing. */
static void
closure_record(struct closure *c, const char *text, const char *name,
               const cJSON *mission, bool list)
{
	cJSON *r = text != NULL ? cJSON_Parse(text) : NULL;
	const cJSON *custom = cJSON_GetObjectItemCaseSensitive(r, "custom");
	/* A mission beyond reach ("ceiling" set) does not size as asked,
	 * whatever design its custom run shows. */
	const cJSON *ceiling = cJSON_GetObjectItemCaseSensitive(r, "ceiling");
	if (!cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(custom, "ran"))
	    || !cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(custom, "converged"))
	    || cJSON_IsObject(ceiling)) {
		if (r == NULL)
			closure_count(c, "(no result)");
		cJSON_Delete(r);
		return;
	}
	c->n_continuous++;
	double m_cont = cJSON_GetNumberValue(
	    cJSON_GetObjectItemCaseSensitive(custom, "total_mass_kg"));
	size_t band = 0;
	while (band + 1 < CLOSURE_BANDS && !(m_cont < closure_band_kg[band]))
		band++;
	c->band_sized[band]++;
	bool cont_feasible = cJSON_IsTrue(
	    cJSON_GetObjectItemCaseSensitive(custom, "feasible"));
	c->n_feasible += cont_feasible;
	const cJSON *rec = cJSON_GetObjectItemCaseSensitive(r, "design_of_record");
	double m_rec = cJSON_GetNumberValue(
	    cJSON_GetObjectItemCaseSensitive(rec, "total_mass_kg"));
	bool buildable = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(r, "buildable"));
	int failed = 0;
	const cJSON *v;
	cJSON_ArrayForEach(v, cJSON_GetObjectItemCaseSensitive(r, "violations")) {
		const char *run = cJSON_GetStringValue(
		    cJSON_GetObjectItemCaseSensitive(v, "run"));
		const char *code = cJSON_GetStringValue(
		    cJSON_GetObjectItemCaseSensitive(v, "code"));
		if (run != NULL && code != NULL && strcmp(run, "closed") == 0) {
			closure_count(c, code);
			failed++;
		}
	}
	if (buildable && failed == 0 && m_cont > 0.0) {
		for (size_t k = 0; k < CLOSURE_PARTS; k++) {
			double rec_kg = cJSON_GetNumberValue(cJSON_GetObjectItemCaseSensitive(
			    rec, closure_part_key[k]));
			double cont_kg = cJSON_GetNumberValue(cJSON_GetObjectItemCaseSensitive(
			    custom, closure_part_key[k]));
			c->part_gap[k][c->n_closed] = isfinite(rec_kg - cont_kg)
			    ? (rec_kg - cont_kg) / m_cont : 0.0;
		}
		c->gap[c->n_closed++] = m_rec / m_cont - 1.0;
		c->band_closed[band]++;
		c->n_feasible_closed += cont_feasible;
	} else if (list) {
		char *m = cJSON_PrintUnformatted(mission);
		printf("  open %s %s\n", name, m != NULL ? m : "");
		free(m);
	}
	cJSON_Delete(r);
}

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The median of n sorted values (n >= 1). */
static double
median_sorted(const double *v, int n)
{
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static void
closure_init(struct closure *c, int cap)
{
	memset(c, 0, sizeof *c);
	c->gap = calloc((size_t)cap, sizeof *c->gap);
	for (size_t k = 0; k < CLOSURE_PARTS; k++)
		c->part_gap[k] = calloc((size_t)cap, sizeof *c->part_gap[k]);
}

static void
closure_free(struct closure *c)
{
	free(c->gap);
	for (size_t k = 0; k < CLOSURE_PARTS; k++)
		free(c->part_gap[k]);
}

/* The n missions of seed, each solved, recorded in c; dir is scratch. */
static int
closure_run(uint64_t seed, int n, const char *bin, const char *db,
            const char *dir, struct closure *c)
{
	bool list = getenv("CLOSURE_LIST") != NULL;
	uint64_t s = seed * 0x9E3779B97F4A7C15u + 1;
	int rc = 0;
	for (int i = 0; i < n && rc == 0; i++) {
		char name[48], path[4200], cmd[8600];
		snprintf(name, sizeof name, "s%llu-m%04d", (unsigned long long)seed, i);
		snprintf(path, sizeof path, "%s/%s.json", dir, name);
		cJSON *m = closure_mission(&s);
		rc = write_json(path, m);
		if (rc == 0) {
			snprintf(cmd, sizeof cmd, "'%s' solve %s%s%s '%s' 2>/dev/null",
			    bin, db != NULL ? "--db '" : "", db != NULL ? db : "",
			    db != NULL ? "'" : "", path);
			char *out = closure_solve(cmd);
			closure_record(c, out, name, m, list);
			free(out);
			c->n_missions++;
		}
		remove(path);
		cJSON_Delete(m);
	}
	return rc;
}

/* Add src's counts, gaps and failure codes to dst (room for them). */
static void
closure_merge(struct closure *dst, const struct closure *src)
{
	for (int i = 0; i < src->n_closed; i++) {
		dst->gap[dst->n_closed + i] = src->gap[i];
		for (size_t k = 0; k < CLOSURE_PARTS; k++)
			dst->part_gap[k][dst->n_closed + i] = src->part_gap[k][i];
	}
	for (size_t b = 0; b < CLOSURE_BANDS; b++) {
		dst->band_sized[b] += src->band_sized[b];
		dst->band_closed[b] += src->band_closed[b];
	}
	dst->n_missions += src->n_missions;
	dst->n_continuous += src->n_continuous;
	dst->n_closed += src->n_closed;
	dst->n_feasible += src->n_feasible;
	dst->n_feasible_closed += src->n_feasible_closed;
	for (int i = 0; i < src->n_codes; i++)
		for (int j = 0; j < src->n_code[i]; j++)
			closure_count(dst, src->code[i]);
}

/* The line of a closure report that keeps the missions whose continuous
 * design passes every check: a continuous design that fails one (tip
 * Mach, most often) is a mission no aircraft flies, and real parts are not
 * asked to close it. */
static void
print_feasible_rate(int n_feasible, int n_feasible_closed)
{
	printf("of those, continuous design feasible %d, closed on real parts "
	    "%d (%.1f %%)\n", n_feasible, n_feasible_closed,
	    n_feasible > 0 ? 100.0 * n_feasible_closed / n_feasible : 0.0);
}

/* The report's lines for c; seeds names the sample ("seed 1", "seeds 1-3"). */
static void
closure_print(struct closure *c, const char *seeds)
{
	printf("missions %d (%s), sized continuously %d, closed on real "
	    "parts %d (%.1f %%)\n", c->n_missions, seeds, c->n_continuous,
	    c->n_closed, c->n_continuous > 0
	    ? 100.0 * c->n_closed / c->n_continuous : 0.0);
	print_feasible_rate(c->n_feasible, c->n_feasible_closed);
	printf("closed by continuous takeoff mass:");
	for (size_t b = 0; b < CLOSURE_BANDS; b++) {
		if (b == 0)
			printf(" below %.0f kg", closure_band_kg[0]);
		else if (b + 1 == CLOSURE_BANDS)
			printf(", %.0f kg and over", closure_band_kg[b - 1]);
		else
			printf(", %.0f-%.0f kg", closure_band_kg[b - 1], closure_band_kg[b]);
		printf(" %d of %d", c->band_closed[b], c->band_sized[b]);
	}
	printf("\n");
	if (c->n_closed > 0) {
		double *abs_gap = calloc((size_t)c->n_closed, sizeof *abs_gap);
		double worst = 0.0;
		for (int i = 0; i < c->n_closed; i++) {
			abs_gap[i] = fabs(c->gap[i]);
			if (abs_gap[i] > fabs(worst))
				worst = c->gap[i];
		}
		qsort(c->gap, (size_t)c->n_closed, sizeof *c->gap, cmp_double);
		qsort(abs_gap, (size_t)c->n_closed, sizeof *abs_gap, cmp_double);
		double med = median_sorted(c->gap, c->n_closed);
		double med_abs = median_sorted(abs_gap, c->n_closed);
		printf("closed vs continuous takeoff mass: median %+.1f %%, median "
		    "|gap| %.1f %%, worst %+.1f %%\n", 100.0 * med, 100.0 * med_abs,
		    100.0 * worst);
		free(abs_gap);
		/* Where the gap sits: each mass line's median share of the
		 * continuous takeoff mass, the largest first. */
		double part_med[CLOSURE_PARTS];
		bool shown[CLOSURE_PARTS] = { false };
		for (size_t k = 0; k < CLOSURE_PARTS; k++) {
			qsort(c->part_gap[k], (size_t)c->n_closed, sizeof *c->part_gap[k],
			    cmp_double);
			part_med[k] = median_sorted(c->part_gap[k], c->n_closed);
		}
		printf("gap by mass line (record - continuous, median, of the "
		    "continuous takeoff mass):");
		for (size_t done = 0; done < CLOSURE_PARTS; done++) {
			size_t best = CLOSURE_PARTS;
			for (size_t k = 0; k < CLOSURE_PARTS; k++)
				if (!shown[k] && (best == CLOSURE_PARTS
				    || fabs(part_med[k]) > fabs(part_med[best])))
					best = k;
			shown[best] = true;
			if (fabs(part_med[best]) >= 0.0005)
				printf("%s %s %+.1f %%", done ? "," : "",
				    closure_part_name[best], 100.0 * part_med[best]);
		}
		printf("\n");
	}
	/* Failures by code, most first (ties by name: deterministic). */
	printf("failures by code (missions sized continuously but not closed):");
	int shown_codes[CLOSURE_MAX_CODES] = { 0 };
	for (int done = 0; done < c->n_codes; done++) {
		int best = -1;
		for (int i = 0; i < c->n_codes; i++)
			if (!shown_codes[i] && (best < 0 || c->n_code[i] > c->n_code[best]
			    || (c->n_code[i] == c->n_code[best]
			    && strcmp(c->code[i], c->code[best]) < 0)))
				best = i;
		shown_codes[best] = 1;
		printf("%s %s %d", done ? "," : "", c->code[best], c->n_code[best]);
	}
	printf("%s\n", c->n_codes ? "" : " none");
}

/* The closure report over seeds lo..hi, n missions each: a line per seed
 * when there are several, then the whole sample. */
static int
closure_report(uint64_t lo, uint64_t hi, int n, const char *bin, const char *db)
{
	char dir[] = "/tmp/aeroeval-closure-XXXXXX";
	if (n < 1 || hi < lo || hi - lo >= 100 || mkdtemp(dir) == NULL) {
		fprintf(stderr, "bench: closure needs N >= 1, at most 100 seeds "
		    "and a temporary folder\n");
		return 2;
	}
	int n_seeds = (int)(hi - lo + 1);
	struct closure all;
	closure_init(&all, n * n_seeds);
	int rc = 0;
	for (uint64_t seed = lo; seed <= hi && rc == 0; seed++) {
		struct closure c;
		closure_init(&c, n);
		rc = closure_run(seed, n, bin, db, dir, &c);
		if (n_seeds > 1)
			printf("  seed %llu: %d missions, sized continuously %d, closed "
			    "%d (%.1f %%)\n", (unsigned long long)seed, c.n_missions,
			    c.n_continuous, c.n_closed, c.n_continuous > 0
			    ? 100.0 * c.n_closed / c.n_continuous : 0.0);
		closure_merge(&all, &c);
		closure_free(&c);
	}
	rmdir(dir);
	char seeds[64];
	if (n_seeds > 1)
		snprintf(seeds, sizeof seeds, "seeds %llu-%llu",
		    (unsigned long long)lo, (unsigned long long)hi);
	else
		snprintf(seeds, sizeof seeds, "seed %llu", (unsigned long long)lo);
	closure_print(&all, seeds);
	closure_free(&all);
	return rc;
}

/* ---- closure on real aircraft's missions --------------------------------- */

/* The codes of r's violations of run, comma-separated, into buf. */
static int
run_codes(const struct solve_result *r, const char *run, char *buf, size_t n)
{
	int count = 0;
	size_t len = 0;
	buf[0] = '\0';
	for (int i = 0; i < r->n_violations; i++) {
		if (strcmp(r->violations[i].run, run) != 0)
			continue;
		int w = snprintf(buf + len, n - len, "%s%s", count ? "," : "",
		    r->violations[i].code);
		if (w > 0 && (size_t)w < n - len)
			len += (size_t)w;
		count++;
	}
	return count;
}

static int
aircraft_report(const char *cohort_path, const char *db)
{
	struct cli_env env;
	if (cli_env_load(&env, db, 1, stderr) != 0)
		return 2;
	struct cohort co;
	if (cohort_load(cohort_path, &co) != 0 || co.n_errors > 0) {
		fprintf(stderr, "bench: %s: not a readable cohort\n", cohort_path);
		cli_env_free(&env);
		return 2;
	}
	bool list = getenv("CLOSURE_LIST") != NULL;
	struct solve_result *r = xmalloc(sizeof *r);
	int n_rows = 0, n_sized = 0, n_feasible = 0, n_closed = 0;
	int n_feasible_closed = 0;
	printf("%-32s %9s %11s %9s  %s\n", "aircraft", "real kg", "continuous",
	    "record", "verdict");
	for (size_t i = 0; i < co.n_rows; i++) {
		struct mission_spec spec;
		unsigned notes;
		if (validate_mission_from_row(&co.rows[i], &env.model, &spec, &notes)
		    != VALIDATE_SKIP_NONE)
			continue;
		/* The mission, not the maker's design: what the aircraft flies
		 * on its frame; its propeller, bus, chemistry and packs are the
		 * search's to choose (validate locks the published ones). */
		spec.locks.is_prop_locked = false;
		spec.given[SPECF_LOCK_PROP] = false;
		spec.given[SPECF_LOCK_DIAMETER_IN] = false;
		spec.given[SPECF_LOCK_PITCH_IN] = false;
		spec.nominal_cell_count = 0;
		spec.given[SPECF_NOMINAL_CELL_COUNT] = false;
		spec.given[SPECF_BATTERY_CHEMISTRY] = false;
		spec.battery_pack_count = 1;
		spec.given[SPECF_BATTERY_PACK_COUNT] = false;
		n_rows++;
		memset(r, 0, sizeof *r);
		engine_solve(&spec, &env.model, env.cat, r);
		char codes[512];
		/* Beyond reach: the mission as asked does not size (the custom
		 * run may hold the ceiling design, the longest flight that
		 * does). */
		if (!r->custom.ran || !r->custom.converged || r->ceiling.valid) {
			run_codes(r, "custom", codes, sizeof codes);
			printf("%-32.32s %9.3f %11s %9s  %s (%s)\n",
			    co.rows[i].name, co.rows[i].takeoff_mass_kg, "-", "-",
			    r->ceiling.valid ? "beyond reach" : "not sized", codes);
			continue;
		}
		n_sized++;
		n_feasible += r->custom.feasible;
		int failed = run_codes(r, "closed", codes, sizeof codes);
		bool closed = r->parts_selected && failed == 0;
		n_closed += closed;
		n_feasible_closed += closed && r->custom.feasible;
		printf("%-32.32s %9.3f %11.3f %9.3f  %s%s%s%s\n", co.rows[i].name,
		    co.rows[i].takeoff_mass_kg, r->custom.mass.total_kg,
		    r->parts_selected ? r->closed.mass.total_kg : 0.0,
		    closed ? "closes" : "open (", closed ? "" : codes,
		    closed ? "" : ")", r->custom.feasible ? ""
		    : " [continuous design infeasible]");
		for (int k = 0; list && !closed && k < r->n_violations; k++)
			if (strcmp(r->violations[k].run, "closed") == 0)
				printf("    %s\n", r->violations[k].message);
	}
	printf("aircraft %d with a mission, sized continuously %d, closed on real "
	    "parts %d (%.1f %%)\n", n_rows, n_sized, n_closed,
	    n_sized > 0 ? 100.0 * n_closed / n_sized : 0.0);
	print_feasible_rate(n_feasible, n_feasible_closed);
	free(r);
	cohort_free(&co);
	cli_env_free(&env);
	return 0;
}

int
main(int argc, char **argv)
{
	if ((argc == 5 || argc == 6) && strcmp(argv[1], "closure") == 0) {
		/* SEED or a range LO-HI. */
		char *end;
		uint64_t lo = strtoull(argv[2], &end, 10), hi = lo;
		if (*end == '-')
			hi = strtoull(end + 1, &end, 10);
		if (*end != '\0') {
			fprintf(stderr, "bench: closure SEED is a number or LO-HI\n");
			return 2;
		}
		return closure_report(lo, hi, atoi(argv[3]), argv[4],
		    argc == 6 ? argv[5] : NULL);
	}
	if ((argc == 3 || argc == 4) && strcmp(argv[1], "aircraft") == 0)
		return aircraft_report(argv[2], argc == 4 ? argv[3] : NULL);
	if (argc == 5 && strcmp(argv[1], "missions") == 0)
		return make_missions(strtoull(argv[2], NULL, 10), atoi(argv[3]), argv[4]);
	if (argc == 5 && strcmp(argv[1], "catalog") == 0 && atoi(argv[4]) >= 1)
		return grow_catalog(argv[2], argv[3], atoi(argv[4]));
	fprintf(stderr, "usage: bench missions SEED N DIR\n"
	                "       bench closure SEED|LO-HI N AEROEVAL [DB]\n"
	                "       bench aircraft COHORT [DB]\n"
	                "       bench catalog SRC DST FACTOR\n");
	return 2;
}
