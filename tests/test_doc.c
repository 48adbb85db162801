/* test_doc.c — the document engine: a demo dossier with every element. */
#include "test_util.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cairo.h>

#include "pdf/doc.h"
#include "pdf/doc_int.h"
#include "pdf/plot.h"
#include "cli/cli.h"
#include "template/template.h"

#define DEMO_PAGES 9   /* pages of the demo document, checked by eye */

static const char lorem[] =
	"The custom run sizes the aircraft with the role applied: the spray "
	"system adds tank, pump and boom mass, which raises hover power, which "
	"raises the battery, which raises the frame. The loop converges when "
	"the mass changes by less than 0.1 g between iterations. Ambient 35 °C "
	"± 2 °C, cell resistance 1.8 mΩ, disk loading 142 N/m², µ = 0.35, "
	"peak temperature ≤ 60 °C.";

static void
fig_power(struct doc *d)
{
	double v[40], p1[40], p2[40];
	for (int i = 0; i < 40; i++) {
		v[i] = 0.5 * i;
		p1[i] = 410.0 + 0.09 * pow(v[i], 3) - 18.0 * v[i] + 0.0 * i;
		p2[i] = 1.18 * p1[i];
	}
	p2[17] = NAN;   /* a gap, never a jump */
	struct plot *p = plot_alloc(0, 210, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Forward speed (m/s)");
	plot_axis_title(pp, PLOT_Y, "Electrical power (W)");
	plot_line(pp, v, p1, 40, "Baseline", PLOT_COLOUR_AUTO, PLOT_DASH_SOLID);
	plot_line(pp, v, p2, 40, "Custom (spray role)", PLOT_COLOUR_AUTO, PLOT_DASH_SOLID);
	plot_vline(pp, 8.2, "minimum-power speed 8.2 m/s", PLOT_COLOUR_ACCENT, PLOT_DASH_DASHED);
	plot_hline(pp, 900, "ESC continuous limit", PLOT_COLOUR_FAIL, PLOT_DASH_DOTTED);
	doc_figure(d, p, "Power required vs forward speed, baseline and custom runs.");
	plot_free(p);
}

static void
fig_thermal(struct doc *d)
{
	enum { N = 120 };
	double t[N], temp[N], volt[N], soc[N], cur[N];
	for (int i = 0; i < N; i++) {
		t[i] = i * 10.0;
		temp[i] = 25.0 + 30.0 * (1 - exp(-t[i] / 500.0));
		volt[i] = 25.2 - 3.5 * t[i] / 1200.0 - (i > 100 ? 0.5 : 0.0);
		soc[i] = 100.0 - 80.0 * t[i] / 1190.0;
		cur[i] = i < 10 ? 60.0 : (i < 100 ? 42.0 : 48.0);
	}
	struct plot *p = plot_alloc(0, 330, 2, 2);
	struct plot_panel *a = plot_panel(p, 0, 0), *b = plot_panel(p, 0, 1),
	                  *c = plot_panel(p, 1, 0), *e = plot_panel(p, 1, 1);
	plot_title(a, "Battery temperature");
	plot_axis_title(a, PLOT_Y, "T (°C)");
	plot_line(a, t, temp, N, NULL, 1, PLOT_DASH_SOLID);
	plot_hline(a, 60.0, "60 °C runaway limit", PLOT_COLOUR_FAIL, PLOT_DASH_DASHED);
	plot_title(b, "Terminal voltage");
	plot_axis_title(b, PLOT_Y, "V (V)");
	plot_line(b, t, volt, N, NULL, 0, PLOT_DASH_SOLID);
	plot_hline(b, 19.8, "voltage floor 3.3 V/cell", PLOT_COLOUR_WARN, PLOT_DASH_DASHED);
	plot_title(c, "State of charge");
	plot_axis_title(c, PLOT_X, "Time (s)");
	plot_axis_title(c, PLOT_Y, "SOC (%)");
	plot_axis_range(c, PLOT_Y, 0, 100);
	plot_line(c, t, soc, N, NULL, 2, PLOT_DASH_SOLID);
	plot_title(e, "Current");
	plot_axis_title(e, PLOT_X, "Time (s)");
	plot_axis_title(e, PLOT_Y, "I (A)");
	plot_line(e, t, cur, N, NULL, 3, PLOT_DASH_SOLID);
	doc_figure(d, p, "Thermal and electrical traces over the mission.");
	plot_free(p);
}

static void
fig_motors(struct doc *d)
{
	double kv[] = { 320, 380, 400, 480, 500, 620, 690, 720, 900, 1100 };
	double g[] = { 260, 210, 245, 180, 150, 128, 110, 135, 88, 70 };
	double kv2[] = { 340, 450, 580 }, g2[] = { 300, 230, 190 };
	struct plot *p = plot_alloc(0, 220, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Motor KV (rpm/V)");
	plot_axis_title(pp, PLOT_Y, "Motor mass (g)");
	plot_scatter(pp, kv, g, 10, "Catalogue motors", PLOT_MARKER_CIRCLE, PLOT_COLOUR_AUTO);
	plot_scatter(pp, kv2, g2, 3, "Rejected (overlap)", PLOT_MARKER_CROSS, PLOT_COLOUR_AUTO);
	double sq[] = { 800 }, sqm[] = { 240 };
	plot_scatter(pp, sq, sqm, 1, "Square", PLOT_MARKER_SQUARE, PLOT_COLOUR_AUTO);
	double tr[] = { 1000 }, trm[] = { 200 };
	plot_scatter(pp, tr, trm, 1, "Triangle", PLOT_MARKER_TRIANGLE, PLOT_COLOUR_AUTO);
	double di[] = { 1050 }, dim[] = { 240 };
	plot_scatter(pp, di, dim, 1, "Diamond", PLOT_MARKER_DIAMOND, PLOT_COLOUR_AUTO);
	plot_crosshair(pp, 560, 140, "continuous optimum", PLOT_COLOUR_ACCENT);
	plot_point_label(pp, 690, 110, "T-Motor MN5008 (J = 0.82)");
	plot_point_label(pp, 1100, 70, "edge label");
	plot_text(pp, 330, 80, "free text at (330, 80)", PLOT_ALIGN_LEFT);
	doc_figure(d, p, "Motor selection: every catalogue motor, the continuous optimum "
	                 "and the chosen part.");
	plot_free(p);
}

static void
fig_loglog(struct doc *d)
{
	enum { N = 9 };
	double a[N] = { 0.3, 0.6, 1.1, 2.4, 4.0, 7.5, 15, 33, 80 };
	double pr[N] = { 0.33, 0.55, 1.25, 2.2, 4.6, 7.0, 16.5, 30, 71 };
	double line[2] = { 0.2, 100 }, lo10[2], hi10[2], lo25[2], hi25[2];
	for (int i = 0; i < 2; i++) {
		lo10[i] = line[i] * 0.9;
		hi10[i] = line[i] * 1.1;
		lo25[i] = line[i] * 0.75;
		hi25[i] = line[i] * 1.25;
	}
	struct plot *p = plot_alloc(300, 260, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_log(pp, PLOT_X, 1);
	plot_axis_log(pp, PLOT_Y, 1);
	plot_axis_range(pp, PLOT_X, 0.2, 100);
	plot_axis_range(pp, PLOT_Y, 0.2, 100);
	plot_axis_title(pp, PLOT_X, "Actual takeoff mass (kg)");
	plot_axis_title(pp, PLOT_Y, "Predicted takeoff mass (kg)");
	plot_band(pp, line, lo25, hi25, 2, "±25 %", PLOT_COLOUR_MUTED, 0.15);
	plot_band(pp, line, lo10, hi10, 2, "±10 %", PLOT_COLOUR_ACCENT, 0.25);
	plot_line(pp, line, line, 2, NULL, PLOT_COLOUR_TEXT, PLOT_DASH_SOLID);
	plot_scatter(pp, a, pr, N, "Cohort aircraft", PLOT_MARKER_DIAMOND, 0);
	doc_figure(d, p, "Predicted vs actual mass on log-log axes with ±10 % and ±25 % bands.");
	plot_free(p);
}

static void
fig_bars(struct doc *d)
{
	const char *bars[] = { "Baseline", "Custom" };
	const char *parts[] = { "Payload", "Battery", "Frame", "Arms", "Motors", "Propellers",
	                        "ESCs", "Wiring", "Avionics", "Role auxiliary", "Other" };
	double v[22] = { 5000, 4200, 2100, 640, 1180, 260, 320, 380, 450, 0, 200,
	                 5000, 5400, 2400, 720, 1350, 290, 360, 420, 450, 1900, 230 };
	struct plot *p = plot_alloc(0, 250, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_Y, "Mass (g)");
	plot_stacked_bars(pp, 2, bars, 11, parts, v, 0);
	doc_figure(d, p, "Mass budget, baseline vs custom.");
	plot_free(p);
}

static void
fig_tornado(struct doc *d)
{
	const char *names[] = { "Payload mass", "Cell specific energy", "Figure of merit",
	                        "Frame mass fraction", "Air density", "Drag area" };
	double lo[] = { 21.5, 27.9, 28.4, 23.2, 24.9, 25.5 };
	double hi[] = { 29.0, 22.6, 21.9, 26.3, 24.3, 24.6 };
	struct plot *p = plot_alloc(0, 190, 1, 1);
	struct plot_panel *pp = plot_panel(p, 0, 0);
	plot_axis_title(pp, PLOT_X, "Flight time (min)");
	plot_tornado(pp, 6, names, lo, hi, 24.8, "parameter −10 %", "parameter +10 %");
	doc_figure(d, p, "Sensitivity of flight time to ±10 % parameter changes.");
	plot_free(p);
}

static void
fig_degenerate(struct doc *d)
{
	double x[3] = { 2.0, 2.0, 2.0 }, y[3] = { 5.0, 5.0, 5.0 };
	double nx[2] = { NAN, INFINITY }, ny[2] = { 1.0, NAN };
	double it[12], m1[12], m2[12];
	for (int i = 0; i < 12; i++) {
		it[i] = i + 1;
		m1[i] = 24.0 + 6.0 * exp(-0.8 * i);
		m2[i] = 26.5 + 8.0 * exp(-0.6 * i);
	}
	struct plot *p = plot_alloc(0, 150, 1, 3);
	plot_title(plot_panel(p, 0, 0), "Empty panel");
	plot_title(plot_panel(p, 0, 1), "One value, non-finite");
	plot_series(plot_panel(p, 0, 1), x, y, 3, "constant", NULL);
	plot_series(plot_panel(p, 0, 1), nx, ny, 2, "all NaN", NULL);
	struct plot_panel *c = plot_panel(p, 0, 2);
	struct plot_style st = { .auto_colour = 1, .marker = PLOT_MARKER_CIRCLE,
	                         .marker_size_pt = 3.5 };
	plot_title(c, "Convergence");
	plot_axis_title(c, PLOT_X, "Iteration");
	plot_axis_title(c, PLOT_Y, "Mass (kg)");
	plot_series(c, it, m1, 12, "Baseline", &st);
	st.open_marker = 1;
	st.marker = PLOT_MARKER_SQUARE;
	plot_series(c, it, m2, 12, "Custom", &st);
	doc_figure(d, p, "Degenerate panels: no data, a single repeated value, only non-finite points.");
	plot_free(p);
}

/* Numbers, units and a web address in columns narrower than their
 * words: the columns widen to the numbers, a number keeps its unit
 * (no-break space), the address wraps only after '/' or '-' and is a link. */
static void
narrow_table(struct doc *d)
{
	static const struct doc_column cols[] = {
		{ "Part", 1.0, DOC_ALIGN_LEFT }, { "Maker's page", 1.2, DOC_ALIGN_LEFT },
		{ "Mass", 0.25, DOC_ALIGN_RIGHT }, { "Price (USD)", 0.25, DOC_ALIGN_RIGHT },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 4);
	for (int i = 0; i < 3; i++) {
		doc_table_cell(&t, DOC_CELL_NORMAL, "Motor %d with a description long enough to wrap", i + 1);
		doc_table_cell(&t, DOC_CELL_MUTED, "https://example.com/products/motors/long-name-of-the-motor-%d", i + 1);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%.2f\xc2\xa0kg", 3340.25 + i);
		doc_table_cell(&t, DOC_CELL_NORMAL, "\xe2\x89\xa5\xc2\xa0%.2f", 1199.96 + i);
	}
	const char *total[] = { "Total", "", "10023.75\xc2\xa0kg", "\xe2\x89\xa5\xc2\xa0" "3602.88" };
	doc_table_row(&t, total);
	t.total_row = 1;
	doc_table(d, &t);
	doc_table_clear(&t);
}

/* Builds the demo into memory; returns 0 and the bytes, or -1. */
static int
build_demo(const struct template *tpl, unsigned char **pdf, size_t *n, int *pages)
{
	struct doc_info info = { .title = "Design dossier — agri-sprayer",
	                         .mission = "agri-sprayer", .author = "Example Client GmbH",
	                         .subject = "Multirotor sizing", .date = "2026-11-22" };
	struct doc *d = doc_alloc(tpl, &info);
	doc_title(d, "Design dossier: agri-sprayer", "Hexacopter, 10 L spray role — revision B");
	doc_callout(d, DOC_CALLOUT_PASS, "FEASIBLE", "Every constraint holds; the binding "
	            "one is the battery temperature (margin 4.1 °C).");
	const char *kv[] = { "Client", "Example Client GmbH", "Mission", "agri-sprayer",
	                     "Input SHA-256", "3f5a0c9e1b7d2f4a6c8e0b1d3f5a7c9e1b3d5f7a9c1e3b5d7f9a1c3e5b7d9f1a",
	                     "Engine", "aeroeval 0.1.0", "MTOW", "24.8 kg ± 0.3 kg" };
	doc_kv_table(d, kv, 5);
	doc_callout(d, DOC_CALLOUT_FAIL, "INFEASIBLE", "(demo of the other verdict style)");
	doc_callout(d, DOC_CALLOUT_WARN, NULL, "A warning callout without a title.");
	doc_contents(d, "Contents", 4);

	doc_heading(d, 1, "1  Executive summary");
	doc_paragraph(d, lorem);
	doc_paragraph(d, "A long unbreakable token follows: "
	              "AAAAAAAAAABBBBBBBBBBCCCCCCCCCCDDDDDDDDDDEEEEEEEEEEFFFFFFFFFFGGGGGGGGGG"
	              "HHHHHHHHHHIIIIIIIIIIJJJJJJJJJJKKKKKKKKKKLLLLLLLLLLMMMMMMMMMMNNNNNNNNNN"
	              "OOOOOOOOOOPPPPPPPPPPQQQQQQQQQQRRRRRRRRRRSSSSSSSSSSTTTTTTTTTT °C±µΩ²≤ "
	              "and the paragraph continues after it.\nA forced line break.\n\nA new paragraph.");
	doc_heading(d, 2, "1.1  Regulatory class");
	const char *items[] = { "EU class: C4 (informative), MTOW above 4 kg.",
	                        "US Part 107: above the 25 kg (55 lb) limit? No: 24.8 kg.",
	                        lorem };
	doc_bullets(d, items, 3);
	doc_heading(d, 3, "A run-in level-3 heading");
	doc_code(d, "sha256 3f5a0c9e1b7d2f4a6c8e0b1d3f5a7c9e1b3d5f7a9c1e3b5d7f9a1c3e5b7d9f1a");

	doc_heading(d, 1, "2  Figures");
	fig_power(d);
	fig_thermal(d);
	fig_motors(d);
	fig_loglog(d);
	fig_bars(d);
	fig_tornado(d);
	fig_degenerate(d);

	doc_heading(d, 1, "3  Bill of materials");
	narrow_table(d);
	static const struct doc_column cols[] = {
		{ "Item", 0.6, DOC_ALIGN_RIGHT }, { "Part", 3.0, DOC_ALIGN_LEFT },
		{ "Qty", 0.6, DOC_ALIGN_RIGHT }, { "Mass (g)", 1.1, DOC_ALIGN_RIGHT },
		{ "Price (USD)", 1.1, DOC_ALIGN_RIGHT }, { "Check", 0.9, DOC_ALIGN_CENTER },
	};
	struct doc_table t;
	doc_table_init(&t, cols, 6);
	for (int i = 0; i < 120; i++) {
		doc_table_cell(&t, DOC_CELL_NORMAL, "%d", i + 1);
		if (i % 17 == 3)
			doc_table_cell(&t, DOC_CELL_NORMAL, "A part with a long description that "
			               "must wrap inside its cell, row %d", i + 1);
		else
			doc_table_cell(&t, i % 5 == 0 ? DOC_CELL_MONO : DOC_CELL_NORMAL,
			               "Part %03d µ-ESC 60 A", i + 1);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%d", 1 + i % 4);
		doc_table_cell(&t, DOC_CELL_NORMAL, "%.1f", 12.5 * (i % 9 + 1));
		doc_table_cell(&t, DOC_CELL_NORMAL, "%.2f", 3.75 * (i % 11 + 1));
		doc_table_cell(&t, i % 13 == 0 ? DOC_CELL_FAIL : DOC_CELL_PASS, "%s",
		               i % 13 == 0 ? "FAIL" : "PASS");
	}
	const char *total[] = { "", "Total", "", "12 345.0", "6 789.00", "" };
	doc_table_row(&t, total);
	t.total_row = 1;
	doc_table(d, &t);
	doc_table_clear(&t);

	static const char mission[] = "{\n  \"name\": \"agri-sprayer\",\n  \"payload_kg\": 10.0\n}\n";
	doc_attach(d, "agri-sprayer.json", mission, sizeof mission - 1);
	*pages = doc_page_count(d);
	int rc = doc_save_mem(d, pdf, n);
	if (rc != 0)
		print_error("doc error: %s\n", doc_error(d) ? doc_error(d) : "?");
	doc_free(d);
	return rc;
}

/* dir/name, dir being $AEROEVAL_TEST_OUT (a test script's own folder) or
 * build/, made if missing: where the demo dossiers are written to look at
 * (tests/cli_doc.sh reads them). */
static const char *
out_path(char *buf, size_t n, const char *name)
{
	const char *dir = getenv("AEROEVAL_TEST_OUT");
	if (dir == NULL || *dir == '\0')
		dir = "build";
	mkdir(dir, 0777);
	snprintf(buf, n, "%s/%s", dir, name);
	return buf;
}

static void
doc_demo_should_build_without_error_and_be_reproducible(void **state)
{
	(void)state;
	struct template *tpl = template_default();
	unsigned char *a = NULL, *b = NULL;
	size_t na = 0, nb = 0;
	int pages_a = 0, pages_b = 0;
	assert_int_equal(build_demo(tpl, &a, &na, &pages_a), 0);
	assert_int_equal(build_demo(tpl, &b, &nb, &pages_b), 0);
	char path[4200];
	FILE *fb = fopen(out_path(path, sizeof path, "doc_demo_b.pdf"), "wb");
	if (fb != NULL) {
		fwrite(b, 1, nb, fb);
		fclose(fb);
	}
	assert_int_equal(pages_a, DEMO_PAGES);
	assert_int_equal(pages_a, pages_b);
	assert_true(na > 1000);
	assert_true(memcmp(a, "%PDF-", 5) == 0);
	FILE *f = fopen(out_path(path, sizeof path, "doc_demo.pdf"), "wb");
	if (f != NULL) {
		fwrite(a, 1, na, f);
		fclose(f);
	}
	assert_int_equal(na, nb);
	assert_memory_equal(a, b, na);
	free(a);
	free(b);
	template_free(tpl);
}

static void
doc_letter_template_should_build(void **state)
{
	(void)state;
	struct template *tpl = cli_template_load("templates/letter.json", stderr);
	assert_non_null(tpl);
	unsigned char *a = NULL;
	size_t na = 0;
	int pages = 0;
	/* With a logo on the cover: a tiny PNG drawn here with cairo. */
	cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 48, 48);
	cairo_t *cr = cairo_create(s);
	cairo_set_source_rgb(cr, 0.12, 0.23, 0.37);
	cairo_arc(cr, 24, 24, 20, 0, 2 * M_PI);
	cairo_fill(cr);
	cairo_destroy(cr);
	char png[] = "/tmp/aeroeval-logo-XXXXXX";
	int fd = mkstemp(png);
	assert_true(fd >= 0);
	close(fd);
	assert_int_equal(cairo_surface_write_to_png(s, png), CAIRO_STATUS_SUCCESS);
	cairo_surface_destroy(s);
	snprintf(tpl->logo, sizeof tpl->logo, "%s", png);
	assert_int_equal(build_demo(tpl, &a, &na, &pages), 0);
	unlink(png);
	assert_true(pages >= DEMO_PAGES - 2 && pages <= DEMO_PAGES + 2);
	char path[4200];
	FILE *f = fopen(out_path(path, sizeof path, "doc_demo_letter.pdf"), "wb");
	if (f != NULL) {
		fwrite(a, 1, na, f);
		fclose(f);
	}
	free(a);
	template_free(tpl);
}

/* The widths a document measures from its cache of glyph widths are the
 * ones libharu gives for the whole string: Latin, Greek, Cyrillic and
 * signs, a stray byte, an overlong form and a character beyond the Basic
 * Multilingual Plane (measured whole), first and second time alike. */
static void
doc_widths_should_equal_libharus_whole_string_measure(void **state)
{
	(void)state;
	struct template *tpl = template_default();
	struct doc *d = doc_alloc(tpl, NULL);
	assert_null(doc_error(d));
	const char *texts[] = {
		"Takeoff mass (MTOW)", "\xe2\x89\xa4 0.75 \xc2\xb7 \xce\xb1\xce\xb2 \xe2\x86\x92 \xe2\x88\x9e",
		"\xc3\xa9\xc3\xbc\xc3\xb1 \xc5\x81 \xd0\x96\xd0\x94 \xc2\xb2", "a stray \xff byte",
		"overlong \xc1\x81 A", "beyond \xf0\x9f\x98\x80 the plane", "x", "",
	};
	HPDF_Font fonts[] = { d->font, d->bold, doc_mono_font(d) };
	for (int pass = 0; pass < 2; pass++)
		for (size_t f = 0; f < sizeof fonts / sizeof fonts[0]; f++)
			for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
				size_t n = strlen(texts[i]);
				double want = n == 0 ? 0.0 : HPDF_Font_TextWidth(fonts[f],
				    (const HPDF_BYTE *)texts[i], (HPDF_UINT)n).width * 10.0 / 1000.0;
				assert_true(doc_width(fonts[f], 10.0, texts[i], n) == want);
			}
	doc_free(d);
	template_free(tpl);
}

static void
doc_bad_font_should_fail_and_write_nothing(void **state)
{
	(void)state;
	struct template *tpl = template_default();
	snprintf(tpl->font_bold, sizeof tpl->font_bold, "/nonexistent/font.ttf");
	struct doc *d = doc_alloc(tpl, NULL);
	assert_non_null(doc_error(d));
	assert_int_equal(doc_paragraph(d, "text"), -1);
	unsigned char *out = (unsigned char *)"x";
	size_t n = 7;
	assert_int_equal(doc_save_mem(d, &out, &n), -1);
	assert_null(out);
	assert_int_equal(n, 0);
	doc_free(d);
	template_free(tpl);
}

static void
doc_bad_inputs_should_be_sticky_errors(void **state)
{
	(void)state;
	struct template *tpl = template_default();
	struct doc_info info = { .title = "t", .date = "22/11/2026" };
	struct doc *d = doc_alloc(tpl, &info);
	assert_non_null(doc_error(d));
	assert_non_null(strstr(doc_error(d), "date"));
	doc_free(d);

	d = doc_alloc(tpl, NULL);
	assert_null(doc_error(d));
	assert_int_equal(doc_attach(d, "dir/mission.json", "{}", 2), -1);
	assert_non_null(strstr(doc_error(d), "bare file name"));
	doc_free(d);

	static const struct doc_column cols[2] = { { "a", 1, DOC_ALIGN_LEFT },
	                                           { "b", 1, DOC_ALIGN_LEFT } };
	struct doc_table t;
	doc_table_init(&t, cols, 2);
	doc_table_cell(&t, DOC_CELL_NORMAL, "%d", 1);
	d = doc_alloc(tpl, NULL);
	assert_int_equal(doc_table(d, &t), -1);   /* half a row */
	assert_non_null(strstr(doc_error(d), "table"));
	doc_free(d);
	doc_table_clear(&t);

	d = doc_alloc(tpl, NULL);
	unsigned char *out;
	size_t n;
	assert_int_equal(doc_paragraph(d, ""), 0);
	assert_int_equal(doc_save_mem(d, &out, &n), 0);
	free(out);
	assert_int_equal(doc_save_mem(d, &out, &n), -1);   /* saved twice */
	doc_free(d);
	doc_free(NULL);
	template_free(tpl);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(doc_demo_should_build_without_error_and_be_reproducible),
		cmocka_unit_test(doc_letter_template_should_build),
		cmocka_unit_test(doc_widths_should_equal_libharus_whole_string_measure),
		cmocka_unit_test(doc_bad_font_should_fail_and_write_nothing),
		cmocka_unit_test(doc_bad_inputs_should_be_sticky_errors),
	};
	int rc = cmocka_run_group_tests(tests, NULL, NULL);
	doc_global_cleanup();
	return rc;
}
