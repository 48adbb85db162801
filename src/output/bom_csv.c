/* bom_csv.c — bom.csv writer (see bom_csv.h for the format). */
#include "output/bom_csv.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "util/xalloc.h"

/* The CSV text being built, and the non-finite values met. */
struct csv {
	char *text;     /* NUL-terminated */
	size_t used;    /* bytes before the NUL */
	size_t room;    /* bytes allocated */
	bool first;     /* next field is the first of its record */
	int n_invalid;  /* non-finite numbers left as empty cells */
};

static void
csv_bytes(struct csv *c, const char *s, size_t n)
{
	if (c->used + n >= c->room) {
		c->room = 2 * (c->used + n) + 1024;
		c->text = xrealloc(c->text, c->room);
	}
	memcpy(c->text + c->used, s, n);
	c->used += n;
	c->text[c->used] = '\0';
}

/* Ends the record: RFC 4180 says CRLF, after the last record too. */
static void
csv_end_record(struct csv *c)
{
	csv_bytes(c, "\r\n", 2);
	c->first = true;
}

/* One field (at most max bytes of s), quoted only when it must be. */
static void
csv_field(struct csv *c, const char *s, size_t max)
{
	size_t n = strnlen(s, max);
	if (!c->first)
		csv_bytes(c, ",", 1);
	c->first = false;
	bool quote = false;
	for (size_t i = 0; i < n && !quote; i++)
		quote = s[i] == ',' || s[i] == '"' || s[i] == '\r' || s[i] == '\n';
	if (!quote) {
		csv_bytes(c, s, n);
		return;
	}
	csv_bytes(c, "\"", 1);
	for (size_t i = 0; i < n; i++) {
		if (s[i] == '"')
			csv_bytes(c, "\"", 1); /* an inner quote is doubled */
		csv_bytes(c, s + i, 1);
	}
	csv_bytes(c, "\"", 1);
}

#define CSV_FIELD(c, arr) csv_field((c), (arr), sizeof(arr))

static void
csv_empty(struct csv *c)
{
	csv_field(c, "", 0);
}

static void
csv_int(struct csv *c, int v)
{
	char t[16];
	snprintf(t, sizeof t, "%d", v);
	csv_field(c, t, sizeof t);
}

/* x with a fixed number of decimals; never "-0.0".  A non-finite x is an
 * engine bug: the cell stays empty and is counted. */
static void
csv_fixed(struct csv *c, double x, int decimals)
{
	/* 309 integer digits of DBL_MAX + sign + point + decimals fit. */
	char t[330];
	if (!isfinite(x)) {
		c->n_invalid++;
		csv_empty(c);
		return;
	}
	snprintf(t, sizeof t, "%.*f", decimals, x);
	const char *p = t;
	if (t[0] == '-' && strspn(t + 1, "0.") == strlen(t + 1))
		p++; /* rounds to zero: drop the sign */
	csv_field(c, p, sizeof t);
}

static void
csv_grams(struct csv *c, double kg)
{
	csv_fixed(c, kg * 1000.0, 1);
}

/* A price in USD; 0 (unknown) is an empty cell. */
static void
csv_price(struct csv *c, double usd)
{
	if (usd == 0.0)
		csv_empty(c);
	else
		csv_fixed(c, usd, 2);
}

int
bom_csv_missing_prices(const struct solve_result *r)
{
	if (!r->parts_selected)
		return 0;
	int n = r->n_bom < 0 ? 0 : r->n_bom > RES_MAX_BOM ? RES_MAX_BOM : r->n_bom;
	int missing = 0;
	for (int i = 0; i < n; i++)
		missing += r->bom[i].unit_price_usd == 0.0;
	return missing;
}

char *
bom_csv_render_checked(const struct solve_result *r, int *n_invalid)
{
	static const char *const header[] = {
		"item", "qty", "category", "manufacturer", "part_number",
		"description", "unit_mass_g", "total_mass_g", "unit_price_usd",
		"total_price_usd", "catalogue_id"
	};
	struct csv c = { NULL, 0, 0, true, 0 };
	for (size_t i = 0; i < sizeof header / sizeof header[0]; i++)
		csv_field(&c, header[i], strlen(header[i]));
	csv_end_record(&c);

	/* A count outside the array is an engine bug like a NaN. */
	int n = 0;
	if (r->parts_selected) {
		n = r->n_bom;
		if (n < 0 || n > RES_MAX_BOM) {
			c.n_invalid++;
			n = n < 0 ? 0 : RES_MAX_BOM;
		}
	}
	for (int i = 0; i < n; i++) {
		const struct res_bom_line *b = &r->bom[i];
		csv_int(&c, b->item);
		csv_int(&c, b->qty);
		CSV_FIELD(&c, b->category);
		CSV_FIELD(&c, b->manufacturer);
		CSV_FIELD(&c, b->part_number);
		CSV_FIELD(&c, b->description);
		csv_grams(&c, b->unit_mass_kg);
		csv_grams(&c, b->total_mass_kg);
		csv_price(&c, b->unit_price_usd);
		csv_price(&c, b->unit_price_usd == 0.0 ? 0.0 : b->total_price_usd);
		CSV_FIELD(&c, b->catalogue_id);
		csv_end_record(&c);
	}

	/* The total record: item, qty empty; category "total"; a note in the
	 * description column when prices are missing or there is no BOM. */
	char note[96] = "";
	if (!r->parts_selected)
		snprintf(note, sizeof note, "no parts selected");
	else if (bom_csv_missing_prices(r) > 0)
		res_price_text(r, note, sizeof note);
	csv_empty(&c);
	csv_empty(&c);
	csv_field(&c, "total", 5);
	csv_empty(&c);
	csv_empty(&c);
	csv_field(&c, note, sizeof note);
	csv_empty(&c);
	csv_grams(&c, r->parts_selected ? r->bom_mass_kg : 0.0);
	csv_empty(&c);
	/* The known-price sum, also when it is 0 (nothing known, or no BOM). */
	csv_fixed(&c, r->parts_selected ? r->bom_price_usd : 0.0, 2);
	csv_empty(&c);
	csv_end_record(&c);

	if (n_invalid)
		*n_invalid = c.n_invalid;
	return c.text;
}

char *
bom_csv_render(const struct solve_result *r)
{
	int bad;
	char *text = bom_csv_render_checked(r, &bad);
	assert(bad == 0 && "bom.csv: non-finite value or bad line count");
	(void)bad;
	return text;
}
