/* test_parts.c — the parts search's own rules: which current a motor's
 * rating bounds (its max_current_basis), an integrated system's published
 * thrust, the doubt screen, the avionics and frame-kit choices of
 * parts/kit.c (its compatibility rules: test_kit.c), the price line of
 * the bill of materials, and whole solves: frame kit and avionics on the
 * BOM with their prices and dates, and the agricultural example closing
 * on real parts.  Runs from the repository root. */
#include "test_util.h"

#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "catalog/catalog.h"
#include "diag/diag.h"
#include "engine/engine.h"
#include "input/mission_io.h"
#include "parts/parts_int.h"
#include "parts/screen.h"
#include "util/units.h"
#include "util/xalloc.h"

/* ---- motor ratings ------------------------------------------------------ */

/* The limits of a motor with this rating. */
static void
limits_of(const char *basis, double max_a, bool integrated, double esc_a,
          struct parts_motor_limits *l)
{
	struct catalog_motor m;
	memset(&m, 0, sizeof m);
	m.max_current_basis = basis;
	m.max_current_a = max_a;
	m.integrated = integrated;
	m.integrated_esc_current_a = esc_a;
	parts_motor_limits(&m, l);
}

static void
limits_should_bound_an_integrated_system_by_its_esc_and_published_thrust(void **state)
{
	(void)state;
	struct parts_motor_limits l;
	limits_of("continuous", 30.0, true, 28.5, &l);
	assert_rel(l.sustained_a, 28.5, 1e-12);
	assert_true(l.full_a == 0.0); /* full throttle: the thrust cap instead */
	limits_of("continuous", 30.0, true, 0.0, &l);
	assert_rel(l.sustained_a, 30.0, 1e-12);
}

static void
limits_should_hold_a_continuous_rating_at_full_throttle_too(void **state)
{
	(void)state;
	struct parts_motor_limits l;
	limits_of("continuous", 65.0, false, 0.0, &l);
	assert_rel(l.sustained_a, 65.0, 1e-12);
	assert_rel(l.full_a, 65.0, 1e-12);
	assert_string_equal(l.full_text, "continuous rating");
}

static void
limits_should_name_a_peak_rating_and_an_unknown_duration(void **state)
{
	(void)state;
	struct parts_motor_limits l;
	limits_of("peak_180s", 29.7, false, 0.0, &l);
	assert_rel(l.full_a, 29.7, 1e-12);
	assert_rel(l.sustained_a, 29.7, 1e-12);
	assert_string_equal(l.full_text, "peak rating");
	assert_non_null(strstr(l.sustained_text, "no continuous rating"));
	limits_of("peak_unspecified", 29.7, false, 0.0, &l);
	assert_non_null(strstr(l.full_text, "duration not published"));
	limits_of("", 29.7, false, 0.0, &l);
	assert_non_null(strstr(l.full_text, "duration not published"));
}

/* A context with only what the kit and thrust rules read. */
struct kit_fixture {
	struct mission_spec spec;
	struct sizing_params p;
	struct parts_ctx x;
	struct catalog *cat;
};

static void
kit_fixture(struct kit_fixture *f, int airframe_class, double wheelbase_m,
            int rotors, struct catalog *cat)
{
	memset(f, 0, sizeof *f);
	f->cat = cat;
	f->x.cat = cat;
	f->spec.airframe_class = airframe_class;
	f->p.wheelbase_m = wheelbase_m;
	f->p.n_rotors = rotors;
	f->p.air.rho_kg_m3 = RHO_SL_KG_M3;
	f->x.spec = &f->spec;
	f->x.p = &f->p;
	if (cat != NULL)
		parts_kit_init(&f->x);
}

static void
published_thrust_should_scale_with_density_and_the_bus_squared(void **state)
{
	(void)state;
	struct kit_fixture f;
	kit_fixture(&f, AF_AGRICULTURAL, 2.6, 8, NULL);
	struct catalog_motor m;
	memset(&m, 0, sizeof m);
	m.integrated = true;
	m.cells_max = 14;
	m.max_thrust_n = 235.36; /* 24 kgf */
	assert_rel(parts_published_thrust_n(&f.x, &m, 14), 235.36, 1e-12);
	assert_rel(parts_published_thrust_n(&f.x, &m, 12),
	    235.36 * (12.0 / 14.0) * (12.0 / 14.0), 1e-12);
	f.p.air.rho_kg_m3 = 1.0070; /* about 2000 m */
	assert_rel(parts_published_thrust_n(&f.x, &m, 14),
	    235.36 * 1.0070 / RHO_SL_KG_M3, 1e-12);
	m.integrated = false;
	assert_true(parts_published_thrust_n(&f.x, &m, 14) == 0.0);
}

/* ---- the doubt screen --------------------------------------------------- */

static void
doubt_should_refuse_an_uncertain_number_the_search_sizes_on(void **state)
{
	(void)state;
	char why[128];
	struct catalog_prop p;
	memset(&p, 0, sizeof p);
	p.uncertain = "price_usd,mass_g";
	assert_non_null(screen_doubt_prop(&p, why, sizeof why));
	assert_non_null(strstr(why, "mass_g"));
	p.uncertain = "price_usd,mass_gx,ct_static";
	assert_null(screen_doubt_prop(&p, why, sizeof why));
	assert_true(screen_uncertain(p.uncertain, "ct_static"));
	assert_false(screen_uncertain(p.uncertain, "mass_g"));

	struct catalog_battery b;
	memset(&b, 0, sizeof b);
	b.uncertain = "chemistry"; /* the family is known: not a reason */
	assert_null(screen_doubt_battery(&b, why, sizeof why));
	b.uncertain = "chemistry,continuous_c";
	assert_non_null(screen_doubt_battery(&b, why, sizeof why));

	struct catalog_motor m;
	memset(&m, 0, sizeof m);
	m.uncertain = "max_thrust_g";
	assert_null(screen_doubt_motor(&m, why, sizeof why));
	m.integrated = true; /* an integrated system is flown on it */
	assert_non_null(screen_doubt_motor(&m, why, sizeof why));
}

/* ---- connectors and the avionics set ------------------------------------ */

static struct catalog_avionics
avionics(const char *id, const char *kind, double mass_g, double max_a,
         const char *description)
{
	struct catalog_avionics a;
	memset(&a, 0, sizeof a);
	a.id = id;
	a.manufacturer = "Test";
	a.part_number = id;
	a.source = "";
	a.confidence = "medium";
	a.uncertain = "";
	a.price_date = "";
	a.kind = kind;
	a.mass_kg = mass_g / 1000.0;
	a.max_current_a = max_a;
	a.description = description;
	a.usable = mass_g > 0.0;
	return a;
}

static struct catalog *
avionics_catalog(void)
{
	struct catalog_avionics *a = xcalloc(8, sizeof *a);
	a[0] = avionics("t-xt60", "connector", 0.0, 30.0, "XT60 pair"); /* no mass */
	a[1] = avionics("t-xt90", "connector", 28.0, 90.0, "XT90 pair");
	a[2] = avionics("t-as150", "connector", 24.0, 150.0, "AS150 pair");
	a[3] = avionics("t-fc-light", "flight_controller", 8.0, 0.0,
	    "FPV flight controller, H7");
	a[4] = avionics("t-fc-dual", "flight_controller", 39.2, 0.0,
	    "flight controller, H7, dual IMU");
	a[5] = avionics("t-aio", "flight_controller", 5.0, 45.0,
	    "all-in-one flight controller, dual IMU, with 45 A ESC");
	a[6] = avionics("t-gnss-bare", "gnss", 2.7, 0.0, "GNSS without compass");
	a[7] = avionics("t-rx", "receiver", 1.4, 0.0, "receiver");
	struct catalog *c = catalog_alloc();
	catalog_adopt(c, CATALOG_AVIONICS, a, 8);
	catalog_finish(c);
	return c;
}

/* The kit of a 12S aircraft lighter than Remote ID asks for, carrying
 * sustained_a and twice that at full throttle. */
static void
kit_pick(struct kit_fixture *f, double sustained_a, int series, int parallel,
         struct parts_kit *kit)
{
	struct parts_option o;
	memset(&o, 0, sizeof o);
	o.cells = 12;
	struct parts_pack pk;
	memset(&pk, 0, sizeof pk);
	pk.series = series;
	pk.parallel = parallel;
	struct parts_load load = { sustained_a, 2.0 * sustained_a, 0.5 * sustained_a,
		0.2 };
	parts_kit_pick(&f->x, &o, &pk, NULL, &load, kit);
}

static void
avionics_should_meet_the_class_need_and_keep_allowances_for_the_rest(void **state)
{
	(void)state;
	struct kit_fixture f;
	kit_fixture(&f, AF_ENTERPRISE_RUGGED, 1.0, 4, avionics_catalog());
	struct parts_kit kit;
	kit_pick(&f, 20.0, 1, 1, &kit);
	/* Enterprise: the dual-IMU board, not the lighter single one nor the
	 * all-in-one; the GNSS without compass does not do; the receiver
	 * does; telemetry, GNSS, power distribution and sensors stay
	 * allowances. */
	assert_int_equal(kit.n_part, 2);
	assert_string_equal(kit.part[0]->id, "t-fc-dual");
	assert_string_equal(kit.part[1]->id, "t-rx");
	assert_int_equal(kit.n_allowance, 5);
	double allowances = 0.0;
	for (int i = 0; i < kit.n_allowance - 1; i++)
		allowances += kit.allowance_kg[i];
	assert_rel(allowances, 0.080 + 0.090 + 0.050 + 0.060, 1e-12);
	/* The antennas, last: a share of the rest. */
	assert_string_equal(kit.allowance_what[4], "Antennas");
	double rest = 0.0392 + 0.0014 + allowances;
	assert_rel(kit.allowance_kg[4], 0.10 * rest, 1e-12);
	assert_rel(kit.avionics_kg, 1.10 * rest, 1e-12);
	/* Consumer: any flight controller, the lightest (not the AIO). */
	f.spec.airframe_class = AF_CONSUMER_FOLDING;
	kit_pick(&f, 20.0, 1, 1, &kit);
	assert_string_equal(kit.part[0]->id, "t-fc-light");
	parts_kit_free(&f.x);
	catalog_free(f.cat);
}

/* An all-in-one ESC board carries the flight controller (and here the
 * receiver): the kit buys neither again, nor keeps an allowance for them;
 * a redundant flight controller is never an AIO's. */
static void
avionics_should_not_buy_twice_what_the_esc_board_carries(void **state)
{
	(void)state;
	struct kit_fixture f;
	kit_fixture(&f, AF_MICRO_AIO, 0.1, 4, avionics_catalog());
	struct parts_option o;
	memset(&o, 0, sizeof o);
	o.cells = 4;
	struct parts_pack pk;
	memset(&pk, 0, sizeof pk);
	pk.series = pk.parallel = 1;
	struct catalog_esc aio;
	memset(&aio, 0, sizeof aio);
	aio.carries = "flight_controller,receiver";
	aio.channels = 4;
	struct parts_kit bare, kit;
	struct parts_load load = { 10.0, 20.0, 5.0, 0.2 };
	parts_kit_pick(&f.x, &o, &pk, NULL, &load, &bare);
	parts_kit_pick(&f.x, &o, &pk, &aio, &load, &kit);
	/* Micro: the light FC and the receiver as parts, the VTX and camera
	 * as allowances; on the AIO only the allowances stay. */
	assert_int_equal(bare.n_part, 2);
	assert_int_equal(bare.n_on_esc, 0);
	assert_int_equal(kit.n_part, 0);
	assert_int_equal(kit.n_on_esc, 2);
	assert_int_equal(kit.n_allowance, bare.n_allowance);
	/* The parts and their share of the antennas stay off the kit. */
	assert_rel(kit.avionics_kg, bare.avionics_kg - 1.10 * (0.0080 + 0.0014),
	    1e-12);
	/* "receiver" is matched as a whole kind, not inside another word. */
	aio.carries = "flight_controller,receivers";
	parts_kit_pick(&f.x, &o, &pk, &aio, &load, &kit);
	assert_int_equal(kit.n_on_esc, 1);
	/* Enterprise needs a redundant flight controller: bought apart (and
	 * the ESC pick does not take such a board there: test_kit.c). */
	f.spec.airframe_class = AF_ENTERPRISE_RUGGED;
	aio.carries = "flight_controller";
	parts_kit_pick(&f.x, &o, &pk, &aio, &load, &kit);
	assert_int_equal(kit.n_on_esc, 0);
	assert_string_equal(kit.part[0]->id, "t-fc-dual");
	assert_false(parts_kit_takes_board_fc(&f.x));
	f.spec.airframe_class = AF_MICRO_AIO;
	assert_true(parts_kit_takes_board_fc(&f.x));
	parts_kit_free(&f.x);
	catalog_free(f.cat);
}

/* ---- frame kits --------------------------------------------------------- */

static struct catalog_frame
frame(const char *id, int rotors, double wheelbase_mm, double mass_g,
      double max_prop_in, const char *cls, const char *uncertain)
{
	struct catalog_frame f;
	memset(&f, 0, sizeof f);
	f.id = id;
	f.manufacturer = "Test";
	f.part_number = id;
	f.source = "";
	f.confidence = "medium";
	f.uncertain = uncertain;
	f.price_date = "";
	f.rotor_count = rotors;
	f.wheelbase_m = wheelbase_mm / 1000.0;
	f.mass_kg = mass_g / 1000.0;
	f.includes = "plates and arms";
	f.max_prop_in = max_prop_in;
	f.frame_class = cls;
	f.folding = -1;
	f.usable = true;
	return f;
}

static struct catalog *
frame_catalog(void)
{
	struct catalog_frame *fr = xcalloc(5, sizeof *fr);
	fr[0] = frame("t-450", 4, 450.0, 282.0, 10.0, "ConsumerFolding", "");
	fr[1] = frame("t-480-doubt", 4, 480.0, 150.0, 12.0, "ConsumerFolding", "mass_g");
	fr[2] = frame("t-550-hex", 6, 550.0, 478.0, 10.0, "ConsumerFolding", "");
	fr[3] = frame("t-460-enterprise", 4, 460.0, 200.0, 11.0, "EnterpriseRugged", "");
	fr[4] = frame("t-440", 4, 440.0, 240.0, 9.0, "", "");
	struct catalog *c = catalog_alloc();
	catalog_adopt(c, CATALOG_FRAME, fr, 5);
	catalog_finish(c);
	return c;
}

static void
frame_kit_should_fit_rotors_wheelbase_class_and_propeller(void **state)
{
	(void)state;
	struct kit_fixture f;
	kit_fixture(&f, AF_CONSUMER_FOLDING, 0.47, 4, frame_catalog());
	const struct catalog_frame *k;
	/* 9 in: the 440 (unclassed, 6 % below) is lighter than the 450; the
	 * 480 is above the wheelbase and doubted anyway; the 460 is another
	 * class. */
	k = parts_kit_frame(&f.x, 9.0, 1.2, 0.010, 0.200);
	assert_non_null(k);
	assert_string_equal(k->id, "t-440");
	/* 10 in: beyond the 440's limit, the 450 fits. */
	k = parts_kit_frame(&f.x, 10.0, 1.2, 0.010, 0.200);
	assert_string_equal(k->id, "t-450");
	/* A kit more than twice the custom structure is for a heavier
	 * aircraft. */
	assert_null(parts_kit_frame(&f.x, 10.0, 1.2, 0.010, 0.120));
	/* 0.52 m: both quads more than 10 % below the wheelbase. */
	f.p.wheelbase_m = 0.52;
	assert_null(parts_kit_frame(&f.x, 9.0, 1.2, 0.010, 0.200));
	/* Six rotors on 0.55 m: the hexacopter kit. */
	f.p.wheelbase_m = 0.55;
	f.p.n_rotors = 6;
	k = parts_kit_frame(&f.x, 10.0, 2.0, 0.010, 0.400);
	assert_string_equal(k->id, "t-550-hex");
	/* Its arm tube is checked where the kit publishes one. */
	struct catalog_frame tube = *k;
	tube.arm_tube_od_m = 0.012;
	assert_false(parts_kit_frame_fits(&f.x, &tube, 10.0, 2.0, 0.016, 0.400));
	assert_true(parts_kit_frame_fits(&f.x, &tube, 10.0, 2.0, 0.010, 0.400));
	parts_kit_free(&f.x);
	catalog_free(f.cat);
}

/* ---- the price line ----------------------------------------------------- */

/* The parts search's counts of the lines to buy and of those priced
 * (parts/bom.c), which every writer prints: kept in step with the lines. */
static void
recount(struct solve_result *r)
{
	r->bom_parts_lines = r->bom_priced_lines = 0;
	for (int i = 0; i < r->n_bom; i++)
		if (strcmp(r->bom[i].category, "payload") != 0) {
			r->bom_parts_lines++;
			r->bom_priced_lines += r->bom[i].unit_price_usd > 0.0;
		}
}

static void
bom_line(struct solve_result *r, const char *category, int qty, double usd)
{
	struct res_bom_line *b = &r->bom[r->n_bom++];
	memset(b, 0, sizeof *b);
	b->item = r->n_bom;
	b->qty = qty;
	snprintf(b->category, sizeof b->category, "%s", category);
	b->unit_price_usd = usd;
	b->total_price_usd = usd * qty;
	r->bom_price_usd += usd * qty;
	recount(r);
}

static void
price_text_should_say_at_least_and_count_the_unpriced_lines(void **state)
{
	(void)state;
	struct solve_result *r = xcalloc(1, sizeof *r);
	char text[96];
	assert_string_equal(res_price_text(r, text, sizeof text), "");
	r->parts_selected = true;
	bom_line(r, "motor", 4, 129.99);
	bom_line(r, "frame", 1, 0.0);
	bom_line(r, "avionics", 1, 45.5);
	bom_line(r, "custom", 4, 0.0);
	bom_line(r, "payload", 1, 0.0); /* furnished: not a line to buy */
	assert_string_equal(res_price_text(r, text, sizeof text),
	    "≥ 565.46 USD, 2 of 4 lines unpriced");
	r->bom[1].unit_price_usd = 39.99;
	r->bom[3].unit_price_usd = 7.0;
	r->bom_price_usd += 39.99 + 28.0;
	recount(r);
	assert_string_equal(res_price_text(r, text, sizeof text), "633.45 USD");
	for (int i = 0; i < r->n_bom; i++)
		r->bom[i].unit_price_usd = 0.0;
	recount(r);
	assert_string_equal(res_price_text(r, text, sizeof text),
	    "unpriced (4 lines)");
	free(r);
}

/* ---- whole solves -------------------------------------------------------- */

static double
bom_sum_kg(const struct solve_result *r)
{
	double kg = 0.0;
	for (int i = 0; i < r->n_bom; i++)
		kg += r->bom[i].total_mass_kg;
	return kg;
}

static const struct res_bom_line *
bom_find(const struct solve_result *r, const char *category, const char *id)
{
	for (int i = 0; i < r->n_bom; i++)
		if (strcmp(r->bom[i].category, category) == 0
		    && (id == NULL || strcmp(r->bom[i].catalogue_id, id) == 0))
			return &r->bom[i];
	return NULL;
}

static void
solve_file(const struct cli_env *env, const char *path, struct solve_result *r)
{
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	int errors = mission_io_load(path, env->model.chem_names, dg, &s);
	if (errors != 0)
		print_error("%s: %s\n", path, diag_text(dg));
	diag_free(dg);
	assert_int_equal(errors, 0);
	memset(r, 0, sizeof *r);
	assert_int_equal(engine_solve(&s, &env->model, env->cat, r), 0);
}

static bool
copy_into(const char *dir, const char *src_dir, const char *file)
{
	char src[512], dst[512];
	snprintf(src, sizeof src, "%s/%s", src_dir, file);
	snprintf(dst, sizeof dst, "%s/%s", dir, file);
	return test_copy_file(src, dst);
}

static void
bom_should_order_the_frame_kit_and_avionics_with_prices_and_dates(void **state)
{
	(void)state;
	/* The shipped propulsion parts with the fixture's priced frame kit and
	 * avionics (tests/fixtures/catalog/priced). */
	char dir[] = "/tmp/aeroeval-test-parts-XXXXXX";
	assert_non_null(mkdtemp(dir));
	static const char *const shipped[] = { "motors.json", "propellers.json",
		"batteries.json", "escs.json" };
	for (size_t i = 0; i < 4; i++)
		assert_true(copy_into(dir, "data/catalog", shipped[i]));
	assert_true(copy_into(dir, "tests/fixtures/catalog/priced", "frames.json"));
	assert_true(copy_into(dir, "tests/fixtures/catalog/priced", "avionics.json"));
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, dir, 1, stderr), 0);

	char mission[600];
	snprintf(mission, sizeof mission, "%s/quad.json", dir);
	FILE *m = fopen(mission, "w");
	assert_non_null(m);
	/* The kit's own 450 mm wheelbase: the propeller the mission's
	 * wheelbase admits then fits the kit's overlap limit too. */
	fputs("{\"payload_kg\": 0.3, \"max_diameter_m\": 0.45, \"num_rotors\": 4,"
	    " \"airframe_class\": \"ConsumerFolding\", \"t_hover_s\": 600}\n", m);
	assert_int_equal(fclose(m), 0);
	struct solve_result *r = xcalloc(1, sizeof *r);
	solve_file(&env, mission, r);
	assert_true(r->parts_selected);

	const struct res_bom_line *kit = bom_find(r, "frame", "fixture-kit-450");
	assert_non_null(kit);
	assert_rel(kit->unit_price_usd, 39.99, 1e-12);
	assert_string_equal(kit->price_date, "2025-06");
	assert_string_equal(kit->source_url, "https://example.com/kit-450");
	assert_rel(r->closed.mass.frame_kg, 0.095, 1e-12);
	assert_true(r->closed.mass.arm_kg == 0.0);
	for (int i = 0; i < r->n_bom; i++)
		assert_string_not_equal(r->bom[i].part_number, "Carbon arm");

	const struct res_bom_line *fc = bom_find(r, "avionics", "fixture-fc");
	assert_non_null(fc);
	assert_string_equal(fc->price_date, "2025-06");
	assert_non_null(bom_find(r, "avionics", "fixture-gnss"));
	assert_null(bom_find(r, "avionics", "fixture-gnss-bare"));
	const struct res_bom_line *tm = bom_find(r, "avionics", "fixture-telemetry");
	assert_non_null(tm);
	assert_string_equal(tm->price_date, ""); /* no price, no date */
	assert_non_null(bom_find(r, "connector", "fixture-xt90"));

	/* The record's items are the BOM's lines. */
	double av = 0.0;
	for (int i = 0; i < r->n_bom; i++)
		if (strcmp(r->bom[i].category, "avionics") == 0
		    || (strcmp(r->bom[i].category, "custom") == 0
		    && strstr(r->bom[i].description, "allowance") != NULL))
			av += r->bom[i].total_mass_kg;
	assert_rel(av, r->closed.mass.avionics_kg, 1e-9);
	assert_true(fabs(bom_sum_kg(r) - r->closed.mass.total_kg) < 0.001);

	char text[96];
	res_price_text(r, text, sizeof text);
	assert_non_null(strstr(text, "≥ "));
	assert_non_null(strstr(text, "lines unpriced"));

	free(r);
	cli_env_free(&env);
	static const char *const all[] = { "motors.json", "propellers.json",
		"batteries.json", "escs.json", "frames.json", "avionics.json",
		"quad.json" };
	for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
		char p[600];
		snprintf(p, sizeof p, "%s/%s", dir, all[i]);
		remove(p);
	}
	rmdir(dir);
}

/* The agricultural examples size, and where the catalogue holds the
 * propulsion for them they close feasibly on real parts: the record holds
 * the role's T/W, the reserve and the downwash limit, and its bill of
 * materials weighs what it flies.  The static 20 kg hexacopter (66 kg,
 * 20 kgf a rotor at full throttle on 40 in propellers) finds no motor in
 * the catalogue and says so (NO_PARTS, with the census). */
static void
agricultural_sprayers_should_close_feasibly_on_real_parts(void **state)
{
	(void)state;
	static const char *const files[] = { "examples/agri_spray_octo.json",
		"examples/agri_static_20kg.json", "examples/agri_dynamic_20kg.json" };
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	struct solve_result *r = xcalloc(1, sizeof *r);
	double continuous_kg[3] = { 0.0, 0.0, 0.0 };
	int closed = 0;
	for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
		solve_file(&env, files[k], r);
		assert_true(r->custom.converged && r->custom.feasible);
		continuous_kg[k] = r->custom.mass.total_kg;
		if (!r->parts_selected) {
			bool said = false;
			for (int i = 0; i < r->n_violations; i++)
				said |= strcmp(r->violations[i].code, "NO_PARTS") == 0;
			assert_true(said);
			continue;
		}
		closed++;
		assert_true(r->closed.feasible && r->feasible);
		/* The agriculture role's T/W 1.8 with the largest payload
		 * aboard: a requirement, held exactly. */
		double m = r->closed.mass.total_kg;
		double extra = fmax(0.0, r->mission.max_payload_kg - r->mission.payload_kg);
		assert_true(r->closed.thrust_to_weight * m / (m + extra)
		    >= 1.8 * (1.0 - 1e-9));
		assert_true(r->closed.end_soc >= r->closed.reserve_soc);
		assert_true(r->closed.downwash_ms <= r->mission.payload_role.ag_max_downwash_ms);
		assert_true(r->closed.mass.total_kg > 20.0 && r->closed.mass.total_kg < 100.0);
		/* Agricultural avionics: RTK GNSS is not in the catalogue, nor
		 * radars or a pump controller: allowance lines. */
		int allowances = 0;
		for (int i = 0; i < r->n_bom; i++)
			allowances += strcmp(r->bom[i].category, "custom") == 0
			    && strstr(r->bom[i].description, "allowance") != NULL;
		assert_true(allowances >= 2);
		assert_true(fabs(bom_sum_kg(r) - r->closed.mass.total_kg) < 0.001);
	}
	assert_true(closed >= 2);
	/* The tank sprayed out as it flies needs less battery than a full one
	 * carried throughout: the dynamic pair's aircraft is the lighter. */
	assert_true(continuous_kg[2] < continuous_kg[1]);
	free(r);
	cli_env_free(&env);
}

/* Solve the fixture mission at path into *r (the caller frees it), and
 * check it sizes continuously, closes feasibly on real parts, lands above
 * its reserve and its BOM weighs its takeoff mass. */
static struct solve_result *
fixture_closes(const struct cli_env *env, const char *path)
{
	struct solve_result *r = xcalloc(1, sizeof *r);
	solve_file(env, path, r);
	assert_true(r->custom.converged && r->custom.feasible);
	assert_true(r->parts_selected && r->closed.feasible);
	assert_true(r->closed.end_soc >= r->closed.reserve_soc);
	assert_true(fabs(bom_sum_kg(r) - r->closed.mass.total_kg) < 0.001);
	return r;
}

/* A mission whose real parts close lighter than its continuous design
 * (whose laws fit the catalogue's median part): ranked and closed at the
 * continuous mass and at the mass its closest closing grew to, no option
 * passes; the ranking that trusts an option's lighter estimate finds the
 * closing.  This 16 kg delivery hexacopter closes only through that round
 * (with the round removed from parts.c it is infeasible; measured when the
 * fixture was chosen, tests/fixtures/missions). */
static void
search_should_trust_an_options_lighter_estimate_when_nothing_else_closes(void **state)
{
	(void)state;
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	struct solve_result *r = fixture_closes(&env,
	    "tests/fixtures/missions/lighter_on_parts.json");
	assert_true(r->closed.mass.total_kg < r->custom.mass.total_kg);
	free(r);
	cli_env_free(&env);
}

/* A closing with charge to spare that fails only on its pack's checks
 * (current, burst, sag, thrust) also tries the lighter pack its charge
 * asks for.  This imaging quad closes on one bank of two 6S 6500 mAh packs
 * that way; without that try the search settles on two banks of 4S
 * 5500 mAh packs, 0.38 kg heavier (measured when the fixture was chosen,
 * tests/fixtures/missions). */
static void
search_should_try_the_lighter_pack_a_closing_with_spare_charge_asks_for(void **state)
{
	(void)state;
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	struct solve_result *r = fixture_closes(&env,
	    "tests/fixtures/missions/lighter_pack_by_charge.json");
	assert_int_equal(r->battery_parallel_packs, 1);
	assert_true(r->closed.mass.total_kg < r->custom.mass.total_kg);
	free(r);
	cli_env_free(&env);
}

/* More than PARTS_BANK_PARALLEL packs in parallel only when nothing closes
 * on fewer: the delivery quad keeps a bank of at most four; a mission that
 * closes only on a wider bank (this 21 kg inspection octocopter, whose
 * packs' connectors carry the full-throttle current only when shared six
 * ways) gets one, of at most PARTS_MAX_PACKS packs. */
static void
search_should_wire_a_wider_bank_of_packs_only_as_a_last_resort(void **state)
{
	(void)state;
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	struct solve_result *r = fixture_closes(&env, "examples/delivery_quad.json");
	assert_true(r->battery_parallel_packs >= 1);
	assert_true(r->battery_parallel_packs <= PARTS_BANK_PARALLEL);
	free(r);

	r = fixture_closes(&env, "tests/fixtures/missions/wide_bank.json");
	assert_true(r->battery_parallel_packs > PARTS_BANK_PARALLEL);
	assert_true(r->battery_parallel_packs <= PARTS_MAX_PARALLEL);
	assert_true(r->battery_series_packs * r->battery_parallel_packs
	    <= PARTS_MAX_PACKS);
	/* The BOM says how the packs are wired: banks in parallel, the banks
	 * in series. */
	char banks[64];
	snprintf(banks, sizeof banks, "%d banks of %d packs in parallel",
	    r->battery_series_packs, r->battery_parallel_packs);
	const struct res_bom_line *lead = NULL;
	for (int i = 0; i < r->n_bom; i++)
		if (strcmp(r->bom[i].part_number, "Series-parallel lead") == 0)
			lead = &r->bom[i];
	assert_non_null(lead);
	assert_non_null(strstr(lead->description, banks));
	free(r);
	cli_env_free(&env);
}

/* An integrated system's full-throttle burst (longer than the seconds its
 * ESC's peak rating allows) stays within that ESC's continuous rating:
 * the Hobbywing X9 G2L, locked on a light six-rotor sprayer, would
 * otherwise be flown to its published 24 kgf, 116 A a motor through a
 * 30 A ESC (tests/fixtures/missions). */
static void
integrated_system_should_stay_within_its_esc_at_full_throttle(void **state)
{
	(void)state;
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	struct solve_result *r = xcalloc(1, sizeof *r);
	solve_file(&env, "tests/fixtures/missions/integrated_esc_cap.json", r);
	assert_true(r->parts_selected);
	const struct catalog_motor *m = catalog_find_motor(env.cat,
	    "hobbywing-xrotor-x9-g2l-integrated-system");
	assert_non_null(m);
	assert_true(m->integrated && m->integrated_esc_current_a > 0.0);
	const struct res_op *full = &r->closed.perf.op[OP_FULL];
	assert_true(full->valid);
	assert_true(full->motor_current_a <= m->integrated_esc_current_a * 1.001);
	assert_true(full->thrust_n > 0.0);
	free(r);
	cli_env_free(&env);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(limits_should_bound_an_integrated_system_by_its_esc_and_published_thrust),
		cmocka_unit_test(limits_should_hold_a_continuous_rating_at_full_throttle_too),
		cmocka_unit_test(limits_should_name_a_peak_rating_and_an_unknown_duration),
		cmocka_unit_test(published_thrust_should_scale_with_density_and_the_bus_squared),
		cmocka_unit_test(doubt_should_refuse_an_uncertain_number_the_search_sizes_on),
		cmocka_unit_test(avionics_should_meet_the_class_need_and_keep_allowances_for_the_rest),
		cmocka_unit_test(avionics_should_not_buy_twice_what_the_esc_board_carries),
		cmocka_unit_test(frame_kit_should_fit_rotors_wheelbase_class_and_propeller),
		cmocka_unit_test(price_text_should_say_at_least_and_count_the_unpriced_lines),
		cmocka_unit_test(bom_should_order_the_frame_kit_and_avionics_with_prices_and_dates),
		cmocka_unit_test(agricultural_sprayers_should_close_feasibly_on_real_parts),
		cmocka_unit_test(search_should_trust_an_options_lighter_estimate_when_nothing_else_closes),
		cmocka_unit_test(search_should_try_the_lighter_pack_a_closing_with_spare_charge_asks_for),
		cmocka_unit_test(search_should_wire_a_wider_bank_of_packs_only_as_a_last_resort),
		cmocka_unit_test(integrated_system_should_stay_within_its_esc_at_full_throttle),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
