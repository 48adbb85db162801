/* test_assets.c — the checks of a template's fonts and logo: the real
 * fonts pass, every kind of non-font and broken PNG is named, and nothing
 * aborts the process (a corrupt PNG once did, inside libpng). */
#include "test_util.h"

#include <stdlib.h>
#include <string.h>

#include <cairo.h>

#include "pdf/assets.h"
#include "util/file.h"
#include "util/strbuf.h"

#define DEJAVU "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

/* The bytes of path (caller frees). */
static unsigned char *
slurp(const char *path, size_t *n)
{
	unsigned char *buf;
	char err[256];
	if (file_read(path, 64u << 20, &buf, n, err, sizeof err) != 0)
		fail_msg("%s", err);
	return buf;
}

static void
assets_should_accept_the_dejavu_fonts(void **state)
{
	(void)state;
	static const char *const fonts[] = { DEJAVU,
		"/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
		"/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf" };
	for (size_t i = 0; i < 3; i++) {
		size_t n;
		unsigned char *buf = slurp(fonts[i], &n);
		char err[256] = "";
		if (assets_check(TEMPLATE_ASSET_FONT, fonts[i], buf, n, err, sizeof err) != 0)
			fail_msg("%s: %s", fonts[i], err);
		free(buf);
	}
}

/* The font check's reason for bytes b[0..n) (as if read from DEJAVU). */
static const char *
font_reason(const unsigned char *b, size_t n)
{
	static char err[256];
	err[0] = '\0';
	assert_int_equal(assets_check_font(DEJAVU, b, n, err, sizeof err), -1);
	return err;
}

static void
assets_should_name_why_a_file_is_not_a_usable_font(void **state)
{
	(void)state;
	assert_string_equal(font_reason((const unsigned char *)"", 0),
	                    "0 bytes, too short for a font");
	assert_string_equal(font_reason((const unsigned char *)"{\"fonts\": {}}  ", 15),
	                    "not a TrueType font (it starts with bytes 7b 22 66 6f)");
	assert_string_equal(font_reason((const unsigned char *)"OTTO\0\x0a\0\0\0\0\0\0", 12),
	                    "an OpenType font with PostScript (CFF) outlines; the PDF "
	                    "writer embeds TrueType outlines only");
	assert_string_equal(font_reason((const unsigned char *)"ttcf\0\x01\0\0\0\0\0\0", 12),
	                    "a font collection (.ttc); name a single .ttf");
	assert_string_equal(font_reason((const unsigned char *)"wOFF\0\x01\0\0\0\0\0\0", 12),
	                    "a compressed web font (WOFF); name the .ttf");

	size_t n;
	unsigned char *buf = slurp(DEJAVU, &n);
	/* Cut short: the directory points past the end. */
	assert_non_null(strstr(font_reason(buf, 4096), "runs past the end of the file"));
	/* No glyph table: rename 'glyf' in the directory. */
	unsigned char *copy = malloc(n);
	assert_non_null(copy);
	memcpy(copy, buf, n);
	unsigned tables = (unsigned)copy[4] << 8 | copy[5];
	for (unsigned i = 0; i < tables; i++)
		if (memcmp(copy + 12 + 16 * i, "glyf", 4) == 0)
			memcpy(copy + 12 + 16 * i, "glyX", 4);
	assert_string_equal(font_reason(copy, n), "no 'glyf' table");
	/* A table count no font has. */
	memcpy(copy, buf, n);
	copy[4] = 0xff;
	assert_non_null(strstr(font_reason(copy, n), "a broken table directory"));
	free(copy);
	free(buf);
}

/* A w x h PNG cairo wrote, as bytes. */
static cairo_status_t
png_to_strbuf(void *closure, const unsigned char *data, unsigned int length)
{
	strbuf_append(closure, data, length);
	return CAIRO_STATUS_SUCCESS;
}

static void
assets_should_decode_a_png_and_refuse_a_broken_one(void **state)
{
	(void)state;
	struct strbuf sb = STRBUF_INIT;
	cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 24, 12);
	assert_int_equal(cairo_surface_write_to_png_stream(s, png_to_strbuf, &sb),
	                 CAIRO_STATUS_SUCCESS);
	cairo_surface_destroy(s);
	const unsigned char *png = (const unsigned char *)sb.data;
	char err[256] = "";
	assert_int_equal(assets_check(TEMPLATE_ASSET_LOGO, "x.png", png, sb.len, err, sizeof err), 0);

	/* Truncated in the image data: an error status, not an abort. */
	assert_int_equal(assets_check_png(png, sb.len - 20, err, sizeof err), -1);
	assert_non_null(strstr(err, "the image does not decode ("));
	/* Corrupt image data. */
	unsigned char *bad = malloc(sb.len);
	assert_non_null(bad);
	memcpy(bad, png, sb.len);
	for (size_t i = 41; i < sb.len - 12; i++)
		bad[i] ^= 0x5a;
	assert_int_equal(assets_check_png(bad, sb.len, err, sizeof err), -1);
	assert_non_null(strstr(err, "the image does not decode ("));
	/* A header that claims a decompression bomb. */
	memcpy(bad, png, sb.len);
	bad[16] = 0x00; bad[17] = 0x01; bad[18] = 0x00; bad[19] = 0x00;   /* 65536 wide */
	assert_int_equal(assets_check_png(bad, sb.len, err, sizeof err), -1);
	assert_string_equal(err, "65536 x 12 pixels (at most 10000 on a side)");
	/* Not a PNG at all. */
	assert_int_equal(assets_check_png((const unsigned char *)"GIF89a", 6, err, sizeof err), -1);
	assert_string_equal(err, "not a PNG file (no PNG signature and header)");
	free(bad);
	strbuf_free(&sb);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(assets_should_accept_the_dejavu_fonts),
		cmocka_unit_test(assets_should_name_why_a_file_is_not_a_usable_font),
		cmocka_unit_test(assets_should_decode_a_png_and_refuse_a_broken_one),
	};
	return cmocka_run_group_tests_name("assets", tests, NULL, NULL);
}
