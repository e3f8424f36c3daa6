/* Targets as the passes declare them (targets.h). */
#include <string.h>

#include "targets.h"
#include "bindings.h"
#include "pass.h"

/* A target samples on texture unit = its id: the material textures' units come after them. */
_Static_assert((int)TL_TARGET_COUNT <= (int)TL__UNIT_ALBEDO_TEXTURE, "target texture units overlap the material textures'");
/* TL_TARGET_BIT sets are 32 bits */
_Static_assert((int)TL_TARGET_COUNT <= 32, "more targets than TL_TARGET_BIT sets hold");

void tl__target_defs(const tl__target_def *out[TL_TARGET_COUNT])
{
    for (int t = 0; t < TL_TARGET_COUNT; t++) out[t] = NULL;
    for (int i = 0; i < TL_PASS_COUNT; i++)
        for (int k = 0; k < TL__PASS_MAX_TARGETS && tl__pass_table[i]->targets[k]; k++) {
            const tl__target_def *d = tl__pass_table[i]->targets[k];
            if ((unsigned)d->id < TL_TARGET_COUNT) out[d->id] = d;
        }
}

const char *tl_target_name(tl_target_id t)
{
    const tl__target_def *defs[TL_TARGET_COUNT];
    tl__target_defs(defs);
    return (unsigned)t < TL_TARGET_COUNT && defs[t] ? defs[t]->name : "unknown";
}

tl_result tl_target_from_name(const char *name, tl_target_id *target)
{
    const tl__target_def *defs[TL_TARGET_COUNT];
    tl__target_defs(defs);
    for (int t = 0; name && target && t < TL_TARGET_COUNT; t++)
        if (defs[t] && strcmp(defs[t]->name, name) == 0) {
            *target = (tl_target_id)t;
            return TL_OK;
        }
    return TL_ERROR_INVALID_ARGUMENT;
}

uint32_t tl__target_format(const tl__target_def *def, const tl_renderer_options *o)
{
    if (!def || def->buffer_bytes) return 0;
    return def->format_of ? def->format_of(o) : def->format;
}

uint32_t tl__target_shift(const tl__target_def *def, const tl_renderer_options *o)
{
    if (!def) return 0u;
    return def->shift_of ? def->shift_of(o) : def->shift;
}

uint32_t tl__target_samples(const tl__target_def *def, const tl_renderer_options *o)
{
    return def && def->samples_of ? def->samples_of(o) : 1u;
}

const char *tl__msaa_refusal(const tl_renderer_options *o)
{
    if (o->msaa <= 1u) return NULL;
    if (o->mode != TL_MODE_THIN_LPP && o->mode != TL_MODE_FORWARD) return "thin-deferred and fat have no multisampled G-buffer";
    if (tl__light_shift(o)) return "the reduced light buffer's upsample runs at one sample";
    if (o->ssao.method != TL_SSAO_OFF || o->fog.mode != TL_FOG_OFF || o->dof.enabled || o->bloom.enabled || o->ssr.enabled ||
        o->vignette.enabled)
        return "screen-space effects read a one-sample HDR and depth";
    return NULL;
}

uint32_t tl__msaa_samples(const tl_renderer_options *o) { return o->msaa > 1u && !tl__msaa_refusal(o) ? o->msaa : 1u; }

uint32_t tl__light_shift(const tl_renderer_options *o)
{
    if (o->mode != TL_MODE_THIN_LPP) return 0u;
    return o->light_scale == 0.25f ? 2u : o->light_scale == 0.5f ? 1u : 0u;
}

void tl__target_size(const tl__target_def *def, const tl_renderer_options *o, uint32_t width, uint32_t height,
                     uint32_t *out_width, uint32_t *out_height, uint32_t *levels)
{
    unsigned shift = tl__target_shift(def, o);
    uint32_t w = (uint32_t)(((uint64_t)width + (1u << shift) - 1u) >> shift);
    uint32_t h = (uint32_t)(((uint64_t)height + (1u << shift) - 1u) >> shift);
    *out_width = w ? w : 1u;
    *out_height = h ? h : 1u;
    uint32_t want = def && def->levels_of ? def->levels_of(o) : 1u, n = 1;
    /* GL halves each level rounding down, to 1x1 at the least: a level exists while the larger side is >= 2^level */
    while (n < want && n < TL__MAX_LEVELS && ((*out_width > *out_height ? *out_width : *out_height) >> n) >= 1u) n++;
    *levels = n;
}
