/* The renderer's GL device: the loaded context, the state cache (gl/state.h), the limits read once
 * at creation, the program cache (programs.c), the objects every pass shares (an empty vertex
 * array for full-screen triangles, a linear sampler), the per-frame stream, the allocator, the log
 * and the context check (context_check.c). Every other module of src/render takes it; it uses
 * nothing of theirs. */
#ifndef TL_RENDER_DEVICE_H
#define TL_RENDER_DEVICE_H

#include <threads.h>

#include "bindings.h"
#include "core/alloc.h"
#include "core/log.h"
#include "gl/gl.h"
#include "gl/state.h"
#include "gl/stream.h"
#include "permutation.h"
#include "platform/context_link.h"
#include "thinlight/renderer.h"

#define TL__OUTPUTS_KNOWN 4 /* framebuffers render_to checked and does not ask about again */
#define TL__LIGHT_BYTES 64u  /* one light of the lights storage block (lights.h, tl__light_record) */

/* What the context allows, read once at creation. */
typedef struct tl__limits {
    size_t ubo_align, ssbo_align;
    size_t storage_max;     /* bytes one storage block binding may hold (GL's, or the descriptor's lower one) */
    size_t max_lights;      /* TL_RENDERER_MAX_LIGHTS, or fewer when storage_max holds fewer */
    GLint max_texture_size; /* GL_MAX_TEXTURE_SIZE */
    /* the sample counts a multisampled target of every format the renderer multisamples can have
     * (bit n: n samples; GL_SAMPLES of glGetInternalformativ): a target asked for n samples gets
     * the smallest of these >= n, so the renderer asks for exactly that (tl__device_samples) */
    uint32_t sample_counts;
} tl__limits;

/* programs.c: permutations built on demand, cached by (sources, key, the pass's targets). */
typedef struct tl__program_src {
    const char *name; /* NULL ends the list */
    const char *vs, *fs;
    const char *cs;   /* a compute program instead */
} tl__program_src;
/* The targets a program's pass samples, writes as images and writes as colours: their units are 0,
 * 1, ... in tl_target_id order (TL_UNIT_<TARGET>, TL_IMAGE_<TARGET>), every other target's
 * TL_UNIT_NONE / TL_IMAGE_NONE; colour writes get TL_OUT_<TARGET> locations 0, 1, ... NULL: no
 * target (programs outside the frame graph). */
typedef struct tl__program_units {
    tl_target_set samples, images, writes;
} tl__program_units;
typedef struct tl__program_entry {
    GLuint program;
    /* what it was built for (compared whole, padding zeroed) */
    const tl__program_src *src;
    tl__perm key;
    tl__program_units units;
} tl__program_entry;

typedef struct tl__device {
    GladGLContext gl;
    tl__state state;
    tl_allocator alloc;
    tl__log log;
    tl__limits lim;
    tl__stream stream;       /* the frame's uniform blocks, per-object records, lights and lists */
    GLuint vao_empty;        /* full-screen triangles */
    GLuint sampler_linear;   /* passes that resample a target bilinearly */
    /* programs, cached by sources and defines for the renderer's life (programs.c) */
    tl__program_entry *cache;
    size_t cache_count, cache_capacity;
    uint32_t programs_compiled;
    /* the context check (context_check.c) */
    tl_get_proc_address_fn get_proc_address;
    void *get_proc_address_user;
    int (*is_current)(void *user); /* the descriptor's, or NULL: thinlight's own context, or the thread check */
    /* thinlight's own context (tl_context_proc_loader without is_current): linked to it, so that
     * its destruction before the renderer's is seen without reading the freed context */
    int own_context;
    tl__context_link context_link;
    thrd_t thread;                 /* the thread that last had the context (without is_current) */
    int thread_known;
    GLuint outputs_known[TL__OUTPUTS_KNOWN]; /* framebuffers render_to found complete */
    unsigned output_known_count, output_next;
} tl__device;

/* Records the message as the last error of `owner` (anything with a tl__log `log`), logs it,
 * returns res. */
#define tl__fail(owner, res, ...) tl__log_fail(&(owner)->log, (res), __VA_ARGS__)

/* device.c: loading GL through get_proc_address (nothing to free when it fails); the limits and
 * the shared objects; the device's GL objects freed. */
tl_result tl__device_load(tl__device *dev);
tl_result tl__device_init(tl__device *dev, const tl_renderer_desc *desc);
/* The samples a multisampled target asked for `asked` gets in this context (the smallest count of
 * lim.sample_counts >= asked), 1 for asked <= 1, 0 when the context has none that many. */
uint32_t tl__device_samples(const tl__device *dev, uint32_t asked);
void tl__device_release(tl__device *dev);

tl_result tl__program_get(tl__device *dev, const char *label, const tl__program_src *src, const tl__perm *key,
                          const tl__program_units *units, GLuint *out);
void tl__program_cache_destroy(tl__device *dev);

/* context_check.c: the device's context is current (the descriptor's is_current, thinlight's own
 * contexts, or one GL query when the calling thread changes); render_to's framebuffer. */
void tl__context_check_init(tl__device *dev, tl_is_current_fn is_current);
/* Takes the device off its own context's dependants (destroy); nothing for other contexts. */
void tl__context_check_release(tl__device *dev);
/* 1 when the device's own tl_context was destroyed before it: its GL objects are gone with it. */
int tl__context_gone(const tl__device *dev);
/* context_lost.c: the device's GL table made one whose deletions do nothing (the context is gone),
 * for the release steps of tl_renderer_destroy. */
void tl__device_lose(tl__device *dev);
int tl__context_current(tl__device *dev);
/* TL_ERROR_GL naming `call` when the context is not current. */
tl_result tl__need_context(tl__device *dev, const char *call);
/* TL_ERROR_INVALID_ARGUMENT for a framebuffer that does not exist or is not complete. */
tl_result tl__output_check(tl__device *dev, const tl_render_output *out);

/* stats.c: clocks. */
double tl__now_ms(void);
double tl__thread_cpu_ms(void); /* CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID) */

#endif
