/* fsfolder.c — a mission's output folder, replaced as a whole (see fsfolder.h).
 *
 * _GNU_SOURCE: renameat2() and RENAME_EXCHANGE are Linux extensions; where
 * they are missing the two-rename fallback below is compiled alone.
 */
#define _GNU_SOURCE
#include "fs/fsfolder.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "fs/fsout_int.h"
#include "util/file.h"

#define LOCK_POLL_MS 20  /* how often a waiting writer tries the lock again */
#define MAX_TEMP_TRIES 100 /* temporary names tried before giving up */

/* Where a message's path points: the folder DIR/NAME, a file in it, or
 * an entry of DIR beside it (the lock file). */
enum where { AT_FOLDER, IN_FOLDER, IN_DIR };

__attribute__((format(printf, 6, 7)))
static void
fail(const struct fsfolder *f, enum where w, const char *file, char *err,
     size_t errlen, const char *fmt, ...)
{
	if (err == NULL || errlen == 0)
		return;
	size_t dl = strlen(f->dir);
	const char *sep = dl > 0 && f->dir[dl - 1] == '/' ? "" : "/";
	int k;
	if (w == AT_FOLDER)
		k = snprintf(err, errlen, "%s%s%s: error: ", f->dir, sep, f->name);
	else if (w == IN_DIR)
		k = snprintf(err, errlen, "%s%s%s: error: ", f->dir, sep, file);
	else
		k = snprintf(err, errlen, "%s%s%s/%s: error: ", f->dir, sep, f->name, file);
	if (k < 0 || (size_t)k >= errlen)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(err + k, errlen - (size_t)k, fmt, ap);
	va_end(ap);
}

/* A name's trouble in words; ELOOP from O_NOFOLLOW means a symbolic link. */
static const char *
why(int e)
{
	return e == ELOOP ? "is a symbolic link, which aeroeval never follows here"
	    : strerror(e);
}

static double
now_s(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void
lock_name(const struct fsfolder *f, char *out, size_t n)
{
	snprintf(out, n, ".%s.lock", f->name);
}

/* Takes DIR/.NAME.lock.  The holder removes the file before it unlocks,
 * so a waiter that gets the lock checks that its file is still the one at
 * that name, and else starts again with the new one. */
static int
lock_take(struct fsfolder *f, int flags, double wait_s, char *err, size_t errlen)
{
	char lk[FSOUT_NAME_MAX + 16];
	lock_name(f, lk, sizeof lk);
	double t_end = now_s() + wait_s;
	for (;;) {
		int fd = openat(f->dir_fd, lk, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC
		    | O_NONBLOCK, 0644);
		if (fd < 0 && (flags & FSFOLDER_NOWAIT)
		    && (errno == EROFS || errno == EACCES || errno == EPERM))
			return 0;  /* read-only DIR: nobody can swap a set in, and
			            * sets are only ever swapped whole anyway */
		if (fd < 0 && errno == ELOOP) {
			fail(f, IN_DIR, lk, err, errlen, "%s", why(errno));
			return -1;
		}
		if (fd < 0) {  /* read-only, no space...: about the folder, really */
			fail(f, AT_FOLDER, NULL, err, errlen, "cannot write: %s", strerror(errno));
			return -1;
		}
		struct stat a, b;
		if (fstat(fd, &a) != 0 || !S_ISREG(a.st_mode)) {
			fail(f, IN_DIR, lk, err, errlen, "not a regular file");
			close(fd);
			return -1;
		}
		while (flock(fd, LOCK_EX | LOCK_NB) != 0) {
			int e = errno;
			if (e == EINTR)
				continue;
			if (e == EWOULDBLOCK && (flags & FSFOLDER_NOWAIT)) {
				close(fd);
				return FSFOLDER_BUSY;
			}
			if (e != EWOULDBLOCK || now_s() >= t_end) {
				if (e == EWOULDBLOCK)
					fail(f, AT_FOLDER, NULL, err, errlen, "another build has been writing it "
					    "for %.0f s (it holds %s)", wait_s, lk);
				else
					fail(f, IN_DIR, lk, err, errlen, "cannot lock: %s", strerror(e));
				close(fd);
				return -1;
			}
			struct timespec ts = { 0, LOCK_POLL_MS * 1000000L };
			nanosleep(&ts, NULL);
		}
		if (fstatat(f->dir_fd, lk, &b, AT_SYMLINK_NOFOLLOW) == 0
		    && a.st_dev == b.st_dev && a.st_ino == b.st_ino) {
			f->lock_fd = fd;
			return 0;
		}
		close(fd);  /* the holder we waited for removed it: start again */
	}
}

/* Old aeroeval wrote each file through ".FILE.tmp.PID.SEQ" in the folder. */
static int
is_old_temp(const char *s)
{
	const char *t = strstr(s, ".tmp.");
	if (s[0] != '.' || t == NULL)
		return 0;
	t += 5;
	size_t d1 = strspn(t, "0123456789");
	if (d1 == 0 || t[d1] != '.')
		return 0;
	t += d1 + 1;
	size_t d2 = strspn(t, "0123456789");
	return d2 > 0 && t[d2] == '\0';
}

/* s matches the file list entry pat: the same name, or, for "*SUFFIX", a
 * name ending in SUFFIX, not hidden, of the bytes fsout_safe_name() allows. */
static int
matches(const char *pat, const char *s)
{
	if (pat[0] != '*')
		return strcmp(pat, s) == 0;
	size_t n = strlen(s), k = strlen(pat + 1);
	return s[0] != '.' && n > k && strcmp(s + n - k, pat + 1) == 0
	    && strspn(s, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789._-") == n;
}

static int
is_listed(const struct fsfolder *f, const char *s)
{
	for (size_t i = 0; f->files[i] != NULL; i++)
		if (matches(f->files[i], s))
			return 1;
	return 0;
}

/* The kinds of folder a writer of NAME leaves beside DIR/NAME. */
enum temp_kind {
	TEMP_NEW,  /* ".NAME.tmp.PID.SEQ": a new set being written */
	TEMP_OLD   /* ".NAME.old.PID.SEQ": the old set set aside by the two-rename
	            * swap, the only copy of it until the new set is in */
};

static const char *const temp_tag[] = { "tmp", "old" };

/* The pid of ".NAME.<tag>.PID.SEQ" for the kind's tag, or 0 when s is not
 * such a name. */
static long
temp_owner(const struct fsfolder *f, const char *s, enum temp_kind kind)
{
	size_t nl = strlen(f->name);
	if (s[0] != '.' || strncmp(s + 1, f->name, nl) != 0 || s[1 + nl] != '.'
	    || strncmp(s + 2 + nl, temp_tag[kind], 3) != 0 || s[5 + nl] != '.')
		return 0;
	const char *p = s + 6 + nl;
	size_t d1 = strspn(p, "0123456789");
	if (d1 == 0 || d1 > 9 || p[d1] != '.')
		return 0;
	size_t d2 = strspn(p + d1 + 1, "0123456789");
	if (d2 == 0 || p[d1 + 1 + d2] != '\0')
		return 0;
	return strtol(p, NULL, 10);
}

/* Opens DIR/NAME when it exists and checks that it holds only our files. */
static int
inspect(struct fsfolder *f, char *err, size_t errlen)
{
	struct stat st;
	if (fstatat(f->dir_fd, f->name, &st, AT_SYMLINK_NOFOLLOW) != 0) {
		if (errno == ENOENT)
			return 0;
		fail(f, AT_FOLDER, NULL, err, errlen, "%s", strerror(errno));
		return -1;
	}
	if (S_ISLNK(st.st_mode)) {
		fail(f, AT_FOLDER, NULL, err, errlen, "%s", why(ELOOP));
		return -1;
	}
	if (!S_ISDIR(st.st_mode)) {
		fail(f, AT_FOLDER, NULL, err, errlen, "exists and is not a directory");
		return -1;
	}
	f->cur_fd = openat(f->dir_fd, f->name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
	DIR *d = f->cur_fd >= 0 ? file_dir_stream(f->cur_fd) : NULL;
	if (d == NULL) {
		fail(f, AT_FOLDER, NULL, err, errlen, "cannot read the folder: %s", why(errno));
		return -1;
	}
	int rc = 0;
	struct dirent *e;
	while (rc == 0 && (e = readdir(d)) != NULL) {
		const char *s = e->d_name;
		if (strcmp(s, ".") == 0 || strcmp(s, "..") == 0)
			continue;
		if (fstatat(f->cur_fd, s, &st, AT_SYMLINK_NOFOLLOW) != 0) {
			fail(f, IN_FOLDER, s, err, errlen, "%s", strerror(errno));
			rc = -1;
		} else if (S_ISLNK(st.st_mode)) {
			fail(f, IN_FOLDER, s, err, errlen, "%s", why(ELOOP));
			rc = -1;
		} else if (!S_ISREG(st.st_mode)) {
			fail(f, IN_FOLDER, s, err, errlen, "not a regular file");
			rc = -1;
		} else if (!is_listed(f, s) && !is_old_temp(s)) {
			fail(f, IN_FOLDER, s, err, errlen, "not an output of aeroeval; the folder is "
			    "replaced as a whole, so move the file away first");
			rc = -1;
		}
	}
	closedir(d);
	return rc;
}

/* Puts back an old set that a writer killed between the two renames of
 * swap_in() left set aside, where DIR/NAME is missing: with the lock held
 * no live writer is swapping, so the aside is the only copy of the last
 * whole set (the newest, should there be several).  The new set of that
 * writer, whole or not, stays a temporary that fsfolder_clean() removes. */
static void
recover(struct fsfolder *f)
{
	struct stat st;
	if (f->lock_fd < 0 || fstatat(f->dir_fd, f->name, &st, AT_SYMLINK_NOFOLLOW) == 0
	    || errno != ENOENT)
		return;
	DIR *d = file_dir_stream(f->dir_fd);
	if (d == NULL)
		return;
	char best[sizeof f->tmp] = "";
	struct timespec t_best = { 0, 0 };
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		if (temp_owner(f, e->d_name, TEMP_OLD) <= 0
		    || fstatat(f->dir_fd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0
		    || !S_ISDIR(st.st_mode) || strlen(e->d_name) >= sizeof best)
			continue;
		/* The rename that set it aside changed its ctime. */
		if (best[0] == '\0' || st.st_ctim.tv_sec > t_best.tv_sec
		    || (st.st_ctim.tv_sec == t_best.tv_sec && st.st_ctim.tv_nsec > t_best.tv_nsec)) {
			strcpy(best, e->d_name);
			t_best = st.st_ctim;
		}
	}
	closedir(d);
	if (best[0] != '\0')
		renameat(f->dir_fd, best, f->dir_fd, f->name);
}

int
fsfolder_open(struct fsfolder *f, const char *dir, const char *name,
              const char *const *files, int flags, double wait_s,
              char *err, size_t errlen)
{
	memset(f, 0, sizeof *f);
	f->dir_fd = f->lock_fd = f->cur_fd = f->tmp_fd = -1;
	f->files = files;
	snprintf(f->dir, sizeof f->dir, "%s", dir);
	snprintf(f->name, sizeof f->name, "%s", name);
	if (name[0] == '\0' || strchr(name, '/') != NULL || strcmp(name, ".") == 0
	    || strcmp(name, "..") == 0 || strlen(name) > FSOUT_NAME_MAX) {
		fail(f, AT_FOLDER, NULL, err, errlen, "not a usable folder name");
		return -1;
	}
	f->dir_fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (f->dir_fd < 0) {
		snprintf(err, errlen, "%s: error: cannot open the output folder: %s",
		    dir, strerror(errno));
		return -1;
	}
	int rc = lock_take(f, flags, wait_s, err, errlen);
	if (rc != 0)
		return rc;
	recover(f);
	return inspect(f, err, errlen);
}

int
fsfolder_exists(const struct fsfolder *f)
{
	return f->cur_fd >= 0;
}

/* Opens DIR/NAME/file for reading: a regular file only, never a link, and
 * a FIFO is not waited on. */
static int
open_current(const struct fsfolder *f, const char *file)
{
	if (f->cur_fd < 0)
		return -1;
	int fd = openat(f->cur_fd, file, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
	struct stat st;
	if (fd >= 0 && (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))) {
		close(fd);
		fd = -1;
	}
	return fd;
}

int
fsfolder_hash(const struct fsfolder *f, const char *file, char hex[SHA256_HEX_LEN])
{
	int fd = open_current(f, file);
	if (fd < 0)
		return -1;
	struct sha256_ctx c;
	unsigned char d[SHA256_DIGEST_LEN];
	sha256_init(&c);
	int rc = sha256_update_fd(&c, fd, NULL);
	close(fd);
	if (rc != 0)
		return -1;
	sha256_final(&c, d);
	sha256_to_hex(d, hex);
	return 0;
}

int
fsfolder_read(const struct fsfolder *f, const char *file, char *buf, size_t cap,
              size_t *n)
{
	*n = 0;
	int fd = cap > 0 ? open_current(f, file) : -1;
	if (fd < 0)
		return -1;
	size_t len = 0;
	for (;;) {
		ssize_t k = read(fd, buf + len, cap - len);
		if (k < 0 && errno == EINTR)
			continue;
		if (k <= 0 || (len += (size_t)k) == cap)
			break;
	}
	close(fd);
	if (len == cap)
		return -1;  /* too long to be what the caller wants */
	buf[len] = '\0';
	*n = len;
	return 0;
}

/* Removes the folder name in parent_fd and the files in it, never
 * following a link; a folder inside it (not ours) makes it stay. */
static int
remove_tree(int parent_fd, const char *name)
{
	int fd = openat(parent_fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
	DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
	if (d == NULL) {
		if (fd >= 0)
			close(fd);
		return -1;
	}
	struct dirent *e;
	struct stat st;
	while ((e = readdir(d)) != NULL)
		if (fstatat(fd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && !S_ISDIR(st.st_mode))
			unlinkat(fd, e->d_name, 0);
	closedir(d);
	return unlinkat(parent_fd, name, AT_REMOVEDIR);
}

/* True when process pid has ended: no such process, or a zombie (dead but
 * not reaped, as orphans stay where pid 1 does not reap them; a zombie
 * writes nothing more).  /proc is read only on Linux, where it exists. */
static int
owner_gone(long pid)
{
	if (kill((pid_t)pid, 0) != 0 && errno == ESRCH)
		return 1;
	char p[64], buf[256];
	snprintf(p, sizeof p, "/proc/%ld/stat", pid);
	int fd = open(p, O_RDONLY | O_CLOEXEC);
	if (fd < 0)
		return 0;
	ssize_t n = read(fd, buf, sizeof buf - 1);
	close(fd);
	if (n <= 0)
		return 0;
	buf[n] = '\0';
	/* "PID (COMMAND) STATE ...": the command may hold ')', so the last. */
	const char *rp = strrchr(buf, ')');
	return rp != NULL && rp[1] == ' ' && (rp[2] == 'Z' || rp[2] == 'X');
}

int
fsfolder_clean(struct fsfolder *f, double max_age_s)
{
	if (f->lock_fd < 0)
		return 0;
	DIR *d = file_dir_stream(f->dir_fd);
	if (d == NULL)
		return 0;
	int n = 0;
	time_t now = time(NULL);
	struct stat st;
	/* A set-aside old set goes only while DIR/NAME holds a set:
	 * fsfolder_open() has put it back where DIR/NAME was missing. */
	int have_set = fstatat(f->dir_fd, f->name, &st, AT_SYMLINK_NOFOLLOW) == 0;
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		long pid = temp_owner(f, e->d_name, TEMP_NEW);
		if (pid == 0 && have_set)
			pid = temp_owner(f, e->d_name, TEMP_OLD);
		if (pid <= 0 || pid == (long)getpid() || strcmp(e->d_name, f->tmp) == 0
		    || fstatat(f->dir_fd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0
		    || !S_ISDIR(st.st_mode))
			continue;
		if ((owner_gone(pid) || difftime(now, st.st_mtime) > max_age_s)
		    && remove_tree(f->dir_fd, e->d_name) == 0)
			n++;
	}
	closedir(d);
	return n;
}

/* A free ".NAME.tmp.PID.SEQ" made by mkdir (begin), or a free
 * ".NAME.old.PID.SEQ" only named (the aside of the two-rename swap). */
static int
new_temp(struct fsfolder *f, char *out, size_t n, int make)
{
	struct stat st;
	for (unsigned seq = 0; seq < MAX_TEMP_TRIES; seq++) {
		snprintf(out, n, ".%s.%s.%ld.%u", f->name, temp_tag[make ? TEMP_NEW : TEMP_OLD],
		    (long)getpid(), seq);
		if (make ? mkdirat(f->dir_fd, out, 0755) == 0
		    : fstatat(f->dir_fd, out, &st, AT_SYMLINK_NOFOLLOW) != 0 && errno == ENOENT)
			return 0;
		if (make && errno != EEXIST)
			return -1;
	}
	errno = EEXIST;
	return -1;
}

int
fsfolder_begin(struct fsfolder *f, char *err, size_t errlen)
{
	if (f->lock_fd < 0 || f->tmp[0] != '\0') {
		fail(f, AT_FOLDER, NULL, err, errlen, "not locked for writing");
		return -1;
	}
	if (new_temp(f, f->tmp, sizeof f->tmp, 1) != 0) {
		f->tmp[0] = '\0';
		fail(f, AT_FOLDER, NULL, err, errlen, "cannot write: %s", strerror(errno));
		return -1;
	}
	f->tmp_fd = openat(f->dir_fd, f->tmp, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
	if (f->tmp_fd < 0) {
		fail(f, AT_FOLDER, NULL, err, errlen, "cannot write: %s", why(errno));
		return -1;
	}
	return 0;
}

int
fsfolder_put(struct fsfolder *f, const char *file, const void *data, size_t n,
             int sync, char *err, size_t errlen)
{
	if (f->tmp_fd < 0) {
		fail(f, IN_FOLDER, file, err, errlen, "no new set begun");
		return -1;
	}
	fsout_test_delay();
	int inject = fsout_fault_take();
	int fd = openat(f->tmp_fd, file, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
	int rc = fd >= 0 ? 0 : -1;
	/* The umask may have narrowed 0644; outputs get the same mode always. */
	if (rc == 0)
		rc = fchmod(fd, 0644);
	if (rc == 0 && inject) {
		(void)fsout_write_all(fd, data, n / 2);
		errno = inject;
		rc = -1;
	}
	if (rc == 0)
		rc = fsout_write_all(fd, data, n);
	if (rc == 0 && sync)
		rc = fsync(fd);
	int e = errno;
	if (fd >= 0 && close(fd) != 0 && rc == 0) {
		rc = -1;
		e = errno;
	}
	if (rc != 0)
		fail(f, IN_FOLDER, file, err, errlen, "cannot write: %s%s", why(e),
		    inject ? " (AEROEVAL_FAIL_WRITE)" : "");
	return rc;
}

int
fsfolder_carry(struct fsfolder *f, const char *file, char *err, size_t errlen)
{
	if (f->tmp_fd < 0) {
		fail(f, IN_FOLDER, file, err, errlen, "no new set begun");
		return -1;
	}
	int in = open_current(f, file);
	if (in < 0)
		return 0;  /* not in the current set: nothing to keep */
	int inject = fsout_fault_take();
	int fd = openat(f->tmp_fd, file, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
	int rc = fd >= 0 ? fchmod(fd, 0644) : -1;
	if (rc == 0 && inject) {
		errno = inject;
		rc = -1;
	}
	char buf[1 << 16];
	while (rc == 0) {
		ssize_t k = read(in, buf, sizeof buf);
		if (k < 0 && errno == EINTR)
			continue;
		if (k <= 0) {
			rc = k < 0 ? -1 : 0;
			break;
		}
		rc = fsout_write_all(fd, buf, (size_t)k);
	}
	if (rc == 0)
		rc = fsync(fd);
	int e = errno;
	if (fd >= 0 && close(fd) != 0 && rc == 0) {
		rc = -1;
		e = errno;
	}
	close(in);
	if (rc != 0)
		fail(f, IN_FOLDER, file, err, errlen, "cannot write: %s%s", why(e),
		    inject ? " (AEROEVAL_FAIL_WRITE)" : "");
	return rc;
}

/* Ignores what a file system cannot do for a directory fsync. */
static int
sync_dir(int fd)
{
	if (fsync(fd) == 0 || errno == EINVAL || errno == ENOTSUP)
		return 0;
	return -1;
}

/* The new set replaces an existing DIR/NAME: exchanged in one step where
 * the file system can, else by two renames.  The old set ends up in a
 * temporary folder, removed afterwards. */
static int
swap_in(struct fsfolder *f, char *err, size_t errlen)
{
#ifdef RENAME_EXCHANGE
#ifdef AEROEVAL_TEST_HOOKS
	/* AEROEVAL_TEST_NO_EXCHANGE: tests take the fallback on any disk. */
	if (getenv("AEROEVAL_TEST_NO_EXCHANGE") != NULL)
		errno = ENOSYS;
	else
#endif
	if (renameat2(f->dir_fd, f->tmp, f->dir_fd, f->name, RENAME_EXCHANGE) == 0) {
		remove_tree(f->dir_fd, f->tmp);  /* a leftover goes at the next clean */
		return 0;
	}
	if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) {
		fail(f, AT_FOLDER, NULL, err, errlen, "cannot replace: %s", strerror(errno));
		return -1;
	}
#endif
	/* Old set aside, new set in.  Between the two renames DIR/NAME is
	 * missing and the aside holds the only copy of the old set, so the
	 * signals that stop a build (^C, the SIGTERM batch.c sends its
	 * workers, a hang-up) wait until the new set is in and the old one
	 * gone.  SIGKILL cannot wait: the next writer puts the aside back
	 * (recover()). */
	sigset_t stop, old_mask;
	sigemptyset(&stop);
	sigaddset(&stop, SIGINT);
	sigaddset(&stop, SIGTERM);
	sigaddset(&stop, SIGHUP);
	sigaddset(&stop, SIGQUIT);
	sigprocmask(SIG_BLOCK, &stop, &old_mask);
	char aside[sizeof f->tmp];
	int rc = -1, e = 0;
	if (new_temp(f, aside, sizeof aside, 0) != 0
	    || renameat(f->dir_fd, f->name, f->dir_fd, aside) != 0) {
		e = errno;
	} else {
		fsout_test_delay();
		if (renameat(f->dir_fd, f->tmp, f->dir_fd, f->name) != 0) {
			e = errno;
			renameat(f->dir_fd, aside, f->dir_fd, f->name);
		} else {
			remove_tree(f->dir_fd, aside);
			rc = 0;
		}
	}
	sigprocmask(SIG_SETMASK, &old_mask, NULL);
	if (rc != 0)
		fail(f, AT_FOLDER, NULL, err, errlen, "cannot replace: %s", strerror(e));
	return rc;
}

int
fsfolder_commit(struct fsfolder *f, char *err, size_t errlen)
{
	if (f->tmp_fd < 0) {
		fail(f, AT_FOLDER, NULL, err, errlen, "no new set begun");
		return -1;
	}
	/* The files are synced; the folder's entries must be too before the
	 * swap makes them the current set. */
	if (sync_dir(f->tmp_fd) != 0) {
		fail(f, AT_FOLDER, NULL, err, errlen, "cannot write: %s", strerror(errno));
		return -1;
	}
	fsout_test_delay();
	if (f->cur_fd >= 0) {
		if (swap_in(f, err, errlen) != 0)
			return -1;
	} else if (renameat(f->dir_fd, f->tmp, f->dir_fd, f->name) != 0) {
		fail(f, AT_FOLDER, NULL, err, errlen, "cannot write: %s", strerror(errno));
		return -1;
	}
	close(f->tmp_fd);
	f->tmp_fd = -1;
	f->tmp[0] = '\0';
	if (sync_dir(f->dir_fd) != 0) {
		fail(f, AT_FOLDER, NULL, err, errlen, "cannot sync the output folder: %s", strerror(errno));
		return -1;
	}
	return 0;
}

void
fsfolder_close(struct fsfolder *f)
{
	if (f->tmp_fd >= 0)
		close(f->tmp_fd);
	if (f->tmp[0] != '\0' && f->dir_fd >= 0)
		remove_tree(f->dir_fd, f->tmp);
	if (f->cur_fd >= 0)
		close(f->cur_fd);
	if (f->lock_fd >= 0) {
		char lk[FSOUT_NAME_MAX + 16];
		lock_name(f, lk, sizeof lk);
		unlinkat(f->dir_fd, lk, 0);  /* before unlocking: see lock_take() */
		close(f->lock_fd);
	}
	if (f->dir_fd >= 0)
		close(f->dir_fd);
	f->dir_fd = f->lock_fd = f->cur_fd = f->tmp_fd = -1;
	f->tmp[0] = '\0';
}
