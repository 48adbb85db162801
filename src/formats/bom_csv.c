/* bom_csv.c — bom.csv and bom_totals.csv (see bom_csv.h for the format). */
#include "formats/bom_csv.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

#include "util/csv.h"
#include "util/strbuf.h"

/* The number of lines to write: none without parts, and a count outside
 * the array is an engine bug like a NaN (counted in *bad). */
static int
n_lines(const struct solve_result *r, int *bad)
{
	if (!r->parts_selected)
		return 0;
	if (r->n_bom < 0 || r->n_bom > RES_MAX_BOM) {
		(*bad)++;
		return r->n_bom < 0 ? 0 : RES_MAX_BOM;
	}
	return r->n_bom;
}

int
bom_csv_missing_prices(const struct solve_result *r)
{
	/* The one count every output prints (res_figures()): the lines to
	 * buy without a price, the payload's line aside. */
	struct res_figures f;
	res_figures(r, &f);
	return f.unpriced_lines;
}

/* ---- what is ordered ------------------------------------------------------- */

/* The parts search lists the counter-rotating half of a propeller without
 * a catalogue CCW part number as "<part number> (CCW)" (src/parts/bom.c):
 * a part number no maker sells.  Is b that line? */
static bool
ccw_made_up(const struct solve_result *r, const struct res_bom_line *b)
{
	char want[sizeof r->prop.part_number + 8];
	if (!r->prop.chosen || strcmp(b->category, "propeller") != 0)
		return false;
	snprintf(want, sizeof want, "%s (CCW)", r->prop.part_number);
	return strcmp(b->part_number, want) == 0;
}

/* Is b the clockwise half of such a set? */
static bool
cw_of_made_up_set(const struct solve_result *r, const struct res_bom_line *b)
{
	if (!r->prop.chosen || strcmp(b->category, "propeller") != 0
	    || strcmp(b->part_number, r->prop.part_number) != 0)
		return false;
	int bad = 0, n = n_lines(r, &bad);
	for (int i = 0; i < n; i++)
		if (ccw_made_up(r, &r->bom[i]))
			return true;
	return false;
}

const char *
bom_csv_part_number(const struct solve_result *r, const struct res_bom_line *b)
{
	return ccw_made_up(r, b) ? r->prop.part_number : b->part_number;
}

/* The catalogue's source and doubted keys of line b's entry, by the
 * category the parts search files it under; false when not found. */
static bool
entry_of(const struct catalog *cat, const struct res_bom_line *b, const char **source,
         const char **uncertain)
{
	const char *c = b->category, *id = b->catalogue_id;
	if (cat == NULL || id[0] == '\0')
		return false;
#define FROM(T, find) do { \
	const struct T *e_ = find(cat, id); \
	if (e_ == NULL) \
		return false; \
	*source = e_->source; \
	*uncertain = e_->uncertain; \
	return true; \
} while (0)
	if (strcmp(c, "motor") == 0)
		FROM(catalog_motor, catalog_find_motor);
	if (strcmp(c, "propeller") == 0)
		FROM(catalog_prop, catalog_find_prop);
	if (strcmp(c, "battery") == 0)
		FROM(catalog_battery, catalog_find_battery);
	if (strcmp(c, "esc") == 0)
		FROM(catalog_esc, catalog_find_esc);
	if (strcmp(c, "frame") == 0)
		FROM(catalog_frame, catalog_find_frame);
	FROM(catalog_avionics, catalog_find_avionics);  /* avionics, connectors */
#undef FROM
}

void
bom_csv_order(const struct solve_result *r, const struct res_bom_line *b,
              const struct catalog *cat, struct bom_order *o)
{
	memset(o, 0, sizeof *o);
	o->orderable = BOM_ORDER_YES;
	o->part_number = bom_csv_part_number(r, b);
	if (strcmp(b->category, "payload") == 0) {
		o->orderable = BOM_ORDER_NO;
		snprintf(o->note, sizeof o->note, "furnished by the customer: nothing to order");
		return;
	}
	if (b->catalogue_id[0] == '\0') {
		o->orderable = BOM_ORDER_NO;
		snprintf(o->note, sizeof o->note, "not a catalogue part: made to this "
		    "description, or a mass allowance of the airframe class; its mass "
		    "is the design's estimate");
		return;
	}
	const char *source = "", *uncertain = "";
	if (entry_of(cat, b, &source, &uncertain)) {
		/* Up to the caveats: the maker's page, then the copy read. */
		const char *end = strstr(source, " | note");
		size_t n = end != NULL ? (size_t)(end - source) : strlen(source);
		if (n < sizeof o->source)
			snprintf(o->source, sizeof o->source, "%.*s", (int)n, source);
		else  /* longer than any shipped one: cut, and say so */
			snprintf(o->source, sizeof o->source, "%.*s...",
			    (int)(sizeof o->source - 4), source);
	}
	if (catalog_list_names(uncertain, "part_number")) {
		o->orderable = BOM_ORDER_CONFIRM;
		snprintf(o->note, sizeof o->note, "the catalogue doubts this part number (the "
		    "name its source lists, not confirmed as %s's orderable designation): "
		    "confirm it with the maker before ordering", b->manufacturer);
	} else if (ccw_made_up(r, b)) {
		snprintf(o->note, sizeof o->note, "CCW (pusher) blades: the catalogue has no "
		    "separate CCW part number; order them under the maker's part number, "
		    "as the CCW half of its CW/CCW set");
	} else if (cw_of_made_up_set(r, b)) {
		snprintf(o->note, sizeof o->note, "CW (normal) blades; the CCW blades are "
		    "ordered under the same part number, the maker's CW/CCW set");
	}
}

/* ---- bom.csv --------------------------------------------------------------- */

static const char *const header[] = {
	"item", "qty", "category", "manufacturer", "part_number", "description",
	"unit_mass_g", "total_mass_g", "unit_price_usd", "total_price_usd",
	"catalogue_id", "currency", "price_date", "supplier_url", "source",
	"orderable", "order_note", NULL
};

static const char *const orderable_name[] = { "yes", "confirm", "no" };

static void
put_int(struct csv_out *o, int v)
{
	char t[16];
	snprintf(t, sizeof t, "%d", v);
	csv_out_field(o, t);
}

/* The text of sb, after a byte order mark when it holds any byte beyond
 * ASCII (bom_csv.h: Encoding).  Ownership: free(). */
static char *
take_marked(struct strbuf *sb)
{
	const char *s = strbuf_str(sb);
	bool ascii = true;
	for (size_t i = 0; s[i] != '\0' && ascii; i++)
		ascii = (unsigned char)s[i] < 0x80;
	if (ascii)
		return strbuf_take(sb, NULL);
	struct strbuf m = STRBUF_INIT;
	strbuf_append_str(&m, "\xEF\xBB\xBF");
	strbuf_append_str(&m, s);
	strbuf_free(sb);
	return strbuf_take(&m, NULL);
}

char *
bom_csv_render_checked(const struct solve_result *r, const struct catalog *cat,
                       int *n_invalid)
{
	struct strbuf sb = STRBUF_INIT;
	struct csv_out o = { &sb, 0 };
	int bad = 0;
	for (size_t i = 0; header[i] != NULL; i++)
		csv_out_field(&o, header[i]);
	csv_out_end(&o);

	int n = n_lines(r, &bad);
	for (int i = 0; i < n; i++) {
		const struct res_bom_line *b = &r->bom[i];
		struct bom_order ord;
		bom_csv_order(r, b, cat, &ord);
		bool priced = b->unit_price_usd != 0.0;
		put_int(&o, b->item);
		put_int(&o, b->qty);
		csv_out_field(&o, b->category);
		csv_out_field(&o, b->manufacturer);
		csv_out_field(&o, ord.part_number);
		csv_out_field(&o, b->description);
		bad += !csv_out_num(&o, true, 1000.0 * b->unit_mass_kg, 1);
		bad += !csv_out_num(&o, true, 1000.0 * b->total_mass_kg, 1);
		bad += !csv_out_num(&o, priced, b->unit_price_usd, 2);
		bad += !csv_out_num(&o, priced, b->total_price_usd, 2);
		csv_out_field(&o, b->catalogue_id);
		csv_out_field(&o, priced ? "USD" : "");
		csv_out_field(&o, priced ? b->price_date : "");
		csv_out_field(&o, b->source_url);
		csv_out_field(&o, ord.source);
		csv_out_field(&o, orderable_name[ord.orderable]);
		csv_out_field(&o, ord.note);
		csv_out_end(&o);
	}
	if (n_invalid)
		*n_invalid = bad;
	return take_marked(&sb);
}

char *
bom_csv_render(const struct solve_result *r, const struct catalog *cat)
{
	int bad;
	char *text = bom_csv_render_checked(r, cat, &bad);
	assert(bad == 0 && "bom.csv: non-finite value or bad line count");
	(void)bad;
	return text;
}

/* ---- bom_totals.csv -------------------------------------------------------- */

char *
bom_csv_totals(const struct solve_result *r, int *n_invalid)
{
	static const char *const cols[] = {
		"parts_mass_g", "payload_mass_g", "takeoff_mass_g", "lines", "priced_lines",
		"unpriced_lines", "known_price", "currency", "price_note", NULL
	};
	struct strbuf sb = STRBUF_INIT, note = STRBUF_INIT;
	struct csv_out o = { &sb, 0 };
	int bad = 0, n = n_lines(r, &bad);
	for (size_t i = 0; cols[i] != NULL; i++)
		csv_out_field(&o, cols[i]);
	csv_out_end(&o);

	double payload_kg = 0.0;
	for (int i = 0; i < n; i++)
		if (strcmp(r->bom[i].category, "payload") == 0)
			payload_kg += r->bom[i].total_mass_kg;
	double parts_kg = r->parts_selected ? r->bom_mass_kg : 0.0;
	double price = r->parts_selected ? r->bom_price_usd : 0.0;
	int lines = r->parts_selected ? r->bom_parts_lines : 0;
	int priced = r->parts_selected ? r->bom_priced_lines : 0;
	if (!r->parts_selected)
		strbuf_append_str(&note, "no parts selected");
	else if (priced == 0)
		strbuf_printf(&note, "no line priced");
	else if (priced == lines)
		strbuf_printf(&note, "all %d lines priced", lines);
	else
		strbuf_printf(&note, "at least %.2f USD: %d of %d lines unpriced", price,
		    lines - priced, lines);
	bad += !csv_out_num(&o, true, 1000.0 * parts_kg, 1);
	bad += !csv_out_num(&o, true, 1000.0 * payload_kg, 1);
	bad += !csv_out_num(&o, true, 1000.0 * (parts_kg + payload_kg), 1);
	put_int(&o, lines);
	put_int(&o, priced);
	put_int(&o, lines - priced);
	bad += !csv_out_num(&o, true, price, 2);
	csv_out_field(&o, "USD");
	csv_out_field(&o, strbuf_str(&note));
	csv_out_end(&o);
	strbuf_free(&note);
	if (n_invalid)
		*n_invalid = bad;
	return strbuf_take(&sb, NULL);
}
