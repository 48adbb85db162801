/* report.h — the design dossier (dossier.pdf, README.md): what it says.
 *
 * doc.h and plot.h know how a page looks; this module knows what a client,
 * a procurement team and an archive need to read about one solve: the
 * cover with the verdict, the executive summary, the rationale, the mass
 * budget, mission energy, thermal and electrical traces, structure and
 * resonance, propulsion selection, convergence, the endurance explorer, the
 * bill of materials, the checks and the appendix with the whole defaulted
 * mission.  Sections appear in the template's order, each only if enabled,
 * under the template's titles; the mission file travels inside the PDF as
 * an attachment.  An infeasible design gets the full dossier too.
 *
 * Colours are fixed by role in every figure: the baseline run is palette
 * entry 0, the custom run entry 1, the BOM-closed run entry 2.
 *
 * The output depends only on the input (no clock, no environment), so two
 * renders of the same solve are byte-identical.  Reentrant: several
 * missions may be rendered in parallel.
 *
 * Who may include it: the command layer (cli_*.c) and the tests.
 */
#ifndef AEROEVAL_REPORT_H
#define AEROEVAL_REPORT_H

#include <stddef.h>

#include "pdf/report_input.h"
#include "result/result.h"
#include "template/template.h"

/* Renders the dossier into a new buffer (*pdf, *n).  Returns 0, or -1 with
 * a one-line message in err (nothing returned: *pdf NULL, *n 0).
 * Ownership: the caller frees *pdf with free(). */
int report_render(const struct report_input *in, unsigned char **pdf, size_t *n,
                  char *err, size_t errlen);


#endif
