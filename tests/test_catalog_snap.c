/* test_catalog_snap.c — the catalogue snapshot the program carries: it
 * gives back exactly what catalog_io_load() read, and only while the files
 * it was made from are unchanged; a damaged snapshot is refused. */
#include "test_util.h"
#include "core/catalog.h"
#include "input/catalog_io.h"
#include "input/catalog_snap.h"

#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define SHA_HEX "0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef"

static struct catalog *
load(const char *data_dir)
{
	char dir[512];
	snprintf(dir, sizeof dir, "%s/catalog", data_dir);
	struct diag *dg = diag_alloc(stderr);
	struct catalog *c = catalog_io_load(dir, NULL, dg);
	diag_flush(dg);
	diag_free(dg);
	assert_non_null(c);
	return c;
}

/* The snapshot of c (made from data_dir) in memory; *n its size. */
static unsigned char *
snap_of(const struct catalog *c, const char *data_dir, size_t *n)
{
	char *buf = NULL, err[256];
	FILE *f = open_memstream(&buf, n);
	assert_non_null(f);
	assert_int_equal(catalog_snap_write(c, SHA_HEX, data_dir, f, err, sizeof err), 0);
	assert_int_equal(fclose(f), 0);
	return (unsigned char *)buf;
}

/* Every entry of a and b alike: the same text in every text field, and the
 * same bytes everywhere else (numbers, flags, padding). */
static void
assert_same_catalog(const struct catalog *a, const struct catalog *b)
{
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		enum catalog_category cat = (enum catalog_category)k;
		size_t offs[32], size = catalog_entry_size(cat);
		size_t n_text = catalog_io_text_fields(cat, offs, 32);
		assert_true(n_text >= 6);
		assert_int_equal(catalog_count(a, cat), catalog_count(b, cat));
		unsigned char *x = malloc(size), *y = malloc(size);
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
	/* The derived index too: the propellers by diameter, ids found. */
	for (size_t i = 0; i < catalog_n_props(a); i++)
		assert_int_equal(catalog_props_by_diameter(a)[i], catalog_props_by_diameter(b)[i]);
	const struct catalog_motor *m = catalog_motor(a, catalog_n_motors(a) - 1);
	assert_non_null(catalog_find_motor(b, m->id));
}

static void
snapshot_should_give_back_what_the_json_loader_read(void **state)
{
	(void)state;
	struct catalog *c = load("data");
	size_t n;
	unsigned char *blob = snap_of(c, "data", &n);
	char sha[65] = "";
	struct catalog *s = catalog_snap_read(blob, n, "data", sha);
	assert_non_null(s);
	assert_string_equal(sha, SHA_HEX);
	assert_true(catalog_n_motors(s) >= 250 && catalog_n_props(s) >= 300);
	assert_same_catalog(c, s);
	catalog_free(s);
	catalog_free(c);
	free(blob);
}

/* A copy of data/'s chemistries and catalogue in a new directory. */
static void
copy_data(char *dir)
{
	strcpy(dir, "/tmp/aeroeval-snap-XXXXXX");
	assert_non_null(mkdtemp(dir));
	char src[600], dst[600];
	snprintf(dst, sizeof dst, "%s/catalog", dir);
	assert_int_equal(mkdir(dst, 0700), 0);
	snprintf(dst, sizeof dst, "%s/chemistries.json", dir);
	assert_true(test_copy_file("data/chemistries.json", dst));
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		snprintf(src, sizeof src, "data/catalog/%s", catalog_io_files[k]);
		snprintf(dst, sizeof dst, "%s/catalog/%s", dir, catalog_io_files[k]);
		assert_true(test_copy_file(src, dst));
	}
}

static void
remove_data(const char *dir)
{
	char p[600];
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		snprintf(p, sizeof p, "%s/catalog/%s", dir, catalog_io_files[k]);
		unlink(p);
	}
	snprintf(p, sizeof p, "%s/chemistries.json", dir);
	unlink(p);
	snprintf(p, sizeof p, "%s/catalog", dir);
	rmdir(p);
	rmdir(dir);
}

/* Sets a file's modification time one second later: an edit as make and
 * the snapshot see one, whatever its bytes. */
static void
touch_later(const char *path)
{
	struct stat st;
	assert_int_equal(stat(path, &st), 0);
	struct timespec t[2] = { st.st_atim, st.st_mtim };
	t[1].tv_sec += 1;
	assert_int_equal(utimensat(AT_FDCWD, path, t, 0), 0);
}

static void
snapshot_should_be_refused_once_a_file_it_was_made_from_changes(void **state)
{
	(void)state;
	char dir[64], p[600], sha[65];
	copy_data(dir);
	struct catalog *c = load(dir);
	size_t n;
	unsigned char *blob = snap_of(c, dir, &n);
	struct catalog *s = catalog_snap_read(blob, n, dir, sha);
	assert_non_null(s);
	catalog_free(s);

	/* Another data directory: its files are not the snapshot's. */
	assert_null(catalog_snap_read(blob, n, "tests/fixtures", sha));
	/* Each file the snapshot depends on, the chemistries included. */
	const char *files[] = { "catalog/motors.json", "catalog/frames.json",
		"chemistries.json" };
	for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
		snprintf(p, sizeof p, "%s/%s", dir, files[i]);
		touch_later(p);
		assert_null(catalog_snap_read(blob, n, dir, sha));
		free(blob);
		blob = snap_of(c, dir, &n);     /* made again: valid again */
		s = catalog_snap_read(blob, n, dir, sha);
		assert_non_null(s);
		catalog_free(s);
	}
	/* An optional file that appears or vanishes. */
	snprintf(p, sizeof p, "%s/catalog/avionics.json", dir);
	assert_int_equal(unlink(p), 0);
	assert_null(catalog_snap_read(blob, n, dir, sha));
	/* A file replaced by a symbolic link to the same bytes. */
	char real[4096];
	assert_non_null(realpath("data/catalog/avionics.json", real));
	assert_int_equal(symlink(real, p), 0);
	assert_null(catalog_snap_read(blob, n, dir, sha));
	unlink(p);

	free(blob);
	catalog_free(c);
	remove_data(dir);
}

static void
snapshot_should_refuse_damaged_bytes(void **state)
{
	(void)state;
	struct catalog *c = load("data");
	size_t n;
	unsigned char *blob = snap_of(c, "data", &n);
	char sha[65];
	assert_null(catalog_snap_read(NULL, 0, "data", sha));
	assert_null(catalog_snap_read(blob, 16, "data", sha));      /* truncated */
	assert_null(catalog_snap_read(blob, n - 1, "data", sha));   /* short text */
	unsigned char *bad = malloc(n);
	memcpy(bad, blob, n);
	bad[0] ^= 1;                                                 /* magic */
	assert_null(catalog_snap_read(bad, n, "data", sha));
	/* A text offset past the end: the first motor's id (its struct's
	 * first member) right after the header. */
	memcpy(bad, blob, n);
	size_t header = catalog_snap_header_bytes();
	assert_true(header < n);
	uintptr_t far = (uintptr_t)n;
	memcpy(bad + header, &far, sizeof far);
	assert_null(catalog_snap_read(bad, n, "data", sha));
	free(bad);
	free(blob);
	catalog_free(c);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(snapshot_should_give_back_what_the_json_loader_read),
		cmocka_unit_test(snapshot_should_be_refused_once_a_file_it_was_made_from_changes),
		cmocka_unit_test(snapshot_should_refuse_damaged_bytes),
	};
	return cmocka_run_group_tests_name("catalog_snap", tests, NULL, NULL);
}
