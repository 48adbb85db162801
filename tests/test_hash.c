/* test_hash.c — the string and pointer hash tables: they keep the first
 * value of a key, grow, and stay linear (counted in probes, not timed). */
#include "test_util.h"
#include "util/hash.h"

#include <stdlib.h>
#include <string.h>

#define N_KEYS 150000

static void
strmap_should_keep_the_first_value_of_a_key(void **state)
{
	(void)state;
	struct strmap *m = strmap_alloc(0);
	size_t v = 0;
	assert_true(strmap_put(m, "mass_g", 7, NULL));
	assert_true(strmap_put(m, "Mass_g", 8, NULL));      /* case matters */
	assert_false(strmap_put(m, "mass_g", 9, &v));
	assert_int_equal(v, 7);
	assert_true(strmap_get(m, "mass_g", &v));
	assert_int_equal(v, 7);
	assert_false(strmap_get(m, "mass", NULL));
	assert_true(strmap_put(m, "", 3, NULL));             /* the empty key is a key */
	assert_true(strmap_get(m, "", &v));
	assert_int_equal(v, 3);
	assert_int_equal(strmap_count(m), 3);
	strmap_free(m);
	strmap_free(NULL);
}

static void
strmap_should_stay_linear_over_150000_keys(void **state)
{
	(void)state;
	char (*keys)[16] = malloc(N_KEYS * sizeof *keys);
	assert_non_null(keys);
	struct strmap *m = strmap_alloc(0);   /* grows from the smallest table */
	for (size_t i = 0; i < N_KEYS; i++) {
		snprintf(keys[i], sizeof keys[i], "k%zu", i);
		assert_true(strmap_put(m, keys[i], i, NULL));
	}
	for (size_t i = 0; i < N_KEYS; i++) {
		size_t v;
		assert_true(strmap_get(m, keys[i], &v));
		assert_int_equal(v, i);
	}
	/* 2 * N operations at about 1.5 probes each at half fill (growth
	 * re-inserts do not count): a quadratic table would need ~N^2 / 2. */
	assert_int_equal(strmap_count(m), N_KEYS);
	assert_true(strmap_probes(m) < 8 * (size_t)N_KEYS);
	strmap_free(m);
	free(keys);
}

static void
ptrmap_should_key_by_address_and_stay_linear(void **state)
{
	(void)state;
	char *block = malloc(N_KEYS);
	assert_non_null(block);
	struct ptrmap *m = ptrmap_alloc(N_KEYS);
	for (size_t i = 0; i < N_KEYS; i++)
		assert_true(ptrmap_put(m, block + i, i, NULL));
	size_t v;
	assert_false(ptrmap_put(m, block + 12, 99, &v));
	assert_int_equal(v, 12);
	for (size_t i = 0; i < N_KEYS; i++) {
		assert_true(ptrmap_get(m, block + i, &v));
		assert_int_equal(v, i);
	}
	assert_true(ptrmap_probes(m) < 8 * (size_t)N_KEYS);
	ptrmap_free(m);
	ptrmap_free(NULL);
	free(block);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(strmap_should_keep_the_first_value_of_a_key),
		cmocka_unit_test(strmap_should_stay_linear_over_150000_keys),
		cmocka_unit_test(ptrmap_should_key_by_address_and_stay_linear),
	};
	return cmocka_run_group_tests_name("hash", tests, NULL, NULL);
}
