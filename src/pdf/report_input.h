/* report_input.h — what one dossier is rendered from (struct report_input).
 *
 * The caller fills it (report.h: report_render()); the driver and every
 * section read it through struct rep (report_util.h).  A header of its own
 * so that the sections see the input without seeing the driver.
 *
 * Who may include it: report.h and report_util.h.
 */
#ifndef AEROEVAL_REPORT_INPUT_H
#define AEROEVAL_REPORT_INPUT_H

#include <stddef.h>

struct catalog;
struct doc;
struct solve_result;
struct strbuf;
struct template;

/* Draws an optional section into the dossier (the study layer's trade
 * study): returns 0, or -1 when it could not. */
typedef int report_section_fn(struct doc *d, const struct template *t,
                              const void *arg);

/* Everything one dossier needs.  Only r and tpl are required; a NULL
 * string prints as absent, a NULL mission_bytes attaches nothing. */
struct report_input {
	const struct solve_result *r;          /* the solve */
	const struct template *tpl;            /* layout, sections, colours */
	const char *mission_name;              /* output folder name, e.g. "sar_imaging_quad" */
	const char *mission_file_name;         /* bare name for the attachment, e.g. "sar_imaging_quad.json" */
	const unsigned char *mission_bytes;    /* the mission file, embedded as attachment */
	size_t mission_len;
	const char *date;                      /* "YYYY-MM-DD", already resolved by the caller */
	const char *engine_version;            /* AEROEVAL_VERSION */
	const struct catalog *cat;             /* may be NULL: for the crosshair figure (all motors) and the appendix */
	report_section_fn *sensitivity;        /* may be NULL: draws the optional Sensitivity section */
	const void *sensitivity_arg;           /* ... from this */
	struct strbuf *transcript;             /* may be NULL: receives the dossier's
	                                          text as drawn (doc_set_transcript()) */
};

#endif
