/* main.c — argv, subcommand dispatch, exit status.  Drives; computes nothing. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/cli_build.h"
#include "cli/cli_calibrate.h"
#include "cli/cli_front.h"
#include "cli/cli_help.h"
#include "cli/cli_sens.h"
#include "cli/cli_solve.h"
#include "cli/cli_summary.h"
#include "cli/cli_validate.h"
#include "pdf/doc.h"
#include "util/xalloc.h"

/* The commands this program runs; cli_help.c documents them. */
struct command {
	const char *name;
	int (*run)(int argc, char **argv);  /* argv[0] is the command name */
};

static const struct command commands[] = {
	{ "build", cli_build },
	{ "solve", cli_solve },
	{ "check", cli_check },
	{ "schema", cli_schema },
	{ "validate", cli_validate },
	{ "calibrate", cli_calibrate },
	{ "sensitivity", cli_sensitivity },
	{ "summary", cli_summary },
};

static int
is_help(const char *a)
{
	return strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0;
}

/* Runs the command argv names; returns its exit status. */
static int
run(int argc, char **argv)
{
	if (argc < 2) {
		cli_help_overview(stderr);
		return 2;
	}
	const char *cmd = argv[1];
	if (strcmp(cmd, "--version") == 0) {
		cli_help_version(stdout);
		return 0;
	}
	if (is_help(cmd) || (strcmp(cmd, "help") == 0 && argc == 2)) {
		cli_help_overview(stdout);
		return 0;
	}
	if (strcmp(cmd, "help") == 0) {
		if (cli_help_command(argv[2], stdout) == 0)
			return 0;
		fprintf(stderr, "aeroeval: no command \"%s\"; 'aeroeval --help' lists them\n",
		        argv[2]);
		return 2;
	}
	if (argc >= 3 && is_help(argv[2]) && cli_help_command(cmd, stdout) == 0)
		return 0;
	for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
		if (strcmp(cmd, commands[i].name) == 0)
			return commands[i].run(argc - 1, argv + 1);
	fprintf(stderr, "aeroeval: no command \"%s\"; 'aeroeval --help' lists them\n", cmd);
	return 2;
}

int
main(int argc, char **argv)
{
	atexit(doc_global_cleanup); /* cairo's static data: a valgrind-clean exit */
	/* Every command's output is checked once here, after its last write. */
	return cli_close_stdout(run(argc, argv));
}
