/* file.c — reading a whole input file, safely (see file.h). */
#include "util/file.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "util/text.h"
#include "util/xalloc.h"

/* Reads the open file fd (named path in messages) whole, as file_read()
 * describes, and closes it. */
static int
read_fd(int fd, const char *path, size_t max_n, unsigned char **out,
        size_t *n, char *err, size_t errlen)
{
	struct stat st;
	if (fstat(fd, &st) < 0 || !S_ISREG(st.st_mode)) {
		text_errf(err, errlen, "%s: not a regular file", path);
		close(fd);
		return -1;
	}
	if ((unsigned long long)st.st_size > max_n) {
		text_errf(err, errlen, "%s: file too large (%lld bytes, limit %zu)",
		        path, (long long)st.st_size, max_n);
		close(fd);
		return -1;
	}
	/* The size is a hint only: a file that grows while we read is read
	 * to its end, up to the cap. */
	size_t cap = (size_t)st.st_size + 1, len = 0;
	unsigned char *buf = xmalloc(cap);
	for (;;) {
		if (len + 1 >= cap) {
			cap *= 2;
			buf = xrealloc(buf, cap);
		}
		ssize_t k = read(fd, buf + len, cap - 1 - len);
		if (k < 0 && errno == EINTR)
			continue;
		if (k < 0) {
			text_errf(err, errlen, "%s: read failed: %s", path, strerror(errno));
			goto fail;
		}
		if (k == 0)
			break;
		len += (size_t)k;
		if (len > max_n) {
			text_errf(err, errlen, "%s: file too large (limit %zu bytes)", path, max_n);
			goto fail;
		}
	}
	close(fd);
	buf[len] = '\0';
	*out = buf;
	*n = len;
	return 0;
fail:
	close(fd);
	free(buf);
	return -1;
}

DIR *
file_dir_stream(int dir_fd)
{
	int fd = fcntl(dir_fd, F_DUPFD_CLOEXEC, 0);
	DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
	if (d == NULL) {
		int e = errno;
		if (fd >= 0)
			close(fd);
		errno = e;
		return NULL;
	}
	rewinddir(d);  /* the duplicate shares dir_fd's position */
	return d;
}

int
file_read(const char *path, size_t max_n, unsigned char **out,
                size_t *n, char *err, size_t errlen)
{
	*out = NULL;
	*n = 0;
	/* O_NONBLOCK: opening a FIFO must not wait for a writer (it is then
	 * refused as not a regular file); reads of a regular file are
	 * unaffected. */
	int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
	if (fd < 0) {
		text_errf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
		return -1;
	}
	return read_fd(fd, path, max_n, out, n, err, errlen);
}

int
file_read_at(int dir_fd, const char *name, const char *path, size_t max_n,
             unsigned char **out, size_t *n, char *err, size_t errlen)
{
	*out = NULL;
	*n = 0;
	int fd = openat(dir_fd, name, O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOFOLLOW);
	if (fd < 0) {
		text_errf(err, errlen, "%s: cannot open: %s", path, errno == ELOOP
		    ? "a symbolic link, which aeroeval does not follow here" : strerror(errno));
		return -1;
	}
	return read_fd(fd, path, max_n, out, n, err, errlen);
}

static int
has_file(const char *dir, const char *file)
{
	char path[PATH_MAX + 256];
	struct stat st;
	int w = snprintf(path, sizeof path, "%s/%s", dir, file);
	return w > 0 && (size_t)w < sizeof path && stat(path, &st) == 0;
}

int
file_shipped_dir(const char *name, const char *probe, char *out, size_t n)
{
	char exe[PATH_MAX];
	ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
	if (len > 0) {
		exe[len] = '\0';
		char *slash = strrchr(exe, '/');
		if (slash != NULL) {
			*slash = '\0';
			static const char *const rel[] = { "/../", "/../share/aeroeval/", "/" };
			for (size_t i = 0; i < sizeof rel / sizeof rel[0]; i++) {
				char cand[2 * PATH_MAX];
				snprintf(cand, sizeof cand, "%s%s%s", exe, rel[i], name);
				if (has_file(cand, probe)) {
					char real[PATH_MAX];
					snprintf(out, n, "%s", realpath(cand, real) ? real : cand);
					return 0;
				}
			}
		}
	}
	char real[PATH_MAX];
	if (has_file(name, probe) && realpath(name, real) != NULL) {
		snprintf(out, n, "%s", real);
		return 0;
	}
	snprintf(out, n, "%s", name);
	return -1;
}
