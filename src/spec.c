/* spec.c — the mission field table and its defaults (see spec.h). */
#include "spec.h"

#include <string.h>

const char *const spec_enum_airframe[] = {
	"MicroAIO", "ConsumerFolding", "EnterpriseRugged", "Agricultural", NULL
};
const char *const spec_enum_role[] = {
	"none", "imaging", "delivery", "agriculture", "racing", "inspection",
	"mapping", NULL
};
const char *const spec_enum_arm[] = { "offset", "folding", "under_rotor", NULL };
const char *const spec_enum_fom_mode[] = { "installed", "isolated", NULL };
const char *const spec_enum_body[] = {
	"commercial_compact", "commercial_bulky", "research_exposed", NULL
};
const char *const spec_enum_prop[] = { "auto", "plastic", "carbon", "wood", NULL };
const char *const spec_enum_transport[] = {
	"none", "backpack", "car_trunk", "industrial", NULL
};
const char *const spec_enum_priority[] = {
	"none", "endurance", "range", "payload", "min_mass", NULL
};
const char *const spec_enum_preset[] = {
	"none", "dslr_camera", "survey_lidar", "spray_tank_10l", "parcel_2kg",
	"thermal_camera", NULL
};

_Static_assert(sizeof spec_enum_airframe / sizeof *spec_enum_airframe == AF_CLASS_MAX + 1, "airframe spellings");
_Static_assert(sizeof spec_enum_role / sizeof *spec_enum_role == ROLE_MAX + 1, "role spellings");
_Static_assert(sizeof spec_enum_arm / sizeof *spec_enum_arm == ARM_CONFIG_MAX + 1, "arm spellings");
_Static_assert(sizeof spec_enum_fom_mode / sizeof *spec_enum_fom_mode == FOM_MODE_MAX + 1, "fom spellings");
_Static_assert(sizeof spec_enum_body / sizeof *spec_enum_body == BODY_CLASS_MAX + 1, "body spellings");
_Static_assert(sizeof spec_enum_prop / sizeof *spec_enum_prop == PROP_CLASS_MAX + 1, "prop spellings");
_Static_assert(sizeof spec_enum_transport / sizeof *spec_enum_transport == TRANSPORT_MAX + 1, "transport spellings");
_Static_assert(sizeof spec_enum_priority / sizeof *spec_enum_priority == PRIORITY_MAX + 1, "priority spellings");
_Static_assert(sizeof spec_enum_preset / sizeof *spec_enum_preset == PRESET_MAX + 1, "preset spellings");

const struct spec_field_info spec_fields[SPEC_N_FIELDS] = {
#define SPEC_X_ROW(id, path, type, member, unit, def, lo, hi, flags, enums, help) \
	{ SPECF_##id, path, type, offsetof(struct mission_spec, member), unit, \
	  (double)(def), (double)(lo), (double)(hi), flags, enums, help },
	SPEC_FIELDS(SPEC_X_ROW)
#undef SPEC_X_ROW
};

void *
spec_member(struct mission_spec *s, const struct spec_field_info *f)
{
	return (char *)s + f->offset;
}

const void *
spec_member_const(const struct mission_spec *s, const struct spec_field_info *f)
{
	return (const char *)s + f->offset;
}

void
spec_defaults(struct mission_spec *s)
{
	memset(s, 0, sizeof *s);
	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[i];
		void *p = spec_member(s, f);
		switch (f->type) {
		case SPEC_NUM:
		case SPEC_SPEED:
			*(double *)p = f->def;
			break;
		case SPEC_INT:
		case SPEC_ENUM:
			*(int *)p = (int)f->def;
			break;
		case SPEC_BOOL:
			*(bool *)p = f->def != 0.0;
			break;
		case SPEC_STR:
		case SPEC_DATE:
			break; /* already "" */
		}
	}
	/* The one string with a non-empty default. */
	strcpy(s->battery_chemistry, "LiPo");
}

const struct spec_field_info *
spec_field_by_path(const char *path)
{
	for (size_t i = 0; i < SPEC_N_FIELDS; i++)
		if (strcmp(spec_fields[i].path, path) == 0)
			return &spec_fields[i];
	return NULL;
}

int
spec_enum_index(const char *const *table, const char *name)
{
	for (int i = 0; table[i] != NULL; i++)
		if (strcmp(table[i], name) == 0)
			return i;
	return -1;
}
