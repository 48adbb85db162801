/* test_report.c — the design dossier: every example solved and rendered.
 *
 * Runs from the repository root (data/, examples/, templates/).  Each
 * dossier is also written to build/dossier_NAME.pdf for looking at.
 */
#include "test_util.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "catalog/catalog.h"
#include "cli/cli.h"
#include "diag/diag.h"
#include "pdf/doc.h"
#include "engine/engine.h"
#include "input/mission_io.h"
#include "pdf/report.h"
#include "pdf/report_util.h"
#include "util/sha256.h"
#include "util/strbuf.h"
#include "template/template.h"
#include "util/xalloc.h"

/* A full dossier: cover, 11 sections of one to three pages, the appendix. */
#define MIN_PAGES 14
#define MAX_PAGES 40
/* Generous bound for one render so a slow CI machine or valgrind passes;
 * the measured process CPU time is printed (about 50 ms with -O2, most of
 * it libharu building the font tables and compressing at save). */
#define MAX_RENDER_MS 5000.0

static const char *const examples[] = {
	"agri_dynamic_20kg", "agri_spray_octo", "agri_static_20kg", "coaxial_inspection_quad",
	"delivery_drop_3p5kg", "delivery_quad", "fpv_racing_quad", "infeasible_compact_lifter",
	"lidar_mapping_quad", "sar_imaging_quad",
};
#define N_EXAMPLES ((int)(sizeof examples / sizeof examples[0]))

struct fixture {
	struct cli_env env;
	struct template *tpl;
};

static int
setup(void **state)
{
	struct fixture *fx = xcalloc(1, sizeof *fx);
	if (cli_env_load(&fx->env, NULL, 1, stderr) != 0)
		return -1;
	fx->tpl = template_default();
	*state = fx;
	return 0;
}

static int
teardown(void **state)
{
	struct fixture *fx = *state;
	template_free(fx->tpl);
	cli_env_free(&fx->env);
	free(fx);
	doc_global_cleanup();
	return 0;
}

static unsigned char *
read_file(const char *path, size_t *n)
{
	FILE *f = fopen(path, "rb");
	assert_non_null(f);
	fseek(f, 0, SEEK_END);
	long len = ftell(f);
	fseek(f, 0, SEEK_SET);
	unsigned char *buf = xmalloc((size_t)len + 1);
	assert_int_equal(fread(buf, 1, (size_t)len, f), (size_t)len);
	fclose(f);
	*n = (size_t)len;
	return buf;
}

/* Solves examples/NAME.json; payload_kg >= 0 overrides the payload. */
static struct solve_result *
solve(struct fixture *fx, const char *name, double payload_kg, unsigned char **bytes, size_t *n)
{
	char path[256];
	snprintf(path, sizeof path, "examples/%s.json", name);
	*bytes = read_file(path, n);
	struct diag *dg = diag_alloc(stderr);
	struct mission_spec spec;
	assert_int_equal(mission_io_load(path, fx->env.model.chem_names, dg, &spec), 0);
	diag_free(dg);
	if (payload_kg >= 0) {
		spec.payload_kg = payload_kg;
		spec.given[SPECF_PAYLOAD_KG] = true;
	}
	struct solve_result *r = xcalloc(1, sizeof *r);
	assert_int_equal(engine_solve(&spec, &fx->env.model, fx->env.cat, r), 0);
	engine_explore(r, &fx->env.model);
	sha256_hex(*bytes, *n, r->input_sha256);
	snprintf(r->catalogue_sha256, sizeof r->catalogue_sha256, "%064d", 0);
	return r;
}

/* Pages of a PDF written by libharu (uncompressed object dictionaries). */
static int
count_pages(const unsigned char *pdf, size_t n)
{
	static const char key[] = "/Type /Page";
	int pages = 0;
	for (size_t i = 0; i + sizeof key < n; i++)
		if (memcmp(pdf + i, key, sizeof key - 1) == 0 && pdf[i + sizeof key - 1] != 's')
			pages++;
	return pages;
}

static double
now_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

/* Renders, checks and writes DIR/dossier_<out>.pdf (DIR: see below);
 * returns the pages. */
static int
render_and_check(struct fixture *fx, const struct solve_result *r, const char *name,
                 const char *out, const unsigned char *bytes, size_t n_bytes)
{
	char file[256], err[256] = "";
	snprintf(file, sizeof file, "%s.json", name);
	struct report_input in = {
		.r = r, .tpl = fx->tpl, .mission_name = name, .mission_file_name = file,
		.mission_bytes = bytes, .mission_len = n_bytes, .date = "2026-11-22",
		.engine_version = AEROEVAL_VERSION, .cat = fx->env.cat,
	};
	unsigned char *a = NULL, *b = NULL;
	size_t na = 0, nb = 0;
	double t0 = now_ms();
	int rc = report_render(&in, &a, &na, err, sizeof err);
	double ms = now_ms() - t0;
	if (rc != 0)
		print_error("%s: %s\n", name, err);
	assert_int_equal(rc, 0);
	assert_true(ms < MAX_RENDER_MS);
	assert_int_equal(report_render(&in, &b, &nb, err, sizeof err), 0);
	assert_int_equal(na, nb);
	assert_memory_equal(a, b, na);   /* reproducible to the byte */
	assert_memory_equal(a, "%PDF-", 5);
	int pages = count_pages(a, na);
	print_message("dossier %-28s %2d pages %7zu bytes %6.1f ms\n", out, pages, na, ms);
	/* $AEROEVAL_TEST_OUT (a test script's own folder) or build/. */
	const char *dir = getenv("AEROEVAL_TEST_OUT");
	if (dir == NULL || *dir == '\0')
		dir = "build";
	mkdir(dir, 0777);
	char path[4200];
	snprintf(path, sizeof path, "%s/dossier_%s.pdf", dir, out);
	FILE *f = fopen(path, "wb");
	if (f != NULL) {
		fwrite(a, 1, na, f);
		fclose(f);
	}
	free(a);
	free(b);
	return pages;
}

static void
report_every_example_should_render_reproducibly(void **state)
{
	struct fixture *fx = *state;
	for (int i = 0; i < N_EXAMPLES; i++) {
		unsigned char *bytes;
		size_t n;
		struct solve_result *r = solve(fx, examples[i], -1, &bytes, &n);
		int pages = render_and_check(fx, r, examples[i], examples[i], bytes, n);
		assert_in_range(pages, MIN_PAGES, MAX_PAGES);
		free(r);
		free(bytes);
	}
}

/* A mission beyond reach still gets its dossier.  400 kg on the delivery
 * quad: no shorter flight sizes, so the pages of a design are left out
 * (a diverged iterate describes no aircraft) and the cover, rationale,
 * convergence, checks and appendix remain.  With 60 kg a shorter flight
 * (about 43 % of the mission) sizes, and its aircraft is shown in full. */
static void
report_infeasible_design_should_still_get_a_dossier(void **state)
{
	struct fixture *fx = *state;
	unsigned char *bytes;
	size_t n;
	struct solve_result *r = solve(fx, "delivery_quad", 400.0, &bytes, &n);
	assert_false(r->feasible);
	assert_true(r->ceiling.valid && !r->ceiling.shown);
	int pages = render_and_check(fx, r, "delivery_quad", "infeasible_payload", bytes, n);
	assert_in_range(pages, 4, MIN_PAGES - 1);
	free(r);
	free(bytes);
	r = solve(fx, "delivery_quad", 60.0, &bytes, &n);
	assert_false(r->feasible);
	assert_true(r->ceiling.valid && r->ceiling.shown);
	pages = render_and_check(fx, r, "delivery_quad", "beyond_reach", bytes, n);
	assert_in_range(pages, MIN_PAGES, MAX_PAGES);
	free(r);
	free(bytes);
}

/* A hand-made selection (one motor, made-up BOM lines and candidates, a
 * closed run copied from the continuous one) still renders: the parts
 * paths must not depend on the search's own bookkeeping. */
static void
report_selected_parts_should_render(void **state)
{
	struct fixture *fx = *state;
	unsigned char *bytes;
	size_t n;
	struct solve_result *r = solve(fx, "sar_imaging_quad", -1, &bytes, &n);
	const struct catalog_motor *m = catalog_motor(fx->env.cat, 7);
	assert_non_null(m);
	r->parts_selected = true;
	r->motor = (struct res_part){ .chosen = true, .qty = 4, .unit_mass_kg = m->mass_kg,
	                              .unit_price_usd = m->price_usd, .j_score = 0.213 };
	snprintf(r->motor.id, sizeof r->motor.id, "%s", m->id);
	snprintf(r->motor.manufacturer, sizeof r->motor.manufacturer, "%.63s", m->manufacturer);
	snprintf(r->motor.part_number, sizeof r->motor.part_number, "%s", m->part_number);
	r->closed = r->custom;
	r->closed.mass.total_kg *= 1.03;
	for (int i = 0; i < 40 && (size_t)i < catalog_n_motors(fx->env.cat); i++) {
		const struct catalog_motor *c = catalog_motor(fx->env.cat, (size_t)i);
		struct res_candidate *cd = &r->candidates[r->n_candidates++];
		snprintf(cd->id, sizeof cd->id, "%s", c->id);
		cd->kv = c->kv_rpm_per_v;
		cd->mass_kg = c->mass_kg;
		cd->feasible = i % 7 != 0;
		cd->j_score = cd->feasible ? 0.2 + 0.037 * i : 1e9;
	}
	static const char *const cats[] = { "motor", "propeller", "battery", "esc", "custom" };
	for (int i = 0; i < 5; i++) {
		struct res_bom_line *l = &r->bom[r->n_bom++];
		l->item = i + 1;
		l->qty = i < 2 ? 4 : 1;
		snprintf(l->category, sizeof l->category, "%s", cats[i]);
		snprintf(l->manufacturer, sizeof l->manufacturer, "%s", i == 4 ? "" : "Maker");
		snprintf(l->part_number, sizeof l->part_number, "PN-%d", 100 + i);
		snprintf(l->description, sizeof l->description, "%s", i == 4 ? "Carbon arm tube Ø14.2 × 0.5 mm, 420 mm" : "");
		l->unit_mass_kg = 0.05 * (i + 1);
		l->total_mass_kg = l->unit_mass_kg * l->qty;
		l->unit_price_usd = i == 4 ? 0 : 12.5 * (i + 1);
		l->total_price_usd = l->unit_price_usd * l->qty;
		r->bom_mass_kg += l->total_mass_kg;
		r->bom_price_usd += l->total_price_usd;
	}
	int pages = render_and_check(fx, r, "sar_imaging_quad", "parts_selected", bytes, n);
	assert_in_range(pages, MIN_PAGES, MAX_PAGES);
	free(r);
	free(bytes);
}

static void
report_template_order_and_sensitivity_should_be_honoured(void **state)
{
	struct fixture *fx = *state;
	unsigned char *bytes;
	size_t n;
	struct solve_result *r = solve(fx, "fpv_racing_quad", -1, &bytes, &n);
	struct template *tpl = template_default();
	/* Only checks, then the cover, then sensitivity. */
	for (int i = 0; i < tpl->n_sections; i++)
		tpl->sections[i].enabled = 0;
	struct template_section order[3] = { tpl->sections[TEMPLATE_SEC_CHECKS],
	                                     tpl->sections[TEMPLATE_SEC_COVER],
	                                     tpl->sections[TEMPLATE_SEC_SENSITIVITY] };
	for (int i = 0; i < 3; i++)
		order[i].enabled = 1;
	memcpy(tpl->sections, order, sizeof order);
	tpl->n_sections = 3;
	struct report_input in = { .r = r, .tpl = tpl, .mission_name = "fpv" };
	unsigned char *pdf = NULL;
	size_t np = 0;
	char err[128];
	assert_int_equal(report_render(&in, &pdf, &np, err, sizeof err), 0);
	assert_in_range(count_pages(pdf, np), 3, 7); /* the checks table runs to ~35 rows */
	free(pdf);
	template_free(tpl);
	free(r);
	free(bytes);
}

static void
report_letter_template_should_render(void **state)
{
	struct fixture *fx = *state;
	unsigned char *bytes;
	size_t n;
	struct solve_result *r = solve(fx, "lidar_mapping_quad", -1, &bytes, &n);
	struct template *letter = cli_template_load("templates/letter.json", stderr);
	assert_non_null(letter);
	struct template *a4 = fx->tpl;
	fx->tpl = letter;
	int pages = render_and_check(fx, r, "lidar_mapping_quad", "letter", bytes, n);
	fx->tpl = a4;
	assert_in_range(pages, MIN_PAGES, MAX_PAGES);
	template_free(letter);
	free(r);
	free(bytes);
}

static void
report_bad_input_should_fail_with_a_message(void **state)
{
	(void)state;
	struct report_input in = { 0 };
	unsigned char *pdf = (unsigned char *)"x";
	size_t n = 3;
	char err[128] = "";
	assert_int_equal(report_render(&in, &pdf, &n, err, sizeof err), -1);
	assert_null(pdf);
	assert_int_equal(n, 0);
	assert_true(strlen(err) > 0);
}

/* The render state the sections see, for one solve. */
static struct rep
rep_of(const struct report_input *in)
{
	struct rep rp = { .in = in, .r = in->r, .tpl = in->tpl, .mass_scale = 1.0, .mass_unit = "kg",
	                  .mass_dec = 3 };
	rp.rec = res_record(in->r, &rp.buildable);
	rp.rec_ok = rp.buildable && rp.rec->feasible;
	res_figures(in->r, &rp.fig);
	return rp;
}

static void
report_mtow_should_be_the_bom_plus_the_payload_and_the_record_mass(void **state)
{
	struct fixture *fx = *state;
	int n_buildable = 0;
	for (int i = 0; i < N_EXAMPLES; i++) {
		unsigned char *bytes;
		size_t n;
		struct solve_result *r = solve(fx, examples[i], -1, &bytes, &n);
		struct report_input in = { .r = r, .tpl = fx->tpl, .cat = fx->env.cat };
		struct rep rp = rep_of(&in);
		/* An example the parts do not close has no BOM aircraft (the
		 * unbuildable test below covers how it renders). */
		if (!rp.buildable) {
			free(r);
			free(bytes);
			continue;
		}
		n_buildable++;
		double payload = 0.0;
		for (int k = 0; k < r->n_bom; k++)
			if (strcmp(r->bom[k].category, "payload") == 0)
				payload += r->bom[k].total_mass_kg;
		assert_rel(report_mtow(&rp), r->bom_mass_kg + payload, 1e-12);
		assert_true(fabs(report_mtow(&rp) - r->closed.mass.total_kg) < 1e-3);
		free(r);
		free(bytes);
	}
	assert_true(n_buildable >= N_EXAMPLES / 2);
}

static void
report_price_should_be_a_lower_bound_never_a_zero(void **state)
{
	struct fixture *fx = *state;
	struct solve_result *r = xcalloc(1, sizeof *r);
	struct report_input in = { .r = r, .tpl = fx->tpl };
	struct rep rp = rep_of(&in);
	struct strbuf sb = STRBUF_INIT;
	r->bom_price_usd = 1199.96;
	r->bom_parts_lines = 12;
	r->bom_priced_lines = 1;
	assert_string_equal(report_price(&rp, &sb), "≥" NBSP "1199.96" NBSP "USD, 11 of 12 lines unpriced");
	r->bom_priced_lines = 12;
	assert_string_equal(report_price(&rp, &sb), "1199.96" NBSP "USD");
	r->bom_price_usd = 0.0;
	r->bom_priced_lines = 0;
	assert_string_equal(report_price(&rp, &sb), "not known (none of the 12 lines has a price)");
	strbuf_free(&sb);
	free(r);
}

static void
report_unbuildable_design_should_render_the_continuous_design_as_such(void **state)
{
	struct fixture *fx = *state;
	unsigned char *bytes;
	size_t n;
	struct solve_result *r = solve(fx, "sar_imaging_quad", -1, &bytes, &n);
	/* No parts: what a build without a catalogue gives. */
	r->parts_selected = false;
	r->closed.ran = false;
	r->n_bom = 0;
	r->bom_parts_lines = r->bom_priced_lines = 0;
	struct report_input in = { .r = r, .tpl = fx->tpl };
	struct rep rp = rep_of(&in);
	assert_false(rp.buildable);
	assert_ptr_equal(rp.rec, &r->custom);
	assert_string_equal(report_record_name(&rp), "Continuous design (not buildable)");
	assert_rel(report_mtow(&rp), r->custom.mass.total_kg, 1e-12);
	int pages = render_and_check(fx, r, "sar_imaging_quad", "unbuildable", bytes, n);
	assert_in_range(pages, MIN_PAGES, MAX_PAGES);
	free(r);
	free(bytes);
}

/* The calibration's accuracy and the interval on the takeoff mass are
 * quoted once the engine fills them (cover row, assumptions paragraph). */
static void
report_accuracy_and_interval_should_render_when_valid(void **state)
{
	struct fixture *fx = *state;
	unsigned char *bytes;
	size_t n;
	struct solve_result *r = solve(fx, "lidar_mapping_quad", -1, &bytes, &n);
	r->accuracy = (struct res_accuracy){ .valid = true, .n_rows = 37, .mape = 0.1237,
	                                     .battery_mape = 0.1911, .level = 0.90, .ratio_lo = 0.83,
	                                     .ratio_hi = 1.21, .coverage = 0.892 };
	bool buildable;
	double m = res_record(r, &buildable)->mass.total_kg;
	r->mtow_interval = (struct res_interval){ .valid = true, .level = 0.90, .lo_kg = 0.83 * m,
	                                          .hi_kg = 1.21 * m };
	int pages = render_and_check(fx, r, "lidar_mapping_quad", "accuracy", bytes, n);
	assert_in_range(pages, MIN_PAGES, MAX_PAGES);
	free(r);
	free(bytes);
}

static void
res_eu_class_should_follow_the_mass_limits(void **state)
{
	(void)state;
	assert_string_equal(res_eu_class(0.249), "C0");
	assert_string_equal(res_eu_class(0.25), "C1");
	assert_string_equal(res_eu_class(0.899), "C1");
	assert_string_equal(res_eu_class(3.999), "C2");
	assert_string_equal(res_eu_class(4.0), "C3/C4");
	assert_string_equal(res_eu_class(24.99), "C3/C4");
	assert_string_equal(res_eu_class(25.0), "specific");
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(res_eu_class_should_follow_the_mass_limits),
		cmocka_unit_test(report_bad_input_should_fail_with_a_message),
		cmocka_unit_test(report_mtow_should_be_the_bom_plus_the_payload_and_the_record_mass),
		cmocka_unit_test(report_price_should_be_a_lower_bound_never_a_zero),
		cmocka_unit_test(report_unbuildable_design_should_render_the_continuous_design_as_such),
		cmocka_unit_test(report_accuracy_and_interval_should_render_when_valid),
		cmocka_unit_test(report_every_example_should_render_reproducibly),
		cmocka_unit_test(report_infeasible_design_should_still_get_a_dossier),
		cmocka_unit_test(report_selected_parts_should_render),
		cmocka_unit_test(report_template_order_and_sensitivity_should_be_honoured),
		cmocka_unit_test(report_letter_template_should_render),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
