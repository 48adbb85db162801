/* test_catalog_snap.c — the catalogue snapshot (input/catalog_snap.h): it
 * gives exactly what the JSON gives, and only for the very bytes it was
 * made from.  A byte edited in place (same size, same times), a file grown,
 * an optional file removed or added, another chemistry list and a damaged
 * snapshot each send the caller back to the JSON. */
#include "test_util.h"
#include "catalog/catalog.h"
#include "input/catalog_io.h"
#include "input/catalog_snap.h"
#include "util/file.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define SHIPPED_DIR "data/catalog"
#define FIXTURE_DIR "tests/fixtures/catalog/good"

/* A snapshot in memory. */
struct snap {
	unsigned char *p;
	size_t n;
};

static struct snap
snap_of(const char *dir, const char *const *chems)
{
	struct snap s = { NULL, 0 };
	char err[256];
	FILE *f = open_memstream((char **)&s.p, &s.n);
	assert_non_null(f);
	struct diag *dg = diag_alloc(stderr);
	assert_int_equal(catalog_snap_write(dir, chems, dg, f, err, sizeof err), 0);
	assert_int_equal(fclose(f), 0);
	diag_free(dg);
	return s;
}

/* A copy of dir's files in a new temporary folder (tmpl, mkdtemp's). */
static void
copy_dir(const char *dir, char *tmpl)
{
	char cmd[1200];
	assert_non_null(mkdtemp(tmpl));
	snprintf(cmd, sizeof cmd, "cp -p %s/*.json %s/", dir, tmpl);
	assert_int_equal(system(cmd), 0);
}

static void
remove_dir(const char *dir)
{
	char cmd[600];
	snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
	assert_int_equal(system(cmd), 0);
}

/* Every entry of a equals b's: the text fields as text, every other byte
 * of the struct (numbers, flags, padding) as bytes, so a pointer the
 * snapshot failed to turn into text would show. */
static void
assert_same_catalog(const struct catalog *a, const struct catalog *b)
{
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		enum catalog_category cat = (enum catalog_category)k;
		size_t offs[32], size = catalog_entry_size(cat);
		size_t n_text = catalog_io_text_fields(cat, offs, 32);
		assert_int_equal(catalog_count(a, cat), catalog_count(b, cat));
		unsigned char *x = malloc(size), *y = malloc(size);
		assert_non_null(x);
		assert_non_null(y);
		for (size_t i = 0; i < catalog_count(a, cat); i++) {
			memcpy(x, catalog_item(a, cat, i), size);
			memcpy(y, catalog_item(b, cat, i), size);
			for (size_t f = 0; f < n_text; f++) {
				const char *sx, *sy;
				memcpy(&sx, x + offs[f], sizeof sx);
				memcpy(&sy, y + offs[f], sizeof sy);
				assert_string_equal(sx, sy);
				memset(x + offs[f], 0, sizeof sx);
				memset(y + offs[f], 0, sizeof sy);
			}
			assert_memory_equal(x, y, size);
		}
		free(x);
		free(y);
	}
	/* The index and the propeller order are rebuilt alike. */
	const struct catalog_motor *m = catalog_motor(a, 0);
	assert_ptr_equal(catalog_find_motor(b, m->id), catalog_motor(b, 0));
	size_t n = catalog_n_props(a);
	assert_memory_equal(catalog_props_by_diameter(a), catalog_props_by_diameter(b),
	                    n * sizeof(size_t));
}

static void
snapshot_should_hold_what_the_json_gives(void **state)
{
	(void)state;
	struct snap s = snap_of(SHIPPED_DIR, NULL);
	char sha_json[65], sha_snap[65];
	struct diag *dg = diag_alloc(stderr);
	struct catalog *json = catalog_io_load(SHIPPED_DIR, NULL, dg, sha_json);
	struct catalog *snap = catalog_snap_read(s.p, s.n, SHIPPED_DIR, NULL, sha_snap);
	assert_non_null(json);
	assert_non_null(snap);
	assert_string_equal(sha_snap, sha_json);
	assert_same_catalog(json, snap);
	catalog_free(json);
	catalog_free(snap);
	diag_free(dg);
	free(s.p);
}

/* One digit changed in place: same size, same times (touch -r), the
 * snapshot is refused and the JSON gives the new mass and hash. */
static void
snapshot_should_refuse_a_byte_edited_in_place(void **state)
{
	(void)state;
	char dir[] = "/tmp/aeroeval-snap-XXXXXX", path[600], cmd[4000], sha[65];
	copy_dir(FIXTURE_DIR, dir);
	struct snap s = snap_of(dir, NULL);
	struct catalog *c = catalog_snap_read(s.p, s.n, dir, NULL, sha);
	assert_non_null(c);
	catalog_free(c);

	snprintf(path, sizeof path, "%s/motors.json", dir);
	struct stat before, after;
	assert_int_equal(stat(path, &before), 0);
	snprintf(cmd, sizeof cmd, "cp -p %s %s.keep && sed -i '0,/\"mass_g\": 1/s//\"mass_g\": 2/' %s"
	         " && touch -r %s.keep %s", path, path, path, path, path);
	assert_int_equal(system(cmd), 0);
	assert_int_equal(stat(path, &after), 0);
	assert_int_equal(after.st_size, before.st_size);
	assert_int_equal(after.st_mtim.tv_sec, before.st_mtim.tv_sec);
	assert_int_equal(after.st_mtim.tv_nsec, before.st_mtim.tv_nsec);
	snprintf(cmd, sizeof cmd, "cmp -s %s %s.keep", path, path);
	assert_int_not_equal(system(cmd), 0);
	snprintf(cmd, sizeof cmd, "rm %s.keep", path);
	assert_int_equal(system(cmd), 0);

	assert_null(catalog_snap_read(s.p, s.n, dir, NULL, sha));
	free(s.p);
	remove_dir(dir);
}

static void
snapshot_should_refuse_a_grown_file(void **state)
{
	(void)state;
	char dir[] = "/tmp/aeroeval-snap-XXXXXX", cmd[700], sha[65];
	copy_dir(FIXTURE_DIR, dir);
	struct snap s = snap_of(dir, NULL);
	snprintf(cmd, sizeof cmd, "printf ' ' >>%s/escs.json", dir);
	assert_int_equal(system(cmd), 0);
	assert_null(catalog_snap_read(s.p, s.n, dir, NULL, sha));
	free(s.p);
	remove_dir(dir);
}

/* An optional file (frames.json) added to a folder whose snapshot was made
 * without it, then removed from one whose snapshot was made with it. */
static void
snapshot_should_refuse_an_optional_file_added_or_removed(void **state)
{
	(void)state;
	char dir[] = "/tmp/aeroeval-snap-XXXXXX", cmd[700], sha[65];
	copy_dir(FIXTURE_DIR, dir);
	struct snap without = snap_of(dir, NULL);
	struct catalog *c = catalog_snap_read(without.p, without.n, dir, NULL, sha);
	assert_non_null(c);
	assert_int_equal(catalog_n_frames(c), 0);
	catalog_free(c);
	snprintf(cmd, sizeof cmd, "cp %s/frames.json %s/", SHIPPED_DIR, dir);
	assert_int_equal(system(cmd), 0);
	assert_null(catalog_snap_read(without.p, without.n, dir, NULL, sha));

	struct snap with = snap_of(dir, NULL);
	c = catalog_snap_read(with.p, with.n, dir, NULL, sha);
	assert_non_null(c);
	assert_true(catalog_n_frames(c) > 0);
	catalog_free(c);
	snprintf(cmd, sizeof cmd, "rm %s/frames.json", dir);
	assert_int_equal(system(cmd), 0);
	assert_null(catalog_snap_read(with.p, with.n, dir, NULL, sha));
	free(with.p);
	free(without.p);
	remove_dir(dir);
}

/* The batteries were checked against a chemistry list: another list (one
 * name more, one fewer, or another order) is not the same check. */
static void
snapshot_should_refuse_another_chemistry_list(void **state)
{
	(void)state;
	static const char *const one[] = { "LiPo", NULL };
	static const char *const two[] = { "LiPo", "Li-ion", NULL };
	static const char *const swapped[] = { "Li-ion", "LiPo", NULL };
	char sha[65];
	struct snap s = snap_of(FIXTURE_DIR, two);
	struct catalog *c = catalog_snap_read(s.p, s.n, FIXTURE_DIR, two, sha);
	assert_non_null(c);
	catalog_free(c);
	assert_null(catalog_snap_read(s.p, s.n, FIXTURE_DIR, one, sha));
	assert_null(catalog_snap_read(s.p, s.n, FIXTURE_DIR, swapped, sha));
	assert_null(catalog_snap_read(s.p, s.n, FIXTURE_DIR, NULL, sha));
	free(s.p);
}

/* A snapshot cut short, with a wrong magic, or with every byte after its
 * header flipped in turn is refused or gives the same catalogue, and
 * never reads outside itself (the sanitizer build runs this). */
static void
snapshot_should_refuse_a_damaged_snapshot(void **state)
{
	(void)state;
	char sha[65];
	struct snap s = snap_of(FIXTURE_DIR, NULL);
	for (size_t cut = 0; cut < s.n; cut += 1 + cut / 3)
		assert_null(catalog_snap_read(s.p, cut, FIXTURE_DIR, NULL, sha));
	assert_null(catalog_snap_read(NULL, 0, FIXTURE_DIR, NULL, sha));
	unsigned char *bad = malloc(s.n);
	assert_non_null(bad);
	memcpy(bad, s.p, s.n);
	bad[0] ^= 1;
	assert_null(catalog_snap_read(bad, s.n, FIXTURE_DIR, NULL, sha));
	/* The header's sizes and counts: any one byte of them damaged no
	 * longer adds up to the snapshot's length. */
	for (size_t i = 8; i < 8 + 8 * 3 * CATALOG_N_CATEGORIES + 16; i++) {
		memcpy(bad, s.p, s.n);
		bad[i] ^= 0x40;
		assert_null(catalog_snap_read(bad, s.n, FIXTURE_DIR, NULL, sha));
	}
	/* A byte of the recorded motors.json: the files no longer equal the
	 * folder's. */
	unsigned char *motors;
	size_t n_motors;
	char err[256];
	assert_int_equal(file_read(FIXTURE_DIR "/motors.json", (size_t)1 << 20, &motors,
	                           &n_motors, err, sizeof err), 0);
	size_t at = 0;
	while (at + n_motors <= s.n && memcmp(s.p + at, motors, n_motors) != 0)
		at++;
	assert_true(at + n_motors <= s.n);
	memcpy(bad, s.p, s.n);
	bad[at + n_motors / 2] ^= 1;
	free(motors);
	assert_null(catalog_snap_read(bad, s.n, FIXTURE_DIR, NULL, sha));
	free(bad);
	free(s.p);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(snapshot_should_hold_what_the_json_gives),
		cmocka_unit_test(snapshot_should_refuse_a_byte_edited_in_place),
		cmocka_unit_test(snapshot_should_refuse_a_grown_file),
		cmocka_unit_test(snapshot_should_refuse_an_optional_file_added_or_removed),
		cmocka_unit_test(snapshot_should_refuse_another_chemistry_list),
		cmocka_unit_test(snapshot_should_refuse_a_damaged_snapshot),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
