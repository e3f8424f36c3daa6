/* The option registry's private side (thinlight/options.h is the public one): the row builders the
 * registry's tables are written with (options.c: the frame's own fields and the shadows'; each pass
 * its own, tl__pass_def.option_rows), the enum names every row and name function share
 * (option_names.c), and the check and the defaults every set of options goes through (desc.c):
 * a range is spelled once, in its row, and a refusal names the field, its value and that range,
 * e.g. "options.ssr.refine = 9 is out of range (1..8; 0: 4)". */
#ifndef TL_RENDER_OPTION_CHECK_H
#define TL_RENDER_OPTION_CHECK_H

#include <float.h>
#include <stddef.h>
#include <stdint.h>

#include "core/log.h"
#include "thinlight/options.h"

/* Why options were refused: one line naming the field, its value and what it may be. */
typedef struct tl__why {
    char text[256];
} tl__why;

/* Writes a message of its own into `why` (may be NULL); returns 0, a refusal. */
int tl__why_say(tl__why *why, const char *fmt, ...) TL__PRINTF_LIKE(2, 3);

/* ---- the enums' names ------------------------------------------------------------------------ */

/* Every option enum: its C type, its count and the name of each value from 0 (DEFAULT: the name of
 * the value it stands for, or its own where it means "the planner picks"). option_names.c makes
 * from each line the public tl_X_name / tl_X_from_name and the registry's value_name. */
#define TL__OPTION_ENUMS(X)                                                                                       \
    X(tl_render_mode, render_mode, TL_MODE_COUNT_, "thin-lpp", "thin-lpp", "thin-deferred", "fat", "forward", "visibility")     \
    X(tl_rt0_packing, rt0_packing, TL_RT0_COUNT_, "rgba8", "rgba8", "rgb10a2")                                    \
    X(tl_light_buffer, light_buffer, TL_LIGHT_BUFFER_COUNT_, "exact", "exact", "compact")                         \
    X(tl_light_format, light_format, TL_LIGHT_FORMAT_COUNT_, "rgba16f", "rgba16f", "r11g11b10f")                  \
    X(tl_light_strategy, light_strategy, TL_LIGHT_STRATEGY_COUNT_, "auto", "volumes", "tiled")                    \
    X(tl_tiled_shading, tiled_shading, TL_TILED_SHADING_COUNT_, "auto", "fragment", "compute")                    \
    X(tl_lighting_model, lighting_model, TL_LIGHTING_COUNT_, "auto", "blinn-phong", "ggx")                        \
    X(tl_fresnel_layout, fresnel_layout, TL_FRESNEL_COUNT_, "two-sums", "two-sums", "nv")                         \
    X(tl_transparency, transparency, TL_TRANSPARENCY_COUNT_, "auto", "forward", "stipple")                        \
    X(tl_msaa_lighting, msaa_lighting, TL_MSAA_LIGHTING_COUNT_, "default", "material-pass", "per-sample-edges")   \
    X(tl_clearcoat_lighting, clearcoat_lighting, TL_CLEARCOAT_COUNT_, "auto", "approx", "sums")                   \
    X(tl_fxaa_preset, fxaa_preset, TL_FXAA_COUNT_, "29", "off", "12", "29", "39")                                 \
    X(tl_ssao_method, ssao_method, TL_SSAO_COUNT_, "disc", "disc", "hemisphere")                                  \
    X(tl_fog_mode, fog_mode, TL_FOG_COUNT_, "distance", "distance", "height")                                     \
    X(tl_shadow_filter, shadow_filter, TL_SHADOW_FILTER_COUNT_, "pcf", "pcf", "pcss", "bilinear")                 \
    X(tl_switch, switch, TL_SWITCH_COUNT_, "on", "on", "off")

/* The registry's value_name of each enum (and of tl_depth_format, whose names codec.h has). */
#define TL__VALUE_NAME_DECL(type, short_, count, ...) const char *tl__value_name_##type(uint32_t value);
TL__OPTION_ENUMS(TL__VALUE_NAME_DECL)
#undef TL__VALUE_NAME_DECL
const char *tl__value_name_tl_depth_format(uint32_t value);
const char *tl__value_name_tl_target_id(uint32_t value);

/* ---- rows ------------------------------------------------------------------------------------- */

#define TL__OPT_AT(path)                                                                                          \
    .name = #path, .offset = offsetof(tl_renderer_options, path), .size = sizeof(((tl_renderer_options *)0)->path)
/* A field that is off by default (an effect's `enabled`): 0 or 1. */
#define TL__OPT_BOOL(path, help_) {TL__OPT_AT(path), .type = TL_OPTION_BOOL, .max = 1, .unit = "", .help = (help_)}
/* A behaviour that is on unless turned off (tl_switch). */
#define TL__OPT_SWITCH(path, help_)                                                                               \
    {TL__OPT_AT(path), .type = TL_OPTION_SWITCH, .max = TL_SWITCH_COUNT_ - 1, .zero = TL_SWITCH_ON, .unit = "",    \
     .help = (help_), .c_type = "tl_switch", .count = TL_SWITCH_COUNT_, .value_name = tl__value_name_tl_switch}
/* An enum whose zero resolves to `zero_` (zero_text_ NULL) or means what zero_text_ says. */
#define TL__OPT_ENUM(path, ctype, count_, zero_, zero_text_, help_)                                               \
    {TL__OPT_AT(path), .type = TL_OPTION_ENUM, .max = (count_) - 1, .zero = (zero_), .zero_text = (zero_text_),   \
     .unit = "", .help = (help_), .c_type = #ctype, .count = (count_), .value_name = tl__value_name_##ctype}
#define TL__OPT_UINT(path, lo, hi, flags_, zero_, unit_, help_)                                                   \
    {TL__OPT_AT(path), .type = TL_OPTION_UINT, .min = (lo), .max = (hi), .flags = (flags_), .zero = (zero_),      \
     .unit = (unit_), .help = (help_)}
/* (TL__OPT_FLOAT and TL__OPT_FLOAT3 expand their arguments first: TL__OPT_ABOVE_0 is three of them.) */
#define TL__OPT_FLOAT(...) TL__OPT_FLOAT_(__VA_ARGS__)
#define TL__OPT_FLOAT3(...) TL__OPT_FLOAT3_(__VA_ARGS__)
#define TL__OPT_FLOAT_(path, lo, hi, flags_, zero_, zero_text_, unit_, help_)                                     \
    {TL__OPT_AT(path), .type = TL_OPTION_FLOAT, .min = (lo), .max = (hi), .flags = (flags_), .zero = (zero_),     \
     .zero_text = (zero_text_), .unit = (unit_), .help = (help_)}
#define TL__OPT_FLOAT3_(path, lo, hi, flags_, zero_text_, unit_, help_)                                           \
    {TL__OPT_AT(path), .type = TL_OPTION_FLOAT3, .min = (lo), .max = (hi), .flags = (flags_),                     \
     .zero_text = (zero_text_), .unit = (unit_), .help = (help_)}
/* No bound but finite; an interval open at 0 (values above 0). */
#define TL__OPT_FINITE FLT_MAX
#define TL__OPT_ABOVE_0 0.0, FLT_MAX, TL_OPTION_MIN_OPEN

/* The frame's own fields and the shadows' (options.c); the passes' are in the pass table. */
extern const tl_option_info tl__frame_option_rows[];
extern const size_t tl__frame_option_row_count;

/* ---- checks and defaults (option_check.c) -------------------------------------------------- */

/* 1 when every field of `o` holds zero, a value in range or (TL_OPTION_NEGATIVE_ZERO) a negative
 * one; 0 with the first that does not in `why` (may be NULL) as "options.NAME = VALUE is out of
 * range (RANGE)". The fields below an effect's `enabled` (its struct's rows, which follow it) are
 * not looked at while it is 0. */
int tl__options_check(const tl_renderer_options *o, tl__why *why);
/* Every field whose default is one value (zero_text NULL): zero becomes `zero`, and with
 * TL_OPTION_NEGATIVE_ZERO a negative float becomes 0. Computed defaults are the passes' (resolve). */
void tl__options_defaults(tl_renderer_options *o);

#endif
