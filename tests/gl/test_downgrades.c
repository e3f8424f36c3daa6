/* Downgrades (docs/frame.md, "Downgrades"): an option the plan does not honour as asked is listed
 * in tl_frame_plan.downgrades with its name, the value asked, what the plan does instead and why;
 * the same options at their defaults (or without the conflicting one) list nothing; the renderer
 * logs each downgrade once, however many frames and re-plans follow; forward keeps MSAA with
 * reflections asked (it runs none). Before, none of this was listed (no such field), the reasons
 * were only in msaa_reason and the like, and forward with ssr dropped MSAA. */
#include "tl_test.h"

#include <string.h>

#include "render_room.h"
#include "thinlight/renderer.h"

/* The scene a case plans for: lights, specular, GGX materials, a clearcoat and a blended object. */
static tl_scene_feature_set features(size_t local_lights, size_t shadow_lights)
{
    return (tl_scene_feature_set){.point_lights = local_lights, .directional_lights = 1, .has_specular = 1,
                                  .has_microfacet = 1, .has_alpha_blend = 1, .alpha_blend_objects = 1,
                                  .material_models = (1u << TL_MATERIAL_MODEL_STANDARD) |
                                                     (1u << TL_MATERIAL_MODEL_CLEARCOAT),
                                  .shadow_lights = shadow_lights};
}

typedef struct downgrade_case {
    const char *name;
    tl_renderer_options asked; /* the options making the downgrade */
    tl_renderer_options fixed; /* the same but the option given up (or its conflict): nothing listed */
    size_t lights;             /* local lights (32 and more: the tiled strategy) */
    const char *option, *value, *planned, *why; /* the downgrade expected (why: part of its reason) */
} downgrade_case;

static const downgrade_case k_cases[] = {
    {"msaa with a light scale", {.msaa = 4, .light_scale = 0.5f}, {.light_scale = 0.5f}, 4, "msaa", "4", "1",
     "reduced light buffer"},
    {"msaa with per-sample edges in forward",
     {.mode = TL_MODE_FORWARD, .msaa = 4, .msaa_lighting = TL_MSAA_LIGHTING_SAMPLE_EDGES},
     {.mode = TL_MODE_FORWARD, .msaa = 4}, 4, "msaa", "4", "1", "every sample"},
    {"msaa with an effect", {.msaa = 2, .bloom.enabled = 1}, {.bloom.enabled = 1}, 4, "msaa", "2", "1", "bloom reads a one-sample HDR"},
    {"light scale outside thin-lpp", {.mode = TL_MODE_FAT, .light_scale = 0.25f}, {.mode = TL_MODE_FAT}, 4,
     "light_scale", "0.25", "1", "only thin-lpp"},
    {"stipple with fog", {.transparency = TL_TRANSPARENCY_STIPPLE, .fog = {.enabled = 1, .mode = TL_FOG_DISTANCE}},
     {.fog = {.enabled = 1, .mode = TL_FOG_DISTANCE}}, 4, "transparency", "stipple", "forward", "fog"},
    {"stipple in fat", {.mode = TL_MODE_FAT, .transparency = TL_TRANSPARENCY_STIPPLE}, {.mode = TL_MODE_FAT}, 4,
     "transparency", "stipple", "forward", "thin-lpp"},
    {"clearcoat sums with MSAA", {.clearcoat = TL_CLEARCOAT_SUMS, .msaa = 4}, {.msaa = 4}, 4, "clearcoat", "sums",
     "approx", "MSAA"},
    {"clearcoat sums with a light scale", {.clearcoat = TL_CLEARCOAT_SUMS, .light_scale = 0.5f}, {.light_scale = 0.5f},
     4, "clearcoat", "sums", "approx", "reduced light buffer"},
    {"two Fresnel sums in the compact light buffer",
     {.fresnel = TL_FRESNEL_TWO_SUMS, .light_buffer = TL_LIGHT_BUFFER_COMPACT},
     {.light_buffer = TL_LIGHT_BUFFER_COMPACT}, 4, "fresnel", "two-sums", "nv", "compact"},
    {"reflections in forward", {.mode = TL_MODE_FORWARD, .ssr.enabled = 1}, {.mode = TL_MODE_FORWARD}, 4,
     "ssr.enabled", "1", "0", "forward"},
    {"SSAO in forward without the pre-pass",
     {.mode = TL_MODE_FORWARD, .forward_depth_prepass = TL_SWITCH_OFF, .ssao = {.enabled = 1, .method = TL_SSAO_HEMISPHERE}},
     {.mode = TL_MODE_FORWARD, .forward_depth_prepass = TL_SWITCH_OFF}, 4, "ssao.enabled", "1", "0", "pre-pass"},
    {"no pre-pass in Forward+", {.mode = TL_MODE_FORWARD, .forward_depth_prepass = TL_SWITCH_OFF}, {.mode = TL_MODE_FORWARD},
     40, "forward_depth_prepass", "off", "on", "Forward+"},
    {"shadow debug with per-sample edges", {.mode = TL_MODE_FAT, .msaa = 4, .shadow_debug = 1},
     {.mode = TL_MODE_FAT, .msaa = 4}, 4, "shadow_debug", "1", "0", "multisampled"},
    {"full-screen lights with tiles", {.fullscreen_lights = 1}, {0}, 40, "fullscreen_lights", "1", "0", "tiled"},
    /* visibility lights in its compute resolve from the tile lists, and has no light buffer */
    {"light volumes in visibility", {.mode = TL_MODE_VISIBILITY, .light_strategy = TL_LIGHT_STRATEGY_VOLUMES},
     {.mode = TL_MODE_VISIBILITY}, 4, "light_strategy", "volumes", "tiled", "tile lists"},
    {"fragment tiles in visibility", {.mode = TL_MODE_VISIBILITY, .tiled_shading = TL_TILED_SHADING_FRAGMENT},
     {.mode = TL_MODE_VISIBILITY}, 4, "tiled_shading", "fragment", "compute", "compute pass"},
    {"light scale in visibility", {.mode = TL_MODE_VISIBILITY, .light_scale = 0.5f}, {.mode = TL_MODE_VISIBILITY}, 4,
     "light_scale", "0.5", "1", "only thin-lpp"},
    {"stipple in visibility", {.mode = TL_MODE_VISIBILITY, .transparency = TL_TRANSPARENCY_STIPPLE},
     {.mode = TL_MODE_VISIBILITY}, 4, "transparency", "stipple", "forward", "thin-lpp"},
};

/* The room (render_room.h) with a point light and a directional one. */
static void lit_room(test_scene *t)
{
    build_room(t);
    t->lights[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {2.0f, 4.0f, 3.0f}, .color = {3.0f, 2.5f, 2.0f},
                              .radius = 12.0f};
    t->lights[1] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0.3f, -1.0f, -0.2f}, .color = {0.4f, 0.4f, 0.5f}};
    t->s.light_count = 2;
}

static void plan(const tl_renderer_options *o, size_t lights, tl_frame_plan *p)
{
    tl_scene_feature_set f = features(lights, 1);
    TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 160, .height = 90, .options = *o}, &f, p) == TL_OK);
}

TL_TEST(plan_lists_each_downgrade_with_option_value_and_reason)
{
    static tl_frame_plan p, q;
    for (size_t i = 0; i < sizeof k_cases / sizeof k_cases[0]; i++) {
        const downgrade_case *c = &k_cases[i];
        plan(&c->asked, c->lights, &p);
        plan(&c->fixed, c->lights, &q);
        char line[256];
        tl_plan_downgrade_format(p.downgrade_count ? &p.downgrades[0] : NULL, line, sizeof line);
        printf("  %-44s %zu listed: %s\n", c->name, p.downgrade_count, line);
        TL_CHECK_EQ_U(p.downgrade_count, 1);
        TL_CHECK_EQ_U(q.downgrade_count, 0);
        if (p.downgrade_count != 1) continue;
        const tl_plan_downgrade *d = &p.downgrades[0];
        TL_CHECK(!strcmp(d->option, c->option) && !strcmp(d->asked, c->value) && !strcmp(d->planned, c->planned));
        TL_CHECK(strstr(d->reason, c->why) != NULL);
        /* one line: "options.NAME = VALUE is planned as PLANNED: REASON", in --print-plan too */
        char want[320], text[16384];
        snprintf(want, sizeof want, "options.%s = %s is planned as %s: %s", c->option, c->value, c->planned, d->reason);
        TL_CHECK(!strcmp(line, want));
        TL_CHECK(tl_plan_downgrade_format(d, NULL, 0) == strlen(want));
        TL_CHECK(tl_frame_plan_format(&p, text, sizeof text) < sizeof text);
        snprintf(want, sizeof want, "downgrade: %s\n", line);
        TL_CHECK(strstr(text, want) != NULL);
    }
    /* every default, and the automatic choices a scene leads to, list nothing */
    const tl_renderer_options autos[] = {{0},
                                         {.fog = {.enabled = 1, .mode = TL_FOG_DISTANCE}},                 /* auto transparency: forward */
                                         {.msaa = 4},                                   /* auto clearcoat: approx */
                                         {.light_buffer = TL_LIGHT_BUFFER_COMPACT},     /* default Fresnel: nv */
                                         {.mode = TL_MODE_FORWARD, .tile_size = 32},    /* a tile size with volumes */
                                         {.mode = TL_MODE_FAT, .rt0 = TL_RT0_RGB10A2},  /* RT0 fat does not have */
                                         {.mode = TL_MODE_VISIBILITY},                  /* tiles by the mode */
                                         {.mode = TL_MODE_VISIBILITY, .light_strategy = TL_LIGHT_STRATEGY_TILED,
                                          .tiled_shading = TL_TILED_SHADING_COMPUTE, .light_scale = 1.0f}};
    for (size_t i = 0; i < sizeof autos / sizeof autos[0]; i++) {
        plan(&autos[i], 4, &p);
        TL_CHECK_EQ_U(p.downgrade_count, 0);
    }
    /* several at once, each listed */
    tl_renderer_options many = {.mode = TL_MODE_FORWARD, .msaa = 4, .msaa_lighting = TL_MSAA_LIGHTING_SAMPLE_EDGES,
                                .light_scale = 0.5f, .transparency = TL_TRANSPARENCY_STIPPLE, .ssr.enabled = 1};
    plan(&many, 4, &p);
    TL_CHECK_EQ_U(p.downgrade_count, 4);
    TL_CHECK(tl_plan_downgrade_format(NULL, NULL, 0) == 0);
}

/* Forward runs no reflections, so asking for them costs it nothing: MSAA stays, every target
 * multisampled as without ssr, and the frame is the same bytes. Before: MSAA dropped (1 sample). */
TL_TEST(forward_with_ssr_keeps_msaa)
{
    tl_frame_plan with, without;
    tl_renderer_options o = {.mode = TL_MODE_FORWARD, .msaa = 4, .fxaa = TL_FXAA_OFF};
    plan(&o, 4, &without);
    o.ssr.enabled = 1;
    plan(&o, 4, &with);
    TL_CHECK_EQ_U(with.msaa, 4);
    TL_CHECK_EQ_U(with.target_info[TL_TARGET_DEPTH].samples, 4);
    TL_CHECK_EQ_U(with.targets, without.targets);
    TL_CHECK(with.downgrade_count == 1 && !strcmp(with.downgrades[0].option, "ssr.enabled")); /* ssr, not msaa */
    if (!ensure_context()) return;
    test_scene t;
    lit_room(&t);
    uint8_t *px[2] = {NULL, NULL};
    size_t size = 160u * 90u * 4u;
    for (int k = 0; k < 2; k++) {
        tl_renderer_desc d = {.width = 160, .height = 90, .options = o};
        d.options.ssr.enabled = k;
        tl_renderer *r = tl_test_render_once(&t.s, d);
        tl_frame_plan p;
        TL_CHECK(r && tl_renderer_get_plan(r, &p) == TL_OK && p.msaa == 4);
        px[k] = malloc(size);
        TL_CHECK(r && px[k] && tl_renderer_read_output(r, px[k], &size) == TL_OK);
        tl_renderer_destroy(r);
    }
    size_t differ = 0;
    for (size_t i = 0; px[0] && px[1] && i < size; i++) differ += px[0][i] != px[1][i];
    printf("  forward, msaa 4: %zu of %zu bytes differ with ssr asked\n", differ, size);
    TL_CHECK_EQ_U(differ, 0);
    free(px[0]);
    free(px[1]);
}

typedef struct log_count {
    size_t msaa, warnings;
    char last[512];
} log_count;

static void count_log(void *user, tl_log_level level, const char *message)
{
    log_count *c = (log_count *)user;
    if (level != TL_LOG_WARNING) return;
    c->warnings++;
    c->msaa += strstr(message, "options.msaa = 4 is planned as 1") != NULL;
    snprintf(c->last, sizeof c->last, "%s", message);
}

/* The renderer logs a downgrade (TL_LOG_WARNING) when it first appears in a plan: once over frames,
 * a new scene, lights, a resize and the same options given again; again only after it went away
 * and came back. */
TL_TEST(renderer_logs_each_downgrade_once)
{
    if (!ensure_context()) return;
    test_scene t;
    lit_room(&t);
    log_count c = {0};
    tl_renderer_desc d = {.width = 96, .height = 54, .options = {.msaa = 4, .light_scale = 0.5f}, .logger = {count_log, &c}};
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .scene = &t.s});
    if (!r) return;
    for (int f = 0; f < 4; f++) TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK(tl_renderer_set_lights(r, t.s.lights, 1) == TL_OK); /* fewer light types: a re-plan */
    TL_CHECK(tl_renderer_resize(r, 80, 45) == TL_OK);
    TL_CHECK(tl_renderer_set_options(r, &d.options) == TL_OK);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    printf("  after frames, lights, a resize and the same options: %zu (\"%s\")\n", c.msaa, c.last);
    TL_CHECK_EQ_U(c.msaa, 1);
    TL_CHECK(strstr(c.last, "renderer: options.msaa = 4 is planned as 1: ") == c.last);
    tl_renderer_options o = d.options;
    o.light_scale = 1.0f; /* honoured: nothing to say */
    TL_CHECK(tl_renderer_set_options(r, &o) == TL_OK);
    TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
    TL_CHECK_EQ_U(c.msaa, 1);
    TL_CHECK(tl_renderer_set_options(r, &d.options) == TL_OK); /* back: said again */
    TL_CHECK_EQ_U(c.msaa, 2);
    TL_CHECK_EQ_U(c.warnings, 2);
    tl_frame_plan p;
    TL_CHECK(tl_renderer_get_plan(r, &p) == TL_OK && p.downgrade_count == 1);
    tl_renderer_destroy(r);
}
