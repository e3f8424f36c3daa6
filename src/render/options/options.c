/* The option registry (thinlight/options.h): the frame's own fields and the shadows' here, each
 * effect's in its pass file (tl__pass_def.option_rows), enumerated in that order. */
#include <string.h>

#include "pass.h"
#include "plan_internal.h"
#include "shadows.h"

#define TL__E(x) ((double)(x))

const tl_option_info tl__frame_option_rows[] = {
    TL__OPT_ENUM(mode, tl_render_mode, TL_MODE_COUNT_, TL_MODE_THIN_LPP, NULL,
                 "how the frame is rendered: thin G-buffer with light buffer, thin deferred, fat (the reference), forward, "
                 "or a visibility buffer (depth and a triangle id, shaded by a compute resolve)"),
    TL__OPT_ENUM(depth_format, tl_depth_format, TL_DEPTH_FORMAT_COUNT_, TL_DEPTH_FORMAT_D24, NULL,
                 "depth storage: D24S8, D32F, or D32F with reversed Z"),
    TL__OPT_ENUM(rt0, tl_rt0_packing, TL_RT0_COUNT_, TL_RT0_RGBA8, NULL,
                 "thin RT0: octahedral normal 2x12 + gloss 8, or 2x10 + gloss 10"),
    TL__OPT_ENUM(light_buffer, tl_light_buffer, TL_LIGHT_BUFFER_COUNT_, TL_LIGHT_BUFFER_EXACT, NULL,
                 "thin-lpp light buffer: diffuse and specular apart (exact), or one RGBA16F (compact)"),
    TL__OPT_ENUM(light_format, tl_light_format, TL_LIGHT_FORMAT_COUNT_, TL_LIGHT_FORMAT_RGBA16F, NULL,
                 "light buffer storage; r11g11b10f needs the exact layout"),
    TL__OPT_ENUM(light_strategy, tl_light_strategy, TL_LIGHT_STRATEGY_COUNT_, 0, "auto: the planner picks",
                 "how lights are accumulated: light volumes or screen tiles"),
    TL__OPT_ENUM(lighting, tl_lighting_model, TL_LIGHTING_COUNT_, 0, "auto: from the scene's materials",
                 "the frame's lighting model"),
    TL__OPT_ENUM(fresnel, tl_fresnel_layout, TL_FRESNEL_COUNT_, TL_FRESNEL_TWO_SUMS, NULL,
                 "thin-lpp with GGX: two specular sums (exact) or one, Schlick with n.v per pixel"),
    TL__OPT_UINT(tile_size, 8, 32, TL_OPTION_POW2, TL__TILE_SIZE_DEFAULT, "px", "tiled strategy: tile side"),
    TL__OPT_ENUM(tiled_shading, tl_tiled_shading, TL_TILED_SHADING_COUNT_, 0, "auto: the planner picks",
                 "tiled strategy: the pass that shades the tiles"),
    TL__OPT_FLOAT(light_scale, 0.25, 1, TL_OPTION_POW2, 1, NULL, "per axis",
                  "thin-lpp: the light buffer's size against the frame's"),
    TL__OPT_ENUM(transparency, tl_transparency, TL_TRANSPARENCY_COUNT_, 0, "auto: stipple where it applies",
                 "alpha-blended materials: forward after the opaque frame, or stippled into the G-buffer"),
    TL__OPT_UINT(msaa, 1, 8, TL_OPTION_POW2, 1, "samples", "multisample antialiasing (1: off)"),
    TL__OPT_ENUM(fxaa, tl_fxaa_preset, TL_FXAA_COUNT_, TL_FXAA_29, NULL, "FXAA quality preset, or off"),
    TL__OPT_FLOAT(fxaa_edge_threshold, TL__OPT_ABOVE_0, 0.166, NULL, "", "FXAA: relative local contrast of an edge"),
    TL__OPT_FLOAT(fxaa_edge_threshold_min, TL__OPT_ABOVE_0, 0.0833, NULL, "gamma-encoded luma",
                  "FXAA: least absolute contrast of an edge"),
    TL__OPT_FLOAT(fxaa_subpix, 0.0, TL__OPT_FINITE, TL_OPTION_MIN_OPEN | TL_OPTION_NEGATIVE_ZERO, 0.75, NULL, "",
                  "FXAA: sub-pixel aliasing removal"),
    TL__OPT_FLOAT(exposure, TL__OPT_ABOVE_0, 1, NULL, "", "multiplies HDR colour before tone mapping"),
    TL__OPT_FLOAT3(ambient, 0.0, TL__OPT_FINITE, TL_OPTION_NEGATIVE_ZERO, "the scene's ambient (all three 0)",
                   "linear radiance", "ambient radiance replacing the scene's"),
    TL__OPT_SWITCH(forward_depth_prepass, "forward mode's depth pre-pass"),
    TL__OPT_SWITCH(planning, "off: plan for every feature whatever the scene uses (what planning saves)"),
    TL__OPT_BOOL(fullscreen_lights, "point and spot lights shaded over the whole screen (the volumes' reference)"),
    {TL__OPT_AT(keep_targets), .type = TL_OPTION_TARGETS, .max = 0x1p53, .unit = "",
     .help = "targets given memory of their own, to read back after a frame", .count = TL_TARGET_COUNT,
     .value_name = tl__value_name_tl_target_id},
    TL__OPT_BOOL(synchronous_stats, "every frame waits for the GPU and reads its own statistics"),
    TL__OPT_ENUM(msaa_lighting, tl_msaa_lighting, TL_MSAA_LIGHTING_COUNT_, 0,
                 "the mode's: thin-lpp the material pass, thin-deferred and fat per-sample edges",
                 "how a multisampled frame is lit"),
    TL__OPT_ENUM(clearcoat, tl_clearcoat_lighting, TL_CLEARCOAT_COUNT_, 0, "auto: the coat's own sums where they apply",
                 "thin-lpp: how a clearcoat's coat is lit"),
    /* the shadow atlas (shadows.h; not a pass of the table) */
    TL__OPT_SWITCH(shadows.enabled, "off: no light casts, whatever its shadow flag says"),
    TL__OPT_UINT(shadows.atlas_size, 1024, 16384, TL_OPTION_POW2, 4096, "texels", "the shadow atlas's side"),
    TL__OPT_UINT(shadows.max_lights, 1, TL__SHADOW_MAX_LIGHTS, 0, TL_SHADOW_DEFAULT_MAX_LIGHTS, "lights",
                 "most casting lights given a map per frame (the budget)"),
    TL__OPT_UINT(shadows.pcf_radius, 1, 3, 0, 1, "texels", "PCF kernel radius r: (2 r + 1)^2 bilinear compare taps"),
    TL__OPT_SWITCH(shadows.cache, "off: every shadow map rendered every frame"),
    TL__OPT_ENUM(shadows.filter, tl_shadow_filter, TL_SHADOW_FILTER_COUNT_, TL_SHADOW_FILTER_PCF, NULL,
                 "shadow filter: PCF, PCSS (penumbrae from the light's size) or one bilinear tap"),
    TL__OPT_FLOAT(shadows.directional_angle, 0.0, 0.2, TL_OPTION_MIN_OPEN, 0.00465, NULL, "radians",
                  "PCSS: angular radius of directional lights' discs"),
};
const size_t tl__frame_option_row_count = sizeof tl__frame_option_rows / sizeof tl__frame_option_rows[0];

size_t tl_option_count(void)
{
    size_t n = tl__frame_option_row_count;
    for (int i = 0; i < TL_PASS_COUNT; i++) n += tl__pass_table[i]->option_row_count;
    return n;
}

const tl_option_info *tl_option_at(size_t index)
{
    if (index < tl__frame_option_row_count) return &tl__frame_option_rows[index];
    index -= tl__frame_option_row_count;
    for (int i = 0; i < TL_PASS_COUNT; i++) {
        const tl__pass_def *p = tl__pass_table[i];
        if (index < p->option_row_count) return &p->option_rows[index];
        index -= p->option_row_count;
    }
    return NULL;
}

const tl_option_info *tl_option_find(const char *name)
{
    const tl_option_info *o;
    for (size_t i = 0; name && (o = tl_option_at(i)) != NULL; i++)
        if (strcmp(o->name, name) == 0) return o;
    return NULL;
}
