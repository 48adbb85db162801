/* doc_pdfa.c — every document as PDF/A-3b (ISO 19005-3, conformance
 * level B): the parts libharu does not write, or writes otherwise.
 *
 * libharu 2.3.0 offers HPDF_PDFA_SetPDFAConformance for PDF/A-1 only, and
 * it would not do here: PDF/A-1 forbids the embedded mission file and the
 * transparency of the figures' translucent fills, its XMP fails on a date
 * in UTC ('Z'), and its trailer /ID is an MD5 of the clock (ctime()), so the
 * same inputs would no longer give the same bytes.  So this module writes
 * PDF/A-3b's requirements itself, with libharu's object layer:
 *
 *   - the output intent (ISO 19005-3 6.2.2-3): an sRGB ICC profile stream
 *     (/N 3, the template's icc_profile, shipped as templates/icc/sRGB.icc)
 *     as /DestOutputProfile of an /OutputIntent /S /GTS_PDFA1 in the
 *     catalogue's /OutputIntents, appended by HPDF_PDFA_AppendOutputIntents
 *     (which writes the key as "DestOutputProfile " with a space: PDF
 *     readers take the name up to the white space, as checked in the
 *     tests);
 *   - the XMP metadata stream (6.6), unfiltered, in the catalogue's
 *     /Metadata: dc:title, dc:creator, dc:description, xmp:CreatorTool,
 *     xmp:CreateDate/ModifyDate and pdf:Producer equal to the Info
 *     dictionary's entries (6.6.3), pdfaid:part 3 and conformance B, the
 *     document's identity (dc:identifier the document number,
 *     xmpMM:VersionID the revision) and its own properties (document
 *     number, revision, input and catalogue fingerprints) in an aeroeval
 *     schema described by a PDF/A extension schema (6.6.2.3);
 *   - the trailer /ID (6.1.3): two equal 16-byte strings, the start of the
 *     SHA-256 of the XMP packet and of every attached file, so a document
 *     is named by what it holds and the same inputs give the same bytes;
 *   - every annotation printable (6.3.2: /F 4; the contents' and the bill
 *     of materials' links);
 *   - the attached mission as an associated file (6.8): its file
 *     specification with /UF, /AFRelationship /Source and /Desc, its stream
 *     with a MIME /Subtype and /Params (/Size, and /ModDate, the document's
 *     date, when it is dated), and the catalogue's /AF naming it.
 * What libharu writes already meets the rest: a binary comment after the
 * header, embedded TrueType fonts (CIDFontType2 with a CIDToGIDMap), no
 * encryption, no JavaScript, DeviceRGB and DeviceGray with an output
 * intent, transparency allowed from PDF/A-2 on.
 */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hpdf.h>
#include <hpdf_objects.h>
#include <hpdf_pdfa.h>
#include <hpdf_streams.h>

#include "pdf/doc_int.h"
#include "util/file.h"
#include "util/sha256.h"
#include "util/strbuf.h"
#include "util/xalloc.h"

#define ICC_MAX ((size_t)1 << 20)    /* an sRGB profile is a few KiB */
#define ICC_NAME "sRGB IEC61966-2.1" /* the output condition's identifier */
#define AEROEVAL_NS "urn:aeroeval:ns:dossier:1.0/"

/* ---- the output intent ---------------------------------------------------- */

void
doc_pdfa_begin(struct doc *d)
{
	if (doc_failed(d))
		return;
	char err[256];
	unsigned char *icc = NULL;
	size_t n = 0;
	if (d->tpl.icc_profile[0] == '\0') {
		doc_fail(d, "no sRGB ICC profile for the PDF/A output intent "
		    "(templates/icc/sRGB.icc is missing)");
		return;
	}
	if (file_read(d->tpl.icc_profile, ICC_MAX, &icc, &n, err, sizeof err) != 0) {
		doc_fail(d, "PDF/A output intent: %s", err);
		return;
	}
	/* An ICC profile: a header of 128 bytes, "acsp" at 36, an RGB device
	 * ("RGB " at 16) for the DeviceRGB the document paints in. */
	if (n < 128 || memcmp(icc + 36, "acsp", 4) != 0 || memcmp(icc + 16, "RGB ", 4) != 0) {
		free(icc);
		doc_fail(d, "%s is not an RGB ICC profile", d->tpl.icc_profile);
		return;
	}
	HPDF_Dict profile = HPDF_DictStream_New(d->pdf->mmgr, d->pdf->xref);
	if (profile == NULL) {
		free(icc);
		doc_fail(d, "PDF/A output intent: cannot create the profile stream");
		return;
	}
	profile->filter = HPDF_STREAM_FILTER_FLATE_DECODE;
	HPDF_STATUS st = HPDF_Dict_AddNumber(profile, "N", 3);
	st += HPDF_Stream_Write(profile->stream, icc, (HPDF_UINT)n);
	free(icc);
	st += HPDF_PDFA_AppendOutputIntents(d->pdf, ICC_NAME, profile);
	if (st != HPDF_OK)
		doc_fail(d, "PDF/A output intent: cannot add it");
}

/* ---- the associated file -------------------------------------------------- */

/* A text string object, or NULL after recording the failure. */
static HPDF_String
text_object(struct doc *d, const char *s)
{
	HPDF_String t = HPDF_String_New(d->pdf->mmgr, s, NULL);
	if (t == NULL)
		doc_fail(d, "PDF/A: cannot create a string");
	return t;
}

/* The "D:YYYYMMDD000000Z00'00'" of a "YYYY-MM-DD" date, as libharu writes
 * the Info dictionary's dates. */
static void
pdf_date(const char *ymd, char out[32])
{
	snprintf(out, 32, "D:%.4s%.2s%.2s000000Z00'00'", ymd, ymd + 5, ymd + 8);
}

void
doc_pdfa_associate(struct doc *d, HPDF_Dict spec, HPDF_Dict file, const char *name,
                   const void *data, size_t n)
{
	if (doc_failed(d))
		return;
	size_t len = strlen(name);
	bool json = len > 5 && strcmp(name + len - 5, ".json") == 0;
	HPDF_MMgr mm = d->pdf->mmgr;
	HPDF_STATUS st = HPDF_Dict_AddName(file, "Subtype", json ? "application/json"
	    : "application/octet-stream");
	HPDF_Dict params = HPDF_Dict_New(mm);
	if (params == NULL) {
		doc_fail(d, "PDF/A: cannot describe the attachment");
		return;
	}
	st += HPDF_Dict_AddNumber(params, "Size", (HPDF_INT)n);
	if (d->date[0] != '\0') {
		char when[32];
		pdf_date(d->date, when);
		st += HPDF_Dict_Add(params, "ModDate", text_object(d, when));
	}
	st += HPDF_Dict_Add(file, "Params", params);
	st += HPDF_Dict_AddName(spec, "AFRelationship", "Source");
	st += HPDF_Dict_Add(spec, "Desc", text_object(d, json ? "The mission file this "
	    "document was compiled from" : "A source file of this document"));
	if (d->af == NULL) {
		d->af = HPDF_Array_New(mm);
		if (d->af == NULL || HPDF_Dict_Add(d->pdf->catalog, "AF", d->af) != HPDF_OK) {
			doc_fail(d, "PDF/A: cannot list the associated files");
			return;
		}
	}
	st += HPDF_Array_Add(d->af, spec);
	if (st != HPDF_OK)
		doc_fail(d, "PDF/A: cannot associate %s", name);
	sha256_update(&d->id_ctx, data, n);
}

/* ---- the XMP metadata ------------------------------------------------------ */

/* s as XML character data. */
static void
xml_text(struct strbuf *sb, const char *s)
{
	for (; *s != '\0'; s++) {
		switch (*s) {
		case '&': strbuf_append_str(sb, "&amp;"); break;
		case '<': strbuf_append_str(sb, "&lt;"); break;
		case '>': strbuf_append_str(sb, "&gt;"); break;
		case '"': strbuf_append_str(sb, "&quot;"); break;
		default:
			/* The texts are valid UTF-8 without control characters
			 * (the mission and template readers refuse others); a tab
			 * or line end still reads as XML white space. */
			strbuf_append_char(sb, *s);
		}
	}
}

/* <tag>text</tag> on its own line, when text is given. */
static void
xml_element(struct strbuf *sb, const char *tag, const char *text)
{
	if (text == NULL || text[0] == '\0')
		return;
	strbuf_printf(sb, "   <%s>", tag);
	xml_text(sb, text);
	strbuf_printf(sb, "</%s>\n", tag);
}

/* A language alternative (dc:title, dc:description) in the default
 * language, as PDF/A equates it with an Info dictionary string. */
static void
xml_alt(struct strbuf *sb, const char *tag, const char *text)
{
	if (text == NULL || text[0] == '\0')
		return;
	strbuf_printf(sb, "   <%s><rdf:Alt><rdf:li xml:lang=\"x-default\">", tag);
	xml_text(sb, text);
	strbuf_printf(sb, "</rdf:li></rdf:Alt></%s>\n", tag);
}

/* The aeroeval properties, described for PDF/A by an extension schema. */
static const struct { const char *name, *description; } aeroeval_props[] = {
	{ "DocumentNumber", "Document number of the design dossier" },
	{ "Revision", "Document revision" },
	{ "InputSHA256", "SHA-256 of the mission file the document was compiled from" },
	{ "CatalogueSHA256", "SHA-256 of the parts catalogue the design was built from" },
};

static void
xmp_extension_schema(struct strbuf *sb)
{
	strbuf_append_str(sb, "   <pdfaExtension:schemas><rdf:Bag>\n"
	    "    <rdf:li rdf:parseType=\"Resource\">\n"
	    "     <pdfaSchema:schema>aeroeval design dossier</pdfaSchema:schema>\n"
	    "     <pdfaSchema:namespaceURI>" AEROEVAL_NS "</pdfaSchema:namespaceURI>\n"
	    "     <pdfaSchema:prefix>aeroeval</pdfaSchema:prefix>\n"
	    "     <pdfaSchema:property><rdf:Seq>\n");
	for (size_t i = 0; i < sizeof aeroeval_props / sizeof aeroeval_props[0]; i++)
		strbuf_printf(sb, "      <rdf:li rdf:parseType=\"Resource\">\n"
		    "       <pdfaProperty:name>%s</pdfaProperty:name>\n"
		    "       <pdfaProperty:valueType>Text</pdfaProperty:valueType>\n"
		    "       <pdfaProperty:category>external</pdfaProperty:category>\n"
		    "       <pdfaProperty:description>%s</pdfaProperty:description>\n"
		    "      </rdf:li>\n", aeroeval_props[i].name, aeroeval_props[i].description);
	strbuf_append_str(sb, "     </rdf:Seq></pdfaSchema:property>\n"
	    "    </rdf:li>\n"
	    "   </rdf:Bag></pdfaExtension:schemas>\n");
}

/* The XMP packet of the document (ISO 16684-1 as PDF/A reads it). */
static void
xmp_packet(const struct doc *d, struct strbuf *sb)
{
	const struct doc_meta *m = &d->meta;
	const char *producer = HPDF_GetInfoAttr(d->pdf, HPDF_INFO_PRODUCER);
	char when[32] = "";
	if (d->date[0] != '\0')
		snprintf(when, sizeof when, "%sT00:00:00Z", d->date);
	strbuf_append_str(sb, "<?xpacket begin=\"\xEF\xBB\xBF\" id=\"W5M0MpCehiHzreSzNTczkc9d\"?>\n"
	    "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\">\n"
	    " <rdf:RDF xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\">\n"
	    "  <rdf:Description rdf:about=\"\"\n"
	    "    xmlns:dc=\"http://purl.org/dc/elements/1.1/\"\n"
	    "    xmlns:xmp=\"http://ns.adobe.com/xap/1.0/\"\n"
	    "    xmlns:xmpMM=\"http://ns.adobe.com/xap/1.0/mm/\"\n"
	    "    xmlns:pdf=\"http://ns.adobe.com/pdf/1.3/\"\n"
	    "    xmlns:pdfaid=\"http://www.aiim.org/pdfa/ns/id/\"\n"
	    "    xmlns:aeroeval=\"" AEROEVAL_NS "\"\n"
	    "    xmlns:pdfaExtension=\"http://www.aiim.org/pdfa/ns/extension/\"\n"
	    "    xmlns:pdfaSchema=\"http://www.aiim.org/pdfa/ns/schema#\"\n"
	    "    xmlns:pdfaProperty=\"http://www.aiim.org/pdfa/ns/property#\">\n"
	    "   <pdfaid:part>3</pdfaid:part>\n"
	    "   <pdfaid:conformance>B</pdfaid:conformance>\n");
	xml_alt(sb, "dc:title", m->title);
	if (m->author[0] != '\0') {
		strbuf_append_str(sb, "   <dc:creator><rdf:Seq><rdf:li>");
		xml_text(sb, m->author);
		strbuf_append_str(sb, "</rdf:li></rdf:Seq></dc:creator>\n");
	}
	xml_alt(sb, "dc:description", m->subject);
	xml_element(sb, "dc:format", "application/pdf");
	xml_element(sb, "dc:identifier", m->doc_number);
	xml_element(sb, "xmpMM:VersionID", m->revision);
	xml_element(sb, "xmp:CreatorTool", "aeroeval " AEROEVAL_VERSION);
	xml_element(sb, "xmp:CreateDate", when);
	xml_element(sb, "xmp:ModifyDate", when);
	xml_element(sb, "xmp:MetadataDate", when);
	xml_element(sb, "pdf:Producer", producer);
	xml_element(sb, "aeroeval:DocumentNumber", m->doc_number);
	xml_element(sb, "aeroeval:Revision", m->revision);
	xml_element(sb, "aeroeval:InputSHA256", m->input_sha256);
	xml_element(sb, "aeroeval:CatalogueSHA256", m->catalogue_sha256);
	xmp_extension_schema(sb);
	strbuf_append_str(sb, "  </rdf:Description>\n"
	    " </rdf:RDF>\n"
	    "</x:xmpmeta>\n"
	    "<?xpacket end=\"w\"?>");
}

/* ---- at save --------------------------------------------------------------- */

/* Every page's annotations printable, and shown (/F 4: Print). */
static void
print_annotations(struct doc *d)
{
	for (int i = 0; i < d->n_pages && !doc_failed(d); i++) {
		HPDF_Array annots = HPDF_Dict_GetItem(d->pages[i], "Annots", HPDF_OCLASS_ARRAY);
		if (annots == NULL) {
			HPDF_ResetError(d->pdf);  /* a page without annotations */
			continue;
		}
		for (HPDF_UINT k = 0; k < annots->list->count; k++) {
			HPDF_Dict a = HPDF_Array_GetItem(annots, k, HPDF_OCLASS_DICT);
			if (a == NULL || HPDF_Dict_AddNumber(a, "F", 4) != HPDF_OK)
				doc_fail(d, "PDF/A: cannot flag an annotation printable");
		}
	}
}

void
doc_pdfa_finish(struct doc *d)
{
	if (doc_failed(d))
		return;
	print_annotations(d);
	struct strbuf xmp = STRBUF_INIT;
	xmp_packet(d, &xmp);
	HPDF_Dict meta = HPDF_DictStream_New(d->pdf->mmgr, d->pdf->xref);
	HPDF_Array id = HPDF_Array_New(d->pdf->mmgr);
	if (meta == NULL || id == NULL) {
		strbuf_free(&xmp);
		doc_fail(d, "PDF/A: cannot create the metadata");
		return;
	}
	/* Unfiltered: a reader finds the packet by scanning, as XMP allows. */
	meta->filter = HPDF_STREAM_FILTER_NONE;
	HPDF_STATUS st = HPDF_Dict_AddName(meta, "Type", "Metadata");
	st += HPDF_Dict_AddName(meta, "Subtype", "XML");
	st += HPDF_Stream_Write(meta->stream, (const HPDF_BYTE *)xmp.data, (HPDF_UINT)xmp.len);
	st += HPDF_Dict_Add(d->pdf->catalog, "Metadata", meta);
	/* The trailer's /ID: what the document holds, not when it was made.
	 * libharu adds its own (from the clock) only when none is there. */
	unsigned char digest[SHA256_DIGEST_LEN];
	sha256_update(&d->id_ctx, xmp.data, xmp.len);
	sha256_final(&d->id_ctx, digest);
	st += HPDF_Array_Add(id, HPDF_Binary_New(d->pdf->mmgr, digest, 16));
	st += HPDF_Array_Add(id, HPDF_Binary_New(d->pdf->mmgr, digest, 16));
	st += HPDF_Dict_Add(d->pdf->trailer, "ID", id);
	strbuf_free(&xmp);
	if (st != HPDF_OK)
		doc_fail(d, "PDF/A: cannot write the metadata");
}
