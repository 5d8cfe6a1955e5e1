/*
 * sha256.h - a small SHA-256 (FIPS 180-4) for the tests: tree hashes
 * (test_hashes.c) without a dependency on a crypto library.
 */
#ifndef ATRBVH_TEST_SHA256_H
#define ATRBVH_TEST_SHA256_H

#include <stddef.h>
#include <stdint.h>

typedef struct sha256_ctx {
    uint32_t h[8];
    uint64_t length;        /* bytes hashed so far */
    unsigned char block[64];
    size_t used;            /* bytes waiting in block */
} sha256_ctx;

void sha256_init(sha256_ctx *c);
void sha256_update(sha256_ctx *c, const void *data, size_t n);
/* The 32-byte digest; c must be initialised again before reuse. */
void sha256_final(sha256_ctx *c, unsigned char digest[32]);
/* The digest as 64 lower-case hex digits and a NUL. */
void sha256_hex(const unsigned char digest[32], char hex[65]);

#endif
