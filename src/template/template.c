/* template.c — the default dossier template and the section helpers (see
 * template.h); templates/NAME.json files are read by input/template_io.c. */
#include "template/template.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "util/file.h"
#include "util/strbuf.h"
#include "util/text.h"
#include "util/xalloc.h"

#define DEJAVU_DIR "/usr/share/fonts/truetype/dejavu"
#define SYSTEM_SRGB "/usr/share/color/icc/sRGB.icc"   /* icc-profiles-free */

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
	/* The sRGB profile of the PDF/A output intent: shipped in
	 * templates/icc/ (its licence beside it), else Debian's
	 * icc-profiles-free copy; none found leaves it "" and the document
	 * reports it when it is made. */
	if (file_shipped_dir("templates", "icc/sRGB.icc", dir, sizeof dir) == 0)
		snprintf(t->icc_profile, sizeof t->icc_profile, "%s/icc/sRGB.icc", dir);
	else if (access(SYSTEM_SRGB, R_OK) == 0)
		snprintf(t->icc_profile, sizeof t->icc_profile, "%s", SYSTEM_SRGB);
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

int
template_section_id(const char *name)
{
	for (int i = 0; i < TEMPLATE_SEC_MAX; i++)
		if (strcmp(name, section_names[i]) == 0)
			return i;
	return -1;
}

const char *
template_section_title(enum template_section_id id)
{
	if ((int)id < 0 || id >= TEMPLATE_SEC_MAX)
		return NULL;
	return section_titles[id];
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

int
template_parse_colour(const char *s, struct template_colour *out)
{
	unsigned rgb = 0;
	if (s == NULL || s[0] != '#' || strlen(s) != 7)
		return -1;
	for (int i = 1; i < 7; i++) {
		int v = text_hex_digit((unsigned char)s[i]);
		if (v < 0)
			return -1;
		rgb = rgb * 16u + (unsigned)v;
	}
	set_colour(out, rgb);
	return 0;
}

