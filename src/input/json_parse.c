/* json_parse.c — the one-pass JSON parser (see json_parse.h).
 *
 * A recursive descent over the bytes.  Nodes come from blocks that double
 * in size; keys and strings are unescaped into one buffer as long as the
 * text (a string never unescapes to more bytes than it takes quoted, NUL
 * included).  Lines and columns are kept as the text is read: the line
 * and the offset where it starts, and a count of UTF-8 continuation bytes
 * (which take no column), so a value's column is a subtraction.
 */
#include "input/json_parse.h"

#include <limits.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "util/text.h"
#include "util/xalloc.h"

/* A block of nodes. */
struct json_block {
	struct json_block *next;     /* the previous (smaller) block */
	size_t used, cap;
	struct json_node node[];
};

struct json_doc {
	struct json_block *blocks;   /* newest first */
	char *strings;               /* every key and string, NUL after each */
	size_t strings_used;
	const cJSON *root;
	size_t end;                  /* offset just past the root value */
	struct json_problem *problems;
	size_t n_problems, cap_problems;
};

struct parser {
	const unsigned char *b;      /* the text */
	size_t len;                  /* its length */
	size_t pos;                  /* next byte to read */
	int line;                    /* line of b[pos] */
	size_t line_start;           /* offset where that line starts */
	size_t cont;                 /* continuation bytes before pos */
	size_t cont_line;            /* continuation bytes before line_start */
	int depth;                   /* open arrays and objects */
	size_t first_block;          /* nodes in the first block */
	bool failed;                 /* malformed text met: stop */
	size_t err;                  /* where */
	struct json_doc *d;
};

/* What a byte means inside a string. */
enum { C_PLAIN, C_QUOTE, C_ESCAPE, C_CONTROL, C_CONT };

static int
string_class(unsigned char c)
{
	if (c == '"')
		return C_QUOTE;
	if (c == '\\')
		return C_ESCAPE;
	if (c < 0x20)
		return C_CONTROL;
	return (c & 0xc0) == 0x80 ? C_CONT : C_PLAIN;
}

/* Where the run of printable ASCII but '"' and '\\' that starts at b[i]
 * ends (at most at len): such bytes need no look, only a copy.  Eight
 * bytes at a time while none of them is special (the usual bit tricks:
 * x - 0x20 in each byte borrows from a byte below 0x20; a byte equal to
 * c is zero in x ^ c). */
static size_t
plain_run(const unsigned char *b, size_t i, size_t len)
{
	const uint64_t ones = 0x0101010101010101u, highs = 0x8080808080808080u;
	while (len - i >= 8) {
		uint64_t x, q, bs;
		memcpy(&x, b + i, 8);
		q = x ^ (ones * '"');
		bs = x ^ (ones * '\\');
		uint64_t special = (x & highs) | ((x - ones * 0x20) & ~x & highs) |
		                   ((q - ones) & ~q & highs) | ((bs - ones) & ~bs & highs);
		if (special != 0)
			break;
		i += 8;
	}
	while (i < len && b[i] >= 0x20 && b[i] < 0x80 && b[i] != '"' && b[i] != '\\')
		i++;
	return i;
}

/* A byte of a number: what C's strtod() reads of a decimal number. */
static bool
number_char(unsigned char c)
{
	return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
}

/* ---- position and failure ------------------------------------------------ */

/* Column of offset off, which must not lie before a continuation byte not
 * yet counted (so: the next byte to read, or one being read). */
static int
col_of(const struct parser *p, size_t off)
{
	return (int)(off - p->line_start - (p->cont - p->cont_line)) + 1;
}

/* The byte at off (read) was a newline. */
static void
newline_at(struct parser *p, size_t off)
{
	p->line++;
	p->line_start = off + 1;
	p->cont_line = p->cont;
}

static void
fail(struct parser *p, size_t off)
{
	if (!p->failed) {
		p->failed = true;
		p->err = off;
	}
}

static void
skip_ws(struct parser *p)
{
	const unsigned char *b = p->b;
	size_t i = p->pos;
	while (i < p->len) {
		unsigned char c = b[i];
		if (c == '\n')
			newline_at(p, i);
		else if (c != ' ' && c != '\t' && c != '\r')
			break;
		i++;
	}
	p->pos = i;
}

static bool
at(const struct parser *p, char c)
{
	return p->pos < p->len && p->b[p->pos] == (unsigned char)c;
}

/* ---- nodes and problems --------------------------------------------------- */

static struct json_node *
new_node(struct parser *p)
{
	struct json_doc *d = p->d;
	struct json_block *bl = d->blocks;
	if (bl == NULL || bl->used == bl->cap) {
		size_t cap = bl != NULL ? 2 * bl->cap : p->first_block;
		struct json_block *nb = xmalloc(sizeof *nb + cap * sizeof nb->node[0]);
		nb->next = bl;
		nb->used = 0;
		nb->cap = cap;
		d->blocks = bl = nb;
	}
	struct json_node *n = &bl->node[bl->used++];
	memset(n, 0, sizeof *n);
	return n;
}

static void
problem(struct parser *p, enum json_problem_kind kind, const struct json_node *n,
        int line, int col, unsigned char byte)
{
	struct json_doc *d = p->d;
	if (d->n_problems == d->cap_problems) {
		d->cap_problems = d->cap_problems ? 2 * d->cap_problems : 8;
		d->problems = xrealloc(d->problems, d->cap_problems * sizeof *d->problems);
	}
	d->problems[d->n_problems++] = (struct json_problem){ kind, n, line, col, byte };
}

/* ---- strings ---------------------------------------------------------------- */

/* The code unit of "\uXXXX" at b[i] (the backslash), or -1. */
static long
utf16_unit(const struct parser *p, size_t i)
{
	if (p->len - i < 6 || p->b[i] != '\\' || p->b[i + 1] != 'u')
		return -1;
	long u = 0;
	for (size_t k = 2; k < 6; k++) {
		int h = text_hex_digit(p->b[i + k]);
		if (h < 0)
			return -1;
		u = u * 16 + h;
	}
	return u;
}

/* Writes code point cp as UTF-8 at o; returns the bytes written. */
static size_t
put_utf8(char *o, unsigned long cp)
{
	if (cp < 0x80) {
		o[0] = (char)cp;
		return 1;
	}
	if (cp < 0x800) {
		o[0] = (char)(0xc0 | (cp >> 6));
		o[1] = (char)(0x80 | (cp & 0x3f));
		return 2;
	}
	if (cp < 0x10000) {
		o[0] = (char)(0xe0 | (cp >> 12));
		o[1] = (char)(0x80 | ((cp >> 6) & 0x3f));
		o[2] = (char)(0x80 | (cp & 0x3f));
		return 3;
	}
	o[0] = (char)(0xf0 | (cp >> 18));
	o[1] = (char)(0x80 | ((cp >> 12) & 0x3f));
	o[2] = (char)(0x80 | ((cp >> 6) & 0x3f));
	o[3] = (char)(0x80 | (cp & 0x3f));
	return 4;
}

/* The escape at b[i] (the backslash) unescaped at o: returns the bytes of
 * text it took (0 when malformed) and adds to *o_len what it wrote. */
static size_t
unescape(const struct parser *p, size_t i, char *o, size_t *o_len, bool *nul)
{
	static const char simple_from[] = "\"\\/bfnrt", simple_to[] = "\"\\/\b\f\n\r\t";
	if (i + 1 >= p->len)
		return 0;
	const char *s = p->b[i + 1] != '\0' ? strchr(simple_from, p->b[i + 1]) : NULL;
	if (s != NULL) {
		o[0] = simple_to[s - simple_from];
		*o_len += 1;
		return 2;
	}
	long hi = utf16_unit(p, i);
	if (hi < 0 || (hi >= 0xdc00 && hi <= 0xdfff))
		return 0;   /* not \uXXXX, or a lone low surrogate */
	unsigned long cp = (unsigned long)hi;
	size_t took = 6;
	if (hi >= 0xd800 && hi <= 0xdbff) {
		long lo = utf16_unit(p, i + 6);
		if (lo < 0xdc00 || lo > 0xdfff)
			return 0;   /* a high surrogate needs its low half */
		cp = 0x10000 + (((unsigned long)hi - 0xd800) << 10) + ((unsigned long)lo - 0xdc00);
		took = 12;
	}
	*nul = *nul || cp == 0;
	*o_len += put_utf8(o, cp);
	return took;
}

/* Reads the string whose opening quote is at p->pos into the string
 * buffer and returns it (NULL after failing).  *flags gains nul_flag when
 * it spells \u0000, and JSON_PARSE_BAD when it holds a raw control
 * character (the first is a problem of node n). */
static char *
parse_string(struct parser *p, const struct json_node *n, unsigned nul_flag,
             unsigned *flags)
{
	const unsigned char *b = p->b;
	size_t start = p->pos, i = start + 1;
	char *out = p->d->strings + p->d->strings_used;
	size_t o = 0;
	bool nul = false;
	for (;;) {
		size_t run = plain_run(b, i, p->len);
		memcpy(out + o, b + i, run - i);
		o += run - i;
		i = run;
		if (i >= p->len) {
			fail(p, start);   /* unterminated */
			return NULL;
		}
		unsigned char c = b[i];
		switch (string_class(c)) {
		case C_QUOTE:
			out[o++] = '\0';
			p->d->strings_used += o;
			p->pos = i + 1;
			if (nul)
				*flags |= nul_flag;
			return out;
		case C_ESCAPE: {
			size_t took = unescape(p, i, out + o, &o, &nul);
			if (took == 0) {
				fail(p, i);
				return NULL;
			}
			i += took;
			continue;
		}
		case C_CONTROL:
			if (!(*flags & JSON_PARSE_BAD)) {
				problem(p, JSON_PROBLEM_CONTROL, n, p->line, col_of(p, i), c);
				*flags |= JSON_PARSE_BAD;
			}
			if (c == '\n')
				newline_at(p, i);
			break;
		case C_CONT:
			p->cont++;
			break;
		default:
			break;
		}
		out[o++] = (char)c;
		i++;
	}
}

/* ---- numbers ---------------------------------------------------------------- */

/* Powers of ten a double holds exactly. */
static const double exact_pow10[] = {
	1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
	1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
};
#define EXACT_POW10_MAX 22
#define FAST_DIGITS 15   /* below 2^53: the mantissa is exact */

/* A number as JSON spells it: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
 * over all of s[0..n).  When it is one, *x is its value if the fast path
 * below gives it exactly, and *fast says so. */
static bool
json_number(const unsigned char *s, size_t n, double *x, bool *fast)
{
	size_t i = 0;
	bool neg = false;
	uint64_t m = 0;
	int sig = 0, scale = 0;    /* significant digits in m; 10^scale applies */
	long ex = 0;
#define DIGIT(k) ((k) < n && s[k] >= '0' && s[k] <= '9')
	if (i < n && s[i] == '-') {
		neg = true;
		i++;
	}
	if (!DIGIT(i))
		return false;
	if (s[i] == '0') {
		i++;
	} else {
		for (; DIGIT(i); i++)
			if (sig < 19) {
				m = m * 10 + (uint64_t)(s[i] - '0');
				sig += sig > 0 || s[i] != '0';
			} else {
				scale++, sig++;
			}
	}
	if (i < n && s[i] == '.') {
		i++;
		if (!DIGIT(i))
			return false;
		for (; DIGIT(i); i++)
			if (sig < 19) {
				m = m * 10 + (uint64_t)(s[i] - '0');
				sig += sig > 0 || s[i] != '0';
				scale--;
			} else {
				sig++;
			}
	}
	if (i < n && (s[i] == 'e' || s[i] == 'E')) {
		i++;
		bool eneg = i < n && s[i] == '-';
		if (i < n && (s[i] == '+' || s[i] == '-'))
			i++;
		if (!DIGIT(i))
			return false;
		for (; DIGIT(i); i++)
			if (ex < 100000)
				ex = ex * 10 + (s[i] - '0');
		if (eneg)
			ex = -ex;
	}
#undef DIGIT
	if (i != n)
		return false;
	/* Clinger's fast path: with the mantissa and the power of ten both
	 * exact doubles, one multiplication or division rounds correctly. */
	long e10 = scale + ex;
	*fast = m == 0 || (sig <= FAST_DIGITS && e10 >= -EXACT_POW10_MAX &&
	                   e10 <= EXACT_POW10_MAX);
	if (*fast) {
		double v = (double)m;
		if (m != 0)
			v = e10 < 0 ? v / exact_pow10[-e10] : v * exact_pow10[e10];
		*x = neg ? -v : v;
	}
	return true;
}

/* strtod() of s[0..n) (which holds no NUL), through a NUL-terminated copy;
 * *used receives the bytes it read. */
static double
strtod_span(const unsigned char *s, size_t n, size_t *used)
{
	char small[64];
	char *buf = n < sizeof small ? small : xmalloc(n + 1);
	memcpy(buf, s, n);
	buf[n] = '\0';
	char *end;
	double x = strtod(buf, &end);
	*used = (size_t)(end - buf);
	if (buf != small)
		free(buf);
	return x;
}

static void
parse_number(struct parser *p, struct json_node *node)
{
	const unsigned char *s = p->b + p->pos;
	size_t n = 0;
	while (p->pos + n < p->len && number_char(s[n]))
		n++;
	double x = 0;
	bool fast = false;
	size_t used = n;
	if (json_number(s, n, &x, &fast)) {
		if (!fast)
			x = strtod_span(s, n, &used);
	} else {
		/* Not JSON: as much as strtod() reads of it, a problem to report. */
		x = strtod_span(s, n, &used);
		if (used == 0) {
			fail(p, p->pos);
			return;
		}
		double y;
		if (!json_number(s, used, &y, &fast)) {
			problem(p, JSON_PROBLEM_NUMBER, node, p->line, col_of(p, p->pos), 0);
			node->flags |= JSON_PARSE_BAD;
		}
	}
	node->item.type = cJSON_Number;
	node->item.valuedouble = x;
	/* cJSON's own rule for valueint: saturated. */
	if (x >= INT_MAX)
		node->item.valueint = INT_MAX;
	else if (x <= (double)INT_MIN)
		node->item.valueint = INT_MIN;
	else
		node->item.valueint = (int)x;
	p->pos += used;
}

/* ---- values ----------------------------------------------------------------- */

static void parse_value(struct parser *p, struct json_node *n);

/* Appends child c to parent n (whose last child is *last). */
static void
link_child(struct json_node *n, cJSON **last, struct json_node *c)
{
	if (*last == NULL)
		n->item.child = &c->item;
	else
		(*last)->next = &c->item;
	c->item.prev = *last;
	*last = &c->item;
}

/* After a member or element: true when a comma says another follows,
 * false at the closing bracket (consumed) or after failing. */
static bool
next_in(struct parser *p, char close)
{
	skip_ws(p);
	if (at(p, ',')) {
		p->pos++;
		skip_ws(p);
		return true;
	}
	if (at(p, close))
		p->pos++;
	else
		fail(p, p->pos);
	return false;
}

static void
parse_object(struct parser *p, struct json_node *n)
{
	cJSON *last = NULL;
	n->item.type = cJSON_Object;
	p->pos++;   /* '{' */
	skip_ws(p);
	if (at(p, '}')) {
		p->pos++;
		return;
	}
	do {
		if (!at(p, '"')) {
			fail(p, p->pos);
			return;
		}
		struct json_node *m = new_node(p);
		m->key_line = p->line;
		m->key_col = col_of(p, p->pos);
		unsigned kf = 0;
		m->item.string = parse_string(p, m, JSON_PARSE_KEY_NUL, &kf);
		if (m->item.string == NULL)
			return;
		m->flags = (unsigned char)kf;
		skip_ws(p);
		if (!at(p, ':')) {
			fail(p, p->pos);
			return;
		}
		p->pos++;
		skip_ws(p);
		link_child(n, &last, m);
		parse_value(p, m);
	} while (!p->failed && next_in(p, '}'));
	if (n->item.child != NULL)
		n->item.child->prev = last;   /* cJSON keeps the last child there */
}

static void
parse_array(struct parser *p, struct json_node *n)
{
	cJSON *last = NULL;
	n->item.type = cJSON_Array;
	p->pos++;   /* '[' */
	skip_ws(p);
	if (at(p, ']')) {
		p->pos++;
		return;
	}
	do {
		struct json_node *e = new_node(p);
		link_child(n, &last, e);
		parse_value(p, e);
	} while (!p->failed && next_in(p, ']'));
	if (n->item.child != NULL)
		n->item.child->prev = last;
}

/* The literal word at p->pos, if it is one. */
static bool
literal(struct parser *p, const char *word)
{
	size_t k = strlen(word);
	if (p->len - p->pos < k || memcmp(p->b + p->pos, word, k) != 0)
		return false;
	p->pos += k;
	return true;
}

static void
parse_value(struct parser *p, struct json_node *n)
{
	n->val_line = p->line;
	n->val_col = col_of(p, p->pos);
	n->val_off = (uint32_t)p->pos;
	if (p->pos >= p->len) {
		fail(p, p->pos);
		return;
	}
	unsigned char c = p->b[p->pos];
	unsigned flags = 0;
	if (c == '{' || c == '[') {
		if (++p->depth > JSON_PARSE_MAX_DEPTH) {
			fail(p, p->pos);
			return;
		}
		if (c == '{')
			parse_object(p, n);
		else
			parse_array(p, n);
		p->depth--;
	} else if (c == '"') {
		n->item.type = cJSON_String;
		n->item.valuestring = parse_string(p, n, JSON_PARSE_VAL_NUL, &flags);
	} else if (c == '-' || (c >= '0' && c <= '9')) {
		parse_number(p, n);
	} else if (literal(p, "true")) {
		n->item.type = cJSON_True;
		n->item.valueint = 1;
	} else if (literal(p, "false")) {
		n->item.type = cJSON_False;
	} else if (literal(p, "null")) {
		n->item.type = cJSON_NULL;
	} else {
		fail(p, p->pos);
	}
	n->val_end = (uint32_t)p->pos;
	n->flags |= (unsigned char)flags;
}

/* ---- the document ----------------------------------------------------------- */

struct json_doc *
json_parse(const char *text, size_t len, size_t *err_off)
{
	*err_off = 0;
	if (len >= UINT32_MAX)
		return NULL;   /* offsets are 32-bit */
	struct json_doc *d = xcalloc(1, sizeof *d);
	d->strings = xmalloc(len + 1);
	size_t bom = text_bom(text, len);
	struct parser p = {
		.b = (const unsigned char *)text, .len = len, .pos = bom, .line = 1,
		.line_start = bom, .first_block = len / 32 + 16, .d = d,
	};
	skip_ws(&p);
	struct json_node *root = new_node(&p);
	parse_value(&p, root);
	if (p.failed) {
		*err_off = p.err < len ? p.err : len;
		json_doc_free(d);
		return NULL;
	}
	d->root = &root->item;
	d->end = p.pos;
	return d;
}

void
json_doc_free(struct json_doc *d)
{
	if (d == NULL)
		return;
	for (struct json_block *bl = d->blocks, *next; bl != NULL; bl = next) {
		next = bl->next;
		free(bl);
	}
	free(d->strings);
	free(d->problems);
	free(d);
}

const cJSON *
json_doc_root(const struct json_doc *d)
{
	return d->root;
}

size_t
json_doc_end(const struct json_doc *d)
{
	return d->end;
}

size_t
json_doc_n_problems(const struct json_doc *d)
{
	return d->n_problems;
}

const struct json_problem *
json_doc_problem_at(const struct json_doc *d, size_t i)
{
	return i < d->n_problems ? &d->problems[i] : NULL;
}
