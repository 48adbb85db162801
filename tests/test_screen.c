/* test_screen.c — the plausibility screens of parts/screen.h: hand cases,
 * and the shipped catalogue screened entry by entry. */
#include "test_util.h"

#include <math.h>
#include <string.h>

#include "catalog/catalog.h"
#include "diag/diag.h"
#include "input/catalog_io.h"
#include "parts/screen.h"
#include "physics/motor.h"

/* The name of the field a screen names ("mass_g: ..." -> "mass_g"). */
static void
field_of(const char *why, char *out, size_t n)
{
	size_t k = strcspn(why, ":");
	if (k >= n)
		k = n - 1;
	memcpy(out, why, k);
	out[k] = '\0';
}

/* Is `field` in the comma-separated `uncertain` list? */
static bool
listed(const char *uncertain, const char *field)
{
	size_t n = strlen(field);
	for (const char *p = uncertain; (p = strstr(p, field)) != NULL; p += n)
		if ((p == uncertain || p[-1] == ',' || p[-1] == ' ')
		    && (p[n] == '\0' || p[n] == ','))
			return true;
	return false;
}

/* The shipped catalogue (its diagnostics, if any, on stderr). */
static struct catalog *
load_shipped(void)
{
	struct diag *dg = diag_alloc(stderr);
	struct catalog *cat = catalog_io_load("data/catalog", NULL, dg, NULL);
	diag_flush(dg);
	diag_free(dg);
	assert_non_null(cat);
	return cat;
}

static void
screen_esc_should_refuse_16_amps_per_gram(void **state)
{
	(void)state;
	char why[256];
	struct catalog_esc e;
	memset(&e, 0, sizeof e);
	e.continuous_current_a = 40.0;
	e.channels = 1;
	e.mass_kg = 0.0025; /* 40 A / 2.5 g = 16.0 A/g */
	assert_non_null(screen_esc(&e, why, sizeof why));
	assert_non_null(strstr(why, "16.0 A/g"));
	e.mass_kg = 0.0385; /* 1.04 A/g: a real 40 A ESC */
	assert_null(screen_esc(&e, why, sizeof why));
}

static void
screen_battery_should_refuse_lipo_packs_beyond_260_wh_per_kg(void **state)
{
	(void)state;
	char why[256];
	struct catalog_battery b;
	memset(&b, 0, sizeof b);
	b.chemistry = "LiPo";
	b.cells_series = 6;
	b.capacity_ah = 5.2;
	b.nominal_voltage_v = 22.2;
	b.continuous_c = 25.0;
	b.mass_kg = 0.285;   /* 115.4 Wh / 0.285 kg = 405 Wh/kg */
	assert_non_null(screen_battery(&b, why, sizeof why));
	b.mass_kg = 0.745;   /* 155 Wh/kg */
	assert_null(screen_battery(&b, why, sizeof why));
	b.continuous_c = 150.0; /* 150C × 155 Wh/kg = 23 kW/kg sustained */
	assert_non_null(screen_battery(&b, why, sizeof why));
	assert_non_null(strstr(why, "continuous_c"));
}

static void
screen_motor_should_refuse_power_its_current_cannot_carry(void **state)
{
	(void)state;
	char why[256];
	struct catalog_motor m;
	memset(&m, 0, sizeof m);
	m.kv_rpm_per_v = 580.0;
	m.mass_kg = 0.086;
	m.max_current_a = 18.0;
	m.cells_max = 4;
	/* 18 A × 4.35 V × 4 × 1.25 = 391.5 W: 400 W is more */
	m.max_power_w = 400.0;
	assert_non_null(screen_motor(&m, why, sizeof why));
	assert_non_null(strstr(why, "max_power_w"));
	m.max_power_w = 300.0;
	assert_null(screen_motor(&m, why, sizeof why));
}

/* Every entry the screens find implausible says so itself: the doubtful
 * field is listed as uncertain.  The counts are printed. */
static void
screen_shipped_catalogue_should_flag_every_implausible_entry(void **state)
{
	(void)state;
	struct catalog *cat = load_shipped();
	int n_off = 0, n_unflagged = 0, n_all = 0;
	char why[512], field[64];
#define SCREEN_EACH(count, get, screen)                                      \
	for (size_t i = 0; i < count(cat); i++) {                             \
		const __typeof__(*get(cat, 0)) *e = get(cat, i);              \
		n_all++;                                                      \
		if (screen(e, why, sizeof why) == NULL)                       \
			continue;                                             \
		n_off++;                                                      \
		field_of(why, field, sizeof field);                          \
		if (!listed(e->uncertain, field)) {                           \
			n_unflagged++;                                        \
			print_error("%s: %s (not listed as uncertain)\n", e->id, why); \
		}                                                             \
	}
	SCREEN_EACH(catalog_n_motors, catalog_motor, screen_motor)
	SCREEN_EACH(catalog_n_props, catalog_prop, screen_prop)
	SCREEN_EACH(catalog_n_batteries, catalog_battery, screen_battery)
	SCREEN_EACH(catalog_n_escs, catalog_esc, screen_esc)
#undef SCREEN_EACH
	printf("screen: %d entries, %d implausible (left out of the search), "
	    "%d of them not flagged\n", n_all, n_off, n_unflagged);
	catalog_free(cat);
	assert_int_equal(n_unflagged, 0);
}

static void
stator_should_read_diameter_by_height(void **state)
{
	(void)state;
	struct catalog_motor m;
	memset(&m, 0, sizeof m);
	double d, h;
	m.stator = "22x07";
	assert_true(catalog_motor_stator_mm(&m, &d, &h));
	assert_rel(d, 22.0, 0.0);
	assert_rel(h, 7.0, 0.0);
	m.stator = "22.6x06.5";
	assert_true(catalog_motor_stator_mm(&m, &d, &h));
	assert_rel(d, 22.6, 0.0);
	assert_rel(h, 6.5, 0.0);
	const char *bad[] = { "", "22", "22x", "x07", "22x07mm", "0x07", "-22x07",
		"22 07", "1e9x7" };
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		m.stator = bad[i];
		assert_false(catalog_motor_stator_mm(&m, &d, &h));
	}
	m.stator = NULL;
	assert_false(catalog_motor_stator_mm(&m, &d, &h));
}

/* Over the shipped motors that publish R and I0 with their stator, the
 * stator's estimate lands nearer than the mass law's (the reason the
 * search prefers it, physics/motor.c). */
static void
stator_estimates_should_beat_the_mass_law_on_the_catalogue(void **state)
{
	(void)state;
	struct catalog *cat = load_shipped();
	double err_stator = 0.0, err_mass = 0.0;
	int n = 0;
	for (size_t i = 0; i < catalog_n_motors(cat); i++) {
		const struct catalog_motor *m = catalog_motor(cat, i);
		double d, h;
		if (m->integrated || !(m->resistance_ohm > 0.0)
		    || !(m->mass_kg > 0.0) || !catalog_motor_stator_mm(m, &d, &h))
			continue;
		double r_ohm, i0_a;
		screen_motor_estimates(m, &r_ohm, &i0_a);
		err_stator += fabs(log(r_ohm / m->resistance_ohm));
		err_mass += fabs(log(motor_estimate_resistance_ohm(
		    m->kv_rpm_per_v, m->mass_kg) / m->resistance_ohm));
		n++;
	}
	catalog_free(cat);
	printf("stator law: %d motors, mean |ln error| %.3f (mass law %.3f)\n",
	    n, err_stator / n, err_mass / n);
	assert_true(n >= 100);
	assert_true(err_stator < 0.8 * err_mass);
}

/* What an ESC board says it carries are avionics kinds the class sets
 * know, so the kit can leave them out (parts/kit.c). */
static void
esc_carries_should_name_known_avionics_kinds(void **state)
{
	(void)state;
	static const char *const kinds[] = { "flight_controller", "receiver",
		"video_tx" };
	struct catalog *cat = load_shipped();
	int n_aio = 0;
	for (size_t i = 0; i < catalog_n_escs(cat); i++) {
		const struct catalog_esc *e = catalog_esc(cat, i);
		if (e->carries == NULL || e->carries[0] == '\0')
			continue;
		n_aio++;
		char list[128];
		snprintf(list, sizeof list, "%s", e->carries);
		for (char *save = NULL, *k = strtok_r(list, ",", &save); k != NULL;
		    k = strtok_r(NULL, ",", &save)) {
			bool known = false;
			for (size_t j = 0; j < sizeof kinds / sizeof kinds[0]; j++)
				known |= strcmp(k, kinds[j]) == 0;
			if (!known)
				print_error("%s: carries unknown kind \"%s\"\n", e->id, k);
			assert_true(known);
		}
	}
	catalog_free(cat);
	assert_true(n_aio >= 40);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(screen_esc_should_refuse_16_amps_per_gram),
		cmocka_unit_test(screen_battery_should_refuse_lipo_packs_beyond_260_wh_per_kg),
		cmocka_unit_test(screen_motor_should_refuse_power_its_current_cannot_carry),
		cmocka_unit_test(screen_shipped_catalogue_should_flag_every_implausible_entry),
		cmocka_unit_test(stator_should_read_diameter_by_height),
		cmocka_unit_test(esc_carries_should_name_known_avionics_kinds),
		cmocka_unit_test(stator_estimates_should_beat_the_mass_law_on_the_catalogue),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
