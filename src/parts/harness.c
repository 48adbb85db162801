/* harness.c — the power harness of a closing in copper: each run's wire
 * gauge for the current it carries at full throttle, and its mass.
 *
 * The continuous model sizes the harness by a calibrated coefficient times
 * current times wheelbase (sizing/airframe.c), which on a 5-inch racer
 * gives under a gram for 57 A.  The design of record's harness is the
 * copper its parts need instead, in three runs:
 *
 *   main  one pair of conductors from the packs' junction to the
 *         distribution point, carrying the whole battery current, half
 *         an arm long (the pack bay and the distribution board both sit
 *         in the centre body, whose size follows the wheelbase: an
 *         estimate, HARNESS_MAIN_FRAC);
 *   pack  with several packs, each pack's lead to the junction (series
 *         jumpers and parallel leads alike), carrying its share, a
 *         quarter arm long (HARNESS_PACK_FRAC, an estimate);
 *   arm   with ESCs out on the arms (single ESCs, or an integrated
 *         system's), each rotor's pair of DC conductors along its arm,
 *         carrying one motor's current.  A 4-in-1 board sits in the
 *         centre and the motors' own leads, in their published mass,
 *         reach it: no arm run.
 *
 * Each conductor is the lightest AWG gauge whose chassis-wiring ampacity
 * carries the run's full-throttle current, continuously: conservative for
 * a 10 s burst, but the same wire carries the sustained current for the
 * whole flight and the table gives no short-time rating.  Beyond the
 * largest gauge, wires of one gauge run in parallel.  The mass is the
 * copper's (8960 kg/m^3); insulation, lugs and solder are not counted.
 *
 * Parts layer; no I/O.
 */
#include <math.h>
#include <string.h>

#include "parts/parts_int.h"

#define COPPER_KG_M3      8960.0 /* density of copper */
#define HARNESS_MAIN_FRAC 0.5    /* main lead, of the arm length */
#define HARNESS_PACK_FRAC 0.25   /* each pack's lead, of the arm length */

/* American Wire Gauge copper: the area, and the "maximum amps for chassis
 * wiring" of the Handbook of Electronic Tables and Formulas for American
 * Wire Gauge (short runs in open air), as tabulated at
 * https://utilitiesbunker.com/kb/awg-current-capacity (its chassis
 * column; the same figures as the chassis-wiring column of the table at
 * https://www.oocities.org/dtmcbride/home_garden/wire.html).  Lightest
 * first. */
static const struct {
	const char *awg;
	double area_mm2;
	double ampacity_a;
} gauges[] = {
	{ "22", 0.326, 7.0 },   { "20", 0.518, 11.0 }, { "18", 0.823, 16.0 },
	{ "16", 1.31, 22.0 },   { "14", 2.08, 32.0 },  { "12", 3.31, 41.0 },
	{ "10", 5.26, 55.0 },   { "8", 8.37, 73.0 },   { "6", 13.3, 101.0 },
	{ "4", 21.2, 135.0 },   { "2", 33.6, 181.0 },  { "1", 42.4, 211.0 },
	{ "1/0", 53.5, 245.0 }, { "2/0", 67.4, 283.0 }, { "3/0", 85.0, 328.0 },
	{ "4/0", 107.2, 380.0 },
};
#define N_GAUGES (sizeof gauges / sizeof gauges[0])

void
parts_harness_run(double current_a, double length_m, int n_runs,
                  struct parts_run *out)
{
	memset(out, 0, sizeof *out);
	if (!(current_a > 0.0) || !(length_m > 0.0) || n_runs <= 0)
		return;
	const double largest = gauges[N_GAUGES - 1].ampacity_a;
	int parallel = (int)ceil(current_a / largest);
	if (parallel < 1)
		parallel = 1;
	size_t g = 0;
	while (g + 1 < N_GAUGES && (double)parallel * gauges[g].ampacity_a < current_a)
		g++;
	out->awg = gauges[g].awg;
	out->area_mm2 = gauges[g].area_mm2;
	out->parallel = parallel;
	out->ampacity_a = (double)parallel * gauges[g].ampacity_a;
	out->current_a = current_a;
	out->length_m = length_m;
	out->n_runs = n_runs;
	/* Two conductors a run (plus and minus). */
	out->kg = (double)n_runs * 2.0 * (double)parallel * gauges[g].area_mm2 * 1e-6
	    * length_m * COPPER_KG_M3;
}

void
parts_harness(const struct parts_ctx *x, const struct parts_pack *pk,
              const struct catalog_esc *esc, struct parts_kit *kit)
{
	const struct sizing_params *p = x->p;
	double arm_m = 0.5 * p->wheelbase_m;
	int n_packs = pk->series * pk->parallel;
	parts_harness_run(kit->load.full_a, HARNESS_MAIN_FRAC * arm_m, 1,
	    &kit->harness_main);
	if (n_packs > 1)
		parts_harness_run(kit->load.full_a / (double)pk->parallel,
		    HARNESS_PACK_FRAC * arm_m, n_packs, &kit->harness_pack);
	else
		memset(&kit->harness_pack, 0, sizeof kit->harness_pack);
	/* ESCs on the arms: one per rotor, or an integrated system's. */
	if (esc == NULL || esc->channels <= 1)
		parts_harness_run(kit->load.motor_full_a, arm_m, p->n_rotors,
		    &kit->harness_arm);
	else
		memset(&kit->harness_arm, 0, sizeof kit->harness_arm);
	kit->harness_kg = kit->harness_main.kg + kit->harness_pack.kg
	    + kit->harness_arm.kg;
}
