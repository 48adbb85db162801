/* shard.h — which missions one of N machines compiles (`build --shard K/N`).
 *
 * A study too large for one machine is split by an existing scheduler (GNU
 * Parallel, a Slurm job array): every machine runs the same build with its
 * own K and writes into one shared output folder.  The machines never talk
 * to each other, so the split must be a pure function of what each one
 * sees: a mission belongs to shard 1 + (h mod N), h the first eight bytes
 * (big-endian) of the SHA-256 of its output name (its file's base name
 * without ".json").  Adding or removing other missions moves no mission to
 * another shard, and two files of one name (which would clash in one
 * output folder) always land on the same machine, where the clash is
 * reported.
 *
 * CLI layer.  No state: plain functions over a struct shard value.
 */
#ifndef AEROEVAL_SHARD_H
#define AEROEVAL_SHARD_H

#include <stdbool.h>
#include <stddef.h>

/* Largest N accepted: more machines than this is a typo. */
#define SHARD_MAX 100000

/* One share: k of n, 1 <= k <= n; n == 0 means no sharding (everything). */
struct shard {
	unsigned k;  /* this machine's share, 1-based */
	unsigned n;  /* number of shares */
};

/* Parses "K/N" (decimal digits only, 1 <= K <= N <= SHARD_MAX) into *out.
 * Returns 0, or -1 with a message for "--shard: ..." in err (no trailing
 * newline), *out untouched. */
int shard_parse(const char *s, struct shard *out, char *err, size_t errlen);

/* The 1-based shard of a mission named name among n (n >= 1). */
unsigned shard_of(const char *name, unsigned n);

/* True when the mission named name belongs to sh (always, when sh->n == 0). */
bool shard_has(const struct shard *sh, const char *name);

#endif
