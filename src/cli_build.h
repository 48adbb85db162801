/* cli_build.h — `aeroeval build`: compile missions into DIR/<name>/. */
#ifndef AEROEVAL_CLI_BUILD_H
#define AEROEVAL_CLI_BUILD_H

/* argv[0] is "build".  Exit status: the worst mission outcome (PRODUCT.md §2). */
int cli_build(int argc, char **argv);

#endif
