/* sens_report.h — the sensitivity suite as text, JSON and PDF.
 *
 * A renderer: reads a finished struct sens_result (sens.h), writes no file
 * (the caller writes the bytes atomically with fsout).  Everything printed is
 * finite: a derivative that could not be taken prints "n/a" in the tables
 * and is left out of the JSON.
 *
 * The dossier may add a "Sensitivity" section (template section id
 * TEMPLATE_SEC_SENSITIVITY, off in the default template) by running the suite
 * (sens_run) and calling sens_report_section() where the section belongs:
 * a heading, one paragraph, the 14-row table and the tornado figure.
 *
 * Who may include it: the command drivers.
 */
#ifndef AEROEVAL_SENS_REPORT_H
#define AEROEVAL_SENS_REPORT_H

#include <stddef.h>
#include <stdio.h>

#include "pdf/doc.h"
#include "study/sens.h"
#include "template/template.h"

/* One row of the sensitivity table, as text. */
struct sens_row {
	char param[96];     /* "Payload mass (delivery role)" */
	char at[48];        /* the mission's value: "1.5 kg" */
	char mtow[48];      /* "+1.692 kg/kg", "n/a" */
	char hover[48];     /* "-1.703 min/kg" */
	char flight[48];    /* approved flight time: "0.000 min/kg" */
	char cross[128];    /* "above 25.4 m/s (MASS_RUNAWAY)", "none" */
};

/* The text of row c.  A one-sided difference is marked "(fwd)"/"(bwd)". */
void sens_report_row(const struct sens_curve *c, struct sens_row *row);

/* The table as plain text (one header line, 14 rows) plus a line naming the
 * nominal design and the solve count; returns 0 or -1 on a write error. */
int sens_report_text(FILE *out, const struct sens_result *s);

/* The same table as tab-separated values for scripts (tests/paper.sh): a
 * header line, then per parameter: key, x0, unit, difference kind, d_mtow,
 * d_hover_min, d_flight_min (empty when not taken), x of the low and the
 * high crossing and their reasons (empty when none).  0 or -1. */
int sens_report_tsv(FILE *out, const struct sens_result *s);

/* sensitivity.json: every curve point and derivative, finite numbers only,
 * deterministic text (no timing).  Ownership: free() the result; never NULL. */
char *sens_report_json(const struct sens_result *s, const char *aeroeval_version);

/* The dossier section: heading (the template's title for
 * TEMPLATE_SEC_SENSITIVITY, "Sensitivity" when the template does not list
 * it), a paragraph, the table and the tornado figure of MTOW change over
 * each sweep's good range.  Returns 0, or -1 when the document is in error
 * (doc_error() says why). */
int sens_report_section(struct doc *d, const struct template *t,
                        const struct sens_result *s);

/* sensitivity.pdf: title, the section above, then one small figure per
 * parameter (MTOW and hover flight time against the parameter, as % change
 * from the nominal, crossings marked) in a grid.  date is "YYYY-MM-DD" or
 * NULL.  Returns 0 with *out and *n set (free() *out), or -1 with err filled. */
int sens_report_pdf(const struct sens_result *s, const struct template *t,
                    const char *date, unsigned char **out, size_t *n,
                    char *err, size_t errlen);

#endif
