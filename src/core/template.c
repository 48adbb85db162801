/* template.c — load and validate dossier templates (see template.h). */
#include "core/template.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "util/file.h"
#include "util/strbuf.h"
#include "util/xalloc.h"

#define DEJAVU_DIR "/usr/share/fonts/truetype/dejavu"

/* JSON ids and default titles, indexed by enum template_section_id. */
static const char *const section_names[TEMPLATE_SEC_MAX] = {
	"cover", "summary", "rationale", "mass", "mission", "thermal", "structure",
	"propulsion", "convergence", "endurance", "bom", "checks", "appendix",
	"sensitivity",
};
static const char *const section_titles[TEMPLATE_SEC_MAX] = {
	"Cover", "Executive summary", "Design rationale", "Mass budget",
	"Mission and energy", "Thermal and electrical traces",
	"Structure and resonance", "Propulsion selection", "Convergence",
	"Endurance explorer", "Bill of materials", "Checks", "Appendix",
	"Sensitivity",
};

/* State of one load: where errors go and how many there were. */
struct tload {
	const char *file;  /* template path, for messages */
	char dir[TEMPLATE_PATH_MAX]; /* its directory with trailing '/', or "" */
	FILE *err;         /* may be NULL */
	int n_error;       /* errors reported so far */
};

static void
tl_error(struct tload *tl, const char *path, const char *fmt, ...)
{
	tl->n_error++;
	if (tl->err == NULL)
		return;
	va_list ap;
	fprintf(tl->err, "%s: error: %s: ", tl->file, path);
	va_start(ap, fmt);
	vfprintf(tl->err, fmt, ap);
	va_end(ap);
	fputc('\n', tl->err);
}

static void
set_colour(struct template_colour *c, unsigned rgb)
{
	c->r = ((rgb >> 16) & 0xff) / 255.0;
	c->g = ((rgb >> 8) & 0xff) / 255.0;
	c->b = (rgb & 0xff) / 255.0;
}

static void
fill_default(struct template *t)
{
	/* A sober engineering palette: dark navy headings, a teal accent, the
	 * usual traffic-light semantics, and a colour-blind-safe series palette
	 * (Okabe-Ito ordering, darkened a little for print). */
	static const unsigned series[] = { 0x0072b2, 0xd55e00, 0x009e73, 0xcc79a7,
	                                   0xe69f00, 0x56b4e9, 0x7f7f7f, 0x000000 };
	memset(t, 0, sizeof *t);
	str_copy(t->name, sizeof t->name, "A4 default");
	t->page_width_mm = 210.0;
	t->page_height_mm = 297.0;
	t->margin_top_mm = 22.0;
	t->margin_bottom_mm = 20.0;
	t->margin_left_mm = 20.0;
	t->margin_right_mm = 20.0;
	/* DejaVu as shipped in templates/fonts/: cut to the characters a
	 * dossier can print (`make fonts`), which libharu reads for every
	 * document in a tenth of the time of the whole font; the system's
	 * full DejaVu when the program runs without its templates. */
	char dir[TEMPLATE_PATH_MAX - 32];
	const char *fonts = DEJAVU_DIR, *sub = "";
	if (file_shipped_dir("templates", "fonts/DejaVuSans.ttf", dir, sizeof dir) == 0) {
		fonts = dir;
		sub = "/fonts";
	}
	snprintf(t->font_regular, sizeof t->font_regular, "%s%s/DejaVuSans.ttf", fonts, sub);
	snprintf(t->font_bold, sizeof t->font_bold, "%s%s/DejaVuSans-Bold.ttf", fonts, sub);
	snprintf(t->font_mono, sizeof t->font_mono, "%s%s/DejaVuSansMono.ttf", fonts, sub);
	t->font_size_pt = 9.5;
	set_colour(&t->text, 0x1a1a1a);
	set_colour(&t->primary, 0x1f3a5f);
	set_colour(&t->accent, 0x00798c);
	set_colour(&t->muted, 0x6b6b6b);
	set_colour(&t->grid, 0xd9d9d9);
	set_colour(&t->pass, 0x1b7f3b);
	set_colour(&t->fail, 0xc0392b);
	set_colour(&t->warn, 0xb9770e);
	for (int i = 0; i < TEMPLATE_MAX_SERIES; i++)
		set_colour(&t->series[i], series[i]);
	t->n_series = TEMPLATE_MAX_SERIES;
	for (int i = 0; i < TEMPLATE_SEC_MAX; i++) {
		t->sections[i].id = (enum template_section_id)i;
		str_copy(t->sections[i].title, sizeof t->sections[i].title, section_titles[i]);
		t->sections[i].enabled = i != TEMPLATE_SEC_SENSITIVITY;
	}
	t->n_sections = TEMPLATE_SEC_MAX;
}

struct template *
template_default(void)
{
	struct template *t = xmalloc(sizeof *t);
	fill_default(t);
	return t;
}

void
template_free(struct template *t)
{
	free(t);
}

const char *
template_section_name(enum template_section_id id)
{
	if ((int)id < 0 || id >= TEMPLATE_SEC_MAX)
		return NULL;
	return section_names[id];
}

const struct template_section *
template_section_get(const struct template *t, enum template_section_id id)
{
	for (int i = 0; i < t->n_sections; i++)
		if (t->sections[i].id == id)
			return &t->sections[i];
	return NULL;
}

int
template_section_enabled(const struct template *t, enum template_section_id id)
{
	const struct template_section *s = template_section_get(t, id);
	return s != NULL && s->enabled;
}

static int
hexval(char c)
{
	if (c >= '0' && c <= '9')
		return c - '0';
	if (c >= 'a' && c <= 'f')
		return c - 'a' + 10;
	if (c >= 'A' && c <= 'F')
		return c - 'A' + 10;
	return -1;
}

int
template_parse_colour(const char *s, struct template_colour *out)
{
	unsigned rgb = 0;
	if (s == NULL || s[0] != '#' || strlen(s) != 7)
		return -1;
	for (int i = 1; i < 7; i++) {
		int v = hexval(s[i]);
		if (v < 0)
			return -1;
		rgb = rgb * 16u + (unsigned)v;
	}
	set_colour(out, rgb);
	return 0;
}

/* ---- file reading and JSON helpers ------------------------------------ */

/* Reads a whole file into a NUL-terminated buffer; NULL if unreadable. */
static char *
read_file(const char *path, size_t *n_out)
{
	FILE *f = fopen(path, "rb");
	if (f == NULL)
		return NULL;
	size_t cap = 4096, n = 0;
	char *buf = xmalloc(cap);
	for (;;) {
		if (n + 1 >= cap)
			buf = xrealloc(buf, cap *= 2);
		size_t got = fread(buf + n, 1, cap - n - 1, f);
		if (got == 0)
			break;
		n += got;
	}
	int bad = ferror(f);
	fclose(f);
	if (bad) {
		free(buf);
		return NULL;
	}
	buf[n] = '\0';
	*n_out = n;
	return buf;
}

/* Checks that every key of obj is one of the NULL-terminated names. */
static void
check_keys(struct tload *tl, const cJSON *obj, const char *path,
           const char *const *names)
{
	for (const cJSON *it = obj->child; it != NULL; it = it->next) {
		int known = 0;
		for (int i = 0; names[i] != NULL; i++)
			if (strcmp(it->string, names[i]) == 0)
				known = 1;
		if (!known) {
			if (path[0] != '\0')
				tl_error(tl, path, "unknown key \"%s\"", it->string);
			else
				tl_error(tl, it->string, "unknown key");
		}
	}
}

static void
join_path(char *dst, size_t cap, const char *parent, const char *key)
{
	if (parent[0] == '\0')
		snprintf(dst, cap, "%s", key);
	else
		snprintf(dst, cap, "%s.%s", parent, key);
}

/* Reads an optional number in [lo, hi] into *out. */
static void
get_number(struct tload *tl, const cJSON *obj, const char *parent, const char *key,
           double lo, double hi, double *out)
{
	char path[128];
	const cJSON *it = cJSON_GetObjectItemCaseSensitive(obj, key);
	if (it == NULL)
		return;
	join_path(path, sizeof path, parent, key);
	if (!cJSON_IsNumber(it) || !isfinite(it->valuedouble)) {
		tl_error(tl, path, "must be a number");
		return;
	}
	if (it->valuedouble < lo || it->valuedouble > hi) {
		tl_error(tl, path, "must be in [%g, %g] (got %g)", lo, hi, it->valuedouble);
		return;
	}
	*out = it->valuedouble;
}

static void
get_colour(struct tload *tl, const cJSON *obj, const char *key, struct template_colour *out)
{
	char path[128];
	const cJSON *it = cJSON_GetObjectItemCaseSensitive(obj, key);
	if (it == NULL)
		return;
	join_path(path, sizeof path, "colours", key);
	if (!cJSON_IsString(it) || template_parse_colour(it->valuestring, out) != 0)
		tl_error(tl, path, "must be a colour \"#rrggbb\"");
}

/* Resolves a path from the template against its directory and checks that
 * the file is readable. */
static void
get_file(struct tload *tl, const cJSON *it, const char *path, char *out, size_t cap)
{
	if (!cJSON_IsString(it) || it->valuestring[0] == '\0') {
		tl_error(tl, path, "must be a non-empty file path");
		return;
	}
	char full[TEMPLATE_PATH_MAX];
	int w;
	if (it->valuestring[0] == '/')
		w = snprintf(full, sizeof full, "%s", it->valuestring);
	else
		w = snprintf(full, sizeof full, "%s%s", tl->dir, it->valuestring);
	if (w < 0 || (size_t)w >= sizeof full || (size_t)w >= cap) {
		tl_error(tl, path, "path too long");
		return;
	}
	if (access(full, R_OK) != 0) {
		tl_error(tl, path, "file \"%s\" not found or not readable", full);
		return;
	}
	str_copy(out, cap, full);
}

/* ---- the sections of a template file ---------------------------------- */

static void
load_page(struct tload *tl, const cJSON *it, struct template *t)
{
	static const char *const keys[] = { "width_mm", "height_mm", NULL };
	if (cJSON_IsString(it)) {
		if (strcmp(it->valuestring, "A4") == 0) {
			t->page_width_mm = 210.0;
			t->page_height_mm = 297.0;
		} else if (strcmp(it->valuestring, "Letter") == 0) {
			t->page_width_mm = 8.5 * 25.4;
			t->page_height_mm = 11.0 * 25.4;
		} else {
			tl_error(tl, "page", "unknown page size \"%s\" (want \"A4\", \"Letter\" "
			         "or {\"width_mm\", \"height_mm\"})", it->valuestring);
		}
		return;
	}
	if (!cJSON_IsObject(it)) {
		tl_error(tl, "page", "must be \"A4\", \"Letter\" or an object");
		return;
	}
	check_keys(tl, it, "page", keys);
	if (cJSON_GetObjectItemCaseSensitive(it, "width_mm") == NULL ||
	    cJSON_GetObjectItemCaseSensitive(it, "height_mm") == NULL)
		tl_error(tl, "page", "needs both width_mm and height_mm");
	get_number(tl, it, "page", "width_mm", 100.0, 1000.0, &t->page_width_mm);
	get_number(tl, it, "page", "height_mm", 100.0, 1000.0, &t->page_height_mm);
}

static void
load_margins(struct tload *tl, const cJSON *it, struct template *t)
{
	static const char *const keys[] = { "top", "bottom", "left", "right", NULL };
	if (!cJSON_IsObject(it)) {
		tl_error(tl, "margins_mm", "must be an object");
		return;
	}
	check_keys(tl, it, "margins_mm", keys);
	get_number(tl, it, "margins_mm", "top", 12.0, 80.0, &t->margin_top_mm);
	get_number(tl, it, "margins_mm", "bottom", 12.0, 80.0, &t->margin_bottom_mm);
	get_number(tl, it, "margins_mm", "left", 5.0, 80.0, &t->margin_left_mm);
	get_number(tl, it, "margins_mm", "right", 5.0, 80.0, &t->margin_right_mm);
}

static void
load_fonts(struct tload *tl, const cJSON *it, struct template *t)
{
	static const char *const keys[] = { "regular", "bold", "mono", "size_pt", NULL };
	const cJSON *f;
	if (!cJSON_IsObject(it)) {
		tl_error(tl, "fonts", "must be an object");
		return;
	}
	check_keys(tl, it, "fonts", keys);
	if ((f = cJSON_GetObjectItemCaseSensitive(it, "regular")) != NULL)
		get_file(tl, f, "fonts.regular", t->font_regular, sizeof t->font_regular);
	if ((f = cJSON_GetObjectItemCaseSensitive(it, "bold")) != NULL)
		get_file(tl, f, "fonts.bold", t->font_bold, sizeof t->font_bold);
	if ((f = cJSON_GetObjectItemCaseSensitive(it, "mono")) != NULL)
		get_file(tl, f, "fonts.mono", t->font_mono, sizeof t->font_mono);
	get_number(tl, it, "fonts", "size_pt", 6.0, 16.0, &t->font_size_pt);
}

static void
load_colours(struct tload *tl, const cJSON *it, struct template *t)
{
	static const char *const keys[] = { "text", "primary", "accent", "muted", "grid",
	                                    "pass", "fail", "warn", "series", NULL };
	if (!cJSON_IsObject(it)) {
		tl_error(tl, "colours", "must be an object");
		return;
	}
	check_keys(tl, it, "colours", keys);
	get_colour(tl, it, "text", &t->text);
	get_colour(tl, it, "primary", &t->primary);
	get_colour(tl, it, "accent", &t->accent);
	get_colour(tl, it, "muted", &t->muted);
	get_colour(tl, it, "grid", &t->grid);
	get_colour(tl, it, "pass", &t->pass);
	get_colour(tl, it, "fail", &t->fail);
	get_colour(tl, it, "warn", &t->warn);
	const cJSON *s = cJSON_GetObjectItemCaseSensitive(it, "series");
	if (s == NULL)
		return;
	int n = cJSON_IsArray(s) ? cJSON_GetArraySize(s) : -1;
	if (n < 2 || n > TEMPLATE_MAX_SERIES) {
		tl_error(tl, "colours.series", "must be an array of 2 to %d colours",
		         TEMPLATE_MAX_SERIES);
		return;
	}
	int i = 0;
	for (const cJSON *c = s->child; c != NULL; c = c->next, i++) {
		if (!cJSON_IsString(c) || template_parse_colour(c->valuestring, &t->series[i]) != 0) {
			char path[64];
			snprintf(path, sizeof path, "colours.series[%d]", i);
			tl_error(tl, path, "must be a colour \"#rrggbb\"");
		}
	}
	t->n_series = n;
}

static int
section_id_of(const char *name)
{
	for (int i = 0; i < TEMPLATE_SEC_MAX; i++)
		if (strcmp(name, section_names[i]) == 0)
			return i;
	return -1;
}

static void
load_sections(struct tload *tl, const cJSON *it, struct template *t)
{
	static const char *const keys[] = { "id", "title", "enabled", NULL };
	int seen[TEMPLATE_SEC_MAX] = { 0 };
	if (!cJSON_IsArray(it)) {
		tl_error(tl, "sections", "must be an array of {\"id\", \"title\", \"enabled\"}");
		return;
	}
	t->n_sections = 0;
	int i = 0;
	for (const cJSON *s = it->child; s != NULL; s = s->next, i++) {
		char path[64];
		snprintf(path, sizeof path, "sections[%d]", i);
		if (!cJSON_IsObject(s)) {
			tl_error(tl, path, "must be an object");
			continue;
		}
		check_keys(tl, s, path, keys);
		const cJSON *id = cJSON_GetObjectItemCaseSensitive(s, "id");
		const cJSON *title = cJSON_GetObjectItemCaseSensitive(s, "title");
		const cJSON *en = cJSON_GetObjectItemCaseSensitive(s, "enabled");
		int k = -1;
		if (!cJSON_IsString(id)) {
			tl_error(tl, path, "needs a string \"id\"");
		} else if ((k = section_id_of(id->valuestring)) < 0) {
			tl_error(tl, path, "unknown section id \"%s\" (known: cover, summary, "
			         "rationale, mass, mission, thermal, structure, propulsion, "
			         "convergence, endurance, bom, checks, appendix, sensitivity)",
			         id->valuestring);
		} else if (seen[k]++) {
			tl_error(tl, path, "section \"%s\" listed twice", id->valuestring);
			k = -1;
		}
		if (title != NULL && (!cJSON_IsString(title) || title->valuestring[0] == '\0' ||
		                      strlen(title->valuestring) >= TEMPLATE_TITLE_MAX)) {
			tl_error(tl, path, "title must be a string of 1 to %d bytes",
			         TEMPLATE_TITLE_MAX - 1);
			k = -1;
		}
		if (en != NULL && !cJSON_IsBool(en)) {
			tl_error(tl, path, "enabled must be true or false");
			k = -1;
		}
		if (k < 0)
			continue;
		struct template_section *dst = &t->sections[t->n_sections++];
		dst->id = (enum template_section_id)k;
		str_copy(dst->title, sizeof dst->title,
		         title != NULL ? title->valuestring : section_titles[k]);
		dst->enabled = en != NULL ? cJSON_IsTrue(en) : 1;
	}
}

/* Prints a syntax error with line:col computed from the parse end. */
static void
syntax_error(struct tload *tl, const char *buf, const char *end)
{
	int line = 1, col = 1;
	for (const char *p = buf; p < end && *p != '\0'; p++) {
		if (*p == '\n') {
			line++;
			col = 1;
		} else if (((unsigned char)*p & 0xc0) != 0x80) {
			col++;
		}
	}
	tl->n_error++;
	if (tl->err != NULL)
		fprintf(tl->err, "%s:%d:%d: error: JSON syntax error near here\n", tl->file,
		        line, col);
}

struct template *
template_load(const char *path, FILE *err)
{
	static const char *const keys[] = { "name", "page", "margins_mm", "fonts",
	                                    "colours", "logo", "sections", NULL };
	struct tload tl = { .file = path, .err = err };
	const char *slash = strrchr(path, '/');
	if (slash != NULL && (size_t)(slash - path) + 2 < sizeof tl.dir)
		snprintf(tl.dir, sizeof tl.dir, "%.*s/", (int)(slash - path), path);

	size_t n = 0;
	char *buf = read_file(path, &n);
	if (buf == NULL) {
		if (err != NULL)
			fprintf(err, "%s: error: cannot read template file\n", path);
		return NULL;
	}
	const char *end = NULL;
	cJSON *root = cJSON_ParseWithLengthOpts(buf, n + 1, &end, 1);
	if (root == NULL) {
		syntax_error(&tl, buf, end != NULL ? end : buf + n);
		free(buf);
		return NULL;
	}
	struct template *t = template_default();
	if (!cJSON_IsObject(root)) {
		tl_error(&tl, "(root)", "a template must be a JSON object");
		goto done;
	}
	check_keys(&tl, root, "", keys);
	const cJSON *it;
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "name")) != NULL) {
		if (cJSON_IsString(it) && strlen(it->valuestring) < sizeof t->name)
			str_copy(t->name, sizeof t->name, it->valuestring);
		else
			tl_error(&tl, "name", "must be a string shorter than %zu bytes", sizeof t->name);
	}
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "page")) != NULL)
		load_page(&tl, it, t);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "margins_mm")) != NULL)
		load_margins(&tl, it, t);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "fonts")) != NULL)
		load_fonts(&tl, it, t);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "colours")) != NULL)
		load_colours(&tl, it, t);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "logo")) != NULL) {
		if (cJSON_IsNull(it))
			t->logo[0] = '\0';
		else
			get_file(&tl, it, "logo", t->logo, sizeof t->logo);
	}
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "sections")) != NULL)
		load_sections(&tl, it, t);
	/* The margins must leave a usable text block. */
	if (t->page_width_mm - t->margin_left_mm - t->margin_right_mm < 80.0 ||
	    t->page_height_mm - t->margin_top_mm - t->margin_bottom_mm < 100.0)
		tl_error(&tl, "margins_mm", "leave less than 80 x 100 mm for the text");
done:
	cJSON_Delete(root);
	free(buf);
	if (tl.n_error > 0) {
		template_free(t);
		return NULL;
	}
	return t;
}
