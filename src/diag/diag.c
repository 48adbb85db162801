/* diag.c — compiler-style diagnostics: message table, buffer, exit status. */
#include "diag/diag.h"

#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/text.h"
#include "util/xalloc.h"

struct diag_kind_info {
	enum diag_severity sev;  /* error or note */
	int status;              /* exit status the kind implies */
	const char *summary;     /* fixed text after "path: " */
};

static const struct diag_kind_info diag_kinds[] = {
#define DIAG_X_ROW(id, sev, status, text) { sev, status, text },
	DIAG_KINDS(DIAG_X_ROW)
#undef DIAG_X_ROW
};
_Static_assert(sizeof diag_kinds / sizeof diag_kinds[0] == DIAG_MAX,
               "one row per diagnostic kind");

struct diag {
	FILE *out;        /* where diag_flush writes; NULL = keep only */
	char *text;       /* buffered lines, NUL-terminated */
	size_t len;       /* bytes in text */
	size_t cap;       /* allocated bytes of text */
	int n_errors;     /* errors reported, ever */
	int status;       /* worst exit status seen */
};

struct diag *
diag_alloc(FILE *out)
{
	struct diag *dg = xcalloc(1, sizeof *dg);
	dg->out = out;
	dg->cap = 256;
	dg->text = xmalloc(dg->cap);
	dg->text[0] = '\0';
	return dg;
}

void
diag_free(struct diag *dg)
{
	if (dg == NULL)
		return;
	free(dg->text);
	free(dg);
}

/* Append formatted text to the buffer, growing it as needed. */
static void
diag_vappend(struct diag *dg, const char *fmt, va_list ap)
	__attribute__((format(printf, 2, 0)));

static void
diag_vappend(struct diag *dg, const char *fmt, va_list ap)
{
	va_list aq;
	va_copy(aq, ap);
	int need = vsnprintf(dg->text + dg->len, dg->cap - dg->len, fmt, aq);
	va_end(aq);
	if (need < 0)
		return; /* an encoding error: drop the fragment, keep the line */
	if ((size_t)need >= dg->cap - dg->len) {
		while ((size_t)need >= dg->cap - dg->len)
			dg->cap *= 2;
		dg->text = xrealloc(dg->text, dg->cap);
		vsnprintf(dg->text + dg->len, dg->cap - dg->len, fmt, ap);
	}
	dg->len += (size_t)need;
}

static void
diag_append(struct diag *dg, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

static void
diag_append(struct diag *dg, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	diag_vappend(dg, fmt, ap);
	va_end(ap);
}

void
diag_quote(const char *s, size_t len, size_t max_chars, char *out, size_t n)
{
	size_t o = 0, chars = 0, i = 0;
	/* Reserve room for the closing quote, "..." and the NUL. */
	if (n < 8) {
		if (n > 0)
			out[0] = '\0';
		return;
	}
	out[o++] = '"';
	while (i < len) {
		char piece[8];
		size_t plen;
		unsigned char c = (unsigned char)s[i];
		size_t seq = text_utf8_seq(s + i, len - i);
		if (chars == max_chars || o + 6 + 4 >= n) {
			memcpy(out + o, "...", 3);
			o += 3;
			break;
		}
		if (c == '"' || c == '\\') {
			piece[0] = '\\';
			piece[1] = (char)c;
			plen = 2;
			seq = 1;
		} else if (c < 0x20 || c == 0x7f || seq == 0) {
			plen = (size_t)snprintf(piece, sizeof piece, "\\x%02x", c);
			seq = 1;
		} else {
			memcpy(piece, s + i, seq);
			plen = seq;
		}
		memcpy(out + o, piece, plen);
		o += plen;
		i += seq;
		chars++;
	}
	out[o++] = '"';
	out[o] = '\0';
}

void
diag_report(struct diag *dg, enum diag_kind kind, const struct diag_loc *loc,
            const char *path, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	diag_vreport(dg, kind, loc, path, fmt, ap);
	va_end(ap);
}

void
diag_vreport(struct diag *dg, enum diag_kind kind, const struct diag_loc *loc,
             const char *path, const char *fmt, va_list ap)
{
	const struct diag_kind_info *k = &diag_kinds[kind];

	if (loc != NULL && loc->line > 0)
		diag_append(dg, "%s:%d:%d: ", loc->file, loc->line, loc->col);
	else if (loc != NULL && loc->file != NULL)
		diag_append(dg, "%s: ", loc->file);
	diag_append(dg, "%s: ", diag_severity_name(k->sev));
	if (path != NULL && path[0] != '\0') {
		/* A path holds user keys (an unknown field), so it is printed
		 * through the quoting rules without the quotes. */
		char q[3 * 128 + 16];
		diag_quote(path, strlen(path), 128, q, sizeof q);
		q[strlen(q) - 1] = '\0';
		diag_append(dg, "%s: ", q + 1);
	}
	diag_append(dg, "%s", k->summary);
	if (fmt != NULL)
		diag_vappend(dg, fmt, ap);
	diag_append(dg, "\n");

	if (k->sev == DIAG_ERROR)
		dg->n_errors++;
	diag_raise_status(dg, k->status);
}

void
diag_count(struct diag *dg, enum diag_kind kind)
{
	if (diag_kinds[kind].sev == DIAG_ERROR)
		dg->n_errors++;
	diag_raise_status(dg, diag_kinds[kind].status);
}

void
diag_flush(struct diag *dg)
{
	if (dg->len == 0)
		return;
	if (dg->out != NULL) {
		/* One fwrite of the whole buffer: with an unbuffered stderr this
		 * is one write(2), so parallel missions do not interleave lines. */
		fwrite(dg->text, 1, dg->len, dg->out);
		fflush(dg->out);
	}
	dg->len = 0;
	dg->text[0] = '\0';
}

const char *
diag_text(const struct diag *dg)
{
	return dg->text;
}

int
diag_n_errors(const struct diag *dg)
{
	return dg->n_errors;
}

void
diag_raise_status(struct diag *dg, int status)
{
	if (status > dg->status)
		dg->status = status;
}

int
diag_exit_status(const struct diag *dg)
{
	return dg->status;
}

const char *
diag_severity_name(enum diag_severity sev)
{
	return sev == DIAG_NOTE ? "note" : "error";
}

enum diag_severity
diag_kind_severity(enum diag_kind kind)
{
	return diag_kinds[kind].sev;
}
