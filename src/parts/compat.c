/* compat.c — do two parts work together?  The rules the parts kit and the
 * ESC pick apply before a combination reaches a bill of materials (issue
 * 33: a Walksnail camera on an analog transmitter, an XT90 pair
 * re-terminated onto an XT60 pack that carries 5 A, a whoop board driving
 * 5-inch motors on 6S).  Each rule is one small function over catalogue
 * entries and currents: NULL when the parts work together, else the
 * reason, written into why (size n) and returned, in words a builder
 * reads ("the camera is walksnail, the transmitter analog").  why NULL
 * asks only the answer: the search's loops ask thousands of times and
 * print none, so the reason is not formatted (a non-NULL constant is
 * returned instead).
 *
 * Ratings and bursts.  A rated part (battery connector, power module, ESC
 * channel) carries the mission's sustained current within its continuous
 * rating.  At full throttle the record flies a burst of
 * PERF_FULL_THROTTLE_S (10 s); a part whose maker publishes a burst rating
 * together with how long it holds may carry that burst up to its burst
 * rating when the burst holds at least that long (AMASS's XT90: 45 A
 * continuous, 90 A for 1 min, so 90 A for a 10 s burst); a burst rating
 * without a duration, or a shorter one (an ESC's 3 s), is no rating for a
 * 10 s burst, and the continuous rating bounds it.
 *
 * Parts layer; no I/O.
 */
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "parts/parts_int.h"

const char *
compat_reason(char *why, size_t n, const char *fmt, ...)
{
	if (why == NULL)
		return "incompatible";
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(why, n, fmt, ap);
	va_end(ap);
	return why;
}

double
compat_rating_for(const struct compat_rating *r, double need_s)
{
	if (r->burst_a > r->continuous_a && r->burst_s > 0.0 && r->burst_s >= need_s)
		return r->burst_a;
	return r->continuous_a;
}

const char *
compat_rated(const struct compat_rating *r, double sustained_a, double full_a,
             double need_s, char *why, size_t n)
{
	if (!(r->continuous_a > 0.0))
		return compat_reason(why, n, "no current rating published");
	if (sustained_a > r->continuous_a)
		return compat_reason(why, n, "%.1f A sustained, above its %.0f A "
		    "continuous rating", sustained_a, r->continuous_a);
	double full_rating = compat_rating_for(r, need_s);
	if (full_a > full_rating)
		return compat_reason(why, n, "%.1f A at full throttle, above its %.0f A %s",
		    full_a, full_rating, full_rating > r->continuous_a ? "burst rating"
		    : "continuous rating (no burst rating that holds for the burst)");
	return NULL;
}

/* ---- video ---------------------------------------------------------------- */

/* A camera and a transmitter work together only on one video system: an
 * analog camera's composite signal means nothing to a digital
 * transmitter, and each digital system (DJI, Walksnail, HDZero) takes
 * its own cameras over its own interface.  camera NULL: the transmitter
 * carries its own camera (an O3 Air Unit), which needs none apart. */
const char *
compat_video(const struct catalog_avionics *camera, const char *vtx_system,
             bool vtx_has_camera, char *why, size_t n)
{
	if (vtx_system == NULL || vtx_system[0] == '\0')
		return compat_reason(why, n, "the video transmitter names no video system");
	if (camera == NULL && !vtx_has_camera)
		return compat_reason(why, n, "the %s transmitter carries no camera",
		    vtx_system);
	if (camera == NULL)
		return NULL;
	if (vtx_has_camera)
		return compat_reason(why, n, "the transmitter carries its own camera; %s is "
		    "a second", camera->id);
	if (camera->video_system[0] == '\0'
	    || strcmp(camera->video_system, vtx_system) != 0)
		return compat_reason(why, n, "the camera is %s, the transmitter %s",
		    camera->video_system[0] ? camera->video_system : "of no named system",
		    vtx_system);
	return NULL;
}

/* ---- battery connectors ---------------------------------------------------- */

void
compat_connector_family(const char *name, char *out, size_t n)
{
	size_t k = 0;
	for (; *name != '\0' && *name != ' ' && *name != '(' && *name != '/'; name++)
		if (isalnum((unsigned char)*name) && k + 1 < n)
			out[k++] = (char)toupper((unsigned char)*name);
	/* AMASS's half-connector suffixes: "XT60-M" is an XT60. */
	if (k > 1 && (out[k - 1] == 'M' || out[k - 1] == 'F')
	    && isdigit((unsigned char)out[k - 2]))
		k--;
	out[k] = '\0';
}

bool
compat_connector_half(const struct catalog_avionics *a)
{
	/* AMASS names a half "XT60-M" or "XT60-F": digits, a dash, M or F,
	 * then the end of the name's first word. */
	const char *p = a->part_number;
	size_t n = strcspn(p, " (/");
	return n >= 3 && p[n - 2] == '-' && (p[n - 1] == 'M' || p[n - 1] == 'F')
	    && isdigit((unsigned char)p[n - 3]);
}

bool
compat_mates(const char *pack_connector, const struct catalog_avionics *a)
{
	char want[32], have[32];
	compat_connector_family(a->part_number, have, sizeof have);
	if (have[0] == '\0' || pack_connector == NULL)
		return false;
	for (const char *p = pack_connector; *p != '\0'; ) {
		compat_connector_family(p, want, sizeof want);
		if (strcmp(want, have) == 0)
			return true;
		const char *slash = strchr(p, '/');
		if (slash == NULL)
			break;
		p = slash + 1;
	}
	return false;
}

/* A pack is joined to the harness through its own plug: a connector of
 * another family does not mate with it (an XT90 pair does not take an
 * XT60 pack), and the plug's rating must carry the pack's share of the
 * current, sustained and in the full-throttle burst (its leads are sized
 * for that plug; fitting a larger one does not make them carry more). */
const char *
compat_connector(const char *pack_connector, const struct catalog_avionics *a,
                 double sustained_a, double full_a, double need_s, char *why,
                 size_t n)
{
	bool named = pack_connector != NULL && pack_connector[0] != '\0'
	    && strcmp(pack_connector, "smart") != 0;
	if (named && !compat_mates(pack_connector, a))
		return compat_reason(why, n, "%s does not mate with the pack's %s plug",
		    a->part_number, pack_connector);
	struct compat_rating r = { a->max_current_a, a->burst_current_a, a->burst_s };
	char rated[128];
	if (compat_rated(&r, sustained_a, full_a, need_s, why ? rated : NULL,
	    sizeof rated) != NULL)
		return compat_reason(why, n, "%s: %s", a->part_number, rated);
	return NULL;
}

/* ---- ESC ------------------------------------------------------------------- */

/* An ESC drives a motor on a bus when the bus is within the ESC's cell
 * range (a board with none published: PARTS_UNRATED_ESC_CELLS at most)
 * and the motor's, and each channel carries one motor's current: the
 * sustained current within its continuous rating, the full-throttle
 * current with `margin` within the rating that holds for the burst.  A
 * whoop all-in-one board (1-2S, 5-12 A a channel) fails both on a 5-inch
 * motor at 6S. */
const char *
compat_esc(const struct catalog_esc *e, const struct catalog_motor *m, int cells,
           double sustained_a, double full_a, double margin, double need_s,
           char *why, size_t n)
{
	int hi = e->cells_max > 0 ? e->cells_max : PARTS_UNRATED_ESC_CELLS;
	if (cells > hi || (e->cells_min > 0 && cells < e->cells_min))
		return compat_reason(why, n, "%s takes %d-%dS, the bus is %dS", e->part_number,
		    e->cells_min > 0 ? e->cells_min : 1, hi, cells);
	if (m != NULL && ((m->cells_max > 0 && cells > m->cells_max)
	    || (m->cells_min > 0 && cells < m->cells_min)))
		return compat_reason(why, n, "the motor takes %d-%dS, the bus is %dS",
		    m->cells_min, m->cells_max, cells);
	struct compat_rating r = { e->continuous_current_a, e->burst_current_a,
		e->burst_s };
	char rated[128];
	if (compat_rated(&r, sustained_a, margin * full_a, need_s,
	    why ? rated : NULL, sizeof rated) != NULL)
		return compat_reason(why, n, "%s per channel, with the %.0f %% margin: %s",
		    e->part_number, 100.0 * (margin - 1.0), rated);
	return NULL;
}

/* An ESC board that carries a flight controller (an all-in-one board or
 * an FC + ESC stack) puts that controller on the aircraft: it must be
 * the one the airframe class flies (not where the class needs a
 * redundant one), and one only (two boards would carry two). */
const char *
compat_board_fc(const struct catalog_esc *e, int n_boards, bool class_takes_it,
                char *why, size_t n)
{
	if (!catalog_list_names(e->carries, "flight_controller"))
		return NULL;
	if (!class_takes_it) {
		return compat_reason(why, n, "%s carries a flight controller; the airframe "
		    "class needs a redundant one, bought apart", e->part_number);
	}
	if (n_boards > 1)
		return compat_reason(why, n, "%d x %s would carry %d flight controllers",
		    n_boards, e->part_number, n_boards);
	return NULL;
}

/* ---- Remote ID -------------------------------------------------------------- */

/* EU: Regulation (EU) 2019/945 gives class C1 and up (250 g and more)
 * direct remote identification; US: 14 CFR Part 89 asks it of every
 * aircraft that must be registered, 250 g (0.55 lb) and more. */
bool
compat_remote_id_required(double mass_kg)
{
	return mass_kg >= RES_EU_C0_KG;
}

bool
compat_does(const struct catalog_avionics *a, const char *kind)
{
	return strcmp(a->kind, kind) == 0 || catalog_list_names(a->carries, kind);
}
