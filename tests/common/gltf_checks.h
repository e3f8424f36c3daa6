/* What the glTF tests (tests/io, tests/input) share: loading a fixture written by gltf_fixtures.h
 * into TL_GLTF_TEST_DIR/<test name> with a capturing logger and a counting allocator, the checks
 * every load makes, and the invariants of a loaded scene. */
#ifndef TL_GLTF_CHECKS_H
#define TL_GLTF_CHECKS_H

#include <stddef.h>

#include "gltf_fixtures.h"
#include "thinlight/io.h"
#include "thinlight/scene.h"
#include "tl_test.h"

/* The logger: counts, keeps the last error and all warnings, and checks one line per message. */
typedef struct capture {
    int errors, warnings, multiline;
    char last_error[1024];
    char warnings_text[8192];
} capture;
void capture_fn(void *user, tl_log_level level, const char *message);

/* Counts live allocations; fails the fail_at-th call (1-based) when set. */
typedef struct counter {
    long live;
    size_t calls, fail_at;
} counter;

void *count_alloc(size_t size, void *user);
void count_free(void *ptr, void *user);

/* Makes the test's directory TL_GLTF_TEST_DIR/<test>; its path into `out`. */
void case_dir(char *out, size_t n, const char *test);
/* Writes fixture `fixture` into the test's directory; its path into `path`. */
int fixture(const char *test, const char *fixture_name, char *path, size_t n);

/* One load: its result and scene, what the logger and the allocator saw, the error text. */
typedef struct loaded {
    tl_result result;
    tl_scene *scene;
    capture log;
    counter count;
    char error[1024];
    char path[1024];
} loaded;

/* Loads with a capture logger and a counting allocator on top of `base` options, and checks what
 * every load promises: one-line messages; on failure no scene, nothing allocated left, one error
 * that starts with the file; on success no error. */
void load_opts(loaded *l, const char *test, const char *fixture_name, const tl_gltf_options *base);
void load(loaded *l, const char *test, const char *fixture_name);
/* Destroys the scene; checks that every allocation was freed. */
void unload(loaded *l);
/* Expects failure `want` whose message contains `needle` (may be NULL). */
void expect_failure(const char *test, const char *fixture_name, tl_result want, const char *needle);

int near(float a, float b, float tol);
int near3(const float *a, float x, float y, float z, float tol);
float len3(const float v[3]);
float dot3f(const float a[3], const float b[3]);
/* Every index in range, every vertex finite with a unit normal, every reference valid. */
void check_geometry(const tl_scene *s);
/* Unit tangents orthogonal to their normals, w = +-1, for vertices [first, first + count). */
void check_tangents(const tl_scene *s, size_t first, size_t count);

#endif
