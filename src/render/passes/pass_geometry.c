/* The geometry passes of the table: depth pre-pass, G-buffer, material (the light pre-pass's
 * second geometry pass), forward and transparent. Each declares its targets and state for a mode
 * (the mode table says what the G-buffer holds) and draws the visible objects. The G-buffer pass
 * owns the targets geometry writes: depth, the thin and fat G-buffers and HDR. */
#include <stdio.h>

#include "gl/gl.h"
#include "lights.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

/* fat is the full-float reference: D32F. No pass uses stencil, so float depth carries none
 * (D32F_S8 would cost 8 B/px); D24 comes packed with its stencil byte. */
uint32_t tl__depth_format(const tl_renderer_options *o)
{
    int f32 = o->mode == TL_MODE_FAT || o->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ||
              o->depth_format == TL_DEPTH_FORMAT_D32F;
    return f32 ? GL_DEPTH_COMPONENT32F : GL_DEPTH24_STENCIL8;
}

uint32_t tl__rt0_format(const tl_renderer_options *o)
{
    return o->rt0 == TL_RT0_RGB10A2 ? GL_RGB10_A2 : GL_RGBA8;
}

/* MSAA (docs/antialiasing.md): with per-sample edges (thin-deferred, fat; pass_msaa.c) the whole
 * G-buffer is multisampled (tl__gbuffer_samples); otherwise forward's depth and the HDR image of
 * forward and thin-lpp are multisampled; thin-lpp's G-buffer depth stays at one sample for the
 * light pass, and the material pass tests against a multisampled depth of its own that the depth
 * pre-pass writes. */
static uint32_t tl__depth_samples(const tl_renderer_options *o)
{
    return o->mode == TL_MODE_FORWARD ? tl__msaa_samples(o) : tl__gbuffer_samples(o);
}

static const tl__target_def tl__target_depth = {TL__TARGET(DEPTH, "depth"), .format_of = tl__depth_format,
                                                .samples_of = tl__depth_samples, .store = TL__STORE_GBUFFER, .depth = 1};
static const tl__target_def tl__target_depth_msaa = {TL__TARGET(DEPTH_MSAA, "depth.msaa"), .format_of = tl__depth_format,
                                                     .samples_of = tl__msaa_samples, .store = TL__STORE_GBUFFER,
                                                     .depth = 1};
static const tl__target_def tl__target_rt0 = {TL__TARGET(RT0, "rt0"), .format_of = tl__rt0_format,
                                              .samples_of = tl__gbuffer_samples, .store = TL__STORE_GBUFFER,
                                              .read_rt0 = 1};
static const tl__target_def tl__target_rt1 = {TL__TARGET(RT1, "rt1"), .format = GL_RGBA8,
                                              .samples_of = tl__gbuffer_samples, .store = TL__STORE_GBUFFER};
static const tl__target_def tl__target_fat_position = {TL__TARGET(FAT_POSITION, "fat.position"), .format = GL_RGBA32F,
                                                       .samples_of = tl__gbuffer_samples, .store = TL__STORE_GBUFFER};
static const tl__target_def tl__target_fat_normal = {TL__TARGET(FAT_NORMAL, "fat.normal"), .format = GL_RGBA16F,
                                                     .samples_of = tl__gbuffer_samples, .store = TL__STORE_GBUFFER};
static const tl__target_def tl__target_fat_albedo = {TL__TARGET(FAT_ALBEDO, "fat.albedo"), .format = GL_RGBA16F,
                                                     .samples_of = tl__gbuffer_samples, .store = TL__STORE_GBUFFER};
static const tl__target_def tl__target_fat_material = {TL__TARGET(FAT_MATERIAL, "fat.material"), .format = GL_RGBA16F,
                                                       .samples_of = tl__gbuffer_samples, .store = TL__STORE_GBUFFER};
/* TL_CLEARCOAT_SUMS: the coat's gloss beside RT0's (coat_sums.glsl); declared with the material
 * pass, which is there only in thin-lpp (the G-buffer pass's table of targets is full). */
static const tl__target_def tl__target_coat_gloss = {TL__TARGET(COAT_GLOSS, "coat.gloss"), .format = GL_R8,
                                                     .store = TL__STORE_GBUFFER};
static const tl__target_def tl__target_hdr = {TL__TARGET(HDR, "hdr"), .format = GL_RGBA16F, .samples_of = tl__msaa_samples};

/* Every geometry pass that decides visibility tests LEQUAL (GEQUAL reversed): of fragments at the
 * same stored depth the last drawn wins, as it does in a later pass at EQUAL, which draws the same
 * objects in the same order. With LESS the G-buffer kept the first drawn and the material pass
 * shaded the last: where two surfaces quantise to one depth (coplanar parts, decals, D24), the
 * light of one surface with the material of the other (docs/frame.md, "Coplanar surfaces"). */
static const tl__pipeline tl__opaque = {.depth_test = TL__DEPTH_LEQUAL, .depth_write = 1, .color_write = 1,
                                        .cull = TL__CULL_BACK};

static tl__pipeline tl__geometry_state(const tl__plan_input *in, tl__depth_test test, int write, tl__blend blend)
{
    tl__pipeline p = tl__opaque;
    p.depth_test = (uint8_t)test;
    p.depth_write = (uint8_t)write;
    p.blend = (uint8_t)blend;
    p.clip_zero_one = in->o->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
    return p;
}

/* Forward+ (forward with tiled lights): the tiles' depth bounds come from the depth pre-pass. */

/* ---- depth pre-pass (forward; thin-lpp's multisampled depth with MSAA) ----------------------- */

tl_target_id tl__shading_depth(const tl__plan_input *in)
{
    /* per-sample edges: the G-buffer's own depth is multisampled (pass_msaa.c) */
    return in->mode->material_pass && in->msaa > 1 && !tl__msaa_sample_edges(in->o) ? TL_TARGET_DEPTH_MSAA
                                                                                     : TL_TARGET_DEPTH;
}

static void tl__prepass_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (in->mode->forward ? !tl__forward_prepass(in) : tl__shading_depth(in) == TL_TARGET_DEPTH) return;
    d->depth_target = (uint8_t)tl__shading_depth(in);
    d->writes = d->clears = TL_TARGET_BIT(d->depth_target);
    d->attach_depth = 1;
    d->state = tl__geometry_state(in, TL__DEPTH_LEQUAL, 1, TL__BLEND_OFF);
    d->state.color_write = 0;
}

static void tl__prepass_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    tl__perm_flag(&out->slot[0], TL__F_DEPTH_ONLY);
    if (in->f.has_alpha_mask) tl__perm_merge(&out->slot[0], &in->material);
}

const tl__pass_def tl__pass_depth_prepass = {
    .id = TL_PASS_DEPTH_PREPASS,
    .name = "depth-prepass",
    .programs = {{"depth-prepass", "gbuffer.vert.glsl", "forward.frag.glsl"}},
    .targets = {&tl__target_depth_msaa},
    .declare = tl__prepass_declare,
    .permute = tl__prepass_permute,
    .execute = tl__draw_opaque,
    .services = TL__PASS_SCENE,
};

/* ---- G-buffer -------------------------------------------------------------------------------- */

static void tl__gbuffer_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (in->mode->forward) return;
    d->writes = d->clears = TL__B(DEPTH) | in->mode->gbuffer_writes;
    d->optional = in->mode->gbuffer_writes & ~TL__B(HDR); /* kept when the light pass reads them */
    if (in->coat_sums) { /* the coat's gloss for the light pass (coat_sums.glsl) */
        d->writes |= TL__B(COAT_GLOSS);
        d->clears |= TL__B(COAT_GLOSS);
        d->optional |= TL__B(COAT_GLOSS);
    }
    d->attach_depth = 1;
    d->state = tl__geometry_state(in, TL__DEPTH_LEQUAL, 1, TL__BLEND_OFF);
}

static void tl__gbuffer_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    int colour = (d->writes & ~TL__B(DEPTH)) != 0;
    if (!colour) tl__perm_flag(k, TL__F_DEPTH_ONLY);
    else if (d->writes & TL__B(RT0)) tl__perm_flag(k, in->rt0_flag);
    tl__perm_merge(k, &in->material);
    if (colour && tl__ssao_pass(in) == 2) tl__perm_flag(k, TL__F_AO_STORE);
}

const tl__pass_def tl__pass_gbuffer = {
    .id = TL_PASS_GBUFFER,
    .name = "gbuffer",
    .programs = {{"gbuffer", "gbuffer.vert.glsl", "gbuffer.frag.glsl"}},
    .targets = {&tl__target_depth, &tl__target_rt0, &tl__target_rt1, &tl__target_fat_position, &tl__target_fat_normal,
                &tl__target_fat_albedo, &tl__target_fat_material, &tl__target_hdr},
    .declare = tl__gbuffer_declare,
    .permute = tl__gbuffer_permute,
    .execute = tl__draw_opaque,
    .services = TL__PASS_SCENE,
};

/* ---- material: the light pre-pass's second geometry pass ------------------------------------- */

/* The count of the pixels the light scale's light-upsample re-lit, or of the samples MSAA's material
 * pass re-lit (fixup.c); they are lit where they are found, from their tile's lists or their object's. */
static size_t tl__fixup_bytes(const tl_frame_plan *p, const tl_renderer_options *o)
{
    (void)p;
    (void)o;
    return 16u;
}

static const tl__target_def tl__target_light_fixup = {TL__TARGET(LIGHT_FIXUP, "light.fixup"),
                                                      .buffer_bytes = tl__fixup_bytes, .store = TL__STORE_LISTS};

/* The lists a material pass re-lights a pixel from: its tile's (tiled) or its object's (volumes). */
static void tl__material_relight_lists(const tl__plan_input *in, tl__pass_decl *d)
{
    if (in->strategy == TL_LIGHT_STRATEGY_TILED) {
        d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_TILES;
        d->reads |= TL__B(LIGHT_LISTS);
    } else {
        d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_INDEX_BUFFER | TL__LIGHTS_OBJECT_LISTS;
    }
}

static void tl__material_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->mode->material_pass) return;
    d->writes = d->clears = TL__B(HDR);
    d->samples = TL__B(LIGHT_DIFFUSE) | TL__B(LIGHT_SPECULAR) | TL__B(LIGHT_FRESNEL) | /* those the light pass writes */
                 (tl__ssao_pass(in) ? TL__B(AO) : 0u) | (in->coat_sums ? TL__B(LIGHT_COAT) : 0u);
    /* the light scale: light-upsample (pass_light_upsample.c) made the full-size light buffer, so the
     * material pass is scale 1's */
    if (in->msaa > 1 && in->lights) {
        /* MSAA: a sample whose surface is not the one the G-buffer kept at its pixel (an edge)
         * takes the light of the neighbouring texel with its depth and normal, else it is re-lit
         * here from its tile's lists or its object's (light_msaa.glsl); the re-lit ones are counted */
        d->samples |= TL__B(DEPTH) | TL__B(RT0);
        d->writes |= TL__B(LIGHT_FIXUP);
        tl__material_relight_lists(in, d);
    }
    d->depth_target = (uint8_t)tl__shading_depth(in);
    if (in->stipple) {
        /* transparent layers took some G-buffer pixels (pass_stipple.c): the opaque depth decides
         * visibility; the G-buffer which samples are whose; the object's lights where none is */
        d->samples |= TL__B(DEPTH) | TL__B(RT0);
        d->depth_target = TL_TARGET_OPAQUE_DEPTH;
        d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_INDEX_BUFFER | TL__LIGHTS_OBJECT_LISTS;
    }
    d->reads |= d->samples | TL_TARGET_BIT(d->depth_target);
    d->attach_depth = 1;
    /* the stipple's copy of the opaque depth may lie a step behind (pass_stipple.c): LEQUAL then
     * passes the same fragments as EQUAL would, the last drawn of a coplanar pair winning */
    d->state = tl__geometry_state(in, in->stipple ? TL__DEPTH_LEQUAL : TL__DEPTH_EQUAL, 0, TL__BLEND_OFF);
}

static void tl__material_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    tl__perm k = {0};
    int lit = (d->samples & TL__B(LIGHT_DIFFUSE)) != 0, tiles = (d->reads & TL__B(LIGHT_LISTS)) != 0;
    if (lit) tl__perm_merge(&k, &in->spec_perm);
    else tl__perm_flag(&k, TL__F_NO_LIGHTS);
    tl__perm_merge(&k, &in->material);
    tl__ssao_perm(in, d, &k);
    int sample_edges = tl__msaa_sample_edges(in->o);
    if (lit && ((d->depth_target == TL_TARGET_DEPTH_MSAA) || sample_edges)) { /* MSAA (pass_msaa.c) */
        tl__perm_flag(&k, TL__F_MSAA_LIGHT);
        if (sample_edges) tl__perm_value(&k, TL__V_LIGHT_SAMPLES, in->msaa);
        tl__perm_flag(&k, in->rt0_flag);
        if (tiles) tl__perm_flag(&k, TL__F_RELIGHT_TILES);
        if (tl__depth_format(in->o) == GL_DEPTH_COMPONENT32F) tl__perm_flag(&k, TL__F_DEPTH_FLOAT);
    } else if (in->stipple && lit) {
        tl__perm_flag(&k, TL__F_STIPPLE);
        tl__perm_flag(&k, in->rt0_flag);
    }
    tl__material_model_slots(in, &k, out); /* one program per material model */
}

/* MSAA's re-lit samples are counted (fixup.c); with a light scale light-upsample counts its pixels
 * there, and the material pass re-lights nothing (MSAA is refused with it). */
static void tl__material_execute(const tl__pass_ctx *ctx)
{
    tl__fixup *f = ctx->lights && !ctx->light_shift ? &ctx->lights->fixup : NULL;
    if (f) tl__fixup_begin(ctx->gl, f);
    tl__material_models_draw(ctx);
    if (f) tl__fixup_end(ctx->gl, f, ctx->frame);
}

const tl__pass_def tl__pass_material = {
    .id = TL_PASS_MATERIAL,
    .name = "material",
    .programs = {{"material", "gbuffer.vert.glsl", "material.frag.glsl"},
                 {"material.unlit", "gbuffer.vert.glsl", "material.frag.glsl"},
                 {"material.clearcoat", "gbuffer.vert.glsl", "material.frag.glsl"},
                 {"material.sheen", "gbuffer.vert.glsl", "material.frag.glsl"},
                 {"material.wrap", "gbuffer.vert.glsl", "material.frag.glsl"},
                 {"material.toon", "gbuffer.vert.glsl", "material.frag.glsl"}},
    .targets = {&tl__target_coat_gloss, &tl__target_light_fixup},
    .declare = tl__material_declare,
    .permute = tl__material_permute,
    .execute = tl__material_execute,
    .services = TL__PASS_SCENE | TL__PASS_LIGHTS,
};

/* ---- forward, and transparent objects in every mode ------------------------------------------ */

static void tl__forward_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->mode->forward) return;
    int prepass = tl__forward_prepass(in), plus = tl__forward_plus(in);
    d->writes = d->clears = TL__B(HDR) | (prepass ? 0u : TL__B(DEPTH));
    d->reads = (prepass ? TL__B(DEPTH) : 0u) | (plus ? TL__B(LIGHT_LISTS) : 0u);
    d->samples = tl__ssao_pass(in) ? TL__B(AO) : 0u;
    d->reads |= d->samples;
    d->attach_depth = 1;
    d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_INDEX_BUFFER | (plus ? 0u : TL__LIGHTS_OBJECT_LISTS);
    d->state = tl__geometry_state(in, prepass ? TL__DEPTH_EQUAL : TL__DEPTH_LEQUAL, !prepass, TL__BLEND_OFF);
}

static void tl__forward_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    tl__perm_flag(k, TL__F_FORWARD);
    if (d->reads & TL__B(LIGHT_LISTS)) tl__perm_flag(k, TL__F_FORWARD_TILED);
    tl__perm_merge(k, &in->spec_perm);
    tl__perm_merge(k, &in->material);
    tl__ssao_perm(in, d, k);
}

const tl__pass_def tl__pass_forward = {
    .id = TL_PASS_FORWARD,
    .name = "forward",
    .programs = {{"forward", "gbuffer.vert.glsl", "forward.frag.glsl"}},
    .declare = tl__forward_declare,
    .permute = tl__forward_permute,
    .execute = tl__draw_opaque,
    .services = TL__PASS_SCENE,
};

static void tl__transparent_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->f.has_alpha_blend || in->stipple) return; /* the stipple's passes draw them (pass_stipple.c) */
    d->writes = TL__B(HDR);
    d->depth_target = (uint8_t)tl__shading_depth(in);
    d->reads = TL_TARGET_BIT(d->depth_target) | TL__B(HDR); /* blended onto */
    d->attach_depth = 1;
    /* per-object lists: tiles hold lights for the opaque surfaces' depths only */
    d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_INDEX_BUFFER | TL__LIGHTS_OBJECT_LISTS;
    d->state = tl__geometry_state(in, TL__DEPTH_LEQUAL, 0, TL__BLEND_ALPHA);
}

static void tl__transparent_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    tl__perm_flag(k, TL__F_FORWARD);
    tl__perm_flag(k, TL__F_TRANSPARENT);
    tl__perm_merge(k, &in->spec_perm);
    tl__perm_merge(k, &in->material);
}

const tl__pass_def tl__pass_transparent = {
    .id = TL_PASS_TRANSPARENT,
    .name = "transparent",
    .programs = {{"transparent", "gbuffer.vert.glsl", "forward.frag.glsl"}},
    .declare = tl__transparent_declare,
    .permute = tl__transparent_permute,
    .execute = tl__draw_transparent,
    .services = TL__PASS_SCENE,
};
