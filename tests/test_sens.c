/* test_sens.c — the sensitivity suite, its outputs and the shedding study. */
#include "test_util.h"

#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "cli/cli.h"
#include "diag/diag.h"
#include "pdf/doc.h"
#include "engine/engine.h"
#include "input/mission_io.h"
#include "study/sens.h"
#include "study/sens_report.h"
#include "template/template.h"
#include "util/units.h"
#include "util/xalloc.h"

/* The reference tables, loaded once for the whole program (tests run from
 * the repository root, where data/ is). */
static int
setup_env(void **state)
{
	struct cli_env *env = xcalloc(1, sizeof *env);
	if (cli_env_load(env, NULL, 0, stderr) != 0) {
		free(env);
		return -1;
	}
	*state = env;
	return 0;
}

static int
teardown_env(void **state)
{
	struct cli_env *env = *state;
	cli_env_free(env);
	free(env);
	return 0;
}

static void
load(const struct cli_env *env, const char *path, struct mission_spec *s)
{
	struct diag *dg = diag_alloc(stderr);
	int n_err = mission_io_load(path, env->model.chem_names, dg, s);
	diag_flush(dg);
	diag_free(dg);
	assert_int_equal(n_err, 0);
}

/* A small quad: 0.4 kg payload on a 450 mm wheelbase, ten minutes forward. */
static void
small_drone(struct mission_spec *s)
{
	spec_defaults(s);
	snprintf(s->name, sizeof s->name, "small test quad");
	s->payload_kg = 0.4;
	s->max_diameter_m = 0.45;
	s->t_hover_s = 120;
	s->t_forward_s = 600;
	s->v_forward_ms = 10;
	s->given[SPECF_PAYLOAD_KG] = true;
	s->given[SPECF_MAX_DIAMETER_M] = true;
	s->given[SPECF_T_HOVER_S] = true;
	s->given[SPECF_T_FORWARD_S] = true;
	s->given[SPECF_V_FORWARD_MS] = true;
}

static bool
point_finite(const struct sens_point *p)
{
	return isfinite(p->x) && isfinite(p->mtow_kg) && isfinite(p->hover_endurance_s)
	    && isfinite(p->flight_time_s) && isfinite(p->margin);
}

/* The derivative is exactly the two-point difference of two direct solves
 * at x0 ± h, in the paper's units. */
static void
sens_fd_should_agree_with_direct_two_point_solve(void **state)
{
	const struct cli_env *env = *state;
	struct mission_spec s;
	load(env, "examples/sar_imaging_quad.json", &s);
	static const enum sens_param ids[] = { SENS_PAYLOAD, SENS_ALTITUDE,
		SENS_AUX_POWER, SENS_DIAM_LIMIT };
	for (size_t k = 0; k < sizeof ids / sizeof ids[0]; k++) {
		struct sens_curve *c = xmalloc(sizeof *c);
		sens_sweep(&s, &env->model, ids[k], 0, 0, 0, c, NULL);
		assert_int_equal(c->fd_kind, 0);
		assert_rel(c->x0, sens_nominal_x(&s, &env->model, ids[k]), 1e-12);
		struct sens_point lo, hi;
		sens_eval(&s, &env->model, ids[k], c->x0 - c->h, &lo);
		sens_eval(&s, &env->model, ids[k], c->x0 + c->h, &hi);
		assert_int_equal(lo.status, SENS_OK);
		assert_int_equal(hi.status, SENS_OK);
		double per = sens_params[ids[k]].step / (2.0 * c->h);
		assert_rel(c->d_mtow, (hi.mtow_kg - lo.mtow_kg) * per, 1e-9);
		assert_rel(c->d_hover_min,
		    (hi.hover_endurance_s - lo.hover_endurance_s) / 60.0 * per, 1e-9);
		free(c);
	}
}

/* Payload and altitude cost mass; the resized aircraft still flies the
 * mission, so its hover time moves by little (under 5 % per kg). */
static void
sens_signs_should_be_physical(void **state)
{
	const struct cli_env *env = *state;
	struct mission_spec s;
	load(env, "examples/sar_imaging_quad.json", &s);
	struct sens_curve *c = xmalloc(sizeof *c);
	sens_sweep(&s, &env->model, SENS_PAYLOAD, 0, 0, 0, c, NULL);
	assert_true(c->d_mtow > 1.0);        /* more than the payload itself */
	assert_true(fabs(c->d_hover_min)
	    < 0.05 * c->nominal.hover_endurance_s / 60.0);
	sens_sweep(&s, &env->model, SENS_ALTITUDE, 0, 0, 0, c, NULL);
	assert_true(c->d_mtow > 0.0);
	free(c);
}

/* A small drone pushed to 40 m/s leaves the feasible region, and the
 * crossing lies between the last good and the first bad point. */
static void
sens_sweep_should_report_the_crossing_into_infeasibility(void **state)
{
	const struct cli_env *env = *state;
	struct mission_spec s;
	small_drone(&s);
	struct sens_curve *c = xmalloc(sizeof *c);
	int n_solves = 0;
	sens_sweep(&s, &env->model, SENS_V_FORWARD, 2.0, 40.0, 20, c, &n_solves);
	assert_int_equal(c->nominal.status, SENS_OK);
	assert_rel(c->x0, 10.0, 1e-12);
	assert_true(n_solves >= 20);
	assert_true(c->cross_hi);
	assert_true(c->why_hi[0] != '\0');
	int first_bad = -1;
	for (int i = 0; i < c->n; i++)
		if (c->pt[i].x > c->x0 && c->pt[i].status != SENS_OK) {
			first_bad = i;
			break;
		}
	assert_true(first_bad > 0);
	assert_true(c->x_cross_hi <= c->pt[first_bad].x);
	assert_true(c->x_cross_hi >= c->pt[first_bad - 1].x);
	assert_true(c->x_good_hi <= c->x_cross_hi);
	free(c);
}

/* The crossing of a check that fails continuously is interpolated on that
 * check's margin, so it lands strictly inside the bracketing interval. */
static void
sens_crossing_should_interpolate_a_failing_check(void **state)
{
	const struct cli_env *env = *state;
	struct mission_spec s;
	load(env, "examples/sar_imaging_quad.json", &s);
	struct sens_curve *c = xmalloc(sizeof *c);
	sens_sweep(&s, &env->model, SENS_BATT_LOCK, 0, 0, 0, c, NULL);
	assert_true(c->cross_lo);
	assert_true(c->x_cross_lo < c->x0);
	assert_true(c->x_cross_lo > c->pt[0].x);
	free(c);
}

/* Paper §VII-D: dynamic shedding sizes a lighter battery and structure. */
static void
sens_shedding_should_save_energy_and_frame_mass(void **state)
{
	const struct cli_env *env = *state;
	struct mission_spec st, dy;
	load(env, "examples/agri_static_20kg.json", &st);
	load(env, "examples/agri_dynamic_20kg.json", &dy);
	struct solve_result *rs = xcalloc(1, sizeof *rs);
	struct solve_result *rd = xcalloc(1, sizeof *rd);
	assert_int_equal(engine_solve(&st, &env->model, NULL, rs), 0);
	assert_int_equal(engine_solve(&dy, &env->model, NULL, rd), 0);
	assert_true(rs->custom.converged && rd->custom.converged);
	assert_true(rd->custom.energy_wh < rs->custom.energy_wh);
	const struct res_mass *a = &rs->custom.mass, *b = &rd->custom.mass;
	assert_true(b->frame_kg + b->arm_kg + b->other_kg
	    < a->frame_kg + a->arm_kg + a->other_kg);

	struct sens_shedding sh;
	sens_shedding(&st, &dy, &env->model, &sh);
	assert_true(sh.ok);
	assert_rel(sh.energy_static_wh, rs->custom.energy_wh, 1e-12);
	assert_rel(sh.energy_dynamic_wh, rd->custom.energy_wh, 1e-12);
	assert_true(sh.energy_saving > 0.0);
	assert_true(sh.frame_saving > 0.0);
	assert_true(sh.mtow_dynamic_kg < sh.mtow_static_kg);

	/* The same comparison with the static case derived from the file. */
	struct sens_shedding sh2;
	sens_shedding(NULL, &dy, &env->model, &sh2);
	assert_rel(sh2.energy_saving, sh.energy_saving, 1e-12);
	free(rs);
	free(rd);
}

/* A delivery drop halfway lowers the time-mean mass below the static MTOW. */
static void
sens_delivery_drop_should_lower_the_mean_mass(void **state)
{
	const struct cli_env *env = *state;
	struct mission_spec dy;
	load(env, "examples/delivery_drop_3p5kg.json", &dy);
	struct sens_shedding sh;
	sens_shedding(NULL, &dy, &env->model, &sh);
	assert_true(sh.ok);
	assert_true(sh.avg_mass_reduction > 0.1);
	assert_true(sh.avg_mass_dynamic_kg < sh.mtow_dynamic_kg);
}

/* Walks every number of a JSON tree. */
static int
json_nonfinite(const cJSON *o)
{
	int bad = 0;
	for (const cJSON *c = o->child; c != NULL; c = c->next) {
		if (cJSON_IsNumber(c) && !isfinite(c->valuedouble))
			bad++;
		bad += json_nonfinite(c);
	}
	return bad;
}

/* The whole suite on one example: nominal good everywhere, every number
 * finite, the JSON clean, the threaded sweeps equal to a serial one. */
static void
sens_run_should_be_clean_on_an_example(void **state)
{
	const struct cli_env *env = *state;
	struct mission_spec s;
	load(env, "examples/sar_imaging_quad.json", &s);
	struct sens_result *r = xmalloc(sizeof *r);
	assert_int_equal(sens_run(&s, &env->model, r), 0);
	assert_int_equal(r->nominal.status, SENS_OK);
	assert_true(r->n_solves > 150);
	for (int i = 0; i < SENS_N_PARAMS; i++) {
		const struct sens_curve *c = &r->c[i];
		/* A role copy (spray on an imaging quad) may fail a role check
		 * such as the downwash cap; it must still converge. */
		assert_true(c->nominal.status == SENS_OK
		    || (c->role_substituted && c->nominal.status == SENS_INFEASIBLE));
		assert_true(point_finite(&c->nominal));
		assert_true(c->fd_kind != 2);
		assert_true(isfinite(c->d_mtow) && isfinite(c->d_hover_min)
		    && isfinite(c->d_flight_min));
		assert_true(c->n >= 9 && c->n <= 15);
		for (int k = 0; k < c->n; k++)
			assert_true(point_finite(&c->pt[k]));
	}
	/* Role-specific sweeps of an imaging mission run on a role copy. */
	assert_true(r->c[SENS_DROP_MASS].role_substituted);
	assert_true(r->c[SENS_SPRAY_RATE].role_substituted);
	assert_false(r->c[SENS_PAYLOAD].role_substituted);

	struct sens_curve *c = xmalloc(sizeof *c);
	sens_sweep(&s, &env->model, SENS_CG_SHIFT, 0, 0, 0, c, NULL);
	assert_memory_equal(c, &r->c[SENS_CG_SHIFT], sizeof *c);
	free(c);

	char *json = sens_report_json(r, "test");
	cJSON *root = cJSON_Parse(json);
	assert_non_null(root);
	assert_int_equal(json_nonfinite(root), 0);
	assert_null(strstr(json, "NaN"));
	cJSON *params = cJSON_GetObjectItemCaseSensitive(root, "parameters");
	assert_int_equal(cJSON_GetArraySize(params), SENS_N_PARAMS);
	cJSON_Delete(root);
	free(json);

	struct template *t = template_default();
	unsigned char *pdf = NULL;
	size_t n = 0;
	char err[256] = "";
	assert_int_equal(sens_report_pdf(r, t, "2026-11-22", &pdf, &n, err, sizeof err), 0);
	assert_true(n > 1000);
	assert_memory_equal(pdf, "%PDF", 4);
	free(pdf);
	template_free(t);
	free(r);
}

/* The dossier section renders into someone else's document. */
static void
sens_report_section_should_render_into_a_dossier(void **state)
{
	const struct cli_env *env = *state;
	struct mission_spec s;
	small_drone(&s);
	struct sens_result *r = xmalloc(sizeof *r);
	sens_run(&s, &env->model, r);
	struct template *t = template_default();
	struct doc_info info = { .title = "Design dossier", .mission = "small" };
	struct doc *d = doc_alloc(t, &info);
	doc_heading(d, 1, "Summary");
	doc_paragraph(d, "Before the sensitivity section.");
	assert_int_equal(sens_report_section(d, t, r), 0);
	unsigned char *pdf = NULL;
	size_t n = 0;
	assert_int_equal(doc_save_mem(d, &pdf, &n), 0);
	assert_true(doc_page_count(d) >= 2);
	free(pdf);
	doc_free(d);
	template_free(t);
	free(r);
}

/* A row that has no derivative says so instead of printing a number. */
static void
sens_report_row_should_print_na_without_a_derivative(void **state)
{
	(void)state;
	struct sens_curve *c = xcalloc(1, sizeof *c);
	c->id = SENS_V_FORWARD;
	c->fd_kind = 2;
	c->x0 = 12.0;
	c->nominal.status = SENS_RUNAWAY;
	snprintf(c->nominal.reason, sizeof c->nominal.reason, "MASS_RUNAWAY");
	struct sens_row row;
	sens_report_row(c, &row);
	assert_string_equal(row.mtow, "n/a");
	assert_string_equal(row.hover, "n/a");
	assert_non_null(strstr(row.cross, "MASS_RUNAWAY"));
	c->fd_kind = -1;
	c->d_mtow = 0.0625;
	c->nominal.status = SENS_OK;
	c->cross_hi = true;
	c->x_cross_hi = 25.5;
	snprintf(c->why_hi, sizeof c->why_hi, "MASS_RUNAWAY");
	sens_report_row(c, &row);
	assert_string_equal(row.mtow, "+0.062 kg/m/s (bwd)");
	assert_string_equal(row.cross, "above 25.5 m/s (MASS_RUNAWAY)");
	free(c);
}

/* A role's thrust target is a requirement: every point of a sweep flies
 * the role's T/W, whatever the parameter swept (nothing is relaxed to make
 * a point close; a point that cannot close is reported, not resized). */
static void
sens_should_fly_the_role_thrust_requirement_at_every_point(void **state)
{
	const struct cli_env *env = *state;
	struct mission_spec s;
	load(env, "examples/sar_imaging_quad.json", &s);
	double margin = env->model.role[ROLE_IMAGING].thrust_margin;
	const double scale[] = { 0.5, 1.0, 1.6 };
	for (size_t i = 0; i < sizeof scale / sizeof scale[0]; i++) {
		struct sens_point pt;
		sens_eval(&s, &env->model, SENS_PAYLOAD, scale[i] * s.payload_kg, &pt);
		if (pt.status != SENS_OK)
			continue;
		struct mission_spec t = s;
		t.payload_kg = scale[i] * s.payload_kg;
		struct solve_result *r = xmalloc(sizeof *r);
		memset(r, 0, sizeof *r);
		assert_int_equal(engine_solve(&t, &env->model, NULL, r), 0);
		assert_rel(r->custom.thrust_margin, margin, 1e-15);
		assert_rel(pt.mtow_kg, r->custom.mass.total_kg, 1e-12);
		free(r);
	}
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sens_fd_should_agree_with_direct_two_point_solve),
		cmocka_unit_test(sens_signs_should_be_physical),
		cmocka_unit_test(sens_sweep_should_report_the_crossing_into_infeasibility),
		cmocka_unit_test(sens_crossing_should_interpolate_a_failing_check),
		cmocka_unit_test(sens_shedding_should_save_energy_and_frame_mass),
		cmocka_unit_test(sens_delivery_drop_should_lower_the_mean_mass),
		cmocka_unit_test(sens_run_should_be_clean_on_an_example),
		cmocka_unit_test(sens_report_section_should_render_into_a_dossier),
		cmocka_unit_test(sens_report_row_should_print_na_without_a_derivative),
		cmocka_unit_test(sens_should_fly_the_role_thrust_requirement_at_every_point),
	};
	int rc = cmocka_run_group_tests(tests, setup_env, teardown_env);
	doc_global_cleanup();
	return rc;
}
