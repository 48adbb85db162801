/* fuzz_cohort.c — libFuzzer harness: any bytes through the cohort reader.
 *
 * Every kept row must keep the header's promises (cohort.h): a non-empty
 * name, a takeoff mass > 0, text fields never NULL.
 */
#include <stdint.h>
#include <stdlib.h>

#include "input/cohort.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct cohort c;
	cohort_parse("fuzz.csv", (const char *)data, size, &c);
	for (size_t i = 0; i < c.n_rows; i++) {
		const struct cohort_row *r = &c.rows[i];
		if (r->name == NULL || r->name[0] == '\0' || !(r->takeoff_mass_kg > 0)
		    || r->cohort == NULL || r->battery_chemistry == NULL
		    || r->source == NULL || r->notes == NULL)
			abort();
	}
	for (size_t i = 0; i < c.n_errors; i++)
		if (c.errors[i] == NULL)
			abort();
	cohort_free(&c);
	return 0;
}
