/* valreport.c — the validation dossier PDF (see valreport.h). */
#include "valreport.h"

#include <stdio.h>

const char *const valreport_rule_text[] = { NULL };

int
valreport_render(const struct cohort *c, const struct validate_report *v,
                 const char *cohort_name, const char *date,
                 unsigned char **pdf, size_t *n, char *err, size_t errlen)
{
	(void)c; (void)v; (void)cohort_name; (void)date; (void)pdf; (void)n;
	snprintf(err, errlen, "not yet");
	return -1;
}
