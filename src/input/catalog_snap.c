/* catalog_snap.c — the catalogue snapshot (see catalog_snap.h).
 *
 * Layout, all in the building machine's own byte order:
 *     struct snap_header
 *     the entries of each category in turn, n[k] * entry_size[k] bytes,
 *       every text pointer replaced by its offset into the text
 *     the text: every string, NUL-terminated, text_bytes in all
 */
#include "input/catalog_snap.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "input/catalog_io.h"
#include "util/xalloc.h"

#define SNAP_MAGIC "AESNAP01"
#define MAX_TEXT_FIELDS 32
/* The files a snapshot depends on: each category's file, then the
 * chemistries that the battery entries were checked against. */
#define N_DEPS (CATALOG_N_CATEGORIES + 1)

/* One file as stat() saw it when the snapshot was made; size -1: absent. */
struct snap_dep {
	int64_t size;
	int64_t mtime_s;
	int64_t mtime_ns;
};

struct snap_header {
	char magic[8];
	uint64_t entry_size[CATALOG_N_CATEGORIES];
	uint64_t n[CATALOG_N_CATEGORIES];
	uint64_t text_bytes;
	char sha256[72];                 /* hex, NUL-terminated, zero-padded */
	struct snap_dep deps[N_DEPS];
};

static void
dep_path(const char *data_dir, int i, char *out, size_t n)
{
	if (i < CATALOG_N_CATEGORIES)
		snprintf(out, n, "%s/catalog/%s", data_dir, catalog_io_files[i]);
	else
		snprintf(out, n, "%s/chemistries.json", data_dir);
}

/* The file as stat() sees it now; -1 when it cannot say (not a regular
 * file, or an error other than "absent"). */
static int
dep_stat(const char *path, struct snap_dep *d)
{
	struct stat st;
	memset(d, 0, sizeof *d);
	if (lstat(path, &st) != 0) {
		d->size = -1;
		return errno == ENOENT ? 0 : -1;
	}
	if (!S_ISREG(st.st_mode))
		return -1;
	d->size = (int64_t)st.st_size;
	d->mtime_s = (int64_t)st.st_mtim.tv_sec;
	d->mtime_ns = (int64_t)st.st_mtim.tv_nsec;
	return 0;
}

/* ---- writing ------------------------------------------------------------- */

struct buf {
	unsigned char *p;
	size_t n, cap;
};

static size_t
buf_put(struct buf *b, const void *src, size_t n)
{
	if (b->cap - b->n < n) {
		b->cap = (b->n + n) * 2;
		b->p = xrealloc(b->p, b->cap);
	}
	size_t at = b->n;
	memcpy(b->p + at, src, n);
	b->n += n;
	return at;
}

int
catalog_snap_write(const struct catalog *c, const char *sha256_hex,
                   const char *data_dir, FILE *out, char *err, size_t errlen)
{
	struct snap_header h;
	memset(&h, 0, sizeof h);
	memcpy(h.magic, SNAP_MAGIC, sizeof h.magic);
	snprintf(h.sha256, sizeof h.sha256, "%s", sha256_hex);
	for (int i = 0; i < N_DEPS; i++) {
		char path[4200];
		dep_path(data_dir, i, path, sizeof path);
		if (dep_stat(path, &h.deps[i]) != 0) {
			snprintf(err, errlen, "%s: not a regular file", path);
			return -1;
		}
	}
	struct buf items = { 0 }, text = { 0 };
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		enum catalog_category cat = (enum catalog_category)k;
		size_t offs[MAX_TEXT_FIELDS];
		size_t n_text = catalog_io_text_fields(cat, offs, MAX_TEXT_FIELDS);
		size_t size = catalog_entry_size(cat);
		unsigned char *e = xmalloc(size);
		h.entry_size[k] = size;
		h.n[k] = catalog_count(c, cat);
		for (size_t i = 0; i < h.n[k]; i++) {
			memcpy(e, catalog_item(c, cat, i), size);
			for (size_t f = 0; f < n_text; f++) {
				const char *s;
				memcpy(&s, e + offs[f], sizeof s);
				uintptr_t at = buf_put(&text, s, strlen(s) + 1);
				memcpy(e + offs[f], &at, sizeof at);
			}
			buf_put(&items, e, size);
		}
		free(e);
	}
	h.text_bytes = text.n;
	int ok = fwrite(&h, sizeof h, 1, out) == 1
	    && (items.n == 0 || fwrite(items.p, items.n, 1, out) == 1)
	    && (text.n == 0 || fwrite(text.p, text.n, 1, out) == 1);
	free(items.p);
	free(text.p);
	if (!ok) {
		snprintf(err, errlen, "writing the snapshot: %s", strerror(errno));
		return -1;
	}
	return 0;
}

/* ---- reading ------------------------------------------------------------- */

/* Is every file the snapshot was made from unchanged? */
static int
deps_unchanged(const struct snap_header *h, const char *data_dir)
{
	for (int i = 0; i < N_DEPS; i++) {
		char path[4200];
		struct snap_dep now;
		dep_path(data_dir, i, path, sizeof path);
		if (dep_stat(path, &now) != 0 || now.size != h->deps[i].size
		    || now.mtime_s != h->deps[i].mtime_s
		    || now.mtime_ns != h->deps[i].mtime_ns)
			return 0;
	}
	return 1;
}

/* Turns the text offsets of the n entries at items back into pointers;
 * 0 when an offset points outside the text. */
static int
fix_text(unsigned char *items, size_t n, size_t size, enum catalog_category k,
         const char *text, size_t text_bytes)
{
	size_t offs[MAX_TEXT_FIELDS];
	size_t n_text = catalog_io_text_fields(k, offs, MAX_TEXT_FIELDS);
	for (size_t i = 0; i < n; i++) {
		unsigned char *e = items + i * size;
		for (size_t f = 0; f < n_text; f++) {
			uintptr_t at;
			memcpy(&at, e + offs[f], sizeof at);
			if (at >= text_bytes)
				return 0;
			const char *s = text + at;
			memcpy(e + offs[f], &s, sizeof s);
		}
	}
	return 1;
}

struct catalog *
catalog_snap_read(const unsigned char *blob, size_t n, const char *data_dir,
                  char sha256_hex[65])
{
	struct snap_header h;
	if (blob == NULL || n < sizeof h)
		return NULL;
	memcpy(&h, blob, sizeof h);
	if (memcmp(h.magic, SNAP_MAGIC, sizeof h.magic) != 0
	    || strnlen(h.sha256, sizeof h.sha256) != 64)
		return NULL;
	size_t need = sizeof h;
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		if (h.entry_size[k] != catalog_entry_size((enum catalog_category)k)
		    || h.n[k] > n / h.entry_size[k])
			return NULL;
		need += h.n[k] * h.entry_size[k];
	}
	if (need > n || h.text_bytes != n - need
	    || (h.text_bytes > 0 && blob[n - 1] != '\0'))
		return NULL;
	if (!deps_unchanged(&h, data_dir))
		return NULL;

	const char *text = (const char *)blob + need;
	struct catalog *c = catalog_alloc();
	size_t at = sizeof h;
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		enum catalog_category cat = (enum catalog_category)k;
		size_t bytes = h.n[k] * h.entry_size[k];
		unsigned char *items = xmalloc(bytes > 0 ? bytes : 1);
		memcpy(items, blob + at, bytes);
		at += bytes;
		catalog_adopt(c, cat, items, h.n[k]);
		if (!fix_text(items, h.n[k], h.entry_size[k], cat, text, h.text_bytes)) {
			catalog_free(c);
			return NULL;
		}
	}
	catalog_finish(c);
	memcpy(sha256_hex, h.sha256, 65);
	return c;
}

size_t
catalog_snap_header_bytes(void)
{
	return sizeof(struct snap_header);
}
