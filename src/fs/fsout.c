/* fsout.c — atomic file output, mkdir -p, whole-file reads, deterministic
 * dossier dates and safe output names (see fsout.h). */
#include "fs/fsout.h"
#include "fs/fsout_int.h"

#include <errno.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "formats/index.h"
#include "util/strbuf.h"
#include "util/text.h"
#include "util/xalloc.h"

/* Counts fsout_write_atomic calls for the AEROEVAL_FAIL_WRITE hook.  Like
 * xalloc's countdown this is process-wide on purpose (the hook numbers the
 * writes of a whole run); it is atomic so -j N threads count correctly. */
static atomic_ulong write_count;

/* Makes temporary names unique between threads of one process; O_EXCL
 * makes them safe against everything else. */
static atomic_ulong temp_seq;

void
fsout_fault_reset(void)
{
	atomic_store(&write_count, 0);
}

#ifdef AEROEVAL_TEST_HOOKS   /* (fsout_int.h: no-ops otherwise) */
/* The errno names AEROEVAL_FAIL_WRITE=N:NAME may ask for. */
static const struct {
	const char *name;
	int code;
} fault_errnos[] = {
	{ "ENOSPC", ENOSPC }, { "EIO", EIO }, { "EDQUOT", EDQUOT },
	{ "EROFS", EROFS }, { "EFBIG", EFBIG },
};

int
fsout_fault_take(void)
{
	unsigned long k = atomic_fetch_add(&write_count, 1) + 1;
	const char *e = getenv("AEROEVAL_FAIL_WRITE");
	if (e == NULL || *e == '\0')
		return 0;
	char *end;
	unsigned long want = strtoul(e, &end, 10);
	if (want != k)
		return 0;
	if (*end == '\0')
		return ENOSPC;
	for (size_t i = 0; *end == ':' && i < sizeof fault_errnos / sizeof fault_errnos[0]; i++)
		if (strcmp(end + 1, fault_errnos[i].name) == 0)
			return fault_errnos[i].code;
	return 0;
}

void
fsout_test_delay(void)
{
	const char *e = getenv("AEROEVAL_TEST_WRITE_DELAY_MS");
	long ms = e != NULL ? strtol(e, NULL, 10) : 0;
	if (ms > 0 && ms <= 10000) {
		struct timespec ts = { ms / 1000, (ms % 1000) * 1000000L };
		while (nanosleep(&ts, &ts) != 0 && errno == EINTR)
			;
	}
}
#endif /* AEROEVAL_TEST_HOOKS */

int
fsout_write_all(int fd, const void *data, size_t n)
{
	const unsigned char *p = data;
	while (n > 0) {
		ssize_t k = write(fd, p, n);
		if (k < 0) {
			if (errno == EINTR)
				continue;
			return -1;
		}
		p += k;
		n -= (size_t)k;
	}
	return 0;
}

/* fsync the directory dir so that a rename inside it survives a crash. */
static int
sync_dir(const char *dir)
{
	int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (fd < 0)
		return -1;
	int rc = fsync(fd);
	int saved = errno;
	close(fd);
	errno = saved;
	/* Some filesystems cannot sync a directory; that is not a failure of
	 * ours and the rename has happened anyway. */
	if (rc < 0 && (errno == EINVAL || errno == ENOTSUP))
		rc = 0;
	return rc;
}

int
fsout_write_atomic(const char *path, const void *data, size_t n,
                   char *err, size_t errlen)
{
	struct strbuf dir = STRBUF_INIT, tmp = STRBUF_INIT;
	int fd = -1, rc = -1, inject = fsout_fault_take();
	const char *slash = strrchr(path, '/');
	const char *base = slash ? slash + 1 : path;

	if (*base == '\0') {
		text_errf(err, errlen, "%s: not a file name", path);
		goto done;
	}
	/* Only a regular file is replaced: rename(2) would put the output in
	 * place of a link (not where it points), a device such as /dev/null
	 * (as root) or a FIFO, and fail late on a folder. */
	struct stat st;
	if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
		text_errf(err, errlen, "%s: %s", path, S_ISLNK(st.st_mode)
		    ? "is a symbolic link, which aeroeval never follows or replaces"
		    : S_ISDIR(st.st_mode) ? "is a folder, not a file"
		    : "is not a regular file; aeroeval replaces only its own files");
		goto done;
	}
	if (slash == NULL)
		strbuf_append_str(&dir, ".");
	else if (slash == path)
		strbuf_append_str(&dir, "/");
	else
		strbuf_append(&dir, path, (size_t)(slash - path));

	/* O_EXCL refuses a name that exists (a stale temp, another writer);
	 * then the next sequence number is tried. */
	for (int tries = 0; fd < 0 && tries < 100; tries++) {
		strbuf_reset(&tmp);
		strbuf_printf(&tmp, "%s/.%s.tmp.%ld.%lu", strbuf_str(&dir), base,
		              (long)getpid(), atomic_fetch_add(&temp_seq, 1));
		fd = open(strbuf_str(&tmp), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
		if (fd < 0 && errno != EEXIST)
			break;
	}
	if (fd < 0) {
		text_errf(err, errlen, "%s: cannot create temporary file: %s", path, strerror(errno));
		strbuf_reset(&tmp); /* nothing to remove */
		goto done;
	}
	/* The umask may have narrowed 0644; outputs get the same mode always. */
	if (fchmod(fd, 0644) < 0) {
		text_errf(err, errlen, "%s: cannot set mode: %s", strbuf_str(&tmp), strerror(errno));
		goto fail;
	}
	if (inject) {
		(void)fsout_write_all(fd, data, n / 2);
		errno = inject;
		text_errf(err, errlen, "%s: write failed: %s (AEROEVAL_FAIL_WRITE)",
		        strbuf_str(&tmp), strerror(errno));
		goto fail;
	}
	if (fsout_write_all(fd, data, n) < 0) {
		text_errf(err, errlen, "%s: write failed: %s", strbuf_str(&tmp), strerror(errno));
		goto fail;
	}
	if (fsync(fd) < 0) {
		text_errf(err, errlen, "%s: fsync failed: %s", strbuf_str(&tmp), strerror(errno));
		goto fail;
	}
	if (close(fd) < 0) {
		fd = -1;
		text_errf(err, errlen, "%s: close failed: %s", strbuf_str(&tmp), strerror(errno));
		goto fail;
	}
	fd = -1;
	if (rename(strbuf_str(&tmp), path) < 0) {
		text_errf(err, errlen, "%s: rename failed: %s", path, strerror(errno));
		goto fail;
	}
	/* From here the new content is in place; only durability is left. */
	strbuf_reset(&tmp);
	if (sync_dir(strbuf_str(&dir)) < 0) {
		text_errf(err, errlen, "%s: fsync of directory failed: %s",
		        strbuf_str(&dir), strerror(errno));
		goto done;
	}
	rc = 0;
	goto done;
fail:
	if (fd >= 0)
		close(fd);
	unlink(strbuf_str(&tmp));
done:
	strbuf_free(&dir);
	strbuf_free(&tmp);
	return rc;
}

/* mkdir that counts an existing directory as success. */
static int
mkdir_one(const char *p, char *err, size_t errlen)
{
	struct stat st;
	if (mkdir(p, 0755) == 0)
		return 0;
	int saved = errno;
	if (saved == EEXIST && stat(p, &st) == 0) {
		if (S_ISDIR(st.st_mode))
			return 0;
		text_errf(err, errlen, "%s: exists and is not a directory", p);
		return -1;
	}
	text_errf(err, errlen, "%s: cannot create directory: %s", p, strerror(saved));
	return -1;
}

int
fsout_mkdirs(const char *dir, char *err, size_t errlen)
{
	if (*dir == '\0') {
		text_errf(err, errlen, "empty directory name");
		return -1;
	}
	char *p = xstrdup(dir);
	int rc = 0;
	/* Create each prefix ending before a '/', then the whole path.  The
	 * leading '/' of an absolute path and doubled slashes are skipped. */
	for (char *s = p + 1; *s != '\0' && rc == 0; s++) {
		if (*s != '/' || s[-1] == '/')
			continue;
		*s = '\0';
		rc = mkdir_one(p, err, errlen);
		*s = '/';
	}
	if (rc == 0)
		rc = mkdir_one(p, err, errlen);
	free(p);
	return rc;
}


static int
is_leap(int y)
{
	return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

/* Parses a YYYY-MM-DD calendar date; 0 when it is one, -1 otherwise. */
static int
check_ymd(const char *s)
{
	static const int mdays[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
	if (strlen(s) != 10 || s[4] != '-' || s[7] != '-')
		return -1;
	for (int i = 0; i < 10; i++)
		if (i != 4 && i != 7 && (s[i] < '0' || s[i] > '9'))
			return -1;
	int y = (s[0] - '0') * 1000 + (s[1] - '0') * 100 + (s[2] - '0') * 10 + (s[3] - '0');
	int m = (s[5] - '0') * 10 + (s[6] - '0');
	int d = (s[8] - '0') * 10 + (s[9] - '0');
	if (y < 1 || m < 1 || m > 12 || d < 1)
		return -1;
	int dmax = mdays[m - 1] + (m == 2 && is_leap(y));
	return d <= dmax ? 0 : -1;
}

/* Formats t (seconds since the epoch) as a UTC date; -1 outside years
 * 0..9999, which YYYY cannot spell. */
static int
format_utc(long long t, char out[11])
{
	struct tm tm;
	time_t tt = (time_t)t;
	if ((long long)tt != t || gmtime_r(&tt, &tm) == NULL)
		return -1;
	int y = tm.tm_year + 1900;
	if (y < 0 || y > 9999)
		return -1;
	/* By hand: snprintf's truncation warning cannot see the ranges. */
	int m = tm.tm_mon + 1, d = tm.tm_mday;
	out[0] = (char)('0' + y / 1000);
	out[1] = (char)('0' + y / 100 % 10);
	out[2] = (char)('0' + y / 10 % 10);
	out[3] = (char)('0' + y % 10);
	out[4] = '-';
	out[5] = (char)('0' + m / 10);
	out[6] = (char)('0' + m % 10);
	out[7] = '-';
	out[8] = (char)('0' + d / 10);
	out[9] = (char)('0' + d % 10);
	out[10] = '\0';
	return 0;
}

int
fsout_resolve_date(const char *report_date, char out[11], char *err, size_t errlen)
{
	/* 9999-12-31T23:59:59Z, the last second YYYY can spell. */
	const long long epoch_max = 253402300799LL;
	out[0] = '\0';

	if (report_date != NULL && *report_date != '\0') {
		if (check_ymd(report_date) < 0) {
			text_errf(err, errlen, "report.date: \"%s\" is not a date YYYY-MM-DD", report_date);
			return -1;
		}
		memcpy(out, report_date, 11);
		return FSOUT_DATE_REPORT;
	}

	const char *e = getenv("SOURCE_DATE_EPOCH");
	if (e != NULL && *e != '\0') {
		/* The reproducible-builds spec: an integer of decimal digits.
		 * Signs, spaces, fractions and overflow are refused. */
		long long t = 0;
		const char *s;
		for (s = e; *s >= '0' && *s <= '9' && t <= epoch_max; s++)
			t = t * 10 + (*s - '0');
		if (*s != '\0' || t > epoch_max || format_utc(t, out) < 0) {
			out[0] = '\0';
			text_errf(err, errlen, "SOURCE_DATE_EPOCH: \"%s\" is not a number of seconds "
			        "since 1970 (digits only, at most %lld)", e, epoch_max);
			return -1;
		}
		return FSOUT_DATE_EPOCH_ENV;
	}

	/* No date given: the dossier is undated.  Never a file time or the
	 * clock, so the same inputs give the same bytes whenever and wherever
	 * the file was copied or touched. */
	return FSOUT_DATE_NONE;
}

int
fsout_safe_name(const char *mission_path, char *out, size_t n)
{
	if (n > 0)
		out[0] = '\0';
	const char *slash = strrchr(mission_path, '/');
	const char *base = slash ? slash + 1 : mission_path;
	size_t len = strlen(base);
	if (len >= 5 && strcmp(base + len - 5, ".json") == 0)
		len -= 5;
	if (len == 0)
		return -1;
	if (len > FSOUT_NAME_MAX || len >= n)
		return -2;
	/* A hidden name is the program's (temporaries ".NAME.tmp.PID.SEQ",
	 * locks, stamps) and a summary never lists it: refused, "." and ".."
	 * with it. */
	if (base[0] == '.')
		return -1;
	for (size_t i = 0; i < len; i++) {
		char c = base[i];
		int ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
		         (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
		if (!ok)
			return -1;
	}
	for (size_t i = 0; index_file_names[i] != NULL; i++)
		if (strlen(index_file_names[i]) == len && memcmp(index_file_names[i], base, len) == 0)
			return -3;
	memcpy(out, base, len);
	out[len] = '\0';
	return 0;
}
