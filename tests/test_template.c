/* test_template.c — template defaults, shipped templates, strict loading. */
#include "test_util.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/template.h"

static void
default_template_should_be_a4_with_every_section_but_sensitivity(void **state)
{
	(void)state;
	struct template *t = template_default();
	assert_rel(t->page_width_mm, 210.0, 1e-12);
	assert_rel(t->page_height_mm, 297.0, 1e-12);
	assert_int_equal(t->n_sections, TEMPLATE_SEC_MAX);
	assert_int_equal(t->sections[0].id, TEMPLATE_SEC_COVER);
	assert_true(template_section_enabled(t, TEMPLATE_SEC_CHECKS));
	assert_false(template_section_enabled(t, TEMPLATE_SEC_SENSITIVITY));
	assert_string_equal(template_section_get(t, TEMPLATE_SEC_BOM)->title, "Bill of materials");
	assert_string_equal(template_section_name(TEMPLATE_SEC_ENDURANCE), "endurance");
	assert_null(template_section_name(TEMPLATE_SEC_MAX));
	assert_int_equal(access(t->font_regular, R_OK), 0);
	assert_int_equal(access(t->font_bold, R_OK), 0);
	assert_int_equal(access(t->font_mono, R_OK), 0);
	assert_true(t->n_series >= 6);
	assert_string_equal(t->logo, "");
	template_free(t);
	template_free(NULL);
}

static void
shipped_templates_should_load(void **state)
{
	(void)state;
	struct template *a4 = template_load("templates/a4.json", stderr);
	assert_non_null(a4);
	struct template *def = template_default();
	/* a4.json spells out the defaults: the two must agree. */
	assert_rel(a4->page_width_mm, def->page_width_mm, 1e-12);
	assert_rel(a4->margin_left_mm, def->margin_left_mm, 1e-12);
	assert_rel(a4->font_size_pt, def->font_size_pt, 1e-12);
	assert_rel(a4->primary.r, def->primary.r, 1e-12);
	assert_int_equal(a4->n_sections, def->n_sections);
	for (int i = 0; i < def->n_sections; i++) {
		assert_int_equal(a4->sections[i].id, def->sections[i].id);
		assert_string_equal(a4->sections[i].title, def->sections[i].title);
		assert_int_equal(a4->sections[i].enabled, def->sections[i].enabled);
	}
	struct template *lt = template_load("templates/letter.json", stderr);
	assert_non_null(lt);
	assert_rel(lt->page_width_mm, 215.9, 1e-9);
	assert_rel(lt->page_height_mm, 279.4, 1e-9);
	template_free(a4);
	template_free(def);
	template_free(lt);
}

static void
colour_parser_should_accept_only_hash_rrggbb(void **state)
{
	(void)state;
	struct template_colour c;
	assert_int_equal(template_parse_colour("#FF8000", &c), 0);
	assert_rel(c.r, 1.0, 1e-12);
	assert_rel(c.g, 128.0 / 255.0, 1e-12);
	assert_true(c.b == 0.0);
	assert_int_equal(template_parse_colour("#ff800", &c), -1);
	assert_int_equal(template_parse_colour("ff8000", &c), -1);
	assert_int_equal(template_parse_colour("#ff80zz", &c), -1);
	assert_int_equal(template_parse_colour("#ff80001", &c), -1);
	assert_int_equal(template_parse_colour(NULL, &c), -1);
}

/* Writes json to a temp file, loads it, returns the template (or NULL) and
 * the error text in msg. */
static struct template *
load_text(const char *json, char *msg, size_t cap, char *path, size_t path_cap)
{
	snprintf(path, path_cap, "/tmp/aeroeval-tpl-XXXXXX");
	int fd = mkstemp(path);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, json, strlen(json)), (ssize_t)strlen(json));
	close(fd);
	FILE *err = tmpfile();
	struct template *t = template_load(path, err);
	rewind(err);
	size_t n = fread(msg, 1, cap - 1, err);
	msg[n] = '\0';
	fclose(err);
	unlink(path);
	return t;
}

/* Each bad template fails, naming the file, the path and the problem. */
static void
bad_templates_should_fail_with_clear_messages(void **state)
{
	(void)state;
	static const struct {
		const char *json;
		const char *want;  /* substring of the message after "FILE: error: " */
	} cases[] = {
		{ "{\"pagesize\": \"A4\"}", "pagesize: unknown key" },
		{ "{\"margins_mm\": {\"top\": 20, \"inner\": 3}}", "margins_mm: unknown key \"inner\"" },
		{ "{\"margins_mm\": {\"top\": \"20\"}}", "margins_mm.top: must be a number" },
		{ "{\"margins_mm\": {\"top\": 2}}", "margins_mm.top: must be in [12, 80] (got 2)" },
		{ "{\"page\": \"A5\"}", "page: unknown page size \"A5\"" },
		{ "{\"page\": {\"width_mm\": 200}}", "page: needs both width_mm and height_mm" },
		{ "{\"page\": 4}", "page: must be \"A4\", \"Letter\" or an object" },
		{ "{\"colours\": {\"primary\": \"#12345\"}}", "colours.primary: must be a colour \"#rrggbb\"" },
		{ "{\"colours\": {\"primary\": 12}}", "colours.primary: must be a colour" },
		{ "{\"colours\": {\"pink\": \"#ffc0cb\"}}", "colours: unknown key \"pink\"" },
		{ "{\"colours\": {\"series\": [\"#000000\"]}}", "colours.series: must be an array of 2 to 8" },
		{ "{\"colours\": {\"series\": [\"#000000\", \"red\"]}}", "colours.series[1]: must be a colour" },
		{ "{\"fonts\": {\"regular\": \"/no/such/font.ttf\"}}", "fonts.regular: file \"/no/such/font.ttf\" not found" },
		{ "{\"fonts\": {\"bold\": \"missing-bold.ttf\"}}", "fonts.bold: file \"/tmp/missing-bold.ttf\" not found" },
		{ "{\"fonts\": {\"size_pt\": 40}}", "fonts.size_pt: must be in [6, 16]" },
		{ "{\"logo\": \"nologo.png\"}", "logo: file \"/tmp/nologo.png\" not found" },
		{ "{\"sections\": [{\"id\": \"intro\"}]}", "sections[0]: unknown section id \"intro\"" },
		{ "{\"sections\": [{\"id\": \"bom\"}, {\"id\": \"bom\"}]}", "sections[1]: section \"bom\" listed twice" },
		{ "{\"sections\": [{\"id\": \"bom\", \"enabled\": 1}]}", "sections[0]: enabled must be true or false" },
		{ "{\"sections\": [{\"id\": \"bom\", \"hidden\": true}]}", "sections[0]: unknown key \"hidden\"" },
		{ "{\"sections\": [{\"title\": \"x\"}]}", "sections[0]: needs a string \"id\"" },
		{ "{\"sections\": {}}", "sections: must be an array" },
		{ "[1, 2]", "(root): a template must be a JSON object" },
		{ "{\"margins_mm\": {\"left\": 80, \"right\": 80}}", "margins_mm: leave less than 80 x 100 mm" },
	};
	char msg[1024], path[64];
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct template *t = load_text(cases[i].json, msg, sizeof msg, path, sizeof path);
		char prefix[128];
		snprintf(prefix, sizeof prefix, "%s: error: ", path);
		if (t != NULL || strncmp(msg, prefix, strlen(prefix)) != 0 ||
		    strstr(msg, cases[i].want) == NULL)
			print_error("case %zu: %s\n  got: %s  want: %s\n", i, cases[i].json, msg,
			            cases[i].want);
		assert_null(t);
		assert_non_null(strstr(msg, cases[i].want));
		assert_memory_equal(msg, prefix, strlen(prefix));
	}
}

static void
template_errors_should_all_be_reported_in_one_pass(void **state)
{
	(void)state;
	char msg[1024], path[64];
	struct template *t = load_text("{\"page\": \"A5\", \"colours\": {\"grid\": \"#zzzzzz\"},\n"
	                               " \"extra\": 1}", msg, sizeof msg, path, sizeof path);
	assert_null(t);
	int lines = 0;
	for (const char *p = msg; *p != '\0'; p++)
		lines += *p == '\n';
	assert_int_equal(lines, 3);
}

static void
template_syntax_errors_should_give_line_and_column(void **state)
{
	(void)state;
	char msg[512], path[64];
	struct template *t = load_text("{\n  \"page\": \"A4\",\n  \"name\" \"x\"\n}\n", msg,
	                               sizeof msg, path, sizeof path);
	assert_null(t);
	char want[128];
	snprintf(want, sizeof want, "%s:3:", path);
	assert_non_null(strstr(msg, want));
	assert_non_null(strstr(msg, "JSON syntax error"));
	FILE *err = tmpfile();
	assert_null(template_load("/nonexistent/template.json", err));
	rewind(err);
	size_t n = fread(msg, 1, sizeof msg - 1, err);
	msg[n] = '\0';
	fclose(err);
	assert_string_equal(msg, "/nonexistent/template.json: error: cannot read template file\n");
}

static void
partial_template_should_keep_defaults_and_reorder_sections(void **state)
{
	(void)state;
	char msg[512], path[64];
	struct template *t = load_text(
		"{\"page\": {\"width_mm\": 250, \"height_mm\": 353},\n"
		" \"colours\": {\"primary\": \"#AA0011\"},\n"
		" \"sections\": [{\"id\": \"bom\", \"title\": \"Stückliste\"},\n"
		"              {\"id\": \"cover\", \"enabled\": false},\n"
		"              {\"id\": \"sensitivity\", \"enabled\": true}]}",
		msg, sizeof msg, path, sizeof path);
	assert_non_null(t);
	assert_string_equal(msg, "");
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

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(default_template_should_be_a4_with_every_section_but_sensitivity),
		cmocka_unit_test(shipped_templates_should_load),
		cmocka_unit_test(colour_parser_should_accept_only_hash_rrggbb),
		cmocka_unit_test(bad_templates_should_fail_with_clear_messages),
		cmocka_unit_test(template_errors_should_all_be_reported_in_one_pass),
		cmocka_unit_test(template_syntax_errors_should_give_line_and_column),
		cmocka_unit_test(partial_template_should_keep_defaults_and_reorder_sections),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
