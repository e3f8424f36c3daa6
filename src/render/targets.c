/* The target table (targets.h). */
#include "targets.h"
#include "bindings.h"

#include "gl/gl.h"

/* A target samples on texture unit = its id: the material textures' units come after them. */
_Static_assert((int)TL_TARGET_COUNT <= (int)TL__UNIT_ALBEDO_TEXTURE, "target texture units overlap the material textures'");

const tl__target_def tl__targets[TL_TARGET_COUNT] = {
    [TL_TARGET_DEPTH] = {"depth", "DEPTH", 0, TL__STORE_GBUFFER},
    [TL_TARGET_RT0] = {"rt0", "RT0", 0, TL__STORE_GBUFFER},
    [TL_TARGET_RT1] = {"rt1", "RT1", GL_RGBA8, TL__STORE_GBUFFER},
    [TL_TARGET_LIGHT_DIFFUSE] = {"light.diffuse", "LIGHT_DIFFUSE", GL_RGBA16F, TL__STORE_LIGHT},
    [TL_TARGET_LIGHT_SPECULAR] = {"light.specular", "LIGHT_SPECULAR", GL_RGBA16F, TL__STORE_LIGHT},
    [TL_TARGET_FAT_POSITION] = {"fat.position", "FAT_POSITION", GL_RGBA32F, TL__STORE_GBUFFER},
    [TL_TARGET_FAT_NORMAL] = {"fat.normal", "FAT_NORMAL", GL_RGBA16F, TL__STORE_GBUFFER},
    [TL_TARGET_FAT_ALBEDO] = {"fat.albedo", "FAT_ALBEDO", GL_RGBA16F, TL__STORE_GBUFFER},
    [TL_TARGET_FAT_MATERIAL] = {"fat.material", "FAT_MATERIAL", GL_RGBA16F, TL__STORE_GBUFFER},
    [TL_TARGET_HDR] = {"hdr", "HDR", GL_RGBA16F, 0},
    [TL_TARGET_LDR] = {"ldr", "LDR", GL_RGBA8, 0},
    [TL_TARGET_OUTPUT] = {"output", "OUTPUT", GL_RGBA8, 0},
    [TL_TARGET_LIGHT_LISTS] = {"light.lists", "LIGHT_LISTS", 0, TL__STORE_LISTS, 1},
    [TL_TARGET_AO_RAW] = {"ao.raw", "AO_RAW", GL_R16F, 0},
    [TL_TARGET_AO] = {"ao", "AO", GL_R16F, 0},
    [TL_TARGET_DOF] = {"dof", "DOF", GL_RGBA16F, 0},
    [TL_TARGET_LIGHT_FRESNEL] = {"light.fresnel", "LIGHT_FRESNEL", GL_RGBA16F, TL__STORE_LIGHT},
    [TL_TARGET_BLOOM] = {"bloom", "BLOOM", GL_RGBA16F, 0, 0, 1, 1},
    [TL_TARGET_SSR] = {"ssr", "SSR", GL_RGBA16F, 0},
};

size_t tl__light_lists_bytes(size_t tiles) { return 16u + 8u * tiles + 4u * TL__TILE_START_ENTRIES * tiles; }

const char *tl_target_name(tl_target_id t) { return (unsigned)t < TL_TARGET_COUNT ? tl__targets[t].name : "unknown"; }

uint32_t tl__target_format(const tl_renderer_desc *d, tl_target_id id)
{
    if ((unsigned)id >= TL_TARGET_COUNT) return 0;
    if (id == TL_TARGET_DEPTH) {
        /* fat is the full-float reference: D32F. No pass uses stencil, so float depth carries
         * none (D32F_S8 would cost 8 B/px); D24 comes packed with its stencil byte. */
        int f32 = d->options.mode == TL_MODE_FAT || d->options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ||
                  d->options.depth_format == TL_DEPTH_FORMAT_D32F;
        return f32 ? GL_DEPTH_COMPONENT32F : GL_DEPTH24_STENCIL8;
    }
    if (id == TL_TARGET_RT0) return d->options.rt0 == TL_RT0_RGB10A2 ? GL_RGB10_A2 : GL_RGBA8;
    if ((id == TL_TARGET_LIGHT_DIFFUSE || id == TL_TARGET_LIGHT_SPECULAR || id == TL_TARGET_LIGHT_FRESNEL) &&
        d->options.light_format == TL_LIGHT_FORMAT_R11G11B10F)
        return GL_R11F_G11F_B10F;
    return tl__targets[id].format;
}

void tl__target_size(const tl_renderer_desc *d, tl_target_id id, uint32_t *width, uint32_t *height, uint32_t *levels)
{
    unsigned shift = (unsigned)id < TL_TARGET_COUNT ? tl__targets[id].shift : 0u;
    uint32_t w = (uint32_t)(((uint64_t)d->width + (1u << shift) - 1u) >> shift);
    uint32_t h = (uint32_t)(((uint64_t)d->height + (1u << shift) - 1u) >> shift);
    *width = w ? w : 1u;
    *height = h ? h : 1u;
    uint32_t want = id == TL_TARGET_BLOOM ? d->options.bloom.levels : 1u, n = 1;
    /* GL halves each level rounding down, to 1x1 at the least: a level exists while the larger side is >= 2^level */
    while (n < want && n < TL__MAX_LEVELS && ((*width > *height ? *width : *height) >> n) >= 1u) n++;
    *levels = n;
}
