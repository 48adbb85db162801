/* stats.c — MAPE, median APE, RMSE, k-factor, bootstrap CI (see stats.h). */
#include "util/stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/xalloc.h"

/* Every value must be finite and > 0: APE divides by the actual, k by the
 * prediction. */
static int
pairs_ok(const double *a, const double *p, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (!(isfinite(a[i]) && a[i] > 0 && isfinite(p[i]) && p[i] > 0))
			return 0;
	return 1;
}

static double
ape_pct(double a, double p)
{
	return 100.0 * fabs(p - a) / a;
}

static int
cmp_double(const void *x, const void *y)
{
	double a = *(const double *)x, b = *(const double *)y;
	return (a > b) - (a < b);
}

double
stats_quantile_sorted(const double *sorted, size_t n, double p)
{
	if (n == 0)
		return 0.0;
	if (!(p > 0))   /* also NaN */
		p = 0;
	if (p > 1)
		p = 1;
	double h = (double)(n - 1) * p;
	size_t lo = (size_t)h;
	if (lo + 1 >= n)
		return sorted[n - 1];
	return sorted[lo] + (h - (double)lo) * (sorted[lo + 1] - sorted[lo]);
}

int
stats_summarize(const double *actual_kg, const double *predicted_kg,
                size_t n, struct stats_summary *out)
{
	memset(out, 0, sizeof *out);
	if (!pairs_ok(actual_kg, predicted_kg, n))
		return -1;
	out->n = n;
	if (n == 0)
		return 0;

	double *ape = xmalloc(n * sizeof *ape);
	double sum_ape = 0, sum_sq = 0, sum_k = 0;
	for (size_t i = 0; i < n; i++) {
		double e = predicted_kg[i] - actual_kg[i];
		ape[i] = ape_pct(actual_kg[i], predicted_kg[i]);
		sum_ape += ape[i];
		sum_sq += e * e;
		sum_k += actual_kg[i] / predicted_kg[i];
	}
	out->mape_pct = sum_ape / (double)n;
	out->rmse_kg = sqrt(sum_sq / (double)n);
	out->k_mean = sum_k / (double)n;
	if (n >= 2) {
		/* Two passes: the mean first, then squared deviations from it,
		 * which is exact enough and needs no running-variance trick. */
		double ss = 0;
		for (size_t i = 0; i < n; i++) {
			double d = actual_kg[i] / predicted_kg[i] - out->k_mean;
			ss += d * d;
		}
		out->k_sd = sqrt(ss / (double)(n - 1));
	}
	qsort(ape, n, sizeof *ape, cmp_double);
	out->median_ape_pct = stats_quantile_sorted(ape, n, 0.5);
	free(ape);
	return 0;
}

int
stats_signed_errors(const double *actual_kg, const double *predicted_kg,
                    size_t n, double *err_kg, double *err_pct)
{
	int ok = pairs_ok(actual_kg, predicted_kg, n);
	for (size_t i = 0; i < n; i++) {
		double e = ok ? predicted_kg[i] - actual_kg[i] : 0.0;
		if (err_kg != NULL)
			err_kg[i] = e;
		if (err_pct != NULL)
			err_pct[i] = ok ? 100.0 * e / actual_kg[i] : 0.0;
	}
	return ok ? 0 : -1;
}

/* splitmix64: one step of a Weyl sequence through a 64-bit mixer.  Used
 * only to spread a user seed over the xoshiro state. */
static uint64_t
splitmix64(uint64_t *x)
{
	uint64_t z = (*x += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

void
stats_rng_seed(struct stats_rng *r, uint64_t seed)
{
	for (int i = 0; i < 4; i++)
		r->s[i] = splitmix64(&seed);
	/* splitmix64 is a bijection of distinct counters, so four outputs
	 * cannot all be zero; the state is valid for xoshiro. */
}

static uint64_t
rotl(uint64_t x, int k)
{
	return (x << k) | (x >> (64 - k));
}

uint64_t
stats_rng_next(struct stats_rng *r)
{
	uint64_t *s = r->s;
	uint64_t result = rotl(s[1] * 5, 7) * 9;
	uint64_t t = s[1] << 17;
	s[2] ^= s[0];
	s[3] ^= s[1];
	s[1] ^= s[2];
	s[0] ^= s[3];
	s[2] ^= t;
	s[3] = rotl(s[3], 45);
	return result;
}

uint64_t
stats_rng_below(struct stats_rng *r, uint64_t bound)
{
	if (bound == 0)
		return 0;
	/* Values below 2^64 mod bound would make the low residues more
	 * likely; draw again instead (at most half the draws for any bound). */
	uint64_t threshold = (0 - bound) % bound;
	for (;;) {
		uint64_t x = stats_rng_next(r);
		if (x >= threshold)
			return x % bound;
	}
}

double
stats_rng_uniform(struct stats_rng *r, double lo, double hi)
{
	/* The top 53 bits: every double of [0, 1) on the 2^-53 grid. */
	return lo + (hi - lo) * (double)(stats_rng_next(r) >> 11) * 0x1.0p-53;
}

int
stats_bootstrap_mape_ci(const double *actual_kg, const double *predicted_kg,
                        size_t n, size_t n_resamples, uint64_t seed,
                        double *lo_pct, double *hi_pct)
{
	*lo_pct = 0;
	*hi_pct = 0;
	if (!pairs_ok(actual_kg, predicted_kg, n))
		return -1;
	if (n == 0)
		return 0;
	if (n == 1 || n_resamples == 0) {
		/* One row resamples to itself; no resamples means no spread. */
		double m = 0;
		for (size_t i = 0; i < n; i++)
			m += ape_pct(actual_kg[i], predicted_kg[i]);
		*lo_pct = *hi_pct = m / (double)n;
		return 0;
	}

	struct stats_rng rng;
	stats_rng_seed(&rng, seed);
	double *mape = xmalloc(n_resamples * sizeof *mape);
	for (size_t b = 0; b < n_resamples; b++) {
		double sum = 0;
		for (size_t j = 0; j < n; j++) {
			size_t i = (size_t)stats_rng_below(&rng, n);
			sum += ape_pct(actual_kg[i], predicted_kg[i]);
		}
		mape[b] = sum / (double)n;
	}
	qsort(mape, n_resamples, sizeof *mape, cmp_double);
	*lo_pct = stats_quantile_sorted(mape, n_resamples, 0.025);
	*hi_pct = stats_quantile_sorted(mape, n_resamples, 0.975);
	free(mape);
	return 0;
}

/* qsort context-free comparison of row indices by key: the keys travel
 * with the index in a small pair. */
struct keyed {
	const char *key;
	size_t i;
};

static int
cmp_keyed(const void *x, const void *y)
{
	const struct keyed *a = x, *b = y;
	int c = strcmp(a->key, b->key);
	if (c != 0)
		return c;
	/* Ties in file order, so sums add in a fixed order on every libc. */
	return (a->i > b->i) - (a->i < b->i);
}

int
stats_group_mape(const char *const *keys, const double *actual_kg,
                 const double *predicted_kg, size_t n,
                 struct stats_group **out, size_t *n_groups)
{
	*out = NULL;
	*n_groups = 0;
	if (!pairs_ok(actual_kg, predicted_kg, n))
		return -1;
	if (n == 0)
		return 0;

	struct keyed *order = xmalloc(n * sizeof *order);
	for (size_t i = 0; i < n; i++) {
		order[i].key = keys[i];
		order[i].i = i;
	}
	qsort(order, n, sizeof *order, cmp_keyed);

	struct stats_group *g = xmalloc(n * sizeof *g); /* at most n groups */
	size_t k = 0;
	for (size_t j = 0; j < n; ) {
		double sum = 0;
		size_t start = j;
		for (; j < n && strcmp(order[j].key, order[start].key) == 0; j++)
			sum += ape_pct(actual_kg[order[j].i], predicted_kg[order[j].i]);
		g[k].key = order[start].key;
		g[k].n = j - start;
		g[k].mape_pct = sum / (double)g[k].n;
		k++;
	}
	free(order);
	*out = g;
	*n_groups = k;
	return 0;
}
