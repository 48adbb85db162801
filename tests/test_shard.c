/* test_shard.c — `build --shard K/N`: the argument, and a split that is a
 * pure function of the mission's name. */
#include "test_util.h"

#include "cli/shard.h"

static void
shard_should_accept_k_of_n(void **state)
{
	(void)state;
	static const struct { const char *s; unsigned k, n; } ok[] = {
		{ "1/1", 1, 1 }, { "1/3", 1, 3 }, { "3/3", 3, 3 }, { "12/100000", 12, 100000 },
		{ "007/9", 7, 9 },
	};
	for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++) {
		struct shard sh = { 0, 0 };
		char err[160];
		assert_int_equal(shard_parse(ok[i].s, &sh, err, sizeof err), 0);
		assert_int_equal(sh.k, ok[i].k);
		assert_int_equal(sh.n, ok[i].n);
	}
}

static void
shard_should_refuse_what_is_not_k_of_n(void **state)
{
	(void)state;
	static const char *const bad[] = {
		"0/3", "4/3", "3", "/3", "1/", "a/3", "1/3x", "1/0", "0/0", "-1/3", "+1/3",
		" 1/3", "1/3 ", "1/100001", "1//3", "1.0/3", "", "9999999999/3",
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		struct shard sh = { 7, 7 };
		char err[160] = "";
		assert_int_equal(shard_parse(bad[i], &sh, err, sizeof err), -1);
		assert_true(strncmp(err, "--shard", 7) == 0);
		assert_int_equal(sh.k, 7);  /* untouched */
	}
}

static void
every_mission_should_fall_in_exactly_one_shard(void **state)
{
	(void)state;
	struct shard sh[3] = { { 1, 3 }, { 2, 3 }, { 3, 3 } };
	size_t count[3] = { 0, 0, 0 };
	char name[32];
	for (int i = 0; i < 3000; i++) {
		snprintf(name, sizeof name, "mission_%04d", i);
		int hits = 0;
		for (int k = 0; k < 3; k++)
			if (shard_has(&sh[k], name)) {
				hits++;
				count[k]++;
			}
		assert_int_equal(hits, 1);
	}
	/* SHA-256 spreads them evenly: each share within 10 % of a third. */
	for (int k = 0; k < 3; k++)
		assert_true(count[k] >= 900 && count[k] <= 1100);
	struct shard all = { 0, 0 };
	assert_true(shard_has(&all, "anything"));
}

/* The split is part of a study's setup: machines of one study, or a study
 * resumed with a newer aeroeval, must agree.  These values pin it. */
static void
shard_of_a_name_should_never_change(void **state)
{
	(void)state;
	assert_int_equal(shard_of("sar_imaging_quad", 3), 3);
	assert_int_equal(shard_of("agri_spray_octo", 3), 3);
	assert_int_equal(shard_of("fpv_racing_quad", 3), 2);
	assert_int_equal(shard_of("agri_spray_octo", 7), 4);
	assert_int_equal(shard_of("delivery_quad", 7), 5);
	assert_int_equal(shard_of("fpv_racing_quad", 7), 1);
	assert_int_equal(shard_of("anything", 1), 1);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(shard_should_accept_k_of_n),
		cmocka_unit_test(shard_should_refuse_what_is_not_k_of_n),
		cmocka_unit_test(every_mission_should_fall_in_exactly_one_shard),
		cmocka_unit_test(shard_of_a_name_should_never_change),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
