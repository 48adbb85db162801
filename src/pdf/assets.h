/* assets.h — checks of the files a dossier template names, the fonts and
 * the logo, run when the template loads (input/template_io.h), before any
 * mission is solved.
 *
 * They live in the PDF layer because the real judges are the libraries
 * that will use the files: a font is read by its header tables and then
 * loaded once by libharu, a PNG is decoded by cairo, which returns an error
 * status where libpng inside libharu would abort the process.  Without
 * them a corrupt logo killed a worker with signal 6 and a file that is not
 * a font failed every mission after solving ("libharu error 0x105F").
 *
 * Who may include it: the command layer (and tests).
 */
#ifndef AEROEVAL_ASSETS_H
#define AEROEVAL_ASSETS_H

#include <stddef.h>

#include "template/template.h"

/* The largest logo accepted, in pixels per side (a logo is drawn 42 pt
 * high; this only stops a decompression bomb). */
#define ASSETS_LOGO_MAX_PX 10000

/* 0 when buf[0..n), the bytes of the file at path, is a TrueType font that
 * libharu loads; else -1 with the reason in err (e.g. "no 'glyf' table",
 * "a font collection (.ttc)"). */
int assets_check_font(const char *path, const unsigned char *buf, size_t n,
                      char *err, size_t errlen);

/* 0 when buf[0..n) is a PNG image cairo decodes, at most ASSETS_LOGO_MAX_PX
 * on a side; else -1 with the reason in err. */
int assets_check_png(const unsigned char *buf, size_t n, char *err, size_t errlen);

/* The check template_io_load() takes: by kind, one of the above. */
int assets_check(enum template_asset kind, const char *path,
                 const unsigned char *buf, size_t n, char *err, size_t errlen);

#endif
