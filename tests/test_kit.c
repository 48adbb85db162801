/* test_kit.c — parts that work together (issue 33): the compatibility
 * rules of parts/compat.c and the kit of parts/kit.c that applies them.
 * Each rule is shown to reject the mismatch the issue found in the
 * examples (a Walksnail camera on a TBS Unify analog transmitter, an XT90
 * pair re-terminated onto an XT60 pack, a whoop all-in-one board driving
 * 5-inch motors on 6S) and to accept a pairing that works; then whole
 * solves of the shipped examples: matched video, plugs of the pack's own
 * family within their ratings, Remote ID, the pump counted once, the
 * power path exposed for the checks.  Runs from the repository root. */
#include "test_util.h"

#include "cli/cli.h"
#include "catalog/catalog.h"
#include "diag/diag.h"
#include "engine/engine.h"
#include "input/mission_io.h"
#include "parts/parts_int.h"
#include "sizing/perf.h"
#include "util/xalloc.h"

#define BURST_S PERF_FULL_THROTTLE_S

/* An avionics entry with the common fields a kit reads; the rest by
 * designated initializers. */
#define PART(id_, kind_, mass_g, ...)                                          \
	{ .id = id_, .manufacturer = "Test", .source = "", .confidence = "medium", \
	  .uncertain = "", .price_date = "", .kind = kind_,                       \
	  .mass_kg = (mass_g) / 1000.0, .usable = (mass_g) > 0.0, __VA_ARGS__ }

/* The parts the issue saw together, and what works instead (ratings as
 * the shipped catalogue gives them). */
static const struct catalog_avionics parts[] = {
	PART("t-walksnail-cam", "camera_fpv", 3.0, .part_number = "Avatar HD Nano V3",
	    .video_system = "walksnail", .carries = "", .description = "digital camera"),
	PART("t-unify", "video_tx", 1.0, .part_number = "Unify Pro32 Nano",
	    .video_system = "analog", .carries = "", .description = "analog VTX"),
	PART("t-ratel", "camera_fpv", 5.9, .part_number = "Ratel 2",
	    .video_system = "analog", .carries = "", .description = "analog camera"),
	PART("t-avatar-vtx", "video_tx", 8.7, .part_number = "Avatar HD Mini",
	    .video_system = "walksnail", .carries = "", .description = "digital VTX"),
	PART("t-o3", "video_tx", 36.4, .part_number = "O3 Air Unit",
	    .video_system = "dji_o3", .carries = "camera_fpv",
	    .description = "air unit with camera"),
	PART("t-xt60-m", "connector", 3.0, .part_number = "XT60-M (male half)",
	    .max_current_a = 30.0, .burst_current_a = 60.0, .burst_s = 60.0,
	    .video_system = "", .carries = "", .description = "XT60 harness half"),
	PART("t-xt90", "connector", 28.0, .part_number = "XT90 (mated pair)",
	    .max_current_a = 45.0, .burst_current_a = 90.0, .burst_s = 60.0,
	    .video_system = "", .carries = "", .description = "XT90 pair"),
	PART("t-as150", "connector", 24.0, .part_number = "AS150 (mated pair)",
	    .max_current_a = 75.0, .burst_current_a = 150.0, .burst_s = 60.0,
	    .video_system = "", .carries = "", .description = "AS150 pair"),
	PART("t-xt30", "connector", 0.0, .part_number = "XT30 (mated pair)",
	    .max_current_a = 15.0, .burst_current_a = 30.0, .video_system = "",
	    .carries = "", .description = "XT30 pair, no mass"),
	PART("t-rid-fc", "remote_id", 4.0, .part_number = "RID board",
	    .video_system = "", .carries = "",
	    .description = "Remote ID fed by the flight controller"),
	PART("t-rid-alone", "remote_id", 16.0, .part_number = "RID beacon",
	    .video_system = "", .carries = "",
	    .description = "standalone beacon with its own GNSS"),
	PART("t-pm", "power_module", 20.0, .part_number = "PM 60 A",
	    .max_current_a = 60.0, .burst_current_a = 120.0, .burst_s = 60.0,
	    .video_system = "", .carries = "", .description = "power module"),
};
#define N_PARTS (sizeof parts / sizeof parts[0])

static const struct catalog_avionics *
part(const char *id)
{
	for (size_t i = 0; i < N_PARTS; i++)
		if (strcmp(parts[i].id, id) == 0)
			return &parts[i];
	fail_msg("no test part %s", id);
	return NULL;
}

/* A catalogue of the parts above but those named in `without` (ids
 * joined by commas). */
static struct catalog *
catalogue(const char *without)
{
	struct catalog_avionics *a = xcalloc(N_PARTS, sizeof *a);
	size_t n = 0;
	for (size_t i = 0; i < N_PARTS; i++)
		if (!catalog_list_names(without, parts[i].id))
			a[n++] = parts[i];
	struct catalog *c = catalog_alloc();
	catalog_adopt(c, CATALOG_AVIONICS, a, n);
	catalog_finish(c);
	return c;
}

/* What a kit is picked in: the mission's class, a 1 m quad. */
struct setting {
	struct mission_spec spec;
	struct sizing_params p;
	struct parts_ctx x;
	struct catalog *cat;
	struct parts_option o;
	struct catalog_battery b;
	struct parts_pack pk;
};

static void
setting(struct setting *s, int airframe_class, const char *without)
{
	memset(s, 0, sizeof *s);
	s->cat = catalogue(without);
	s->spec.airframe_class = airframe_class;
	s->p.wheelbase_m = 1.0;
	s->p.n_rotors = 4;
	s->x.spec = &s->spec;
	s->x.p = &s->p;
	s->x.cat = s->cat;
	parts_kit_init(&s->x);
	s->o.cells = 6;
	s->b.connector = "";
	s->pk.b = &s->b;
	s->pk.series = s->pk.parallel = 1;
}

static void
setting_free(struct setting *s)
{
	parts_kit_free(&s->x);
	catalog_free(s->cat);
}

static void
pick(struct setting *s, const struct catalog_esc *esc, double sustained_a,
     double full_a, double mass_kg, struct parts_kit *kit)
{
	struct parts_load load = { sustained_a, full_a, full_a / 4.0, mass_kg };
	parts_kit_pick(&s->x, &s->o, &s->pk, esc, &load, kit);
}

/* The setting's own copy of a test part (the kit points into it). */
static const struct catalog_avionics *
part_in(const struct setting *s, const char *id)
{
	return catalog_find_avionics(s->cat, id);
}

static bool
kit_has(const struct parts_kit *kit, const char *id)
{
	for (int i = 0; i < kit->n_part; i++)
		if (strcmp(kit->part[i]->id, id) == 0)
			return true;
	return false;
}

/* ---- video ------------------------------------------------------------------ */

static void
video_should_reject_a_walksnail_camera_on_an_analog_transmitter(void **state)
{
	(void)state;
	char why[160];
	const char *no = compat_video(part("t-walksnail-cam"), "analog", false, why,
	    sizeof why);
	assert_non_null(no);
	assert_string_equal(no, "the camera is walksnail, the transmitter analog");
	/* The same camera on its own system's transmitter, and the analog
	 * pair, work. */
	assert_null(compat_video(part("t-walksnail-cam"), "walksnail", false, why,
	    sizeof why));
	assert_null(compat_video(part("t-ratel"), "analog", false, why, sizeof why));
	/* An air unit with its own camera takes no second one, and a bare
	 * transmitter needs one. */
	assert_null(compat_video(NULL, "dji_o3", true, why, sizeof why));
	assert_non_null(compat_video(part("t-ratel"), "dji_o3", true, why, sizeof why));
	assert_non_null(compat_video(NULL, "analog", false, why, sizeof why));
}

/* The micro class's kit buys one system: the lightest matched pair (the
 * analog pair, 6.9 g, not the 4 g of the Walksnail camera on the Unify),
 * the digital pair when no analog camera is sold, the air unit alone
 * when it is the only transmitter, and a camera of the transmitter's
 * system when the ESC board carries the transmitter. */
static void
kit_should_buy_a_camera_and_transmitter_of_one_system(void **state)
{
	(void)state;
	struct setting s;
	struct parts_kit kit;
	setting(&s, AF_MICRO_AIO, "");
	pick(&s, NULL, 5.0, 40.0, 0.2, &kit);
	assert_true(kit_has(&kit, "t-unify") && kit_has(&kit, "t-ratel"));
	assert_false(kit_has(&kit, "t-walksnail-cam"));
	setting_free(&s);

	setting(&s, AF_MICRO_AIO, "t-ratel");
	pick(&s, NULL, 5.0, 40.0, 0.2, &kit);
	assert_true(kit_has(&kit, "t-avatar-vtx") && kit_has(&kit, "t-walksnail-cam"));
	assert_false(kit_has(&kit, "t-unify"));
	setting_free(&s);

	setting(&s, AF_MICRO_AIO, "t-unify,t-avatar-vtx");
	pick(&s, NULL, 5.0, 40.0, 0.2, &kit);
	assert_true(kit_has(&kit, "t-o3") && kit.camera_on_vtx);
	assert_false(kit_has(&kit, "t-ratel") || kit_has(&kit, "t-walksnail-cam"));
	setting_free(&s);

	struct catalog_esc aio;
	memset(&aio, 0, sizeof aio);
	aio.channels = 4;
	aio.carries = "flight_controller,video_tx";
	aio.video_system = "analog";
	setting(&s, AF_MICRO_AIO, "");
	pick(&s, &aio, 5.0, 40.0, 0.2, &kit);
	assert_true(kit_has(&kit, "t-ratel"));
	assert_false(kit_has(&kit, "t-unify") || kit_has(&kit, "t-walksnail-cam"));
	assert_int_equal(kit.n_on_esc, 2);
	setting_free(&s);
}

/* ---- battery connectors ----------------------------------------------------- */

static void
connector_should_reject_another_family_and_a_plug_over_its_rating(void **state)
{
	(void)state;
	char why[160];
	/* The XT90 pair on an XT60 pack carrying 5 A: another
	 * family, however well it is rated. */
	const char *no = compat_connector("XT60", part("t-xt90"), 5.0, 12.0,
	    BURST_S, why, sizeof why);
	assert_non_null(no);
	assert_non_null(strstr(no, "does not mate with the pack's XT60 plug"));
	/* The XT60's own mate carries 5 A and, within AMASS's 60 A for
	 * 1 min, a 57 A burst of 10 s; not 70 A. */
	assert_null(compat_connector("XT60", part("t-xt60-m"), 5.0, 57.0, BURST_S,
	    why, sizeof why));
	assert_non_null(compat_connector("XT60", part("t-xt60-m"), 5.0, 70.0,
	    BURST_S, why, sizeof why));
	assert_non_null(strstr(why, "above its 60 A burst rating"));
	/* Above the continuous rating through the mission: no. */
	assert_non_null(compat_connector("XT60", part("t-xt60-m"), 31.0, 40.0,
	    BURST_S, why, sizeof why));
	/* A burst with no published duration holds for no 10 s burst. */
	assert_non_null(compat_connector("XT30", part("t-xt30"), 5.0, 25.0, BURST_S,
	    why, sizeof why));
	assert_non_null(strstr(why, "no burst rating that holds"));
	/* "XT90S" packs and "AS150/XT150" plugs name their families. */
	assert_true(compat_mates("AS150/XT150", part("t-as150")));
	assert_true(compat_mates("xt60", part("t-xt60-m")));
	assert_false(compat_mates("XT90S", part("t-xt90")));
}

/* A pack joins the harness through its own plug's mate when the
 * catalogue sells it; a plug over its rating, or one the catalogue cannot
 * rate, keeps its pack out of the search; a pack with no published plug
 * is fitted with the lightest whole pair that carries its share. */
static void
kit_should_mate_the_packs_own_plug_within_its_rating(void **state)
{
	(void)state;
	struct setting s;
	struct parts_kit kit;
	char why[160];
	setting(&s, AF_ENTERPRISE_RUGGED, "");
	s.b.connector = "XT60";
	pick(&s, NULL, 5.0, 40.0, 0.2, &kit);
	assert_ptr_equal(kit.connector, part_in(&s, "t-xt60-m"));
	assert_true(kit.connector_mates);
	assert_int_equal(kit.n_connectors, 1);
	assert_rel(kit.connector_kg, 0.003, 1e-12);
	assert_null(parts_kit_plug(&s.x, &s.pk, 5.0, 40.0, why, sizeof why));
	/* 70 A at full throttle: not through an XT60, one pack or two in
	 * series; two in parallel share it, 35 A each. */
	assert_non_null(parts_kit_plug(&s.x, &s.pk, 5.0, 70.0, why, sizeof why));
	s.pk.series = 2;
	assert_non_null(parts_kit_plug(&s.x, &s.pk, 5.0, 70.0, why, sizeof why));
	s.pk.series = 1;
	s.pk.parallel = 2;
	assert_null(parts_kit_plug(&s.x, &s.pk, 5.0, 70.0, why, sizeof why));
	s.pk.parallel = 1;
	/* A JST plug: no rating in the catalogue, no pack. */
	s.b.connector = "JST";
	assert_non_null(parts_kit_plug(&s.x, &s.pk, 1.0, 2.0, why, sizeof why));
	assert_non_null(strstr(why, "no current rating for its JST plug"));
	/* An XT30 carries 10 A (its rating), but its mate has no mass: the
	 * lightest pair that carries it is fitted, the XT30 still bounding
	 * the pack. */
	s.b.connector = "XT30";
	assert_null(parts_kit_plug(&s.x, &s.pk, 5.0, 10.0, why, sizeof why));
	assert_non_null(parts_kit_plug(&s.x, &s.pk, 5.0, 20.0, why, sizeof why));
	pick(&s, NULL, 5.0, 10.0, 0.2, &kit);
	assert_false(kit.connector_mates);
	assert_ptr_equal(kit.plug, part_in(&s, "t-xt30"));
	assert_string_equal(kit.connector->id, "t-as150");
	/* No published plug: a whole pair (never the XT60's half), the
	 * lightest that carries 80 A: the AS150 (24 g) over the XT90 (28 g). */
	s.b.connector = "";
	pick(&s, NULL, 5.0, 80.0, 0.2, &kit);
	assert_string_equal(kit.connector->id, "t-as150");
	assert_null(kit.plug);
	setting_free(&s);
}

/* ---- ESC class --------------------------------------------------------------- */

/* A whoop all-in-one board (12 A a channel, 1-2S) against a 2207 motor
 * on 6S drawing 30 A at full throttle: refused for the bus, and on 2S for
 * the current; a 5-inch 4-in-1 board (55 A, 3-6S) drives it.  A burst
 * rating helps only where it holds for the full-throttle burst. */
static void
esc_should_refuse_a_whoop_board_for_5_inch_motors_on_6s(void **state)
{
	(void)state;
	char why[200];
	struct catalog_esc whoop, five, burst;
	memset(&whoop, 0, sizeof whoop);
	whoop.part_number = "whoop AIO 12A";
	whoop.continuous_current_a = 12.0;
	whoop.burst_current_a = 15.0;
	whoop.cells_min = 1;
	whoop.cells_max = 2;
	whoop.channels = 4;
	five = whoop;
	five.part_number = "4in1 55A";
	five.continuous_current_a = 55.0;
	five.burst_current_a = 65.0;
	five.cells_min = 3;
	five.cells_max = 6;
	struct catalog_motor m2207;
	memset(&m2207, 0, sizeof m2207);
	m2207.cells_min = 4;
	m2207.cells_max = 6;

	const char *no = compat_esc(&whoop, &m2207, 6, 6.0, 30.0, 1.1, BURST_S, why,
	    sizeof why);
	assert_non_null(no);
	assert_non_null(strstr(no, "takes 1-2S, the bus is 6S"));
	assert_non_null(compat_esc(&whoop, NULL, 2, 6.0, 30.0, 1.1, BURST_S, why,
	    sizeof why));
	assert_non_null(strstr(why, "above its 12 A continuous rating"));
	assert_null(compat_esc(&five, &m2207, 6, 6.0, 30.0, 1.1, BURST_S, why,
	    sizeof why));
	/* The motor's own range: a 4-6S motor on 3S is refused. */
	assert_non_null(compat_esc(&five, &m2207, 3, 6.0, 30.0, 1.1, BURST_S, why,
	    sizeof why));
	/* 40 A continuous, 60 A for 10 s: a 50 A burst (55 A with the
	 * margin) fits; the same 60 A for 3 s does not. */
	burst = five;
	burst.continuous_current_a = 40.0;
	burst.burst_current_a = 60.0;
	burst.burst_s = 10.0;
	assert_null(compat_esc(&burst, NULL, 6, 6.0, 50.0, 1.1, BURST_S, why,
	    sizeof why));
	burst.burst_s = 3.0;
	assert_non_null(compat_esc(&burst, NULL, 6, 6.0, 50.0, 1.1, BURST_S, why,
	    sizeof why));
}

/* An all-in-one board's flight controller flies the aircraft: not where
 * the class needs a redundant one, and one board only. */
static void
esc_board_should_carry_the_one_flight_controller_the_class_flies(void **state)
{
	(void)state;
	char why[200];
	struct catalog_esc aio;
	memset(&aio, 0, sizeof aio);
	aio.part_number = "AIO";
	aio.carries = "flight_controller";
	assert_null(compat_board_fc(&aio, 1, true, why, sizeof why));
	assert_non_null(compat_board_fc(&aio, 1, false, why, sizeof why));
	assert_non_null(compat_board_fc(&aio, 2, true, why, sizeof why));
	aio.carries = "";
	assert_null(compat_board_fc(&aio, 2, false, why, sizeof why));
}

/* ---- Remote ID, the role's hardware, the harness ---------------------------- */

static void
kit_should_add_remote_id_from_250_g_where_no_part_does_it(void **state)
{
	(void)state;
	assert_false(compat_remote_id_required(0.2499));
	assert_true(compat_remote_id_required(0.25));
	struct setting s;
	struct parts_kit kit;
	setting(&s, AF_MICRO_AIO, "");
	pick(&s, NULL, 5.0, 40.0, 0.2, &kit);
	assert_false(kit.remote_id_required);
	assert_false(kit_has(&kit, "t-rid-fc") || kit_has(&kit, "t-rid-alone"));
	/* A racer's flight controller feeds no module: the standalone one. */
	pick(&s, NULL, 5.0, 40.0, 0.4, &kit);
	assert_true(kit.remote_id_required && kit_has(&kit, "t-rid-alone"));
	setting_free(&s);
	/* An autopilot's aircraft: the lightest, fed by the controller. */
	setting(&s, AF_ENTERPRISE_RUGGED, "");
	pick(&s, NULL, 5.0, 40.0, 2.0, &kit);
	assert_true(kit_has(&kit, "t-rid-fc") && !kit_has(&kit, "t-rid-alone"));
	setting_free(&s);
	/* None sold: said so. */
	setting(&s, AF_ENTERPRISE_RUGGED, "t-rid-fc,t-rid-alone");
	pick(&s, NULL, 5.0, 40.0, 2.0, &kit);
	assert_true(kit.remote_id_missing);
	setting_free(&s);
}

/* The agricultural class's pump and flow controller is role hardware:
 * the kit says so, and the closing keeps it out of the role's allowance. */
static void
kit_should_count_the_pump_once(void **state)
{
	(void)state;
	struct setting s;
	struct parts_kit kit;
	setting(&s, AF_AGRICULTURAL, "");
	s.p.n_rotors = 6;
	pick(&s, NULL, 100.0, 300.0, 40.0, &kit);
	assert_rel(kit.role_supplied_kg, 0.160, 1e-12);
	assert_string_equal(kit.role_supplied_what, "Pump and flow controller");
	setting_free(&s);
	setting(&s, AF_ENTERPRISE_RUGGED, "");
	pick(&s, NULL, 10.0, 40.0, 3.0, &kit);
	assert_true(kit.role_supplied_kg == 0.0 && kit.role_supplied_what == NULL);
	setting_free(&s);
}

/* Each conductor in the lightest gauge whose chassis-wiring ampacity
 * carries the run, its copper weighed: 57 A over 55 mm in 8 AWG
 * (73 A, 8.37 mm^2): 2 x 8.37e-6 x 0.055 x 8960 = 8.25 g; 600 A in two
 * 3/0 wires a conductor (2 x 328 A); 3 A in 22 AWG. */
static void
harness_should_carry_full_throttle_in_copper(void **state)
{
	(void)state;
	struct parts_run run;
	parts_harness_run(57.0, 0.055, 1, &run);
	assert_string_equal(run.awg, "8");
	assert_int_equal(run.parallel, 1);
	assert_rel(run.ampacity_a, 73.0, 1e-12);
	assert_rel(run.kg, 2.0 * 8.37e-6 * 0.055 * 8960.0, 1e-12);
	parts_harness_run(600.0, 0.5, 1, &run);
	assert_string_equal(run.awg, "3/0");
	assert_int_equal(run.parallel, 2);
	assert_rel(run.ampacity_a, 656.0, 1e-12);
	parts_harness_run(3.0, 0.2, 4, &run);
	assert_string_equal(run.awg, "22");
	assert_rel(run.kg, 4.0 * 2.0 * 0.326e-6 * 0.2 * 8960.0, 1e-12);
	parts_harness_run(0.0, 0.2, 4, &run);
	assert_null(run.awg);
	assert_true(run.kg == 0.0);
}

/* ---- the shipped examples ------------------------------------------------------ */

static struct solve_result *
solve_example(const struct cli_env *env, const char *name)
{
	char path[128];
	snprintf(path, sizeof path, "examples/%s.json", name);
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	assert_int_equal(mission_io_load(path, env->model.chem_names, dg, &s), 0);
	diag_free(dg);
	struct solve_result *r = xcalloc(1, sizeof *r);
	assert_int_equal(engine_solve(&s, &env->model, env->cat, r), 0);
	assert_true(r->parts_selected);
	return r;
}

/* The catalogue entry of a BOM line, or NULL. */
static const struct catalog_avionics *
line_part(const struct cli_env *env, const struct res_bom_line *b)
{
	return b->catalogue_id[0] ? catalog_find_avionics(env->cat, b->catalogue_id)
	    : NULL;
}

/* Does the catalogue sell a mate (with a mass) of plug's family? */
static bool
sells_mate(const struct catalog *cat, const char *plug)
{
	for (size_t i = 0; i < catalog_n_avionics(cat); i++) {
		const struct catalog_avionics *a = catalog_avionics(cat, i);
		if (a->usable && strcmp(a->kind, "connector") == 0
		    && compat_mates(plug, a))
			return true;
	}
	return false;
}

/* Every example's bill: a camera only with a transmitter of its system,
 * a connector of the pack's own family when it names one the catalogue
 * rates, within its rating for the pack's share, and Remote ID from
 * 250 g. */
static void
examples_should_buy_parts_that_work_together(void **state)
{
	(void)state;
	static const char *const names[] = { "fpv_racing_quad", "sar_imaging_quad",
		"agri_dynamic_20kg", "lidar_mapping_quad", "workspace_backpack_inspection" };
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
		struct solve_result *r = solve_example(&env, names[k]);
		const struct catalog_avionics *cam = NULL, *vtx = NULL, *conn = NULL;
		bool rid = false;
		for (int i = 0; i < r->n_bom; i++) {
			const struct catalog_avionics *a = line_part(&env, &r->bom[i]);
			if (a == NULL)
				continue;
			if (strcmp(a->kind, "camera_fpv") == 0)
				cam = a;
			if (strcmp(a->kind, "video_tx") == 0)
				vtx = a;
			if (strcmp(a->kind, "connector") == 0)
				conn = a;
			rid |= compat_does(a, "remote_id");
		}
		char why[200];
		if (vtx != NULL)
			assert_null(compat_video(cam, vtx->video_system,
			    compat_does(vtx, "camera_fpv"), why, sizeof why));
		assert_int_equal(rid, r->closed.mass.total_kg >= 0.25);
		const struct catalog_battery *b = catalog_find_battery(env.cat,
		    r->battery.id);
		const struct res_power_rating *pc = &r->power_path.connector;
		assert_non_null(conn);
		assert_true(pc->present);
		/* The pack's own family's mate where the catalogue sells one;
		 * else a whole pair fitted to the pack, never a half. */
		if (sells_mate(env.cat, b->connector))
			assert_true(compat_mates(b->connector, conn));
		else
			assert_false(compat_connector_half(conn));
		/* The plug that bounds the pack carries its share as sized. */
		assert_true(pc->sized_for_a <= pc->rated_full_a);
		assert_true(pc->sustained_a <= pc->continuous_a);
		free(r);
	}
	cli_env_free(&env);
}

/* The power path the checks read: the record's connectors, harness and
 * ESC with their ratings and currents; the harness in copper for full
 * throttle (the FPV racer's was 0.5 g for 57 A). */
static void
power_path_should_give_ratings_and_currents(void **state)
{
	(void)state;
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	struct solve_result *r = solve_example(&env, "sar_imaging_quad");
	const struct res_power_path *pp = &r->power_path;
	assert_rel(pp->burst_need_s, PERF_FULL_THROTTLE_S, 1e-12);
	const struct catalog_avionics *a = NULL;
	for (int i = 0; i < r->n_bom; i++)
		if (strcmp(r->bom[i].category, "connector") == 0)
			a = catalog_find_avionics(env.cat, r->bom[i].catalogue_id);
	assert_non_null(a);
	assert_rel(pp->connector.continuous_a, a->max_current_a, 1e-12);
	assert_rel(pp->connector.burst_a, a->burst_current_a, 1e-12);
	assert_int_equal(pp->connector.count,
	    r->battery_series_packs * r->battery_parallel_packs);
	assert_rel(pp->connector.full_a, r->closed.peak_current_a
	    / r->battery_parallel_packs, 1e-12);
	assert_true(pp->harness_main.present && pp->harness_arm.present);
	assert_true(pp->harness_main.sized_for_a <= pp->harness_main.continuous_a);
	assert_true(pp->esc.present && pp->esc.count == 4);
	assert_rel(pp->esc.full_a, r->closed.perf.op[OP_FULL].motor_current_a, 1e-12);
	free(r);

	r = solve_example(&env, "fpv_racing_quad");
	double harness_kg = 0.0;
	for (int i = 0; i < r->n_bom; i++)
		if (strcmp(r->bom[i].part_number, "Power harness") == 0)
			harness_kg = r->bom[i].total_mass_kg;
	/* At least the main lead's two conductors of 10 AWG (the lightest
	 * gauge for more than 41 A: the racer's full throttle draws 45-55 A
	 * on its race pack) over half the 100 mm arm. */
	assert_true(r->power_path.harness_main.sized_for_a > 41.0);
	assert_true(harness_kg >= 2.0 * 5.26e-6 * 0.05 * 8960.0 * 0.99);
	assert_true(r->power_path.harness_main.sized_for_a
	    <= r->power_path.harness_main.continuous_a);
	free(r);
	cli_env_free(&env);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(video_should_reject_a_walksnail_camera_on_an_analog_transmitter),
		cmocka_unit_test(kit_should_buy_a_camera_and_transmitter_of_one_system),
		cmocka_unit_test(connector_should_reject_another_family_and_a_plug_over_its_rating),
		cmocka_unit_test(kit_should_mate_the_packs_own_plug_within_its_rating),
		cmocka_unit_test(esc_should_refuse_a_whoop_board_for_5_inch_motors_on_6s),
		cmocka_unit_test(esc_board_should_carry_the_one_flight_controller_the_class_flies),
		cmocka_unit_test(kit_should_add_remote_id_from_250_g_where_no_part_does_it),
		cmocka_unit_test(kit_should_count_the_pump_once),
		cmocka_unit_test(harness_should_carry_full_throttle_in_copper),
		cmocka_unit_test(examples_should_buy_parts_that_work_together),
		cmocka_unit_test(power_path_should_give_ratings_and_currents),
	};
	return cmocka_run_group_tests_name("kit", tests, NULL, NULL);
}
