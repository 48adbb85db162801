/* index_pdf.h — overview.pdf: a study's design space on two figures and a
 * table.
 *
 * Figure 1 puts every compiled mission's takeoff mass of record against its
 * payload, one marker style per verdict (feasible, infeasible, not
 * buildable), with the prediction interval as a vertical bar where
 * result.json carries one.  Figure 2 puts the cost of the buildable designs
 * (the sum of their known BOM prices: a lower bound where some are
 * unknown) against their hover endurance.  The table lists every row.
 * Names label the markers while there are few enough to read (at most
 * INDEX_PDF_MAX_LABELS).  No date is set: the same rows give the same
 * bytes.
 *
 * PDF layer (doc.h, plot.h).
 */
#ifndef AEROEVAL_INDEX_PDF_H
#define AEROEVAL_INDEX_PDF_H

#include <stddef.h>

#include "result/table_row.h"
#include "template/template.h"

#define INDEX_PDF_MAX_LABELS 16

/* Renders the overview into *pdf (*n bytes; free() it).  Returns 0, or -1
 * with err set (*pdf NULL). */
int index_pdf_render(const struct table_rows *s, const struct template *tpl,
                     unsigned char **pdf, size_t *n, char *err, size_t errlen);

#endif
