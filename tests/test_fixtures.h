/* test_fixtures.h — hand-worked physics fixtures shared by the physics
 * tests (test_batt.c, test_discharge.c, test_mission.c), so that every
 * hand value starts from the same aircraft and the same cells. */
#ifndef AEROEVAL_TEST_FIXTURES_H
#define AEROEVAL_TEST_FIXTURES_H

#include <stdbool.h>
#include <string.h>

#include "physics/atmo.h"
#include "physics/batt.h"
#include "physics/mission.h"

/* The paper's LiPo profile (Table chem) with the V_exp, specific
 * power and a 3.3 V loaded cut-off. */
static inline struct batt_chem
fixture_lipo(void)
{
	struct batt_chem c;
	memset(&c, 0, sizeof c);
	strcpy(c.name, "LiPo");
	c.e_spec_wh_kg = 180.0;
	c.p_spec_w_kg = 3500.0;
	c.r_cell_mohm = 5.0;
	c.v_full = 4.2;
	c.v_nom = 3.7;
	c.v_exp = 3.9;
	c.v_cutoff = 3.3;
	c.b = 5.5;
	c.k = 0.046;
	c.pouch = true;
	return c;
}

/* The hand aircraft: ISA sea level, four 0.3385 m rotors at installed FoM
 * 0.585, η 0.85, aux 22.5 W, 22.2 V bus, f_scale 0.012, ΔA 0.02 m²,
 * forward multiplier 1.5, C_d,h 1.0, C_d,v 1.2. */
static inline void
fixture_hand_model(struct mission_model *m, bool coaxial)
{
	memset(m, 0, sizeof *m);
	atmo_at(0.0, atmo_isa_temp_k(0.0), &m->air);
	m->rotor.diameter_m = 0.3385;
	m->rotor.ct = 0.12;
	m->rotor.fom = 0.585;
	m->rotor.n_blades = 2;
	m->n_rotors = 4;
	m->coaxial = coaxial;
	m->f_scale = 0.012;
	m->added_drag_m2 = 0.02;
	m->fwd_drag_mult = 1.5;
	m->cd_h = 1.0;
	m->cd_v = 1.2;
	m->eta_drive = 0.85;
	m->aux_w = 22.5;
	m->bus_voltage_v = 22.2;
}

#endif
