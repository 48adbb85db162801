/* spec.c — the mission field table and its defaults (see spec.h). */
#include "spec/spec.h"

#include <stdio.h>
#include <string.h>

#include "util/text.h"

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

const struct spec_essential spec_essentials[SPEC_N_ESSENTIALS] = {
	{ "payload_kg", { SPECF_PAYLOAD_KG, SPEC_N_FIELDS, SPEC_N_FIELDS }, false,
	  SPECF_REQ_PRESET },
	{ "max_diameter_m", { SPECF_MAX_DIAMETER_M, SPEC_N_FIELDS, SPEC_N_FIELDS }, false,
	  SPECF_REQ_TRANSPORT },
	{ "a mission time", { SPECF_T_HOVER_S, SPECF_T_FORWARD_S, SPECF_T_CLIMB_S }, true,
	  SPEC_N_FIELDS },
};

bool
spec_essential_met(const struct mission_spec *s, const struct spec_essential *e)
{
	for (int i = 0; i < SPEC_ESSENTIAL_FIELDS && e->any_of[i] != SPEC_N_FIELDS; i++) {
		const struct spec_field_info *f = &spec_fields[e->any_of[i]];
		if (s->given[f->id] && (!e->positive || *(const double *)spec_member_const(s, f) > 0.0))
			return true;
	}
	/* A requirements enum set to other than its first value, "none". */
	return e->derived_by != SPEC_N_FIELDS && s->given[e->derived_by]
	    && *(const int *)spec_member_const(s, &spec_fields[e->derived_by]) != 0;
}

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
	strcpy(s->battery_chemistry, "LiHV");
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

const char *
spec_split(const char *path, char *buf, size_t n)
{
	const char *dot = strchr(path, '.');
	if (dot == NULL) {
		buf[0] = '\0';
		return path;
	}
	snprintf(buf, n, "%.*s", (int)(dot - path), path);
	return dot + 1;
}

bool
spec_is_group(const char *name)
{
	size_t n = strlen(name);
	for (size_t i = 0; i < SPEC_N_FIELDS; i++)
		if (strncmp(spec_fields[i].path, name, n) == 0 && spec_fields[i].path[n] == '.')
			return true;
	return false;
}

void
spec_range_text(const struct spec_field_info *f, char *buf, size_t n)
{
	const char *sp = f->unit[0] != '\0' ? " " : "";
	if (f->flags & SPEC_F_MIN_EXCL)
		snprintf(buf, n, "above %.15g up to %.15g%s%s", f->min, f->max, sp, f->unit);
	else
		snprintf(buf, n, "%.15g to %.15g%s%s", f->min, f->max, sp, f->unit);
}

bool
spec_suggest(const char *path, char *out, size_t n)
{
	char group[TEXT_DISTANCE_MAX + 1], fgroup[TEXT_DISTANCE_MAX + 1];
	const char *key = spec_split(path, group, sizeof group);
	size_t klen = strlen(key);
	/* Close enough: about one edit per three characters, at least one. */
	size_t best_d = text_typo_limit(klen) + 1;
	const char *best = NULL;
	size_t best_len = 0;

	for (size_t i = 0; i < SPEC_N_FIELDS; i++) {
		const char *fpath = spec_fields[i].path;
		const char *fkey = spec_split(fpath, fgroup, sizeof fgroup);
		/* The same key under another group costs one edit more, so a
		 * typo in the right group wins over an exact key elsewhere. */
		size_t d = text_distance(key, fkey) + (strcmp(group, fgroup) != 0);
		size_t dp = text_distance(path, fpath);
		if (dp < d)
			d = dp;
		if (d < best_d) {
			best_d = d;
			best = fpath;
			best_len = strlen(fpath);
		}
		/* A misspelt group name at the top level: "lock" -> "locks". */
		if (group[0] == '\0' && fgroup[0] != '\0') {
			d = text_distance(key, fgroup);
			if (d < best_d) {
				best_d = d;
				best = fpath;
				best_len = strlen(fgroup);
			}
		}
	}
	out[0] = '\0';
	if (best == NULL || (strlen(path) == best_len && strncmp(path, best, best_len) == 0))
		return false;
	snprintf(out, n, "%.*s", (int)best_len, best);
	return true;
}

void
spec_format_value(const struct mission_spec *s,
                        const struct spec_field_info *f, char *buf, size_t n)
{
	const void *p = spec_member_const(s, f);
	const char *sp = f->unit[0] != '\0' ? " " : "";

	switch (f->type) {
	case SPEC_SPEED:
		if (s->v_forward_auto) {
			snprintf(buf, n, "auto");
			break;
		}
		/* fall through */
	case SPEC_NUM:
		snprintf(buf, n, "%.15g%s%s", *(const double *)p, sp, f->unit);
		break;
	case SPEC_INT:
		snprintf(buf, n, "%d%s%s", *(const int *)p, sp, f->unit);
		break;
	case SPEC_BOOL:
		snprintf(buf, n, "%s", *(const bool *)p ? "true" : "false");
		break;
	case SPEC_ENUM:
		snprintf(buf, n, "%s", f->enums[*(const int *)p]);
		break;
	case SPEC_STR:
	case SPEC_DATE:
		snprintf(buf, n, "%s", ((const char *)p)[0] != '\0' ? (const char *)p : "(none)");
		break;
	}
}
