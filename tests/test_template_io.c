/* test_template_io.c — the template loader: the shipped templates, every
 * kind of bad template with file:line:col, and the fonts and logo judged
 * when the template loads (/dev/zero, a FIFO, a corrupt PNG, a non-font). */
#include "test_util.h"

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "template/template.h"
#include "input/template_io.h"
#include "pdf/assets.h"

#include <cairo.h>

#define DEJAVU "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

/* Loads path with the real asset checks; the diagnostics go to *msg
 * (caller frees). */
static struct template *
load_path(const char *path, char **msg)
{
	struct diag *dg = diag_alloc(NULL);
	struct template *t = template_io_load(path, assets_check, dg);
	*msg = strdup(diag_text(dg));
	assert_int_equal(t == NULL, diag_n_errors(dg) > 0);
	if (t == NULL)
		assert_int_equal(diag_exit_status(dg), 2);
	diag_free(dg);
	return t;
}

/* A scratch directory for one test, removed with its files by rm_dir. */
static void
make_dir(char *dir)
{
	strcpy(dir, "/tmp/aeroeval-tpl-XXXXXX");
	assert_non_null(mkdtemp(dir));
}

static void
write_file(const char *dir, const char *name, const void *data, size_t n)
{
	char path[512];
	snprintf(path, sizeof path, "%s/%s", dir, name);
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(data, 1, n, f), n);
	fclose(f);
}

static void
rm_dir(const char *dir)
{
	static const char *const names[] = { "t.json", "logo.png", "font.ttf", "fifo.ttf", NULL };
	char path[512];
	for (int i = 0; names[i] != NULL; i++) {
		snprintf(path, sizeof path, "%s/%s", dir, names[i]);
		unlink(path);
	}
	rmdir(dir);
}

/* json written as dir/t.json (its path into path[128]), then loaded. */
static struct template *
load_in(const char *dir, const char *json, char *path, char **msg)
{
	write_file(dir, "t.json", json, strlen(json));
	snprintf(path, 128, "%s/t.json", dir);
	return load_path(path, msg);
}

/* json as DIR/t.json, loaded; the diagnostics with DIR written "T". */
static struct template *
load_text(const char *json, char **msg)
{
	char dir[64], path[128];
	make_dir(dir);
	write_file(dir, "t.json", json, strlen(json));
	snprintf(path, sizeof path, "%s/t.json", dir);
	struct template *t = load_path(path, msg);
	/* Every DIR/t.json in the text becomes "T". */
	char *p;
	while ((p = strstr(*msg, dir)) != NULL) {
		size_t k = strlen(dir) + strlen("/t.json");
		p[0] = 'T';
		memmove(p + 1, p + k, strlen(p + k) + 1);
	}
	rm_dir(dir);
	return t;
}

static void
template_io_should_load_the_shipped_templates(void **state)
{
	(void)state;
	char *msg;
	struct template *a4 = load_path("templates/a4.json", &msg);
	assert_non_null(a4);
	assert_string_equal(msg, "");
	free(msg);
	struct template *def = template_default();
	/* a4.json spells out the defaults: the two must agree. */
	assert_rel(a4->page_width_mm, def->page_width_mm, 1e-12);
	assert_rel(a4->margin_left_mm, def->margin_left_mm, 1e-12);
	assert_rel(a4->font_size_pt, def->font_size_pt, 1e-12);
	assert_rel(a4->primary.r, def->primary.r, 1e-12);
	assert_string_equal(a4->font_bold, def->font_bold);
	assert_int_equal(a4->n_sections, def->n_sections);
	for (int i = 0; i < def->n_sections; i++) {
		assert_int_equal(a4->sections[i].id, def->sections[i].id);
		assert_string_equal(a4->sections[i].title, def->sections[i].title);
		assert_int_equal(a4->sections[i].enabled, def->sections[i].enabled);
	}
	struct template *lt = load_path("templates/letter.json", &msg);
	assert_non_null(lt);
	free(msg);
	assert_rel(lt->page_width_mm, 215.9, 1e-9);
	assert_rel(lt->page_height_mm, 279.4, 1e-9);
	template_free(a4);
	template_free(def);
	template_free(lt);
}

/* Each bad template fails with exactly this diagnostic (T is the file). */
static void
template_io_should_fail_bad_templates_with_file_line_col(void **state)
{
	(void)state;
	static const struct {
		const char *json;
		const char *want;
	} cases[] = {
		{ "{\"pagesize\": \"A4\"}",
		  "T:1:2: error: pagesize: unknown field\n" },
		{ "{\"colors\": {}}",
		  "T:1:2: error: colors: unknown field; did you mean \"colours\"?\n" },
		{ "{\"margins_mm\": {\"top\": 20, \"inner\": 3}}",
		  "T:1:28: error: margins_mm.inner: unknown field\n" },
		{ "{\"margins_mm\": {\"top\": \"20\"}}",
		  "T:1:24: error: margins_mm.top: wrong type: expected a number, got a string\n" },
		{ "{\"margins_mm\": {\"top\": 2}}",
		  "T:1:24: error: margins_mm.top: out of range: 2 (allowed 12 to 80 mm)\n" },
		{ "{\"page\": \"A5\"}",
		  "T:1:10: error: page: unknown value \"A5\" (allowed: A4, Letter, or "
		  "{\"width_mm\", \"height_mm\"})\n" },
		{ "{\"page\": {\"width_mm\": 200}}",
		  "T:1:10: error: page.height_mm: missing field (a page object gives both "
		  "width_mm and height_mm)\n" },
		{ "{\"page\": 4}",
		  "T:1:10: error: page: wrong type: expected \"A4\", \"Letter\" or an object, "
		  "got a number\n" },
		{ "{\"colours\": {\"primary\": \"#12345\"}}",
		  "T:1:25: error: colours.primary: unknown value \"#12345\" (a colour is \"#rrggbb\")\n" },
		{ "{\"colours\": {\"primary\": 12}}",
		  "T:1:25: error: colours.primary: wrong type: expected a colour \"#rrggbb\", got a number\n" },
		{ "{\"colours\": {\"pink\": \"#ffc0cb\"}}",
		  "T:1:14: error: colours.pink: unknown field\n" },
		{ "{\"colours\": {\"series\": [\"#000000\"]}}",
		  "T:1:24: error: colours.series: out of range: 1 colours (allowed 2 to 8)\n" },
		{ "{\"colours\": {\"series\": [\"#000000\", \"red\"]}}",
		  "T:1:36: error: colours.series[1]: unknown value \"red\" (a colour is \"#rrggbb\")\n" },
		{ "{\"fonts\": {\"regular\": \"/no/such/font.ttf\"}}",
		  "T:1:23: error: fonts.regular: cannot read file: /no/such/font.ttf: "
		  "No such file or directory\n" },
		{ "{\"fonts\": {\"size_pt\": 40}}",
		  "T:1:23: error: fonts.size_pt: out of range: 40 (allowed 6 to 16 pt)\n" },
		{ "{\"sections\": [{\"id\": \"intro\"}]}",
		  "T:1:22: error: sections[0].id: unknown value \"intro\" (allowed: cover, summary, "
		  "rationale, mass, mission, thermal, structure, propulsion, convergence, "
		  "endurance, bom, checks, appendix, sensitivity)\n" },
		{ "{\"sections\": [{\"id\": \"bom\"}, {\"id\": \"bom\"}]}",
		  "T:1:37: error: sections[1].id: duplicate id \"bom\" (first given by sections[0])\n" },
		{ "{\"sections\": [{\"id\": \"bom\", \"enabled\": 1}]}",
		  "T:1:40: error: sections[0].enabled: wrong type: expected true or false, got a number\n" },
		{ "{\"sections\": [{\"id\": \"bom\", \"hidden\": true}]}",
		  "T:1:29: error: sections[0].hidden: unknown field\n" },
		{ "{\"sections\": [{\"title\": \"x\"}]}",
		  "T:1:15: error: sections[0].id: missing field (a section names its id)\n" },
		{ "{\"sections\": {}}",
		  "T:1:14: error: sections: wrong type: expected an array of sections, got an object\n" },
		{ "[1, 2]",
		  "T:1:1: error: the top level must be an object, got an array\n" },
		{ "{\"margins_mm\": {\"left\": 80, \"right\": 80}}",
		  "T:1:16: error: margins_mm: inconsistent values: they leave 50 x 255 mm for "
		  "the text (at least 80 x 100)\n" },
		{ "{\"name\": \"=cmd|' /C calc'!A0\", \"name\": \"x\"}",
		  "T:1:32: error: name: duplicate field (first given at 1:2)\n"
		  "T:1:2: note: name: first given here\n" },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		char *msg;
		struct template *t = load_text(cases[i].json, &msg);
		if (t != NULL || strcmp(msg, cases[i].want) != 0)
			fail_msg("case %zu: %s\n  got: %s  want: %s", i, cases[i].json, msg,
			         cases[i].want);
		free(msg);
	}
}

static void
template_io_should_report_every_error_in_one_pass(void **state)
{
	(void)state;
	char *msg;
	struct template *t = load_text("{\"page\": \"A5\", \"colours\": {\"grid\": \"#zzzzzz\"},\n"
	                               " \"extra\": 1}", &msg);
	assert_null(t);
	int lines = 0;
	for (const char *p = msg; *p != '\0'; p++)
		lines += *p == '\n';
	assert_int_equal(lines, 3);
	free(msg);
}

static void
template_io_should_give_line_and_column_of_a_syntax_error(void **state)
{
	(void)state;
	char *msg;
	assert_null(load_text("{\n  \"page\": \"A4\",\n  \"name\" \"x\"\n}\n", &msg));
	assert_string_equal(msg, "T:3:10: error: malformed JSON near \"\\\"x\\\"\\x0a}\\x0a\"\n");
	free(msg);
	assert_null(load_path("/nonexistent/template.json", &msg));
	assert_string_equal(msg, "/nonexistent/template.json: error: cannot read file: "
	                         "No such file or directory\n");
	free(msg);
}

static void
template_io_should_keep_defaults_and_reorder_sections(void **state)
{
	(void)state;
	char *msg;
	struct template *t = load_text(
		"{\"page\": {\"width_mm\": 250, \"height_mm\": 353},\n"
		" \"colours\": {\"primary\": \"#AA0011\"},\n"
		" \"sections\": [{\"id\": \"bom\", \"title\": \"Stückliste\"},\n"
		"              {\"id\": \"cover\", \"enabled\": false},\n"
		"              {\"id\": \"sensitivity\", \"enabled\": true}]}", &msg);
	assert_non_null(t);
	assert_string_equal(msg, "");
	free(msg);
	assert_rel(t->page_width_mm, 250.0, 1e-12);
	assert_rel(t->primary.r, 170.0 / 255.0, 1e-12);
	assert_rel(t->margin_top_mm, 22.0, 1e-12);   /* default kept */
	assert_int_equal(t->n_sections, 3);
	assert_int_equal(t->sections[0].id, TEMPLATE_SEC_BOM);
	assert_string_equal(t->sections[0].title, "Stückliste");
	assert_false(template_section_enabled(t, TEMPLATE_SEC_COVER));
	assert_true(template_section_enabled(t, TEMPLATE_SEC_SENSITIVITY));
	assert_false(template_section_enabled(t, TEMPLATE_SEC_SUMMARY));   /* not listed */
	assert_null(template_section_get(t, TEMPLATE_SEC_SUMMARY));
	template_free(t);
}

/* ---- files the template names -------------------------------------------- */

static void
template_io_should_refuse_dev_zero_as_a_template(void **state)
{
	(void)state;
	char *msg;
	alarm(10);   /* a reader of /dev/zero that did not stop would be killed */
	assert_null(load_path("/dev/zero", &msg));
	alarm(0);
	assert_string_equal(msg, "/dev/zero: error: cannot read file: not a regular file\n");
	free(msg);
}

static void
template_io_should_refuse_dev_zero_and_a_fifo_as_fonts(void **state)
{
	(void)state;
	char dir[64], path[128], json[512], *msg;
	make_dir(dir);
	snprintf(path, sizeof path, "%s/fifo.ttf", dir);
	assert_int_equal(mkfifo(path, 0600), 0);
	snprintf(json, sizeof json, "{\"fonts\": {\"regular\": \"/dev/zero\",\n"
	         "  \"bold\": \"fifo.ttf\"}}");
	alarm(10);
	assert_null(load_in(dir, json, path, &msg));
	alarm(0);
	char want[1024];
	snprintf(want, sizeof want,
	         "%s:1:23: error: fonts.regular: cannot read file: /dev/zero: not a regular file\n"
	         "%s:2:11: error: fonts.bold: cannot read file: %s/fifo.ttf: not a regular file\n",
	         path, path, dir);
	assert_string_equal(msg, want);
	free(msg);
	rm_dir(dir);
}

static void
template_io_should_refuse_a_non_font_at_load(void **state)
{
	(void)state;
	char dir[64], path[128], *msg;
	make_dir(dir);
	static const char json[] = "{\"fonts\": {\"mono\": \"t.json\"}}";
	assert_null(load_in(dir, json, path, &msg));
	char want[512];
	snprintf(want, sizeof want, "%s:1:20: error: fonts.mono: not a usable TrueType font: "
	         "%s: not a TrueType font (it starts with bytes 7b 22 66 6f)\n", path, path);
	assert_string_equal(msg, want);
	free(msg);
	rm_dir(dir);
}

static void
template_io_should_refuse_a_corrupt_png_logo_at_load(void **state)
{
	(void)state;
	/* A PNG signature and header, then garbage where the image data is:
	 * libpng inside libharu aborted the worker on this (signal 6). */
	static const unsigned char bad_png[] = {
		0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n',
		0, 0, 0, 13, 'I', 'H', 'D', 'R', 0, 0, 0, 16, 0, 0, 0, 16, 8, 2, 0, 0, 0,
		0x90, 0x91, 0x68, 0x36,
		0, 0, 0, 10, 'I', 'D', 'A', 'T', 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 0, 0, 0, 0,
	};
	char dir[64], path[128], *msg;
	make_dir(dir);
	write_file(dir, "logo.png", bad_png, sizeof bad_png);
	static const char json[] = "{\"logo\": \"logo.png\"}";
	assert_null(load_in(dir, json, path, &msg));
	char want[512];
	snprintf(want, sizeof want, "%s:1:10: error: logo: not a usable PNG image: %s/logo.png: "
	         "the image does not decode (", path, dir);
	if (strncmp(msg, want, strlen(want)) != 0)
		fail_msg("got %s want %s...", msg, want);
	free(msg);
	rm_dir(dir);
}

static void
template_io_should_accept_a_real_font_and_logo(void **state)
{
	(void)state;
	char dir[64], path[128], json[512], *msg;
	make_dir(dir);
	/* The smallest honest logo: a 1 x 1 PNG cairo wrote. */
	cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
	snprintf(path, sizeof path, "%s/logo.png", dir);
	assert_int_equal(cairo_surface_write_to_png(s, path), CAIRO_STATUS_SUCCESS);
	cairo_surface_destroy(s);
	snprintf(json, sizeof json, "{\"logo\": \"logo.png\", \"fonts\": {\"bold\": \"%s\"}}", DEJAVU);
	struct template *t = load_in(dir, json, path, &msg);
	assert_non_null(t);
	assert_string_equal(msg, "");
	snprintf(path, sizeof path, "%s/logo.png", dir);
	assert_string_equal(t->logo, path);
	assert_string_equal(t->font_bold, DEJAVU);
	free(msg);
	template_free(t);
	rm_dir(dir);
}

int
main(void)
{
	signal(SIGALRM, SIG_DFL);
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(template_io_should_load_the_shipped_templates),
		cmocka_unit_test(template_io_should_fail_bad_templates_with_file_line_col),
		cmocka_unit_test(template_io_should_report_every_error_in_one_pass),
		cmocka_unit_test(template_io_should_give_line_and_column_of_a_syntax_error),
		cmocka_unit_test(template_io_should_keep_defaults_and_reorder_sections),
		cmocka_unit_test(template_io_should_refuse_dev_zero_as_a_template),
		cmocka_unit_test(template_io_should_refuse_dev_zero_and_a_fifo_as_fonts),
		cmocka_unit_test(template_io_should_refuse_a_non_font_at_load),
		cmocka_unit_test(template_io_should_refuse_a_corrupt_png_logo_at_load),
		cmocka_unit_test(template_io_should_accept_a_real_font_and_logo),
	};
	return cmocka_run_group_tests_name("template_io", tests, NULL, NULL);
}
