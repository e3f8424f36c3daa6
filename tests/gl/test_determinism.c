/* Same input, same image: for a set of option combinations that holds every value of every
 * enumerated option (and every on/off switch) at least once, two renderers created with the same
 * options render the same bytes frame for frame, and one renderer renders the same bytes in every
 * frame (fog's noise, which drifts with the frame counter by design, is compared frame for frame
 * only). llvmpipe shades with several threads, so a result that depends on which fragment or
 * invocation ran first (an atomic counter's order, a shared list) shows up here as differing bytes
 * within a few frames. */
#include <string.h>

#include "tl_test.h"

#include "render_fixture.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

enum { W = 160, H = 90, FRAMES = 3 };

typedef struct combo {
    const char *name;
    int scene; /* 0: the crypt (spots, glass panes, casting lights); 1: the material-model showcase */
    int quick; /* also in the quick case: the paths where shared writes (lists, atomics) meet */
    tl_renderer_options o;
} combo;

#define TILED .light_strategy = TL_LIGHT_STRATEGY_TILED
#define VOLUMES .light_strategy = TL_LIGHT_STRATEGY_VOLUMES
#define LPP .mode = TL_MODE_THIN_LPP
static const combo k_combos[] = {
    {"defaults", 0, 0, {0}},
    {"light scale 1, d24, rgba8, explicit", 0, 0,
     {.light_scale = 1.0f, .depth_format = TL_DEPTH_FORMAT_D24, .rt0 = TL_RT0_RGBA8}},
    {"thin-lpp tiled 1/2", 0, 1, {LPP, TILED, .light_scale = 0.5f}},
    {"thin-lpp tiled 1/4 compute, tiles of 8", 0, 1,
     {LPP, TILED, .light_scale = 0.25f, .tiled_shading = TL_TILED_SHADING_COMPUTE, .tile_size = 8}},
    {"thin-lpp tiled 1/4 fragment, rgb10a2", 0, 1,
     {LPP, TILED, .light_scale = 0.25f, .tiled_shading = TL_TILED_SHADING_FRAGMENT, .rt0 = TL_RT0_RGB10A2}},
    {"thin-lpp volumes 1/2, d32f", 0, 1, {LPP, VOLUMES, .light_scale = 0.5f, .depth_format = TL_DEPTH_FORMAT_D32F}},
    {"thin-lpp tiled 1/2, msaa 4", 0, 1, {LPP, TILED, .light_scale = 0.5f, .msaa = 4}},
    {"thin-lpp auto, 1/2, reversed z", 0, 0, {.light_scale = 0.5f, .depth_format = TL_DEPTH_FORMAT_D32F_REVERSED}},
    {"thin-lpp ggx n.v compact", 0, 0,
     {LPP, .lighting = TL_LIGHTING_GGX, .fresnel = TL_FRESNEL_NV, .light_buffer = TL_LIGHT_BUFFER_COMPACT}},
    {"thin-lpp ggx two sums exact, r11g11b10f, tiles of 32", 0, 0,
     {LPP, TILED, .tile_size = 32, .lighting = TL_LIGHTING_GGX, .fresnel = TL_FRESNEL_TWO_SUMS,
      .light_buffer = TL_LIGHT_BUFFER_EXACT, .light_format = TL_LIGHT_FORMAT_R11G11B10F}},
    {"thin-lpp blinn-phong rgba16f, tiles of 16", 0, 0,
     {LPP, TILED, .tile_size = 16, .lighting = TL_LIGHTING_BLINN_PHONG, .light_format = TL_LIGHT_FORMAT_RGBA16F}},
    {"thin-lpp msaa 2 material pass, volumes", 0, 0,
     {LPP, VOLUMES, .msaa = 2, .msaa_lighting = TL_MSAA_LIGHTING_MATERIAL_PASS}},
    {"thin-lpp msaa 4 sample edges, tiled", 0, 0, {LPP, TILED, .msaa = 4, .msaa_lighting = TL_MSAA_LIGHTING_SAMPLE_EDGES}},
    {"thin-lpp msaa 4 sample edges, compute", 0, 1,
     {LPP, TILED, .msaa = 4, .msaa_lighting = TL_MSAA_LIGHTING_SAMPLE_EDGES,
      .tiled_shading = TL_TILED_SHADING_COMPUTE}},
    {"transparency forward", 0, 0, {.transparency = TL_TRANSPARENCY_FORWARD}},
    {"transparency stipple, tiled", 0, 0, {TILED, .transparency = TL_TRANSPARENCY_STIPPLE}},
    {"thin-deferred tiled, d32f, msaa 4", 0, 0,
     {.mode = TL_MODE_THIN_DEFERRED, TILED, .depth_format = TL_DEPTH_FORMAT_D32F, .msaa = 4}},
    {"thin-deferred compute 1/1, ggx", 0, 0,
     {.mode = TL_MODE_THIN_DEFERRED, TILED, .tiled_shading = TL_TILED_SHADING_COMPUTE, .lighting = TL_LIGHTING_GGX}},
    {"fat volumes, reversed z, blinn-phong", 0, 0,
     {.mode = TL_MODE_FAT, VOLUMES, .depth_format = TL_DEPTH_FORMAT_D32F_REVERSED,
      .lighting = TL_LIGHTING_BLINN_PHONG}},
    {"fat tiled, msaa 2 sample edges", 0, 0,
     {.mode = TL_MODE_FAT, TILED, .msaa = 2, .msaa_lighting = TL_MSAA_LIGHTING_SAMPLE_EDGES}},
    {"forward+, msaa 4", 0, 0, {.mode = TL_MODE_FORWARD, TILED, .msaa = 4}},
    {"forward volumes, no pre-pass", 0, 0, {.mode = TL_MODE_FORWARD, VOLUMES, .forward_depth_prepass = TL_SWITCH_OFF}},
    /* visibility: vis-classify appends each tile to its buckets with atomics (the lists' order
     * follows the workgroups' order), vis-resolve writes HDR per material; the crypt's glass goes
     * forward after it, its casting lights through the resolve's shadow gate */
    {"visibility, glass, shadows", 0, 1, {.mode = TL_MODE_VISIBILITY}},
    {"visibility tiles of 8, reversed z, ggx, ssao, ssr", 0, 0,
     {.mode = TL_MODE_VISIBILITY, .tile_size = 8, .depth_format = TL_DEPTH_FORMAT_D32F_REVERSED,
      .lighting = TL_LIGHTING_GGX, .ssao = {.enabled = 1}, .ssr = {.enabled = 1}}},
    {"effects: ssao disc, distance fog, dof, bloom, ssr, vignette", 0, 0,
     {.ssao = {.enabled = 1, .method = TL_SSAO_DISC}, .fog = {.enabled = 1, .mode = TL_FOG_DISTANCE, .color = {0.1f, 0.1f, 0.12f}},
      .dof = {.enabled = 1}, .bloom = {.enabled = 1, .threshold = 0.3f}, .ssr = {.enabled = 1},
      .vignette = {.enabled = 1}}},
    {"thin-deferred: ssao hemisphere diffuse, height fog with noise", 0, 0,
     {.mode = TL_MODE_THIN_DEFERRED, .ssao = {.enabled = 1, .method = TL_SSAO_HEMISPHERE, .diffuse = 1},
      .fog = {.enabled = 1, .mode = TL_FOG_HEIGHT, .density = 0.2f, .noise = 0.5f}}},
    {"thin-lpp 1/2 tiled with every effect", 0, 0,
     {LPP, TILED, .light_scale = 0.5f, .ssao = {.enabled = 1, .method = TL_SSAO_DISC}, .fog = {.enabled = 1, .mode = TL_FOG_DISTANCE},
      .dof = {.enabled = 1}, .bloom = {.enabled = 1}, .ssr = {.enabled = 1}, .vignette = {.enabled = 1}}},
    {"shadows pcf, radius 3, no cache, debug", 0, 0,
     {.shadows = {.filter = TL_SHADOW_FILTER_PCF, .pcf_radius = 3, .cache = TL_SWITCH_OFF}, .shadow_debug = 1}},
    {"shadows pcss, tiled 1/2", 0, 0, {LPP, TILED, .light_scale = 0.5f, .shadows = {.filter = TL_SHADOW_FILTER_PCSS}}},
    {"shadows one tap, budget 2, fat", 0, 0,
     {.mode = TL_MODE_FAT, .shadows = {.filter = TL_SHADOW_FILTER_BILINEAR, .max_lights = 2, .atlas_size = 2048}}},
    {"shadows disabled", 0, 0, {.shadows = {.enabled = TL_SWITCH_OFF}}},
    {"fxaa off, exposure 2", 0, 0, {.fxaa = TL_FXAA_OFF, .exposure = 2.0f}},
    {"fxaa 12, thresholds", 0, 0, {.fxaa = TL_FXAA_12, .fxaa_edge_threshold = 0.25f, .fxaa_subpix = -1.0f}},
    {"fxaa 29, ambient", 0, 0, {.fxaa = TL_FXAA_29, .ambient = {0.05f, 0.04f, 0.03f}, .fxaa_edge_threshold_min = 0.05f}},
    {"fxaa 39, background", 0, 0, {.fxaa = TL_FXAA_39, .environment = {.background = {0.02f, 0.03f, 0.05f}}}},
    {"no planning, full-screen lights", 0, 0, {.planning = TL_SWITCH_OFF, .fullscreen_lights = 1}},
    {"synchronous statistics, every target kept", 0, 0, {.synchronous_stats = 1, .keep_targets = TL_TARGETS_ALL}},
    {"showcase: defaults", 1, 0, {0}},
    {"showcase: clearcoat approximate", 1, 0, {.clearcoat = TL_CLEARCOAT_APPROXIMATE}},
    {"showcase: clearcoat sums, tiled 1/2", 1, 1, {LPP, TILED, .light_scale = 0.5f, .clearcoat = TL_CLEARCOAT_SUMS}},
    {"showcase: volumes 1/4, msaa 4", 1, 0, {LPP, VOLUMES, .light_scale = 0.25f, .msaa = 4}},
    {"showcase: thin-deferred tiled 1/1, msaa 2", 1, 0, {.mode = TL_MODE_THIN_DEFERRED, TILED, .msaa = 2}},
    {"showcase: visibility (a dispatch per material)", 1, 0, {.mode = TL_MODE_VISIBILITY}},
};
#define COMBOS (sizeof k_combos / sizeof k_combos[0])

static int frame(tl_renderer *r, uint8_t *out)
{
    size_t size = (size_t)W * H * 4;
    return tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_read_output(r, out, &size) == TL_OK;
}

static size_t differ(const uint8_t *a, const uint8_t *b)
{
    size_t n = 0;
    for (size_t i = 0; i < (size_t)W * H * 4; i++) n += a[i] != b[i];
    return n;
}

/* One combination: renderers A and B, FRAMES frames each (with TL_DETERMINISM_DUMP=DIR, the first
 * frame is also written to DIR/NN.rgba: the images of two builds compared byte for byte); A's frame k against B's frame k, and
 * (without fog noise) against A's first frame. Returns the differing bytes found. */
static size_t run_combo(const tl_scene *s, const combo *c, uint8_t *buf[2][FRAMES])
{
    const tl_test_renderer_desc d = {.renderer = {.width = W, .height = H, .options = c->o}, .scene = s};
    tl_renderer *r[2] = {tl_test_renderer(&d), tl_test_renderer(&d)};
    size_t worst = 0;
    int ok = r[0] && r[1];
    for (int k = 0; ok && k < FRAMES; k++) ok = frame(r[0], buf[0][k]) && frame(r[1], buf[1][k]);
    TL_CHECK(ok);
    const char *dump = getenv("TL_DETERMINISM_DUMP"); /* a folder: each combination's first frame, raw RGBA8 */
    if (ok && dump) {
        char path[512];
        snprintf(path, sizeof path, "%s/%02zu.rgba", dump, (size_t)(c - k_combos));
        FILE *f = fopen(path, "wb");
        TL_CHECK(f && fwrite(buf[0][0], 1, (size_t)W * H * 4, f) == (size_t)W * H * 4);
        if (f) fclose(f);
    }
    for (int k = 0; ok && k < FRAMES; k++) {
        size_t across = differ(buf[0][k], buf[1][k]);
        size_t within = c->o.fog.noise > 0.0f ? 0u : differ(buf[0][0], buf[0][k]);
        if (across || within)
            fprintf(stderr, "%s, frame %d: %zu bytes differ between the two renderers, %zu from the first frame\n",
                    c->name, k + 1, across, within);
        worst += across + within;
    }
    tl_renderer_destroy(r[0]);
    tl_renderer_destroy(r[1]);
    return worst;
}

/* Whether some combination holds a value of field f named `name` (DEFAULT counts as the value it
 * stands for: same name). */
static int combos_hold(const tl_option_info *f, const char *name)
{
    for (size_t c = 0; c < COMBOS; c++) {
        int32_t v;
        memcpy(&v, (const char *)&k_combos[c].o + f->offset, sizeof v);
        if (f->type == TL_OPTION_BOOL ? (v != 0) == (strcmp(name, "1") == 0) : strcmp(f->value_name((uint32_t)v), name) == 0)
            return 1;
    }
    return 0;
}

/* Every value of every enumerated option and both of every on/off option of the option registry
 * (a field added to it is covered here with no line written), every light scale, tile size and
 * sample count appears in some combination: a value without a combination fails here. */
static int combos_cover_every_value(void)
{
    int missing = 0;
    for (size_t i = 0; i < tl_option_count(); i++) {
        const tl_option_info *f = tl_option_at(i);
        if (f->type != TL_OPTION_ENUM && f->type != TL_OPTION_SWITCH && f->type != TL_OPTION_BOOL) continue;
        for (uint32_t v = 0; v < (f->type == TL_OPTION_BOOL ? 2u : f->count); v++) {
            const char *name = f->type == TL_OPTION_BOOL ? (v ? "1" : "0") : f->value_name(v);
            if (combos_hold(f, name)) continue;
            fprintf(stderr, "no combination has %s = %s\n", f->name, name);
            missing++;
        }
    }
    const float scales[] = {0.0f, 1.0f, 0.5f, 0.25f};
    const uint32_t tiles[] = {0, 8, 16, 32}, samples[] = {0, 2, 4};
    for (size_t i = 0; i < 4; i++) {
        int s = 0, t = 0, m = 0;
        for (size_t c = 0; c < COMBOS; c++) {
            s |= k_combos[c].o.light_scale == scales[i];
            t |= k_combos[c].o.tile_size == tiles[i];
            m |= i < 3 && k_combos[c].o.msaa == samples[i];
        }
        missing += !s + !t + (i < 3 && !m);
    }
    return missing;
}

static void run_combos(int quick_only)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *scenes[2] = {NULL, NULL};
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 24, .detail = 1, .glass_panes = 2,
                                                              .shadows = 1},
                                     &scenes[0]) == TL_OK);
    TL_CHECK(tl_scene_create_showcase(NULL, &scenes[1]) == TL_OK);
    uint8_t *buf[2][FRAMES];
    int have = 1;
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < FRAMES; k++) have &= (buf[i][k] = malloc((size_t)W * H * 4)) != NULL;
    size_t total = 0, failed = 0, runs = 0;
    for (size_t c = 0; have && scenes[0] && scenes[1] && c < COMBOS; c++) {
        if (quick_only && !k_combos[c].quick) continue;
        size_t d = run_combo(scenes[k_combos[c].scene], &k_combos[c], buf);
        total += d;
        failed += d != 0;
        runs++;
    }
    printf("%zu option combinations, %d frames in each of two renderers: %zu combinations differ (%zu bytes)\n",
           runs, FRAMES, failed, total);
    TL_CHECK_EQ_U(total, 0);
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < FRAMES; k++) free(buf[i][k]);
    tl_scene_destroy(scenes[0]);
    tl_scene_destroy(scenes[1]);
}

/* The combinations where shared writes meet (light scales with tiles and volumes, MSAA's re-lit
 * samples, the compute passes), and that every value is somewhere in the whole set. */
TL_TEST(frames_same_bytes_light_scales_and_tiles)
{
    TL_CHECK_EQ_U(combos_cover_every_value(), 0);
    run_combos(1);
}

/* Every combination: every value of every option. */
TL_TEST_FULL(frames_same_bytes_every_option_value) { run_combos(0); }
