/* valreport.h — the validation dossier PDF (`aeroeval validate --report`).
 *
 * Cover with the headline numbers, the predicted-vs-actual log-log scatter
 * (identity line, ±10 % and ±25 % bands), the error-by-class bar figure, the
 * per-row table (rows not in the statistics listed with why), and the
 * mission rule in words.  A renderer over pdf/doc.h and pdf/plot.h; the
 * date is given by the caller (never the clock), so the file is
 * reproducible.
 */
#ifndef AEROEVAL_VALREPORT_H
#define AEROEVAL_VALREPORT_H

#include <stddef.h>

#include "input/cohort.h"
#include "spec/model.h"
#include "study/validate.h"

/* The rule of validate.h in words, NULL-terminated: one bullet each (the
 * README's text says the same). */
extern const char *const valreport_rule_text[];

/* Renders the dossier for v (computed from cohort c read from cohort_name,
 * with the coefficients cal) into a new buffer *pdf of *n bytes (free with
 * free()).  date is "YYYY-MM-DD" or NULL.  Returns 0, or -1 with a message
 * in err. */
int valreport_render(const struct cohort *c, const struct validate_report *v,
                     const struct model_calibration *cal, const char *cohort_name,
                     const char *date, unsigned char **pdf, size_t *n,
                     char *err, size_t errlen);

#endif
