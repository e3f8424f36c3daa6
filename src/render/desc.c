/* Renderer options with their defaults resolved (the one place a zeroed field becomes a value). */
#include <math.h>
#include <string.h>

#include "plan_internal.h"
#include "targets.h"

static int tl__finite4(float a, float b, float c, float d) { return isfinite(a) && isfinite(b) && isfinite(c) && isfinite(d); }

/* The effects' defaults (docs/effects.md); 0 for values out of range. An effect that is off keeps
 * its zeroes, so that its other fields cannot change a plan. */
static int tl__ssao_resolve(tl_ssao_desc *s)
{
    if ((unsigned)s->method >= TL_SSAO_COUNT_) return 0;
    if (s->method == TL_SSAO_OFF) {
        memset(s, 0, sizeof *s);
        return 1;
    }
    if (!s->samples) s->samples = 16;
    if (!(s->radius > 0.0f)) s->radius = 1.0f;
    if (!(s->falloff > 0.0f)) s->falloff = 2.0f * s->radius;
    if (!(s->exponent > 0.0f)) s->exponent = 3.0f;
    if (!(s->bias > 0.0f)) s->bias = 0.0f;
    if (!s->blur_radius) s->blur_radius = 2;
    s->diffuse = s->diffuse != 0;
    return s->samples <= 64 && s->blur_radius <= 8 && tl__finite4(s->radius, s->falloff, s->exponent, s->bias);
}

static int tl__fog_resolve(tl_fog_desc *f)
{
    if ((unsigned)f->mode >= TL_FOG_COUNT_) return 0;
    if (f->mode == TL_FOG_OFF) {
        memset(f, 0, sizeof *f);
        return 1;
    }
    if (!(f->density > 0.0f)) f->density = 0.05f;
    if (!(f->height_falloff > 0.0f)) f->height_falloff = 0.5f;
    if (!(f->noise > 0.0f)) f->noise = 0.0f;
    if (!(f->noise_scale > 0.0f)) f->noise_scale = 0.5f;
    if (f->noise_speed == 0.0f) f->noise_speed = 0.3f;
    for (int k = 0; k < 3; k++)
        if (!(f->color[k] >= 0.0f) || !isfinite(f->color[k])) return 0;
    return f->noise <= 1.0f && tl__finite4(f->density, f->height, f->height_falloff, f->noise_scale) &&
           isfinite(f->noise_speed);
}

static int tl__dof_resolve(tl_dof_desc *f)
{
    if (!f->enabled) {
        memset(f, 0, sizeof *f);
        return 1;
    }
    f->enabled = 1;
    if (!(f->focus_distance > 0.0f)) f->focus_distance = 0.0f; /* 0: the camera's target, per frame */
    if (!(f->aperture > 0.0f)) f->aperture = 0.01f;
    if (!(f->max_radius > 0.0f)) f->max_radius = 2.0f * f->aperture;
    if (!f->samples) f->samples = 48;
    return f->samples >= 8 && f->samples <= 128 && isfinite(f->focus_distance) && f->aperture <= 1.0f &&
           f->max_radius <= 1.0f;
}

static int tl__bloom_resolve(tl_bloom_desc *b)
{
    if (!b->enabled) {
        memset(b, 0, sizeof *b);
        return 1;
    }
    b->enabled = 1;
    if (b->threshold == 0.0f) b->threshold = 1.0f;
    if (b->threshold < 0.0f) b->threshold = 0.0f;
    if (b->knee == 0.0f) b->knee = 0.5f;
    if (b->knee < 0.0f) b->knee = 0.0f;
    if (!(b->intensity > 0.0f)) b->intensity = 0.5f;
    if (!(b->scatter > 0.0f)) b->scatter = 0.7f;
    if (!b->levels) b->levels = 6;
    return b->levels <= TL__MAX_LEVELS && b->knee <= 1.0f && b->scatter <= 1.0f &&
           tl__finite4(b->threshold, b->knee, b->intensity, b->scatter);
}

static int tl__ssr_resolve(tl_ssr_desc *s)
{
    if (!s->enabled) {
        memset(s, 0, sizeof *s);
        return 1;
    }
    s->enabled = 1;
    if (!s->steps) s->steps = 48;
    if (!s->refine) s->refine = 4;
    if (!(s->max_distance > 0.0f)) s->max_distance = 16.0f;
    if (!(s->thickness > 0.0f)) s->thickness = 0.4f;
    if (!(s->min_gloss > 0.0f)) s->min_gloss = s->min_gloss == 0.0f ? 0.4f : 0.0f;
    if (!(s->edge_fade > 0.0f)) s->edge_fade = 0.1f;
    if (!(s->intensity > 0.0f)) s->intensity = 1.0f;
    return s->steps >= 4 && s->steps <= 256 && s->refine <= 8 && s->min_gloss < 1.0f && s->edge_fade <= 0.5f &&
           tl__finite4(s->max_distance, s->thickness, s->intensity, s->min_gloss);
}

static tl_result tl__effects_resolve(tl_renderer_desc *d)
{
    int ok = tl__ssao_resolve(&d->options.ssao);
    ok &= tl__fog_resolve(&d->options.fog);
    ok &= tl__dof_resolve(&d->options.dof);
    ok &= tl__bloom_resolve(&d->options.bloom);
    ok &= tl__ssr_resolve(&d->options.ssr);
    return ok ? TL_OK : TL_ERROR_INVALID_ARGUMENT;
}

tl_result tl__renderer_desc_resolve(const tl_renderer_desc *in, tl_renderer_desc *d)
{
    *d = *in;
    if (d->options.mode == TL_MODE_DEFAULT) d->options.mode = TL_MODE_THIN_LPP;
    if (!d->width) d->width = 1280;
    if (!d->height) d->height = 720;
    if (d->options.depth_format == TL_DEPTH_FORMAT_DEFAULT) d->options.depth_format = TL_DEPTH_FORMAT_D24;
    if (d->options.rt0 == TL_RT0_DEFAULT) d->options.rt0 = TL_RT0_RGBA8;
    if (d->options.light_buffer == TL_LIGHT_BUFFER_DEFAULT) d->options.light_buffer = TL_LIGHT_BUFFER_EXACT;
    if (d->options.light_format == TL_LIGHT_FORMAT_DEFAULT) d->options.light_format = TL_LIGHT_FORMAT_RGBA16F;
    if (d->options.tiled_shading == TL_TILED_SHADING_DEFAULT) d->options.tiled_shading = TL_TILED_SHADING_FRAGMENT;
    if (d->options.fresnel == TL_FRESNEL_DEFAULT) d->options.fresnel = TL_FRESNEL_TWO_SUMS;
    if (!d->options.tile_size) d->options.tile_size = TL__TILE_SIZE_DEFAULT;
    if (d->options.fxaa == TL_FXAA_DEFAULT) d->options.fxaa = TL_FXAA_29;
    if (d->options.fxaa_edge_threshold <= 0.0f) d->options.fxaa_edge_threshold = 0.166f;
    if (d->options.fxaa_edge_threshold_min <= 0.0f) d->options.fxaa_edge_threshold_min = 0.0833f;
    if (d->options.fxaa_subpix == 0.0f) d->options.fxaa_subpix = 0.75f;
    if (d->options.fxaa_subpix < 0.0f) d->options.fxaa_subpix = 0.0f;
    if (!(d->options.exposure > 0.0f)) d->options.exposure = 1.0f;
    if ((unsigned)d->options.mode >= TL_MODE_COUNT_ || (unsigned)d->options.depth_format >= TL_DEPTH_FORMAT_COUNT_ ||
        (unsigned)d->options.rt0 >= TL_RT0_COUNT_ || (unsigned)d->options.light_buffer >= TL_LIGHT_BUFFER_COUNT_ ||
        (unsigned)d->options.fxaa >= TL_FXAA_COUNT_ || (unsigned)d->options.light_format >= TL_LIGHT_FORMAT_COUNT_ ||
        (unsigned)d->options.light_strategy >= TL_LIGHT_STRATEGY_COUNT_ || (unsigned)d->options.tiled_shading >= TL_TILED_SHADING_COUNT_ ||
        (unsigned)d->options.lighting >= TL_LIGHTING_COUNT_ || (unsigned)d->options.fresnel >= TL_FRESNEL_COUNT_)
        return TL_ERROR_INVALID_ARGUMENT;
    for (int k = 0; k < 3; k++)
        if (!isfinite(d->options.ambient[k])) return TL_ERROR_INVALID_ARGUMENT;
    if (d->options.tile_size != 8 && d->options.tile_size != 16 && d->options.tile_size != 32) return TL_ERROR_INVALID_ARGUMENT;
    /* R11G11B10F has no alpha for the compact layout's specular luminance */
    if (d->options.light_format == TL_LIGHT_FORMAT_R11G11B10F && d->options.light_buffer != TL_LIGHT_BUFFER_EXACT)
        return TL_ERROR_INVALID_ARGUMENT;
    if (d->width > TL__MAX_SIZE || d->height > TL__MAX_SIZE) return TL_ERROR_LIMIT;
    return tl__effects_resolve(d);
}
