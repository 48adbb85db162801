/* kit.c — the parts around the propulsion: a frame kit where one fits, the
 * avionics set of the airframe class, the battery connectors, the power
 * harness (harness.c) and the allowances with a stated basis (see
 * parts.h).  Whatever two parts must do together, the rules of compat.c
 * decide.
 *
 * Avionics.  Each airframe class carries a set of kinds (flight
 * controller, GNSS, receiver, telemetry radio, power module, video), each
 * taken as the lightest usable catalogue part of that kind that meets the
 * class's need and the aircraft's bus and currents.  What the class
 * carries that the catalogue does not sell as a part (obstacle sensors,
 * spray radars, a pump controller), and any kind no catalogue part fits,
 * stays an allowance: the mass data/airframes.json's class note gives
 * that group, as a custom line of the bill of materials.  So the record's
 * avionics mass is the parts it orders plus what it cannot order yet, and
 * it equals the BOM's avionics lines.  On top of the class's set:
 *
 *   video      a camera and a transmitter of one video system, the
 *              lightest such pair (or an air unit that carries its
 *              camera, or a camera for the transmitter the ESC board
 *              carries): never a digital camera on an analog transmitter;
 *   Remote ID  a module where the aircraft weighs 250 g or more (EU C1
 *              and up, US Part 89) and no part of the kit broadcasts it;
 *              on the micro class, whose FPV flight controllers speak no
 *              MAVLink, a standalone one with its own GNSS;
 *   antennas   an allowance of ANTENNA_SHARE of the avionics for the
 *              antennas the radios are sold without (an estimate);
 *   role       class items that are role hardware (the agricultural
 *              pump) are counted out of the role's hardware allowance
 *              (kit->role_supplied_kg), so nothing is counted twice.
 *
 * The power path.  The power module and the connectors are chosen for
 * the currents they carry: the mission's sustained current within their
 * continuous rating, and the full-throttle current within the rating
 * that holds for the full-throttle burst (compat.c).  A pack's own
 * connector is in its published mass; it joins the harness through the
 * mate of its own plug's family whenever the catalogue sells one (an
 * XT60 pack takes the XT60 male half, 3 g, never an XT90 pair), and its
 * plug's rating must carry its share: the search does not take a pack
 * whose plug cannot (parts_kit_plug()).  A pack that names no plug, a
 * smart pack, or one whose mate the catalogue cannot weigh is fitted
 * with the lightest catalogue connector that carries its share, and the
 * bill of materials says so.
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
 * Fasteners.  Four screws hold each motor and four more each custom arm
 * (a frame kit brings its own): steel socket-head cap screws sized by
 * the motor, with the masses of the DIN 912 / ISO 4762 weight table
 * (https://www.fullerkr.com/collections/din-912-weight-chart, kg per 1000
 * pieces).  The counts and sizes are estimates.
 *
 * Parts layer; no I/O.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parts/parts_int.h"
#include "parts/screen.h"
#include "physics/aero.h"
#include "sizing/perf.h"
#include "util/units.h"
#include "util/xalloc.h"

#define PARTS_KIT_WHEELBASE_TOL 0.10  /* a kit up to 10 % below the wheelbase */
#define PARTS_UNRATED_PM_CELLS  6     /* bus of a power module with no range */
#define PARTS_KIT_MASS_FACTOR   2.0   /* a kit at most twice the custom arms
                                         and centre frame it replaces */
#define ANTENNA_SHARE           0.10  /* antennas, of the avionics: an
                                         estimate (most radios in the
                                         catalogue are sold without one) */
#define SCREWS_PER_MOTOR        4     /* a motor's mounting screws */
#define SCREWS_PER_ARM          4     /* a custom arm's clamp to the centre */

/* What one class carries: a catalogue kind with its need, or (kind NULL)
 * an item no catalogue part supplies; allowance_kg is the mass of that
 * group in the class note of data/airframes.json, used when no part fits.
 * role: the item is role hardware (the role's allowance holds it too). */
struct kit_item {
	const char *kind;
	const char *need;          /* meets() key, or NULL for any */
	const char *what;          /* the item in words (allowance lines) */
	double allowance_kg;
	bool role;
};

static const struct kit_item kit_items[AF_CLASS_MAX][PARTS_KIT_ITEMS] = {
	[AF_MICRO_AIO] = {
		{ "flight_controller", NULL, "Flight controller", 0.012, false },
		{ "receiver", NULL, "Control receiver", 0.004, false },
		{ "video_tx", NULL, "Video transmitter", 0.008, false },
		{ "camera_fpv", NULL, "FPV camera", 0.006, false },
	},
	[AF_CONSUMER_FOLDING] = {
		{ "flight_controller", "any", "Flight controller and IMU", 0.020, false },
		{ "gnss", "compass", "GNSS and compass", 0.020, false },
		{ "receiver", NULL, "Control receiver", 0.010, false },
		{ "telemetry", NULL, "Telemetry and video link", 0.025, false },
		{ "power_module", "current", "Power distribution", 0.020, false },
		{ NULL, NULL, "Obstacle sensors", 0.025, false },
	},
	[AF_ENTERPRISE_RUGGED] = {
		{ "flight_controller", "redundant", "Redundant flight controller", 0.060, false },
		{ "gnss", "compass", "GNSS and compass", 0.080, false },
		{ "receiver", NULL, "Control receiver", 0.010, false },
		{ "telemetry", NULL, "Long-range datalink", 0.090, false },
		{ "power_module", "current", "Power distribution", 0.050, false },
		{ NULL, NULL, "Sensors (rangefinder, ADS-B receiver, lights)", 0.060, false },
	},
	[AF_AGRICULTURAL] = {
		{ "flight_controller", "redundant", "Redundant flight controller", 0.060, false },
		{ "gnss", "rtk", "RTK GNSS", 0.080, false },
		{ "receiver", NULL, "Control receiver", 0.010, false },
		{ "telemetry", NULL, "Datalink", 0.090, false },
		{ "power_module", "current", "Power distribution", 0.200, false },
		{ NULL, NULL, "Terrain and obstacle radars", 0.200, false },
		{ NULL, NULL, "Pump and flow controller", 0.160, true },
	},
};

/* Steel socket-head cap screws by the motor they hold: the lightest
 * motors take M2, 22xx-40xx class motors M3, the larger M4 and M5 (an
 * estimate by mass); masses from the DIN 912 table (above). */
static const struct {
	double motor_max_kg;
	const char *size;
	double kg;
} screws[] = {
	{ 0.015, "M2 x 4", 0.000175 },
	{ 0.100, "M3 x 8", 0.0008 },
	{ 0.400, "M4 x 10", 0.0018 },
	{ INFINITY, "M5 x 12", 0.0030 },
};

/* The class of the mission, the enterprise one for an unknown value. */
static int
kit_class(const struct parts_ctx *x)
{
	int cls = x->spec->airframe_class;
	return cls < 0 || cls >= AF_CLASS_MAX ? AF_ENTERPRISE_RUGGED : cls;
}

/* Does the part's description say it? (Case as written in the catalogue.) */
static bool
says(const struct catalog_avionics *a, const char *word)
{
	return strstr(a->description, word) != NULL;
}

/* A power module's or distribution board's ratings. */
static struct compat_rating
rating_of(const struct catalog_avionics *a)
{
	struct compat_rating r = { a->max_current_a, a->burst_current_a, a->burst_s };
	return r;
}

/* Does avionics part a meet need on a bus of `cells` carrying load? */
static bool
meets(const struct catalog_avionics *a, const char *kind, const char *need,
      int cells, const struct parts_load *load)
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
	if (strcmp(need, "standalone") == 0)
		return says(a, "own GNSS");
	if (strcmp(need, "current") == 0) {
		/* The power module carries the whole battery current. */
		struct compat_rating r = rating_of(a);
		int hi = a->cells_max > 0 ? a->cells_max : PARTS_UNRATED_PM_CELLS;
		return cells <= hi && compat_rated(&r, load->sustained_a, load->full_a,
		    PERF_FULL_THROTTLE_S, NULL, 0) == NULL;
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

static const struct catalog_avionics *lightest(const struct parts_ctx *x,
    const char *kind, const char *need, int cells, const struct parts_load *load);
static const struct catalog_avionics *own_plug(const struct parts_ctx *x,
    const char *pack_connector);
static void video_pair(const struct parts_ctx *x,
    const struct catalog_avionics **vtx, const struct catalog_avionics **cam);

/* Is item it chosen on a current rating (the power module), so that the
 * closing's currents decide it, not its bus alone? */
static bool
by_current(const struct kit_item *it)
{
	return it->need != NULL && strcmp(it->need, "current") == 0;
}

/* The Remote ID module's need: a standalone one on the micro class (its
 * FPV flight controllers feed no module), any otherwise. */
static const char *
remote_id_need(const struct parts_ctx *x)
{
	return kit_class(x) == AF_MICRO_AIO ? "standalone" : NULL;
}

/* x->kit_by_bus: every item chosen by its bus alone, on every bus. */
static void
pick_by_bus(struct parts_ctx *x)
{
	x->kit_by_bus_class = kit_class(x);
	const struct kit_item *items = kit_items[x->kit_by_bus_class];
	for (int cells = 1; cells <= PARTS_MAX_CELLS; cells++) {
		for (int i = 0; i < PARTS_KIT_ITEMS && items[i].what != NULL; i++)
			if (items[i].kind != NULL && !by_current(&items[i]))
				x->kit_by_bus[i][cells] = lightest(x, items[i].kind,
				    items[i].need, cells, NULL);
		x->kit_by_bus[PARTS_KIT_ITEMS][cells] = lightest(x, "remote_id",
		    remote_id_need(x), cells, NULL);
	}
}

/* The lightest part for item `slot` of the kit (PARTS_KIT_ITEMS: Remote
 * ID) on `cells` carrying load: the pick of parts_kit_init() where the
 * bus alone decides it. */
static const struct catalog_avionics *
item_part(const struct parts_ctx *x, int slot, const char *kind,
          const char *need, int cells, const struct parts_load *load)
{
	bool on_bus = slot == PARTS_KIT_ITEMS
	    || !by_current(&kit_items[kit_class(x)][slot]);
	if (on_bus && cells >= 1 && cells <= PARTS_MAX_CELLS
	    && x->kit_by_bus_class == kit_class(x))
		return x->kit_by_bus[slot][cells];
	return lightest(x, kind, need, cells, load);
}

/* Two texts alike, NULL only like NULL. */
static bool
same_text(const char *a, const char *b)
{
	return a == b || (a != NULL && b != NULL && strcmp(a, b) == 0);
}

void
parts_kit_init(struct parts_ctx *x)
{
	x->n_kit_kinds = 0;
	size_t n = catalog_n_avionics(x->cat);
	x->plugs.kind = "connector";
	x->plugs.items = xcalloc(n > 0 ? n : 1, sizeof *x->plugs.items);
	x->plugs.n = 0;
	for (size_t i = 0; i < n; i++) {
		const struct catalog_avionics *a = catalog_avionics(x->cat, i);
		if (strcmp(a->kind, "connector") == 0)
			x->plugs.items[x->plugs.n++] = a;
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
	pick_by_bus(x);
	video_pair(x, &x->video_tx, &x->video_cam);
	/* Each pack's own plug, found once (a pack is tried on many
	 * closings, and its plug's row by its name): once per name, which
	 * the packs of a battery and most batteries of a maker share. */
	const struct parts_pack **named = xmalloc((size_t)(x->n_packs > 0
	    ? x->n_packs : 1) * sizeof *named);
	int n_named = 0;
	for (int i = 0; i < x->n_packs; i++) {
		struct parts_pack *pk = &x->packs[i];
		pk->plug_name = pk->b != NULL ? pk->b->connector : NULL;
		int j = 0;
		while (j < n_named && !same_text(named[j]->plug_name, pk->plug_name))
			j++;
		if (j < n_named) {
			pk->plug = named[j]->plug;
			continue;
		}
		pk->plug = own_plug(x, pk->plug_name);
		named[n_named++] = pk;
	}
	free(named);
}

void
parts_kit_free(struct parts_ctx *x)
{
	for (int k = 0; k < x->n_kit_kinds; k++)
		free(x->kit_kinds[k].items);
	x->n_kit_kinds = 0;
	free(x->plugs.items);
	x->plugs.items = NULL;
	x->plugs.n = 0;
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

/* Is a lighter than best (ties by id: deterministic)? */
static bool
lighter(const struct catalog_avionics *a, const struct catalog_avionics *best)
{
	return best == NULL || a->mass_kg < best->mass_kg
	    || (a->mass_kg == best->mass_kg && strcmp(a->id, best->id) < 0);
}

/* The lightest part of kind meeting need. */
static const struct catalog_avionics *
lightest(const struct parts_ctx *x, const char *kind, const char *need,
         int cells, const struct parts_load *load)
{
	const struct catalog_avionics *best = NULL;
	const struct parts_kit_kind *kk = of_kind(x, kind);
	for (int i = 0; kk != NULL && i < kk->n; i++)
		if (meets(kk->items[i], kind, need, cells, load)
		    && lighter(kk->items[i], best))
			best = kk->items[i];
	/* Power distribution: a distribution board will do. */
	kk = best == NULL && strcmp(kind, "power_module") == 0 ? of_kind(x, "pdb") : NULL;
	for (int i = 0; kk != NULL && i < kk->n; i++)
		if (meets(kk->items[i], "pdb", need, cells, load)
		    && lighter(kk->items[i], best))
			best = kk->items[i];
	return best;
}

/* ---- connectors ------------------------------------------------------------ */

/* Does pack connector text name a plug (not unknown, not a smart pack's
 * own)? */
static bool
names_plug(const char *pack_connector)
{
	return pack_connector != NULL && pack_connector[0] != '\0'
	    && strcmp(pack_connector, "smart") != 0;
}

/* The catalogue's row of the pack's own plug family: the usable one (with
 * a mass: the mate the kit buys) when there is one, else any row (whose
 * rating still bounds the pack), else NULL. */
static const struct catalog_avionics *
own_plug(const struct parts_ctx *x, const char *pack_connector)
{
	const struct catalog_avionics *any = NULL, *usable = NULL;
	for (int i = 0; names_plug(pack_connector) && i < x->plugs.n; i++) {
		const struct catalog_avionics *a = x->plugs.items[i];
		if (!compat_mates(pack_connector, a))
			continue;
		if (a->usable && a->max_current_a > 0.0 && lighter(a, usable))
			usable = a;
		if (any == NULL || (a->max_current_a > 0.0 && !(any->max_current_a > 0.0)))
			any = a;
	}
	return usable != NULL ? usable : any;
}

/* The pack's own plug row: the one parts_kit_init() found for it, or
 * looked up now for a pack it did not see. */
static const struct catalog_avionics *
pack_plug(const struct parts_ctx *x, const struct parts_pack *pk)
{
	const char *name = pk->b != NULL ? pk->b->connector : NULL;
	if (pk->plug_name != NULL && pk->plug_name == name)
		return pk->plug;
	return own_plug(x, name);
}

/* The lightest usable mated pair that carries each pack's share (for a
 * pack whose plug the catalogue cannot supply the mate of: both halves
 * are fitted), or NULL. */
static const struct catalog_avionics *
fitting_connector(const struct parts_ctx *x, double sustained_a, double full_a)
{
	const struct catalog_avionics *best = NULL;
	const struct parts_kit_kind *kk = of_kind(x, "connector");
	for (int i = 0; kk != NULL && i < kk->n; i++)
		if (!compat_connector_half(kk->items[i])
		    && compat_connector("", kk->items[i], sustained_a, full_a,
		    PERF_FULL_THROTTLE_S, NULL, 0) == NULL
		    && lighter(kk->items[i], best))
			best = kk->items[i];
	return best;
}

const char *
parts_kit_plug(const struct parts_ctx *x, const struct parts_pack *pk,
               double sustained_a, double full_a, char *why, size_t n)
{
	const char *plug = pk->b != NULL ? pk->b->connector : NULL;
	double s = sustained_a / (double)pk->parallel, f = full_a / (double)pk->parallel;
	const struct catalog_avionics *own = pack_plug(x, pk);
	/* A plug it names must be one the catalogue rates (a JST or an
	 * unrated XT150 cannot be shown to carry anything), and that rating
	 * bounds its pack, whether its mate is bought or not. */
	if (names_plug(plug) && (own == NULL || !(own->max_current_a > 0.0)))
		return compat_reason(why, n, "the catalogue has no current rating "
		    "for its %s plug", plug);
	const char *bad;
	if (own != NULL && (bad = compat_connector(plug, own, s, f,
	    PERF_FULL_THROTTLE_S, why, n)) != NULL)
		return bad;
	if (own != NULL && own->usable)
		return NULL;
	if (fitting_connector(x, s, f) == NULL)
		return compat_reason(why, n, "no catalogue connector carries %.0f A a "
		    "pack at full throttle", f);
	return NULL;
}

/* The pack's mate: its own family's when the catalogue sells one (even
 * over its rating: the check then says so), else the lightest connector
 * that carries the pack's share, else none. */
static void
pick_connector(const struct parts_ctx *x, const struct parts_pack *pk,
               struct parts_kit *kit)
{
	int n_packs = pk->series * pk->parallel;
	double s = kit->load.sustained_a / (double)pk->parallel;
	double f = kit->load.full_a / (double)pk->parallel;
	const struct catalog_avionics *own = pack_plug(x, pk);
	if (own != NULL && own->usable && own->max_current_a > 0.0) {
		kit->connector = own;
		kit->connector_mates = true;
	} else {
		kit->plug = own;
		kit->connector = fitting_connector(x, s, f);
	}
	kit->n_connectors = kit->connector != NULL ? n_packs : 0;
	kit->connector_kg = kit->connector != NULL
	    ? (double)n_packs * kit->connector->mass_kg : 0.0;
}

/* ---- video ------------------------------------------------------------------- */

/* The lightest camera that works with a transmitter of system. */
static const struct catalog_avionics *
camera_for(const struct parts_ctx *x, const char *system)
{
	const struct catalog_avionics *best = NULL;
	const struct parts_kit_kind *cams = of_kind(x, "camera_fpv");
	for (int i = 0; cams != NULL && i < cams->n; i++)
		if (compat_video(cams->items[i], system, false, NULL, 0) == NULL
		    && lighter(cams->items[i], best))
			best = cams->items[i];
	return best;
}

/* The lightest transmitter and camera that work together: an air unit
 * that carries its camera alone, else a transmitter and the lightest
 * camera of its system.  *cam NULL with *vtx set: the air unit's own. */
static void
video_pair(const struct parts_ctx *x, const struct catalog_avionics **vtx,
           const struct catalog_avionics **cam)
{
	*vtx = *cam = NULL;
	double best_kg = INFINITY;
	const struct parts_kit_kind *tx = of_kind(x, "video_tx");
	for (int i = 0; tx != NULL && i < tx->n; i++) {
		const struct catalog_avionics *t = tx->items[i];
		if (t->video_system[0] == '\0')
			continue;
		const struct catalog_avionics *c = compat_does(t, "camera_fpv") ? NULL
		    : camera_for(x, t->video_system);
		if (c == NULL && !compat_does(t, "camera_fpv"))
			continue;
		double kg = t->mass_kg + (c != NULL ? c->mass_kg : 0.0);
		if (kg < best_kg || (kg == best_kg && strcmp(t->id, (*vtx)->id) < 0)) {
			best_kg = kg;
			*vtx = t;
			*cam = c;
		}
	}
}

/* ---- the kit ----------------------------------------------------------------- */

/* Does the ESC board carry avionics kind (its `carries` list)? */
static bool
esc_carries(const struct catalog_esc *esc, const char *kind)
{
	return esc != NULL && catalog_list_names(esc->carries, kind);
}

static void
add_part(struct parts_kit *kit, const struct catalog_avionics *a)
{
	if (kit->n_part < PARTS_KIT_MAX) {
		kit->part[kit->n_part++] = a;
		kit->avionics_kg += a->mass_kg;
	}
}

static void
add_allowance(struct parts_kit *kit, const char *what, const char *basis,
              double kg)
{
	if (kit->n_allowance < PARTS_KIT_MAX) {
		kit->allowance_what[kit->n_allowance] = what;
		kit->allowance_basis[kit->n_allowance] = basis;
		kit->allowance_kg[kit->n_allowance++] = kg;
		kit->avionics_kg += kg;
	}
}

/* One class item: on the ESC board, a part, or its allowance. */
static void
pick_item(const struct parts_ctx *x, int slot, int cells,
          const struct catalog_esc *esc, struct parts_kit *kit)
{
	const struct kit_item *it = &kit_items[kit_class(x)][slot];
	/* An all-in-one board's flight controller, receiver or video
	 * transmitter is in the ESC's mass and order line: not bought
	 * twice.  A redundant flight controller is not an AIO's. */
	if (it->kind != NULL && (it->need == NULL || strcmp(it->need, "any") == 0)
	    && esc_carries(esc, it->kind)) {
		kit->n_on_esc++;
		return;
	}
	const struct catalog_avionics *a = it->kind != NULL
	    ? item_part(x, slot, it->kind, it->need, cells, &kit->load) : NULL;
	if (it->kind != NULL && strcmp(it->kind, "power_module") == 0) {
		kit->power_module_item = true;
		kit->power_module = a;
	}
	if (a != NULL)
		add_part(kit, a);
	else
		add_allowance(kit, it->what, NULL, it->allowance_kg);
	if (it->role) {
		kit->role_supplied_kg += a != NULL ? a->mass_kg : it->allowance_kg;
		kit->role_supplied_what = it->what;
	}
}

/* The camera and transmitter items together: one video system. */
static void
pick_video(const struct parts_ctx *x, const struct kit_item *vtx_item,
           const struct kit_item *cam_item, const struct catalog_esc *esc,
           struct parts_kit *kit)
{
	const struct catalog_avionics *vtx = NULL, *cam = NULL;
	if (esc_carries(esc, "video_tx")) {
		kit->n_on_esc++;
		cam = camera_for(x, esc->video_system);
	} else {
		vtx = x->video_tx;
		cam = x->video_cam;
		if (vtx != NULL)
			add_part(kit, vtx);
		else
			add_allowance(kit, vtx_item->what, NULL, vtx_item->allowance_kg);
		kit->camera_on_vtx = vtx != NULL && cam == NULL;
	}
	if (cam != NULL)
		add_part(kit, cam);
	else if (!kit->camera_on_vtx)
		add_allowance(kit, cam_item->what, NULL, cam_item->allowance_kg);
}

/* A Remote ID module when the aircraft needs one and no part broadcasts
 * it: a standalone one on the micro class (its FPV flight controllers
 * feed no module), the lightest that fits otherwise. */
static void
pick_remote_id(const struct parts_ctx *x, int cells, struct parts_kit *kit)
{
	kit->remote_id_required = compat_remote_id_required(kit->load.mass_kg);
	if (!kit->remote_id_required)
		return;
	for (int i = 0; i < kit->n_part; i++)
		if (compat_does(kit->part[i], "remote_id"))
			return;
	const struct catalog_avionics *a = item_part(x, PARTS_KIT_ITEMS,
	    "remote_id", remote_id_need(x), cells, &kit->load);
	if (a != NULL)
		add_part(kit, a);
	else
		kit->remote_id_missing = true;
}

void
parts_kit_pick(const struct parts_ctx *x, const struct parts_option *o,
               const struct parts_pack *pk, const struct catalog_esc *esc,
               const struct parts_load *load, struct parts_kit *kit)
{
	memset(kit, 0, sizeof *kit);
	kit->load = *load;
	const struct kit_item *items = kit_items[kit_class(x)];
	const struct kit_item *vtx = NULL, *cam = NULL;
	for (int i = 0; i < PARTS_KIT_ITEMS && items[i].what != NULL; i++) {
		const struct kit_item *it = &items[i];
		if (it->kind != NULL && strcmp(it->kind, "video_tx") == 0)
			vtx = it;
		else if (it->kind != NULL && strcmp(it->kind, "camera_fpv") == 0)
			cam = it;
		else
			pick_item(x, i, o->cells, esc, kit);
	}
	if (vtx != NULL && cam != NULL)
		pick_video(x, vtx, cam, esc, kit);
	pick_remote_id(x, o->cells, kit);
	/* Antennas: a share of the avionics but the role hardware. */
	add_allowance(kit, "Antennas", "10 % of the avionics, an estimate: most "
	    "radios are sold without their antennas",
	    ANTENNA_SHARE * (kit->avionics_kg - kit->role_supplied_kg));
	pick_connector(x, pk, kit);
	parts_harness(x, pk, esc, kit);
	/* Fasteners by the motor they hold. */
	size_t k = 0;
	while (o->motor != NULL && o->motor->mass_kg > screws[k].motor_max_kg)
		k++;
	kit->fastener_size = screws[k].size;
	kit->fastener_unit_kg = screws[k].kg;
	kit->n_motor_screws = SCREWS_PER_MOTOR * x->p->n_rotors;
	kit->n_arm_screws = SCREWS_PER_ARM * (x->p->coaxial ? x->p->n_rotors / 2
	    : x->p->n_rotors);
}

int
parts_kit_screws(const struct parts_kit *kit)
{
	return kit->n_motor_screws + (kit->frame != NULL ? 0 : kit->n_arm_screws);
}

double
parts_kit_fastener_kg(const struct parts_kit *kit)
{
	return (double)parts_kit_screws(kit) * kit->fastener_unit_kg;
}

bool
parts_kit_same(const struct parts_kit *a, const struct parts_kit *b)
{
	return a->connector == b->connector && a->n_connectors == b->n_connectors
	    && a->n_part == b->n_part
	    && memcmp(a->part, b->part, sizeof a->part) == 0
	    && a->n_allowance == b->n_allowance
	    && a->avionics_kg == b->avionics_kg
	    && a->harness_kg == b->harness_kg;
}

bool
parts_kit_takes_board_fc(const struct parts_ctx *x)
{
	const struct kit_item *items = kit_items[kit_class(x)];
	for (int i = 0; i < PARTS_KIT_ITEMS && items[i].what != NULL; i++)
		if (items[i].kind != NULL && strcmp(items[i].kind, "flight_controller") == 0)
			return items[i].need == NULL || strcmp(items[i].need, "any") == 0;
	return true;
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
