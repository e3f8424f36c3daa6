/* What the renderer refuses says exactly what is wrong (issue 38): every option out of range names
 * the field, the value and the range (one table row per option, so a new option is one line); a
 * scene's bad object names the one field that fails; an MSAA count over the context's names
 * options.msaa; and reading the output before a frame drew it is refused, not zero bytes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

#define W 64
#define H 64

typedef struct said {
    int errors;
    char last[512];
} said;

static void said_log(void *user, tl_log_level level, const char *message)
{
    said *s = (said *)user;
    if (level != TL_LOG_ERROR) return;
    s->errors++;
    snprintf(s->last, sizeof s->last, "%s", message);
}

static tl_renderer *renderer(said *log)
{
    return tl_test_renderer(&(tl_test_renderer_desc){.renderer = {.width = W, .height = H, .logger = {said_log, log}}});
}

static void lit_room(test_scene *t)
{
    build_room(t);
    t->lights[0] = (tl_light){TL_LIGHT_POINT, {3, 6, -2}, {0, 0, 0}, {60, 55, 50}, 30, 0, 0, 0, 0};
    t->s.light_count = 1;
}

/* ---- reading the output before a frame ---------------------------------------------------------- */

/* read_output before render drew a frame at the renderer's size (none yet, only render_to, or a
 * resize since) is TL_ERROR_INVALID_ARGUMENT saying so, and the buffer is left alone; after a
 * render it reads. Before: TL_OK and whatever the fresh target held. */
TL_TEST(renderer_read_output_before_any_frame_refused)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    said log = {0};
    tl_renderer *r = renderer(&log);
    if (!r) return;
    static test_scene t;
    lit_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    static uint8_t px[W * H * 4], blank[W * H * 4];
    memset(px, 0xAB, sizeof px);
    memset(blank, 0xAB, sizeof blank);
    size_t size = 0;
    TL_CHECK(tl_renderer_read_output(r, NULL, &size) == TL_OK && size == sizeof px); /* asking is fine */
    const char *why = "tl_renderer_read_output: no frame was rendered into the output at 64x64";
    int refused = 0;
    tl_result res = tl_renderer_read_output(r, px, &size);
    refused += res == TL_ERROR_INVALID_ARGUMENT && strstr(log.last, why) && memcmp(px, blank, sizeof px) == 0;
    printf("  before any frame: %s \"%s\"\n", tl_result_string(res), log.last);
    /* render_to draws into the caller's framebuffer (0: OSMesa's), not the output */
    TL_CHECK(tl_renderer_render_to(r, NULL, &(tl_render_output){0}, NULL) == TL_OK);
    res = tl_renderer_read_output(r, px, &size);
    refused += res == TL_ERROR_INVALID_ARGUMENT && strstr(log.last, why) && memcmp(px, blank, sizeof px) == 0;
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_read_output(r, px, &size) == TL_OK && memcmp(px, blank, sizeof px) != 0);
    TL_CHECK(tl_renderer_resize(r, 32, 32) == TL_OK);
    memset(px, 0xAB, sizeof px);
    size = sizeof px;
    res = tl_renderer_read_output(r, px, &size);
    refused += res == TL_ERROR_INVALID_ARGUMENT && strstr(log.last, "no frame was rendered into the output at 32x32") &&
               memcmp(px, blank, sizeof px) == 0;
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_read_output(r, px, &size) == TL_OK && size == (size_t)32 * 32 * 4);
    printf("  %d of 3 reads refused (before a frame, after render_to only, after a resize)\n", refused);
    TL_CHECK_EQ_U(refused, 3);
    tl_renderer_destroy(r);
}

/* ---- options: one row per field ---------------------------------------------------------------- */

typedef struct option_row {
    tl_renderer_options o; /* zeroed but for the one field out of range (and what switches it on) */
    const char *said;      /* the line after "renderer: set_options: " */
    const char *type;      /* an enum: its type; `said` then ends before the range, which the row's count makes */
    unsigned count;
} option_row;

#define ROW(text, ...) {{__VA_ARGS__}, text, NULL, 0}
#define ENUM_ROW(text, count_, type_, ...) {{__VA_ARGS__}, text, type_, (unsigned)(count_)}

/* Every field of tl_renderer_options a value can put out of range, with the line that must name it:
 * a new option is one row. */
static const option_row g_option_rows[] = {
    ENUM_ROW("options.mode = 9", TL_MODE_COUNT_, "tl_render_mode", .mode = (tl_render_mode)9),
    ENUM_ROW("options.mode = -1", TL_MODE_COUNT_, "tl_render_mode", .mode = (tl_render_mode)-1),
    ENUM_ROW("options.depth_format = 7", TL_DEPTH_FORMAT_COUNT_, "tl_depth_format",
             .depth_format = (tl_depth_format)7),
    ENUM_ROW("options.rt0 = 7", TL_RT0_COUNT_, "tl_rt0_packing", .rt0 = (tl_rt0_packing)7),
    ENUM_ROW("options.light_buffer = 7", TL_LIGHT_BUFFER_COUNT_, "tl_light_buffer",
             .light_buffer = (tl_light_buffer)7),
    ENUM_ROW("options.fxaa = 99", TL_FXAA_COUNT_, "tl_fxaa_preset", .fxaa = (tl_fxaa_preset)99),
    ENUM_ROW("options.light_format = 7", TL_LIGHT_FORMAT_COUNT_, "tl_light_format",
             .light_format = (tl_light_format)7),
    ENUM_ROW("options.light_strategy = 7", TL_LIGHT_STRATEGY_COUNT_, "tl_light_strategy",
             .light_strategy = (tl_light_strategy)7),
    ENUM_ROW("options.tiled_shading = 7", TL_TILED_SHADING_COUNT_, "tl_tiled_shading",
             .tiled_shading = (tl_tiled_shading)7),
    ENUM_ROW("options.lighting = 7", TL_LIGHTING_COUNT_, "tl_lighting_model", .lighting = (tl_lighting_model)7),
    ENUM_ROW("options.fresnel = 7", TL_FRESNEL_COUNT_, "tl_fresnel_layout", .fresnel = (tl_fresnel_layout)7),
    ENUM_ROW("options.transparency = 7", TL_TRANSPARENCY_COUNT_, "tl_transparency",
             .transparency = (tl_transparency)7),
    ENUM_ROW("options.msaa_lighting = 7", TL_MSAA_LIGHTING_COUNT_, "tl_msaa_lighting",
             .msaa_lighting = (tl_msaa_lighting)7),
    ENUM_ROW("options.clearcoat = 7", TL_CLEARCOAT_COUNT_, "tl_clearcoat_lighting",
             .clearcoat = (tl_clearcoat_lighting)7),
    ROW("options.ambient[1] = nan is out of range (finite)", .ambient = {0.1f, NAN, 0.1f}),
    ROW("options.fxaa_edge_threshold = inf is out of range (finite; <= 0: 0.166)", .fxaa_edge_threshold = INFINITY),
    ROW("options.fxaa_edge_threshold_min = nan is out of range (finite; <= 0: 0.0833)", .fxaa_edge_threshold_min = NAN),
    ROW("options.fxaa_subpix = nan is out of range (finite; 0: 0.75, < 0: 0)", .fxaa_subpix = NAN),
    ROW("options.exposure = inf is out of range (finite; <= 0: 1)", .exposure = INFINITY),
    ROW("options.tile_size = 12 is out of range (8, 16 or 32; 0: 16)", .tile_size = 12),
    ROW("options.light_scale = 0.3 is out of range (1, 0.5 or 0.25; 0: 1)", .light_scale = 0.3f),
    ROW("options.msaa = 3 is out of range (0, 1, 2, 4 or 8 samples)", .msaa = 3),
    ROW("options.light_format = 2 (R11G11B10F) needs options.light_buffer = 1 (EXACT), not 2",
        .light_format = TL_LIGHT_FORMAT_R11G11B10F, .light_buffer = TL_LIGHT_BUFFER_COMPACT),
    ROW("options.shadows.atlas_size = 1000 is out of range (a power of two, 1024..16384; 0: 4096)",
        .shadows.atlas_size = 1000),
    ROW("options.shadows.max_lights = 65 is out of range (1..64; 0: 8)", .shadows.max_lights = 65),
    ROW("options.shadows.pcf_radius = 4 is out of range (0..3; 0: 1)", .shadows.pcf_radius = 4),
    ROW("options.shadows.filter = 7 is out of range (1 PCF or 2 PCSS; 0: PCF)", .shadows.filter = (tl_shadow_filter)7),
    ROW("options.shadows.directional_angle = 0.5 is out of range ((0, 0.2] radians; 0: 0.00465)",
        .shadows.directional_angle = 0.5f),
    ENUM_ROW("options.ssao.method = 7", TL_SSAO_COUNT_, "tl_ssao_method", .ssao.method = (tl_ssao_method)7),
    ROW("options.ssao.samples = 65 is out of range (1..64; 0: 16)", .ssao = {.method = TL_SSAO_DISC, .samples = 65}),
    ROW("options.ssao.blur_radius = 9 is out of range (1..8; 0: 2)", .ssao = {.method = TL_SSAO_DISC, .blur_radius = 9}),
    ROW("options.ssao.radius = inf is out of range (finite; <= 0: 1)", .ssao = {.method = TL_SSAO_DISC, .radius = INFINITY}),
    ROW("options.ssao.bias = inf is out of range (finite; <= 0: 0)", .ssao = {.method = TL_SSAO_DISC, .bias = INFINITY}),
    ROW("options.ssao.falloff = inf is out of range (finite; <= 0: 2 radius)",
        .ssao = {.method = TL_SSAO_DISC, .falloff = INFINITY}),
    ROW("options.ssao.exponent = inf is out of range (finite; <= 0: 3)",
        .ssao = {.method = TL_SSAO_DISC, .exponent = INFINITY}),
    ENUM_ROW("options.fog.mode = 7", TL_FOG_COUNT_, "tl_fog_mode", .fog.mode = (tl_fog_mode)7),
    ROW("options.fog.color[1] = -1 is out of range (finite, >= 0)", .fog = {.mode = TL_FOG_DISTANCE, .color = {0, -1, 0}}),
    ROW("options.fog.density = inf is out of range (finite; <= 0: 0.05)", .fog = {.mode = TL_FOG_DISTANCE, .density = INFINITY}),
    ROW("options.fog.height = nan is out of range (finite)", .fog = {.mode = TL_FOG_HEIGHT, .height = NAN}),
    ROW("options.fog.height_falloff = inf is out of range (finite; <= 0: 0.5)",
        .fog = {.mode = TL_FOG_HEIGHT, .height_falloff = INFINITY}),
    ROW("options.fog.noise = 2 is out of range (0..1)", .fog = {.mode = TL_FOG_DISTANCE, .noise = 2}),
    ROW("options.fog.noise_scale = inf is out of range (finite; <= 0: 0.5)",
        .fog = {.mode = TL_FOG_DISTANCE, .noise_scale = INFINITY}),
    ROW("options.fog.noise_speed = nan is out of range (finite; 0: 0.3)", .fog = {.mode = TL_FOG_DISTANCE, .noise_speed = NAN}),
    ROW("options.dof.samples = 4 is out of range (8..128; 0: 48)", .dof = {.enabled = 1, .samples = 4}),
    ROW("options.dof.focus_distance = inf is out of range (finite; <= 0: the target's)",
        .dof = {.enabled = 1, .focus_distance = INFINITY}),
    ROW("options.dof.aperture = 2 is out of range ((0, 1]; <= 0: 0.01)", .dof = {.enabled = 1, .aperture = 2}),
    ROW("options.dof.max_radius = 2 is out of range ((0, 1]; <= 0: 2 aperture)", .dof = {.enabled = 1, .max_radius = 2}),
    ROW("options.bloom.levels = 9 is out of range (1..8; 0: 6)", .bloom = {.enabled = 1, .levels = 9}),
    ROW("options.bloom.threshold = inf is out of range (finite; 0: 1, < 0: 0)", .bloom = {.enabled = 1, .threshold = INFINITY}),
    ROW("options.bloom.knee = 2 is out of range (0..1; 0: 0.5, < 0: 0)", .bloom = {.enabled = 1, .knee = 2}),
    ROW("options.bloom.intensity = inf is out of range (finite; <= 0: 0.5)", .bloom = {.enabled = 1, .intensity = INFINITY}),
    ROW("options.bloom.scatter = 2 is out of range ((0, 1]; <= 0: 0.7)", .bloom = {.enabled = 1, .scatter = 2}),
    ROW("options.ssr.steps = 2 is out of range (4..256; 0: 48)", .ssr = {.enabled = 1, .steps = 2}),
    ROW("options.ssr.refine = 9 is out of range (1..8; 0: 4)", .ssr = {.enabled = 1, .refine = 9}),
    ROW("options.ssr.max_distance = inf is out of range (finite; <= 0: 16)", .ssr = {.enabled = 1, .max_distance = INFINITY}),
    ROW("options.ssr.thickness = inf is out of range (finite; <= 0: 0.4)", .ssr = {.enabled = 1, .thickness = INFINITY}),
    ROW("options.ssr.min_gloss = 1 is out of range ([0, 1); 0: 0.4, < 0: 0)", .ssr = {.enabled = 1, .min_gloss = 1}),
    ROW("options.ssr.edge_fade = 0.6 is out of range ((0, 0.5]; <= 0: 0.1)", .ssr = {.enabled = 1, .edge_fade = 0.6f}),
    ROW("options.ssr.intensity = inf is out of range (finite; <= 0: 1)", .ssr = {.enabled = 1, .intensity = INFINITY}),
    ROW("options.vignette.strength = 2 is out of range ((0, 1]; <= 0: 0.5)", .vignette = {.enabled = 1, .strength = 2}),
    ROW("options.vignette.radius = inf is out of range (finite; <= 0: 0.5)", .vignette = {.enabled = 1, .radius = INFINITY}),
    ROW("options.vignette.softness = inf is out of range (finite; <= 0: 0.5)",
        .vignette = {.enabled = 1, .softness = INFINITY}),
    ROW("options.environment.background[2] = -1 is out of range (0..65504)", .environment.background = {0, 0, -1}),
    ROW("options.environment.intensity = -1 is out of range ((0, 65504]; 0: 1)", .environment.intensity = -1),
    ROW("options.shadow_debug = 2 is out of range (0 or 1)", .shadow_debug = 2),
};

/* Each row refused by set_options and by create with TL_ERROR_INVALID_ARGUMENT and exactly one line
 * naming the field, its value and its range; the renderer keeps its options. Before: "options.ssr
 * is out of range" for any field of the struct, "options.mode is out of range" without the value,
 * and the shadows' every range at once. */
TL_TEST(renderer_options_out_of_range_name_field_value_and_range)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    said log = {0};
    tl_renderer *r = renderer(&log);
    if (!r) return;
    size_t n = sizeof g_option_rows / sizeof g_option_rows[0], named = 0, created = 0;
    for (size_t i = 0; i < n; i++) {
        const option_row *row = &g_option_rows[i];
        char want[320], line[400];
        if (row->type) snprintf(want, sizeof want, "%s is out of range (0..%u, a %s)", row->said, row->count - 1u, row->type);
        else snprintf(want, sizeof want, "%s", row->said);
        int before = log.errors;
        tl_result res = tl_renderer_set_options(r, &row->o);
        snprintf(line, sizeof line, "renderer: set_options: %s", want);
        int ok = res == TL_ERROR_INVALID_ARGUMENT && log.errors == before + 1 && strcmp(log.last, line) == 0 &&
                 strcmp(tl_renderer_last_error(r), line) == 0;
        if (!ok) fprintf(stderr, "  row %zu: %s \"%s\"\n      want \"%s\"\n", i, tl_result_string(res), log.last, line);
        named += (size_t)ok;
        /* create says the same, through the descriptor's logger */
        said at_create = {0};
        tl_renderer_desc d = {.width = W, .height = H, .options = row->o, .get_proc_address = tl_context_proc_loader,
                              .get_proc_address_user = g_ctx, .logger = {said_log, &at_create}};
        tl_renderer *bad = NULL;
        snprintf(line, sizeof line, "renderer: %s", want);
        res = tl_renderer_create(&d, &bad);
        int ok_create = res == TL_ERROR_INVALID_ARGUMENT && !bad && at_create.errors == 1 && strcmp(at_create.last, line) == 0;
        if (!ok_create) fprintf(stderr, "  row %zu at create: %s \"%s\"\n", i, tl_result_string(res), at_create.last);
        created += (size_t)ok_create;
        tl_renderer_destroy(bad);
    }
    tl_renderer_options kept;
    tl_renderer_get_options(r, &kept);
    static const tl_renderer_options zero;
    TL_CHECK(memcmp(&kept, &zero, sizeof kept) == 0);
    printf("  %zu of %zu options named with value and range by set_options, %zu by create; e.g. \"%s\"\n", named, n,
           created, log.last);
    TL_CHECK_EQ_U(named, n);
    TL_CHECK_EQ_U(created, n);
    tl_renderer_destroy(r);
}

/* MSAA past the context's sample counts names options.msaa, its value and the counts the context
 * has, from set_options and from create (TL_ERROR_UNSUPPORTED: the context, not the value's range,
 * is the limit); the renderer keeps its options. Before: "target "target.depth.msaa": 8 samples,
 * the context allows 4 (GL_MAX_SAMPLES)", naming a target. */
TL_TEST(renderer_msaa_past_the_context_names_options_msaa)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    typedef void (*get_integer_fn)(unsigned, int *);
    get_integer_fn get_integer = (get_integer_fn)tl_context_get_proc_address(g_ctx, "glGetIntegerv");
    int max_samples = 0;
    if (get_integer) get_integer(0x8D57 /* GL_MAX_SAMPLES */, &max_samples);
    if (max_samples >= 8) {
        printf("  this context has 8 samples (GL_MAX_SAMPLES %d): nothing to refuse\n", max_samples);
        return;
    }
    said log = {0};
    tl_renderer *r = renderer(&log);
    if (!r) return;
    static test_scene t;
    lit_room(&t);
    TL_CHECK(tl_renderer_set_scene(r, &t.s) == TL_OK);
    const char *want = "renderer: set_options: options.msaa = 8 is out of range for this context (0, 1";
    tl_result res = tl_renderer_set_options(r, &(tl_renderer_options){.msaa = 8});
    printf("  set_options: %s \"%s\"\n", tl_result_string(res), log.last);
    TL_CHECK(res == TL_ERROR_UNSUPPORTED && strncmp(log.last, want, strlen(want)) == 0);
    TL_CHECK(strstr(log.last, "the sample counts its multisampled target formats have)") != NULL);
    tl_renderer_options kept;
    tl_renderer_get_options(r, &kept);
    TL_CHECK_EQ_U(kept.msaa, 0);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    said at_create = {0};
    tl_renderer_desc d = {.width = W, .height = H, .options.msaa = 8, .get_proc_address = tl_context_proc_loader,
                          .get_proc_address_user = g_ctx, .logger = {said_log, &at_create}};
    tl_renderer *bad = NULL;
    res = tl_renderer_create(&d, &bad);
    printf("  create: %s \"%s\"\n", tl_result_string(res), at_create.last);
    const char *want_create = "renderer: options.msaa = 8 is out of range for this context (0, 1";
    TL_CHECK(res == TL_ERROR_UNSUPPORTED && !bad);
    TL_CHECK_EQ_U(at_create.errors, 1);
    TL_CHECK(strncmp(at_create.last, want_create, strlen(want_create)) == 0);
    tl_renderer_destroy(bad);
    tl_renderer_destroy(r);
}
