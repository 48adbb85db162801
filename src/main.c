/* main.c — argv, subcommand dispatch, exit status.  Drives; computes nothing. */
#include <stdio.h>
#include <string.h>

#include "cli_build.h"
#include "cli_front.h"
#include "cli_sens.h"
#include "cli_solve.h"
#include "cli_validate.h"

int
main(int argc, char **argv)
{
	if (argc >= 2 && strcmp(argv[1], "--version") == 0) {
		printf("aeroeval %s\n", AEROEVAL_VERSION);
		return 0;
	}
	if (argc >= 2 && strcmp(argv[1], "check") == 0)
		return cli_check(argc - 1, argv + 1);
	if (argc >= 2 && strcmp(argv[1], "schema") == 0)
		return cli_schema(argc - 1, argv + 1);
	if (argc >= 2 && strcmp(argv[1], "build") == 0)
		return cli_build(argc - 1, argv + 1);
	if (argc >= 2 && strcmp(argv[1], "solve") == 0)
		return cli_solve(argc - 1, argv + 1);
	if (argc >= 2 && strcmp(argv[1], "validate") == 0)
		return cli_validate(argc - 1, argv + 1);
	if (argc >= 2 && strcmp(argv[1], "calibrate") == 0)
		return cli_calibrate(argc - 1, argv + 1);
	if (argc >= 2 && strcmp(argv[1], "sensitivity") == 0)
		return cli_sensitivity(argc - 1, argv + 1);
	fprintf(stderr, "usage: aeroeval build|solve|check|schema|validate|calibrate|sensitivity ...\n");
	return 2;
}
