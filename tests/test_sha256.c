/* test_sha256.c — SHA-256 against the FIPS 180-4 / NIST example vectors. */
#include "test_util.h"
#include "util/sha256.h"

#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void
hex_of(const unsigned char d[SHA256_DIGEST_LEN], char out[SHA256_HEX_LEN])
{
	for (int i = 0; i < SHA256_DIGEST_LEN; i++)
		snprintf(out + 2 * i, 3, "%02x", d[i]);
}

static void
sha256_should_hash_the_empty_message(void **state)
{
	(void)state;
	char h[SHA256_HEX_LEN];
	sha256_hex(NULL, 0, h);
	assert_string_equal(h, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

static void
sha256_should_hash_abc(void **state)
{
	(void)state;
	char h[SHA256_HEX_LEN];
	sha256_hex("abc", 3, h);
	assert_string_equal(h, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

static void
sha256_should_hash_the_448_bit_message_across_two_blocks(void **state)
{
	(void)state;
	/* 56 bytes: the padding does not fit, so a second block is needed. */
	const char *m = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
	char h[SHA256_HEX_LEN];
	sha256_hex(m, strlen(m), h);
	assert_string_equal(h, "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

static void
sha256_should_hash_one_million_a(void **state)
{
	(void)state;
	char *m = malloc(1000000);
	assert_non_null(m);
	memset(m, 'a', 1000000);
	char h[SHA256_HEX_LEN];
	sha256_hex(m, 1000000, h);
	assert_string_equal(h, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
	free(m);
}

static void
sha256_updates_should_not_depend_on_the_split(void **state)
{
	(void)state;
	/* The 896-bit NIST message, fed in pieces of 1, 3, 7, 64, 13, ...
	 * bytes so that partial blocks, exact blocks and straddles all occur. */
	const char *m = "abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmn"
	                "hijklmnoijklmnopjklmnopqklmnopqrlmnopqrsmnopqrstnopqrstu";
	const char *want = "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1";
	size_t n = strlen(m);
	assert_int_equal(n, 112);
	static const size_t pieces[] = { 1, 3, 7, 64, 13, 0, 24 };
	struct sha256_ctx c;
	sha256_init(&c);
	size_t at = 0;
	for (size_t i = 0; i < sizeof pieces / sizeof pieces[0]; i++) {
		sha256_update(&c, m + at, pieces[i]);
		at += pieces[i];
	}
	assert_int_equal(at, n);
	unsigned char d[SHA256_DIGEST_LEN];
	char h[SHA256_HEX_LEN];
	sha256_final(&c, d);
	hex_of(d, h);
	assert_string_equal(h, want);

	/* Byte by byte gives the same answer. */
	sha256_init(&c);
	for (size_t i = 0; i < n; i++)
		sha256_update(&c, m + i, 1);
	sha256_final(&c, d);
	hex_of(d, h);
	assert_string_equal(h, want);
}

static void
sha256_update_fd_should_hash_a_file_of_any_size_whole(void **state)
{
	(void)state;
	/* One million 'a' through a file gives the NIST digest. */
	char path[] = "/tmp/aeroeval-sha256-XXXXXX";
	int fd = mkstemp(path);
	assert_true(fd >= 0);
	unlink(path);
	char *m = malloc(1000000);
	assert_non_null(m);
	memset(m, 'a', 1000000);
	assert_int_equal(write(fd, m, 1000000), 1000000);
	free(m);
	assert_int_equal(lseek(fd, 0, SEEK_SET), 0);
	struct sha256_ctx c;
	unsigned char d[SHA256_DIGEST_LEN];
	char h[SHA256_HEX_LEN];
	uint64_t n = 0;
	sha256_init(&c);
	assert_int_equal(sha256_update_fd(&c, fd, &n), 0);
	assert_int_equal(n, 1000000);
	sha256_final(&c, d);
	hex_of(d, h);
	assert_string_equal(h, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");

	/* 70 MiB (sparse) whose last byte differs from all zeros: past the
	 * old 64 MiB cut-off, that byte must still change the digest. */
	const off_t big = (off_t)70 << 20;
	char zeros_hex[SHA256_HEX_LEN], last_hex[SHA256_HEX_LEN];
	assert_int_equal(ftruncate(fd, 0), 0);
	assert_int_equal(ftruncate(fd, big), 0);
	assert_int_equal(lseek(fd, 0, SEEK_SET), 0);
	sha256_init(&c);
	assert_int_equal(sha256_update_fd(&c, fd, &n), 0);
	assert_true(n == (uint64_t)big);
	sha256_final(&c, d);
	hex_of(d, zeros_hex);
	assert_int_equal(pwrite(fd, "x", 1, big - 1), 1);
	assert_int_equal(lseek(fd, 0, SEEK_SET), 0);
	sha256_init(&c);
	assert_int_equal(sha256_update_fd(&c, fd, NULL), 0);
	sha256_final(&c, d);
	hex_of(d, last_hex);
	assert_string_not_equal(zeros_hex, last_hex);
	close(fd);

	/* A read error is reported, not hashed as an empty file. */
	sha256_init(&c);
	assert_int_equal(sha256_update_fd(&c, -1, &n), -1);
}

int
main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sha256_should_hash_the_empty_message),
		cmocka_unit_test(sha256_should_hash_abc),
		cmocka_unit_test(sha256_should_hash_the_448_bit_message_across_two_blocks),
		cmocka_unit_test(sha256_should_hash_one_million_a),
		cmocka_unit_test(sha256_updates_should_not_depend_on_the_split),
		cmocka_unit_test(sha256_update_fd_should_hash_a_file_of_any_size_whole),
	};
	return cmocka_run_group_tests_name("sha256", tests, NULL, NULL);
}
