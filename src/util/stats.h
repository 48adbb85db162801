/* stats.h — accuracy statistics for predicted vs actual masses.
 *
 * For the `validate` and `calibrate` commands.  Inputs are parallel arrays
 * actual[i], predicted[i] (kg, or any positive quantity; the _kg names
 * follow the main use).  Every value must be finite and > 0: a function
 * given anything else returns -1, leaves its outputs zeroed, and so can
 * never pass NaN on.  n = 0 and n = 1 are valid and documented per
 * function.  Definitions (i over the n pairs):
 *	APE_i  = 100 |p_i - a_i| / a_i            (percent of the actual)
 *	MAPE   = mean APE_i
 *	RMSE   = sqrt(mean (p_i - a_i)^2)         (kg)
 *	k_i    = a_i / p_i                        (the factor that would fix p_i)
 *	sd     = sample standard deviation, divisor n - 1
 * Nothing here keeps state between calls; the random generator is a value
 * owned by the caller, so results are reproducible from the seed alone.
 */
#ifndef AEROEVAL_STATS_H
#define AEROEVAL_STATS_H

#include <stddef.h>
#include <stdint.h>

struct stats_summary {
	size_t n;               /* pairs summarised */
	double mape_pct;        /* mean absolute percentage error; 0 if n = 0 */
	double median_ape_pct;  /* median APE (mean of the middle two for even n); 0 if n = 0 */
	double rmse_kg;         /* root-mean-square error; 0 if n = 0 */
	double k_mean;          /* mean of k_i = actual/predicted; 0 if n = 0 */
	double k_sd;            /* sample sd of k_i; 0 if n < 2 */
};

/* Fills *out with the summary above.  Returns 0, or -1 (out zeroed) when a
 * value is not finite and > 0.  Allocates a scratch copy for the median. */
int stats_summarize(const double *actual_kg, const double *predicted_kg,
                    size_t n, struct stats_summary *out);

/* Signed errors per pair, predicted minus actual: err_kg[i] = p_i - a_i and
 * err_pct[i] = 100 (p_i - a_i) / a_i (positive = over-prediction).  Either
 * output may be NULL.  Returns 0, or -1 (outputs zeroed) on a bad value. */
int stats_signed_errors(const double *actual_kg, const double *predicted_kg,
                        size_t n, double *err_kg, double *err_pct);

/* The p-quantile (0 <= p <= 1) of sorted[0..n) by linear interpolation
 * between order statistics (Hyndman & Fan type 7, the R and NumPy
 * default): h = (n - 1) p, q = x[floor h] + (h - floor h)(x[floor h + 1] -
 * x[floor h]).  Returns 0 for n = 0; p is clamped to [0, 1]. */
double stats_quantile_sorted(const double *sorted, size_t n, double p);

/* A small fast generator: xoshiro256** seeded through splitmix64 (both by
 * Blackman and Vigna).  Not for cryptography.  A plain value: copy it to
 * fork a stream, and never share one between threads. */
struct stats_rng {
	uint64_t s[4]; /* xoshiro256 state, never all zero */
};

/* Seeds r from one 64-bit seed; every seed (0 included) is fine. */
void stats_rng_seed(struct stats_rng *r, uint64_t seed);

/* The next 64 random bits. */
uint64_t stats_rng_next(struct stats_rng *r);

/* A uniform integer in [0, bound), without modulo bias (rejection).
 * bound = 0 returns 0. */
uint64_t stats_rng_below(struct stats_rng *r, uint64_t bound);

/* A uniform double in [lo, hi). */
double stats_rng_uniform(struct stats_rng *r, double lo, double hi);

/* Bootstrap 95 % confidence interval of the MAPE, percentile method: draw
 * n_resamples resamples of the n pairs with replacement (generator seeded
 * with `seed`), take the MAPE of each, and report the 2.5 % and 97.5 %
 * quantiles (type 7, see stats_quantile_sorted) in *lo_pct and *hi_pct.
 * n = 0 gives 0, 0; n = 1 or n_resamples = 0 gives the point MAPE twice.
 * Returns 0, or -1 (outputs 0) on a bad value.  Allocates n_resamples
 * doubles of scratch. */
int stats_bootstrap_mape_ci(const double *actual_kg, const double *predicted_kg,
                            size_t n, size_t n_resamples, uint64_t seed,
                            double *lo_pct, double *hi_pct);

/* The MAPE of one group of rows that share a key. */
struct stats_group {
	const char *key;  /* borrowed from the caller's keys[]: keep them alive */
	size_t n;         /* rows in the group, >= 1 */
	double mape_pct;  /* MAPE over the group's rows */
};

/* Groups the pairs by keys[i] (compared with strcmp; NULL is not allowed,
 * use "" for "no group") and computes each group's MAPE.  *out receives
 * *n_groups groups sorted by key (byte order), allocated with xmalloc; the
 * caller frees it with free().  n = 0 gives *out = NULL, *n_groups = 0.
 * Returns 0, or -1 (*out NULL, *n_groups 0) on a bad value. */
int stats_group_mape(const char *const *keys, const double *actual_kg,
                     const double *predicted_kg, size_t n,
                     struct stats_group **out, size_t *n_groups);

#endif
