/* cohort.c — cohort CSV rows into struct cohort_row (see cohort.h). */
#include "input/cohort.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/csv.h"
#include "util/strbuf.h"
#include "util/file.h"
#include "util/text.h"
#include "util/xalloc.h"

/* Largest cohort file accepted: the real ones are a few kB. */
#define COHORT_MAX_BYTES ((size_t)64 << 20)

static const char *const confidence_names[] = { "high", "medium", "low", NULL };

/* How a column's cell is read and checked. */
enum col_kind {
	K_TEXT,    /* any text, kept verbatim */
	K_POS,     /* decimal number > 0 */
	K_NONNEG,  /* decimal number >= 0 */
	K_INT,     /* whole number >= 1 */
	K_BOOL,    /* 0, 1, true, false */
	K_CLASS,   /* enum airframe_class spelling */
	K_ROLE,    /* enum role_type spelling, "none" excluded */
	K_CONF     /* enum cohort_confidence spelling */
};

/* NO_FLAG marks a column without a has_ flag (name, the text columns and
 * takeoff_mass_kg, which must never be empty). */
#define NO_FLAG SIZE_MAX

struct col {
	const char *name;     /* header spelling */
	enum col_kind kind;   /* how to read it */
	size_t off;           /* offset of the value in struct cohort_row */
	size_t has_off;       /* offset of its has_ flag, or NO_FLAG */
	bool required;        /* the header must have it and no cell may be empty */
};

#define COL(f, kind) { #f, kind, offsetof(struct cohort_row, f), \
	offsetof(struct cohort_row, has_##f), false }
#define TEXT(f, req) { #f, K_TEXT, offsetof(struct cohort_row, f), NO_FLAG, req }

/* The README table, in its order. */
static const struct col cols[] = {
	TEXT(name, true),
	TEXT(cohort, false),
	{ "takeoff_mass_kg", K_POS, offsetof(struct cohort_row, takeoff_mass_kg), NO_FLAG, true },
	COL(empty_mass_kg, K_POS),
	COL(payload_kg, K_NONNEG),
	COL(max_payload_kg, K_NONNEG),
	COL(rotor_count, K_INT),
	COL(coaxial, K_BOOL),
	COL(diagonal_wheelbase_mm, K_POS),
	COL(prop_diameter_in, K_POS),
	COL(prop_pitch_in, K_POS),
	TEXT(battery_chemistry, false),
	COL(cell_count, K_INT),
	COL(battery_capacity_mah, K_POS),
	COL(battery_pack_count, K_INT),
	COL(battery_mass_kg, K_POS),
	COL(hover_time_min, K_POS),
	COL(max_flight_time_min, K_POS),
	COL(cruise_speed_ms, K_POS),
	COL(max_speed_ms, K_POS),
	COL(airframe_class, K_CLASS),
	COL(role, K_ROLE),
	TEXT(source, false),
	COL(confidence, K_CONF),
	TEXT(notes, false),
};
#define N_COLS (sizeof cols / sizeof cols[0])

const char *
cohort_confidence_name(enum cohort_confidence c)
{
	return (unsigned)c < COHORT_CONF_MAX ? confidence_names[c] : "";
}

/* Appends one "FILE:LINE: error: COLUMN: message" line to c->errors. */
__attribute__((format(printf, 5, 6)))
static void
add_error(struct cohort *c, const char *file, size_t line, const char *column,
          const char *fmt, ...)
{
	struct strbuf sb = STRBUF_INIT;
	va_list ap;
	strbuf_printf(&sb, "%s:%zu: error: %s: ", file, line, column);
	va_start(ap, fmt);
	strbuf_vprintf(&sb, fmt, ap);
	va_end(ap);
	c->errors = xrealloc(c->errors, (c->n_errors + 1) * sizeof *c->errors);
	c->errors[c->n_errors++] = strbuf_take(&sb, NULL);
}

/* Copies s without leading and trailing blanks into sb; returns the copy. */
static const char *
trimmed(struct strbuf *sb, const char *s)
{
	size_t n = strlen(s);
	while (n > 0 && (*s == ' ' || *s == '\t')) {
		s++;
		n--;
	}
	while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t'))
		n--;
	strbuf_reset(sb);
	strbuf_append(sb, s, n);
	return strbuf_str(sb);
}

/* A plain decimal number: digits, sign, point and exponent only, so that
 * strtod's "nan", "inf" and hex forms are refused; the result is finite. */
static int
parse_decimal(const char *s, double *out)
{
	if (*s == '\0' || strspn(s, "0123456789+-.eE") != strlen(s))
		return -1;
	char *end;
	double v = strtod(s, &end);
	if (*end != '\0' || end == s || !isfinite(v))
		return -1;
	*out = v;
	return 0;
}

/* A whole number >= 1 written with digits only. */
static int
parse_count(const char *s, int *out)
{
	long v = 0;
	if (*s == '\0')
		return -1;
	for (; *s != '\0'; s++) {
		if (*s < '0' || *s > '9' || v > 1000000)
			return -1;
		v = v * 10 + (*s - '0');
	}
	if (v < 1 || v > 1000000)
		return -1;
	*out = (int)v;
	return 0;
}

static int
equal_nocase(const char *a, const char *b)
{
	for (; *a != '\0' && *b != '\0'; a++, b++)
		if (tolower((unsigned char)*a) != tolower((unsigned char)*b))
			return 0;
	return *a == *b;
}

/* Looks s up in the NULL-terminated spelling table, accepting indices from
 * `first` on.  Returns the index, or -1 after an error that lists the
 * accepted spellings. */
static int
read_enum(struct cohort *c, const char *file, size_t line, const struct col *cl,
          const char *s, const char *const *table, int first, const char *what)
{
	int k = spec_enum_index(table, s);
	if (k >= first)
		return k;
	struct strbuf list = STRBUF_INIT;
	for (int i = first; table[i] != NULL; i++)
		strbuf_printf(&list, "%s%s", i > first ? ", " : "", table[i]);
	add_error(c, file, line, cl->name, "unknown %s \"%s\" (%s)", what, s, strbuf_str(&list));
	strbuf_free(&list);
	return -1;
}

/* Reads one non-empty cell s (already trimmed) of column cl into row.
 * Returns 0, or -1 after adding an error message. */
static int
read_cell(struct cohort *c, const char *file, size_t line, const struct col *cl,
          const char *s, struct cohort_row *row)
{
	char *base = (char *)row;
	double v;
	int k;
	switch (cl->kind) {
	case K_TEXT:
		break; /* stored by the caller */
	case K_POS:
	case K_NONNEG:
		if (parse_decimal(s, &v) < 0) {
			add_error(c, file, line, cl->name, "not a number (got \"%s\")", s);
			return -1;
		}
		if (cl->kind == K_POS && !(v > 0)) {
			add_error(c, file, line, cl->name, "must be > 0 (got %s)", s);
			return -1;
		}
		if (cl->kind == K_NONNEG && v < 0) {
			add_error(c, file, line, cl->name, "must be >= 0 (got %s)", s);
			return -1;
		}
		*(double *)(base + cl->off) = v + 0.0; /* + 0.0 turns -0 into 0 */
		break;
	case K_INT:
		if (parse_count(s, &k) < 0) {
			add_error(c, file, line, cl->name,
			          "must be a whole number >= 1 (got \"%s\")", s);
			return -1;
		}
		*(int *)(base + cl->off) = k;
		break;
	case K_BOOL:
		if (strcmp(s, "1") == 0 || equal_nocase(s, "true"))
			*(bool *)(base + cl->off) = true;
		else if (strcmp(s, "0") == 0 || equal_nocase(s, "false"))
			*(bool *)(base + cl->off) = false;
		else {
			add_error(c, file, line, cl->name,
			          "must be 0, 1, true or false (got \"%s\")", s);
			return -1;
		}
		break;
	case K_CLASS:
		if ((k = read_enum(c, file, line, cl, s, spec_enum_airframe, 0,
		                   "airframe class")) < 0)
			return -1;
		*(enum airframe_class *)(base + cl->off) = (enum airframe_class)k;
		break;
	case K_ROLE:
		/* "none" is a mission default, not a role a real aircraft has. */
		if ((k = read_enum(c, file, line, cl, s, spec_enum_role, ROLE_NONE + 1,
		                   "role")) < 0)
			return -1;
		*(enum role_type *)(base + cl->off) = (enum role_type)k;
		break;
	case K_CONF:
		if ((k = read_enum(c, file, line, cl, s, confidence_names, 0,
		                   "confidence")) < 0)
			return -1;
		*(enum cohort_confidence *)(base + cl->off) = (enum cohort_confidence)k;
		break;
	}
	if (cl->has_off != NO_FLAG)
		*(bool *)(base + cl->has_off) = true;
	return 0;
}

/* Text cells end up in reports, JSON and file names: valid UTF-8 (a
 * Latin-1 "é" made `validate --json` print invalid JSON) and no control
 * character (text_is_control(): bidirectional ones too, as mission files),
 * except line breaks and tabs in the free-text columns.
 * Returns 0, or -1 after adding an error. */
static int
check_text(struct cohort *c, const char *file, size_t line, const struct col *cl,
           const char *s)
{
	bool free_text = strcmp(cl->name, "notes") == 0 || strcmp(cl->name, "source") == 0;
	size_t len = strlen(s);
	for (size_t i = 0; i < len;) {
		size_t seq = text_utf8_seq(s + i, len - i);
		unsigned char ch = (unsigned char)s[i];
		if (seq == 0) {
			add_error(c, file, line, cl->name, "not valid UTF-8 (byte 0x%02x at "
			          "offset %zu); save the file as UTF-8", ch, i);
			return -1;
		}
		unsigned long cp = text_utf8_cp(s + i, seq);
		if (text_is_control(cp) && !(free_text && strchr("\t\r\n", ch) != NULL)) {
			if (cp < 0x80)
				add_error(c, file, line, cl->name, "control character 0x%02x at "
				          "offset %zu", ch, i);
			else
				add_error(c, file, line, cl->name, "control character U+%04lX at "
				          "offset %zu", cp, i);
			return -1;
		}
		i += seq;
	}
	return 0;
}

static void
free_row(struct cohort_row *row)
{
	for (size_t j = 0; j < N_COLS; j++)
		if (cols[j].kind == K_TEXT)
			free(*(char **)((char *)row + cols[j].off));
}

/* Fills row from one record whose cell i belongs to column map[i] (or to
 * no known column when map[i] < 0).  Returns the number of errors added. */
static int
read_row(struct cohort *c, const char *file, const struct csv_record *rec,
         const int *map, struct cohort_row *row, struct strbuf *tmp)
{
	int n_bad = 0;
	memset(row, 0, sizeof *row);
	row->line = rec->line;
	for (size_t j = 0; j < N_COLS; j++)
		if (cols[j].kind == K_TEXT)
			*(char **)((char *)row + cols[j].off) = xstrdup("");
	for (size_t i = 0; i < rec->n_fields; i++) {
		if (map[i] < 0)
			continue;
		const struct col *cl = &cols[map[i]];
		if (cl->kind == K_TEXT) {
			/* Text is kept verbatim: quoting already delimits it. */
			char **slot = (char **)((char *)row + cl->off);
			if (check_text(c, file, rec->line, cl, rec->fields[i]) < 0) {
				n_bad++;
				continue;
			}
			free(*slot);
			*slot = xstrdup(rec->fields[i]);
			if (cl->required && trimmed(tmp, rec->fields[i])[0] == '\0') {
				add_error(c, file, rec->line, cl->name, "empty, but required");
				n_bad++;
			}
			continue;
		}
		const char *s = trimmed(tmp, rec->fields[i]);
		if (*s == '\0') {
			if (cl->required) {
				add_error(c, file, rec->line, cl->name, "empty, but required");
				n_bad++;
			}
			continue; /* unknown: the has_ flag stays false */
		}
		if (read_cell(c, file, rec->line, cl, s, row) < 0)
			n_bad++;
	}
	return n_bad;
}

/* Maps the header cells to columns; -1 after adding errors when a column is
 * duplicated or a required one is missing. */
static int
read_header(struct cohort *c, const char *file, const struct csv_record *rec,
            int *map, struct strbuf *tmp)
{
	int seen[N_COLS] = { 0 };
	int rc = 0;
	for (size_t i = 0; i < rec->n_fields; i++) {
		const char *h = trimmed(tmp, rec->fields[i]);
		map[i] = -1;
		for (size_t j = 0; j < N_COLS; j++) {
			if (strcmp(h, cols[j].name) != 0)
				continue;
			if (seen[j]++) {
				add_error(c, file, rec->line, cols[j].name, "column appears twice");
				rc = -1;
			}
			map[i] = (int)j;
		}
	}
	for (size_t j = 0; j < N_COLS; j++) {
		if (cols[j].required && !seen[j]) {
			add_error(c, file, rec->line, cols[j].name, "required column missing from the header");
			rc = -1;
		}
	}
	return rc;
}

int
cohort_parse(const char *file, const char *buf, size_t n, struct cohort *out)
{
	struct csv_reader r;
	struct csv_record rec;
	struct strbuf tmp = STRBUF_INIT;
	char msg[128];
	int *map = NULL;
	size_t n_header = 0, cap = 0;
	enum csv_status st;

	memset(out, 0, sizeof *out);
	csv_init(&r, buf, n);

	/* The header is the first record; a broken header spoils every row. */
	st = csv_next(&r, &rec, msg, sizeof msg);
	if (st == CSV_EOF) {
		add_error(out, file, 1, "row", "empty file, no header line");
		goto done;
	}
	if (st == CSV_MALFORMED) {
		add_error(out, file, rec.line, "row", "header: %s", msg);
		goto done;
	}
	n_header = rec.n_fields;
	map = xmalloc(n_header * sizeof *map);
	if (read_header(out, file, &rec, map, &tmp) < 0)
		goto done;

	while ((st = csv_next(&r, &rec, msg, sizeof msg)) != CSV_EOF) {
		if (st == CSV_MALFORMED) {
			add_error(out, file, rec.line, "row", "%s", msg);
			continue;
		}
		if (rec.n_fields != n_header) {
			add_error(out, file, rec.line, "row", "%zu cells, but the header has %zu",
			          rec.n_fields, n_header);
			continue;
		}
		if (out->n_rows == cap) {
			cap = cap ? 2 * cap : 32;
			out->rows = xrealloc(out->rows, cap * sizeof *out->rows);
		}
		struct cohort_row *row = &out->rows[out->n_rows];
		if (read_row(out, file, &rec, map, row, &tmp) == 0)
			out->n_rows++;
		else
			free_row(row);
	}
done:
	free(map);
	strbuf_free(&tmp);
	csv_free(&r);
	return out->n_errors == 0 ? 0 : -1;
}

int
cohort_load(const char *path, struct cohort *out)
{
	unsigned char *buf;
	size_t n;
	char err[512];
	memset(out, 0, sizeof *out);
	if (file_read(path, COHORT_MAX_BYTES, &buf, &n, err, sizeof err) < 0) {
		struct strbuf sb = STRBUF_INIT;
		size_t lp = strlen(path);
		/* fsout's message starts "PATH: "; put "error: " after it so the
		 * line reads like every other compiler diagnostic. */
		if (strncmp(err, path, lp) == 0 && err[lp] == ':')
			strbuf_printf(&sb, "%s: error:%s", path, err + lp + 1);
		else
			strbuf_printf(&sb, "%s: error: %s", path, err);
		out->errors = xmalloc(sizeof *out->errors);
		out->errors[0] = strbuf_take(&sb, NULL);
		out->n_errors = 1;
		return -1;
	}
	int rc = cohort_parse(path, (const char *)buf, n, out);
	free(buf);
	return rc;
}

void
cohort_free(struct cohort *c)
{
	if (c == NULL)
		return;
	for (size_t i = 0; i < c->n_rows; i++)
		free_row(&c->rows[i]);
	for (size_t i = 0; i < c->n_errors; i++)
		free(c->errors[i]);
	free(c->rows);
	free(c->errors);
	memset(c, 0, sizeof *c);
}
