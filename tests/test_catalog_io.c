/* test_catalog_io.c — the parts catalogue loader: the shipped catalogue
 * (coverage, ids, SI values), catalogue format 2 on fixtures, every kind of
 * diagnostic with file:line:col, hostile files and a 10^5-motor catalogue. */
#include "test_util.h"
#include "catalog/catalog.h"
#include "input/catalog_io.h"
#include "util/file.h"
#include "util/hash.h"
#include "util/sha256.h"
#include "util/strbuf.h"

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#define SHIPPED_DIR "data/catalog"
#define FIXTURE_DIR "tests/fixtures/catalog"
#define JSON_MAX_TEST ((size_t)1 << 20)

/* Loads dir; on failure prints the diagnostics so a broken shipped catalogue
 * explains itself in the test log. */
static struct catalog *
load_or_print(const char *dir)
{
	struct diag *dg = diag_alloc(stderr);
	struct catalog *c = catalog_io_load(dir, NULL, dg, NULL);
	diag_flush(dg);
	if (c == NULL)
		print_error("catalog_io_load(%s) failed with %d errors\n", dir, diag_n_errors(dg));
	assert_non_null(c);
	assert_int_equal(diag_n_errors(dg), 0);
	diag_free(dg);
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
	struct strmap *seen = strmap_alloc(n);
	for (size_t i = 0; i < n; i++) {
		if (!strmap_put(seen, all[i].id, i, NULL))
			fail_msg("duplicate id %s", all[i].id);
		if (all[i].usable)
			assert_true(strlen(all[i].source) > 10);
		assert_true(strcmp(all[i].confidence, "high") == 0 ||
		            strcmp(all[i].confidence, "medium") == 0 ||
		            strcmp(all[i].confidence, "low") == 0);
	}
	strmap_free(seen);
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

/* Loads dir into *c, returning the diagnostics (caller frees). */
static char *
load_text(const char *dir, struct catalog **c)
{
	struct diag *dg = diag_alloc(NULL);
	*c = catalog_io_load(dir, NULL, dg, NULL);
	char *text = strdup(diag_text(dg));
	assert_int_equal(*c == NULL, diag_n_errors(dg) > 0);
	if (*c == NULL)
		assert_int_equal(diag_exit_status(dg), 2);
	diag_free(dg);
	return text;
}

static void
catalog_io_should_read_a_minimal_catalogue_of_format_2(void **state)
{
	(void)state;
	struct catalog *c = load_or_print(FIXTURE_DIR "/good/");   /* trailing '/' is fine */
	assert_int_equal(catalog_n_motors(c), 3);
	assert_int_equal(catalog_n_props(c), 1);
	assert_int_equal(catalog_n_batteries(c), 2);
	assert_int_equal(catalog_n_escs(c), 1);
	assert_int_equal(catalog_n_frames(c), 0);     /* optional files absent: none */
	assert_int_equal(catalog_n_avionics(c), 0);
	assert_null(catalog_frame(c, 0));

	const struct catalog_motor *m = catalog_motor(c, 0);
	assert_string_equal(m->id, "fx-motor-a");
	assert_string_equal(m->part_number, "FX5008 KV340");
	assert_rel(m->mass_kg, 0.1355, 1e-12);
	assert_rel(m->resistance_ohm, 0.055, 1e-12);
	assert_int_equal(m->cells_min, 6);
	assert_int_equal(m->cells_max, 12);
	assert_rel(m->price_usd, 89.99, 1e-12);
	assert_string_equal(m->price_date, "2024-01");
	assert_string_equal(m->max_current_basis, "peak_180s");
	assert_rel(m->no_load_current_a, 0.6, 1e-12);
	assert_rel(m->no_load_voltage_v, 10, 1e-12);
	assert_string_equal(m->stator, "50x08");
	assert_rel(m->max_thrust_n, 2.1 * 9.80665, 1e-12);
	assert_true(m->usable);
	assert_false(m->integrated);
	assert_string_equal(m->uncertain, "");

	m = catalog_find_motor(c, "fx-motor-unknown-mass");
	assert_non_null(m);
	assert_false(m->usable);
	assert_true(m->mass_kg == 0 && m->price_usd == 0 && m->cells_min == 0);
	assert_string_equal(m->price_date, "");
	assert_string_equal(m->stator, "");             /* unknown text: "", never NULL */

	m = catalog_find_motor(c, "fx-system");
	assert_true(m->integrated && m->usable);
	assert_rel(m->integrated_pitch_in, 12, 1e-12);
	assert_rel(m->integrated_esc_current_a, 80, 1e-12);
	assert_string_equal(m->uncertain, "max_current_a,mass_g");
	assert_string_equal(m->confidence, "medium");

	const struct catalog_prop *p = catalog_prop(c, 0);
	assert_rel(p->diameter_m, 18 * 0.0254, 1e-12);
	assert_rel(p->pitch_m, 6.1 * 0.0254, 1e-12);
	assert_rel(p->mass_kg, 0.032, 1e-12);
	assert_int_equal(p->folding, -1);
	assert_string_equal(p->material, "carbon");
	assert_rel(p->ct_static, 0.1105, 1e-12);
	assert_rel(p->cp_static, 0.0485, 1e-12);
	assert_string_equal(p->coeff_source, "fixture thrust table");
	assert_string_equal(p->part_number_ccw, "FX18x6.1 CCW");
	assert_int_equal(catalog_props_by_diameter(c)[0], 0);

	const struct catalog_battery *b = catalog_find_battery(c, "fx-pack");
	assert_rel(b->capacity_ah, 22.0, 1e-12);
	assert_rel(b->mass_kg, 6.0, 1e-12);
	assert_string_equal(b->chemistry, "LiPo");
	assert_int_equal(b->cells_parallel, 1);
	assert_string_equal(b->connector, "AS150U");
	assert_true(b->smart);
	assert_true(b->usable);
	assert_false(catalog_find_battery(c, "fx-liion")->usable);  /* chemistry unknown */

	const struct catalog_esc *e = catalog_esc(c, 0);
	assert_int_equal(e->channels, 4);
	assert_rel(e->mass_kg, 0.0113, 1e-12);
	assert_rel(e->burst_s, 10, 1e-12);
	assert_null(catalog_esc(c, 1));
	catalog_free(c);
	catalog_free(NULL);
}

/* The fingerprint of dir worked out here from its files, as catalog_io.h
 * states it: each file present, in catalog_io_files order, as its name, a
 * NUL, its length (8 bytes, little-endian) and its bytes. */
static void
fingerprint_of(const char *dir, char hex[SHA256_HEX_LEN])
{
	struct sha256_ctx c;
	unsigned char d[SHA256_DIGEST_LEN];
	sha256_init(&c);
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		char path[512], err[256];
		unsigned char *buf, len8[8];
		size_t n;
		snprintf(path, sizeof path, "%s/%s", dir, catalog_io_files[k]);
		if (file_read(path, JSON_MAX_TEST, &buf, &n, err, sizeof err) != 0)
			continue;
		for (int i = 0; i < 8; i++)
			len8[i] = (unsigned char)((uint64_t)n >> (8 * i));
		sha256_update(&c, catalog_io_files[k], strlen(catalog_io_files[k]) + 1);
		sha256_update(&c, len8, 8);
		sha256_update(&c, buf, n);
		free(buf);
	}
	sha256_final(&c, d);
	sha256_to_hex(d, hex);
}

/* The fingerprint is that of the bytes read: one digit of a mass changed
 * in place (same size) changes it, and the load reads the new mass. */
static void
catalog_io_should_fingerprint_the_bytes_it_read(void **state)
{
	(void)state;
	char dir[] = "/tmp/aeroeval-catalog-fp-XXXXXX", path[512], want[SHA256_HEX_LEN];
	char got[SHA256_HEX_LEN], cmd[1200];
	assert_non_null(mkdtemp(dir));
	snprintf(cmd, sizeof cmd, "cp -p " FIXTURE_DIR "/good/*.json %s/", dir);
	assert_int_equal(system(cmd), 0);
	struct diag *dg = diag_alloc(stderr);
	struct catalog *c = catalog_io_load(dir, NULL, dg, got);
	assert_non_null(c);
	fingerprint_of(dir, want);
	assert_string_equal(got, want);
	double mass = catalog_motor(c, 0)->mass_kg;
	catalog_free(c);

	snprintf(path, sizeof path, "%s/motors.json", dir);
	unsigned char *buf;
	size_t n;
	char err[256];
	assert_int_equal(file_read(path, JSON_MAX_TEST, &buf, &n, err, sizeof err), 0);
	char *at = strstr((char *)buf, "\"mass_g\": 1");
	assert_non_null(at);
	at[strlen("\"mass_g\": ")] = '2';     /* 135.5 g becomes 235.5 g */
	FILE *f = fopen(path, "r+b");
	assert_non_null(f);
	assert_int_equal(fwrite(buf, 1, n, f), n);
	assert_int_equal(fclose(f), 0);
	free(buf);

	c = catalog_io_load(dir, NULL, dg, got);
	assert_non_null(c);
	fingerprint_of(dir, want);
	assert_string_equal(got, want);
	assert_rel(catalog_motor(c, 0)->mass_kg, mass + 0.1, 1e-12);
	catalog_free(c);
	diag_free(dg);
	snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
	assert_int_equal(system(cmd), 0);
}

static void
catalog_io_should_accept_a_caller_chemistry_list(void **state)
{
	(void)state;
	static const char *const only_lihv[] = { "LiHV", NULL };
	struct diag *dg = diag_alloc(NULL);
	assert_null(catalog_io_load(FIXTURE_DIR "/good", only_lihv, dg, NULL));
	assert_int_equal(diag_n_errors(dg), 1);      /* fx-pack's LiPo is not in the list */
	diag_free(dg);
}

/* A temporary catalogue directory made of good/ with bad/<name>/ laid over
 * it (name NULL: none), leaving out `leave_out` (or NULL). */
static void
make_dir(char *dir, const char *name, const char *leave_out)
{
	char src[512], dst[512];
	strcpy(dir, "/tmp/aeroeval-catalog-XXXXXX");
	assert_non_null(mkdtemp(dir));
	for (int i = 0; i < 4; i++) {
		const char *f = catalog_io_files[i];
		if (leave_out != NULL && strcmp(f, leave_out) == 0)
			continue;
		snprintf(dst, sizeof dst, "%s/%s", dir, f);
		snprintf(src, sizeof src, FIXTURE_DIR "/bad/%s/%s", name ? name : "-", f);
		if (!test_copy_file(src, dst)) {
			snprintf(src, sizeof src, FIXTURE_DIR "/good/%s", f);
			assert_true(test_copy_file(src, dst));
		}
	}
}

static void
remove_dir(const char *dir)
{
	char p[512];
	for (int i = 0; i < CATALOG_N_CATEGORIES; i++) {
		snprintf(p, sizeof p, "%s/%s", dir, catalog_io_files[i]);
		unlink(p);
	}
	rmdir(dir);
}

/* msg (freed) with every occurrence of the temporary dir written DIR. */
static char *
undir(char *msg, const char *dir)
{
	struct strbuf sb = STRBUF_INIT;
	const char *p = msg, *hit;
	while ((hit = strstr(p, dir)) != NULL) {
		strbuf_append(&sb, p, (size_t)(hit - p));
		strbuf_append_str(&sb, "DIR");
		p = hit + strlen(dir);
	}
	strbuf_append_str(&sb, p);
	free(msg);
	return strbuf_take(&sb, NULL);
}

/* The diagnostics of loading good/ + bad/<name>/; the load must fail. */
static char *
load_bad(const char *name, const char *leave_out)
{
	char dir[64];
	struct catalog *c;
	make_dir(dir, name, leave_out);
	char *msg = load_text(dir, &c);
	assert_null(c);
	remove_dir(dir);
	return undir(msg, dir);
}

/* One bad fixture: its name, the file left out (or NULL), and the whole
 * expected diagnostics. */
struct bad_case {
	const char *name;
	const char *leave_out;
	const char *expect;
};

static const struct bad_case bad_cases[] = {
	{ "negative_mass", NULL,
	  "DIR/motors.json:3:35: error: motors[0].mass_g: out of range: -3 (allowed above 0 g)\n" },
	{ "duplicate_id", NULL,
	  "DIR/escs.json:2:10: error: escs[0].id: duplicate id \"fx-prop\" (first used at "
	  "DIR/propellers.json:2:10, propellers[0])\n" },
	{ "unknown_chemistry", NULL,
	  "DIR/batteries.json:3:17: error: batteries[0].chemistry: unknown battery chemistry "
	  "\"LiPoo\" (known: LiPo, LiHV, Li-ion NCA, Li-ion NMC, Solid State, Li-S, "
	  "LiPo_standard, LiPo_highvoltage, LiPo_premium, LiPo_consumer, LiPo_enterprise, "
	  "LiPo_agricultural)\n" },
	{ "missing_field", NULL,
	  "DIR/propellers.json:2:3: error: propellers[0].pitch_in: missing field\n" },
	{ "wrong_type", NULL,
	  "DIR/batteries.json:3:41: error: batteries[0].cells_series: wrong type: expected "
	  "a whole number, got a string\n" },
	{ "malformed_json", NULL,
	  "DIR/escs.json:4:19: error: malformed JSON near \"\\\"channels\\\": 4, \\\"...\"\n" },
	{ "unknown_key", NULL,
	  "DIR/propellers.json:3:75: error: propellers[0].mas_g: unknown field; did you mean \"mass_g\"?\n"
	  "DIR/propellers.json:2:3: error: propellers[0].mass_g: missing field\n" },
	{ "cells_order", NULL,
	  "DIR/motors.json:4:17: error: motors[0].cells_min: inconsistent values: 12 > "
	  "cells_max 6 (a range goes from low to high)\n" },
	{ "missing_file", "escs.json",
	  "DIR/escs.json: error: cannot read file: No such file or directory\n" },
	/* Every error of one file, each once. */
	{ "many_errors", NULL,
	  "DIR/motors.json:3:35: error: motors[0].mass_g: out of range: 0 (allowed above 0 g)\n"
	  "DIR/motors.json:11:39: error: motors[1].confidence: unknown value \"unsure\" "
	  "(allowed: high, medium, low)\n"
	  "DIR/motors.json:11:63: error: motors[1].uncertain[0]: unknown value \"kv\" (not a key of motors)\n"
	  "DIR/motors.json:10:113: error: motors[1].integrated: wrong type: expected true or "
	  "false, got a string\n"
	  "DIR/motors.json:15:276: error: motors[2].price_usd: duplicate field (first given at 15:232)\n"
	  "DIR/motors.json:15:232: note: motors[2].price_usd: first given here\n"
	  "DIR/motors.json:15:292: error: motors[2].price_date: duplicate field (first given at 15:251)\n"
	  "DIR/motors.json:15:251: note: motors[2].price_date: first given here\n"
	  "DIR/motors.json:12:10: error: motors[2].id: invalid id: \"FX System\" (a lowercase "
	  "slug of a-z, 0-9 and '-')\n"
	  "DIR/motors.json:16:14: error: motors[2].source: wrong type: expected a non-empty "
	  "string, got \"\"\n"
	  "DIR/motors.json:15:265: error: motors[2].price_date: inconsistent values: given while "
	  "price_usd is null (a price is dated, and a date needs a price)\n"
	  "DIR/motors.json:17:3: error: motors[3]: wrong type: expected an object, got an array\n" },
};

static void
catalog_io_should_name_file_line_col_entry_and_field_for_each_error_kind(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++) {
		const struct bad_case *bc = &bad_cases[i];
		char *msg = load_bad(bc->name, bc->leave_out);
		if (strcmp(msg, bc->expect) != 0)
			fail_msg("case %s: want\n%sgot\n%s", bc->name, bc->expect, msg);
		free(msg);
	}
}

static void
catalog_io_should_report_the_errors_of_every_file(void **state)
{
	(void)state;
	char *msg = load_bad("negative_mass", "escs.json");
	assert_non_null(strstr(msg, "mass_g: out of range"));
	assert_non_null(strstr(msg, "DIR/escs.json: error: cannot read file"));
	free(msg);
}

/* good/ with `from` replaced by `to` in one file; returns the diagnostics
 * with the directory written DIR. */
static char *
load_edited(const char *file, const char *from, const char *to)
{
	char dir[64], path[512];
	make_dir(dir, NULL, NULL);
	snprintf(path, sizeof path, "%s/%s", dir, file);
	FILE *f = fopen(path, "rb");
	assert_non_null(f);
	char buf[8192];
	size_t n = fread(buf, 1, sizeof buf - 1, f);
	fclose(f);
	buf[n] = '\0';
	char *at = strstr(buf, from);
	if (at == NULL)
		fail_msg("%s does not hold %s", file, from);
	f = fopen(path, "wb");
	assert_non_null(f);
	fwrite(buf, 1, (size_t)(at - buf), f);
	fputs(to, f);
	fputs(at + strlen(from), f);
	fclose(f);
	struct catalog *c;
	char *msg = load_text(dir, &c);
	catalog_free(c);
	remove_dir(dir);
	return undir(msg, dir);
}

/* One edit of a good file and the one diagnostic it must give. */
struct edit_case {
	const char *file, *from, *to;
	const char *expect;
};

/* Catalogue text is checked like mission strings, and more: it ends up in a
 * CSV that a spreadsheet opens. */
static const struct edit_case text_cases[] = {
	{ "propellers.json", "\"FX18x6.1\"", "\"=HYPERLINK(\\\"http://x.example\\\",\\\"buy\\\")\"",
	  "DIR/propellers.json:2:63: error: propellers[0].part_number: text starts like a "
	  "spreadsheet formula: \"=HYPERLINK(\\\"http://x.exa...\" (text may not "
	  "start with =, +, - or @)\n" },
	{ "propellers.json", "\"FX18x6.1\"", "\"@SUM(A1)\"",
	  "DIR/propellers.json:2:63: error: propellers[0].part_number: text starts like a "
	  "spreadsheet formula: \"@SUM(A1)\" (text may not start with =, +, - or @)\n" },
	{ "propellers.json", "\"Fixture\"", "\"Fixtur\xe9\"",
	  "DIR/propellers.json:2:37: error: propellers[0].manufacturer: string is not valid "
	  "UTF-8 (byte 0xe9 at offset 6)\n" },
	{ "propellers.json", "\"source\": \"fixture\"", "\"source\": \"fix\\u0000ture\"",
	  "DIR/propellers.json:5:14: error: propellers[0].source: string contains a NUL "
	  "character (\\u0000)\n" },
	{ "propellers.json", "\"source\": \"fixture\"", "\"source\": \"fix\\nture\"",
	  "DIR/propellers.json:5:14: error: propellers[0].source: string contains a control "
	  "character (byte 0x0a at offset 3)\n" },
	{ "propellers.json", "\"source\": \"fixture\"", "\"source\": \"fix\tture\"",
	  "DIR/propellers.json:5:18: error: malformed JSON near byte 0x09 (control characters "
	  "in strings must be escaped)\n" },
	{ "propellers.json", "\"mass_g\": 32", "\"mass_g\": 032",
	  "DIR/propellers.json:3:85: error: malformed JSON near \"032\" (not a JSON number)\n" },
	{ "propellers.json", "\"mass_g\": 32", "\"mass_g\": 1e400",
	  "DIR/propellers.json:3:85: error: propellers[0].mass_g: number out of range of a "
	  "double: 1e400\n" },
	{ "propellers.json", "\"blades\": 2", "\"blades\": 2.5",
	  "DIR/propellers.json:3:50: error: propellers[0].blades: must be an integer (got 2.5)\n" },
	{ "propellers.json", "\"fx-prop\"", "\"fx-prop\\u0000\"",
	  "DIR/propellers.json:2:10: error: propellers[0].id: string contains a NUL character "
	  "(\\u0000)\n" },
};

/* Each edit gives exactly its diagnostic. */
static void
run_edit_cases(const struct edit_case *cases, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		char *msg = load_edited(cases[i].file, cases[i].from, cases[i].to);
		if (strcmp(msg, cases[i].expect) != 0)
			fail_msg("case %zu: want\n%sgot\n%s", i, cases[i].expect, msg);
		free(msg);
	}
}

static void
catalog_io_should_reject_bad_text_with_file_line_col(void **state)
{
	(void)state;
	run_edit_cases(text_cases, sizeof text_cases / sizeof text_cases[0]);
}

/* The rules between the fields of one entry. */
static const struct edit_case rule_cases[] = {
	{ "propellers.json", "\"price_date\": \"2024-01\"", "\"price_date\": null",
	  "DIR/propellers.json:4:188: error: propellers[0].price_date: inconsistent values: "
	  "null while price_usd is given (a price is dated, and a date needs a price)\n" },
	{ "escs.json", "\"price_date\": null", "\"price_date\": \"2024\"",
	  "DIR/escs.json:4:107: error: escs[0].price_date: inconsistent values: given while "
	  "price_usd is null (a price is dated, and a date needs a price)\n" },
	{ "propellers.json", "\"2024-01\"", "\"2024-13\"",
	  "DIR/propellers.json:4:188: error: propellers[0].price_date: invalid date "
	  "\"2024-13\" (expected \"YYYY-MM\" or \"YYYY\")\n" },
	{ "propellers.json", "\"cp_static\": 0.0485", "\"cp_static\": null",
	  "DIR/propellers.json:4:72: error: propellers[0].cp_static: inconsistent values: null "
	  "while ct_static is given (the static coefficients come as a pair)\n" },
	{ "batteries.json", "\"burst_c\": 50", "\"burst_c\": 20",
	  "DIR/batteries.json:4:20: error: batteries[0].continuous_c: inconsistent values: "
	  "25 > burst_c 20 (a burst rating is at least the continuous one)\n" },
	{ "escs.json", "\"burst_current_a\": 65", "\"burst_current_a\": 50",
	  "DIR/escs.json:3:28: error: escs[0].continuous_current_a: inconsistent values: "
	  "55 > burst_current_a 50 (a burst rating is at least the continuous one)\n" },
	{ "motors.json", "\"max_thrust_g\": null, \"price_usd\": null, \"price_date\": null,\n"
	  "   \"source\": \"fixture\", \"confidence\": \"low\"",
	  "\"max_thrust_g\": null, \"price_usd\": null, \"price_date\": null,\n"
	  "   \"source\": \"fixture\", \"confidence\": \"high\"",
	  "DIR/motors.json:11:39: error: motors[1].confidence: inconsistent values: \"high\" "
	  "while uncertain lists kv_rpm_per_v (a doubtful field makes it medium or low)\n" },
	{ "motors.json", "\"integrated\": false, \"integrated_prop_in\": null",
	  "\"integrated\": false, \"integrated_prop_in\": 12",
	  "DIR/motors.json:5:140: error: motors[0].integrated_prop_in: inconsistent values: "
	  "given while integrated is false (null for a plain motor)\n" },
	{ "motors.json", "\"max_current_basis\": \"peak_180s\"", "\"max_current_basis\": \"peak\"",
	  "DIR/motors.json:3:84: error: motors[0].max_current_basis: unknown value \"peak\" "
	  "(allowed: continuous, peak_180s, peak_60s, peak_30s, peak_10s, peak_unspecified)\n" },
	/* A board that carries a video transmitter names its system; a
	 * board's `carries` names avionics kinds only. */
	{ "escs.json", "\"carries\": null", "\"carries\": \"flight_controller,video_tx\"",
	  "DIR/escs.json:4:92: error: escs[0].video_system: inconsistent values: null for "
	  "a board that carries a video transmitter (a camera works only with a transmitter "
	  "of its own system)\n" },
	{ "escs.json", "\"video_system\": null", "\"video_system\": \"analog\"",
	  "DIR/escs.json:4:68: error: escs[0].video_system: inconsistent values: given, "
	  "but only a board that carries a video transmitter has one\n" },
	{ "escs.json", "\"carries\": null", "\"carries\": \"flight_controller,reciever\"",
	  "DIR/escs.json:4:46: error: escs[0].carries: unknown value \"reciever\" in the list "
	  "(allowed: flight_controller, gnss, receiver, telemetry, power_module, pdb, bec, "
	  "connector, series_lead, video_tx, camera_fpv, gimbal_camera, companion_computer, "
	  "lidar, remote_id, joined by commas)\n" },
	{ "escs.json", "\"channels\": 4", "\"channels\": 0",
	  "DIR/escs.json:4:32: error: escs[0].channels: out of range: 0 (allowed 1 to 1000)\n" },
	{ "motors.json", "\"kv_rpm_per_v\": 340", "\"kv_rpm_per_v\": 1e300",
	  "DIR/motors.json:3:20: error: motors[0].kv_rpm_per_v: out of range: 1e300 (allowed "
	  "above 0 up to 1e+09 rpm/V)\n" },
	{ "batteries.json", "\"smart\": true", "\"smart\": null",
	  "DIR/batteries.json:4:118: error: batteries[0].smart: wrong type: expected true or "
	  "false, got null\n" },
};

static void
catalog_io_should_check_the_rules_between_fields(void **state)
{
	(void)state;
	run_edit_cases(rule_cases, sizeof rule_cases / sizeof rule_cases[0]);
}

static void
catalog_io_should_read_frames_and_avionics_when_present(void **state)
{
	(void)state;
	char dir[64], path[512];
	make_dir(dir, NULL, NULL);
	snprintf(path, sizeof path, "%s/frames.json", dir);
	assert_true(test_copy_file(FIXTURE_DIR "/extra/frames.json", path));
	snprintf(path, sizeof path, "%s/avionics.json", dir);
	assert_true(test_copy_file(FIXTURE_DIR "/extra/avionics.json", path));
	struct catalog *c = load_or_print(dir);
	assert_int_equal(catalog_n_frames(c), 1);
	assert_int_equal(catalog_n_avionics(c), 2);
	const struct catalog_frame *f = catalog_find_frame(c, "fx-frame-x8");
	assert_non_null(f);
	assert_int_equal(f->rotor_count, 8);
	assert_true(f->coaxial);
	assert_rel(f->wheelbase_m, 1.2, 1e-12);
	assert_rel(f->arm_tube_od_m, 0.030, 1e-12);
	assert_rel(f->mass_kg, 2.385, 1e-12);
	assert_int_equal(f->folding, 1);
	assert_string_equal(f->frame_class, "EnterpriseRugged");
	assert_string_equal(f->includes, "arms, plates, landing gear, PDB");
	assert_true(f->usable);
	const struct catalog_avionics *a = catalog_avionics(c, 1);
	assert_string_equal(a->kind, "power_module");
	assert_int_equal(a->cells_max, 12);
	assert_rel(a->max_current_a, 120, 1e-12);
	assert_string_equal(a->price_date, "2025");
	assert_ptr_equal(catalog_find_avionics(c, "fx-fc"), catalog_avionics(c, 0));
	assert_null(catalog_find_frame(c, "fx-fc"));
	catalog_free(c);
	remove_dir(dir);
}

static void
catalog_io_should_refuse_a_fifo_as_a_catalogue_file(void **state)
{
	(void)state;
	char dir[64], path[512];
	make_dir(dir, NULL, "motors.json");
	snprintf(path, sizeof path, "%s/motors.json", dir);
	assert_int_equal(mkfifo(path, 0600), 0);
	struct catalog *c;
	alarm(10);   /* a loader that waited for a writer would be killed here */
	char *msg = load_text(dir, &c);
	alarm(0);
	assert_null(c);
	msg = undir(msg, dir);
	assert_string_equal(msg, "DIR/motors.json: error: cannot read file: not a regular file\n");
	free(msg);
	/* An optional file that is there must be a regular file too. */
	unlink(path);
	snprintf(path, sizeof path, FIXTURE_DIR "/good/motors.json");
	char dst[512];
	snprintf(dst, sizeof dst, "%s/motors.json", dir);
	assert_true(test_copy_file(path, dst));
	snprintf(path, sizeof path, "%s/frames.json", dir);
	assert_int_equal(mkdir(path, 0700), 0);
	msg = undir(load_text(dir, &c), dir);
	assert_null(c);
	assert_string_equal(msg, "DIR/frames.json: error: cannot read file: not a regular file\n");
	free(msg);
	rmdir(path);
	remove_dir(dir);
}

/* 10^5 motors load, ids checked through one hash set: every pair was once
 * compared, which took 85 s. */
static void
catalog_io_should_load_100000_motors(void **state)
{
	(void)state;
	enum { N = 100000 };
	char dir[64], path[512];
	make_dir(dir, NULL, NULL);
	snprintf(path, sizeof path, "%s/motors.json", dir);
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	fputs("{\"motors\": [\n", f);
	for (int i = 0; i < N; i++)
		fprintf(f, "%s{\"id\": \"gen-%06d\", \"manufacturer\": \"Gen\", \"part_number\": "
		        "\"G%d\", \"kv_rpm_per_v\": %d, \"mass_g\": %d.5, \"max_current_a\": 30, "
		        "\"max_current_basis\": null, \"max_power_w\": null, \"cells_min\": 4, "
		        "\"cells_max\": 6, \"prop_min_in\": null, \"prop_max_in\": null, "
		        "\"resistance_mohm\": null, \"no_load_current_a\": null, "
		        "\"no_load_voltage_v\": null, \"stator\": null, \"integrated\": false, "
		        "\"integrated_prop_in\": null, \"integrated_pitch_in\": null, "
		        "\"integrated_esc_current_a\": null, \"max_thrust_g\": null, "
		        "\"price_usd\": null, \"price_date\": null, \"source\": \"generated\", "
		        "\"confidence\": \"low\", \"uncertain\": []}\n",
		        i ? "," : "", i, i, 100 + i % 3000, 20 + i % 500);
	fputs("]}\n", f);
	fclose(f);
	alarm(120);   /* a guard against a hang, not a speed test */
	struct catalog *c = load_or_print(dir);
	alarm(0);
	assert_int_equal(catalog_n_motors(c), N);
	const struct catalog_motor *m = catalog_find_motor(c, "gen-099999");
	assert_ptr_equal(m, catalog_motor(c, N - 1));
	assert_rel(m->mass_kg, (20 + 99999 % 500 + 0.5) * 1e-3, 1e-12);
	assert_true(m->usable);
	catalog_free(c);
	remove_dir(dir);
}

int
main(void)
{
	signal(SIGALRM, SIG_DFL);
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(catalog_shipped_should_meet_the_coverage_targets),
		cmocka_unit_test(catalog_shipped_ids_should_be_unique_and_usable_entries_sourced),
		cmocka_unit_test(catalog_shipped_part_numbers_should_not_repeat_the_maker),
		cmocka_unit_test(catalog_shipped_values_should_be_converted_to_si),
		cmocka_unit_test(catalog_io_should_read_a_minimal_catalogue_of_format_2),
		cmocka_unit_test(catalog_io_should_fingerprint_the_bytes_it_read),
		cmocka_unit_test(catalog_io_should_accept_a_caller_chemistry_list),
		cmocka_unit_test(catalog_io_should_name_file_line_col_entry_and_field_for_each_error_kind),
		cmocka_unit_test(catalog_io_should_report_the_errors_of_every_file),
		cmocka_unit_test(catalog_io_should_reject_bad_text_with_file_line_col),
		cmocka_unit_test(catalog_io_should_check_the_rules_between_fields),
		cmocka_unit_test(catalog_io_should_read_frames_and_avionics_when_present),
		cmocka_unit_test(catalog_io_should_refuse_a_fifo_as_a_catalogue_file),
		cmocka_unit_test(catalog_io_should_load_100000_motors),
	};
	return cmocka_run_group_tests_name("catalog_io", tests, NULL, NULL);
}
