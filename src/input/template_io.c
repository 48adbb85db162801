/* template_io.c — read and validate a dossier template (see template_io.h). */
#include "input/template_io.h"

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input/json_in.h"
#include "util/strbuf.h"
#include "util/text.h"

/* The smallest text block the margins may leave (mm). */
#define TEXT_MIN_W_MM 80.0
#define TEXT_MIN_H_MM 100.0

/* State of one load. */
struct tload {
	struct json_in *ji;          /* the template file */
	char dir[TEMPLATE_PATH_MAX]; /* its directory with trailing '/', or "" */
	template_io_check check;     /* judges fonts and the logo, or NULL */
};

/* An optional number in [lo, hi] (unit for the message) into *out. */
static void
get_number(struct tload *tl, const cJSON *obj, const char *parent, const char *key,
           double lo, double hi, const char *unit, double *out)
{
	char path[128], src[64];
	const cJSON *it = cJSON_GetObjectItemCaseSensitive(obj, key);
	if (it == NULL)
		return;
	json_in_path(path, sizeof path, parent, key);
	if (!json_in_expect(tl->ji, it, path, cJSON_Number, "a number") ||
	    !json_in_check_number(tl->ji, it, path))
		return;
	if (it->valuedouble < lo || it->valuedouble > hi) {
		json_in_source(tl->ji, it, src, sizeof src);
		json_in_report(tl->ji, DIAG_RANGE, it, JSON_IN_VALUE, path,
		               ": %s (allowed %g to %g %s)", src, lo, hi, unit);
		return;
	}
	*out = it->valuedouble;
}

/* A "#rrggbb" string at path into *out. */
static void
read_colour(struct tload *tl, const cJSON *it, const char *path, struct template_colour *out)
{
	char q[64];
	if (!json_in_expect(tl->ji, it, path, cJSON_String, "a colour \"#rrggbb\"") ||
	    !json_in_check_string(tl->ji, it, path, 64, JSON_IN_NO_CONTROL))
		return;
	if (template_parse_colour(it->valuestring, out) != 0) {
		diag_quote(it->valuestring, strlen(it->valuestring), 20, q, sizeof q);
		json_in_report(tl->ji, DIAG_BAD_ENUM, it, JSON_IN_VALUE, path,
		               " %s (a colour is \"#rrggbb\")", q);
	}
}

/* Resolves a font or logo path from the template against its directory,
 * reads the file (regular files only, capped) and hands the bytes to the
 * check; the resolved path goes to out when all is well. */
static void
get_file(struct tload *tl, const cJSON *it, const char *path,
         enum template_asset kind, char *out, size_t cap)
{
	char full[TEMPLATE_PATH_MAX], why[512];
	if (!json_in_expect(tl->ji, it, path, cJSON_String, "a file path") ||
	    !json_in_check_string(tl->ji, it, path, TEMPLATE_PATH_MAX - 1, JSON_IN_NO_CONTROL))
		return;
	const char *p = it->valuestring;
	if (p[0] == '\0') {
		json_in_report(tl->ji, DIAG_TYPE, it, JSON_IN_VALUE, path,
		               ": expected a file path, got \"\"");
		return;
	}
	int w = snprintf(full, sizeof full, "%s%s", p[0] == '/' ? "" : tl->dir, p);
	if (w < 0 || (size_t)w >= sizeof full || (size_t)w >= cap) {
		json_in_report(tl->ji, DIAG_TOO_LONG, it, JSON_IN_VALUE, path,
		               ": the resolved path has %d bytes (at most %zu)", w, cap - 1);
		return;
	}
	unsigned char *buf;
	size_t n;
	size_t max = kind == TEMPLATE_ASSET_FONT ? TEMPLATE_IO_FONT_MAX : TEMPLATE_IO_LOGO_MAX;
	if (json_in_read_named(tl->ji, it, path, full, max, &buf, &n) != 0)
		return;
	int rc = tl->check != NULL ? tl->check(kind, full, buf, n, why, sizeof why) : 0;
	free(buf);
	if (rc != 0) {
		json_in_report(tl->ji, kind == TEMPLATE_ASSET_FONT ? DIAG_BAD_FONT : DIAG_BAD_IMAGE,
		               it, JSON_IN_VALUE, path, ": %s: %s", full, why);
		return;
	}
	str_copy(out, cap, full);
}

/* ---- the sections of a template file ---------------------------------- */

static void
load_page(struct tload *tl, const cJSON *it, struct template *t)
{
	static const char *const keys[] = { "width_mm", "height_mm", NULL };
	char q[64];
	if (cJSON_IsString(it)) {
		if (strcmp(it->valuestring, "A4") == 0) {
			t->page_width_mm = 210.0;
			t->page_height_mm = 297.0;
		} else if (strcmp(it->valuestring, "Letter") == 0) {
			t->page_width_mm = 8.5 * 25.4;
			t->page_height_mm = 11.0 * 25.4;
		} else if (json_in_check_string(tl->ji, it, "page", 64, 0)) {
			diag_quote(it->valuestring, strlen(it->valuestring), 20, q, sizeof q);
			json_in_report(tl->ji, DIAG_BAD_ENUM, it, JSON_IN_VALUE, "page",
			               " %s (allowed: A4, Letter, or {\"width_mm\", \"height_mm\"})", q);
		}
		return;
	}
	if (!json_in_expect(tl->ji, it, "page", cJSON_Object,
	                    "\"A4\", \"Letter\" or an object"))
		return;
	json_in_check_keys(tl->ji, it, "page", keys, 0);
	for (int i = 0; keys[i] != NULL; i++)
		if (cJSON_GetObjectItemCaseSensitive(it, keys[i]) == NULL) {
			char path[64];
			json_in_path(path, sizeof path, "page", keys[i]);
			json_in_report(tl->ji, DIAG_MISSING, it, JSON_IN_VALUE, path,
			               " (a page object gives both width_mm and height_mm)");
		}
	get_number(tl, it, "page", "width_mm", 100.0, 1000.0, "mm", &t->page_width_mm);
	get_number(tl, it, "page", "height_mm", 100.0, 1000.0, "mm", &t->page_height_mm);
}

static void
load_margins(struct tload *tl, const cJSON *it, struct template *t)
{
	static const char *const keys[] = { "top", "bottom", "left", "right", NULL };
	if (!json_in_expect(tl->ji, it, "margins_mm", cJSON_Object, "an object"))
		return;
	json_in_check_keys(tl->ji, it, "margins_mm", keys, 0);
	get_number(tl, it, "margins_mm", "top", 12.0, 80.0, "mm", &t->margin_top_mm);
	get_number(tl, it, "margins_mm", "bottom", 12.0, 80.0, "mm", &t->margin_bottom_mm);
	get_number(tl, it, "margins_mm", "left", 5.0, 80.0, "mm", &t->margin_left_mm);
	get_number(tl, it, "margins_mm", "right", 5.0, 80.0, "mm", &t->margin_right_mm);
}

static void
load_fonts(struct tload *tl, const cJSON *it, struct template *t)
{
	static const char *const keys[] = { "regular", "bold", "mono", "size_pt", NULL };
	char *const dst[] = { t->font_regular, t->font_bold, t->font_mono };
	if (!json_in_expect(tl->ji, it, "fonts", cJSON_Object, "an object"))
		return;
	json_in_check_keys(tl->ji, it, "fonts", keys, 0);
	for (int i = 0; i < 3; i++) {
		const cJSON *f = cJSON_GetObjectItemCaseSensitive(it, keys[i]);
		char path[32];
		json_in_path(path, sizeof path, "fonts", keys[i]);
		if (f != NULL)
			get_file(tl, f, path, TEMPLATE_ASSET_FONT, dst[i], TEMPLATE_PATH_MAX);
	}
	get_number(tl, it, "fonts", "size_pt", 6.0, 16.0, "pt", &t->font_size_pt);
}

static void
load_colours(struct tload *tl, const cJSON *it, struct template *t)
{
	static const char *const keys[] = { "text", "primary", "accent", "muted", "grid",
	                                    "pass", "fail", "warn", "series", NULL };
	struct template_colour *const dst[] = { &t->text, &t->primary, &t->accent,
		&t->muted, &t->grid, &t->pass, &t->fail, &t->warn };
	char path[64];
	if (!json_in_expect(tl->ji, it, "colours", cJSON_Object, "an object"))
		return;
	json_in_check_keys(tl->ji, it, "colours", keys, 0);
	for (int i = 0; i < 8; i++) {
		const cJSON *c = cJSON_GetObjectItemCaseSensitive(it, keys[i]);
		json_in_path(path, sizeof path, "colours", keys[i]);
		if (c != NULL)
			read_colour(tl, c, path, dst[i]);
	}
	const cJSON *s = cJSON_GetObjectItemCaseSensitive(it, "series");
	if (s == NULL ||
	    !json_in_expect(tl->ji, s, "colours.series", cJSON_Array, "an array of colours"))
		return;
	int n = cJSON_GetArraySize(s);
	if (n < 2 || n > TEMPLATE_MAX_SERIES) {
		json_in_report(tl->ji, DIAG_RANGE, s, JSON_IN_VALUE, "colours.series",
		               ": %d colours (allowed 2 to %d)", n, TEMPLATE_MAX_SERIES);
		return;
	}
	int i = 0;
	for (const cJSON *c = s->child; c != NULL; c = c->next, i++) {
		json_in_path_index(path, sizeof path, "colours.series", (size_t)i);
		read_colour(tl, c, path, &t->series[i]);
	}
	t->n_series = n;
}

/* One entry of "sections"; false when it is left out. */
static bool
load_section(struct tload *tl, const cJSON *s, const char *path, int *first_at,
             struct template_section *dst)
{
	static const char *const keys[] = { "id", "title", "enabled", NULL };
	char sub[64], q[64], list[512];
	const char *names[TEMPLATE_SEC_MAX + 1];
	if (!json_in_expect(tl->ji, s, path, cJSON_Object, "an object"))
		return false;
	json_in_check_keys(tl->ji, s, path, keys, 0);
	const cJSON *id = cJSON_GetObjectItemCaseSensitive(s, "id");
	const cJSON *title = cJSON_GetObjectItemCaseSensitive(s, "title");
	const cJSON *en = cJSON_GetObjectItemCaseSensitive(s, "enabled");
	bool ok = true;
	int k = -1;
	json_in_path(sub, sizeof sub, path, "id");
	if (id == NULL) {
		json_in_report(tl->ji, DIAG_MISSING, s, JSON_IN_VALUE, sub, " (a section names its id)");
		ok = false;
	} else if (json_in_expect(tl->ji, id, sub, cJSON_String, "a section id") &&
	           json_in_check_string(tl->ji, id, sub, 64, JSON_IN_NO_CONTROL)) {
		k = template_section_id(id->valuestring);
		diag_quote(id->valuestring, strlen(id->valuestring), 20, q, sizeof q);
		if (k < 0) {
			for (int i = 0; i < TEMPLATE_SEC_MAX; i++)
				names[i] = template_section_name((enum template_section_id)i);
			names[TEMPLATE_SEC_MAX] = NULL;
			text_join(names, list, sizeof list);
			json_in_report(tl->ji, DIAG_BAD_ENUM, id, JSON_IN_VALUE, sub,
			               " %s (allowed: %s)", q, list);
		} else if (first_at[k] >= 0) {
			json_in_report(tl->ji, DIAG_DUPLICATE_ID, id, JSON_IN_VALUE, sub,
			               " %s (first given by sections[%d])", q, first_at[k]);
			k = -1;
		}
	}
	json_in_path(sub, sizeof sub, path, "title");
	if (title != NULL && (!json_in_expect(tl->ji, title, sub, cJSON_String, "a string") ||
	    !json_in_check_string(tl->ji, title, sub, TEMPLATE_TITLE_MAX - 1, JSON_IN_NO_CONTROL)))
		ok = false;
	else if (title != NULL && title->valuestring[0] == '\0') {
		json_in_report(tl->ji, DIAG_TYPE, title, JSON_IN_VALUE, sub,
		               ": expected a title, got \"\"");
		ok = false;
	}
	json_in_path(sub, sizeof sub, path, "enabled");
	if (en != NULL && !json_in_expect(tl->ji, en, sub, cJSON_True | cJSON_False, "true or false"))
		ok = false;
	if (!ok || k < 0)
		return false;
	dst->id = (enum template_section_id)k;
	str_copy(dst->title, sizeof dst->title,
	         title != NULL ? title->valuestring : template_section_title(dst->id));
	dst->enabled = en != NULL ? cJSON_IsTrue(en) : 1;
	return true;
}

static void
load_sections(struct tload *tl, const cJSON *it, struct template *t)
{
	int first_at[TEMPLATE_SEC_MAX];
	if (!json_in_expect(tl->ji, it, "sections", cJSON_Array, "an array of sections"))
		return;
	for (int k = 0; k < TEMPLATE_SEC_MAX; k++)
		first_at[k] = -1;
	t->n_sections = 0;
	int i = 0;
	for (const cJSON *s = it->child; s != NULL; s = s->next, i++) {
		char path[32];
		json_in_path_index(path, sizeof path, "sections", (size_t)i);
		if (t->n_sections == TEMPLATE_SEC_MAX) {
			json_in_report(tl->ji, DIAG_TOO_MANY, s, JSON_IN_VALUE, "sections",
			               " (%d sections at most)", TEMPLATE_SEC_MAX);
			return;
		}
		struct template_section *dst = &t->sections[t->n_sections];
		if (load_section(tl, s, path, first_at, dst)) {
			first_at[dst->id] = i;
			t->n_sections++;
		}
	}
}

struct template *
template_io_load(const char *path, template_io_check check, struct diag *dg)
{
	static const char *const keys[] = { "name", "page", "margins_mm", "fonts",
	                                    "colours", "logo", "sections", NULL };
	struct tload tl = { .check = check };
	int before = diag_n_errors(dg);
	const char *slash = strrchr(path, '/');
	if (slash != NULL && (size_t)(slash - path) + 2 < sizeof tl.dir)
		snprintf(tl.dir, sizeof tl.dir, "%.*s/", (int)(slash - path), path);

	tl.ji = json_in_load(path, JSON_IN_TEMPLATE_MAX, dg);
	if (tl.ji == NULL)
		return NULL;
	struct template *t = template_default();
	const cJSON *root = json_in_root(tl.ji), *it;
	json_in_check_keys(tl.ji, root, "", keys, 0);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "name")) != NULL &&
	    json_in_expect(tl.ji, it, "name", cJSON_String, "a string") &&
	    json_in_check_string(tl.ji, it, "name", sizeof t->name - 1, JSON_IN_NO_CONTROL))
		str_copy(t->name, sizeof t->name, it->valuestring);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "page")) != NULL)
		load_page(&tl, it, t);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "margins_mm")) != NULL)
		load_margins(&tl, it, t);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "fonts")) != NULL)
		load_fonts(&tl, it, t);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "colours")) != NULL)
		load_colours(&tl, it, t);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "logo")) != NULL && !cJSON_IsNull(it))
		get_file(&tl, it, "logo", TEMPLATE_ASSET_LOGO, t->logo, sizeof t->logo);
	if ((it = cJSON_GetObjectItemCaseSensitive(root, "sections")) != NULL)
		load_sections(&tl, it, t);
	/* The margins must leave a usable text block. */
	double w = t->page_width_mm - t->margin_left_mm - t->margin_right_mm;
	double h = t->page_height_mm - t->margin_top_mm - t->margin_bottom_mm;
	if (w < TEXT_MIN_W_MM || h < TEXT_MIN_H_MM) {
		it = cJSON_GetObjectItemCaseSensitive(root, "margins_mm");
		json_in_report(tl.ji, DIAG_INCONSISTENT, it != NULL ? it : root, JSON_IN_VALUE,
		               "margins_mm", ": they leave %g x %g mm for the text (at least "
		               "%g x %g)", w, h, TEXT_MIN_W_MM, TEXT_MIN_H_MM);
	}
	json_in_free(tl.ji);
	if (diag_n_errors(dg) > before) {
		template_free(t);
		return NULL;
	}
	return t;
}
