/* sha256.c — SHA-256 from FIPS 180-4 §4.1.2, §4.2.2, §5.1.1, §6.2. */
#include "util/sha256.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

/* §4.2.2: the first 32 bits of the fractional parts of the cube roots of
 * the first 64 primes. */
static const uint32_t K[64] = {
	0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1,
	0x923f82a4, 0xab1c5ed5, 0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3,
	0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786,
	0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
	0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147,
	0x06ca6351, 0x14292967, 0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13,
	0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85, 0xa2bfe8a1, 0xa81a664b,
	0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
	0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a,
	0x5b9cca4f, 0x682e6ff3, 0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208,
	0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2,
};

static uint32_t
rotr(uint32_t x, unsigned n)
{
	return (x >> n) | (x << (32 - n));
}

/* §4.1.2 functions. */
/* Ch and Maj are written in equivalent forms with one operation fewer
 * (Ch picks z where x is 0: ((y ^ z) & x) ^ z; Maj is 1 where two of three
 * are: (x & y) | (z & (x | y))), and the big sigmas as nested rotations
 * (rotr(rotr(rotr(x, 9) ^ x, 11) ^ x, 2) is x rotated by 22, 13 and 2,
 * xored): the same values in about 30 instructions a round instead of 37. */
#define CH(x, y, z)  ((((y) ^ (z)) & (x)) ^ (z))
#define MAJ(x, y, z) (((x) & (y)) | ((z) & ((x) | (y))))
#define BSIG0(x) rotr(rotr(rotr((x), 9) ^ (x), 11) ^ (x), 2)
#define BSIG1(x) rotr(rotr(rotr((x), 14) ^ (x), 5) ^ (x), 6)
#define SSIG0(x) (rotr((x), 7) ^ rotr((x), 18) ^ ((x) >> 3))
#define SSIG1(x) (rotr((x), 17) ^ rotr((x), 19) ^ ((x) >> 10))

/* One round of §6.2.2 step 3 on the working variables named in the
 * arguments.  Instead of shifting all eight variables down by one each
 * round, the caller rotates the names: after the round, h holds the new a
 * and d the new e, so the next round passes (h, a, b, c, d, e, f, g). */
#define ROUND(a, b, c, d, e, f, g, h, t)                                  \
	do {                                                              \
		uint32_t t1 = (h) + BSIG1(e) + CH(e, f, g) + K[t] + w[t]; \
		(d) += t1;                                                \
		(h) = t1 + BSIG0(a) + MAJ(a, b, c);                       \
	} while (0)

/* §6.2.2: one 512-bit block.  Words are big-endian regardless of host. */
static void
compress(uint32_t h[8], const unsigned char *p)
{
	uint32_t w[64];
	for (int t = 0; t < 16; t++)
		w[t] = (uint32_t)p[4 * t] << 24 | (uint32_t)p[4 * t + 1] << 16 |
		       (uint32_t)p[4 * t + 2] << 8 | (uint32_t)p[4 * t + 3];
	for (int t = 16; t < 64; t++)
		w[t] = SSIG1(w[t - 2]) + w[t - 7] + SSIG0(w[t - 15]) + w[t - 16];

	uint32_t a = h[0], b = h[1], c = h[2], d = h[3];
	uint32_t e = h[4], f = h[5], g = h[6], hh = h[7];
	/* Eight rounds per pass bring the names back to where they started. */
	for (int t = 0; t < 64; t += 8) {
		ROUND(a, b, c, d, e, f, g, hh, t);
		ROUND(hh, a, b, c, d, e, f, g, t + 1);
		ROUND(g, hh, a, b, c, d, e, f, t + 2);
		ROUND(f, g, hh, a, b, c, d, e, t + 3);
		ROUND(e, f, g, hh, a, b, c, d, t + 4);
		ROUND(d, e, f, g, hh, a, b, c, t + 5);
		ROUND(c, d, e, f, g, hh, a, b, t + 6);
		ROUND(b, c, d, e, f, g, hh, a, t + 7);
	}
	h[0] += a; h[1] += b; h[2] += c; h[3] += d;
	h[4] += e; h[5] += f; h[6] += g; h[7] += hh;
}

void
sha256_init(struct sha256_ctx *c)
{
	/* §5.3.3: fractional parts of the square roots of the first 8 primes. */
	static const uint32_t h0[8] = {
		0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
		0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19,
	};
	memcpy(c->h, h0, sizeof h0);
	c->n_bytes = 0;
	c->n_block = 0;
}

void
sha256_update(struct sha256_ctx *c, const void *data, size_t n)
{
	const unsigned char *p = data;
	if (n == 0) /* data may be NULL then; memcpy(NULL, 0) is undefined */
		return;
	c->n_bytes += n;
	if (c->n_block > 0) {
		size_t take = 64 - c->n_block;
		if (take > n)
			take = n;
		memcpy(c->block + c->n_block, p, take);
		c->n_block += take;
		p += take;
		n -= take;
		if (c->n_block < 64)
			return;
		compress(c->h, c->block);
		c->n_block = 0;
	}
	for (; n >= 64; p += 64, n -= 64)
		compress(c->h, p);
	if (n > 0)
		memcpy(c->block, p, n);
	c->n_block = n;
}

void
sha256_final(struct sha256_ctx *c, unsigned char out[SHA256_DIGEST_LEN])
{
	/* §5.1.1: a 1 bit, zeros up to 56 mod 64 bytes, then the message
	 * length in bits as a 64-bit big-endian integer. */
	uint64_t bits = c->n_bytes * 8;
	c->block[c->n_block++] = 0x80;
	if (c->n_block > 56) {
		memset(c->block + c->n_block, 0, 64 - c->n_block);
		compress(c->h, c->block);
		c->n_block = 0;
	}
	memset(c->block + c->n_block, 0, 56 - c->n_block);
	for (int i = 0; i < 8; i++)
		c->block[56 + i] = (unsigned char)(bits >> (56 - 8 * i));
	compress(c->h, c->block);
	for (int i = 0; i < 8; i++) {
		out[4 * i] = (unsigned char)(c->h[i] >> 24);
		out[4 * i + 1] = (unsigned char)(c->h[i] >> 16);
		out[4 * i + 2] = (unsigned char)(c->h[i] >> 8);
		out[4 * i + 3] = (unsigned char)c->h[i];
	}
}

int
sha256_update_fd(struct sha256_ctx *c, int fd, uint64_t *n_read)
{
	/* 64 KiB: large enough that read(2) calls cost nothing next to the
	 * compression, small enough for any stack. */
	unsigned char buf[1 << 16];
	uint64_t total = 0;
	for (;;) {
		ssize_t k = read(fd, buf, sizeof buf);
		if (k < 0 && errno == EINTR)
			continue;
		if (k < 0)
			return -1;
		if (k == 0)
			break;
		sha256_update(c, buf, (size_t)k);
		total += (uint64_t)k;
	}
	if (n_read != NULL)
		*n_read = total;
	return 0;
}

void
sha256_to_hex(const unsigned char d[SHA256_DIGEST_LEN], char out[SHA256_HEX_LEN])
{
	static const char hex[] = "0123456789abcdef";
	for (int i = 0; i < SHA256_DIGEST_LEN; i++) {
		out[2 * i] = hex[d[i] >> 4];
		out[2 * i + 1] = hex[d[i] & 15];
	}
	out[64] = '\0';
}

void
sha256_hex(const void *data, size_t n, char out[SHA256_HEX_LEN])
{
	struct sha256_ctx c;
	unsigned char d[SHA256_DIGEST_LEN];
	sha256_init(&c);
	sha256_update(&c, data, n);
	sha256_final(&c, d);
	sha256_to_hex(d, out);
}
