/* template.h — the dossier template: page, margins, fonts, colours, sections.
 *
 * A template is a plain value struct loaded from templates/NAME.json by
 * input/template_io.c (or built by template_default()).  It says how the
 * dossier looks and which sections it contains, never what it says.
 *
 * Template JSON (every key optional; what is absent keeps the A4 default):
 *   {
 *     "name":     "A4 default",
 *     "page":     "A4" | "Letter" | {"width_mm": 210, "height_mm": 297},
 *     "margins_mm": {"top": 22, "bottom": 20, "left": 20, "right": 20},
 *     "fonts":    {"regular": PATH, "bold": PATH, "mono": PATH, "size_pt": 9.5},
 *     "colours":  {"text": "#rrggbb", "primary", "accent", "muted", "grid",
 *                  "pass", "fail", "warn": "#rrggbb",
 *                  "series": ["#rrggbb", ...]   (2..8 entries)},
 *     "logo":     PATH to a PNG (relative to the template file), or null,
 *     "sections": [{"id": "cover", "title": "Cover", "enabled": true}, ...]
 *   }
 * Relative font and logo paths are resolved against the template file's
 * directory.  A font not given is the DejaVu face shipped in
 * templates/fonts/ (cut to the characters a dossier prints: `make fonts`),
 * else the system's DejaVu.  "sections" replaces the whole list: its order is the dossier's
 * order, an id missing from it is disabled, a repeated id is an error.
 * Every template takes the sRGB profile shipped in templates/icc/ (else
 * the system's icc-profiles-free copy) as its documents' PDF/A output
 * intent (pdf/doc.h).
 *
 * Who may include it: the input layer (template_io), the PDF layer (doc,
 * plot, report, assets, index_pdf), the study reports and the CLI.
 */
#ifndef AEROEVAL_TEMPLATE_H
#define AEROEVAL_TEMPLATE_H

#define TEMPLATE_PATH_MAX 1024   /* longest font/logo path we keep */
#define TEMPLATE_TITLE_MAX 96    /* longest section title, bytes incl. NUL */
#define TEMPLATE_MAX_SERIES 8    /* most series colours in the palette */

/* Dossier sections, in their default order. */
enum template_section_id {
	TEMPLATE_SEC_COVER,
	TEMPLATE_SEC_SUMMARY,
	TEMPLATE_SEC_RATIONALE,
	TEMPLATE_SEC_MASS,
	TEMPLATE_SEC_MISSION,
	TEMPLATE_SEC_THERMAL,
	TEMPLATE_SEC_STRUCTURE,
	TEMPLATE_SEC_PROPULSION,
	TEMPLATE_SEC_CONVERGENCE,
	TEMPLATE_SEC_ENDURANCE,
	TEMPLATE_SEC_BOM,
	TEMPLATE_SEC_CHECKS,
	TEMPLATE_SEC_APPENDIX,
	TEMPLATE_SEC_SENSITIVITY,
	TEMPLATE_SEC_MAX
};

/* An sRGB colour, each channel in [0, 1]. */
struct template_colour {
	double r, g, b;
};

/* One entry of the ordered section list. */
struct template_section {
	enum template_section_id id;      /* which section */
	char title[TEMPLATE_TITLE_MAX];   /* heading text, UTF-8 */
	int enabled;                      /* 0: left out of the dossier */
};

struct template {
	char name[64];                        /* informative name of the template */
	double page_width_mm;                 /* page width */
	double page_height_mm;                /* page height */
	double margin_top_mm;                 /* the running header sits inside it */
	double margin_bottom_mm;              /* the footer (page n / N) sits inside it */
	double margin_left_mm;
	double margin_right_mm;
	char font_regular[TEMPLATE_PATH_MAX]; /* TTF, body text */
	char font_bold[TEMPLATE_PATH_MAX];    /* TTF, headings, table headers */
	char font_mono[TEMPLATE_PATH_MAX];    /* TTF, fingerprints, appendix */
	double font_size_pt;                  /* body text size; others scale from it */
	struct template_colour text;          /* body text */
	struct template_colour primary;       /* headings, rules, table header */
	struct template_colour accent;        /* highlights, the chosen design */
	struct template_colour muted;         /* captions, secondary text */
	struct template_colour grid;          /* plot grid lines, table rules */
	struct template_colour pass;          /* PASS, FEASIBLE */
	struct template_colour fail;          /* FAIL, INFEASIBLE */
	struct template_colour warn;          /* warnings, margins near zero */
	struct template_colour series[TEMPLATE_MAX_SERIES]; /* plot palette */
	int n_series;                         /* used entries of series[], >= 2 */
	char logo[TEMPLATE_PATH_MAX];         /* PNG path, "" for none */
	char icc_profile[TEMPLATE_PATH_MAX];  /* sRGB ICC profile: the PDF/A
	                                         output intent (not a template
	                                         key: always the shipped
	                                         templates/icc/sRGB.icc, else the
	                                         system's), "" when none found */
	struct template_section sections[TEMPLATE_SEC_MAX]; /* in dossier order */
	int n_sections;                       /* used entries of sections[] */
};

/* The files a template names, checked when it loads (template_io.h). */
enum template_asset {
	TEMPLATE_ASSET_FONT,   /* a TrueType font */
	TEMPLATE_ASSET_LOGO    /* a PNG image */
};

/* The built-in A4 template (DejaVu fonts, every section but sensitivity).
 * Ownership: free with template_free(). Never NULL. */
struct template *template_default(void);

/* Frees a template; NULL is a no-op. */
void template_free(struct template *t);

/* The JSON id of a section ("cover", ...), or NULL for an invalid id. */
const char *template_section_name(enum template_section_id id);

/* The section whose JSON id is name, or -1. */
int template_section_id(const char *name);

/* The default title of a section ("Bill of materials"), NULL if invalid. */
const char *template_section_title(enum template_section_id id);

/* The entry for a section, or NULL if the template does not list it. */
const struct template_section *template_section_get(const struct template *t,
                                                    enum template_section_id id);

/* Nonzero if the section is listed and enabled. */
int template_section_enabled(const struct template *t, enum template_section_id id);

/* Parses "#rrggbb" (case-insensitive).  Returns 0 on success, -1 otherwise. */
int template_parse_colour(const char *s, struct template_colour *out);

#endif
