/* json_print.h — a cJSON tree as the text of a JSON file.
 *
 * For writers that build a small tree with cJSON (index.json, the ArduPilot
 * components file, the sensitivity table) rather than stream it: numbers
 * that must print exactly go in as cJSON_CreateRaw() text from numfmt.h,
 * since cJSON's own number printing rounds (STACK.md §7).
 * Who may include it: every layer but physics.
 */
#ifndef AEROEVAL_JSON_PRINT_H
#define AEROEVAL_JSON_PRINT_H

#include <cjson/cJSON.h>

/* cJSON_Print() of root (tab-indented) with the final newline a text file
 * ends with.  Out of memory exits with status 3 (xalloc.h).
 * Ownership: the caller frees the text with free(); root stays the
 * caller's. */
char *json_print_file(const cJSON *root);

#endif
