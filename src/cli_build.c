/* cli_build.c — `aeroeval build [-o DIR] [--template FILE] [--db DIR] MISSION.json...` */
#include "cli_build.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "pipeline.h"
#include "template.h"
#include "xalloc.h"

#define BUILD_USAGE "usage: aeroeval build [-o DIR] [--template FILE] [--db DIR] MISSION.json|DIR...\n"

/* A growable list of mission paths. */
struct path_list {
	char **v;
	size_t n, cap;
};

static void
list_add(struct path_list *l, const char *s)
{
	if (l->n == l->cap) {
		l->cap = l->cap ? 2 * l->cap : 16;
		l->v = xrealloc(l->v, l->cap * sizeof *l->v);
	}
	l->v[l->n++] = xstrdup(s);
}

static int
cmp_str(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

static int
ends_with_json(const char *s)
{
	size_t n = strlen(s);
	return n > 5 && strcmp(s + n - 5, ".json") == 0;
}

/* A directory contributes its *.json files, sorted for a stable order. */
static int
expand(const char *arg, struct path_list *l)
{
	struct stat st;
	if (stat(arg, &st) != 0) {
		fprintf(stderr, "%s: error: no such file or directory\n", arg);
		return -1;
	}
	if (!S_ISDIR(st.st_mode)) {
		list_add(l, arg);
		return 0;
	}
	DIR *d = opendir(arg);
	if (d == NULL) {
		fprintf(stderr, "%s: error: cannot read the directory\n", arg);
		return -1;
	}
	size_t first = l->n;
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		if (e->d_name[0] == '.' || !ends_with_json(e->d_name))
			continue;
		char p[4400];
		snprintf(p, sizeof p, "%s/%s", arg, e->d_name);
		list_add(l, p);
	}
	closedir(d);
	qsort(l->v + first, l->n - first, sizeof *l->v, cmp_str);
	return 0;
}

int
cli_build(int argc, char **argv)
{
	const char *out = "out", *db = NULL, *tpl_path = NULL;
	struct path_list missions = { 0 };
	int rc = 0;
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
			out = argv[++i];
		else if (strcmp(argv[i], "--db") == 0 && i + 1 < argc)
			db = argv[++i];
		else if (strcmp(argv[i], "--template") == 0 && i + 1 < argc)
			tpl_path = argv[++i];
		else if (argv[i][0] == '-') {
			fputs(BUILD_USAGE, stderr);
			return 2;
		} else if (expand(argv[i], &missions) != 0)
			rc = 2;
	}
	if (missions.n == 0) {
		fputs(BUILD_USAGE, stderr);
		return 2;
	}
	/* Name clashes are an error before anything is written. */
	char (*names)[256] = xcalloc(missions.n, sizeof *names);
	for (size_t i = 0; i < missions.n; i++) {
		if (pipeline_name(missions.v[i], names[i], sizeof names[i]) != 0)
			continue; /* reported per mission below */
		for (size_t j = 0; j < i; j++)
			if (strcmp(names[i], names[j]) == 0) {
				fprintf(stderr, "%s: error: output name \"%s\" clashes with %s\n",
				    missions.v[i], names[i], missions.v[j]);
				rc = 2;
			}
	}
	struct cli_env *env = xcalloc(1, sizeof *env);
	struct template *tpl = NULL;
	if (rc == 0 && cli_env_load(env, db, 1, stderr) != 0)
		rc = 2;
	if (rc == 0) {
		tpl = tpl_path ? template_load(tpl_path, stderr) : template_default();
		if (tpl == NULL)
			rc = 2;
	}
	int n_ok = 0, n_inf = 0, n_rej = 0, n_int = 0;
	if (rc == 0) {
		struct pipeline_opts o = { out, tpl, 1 };
		for (size_t i = 0; i < missions.n; i++) {
			enum pipeline_status st = pipeline_build(env, &o, missions.v[i], stderr);
			switch (st) {
			case PIPE_FEASIBLE: n_ok++; break;
			case PIPE_INFEASIBLE: n_inf++; break;
			case PIPE_REJECTED: n_rej++; break;
			default: n_int++; break;
			}
			fprintf(stderr, "%s: %s\n", missions.v[i],
			    st == PIPE_FEASIBLE ? "compiled" : st == PIPE_INFEASIBLE
			    ? "compiled (infeasible)" : st == PIPE_REJECTED ? "rejected"
			    : "internal error");
		}
		fprintf(stderr, "build: %d compiled, %d infeasible, %d rejected%s\n",
		    n_ok + n_inf, n_inf, n_rej, n_int ? ", internal errors" : "");
		rc = n_int ? 3 : n_rej ? 2 : n_inf ? 1 : 0;
	}
	template_free(tpl);
	cli_env_free(env);
	free(env);
	free(names);
	for (size_t i = 0; i < missions.n; i++)
		free(missions.v[i]);
	free(missions.v);
	return rc;
}
