/* test_bom_csv.c — bom.csv: header, RFC 4180 quoting, CRLF, totals, golden.
 *
 * Run with AEROEVAL_UPDATE_GOLDEN=1 to rewrite the golden files after an
 * intended format change (then review the diff).
 */
#include "test_util.h"
#include "output/bom_csv.h"
#include "util/xalloc.h"

#include <stdlib.h>
#include <string.h>

#define HEADER "item,qty,category,manufacturer,part_number,description," \
	"unit_mass_g,total_mass_g,unit_price_usd,total_price_usd,catalogue_id\r\n"

/* Adds one BOM line and keeps the totals as the engine does: the mass of
 * every line, the price of the lines whose price is known. */
static void
add_line(struct solve_result *r, int qty, const char *category,
         const char *manufacturer, const char *part_number,
         const char *description, double unit_mass_kg, double unit_price_usd,
         const char *catalogue_id)
{
	struct res_bom_line *l = &r->bom[r->n_bom++];
	l->item = r->n_bom;
	l->qty = qty;
	snprintf(l->category, sizeof l->category, "%s", category);
	snprintf(l->manufacturer, sizeof l->manufacturer, "%s", manufacturer);
	snprintf(l->part_number, sizeof l->part_number, "%s", part_number);
	snprintf(l->description, sizeof l->description, "%s", description);
	snprintf(l->catalogue_id, sizeof l->catalogue_id, "%s", catalogue_id);
	l->unit_mass_kg = unit_mass_kg;
	l->total_mass_kg = qty * unit_mass_kg;
	l->unit_price_usd = unit_price_usd;
	l->total_price_usd = qty * unit_price_usd;
	r->bom_mass_kg += l->total_mass_kg;
	r->bom_price_usd += l->total_price_usd;
}

/* A quadcopter BOM with every price known; the caller frees it. */
static struct solve_result *
bom_new(void)
{
	struct solve_result *r = xcalloc(1, sizeof *r);
	r->parts_selected = true;
	add_line(r, 4, "motor", "T-Motor", "MN5008 KV340",
	         "Brushless motor, 340 KV, 6S", 0.13527, 89.9, "tmotor-mn5008-340");
	add_line(r, 4, "propeller", "T-Motor", "P18x6.1",
	         "18\" x 6.1\" carbon \"folding\" prop", 0.0312345, 45.55, "tmotor-p18");
	add_line(r, 1, "battery", "Tattu", "TA-16000-6S",
	         "LiPo 6S 16000 mAh 15C", 1.98768, 279.0, "tattu-16000-6s");
	add_line(r, 4, "esc", "T-Motor", "FLAME 60A",
	         "ESC 60 A\r\nline two", 0.0739, 69.949, "tmotor-flame60");
	return r;
}

/* The text after `skip` CRLFs up to the next CRLF, in a static buffer.  The
 * ESC description holds a CRLF of its own, so from the ESC line on a record
 * is one further than its line number. */
static const char *
record(const char *text, int skip)
{
	static char out[1024];
	for (int i = 0; i < skip; i++) {
		text = strstr(text, "\r\n");
		assert_non_null(text);
		text += 2;
	}
	const char *end = strstr(text, "\r\n");
	assert_non_null(end);
	size_t n = (size_t)(end - text);
	assert_true(n < sizeof out);
	memcpy(out, text, n);
	out[n] = '\0';
	return out;
}

static void
bom_csv_should_start_with_the_product_header(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	char *text = bom_csv_render(r);
	assert_memory_equal(text, HEADER, strlen(HEADER));
	free(text);
	free(r);
}

static void
bom_csv_should_quote_commas_quotes_and_line_breaks(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	char *text = bom_csv_render(r);
	/* Line 1: a comma in the description → quoted. */
	assert_string_equal(record(text, 1),
	        "1,4,motor,T-Motor,MN5008 KV340,\"Brushless motor, 340 KV, 6S\","
	        "135.3,541.1,89.90,359.60,tmotor-mn5008-340");
	/* Line 2: inner quotes doubled. */
	assert_string_equal(record(text, 2),
	        "2,4,propeller,T-Motor,P18x6.1,\"18\"\" x 6.1\"\" carbon \"\"folding\"\" prop\","
	        "31.2,124.9,45.55,182.20,tmotor-p18");
	/* Line 4: CR LF inside a field stays inside the quotes. */
	assert_non_null(strstr(text, "4,4,esc,T-Motor,FLAME 60A,\"ESC 60 A\r\nline two\","
	                             "73.9,295.6,69.95,279.80,tmotor-flame60\r\n"));
	/* Every LF is preceded by CR. */
	for (const char *p = text; *p; p++)
		if (*p == '\n')
			assert_true(p > text && p[-1] == '\r');
	size_t n = strlen(text);
	assert_true(n >= 2 && text[n - 2] == '\r' && text[n - 1] == '\n');
	free(text);
	free(r);
}

static void
bom_csv_total_should_sum_mass_and_known_prices(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	char *text = bom_csv_render(r);
	/* 541.08 + 124.938 + 1987.68 + 295.6 g; 359.6 + 182.2 + 279 + 279.796 USD */
	assert_string_equal(record(text, 6), ",,total,,,,,2949.3,,1100.60,");
	assert_int_equal(bom_csv_missing_prices(r), 0);
	free(text);

	/* Two prices unknown: the known sum and a note. */
	add_line(r, 4, "custom", "", "", "CFRP arm tube 22.0 x 20.0 mm, 0.412 m",
	         0.04321, 0.0, "");
	add_line(r, 1, "custom", "", "", "Power harness 10 AWG", 0.1502, 0.0, "");
	text = bom_csv_render(r);
	assert_string_equal(record(text, 6),
	        "5,4,custom,,,\"CFRP arm tube 22.0 x 20.0 mm, 0.412 m\",43.2,172.8,,,");
	assert_string_equal(record(text, 8),
	        ",,total,,,\"≥ 1100.60 USD, 2 of 6 lines unpriced\",,"
	        "3272.3,,1100.60,");
	assert_int_equal(bom_csv_missing_prices(r), 2);
	free(text);
	free(r);
}

static void
bom_csv_should_format_grams_without_negative_zero(void **state)
{
	(void)state;
	struct solve_result *r = xcalloc(1, sizeof *r);
	r->parts_selected = true;
	add_line(r, 3, "custom", "", "", "tiny", 0.00004, 0.004, "");
	add_line(r, 1, "custom", "", "", "rounding", 0.01234567, 1234567.891, "");
	r->bom[0].unit_mass_kg = -0.00001; /* rounds to -0.0 */
	r->bom[0].total_price_usd = -0.001;
	char *text = bom_csv_render(r);
	assert_string_equal(record(text, 1), "1,3,custom,,,tiny,0.0,0.1,0.00,0.00,");
	assert_string_equal(record(text, 2),
	        "2,1,custom,,,rounding,12.3,12.3,1234567.89,1234567.89,");
	assert_null(strstr(text, "-0"));
	free(text);
	free(r);
}

static void
bom_csv_without_parts_should_be_header_and_zero_total(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	r->parts_selected = false; /* lines left over must not be written */
	char *text = bom_csv_render(r);
	assert_string_equal(text, HEADER ",,total,,,no parts selected,,0.0,,0.00,\r\n");
	assert_int_equal(bom_csv_missing_prices(r), 0);
	free(text);
	free(r);
}

static void
bom_csv_should_count_non_finite_values(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	int bad = -1;
	r->bom[2].unit_mass_kg = NAN;
	r->bom_mass_kg = INFINITY;
	char *text = bom_csv_render_checked(r, &bad);
	assert_int_equal(bad, 2);
	assert_string_equal(record(text, 3),
	        "3,1,battery,Tattu,TA-16000-6S,LiPo 6S 16000 mAh 15C,,1987.7,279.00,279.00,tattu-16000-6s");
	assert_string_equal(record(text, 6), ",,total,,,,,,,1100.60,");
	assert_null(strstr(text, "nan"));
	assert_null(strstr(text, "inf"));
	free(text);
	r->n_bom = RES_MAX_BOM + 1;
	r->bom[2].unit_mass_kg = 1.0;
	r->bom_mass_kg = 1.0;
	text = bom_csv_render_checked(r, &bad);
	assert_int_equal(bad, 1);
	free(text);
	free(r);
}

static void
bom_csv_should_match_golden_files(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	char *text = bom_csv_render(r);
	assert_golden("tests/fixtures/outputs/bom_priced.csv.expected", text);
	free(text);
	add_line(r, 4, "custom", "", "", "CFRP arm tube 22.0 x 20.0 mm, 0.412 m",
	         0.04321, 0.0, "");
	text = bom_csv_render(r);
	assert_golden("tests/fixtures/outputs/bom_missing_price.csv.expected", text);
	free(text);
	free(r);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(bom_csv_should_start_with_the_product_header),
		cmocka_unit_test(bom_csv_should_quote_commas_quotes_and_line_breaks),
		cmocka_unit_test(bom_csv_total_should_sum_mass_and_known_prices),
		cmocka_unit_test(bom_csv_should_format_grams_without_negative_zero),
		cmocka_unit_test(bom_csv_without_parts_should_be_header_and_zero_total),
		cmocka_unit_test(bom_csv_should_count_non_finite_values),
		cmocka_unit_test(bom_csv_should_match_golden_files),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
