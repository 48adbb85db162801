/* test_fsout.c — atomic output, mkdir -p, whole-file reads, dossier dates
 * and output names (fsout), and output folders replaced as a whole
 * (fsfolder: the issue 25 guarantees). */
#include "util/file.h"
#include "test_util.h"
#include "fs/fsfolder.h"
#include "fs/fsout.h"
#include "fs/fsout_int.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/types.h>
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
	/* The target is a directory: refused before a temporary file is
	 * made (rename(2) once refused it after the write), nothing left. */
	path_in(fx, "result.json", p, sizeof p);
	assert_int_equal(mkdir(p, 0755), 0);
	assert_int_equal(fsout_write_atomic(p, "{}", 2, err, sizeof err), -1);
	assert_non_null(strstr(err, "is a folder"));
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
fsout_resolve_date_should_prefer_report_then_epoch_then_none(void **state)
{
	(void)state;
	char err[256] = "", d[11];
	setenv("SOURCE_DATE_EPOCH", "1700000000", 1); /* 2023-11-14T22:13:20Z */
	assert_int_equal(fsout_resolve_date("2026-03-17", d, err, sizeof err), FSOUT_DATE_REPORT);
	assert_string_equal(d, "2026-03-17");
	assert_int_equal(fsout_resolve_date("", d, err, sizeof err), FSOUT_DATE_EPOCH_ENV);
	assert_string_equal(d, "2023-11-14");
	/* Neither: undated, whatever the files' times or the clock say. */
	setenv("SOURCE_DATE_EPOCH", "", 1); /* empty counts as unset */
	assert_int_equal(fsout_resolve_date("", d, err, sizeof err), FSOUT_DATE_NONE);
	assert_string_equal(d, "");
	unsetenv("SOURCE_DATE_EPOCH");
	assert_int_equal(fsout_resolve_date(NULL, d, err, sizeof err), FSOUT_DATE_NONE);
	assert_string_equal(d, "");
	/* SOURCE_DATE_EPOCH = 0 is the epoch itself, not "unset". */
	setenv("SOURCE_DATE_EPOCH", "0", 1);
	assert_int_equal(fsout_resolve_date("", d, err, sizeof err), FSOUT_DATE_EPOCH_ENV);
	assert_string_equal(d, "1970-01-01");
	unsetenv("SOURCE_DATE_EPOCH");
}

static void
fsout_resolve_date_should_reject_bad_dates_instead_of_falling_through(void **state)
{
	(void)state;
	char err[256] = "", d[11];

	static const char *const bad_dates[] = {
		"2026-02-29", "2100-02-29", "2026-13-01", "2026-04-31", "26-03-17",
		"2026/03/17", "2026-03-17T00:00", "0000-01-01", "2026-3-170",
	};
	for (size_t i = 0; i < sizeof bad_dates / sizeof bad_dates[0]; i++) {
		assert_int_equal(fsout_resolve_date(bad_dates[i], d, err, sizeof err), -1);
		assert_non_null(strstr(err, "report.date"));
		assert_string_equal(d, "");
	}
	assert_int_equal(fsout_resolve_date("2024-02-29", d, err, sizeof err),
	                 FSOUT_DATE_REPORT);

	static const char *const bad_epochs[] = {
		"-86400", " 1700000000", "1700000000 ", "1.7e9", "0x10", "253402300800",
		"99999999999999999999999",
	};
	for (size_t i = 0; i < sizeof bad_epochs / sizeof bad_epochs[0]; i++) {
		setenv("SOURCE_DATE_EPOCH", bad_epochs[i], 1);
		assert_int_equal(fsout_resolve_date("", d, err, sizeof err), -1);
		assert_non_null(strstr(err, "SOURCE_DATE_EPOCH"));
	}
	setenv("SOURCE_DATE_EPOCH", "253402300799", 1); /* the last second of 9999 */
	assert_int_equal(fsout_resolve_date("", d, err, sizeof err), FSOUT_DATE_EPOCH_ENV);
	assert_string_equal(d, "9999-12-31");
	unsetenv("SOURCE_DATE_EPOCH");
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

static void
fsout_write_atomic_should_replace_only_a_regular_file(void **state)
{
	struct fixture *fx = *state;
	char p[128], target[128], err[256] = "";
	/* A link is neither followed nor replaced: its target keeps its
	 * bytes and the link stays (issue 36: every writer refuses links). */
	path_in(fx, "target.json", target, sizeof target);
	assert_int_equal(fsout_write_atomic(target, "mine", 4, err, sizeof err), 0);
	path_in(fx, "cal.json", p, sizeof p);
	assert_int_equal(symlink(target, p), 0);
	assert_int_equal(fsout_write_atomic(p, "new", 3, err, sizeof err), -1);
	assert_non_null(strstr(err, "symbolic link"));
	assert_file_is(target, "mine");
	struct stat st;
	assert_int_equal(lstat(p, &st), 0);
	assert_true(S_ISLNK(st.st_mode));
	/* A FIFO (a device as root would be the same) is not replaced. */
	path_in(fx, "fifo", p, sizeof p);
	assert_int_equal(mkfifo(p, 0644), 0);
	assert_int_equal(fsout_write_atomic(p, "new", 3, err, sizeof err), -1);
	assert_non_null(strstr(err, "not a regular file"));
	assert_int_equal(lstat(p, &st), 0);
	assert_true(S_ISFIFO(st.st_mode));
	assert_int_equal(count_entries(fx->dir), 3);  /* no temporary left */
}

static void
fsout_safe_name_should_refuse_hidden_and_reserved_names(void **state)
{
	(void)state;
	char out[64];
	/* Hidden names are the program's temporaries, locks and stamps (-1):
	 * a mission ".x.tmp.999999.0" looked like a dead writer's temporary
	 * of mission "x" and was deleted by its next build.  The table's
	 * files beside the mission folders are the program's too (-3). */
	static const struct {
		const char *path;
		int want;
	} refused[] = {
		{ ".x.tmp.999999.0.json", -1 }, { ".hidden.json", -1 },
		{ "m/.aeroeval-index-stamp.json", -1 }, { ".m.lock.json", -1 },
		{ "index.csv.json", -3 }, { "dir/index.json.json", -3 },
		{ "overview.pdf.json", -3 }, { "index.csv", -3 },
	};
	for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
		strcpy(out, "junk");
		assert_int_equal(fsout_safe_name(refused[i].path, out, sizeof out), refused[i].want);
		assert_string_equal(out, "");
	}
	/* Near them is fine. */
	assert_int_equal(fsout_safe_name("index.json", out, sizeof out), 0);
	assert_string_equal(out, "index");
	assert_int_equal(fsout_safe_name("index.csv2.json", out, sizeof out), 0);
	assert_string_equal(out, "index.csv2");
}

/* ---- fsfolder ------------------------------------------------------------ */

/* The names a test folder may hold. */
static const char *const set_files[] = { "a.json", "b.csv", NULL };

/* Writes the set "TAG-a" / "TAG-b" as fx->dir/m; asserts success. */
static void
write_set(const struct fixture *fx, const char *tag)
{
	struct fsfolder f;
	char err[512] = "", a[64], b[64];
	snprintf(a, sizeof a, "%s-a", tag);
	snprintf(b, sizeof b, "%s-b", tag);
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, 0, 1.0, err, sizeof err), 0);
	assert_int_equal(fsfolder_begin(&f, err, sizeof err), 0);
	assert_int_equal(fsfolder_put(&f, "a.json", a, strlen(a), 1, err, sizeof err), 0);
	assert_int_equal(fsfolder_put(&f, "b.csv", b, strlen(b), 0, err, sizeof err), 0);
	assert_int_equal(fsfolder_commit(&f, err, sizeof err), 0);
	fsfolder_close(&f);
}

/* Asserts that fx->dir/m holds exactly the set TAG. */
static void
assert_set(const struct fixture *fx, const char *tag)
{
	char p[160], want[64];
	snprintf(p, sizeof p, "%s/m", fx->dir);
	assert_int_equal(count_entries(p), 2);
	snprintf(p, sizeof p, "%s/m/a.json", fx->dir);
	snprintf(want, sizeof want, "%s-a", tag);
	assert_file_is(p, want);
	snprintf(p, sizeof p, "%s/m/b.csv", fx->dir);
	snprintf(want, sizeof want, "%s-b", tag);
	assert_file_is(p, want);
}

/* Opening fx->dir/m must fail with a message that starts with the path
 * fx->dir/SUB, names it once, and contains what. */
static void
assert_open_refused(const struct fixture *fx, const char *sub, const char *what)
{
	struct fsfolder f;
	char err[512] = "", path[160];
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, 0, 1.0, err, sizeof err), -1);
	fsfolder_close(&f);
	snprintf(path, sizeof path, "%s/%s: error: ", fx->dir, sub);
	if (strncmp(err, path, strlen(path)) != 0 || strstr(err, what) == NULL
	    || strstr(err + 1, fx->dir) != NULL)
		fail_msg("got \"%s\", want \"%s... %s ...\"", err, path, what);
}

static void
fsfolder_commit_should_replace_the_whole_set_and_leave_nothing_beside_it(void **state)
{
	struct fixture *fx = *state;
	write_set(fx, "one");
	assert_set(fx, "one");
	write_set(fx, "two");
	assert_set(fx, "two");
	/* No temporary folder, no old set, no lock file: only m. */
	assert_int_equal(count_entries(fx->dir), 1);
	char p[160];
	struct stat st;
	snprintf(p, sizeof p, "%s/m/b.csv", fx->dir);
	assert_int_equal(stat(p, &st), 0);
	assert_int_equal(st.st_mode & 0777, 0644);
}

static void
fsfolder_commit_without_exchange_should_swap_by_two_renames(void **state)
{
	struct fixture *fx = *state;
	setenv("AEROEVAL_TEST_NO_EXCHANGE", "1", 1);
	write_set(fx, "one");
	write_set(fx, "two");
	unsetenv("AEROEVAL_TEST_NO_EXCHANGE");
	assert_set(fx, "two");
	assert_int_equal(count_entries(fx->dir), 1);  /* the old set is gone */
}

static void
fsfolder_failed_write_should_leave_the_old_set_whole(void **state)
{
	struct fixture *fx = *state;
	/* The hook's setting and the words the message must carry. */
	static const char *const faults[][2] = { { "1", "No space left" },
		{ "2:EIO", "Input/output error" }, { "1:EDQUOT", "quota" } };
	write_set(fx, "old");
	for (size_t i = 0; i < sizeof faults / sizeof faults[0]; i++) {
		struct fsfolder f;
		char err[512] = "";
		fsout_fault_reset();
		setenv("AEROEVAL_FAIL_WRITE", faults[i][0], 1);
		assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, 0, 1.0, err, sizeof err), 0);
		assert_int_equal(fsfolder_begin(&f, err, sizeof err), 0);
		int rc = fsfolder_put(&f, "a.json", "new-a", 5, 1, err, sizeof err);
		if (rc == 0)
			rc = fsfolder_put(&f, "b.csv", "new-b", 5, 1, err, sizeof err);
		assert_int_equal(rc, -1);
		/* One line naming the file the user knows, not the temporary. */
		assert_non_null(strstr(err, "/m/"));
		assert_null(strstr(err, ".tmp."));
		assert_non_null(strstr(err, faults[i][1]));
		fsfolder_close(&f);
		unsetenv("AEROEVAL_FAIL_WRITE");
		assert_set(fx, "old");
		assert_int_equal(count_entries(fx->dir), 1);
	}
}

/* Makes the folder fx->dir/NAME (outside any output set) and gives its path. */
static void
make_dir(const struct fixture *fx, const char *name, char *out, size_t n)
{
	path_in(fx, name, out, n);
	assert_int_equal(mkdir(out, 0755), 0);
}

static void
fsfolder_open_should_refuse_a_linked_or_non_folder_output_naming_it(void **state)
{
	struct fixture *fx = *state;
	char p[160], other[160];
	make_dir(fx, "elsewhere", other, sizeof other);
	path_in(fx, "m", p, sizeof p);
	assert_int_equal(symlink("elsewhere", p), 0);
	assert_open_refused(fx, "m", "symbolic link");
	assert_int_equal(count_entries(other), 0);
	assert_int_equal(unlink(p), 0);
	assert_int_equal(mkfifo(p, 0644), 0);
	assert_open_refused(fx, "m", "not a directory");
	assert_int_equal(unlink(p), 0);
	/* A name that would leave DIR is refused before anything is opened. */
	struct fsfolder f;
	char err[256];
	assert_int_equal(fsfolder_open(&f, fx->dir, "../m", set_files, 0, 1.0, err, sizeof err), -1);
	fsfolder_close(&f);
}

static void
fsfolder_open_should_refuse_links_fifos_and_foreign_files_inside(void **state)
{
	struct fixture *fx = *state;
	char p[200], victim[160];
	snprintf(victim, sizeof victim, "%s/victim", fx->dir);
	FILE *v = fopen(victim, "w");
	assert_non_null(v);
	fputs("precious", v);
	fclose(v);
	write_set(fx, "old");

	/* The link an attacker plants where an older aeroeval put its stamp's
	 * temporary file, and a link in place of an output. */
	snprintf(p, sizeof p, "%s/m/..aeroeval-stamp.tmp.4242.0", fx->dir);
	assert_int_equal(symlink(victim, p), 0);
	assert_open_refused(fx, "m/..aeroeval-stamp.tmp.4242.0", "symbolic link");
	assert_int_equal(unlink(p), 0);
	snprintf(p, sizeof p, "%s/m/b.csv", fx->dir);
	assert_int_equal(unlink(p), 0);
	assert_int_equal(symlink(victim, p), 0);
	assert_open_refused(fx, "m/b.csv", "symbolic link");
	assert_int_equal(unlink(p), 0);
	/* A FIFO where an output goes: refused at once, never opened. */
	assert_int_equal(mkfifo(p, 0644), 0);
	assert_open_refused(fx, "m/b.csv", "not a regular file");
	assert_int_equal(unlink(p), 0);
	/* The folder is replaced whole, so a file of the user's in it would be
	 * lost: refused.  An older aeroeval's temporary file is ours. */
	snprintf(p, sizeof p, "%s/m/notes.txt", fx->dir);
	assert_int_equal(close(open(p, O_CREAT | O_WRONLY, 0644)), 0);
	assert_open_refused(fx, "m/notes.txt", "not an output of aeroeval");
	assert_int_equal(unlink(p), 0);
	snprintf(p, sizeof p, "%s/m/.a.json.tmp.4242.7", fx->dir);
	assert_int_equal(close(open(p, O_CREAT | O_WRONLY, 0644)), 0);
	write_set(fx, "new");
	assert_set(fx, "new");
	assert_file_is(victim, "precious");
}

static void
fsfolder_begin_should_step_over_a_link_planted_at_its_temporary_name(void **state)
{
	struct fixture *fx = *state;
	char p[200], trap[160];
	make_dir(fx, "trap", trap, sizeof trap);
	snprintf(p, sizeof p, "%s/.m.tmp.%ld.0", fx->dir, (long)getpid());
	assert_int_equal(symlink("trap", p), 0);
	write_set(fx, "one");
	assert_set(fx, "one");
	assert_int_equal(count_entries(trap), 0);
	/* Not ours (a link, not a folder), so it is left alone. */
	struct stat st;
	assert_int_equal(lstat(p, &st), 0);
	assert_true(S_ISLNK(st.st_mode));
}

/* A pid that no process has: a child that has exited and been reaped. */
static long
dead_pid(void)
{
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0)
		_exit(0);
	assert_int_equal(waitpid(pid, NULL, 0), pid);
	return (long)pid;
}

/* Makes fx->dir/NAME as a folder with one file, mtime age_s seconds ago. */
static void
make_temp(const struct fixture *fx, const char *name, double age_s)
{
	char p[200], q[240];
	snprintf(p, sizeof p, "%s/%s", fx->dir, name);
	assert_int_equal(mkdir(p, 0755), 0);
	snprintf(q, sizeof q, "%s/result.json", p);
	assert_int_equal(close(open(q, O_CREAT | O_WRONLY, 0644)), 0);
	struct timeval tv[2];
	gettimeofday(&tv[0], NULL);
	tv[0].tv_sec -= (time_t)age_s;
	tv[1] = tv[0];
	assert_int_equal(utimes(p, tv), 0);
}

static int
exists_in(const struct fixture *fx, const char *name)
{
	char p[200];
	struct stat st;
	snprintf(p, sizeof p, "%s/%s", fx->dir, name);
	return lstat(p, &st) == 0;
}

static void
fsfolder_clean_should_remove_only_its_own_stale_temporaries(void **state)
{
	struct fixture *fx = *state;
	char dead[64], dead_other[64], dead_longer[64], live_young[64], live_old[64];
	long gone = dead_pid(), live = (long)getppid();
	snprintf(dead, sizeof dead, ".m.tmp.%ld.0", gone);
	snprintf(dead_other, sizeof dead_other, ".other.tmp.%ld.0", gone);
	snprintf(dead_longer, sizeof dead_longer, ".m.tmp.5.tmp.%ld.0", gone);
	snprintf(live_young, sizeof live_young, ".m.tmp.%ld.1", live);
	snprintf(live_old, sizeof live_old, ".m.tmp.%ld.2", live);
	make_temp(fx, dead, 0.0);
	make_temp(fx, dead_other, 0.0);
	make_temp(fx, dead_longer, 0.0);
	make_temp(fx, live_young, 60.0);
	make_temp(fx, live_old, 2.0 * FSFOLDER_STALE_S);

	struct fsfolder f;
	char err[256];
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, 0, 1.0, err, sizeof err), 0);
	assert_int_equal(fsfolder_clean(&f, FSFOLDER_STALE_S), 2);
	fsfolder_close(&f);
	assert_false(exists_in(fx, dead));        /* its writer is gone */
	assert_false(exists_in(fx, live_old));    /* older than any build */
	assert_true(exists_in(fx, live_young));   /* may still be written */
	assert_true(exists_in(fx, dead_other));   /* another mission's */
	assert_true(exists_in(fx, dead_longer));  /* mission "m.tmp.5"'s */
}

/* Sets fx->dir/m aside as a killed two-rename swap leaves it: m missing,
 * the old set at ".m.old.PID.0" of a writer that is gone, and its new set
 * (whole or not) at ".m.tmp.PID.0". */
static void
leave_swap_half_done(const struct fixture *fx, long pid)
{
	char from[160], to[160];
	snprintf(from, sizeof from, "%s/m", fx->dir);
	snprintf(to, sizeof to, "%s/.m.old.%ld.0", fx->dir, pid);
	assert_int_equal(rename(from, to), 0);
	snprintf(to, sizeof to, ".m.tmp.%ld.0", pid);
	make_temp(fx, to, 0.0);
}

static void
fsfolder_open_should_put_back_an_old_set_a_killed_swap_left_aside(void **state)
{
	struct fixture *fx = *state;
	write_set(fx, "old");
	long gone = dead_pid();
	leave_swap_half_done(fx, gone);
	/* Issue 36: the clean-up of the build's parent deleted the aside,
	 * the only copy of the old set.  Now the next writer (here one that
	 * only looks, as the parent's clean-up does) puts it back first. */
	struct fsfolder f;
	char err[256], tmp[64];
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, FSFOLDER_NOWAIT, 0.0,
	    err, sizeof err), 0);
	assert_true(fsfolder_exists(&f));
	assert_int_equal(fsfolder_clean(&f, FSFOLDER_STALE_S), 1);  /* the new set */
	fsfolder_close(&f);
	assert_set(fx, "old");
	snprintf(tmp, sizeof tmp, ".m.tmp.%ld.0", gone);
	assert_false(exists_in(fx, tmp));
	assert_int_equal(count_entries(fx->dir), 1);
}

static void
fsfolder_clean_should_keep_an_aside_while_the_set_is_missing(void **state)
{
	struct fixture *fx = *state;
	write_set(fx, "old");
	long gone = dead_pid();
	char aside[64], p[160];
	leave_swap_half_done(fx, gone);
	snprintf(aside, sizeof aside, ".m.old.%ld.0", gone);
	/* Whatever happens to m meanwhile, a clean never removes the only
	 * copy: with m missing it leaves the aside (here recover() is kept
	 * from running by a regular file "m" that then goes). */
	snprintf(p, sizeof p, "%s/m", fx->dir);
	assert_int_equal(close(open(p, O_CREAT | O_WRONLY, 0644)), 0);
	struct fsfolder f;
	char err[256];
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, 0, 1.0, err, sizeof err), -1);
	assert_int_equal(unlink(p), 0);
	fsfolder_clean(&f, FSFOLDER_STALE_S);
	fsfolder_close(&f);
	assert_true(exists_in(fx, aside));
	/* A set at m again: the aside is an old copy, and goes. */
	write_set(fx, "new");
	assert_set(fx, "new");
	assert_false(exists_in(fx, aside));
}

static void
fsfolder_carry_should_keep_the_files_it_is_asked_to(void **state)
{
	struct fixture *fx = *state;
	write_set(fx, "one");
	struct fsfolder f;
	char err[256];
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, 0, 1.0, err, sizeof err), 0);
	assert_int_equal(fsfolder_begin(&f, err, sizeof err), 0);
	assert_int_equal(fsfolder_carry(&f, "a.json", err, sizeof err), 0);
	assert_int_equal(fsfolder_carry(&f, "absent.txt", err, sizeof err), 0);
	assert_int_equal(fsfolder_put(&f, "b.csv", "two-b", 5, 1, err, sizeof err), 0);
	assert_int_equal(fsfolder_commit(&f, err, sizeof err), 0);
	fsfolder_close(&f);
	char p[160];
	snprintf(p, sizeof p, "%s/m/a.json", fx->dir);
	assert_file_is(p, "one-a");
	snprintf(p, sizeof p, "%s/m/b.csv", fx->dir);
	assert_file_is(p, "two-b");
}

static void
fsfolder_open_should_take_a_pattern_for_a_folder_of_missions(void **state)
{
	struct fixture *fx = *state;
	static const char *const missions[] = { "*.json", NULL };
	char p[160], err[512] = "";
	snprintf(p, sizeof p, "%s/m", fx->dir);
	assert_int_equal(mkdir(p, 0755), 0);
	snprintf(p, sizeof p, "%s/m/01-Some_thing.v2.json", fx->dir);
	assert_int_equal(close(open(p, O_CREAT | O_WRONLY, 0644)), 0);
	struct fsfolder f;
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", missions, 0, 1.0, err, sizeof err), 0);
	fsfolder_close(&f);
	/* Not a mission file: another suffix, hidden, or a byte outside. */
	static const char *const foreign[] = { "notes.txt", ".x.json", "a b.json", "json" };
	for (size_t i = 0; i < sizeof foreign / sizeof foreign[0]; i++) {
		snprintf(p, sizeof p, "%s/m/%s", fx->dir, foreign[i]);
		assert_int_equal(close(open(p, O_CREAT | O_WRONLY, 0644)), 0);
		assert_int_equal(fsfolder_open(&f, fx->dir, "m", missions, 0, 1.0, err, sizeof err), -1);
		assert_non_null(strstr(err, "not an output of aeroeval"));
		fsfolder_close(&f);
		assert_int_equal(unlink(p), 0);
	}
}

static void
fsfolder_lock_should_keep_a_second_writer_out_until_released(void **state)
{
	struct fixture *fx = *state;
	int to_child[2], to_parent[2];
	assert_int_equal(pipe(to_child), 0);
	assert_int_equal(pipe(to_parent), 0);
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		struct fsfolder f;
		char err[256], c = 0;
		int rc = fsfolder_open(&f, fx->dir, "m", set_files, 0, 1.0, err, sizeof err);
		if (write(to_parent[1], "x", 1) != 1 || read(to_child[0], &c, 1) != 1)
			rc = -1;
		fsfolder_close(&f);
		_exit(rc == 0 ? 0 : 1);
	}
	char c, err[512] = "";
	assert_int_equal(read(to_parent[0], &c, 1), 1);
	struct fsfolder f;
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, FSFOLDER_NOWAIT, 0.0,
	    err, sizeof err), FSFOLDER_BUSY);
	fsfolder_close(&f);
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, 0, 0.1, err, sizeof err), -1);
	assert_non_null(strstr(err, "another build"));
	fsfolder_close(&f);
	assert_int_equal(write(to_child[1], "x", 1), 1);
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, 0, 5.0, err, sizeof err), 0);
	fsfolder_close(&f);
	int status = -1;
	assert_int_equal(waitpid(pid, &status, 0), pid);
	assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
	assert_int_equal(count_entries(fx->dir), 0);  /* the lock file went with it */
	for (int i = 0; i < 2; i++) {
		close(to_child[i]);
		close(to_parent[i]);
	}
}

static void
fsfolder_hash_should_match_the_bytes_written(void **state)
{
	struct fixture *fx = *state;
	write_set(fx, "one");
	struct fsfolder f;
	char err[256], got[SHA256_HEX_LEN], want[SHA256_HEX_LEN], buf[16];
	size_t n;
	assert_int_equal(fsfolder_open(&f, fx->dir, "m", set_files, FSFOLDER_NOWAIT, 0.0,
	    err, sizeof err), 0);
	assert_int_equal(fsfolder_hash(&f, "a.json", got), 0);
	sha256_hex("one-a", 5, want);
	assert_string_equal(got, want);
	assert_int_equal(fsfolder_hash(&f, "missing", got), -1);
	assert_int_equal(fsfolder_read(&f, "b.csv", buf, sizeof buf, &n), 0);
	assert_int_equal(n, 5);
	assert_string_equal(buf, "one-b");
	assert_int_equal(fsfolder_read(&f, "b.csv", buf, 5, &n), -1);  /* too long */
	fsfolder_close(&f);
}

static void
fsout_safe_name_should_refuse_a_name_too_long_for_its_temporaries(void **state)
{
	(void)state;
	char base[FSOUT_NAME_MAX + 16], out[256];
	memset(base, 'n', FSOUT_NAME_MAX);
	strcpy(base + FSOUT_NAME_MAX, ".json");
	assert_int_equal(fsout_safe_name(base, out, sizeof out), 0);
	assert_int_equal(strlen(out), FSOUT_NAME_MAX);
	memset(base, 'n', FSOUT_NAME_MAX + 1);
	strcpy(base + FSOUT_NAME_MAX + 1, ".json");
	assert_int_equal(fsout_safe_name(base, out, sizeof out), -2);
	assert_string_equal(out, "");
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
		cmocka_unit_test_setup_teardown(fsout_resolve_date_should_prefer_report_then_epoch_then_none, setup, teardown),
		cmocka_unit_test_setup_teardown(fsout_resolve_date_should_reject_bad_dates_instead_of_falling_through, setup, teardown),
		cmocka_unit_test(fsout_safe_name_should_keep_only_a_harmless_base_name),
		cmocka_unit_test(fsout_safe_name_should_refuse_a_name_too_long_for_its_temporaries),
		cmocka_unit_test(fsout_safe_name_should_refuse_hidden_and_reserved_names),
		cmocka_unit_test_setup_teardown(fsout_write_atomic_should_replace_only_a_regular_file, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_open_should_put_back_an_old_set_a_killed_swap_left_aside, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_clean_should_keep_an_aside_while_the_set_is_missing, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_carry_should_keep_the_files_it_is_asked_to, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_open_should_take_a_pattern_for_a_folder_of_missions, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_commit_should_replace_the_whole_set_and_leave_nothing_beside_it, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_commit_without_exchange_should_swap_by_two_renames, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_failed_write_should_leave_the_old_set_whole, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_open_should_refuse_a_linked_or_non_folder_output_naming_it, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_open_should_refuse_links_fifos_and_foreign_files_inside, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_begin_should_step_over_a_link_planted_at_its_temporary_name, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_clean_should_remove_only_its_own_stale_temporaries, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_lock_should_keep_a_second_writer_out_until_released, setup, teardown),
		cmocka_unit_test_setup_teardown(fsfolder_hash_should_match_the_bytes_written, setup, teardown),
	};
	return cmocka_run_group_tests_name("fsout", tests, NULL, NULL);
}
