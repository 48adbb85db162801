/* table_row.c — the design-space table's rows (see table_row.h). */
#include "result/table_row.h"

#include <stdlib.h>
#include <string.h>

#include "util/xalloc.h"

void
table_row_add(struct table_rows *s, const struct table_row *row)
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
	return strcmp(((const struct table_row *)a)->name,
	              ((const struct table_row *)b)->name);
}

void
table_row_sort(struct table_rows *s)
{
	if (s->n > 1)  /* qsort must not see a NULL base (UBSan) */
		qsort(s->rows, s->n, sizeof *s->rows, cmp_row);
}

void
table_row_free(struct table_rows *s)
{
	if (s == NULL)
		return;
	free(s->rows);
	s->rows = NULL;
	s->n = s->cap = 0;
}

const char *
table_row_status_name(enum table_row_status st)
{
	static const char *const names[TABLE_ROW_STATUS_MAX] = {
		"feasible", "infeasible", "not buildable"
	};
	return st >= 0 && st < TABLE_ROW_STATUS_MAX ? names[st] : "?";
}

void
table_row_count(const struct table_rows *s, size_t count[TABLE_ROW_STATUS_MAX])
{
	for (int i = 0; i < TABLE_ROW_STATUS_MAX; i++)
		count[i] = 0;
	for (size_t i = 0; i < s->n; i++)
		if (s->rows[i].status >= 0 && s->rows[i].status < TABLE_ROW_STATUS_MAX)
			count[s->rows[i].status]++;
}
