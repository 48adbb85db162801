/* assets.c — fonts and logos judged before use (see assets.h). */
#include "pdf/assets.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cairo.h>
#include <hpdf.h>

/* Big-endian reads (sfnt and PNG are big-endian). */
static uint32_t
be32(const unsigned char *p)
{
	return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static unsigned
be16(const unsigned char *p)
{
	return (unsigned)p[0] << 8 | p[1];
}

#define TAG(a, b, c, d) ((uint32_t)(a) << 24 | (uint32_t)(b) << 16 | (uint32_t)(c) << 8 | (d))
#define SFNT_MAX_TABLES 256        /* fonts hold some 10 to 40 */
#define HEAD_MAGIC 0x5F0F3CF5u      /* 'head' magicNumber, offset 12 */

/* The tables libharu reads when it loads a font (hpdf_fontdef_tt.c). */
static const char *const required_tables[] = {
	"head", "hhea", "hmtx", "maxp", "cmap", "loca", "glyf", "name", "post", NULL,
};

/* The directory entry of table tag, or NULL. */
static const unsigned char *
find_table(const unsigned char *buf, unsigned n_tables, const char *tag)
{
	for (unsigned i = 0; i < n_tables; i++) {
		const unsigned char *rec = buf + 12 + 16 * i;
		if (memcmp(rec, tag, 4) == 0)
			return rec;
	}
	return NULL;
}

/* The sfnt header, the table directory and the tables libharu needs. */
static int
check_sfnt(const unsigned char *buf, size_t n, char *err, size_t errlen)
{
	if (n < 12) {
		snprintf(err, errlen, "%zu bytes, too short for a font", n);
		return -1;
	}
	uint32_t v = be32(buf);
	if (v == TAG('O', 'T', 'T', 'O')) {
		snprintf(err, errlen, "an OpenType font with PostScript (CFF) outlines; "
		         "the PDF writer embeds TrueType outlines only");
		return -1;
	}
	if (v == TAG('t', 't', 'c', 'f')) {
		snprintf(err, errlen, "a font collection (.ttc); name a single .ttf");
		return -1;
	}
	if (v == TAG('w', 'O', 'F', 'F') || v == TAG('w', 'O', 'F', '2')) {
		snprintf(err, errlen, "a compressed web font (WOFF); name the .ttf");
		return -1;
	}
	if (v != 0x00010000u && v != TAG('t', 'r', 'u', 'e')) {
		snprintf(err, errlen, "not a TrueType font (it starts with bytes %02x %02x "
		         "%02x %02x)", buf[0], buf[1], buf[2], buf[3]);
		return -1;
	}
	unsigned n_tables = be16(buf + 4);
	if (n_tables == 0 || n_tables > SFNT_MAX_TABLES || 12 + 16 * (size_t)n_tables > n) {
		snprintf(err, errlen, "a broken table directory (%u tables in %zu bytes)",
		         n_tables, n);
		return -1;
	}
	for (unsigned i = 0; i < n_tables; i++) {
		const unsigned char *rec = buf + 12 + 16 * i;
		uint32_t off = be32(rec + 8), len = be32(rec + 12);
		if (off > n || len > n - off) {
			snprintf(err, errlen, "table '%.4s' runs past the end of the file", rec);
			return -1;
		}
	}
	for (int i = 0; required_tables[i] != NULL; i++)
		if (find_table(buf, n_tables, required_tables[i]) == NULL) {
			snprintf(err, errlen, "no '%s' table", required_tables[i]);
			return -1;
		}
	const unsigned char *head = find_table(buf, n_tables, "head");
	if (be32(head + 12) < 54 || be32(buf + be32(head + 8) + 12) != HEAD_MAGIC) {
		snprintf(err, errlen, "a broken 'head' table");
		return -1;
	}
	const unsigned char *cmap = find_table(buf, n_tables, "cmap");
	if (be32(cmap + 12) < 4 || be16(buf + be32(cmap + 8)) != 0) {
		snprintf(err, errlen, "a 'cmap' table the PDF writer cannot read");
		return -1;
	}
	return 0;
}

int
assets_check_font(const char *path, const unsigned char *buf, size_t n,
                  char *err, size_t errlen)
{
	if (check_sfnt(buf, n, err, errlen) != 0)
		return -1;
	/* The header is sound; let libharu, which embeds it, have the last
	 * word, once, in a scratch document. */
	HPDF_Doc pdf = HPDF_New(NULL, NULL);
	if (pdf == NULL) {
		snprintf(err, errlen, "out of memory in the PDF writer");
		return -1;
	}
	const char *name = HPDF_LoadTTFontFromFile(pdf, path, HPDF_TRUE);
	unsigned long code = HPDF_GetError(pdf);
	HPDF_Free(pdf);
	if (name == NULL) {
		snprintf(err, errlen, "the PDF writer cannot load it (libharu error 0x%04lX)", code);
		return -1;
	}
	return 0;
}

/* cairo's PNG reader over a buffer. */
struct png_src {
	const unsigned char *p;
	size_t left;
};

static cairo_status_t
png_read(void *closure, unsigned char *data, unsigned int length)
{
	struct png_src *s = closure;
	if (length > s->left)
		return CAIRO_STATUS_READ_ERROR;
	memcpy(data, s->p, length);
	s->p += length;
	s->left -= length;
	return CAIRO_STATUS_SUCCESS;
}

int
assets_check_png(const unsigned char *buf, size_t n, char *err, size_t errlen)
{
	static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
	if (n < 33 || memcmp(buf, sig, 8) != 0 || memcmp(buf + 12, "IHDR", 4) != 0) {
		snprintf(err, errlen, "not a PNG file (no PNG signature and header)");
		return -1;
	}
	uint32_t w = be32(buf + 16), h = be32(buf + 20);
	if (w == 0 || h == 0 || w > ASSETS_LOGO_MAX_PX || h > ASSETS_LOGO_MAX_PX) {
		snprintf(err, errlen, "%u x %u pixels (at most %d on a side)", (unsigned)w,
		         (unsigned)h, ASSETS_LOGO_MAX_PX);
		return -1;
	}
	struct png_src src = { buf, n };
	cairo_surface_t *s = cairo_image_surface_create_from_png_stream(png_read, &src);
	cairo_status_t st = cairo_surface_status(s);
	cairo_surface_destroy(s);
	if (st != CAIRO_STATUS_SUCCESS) {
		/* cairo reports a libpng error as "out of memory" (the caps above
		 * rule a real shortage out) and a short stream as a read error. */
		const char *why = st == CAIRO_STATUS_NO_MEMORY ? "corrupt image data"
		    : st == CAIRO_STATUS_READ_ERROR ? "the file ends early"
		    : cairo_status_to_string(st);
		snprintf(err, errlen, "the image does not decode (%s)", why);
		return -1;
	}
	return 0;
}

int
assets_check(enum template_asset kind, const char *path, const unsigned char *buf,
             size_t n, char *err, size_t errlen)
{
	if (kind == TEMPLATE_ASSET_FONT)
		return assets_check_font(path, buf, n, err, errlen);
	return assets_check_png(buf, n, err, errlen);
}
