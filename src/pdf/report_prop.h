/* report_prop.h — the dossier's propulsion section (report_prop.c).
 * Called by the driver (report.c) only.
 */
#ifndef AEROEVAL_REPORT_PROP_H
#define AEROEVAL_REPORT_PROP_H

struct rep;

/* Section: the parts of record, the continuous optimum they were aimed
 * at, the motor crosshair, the operating points on the real parts, what
 * the aircraft can do beyond its mission, the model constants used and
 * the feasibility gates. */
void report_sec_propulsion(struct rep *rp, const char *title);

#endif
