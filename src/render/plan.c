/* The frame planner (DESIGN.md section 4): from the renderer's options and the scene's features,
 * which targets to allocate, which passes to run with what inputs and outputs, which vertex
 * attributes to bind and which shader permutations to compile. Pure: no GL calls, no allocation. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "plan_internal.h"

static const char *const tl__mode_names[TL_MODE_COUNT_] = {"thin-lpp", "thin-lpp", "thin-deferred", "fat",
                                                            "forward"};
static const char *const tl__pass_names[TL_PASS_COUNT] = {"depth-prepass", "gbuffer", "lights", "material",
                                                          "forward", "transparent", "tonemap", "fxaa"};
static const char *const tl__target_names[TL_TARGET_COUNT] = {
    "depth", "rt0", "rt1", "light.diffuse", "light.specular", "fat.position", "fat.normal", "fat.albedo",
    "fat.material", "hdr", "ldr", "output"};

const char *tl_render_mode_name(tl_render_mode mode)
{
    return (unsigned)mode < TL_MODE_COUNT_ ? tl__mode_names[mode] : "unknown";
}

tl_result tl_render_mode_from_name(const char *name, tl_render_mode *mode)
{
    if (!name || !mode) return TL_ERROR_INVALID_ARGUMENT;
    for (int m = TL_MODE_THIN_LPP; m < TL_MODE_COUNT_; m++)
        if (strcmp(name, tl__mode_names[m]) == 0) {
            *mode = (tl_render_mode)m;
            return TL_OK;
        }
    return TL_ERROR_INVALID_ARGUMENT;
}

const char *tl_pass_name(tl_pass pass) { return (unsigned)pass < TL_PASS_COUNT ? tl__pass_names[pass] : "unknown"; }
const char *tl_target_name(tl_target_id t) { return (unsigned)t < TL_TARGET_COUNT ? tl__target_names[t] : "unknown"; }

tl_result tl__renderer_desc_resolve(const tl_renderer_desc *in, tl_renderer_desc *d)
{
    *d = *in;
    if (d->mode == TL_MODE_DEFAULT) d->mode = TL_MODE_THIN_LPP;
    if (!d->width) d->width = 1280;
    if (!d->height) d->height = 720;
    if (d->depth_format == TL_DEPTH_FORMAT_DEFAULT) d->depth_format = TL_DEPTH_FORMAT_D24;
    if (d->rt0 == TL_RT0_DEFAULT) d->rt0 = TL_RT0_RGBA8;
    if (d->light_buffer == TL_LIGHT_BUFFER_DEFAULT) d->light_buffer = TL_LIGHT_BUFFER_EXACT;
    if (d->fxaa == TL_FXAA_DEFAULT) d->fxaa = TL_FXAA_29;
    if (d->fxaa_edge_threshold <= 0.0f) d->fxaa_edge_threshold = 0.166f;
    if (d->fxaa_edge_threshold_min <= 0.0f) d->fxaa_edge_threshold_min = 0.0833f;
    if (d->fxaa_subpix == 0.0f) d->fxaa_subpix = 0.75f;
    if (d->fxaa_subpix < 0.0f) d->fxaa_subpix = 0.0f;
    if (!(d->exposure > 0.0f)) d->exposure = 1.0f;
    if ((unsigned)d->mode >= TL_MODE_COUNT_ || (unsigned)d->depth_format >= TL_DEPTH_FORMAT_COUNT_ ||
        (unsigned)d->rt0 >= TL_RT0_COUNT_ || (unsigned)d->light_buffer >= TL_LIGHT_BUFFER_COUNT_ ||
        (unsigned)d->fxaa >= TL_FXAA_COUNT_)
        return TL_ERROR_INVALID_ARGUMENT;
    if (d->width > TL__MAX_SIZE || d->height > TL__MAX_SIZE) return TL_ERROR_LIMIT;
    return TL_OK;
}

unsigned tl__target_format(const tl_renderer_desc *d, tl_target_id id)
{
    int rev = d->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
    switch (id) {
    case TL_TARGET_DEPTH:
        /* fat is the full-float reference: D32F. No pass uses stencil, so float depth carries
         * none (D32F_S8 would cost 8 B/px); D24 comes packed with its stencil byte. */
        if (d->mode == TL_MODE_FAT || rev || d->depth_format == TL_DEPTH_FORMAT_D32F) return GL_DEPTH_COMPONENT32F;
        return GL_DEPTH24_STENCIL8;
    case TL_TARGET_RT0: return d->rt0 == TL_RT0_RGB10A2 ? GL_RGB10_A2 : GL_RGBA8;
    case TL_TARGET_RT1: return GL_RGBA8;
    case TL_TARGET_LIGHT_DIFFUSE:
    case TL_TARGET_LIGHT_SPECULAR: return GL_RGBA16F;
    case TL_TARGET_FAT_POSITION: return GL_RGBA32F;
    case TL_TARGET_FAT_NORMAL:
    case TL_TARGET_FAT_ALBEDO:
    case TL_TARGET_FAT_MATERIAL:
    case TL_TARGET_HDR: return GL_RGBA16F;
    case TL_TARGET_LDR:
    case TL_TARGET_OUTPUT: return GL_RGBA8;
    case TL_TARGET_COUNT: break;
    }
    return 0;
}

/* ---- programs ------------------------------------------------------------------------------- */

static void tl__add_program(tl_frame_plan *p, tl_pass pass, const char *name, const char *fmt, ...)
{
    if (p->program_count >= TL_PLAN_MAX_PROGRAMS) return;
    tl_plan_program *pr = &p->programs[p->program_count++];
    pr->pass = pass;
    snprintf(pr->name, sizeof pr->name, "%s", name);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(pr->defines, sizeof pr->defines, fmt, ap);
    va_end(ap);
}

/* Material permutation switches for the geometry passes: only what some drawn material uses. */
static void tl__material_defines(const tl_scene_feature_set *f, char *out, size_t size)
{
    snprintf(out, size, "%s%s%s%s%s%s", f->has_textures ? " TL_HAS_UV" : "",
             f->has_normal_maps ? " TL_NORMAL_MAP" : "", f->has_metallic_roughness ? " TL_MR_TEXTURE" : "",
             f->has_emissive_texture ? " TL_EMISSIVE_TEXTURE" : "",
             f->has_occlusion ? " TL_OCCLUSION" : "", f->has_alpha_mask ? " TL_ALPHA_MASK" : "");
}

static void tl__add_pass(tl_frame_plan *p, tl_pass pass, uint32_t reads, uint32_t writes)
{
    p->passes[p->pass_count++] = (tl_plan_pass){pass, reads, writes};
}

#define TL__BIT(t) (1u << (t))

tl_result tl_frame_plan_build(const tl_renderer_desc *desc, const tl_scene_feature_set *features, tl_frame_plan *plan)
{
    if (!desc || !features || !plan) return TL_ERROR_INVALID_ARGUMENT;
    tl_renderer_desc d;
    tl_result res = tl__renderer_desc_resolve(desc, &d);
    if (res != TL_OK) return res;
    tl_scene_feature_set all = *features;
    if (d.no_planning) { /* plan for every feature, as a renderer without a planner would */
        all.point_lights += !all.point_lights;
        all.spot_lights += !all.spot_lights;
        all.directional_lights += !all.directional_lights;
        all.has_specular = all.has_textures = all.has_normal_maps = all.has_emissive = all.has_alpha_mask = 1;
        all.has_metallic_roughness = all.has_occlusion = all.has_emissive_texture = 1;
    }
    const tl_scene_feature_set *f = &all;
    memset(plan, 0, sizeof *plan);
    plan->mode = d.mode;
    plan->width = d.width;
    plan->height = d.height;

    size_t nlights = f->point_lights + f->spot_lights + f->directional_lights;
    int lights = nlights > 0, spec = f->has_specular != 0, fxaa = d.fxaa != TL_FXAA_OFF;
    int blend = f->has_alpha_blend != 0;
    if (f->point_lights) plan->light_types |= 1u << TL_LIGHT_POINT;
    if (f->spot_lights) plan->light_types |= 1u << TL_LIGHT_SPOT;
    if (f->directional_lights) plan->light_types |= 1u << TL_LIGHT_DIRECTIONAL;

    uint32_t t = TL__BIT(TL_TARGET_DEPTH) | TL__BIT(TL_TARGET_HDR) | TL__BIT(TL_TARGET_OUTPUT);
    if (fxaa) t |= TL__BIT(TL_TARGET_LDR);
    uint32_t gbuf_writes = TL__BIT(TL_TARGET_DEPTH), light_reads = TL__BIT(TL_TARGET_DEPTH), light_writes = 0;
    char mat[128];
    tl__material_defines(f, mat, sizeof mat);
    const char *rt0 = d.rt0 == TL_RT0_RGB10A2 ? "TL_RT0_RGB10A2" : "TL_RT0_RGBA8";
    const char *speclayout = !spec ? "TL_SPECULAR_NONE"
                             : d.light_buffer == TL_LIGHT_BUFFER_EXACT ? "TL_SPECULAR_EXACT"
                                                                       : "TL_SPECULAR_COMPACT";
    char gdefs[160] = "", ldefs[160] = "";

    switch (d.mode) {
    case TL_MODE_DEFAULT:
    case TL_MODE_THIN_LPP:
        /* RT0 and the light buffer exist only for the light pass; the material pass samples
         * materials itself, so RT1 has no reader here */
        if (lights) {
            t |= TL__BIT(TL_TARGET_RT0) | TL__BIT(TL_TARGET_LIGHT_DIFFUSE);
            if (spec && d.light_buffer == TL_LIGHT_BUFFER_EXACT) t |= TL__BIT(TL_TARGET_LIGHT_SPECULAR);
            gbuf_writes |= TL__BIT(TL_TARGET_RT0);
            light_reads |= TL__BIT(TL_TARGET_RT0);
            light_writes = t & (TL__BIT(TL_TARGET_LIGHT_DIFFUSE) | TL__BIT(TL_TARGET_LIGHT_SPECULAR));
            snprintf(gdefs, sizeof gdefs, "TL_OUT_RT0=0 %s", rt0);
            snprintf(ldefs, sizeof ldefs, "TL_LIGHT_ACCUM %s %s", rt0, speclayout);
        }
        break;
    case TL_MODE_THIN_DEFERRED:
        /* emissive and ambient go straight to HDR in the G-buffer pass; lights add to it */
        if (lights) {
            t |= TL__BIT(TL_TARGET_RT0) | TL__BIT(TL_TARGET_RT1);
            gbuf_writes |= TL__BIT(TL_TARGET_RT0) | TL__BIT(TL_TARGET_RT1);
            light_reads |= TL__BIT(TL_TARGET_RT0) | TL__BIT(TL_TARGET_RT1);
            light_writes = TL__BIT(TL_TARGET_HDR);
            snprintf(gdefs, sizeof gdefs, "TL_OUT_RT0=0 TL_OUT_RT1=1 TL_OUT_HDR=2 %s", rt0);
            snprintf(ldefs, sizeof ldefs, "TL_LIGHT_SHADE_THIN %s %s", rt0, speclayout);
        } else {
            snprintf(gdefs, sizeof gdefs, "TL_OUT_HDR=0");
        }
        gbuf_writes |= TL__BIT(TL_TARGET_HDR);
        break;
    case TL_MODE_FAT:
        if (lights) {
            t |= TL__BIT(TL_TARGET_FAT_POSITION) | TL__BIT(TL_TARGET_FAT_NORMAL) | TL__BIT(TL_TARGET_FAT_ALBEDO);
            if (spec) t |= TL__BIT(TL_TARGET_FAT_MATERIAL);
            uint32_t fat = t & (TL__BIT(TL_TARGET_FAT_POSITION) | TL__BIT(TL_TARGET_FAT_NORMAL) |
                                TL__BIT(TL_TARGET_FAT_ALBEDO) | TL__BIT(TL_TARGET_FAT_MATERIAL));
            gbuf_writes |= fat;
            light_reads |= fat;
            light_writes = TL__BIT(TL_TARGET_HDR);
            snprintf(gdefs, sizeof gdefs, "TL_OUT_FAT=0 %s", spec ? "TL_OUT_FAT_MATERIAL TL_OUT_HDR=4" : "TL_OUT_HDR=3");
            snprintf(ldefs, sizeof ldefs, "TL_LIGHT_SHADE_FAT %s", speclayout);
        } else {
            snprintf(gdefs, sizeof gdefs, "TL_OUT_HDR=0");
        }
        gbuf_writes |= TL__BIT(TL_TARGET_HDR);
        break;
    case TL_MODE_FORWARD:
    case TL_MODE_COUNT_:
        break;
    }

    plan->vertex_attributes = TL_ATTRIBUTE_POSITION | TL_ATTRIBUTE_NORMAL;
    if (f->has_textures) plan->vertex_attributes |= TL_ATTRIBUTE_UV;
    if (f->has_normal_maps) plan->vertex_attributes |= TL_ATTRIBUTE_TANGENT;

    static const char *const type_defs[3] = {"TL_LIGHT_TYPE=1", "TL_LIGHT_TYPE=2", "TL_LIGHT_TYPE=3"};
    static const char *const type_names[3] = {"lights.point", "lights.spot", "lights.directional"};
    const char *fullscreen = d.fullscreen_lights ? " TL_LIGHT_FULLSCREEN" : "";
    if (d.mode == TL_MODE_FORWARD) {
        int prepass = !d.forward_no_depth_prepass;
        if (prepass) {
            tl__add_pass(plan, TL_PASS_DEPTH_PREPASS, 0, TL__BIT(TL_TARGET_DEPTH));
            tl__add_program(plan, TL_PASS_DEPTH_PREPASS, "depth-prepass", "TL_DEPTH_ONLY%s",
                            f->has_alpha_mask ? mat : "");
        }
        tl__add_pass(plan, TL_PASS_FORWARD, prepass ? TL__BIT(TL_TARGET_DEPTH) : 0,
                     TL__BIT(TL_TARGET_HDR) | (prepass ? 0 : TL__BIT(TL_TARGET_DEPTH)));
        tl__add_program(plan, TL_PASS_FORWARD, "forward", "TL_FORWARD %s%s", speclayout, mat);
    } else {
        tl__add_pass(plan, TL_PASS_GBUFFER, 0, gbuf_writes);
        tl__add_program(plan, TL_PASS_GBUFFER, "gbuffer", "%s%s", gdefs[0] ? gdefs : "TL_DEPTH_ONLY", mat);
        if (lights) {
            tl__add_pass(plan, TL_PASS_LIGHTS, light_reads, light_writes);
            for (int k = 0; k < 3; k++)
                if (plan->light_types & (1u << (k + 1)))
                    tl__add_program(plan, TL_PASS_LIGHTS, type_names[k], "%s %s%s", type_defs[k], ldefs,
                                    k < 2 ? fullscreen : "");
        }
        if (d.mode == TL_MODE_THIN_LPP) {
            uint32_t reads = TL__BIT(TL_TARGET_DEPTH) | (t & (TL__BIT(TL_TARGET_LIGHT_DIFFUSE) |
                                                                  TL__BIT(TL_TARGET_LIGHT_SPECULAR)));
            tl__add_pass(plan, TL_PASS_MATERIAL, reads, TL__BIT(TL_TARGET_HDR));
            tl__add_program(plan, TL_PASS_MATERIAL, "material", "%s%s", lights ? speclayout : "TL_NO_LIGHTS", mat);
        }
    }
    if (blend) {
        tl__add_pass(plan, TL_PASS_TRANSPARENT, TL__BIT(TL_TARGET_DEPTH) | TL__BIT(TL_TARGET_HDR),
                     TL__BIT(TL_TARGET_HDR));
        tl__add_program(plan, TL_PASS_TRANSPARENT, "transparent", "TL_FORWARD TL_TRANSPARENT %s%s", speclayout, mat);
    }
    tl__add_pass(plan, TL_PASS_TONEMAP, TL__BIT(TL_TARGET_HDR), TL__BIT(fxaa ? TL_TARGET_LDR : TL_TARGET_OUTPUT));
    tl__add_program(plan, TL_PASS_TONEMAP, "tonemap", "%s", "");
    if (fxaa) {
        tl__add_pass(plan, TL_PASS_FXAA, TL__BIT(TL_TARGET_LDR), TL__BIT(TL_TARGET_OUTPUT));
        tl__add_program(plan, TL_PASS_FXAA, "fxaa", "%s%s", d.fxaa == TL_FXAA_12 ? "TL_FXAA_STEPS=5" : "TL_FXAA_STEPS=12",
                        d.fxaa == TL_FXAA_39 ? " TL_FXAA_FINE" : "");
    }

    plan->targets = t;
    for (int i = 0; i < TL_TARGET_COUNT; i++) {
        if (!(t & TL__BIT(i))) continue;
        uint32_t b = (uint32_t)tl__format_bytes_per_pixel(tl__target_format(&d, (tl_target_id)i));
        plan->target_bytes_per_pixel[i] = b;
        plan->bytes_per_pixel += b;
        if (i != TL_TARGET_HDR && i != TL_TARGET_LDR && i != TL_TARGET_OUTPUT) plan->gbuffer_bytes_per_pixel += b;
    }
    return TL_OK;
}

/* ---- printing ------------------------------------------------------------------------------- */

typedef struct tl__out {
    char *buf;
    size_t size, len;
} tl__out;

static void tl__printf(tl__out *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *dst = o->len < o->size ? o->buf + o->len : NULL;
    int n = vsnprintf(dst, dst ? o->size - o->len : 0, fmt, ap);
    va_end(ap);
    if (n > 0) o->len += (size_t)n;
}

static void tl__print_targets(tl__out *o, uint32_t bits)
{
    if (!bits) {
        tl__printf(o, "-");
        return;
    }
    const char *sep = "";
    for (int i = 0; i < TL_TARGET_COUNT; i++)
        if (bits & TL__BIT(i)) {
            tl__printf(o, "%s%s", sep, tl__target_names[i]);
            sep = ", ";
        }
}

size_t tl_frame_plan_format(const tl_frame_plan *p, char *buffer, size_t size)
{
    tl__out o = {buffer, buffer ? size : 0, 0};
    if (buffer && size) buffer[0] = '\0';
    if (!p) return 0;
    tl__printf(&o, "frame plan: mode %s, %ux%u\n", tl_render_mode_name(p->mode), p->width, p->height);
    tl__printf(&o, "passes:\n");
    for (size_t i = 0; i < p->pass_count; i++) {
        tl__printf(&o, "  %zu %-13s reads ", i + 1, tl_pass_name(p->passes[i].pass));
        tl__print_targets(&o, p->passes[i].reads);
        tl__printf(&o, "; writes ");
        tl__print_targets(&o, p->passes[i].writes);
        tl__printf(&o, "\n");
    }
    tl__printf(&o, "targets (bytes per pixel):\n");
    for (int i = 0; i < TL_TARGET_COUNT; i++)
        if (p->target_bytes_per_pixel[i])
            tl__printf(&o, "  %-15s %2u\n", tl__target_names[i], p->target_bytes_per_pixel[i]);
    tl__printf(&o, "  %-15s %2u (G-buffer and light buffer: %u)\n", "total", p->bytes_per_pixel,
               p->gbuffer_bytes_per_pixel);
    tl__printf(&o, "vertex attributes: position, normal%s%s\n",
               p->vertex_attributes & TL_ATTRIBUTE_UV ? ", uv" : "",
               p->vertex_attributes & TL_ATTRIBUTE_TANGENT ? ", tangent" : "");
    tl__printf(&o, "light volumes: %s%s%s%s\n", p->light_types & (1u << TL_LIGHT_POINT) ? " point" : "",
               p->light_types & (1u << TL_LIGHT_SPOT) ? " spot" : "",
               p->light_types & (1u << TL_LIGHT_DIRECTIONAL) ? " directional" : "", p->light_types ? "" : " none");
    tl__printf(&o, "programs:\n");
    for (size_t i = 0; i < p->program_count; i++)
        tl__printf(&o, "  %-19s %s\n", p->programs[i].name, p->programs[i].defines[0] ? p->programs[i].defines : "-");
    return o.len;
}
