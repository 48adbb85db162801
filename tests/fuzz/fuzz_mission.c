/* fuzz_mission.c — libFuzzer harness: any bytes through the mission reader.
 *
 * The reader must report every problem as a diagnostic and never crash,
 * hang, leak or hit undefined behaviour.  A valid mission must also survive
 * being printed back (mission_io_to_json) and re-parsed to the same count
 * of errors (zero).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "catalog/catalog.h"
#include "diag/diag.h"
#include "input/mission_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct diag *dg = diag_alloc(NULL);
	struct mission_spec s;
	int n_err = mission_io_parse("fuzz.json", (const char *)data, size,
	    catalog_default_chemistries, dg, &s);
	diag_free(dg);
	if (n_err != 0)
		return 0;
	/* A valid mission prints back to a valid mission. */
	cJSON *j = mission_io_to_json(&s);
	char *text = cJSON_PrintUnformatted(j);
	cJSON_Delete(j);
	if (text == NULL)
		abort();
	struct diag *dg2 = diag_alloc(NULL);
	struct mission_spec s2;
	int n_err2 = mission_io_parse("fuzz-reprint.json", text, strlen(text),
	    catalog_default_chemistries, dg2, &s2);
	diag_free(dg2);
	free(text);
	if (n_err2 != 0)
		abort();
	return 0;
}
