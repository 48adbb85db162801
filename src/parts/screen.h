/* screen.h — is a catalogue entry physically plausible?
 *
 * A catalogue copied from store pages and secondary transcriptions holds
 * typos: a 40 A ESC of 3 g, a pack of 380 Wh/kg, a motor whose maximum
 * power its current cannot carry.  The parts search picks the lightest
 * parts that pass its checks, so it would pick exactly those.  Each screen
 * compares an entry with physics or with the trend of its own category
 * (the fits of sizing.h and prop.h) and names what is off; the search
 * leaves such an entry out unless the mission locks it, and the test
 * tests/test_screen.c requires every one of the shipped catalogue's
 * implausible entries to list the doubtful field as uncertain.
 *
 * Parts layer; no I/O.
 */
#ifndef AEROEVAL_SCREEN_H
#define AEROEVAL_SCREEN_H

#include "catalog/catalog.h"

#define SCREEN_TREND_FACTOR   4.0    /* mass within 1/4..4x its category's trend */
#define SCREEN_VI_SLACK       1.25   /* max power within 1.25 × current × 4.35 V × cells */
#define SCREEN_RI_FACTOR      10.0   /* R and I0 within 1/10..10x the catalogue fit */
#define SCREEN_PACK_MIN_WH_KG 60.0   /* pack specific energy, Wh/kg */
#define SCREEN_PACK_MAX_LIPO  260.0  /* LiPo/LiHV packs (the best cells ~ 280) */
#define SCREEN_PACK_MAX_LIION 350.0  /* Li-ion and solid state: silicon-anode
                                        cells reach 400 Wh/kg bare */
#define SCREEN_PACK_MAX_W_KG  15000.0 /* continuous power per kg (C × Wh/kg) */
#define SCREEN_ESC_MAX_A_G    15.0   /* continuous amps per gram of a single
                                        ESC (racing ESCs rated in 30 m/s of
                                        airflow reach 13) */
#define SCREEN_STACK_MAX_A_G  25.0   /* ... and of a 4-in-1 board (all amps) */
#define SCREEN_FOM_MAX        0.85   /* no static propeller does better */

/* NULL when plausible, else the field at fault and why, e.g.
 * "mass_g: 3 g for 40 A (13.3 A/g, at most 5)" written into why (size n),
 * which is returned. */
const char *screen_motor(const struct catalog_motor *m, char *why, size_t n);
const char *screen_prop(const struct catalog_prop *p, char *why, size_t n);
const char *screen_battery(const struct catalog_battery *b, char *why, size_t n);
const char *screen_esc(const struct catalog_esc *e, char *why, size_t n);

/* A motor's winding resistance and no-load current as the catalogue's
 * fits estimate them (physics/motor.h): from the stator where the entry
 * names one, else from the mass.  Used where the entry publishes none,
 * and to screen what it publishes. */
void screen_motor_estimates(const struct catalog_motor *m, double *r_ohm,
                            double *i0_a);

/* NULL when none of the numbers the parts search sizes on is listed in
 * the entry's `uncertain` (the catalogue's own doubt, README "Entry
 * format"), else the first such key, written into why.  The search builds
 * the design of record on such an entry only when the mission locks it:
 * a number its catalogue doubts cannot carry a bill of materials. */
/* Does the comma-separated `uncertain` list name key? */
bool screen_uncertain(const char *uncertain, const char *key);
const char *screen_doubt_motor(const struct catalog_motor *m, char *why, size_t n);
const char *screen_doubt_prop(const struct catalog_prop *p, char *why, size_t n);
const char *screen_doubt_battery(const struct catalog_battery *b, char *why, size_t n);
const char *screen_doubt_esc(const struct catalog_esc *e, char *why, size_t n);
const char *screen_doubt_frame(const struct catalog_frame *f, char *why, size_t n);

#endif
