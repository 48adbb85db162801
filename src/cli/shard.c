/* shard.c — a deterministic share of the missions (see shard.h). */
#include "cli/shard.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "util/sha256.h"

/* A whole number of at most 9 decimal digits, nothing else; -1 otherwise. */
static long
parse_count(const char *s, size_t len)
{
	if (len == 0 || len > 9)
		return -1;
	long v = 0;
	for (size_t i = 0; i < len; i++) {
		if (s[i] < '0' || s[i] > '9')
			return -1;
		v = 10 * v + (s[i] - '0');
	}
	return v;
}

int
shard_parse(const char *s, struct shard *out, char *err, size_t errlen)
{
	const char *slash = strchr(s, '/');
	long k = slash ? parse_count(s, (size_t)(slash - s)) : -1;
	long n = slash ? parse_count(slash + 1, strlen(slash + 1)) : -1;
	if (k < 0 || n < 0) {
		snprintf(err, errlen, "--shard wants K/N, two whole numbers such as 2/3 "
		    "(got \"%s\")", s);
		return -1;
	}
	if (n < 1 || n > SHARD_MAX || k < 1 || k > n) {
		snprintf(err, errlen, "--shard %s: K/N needs 1 <= K <= N <= %d", s, SHARD_MAX);
		return -1;
	}
	out->k = (unsigned)k;
	out->n = (unsigned)n;
	return 0;
}

unsigned
shard_of(const char *name, unsigned n)
{
	unsigned char d[SHA256_DIGEST_LEN];
	struct sha256_ctx c;
	sha256_init(&c);
	sha256_update(&c, name, strlen(name));
	sha256_final(&c, d);
	uint64_t h = 0;
	for (int i = 0; i < 8; i++)
		h = h << 8 | d[i];
	return n > 0 ? 1u + (unsigned)(h % n) : 1u;
}

bool
shard_has(const struct shard *sh, const char *name)
{
	return sh->n == 0 || shard_of(name, sh->n) == sh->k;
}
