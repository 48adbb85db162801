/* test_consistency.c — one number per quantity: the dossier, result.json,
 * bom.csv, bom_totals.csv and index.csv of a build say the same.
 *
 * Three examples are compiled exactly as `aeroeval build` compiles them
 * (pipeline_build() into a temporary folder, then the study table with
 * cli_summary_refresh()), and for the design of record each quantity is
 * read back from every file that prints it: takeoff mass, hover power at
 * takeoff mass (and after shedding where the mission sheds payload),
 * hover battery current, auxiliary power, hover endurance, flight time,
 * landing state of charge, the bill of materials' mass, price and
 * unpriced lines.  Each printed number must be result.json's full-precision
 * value rounded to the decimals printed.
 *
 * How the dossier is read: the same render that writes dossier.pdf hands
 * over its transcript (pipeline_opts.dossier_text, doc_set_transcript()),
 * every string the document draws, a table row as its cells joined by
 * tabs.  That is robust where reading the PDF back is not: pdftotext's
 * layout mode merges and splits columns by their gaps, and a PDF content
 * stream holds glyph ids of subset fonts, not text.  The transcript is
 * taken at the element that draws (doc.c, doc_table.c, plot.c), so a
 * number can only reach the page through it.
 *
 * Runs from the repository root (data/, examples/, templates/).
 */
#include "test_util.h"

#include <cjson/cJSON.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/cli_summary.h"
#include "cli/pipeline.h"
#include "template/template.h"
#include "pdf/doc.h"
#include "util/csv.h"
#include "util/strbuf.h"
#include "util/xalloc.h"

/* The first three are compared figure by figure; the language test reads
 * the dossiers of the SAR, agricultural, FPV and infeasible examples. */
static const char *const missions[] = {
	"sar_imaging_quad", "agri_spray_octo", "delivery_drop_3p5kg",
	"fpv_racing_quad", "infeasible_compact_lifter",
};
#define N_MISSIONS ((int)(sizeof missions / sizeof missions[0]))

/* Everything one compiled mission wrote. */
struct outputs {
	char *text;        /* the dossier's transcript */
	cJSON *json;       /* result.json */
	char *bom;         /* bom.csv */
	char *totals;      /* bom_totals.csv */
};

struct fixture {
	struct cli_env env;
	struct template *tpl;
	char dir[64];
	char *index;       /* index.csv */
	struct outputs out[N_MISSIONS];
};

static char *
slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	if (f == NULL)
		fail_msg("cannot read %s", path);
	fseek(f, 0, SEEK_END);
	long n = ftell(f);
	fseek(f, 0, SEEK_SET);
	char *buf = xmalloc((size_t)n + 1);
	assert_int_equal(fread(buf, 1, (size_t)n, f), (size_t)n);
	buf[n] = '\0';
	fclose(f);
	return buf;
}

static int
setup(void **state)
{
	struct fixture *fx = xcalloc(1, sizeof *fx);
	if (cli_env_load(&fx->env, NULL, 1, stderr) != 0)
		return -1;
	fx->tpl = template_default();
	snprintf(fx->dir, sizeof fx->dir, "/tmp/aeroeval-consistency-XXXXXX");
	if (mkdtemp(fx->dir) == NULL)
		return -1;
	for (int i = 0; i < N_MISSIONS; i++) {
		struct strbuf text = STRBUF_INIT;
		struct pipeline_opts o = { fx->dir, fx->tpl, 5.0, &text };
		char path[256];
		snprintf(path, sizeof path, "examples/%s.json", missions[i]);
		enum pipeline_status st = pipeline_build(&fx->env, &o, path, NULL, stderr);
		if (st != PIPE_FEASIBLE && st != PIPE_INFEASIBLE)
			return -1;
		fx->out[i].text = strbuf_take(&text, NULL);
		snprintf(path, sizeof path, "%s/%s/result.json", fx->dir, missions[i]);
		char *json = slurp(path);
		fx->out[i].json = cJSON_Parse(json);
		free(json);
		snprintf(path, sizeof path, "%s/%s/bom.csv", fx->dir, missions[i]);
		fx->out[i].bom = slurp(path);
		snprintf(path, sizeof path, "%s/%s/bom_totals.csv", fx->dir, missions[i]);
		fx->out[i].totals = slurp(path);
	}
	if (cli_summary_refresh(fx->dir, NULL, stderr) != 0)
		return -1;
	char path[128];
	snprintf(path, sizeof path, "%s/index.csv", fx->dir);
	fx->index = slurp(path);
	*state = fx;
	return 0;
}

static int
teardown(void **state)
{
	struct fixture *fx = *state;
	for (int i = 0; i < N_MISSIONS; i++) {
		free(fx->out[i].text);
		cJSON_Delete(fx->out[i].json);
		free(fx->out[i].bom);
		free(fx->out[i].totals);
	}
	free(fx->index);
	char cmd[128];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", fx->dir);
	if (system(cmd) != 0)
		fprintf(stderr, "could not remove %s\n", fx->dir);
	template_free(fx->tpl);
	cli_env_free(&fx->env);
	free(fx);
	doc_global_cleanup();
	return 0;
}

/* ---- result.json ------------------------------------------------------------ */

static const cJSON *
jget(const cJSON *o, const char *key)
{
	const cJSON *it = cJSON_GetObjectItemCaseSensitive(o, key);
	if (it == NULL)
		fail_msg("result.json: no \"%s\"", key);
	return it;
}

static double
jnum(const cJSON *o, const char *key)
{
	const cJSON *it = jget(o, key);
	if (!cJSON_IsNumber(it))
		fail_msg("result.json: \"%s\" is not a number", key);
	return it->valuedouble;
}

/* ---- the transcript --------------------------------------------------------- */

/* The k-th (0-based) line of text whose first tab-separated cell is
 * label, copied; NULL when there is none. */
static char *
row_n(const char *text, const char *label, int k)
{
	size_t n = strlen(label);
	for (const char *p = text; p != NULL && *p != '\0';) {
		const char *eol = strchr(p, '\n');
		size_t len = eol ? (size_t)(eol - p) : strlen(p);
		if (len > n && strncmp(p, label, n) == 0 && p[n] == '\t' && k-- == 0) {
			char *line = xmalloc(len + 1);
			memcpy(line, p, len);
			line[len] = '\0';
			return line;
		}
		p = eol ? eol + 1 : NULL;
	}
	return NULL;
}

static char *
row(const char *text, const char *label)
{
	char *line = row_n(text, label, 0);
	if (line == NULL)
		fail_msg("dossier: no row \"%s\"", label);
	return line;
}

/* Cell i of a row (0 = the label), in buf. */
static const char *
cell(const char *line, int i, char *buf, size_t n)
{
	const char *p = line;
	for (int k = 0; k < i; k++) {
		p = strchr(p, '\t');
		if (p == NULL)
			fail_msg("dossier: row \"%s\" has no cell %d", line, i);
		p++;
	}
	size_t len = strcspn(p, "\t");
	snprintf(buf, n, "%.*s", (int)len, p);
	return buf;
}

/* The first number in s from *at on ("≥ 1549.95 USD" gives 1549.95), its
 * decimals in *dec; *at is moved past it.  Fails when there is none. */
static double
number_at(const char **at, int *dec, const char *what)
{
	const char *p = *at;
	while (*p != '\0' && !(*p >= '0' && *p <= '9'))
		p++;
	if (*p == '\0')
		fail_msg("%s: no number in \"%s\"", what, *at);
	const char *start = p;
	bool neg = start > *at && start[-1] == '-';
	while (*p >= '0' && *p <= '9')
		p++;
	*dec = 0;
	if (*p == '.' && p[1] >= '0' && p[1] <= '9') {
		p++;
		while (*p >= '0' && *p <= '9') {
			p++;
			(*dec)++;
		}
	}
	double v = strtod(start, NULL);
	*at = p;
	return neg ? -v : v;
}

/* printed (its first number after skipping `skip` numbers) is value x
 * rounded to the decimals printed. */
static void
assert_printed_nth(const char *what, const char *printed, int skip, double x)
{
	const char *at = printed;
	int dec = 0;
	double v = 0.0;
	for (int k = 0; k <= skip; k++)
		v = number_at(&at, &dec, what);
	char want[64], got[64];
	snprintf(want, sizeof want, "%.*f", dec, fabs(x));
	snprintf(got, sizeof got, "%.*f", dec, fabs(v));
	if (strcmp(want, got) != 0 || (x < 0) != (v < 0 && strtod(got, NULL) != 0.0))
		fail_msg("%s: printed \"%s\", but result.json holds %.12g (%s at %d decimals)",
		         what, printed, x, want, dec);
}

static void
assert_printed(const char *what, const char *printed, double x)
{
	assert_printed_nth(what, printed, 0, x);
}

/* Row label's cell i (its k-th occurrence) prints x. */
static void
assert_cell(const char *text, const char *label, int k, int i, double x)
{
	char *line = row_n(text, label, k);
	char buf[256], what[160];
	if (line == NULL)
		fail_msg("dossier: no row \"%s\" (occurrence %d)", label, k + 1);
	snprintf(what, sizeof what, "dossier \"%s\" (occurrence %d, cell %d)", label, k + 1, i);
	assert_printed(what, cell(line, i, buf, sizeof buf), x);
	free(line);
}

/* The number that follows `before` in the first line that holds it. */
static void
assert_after(const char *text, const char *before, double x)
{
	const char *p = strstr(text, before);
	char what[160];
	if (p == NULL)
		fail_msg("dossier: no \"%s\"", before);
	snprintf(what, sizeof what, "dossier after \"%s\"", before);
	const char *eol = strchr(p, '\n');
	char line[512];
	size_t len = eol ? (size_t)(eol - p) : strlen(p);
	snprintf(line, sizeof line, "%.*s", (int)len, p + strlen(before));
	assert_printed(what, line, x);
}

/* ---- CSV -------------------------------------------------------------------- */

/* Column `col` of the first data record of csv whose first field is key
 * (NULL: the first data record), copied into buf. */
static const char *
csv_cell(const char *csv, const char *key, const char *col, char *buf, size_t n)
{
	struct csv_reader rd;
	struct csv_record rec;
	char err[128];
	csv_init(&rd, csv, strlen(csv));
	assert_int_equal(csv_next(&rd, &rec, err, sizeof err), CSV_RECORD);
	int at = -1;
	for (size_t i = 0; i < rec.n_fields; i++)
		if (strcmp(rec.fields[i], col) == 0)
			at = (int)i;
	if (at < 0)
		fail_msg("csv: no column \"%s\"", col);
	buf[0] = '\0';
	bool found = false;
	while (!found && csv_next(&rd, &rec, err, sizeof err) == CSV_RECORD)
		if (key == NULL || strcmp(rec.fields[0], key) == 0) {
			snprintf(buf, n, "%s", (size_t)at < rec.n_fields ? rec.fields[at] : "");
			found = true;
		}
	csv_free(&rd);
	if (!found)
		fail_msg("csv: no record \"%s\"", key ? key : "(first)");
	return buf;
}

/* bom.csv's own sums over the lines to buy (the payload's aside). */
static void
bom_sums(const char *csv, double *mass_g, double *price, int *lines, int *unpriced)
{
	struct csv_reader rd;
	struct csv_record rec;
	char err[128];
	csv_init(&rd, csv, strlen(csv));
	assert_int_equal(csv_next(&rd, &rec, err, sizeof err), CSV_RECORD);
	*mass_g = *price = 0.0;
	*lines = *unpriced = 0;
	while (csv_next(&rd, &rec, err, sizeof err) == CSV_RECORD) {
		assert_true(rec.n_fields >= 10);
		if (strcmp(rec.fields[2], "payload") == 0)
			continue;
		(*lines)++;
		*mass_g += strtod(rec.fields[7], NULL);
		if (rec.fields[9][0] == '\0')
			(*unpriced)++;
		else
			*price += strtod(rec.fields[9], NULL);
	}
	csv_free(&rd);
}

/* ---- the quantities ----------------------------------------------------------- */

static void
check_mission(const struct fixture *fx, int m)
{
	const struct outputs *o = &fx->out[m];
	const char *text = o->text, *name = missions[m];
	const cJSON *root = o->json, *kf = jget(root, "key_figures");
	const cJSON *dor = jget(root, "design_of_record"), *bom = jget(root, "bom");
	const cJSON *perf = jget(dor, "performance");
	const cJSON *hover_op = cJSON_GetArrayItem(jget(dor, "operating_points"), 0);
	char buf[256], *line;
	print_message("%s\n", name);
	assert_true(cJSON_IsTrue(jget(root, "buildable")));

	/* Takeoff mass: cover, summary, mass budget; result.json; the BOM
	 * totals; the study table. */
	double mtow = jnum(kf, "takeoff_mass_kg");
	assert_true(mtow == jnum(root, "takeoff_mass_kg"));
	assert_true(fabs(jnum(dor, "total_mass_kg") - mtow) < 1e-3);
	assert_cell(text, "Takeoff mass (MTOW)", 0, 1, mtow);
	assert_cell(text, "Takeoff mass MTOW (kg)", 0, 1, mtow);
	assert_cell(text, "Takeoff mass (kg)", 0, 1, mtow);
	assert_printed("bom_totals.csv takeoff_mass_g",
	    csv_cell(o->totals, NULL, "takeoff_mass_g", buf, sizeof buf), 1000.0 * mtow);
	assert_printed("index.csv takeoff_mass_kg",
	    csv_cell(fx->index, name, "takeoff_mass_kg", buf, sizeof buf), mtow);

	/* Hover power at the takeoff mass: cover, summary, operating points. */
	double hp = jnum(kf, "hover_power_at_takeoff_mass_w");
	assert_true(hp == jnum(dor, "hover_power_w"));
	assert_true(hp == jnum(hover_op, "electrical_power_w"));
	assert_true(hp == jnum(jget(root, "hover_power_interval"), "hover_power_w"));
	assert_cell(text, "Hover power at takeoff mass (W)", 0, 1, hp);
	assert_cell(text, "Hover power at takeoff mass (W)", 1, 1, hp);
	assert_cell(text, "Electrical power, aircraft (W)", 0, 1, hp);

	/* ... and after shedding, labelled, where payload leaves on the way:
	 * hover at the lightest mass flown (the hover phase's mean in the
	 * phase table may include hover before the drop). */
	bool sheds = cJSON_IsTrue(jget(kf, "sheds_payload"));
	if (sheds) {
		double hs = jnum(kf, "hover_power_after_shedding_w");
		assert_true(hs == jnum(dor, "hover_power_after_shedding_w"));
		assert_true(hs < hp);
		assert_cell(text, "Hover power after shedding (W)", 0, 1, hs);
		assert_cell(text, "Hover power after shedding (W)", 1, 1, hs);
	} else {
		assert_true(cJSON_IsNull(jget(kf, "hover_power_after_shedding_w")));
		assert_null(row_n(text, "Hover power after shedding (W)", 0));
	}

	/* Hover battery current at the takeoff mass: summary, operating points. */
	double ih = jnum(kf, "hover_battery_current_at_takeoff_mass_a");
	assert_true(ih == jnum(hover_op, "battery_current_a"));
	assert_cell(text, "Hover battery current at takeoff mass (A)", 0, 1, ih);
	assert_cell(text, "Battery current, aircraft (A)", 0, 1, ih);

	/* Auxiliary power: summary, the mission section, the appendix. */
	double aux = jnum(kf, "aux_power_w");
	assert_true(aux == jnum(dor, "aux_power_w"));
	assert_cell(text, "Auxiliary power (W)", 0, 1, aux);
	assert_after(text, "includes ", aux);
	line = row(text, "payload_role.aux_power_w");
	cell(line, 1, buf, sizeof buf);
	free(line);
	const char *flown = strstr(buf, "as set; ");
	assert_printed("appendix payload_role.aux_power_w", flown != NULL ? flown : buf, aux);

	/* Hover endurance to the reserve: cover, summary, beyond the mission. */
	double te = jnum(kf, "hover_endurance_s");
	assert_true(te > 0.0);
	assert_true(te == jnum(dor, "hover_endurance_s"));
	assert_true(te == jnum(perf, "hover_time_s"));
	assert_true(te == jnum(jget(root, "hover_endurance_interval"), "hover_endurance_s"));
	assert_cell(text, "Hover endurance to reserve (min)", 0, 1, te / 60.0);
	assert_cell(text, "Hover endurance to reserve (min)", 1, 1, te / 60.0);
	assert_cell(text, "Flight time to the reserve", 0, 1, te / 60.0);
	assert_printed("index.csv hover_endurance_s",
	    csv_cell(fx->index, name, "hover_endurance_s", buf, sizeof buf), te);

	/* Flight time: cover, summary; the study table. */
	double tf = jnum(kf, "flight_time_s");
	assert_true(tf == jnum(dor, "flight_time_s"));
	assert_cell(text, "Mission flight time (min)", 0, 1, tf / 60.0);
	assert_cell(text, "Mission flight time (min)", 1, 1, tf / 60.0);
	assert_printed("index.csv flight_time_s",
	    csv_cell(fx->index, name, "flight_time_s", buf, sizeof buf), tf);

	/* State of charge at landing: summary, thermal margins, checks. */
	double soc = jnum(kf, "landing_soc");
	assert_true(soc == jnum(dor, "end_soc"));
	assert_true(soc == jnum(perf, "landing_soc"));
	assert_cell(text, "State of charge at landing (%)", 0, 1, 100.0 * soc);
	assert_cell(text, "State of charge at landing", 0, 1, 100.0 * soc);
	assert_cell(text, "State of charge at landing (reserve)", 0, 2, 100.0 * soc);

	/* The bill of materials: mass, price, unpriced lines. */
	double bm = jnum(kf, "bom_mass_kg"), price = jnum(kf, "bom_price_usd");
	int lines = (int)jnum(kf, "bom_lines"), unpriced = (int)jnum(kf, "bom_unpriced_lines");
	assert_true(bm == jnum(bom, "total_mass_kg"));
	assert_true(price == jnum(bom, "total_price_usd"));
	assert_int_equal(unpriced, (int)jnum(bom, "unpriced_lines"));
	assert_int_equal(lines, (int)jnum(bom, "lines_to_buy"));
	const cJSON *bp = jget(dor, "bom_price");
	assert_true(price == jnum(bp, "at_least_usd"));
	assert_int_equal(unpriced, (int)jnum(bp, "unpriced_lines"));
	assert_int_equal(lines, (int)jnum(bp, "lines"));
	assert_cell(text, "  of which parts (BOM) + payload", 0, 1, bm);
	assert_after(text, "The bill of materials holds ", bm);
	line = row(text, "Bill of materials price");
	cell(line, 1, buf, sizeof buf);
	free(line);
	assert_printed("dossier BOM price", buf, price);
	assert_printed_nth("dossier unpriced lines", buf, 1, unpriced);
	assert_printed_nth("dossier lines", buf, 2, lines);
	double mass_g, csv_price;
	int csv_lines, csv_unpriced;
	bom_sums(o->bom, &mass_g, &csv_price, &csv_lines, &csv_unpriced);
	assert_true(fabs(mass_g - 1000.0 * bm) <= 0.05 * csv_lines + 1e-6);
	assert_true(fabs(csv_price - price) <= 0.005 * csv_lines + 1e-6);
	assert_int_equal(csv_lines, lines);
	assert_int_equal(csv_unpriced, unpriced);
	assert_printed("bom_totals.csv parts_mass_g",
	    csv_cell(o->totals, NULL, "parts_mass_g", buf, sizeof buf), 1000.0 * bm);
	assert_printed("bom_totals.csv known_price",
	    csv_cell(o->totals, NULL, "known_price", buf, sizeof buf), price);
	assert_printed("bom_totals.csv unpriced_lines",
	    csv_cell(o->totals, NULL, "unpriced_lines", buf, sizeof buf), unpriced);
	assert_printed("bom_totals.csv lines",
	    csv_cell(o->totals, NULL, "lines", buf, sizeof buf), lines);
	assert_printed("index.csv cost_usd",
	    csv_cell(fx->index, name, "cost_usd", buf, sizeof buf), price);
	assert_printed("index.csv unpriced_lines",
	    csv_cell(fx->index, name, "unpriced_lines", buf, sizeof buf), unpriced);
}

static void
every_quantity_should_read_the_same_in_every_output_sar(void **state)
{
	check_mission(*state, 0);
}

static void
every_quantity_should_read_the_same_in_every_output_agri(void **state)
{
	check_mission(*state, 1);
}

static void
every_quantity_should_read_the_same_in_every_output_delivery_drop(void **state)
{
	check_mission(*state, 2);
}

/* The two shedding missions say so, and hover lighter after it. */
static void
shedding_missions_should_give_both_hover_powers(void **state)
{
	const struct fixture *fx = *state;
	assert_true(cJSON_IsFalse(jget(jget(fx->out[0].json, "key_figures"), "sheds_payload")));
	for (int m = 1; m < 3; m++)
		assert_true(cJSON_IsTrue(jget(jget(fx->out[m].json, "key_figures"), "sheds_payload")));
}

/* ---- a client's language ------------------------------------------------------ */

/* Solver vocabulary a client's engineer should not meet before the
 * clearly titled solver appendix ("Appendix: solver details"), and
 * wording the dossier once printed. */
static const char *const banned[] = {
	"Lipschitz", "Goal γ", "γ", "fixed point", "fixed-point", "under-relax",
	"closing", "closed on", "contraction", "iteration", "iterate", "paper",
	"dead-weight run", "dual run", "none role", "a Octocopter", "a Hexacopter",
	" 1 allowances", " 0 allowances", "mass loop",
};

/* The text before the first line equal to heading (all of it when none). */
static size_t
before(const char *text, const char *heading)
{
	size_t n = strlen(heading);
	for (const char *p = text; *p != '\0';) {
		if (strncmp(p, heading, n) == 0 && (p[n] == '\n' || p[n] == '\0'))
			return (size_t)(p - text);
		const char *eol = strchr(p, '\n');
		if (eol == NULL)
			break;
		p = eol + 1;
	}
	return strlen(text);
}

/* The line of text that holds p, for a message. */
static const char *
line_of(const char *text, const char *p, char *buf, size_t n)
{
	const char *s = p;
	while (s > text && s[-1] != '\n')
		s--;
	size_t len = strcspn(s, "\n");
	snprintf(buf, n, "%.*s", (int)len, s);
	return buf;
}

/* No exponent notation ("1.8e+03") and no percentage beyond ±999 %. */
static void
assert_plain_numbers(const char *name, const char *text)
{
	char line[512];
	for (const char *p = text; *p != '\0'; p++) {
		if (p > text && p[-1] >= '0' && p[-1] <= '9' && (p[0] == 'e' || p[0] == 'E')
		    && (p[1] == '+' || p[1] == '-') && p[2] >= '0' && p[2] <= '9')
			fail_msg("%s: exponent notation in \"%s\"", name, line_of(text, p, line, sizeof line));
		if (p[0] == '%' && p > text) {
			const char *q = p - 1;
			while (q > text && (*q == ' ' || (unsigned char)*q == 0xa0))
				q--;
			const char *e = q + 1;
			while (q > text && ((*q >= '0' && *q <= '9') || *q == '.'))
				q--;
			if (e - q > 1 && strtod(q + 1, NULL) > 999.0)
				fail_msg("%s: percentage beyond 999 %% in \"%s\"", name,
				         line_of(text, p, line, sizeof line));
		}
	}
}

static void
dossiers_should_speak_a_clients_language(void **state)
{
	const struct fixture *fx = *state;
	static const int shown[] = { 0, 1, 3, 4 }; /* SAR, agricultural, FPV, infeasible */
	char line[512];
	for (size_t k = 0; k < sizeof shown / sizeof shown[0]; k++) {
		const struct outputs *o = &fx->out[shown[k]];
		const char *name = missions[shown[k]];
		size_t solver = before(o->text, "## Appendix: solver details");
		assert_true(solver < strlen(o->text));  /* the appendix is there */
		char *head = xmalloc(solver + 1);
		memcpy(head, o->text, solver);
		head[solver] = '\0';
		for (size_t i = 0; i < sizeof banned / sizeof banned[0]; i++) {
			const char *hit = strstr(head, banned[i]);
			if (hit != NULL)
				fail_msg("%s: \"%s\" outside the solver appendix: \"%s\"", name, banned[i],
				         line_of(head, hit, line, sizeof line));
		}
		/* Catalogue parts by maker and part number: their catalogue ids
		 * only in the appendix's list of the entries used. */
		head[before(head, "# 12  Appendix")] = '\0';
		const cJSON *sel = jget(o->json, "selected");
		static const char *const kinds[] = { "motor", "prop", "battery", "esc" };
		for (size_t i = 0; cJSON_IsObject(sel) && i < 4; i++) {
			const cJSON *part = cJSON_GetObjectItemCaseSensitive(sel, kinds[i]);
			const cJSON *id = cJSON_GetObjectItemCaseSensitive(part, "catalogue_id");
			if (!cJSON_IsString(id))
				continue;
			const char *hit = strstr(head, id->valuestring);
			if (hit != NULL)
				fail_msg("%s: catalogue id \"%s\" before the appendix: \"%s\"", name,
				         id->valuestring, line_of(head, hit, line, sizeof line));
		}
		free(head);
		assert_plain_numbers(name, o->text);
	}
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_quantity_should_read_the_same_in_every_output_sar),
		cmocka_unit_test(every_quantity_should_read_the_same_in_every_output_agri),
		cmocka_unit_test(every_quantity_should_read_the_same_in_every_output_delivery_drop),
		cmocka_unit_test(shedding_missions_should_give_both_hover_powers),
		cmocka_unit_test(dossiers_should_speak_a_clients_language),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
