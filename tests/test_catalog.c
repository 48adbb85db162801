/* test_catalog.c — the parts catalogue: shipped coverage, loader, diagnostics. */
#include "test_util.h"
#include "core/catalog.h"
#include "util/file.h"
#include "util/sha256.h"

#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#define SHIPPED_DIR "data/catalog"
#define FIXTURE_DIR "tests/fixtures/catalog"

static const char *const category_files[] = {
	"motors.json", "propellers.json", "batteries.json", "escs.json",
};

/* Loads dir; on failure prints the diagnostics so a broken shipped catalogue
 * explains itself in the test log. */
static struct catalog *
load_or_print(const char *dir)
{
	int n_err = -1;
	struct catalog *c = catalog_load(dir, NULL, stderr, &n_err);
	if (c == NULL)
		print_error("catalog_load(%s) failed with %d errors\n", dir, n_err);
	assert_non_null(c);
	assert_int_equal(n_err, 0);
	return c;
}

/* ---- the shipped catalogue ------------------------------------------------ */

static void
catalog_shipped_should_meet_the_coverage_targets(void **state)
{
	(void)state;
	struct catalog *c = load_or_print(SHIPPED_DIR);
	size_t n_motor = 0, n_prop = 0, n_batt = 0, n_esc = 0;
	bool racer_motor = false, ag_motor = false, five_inch = false, big_prop = false;
	bool racer_pack = false, ag_pack = false, four_in_one = false, ag_esc = false;
	int s_min = 1000, s_max = 0;

	for (size_t i = 0; i < catalog_n_motors(c); i++) {
		const struct catalog_motor *m = catalog_motor(c, i);
		if (!m->usable)
			continue;
		n_motor++;
		racer_motor |= m->kv_rpm_per_v >= 1700 && m->mass_kg < 0.060;
		ag_motor |= m->kv_rpm_per_v <= 150 && m->mass_kg > 0.3;
	}
	for (size_t i = 0; i < catalog_n_props(c); i++) {
		const struct catalog_prop *p = catalog_prop(c, i);
		if (!p->usable)
			continue;
		n_prop++;
		five_inch |= p->diameter_in >= 5 && p->diameter_in <= 5.2;
		big_prop |= p->diameter_in >= 30;
	}
	for (size_t i = 0; i < catalog_n_batteries(c); i++) {
		const struct catalog_battery *b = catalog_battery(c, i);
		if (!b->usable)
			continue;
		n_batt++;
		if (b->cells_series >= 4 && b->cells_series < s_min)
			s_min = b->cells_series;
		if (b->cells_series > s_max)
			s_max = b->cells_series;
		racer_pack |= b->cells_series >= 4 && b->cells_series <= 6 &&
		              b->capacity_ah >= 1.0 && b->capacity_ah <= 1.5;
		ag_pack |= b->cells_series >= 12 && b->capacity_ah >= 14;
	}
	for (size_t i = 0; i < catalog_n_escs(c); i++) {
		const struct catalog_esc *e = catalog_esc(c, i);
		if (!e->usable)
			continue;
		n_esc++;
		four_in_one |= e->channels == 4 && e->continuous_current_a >= 30;
		ag_esc |= e->continuous_current_a >= 80;
	}
	assert_true(n_motor >= 60);
	assert_true(n_prop >= 40);
	assert_true(n_batt >= 40);
	assert_true(n_esc >= 20);
	assert_true(racer_motor);
	assert_true(ag_motor);
	assert_true(five_inch);
	assert_true(big_prop);
	assert_true(racer_pack);
	assert_true(ag_pack);
	assert_true(four_in_one);
	assert_true(ag_esc);
	assert_int_equal(s_min, 4);
	assert_true(s_max >= 12);
	catalog_free(c);
}

/* Each entry's id, source and confidence, whatever its category. */
struct meta {
	const char *id, *source, *confidence, *manufacturer, *part_number;
	bool usable;
};

static size_t
collect_meta(const struct catalog *c, struct meta *out, size_t cap)
{
	size_t n = 0;
#define COLLECT(count, get)                                                   \
	for (size_t i = 0; i < count(c) && n < cap; i++, n++) {                \
		out[n] = (struct meta){ get(c, i)->id, get(c, i)->source,      \
		    get(c, i)->confidence, get(c, i)->manufacturer,               \
		    get(c, i)->part_number, get(c, i)->usable };                  \
	}
	COLLECT(catalog_n_motors, catalog_motor)
	COLLECT(catalog_n_props, catalog_prop)
	COLLECT(catalog_n_batteries, catalog_battery)
	COLLECT(catalog_n_escs, catalog_esc)
#undef COLLECT
	return n;
}

static void
catalog_shipped_ids_should_be_unique_and_usable_entries_sourced(void **state)
{
	(void)state;
	struct catalog *c = load_or_print(SHIPPED_DIR);
	static struct meta all[2048];
	size_t n = collect_meta(c, all, 2048);
	assert_true(n < 2048);
	for (size_t i = 0; i < n; i++) {
		for (size_t j = 0; j < i; j++)
			if (strcmp(all[i].id, all[j].id) == 0)
				fail_msg("duplicate id %s", all[i].id);
		if (all[i].usable)
			assert_true(strlen(all[i].source) > 10);
		assert_true(strcmp(all[i].confidence, "high") == 0 ||
		            strcmp(all[i].confidence, "medium") == 0 ||
		            strcmp(all[i].confidence, "low") == 0);
	}
	catalog_free(c);
}

/* The BOM, the dossier and the rationale print a part as "maker part
 * number": a part number that starts with the maker's name reads
 * "Tattu Tattu 7000mAh ..." there, and is not how the maker lists it. */
static void
catalog_shipped_part_numbers_should_not_repeat_the_maker(void **state)
{
	(void)state;
	struct catalog *c = load_or_print(SHIPPED_DIR);
	static struct meta all[2048];
	size_t n = collect_meta(c, all, 2048);
	for (size_t i = 0; i < n; i++) {
		size_t k = strlen(all[i].manufacturer);
		if (k > 0 && strncasecmp(all[i].part_number, all[i].manufacturer, k) == 0)
			fail_msg("%s: part number \"%s\" repeats the maker \"%s\"",
			    all[i].id, all[i].part_number, all[i].manufacturer);
	}
	catalog_free(c);
}

static void
catalog_shipped_values_should_be_converted_to_si(void **state)
{
	(void)state;
	struct catalog *c = load_or_print(SHIPPED_DIR);
	/* Values checked against the T-Motor MN5008 KV340 row (135 g, 55 mOhm). */
	const struct catalog_motor *m = catalog_find_motor(c, "tmotor-mn5008-kv340");
	assert_non_null(m);
	assert_rel(m->mass_kg, 0.135, 1e-12);
	assert_rel(m->resistance_ohm, 0.055, 1e-12);
	assert_rel(m->kv_rpm_per_v, 340, 1e-12);
	assert_true(m->usable);
	/* An integrated Hobbywing system carries its propeller size. */
	const struct catalog_motor *x = catalog_find_motor(c, "hobbywing-xrotor-x9-g2l-integrated-system");
	assert_non_null(x);
	assert_true(x->integrated);
	assert_rel(x->integrated_prop_in, 36, 1e-12);
	assert_null(catalog_find_motor(c, "no-such-part"));
	assert_null(catalog_find_prop(c, "tmotor-mn5008-kv340"));   /* ids are per category */
	catalog_free(c);
}

/* ---- the loader on fixtures ---------------------------------------------- */

static void
catalog_load_should_read_a_minimal_catalogue(void **state)
{
	(void)state;
	struct catalog *c = load_or_print(FIXTURE_DIR "/good/");   /* trailing '/' is fine */
	assert_int_equal(catalog_n_motors(c), 3);
	assert_int_equal(catalog_n_props(c), 1);
	assert_int_equal(catalog_n_batteries(c), 2);
	assert_int_equal(catalog_n_escs(c), 1);

	const struct catalog_motor *m = catalog_motor(c, 0);
	assert_string_equal(m->id, "fx-motor-a");
	assert_string_equal(m->part_number, "FX5008 KV340");
	assert_rel(m->mass_kg, 0.1355, 1e-12);
	assert_rel(m->resistance_ohm, 0.055, 1e-12);
	assert_int_equal(m->cells_min, 6);
	assert_int_equal(m->cells_max, 12);
	assert_rel(m->price_usd, 89.99, 1e-12);
	assert_true(m->usable);
	assert_false(m->integrated);
	assert_string_equal(m->uncertain, "");

	m = catalog_find_motor(c, "fx-motor-unknown-mass");
	assert_non_null(m);
	assert_false(m->usable);
	assert_true(m->mass_kg == 0 && m->price_usd == 0 && m->cells_min == 0);

	m = catalog_find_motor(c, "fx-system");
	assert_true(m->integrated && m->usable);
	assert_string_equal(m->uncertain, "max_current_a,mass_g");
	assert_string_equal(m->confidence, "medium");

	const struct catalog_prop *p = catalog_prop(c, 0);
	assert_rel(p->diameter_m, 18 * 0.0254, 1e-12);
	assert_rel(p->pitch_m, 6.1 * 0.0254, 1e-12);
	assert_rel(p->mass_kg, 0.032, 1e-12);
	assert_int_equal(p->folding, -1);
	assert_string_equal(p->material, "carbon");

	const struct catalog_battery *b = catalog_find_battery(c, "fx-pack");
	assert_rel(b->capacity_ah, 22.0, 1e-12);
	assert_rel(b->mass_kg, 6.0, 1e-12);
	assert_string_equal(b->chemistry, "LiPo");
	assert_true(b->usable);
	assert_false(catalog_find_battery(c, "fx-liion")->usable);  /* chemistry unknown */

	const struct catalog_esc *e = catalog_esc(c, 0);
	assert_int_equal(e->channels, 4);
	assert_rel(e->mass_kg, 0.0113, 1e-12);
	assert_null(catalog_esc(c, 1));
	catalog_free(c);
	catalog_free(NULL);
}

static void
catalog_load_should_accept_a_caller_chemistry_list(void **state)
{
	(void)state;
	static const char *const only_lihv[] = { "LiHV", NULL };
	int n_err = 0;
	FILE *null_out = fopen("/dev/null", "w");
	assert_non_null(null_out);
	assert_null(catalog_load(FIXTURE_DIR "/good", only_lihv, null_out, &n_err));
	assert_int_equal(n_err, 1);      /* fx-pack's LiPo is not in the list */
	fclose(null_out);
}

/* Copies a file; returns false if src does not exist. */
static bool
copy_file(const char *src, const char *dst)
{
	FILE *in = fopen(src, "rb");
	if (in == NULL)
		return false;
	FILE *out = fopen(dst, "wb");
	assert_non_null(out);
	char buf[4096];
	size_t n;
	while ((n = fread(buf, 1, sizeof buf, in)) > 0)
		assert_int_equal(fwrite(buf, 1, n, out), n);
	fclose(in);
	fclose(out);
	return true;
}

/* Builds good/ + bad/<name>/ (minus `leave_out`) in a temp dir, loads it and
 * returns the diagnostics; *dir receives the temp dir for the caller's checks. */
static char *
load_bad(const char *name, const char *leave_out, char *dir, int *n_err)
{
	char src[512], dst[512];
	strcpy(dir, "/tmp/aeroeval-catalog-XXXXXX");
	assert_non_null(mkdtemp(dir));
	for (size_t i = 0; i < 4; i++) {
		const char *f = category_files[i];
		if (leave_out != NULL && strcmp(f, leave_out) == 0)
			continue;
		snprintf(dst, sizeof dst, "%s/%s", dir, f);
		snprintf(src, sizeof src, FIXTURE_DIR "/bad/%s/%s", name, f);
		if (!copy_file(src, dst)) {
			snprintf(src, sizeof src, FIXTURE_DIR "/good/%s", f);
			assert_true(copy_file(src, dst));
		}
	}
	char *msg = NULL;
	size_t len = 0;
	FILE *err = open_memstream(&msg, &len);
	assert_non_null(err);
	struct catalog *c = catalog_load(dir, NULL, err, n_err);
	fclose(err);
	assert_null(c);
	assert_true(*n_err >= 1);

	for (size_t i = 0; i < 4; i++) {
		snprintf(dst, sizeof dst, "%s/%s", dir, category_files[i]);
		unlink(dst);
	}
	rmdir(dir);
	return msg;
}

/* One bad fixture: its name, the file left out (or NULL), the file the
 * message must name and the rest of the expected message line. */
struct bad_case {
	const char *name;
	const char *leave_out;
	const char *file;
	const char *expect;
};

static const struct bad_case bad_cases[] = {
	{ "negative_mass", NULL, "motors.json",
	  ": error: motors[0] \"fx-motor-a\".mass_g: must be > 0 (got -3)\n" },
	{ "duplicate_id", NULL, "escs.json",
	  ": error: escs[0] \"fx-prop\".id: duplicate id (first used by " },
	{ "unknown_chemistry", NULL, "batteries.json",
	  ": error: batteries[0] \"fx-pack\".chemistry: unknown chemistry \"LiPoo\"\n" },
	{ "missing_field", NULL, "propellers.json",
	  ": error: propellers[0] \"fx-prop\".pitch_in: missing required key\n" },
	{ "wrong_type", NULL, "batteries.json",
	  ": error: batteries[0] \"fx-pack\".cells_series: must be a number (got a string)\n" },
	{ "malformed_json", NULL, "escs.json",
	  ":4:19: error: malformed JSON near '\"channels\": 4, \"pric'\n" },
	{ "unknown_key", NULL, "propellers.json",
	  ": error: propellers[0] \"fx-prop\".mas_g: unknown key (did you mean \"mass_g\"?)\n" },
	{ "cells_order", NULL, "motors.json",
	  ": error: motors[0] \"fx-motor-a\".cells_min: must be <= cells_max (got 12 > 6)\n" },
	{ "missing_file", "escs.json", "escs.json",
	  ": error: cannot read escs file: No such file or directory\n" },
};

static void
catalog_load_should_name_file_entry_and_field_for_each_error_kind(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++) {
		const struct bad_case *bc = &bad_cases[i];
		char dir[64], want[512];
		int n_err = 0;
		char *msg = load_bad(bc->name, bc->leave_out, dir, &n_err);
		snprintf(want, sizeof want, "%s/%s%s", dir, bc->file, bc->expect);
		if (strstr(msg, want) == NULL)
			fail_msg("case %s: want\n  %s\ngot\n  %s", bc->name, want, msg);
		free(msg);
	}
}

static void
catalog_load_should_report_the_errors_of_every_file(void **state)
{
	(void)state;
	char dir[64];
	int n_err = 0;
	/* The negative-mass fixture also leaves the other entries valid: exactly
	 * one error.  Two broken files give the errors of both. */
	char *msg = load_bad("negative_mass", NULL, dir, &n_err);
	assert_int_equal(n_err, 1);
	free(msg);
	msg = load_bad("negative_mass", "escs.json", dir, &n_err);
	assert_int_equal(n_err, 2);
	assert_non_null(strstr(msg, "mass_g: must be > 0"));
	assert_non_null(strstr(msg, "cannot read escs file"));
	free(msg);
}

/* One file with many errors: every one is reported, in file order. */
static void
catalog_load_should_report_all_errors_of_one_file(void **state)
{
	(void)state;
	static const char *const want[] = {
		"motors[0] \"fx-motor-a\".mass_g: must be > 0 (got 0)\n",
		"motors[1] \"fx-motor-b\".integrated: must be true or false (got a string)\n",
		"motors[1] \"fx-motor-b\".confidence: must be \"high\", \"medium\" or \"low\" (got \"unsure\")\n",
		"motors[1] \"fx-motor-b\".uncertain: element 0 names no field of motors (got \"kv\")\n",
		"motors[2] \"FX System\".id: must be a lowercase slug of a-z, 0-9 and '-' (got \"FX System\")\n",
		"motors[2] \"FX System\".price_usd: duplicate key\n",
		"motors[2] \"FX System\".source: must not be empty\n",
		"motors[2] \"FX System\".integrated_prop_in: required when integrated is true (null if unknown)\n",
		"motors[3]: must be an object (got an array)\n",
	};
	char dir[64];
	int n_err = 0;
	char *msg = load_bad("many_errors", NULL, dir, &n_err);
	const char *at = msg;
	for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
		const char *hit = strstr(at, want[i]);
		if (hit == NULL)
			fail_msg("missing or out of order: %s in\n%s", want[i], msg);
		at = hit;
	}
	assert_int_equal(n_err, (int)(sizeof want / sizeof want[0]));
	free(msg);
}

/* The fingerprint is SHA-256 over each file's name, a NUL, its length as
 * 8 bytes little-endian and its bytes, in category order (result.json's
 * catalogue_sha256): computed here from the files themselves. */
static void
catalog_sha256_should_hash_name_length_and_bytes_of_each_file(void **state)
{
	(void)state;
	struct catalog *c = load_or_print(FIXTURE_DIR "/good");
	struct sha256_ctx h;
	sha256_init(&h);
	for (size_t i = 0; i < sizeof category_files / sizeof category_files[0]; i++) {
		char path[256], err[256];
		unsigned char *buf = NULL, len8[8];
		size_t n = 0;
		snprintf(path, sizeof path, "%s/%s", FIXTURE_DIR "/good", category_files[i]);
		assert_int_equal(file_read(path, 1u << 20, &buf, &n, err, sizeof err), 0);
		for (int b = 0; b < 8; b++)
			len8[b] = (unsigned char)((unsigned long long)n >> (8 * b));
		sha256_update(&h, category_files[i], strlen(category_files[i]) + 1);
		sha256_update(&h, len8, sizeof len8);
		sha256_update(&h, buf, n);
		free(buf);
	}
	unsigned char d[SHA256_DIGEST_LEN];
	char want[SHA256_HEX_LEN];
	sha256_final(&h, d);
	for (int i = 0; i < SHA256_DIGEST_LEN; i++)
		snprintf(want + 2 * i, 3, "%02x", d[i]);
	assert_string_equal(catalog_sha256(c), want);
	catalog_free(c);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(catalog_shipped_should_meet_the_coverage_targets),
		cmocka_unit_test(catalog_shipped_ids_should_be_unique_and_usable_entries_sourced),
		cmocka_unit_test(catalog_shipped_part_numbers_should_not_repeat_the_maker),
		cmocka_unit_test(catalog_shipped_values_should_be_converted_to_si),
		cmocka_unit_test(catalog_load_should_read_a_minimal_catalogue),
		cmocka_unit_test(catalog_sha256_should_hash_name_length_and_bytes_of_each_file),
		cmocka_unit_test(catalog_load_should_accept_a_caller_chemistry_list),
		cmocka_unit_test(catalog_load_should_name_file_entry_and_field_for_each_error_kind),
		cmocka_unit_test(catalog_load_should_report_the_errors_of_every_file),
		cmocka_unit_test(catalog_load_should_report_all_errors_of_one_file),
	};
	return cmocka_run_group_tests_name("catalog", tests, NULL, NULL);
}
