/* report_figs.h — the dossier's figure sections (report_figs.c): mission
 * and energy, thermal and electrical traces, structure and resonance,
 * convergence and the endurance explorer.  Called by the driver (report.c)
 * only.
 */
#ifndef AEROEVAL_REPORT_FIGS_H
#define AEROEVAL_REPORT_FIGS_H

struct rep;

/* Section: the phase tables of the record and its references and the
 * power-vs-speed sweep. */
void report_sec_mission(struct rep *rp, const char *title);
/* Section: the record's discharge trace, then every thermal and electrical
 * margin in one table. */
void report_sec_thermal(struct rep *rp, const char *title);
/* Section: the arm sizing of the three designs and the record's resonance
 * figure. */
void report_sec_structure(struct rep *rp, const char *title);
/* Section: how the takeoff mass settled, in an engineer's terms. */
void report_sec_convergence(struct rep *rp, const char *title);
/* Section: hover endurance and takeoff mass against capacity scale, with
 * the design point and where the design of record sits. */
void report_sec_endurance(struct rep *rp, const char *title);

#endif
