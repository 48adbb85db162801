/* model.c — lookups over the reference tables (see model.h). */
#include "spec/model.h"

#include <string.h>

const char *const duty_kind_name[DUTY_KIND_MAX] = { "phases", "race",
	"spray_sorties", "out_and_back" };

const struct batt_chem *
model_chem(const struct model_data *m, const char *name)
{
	for (int i = 0; i < m->n_chem; i++)
		if (strcmp(m->chem[i].name, name) == 0)
			return &m->chem[i];
	return NULL;
}

enum model_lambda
model_lambda_index(int airframe_class, int n_rotors)
{
	switch (airframe_class) {
	case AF_MICRO_AIO:
		return LAMBDA_MICRO;
	case AF_CONSUMER_FOLDING:
		return LAMBDA_CONSUMER;
	case AF_AGRICULTURAL:
		return LAMBDA_AGRI;
	default:
		/* Paper eq. (lambda): hex/octo enterprise frames differ from quads. */
		return n_rotors > 4 ? LAMBDA_ENTERPRISE_MULTI : LAMBDA_ENTERPRISE_QUAD;
	}
}

const struct model_interval *
model_interval_for(const struct model_accuracy *a, int airframe_class)
{
	if (airframe_class >= 0 && airframe_class < AF_CLASS_MAX
	    && a->cls[airframe_class].n > 0)
		return &a->cls[airframe_class];
	return &a->pooled;
}
