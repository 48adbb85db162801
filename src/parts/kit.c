/* kit.c — the parts around the propulsion: a frame kit where one fits, the
 * avionics set of the airframe class, and the battery connectors (see
 * parts.h).
 *
 * Avionics.  Each airframe class carries a set of kinds (flight
 * controller, GNSS, receiver, telemetry radio, power module), each taken
 * as the lightest usable catalogue part of that kind that meets the
 * class's need and the aircraft's bus and current.  What the class carries
 * that the catalogue does not sell as a part (obstacle sensors, spray
 * radars, a pump controller), and any kind no catalogue part fits, stays
 * an allowance: the mass data/airframes.json's class note gives that
 * group, as a custom line of the bill of materials.  So the record's
 * avionics mass is the parts it orders plus what it cannot order yet, and
 * it equals the BOM's avionics lines.
 *
 * Frame kit.  A kit fits when it carries the mission's rotors (coaxial
 * alike), its wheelbase is within PARTS_KIT_WHEELBASE_TOL below the
 * mission's (never above: the wheelbase is a ceiling), the class matches
 * where the kit names one, the propeller fits its limit and the overlap
 * limit of its own wheelbase, the takeoff mass is within its published
 * maximum, its arm tube is no thinner than the one the loads need (where
 * it publishes one), none of its deciding numbers is doubted, and it weighs
 * at most twice the custom arms and centre frame the loads need (a heavier
 * kit is built for a heavier aircraft).  The lightest that fits replaces
 * the custom arm tubes and centre frame; the body, landing gear and shell
 * stay the model's.
 *
 * Connectors.  A pack's own connector is in its published mass; each
 * pack is joined to the harness (or the series lead) by one more mated
 * pair.  That pair is the pack's own family where the pack names one the
 * catalogue has (an XT60 pack mates only with an XT60: the check of its
 * rating then says whether the pack's plug carries the current); else the
 * catalogue connector with the smallest rating that carries the pack's
 * share of the sustained current, several pairs per pack when none carries
 * it alone.  So many small packs cost their connections, which the
 * harness model (one battery lead) omits.
 *
 * Parts layer; no I/O.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parts/parts_int.h"
#include "parts/screen.h"
#include "physics/aero.h"
#include "util/units.h"
#include "util/xalloc.h"

#define PARTS_KIT_WHEELBASE_TOL 0.10  /* a kit up to 10 % below the wheelbase */
#define PARTS_UNRATED_PM_CELLS  6     /* bus of a power module with no range */
#define PARTS_MAX_CONNECTORS    4     /* pairs per pack in parallel */
#define PARTS_KIT_MASS_FACTOR   2.0   /* a kit at most twice the custom arms
                                         and centre frame it replaces */

/* What one class carries: a catalogue kind with its need, or (kind NULL)
 * an item no catalogue part supplies; allowance_kg is the mass of that
 * group in the class note of data/airframes.json, used when no part fits. */
struct kit_item {
	const char *kind;
	const char *need;          /* meets() key, or NULL for any */
	const char *what;          /* the item in words (allowance lines) */
	double allowance_kg;
};

#define KIT_MAX_ITEMS 7
static const struct kit_item kit_items[AF_CLASS_MAX][KIT_MAX_ITEMS] = {
	[AF_MICRO_AIO] = {
		{ "flight_controller", NULL, "Flight controller", 0.012 },
		{ "receiver", NULL, "Control receiver", 0.004 },
		{ "video_tx", NULL, "Video transmitter", 0.008 },
		{ "camera_fpv", NULL, "FPV camera", 0.006 },
	},
	[AF_CONSUMER_FOLDING] = {
		{ "flight_controller", "any", "Flight controller and IMU", 0.020 },
		{ "gnss", "compass", "GNSS and compass", 0.020 },
		{ "receiver", NULL, "Control receiver", 0.010 },
		{ "telemetry", NULL, "Telemetry and video link", 0.025 },
		{ "power_module", "current", "Power distribution", 0.020 },
		{ NULL, NULL, "Obstacle sensors", 0.025 },
	},
	[AF_ENTERPRISE_RUGGED] = {
		{ "flight_controller", "redundant", "Redundant flight controller", 0.060 },
		{ "gnss", "compass", "GNSS and compass", 0.080 },
		{ "receiver", NULL, "Control receiver", 0.010 },
		{ "telemetry", NULL, "Long-range datalink", 0.090 },
		{ "power_module", "current", "Power distribution", 0.050 },
		{ NULL, NULL, "Sensors (rangefinder, ADS-B receiver, lights)", 0.060 },
	},
	[AF_AGRICULTURAL] = {
		{ "flight_controller", "redundant", "Redundant flight controller", 0.060 },
		{ "gnss", "rtk", "RTK GNSS", 0.080 },
		{ "receiver", NULL, "Control receiver", 0.010 },
		{ "telemetry", NULL, "Datalink", 0.090 },
		{ "power_module", "current", "Power distribution", 0.200 },
		{ NULL, NULL, "Terrain and obstacle radars", 0.200 },
		{ NULL, NULL, "Pump and flow controller", 0.160 },
	},
};

/* Does the part's description say it? (Case as written in the catalogue.) */
static bool
says(const struct catalog_avionics *a, const char *word)
{
	return strstr(a->description, word) != NULL;
}

/* Does avionics part a meet need on a bus of `cells` carrying
 * sustained_a? */
static bool
meets(const struct catalog_avionics *a, const char *kind, const char *need,
      int cells, double sustained_a)
{
	if (!a->usable || strcmp(a->kind, kind) != 0)
		return false;
	if ((a->cells_min > 0 && cells < a->cells_min)
	    || (a->cells_max > 0 && cells > a->cells_max))
		return false;
	/* A flight controller with an ESC on board (an all-in-one board)
	 * would replace the ESCs the search picks: not taken. */
	if (strcmp(kind, "flight_controller") == 0 && a->max_current_a > 0.0)
		return false;
	if (need == NULL || strcmp(need, "any") == 0)
		return true;
	if (strcmp(need, "redundant") == 0)
		return says(a, "dual IMU") || says(a, "triple IMU");
	if (strcmp(need, "compass") == 0)
		return (says(a, "compass") && !says(a, "without compass"))
		    || says(a, "RTK");
	if (strcmp(need, "rtk") == 0)
		return says(a, "RTK");
	if (strcmp(need, "current") == 0) {
		int hi = a->cells_max > 0 ? a->cells_max : PARTS_UNRATED_PM_CELLS;
		return cells <= hi && a->max_current_a >= sustained_a;
	}
	return false;
}

/* Is a catalogue frame kit one the search may offer at all: every
 * needed number known and none in doubt (screen.h)?  The catalogue's
 * answer, the same for every closing: parts_kit_init() asks it once. */
static bool
frame_offered(const struct catalog_frame *f)
{
	char why[128];
	return f->usable && screen_doubt_frame(f, why, sizeof why) == NULL;
}

void
parts_kit_init(struct parts_ctx *x)
{
	x->n_kit_kinds = 0;
	size_t n = catalog_n_avionics(x->cat);
	for (size_t i = 0; i < n; i++) {
		const struct catalog_avionics *a = catalog_avionics(x->cat, i);
		if (!a->usable)
			continue;
		int k = 0;
		while (k < x->n_kit_kinds && strcmp(x->kit_kinds[k].kind, a->kind) != 0)
			k++;
		if (k == x->n_kit_kinds) {
			if (k == PARTS_KIT_KINDS)
				continue;   /* more kinds than catalog_io knows: not ours */
			x->kit_kinds[k].kind = a->kind;
			x->kit_kinds[k].items = xcalloc(n, sizeof *x->kit_kinds[k].items);
			x->kit_kinds[k].n = 0;
			x->n_kit_kinds++;
		}
		x->kit_kinds[k].items[x->kit_kinds[k].n++] = a;
	}
	size_t nf = catalog_n_frames(x->cat);
	x->kit_frames = xcalloc(nf > 0 ? nf : 1, sizeof *x->kit_frames);
	x->n_kit_frames = 0;
	for (size_t i = 0; i < nf; i++)
		if (frame_offered(catalog_frame(x->cat, i)))
			x->kit_frames[x->n_kit_frames++] = catalog_frame(x->cat, i);
}

void
parts_kit_free(struct parts_ctx *x)
{
	for (int k = 0; k < x->n_kit_kinds; k++)
		free(x->kit_kinds[k].items);
	x->n_kit_kinds = 0;
	free(x->kit_frames);
	x->kit_frames = NULL;
	x->n_kit_frames = 0;
}

/* The usable parts of one kind, in catalogue order. */
static const struct parts_kit_kind *
of_kind(const struct parts_ctx *x, const char *kind)
{
	for (int k = 0; k < x->n_kit_kinds; k++)
		if (strcmp(x->kit_kinds[k].kind, kind) == 0)
			return &x->kit_kinds[k];
	return NULL;
}

/* The lightest part of kind meeting need (ties by id: deterministic). */
static const struct catalog_avionics *
lightest(const struct parts_ctx *x, const char *kind, const char *need,
         int cells, double sustained_a)
{
	const struct catalog_avionics *best = NULL;
	const struct parts_kit_kind *kk = of_kind(x, kind);
	for (int i = 0; kk != NULL && i < kk->n; i++) {
		const struct catalog_avionics *a = kk->items[i];
		if (!meets(a, kind, need, cells, sustained_a))
			continue;
		if (best == NULL || a->mass_kg < best->mass_kg
		    || (a->mass_kg == best->mass_kg && strcmp(a->id, best->id) < 0))
			best = a;
	}
	/* Agricultural power distribution: a distribution board will do. */
	kk = best == NULL && strcmp(kind, "power_module") == 0 ? of_kind(x, "pdb") : NULL;
	for (int i = 0; kk != NULL && i < kk->n; i++) {
		const struct catalog_avionics *a = kk->items[i];
		if (meets(a, "pdb", need, cells, sustained_a)
		    && (best == NULL || a->mass_kg < best->mass_kg))
			best = a;
	}
	return best;
}

/* The family of a connector's name: its letters and digits, upper case,
 * up to the first space, "(" or "/" ("XT90-S (mated pair)" and "xt90s"
 * both read "XT90S"). */
static void
connector_family(const char *name, char *out, size_t n)
{
	size_t k = 0;
	for (; *name != '\0' && *name != ' ' && *name != '(' && *name != '/'; name++)
		if (isalnum((unsigned char)*name) && k + 1 < n)
			out[k++] = (char)toupper((unsigned char)*name);
	out[k] = '\0';
}

/* Does a pack's connector text ("XT60", "AS150/XT150") name the family of
 * catalogue connector a? */
static bool
mates_with(const char *pack_connector, const struct catalog_avionics *a)
{
	char want[32], have[32];
	connector_family(a->part_number, have, sizeof have);
	if (have[0] == '\0')
		return false;
	for (const char *p = pack_connector; *p != '\0'; ) {
		connector_family(p, want, sizeof want);
		if (strcmp(want, have) == 0)
			return true;
		const char *slash = strchr(p, '/');
		if (slash == NULL)
			break;
		p = slash + 1;
	}
	return false;
}

static void
pick_connector(const struct parts_ctx *x, double per_pack_a,
               struct parts_kit *kit, int n_packs, const char *pack_connector)
{
	const struct catalog_avionics *best = NULL, *largest = NULL;
	const struct parts_kit_kind *kk = of_kind(x, "connector");
	/* The pack's own family, one pair per pack (a pack has one plug),
	 * when it carries the pack's current; else the plug is re-terminated
	 * to a connector that does (below). */
	for (int i = 0; pack_connector != NULL && pack_connector[0] != '\0'
	    && kk != NULL && i < kk->n; i++)
		if (mates_with(pack_connector, kk->items[i])
		    && kk->items[i]->max_current_a >= per_pack_a) {
			kit->connector = kk->items[i];
			kit->connector_mates = true;
			kit->n_connectors = n_packs;
			kit->connector_kg = (double)n_packs * kk->items[i]->mass_kg;
			return;
		}
	for (int i = 0; kk != NULL && i < kk->n; i++) {
		const struct catalog_avionics *a = kk->items[i];
		if (!(a->max_current_a > 0.0))
			continue;
		if (largest == NULL || a->max_current_a > largest->max_current_a)
			largest = a;
		if (a->max_current_a >= per_pack_a && (best == NULL
		    || a->max_current_a < best->max_current_a))
			best = a;
	}
	int per_pack = 1;
	if (best == NULL && largest != NULL) {
		per_pack = (int)ceil(per_pack_a / largest->max_current_a);
		if (per_pack <= PARTS_MAX_CONNECTORS)
			best = largest;
	}
	kit->connector = best;
	kit->n_connectors = best != NULL ? per_pack * n_packs : 0;
	kit->connector_kg = best != NULL ? (double)kit->n_connectors * best->mass_kg
	    : 0.0;
}

/* Does the ESC board carry avionics kind (its `carries` list)? */
static bool
esc_carries(const struct catalog_esc *esc, const char *kind)
{
	return esc != NULL && catalog_list_names(esc->carries, kind);
}

void
parts_kit_pick(const struct parts_ctx *x, const struct parts_option *o,
               const struct parts_pack *pk, const struct catalog_esc *esc,
               double sustained_a, struct parts_kit *kit)
{
	memset(kit, 0, sizeof *kit);
	kit->sized_for_a = sustained_a;
	int cls = x->spec->airframe_class;
	if (cls < 0 || cls >= AF_CLASS_MAX)
		cls = AF_ENTERPRISE_RUGGED;
	for (int i = 0; i < KIT_MAX_ITEMS; i++) {
		const struct kit_item *it = &kit_items[cls][i];
		if (it->what == NULL)
			break;
		/* An all-in-one board's flight controller, receiver or video
		 * transmitter is in the ESC's mass and order line: not bought
		 * twice.  A redundant flight controller is not an AIO's. */
		if (it->kind != NULL && (it->need == NULL || strcmp(it->need, "any") == 0)
		    && esc_carries(esc, it->kind)) {
			kit->n_on_esc++;
			continue;
		}
		const struct catalog_avionics *a = it->kind != NULL
		    ? lightest(x, it->kind, it->need, o->cells, sustained_a)
		    : NULL;
		if (a != NULL && kit->n_part < PARTS_KIT_MAX) {
			kit->part[kit->n_part++] = a;
			kit->avionics_kg += a->mass_kg;
		} else if (kit->n_allowance < PARTS_KIT_MAX) {
			kit->allowance_what[kit->n_allowance] = it->what;
			kit->allowance_kg[kit->n_allowance++] = it->allowance_kg;
			kit->avionics_kg += it->allowance_kg;
		}
	}
	int n_packs = pk->series * pk->parallel;
	pick_connector(x, sustained_a / (double)pk->parallel, kit, n_packs,
	    pk->b != NULL ? pk->b->connector : NULL);
}

/* Does offered kit f fit this aircraft (see parts_kit_frame_fits())? */
static bool
frame_fits(const struct parts_ctx *x, const struct catalog_frame *f,
           double prop_in, double mass_kg, double arm_od_m, double custom_kg)
{
	const struct sizing_params *p = x->p;
	if (f->rotor_count != p->n_rotors || f->coaxial != p->coaxial)
		return false;
	/* A kit far heavier than the structure the loads need is built for a
	 * heavier aircraft. */
	if (f->mass_kg > PARTS_KIT_MASS_FACTOR * custom_kg)
		return false;
	if (f->wheelbase_m > p->wheelbase_m * (1.0 + 1e-9)
	    || f->wheelbase_m < p->wheelbase_m * (1.0 - PARTS_KIT_WHEELBASE_TOL))
		return false;
	if (f->frame_class[0] != '\0'
	    && strcmp(f->frame_class, spec_enum_airframe[x->spec->airframe_class]) != 0)
		return false;
	if (f->max_prop_in > 0.0 && prop_in > f->max_prop_in + 1e-9)
		return false;
	int arms = p->coaxial ? p->n_rotors / 2 : p->n_rotors;
	if (in_to_m(prop_in) > aero_overlap_limit_m(f->wheelbase_m, arms,
	    AERO_TIP_CLEARANCE) * (1.0 + 1e-6))
		return false;
	if (f->max_takeoff_kg > 0.0 && mass_kg > f->max_takeoff_kg)
		return false;
	if (f->arm_tube_od_m > 0.0 && f->arm_tube_od_m < arm_od_m)
		return false;
	return true;
}

bool
parts_kit_frame_fits(const struct parts_ctx *x, const struct catalog_frame *f,
                     double prop_in, double mass_kg, double arm_od_m,
                     double custom_kg)
{
	return frame_offered(f) && frame_fits(x, f, prop_in, mass_kg, arm_od_m,
	    custom_kg);
}

const struct catalog_frame *
parts_kit_frame(const struct parts_ctx *x, double prop_in, double mass_kg,
                double arm_od_m, double custom_kg)
{
	const struct catalog_frame *best = NULL;
	for (int i = 0; i < x->n_kit_frames; i++) {
		const struct catalog_frame *f = x->kit_frames[i];
		if (!frame_fits(x, f, prop_in, mass_kg, arm_od_m, custom_kg))
			continue;
		if (best == NULL || f->mass_kg < best->mass_kg
		    || (f->mass_kg == best->mass_kg && strcmp(f->id, best->id) < 0))
			best = f;
	}
	return best;
}
