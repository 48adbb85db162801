/* summary.c — the design-space table's rows (see summary.h). */
#include "result/summary.h"

#include <stdlib.h>
#include <string.h>

#include "util/xalloc.h"

void
summary_add(struct summary *s, const struct summary_row *row)
{
	if (s->n == s->cap) {
		s->cap = s->cap ? 2 * s->cap : 16;
		s->rows = xrealloc(s->rows, s->cap * sizeof *s->rows);
	}
	s->rows[s->n++] = *row;
}

static int
cmp_row(const void *a, const void *b)
{
	return strcmp(((const struct summary_row *)a)->name,
	              ((const struct summary_row *)b)->name);
}

void
summary_sort(struct summary *s)
{
	if (s->n > 1)  /* qsort must not see a NULL base (UBSan) */
		qsort(s->rows, s->n, sizeof *s->rows, cmp_row);
}

void
summary_free(struct summary *s)
{
	if (s == NULL)
		return;
	free(s->rows);
	s->rows = NULL;
	s->n = s->cap = 0;
}

const char *
summary_status_name(enum summary_status st)
{
	static const char *const names[SUMMARY_STATUS_MAX] = {
		"feasible", "infeasible", "not buildable"
	};
	return st >= 0 && st < SUMMARY_STATUS_MAX ? names[st] : "?";
}

void
summary_count(const struct summary *s, size_t count[SUMMARY_STATUS_MAX])
{
	for (int i = 0; i < SUMMARY_STATUS_MAX; i++)
		count[i] = 0;
	for (size_t i = 0; i < s->n; i++)
		if (s->rows[i].status >= 0 && s->rows[i].status < SUMMARY_STATUS_MAX)
			count[s->rows[i].status]++;
}
