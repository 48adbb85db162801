/* cli_summary.c — the design-space table of an output folder (see
 * cli_summary.h).
 *
 * Nothing under DIR is followed (as fsfolder.h promises for writes): a
 * mission folder that is a symbolic link is not a mission folder, and a
 * result.json that is one is an error naming it.  The folders are read
 * without the per-mission locks: a build swaps a mission's folder in whole,
 * so each result.json read is some complete version.
 */
#include "cli/cli_summary.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli/batch.h"
#include "cli/cli.h"
#include "cli/cli_help.h"
#include "core/diag.h"
#include "core/summary.h"
#include "core/template.h"
#include "input/summary_in.h"
#include "output/fsout.h"
#include "output/index.h"
#include "output/index_pdf.h"
#include "util/file.h"
#include "util/strbuf.h"

#define SUMMARY_USAGE "usage: aeroeval summary [-q] [--stdout] [--no-pdf] " \
	"[--template FILE] DIR\n"

#define RESULT_MAX ((size_t)64 << 20)  /* a result.json is ~150 KB */
#define LOCK_NAME ".aeroeval-index.lock"
#define LOCK_WAIT_S 60.0   /* another machine rewriting the index takes < 1 s */
#define LOCK_POLL_MS 20

/* "DIR/a/b" without a doubled slash. */
static void
join(struct strbuf *sb, const char *dir, const char *a, const char *b)
{
	size_t n = strlen(dir);
	strbuf_reset(sb);
	strbuf_printf(sb, "%s%s%s", dir, n > 0 && dir[n - 1] == '/' ? "" : "/", a);
	if (b != NULL)
		strbuf_printf(sb, "/%s", b);
}

/* ---- the lock ------------------------------------------------------------- */

/* Takes DIR/LOCK_NAME, waiting up to LOCK_WAIT_S.  The holder removes the
 * file before it unlocks, so a waiter that gets the lock checks that its
 * file is still the one at that name (as fsfolder.c does).  Returns the
 * descriptor, or -1 with errno set (EWOULDBLOCK: waited too long). */
static int
lock_take(int dir_fd)
{
	double t_end = batch_now_s() + LOCK_WAIT_S;
	for (;;) {
		int fd = openat(dir_fd, LOCK_NAME, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC
		    | O_NONBLOCK, 0644);
		if (fd < 0)
			return -1;
		while (flock(fd, LOCK_EX | LOCK_NB) != 0) {
			int e = errno;
			if (e == EINTR)
				continue;
			if (e != EWOULDBLOCK || batch_now_s() >= t_end) {
				close(fd);
				errno = e;
				return -1;
			}
			struct timespec ts = { 0, LOCK_POLL_MS * 1000000L };
			nanosleep(&ts, NULL);
		}
		struct stat a, b;
		if (fstat(fd, &a) == 0 && fstatat(dir_fd, LOCK_NAME, &b, AT_SYMLINK_NOFOLLOW) == 0
		    && a.st_dev == b.st_dev && a.st_ino == b.st_ino)
			return fd;
		close(fd);  /* the holder we waited for removed it: again */
	}
}

static void
lock_release(int dir_fd, int fd)
{
	if (fd < 0)
		return;
	unlinkat(dir_fd, LOCK_NAME, 0);  /* before unlocking: see lock_take() */
	close(fd);
}

/* The files the table writes into DIR, each through a temporary
 * ".FILE.tmp.PID.SEQ" (fsout.h) that a killed writer leaves behind. */
static const char *const index_files[] = { "index.csv", "index.json", "overview.pdf", NULL };

/* The pid of a temporary of one of index_files, or 0 when s is not one. */
static long
temp_owner(const char *s)
{
	for (size_t i = 0; index_files[i] != NULL; i++) {
		size_t n = strlen(index_files[i]);
		if (s[0] != '.' || strncmp(s + 1, index_files[i], n) != 0
		    || strncmp(s + 1 + n, ".tmp.", 5) != 0)
			continue;
		const char *p = s + 1 + n + 5;
		size_t d1 = strspn(p, "0123456789");
		if (d1 == 0 || d1 > 9 || p[d1] != '.' || strspn(p + d1 + 1, "0123456789") == 0)
			return 0;
		return strtol(p, NULL, 10);
	}
	return 0;
}

/* Removes the temporaries of the table whose writer is gone or which are
 * an hour old (no table takes an hour to write); with the lock held. */
static void
clean_temps(int dir_fd)
{
	int dfd = dup(dir_fd);
	DIR *d = dfd >= 0 ? fdopendir(dfd) : NULL;
	if (d == NULL) {
		if (dfd >= 0)
			close(dfd);
		return;
	}
	rewinddir(d);
	time_t now = time(NULL);
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		long pid = temp_owner(e->d_name);
		struct stat st;
		if (pid <= 0 || pid == (long)getpid()
		    || fstatat(dir_fd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0
		    || !S_ISREG(st.st_mode))
			continue;
		if ((kill((pid_t)pid, 0) != 0 && errno == ESRCH) || difftime(now, st.st_mtime) > 3600.0)
			unlinkat(dir_fd, e->d_name, 0);
	}
	closedir(d);
}

/* ---- reading the folders ---------------------------------------------------- */

/* The reason part of a util/file.h message "PATH: reason". */
static const char *
reason(const char *msg, const char *path)
{
	size_t n = strlen(path);
	return strncmp(msg, path, n) == 0 && msg[n] == ':' ? msg + n + 2 : msg;
}

/* The row of folder name, if it holds a result.json; added to s.  A
 * result.json that cannot be read is reported to dg. */
static void
scan_one(int dir_fd, const char *dir, const char *name, struct summary *s,
         struct diag *dg)
{
	struct stat st;
	if (fstatat(dir_fd, name, &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISDIR(st.st_mode))
		return;  /* index.csv, a link, ...: not a mission folder */
	int sub = openat(dir_fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
	if (sub < 0)
		return;
	if (fstatat(sub, "result.json", &st, AT_SYMLINK_NOFOLLOW) != 0) {
		close(sub);  /* no result: not a compiled mission */
		return;
	}
	struct strbuf path = STRBUF_INIT;
	join(&path, dir, name, "result.json");
	unsigned char *buf;
	size_t n;
	char msg[4400];
	if (file_read_at(sub, "result.json", strbuf_str(&path), RESULT_MAX, &buf, &n,
	    msg, sizeof msg) != 0) {
		struct diag_loc loc = { strbuf_str(&path), 0, 0 };
		diag_report(dg, DIAG_IO, &loc, NULL, ": %s", reason(msg, strbuf_str(&path)));
	} else {
		struct summary_row row;
		if (summary_in_parse(strbuf_str(&path), (const char *)buf, n, name, &row, dg) == 0)
			summary_add(s, &row);
		free(buf);
	}
	strbuf_free(&path);
	close(sub);
}

/* Every compiled mission of DIR (hidden entries skipped: temporaries and
 * locks), sorted by name. */
static void
scan(int dir_fd, const char *dir, struct summary *s, struct diag *dg)
{
	int dfd = dup(dir_fd);
	DIR *d = dfd >= 0 ? fdopendir(dfd) : NULL;
	if (d == NULL) {
		if (dfd >= 0)
			close(dfd);
		struct diag_loc loc = { dir, 0, 0 };
		diag_report(dg, DIAG_IO, &loc, NULL, ": %s", strerror(errno));
		return;
	}
	rewinddir(d);  /* the duplicate shares dir_fd's position */
	struct dirent *e;
	while ((e = readdir(d)) != NULL)
		if (e->d_name[0] != '.')
			scan_one(dir_fd, dir, e->d_name, s, dg);
	closedir(d);
	summary_sort(s);
}

/* ---- writing ---------------------------------------------------------------- */

/* Writes DIR/file atomically unless it already holds exactly these bytes
 * (an unchanged table keeps its date, and a read-only folder with a current
 * table is no error). */
static int
put(int dir_fd, const char *dir, const char *file, const void *data, size_t n,
    FILE *err)
{
	struct strbuf path = STRBUF_INIT;
	join(&path, dir, file, NULL);
	unsigned char *old;
	size_t n_old;
	char msg[4400];
	int rc = 0;
	if (file_read_at(dir_fd, file, strbuf_str(&path), n, &old, &n_old, msg, sizeof msg) == 0) {
		bool same = n_old == n && memcmp(old, data, n) == 0;
		free(old);
		if (same)
			goto done;
	}
	if (fsout_write_atomic(strbuf_str(&path), data, n, msg, sizeof msg) != 0) {
		fprintf(err, "aeroeval: error: %s\n", msg);
		rc = -1;
	}
done:
	strbuf_free(&path);
	return rc;
}

static int
put_tables(int dir_fd, const char *dir, const struct summary *s, FILE *err)
{
	char *csv = index_csv(s);
	char *json = index_json(s, AEROEVAL_VERSION);
	int rc = put(dir_fd, dir, "index.csv", csv, strlen(csv), err);
	if (rc == 0)
		rc = put(dir_fd, dir, "index.json", json, strlen(json), err);
	free(csv);
	free(json);
	return rc;
}

/* overview.pdf of the rows with template tpl.  Returns the exit status: 0,
 * 2 (a file-system problem) or 3 (the PDF could not be rendered). */
static int
put_overview(int dir_fd, const char *dir, const struct summary *s,
             const struct template *tpl, FILE *err)
{
	unsigned char *pdf = NULL;
	size_t n = 0;
	char msg[512];
	int rc = 0;
	if (index_pdf_render(s, tpl, &pdf, &n, msg, sizeof msg) != 0) {
		fprintf(err, "%s/overview.pdf: internal error: %s\n", dir, msg);
		rc = 3;
	} else if (put(dir_fd, dir, "overview.pdf", pdf, n, err) != 0) {
		rc = 2;
	}
	free(pdf);
	return rc;
}

/* An output folder opened for its table. */
struct table {
	int dir_fd;          /* DIR */
	int lock;            /* the index lock, -1 when not taken */
	struct summary s;    /* every row read */
	int rc;              /* 2 once a result.json could not be read */
};

/* Opens DIR, takes the index lock when `locked` (and then removes a killed
 * writer's temporaries), and reads every row; problems go to err.  Returns
 * 0, or 2 when DIR cannot be opened or locked (t is then closed). */
static int
table_open(struct table *t, const char *dir, bool locked, FILE *err)
{
	memset(t, 0, sizeof *t);
	t->lock = -1;
	t->dir_fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (t->dir_fd < 0) {
		fprintf(err, "%s: error: cannot open the output folder: %s\n", dir, strerror(errno));
		return 2;
	}
	if (locked && (t->lock = lock_take(t->dir_fd)) < 0) {
		fprintf(err, "%s/index.csv: error: cannot take the index lock %s: %s\n", dir,
		    LOCK_NAME, errno == EWOULDBLOCK ? "another build held it too long"
		    : strerror(errno));
		close(t->dir_fd);
		return 2;
	}
	if (locked)
		clean_temps(t->dir_fd);
	struct diag *dg = diag_alloc(err);
	scan(t->dir_fd, dir, &t->s, dg);
	t->rc = diag_n_errors(dg) > 0 ? 2 : 0;
	diag_flush(dg);
	diag_free(dg);
	return 0;
}

static void
table_close(struct table *t)
{
	lock_release(t->dir_fd, t->lock);
	close(t->dir_fd);
	summary_free(&t->s);
}

int
cli_summary_refresh(const char *dir, const struct template *tpl, FILE *err)
{
	struct table t;
	if (table_open(&t, dir, true, err) != 0)
		return 2;
	int rc = t.rc;
	struct stat st;
	if (t.s.n > 0 && put_tables(t.dir_fd, dir, &t.s, err) != 0)
		rc = 2;
	/* An overview drawn by `summary` is kept current too. */
	else if (t.s.n > 0 && tpl != NULL
	    && fstatat(t.dir_fd, "overview.pdf", &st, AT_SYMLINK_NOFOLLOW) == 0) {
		int orc = put_overview(t.dir_fd, dir, &t.s, tpl, err);
		if (orc > rc)
			rc = orc;
	}
	table_close(&t);
	return rc;
}

int
cli_summary_stale(const char *dir)
{
	DIR *d = opendir(dir);
	if (d == NULL)
		return 0;  /* the refresh would only fail to open it */
	int has_csv = 0, leftover = 0;
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		has_csv |= strcmp(e->d_name, "index.csv") == 0;
		leftover |= temp_owner(e->d_name) > 0 || strcmp(e->d_name, LOCK_NAME) == 0;
	}
	closedir(d);
	return !has_csv || leftover;
}

/* ---- the command ------------------------------------------------------------ */

static void
report_counts(const char *dir, const struct summary *s, int pdf)
{
	size_t c[SUMMARY_STATUS_MAX];
	summary_count(s, c);
	fprintf(stderr, "summary: %zu missions (%zu feasible, %zu infeasible, %zu not buildable)"
	    " -> %s: index.csv, index.json%s\n", s->n, c[SUMMARY_FEASIBLE],
	    c[SUMMARY_INFEASIBLE], c[SUMMARY_NOT_BUILDABLE], dir, pdf ? ", overview.pdf" : "");
}

int
cli_summary(int argc, char **argv)
{
	const char *dir = NULL, *tpl_path = NULL;
	int quiet = 0, to_stdout = 0, pdf = 1;
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i];
		if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
			cli_help_command("summary", stdout);
			return 0;
		} else if (strcmp(a, "-q") == 0) {
			quiet = 1;
		} else if (strcmp(a, "--stdout") == 0) {
			to_stdout = 1;
		} else if (strcmp(a, "--no-pdf") == 0) {
			pdf = 0;
		} else if (strcmp(a, "--template") == 0 && i + 1 < argc) {
			tpl_path = argv[++i];
		} else if ((a[0] != '-' || a[1] == '\0') && dir == NULL) {
			dir = a;
		} else {
			fprintf(stderr, "aeroeval summary: unknown option, missing value or "
			    "second folder: %s\n%s", a, SUMMARY_USAGE);
			return 2;
		}
	}
	if (dir == NULL) {
		fprintf(stderr, "aeroeval summary: no output folder given\n%s", SUMMARY_USAGE);
		return 2;
	}
	/* --stdout writes nothing, so it needs no lock (and works read-only). */
	struct table t;
	if (table_open(&t, dir, !to_stdout, stderr) != 0)
		return 2;
	int rc = t.rc;
	if (t.s.n == 0) {
		fprintf(stderr, "%s: error: no compiled mission here (no NAME/result.json)\n", dir);
		rc = 2;
	} else if (to_stdout) {
		char *csv = index_csv(&t.s);
		fputs(csv, stdout);
		free(csv);
	} else {
		int wrc = put_tables(t.dir_fd, dir, &t.s, stderr) != 0 ? 2 : 0;
		struct template *tpl = wrc == 0 && pdf ? cli_template_load(tpl_path, stderr) : NULL;
		if (wrc == 0 && pdf)
			wrc = tpl != NULL ? put_overview(t.dir_fd, dir, &t.s, tpl, stderr) : 2;
		template_free(tpl);
		if (wrc > rc)
			rc = wrc;
		if (wrc == 0 && !quiet)
			report_counts(dir, &t.s, pdf);
	}
	table_close(&t);
	return rc;
}
