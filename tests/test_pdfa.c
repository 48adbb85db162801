/* test_pdfa.c — the dossier is an archive-grade PDF: PDF/A-3b's structural
 * requirements (ISO 19005-3), read back from the bytes aeroeval writes.
 *
 * No PDF/A validator is packaged in Debian 12 (`apt-cache search pdfa`
 * finds none; veraPDF is not in Debian), so the requirements a validator
 * would check first are asserted here on the file itself, object by
 * object: the header's binary comment; a trailer /ID and no /Encrypt; an
 * XMP metadata stream, unfiltered and well-formed XML, that declares
 * pdfaid:part 3 and conformance B and carries the title, document number,
 * revision and input fingerprint, with its dates and tool names equal to
 * the Info dictionary's; an output intent /GTS_PDFA1 with an RGB ICC
 * profile; every font embedded; every annotation printable; the attached
 * mission an associated file (AFRelationship, MIME type, size); every
 * stream's length right.  tests/cli_dossier.sh reads the same with
 * poppler (pdfinfo, pdffonts).
 *
 * A dossier from libharu is plain text between its streams: objects
 * "N 0 obj ... endobj", dictionaries on lines, lengths indirect.
 */
#include "test_util.h"

#include <ctype.h>

#include "cli/cli.h"
#include "cli/pipeline.h"
#include "template/template.h"
#include "pdf/doc.h"
#include "pdf/report.h"
#include "util/xalloc.h"

/* ---- reading the PDF ------------------------------------------------------- */

#define MAX_OBJ 1024

struct pdf {
	const char *b;              /* the file */
	size_t n;
	const char *obj[MAX_OBJ];   /* "N 0 obj\n" of object N, NULL when absent */
	const char *end[MAX_OBJ];   /* its "endobj" */
	const char *trailer;        /* "trailer" */
};

static const char *
find(const char *from, const char *to, const char *s)
{
	size_t k = strlen(s);
	for (const char *p = from; p + k <= to; p++)
		if (memcmp(p, s, k) == 0)
			return p;
	return NULL;
}

static void
pdf_read(struct pdf *p, const unsigned char *bytes, size_t n)
{
	memset(p, 0, sizeof *p);
	p->b = (const char *)bytes;
	p->n = n;
	const char *e = p->b + n;
	for (const char *q = p->b; q < e; q++) {
		if (q > p->b && q[-1] != '\n')
			continue;
		if (!isdigit((unsigned char)*q))
			continue;
		char *after;
		long num = strtol(q, &after, 10);
		if (strncmp(after, " 0 obj\n", 7) != 0 || num <= 0 || num >= MAX_OBJ)
			continue;
		/* A stream holds binary data: its end is the one after "endstream". */
		const char *body = after + 7, *stop = find(body, e, "\nendobj");
		const char *stream = find(body, stop ? stop : e, "\nstream\r\n");
		if (stream != NULL)
			stop = find(find(stream, e, "\nendstream"), e, "\nendobj");
		assert_non_null(stop);
		p->obj[num] = q;
		p->end[num] = stop;
		q = stop;
	}
	p->trailer = find(p->b, e, "\ntrailer\n");
	assert_non_null(p->trailer);
}

/* Object num's text up to its stream, as a NUL-terminated copy (static). */
static const char *
dict(const struct pdf *p, long num)
{
	static char out[8][16384];
	static int k;
	assert_true(num > 0 && num < MAX_OBJ && p->obj[num] != NULL);
	const char *s = find(p->obj[num], p->end[num], "\nstream\r\n");
	const char *e = s != NULL ? s : p->end[num];
	size_t len = (size_t)(e - p->obj[num]);
	char *o = out[k++ % 8];
	if (len >= sizeof out[0])
		len = sizeof out[0] - 1;
	memcpy(o, p->obj[num], len);
	o[len] = '\0';
	return o;
}

/* Object num's stream bytes (n); NULL when it has none. */
static const char *
stream(const struct pdf *p, long num, size_t *n)
{
	const char *s = find(p->obj[num], p->end[num], "\nstream\r\n");
	if (s == NULL)
		return NULL;
	const char *e = find(s, p->b + p->n, "\nendstream");
	*n = (size_t)(e - (s + 9));
	return s + 9;
}

/* The object a key of text refers to ("/Key N 0 R"), or 0. */
static long
ref(const char *text, const char *key)
{
	char k[64];
	snprintf(k, sizeof k, "%s ", key);
	const char *s = strstr(text, k);
	if (s == NULL)
		return 0;
	char *end;
	long num = strtol(s + strlen(k), &end, 10);
	return strncmp(end, " 0 R", 4) == 0 ? num : 0;
}

/* The first object reference inside "/Key [ N 0 R ... ]", or 0. */
static long
first_ref_in_array(const char *text, const char *key)
{
	char k[64];
	snprintf(k, sizeof k, "%s [ ", key);
	const char *s = strstr(text, k);
	return s != NULL ? strtol(s + strlen(k), NULL, 10) : 0;
}

/* An Info dictionary text string (key "/Title"), literal "(...)" or a
 * UTF-16BE hex string "<FEFF...>" with characters below 128, in out. */
static const char *
info_text(const char *info, const char *key, char *out, size_t n)
{
	char k[32];
	snprintf(k, sizeof k, "%s ", key);
	const char *s = strstr(info, k);
	assert_non_null(s);
	s += strlen(k);
	size_t o = 0;
	if (*s == '(') {
		size_t len = strcspn(s + 1, ")");
		snprintf(out, n, "%.*s", (int)len, s + 1);
		return out;
	}
	assert_true(strncmp(s, "<FEFF", 5) == 0);
	for (s += 5; isxdigit((unsigned char)s[0]) && o + 1 < n; s += 4) {
		char unit[5] = { s[0], s[1], s[2], s[3], '\0' };
		long c = strtol(unit, NULL, 16);
		assert_true(c > 0 && c < 128);
		out[o++] = (char)c;
	}
	out[o] = '\0';
	return out;
}

/* ---- a small XML well-formedness check --------------------------------------- */

/* Elements nest and close in order, attributes are quoted, entities are
 * XML's own; processing instructions and comments are skipped. */
static bool
xml_well_formed(const char *s, size_t n)
{
	char stack[64][64];
	int depth = 0, elements = 0;
	const char *e = s + n;
	while (s < e) {
		if (*s == '&') {
			static const char *const ents[] = { "&amp;", "&lt;", "&gt;", "&quot;", "&apos;" };
			bool ok = false;
			for (size_t i = 0; i < 5 && !ok; i++)
				ok = strncmp(s, ents[i], strlen(ents[i])) == 0;
			if (!ok)
				return false;
			s++;
			continue;
		}
		if (*s != '<') {
			s++;
			continue;
		}
		if (strncmp(s, "<?", 2) == 0 || strncmp(s, "<!--", 4) == 0) {
			const char *close = find(s, e, s[1] == '?' ? "?>" : "-->");
			if (close == NULL)
				return false;
			s = close + 2;
			continue;
		}
		bool closing = s[1] == '/';
		s += closing ? 2 : 1;
		size_t len = strcspn(s, " \t\r\n/>");
		if (len == 0 || len >= sizeof stack[0])
			return false;
		char name[64];
		memcpy(name, s, len);
		name[len] = '\0';
		s += len;
		if (closing) {
			s += strspn(s, " \t\r\n");
			if (*s != '>' || depth == 0 || strcmp(stack[--depth], name) != 0)
				return false;
			s++;
			continue;
		}
		for (;;) {   /* attributes: name="value" */
			s += strspn(s, " \t\r\n");
			if (*s == '>' || strncmp(s, "/>", 2) == 0)
				break;
			size_t an = strcspn(s, "= \t\r\n>");
			if (an == 0 || s[an] != '=' || (s[an + 1] != '"' && s[an + 1] != '\''))
				return false;
			const char *q = strchr(s + an + 2, s[an + 1]);
			if (q == NULL || memchr(s + an + 2, '<', (size_t)(q - (s + an + 2))) != NULL)
				return false;
			s = q + 1;
		}
		elements++;
		if (*s == '/') {
			s += 2;
			continue;
		}
		if (depth == 64)
			return false;
		snprintf(stack[depth++], sizeof stack[0], "%s", name);
		s++;
	}
	return depth == 0 && elements > 0;
}

/* The text of <tag>...</tag> in xml (static), or NULL. */
static const char *
xml_value(const char *xml, size_t n, const char *tag)
{
	static char out[512];
	char open[96], close[96];
	snprintf(open, sizeof open, "<%s>", tag);
	snprintf(close, sizeof close, "</%s>", tag);
	const char *s = find(xml, xml + n, open), *e = s ? find(s, xml + n, close) : NULL;
	if (s == NULL || e == NULL)
		return NULL;
	s += strlen(open);
	snprintf(out, sizeof out, "%.*s", (int)(e - s), s);
	return out;
}

/* ---- the fixture ------------------------------------------------------------- */

struct fixture {
	struct cli_env env;
	struct template *tpl;
	struct solve_result *r;
	unsigned char *mission;
	size_t n_mission;
	unsigned char *pdf;
	size_t n_pdf;
};

static unsigned char *
render(struct fixture *fx, const char *date, size_t *n)
{
	struct report_input in = { fx->r, fx->tpl, "sar_imaging_quad", "sar_imaging_quad.json",
		fx->mission, fx->n_mission, date, "9.8.7", fx->env.cat, NULL, NULL, NULL };
	unsigned char *pdf = NULL;
	char err[256];
	assert_int_equal(report_render(&in, &pdf, n, err, sizeof err), 0);
	return pdf;
}

static int
setup(void **state)
{
	struct fixture *fx = xcalloc(1, sizeof *fx);
	if (cli_env_load(&fx->env, NULL, 1, stderr) != 0)
		return -1;
	fx->tpl = template_default();
	fx->r = xmalloc(sizeof *fx->r);
	if (pipeline_solve(&fx->env, "examples/sar_imaging_quad.json", fx->r, stderr,
	    &fx->mission, &fx->n_mission) != PIPE_FEASIBLE)
		return -1;
	fx->pdf = render(fx, "2026-11-22", &fx->n_pdf);
	*state = fx;
	return 0;
}

static int
teardown(void **state)
{
	struct fixture *fx = *state;
	free(fx->pdf);
	free(fx->mission);
	free(fx->r);
	template_free(fx->tpl);
	cli_env_free(&fx->env);
	free(fx);
	doc_global_cleanup();
	return 0;
}

/* The catalogue's object. */
static long
catalog(const struct pdf *p)
{
	long root = ref(p->trailer, "/Root");
	assert_true(root > 0);
	assert_non_null(strstr(dict(p, root), "/Type /Catalog"));
	return root;
}

/* ---- the checks -------------------------------------------------------------- */

static void
file_should_have_a_binary_header_an_id_and_no_encryption(void **state)
{
	struct fixture *fx = *state;
	struct pdf p;
	pdf_read(&p, fx->pdf, fx->n_pdf);
	/* "%PDF-1.n" (n 0..7), then a comment of four bytes above 127. */
	assert_memory_equal(p.b, "%PDF-1.", 7);
	assert_true(p.b[7] >= '0' && p.b[7] <= '7' && p.b[8] == '\n' && p.b[9] == '%');
	for (int i = 10; i < 14; i++)
		assert_true((unsigned char)p.b[i] > 127);
	/* /ID [ <32 hex> <32 hex> ], the same twice; no /Encrypt anywhere. */
	const char *id = strstr(p.trailer, "/ID [ <");
	assert_non_null(id);
	assert_int_equal(strspn(id + 7, "0123456789ABCDEF"), 32);
	assert_memory_equal(id + 7, id + 7 + 35, 32);
	assert_null(find(p.b, p.b + p.n, "/Encrypt"));
	/* The file ends at its %%EOF and an end of line. */
	assert_memory_equal(p.b + p.n - 6, "%%EOF\n", 6);
}

static void
metadata_should_declare_pdfa_3b_and_carry_the_dossier_identity(void **state)
{
	struct fixture *fx = *state;
	struct pdf p;
	pdf_read(&p, fx->pdf, fx->n_pdf);
	long meta = ref(dict(&p, catalog(&p)), "/Metadata");
	assert_true(meta > 0);
	const char *md = dict(&p, meta);
	assert_non_null(strstr(md, "/Type /Metadata"));
	assert_non_null(strstr(md, "/Subtype /XML"));
	assert_null(strstr(md, "/Filter"));
	size_t n;
	const char *xmp = stream(&p, meta, &n);
	assert_non_null(xmp);
	assert_true(xml_well_formed(xmp, n));
	assert_non_null(find(xmp, xmp + n, "<?xpacket begin=\"\xEF\xBB\xBF\" id=\"W5M0MpCehiHzreSzNTczkc9d\"?>"));
	assert_non_null(find(xmp, xmp + n, "<?xpacket end=\"w\"?>"));
	assert_string_equal(xml_value(xmp, n, "pdfaid:part"), "3");
	assert_string_equal(xml_value(xmp, n, "pdfaid:conformance"), "B");
	assert_string_equal(xml_value(xmp, n, "aeroeval:InputSHA256"), fx->r->input_sha256);
	assert_string_equal(xml_value(xmp, n, "aeroeval:CatalogueSHA256"), fx->r->catalogue_sha256);
	assert_string_equal(xml_value(xmp, n, "aeroeval:Revision"), "A");
	assert_string_equal(xml_value(xmp, n, "xmpMM:VersionID"), "A");
	char number[32];
	snprintf(number, sizeof number, "AE-%.4s-%.4s", fx->r->input_sha256, fx->r->input_sha256 + 4);
	for (char *c = number; *c; c++)
		*c = (char)toupper((unsigned char)*c);
	assert_string_equal(xml_value(xmp, n, "aeroeval:DocumentNumber"), number);
	assert_string_equal(xml_value(xmp, n, "dc:identifier"), number);
	/* Every aeroeval property is described by the extension schema. */
	assert_non_null(find(xmp, xmp + n, "<pdfaSchema:prefix>aeroeval</pdfaSchema:prefix>"));
	static const char *const props[] = { "DocumentNumber", "Revision", "InputSHA256",
		"CatalogueSHA256" };
	for (size_t i = 0; i < 4; i++) {
		char t[96];
		snprintf(t, sizeof t, "<pdfaProperty:name>%s</pdfaProperty:name>", props[i]);
		assert_non_null(find(xmp, xmp + n, t));
	}
	/* Equal to the Info dictionary's entries (ISO 19005-3 6.6.3). */
	const char *info = dict(&p, ref(p.trailer, "/Info"));
	char t[256];
	assert_string_equal(info_text(info, "/Title", t, sizeof t),
	                    "SAR imaging quadcopter - design dossier");
	assert_non_null(find(xmp, xmp + n, "<rdf:li xml:lang=\"x-default\">SAR imaging "
	                     "quadcopter - design dossier</rdf:li>"));
	char want[300];
	snprintf(want, sizeof want, "<rdf:li>%s</rdf:li>", info_text(info, "/Author", t, sizeof t));
	assert_non_null(find(xmp, xmp + n, want));
	assert_string_equal(xml_value(xmp, n, "xmp:CreatorTool"),
	                    info_text(info, "/Creator", t, sizeof t));
	assert_string_equal(xml_value(xmp, n, "pdf:Producer"),
	                    info_text(info, "/Producer", t, sizeof t));
	assert_non_null(strstr(info, "/CreationDate (D:20261122000000Z00'00')"));
	assert_string_equal(xml_value(xmp, n, "xmp:CreateDate"), "2026-11-22T00:00:00Z");
	assert_string_equal(xml_value(xmp, n, "xmp:ModifyDate"), "2026-11-22T00:00:00Z");
}

static void
output_intent_should_be_an_rgb_icc_profile(void **state)
{
	struct fixture *fx = *state;
	struct pdf p;
	pdf_read(&p, fx->pdf, fx->n_pdf);
	long oi = first_ref_in_array(dict(&p, catalog(&p)), "/OutputIntents");
	assert_true(oi > 0);
	const char *d = dict(&p, oi);
	assert_non_null(strstr(d, "/Type /OutputIntent"));
	assert_non_null(strstr(d, "/S /GTS_PDFA1"));
	assert_non_null(strstr(d, "/OutputConditionIdentifier ("));
	/* libharu writes the key with a space after it: the name ends there. */
	long prof = ref(d, "/DestOutputProfile");
	if (prof == 0)
		prof = ref(d, "/DestOutputProfile ");
	assert_true(prof > 0);
	assert_non_null(strstr(dict(&p, prof), "/N 3"));
	size_t n;
	assert_non_null(stream(&p, prof, &n));
	assert_true(n > 100);
}

static void
fonts_should_be_embedded_and_annotations_printable(void **state)
{
	struct fixture *fx = *state;
	struct pdf p;
	pdf_read(&p, fx->pdf, fx->n_pdf);
	int descriptors = 0, annots = 0, type0 = 0;
	for (long i = 1; i < MAX_OBJ; i++) {
		if (p.obj[i] == NULL)
			continue;
		const char *d = dict(&p, i);
		if (strstr(d, "/Type /FontDescriptor")) {
			descriptors++;
			assert_true(strstr(d, "/FontFile2 ") || strstr(d, "/FontFile ")
			            || strstr(d, "/FontFile3 "));
		}
		if (strstr(d, "/Type /Font\n")) {
			/* Composite TrueType fonts only: no unembedded base-14. */
			assert_true(strstr(d, "/Subtype /Type0") || strstr(d, "/Subtype /CIDFontType2"));
			type0 += strstr(d, "/Subtype /Type0") != NULL;
		}
		if (strstr(d, "/Type /Annot")) {
			annots++;
			assert_non_null(strstr(d, "/F 4\n"));
		}
	}
	assert_true(type0 >= 2 && descriptors >= type0);
	assert_true(annots >= 10);    /* the contents' links, the BOM's addresses */
}

static void
mission_should_be_an_associated_file(void **state)
{
	struct fixture *fx = *state;
	struct pdf p;
	pdf_read(&p, fx->pdf, fx->n_pdf);
	long spec = first_ref_in_array(dict(&p, catalog(&p)), "/AF");
	assert_true(spec > 0);
	const char *s = dict(&p, spec);
	assert_non_null(strstr(s, "/Type /Filespec"));
	assert_non_null(strstr(s, "/F (sar_imaging_quad.json)"));
	assert_non_null(strstr(s, "/UF (sar_imaging_quad.json)"));
	assert_non_null(strstr(s, "/AFRelationship /Source"));
	assert_non_null(strstr(s, "/Desc ("));
	const char *ef = strstr(s, "/EF");
	assert_non_null(ef);
	long file = ref(ef, "/F");
	assert_true(file > 0);
	const char *f = dict(&p, file);
	assert_non_null(strstr(f, "/Type /EmbeddedFile"));
	assert_non_null(strstr(f, "/Subtype /application#2Fjson"));
	char size[32];
	snprintf(size, sizeof size, "/Size %zu", fx->n_mission);
	assert_non_null(strstr(f, size));
	assert_non_null(strstr(f, "/ModDate (D:20261122000000Z00'00')"));
}

static void
every_stream_length_should_be_its_bytes(void **state)
{
	struct fixture *fx = *state;
	struct pdf p;
	pdf_read(&p, fx->pdf, fx->n_pdf);
	int streams = 0;
	for (long i = 1; i < MAX_OBJ; i++) {
		size_t n;
		if (p.obj[i] == NULL || stream(&p, i, &n) == NULL)
			continue;
		const char *d = dict(&p, i);
		long len_obj = ref(d, "/Length");
		long len = len_obj > 0 ? strtol(dict(&p, len_obj) + strcspn(dict(&p, len_obj), "\n") + 1,
		                                NULL, 10)
		    : strtol(strstr(d, "/Length ") + 8, NULL, 10);
		assert_int_equal((long)n, len);
		streams++;
	}
	assert_true(streams >= 10);
}

/* The same inputs give the same bytes; an undated dossier has no dates in
 * its Info or XMP, and its /ID differs from the dated one's. */
static void
dossier_should_be_reproducible_and_dated_only_by_its_mission(void **state)
{
	struct fixture *fx = *state;
	size_t n;
	unsigned char *again = render(fx, "2026-11-22", &n);
	assert_int_equal(n, fx->n_pdf);
	assert_memory_equal(again, fx->pdf, n);
	free(again);
	unsigned char *undated = render(fx, "", &n);
	struct pdf p;
	pdf_read(&p, undated, n);
	assert_null(strstr(dict(&p, ref(p.trailer, "/Info")), "/CreationDate"));
	size_t xn;
	const char *xmp = stream(&p, ref(dict(&p, catalog(&p)), "/Metadata"), &xn);
	assert_true(xml_well_formed(xmp, xn));
	assert_null(xml_value(xmp, xn, "xmp:CreateDate"));
	assert_null(find(p.b, p.b + p.n, "/ModDate"));
	struct pdf dated;
	pdf_read(&dated, fx->pdf, fx->n_pdf);
	assert_false(memcmp(strstr(p.trailer, "/ID"), strstr(dated.trailer, "/ID"), 44) == 0);
	free(undated);
}

static void
xml_check_should_refuse_what_is_not_well_formed(void **state)
{
	(void)state;
	static const char *const bad[] = { "<a><b></a></b>", "<a x=1/>", "<a>&nbsp;</a>",
		"<a>", "text only", "<a x=\"<\"/>" };
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
		assert_false(xml_well_formed(bad[i], strlen(bad[i])));
	const char *good = "<?xml version=\"1.0\"?><a x='1'><b/>t &amp; u<!-- c --></a>";
	assert_true(xml_well_formed(good, strlen(good)));
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(xml_check_should_refuse_what_is_not_well_formed),
		cmocka_unit_test(file_should_have_a_binary_header_an_id_and_no_encryption),
		cmocka_unit_test(metadata_should_declare_pdfa_3b_and_carry_the_dossier_identity),
		cmocka_unit_test(output_intent_should_be_an_rgb_icc_profile),
		cmocka_unit_test(fonts_should_be_embedded_and_annotations_printable),
		cmocka_unit_test(mission_should_be_an_associated_file),
		cmocka_unit_test(every_stream_length_should_be_its_bytes),
		cmocka_unit_test(dossier_should_be_reproducible_and_dated_only_by_its_mission),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
