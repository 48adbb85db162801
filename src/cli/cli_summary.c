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
#include "cli/pipeline.h"
#include "diag/diag.h"
#include "result/table_row.h"
#include "template/template.h"
#include "input/table_in.h"
#include "fs/fsout.h"
#include "formats/index.h"
#include "pdf/index_pdf.h"
#include "util/file.h"
#include "util/sha256.h"
#include "util/strbuf.h"
#include "util/xalloc.h"

#define SUMMARY_USAGE "usage: aeroeval summary [-q] [--stdout] [--no-pdf] " \
	"[--template FILE] DIR\n"

#define RESULT_MAX ((size_t)64 << 20)  /* a result.json is ~150 KB */
#define LOCK_NAME ".aeroeval-index.lock"
#define LOCK_WAIT_S 60.0   /* another machine rewriting the index takes < 1 s */
#define LOCK_POLL_MS 20
/* The table's stamp (see "the stamp" below) and its first line. */
#define STAMP_NAME ".aeroeval-index-stamp"
#define STAMP_MAGIC "aeroeval-index-stamp 1\n"
#define STAMP_MAX 4096

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

/* The pid of s when it is a temporary ".FILE.tmp.PID.SEQ" of file
 * (fsout.h), which a killed writer leaves behind; else 0. */
static long
temp_pid(const char *s, const char *file)
{
	size_t n = strlen(file);
	if (s[0] != '.' || strncmp(s + 1, file, n) != 0 || strncmp(s + 1 + n, ".tmp.", 5) != 0)
		return 0;
	const char *p = s + 1 + n + 5;
	size_t d1 = strspn(p, "0123456789");
	if (d1 == 0 || d1 > 9 || p[d1] != '.' || strspn(p + d1 + 1, "0123456789") == 0)
		return 0;
	return strtol(p, NULL, 10);
}

/* The pid of a temporary of one of the files the table writes into DIR
 * (index_file_names and the stamp), or 0 when s is not one. */
static long
temp_owner(const char *s)
{
	long pid = temp_pid(s, STAMP_NAME);
	for (size_t i = 0; pid == 0 && index_file_names[i] != NULL; i++)
		pid = temp_pid(s, index_file_names[i]);
	return pid;
}

/* Removes the temporaries of the table whose writer is gone or which are
 * an hour old (no table takes an hour to write); with the lock held. */
static void
clean_temps(int dir_fd)
{
	DIR *d = file_dir_stream(dir_fd);
	if (d == NULL)
		return;
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
scan_one(int dir_fd, const char *dir, const char *name, struct table_rows *s,
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
		struct table_row row;
		if (table_in_parse(strbuf_str(&path), (const char *)buf, n, name, &row, dg) == 0)
			table_row_add(s, &row);
		free(buf);
	}
	strbuf_free(&path);
	close(sub);
}

/* Every compiled mission of DIR (hidden entries skipped: temporaries and
 * locks), sorted by name. */
static void
scan(int dir_fd, const char *dir, struct table_rows *s, struct diag *dg)
{
	DIR *d = file_dir_stream(dir_fd);
	if (d == NULL) {
		struct diag_loc loc = { dir, 0, 0 };
		diag_report(dg, DIAG_IO, &loc, NULL, ": %s", strerror(errno));
		return;
	}
	struct dirent *e;
	while ((e = readdir(d)) != NULL)
		if (e->d_name[0] != '.')
			scan_one(dir_fd, dir, e->d_name, s, dg);
	closedir(d);
	table_row_sort(s);
}

/* ---- the stamp ------------------------------------------------------------ */
/* DIR/.aeroeval-index-stamp says which rows the table was made from and
 * which bytes it was written with:
 *     aeroeval-index-stamp 1
 *     rows HEX                  every row's name, result.json size and SHA-256
 *     sha256 HEX index.csv
 *     sha256 HEX index.json
 * A build whose own missions are all up to date compares it with the
 * folders and the files (cli_summary_stale()), so a table left stale by an
 * interrupted build, damaged or removed is rebuilt, without reading every
 * result.json: a row's SHA-256 is the one its mission stamp vouches for
 * (read, not recomputed), and only content goes in, so the same rows give
 * the same stamp on every machine (sharded builds stay byte-identical). */

/* One row of the table as the stamp sees it. */
struct row_id {
	char *name;                 /* the mission folder */
	long long size;             /* of its result.json */
	char sha[SHA256_HEX_LEN];   /* of its result.json */
};

static int
cmp_row_id(const void *a, const void *b)
{
	return strcmp(((const struct row_id *)a)->name, ((const struct row_id *)b)->name);
}

/* The SHA-256 of the regular file name in dir_fd, streamed; -1 when it is
 * absent, not a regular file (a link is not followed) or unreadable. */
static int
file_sha_at(int dir_fd, const char *name, char hex[SHA256_HEX_LEN])
{
	int fd = openat(dir_fd, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
	struct stat st;
	int rc = -1;
	if (fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
		struct sha256_ctx c;
		unsigned char d[SHA256_DIGEST_LEN];
		sha256_init(&c);
		rc = sha256_update_fd(&c, fd, NULL);
		sha256_final(&c, d);
		sha256_to_hex(d, hex);
	}
	if (fd >= 0)
		close(fd);
	return rc;
}

/* result.json's SHA-256 in the mission folder sub: the line "sha256 HEX
 * result.json" of its stamp (pipeline.h), else the file hashed. */
static int
result_sha(int sub, char hex[SHA256_HEX_LEN])
{
	static const char tail[] = " result.json\n";
	unsigned char *buf;
	size_t n;
	char msg[64];
	if (file_read_at(sub, PIPELINE_STAMP, "", STAMP_MAX, &buf, &n, msg, sizeof msg) == 0) {
		const char *line = (const char *)buf;
		int found = 0;
		while (!found && (line = strstr(line, "sha256 ")) != NULL) {
			found = (line == (const char *)buf || line[-1] == '\n')
			    && strspn(line + 7, "0123456789abcdef") == SHA256_HEX_LEN - 1
			    && strncmp(line + 7 + SHA256_HEX_LEN - 1, tail, sizeof tail - 1) == 0;
			if (found)
				memcpy(hex, line + 7, SHA256_HEX_LEN - 1);
			line += 7;
		}
		free(buf);
		if (found) {
			hex[SHA256_HEX_LEN - 1] = '\0';
			return 0;
		}
	}
	return file_sha_at(sub, "result.json", hex);
}

/* The digest of the rows of DIR: each folder scan() would read (a real
 * folder, not hidden, holding a regular result.json), by name.  Returns
 * how many there are. */
static size_t
rows_digest(int dir_fd, char hex[SHA256_HEX_LEN])
{
	struct row_id *v = NULL;
	size_t n = 0, cap = 0;
	DIR *d = file_dir_stream(dir_fd);
	struct dirent *e;
	while (d != NULL && (e = readdir(d)) != NULL) {
		struct stat st;
		int sub = -1;
		if (e->d_name[0] == '.'
		    || fstatat(dir_fd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISDIR(st.st_mode)
		    || (sub = openat(dir_fd, e->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW
		        | O_CLOEXEC)) < 0)
			continue;
		if (fstatat(sub, "result.json", &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode)) {
			if (n == cap) {
				cap = cap ? 2 * cap : 64;
				v = xrealloc(v, cap * sizeof *v);
			}
			v[n].name = xstrdup(e->d_name);
			v[n].size = (long long)st.st_size;
			if (result_sha(sub, v[n].sha) != 0)
				strcpy(v[n].sha, "unreadable");
			n++;
		}
		close(sub);
	}
	if (d != NULL)
		closedir(d);
	if (n > 1)
		qsort(v, n, sizeof *v, cmp_row_id);
	struct sha256_ctx c;
	unsigned char dg[SHA256_DIGEST_LEN];
	sha256_init(&c);
	for (size_t i = 0; i < n; i++) {
		char line[128];
		/* The name with its NUL, so no two row lists hash alike. */
		sha256_update(&c, v[i].name, strlen(v[i].name) + 1);
		snprintf(line, sizeof line, "%lld %s\n", v[i].size, v[i].sha);
		sha256_update(&c, line, strlen(line));
		free(v[i].name);
	}
	free(v);
	sha256_final(&c, dg);
	sha256_to_hex(dg, hex);
	return n;
}

/* The stamp DIR should hold for rows digest rows and the index.csv and
 * index.json found there, into sb; -1 when either is missing or not a
 * regular file (then no stamp can vouch for the table). */
static int
stamp_text(int dir_fd, const char *rows, struct strbuf *sb)
{
	char csv[SHA256_HEX_LEN], json[SHA256_HEX_LEN];
	strbuf_reset(sb);
	if (file_sha_at(dir_fd, "index.csv", csv) != 0 || file_sha_at(dir_fd, "index.json", json) != 0)
		return -1;
	strbuf_printf(sb, "%srows %s\nsha256 %s index.csv\nsha256 %s index.json\n",
	    STAMP_MAGIC, rows, csv, json);
	return 0;
}

/* True when DIR holds index.csv or index.json (even a damaged one). */
static bool
has_table(int dir_fd)
{
	struct stat st;
	return fstatat(dir_fd, "index.csv", &st, AT_SYMLINK_NOFOLLOW) == 0
	    || fstatat(dir_fd, "index.json", &st, AT_SYMLINK_NOFOLLOW) == 0;
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

/* An output folder opened for its table. */
struct table {
	int dir_fd;          /* DIR */
	int lock;            /* the index lock, -1 when not taken */
	struct table_rows s; /* every row read */
	int rc;              /* 2 once a result.json could not be read */
	char rows[SHA256_HEX_LEN]; /* rows_digest() taken before the rows were
	                      * read (a row changed meanwhile makes the stamp
	                      * stale, never wrongly current); "" unlocked */
};

/* index.csv, index.json, then the stamp that vouches for both; no stamp
 * when a row could not be read, so the next build tries again. */
static int
put_tables(struct table *t, const char *dir, FILE *err)
{
	char *csv = index_csv(&t->s);
	char *json = index_json(&t->s, AEROEVAL_VERSION);
	int rc = put(t->dir_fd, dir, "index.csv", csv, strlen(csv), err);
	if (rc == 0)
		rc = put(t->dir_fd, dir, "index.json", json, strlen(json), err);
	free(csv);
	free(json);
	struct strbuf sb = STRBUF_INIT;
	if (rc == 0 && t->rc == 0 && t->rows[0] != '\0' && stamp_text(t->dir_fd, t->rows, &sb) == 0)
		rc = put(t->dir_fd, dir, STAMP_NAME, sb.data, sb.len, err);
	strbuf_free(&sb);
	return rc;
}

/* overview.pdf of the rows with template tpl.  Returns the exit status: 0,
 * 2 (a file-system problem) or 3 (the PDF could not be rendered). */
static int
put_overview(int dir_fd, const char *dir, const struct table_rows *s,
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
		/* A read-only folder: nobody can change its table, so it is read
		 * unlocked; a current table is then no error (put() writes only
		 * what differs), a stale one fails where it is written. */
		locked = errno != EROFS && errno != EACCES && errno != EPERM;
		if (locked) {
			fprintf(err, "%s/index.csv: error: cannot take the index lock %s: %s\n",
			    dir, LOCK_NAME, errno == EWOULDBLOCK ? "another build held it too long"
			    : strerror(errno));
			close(t->dir_fd);
			return 2;
		}
	}
	if (locked) {
		clean_temps(t->dir_fd);
		rows_digest(t->dir_fd, t->rows);
	}
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
	table_row_free(&t->s);
}

int
cli_summary_refresh(const char *dir, const struct template *tpl, FILE *err)
{
	struct table t;
	if (table_open(&t, dir, true, err) != 0)
		return 2;
	int rc = t.rc;
	struct stat st;
	/* The table lists the folders there are: none at all, it is emptied
	 * rather than left listing what was removed. */
	if ((t.s.n > 0 || has_table(t.dir_fd)) && put_tables(&t, dir, err) != 0)
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
	int dir_fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	DIR *d = dir_fd >= 0 ? file_dir_stream(dir_fd) : NULL;
	if (d == NULL) {
		if (dir_fd >= 0)
			close(dir_fd);
		return 0;  /* the refresh would only fail to open it */
	}
	int stale = 0;
	struct dirent *e;
	while (!stale && (e = readdir(d)) != NULL)  /* a killed writer's leftovers */
		stale = temp_owner(e->d_name) > 0 || strcmp(e->d_name, LOCK_NAME) == 0;
	closedir(d);
	if (!stale) {
		/* Stale unless the stamp vouches for these rows and these files;
		 * a folder with neither rows nor a table has nothing to refresh. */
		char rows[SHA256_HEX_LEN];
		size_t n_rows = rows_digest(dir_fd, rows);
		struct strbuf want = STRBUF_INIT;
		unsigned char *have = NULL;
		size_t n_have = 0;
		char msg[64];
		if (stamp_text(dir_fd, rows, &want) != 0)
			stale = n_rows > 0 || has_table(dir_fd);
		else
			stale = file_read_at(dir_fd, STAMP_NAME, "", STAMP_MAX, &have, &n_have, msg,
			    sizeof msg) != 0 || n_have != want.len || memcmp(have, want.data, n_have) != 0;
		free(have);
		strbuf_free(&want);
	}
	close(dir_fd);
	return stale;
}

/* ---- the command ------------------------------------------------------------ */

static void
report_counts(const char *dir, const struct table_rows *s, int pdf)
{
	size_t c[TABLE_ROW_STATUS_MAX];
	table_row_count(s, c);
	fprintf(stderr, "summary: %zu missions (%zu feasible, %zu infeasible, %zu not buildable)"
	    " -> %s: index.csv, index.json%s\n", s->n, c[TABLE_ROW_FEASIBLE],
	    c[TABLE_ROW_INFEASIBLE], c[TABLE_ROW_NOT_BUILDABLE], dir, pdf ? ", overview.pdf" : "");
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
		int wrc = put_tables(&t, dir, stderr) != 0 ? 2 : 0;
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
