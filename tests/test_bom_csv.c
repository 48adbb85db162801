/* test_bom_csv.c — bom.csv and bom_totals.csv: header, RFC 4180 quoting,
 * CRLF, the procurement columns, totals in their own file, encoding, and
 * every example's bill read back by an RFC 4180 reader.
 *
 * Run with AEROEVAL_UPDATE_GOLDEN=1 to rewrite the golden files after an
 * intended format change (then review the diff).
 */
#include "test_util.h"
#include "cli/cli.h"
#include "cli/pipeline.h"
#include "formats/bom_csv.h"
#include "util/csv.h"
#include "util/xalloc.h"

#include <glob.h>
#include <stdlib.h>
#include <string.h>

/* The eleven bill columns in their order, then the procurement columns. */
#define HEADER "item,qty,category,manufacturer,part_number,description," \
	"unit_mass_g,total_mass_g,unit_price_usd,total_price_usd,catalogue_id," \
	"currency,price_date,supplier_url,source,orderable,order_note\r\n"
#define TOTALS_HEADER "parts_mass_g,payload_mass_g,takeoff_mass_g,lines,priced_lines," \
	"unpriced_lines,known_price,currency,price_note\r\n"

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
	if (unit_price_usd > 0.0)
		snprintf(l->price_date, sizeof l->price_date, "2026-09");
	if (strcmp(category, "payload") == 0)
		return;
	r->bom_mass_kg += l->total_mass_kg;
	r->bom_price_usd += l->total_price_usd;
	r->bom_parts_lines++;
	r->bom_priced_lines += unit_price_usd > 0.0;
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
	char *text = bom_csv_render(r, NULL);
	assert_memory_equal(text, HEADER, strlen(HEADER));
	free(text);
	text = bom_csv_totals(r, NULL);
	assert_memory_equal(text, TOTALS_HEADER, strlen(TOTALS_HEADER));
	free(text);
	free(r);
}

static void
bom_csv_should_quote_commas_quotes_and_line_breaks(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	char *text = bom_csv_render(r, NULL);
	/* Line 1: a comma in the description → quoted. */
	assert_string_equal(record(text, 1),
	        "1,4,motor,T-Motor,MN5008 KV340,\"Brushless motor, 340 KV, 6S\","
	        "135.3,541.1,89.90,359.60,tmotor-mn5008-340,USD,2026-09,,,yes,");
	/* Line 2: inner quotes doubled. */
	assert_string_equal(record(text, 2),
	        "2,4,propeller,T-Motor,P18x6.1,\"18\"\" x 6.1\"\" carbon \"\"folding\"\" prop\","
	        "31.2,124.9,45.55,182.20,tmotor-p18,USD,2026-09,,,yes,");
	/* Line 4: CR LF inside a field stays inside the quotes. */
	assert_non_null(strstr(text, "4,4,esc,T-Motor,FLAME 60A,\"ESC 60 A\r\nline two\","
	                             "73.9,295.6,69.95,279.80,tmotor-flame60,USD,2026-09,,,yes,\r\n"));
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
bom_csv_totals_should_sum_mass_and_known_prices_in_their_own_file(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	char *text = bom_csv_render(r, NULL);
	/* The bill holds the header and its four lines, no total record. */
	assert_null(strstr(text, "total,"));
	assert_int_equal(bom_csv_missing_prices(r), 0);
	free(text);
	/* 541.08 + 124.938 + 1987.68 + 295.6 g; 359.6 + 182.2 + 279 + 279.796 USD */
	text = bom_csv_totals(r, NULL);
	assert_string_equal(text, TOTALS_HEADER
	        "2949.3,0.0,2949.3,4,4,0,1100.60,USD,all 4 lines priced\r\n");
	free(text);

	/* Two prices unknown and the payload: the known sum and a note. */
	add_line(r, 4, "custom", "custom", "Carbon arm", "CFRP arm tube 22.0 x 20.0 mm, 0.412 m",
	         0.04321, 0.0, "");
	add_line(r, 1, "custom", "custom", "Power harness", "Power harness 10 AWG", 0.1502, 0.0, "");
	add_line(r, 1, "payload", "customer-furnished", "Payload", "Payload at takeoff", 1.5, 0.0, "");
	text = bom_csv_render(r, NULL);
	assert_string_equal(record(text, 6),
	        "5,4,custom,custom,Carbon arm,\"CFRP arm tube 22.0 x 20.0 mm, 0.412 m\",43.2,172.8,"
	        ",,,,,,,no,\"not a catalogue part: made to this description, or a mass "
	        "allowance of the airframe class; its mass is the design's estimate\"");
	assert_string_equal(record(text, 8),
	        "7,1,payload,customer-furnished,Payload,Payload at takeoff,1500.0,1500.0,"
	        ",,,,,,,no,furnished by the customer: nothing to order");
	/* the two unpriced parts; the payload is not a line to buy */
	assert_int_equal(bom_csv_missing_prices(r), 2);
	free(text);
	text = bom_csv_totals(r, NULL);
	assert_string_equal(text, TOTALS_HEADER "3272.3,1500.0,4772.3,6,4,2,1100.60,USD,"
	        "at least 1100.60 USD: 2 of 6 lines unpriced\r\n");
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
	char *text = bom_csv_render(r, NULL);
	assert_non_null(strstr(record(text, 1), "1,3,custom,,,tiny,0.0,0.1,0.00,0.00,,USD,"));
	assert_non_null(strstr(record(text, 2),
	        "2,1,custom,,,rounding,12.3,12.3,1234567.89,1234567.89,,USD,"));
	assert_null(strstr(text, ",-0"));
	free(text);
	free(r);
}

static void
bom_csv_without_parts_should_be_header_and_zero_total(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	r->parts_selected = false; /* lines left over must not be written */
	char *text = bom_csv_render(r, NULL);
	assert_string_equal(text, HEADER);
	assert_int_equal(bom_csv_missing_prices(r), 0);
	free(text);
	text = bom_csv_totals(r, NULL);
	assert_string_equal(text, TOTALS_HEADER "0.0,0.0,0.0,0,0,0,0.00,USD,no parts selected\r\n");
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
	char *text = bom_csv_render_checked(r, NULL, &bad);
	assert_int_equal(bad, 1);
	assert_string_equal(record(text, 3),
	        "3,1,battery,Tattu,TA-16000-6S,LiPo 6S 16000 mAh 15C,,1987.7,279.00,279.00,"
	        "tattu-16000-6s,USD,2026-09,,,yes,");
	assert_null(strstr(text, "nan"));
	assert_null(strstr(text, "inf"));
	free(text);
	text = bom_csv_totals(r, &bad);
	assert_int_equal(bad, 2);   /* the parts' and the takeoff mass */
	assert_null(strstr(text, "inf"));
	free(text);
	r->n_bom = RES_MAX_BOM + 1;
	r->bom[2].unit_mass_kg = 1.0;
	r->bom_mass_kg = 1.0;
	text = bom_csv_render_checked(r, NULL, &bad);
	assert_int_equal(bad, 1);
	free(text);
	free(r);
}

static void
bom_csv_should_match_golden_files(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	char *text = bom_csv_render(r, NULL);
	assert_golden("tests/fixtures/outputs/bom_priced.csv.expected", text);
	free(text);
	add_line(r, 4, "custom", "", "", "CFRP arm tube 22.0 x 20.0 mm, 0.412 m",
	         0.04321, 0.0, "");
	text = bom_csv_render(r, NULL);
	assert_golden("tests/fixtures/outputs/bom_missing_price.csv.expected", text);
	free(text);
	free(r);
}

/* The counter-rotating propeller whose part number the parts search made
 * up: ordered under the maker's one part number, and said so. */
static void
bom_csv_should_order_a_made_up_ccw_part_under_the_makers_number(void **state)
{
	(void)state;
	struct solve_result *r = xcalloc(1, sizeof *r);
	r->parts_selected = true;
	r->prop.chosen = true;
	snprintf(r->prop.part_number, sizeof r->prop.part_number, "NS24x7.2");
	add_line(r, 2, "propeller", "T-Motor", "NS24x7.2", "24 x 7.2 in, CW (normal)", 0.037, 0.0,
	         "tmotor-ns24x72");
	add_line(r, 2, "propeller", "T-Motor", "NS24x7.2 (CCW)", "24 x 7.2 in, CCW (pusher)", 0.037,
	         0.0, "tmotor-ns24x72");
	char *text = bom_csv_render(r, NULL);
	assert_null(strstr(text, "(CCW)"));
	assert_non_null(strstr(record(text, 1), ",T-Motor,NS24x7.2,"));
	assert_non_null(strstr(record(text, 1), ",yes,\"CW (normal) blades; the CCW blades are "
	                       "ordered under the same part number"));
	assert_non_null(strstr(record(text, 2), ",T-Motor,NS24x7.2,"));
	assert_non_null(strstr(record(text, 2), "the catalogue has no separate CCW part number"));
	assert_string_equal(bom_csv_part_number(r, &r->bom[1]), "NS24x7.2");
	free(text);
	/* A catalogue CCW part number is the maker's: kept as it is. */
	snprintf(r->bom[1].part_number, sizeof r->bom[1].part_number, "NS24x7.2-CCW");
	assert_string_equal(bom_csv_part_number(r, &r->bom[1]), "NS24x7.2-CCW");
	text = bom_csv_render(r, NULL);
	assert_non_null(strstr(record(text, 2), ",T-Motor,NS24x7.2-CCW,"));
	const char *ccw = record(text, 2);
	size_t len = strlen(ccw);
	assert_true(len >= 5 && strcmp(ccw + len - 5, ",yes,") == 0);  /* no note */
	free(text);
	free(r);
}

/* A part number the catalogue doubts (data/catalog: `uncertain` lists
 * part_number) is to be confirmed before ordering; the source column says
 * where the catalogue read the part, up to its caveats. */
static void
bom_csv_should_ask_to_confirm_a_doubted_part_number(void **state)
{
	(void)state;
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	struct solve_result *r = xcalloc(1, sizeof *r);
	r->parts_selected = true;
	add_line(r, 4, "esc", "YGE", "60", "60 A continuous, up to 6S", 0.035, 0.0, "yge-yge-60");
	add_line(r, 4, "motor", "T-Motor", "U8 Lite KV190", "190 KV", 0.243, 299.99,
	         "tmotor-u8-lite-kv190");
	struct bom_order o;
	bom_csv_order(r, &r->bom[0], env.cat, &o);
	assert_int_equal(o.orderable, BOM_ORDER_CONFIRM);
	assert_non_null(strstr(o.note, "confirm it with the maker"));
	assert_true(strncmp(o.source, "yge.de", 6) == 0);
	assert_null(strstr(o.source, "| note"));
	bom_csv_order(r, &r->bom[1], env.cat, &o);
	assert_int_equal(o.orderable, BOM_ORDER_YES);
	assert_string_equal(o.note, "");
	char *text = bom_csv_render(r, env.cat);
	assert_non_null(strstr(record(text, 1), ",confirm,"));
	free(text);
	free(r);
	cli_env_free(&env);
}

/* ASCII text has no byte order mark; a maker's name beyond ASCII puts one
 * first, so that Excel reads UTF-8. */
static void
bom_csv_should_mark_utf8_only_when_the_text_needs_it(void **state)
{
	(void)state;
	struct solve_result *r = bom_new();
	char *text = bom_csv_render(r, NULL);
	for (const char *p = text; *p != '\0'; p++)
		assert_true((unsigned char)*p < 0x80);
	free(text);
	snprintf(r->bom[0].manufacturer, sizeof r->bom[0].manufacturer, "W\xC3\xBCrth");
	text = bom_csv_render(r, NULL);
	assert_memory_equal(text, "\xEF\xBB\xBF" HEADER, 3 + strlen(HEADER));
	free(text);
	free(r);
}

/* A field of a record read back, by column name. */
static const char *
field_of(const struct csv_record *hdr, const struct csv_record *rec, const char *name)
{
	for (size_t i = 0; i < hdr->n_fields; i++)
		if (strcmp(hdr->fields[i], name) == 0)
			return rec->fields[i];
	fail_msg("no column %s", name);
	return NULL;
}

/* Every example's bill, read back by an RFC 4180 reader: the header, the
 * same number of fields in every record, items 1..n, only parts (no total
 * record), orderable one of yes/no/confirm with a note when not yes, no
 * made-up CCW part number, and bom_totals.csv agreeing with the lines. */
static void
every_example_bill_should_read_back_as_parts_only(void **state)
{
	(void)state;
	struct cli_env env;
	assert_int_equal(cli_env_load(&env, NULL, 1, stderr), 0);
	glob_t g;
	assert_int_equal(glob("examples/*.json", 0, NULL, &g), 0);
	assert_true(g.gl_pathc >= 10);
	for (size_t k = 0; k < g.gl_pathc; k++) {
		struct solve_result *r = xmalloc(sizeof *r);
		enum pipeline_status st = pipeline_solve(&env, g.gl_pathv[k], r, stderr, NULL, NULL);
		assert_true(st == PIPE_FEASIBLE || st == PIPE_INFEASIBLE);
		char *text = bom_csv_render(r, env.cat);
		struct csv_reader rd;
		struct csv_record rec, hdr_copy;
		char err[128];
		csv_init(&rd, text, strlen(text));
		assert_int_equal(csv_next(&rd, &rec, err, sizeof err), CSV_RECORD);
		assert_int_equal(rec.n_fields, 17);
		char *names[17];
		for (int i = 0; i < 17; i++)
			names[i] = xstrdup(rec.fields[i]);
		hdr_copy.fields = (const char *const *)names;
		hdr_copy.n_fields = 17;
		double mass = 0.0, payload = 0.0;
		int item = 0, unpriced = 0, lines = 0;
		while (csv_next(&rd, &rec, err, sizeof err) == CSV_RECORD) {
			assert_int_equal(rec.n_fields, 17);
			assert_int_equal(atoi(field_of(&hdr_copy, &rec, "item")), ++item);
			const char *ord = field_of(&hdr_copy, &rec, "orderable");
			assert_true(strcmp(ord, "yes") == 0 || strcmp(ord, "no") == 0
			            || strcmp(ord, "confirm") == 0);
			if (strcmp(ord, "yes") != 0)
				assert_true(field_of(&hdr_copy, &rec, "order_note")[0] != '\0');
			/* "(CCW)" only where the maker's own CCW part number says
			 * it (HQProp's "MacroQuad 10x4.5x3 (CCW)"). */
			const char *pn = field_of(&hdr_copy, &rec, "part_number");
			const struct catalog_prop *pr = catalog_find_prop(env.cat,
			    field_of(&hdr_copy, &rec, "catalogue_id"));
			if (pr == NULL || strcmp(pn, pr->part_number_ccw) != 0)
				assert_null(strstr(pn, "(CCW)"));
			bool priced = field_of(&hdr_copy, &rec, "unit_price_usd")[0] != '\0';
			assert_int_equal(priced, strcmp(field_of(&hdr_copy, &rec, "currency"), "USD") == 0);
			assert_int_equal(priced, field_of(&hdr_copy, &rec, "price_date")[0] != '\0');
			double g_ = atof(field_of(&hdr_copy, &rec, "total_mass_g"));
			if (strcmp(field_of(&hdr_copy, &rec, "category"), "payload") == 0) {
				payload += g_;
				continue;
			}
			mass += g_;
			lines++;
			unpriced += !priced;
		}
		csv_free(&rd);
		assert_int_equal(item, r->parts_selected ? r->n_bom : 0);
		char *tot = bom_csv_totals(r, NULL);
		csv_init(&rd, tot, strlen(tot));
		assert_int_equal(csv_next(&rd, &rec, err, sizeof err), CSV_RECORD);
		for (int i = 0; i < 9; i++) {
			free(names[i]);
			names[i] = xstrdup(rec.fields[i]);
		}
		hdr_copy.n_fields = 9;
		assert_int_equal(csv_next(&rd, &rec, err, sizeof err), CSV_RECORD);
		assert_true(fabs(atof(field_of(&hdr_copy, &rec, "parts_mass_g")) - mass)
		            <= 0.05 * lines + 0.05);
		assert_true(fabs(atof(field_of(&hdr_copy, &rec, "payload_mass_g")) - payload) <= 0.05);
		assert_int_equal(atoi(field_of(&hdr_copy, &rec, "lines")), lines);
		assert_int_equal(atoi(field_of(&hdr_copy, &rec, "unpriced_lines")), unpriced);
		assert_int_equal(csv_next(&rd, &rec, err, sizeof err), CSV_EOF);
		csv_free(&rd);
		for (int i = 0; i < 17; i++)
			free(names[i]);
		free(tot);
		free(text);
		free(r);
	}
	globfree(&g);
	cli_env_free(&env);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(bom_csv_should_start_with_the_product_header),
		cmocka_unit_test(bom_csv_should_quote_commas_quotes_and_line_breaks),
		cmocka_unit_test(bom_csv_totals_should_sum_mass_and_known_prices_in_their_own_file),
		cmocka_unit_test(bom_csv_should_format_grams_without_negative_zero),
		cmocka_unit_test(bom_csv_without_parts_should_be_header_and_zero_total),
		cmocka_unit_test(bom_csv_should_count_non_finite_values),
		cmocka_unit_test(bom_csv_should_match_golden_files),
		cmocka_unit_test(bom_csv_should_order_a_made_up_ccw_part_under_the_makers_number),
		cmocka_unit_test(bom_csv_should_ask_to_confirm_a_doubted_part_number),
		cmocka_unit_test(bom_csv_should_mark_utf8_only_when_the_text_needs_it),
		cmocka_unit_test(every_example_bill_should_read_back_as_parts_only),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
