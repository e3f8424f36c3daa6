/* Targets as the passes declare them (targets.h). */
#include <math.h>
#include <string.h>

#include "targets.h"
#include "bindings.h"
#include "pass.h"

_Static_assert((int)TL_TARGET_COUNT <= 64, "more targets than a tl_target_set holds");

void tl__target_defs(const tl__target_def *out[TL_TARGET_COUNT])
{
    for (int t = 0; t < TL_TARGET_COUNT; t++) out[t] = NULL;
    for (int i = 0; i < TL_PASS_COUNT; i++)
        for (int k = 0; k < TL__PASS_MAX_TARGETS && tl__pass_table[i]->targets[k]; k++) {
            const tl__target_def *d = tl__pass_table[i]->targets[k];
            if ((unsigned)d->id < TL_TARGET_COUNT) out[d->id] = d;
        }
}

tl_target_id tl__target_frame_output(void)
{
    const tl__target_def *defs[TL_TARGET_COUNT];
    tl__target_defs(defs);
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if (defs[t] && defs[t]->frame_output) return (tl_target_id)t;
    return TL_TARGET_COUNT;
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

/* The MSAA method the options ask for in their mode (the default: thin-lpp's material pass, the
 * deferred modes' per-sample edges; forward, which shades every sample, counts as the first). */
static tl_msaa_lighting tl__msaa_method(const tl_renderer_options *o)
{
    if (o->msaa_lighting != TL_MSAA_LIGHTING_DEFAULT) return o->msaa_lighting;
    int deferred = o->mode == TL_MODE_THIN_DEFERRED || o->mode == TL_MODE_FAT || o->mode == TL_MODE_VISIBILITY;
    return deferred ? TL_MSAA_LIGHTING_SAMPLE_EDGES : TL_MSAA_LIGHTING_MATERIAL_PASS;
}

/* Why per-sample lighting on edges cannot be planned (NULL: it can). */
static const char *tl__sample_edges_refusal(const tl_renderer_options *o)
{
    if (o->mode == TL_MODE_FORWARD) return "forward shades every sample: no per-sample-edges";
    return NULL;
}

const char *tl__msaa_refusal(const tl_renderer_options *o)
{
    if (o->msaa <= 1u) return NULL;
    tl_msaa_lighting m = tl__msaa_method(o);
    if (m == TL_MSAA_LIGHTING_SAMPLE_EDGES && tl__sample_edges_refusal(o)) return tl__sample_edges_refusal(o);
    if (m == TL_MSAA_LIGHTING_MATERIAL_PASS && o->mode != TL_MODE_THIN_LPP && o->mode != TL_MODE_FORWARD)
        return "only thin-lpp has a material pass (msaa-lighting per-sample-edges)";
    if (tl__light_shift(o)) return "the reduced light buffer's upsample runs at one sample";
    const char *effect = tl__passes_refuse(o, TL__REFUSES_MSAA);
    if (effect) return effect;
    return NULL;
}

const char *tl__msaa_how(const tl_renderer_options *o)
{
    if (o->mode == TL_MODE_FORWARD) return "forward: every pass multisampled";
    if (o->mode == TL_MODE_VISIBILITY) return "an id per sample: each triangle of a pixel shaded once, edges per sample";
    if (tl__msaa_sample_edges(o)) return "per-sample edges: G-buffer multisampled, edge pixels lit per sample";
    return "material pass multisampled over the 1x G-buffer and light buffer";
}

uint32_t tl__msaa_samples(const tl_renderer_options *o) { return o->msaa > 1u && !tl__msaa_refusal(o) ? o->msaa : 1u; }

int tl__msaa_sample_edges(const tl_renderer_options *o)
{
    return tl__msaa_samples(o) > 1u && o->mode != TL_MODE_FORWARD && tl__msaa_method(o) == TL_MSAA_LIGHTING_SAMPLE_EDGES;
}

uint32_t tl__gbuffer_samples(const tl_renderer_options *o) { return tl__msaa_sample_edges(o) ? o->msaa : 1u; }

uint32_t tl__light_shift(const tl_renderer_options *o)
{
    if (o->mode != TL_MODE_THIN_LPP) return 0u;
    int e = 0;
    frexpf(o->light_scale, &e); /* a resolved scale is a power of two (its registry row): 2^(1 - e) */
    return o->light_scale > 0.0f && o->light_scale < 1.0f ? (uint32_t)(1 - e) : 0u;
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
