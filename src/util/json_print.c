/* json_print.c — a cJSON tree as file text (see json_print.h). */
#include "util/json_print.h"

#include <string.h>

#include "util/xalloc.h"

char *
json_print_file(const cJSON *root)
{
	char *text = cJSON_Print(root);
	if (text == NULL)
		xalloc_die(0);
	/* The text is cJSON's allocation; the caller gets one of ours. */
	size_t n = strlen(text);
	char *out = xmalloc(n + 2);
	memcpy(out, text, n);
	out[n] = '\n';
	out[n + 1] = '\0';
	cJSON_free(text);
	return out;
}
