/* test_plot.c — nice ticks, data-to-page mapping, robustness of figures. */
#include "test_util.h"

#include <stdlib.h>
#include <string.h>

#include "pdf/doc.h"
#include "pdf/plot.h"
#include "template/template.h"

static void
check_ticks_cover(const struct plot_ticks *t, double lo, double hi)
{
	assert_true(t->n >= 2);
	assert_true(t->lo <= lo && t->hi >= hi);
	for (int i = 1; i < t->n; i++)
		assert_true(t->v[i] > t->v[i - 1]);
}

static void
ticks_should_be_nice_for_unit_range(void **state)
{
	(void)state;
	struct plot_ticks t;
	char buf[32];
	plot_ticks_linear(0.0, 1.0, 6, &t);
	check_ticks_cover(&t, 0.0, 1.0);
	assert_int_equal(t.n, 6);
	assert_rel(t.lo, 0.0, 1e-12);
	assert_rel(t.hi, 1.0, 1e-12);
	assert_rel(t.v[1], 0.2, 1e-12);
	plot_tick_label(&t, 1, buf, sizeof buf);
	assert_string_equal(buf, "0.2");
	plot_tick_label(&t, 0, buf, sizeof buf);
	assert_string_equal(buf, "0.0");
}

static void
ticks_should_handle_small_offset_range(void **state)
{
	(void)state;
	struct plot_ticks t;
	char buf[32];
	plot_ticks_linear(0.0013, 0.0021, 6, &t);
	check_ticks_cover(&t, 0.0013, 0.0021);
	assert_rel(t.v[1] - t.v[0], 0.0002, 1e-9);
	assert_rel(t.lo, 0.0012, 1e-9);
	assert_rel(t.hi, 0.0022, 1e-9);
	assert_int_equal(t.decimals, 4);
	plot_tick_label(&t, 2, buf, sizeof buf);
	assert_string_equal(buf, "0.0016");
}

static void
ticks_should_round_an_odd_range_outwards(void **state)
{
	(void)state;
	struct plot_ticks t;
	char buf[32];
	plot_ticks_linear(3.0, 487.0, 6, &t);
	check_ticks_cover(&t, 3.0, 487.0);
	assert_rel(t.lo, 0.0, 1e-12);
	assert_rel(t.hi, 500.0, 1e-12);
	assert_rel(t.v[1], 100.0, 1e-12);
	plot_tick_label(&t, t.n - 1, buf, sizeof buf);
	assert_string_equal(buf, "500");
	/* 2.5-steps need one more decimal: 0, 2.5, 5, ... prints "2.5". */
	plot_ticks_linear(0.0, 10.0, 5, &t);
	assert_rel(t.v[1], 2.5, 1e-12);
	plot_tick_label(&t, 1, buf, sizeof buf);
	assert_string_equal(buf, "2.5");
	/* Negative ranges never print "-0". */
	plot_ticks_linear(-3.3, 2.385, 6, &t);
	check_ticks_cover(&t, -3.3, 2.385);
	for (int i = 0; i < t.n; i++) {
		plot_tick_label(&t, i, buf, sizeof buf);
		assert_true(strcmp(buf, "-0") != 0 && strcmp(buf, "-0.0") != 0);
	}
}

static void
log_ticks_should_use_125_for_few_decades(void **state)
{
	(void)state;
	struct plot_ticks t;
	char buf[32];
	plot_ticks_log(0.3, 80.0, &t);
	assert_true(t.log10);
	assert_rel(t.lo, 0.2, 1e-12);
	assert_rel(t.hi, 100.0, 1e-12);
	assert_int_equal(t.n, 9);   /* 0.2 0.5 1 2 5 10 20 50 100 */
	plot_tick_label(&t, 0, buf, sizeof buf);
	assert_string_equal(buf, "0.2");
	plot_tick_label(&t, 8, buf, sizeof buf);
	assert_string_equal(buf, "100");
	for (int i = 0; i < t.n; i++)
		assert_true(t.labelled[i]);
}

static void
log_ticks_should_label_decades_for_wide_ranges(void **state)
{
	(void)state;
	struct plot_ticks t;
	plot_ticks_log(0.0013, 4.7e3, &t);
	assert_rel(t.lo, 0.001, 1e-12);
	assert_rel(t.hi, 5000.0, 1e-12);
	int labelled = 0;
	for (int i = 0; i < t.n; i++) {
		if (t.labelled[i]) {
			labelled++;
			double e = log10(t.v[i]);
			assert_rel(e, round(e), 1e-9);   /* only decades carry labels */
		}
	}
	assert_int_equal(labelled, 7);   /* 1e-3 .. 1e3 */
	assert_true(t.n > labelled);     /* minor ticks too */
	/* Non-positive input falls back to 1..10 without crashing. */
	plot_ticks_log(-5.0, 0.0, &t);
	assert_rel(t.lo, 1.0, 1e-12);
	assert_rel(t.hi, 10.0, 1e-12);
}

static void
ticks_should_survive_degenerate_ranges(void **state)
{
	(void)state;
	struct plot_ticks t;
	plot_ticks_linear(5.0, 5.0, 6, &t);
	check_ticks_cover(&t, 5.0, 5.0);
	assert_true(t.lo < 5.0 && t.hi > 5.0);
	assert_true(t.hi - t.lo < 2.0);   /* +-10 %, not a huge window */
	plot_ticks_linear(0.0, 0.0, 6, &t);
	assert_rel(t.lo, 0.0, 1e-12);
	assert_rel(t.hi, 1.0, 1e-12);
	plot_ticks_linear(NAN, INFINITY, 6, &t);
	assert_rel(t.lo, 0.0, 1e-12);
	assert_rel(t.hi, 1.0, 1e-12);
	plot_ticks_linear(NAN, 7.0, 6, &t);
	check_ticks_cover(&t, 7.0, 7.0);
	plot_ticks_linear(9.0, 1.0, 6, &t);   /* reversed */
	check_ticks_cover(&t, 1.0, 9.0);
	plot_ticks_log(42.0, 42.0, &t);
	assert_true(t.lo < 42.0 && t.hi > 42.0);
	plot_ticks_linear(1e-300, 2e-300, 6, &t);
	assert_true(t.n >= 2 && t.n <= PLOT_MAX_TICKS);
	plot_ticks_linear(-1e300, 1e300, 6, &t);
	assert_true(t.n >= 2 && t.n <= PLOT_MAX_TICKS);
}

static void
scale_should_map_data_to_page(void **state)
{
	(void)state;
	struct plot_scale lin = { 0.0, 500.0, 0, 100.0, 400.0 };
	assert_rel(plot_scale_map(&lin, 0.0), 100.0, 1e-12);
	assert_rel(plot_scale_map(&lin, 500.0), 400.0, 1e-12);
	assert_rel(plot_scale_map(&lin, 123.7), 100.0 + 300.0 * 123.7 / 500.0, 1e-12);
	struct plot_scale flip = { 20.0, 60.0, 0, 300.0, 50.0 };   /* y down */
	assert_rel(plot_scale_map(&flip, 60.0), 50.0, 1e-12);
	assert_rel(plot_scale_map(&flip, 35.0), 300.0 - 250.0 * 15.0 / 40.0, 1e-12);
	struct plot_scale lg = { 0.2, 100.0, 1, 0.0, 270.0 };
	double dec = 270.0 / log10(500.0);
	assert_rel(plot_scale_map(&lg, 2.0), dec, 1e-12);
	assert_rel(plot_scale_map(&lg, 20.0), 2 * dec, 1e-12);
	assert_true(isnan(plot_scale_map(&lg, 0.0)));
	assert_true(isnan(plot_scale_map(&lg, -3.0)));
	assert_true(isnan(plot_scale_map(&lin, NAN)));
	assert_true(isnan(plot_scale_map(&lin, INFINITY)));
	struct plot_scale zero = { 4.0, 4.0, 0, 10.0, 30.0 };
	assert_rel(plot_scale_map(&zero, 4.0), 20.0, 1e-12);
}

/* Renders a figure into a one-page document and returns its PDF text size;
 * fails the test on any error. */
static size_t
render_alone(struct plot *p)
{
	struct template *tpl = template_default();
	struct doc *d = doc_alloc(tpl, NULL);
	assert_int_equal(doc_figure(d, p, "test"), 1);
	unsigned char *pdf = NULL;
	size_t n = 0;
	int rc = doc_save_mem(d, &pdf, &n);
	if (rc != 0)
		print_error("%s\n", doc_error(d));
	assert_int_equal(rc, 0);
	free(pdf);
	doc_free(d);
	template_free(tpl);
	return n;
}

static void
plot_should_skip_non_finite_points_and_draw_empty_panels(void **state)
{
	(void)state;
	double x[6] = { 1, 2, NAN, 4, INFINITY, 6 }, y[6] = { 1, -INFINITY, 3, 4, 5, NAN };
	struct plot *p = plot_alloc(0, 200, 2, 2);
	plot_line(plot_panel(p, 0, 0), x, y, 6, "gappy", PLOT_COLOUR_AUTO, PLOT_DASH_DASHED);
	plot_scatter(plot_panel(p, 0, 1), x, y, 6, "markers", PLOT_MARKER_TRIANGLE, 3);
	plot_axis_log(plot_panel(p, 0, 1), PLOT_Y, 1);
	plot_band(plot_panel(p, 1, 0), x, y, y, 6, "band", PLOT_COLOUR_AUTO, 0.3);
	plot_hline(plot_panel(p, 1, 0), NAN, "nowhere", PLOT_COLOUR_FAIL, PLOT_DASH_SOLID);
	plot_vline(plot_panel(p, 1, 0), INFINITY, NULL, PLOT_COLOUR_AUTO, PLOT_DASH_SOLID);
	plot_crosshair(plot_panel(p, 1, 0), NAN, 2.0, "x", PLOT_COLOUR_AUTO);
	plot_line(plot_panel(p, 1, 1), NULL, NULL, 0, "empty", PLOT_COLOUR_AUTO, PLOT_DASH_SOLID);
	plot_axis_range(plot_panel(p, 1, 1), PLOT_X, 5.0, 1.0);   /* ignored: bad range */
	assert_true(render_alone(p) > 0);
	plot_free(p);
}

static void
plot_should_render_bars_and_tornado_with_bad_values(void **state)
{
	(void)state;
	const char *bars[] = { "A", NULL };
	double v[4] = { 1.5, NAN, -2.0, 3.25 };
	double lo[2] = { NAN, 1.0 }, hi[2] = { 2.0, INFINITY };
	struct plot *p = plot_alloc(300, 160, 1, 2);
	plot_stacked_bars(plot_panel(p, 0, 0), 2, bars, 2, NULL, v, 1);
	plot_tornado(plot_panel(p, 0, 1), 2, NULL, lo, hi, 1.5, NULL, NULL);
	plot_stacked_bars(plot_panel(p, 0, 0), 0, NULL, 0, NULL, NULL, 0);   /* ignored */
	assert_true(render_alone(p) > 0);
	plot_free(p);
	plot_free(NULL);
}

/* The thermal page's collisions: the state of charge lands on the reserve
 * line right where its label would go, the runaway-limit label sits where
 * the phase labels run down from the top, two phase lines stand close. */
static void
plot_labels_should_cover_neither_each_other_nor_the_data(void **state)
{
	(void)state;
	double t[40], soc[40], temp[40];
	for (int i = 0; i < 40; i++) {
		t[i] = 40.0 * i;
		soc[i] = 100.0 - 83.3 * i / 39.0;        /* lands at the reserve */
		temp[i] = 20.0 + 38.5 * i / 39.0;        /* climbs to the limit */
	}
	struct plot *p = plot_alloc(400, 300, 2, 1);
	struct plot_panel *a = plot_panel(p, 0, 0), *s = plot_panel(p, 1, 0);
	plot_line(a, t, temp, 40, NULL, 1, PLOT_DASH_SOLID);
	plot_hline(a, 60.0, "60 °C runaway limit", PLOT_COLOUR_FAIL, PLOT_DASH_DASHED);
	plot_vline(a, 1500.0, "forward", PLOT_COLOUR_MUTED, PLOT_DASH_DOTTED);
	plot_vline(a, 1530.0, "hover", PLOT_COLOUR_MUTED, PLOT_DASH_DOTTED);
	plot_line(s, t, soc, 40, NULL, 1, PLOT_DASH_SOLID);
	plot_axis_range(s, PLOT_Y, 0, 100);
	plot_hline(s, 16.7, "reserve 17 %", PLOT_COLOUR_WARN, PLOT_DASH_DASHED);
	plot_crosshair(s, 1400.0, 30.0, "continuous optimum", PLOT_COLOUR_ACCENT);
	plot_point_label(s, 1400.0, 30.0, "chosen part (J = -14.1 %)");
	plot_keep_label_boxes(p);
	assert_true(render_alone(p) > 0);
	const struct plot_label_box *b;
	int n = plot_label_boxes(p, &b);
	assert_int_equal(n, 6);
	for (int i = 0; i < n; i++) {
		assert_int_equal(b[i].overlaps, 0);
		assert_int_equal(b[i].data_hits, 0);
		for (int k = 0; k < i; k++)
			assert_false(b[i].panel == b[k].panel && b[i].x0 < b[k].x1 && b[k].x0 < b[i].x1 &&
			             b[i].y0 < b[k].y1 && b[k].y0 < b[i].y1);
	}
	plot_free(p);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(ticks_should_be_nice_for_unit_range),
		cmocka_unit_test(ticks_should_handle_small_offset_range),
		cmocka_unit_test(ticks_should_round_an_odd_range_outwards),
		cmocka_unit_test(log_ticks_should_use_125_for_few_decades),
		cmocka_unit_test(log_ticks_should_label_decades_for_wide_ranges),
		cmocka_unit_test(ticks_should_survive_degenerate_ranges),
		cmocka_unit_test(scale_should_map_data_to_page),
		cmocka_unit_test(plot_should_skip_non_finite_points_and_draw_empty_panels),
		cmocka_unit_test(plot_should_render_bars_and_tornado_with_bad_values),
		cmocka_unit_test(plot_labels_should_cover_neither_each_other_nor_the_data),
	};
	int rc = cmocka_run_group_tests(tests, NULL, NULL);
	doc_global_cleanup();
	return rc;
}
