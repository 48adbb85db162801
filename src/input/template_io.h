/* template_io.h — read and validate a dossier template (templates/NAME.json)
 * into a struct template (template/template.h).
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
 * directory.  "sections" replaces the whole list: its order is the dossier's
 * order, an id missing from it is disabled, a repeated id is an error.
 *
 * The file is read through json_in, so every problem is a diagnostic with
 * file:line:col and the JSON path, all of them in one pass.  The fonts and
 * the logo are read when the template loads, through file_read (a FIFO,
 * device or directory is refused at once), and their bytes handed to the
 * caller's check, so a corrupt PNG or a file that is not a font is an
 * error naming it before any mission is solved.  The checks that need
 * cairo and libharu live in the PDF layer (pdf/assets.h); the
 * command layer passes them in.
 *
 * Who may include it: the command layer (and tests).
 */
#ifndef AEROEVAL_TEMPLATE_IO_H
#define AEROEVAL_TEMPLATE_IO_H

#include <stddef.h>

#include "diag/diag.h"
#include "template/template.h"

/* The largest font and logo file read (bytes). */
#define TEMPLATE_IO_FONT_MAX ((size_t)32 << 20)
#define TEMPLATE_IO_LOGO_MAX ((size_t)8 << 20)

/* A check of one file the template names: 0 when the bytes buf[0..n) of
 * the file at path are usable as kind, else -1 with the reason in err. */
typedef int (*template_io_check)(enum template_asset kind, const char *path,
                                 const unsigned char *buf, size_t n,
                                 char *err, size_t errlen);

/* Loads and validates the template file at path.  check (may be NULL:
 * only readability) judges each font and the logo.  Every problem is
 * reported into dg (exit status 2).  Returns NULL when any error was
 * found.  Ownership: free with template_free(). */
struct template *template_io_load(const char *path, template_io_check check,
                                  struct diag *dg);

#endif
