/* test_fsout.c — atomic output, mkdir -p, whole-file reads, dossier dates
 * and output names. */
#include "util/file.h"
#include "test_util.h"
#include "output/fsout.h"

#include <dirent.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

/* Each test works in its own fresh directory under /tmp. */
struct fixture {
	char dir[64];
};

static int
setup(void **state)
{
	struct fixture *fx = calloc(1, sizeof *fx);
	strcpy(fx->dir, "/tmp/aeroeval-fsout-XXXXXX");
	if (mkdtemp(fx->dir) == NULL)
		return -1;
	*state = fx;
	unsetenv("AEROEVAL_FAIL_WRITE");
	unsetenv("SOURCE_DATE_EPOCH");
	return 0;
}

static int
teardown(void **state)
{
	struct fixture *fx = *state;
	char cmd[128];
	chmod(fx->dir, 0755);
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", fx->dir);
	int rc = system(cmd);
	free(fx);
	return rc;
}

static void
path_in(const struct fixture *fx, const char *name, char *out, size_t n)
{
	snprintf(out, n, "%s/%s", fx->dir, name);
}

/* Number of directory entries other than . and .. (temp files included). */
static int
count_entries(const char *dir)
{
	DIR *d = opendir(dir);
	assert_non_null(d);
	int k = 0;
	struct dirent *e;
	while ((e = readdir(d)) != NULL)
		if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
			k++;
	closedir(d);
	return k;
}

static void
assert_file_is(const char *path, const char *want)
{
	unsigned char *buf;
	size_t n;
	char err[256];
	assert_int_equal(file_read(path, 1 << 20, &buf, &n, err, sizeof err), 0);
	assert_int_equal(n, strlen(want));
	assert_memory_equal(buf, want, n);
	free(buf);
}

static void
fsout_write_atomic_should_create_then_replace_content(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256] = "";
	path_in(fx, "result.json", p, sizeof p);
	const char *v1 = "{\"takeoff_mass_kg\": 2.385}\n";
	const char *v2 = "{\"takeoff_mass_kg\": 1.282}\n";
	assert_int_equal(fsout_write_atomic(p, v1, strlen(v1), err, sizeof err), 0);
	assert_file_is(p, v1);
	assert_int_equal(fsout_write_atomic(p, v2, strlen(v2), err, sizeof err), 0);
	assert_file_is(p, v2);
	assert_int_equal(count_entries(fx->dir), 1); /* no temp file left */
	struct stat st;
	assert_int_equal(stat(p, &st), 0);
	assert_int_equal(st.st_mode & 0777, 0644);
	/* An empty file is a valid output too. */
	assert_int_equal(fsout_write_atomic(p, "", 0, err, sizeof err), 0);
	assert_file_is(p, "");
}

static void
fsout_write_atomic_should_keep_mode_0644_under_a_strict_umask(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256];
	path_in(fx, "bom.csv", p, sizeof p);
	mode_t old = umask(077);
	int rc = fsout_write_atomic(p, "a,b\n", 4, err, sizeof err);
	umask(old);
	assert_int_equal(rc, 0);
	struct stat st;
	assert_int_equal(stat(p, &st), 0);
	assert_int_equal(st.st_mode & 0777, 0644);
}

static void
fsout_injected_write_failure_should_leave_previous_file_intact(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256] = "";
	path_in(fx, "dossier.pdf", p, sizeof p);
	const char *good = "%PDF-1.3 previous good output, 48 bytes long..\n";
	assert_int_equal(fsout_write_atomic(p, good, strlen(good), err, sizeof err), 0);

	/* The second write from now fails half-way through its temp file. */
	fsout_fault_reset();
	setenv("AEROEVAL_FAIL_WRITE", "2", 1);
	char other[128];
	path_in(fx, "other.json", other, sizeof other);
	assert_int_equal(fsout_write_atomic(other, "{}", 2, err, sizeof err), 0);
	const char *bad = "%PDF-1.3 new output that must never land half-written\n";
	assert_int_equal(fsout_write_atomic(p, bad, strlen(bad), err, sizeof err), -1);
	assert_non_null(strstr(err, "AEROEVAL_FAIL_WRITE"));
	assert_file_is(p, good);
	assert_int_equal(count_entries(fx->dir), 2); /* dossier.pdf, other.json */

	/* Only the N-th write fails: the next one goes through. */
	assert_int_equal(fsout_write_atomic(p, bad, strlen(bad), err, sizeof err), 0);
	assert_file_is(p, bad);
	unsetenv("AEROEVAL_FAIL_WRITE");
}

static void
fsout_write_into_missing_directory_should_fail_cleanly(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256] = "";
	path_in(fx, "no/such/dir/result.json", p, sizeof p);
	assert_int_equal(fsout_write_atomic(p, "x", 1, err, sizeof err), -1);
	assert_non_null(strstr(err, "cannot create temporary file"));
	assert_int_equal(count_entries(fx->dir), 0);
	/* A path that names a directory, not a file. */
	path_in(fx, "", p, sizeof p);
	assert_int_equal(fsout_write_atomic(p, "x", 1, err, sizeof err), -1);
}

static void
fsout_write_into_readonly_directory_should_keep_previous_file(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256] = "";
	path_in(fx, "result.json", p, sizeof p);
	assert_int_equal(fsout_write_atomic(p, "old", 3, err, sizeof err), 0);
	assert_int_equal(chmod(fx->dir, 0555), 0);
	if (geteuid() != 0) {
		assert_int_equal(fsout_write_atomic(p, "new!", 4, err, sizeof err), -1);
	} else {
		/* Root ignores directory permissions, so the write is tried by
		 * a child that has given up root (uid/gid 65534, "nobody"). */
		pid_t pid = fork();
		assert_true(pid >= 0);
		if (pid == 0) {
			if (setgid(65534) != 0 || setuid(65534) != 0)
				_exit(2);
			_exit(fsout_write_atomic(p, "new!", 4, err, sizeof err) == -1 ? 0 : 1);
		}
		int status = -1;
		assert_int_equal(waitpid(pid, &status, 0), pid);
		assert_true(WIFEXITED(status));
		assert_int_equal(WEXITSTATUS(status), 0);
	}
	assert_int_equal(chmod(fx->dir, 0755), 0);
	assert_file_is(p, "old");
	assert_int_equal(count_entries(fx->dir), 1);
}

static void
fsout_failed_rename_should_remove_the_temporary_file(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256] = "";
	/* The target is a directory: the temp file is written and synced,
	 * then rename(2) refuses, and the temp file must go. */
	path_in(fx, "result.json", p, sizeof p);
	assert_int_equal(mkdir(p, 0755), 0);
	assert_int_equal(fsout_write_atomic(p, "{}", 2, err, sizeof err), -1);
	assert_non_null(strstr(err, "rename failed"));
	assert_int_equal(count_entries(fx->dir), 1);
	/* A file where the directory should be. */
	path_in(fx, "plain", p, sizeof p);
	assert_int_equal(fsout_write_atomic(p, "f", 1, err, sizeof err), 0);
	path_in(fx, "plain/result.json", p, sizeof p);
	assert_int_equal(fsout_write_atomic(p, "x", 1, err, sizeof err), -1);
	assert_int_equal(count_entries(fx->dir), 2);
}

/* One writer thread: 40 complete versions of the same file. */
struct writer {
	const char *path;
	char tag;   /* every byte this writer writes */
	int n_fail;
};

static void *
writer_main(void *arg)
{
	struct writer *w = arg;
	char buf[4096], err[256];
	memset(buf, w->tag, sizeof buf);
	for (int i = 0; i < 40; i++)
		if (fsout_write_atomic(w->path, buf, sizeof buf, err, sizeof err) != 0)
			w->n_fail++;
	return NULL;
}

static void
fsout_concurrent_writers_should_never_mix_or_leave_temps(void **state)
{
	struct fixture *fx = *state;
	char p[128];
	path_in(fx, "result.json", p, sizeof p);
	/* Six threads (as under -j 6) replace one file 240 times in all; the
	 * survivor must be one writer's complete 4096 bytes. */
	pthread_t th[6];
	struct writer w[6];
	for (int i = 0; i < 6; i++) {
		w[i] = (struct writer){ p, (char)('A' + i), 0 };
		assert_int_equal(pthread_create(&th[i], NULL, writer_main, &w[i]), 0);
	}
	for (int i = 0; i < 6; i++) {
		assert_int_equal(pthread_join(th[i], NULL), 0);
		assert_int_equal(w[i].n_fail, 0);
	}
	unsigned char *buf;
	size_t n;
	char err[256];
	assert_int_equal(file_read(p, 1 << 20, &buf, &n, err, sizeof err), 0);
	assert_int_equal(n, 4096);
	assert_true(buf[0] >= 'A' && buf[0] <= 'F');
	for (size_t i = 1; i < n; i++)
		assert_int_equal(buf[i], buf[0]);
	free(buf);
	assert_int_equal(count_entries(fx->dir), 1);
}

static void
fsout_mkdirs_should_create_every_missing_parent(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256] = "";
	struct stat st;
	path_in(fx, "out//agri-x8/figures/", p, sizeof p);
	assert_int_equal(fsout_mkdirs(p, err, sizeof err), 0);
	assert_int_equal(stat(p, &st), 0);
	assert_true(S_ISDIR(st.st_mode));
	assert_int_equal(fsout_mkdirs(p, err, sizeof err), 0); /* exists: fine */

	path_in(fx, "plain", p, sizeof p);
	assert_int_equal(fsout_write_atomic(p, "f", 1, err, sizeof err), 0);
	path_in(fx, "plain/sub", p, sizeof p);
	assert_int_equal(fsout_mkdirs(p, err, sizeof err), -1);
	assert_non_null(strstr(err, "not a directory"));
	assert_int_equal(fsout_mkdirs("", err, sizeof err), -1);
}

static void
fsout_read_file_should_add_a_nul_and_respect_the_cap(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256] = "";
	unsigned char *buf = (unsigned char *)"sentinel";
	size_t n = 7;
	path_in(fx, "mission.json", p, sizeof p);
	const char *text = "{\"payload_kg\": 0.365}";
	assert_int_equal(fsout_write_atomic(p, text, 21, err, sizeof err), 0);
	assert_int_equal(file_read(p, 21, &buf, &n, err, sizeof err), 0);
	assert_int_equal(n, 21);
	assert_int_equal(buf[21], '\0');
	assert_string_equal((char *)buf, text);
	free(buf);

	assert_int_equal(file_read(p, 20, &buf, &n, err, sizeof err), -1);
	assert_null(buf);
	assert_int_equal(n, 0);
	assert_non_null(strstr(err, "too large"));

	path_in(fx, "missing.json", p, sizeof p);
	assert_int_equal(file_read(p, 100, &buf, &n, err, sizeof err), -1);
	assert_non_null(strstr(err, "cannot open"));
	assert_int_equal(file_read(fx->dir, 100, &buf, &n, err, sizeof err), -1);
	assert_non_null(strstr(err, "not a regular file"));
}

static void
fsout_resolve_date_should_prefer_report_then_epoch_then_mtime(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256] = "", d[11];
	path_in(fx, "m.json", p, sizeof p);
	assert_int_equal(fsout_write_atomic(p, "{}", 2, err, sizeof err), 0);
	/* mtime 951782400 s = 11016 days = 2000-02-29T00:00:00Z (leap day). */
	struct timeval tv[2] = { { 951782400, 0 }, { 951782400, 0 } };
	assert_int_equal(utimes(p, tv), 0);

	setenv("SOURCE_DATE_EPOCH", "1700000000", 1); /* 2023-11-14T22:13:20Z */
	assert_int_equal(fsout_resolve_date("2026-03-17", p, d, err, sizeof err),
	                 FSOUT_DATE_REPORT);
	assert_string_equal(d, "2026-03-17");
	assert_int_equal(fsout_resolve_date("", p, d, err, sizeof err), FSOUT_DATE_EPOCH_ENV);
	assert_string_equal(d, "2023-11-14");
	setenv("SOURCE_DATE_EPOCH", "", 1); /* empty counts as unset */
	assert_int_equal(fsout_resolve_date("", p, d, err, sizeof err),
	                 FSOUT_DATE_MISSION_MTIME);
	assert_string_equal(d, "2000-02-29");
	unsetenv("SOURCE_DATE_EPOCH");
	assert_int_equal(fsout_resolve_date(NULL, p, d, err, sizeof err),
	                 FSOUT_DATE_MISSION_MTIME);
	assert_string_equal(d, "2000-02-29");
	/* SOURCE_DATE_EPOCH = 0 is the epoch itself, not "unset". */
	setenv("SOURCE_DATE_EPOCH", "0", 1);
	assert_int_equal(fsout_resolve_date("", p, d, err, sizeof err), FSOUT_DATE_EPOCH_ENV);
	assert_string_equal(d, "1970-01-01");
	unsetenv("SOURCE_DATE_EPOCH");
}

static void
fsout_resolve_date_should_reject_bad_dates_instead_of_falling_through(void **state)
{
	struct fixture *fx = *state;
	char p[128], err[256] = "", d[11];
	path_in(fx, "m.json", p, sizeof p);
	assert_int_equal(fsout_write_atomic(p, "{}", 2, err, sizeof err), 0);

	static const char *const bad_dates[] = {
		"2026-02-29", "2100-02-29", "2026-13-01", "2026-04-31", "26-03-17",
		"2026/03/17", "2026-03-17T00:00", "0000-01-01", "2026-3-170",
	};
	for (size_t i = 0; i < sizeof bad_dates / sizeof bad_dates[0]; i++) {
		assert_int_equal(fsout_resolve_date(bad_dates[i], p, d, err, sizeof err), -1);
		assert_non_null(strstr(err, "report.date"));
		assert_string_equal(d, "");
	}
	assert_int_equal(fsout_resolve_date("2024-02-29", p, d, err, sizeof err),
	                 FSOUT_DATE_REPORT);

	static const char *const bad_epochs[] = {
		"-86400", " 1700000000", "1700000000 ", "1.7e9", "0x10", "253402300800",
		"99999999999999999999999",
	};
	for (size_t i = 0; i < sizeof bad_epochs / sizeof bad_epochs[0]; i++) {
		setenv("SOURCE_DATE_EPOCH", bad_epochs[i], 1);
		assert_int_equal(fsout_resolve_date("", p, d, err, sizeof err), -1);
		assert_non_null(strstr(err, "SOURCE_DATE_EPOCH"));
	}
	setenv("SOURCE_DATE_EPOCH", "253402300799", 1); /* the last second of 9999 */
	assert_int_equal(fsout_resolve_date("", p, d, err, sizeof err), FSOUT_DATE_EPOCH_ENV);
	assert_string_equal(d, "9999-12-31");
	unsetenv("SOURCE_DATE_EPOCH");

	path_in(fx, "gone.json", p, sizeof p);
	assert_int_equal(fsout_resolve_date("", p, d, err, sizeof err), -1);
	assert_non_null(strstr(err, "modification time"));
}

static void
fsout_safe_name_should_keep_only_a_harmless_base_name(void **state)
{
	(void)state;
	char out[64];
	assert_int_equal(fsout_safe_name("missions/agri-x8_v2.json", out, sizeof out), 0);
	assert_string_equal(out, "agri-x8_v2");
	assert_int_equal(fsout_safe_name("survey.v3", out, sizeof out), 0);
	assert_string_equal(out, "survey.v3");
	assert_int_equal(fsout_safe_name("a.json.json", out, sizeof out), 0);
	assert_string_equal(out, "a.json");
	/* The directories of the input never reach the output path: the
	 * result is one component, so out/<name>/ stays inside out/. */
	assert_int_equal(fsout_safe_name("../../etc.json", out, sizeof out), 0);
	assert_string_equal(out, "etc");
	assert_null(strchr(out, '/'));

	static const char *const rejected[] = {
		".json", "dir/.json", "..json", "...json", "a b.json", "missions/",
		"", "caf\xc3\xa9.json", "semi;colon.json", "back\\slash.json",
		"tab\t.json", "../..", ".",
	};
	for (size_t i = 0; i < sizeof rejected / sizeof rejected[0]; i++) {
		strcpy(out, "junk");
		assert_int_equal(fsout_safe_name(rejected[i], out, sizeof out), -1);
		assert_string_equal(out, "");
	}
	/* Too long for the caller's buffer: refused, not truncated. */
	assert_int_equal(fsout_safe_name("abcdefgh.json", out, 8), -2);  /* too long for n */
	assert_int_equal(fsout_safe_name("abcdefg.json", out, 8), 0);
	assert_string_equal(out, "abcdefg");
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(fsout_write_atomic_should_create_then_replace_content, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_write_atomic_should_keep_mode_0644_under_a_strict_umask, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_injected_write_failure_should_leave_previous_file_intact, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_write_into_missing_directory_should_fail_cleanly, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_write_into_readonly_directory_should_keep_previous_file, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_failed_rename_should_remove_the_temporary_file, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_concurrent_writers_should_never_mix_or_leave_temps, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_mkdirs_should_create_every_missing_parent, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_read_file_should_add_a_nul_and_respect_the_cap, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_resolve_date_should_prefer_report_then_epoch_then_mtime, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_resolve_date_should_reject_bad_dates_instead_of_falling_through, setup, teardown),
		cmocka_unit_test(fsout_safe_name_should_keep_only_a_harmless_base_name),
	};
	return cmocka_run_group_tests_name("fsout", tests, NULL, NULL);
}
