/* report_cover.h — the dossier's opening sections (report_cover.c): the
 * cover, the document control and contents, the executive summary and the
 * design rationale.  Called by the driver (report.c) only.
 */
#ifndef AEROEVAL_REPORT_COVER_H
#define AEROEVAL_REPORT_COVER_H

#include <stddef.h>

struct rep;
struct solve_result;

/* The dossier's document number, from the input fingerprint
 * ("AE-4FBB-C60E"), in buf: the same mission file always carries the same
 * number. */
const char *report_doc_number(const struct solve_result *r, char *buf, size_t n);

/* The cover: the status first, the key figures of the design of record
 * beside the continuous optimum, the dossier's identity.  `first` is
 * nonzero when it opens the document.  Not numbered. */
void report_sec_cover(struct rep *rp, int first);
/* The page after the cover: who prepared, checked and approved this
 * revision, its history, then the contents with page numbers. */
void report_sec_control(struct rep *rp);
/* Section: the design of record beside its two references, the parts, the
 * role overhead, the regulatory class, the assumptions. */
void report_sec_summary(struct rep *rp, const char *title);
/* Section: the engine's rationale sentences in order; a design that cannot
 * be built as specified leads with what failed. */
void report_sec_rationale(struct rep *rp, const char *title);

#endif
