/* test_template.c — the built-in template, the section helpers and the
 * colour parser (the loader is tested in test_template_io.c). */
#include "test_util.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "template/template.h"

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
	assert_int_equal(template_section_id("endurance"), TEMPLATE_SEC_ENDURANCE);
	assert_int_equal(template_section_id("Endurance"), -1);
	assert_string_equal(template_section_title(TEMPLATE_SEC_BOM), "Bill of materials");
	assert_null(template_section_title(TEMPLATE_SEC_MAX));
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

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(default_template_should_be_a4_with_every_section_but_sensitivity),
		cmocka_unit_test(colour_parser_should_accept_only_hash_rrggbb),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
