/* Shared by the libFuzzer targets (tests/fuzz, README.md there): a counting allocator that the
 * targets use to prove nothing leaks on any path, and the one way a target reports a broken
 * property (abort, which libFuzzer records as a crash with the input). */
#ifndef TL_FUZZ_COMMON_H
#define TL_FUZZ_COMMON_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "thinlight/base.h"

typedef struct fuzz_counter {
    long live;
} fuzz_counter;

static inline void *fuzz_alloc(size_t size, void *user)
{
    fuzz_counter *c = (fuzz_counter *)user;
    void *p = malloc(size);
    if (p) c->live++;
    return p;
}

static inline void fuzz_free(void *ptr, void *user)
{
    fuzz_counter *c = (fuzz_counter *)user;
    if (ptr) c->live--;
    free(ptr);
}

/* A property every input must keep; a broken one aborts with the reason. */
#define FUZZ_REQUIRE(cond)                                                                          \
    do {                                                                                            \
        if (!(cond)) {                                                                              \
            fprintf(stderr, "%s:%d: property broken: %s\n", __FILE__, __LINE__, #cond);             \
            abort();                                                                                \
        }                                                                                           \
    } while (0)

/* The logger: every message must be one line. */
static inline void fuzz_log(void *user, tl_log_level level, const char *message)
{
    (void)user;
    (void)level;
    for (const char *p = message; *p; p++) FUZZ_REQUIRE(*p != '\n' && *p != '\r');
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#endif
