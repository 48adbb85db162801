/* csv.c — RFC 4180 reader with per-record error recovery (see csv.h). */
#include "util/csv.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/numfmt.h"
#include "util/xalloc.h"

void
csv_init(struct csv_reader *r, const char *buf, size_t n)
{
	r->p = buf;
	r->end = buf + n;
	r->line = 1;
	strbuf_init(&r->text);
	r->offs = NULL;
	r->fields = NULL;
	r->cap_fields = 0;
	/* A UTF-8 byte order mark (EF BB BF), as spreadsheet exports write. */
	if (n >= 3 && memcmp(buf, "\xEF\xBB\xBF", 3) == 0)
		r->p += 3;
}

void
csv_free(struct csv_reader *r)
{
	if (r == NULL)
		return;
	strbuf_free(&r->text);
	free(r->offs);
	free(r->fields);
	r->offs = NULL;
	r->fields = NULL;
	r->cap_fields = 0;
}

/* Records that field number i starts at the current end of r->text. */
static void
start_field(struct csv_reader *r, size_t i)
{
	if (i >= r->cap_fields) {
		r->cap_fields = r->cap_fields ? 2 * r->cap_fields : 32;
		r->offs = xrealloc(r->offs, r->cap_fields * sizeof *r->offs);
		r->fields = xrealloc(r->fields, r->cap_fields * sizeof *r->fields);
	}
	r->offs[i] = r->text.len;
}

/* Length of the line end at p (1 for LF, 2 for CRLF), 0 if none. */
static size_t
eol_len(const struct csv_reader *r, const char *p)
{
	if (p < r->end && *p == '\n')
		return 1;
	if (p + 1 < r->end && p[0] == '\r' && p[1] == '\n')
		return 2;
	return 0;
}

/* Error recovery: moves past the next LF at or after `from` (which is on
 * line `line`), so reading resumes at the start of the following line. */
static void
skip_line(struct csv_reader *r, const char *from, size_t line)
{
	const char *nl = memchr(from, '\n', (size_t)(r->end - from));
	r->p = nl ? nl + 1 : r->end;
	r->line = nl ? line + 1 : line;
}

static void
set_msg(char *err, size_t errlen, const char *msg, size_t field)
{
	if (err != NULL && errlen > 0)
		snprintf(err, errlen, "%s (field %zu)", msg, field + 1);
}

enum csv_status
csv_next(struct csv_reader *r, struct csv_record *rec, char *err, size_t errlen)
{
	size_t k;
	/* Empty lines are not records. */
	while ((k = eol_len(r, r->p)) > 0) {
		r->p += k;
		r->line++;
	}
	if (r->p >= r->end)
		return CSV_EOF;

	const size_t rec_line = r->line;
	size_t n = 0;
	strbuf_reset(&r->text);
	rec->line = rec_line;
	rec->n_fields = 0;
	rec->fields = NULL;

	for (;;) {
		start_field(r, n);
		const char *p = r->p;
		if (p < r->end && *p == '"') {
			/* Quoted field: runs to the next lone quote; "" is a quote;
			 * line breaks inside count toward the line number. */
			const char *open = p;
			const size_t open_line = r->line;
			p++;
			for (;;) {
				if (p >= r->end) {
					set_msg(err, errlen, "unterminated quoted field", n);
					/* Assume the quote was a typo: the rest of its
					 * line is lost, the next line is read again. */
					skip_line(r, open, open_line);
					return CSV_MALFORMED;
				}
				if (*p == '"') {
					if (p + 1 < r->end && p[1] == '"') {
						strbuf_append_char(&r->text, '"');
						p += 2;
						continue;
					}
					p++;
					break;
				}
				if (*p == '\0') {
					set_msg(err, errlen, "NUL byte in field", n);
					skip_line(r, p, r->line);
					return CSV_MALFORMED;
				}
				if (*p == '\n')
					r->line++;
				strbuf_append_char(&r->text, *p);
				p++;
			}
			if (p < r->end && *p != ',' && eol_len(r, p) == 0) {
				set_msg(err, errlen, "text after closing quote", n);
				skip_line(r, p, r->line);
				return CSV_MALFORMED;
			}
		} else {
			const char *q = p;
			while (q < r->end && *q != ',' && eol_len(r, q) == 0) {
				if (*q == '"' || *q == '\0') {
					set_msg(err, errlen, *q == '"' ? "quote inside unquoted field"
					                              : "NUL byte in field", n);
					skip_line(r, q, r->line);
					return CSV_MALFORMED;
				}
				q++;
			}
			strbuf_append(&r->text, p, (size_t)(q - p));
			p = q;
		}
		strbuf_append_char(&r->text, '\0');
		n++;
		/* Here p is at ',', a line end or the end of the buffer. */
		if (p < r->end && *p == ',') {
			r->p = p + 1;
			continue;
		}
		k = eol_len(r, p);
		r->p = p + k;
		if (k > 0)
			r->line++;
		break;
	}

	/* The text buffer may have moved while growing: pointers last. */
	for (size_t i = 0; i < n; i++)
		r->fields[i] = r->text.data + r->offs[i];
	rec->fields = r->fields;
	rec->n_fields = n;
	return CSV_RECORD;
}

void
csv_write_field(struct strbuf *sb, const char *s)
{
	if (strpbrk(s, ",\"\r\n") == NULL) {
		strbuf_append_str(sb, s);
		return;
	}
	strbuf_append_char(sb, '"');
	for (; *s != '\0'; s++) {
		if (*s == '"')
			strbuf_append_char(sb, '"');  /* an inner quote is doubled */
		strbuf_append_char(sb, *s);
	}
	strbuf_append_char(sb, '"');
}

void
csv_out_field(struct csv_out *o, const char *s)
{
	if (o->n++ > 0)
		strbuf_append_char(o->sb, ',');
	csv_write_field(o->sb, s);
}

bool
csv_out_num(struct csv_out *o, bool known, double x, int decimals)
{
	char t[400];   /* the 309 digits of DBL_MAX, its sign, point and decimals */
	bool ok = !known || numfmt_fixed(t, sizeof t, x, decimals) > 0;
	if (!known || !ok)
		t[0] = '\0';
	csv_out_field(o, t);
	return ok;
}

void
csv_out_end(struct csv_out *o)
{
	strbuf_append(o->sb, "\r\n", 2);
	o->n = 0;
}
