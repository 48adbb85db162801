/* doc.c — the dossier document: flow layout over libharu (see doc.h); its
 * tables are in doc_table.c. */
#include "pdf/doc.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hpdf.h>
#include <hpdf_doc.h>        /* internals: a loaded font's definition */
#include <hpdf_encoder.h>    /* internals: the UTF-8 encoder's code map */
#include <hpdf_fontdef.h>    /* internals: a TrueType font's cmap */
#include <hpdf_namedict.h>   /* internals: the attachment's name tree */
#include <hpdf_objects.h>    /* internals: the fonts' ToUnicode maps */
#include <hpdf_streams.h>

#include "pdf/doc_int.h"
#include "util/xalloc.h"

#ifndef AEROEVAL_VERSION
#define AEROEVAL_VERSION "unknown"
#endif

#define PT_PER_MM (72.0 / 25.4)
#define MIN_LINES_AFTER_HEADING 3  /* keep a heading with this many lines */

/* ---- errors ---------------------------------------------------------------- */

/* libharu calls this on every raised error; the document is poisoned from
 * then on (docs/libraries.md, libharu), so the first error is the one to
 * report. */
static void
on_hpdf_error(HPDF_STATUS error_no, HPDF_STATUS detail_no, void *user)
{
	if (error_no == HPDF_FAILD_TO_ALLOC_MEM)  /* hpdf_alloc() exits first */
		doc_fail(user, "out of memory");
	else
		doc_fail(user, "libharu error 0x%04X (detail %u)", (unsigned)error_no,
		         (unsigned)detail_no);
}

/* libharu's allocator: through xmalloc, so running out of memory inside
 * libharu is the one out-of-memory error of the program (exit 3) and not
 * "libharu error 0x1015", and AEROEVAL_FAIL_ALLOC reaches it too. */
static void *
hpdf_alloc(HPDF_UINT size)
{
	return xmalloc(size);
}

static void
hpdf_free(void *p)
{
	free(p);
}

const char *
doc_error(const struct doc *d)
{
	return doc_failed(d) ? d->err : NULL;
}

/* ---- text measuring and wrapping ------------------------------------------- */

/* Bytes of the UTF-8 character starting at s (1 for a stray byte). */
static size_t
utf8_len(const char *s)
{
	unsigned char c = (unsigned char)*s;
	size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 1;
	for (size_t i = 1; i < n; i++)
		if (((unsigned char)s[i] & 0xc0) != 0x80)
			return 1;
	return n;
}

/* Glyph widths by code point, per font, filled as text is measured:
 * HPDF_Font_TextWidth walks the font's character map for every character,
 * and a dossier measures the same few hundred characters thousands of
 * times (wrapping, alignment).  The slots of a document's fonts are
 * emptied when it is freed (forget_widths). */
#define WIDTH_FONTS 8
#define WIDTH_CODES 0x10000
static struct width_slot {
	HPDF_Font font;
	int32_t *units;            /* per code point; -1 not yet measured */
} width_slots[WIDTH_FONTS];

static int32_t *
widths_of(HPDF_Font f)
{
	struct width_slot *free_slot = NULL;
	for (int i = 0; i < WIDTH_FONTS; i++) {
		if (width_slots[i].font == f)
			return width_slots[i].units;
		if (width_slots[i].font == NULL && free_slot == NULL)
			free_slot = &width_slots[i];
	}
	if (free_slot == NULL)
		return NULL;       /* every slot taken: measure directly */
	free_slot->font = f;
	free_slot->units = xmalloc(WIDTH_CODES * sizeof *free_slot->units);
	for (int c = 0; c < WIDTH_CODES; c++)
		free_slot->units[c] = -1;
	return free_slot->units;
}

static void
forget_widths(HPDF_Font f)
{
	for (int i = 0; f != NULL && i < WIDTH_FONTS; i++)
		if (width_slots[i].font == f) {
			free(width_slots[i].units);
			width_slots[i].font = NULL;
			width_slots[i].units = NULL;
		}
}

/* The code point of the UTF-8 character of n bytes at s. */
static long
code_of(const char *s, size_t n)
{
	const unsigned char *u = (const unsigned char *)s;
	if (n == 1)
		return u[0];
	long c = u[0] & (0x7f >> n);
	for (size_t i = 1; i < n; i++)
		c = c << 6 | (u[i] & 0x3f);
	return c;
}

/* Advance width of len bytes of s in font units (1/1000 em): the sum of
 * the glyphs' widths, so the width of a concatenation is the sum of its
 * parts' (libharu applies no kerning); each glyph's measured once.  Text
 * that is not well-formed UTF-8 is measured whole, as libharu reads it. */
static HPDF_UINT
units_of(HPDF_Font f, const char *s, size_t len)
{
	if (len == 0 || f == NULL)
		return 0;
	int32_t *w = widths_of(f);
	HPDF_UINT sum = 0;
	for (size_t i = 0; w != NULL && i < len; ) {
		size_t n = utf8_len(s + i);
		if (i + n > len || (n == 1 && (unsigned char)s[i] >= 0x80))
			break;
		long c = code_of(s + i, n);
		if (c >= WIDTH_CODES || (n == 2 && c < 0x80) || (n == 3 && c < 0x800))
			break;     /* beyond the table, or an overlong form */
		if (w[c] < 0)
			w[c] = (int32_t)HPDF_Font_TextWidth(f, (const HPDF_BYTE *)(s + i),
			    (HPDF_UINT)n).width;
		sum += (HPDF_UINT)w[c];
		i += n;
		if (i == len)
			return sum;
	}
	return HPDF_Font_TextWidth(f, (const HPDF_BYTE *)s, (HPDF_UINT)len).width;
}

static double
to_points(HPDF_UINT units, double size)
{
	return units * size / 1000.0;
}

double
doc_width(HPDF_Font f, double size, const char *s, size_t len)
{
	return to_points(units_of(f, s, len), size);
}

static void
lines_push(struct lines *L, const char *s, size_t len)
{
	if (L->n == L->cap) {
		L->cap = L->cap ? 2 * L->cap : 16;
		L->v = xrealloc(L->v, (size_t)L->cap * sizeof *L->v);
	}
	L->v[L->n].s = s;
	L->v[L->n].len = len;
	L->n++;
}

static int
is_digit(char c)
{
	return c >= '0' && c <= '9';
}

/* A character of a number as printed: digits, the decimal point, the
 * thousands comma. */
static int
is_numeric(char c)
{
	return is_digit(c) || c == '.' || c == ',';
}

/* May the word [s, e) break after its character c?  After a '/' (but not
 * inside the "//" of "https://") or a '-' that is not a leading minus. */
int
doc_breaks_after(const char *s, const char *c, const char *e)
{
	if (*c == '/')
		return (c + 1 >= e || c[1] != '/') && !(c > s && c[-1] == '/');
	return *c == '-' && c > s;
}

/* Where to cut a word [s, e) that is wider than the line: after the last
 * '/' or '-' that fits (a web address or a part id then breaks where a
 * reader expects it, never in the middle of a name), else after the last
 * character that fits, moved back to the start of a number so that digits
 * stay together.  Always takes at least one character. */
static const char *
word_cut(HPDF_Font f, double size, double width, const char *s, const char *e)
{
	const char *c = s, *fit = s, *brk = NULL;
	HPDF_UINT cu = 0;
	while (c < e) {
		size_t cl = utf8_len(c);
		cu += units_of(f, c, cl);
		if (c != s && to_points(cu, size) > width)
			break;
		c += cl;
		fit = c;
		if (doc_breaks_after(s, c - 1, e))
			brk = c;
	}
	if (fit >= e)
		return e;
	if (brk != NULL && brk < e)
		return brk;
	/* A number is never cut: it overflows its cell by a little rather
	 * than read as two numbers. */
	const char *cut = fit;
	while (cut > s && is_numeric(*cut) && is_numeric(cut[-1]))
		cut--;
	return cut > s ? cut : is_numeric(*s) ? e : fit;
}

/* Greedy word wrap of text into lines no wider than width.  Spaces separate
 * words; "\n" forces a break; a word wider than the line is cut between
 * characters (TextRect would stall on it, docs/libraries.md, libharu). */
void
doc_wrap(HPDF_Font f, double size, double width, const char *text, struct lines *out)
{
	const char *p = text;
	for (;;) {
		const char *eol = strchr(p, '\n');
		if (eol == NULL)
			eol = p + strlen(p);
		const char *q = p;
		int emitted = 0;
		while (q < eol) {
			while (q < eol && *q == ' ')
				q++;
			if (q == eol)
				break;
			/* The line's width grows by each word and the spaces
			 * before it, measured once (widths add up). */
			const char *start = q, *end = q;
			HPDF_UINT units = 0;
			for (;;) {
				const char *ws = end;
				while (ws < eol && *ws == ' ')
					ws++;
				if (ws == eol)
					break;
				const char *we = ws;
				while (we < eol && *we != ' ')
					we++;
				HPDF_UINT nu = units + units_of(f, end, (size_t)(we - end));
				double nw = to_points(nu, size);
				if (end != start && nw > width)
					break;
				if (end == start && nw > width) {
					/* First word alone overflows: take what fits of it. */
					end = word_cut(f, size, width, start, we);
					break;
				}
				end = we;
				units = nu;
			}
			lines_push(out, start, (size_t)(end - start));
			emitted = 1;
			q = end;
		}
		if (!emitted)
			lines_push(out, p, 0);   /* blank line */
		if (*eol == '\0')
			break;
		p = eol + 1;
	}
}

/* Draws len bytes of s at baseline (x, y) (page coordinates).  A
 * no-break space (U+00A0, which keeps a number with its unit when text is
 * wrapped) is drawn as a plain space, so that extracted text reads as
 * typed. */
static void
put_text(struct doc *d, HPDF_Font f, double size, double x, double y, const char *s,
         size_t len, struct template_colour k)
{
	char small[256];
	char *buf = len < sizeof small ? small : xmalloc(len + 1);
	size_t n = 0;
	for (size_t i = 0; i < len; i++) {
		if ((unsigned char)s[i] == 0xc2 && i + 1 < len && (unsigned char)s[i + 1] == 0xa0) {
			buf[n++] = ' ';
			i++;
		} else {
			buf[n++] = s[i];
		}
	}
	buf[n] = '\0';
	plot_begin_text(d->page, f, size, k);
	HPDF_Page_TextOut(d->page, (HPDF_REAL)x, (HPDF_REAL)y, buf);
	HPDF_Page_EndText(d->page);
	if (buf != small)
		free(buf);
}

/* Draws s aligned between x0 and x1; returns the x it starts at. */
double
doc_put_aligned(struct doc *d, HPDF_Font f, double size, double x0, double x1, double y,
            const char *s, size_t len, enum doc_align al, struct template_colour k)
{
	double w = doc_width(f, size, s, len), x = x0;
	if (al == DOC_ALIGN_RIGHT)
		x = x1 - w;
	else if (al == DOC_ALIGN_CENTER)
		x = 0.5 * (x0 + x1 - w);
	put_text(d, f, size, x, y, s, len, k);
	return x;
}

void
doc_fill_rect(struct doc *d, double x, double y, double w, double h, struct template_colour k)
{
	HPDF_Page_SetRGBFill(d->page, (HPDF_REAL)k.r, (HPDF_REAL)k.g, (HPDF_REAL)k.b);
	HPDF_Page_Rectangle(d->page, (HPDF_REAL)x, (HPDF_REAL)y, (HPDF_REAL)w, (HPDF_REAL)h);
	HPDF_Page_Fill(d->page);
}

void
doc_hrule(struct doc *d, double x0, double x1, double y, double width, struct template_colour k)
{
	HPDF_Page_SetRGBStroke(d->page, (HPDF_REAL)k.r, (HPDF_REAL)k.g, (HPDF_REAL)k.b);
	HPDF_Page_SetLineWidth(d->page, (HPDF_REAL)width);
	HPDF_Page_SetDash(d->page, NULL, 0, 0);
	HPDF_Page_MoveTo(d->page, (HPDF_REAL)x0, (HPDF_REAL)y);
	HPDF_Page_LineTo(d->page, (HPDF_REAL)x1, (HPDF_REAL)y);
	HPDF_Page_Stroke(d->page);
}

struct template_colour
doc_mix_white(struct template_colour k, double f)
{
	struct template_colour m = { k.r * f + (1 - f), k.g * f + (1 - f), k.b * f + (1 - f) };
	return m;
}

/* ---- pages ----------------------------------------------------------------- */

void
doc_add_page(struct doc *d)
{
	HPDF_Page pg = HPDF_AddPage(d->pdf);
	if (pg == NULL) {
		doc_fail(d, "cannot add a page");
		return;
	}
	HPDF_Page_SetWidth(pg, (HPDF_REAL)d->page_w);
	HPDF_Page_SetHeight(pg, (HPDF_REAL)d->page_h);
	if (d->n_pages == d->cap_pages) {
		d->cap_pages = d->cap_pages ? 2 * d->cap_pages : 16;
		d->pages = xrealloc(d->pages, (size_t)d->cap_pages * sizeof *d->pages);
	}
	d->pages[d->n_pages++] = pg;
	d->page = pg;
	d->y = d->top;
	d->at_top = 1;
	d->after_heading = 0;
}

int
doc_new_page(struct doc *d)
{
	if (doc_failed(d))
		return -1;
	doc_add_page(d);
	return doc_failed(d) ? -1 : 0;
}

double doc_space_left(const struct doc *d) { return d->y - d->bottom; }
double doc_text_width(const struct doc *d) { return d->right - d->left; }
int doc_page_count(const struct doc *d) { return d->n_pages; }
int doc_next_figure_number(const struct doc *d) { return d->n_figures + 1; }

int
doc_ensure_space(struct doc *d, double h)
{
	if (doc_failed(d))
		return -1;
	if (d->y - h < d->bottom && !d->at_top)
		doc_add_page(d);
	return doc_failed(d) ? -1 : 0;
}

/* Moves the cursor down by h after placing something. */
void
doc_advance(struct doc *d, double h)
{
	d->y -= h;
	d->at_top = 0;
	d->after_heading = 0;
}

/* ---- document -------------------------------------------------------------- */

/* Rewrites the ToUnicode map of a UTF-8 font.  libharu 2.3.0 writes it
 * with a `begincidrange` block, which is an operator of CID maps, not of
 * ToUnicode maps: poppler warns on every such font ("Invalid
 * 'begincidrange' operator in ToUnicode CMap", docs/libraries.md) and other
 * readers may not extract the text at all.  With the UTF-8 encoder the
 * code of a glyph is its Unicode value (the CIDToGIDMap does the rest), so
 * the right map is the identity: one bfrange per high byte (a bfrange may
 * not cross a change of the first byte, PDF 1.7 §9.10.3), the surrogate
 * block left out, at most 100 ranges per block. */
static void
fix_to_unicode(struct doc *d, HPDF_Font font)
{
	HPDF_Dict map = HPDF_Dict_GetItem(font, "ToUnicode", HPDF_OCLASS_DICT);
	if (map == NULL || map->stream == NULL) {
		HPDF_ResetError(d->pdf);   /* no map to fix: nothing is wrong */
		return;
	}
	HPDF_Stream s = map->stream;
	HPDF_MemStream_FreeData(s);
	if (d->to_unicode != NULL) {
		/* The map is the same for every font: the fonts after the first
		 * name the first's, and their own is left empty (written, but
		 * nothing refers to it), which saves deflating it again. */
		HPDF_Dict_Add(font, "ToUnicode", d->to_unicode);
		return;
	}
	d->to_unicode = map;
	HPDF_Stream_WriteStr(s, "/CIDInit /ProcSet findresource begin\n"
	    "12 dict begin\nbegincmap\n"
	    "/CIDSystemInfo << /Registry (Adobe) /Ordering (UCS) /Supplement 0 >> def\n"
	    "/CMapName /Adobe-Identity-UCS def\n/CMapType 2 def\n"
	    "1 begincodespacerange\n<0000> <FFFF>\nendcodespacerange\n");
	int hi[256], n = 0;
	for (int h = 0; h < 256; h++)
		if (h < 0xd8 || h > 0xdf)
			hi[n++] = h;
	char line[48];
	for (int i = 0; i < n; i += 100) {
		int m = n - i < 100 ? n - i : 100;
		snprintf(line, sizeof line, "%d beginbfrange\n", m);
		HPDF_Stream_WriteStr(s, line);
		for (int k = i; k < i + m; k++) {
			snprintf(line, sizeof line, "<%02X00> <%02XFF> <%02X00>\n", hi[k], hi[k], hi[k]);
			HPDF_Stream_WriteStr(s, line);
		}
		HPDF_Stream_WriteStr(s, "endbfrange\n");
	}
	HPDF_Stream_WriteStr(s, "endcmap\nCMapName currentdict /CMap defineresource pop\n"
	    "end\nend\n");
	/* The map's own dictionary named it a CID map; a ToUnicode stream
	 * needs none of those keys. */
	HPDF_Dict_RemoveElement(map, "Type");
	HPDF_Dict_RemoveElement(map, "CMapName");
	HPDF_Dict_RemoveElement(map, "CIDSystemInfo");
	HPDF_Dict_RemoveElement(map, "WMode");
}

/* Cuts a UTF-8 font's CIDToGIDMap after the last code point its font
 * has a glyph for.  libharu writes the map for the whole Basic
 * Multilingual Plane (65 536 codes x 2 bytes = 128 KiB per font), which
 * the document then deflates and carries; codes past the end of a map have
 * no glyph (.notdef) in every reader, exactly as a zero entry, so the cut
 * map means the same.  The shipped fonts stop at U+22FF (Makefile, `make
 * fonts`): 18 KiB. */
static void
trim_cid_map(struct doc *d, HPDF_Font font)
{
	HPDF_Array desc = HPDF_Dict_GetItem(font, "DescendantFonts", HPDF_OCLASS_ARRAY);
	HPDF_Dict cid = desc != NULL ? HPDF_Array_GetItem(desc, 0, HPDF_OCLASS_DICT) : NULL;
	HPDF_Dict map = cid != NULL ? HPDF_Dict_GetItem(cid, "CIDToGIDMap", HPDF_OCLASS_DICT) : NULL;
	if (map == NULL || map->stream == NULL || map->stream->type != HPDF_STREAM_MEMORY) {
		HPDF_ResetError(d->pdf);   /* no map to cut: nothing is wrong */
		return;
	}
	HPDF_Stream s = map->stream;
	HPDF_UINT size = s->size;
	HPDF_BYTE *bytes = xmalloc(size > 0 ? size : 1);
	HPDF_UINT at = 0;
	for (HPDF_UINT i = 0; i < HPDF_MemStream_GetBufCount(s) && at < size; i++) {
		HPDF_UINT len = 0;
		HPDF_BYTE *p = HPDF_MemStream_GetBufPtr(s, i, &len);
		if (p == NULL || len > size - at)
			break;
		memcpy(bytes + at, p, len);
		at += len;
	}
	HPDF_UINT keep = at;
	while (keep >= 2 && bytes[keep - 1] == 0 && bytes[keep - 2] == 0)
		keep -= 2;
	if (at == size && keep < size) {
		HPDF_MemStream_FreeData(s);
		HPDF_Stream_Write(s, bytes, keep);
	}
	free(bytes);
}

/* The encoder's tables as they were before narrow_codes(). */
struct code_tables {
	HPDF_Encoder_ToUnicode_Func to_unicode_fn;
	HPDF_UNICODE unicode_map[256][256];
	HPDF_UINT16 cid_map[256][256];
};

/* Makes HPDF_GetFont map only the codes the font has glyphs for, keeping
 * the encoder as it was in *keep (restore_codes() puts it back).  For the
 * UTF-8 encoder libharu 2.3.0 builds a font's CID-to-glyph map and widths
 * by looking up all 65 536 codes in the font's cmap, each a walk over its
 * segments (~30 M instructions for three fonts); for an encoder whose
 * to_unicode_fn is the generic table lookup it looks up only the codes
 * its tables list.  So for this one call the tables list each code of the
 * font's segments as itself.  A code left out has no glyph, so it maps to
 * glyph 0 and the default width either way: the font comes out byte for
 * byte the same.  The code after the last segment is listed too, because
 * libharu writes the map up to, not including, the highest code listed.
 * Returns 0, having changed nothing, when the font's cmap is not one this
 * can read. */
static int
narrow_codes(HPDF_Encoder enc, HPDF_FontDef def, struct code_tables *keep)
{
	if (enc == NULL || enc->type != HPDF_ENCODER_TYPE_DOUBLE_BYTE || def == NULL ||
	    def->type != HPDF_FONTDEF_TYPE_TRUETYPE)
		return 0;
	const HPDF_TTF_CmapRange *cm = &((HPDF_TTFontDefAttr)def->attr)->cmap;
	if (cm->format != 4 || cm->seg_count_x2 == 0)
		return 0;
	HPDF_CMapEncoderAttr ea = enc->attr;
	keep->to_unicode_fn = enc->to_unicode_fn;
	memcpy(keep->unicode_map, ea->unicode_map, sizeof keep->unicode_map);
	memcpy(keep->cid_map, ea->cid_map, sizeof keep->cid_map);
	memset(ea->cid_map, 0, sizeof ea->cid_map);
	long last = -1;
	for (int i = 0; i < cm->seg_count_x2 / 2; i++) {
		long lo = cm->start_count[i], hi = cm->end_count[i];
		if (lo == 0xffff || hi < lo)
			continue;      /* the closing segment, or a broken one */
		for (long c = lo; c <= hi; c++) {
			ea->cid_map[c >> 8][c & 0xff] = (HPDF_UINT16)c;
			ea->unicode_map[c >> 8][c & 0xff] = (HPDF_UNICODE)c;
		}
		if (hi > last)
			last = hi;
	}
	if (last >= 0 && last < 0xffff) {
		last++;
		ea->cid_map[last >> 8][last & 0xff] = (HPDF_UINT16)last;
		ea->unicode_map[last >> 8][last & 0xff] = (HPDF_UNICODE)last;
	}
	enc->to_unicode_fn = HPDF_CMapEncoder_ToUnicode;
	return 1;
}

static void
restore_codes(HPDF_Encoder enc, const struct code_tables *keep)
{
	HPDF_CMapEncoderAttr ea = enc->attr;
	enc->to_unicode_fn = keep->to_unicode_fn;
	memcpy(ea->unicode_map, keep->unicode_map, sizeof ea->unicode_map);
	memcpy(ea->cid_map, keep->cid_map, sizeof ea->cid_map);
}

static HPDF_Font
load_font(struct doc *d, const char *path)
{
	const char *name = HPDF_LoadTTFontFromFile(d->pdf, path, HPDF_TRUE);
	if (name == NULL) {
		doc_fail(d, "cannot load font %s", path);
		return NULL;
	}
	struct code_tables *keep = xmalloc(sizeof *keep);
	int narrowed = narrow_codes(d->utf8, HPDF_GetFontDef(d->pdf, name), keep);
	HPDF_Font f = HPDF_GetFont(d->pdf, name, "UTF-8");
	if (narrowed)
		restore_codes(d->utf8, keep);
	free(keep);
	if (f != NULL)
		fix_to_unicode(d, f);
	if (f != NULL)
		trim_cid_map(d, f);
	return f;
}

HPDF_Font
doc_mono_font(struct doc *d)
{
	if (d->mono == NULL && !doc_failed(d))
		d->mono = load_font(d, d->tpl.font_mono);
	return d->mono;
}

/* Parses "YYYY-MM-DD" into a libharu date at 00:00 UTC. */
static int
parse_date(const char *s, HPDF_Date *out)
{
	int y, m, dd;
	char tail;
	if (sscanf(s, "%4d-%2d-%2d%c", &y, &m, &dd, &tail) != 3 || strlen(s) != 10)
		return -1;
	if (y < 1900 || y > 9999 || m < 1 || m > 12 || dd < 1 || dd > 31)
		return -1;
	memset(out, 0, sizeof *out);
	out->year = y;
	out->month = m;
	out->day = dd;
	out->ind = 'Z';
	return 0;
}

static void
set_info(struct doc *d, const struct doc_info *info)
{
	if (info->title != NULL)
		HPDF_SetInfoAttr(d->pdf, HPDF_INFO_TITLE, info->title);
	if (info->author != NULL)
		HPDF_SetInfoAttr(d->pdf, HPDF_INFO_AUTHOR, info->author);
	if (info->subject != NULL)
		HPDF_SetInfoAttr(d->pdf, HPDF_INFO_SUBJECT, info->subject);
	HPDF_SetInfoAttr(d->pdf, HPDF_INFO_CREATOR, "aeroeval " AEROEVAL_VERSION);
	if (info->date != NULL && info->date[0] != '\0') {
		HPDF_Date date;
		if (parse_date(info->date, &date) != 0) {
			doc_fail(d, "bad document date \"%s\" (want YYYY-MM-DD)", info->date);
			return;
		}
		HPDF_SetInfoDateAttr(d->pdf, HPDF_INFO_CREATION_DATE, date);
		HPDF_SetInfoDateAttr(d->pdf, HPDF_INFO_MOD_DATE, date);
	}
}

struct doc *
doc_alloc(const struct template *tpl, const struct doc_info *info)
{
	static const struct doc_info none = { 0 };
	struct doc *d = xcalloc(1, sizeof *d);
	d->tpl = *tpl;
	if (info == NULL)
		info = &none;
	d->title = xstrdup(info->title != NULL ? info->title : "");
	d->mission = xstrdup(info->mission != NULL ? info->mission : "");
	struct doc_meta *m = &d->meta;
	m->title = xstrdup(info->title != NULL ? info->title : "");
	m->author = xstrdup(info->author != NULL ? info->author : "");
	m->subject = xstrdup(info->subject != NULL ? info->subject : "");
	m->doc_number = xstrdup(info->doc_number != NULL ? info->doc_number : "");
	m->revision = xstrdup(info->revision != NULL ? info->revision : "");
	m->input_sha256 = xstrdup(info->input_sha256 != NULL ? info->input_sha256 : "");
	m->catalogue_sha256 = xstrdup(info->catalogue_sha256 != NULL ? info->catalogue_sha256 : "");
	if (info->date != NULL && strlen(info->date) == 10)
		memcpy(d->date, info->date, 11);
	sha256_init(&d->id_ctx);
	d->page_w = tpl->page_width_mm * PT_PER_MM;
	d->page_h = tpl->page_height_mm * PT_PER_MM;
	d->left = tpl->margin_left_mm * PT_PER_MM;
	d->right = d->page_w - tpl->margin_right_mm * PT_PER_MM;
	d->top = d->page_h - tpl->margin_top_mm * PT_PER_MM;
	d->bottom = tpl->margin_bottom_mm * PT_PER_MM;

	d->pdf = HPDF_NewEx(on_hpdf_error, hpdf_alloc, hpdf_free, 0, d);
	if (d->pdf == NULL) {
		doc_fail(d, "cannot create a PDF document");
		return d;
	}
	/* Deflate everything (libharu's zlib level is fixed at the default;
	 * PDF/A-3b leaves only the XMP metadata unfiltered, doc_pdfa.c).
	 * Measured on the SAR example: leaving the page content undeflated
	 * saves 48 M instructions of the dossier's 157 M and makes the PDF
	 * 519 KB instead of 175 KB.  A dossier is mailed and archived, so
	 * the ~15 ms are spent. */
	HPDF_SetCompressionMode(d->pdf, HPDF_COMP_ALL);
	HPDF_UseUTFEncodings(d->pdf);
	HPDF_SetCurrentEncoder(d->pdf, "UTF-8");
	d->utf8 = HPDF_GetEncoder(d->pdf, "UTF-8");
	HPDF_SetPageMode(d->pdf, HPDF_PAGE_MODE_USE_OUTLINE);
	d->font = load_font(d, tpl->font_regular);
	d->bold = load_font(d, tpl->font_bold);
	set_info(d, info);
	doc_pdfa_begin(d);
	if (!doc_failed(d))
		doc_add_page(d);
	return d;
}

void
doc_free(struct doc *d)
{
	if (d == NULL)
		return;
	forget_widths(d->font);
	forget_widths(d->bold);
	forget_widths(d->mono);
	if (d->pdf != NULL)
		HPDF_Free(d->pdf);
	for (int i = 0; i < d->n_toc; i++)
		free(d->toc[i].text);
	free(d->toc);
	free(d->pages);
	free(d->title);
	free(d->mission);
	char **meta[] = { &d->meta.title, &d->meta.author, &d->meta.subject, &d->meta.doc_number,
		&d->meta.revision, &d->meta.input_sha256, &d->meta.catalogue_sha256 };
	for (size_t i = 0; i < sizeof meta / sizeof meta[0]; i++)
		free(*meta[i]);
	free(d);
}

void
doc_global_cleanup(void)
{
	plot_global_cleanup();
}

/* ---- transcript -------------------------------------------------------------- */

void
doc_set_transcript(struct doc *d, struct strbuf *sb)
{
	d->transcript = sb;
}

void
doc_transcribe(struct doc *d, const char *prefix, const char *text)
{
	if (d->transcript == NULL || doc_failed(d))
		return;
	strbuf_append_str(d->transcript, prefix != NULL ? prefix : "");
	for (const char *p = text != NULL ? text : ""; *p != '\0'; p++) {
		if ((unsigned char)p[0] == 0xc2 && (unsigned char)p[1] == 0xa0) {
			strbuf_append_str(d->transcript, " ");
			p++;
		} else {
			strbuf_append(d->transcript, p, 1);
		}
	}
	strbuf_append_str(d->transcript, "\n");
}

/* ---- text blocks ------------------------------------------------------------ */

/* Flows wrapped text from x0 to x1, breaking pages between lines. */
static void
flow_text(struct doc *d, HPDF_Font f, double size, double x0, double x1, const char *text,
          struct template_colour k)
{
	struct lines L = { 0 };
	double lh = size * LEADING;
	doc_wrap(f, size, x1 - x0, text, &L);
	for (int i = 0; i < L.n && !doc_failed(d); i++) {
		if (d->y - lh < d->bottom)
			doc_add_page(d);
		put_text(d, f, size, x0, d->y - size, L.v[i].s, L.v[i].len, k);
		doc_advance(d, lh);
	}
	free(L.v);
}

int
doc_paragraph(struct doc *d, const char *text)
{
	if (doc_failed(d))
		return -1;
	doc_transcribe(d, NULL, text);
	flow_text(d, d->font, d->tpl.font_size_pt, d->left, d->right, text != NULL ? text : "",
	          d->tpl.text);
	if (!d->at_top)
		d->y -= 0.55 * d->tpl.font_size_pt;
	return doc_failed(d) ? -1 : 0;
}

int
doc_code(struct doc *d, const char *text)
{
	HPDF_Font f = doc_mono_font(d);
	if (doc_failed(d))
		return -1;
	doc_transcribe(d, NULL, text);
	flow_text(d, f, 0.85 * d->tpl.font_size_pt, d->left + 6.0, d->right,
	          text != NULL ? text : "", d->tpl.text);
	if (!d->at_top)
		d->y -= 0.55 * d->tpl.font_size_pt;
	return doc_failed(d) ? -1 : 0;
}

int
doc_bullets(struct doc *d, const char *const *items, int n)
{
	double size = d->tpl.font_size_pt, indent = 13.0;
	for (int i = 0; i < n && !doc_failed(d); i++) {
		if (d->y - size * LEADING < d->bottom)
			doc_add_page(d);
		put_text(d, d->font, size, d->left + 3.0, d->y - size, "\xe2\x80\xa2", 3,
		         d->tpl.primary);
		doc_transcribe(d, "\xe2\x80\xa2 ", items[i]);
		flow_text(d, d->font, size, d->left + indent, d->right,
		          items[i] != NULL ? items[i] : "", d->tpl.text);
		d->y -= 0.2 * size;
	}
	if (!d->at_top)
		d->y -= 0.4 * size;
	return doc_failed(d) ? -1 : 0;
}

static void bookmark(struct doc *d, int level, const char *text, double y);

int
doc_title(struct doc *d, const char *title, const char *subtitle)
{
	if (doc_failed(d))
		return -1;
	/* The cover gets its outline entry too; level-2 headings under it nest. */
	bookmark(d, 1, title != NULL ? title : "", d->y);
	doc_transcribe(d, NULL, title);
	if (subtitle != NULL)
		doc_transcribe(d, NULL, subtitle);
	double size = 2.6 * d->tpl.font_size_pt;
	double logo_w = 0.0;
	if (d->tpl.logo[0] != '\0') {
		HPDF_Image img = HPDF_LoadPngImageFromFile(d->pdf, d->tpl.logo);
		if (img != NULL) {
			double iw = HPDF_Image_GetWidth(img), ih = HPDF_Image_GetHeight(img);
			double h = 42.0, w = ih > 0 ? iw * h / ih : h;
			HPDF_Page_DrawImage(d->page, img, (HPDF_REAL)(d->right - w),
			                    (HPDF_REAL)(d->y - h), (HPDF_REAL)w, (HPDF_REAL)h);
			logo_w = w + 12.0;
		}
	}
	d->y -= 0.3 * size;
	flow_text(d, d->bold, size, d->left, d->right - logo_w, title != NULL ? title : "",
	          d->tpl.primary);
	if (subtitle != NULL) {
		d->y -= 2.0;
		flow_text(d, d->font, 1.4 * d->tpl.font_size_pt, d->left, d->right - logo_w,
		          subtitle, d->tpl.muted);
	}
	d->y -= 6.0;
	doc_hrule(d, d->left, d->right, d->y, 1.6, d->tpl.primary);
	doc_advance(d, 14.0);
	return doc_failed(d) ? -1 : 0;
}

static void
bookmark(struct doc *d, int level, const char *text, double y)
{
	HPDF_Outline parent = level == 2 ? d->outline_l1 : NULL;
	HPDF_Outline o = HPDF_CreateOutline(d->pdf, parent, text, d->utf8);
	if (o == NULL)
		return;
	HPDF_Destination dst = HPDF_Page_CreateDestination(d->page);
	if (dst != NULL) {
		HPDF_Destination_SetFitH(dst, (HPDF_REAL)fmin(y + 6.0, d->page_h));
		HPDF_Outline_SetDestination(o, dst);
	}
	HPDF_Outline_SetOpened(o, HPDF_FALSE);
	if (level == 1)
		d->outline_l1 = o;
	if (level == 1 && d->toc_on) {
		if (d->n_toc == d->cap_toc) {
			d->cap_toc = d->cap_toc ? 2 * d->cap_toc : 16;
			d->toc = xrealloc(d->toc, (size_t)d->cap_toc * sizeof *d->toc);
		}
		d->toc[d->n_toc++] = (struct toc_entry){ xstrdup(text), d->n_pages - 1, y };
	}
}

/* Line height of the contents list. */
#define TOC_LEADING 1.6

int
doc_contents(struct doc *d, const char *title, int n_rows)
{
	if (doc_failed(d))
		return -1;
	if (d->toc_on) {
		doc_fail(d, "contents placed twice");
		return -1;
	}
	double lh = TOC_LEADING * d->tpl.font_size_pt;
	double h = n_rows * lh + 3.0 * d->tpl.font_size_pt;
	if (d->y - h < d->bottom && !d->at_top)
		doc_add_page(d);
	doc_heading(d, 2, title != NULL ? title : "Contents");
	d->toc_page = d->n_pages - 1;
	d->toc_top = d->y;
	d->toc_rows = n_rows;
	d->toc_on = 1;
	doc_advance(d, fmin(n_rows * lh, d->y - d->bottom));
	return doc_failed(d) ? -1 : 0;
}

/* Fills the area doc_contents reserved: each heading, a dotted leader, its
 * page number, the whole line a link to the heading. */
static void
draw_contents(struct doc *d)
{
	if (!d->toc_on)
		return;
	double size = d->tpl.font_size_pt, lh = TOC_LEADING * size;
	char num[16];
	d->page = d->pages[d->toc_page];
	for (int i = 0; i < d->n_toc && i < d->toc_rows && !doc_failed(d); i++) {
		const struct toc_entry *e = &d->toc[i];
		double y = d->toc_top - i * lh - size;
		snprintf(num, sizeof num, "%d", e->page + 1);
		double tw = doc_width(d->font, size, e->text, strlen(e->text));
		double nw = doc_width(d->font, size, num, strlen(num));
		put_text(d, d->font, size, d->left + 6.0, y, e->text, strlen(e->text), d->tpl.text);
		put_text(d, d->font, size, d->right - nw, y, num, strlen(num), d->tpl.text);
		HPDF_UINT16 dots[2] = { 1, 3 };
		HPDF_Page_SetRGBStroke(d->page, (HPDF_REAL)d->tpl.muted.r, (HPDF_REAL)d->tpl.muted.g,
		                       (HPDF_REAL)d->tpl.muted.b);
		HPDF_Page_SetLineWidth(d->page, 0.6);
		HPDF_Page_SetDash(d->page, dots, 2, 0);
		HPDF_Page_MoveTo(d->page, (HPDF_REAL)(d->left + 6.0 + tw + 4.0), (HPDF_REAL)(y + 1.0));
		HPDF_Page_LineTo(d->page, (HPDF_REAL)(d->right - nw - 4.0), (HPDF_REAL)(y + 1.0));
		HPDF_Page_Stroke(d->page);
		HPDF_Page_SetDash(d->page, NULL, 0, 0);
		HPDF_Destination dst = HPDF_Page_CreateDestination(d->pages[e->page]);
		if (dst == NULL)
			continue;
		HPDF_Destination_SetFitH(dst, (HPDF_REAL)fmin(e->y + 6.0, d->page_h));
		HPDF_Rect rect = { (HPDF_REAL)d->left, (HPDF_REAL)(y - 0.3 * size),
		                   (HPDF_REAL)d->right, (HPDF_REAL)(y + 0.9 * size) };
		HPDF_Annotation an = HPDF_Page_CreateLinkAnnot(d->page, rect, dst);
		if (an != NULL)
			HPDF_LinkAnnot_SetBorderStyle(an, 0, 0, 0);
	}
}

int
doc_heading(struct doc *d, int level, const char *text)
{
	if (doc_failed(d))
		return -1;
	double base = d->tpl.font_size_pt;
	text = text != NULL ? text : "";
	doc_transcribe(d, level <= 1 ? "# " : level == 2 ? "## " : "### ", text);
	if (level <= 1) {
		if (!d->at_top)
			doc_add_page(d);
		double size = 1.75 * base;
		bookmark(d, 1, text, d->y);
		flow_text(d, d->bold, size, d->left, d->right, text, d->tpl.primary);
		doc_hrule(d, d->left, d->right, d->y + 0.04 * size, 0.8, d->tpl.primary);
		d->y -= 0.7 * base;
	} else {
		double size = level == 2 ? 1.25 * base : 1.05 * base;
		double need = size * LEADING + MIN_LINES_AFTER_HEADING * base * LEADING;
		if (!d->at_top)
			d->y -= 0.5 * base;
		if (d->y - need < d->bottom && !d->at_top)
			doc_add_page(d);
		if (level == 2)
			bookmark(d, 2, text, d->y);
		flow_text(d, d->bold, size, d->left, d->right, text,
		          level == 2 ? d->tpl.primary : d->tpl.text);
		d->y -= 0.25 * base;
		d->after_heading = 1;
	}
	return doc_failed(d) ? -1 : 0;
}

int
doc_callout(struct doc *d, enum doc_callout_style style, const char *title, const char *text)
{
	if (doc_failed(d))
		return -1;
	struct template_colour k = style == DOC_CALLOUT_PASS ? d->tpl.pass
	                         : style == DOC_CALLOUT_FAIL ? d->tpl.fail
	                         : style == DOC_CALLOUT_WARN ? d->tpl.warn : d->tpl.primary;
	double base = d->tpl.font_size_pt, tsize = 1.9 * base, pad = 8.0, bar = 4.0;
	double x0 = d->left + bar + pad, x1 = d->right - pad;
	if (title != NULL)
		doc_transcribe(d, NULL, title);
	if (text != NULL)
		doc_transcribe(d, NULL, text);
	struct lines tl = { 0 }, bl = { 0 };
	if (title != NULL)
		doc_wrap(d->bold, tsize, x1 - x0, title, &tl);
	if (text != NULL)
		doc_wrap(d->font, base, x1 - x0, text, &bl);
	double h = 2 * pad + tl.n * tsize * 1.2 + bl.n * base * LEADING +
	           (tl.n > 0 && bl.n > 0 ? 3.0 : 0.0);
	/* A callout is kept whole unless it is taller than a page. */
	if (d->y - h < d->bottom && !d->at_top)
		doc_add_page(d);
	double y = d->y;
	doc_fill_rect(d, d->left, y - h, d->right - d->left, h, doc_mix_white(k, 0.12));
	doc_fill_rect(d, d->left, y - h, bar, h, k);
	y -= pad;
	for (int i = 0; i < tl.n; i++) {
		put_text(d, d->bold, tsize, x0, y - tsize * 0.95, tl.v[i].s, tl.v[i].len, k);
		y -= tsize * 1.2;
	}
	if (tl.n > 0 && bl.n > 0)
		y -= 3.0;
	for (int i = 0; i < bl.n; i++) {
		put_text(d, d->font, base, x0, y - base, bl.v[i].s, bl.v[i].len, d->tpl.text);
		y -= base * LEADING;
	}
	free(tl.v);
	free(bl.v);
	doc_advance(d, h + 0.9 * base);
	return doc_failed(d) ? -1 : 0;
}

int
doc_figure(struct doc *d, const struct plot *p, const char *caption)
{
	if (doc_failed(d) || p == NULL)
		return -1;
	double tw = d->right - d->left;
	double w = plot_width_pt(p) > 0 ? fmin(plot_width_pt(p), tw) : tw;
	double h = plot_height_pt(p);
	double csize = 0.9 * d->tpl.font_size_pt;
	char *cap = xmalloc(strlen(caption != NULL ? caption : "") + 32);
	sprintf(cap, "Figure %d: %s", d->n_figures + 1, caption != NULL ? caption : "");
	struct lines L = { 0 };
	doc_wrap(d->font, csize, w, cap, &L);
	double need = h + 6.0 + L.n * csize * LEADING;
	if (d->y - need < d->bottom && !d->at_top)
		doc_add_page(d);
	double x = d->left + 0.5 * (tw - w);
	struct plot_render r = { .pdf = d->pdf, .page = d->page, .font = d->font,
	                         .bold = d->bold, .tpl = &d->tpl, .x_pt = x,
	                         .y_top_pt = d->y - 4.0, .width_pt = w,
	                         .transcript = doc_failed(d) ? NULL : d->transcript };
	if (!doc_failed(d) && plot_render(p, &r) != 0)
		doc_fail(d, "figure %d: cairo could not build the paths", d->n_figures + 1);
	d->n_figures++;
	doc_transcribe(d, NULL, cap);
	doc_advance(d, h + 10.0);
	for (int i = 0; i < L.n && !doc_failed(d); i++) {
		/* One line is centred under the figure, several are left aligned. */
		doc_put_aligned(d, d->font, csize, x, x + w, d->y - csize, L.v[i].s, L.v[i].len,
		            L.n == 1 ? DOC_ALIGN_CENTER : DOC_ALIGN_LEFT, d->tpl.muted);
		doc_advance(d, csize * LEADING);
	}
	d->y -= 0.8 * d->tpl.font_size_pt;
	free(L.v);
	free(cap);
	return doc_failed(d) ? -1 : d->n_figures;
}

/* ---- attachment --------------------------------------------------------------- */

/* The catalogue's EmbeddedFiles name tree, made on first use. */
static HPDF_NameTree
embedded_files(struct doc *d)
{
	HPDF_NameDict names = HPDF_Catalog_GetNames(d->pdf->catalog);
	if (names == NULL) {
		names = HPDF_NameDict_New(d->pdf->mmgr, d->pdf->xref);
		if (names == NULL || HPDF_Catalog_SetNames(d->pdf->catalog, names) != HPDF_OK)
			return NULL;
	}
	HPDF_NameTree tree = HPDF_NameDict_GetNameTree(names, HPDF_NAME_EMBEDDED_FILES);
	if (tree == NULL) {
		tree = HPDF_NameTree_New(d->pdf->mmgr, d->pdf->xref);
		if (tree == NULL
		    || HPDF_NameDict_SetNameTree(names, HPDF_NAME_EMBEDDED_FILES, tree) != HPDF_OK)
			return NULL;
	}
	return tree;
}

int
doc_attach(struct doc *d, const char *name, const void *data, size_t n)
{
	if (doc_failed(d))
		return -1;
	/* 255: the longest file name a reader can save the attachment as. */
	if (name == NULL || name[0] == '\0' || strchr(name, '/') != NULL ||
	    strcmp(name, ".") == 0 || strcmp(name, "..") == 0 || strlen(name) > 255) {
		doc_fail(d, "attachment name must be a bare file name");
		return -1;
	}
	/* libharu attaches only a file it reads from disk by path, so the
	 * file specification (PDF 1.7 §7.11.3-4) is built here from memory:
	 * no temporary file, nothing written outside the output folder, and
	 * TMPDIR plays no part.  The spec dictionary is an indirect object
	 * keyed by the bare name in the EmbeddedFiles tree; its /EF entry
	 * holds the compressed stream of the bytes. */
	HPDF_MMgr mm = d->pdf->mmgr;
	HPDF_NameTree tree = embedded_files(d);
	HPDF_Dict spec = tree != NULL ? HPDF_Dict_New(mm) : NULL;
	if (spec == NULL || HPDF_Xref_Add(d->pdf->xref, spec) != HPDF_OK) {
		doc_fail(d, "attachment: cannot create the file specification");
		return -1;
	}
	HPDF_Dict file = HPDF_DictStream_New(mm, d->pdf->xref);
	HPDF_Dict ef = HPDF_Dict_New(mm);
	if (file == NULL || ef == NULL) {
		doc_fail(d, "attachment: cannot create the embedded file");
		return -1;
	}
	file->filter = HPDF_STREAM_FILTER_FLATE_DECODE;
	HPDF_STATUS st = HPDF_Stream_Write(file->stream, data, (HPDF_UINT)n);
	st += HPDF_Dict_AddName(file, "Type", "EmbeddedFile");
	st += HPDF_Dict_Add(ef, "F", file);
	st += HPDF_Dict_AddName(spec, "Type", "Filespec");
	st += HPDF_Dict_Add(spec, "F", HPDF_String_New(mm, name, NULL));
	st += HPDF_Dict_Add(spec, "UF", HPDF_String_New(mm, name, NULL));
	st += HPDF_Dict_Add(spec, "EF", ef);
	st += HPDF_NameTree_Add(tree, HPDF_String_New(mm, name, NULL), spec);
	if (st != HPDF_OK)
		doc_fail(d, "attachment: cannot embed %s", name);
	doc_pdfa_associate(d, spec, file, name, data, n);
	return doc_failed(d) ? -1 : 0;
}

/* ---- save ---------------------------------------------------------------------- */

/* Running header and footer on every page; the cover (page 1) gets only
 * the footer. */
static void
decorate_pages(struct doc *d)
{
	double size = 0.8 * d->tpl.font_size_pt;
	double hy = d->top + 12.0, fy = 0.5 * d->bottom;
	char num[32];
	for (int i = 0; i < d->n_pages && !doc_failed(d); i++) {
		d->page = d->pages[i];
		if (i > 0) {
			put_text(d, d->font, size, d->left, hy, d->title, strlen(d->title), d->tpl.muted);
			doc_put_aligned(d, d->font, size, d->left, d->right, hy, d->mission,
			            strlen(d->mission), DOC_ALIGN_RIGHT, d->tpl.muted);
			doc_hrule(d, d->left, d->right, hy - 4.0, 0.4, d->tpl.grid);
		}
		snprintf(num, sizeof num, "%d / %d", i + 1, d->n_pages);
		doc_put_aligned(d, d->font, size, d->left, d->right, fy, num, strlen(num),
		            DOC_ALIGN_CENTER, d->tpl.muted);
	}
}

int
doc_save_mem(struct doc *d, unsigned char **out, size_t *n)
{
	*out = NULL;
	*n = 0;
	if (d->saved && !doc_failed(d))
		doc_fail(d, "document saved twice");
	if (doc_failed(d))
		return -1;
	d->saved = 1;
	draw_contents(d);
	decorate_pages(d);
	doc_pdfa_finish(d);
	if (doc_failed(d) || HPDF_SaveToStream(d->pdf) != HPDF_OK || doc_failed(d))
		return -1;
	HPDF_UINT32 size = HPDF_GetStreamSize(d->pdf);
	unsigned char *buf = xmalloc(size ? size : 1);
	HPDF_UINT32 got = 0;
	while (got < size) {
		HPDF_UINT32 chunk = size - got;
		HPDF_STATUS st = HPDF_ReadFromStream(d->pdf, buf + got, &chunk);
		got += chunk;
		if (st != HPDF_OK || chunk == 0)
			break;
	}
	if (got != size || size == 0) {
		doc_fail(d, "cannot read the PDF back from memory (%u of %u bytes)", (unsigned)got,
		         (unsigned)size);
		free(buf);
		return -1;
	}
	/* Reading to the end may raise HPDF_STREAM_EOF; that is not a failure. */
	if (doc_failed(d) && HPDF_GetError(d->pdf) == HPDF_STREAM_EOF) {
		d->err[0] = '\0';
		HPDF_ResetError(d->pdf);
	}
	if (doc_failed(d)) {
		free(buf);
		return -1;
	}
	*out = buf;
	*n = size;
	return 0;
}
