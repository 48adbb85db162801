/* report_tables.h — the dossier's table sections (report_tables.c): the
 * mass budget, the bill of materials, the checks and the appendix.  Called
 * by the driver (report.c) only.
 */
#ifndef AEROEVAL_REPORT_TABLES_H
#define AEROEVAL_REPORT_TABLES_H

struct rep;

/* Section: every mass item of the three designs, as stacked bars and as a
 * table with each item's share of its design's takeoff mass. */
void report_sec_mass(struct rep *rp, const char *title);
/* Section: the BOM lines with totals, or why there are none and what the
 * continuous design asks of suppliers instead. */
void report_sec_bom(struct rep *rp, const char *title);
/* Section: the verdict on the design of record, the violations with fixes,
 * the record's checks, then those of the two references. */
void report_sec_checks(struct rep *rp, const char *title);
/* Section: every field of the mission contract as this build used it,
 * marking where each value came from. */
void report_sec_appendix(struct rep *rp, const char *title);

#endif
