/* test_csv.c — the RFC 4180 reader: quoting, line ends, recovery. */
#include "test_util.h"
#include "util/csv.h"

#include <string.h>

/* Reads every record of text into a flat description such as
 * "1:[a|b] 3:[c] !4:unterminated quoted field (field 2) ", which makes the
 * expected result of a whole file one readable string. */
static void
describe(const char *text, size_t n, char *out, size_t outlen)
{
	struct csv_reader r;
	struct csv_record rec;
	char err[128];
	size_t at = 0;
	enum csv_status st;
	out[0] = '\0';
	csv_init(&r, text, n);
	while ((st = csv_next(&r, &rec, err, sizeof err)) != CSV_EOF) {
		if (st == CSV_MALFORMED) {
			at += (size_t)snprintf(out + at, outlen - at, "!%zu:%s ", rec.line, err);
			continue;
		}
		at += (size_t)snprintf(out + at, outlen - at, "%zu:[", rec.line);
		for (size_t i = 0; i < rec.n_fields; i++)
			at += (size_t)snprintf(out + at, outlen - at, "%s%s", i ? "|" : "", rec.fields[i]);
		at += (size_t)snprintf(out + at, outlen - at, "] ");
	}
	csv_free(&r);
}

#define assert_csv(text, want) do { \
		char got_[1024]; \
		describe((text), sizeof(text) - 1, got_, sizeof got_); \
		assert_string_equal(got_, (want)); \
	} while (0)

static void
csv_should_split_plain_fields_on_lf_and_crlf(void **state)
{
	(void)state;
	assert_csv("name,rotor_count\nIris+,4\n", "1:[name|rotor_count] 2:[Iris+|4] ");
	assert_csv("a,b\r\nc,d\r\n", "1:[a|b] 2:[c|d] ");
	assert_csv("a,b\nc,d", "1:[a|b] 2:[c|d] "); /* no final line end */
	assert_csv("a,,\n,x,\n", "1:[a||] 2:[|x|] "); /* empty fields kept */
	assert_csv(" a , b \n", "1:[ a | b ] "); /* spaces are data */
	assert_csv("", "");
}

static void
csv_should_unquote_commas_quotes_and_line_breaks(void **state)
{
	(void)state;
	assert_csv("\"250 mm, 5-in\",x\n", "1:[250 mm, 5-in|x] ");
	assert_csv("\"Holybro QAV-R 5\"\"\",0.65\n", "1:[Holybro QAV-R 5\"|0.65] ");
	assert_csv("\"\"\"\",\"\"\n", "1:[\"|] "); /* a lone quote; an empty quoted field */
	/* A quoted line break: the record starts on line 1, the next on 3. */
	assert_csv("\"two\nlines\",b\nc,d\n", "1:[two\nlines|b] 3:[c|d] ");
	/* CRLF inside quotes is kept byte for byte. */
	assert_csv("\"x\r\ny\"\r\nz\r\n", "1:[x\r\ny] 3:[z] ");
	assert_csv("a,\"b\"", "1:[a|b] ");
}

static void
csv_should_skip_bom_and_empty_lines_and_count_them(void **state)
{
	(void)state;
	assert_csv("\xEF\xBB\xBFname\n\nQAV250\r\n\r\n\nF450\n\n",
	           "1:[name] 3:[QAV250] 6:[F450] ");
	/* A BOM anywhere else is data. */
	assert_csv("a\n\xEF\xBB\xBF" "b\n", "1:[a] 2:[\xEF\xBB\xBF" "b] ");
}

static void
csv_should_report_a_stray_quote_and_keep_the_next_rows(void **state)
{
	(void)state;
	assert_csv("h1,h2\nQAV-R 5\",0.65\nF450,1.2\n",
	           "1:[h1|h2] !2:quote inside unquoted field (field 1) 3:[F450|1.2] ");
	assert_csv("h\n\"ok\"x,1\nnext,2\n",
	           "1:[h] !2:text after closing quote (field 1) 3:[next|2] ");
	assert_csv("a,b\nc,d\"\ne,f",
	           "1:[a|b] !2:quote inside unquoted field (field 2) 3:[e|f] ");
}

static void
csv_should_report_an_unterminated_quote_and_resume_next_line(void **state)
{
	(void)state;
	/* The quote on line 2 never closes: line 2 is reported, and reading
	 * resumes on line 3 rather than losing the rest of the file. */
	assert_csv("h1,h2\nF450,\"1.2\nIris,1.282\nQAV,0.58\n",
	           "1:[h1|h2] !2:unterminated quoted field (field 2) 3:[Iris|1.282] 4:[QAV|0.58] ");
	/* The open quote is on the second line of a multi-line record: the
	 * record's own line (2) is reported, and reading resumes after the
	 * line holding the open quote. */
	assert_csv("h\n\"a\nb\",\"c\nd,e\n",
	           "1:[h] !2:unterminated quoted field (field 2) 4:[d|e] ");
}

static void
csv_should_refuse_nul_bytes(void **state)
{
	(void)state;
	assert_csv("a,b\0c\nd\n", "!1:NUL byte in field (field 2) 2:[d] ");
	assert_csv("\"a\0\"\nd\n", "!1:NUL byte in field (field 1) 2:[d] ");
}

static void
csv_should_handle_many_fields_and_long_records(void **state)
{
	(void)state;
	/* 100 fields forces the field table and the text buffer to grow;
	 * the pointers must still be right afterwards. */
	char text[2048];
	size_t at = 0;
	for (int i = 0; i < 100; i++)
		at += (size_t)snprintf(text + at, sizeof text - at, "%sf%d", i ? "," : "", i * 7);
	struct csv_reader r;
	struct csv_record rec;
	char err[64];
	csv_init(&r, text, at);
	assert_int_equal(csv_next(&r, &rec, err, sizeof err), CSV_RECORD);
	assert_int_equal(rec.n_fields, 100);
	assert_string_equal(rec.fields[0], "f0");
	assert_string_equal(rec.fields[57], "f399");
	assert_string_equal(rec.fields[99], "f693");
	assert_int_equal(csv_next(&r, &rec, err, sizeof err), CSV_EOF);
	csv_free(&r);
	csv_free(NULL);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(csv_should_split_plain_fields_on_lf_and_crlf),
		cmocka_unit_test(csv_should_unquote_commas_quotes_and_line_breaks),
		cmocka_unit_test(csv_should_skip_bom_and_empty_lines_and_count_them),
		cmocka_unit_test(csv_should_report_a_stray_quote_and_keep_the_next_rows),
		cmocka_unit_test(csv_should_report_an_unterminated_quote_and_resume_next_line),
		cmocka_unit_test(csv_should_refuse_nul_bytes),
		cmocka_unit_test(csv_should_handle_many_fields_and_long_records),
	};
	return cmocka_run_group_tests_name("csv", tests, NULL, NULL);
}
