/* The EGL back end and the back-end choice: device listing, surfaceless and device contexts, the
 * AUTO order, bad input, and the same pixels as OSMesa on the same llvmpipe in every render mode.
 * CI has no GPU: EGL is Mesa's (one software device, the surfaceless platform). */
#include <stdint.h>
#include <string.h>

#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tl_test.h"

#define GL_MAJOR_VERSION 0x821B
#define GL_MINOR_VERSION 0x821C
#define GL_CONTEXT_PROFILE_MASK 0x9126
#define GL_CONTEXT_CORE_PROFILE_BIT 0x1
typedef void (*get_integerv_fn)(unsigned int name, int *data);

#define MAX_DEVICES 16

typedef struct logged {
    int errors;
    char last[1024];
} logged;

static void keep_error(void *user, tl_log_level level, const char *message)
{
    if (level == TL_LOG_ERROR) snprintf((char *)user, 1024, "%s", message);
}

static void log_count(void *user, tl_log_level level, const char *message)
{
    logged *l = user;
    if (level == TL_LOG_ERROR) l->errors++;
    snprintf(l->last, sizeof l->last, "%s", message);
}

static size_t list_devices(tl_egl_device *devices)
{
    size_t count = 0;
    logged l = {0};
    tl_result r = tl_context_egl_devices(devices, MAX_DEVICES, &count, &(tl_logger){log_count, &l});
    if (r != TL_OK) fprintf(stderr, "tl_context_egl_devices: %s: %s\n", tl_result_string(r), l.last);
    TL_CHECK(r == TL_OK);
    return count < MAX_DEVICES ? count : MAX_DEVICES;
}

/* A context of `desc` (logged failures printed), checked to be current 4.5 core. */
static tl_context *open_checked(tl_context_desc desc)
{
    logged l = {0};
    desc.logger = (tl_logger){log_count, &l};
    tl_context *ctx = NULL;
    tl_result r = tl_context_create(&desc, &ctx);
    if (r != TL_OK) fprintf(stderr, "tl_context_create: %s: %s\n", tl_result_string(r), l.last);
    TL_CHECK(r == TL_OK && ctx != NULL && l.errors == 0);
    if (!ctx) return NULL;
    get_integerv_fn get = (get_integerv_fn)tl_context_get_proc_address(ctx, "glGetIntegerv");
    TL_CHECK(get != NULL);
    int major = 0, minor = 0, mask = 0;
    if (get) {
        get(GL_MAJOR_VERSION, &major);
        get(GL_MINOR_VERSION, &minor);
        get(GL_CONTEXT_PROFILE_MASK, &mask);
    }
    TL_CHECK(major > 4 || (major == 4 && minor >= 5));
    TL_CHECK(mask & GL_CONTEXT_CORE_PROFILE_BIT);
    int cmaj = 0, cmin = 0;
    tl_context_gl_version(ctx, &cmaj, &cmin);
    TL_CHECK(cmaj == major && cmin == minor);
    printf("%s: %s | %s | %s\n", tl_context_backend_name(tl_context_get_backend(ctx)), tl_context_platform_string(ctx),
           tl_context_renderer_string(ctx), tl_context_version_string(ctx));
    return ctx;
}

/* Every back end's name parses back to it; anything else is refused. */
TL_TEST(context_backend_names_round_trip)
{
    for (int b = 0; b < TL_CONTEXT_BACKEND_COUNT_; b++) {
        tl_context_backend parsed = TL_CONTEXT_BACKEND_COUNT_;
        TL_CHECK(tl_context_backend_from_name(tl_context_backend_name((tl_context_backend)b), &parsed) == TL_OK);
        TL_CHECK((int)parsed == b);
    }
    tl_context_backend b = TL_CONTEXT_BACKEND_OSMESA;
    TL_CHECK(strcmp(tl_context_backend_name(TL_CONTEXT_BACKEND_EGL), "egl") == 0);
    TL_CHECK(strcmp(tl_context_backend_name(TL_CONTEXT_BACKEND_COUNT_), "unknown") == 0);
    TL_CHECK(tl_context_backend_from_name("EGL", &b) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_context_backend_from_name("", &b) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_context_backend_from_name(NULL, &b) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_context_backend_from_name("egl", NULL) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(b == TL_CONTEXT_BACKEND_OSMESA);
    TL_CHECK(tl_context_backend_available(TL_CONTEXT_BACKEND_EGL));
    TL_CHECK(tl_context_backend_available(TL_CONTEXT_BACKEND_AUTO));
    TL_CHECK(!tl_context_backend_available(TL_CONTEXT_BACKEND_COUNT_));
}

/* The list: a count without storage, entries in index order, a short array filled only so far. */
TL_TEST(egl_devices_listed)
{
    tl_egl_device devices[MAX_DEVICES];
    size_t count = 0, again = 0;
    TL_CHECK(tl_context_egl_devices(NULL, 0, &count, NULL) == TL_OK);
    TL_CHECK(count >= 1); /* Mesa lists its software device even without a GPU */
    TL_CHECK(list_devices(devices) == (count < MAX_DEVICES ? count : MAX_DEVICES));
    for (size_t i = 0; i < count && i < MAX_DEVICES; i++) {
        const tl_egl_device *d = &devices[i];
        TL_CHECK(d->index == i);
        printf("device %u: %s; drm '%s'; render node '%s'; driver '%s'; vendor '%s'; renderer '%s'\n",
               (unsigned)d->index, d->software ? "software" : "GPU", d->drm_device, d->render_node, d->driver,
               d->vendor, d->renderer);
        if (d->software) TL_CHECK(d->render_node[0] == '\0' && d->drm_device[0] == '\0');
    }
    memset(devices, 0xAB, sizeof devices);
    TL_CHECK(tl_context_egl_devices(devices, 0, &again, NULL) == TL_OK && again == count);
    TL_CHECK(devices[0].index == 0xABABABABu); /* capacity 0: nothing written */
    logged l = {0};
    TL_CHECK(tl_context_egl_devices(devices, 1, NULL, &(tl_logger){log_count, &l}) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(l.errors == 1);
}

/* Mesa's surfaceless platform: 4.5 core with no surface, no default framebuffer. */
TL_TEST(egl_context_surfaceless_core45)
{
    tl_context *ctx = open_checked((tl_context_desc){.backend = TL_CONTEXT_BACKEND_EGL, .width = 32, .height = 16,
                                                     .egl_platform = TL_EGL_PLATFORM_SURFACELESS, .debug = true});
    if (!ctx) return;
    TL_CHECK(tl_context_get_backend(ctx) == TL_CONTEXT_BACKEND_EGL);
    TL_CHECK(strncmp(tl_context_platform_string(ctx), "EGL surfaceless", 15) == 0);
    TL_CHECK(strlen(tl_context_renderer_string(ctx)) > 0);
    uint32_t w = 0, h = 0;
    tl_context_get_size(ctx, &w, &h);
    TL_CHECK(w == 32 && h == 16);
    TL_CHECK(tl_context_get_proc_address(ctx, "glDispatchCompute") != NULL);
    TL_CHECK(tl_context_swap(ctx) == TL_OK);
    TL_CHECK(tl_context_make_current(NULL) == TL_OK);
    TL_CHECK(tl_context_make_current(ctx) == TL_OK);
    TL_CHECK(strcmp(tl_context_last_error(ctx), "") == 0);
    tl_context_destroy(ctx);
}

/* Every device EGL lists gives a context; the index after the last is refused and logged. */
TL_TEST(egl_context_each_device)
{
    tl_egl_device devices[MAX_DEVICES];
    size_t count = list_devices(devices);
    for (size_t i = 0; i < count; i++) {
        tl_context *ctx = open_checked((tl_context_desc){.backend = TL_CONTEXT_BACKEND_EGL,
                                                         .egl_platform = TL_EGL_PLATFORM_DEVICE,
                                                         .egl_device = (uint32_t)i});
        char expect[32];
        snprintf(expect, sizeof expect, "EGL device %zu", i);
        if (ctx) TL_CHECK(strncmp(tl_context_platform_string(ctx), expect, strlen(expect)) == 0);
        tl_context_destroy(ctx);
    }
    logged l = {0};
    tl_context *ctx = (tl_context *)&l;
    TL_CHECK(tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_EGL,
                                                  .egl_platform = TL_EGL_PLATFORM_DEVICE,
                                                  .egl_device = (uint32_t)count, .logger = {log_count, &l}},
                               &ctx) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(ctx == NULL && l.errors == 1 && strstr(l.last, "no EGL device") != NULL);
    printf("device %zu: %s\n", count, l.last);
}

/* An unknown EGL platform is refused before anything is made; the message goes to the logger only. */
TL_TEST(egl_bad_input)
{
    logged l = {0};
    tl_context *ctx = (tl_context *)&l;
    TL_CHECK(tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_EGL,
                                                  .egl_platform = TL_EGL_PLATFORM_COUNT_, .logger = {log_count, &l}},
                               &ctx) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(ctx == NULL && l.errors == 1);
    TL_CHECK(strcmp(tl_context_last_error(NULL), "") == 0);
    TL_CHECK(tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_EGL, .gl_major = 5,
                                                  .logger = {log_count, &l}},
                               &ctx) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(l.errors == 2);
    /* an exact version EGL cannot give: refused with a message, nothing leaked */
    TL_CHECK(tl_context_create(&(tl_context_desc){.backend = TL_CONTEXT_BACKEND_EGL, .gl_major = 4, .gl_minor = 9,
                                                  .exact_version = true, .logger = {log_count, &l}},
                               &ctx) == TL_ERROR_GL);
    TL_CHECK(ctx == NULL && l.errors == 3);
    printf("4.9 exact: %s\n", l.last);
}

/* AUTO takes the first EGL GPU device, else OSMesa, else EGL surfaceless: which one follows
 * from the device list alone. */
TL_TEST(context_auto_order)
{
    tl_egl_device devices[MAX_DEVICES];
    size_t count = list_devices(devices), gpu = count;
    for (size_t i = count; i-- > 0;)
        if (!devices[i].software) gpu = i;
    tl_context *ctx = open_checked((tl_context_desc){.backend = TL_CONTEXT_BACKEND_AUTO});
    if (!ctx) return;
    const char *platform = tl_context_platform_string(ctx);
    if (gpu < count) {
        char expect[32];
        snprintf(expect, sizeof expect, "EGL device %zu", gpu);
        TL_CHECK(tl_context_get_backend(ctx) == TL_CONTEXT_BACKEND_EGL);
        TL_CHECK(strncmp(platform, expect, strlen(expect)) == 0);
    } else if (tl_context_backend_available(TL_CONTEXT_BACKEND_OSMESA)) {
        TL_CHECK(tl_context_get_backend(ctx) == TL_CONTEXT_BACKEND_OSMESA);
    } else {
        TL_CHECK(strncmp(platform, "EGL surfaceless", 15) == 0);
    }
    tl_context_destroy(ctx);
}

/* ---- same pixels ---------------------------------------------------------------------------- */

#define PX_W 192u
#define PX_H 108u
#define PX_MODES (2 * (TL_MODE_COUNT_ - 1)) /* every mode, with volumes and with tiles */

typedef struct frame_pixels {
    uint8_t ldr[PX_W * PX_H * 4];
    float hdr[PX_W * PX_H * 4];
    char renderer[128];
} frame_pixels;

/* The crypt in every mode through one context: its output and HDR target per mode. */
static bool render_every_mode(tl_context_desc desc, const tl_scene *scene, frame_pixels *out)
{
    desc.width = PX_W;
    desc.height = PX_H;
    tl_context *ctx = open_checked(desc);
    if (!ctx) return false;
    snprintf(out[0].renderer, sizeof out[0].renderer, "%s", tl_context_renderer_string(ctx));
    bool ok = true;
    for (int m = 0; m < PX_MODES; m++) {
        tl_renderer *r = NULL;
        char err[1024] = "";
        /* every mode with light volumes, then with tiles */
        tl_renderer_desc rd = {.options.mode = (tl_render_mode)(m % 4 + 1), .width = PX_W, .height = PX_H,
                               .options.light_strategy = m < 4 ? TL_LIGHT_STRATEGY_VOLUMES : TL_LIGHT_STRATEGY_TILED,
                               .options.keep_targets = TL_TARGET_BIT(TL_TARGET_HDR),
                               .get_proc_address = tl_context_proc_loader, .get_proc_address_user = ctx,
                               .logger = {keep_error, err}};
        tl_result res = tl_renderer_create(&rd, &r);
        if (res == TL_OK) res = tl_renderer_set_scene(r, scene);
        if (res == TL_OK) res = tl_renderer_render(r, NULL, NULL);
        if (res == TL_OK) res = tl_renderer_read_output(r, out[m].ldr, &(size_t){sizeof out[m].ldr});
        if (res == TL_OK) res = tl_renderer_read_target(r, TL_TARGET_HDR, out[m].hdr, &(size_t){sizeof out[m].hdr});
        if (res != TL_OK) fprintf(stderr, "%s: %s\n", tl_render_mode_name(rd.options.mode),
                                  r ? tl_renderer_last_error(r) : err);
        TL_CHECK(res == TL_OK);
        ok = ok && res == TL_OK;
        /* a lit image, not a blank one: comparing two blank images would prove nothing */
        size_t lit = 0;
        for (size_t i = 0; i < PX_W * PX_H; i++) lit += out[m].ldr[i * 4] + out[m].ldr[i * 4 + 1] > 16;
        TL_CHECK(lit > PX_W * PX_H / 8);
        tl_renderer_destroy(r);
    }
    tl_context_destroy(ctx);
    return ok;
}

static size_t bytes_differing(const void *a, const void *b, size_t n)
{
    const uint8_t *x = a, *y = b;
    size_t d = 0;
    for (size_t i = 0; i < n; i++) d += x[i] != y[i];
    return d;
}

/* Compares `other` with the OSMesa frames, mode by mode; every byte must agree. */
static void compare_frames(const char *what, const frame_pixels *osmesa, const frame_pixels *other)
{
    if (strcmp(osmesa[0].renderer, other[0].renderer) != 0) {
        fprintf(stderr, "%s renders on '%s', OSMesa on '%s': not the same rasteriser (run with "
                        "LIBGL_ALWAYS_SOFTWARE=1)\n", what, other[0].renderer, osmesa[0].renderer);
        tl_test_failures++;
        return;
    }
    for (int m = 0; m < PX_MODES; m++) {
        size_t ldr = bytes_differing(osmesa[m].ldr, other[m].ldr, sizeof osmesa[m].ldr);
        size_t hdr = bytes_differing(osmesa[m].hdr, other[m].hdr, sizeof osmesa[m].hdr);
        printf("%-13s %-7s %s vs OSMesa: %zu of %zu output bytes differ, %zu of %zu HDR bytes\n",
               tl_render_mode_name((tl_render_mode)(m % 4 + 1)), m < 4 ? "volumes" : "tiled", what, ldr,
               sizeof osmesa[m].ldr, hdr, sizeof osmesa[m].hdr);
        TL_CHECK_EQ_U(ldr, 0);
        TL_CHECK_EQ_U(hdr, 0);
    }
}

#ifdef TL_TEST_OSMESA
/* The built-in crypt through EGL (surfaceless, and Mesa's software device when listed) and
 * through OSMesa, on the same llvmpipe: 0 bytes of difference in every mode. */
TL_TEST_FULL(egl_same_pixels_as_osmesa_every_mode)
{
    static frame_pixels osmesa[PX_MODES], egl[PX_MODES];
    tl_scene *scene = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 24, .spot_lights = 4, .detail = 1},
                                     &scene) == TL_OK);
    if (!scene) return;
    if (render_every_mode((tl_context_desc){.backend = TL_CONTEXT_BACKEND_OSMESA}, scene, osmesa)) {
        if (render_every_mode((tl_context_desc){.backend = TL_CONTEXT_BACKEND_EGL,
                                                .egl_platform = TL_EGL_PLATFORM_SURFACELESS},
                              scene, egl))
            compare_frames("EGL surfaceless", osmesa, egl);
        tl_egl_device devices[MAX_DEVICES];
        size_t count = list_devices(devices);
        for (size_t i = 0; i < count; i++)
            if (devices[i].software &&
                render_every_mode((tl_context_desc){.backend = TL_CONTEXT_BACKEND_EGL,
                                                    .egl_platform = TL_EGL_PLATFORM_DEVICE, .egl_device = (uint32_t)i},
                                  scene, egl))
                compare_frames("EGL software device", osmesa, egl);
    }
    tl_scene_destroy(scene);
}
#endif
