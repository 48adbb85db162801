/* catalog_snap.c — the catalogue snapshot (see catalog_snap.h).
 *
 * Layout, all in the building machine's own byte order:
 *     struct snap_header
 *     the bytes of each category's file in turn, file_bytes[k] of them
 *       (none for an absent optional file, file_bytes[k] = -1)
 *     the chemistry names, each NUL-terminated, chem_bytes in all
 *     the entries of each category in turn, n[k] * entry_size[k] bytes,
 *       every text pointer replaced by its offset into the text
 *     the text: every string, NUL-terminated, text_bytes in all
 */
#include "input/catalog_snap.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "input/catalog_io.h"
#include "input/json_in.h"
#include "util/file.h"
#include "util/xalloc.h"

#define SNAP_MAGIC "AESNAP02"
#define MAX_TEXT_FIELDS 32

struct snap_header {
	char magic[8];
	uint64_t entry_size[CATALOG_N_CATEGORIES];
	uint64_t n[CATALOG_N_CATEGORIES];
	int64_t file_bytes[CATALOG_N_CATEGORIES];  /* -1: absent */
	uint64_t chem_bytes;
	uint64_t text_bytes;
	char sha256[72];                 /* hex, NUL-terminated, zero-padded */
};

/* Category k's file of folder dir as it is now: *bytes (heap, free()) and
 * *len, *bytes NULL for an absent optional file.  -1 when a file that is
 * there cannot be read. */
static int
read_file(const char *dir, enum catalog_category k, unsigned char **bytes,
          size_t *len)
{
	char msg[256];
	char *path = catalog_io_path(dir, k);
	*bytes = NULL;
	*len = 0;
	int rc = catalog_io_absent(path, k) ? 0
	    : file_read(path, JSON_IN_CATALOG_MAX, bytes, len, msg, sizeof msg);
	free(path);
	return rc != 0 ? -1 : 0;
}

static void
free_files(unsigned char *bytes[CATALOG_N_CATEGORIES])
{
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++)
		free(bytes[k]);
}

/* Every file of folder dir (read_file()); -1, nothing left allocated,
 * when one cannot be read. */
static int
read_files(const char *dir, unsigned char *bytes[CATALOG_N_CATEGORIES],
           size_t len[CATALOG_N_CATEGORIES])
{
	int rc = 0;
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		bytes[k] = NULL;
		if (rc == 0)
			rc = read_file(dir, (enum catalog_category)k, &bytes[k], &len[k]);
	}
	if (rc != 0)
		free_files(bytes);
	return rc;
}

static const char *const *
chem_list(const char *const *known_chemistries)
{
	return known_chemistries != NULL ? known_chemistries : catalog_default_chemistries;
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
	if (n > 0)
		memcpy(b->p + at, src, n);
	b->n += n;
	return at;
}

/* The snapshot of catalogue c, whose files' bytes are bytes/len and whose
 * fingerprint is sha256_hex, into out (header, then everything after it). */
static void
snap_build(const struct catalog *c, unsigned char *const bytes[CATALOG_N_CATEGORIES],
           const size_t len[CATALOG_N_CATEGORIES], const char *const *chems,
           const char *sha256_hex, struct buf *out)
{
	struct snap_header h;
	struct buf files = { 0 }, names = { 0 }, items = { 0 }, text = { 0 };
	memset(&h, 0, sizeof h);
	memcpy(h.magic, SNAP_MAGIC, sizeof h.magic);
	snprintf(h.sha256, sizeof h.sha256, "%s", sha256_hex);
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		h.file_bytes[k] = bytes[k] != NULL ? (int64_t)len[k] : -1;
		if (bytes[k] != NULL)
			buf_put(&files, bytes[k], len[k]);
	}
	for (const char *const *s = chems; *s != NULL; s++)
		buf_put(&names, *s, strlen(*s) + 1);
	h.chem_bytes = names.n;
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
	buf_put(out, &h, sizeof h);
	buf_put(out, files.p, files.n);
	buf_put(out, names.p, names.n);
	buf_put(out, items.p, items.n);
	buf_put(out, text.p, text.n);
	free(files.p);
	free(names.p);
	free(items.p);
	free(text.p);
}

int
catalog_snap_write(const char *dir, const char *const *known_chemistries,
                   struct diag *dg, FILE *out, char *err, size_t errlen)
{
	char sha[65], again[65];
	err[0] = '\0';
	struct catalog *c = catalog_io_load(dir, known_chemistries, dg, sha);
	if (c == NULL)
		return -1;
	/* The files are read a second time for their bytes; the fingerprint
	 * proves they are the bytes the catalogue was loaded from. */
	unsigned char *bytes[CATALOG_N_CATEGORIES];
	size_t len[CATALOG_N_CATEGORIES];
	if (read_files(dir, bytes, len) != 0) {
		snprintf(err, errlen, "%s: a catalogue file cannot be read again", dir);
		catalog_free(c);
		return -1;
	}
	catalog_io_fingerprint((const char *const *)bytes, len, again);
	int rc = 0;
	if (strcmp(sha, again) != 0) {
		snprintf(err, errlen, "%s: the catalogue changed while it was read", dir);
		rc = -1;
	} else {
		struct buf snap = { 0 };
		snap_build(c, bytes, len, chem_list(known_chemistries), sha, &snap);
		if (fwrite(snap.p, 1, snap.n, out) != snap.n) {
			snprintf(err, errlen, "writing the snapshot: %s", strerror(errno));
			rc = -1;
		}
		free(snap.p);
	}
	free_files(bytes);
	catalog_free(c);
	return rc;
}

/* ---- reading ------------------------------------------------------------- */

/* Is the recorded chemistry list (n bytes at names) exactly chems? */
static int
same_chems(const char *names, size_t n, const char *const *chems)
{
	size_t at = 0;
	for (const char *const *s = chems; *s != NULL; s++) {
		size_t l = strlen(*s) + 1;
		if (n - at < l || memcmp(names + at, *s, l) != 0)
			return 0;
		at += l;
	}
	return at == n;
}

/* Are the files of dir now exactly the recorded ones (files at blob)?
 * Read one at a time, up to the first that differs. */
static int
same_files(const struct snap_header *h, const unsigned char *files, const char *dir)
{
	int same = 1;
	for (int k = 0; k < CATALOG_N_CATEGORIES && same; k++) {
		unsigned char *bytes;
		size_t len;
		if (read_file(dir, (enum catalog_category)k, &bytes, &len) != 0)
			return 0;
		if (h->file_bytes[k] < 0) {
			same = bytes == NULL;
		} else {
			same = bytes != NULL && len == (uint64_t)h->file_bytes[k]
			    && memcmp(bytes, files, len) == 0;
			files += h->file_bytes[k];
		}
		free(bytes);
	}
	return same;
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

/* The bytes the snapshot's header h announces after itself; 0 when its
 * counts are out of bounds for a blob of n bytes. */
static size_t
announced_bytes(const struct snap_header *h, size_t n)
{
	uint64_t need = h->chem_bytes;
	if (need > n || h->text_bytes > n - need)
		return 0;
	need += h->text_bytes;
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		enum catalog_category cat = (enum catalog_category)k;
		if (h->file_bytes[k] < -1 || h->entry_size[k] != catalog_entry_size(cat))
			return 0;
		uint64_t file = h->file_bytes[k] > 0 ? (uint64_t)h->file_bytes[k] : 0;
		if (h->n[k] > n / h->entry_size[k] || file > n)
			return 0;
		need += h->n[k] * h->entry_size[k] + file;   /* each term <= n */
		if (need > n)
			return 0;
	}
	return (size_t)need;
}

struct catalog *
catalog_snap_read(const unsigned char *blob, size_t n, const char *dir,
                  const char *const *known_chemistries, char sha256_hex[65])
{
	struct snap_header h;
	if (blob == NULL || n < sizeof h)
		return NULL;
	memcpy(&h, blob, sizeof h);
	if (memcmp(h.magic, SNAP_MAGIC, sizeof h.magic) != 0
	    || strnlen(h.sha256, sizeof h.sha256) != 64
	    || announced_bytes(&h, n - sizeof h) != n - sizeof h
	    || (h.text_bytes > 0 && blob[n - 1] != '\0'))
		return NULL;
	const unsigned char *files = blob + sizeof h;
	size_t files_bytes = 0;
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++)
		files_bytes += h.file_bytes[k] > 0 ? (size_t)h.file_bytes[k] : 0;
	const char *names = (const char *)files + files_bytes;
	if (!same_chems(names, h.chem_bytes, chem_list(known_chemistries))
	    || !same_files(&h, files, dir))
		return NULL;

	const char *text = (const char *)blob + n - h.text_bytes;
	struct catalog *c = catalog_alloc();
	const unsigned char *at = (const unsigned char *)names + h.chem_bytes;
	for (int k = 0; k < CATALOG_N_CATEGORIES; k++) {
		enum catalog_category cat = (enum catalog_category)k;
		size_t bytes = h.n[k] * h.entry_size[k];
		unsigned char *items = xmalloc(bytes > 0 ? bytes : 1);
		if (bytes > 0)
			memcpy(items, at, bytes);
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
