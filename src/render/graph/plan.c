/* The frame planner (docs/frame.md): every pass of the table declares what it would
 * read and write for this configuration and scene; passes whose outputs nobody reads are culled,
 * writes nobody reads are dropped, every target gets a lifetime (first write to last read) and
 * targets with disjoint lifetimes and view-compatible formats share one allocation. Then each pass
 * names its programs' #defines. Pure: no GL calls, no allocation. */
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "plan_internal.h"
#include "targets.h"

#define TL__BIT(t) TL_TARGET_BIT(t)

static void tl__material_perm(const tl_scene_feature_set *f, tl__perm *k)
{
    const struct { int on; unsigned flag; } m[] = {
        {f->has_textures, TL__F_HAS_UV}, {f->has_normal_maps, TL__F_NORMAL_MAP},
        {f->has_metallic_roughness, TL__F_MR_TEXTURE}, {f->has_emissive_texture, TL__F_EMISSIVE_TEXTURE},
        {f->has_occlusion, TL__F_OCCLUSION}, {f->has_alpha_mask, TL__F_ALPHA_MASK},
        {f->has_vertex_colors, TL__F_VCOLOR}, {f->has_uv1 && f->has_textures, TL__F_UV1},
        {tl__plan_has_models(f), TL__F_MATERIAL_MODELS}}; /* material_models.c */
    for (size_t i = 0; i < sizeof m / sizeof m[0]; i++)
        if (m[i].on) tl__perm_flag(k, m[i].flag);
}

/* Volumes or tiles: forced by the options, else by the number of local lights (docs/frame.md
 * gives the crossover measured on the crypt and the glTF scenes). */
static void tl__plan_strategy(tl__plan_input *in)
{
    size_t local = in->f.point_lights + in->f.spot_lights;
    tl_light_strategy s = in->o->light_strategy;
    if (in->mode->visibility) {
        s = TL_LIGHT_STRATEGY_TILED;
        snprintf(in->strategy_reason, sizeof in->strategy_reason, "visibility: the resolve lights from the tile lists");
    } else if (s != TL_LIGHT_STRATEGY_DEFAULT) {
        snprintf(in->strategy_reason, sizeof in->strategy_reason, "forced by the options");
    } else if (local >= TL__TILED_CROSSOVER) {
        s = TL_LIGHT_STRATEGY_TILED;
        snprintf(in->strategy_reason, sizeof in->strategy_reason, "auto: %zu local lights >= %u", local,
                 TL__TILED_CROSSOVER);
    } else {
        s = TL_LIGHT_STRATEGY_VOLUMES;
        snprintf(in->strategy_reason, sizeof in->strategy_reason, "auto: %zu local lights < %u", local,
                 TL__TILED_CROSSOVER);
    }
    in->strategy = s;
    /* tiles are counted in the frame's pixels: at a light scale below 1 a tile covers tile_size
     * texels of the light buffer, and the edge fix-up reads the list of its pixel's tile */
    in->tile_size = in->o->tile_size << (in->light_shift ? 1u : 0u);
    in->tiles_x = (in->d.width + in->tile_size - 1) / in->tile_size;
    in->tiles_y = (in->d.height + in->tile_size - 1) / in->tile_size;
    /* the tiled light pass: as asked, or TL__TILED_SHADING_AUTO's pick (docs/frame.md, "Fragment or compute") */
    tl_tiled_shading ts = in->o->tiled_shading == TL_TILED_SHADING_AUTO ? TL__TILED_SHADING_AUTO : in->o->tiled_shading;
    in->tiled_compute = ts == TL_TILED_SHADING_COMPUTE || in->mode->visibility; /* vis-resolve: a compute pass */
}

/* The lighting model (forced, or GGX for materials authored for it) and the shaders' switches. */
static void tl__plan_lighting(tl__plan_input *in)
{
    const tl_renderer_desc *d = &in->d;
    in->lighting = d->options.lighting;
    if (d->options.lighting != TL_LIGHTING_DEFAULT) {
        snprintf(in->lighting_reason, sizeof in->lighting_reason, "forced by the options");
    } else if (in->f.has_microfacet) {
        in->lighting = TL_LIGHTING_GGX;
        snprintf(in->lighting_reason, sizeof in->lighting_reason, "auto: materials authored for GGX (glTF)");
    } else {
        in->lighting = TL_LIGHTING_BLINN_PHONG;
        snprintf(in->lighting_reason, sizeof in->lighting_reason, "auto: no material authored for GGX");
    }
    int ggx = in->lighting == TL_LIGHTING_GGX, exact = d->options.light_buffer == TL_LIGHT_BUFFER_EXACT;
    if (ggx && in->spec && in->mode->material_pass) in->fresnel = exact ? d->options.fresnel : TL_FRESNEL_NV;
    tl__perm_flag(&in->spec_perm, !in->spec ? TL__F_SPECULAR_NONE : exact ? TL__F_SPECULAR_EXACT : TL__F_SPECULAR_COMPACT);
    if (ggx) tl__perm_flag(&in->spec_perm, TL__F_GGX);
    if (in->fresnel == TL_FRESNEL_TWO_SUMS) tl__perm_flag(&in->spec_perm, TL__F_FRESNEL_SUMS);
    if (in->fresnel == TL_FRESNEL_NV) tl__perm_flag(&in->spec_perm, TL__F_FRESNEL_NV);
}

/* Stipple or forward for the alpha-blended materials (docs/frame.md, "2d. Transparency through the
 * light buffer"). The stipple has TL_STIPPLE_LAYERS layers and the frame gives each visible blended
 * object its own, far to near (draw.c), so it fits in every view when the scene draws at most that
 * many blended objects; the plan then never depends on the camera. */
static void tl__plan_transparency(tl__plan_input *in)
{
    const tl_renderer_options *o = in->o;
    size_t n = in->f.alpha_blend_objects;
    const char *why = NULL, *how = o->transparency == TL_TRANSPARENCY_STIPPLE ? "stipple asked" : "auto";
    if (!in->f.has_alpha_blend) return;
    if (o->transparency == TL_TRANSPARENCY_FORWARD) why = "forced by the options";
    else if (!in->mode->material_pass) why = "only thin-lpp lights its G-buffer's layers";
    else if (in->light_shift) why = "the reduced light buffer would collapse the 2x2 stipple";
    else if (in->msaa > 1) why = "MSAA: the material pass's samples would split the 2x2 stipple";
    else if (!in->lights) why = "no lights: nothing to gather";
    else if (tl__passes_refuse(o, TL__REFUSES_STIPPLE))
        why = tl__passes_refuse(o, TL__REFUSES_STIPPLE);
    if (why) {
        const char *lead = o->transparency == TL_TRANSPARENCY_FORWARD   ? ""
                           : o->transparency == TL_TRANSPARENCY_STIPPLE ? "stipple asked, but "
                                                                        : "auto: ";
        snprintf(in->transparency_reason, sizeof in->transparency_reason, "%s%s", lead, why);
    } else if (n == 0) { /* a feature set made by hand: the count is unknown */
        why = "blended objects not counted";
        snprintf(in->transparency_reason, sizeof in->transparency_reason, "%s: %s", how, why);
    } else if (n > TL_STIPPLE_LAYERS) {
        why = "more blended objects than stipple layers";
        snprintf(in->transparency_reason, sizeof in->transparency_reason, "%s: %zu blended objects > %d stipple layers",
                 how, n, TL_STIPPLE_LAYERS);
    } else {
        in->stipple = 1;
        snprintf(in->transparency_reason, sizeof in->transparency_reason,
                 "%s: %zu blended object%s, one 2x2 stipple layer each", how, n, n == 1 ? "" : "s");
    }
    in->transparency_why = why;
}

/* The clearcoat's lighting and why, where a clearcoat is drawn in thin-lpp with lights. */
static void tl__plan_clearcoat(const tl__plan_input *in, tl_frame_plan *p)
{
    if (!in->mode->material_pass || !in->lights || !(tl__plan_models(&in->f) & (1u << TL_MATERIAL_MODEL_CLEARCOAT)))
        return;
    tl_clearcoat_lighting asked = in->o->clearcoat;
    p->clearcoat = in->coat_sums ? TL_CLEARCOAT_SUMS : TL_CLEARCOAT_APPROXIMATE;
    const char *lead = asked == TL_CLEARCOAT_DEFAULT ? "auto" : "asked";
    if (asked == TL_CLEARCOAT_APPROXIMATE) snprintf(p->clearcoat_reason, sizeof p->clearcoat_reason, "asked");
    else if (in->coat_sums) snprintf(p->clearcoat_reason, sizeof p->clearcoat_reason, "%s: the coat's own sums", lead);
    else snprintf(p->clearcoat_reason, sizeof p->clearcoat_reason, "%s, but %s", lead, in->coat_why);
}

static void tl__plan_input_init(const tl_renderer_desc *d, const tl_scene_feature_set *features, tl__plan_input *in)
{
    memset(in, 0, sizeof *in);
    in->d = *d;
    in->o = &in->d.options;
    in->f = *features;
    tl_scene_feature_set *f = &in->f;
    if (d->options.planning == TL_SWITCH_OFF) { /* plan for every feature, as a renderer without a planner would */
        f->point_lights += !f->point_lights;
        f->spot_lights += !f->spot_lights;
        f->directional_lights += !f->directional_lights;
        f->has_specular = f->has_textures = f->has_normal_maps = f->has_emissive = f->has_alpha_mask = 1;
        f->has_metallic_roughness = f->has_occlusion = f->has_emissive_texture = 1;
    }
    in->mode = &tl__modes[d->options.mode];
    in->lights = f->point_lights + f->spot_lights + f->directional_lights > 0;
    in->light_shift = tl__light_shift(in->o);
    in->msaa = tl__msaa_samples(in->o);
    tl__plan_strategy(in);
    in->spec = f->has_specular != 0;
    tl__plan_lighting(in);
    tl__shadows_plan(in);
    tl__plan_transparency(in);
    in->rt0_flag = d->options.rt0 == TL_RT0_RGB10A2 ? TL__F_RT0_RGB10A2 : TL__F_RT0_RGBA8;
    tl__material_perm(f, &in->material);
    in->coat_sums = tl__plan_coat_sums(in, &in->coat_why);
    if (in->coat_sums) tl__perm_flag(&in->material, TL__F_COAT_SUMS); /* coat_sums.glsl */
    if (f->has_environment) tl__perm_flag(&in->material, TL__F_IBL); /* image-based light (ibl.glsl) */
}

/* ---- selection and culling ------------------------------------------------------------------ */

static void tl__add_pass(tl__plan *p, const tl__pass_def *def, int app, const tl__pass_decl *decl, const char *name)
{
    size_t i = p->pub.pass_count++;
    p->def[i] = def;
    p->app[i] = (int8_t)app;
    p->decl[i] = *decl;
    tl_plan_pass *pp = &p->pub.passes[i];
    pp->pass = def ? def->id : TL_PASS_COUNT;
    snprintf(pp->name, sizeof pp->name, "%s", name);
}

/* An application pass: its reads sampled, the first depth target it reads attached (read-only). */
static void tl__app_decl(const tl__plan *p, const tl__app_pass *a, tl__pass_decl *d)
{
    memset(d, 0, sizeof *d);
    d->writes = a->desc.writes;
    d->reads = d->samples = a->desc.reads;
    for (int t = 0; t < TL_TARGET_COUNT && !d->attach_depth; t++)
        if (p->targets[t] && p->targets[t]->depth && (a->desc.reads & TL__BIT(t))) {
            d->attach_depth = 1;
            d->depth_target = (uint8_t)t;
        }
    d->state.color_write = 1;
}

static void tl__add_apps(tl__plan *p, const tl__app_pass *apps, size_t n, int anchor, int after)
{
    for (size_t k = 0; k < n; k++) {
        if (apps[k].anchor != anchor || apps[k].after != after) continue;
        tl__pass_decl d;
        tl__app_decl(p, &apps[k], &d);
        tl__add_pass(p, NULL, (int)k, &d, apps[k].name);
    }
}

/* Every pass of the table that declares a write, application passes at their anchors. */
static void tl__select(const tl__plan_input *in, const tl__app_pass *apps, size_t n, tl__plan *p)
{
    for (int t = 0; t < TL_PASS_COUNT; t++) {
        tl__add_apps(p, apps, n, t, 0);
        const tl__pass_def *def = tl__pass_table[t];
        tl__pass_decl d;
        memset(&d, 0, sizeof d);
        def->declare(in, &d);
        if (d.writes) tl__add_pass(p, def, -1, &d, def->name);
        tl__add_apps(p, apps, n, t, 1);
    }
}

static void tl__remove_pass(tl__plan *p, size_t i)
{
    size_t n = p->pub.pass_count, tail = n - i - 1;
    memmove(&p->pub.passes[i], &p->pub.passes[i + 1], tail * sizeof p->pub.passes[0]);
    memmove(&p->decl[i], &p->decl[i + 1], tail * sizeof p->decl[0]);
    memmove(&p->def[i], &p->def[i + 1], tail * sizeof p->def[0]);
    memmove(&p->app[i], &p->app[i + 1], tail * sizeof p->app[0]);
    p->pub.pass_count--;
}

/* Backwards: a pass none of whose writes a later pass (or the caller) reads is culled; writes it
 * declared optional are dropped when unread. Then forwards: reads of targets nobody wrote are
 * dropped (a light buffer the light pass does not write, say). */
static void tl__cull_passes(tl__plan *p, tl_target_set sinks)
{
    tl_target_set needed = sinks;
    for (size_t i = p->pub.pass_count; i-- > 0;) {
        tl__pass_decl *d = &p->decl[i];
        if (!(d->writes & needed) && p->app[i] < 0) {
            tl__remove_pass(p, i);
            continue;
        }
        d->writes &= ~(d->optional & ~needed);
        d->clears &= d->writes;
        needed |= d->reads;
    }
    tl_target_set written = 0;
    for (size_t i = 0; i < p->pub.pass_count; i++) {
        tl__pass_decl *d = &p->decl[i];
        d->reads &= written | d->writes;
        d->samples &= written;
        d->attach_depth = d->attach_depth && ((written | d->writes) & TL__BIT(d->depth_target));
        written |= d->writes;
        tl_plan_pass *pp = &p->pub.passes[i];
        pp->reads = d->reads;
        pp->writes = d->writes;
        pp->clears = d->clears;
    }
}

/* ---- targets, lifetimes, shared memory ------------------------------------------------------ */

/* Format, size, levels and bytes of a target; a storage buffer's or a reduced target's bytes per
 * pixel are its bytes over the frame's pixels, rounded up. */
static void tl__target_memory(const tl_renderer_desc *d, const tl__target_def *def, const tl_frame_plan *fp,
                              tl_plan_target *ti)
{
    size_t px = (size_t)d->width * d->height, bpp;
    ti->format = tl__target_format(def, &d->options);
    bpp = tl__format_bytes_per_pixel(ti->format);
    tl__target_size(def, &d->options, d->width, d->height, &ti->width, &ti->height, &ti->levels);
    ti->samples = tl__target_samples(def, &d->options);
    ti->bytes = 0;
    for (uint32_t k = 0; k < ti->levels; k++) {
        size_t w = ti->width >> k, h = ti->height >> k;
        ti->bytes += (w ? w : 1u) * (h ? h : 1u) * bpp * ti->samples;
    }
    if (def->buffer_bytes) ti->bytes = def->buffer_bytes(fp, &d->options);
    ti->bytes_per_pixel = (uint32_t)((ti->bytes + px - 1) / px);
}

static void tl__lifetimes(tl__plan *p, const tl_renderer_desc *d, tl_target_set sinks)
{
    tl_frame_plan *fp = &p->pub;
    for (size_t i = 0; i < fp->pass_count; i++) fp->targets |= fp->passes[i].reads | fp->passes[i].writes;
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        tl_plan_target *ti = &fp->target_info[t];
        if (!(fp->targets & TL__BIT(t))) continue;
        tl__target_memory(d, p->targets[t], fp, ti);
        fp->target_bytes_per_pixel[t] = ti->bytes_per_pixel;
        fp->bytes_per_pixel += ti->bytes_per_pixel;
        if (p->targets[t]->store != TL__STORE_NONE) fp->gbuffer_bytes_per_pixel += ti->bytes_per_pixel;
        ti->first_pass = (uint32_t)fp->pass_count;
        for (size_t i = 0; i < fp->pass_count; i++) {
            if (!((fp->passes[i].reads | fp->passes[i].writes) & TL__BIT(t))) continue;
            if (ti->first_pass == fp->pass_count) ti->first_pass = (uint32_t)i;
            ti->last_pass = (uint32_t)i;
        }
        if (sinks & TL__BIT(t)) ti->last_pass = (uint32_t)fp->pass_count;
    }
    for (size_t i = 0; i < fp->pass_count; i++) {
        uint32_t live = 0;
        for (int t = 0; t < TL_TARGET_COUNT; t++) {
            const tl_plan_target *ti = &fp->target_info[t];
            if (ti->bytes_per_pixel && ti->first_pass <= i && i <= ti->last_pass) live += ti->bytes_per_pixel;
        }
        if (live > fp->peak_live_bytes_per_pixel) fp->peak_live_bytes_per_pixel = live;
    }
}

/* Greedy interval sharing, targets in order of first use: a target joins a block of its view
 * class whose last member ended before it starts. Depth shares with nothing. Kept targets live to
 * the end of the frame, so no target joins their block after them (they may reuse the memory of
 * targets that died before they start: those are the ones a readback refuses). */
static void tl__share_memory(tl__plan *p, const tl_renderer_options *o)
{
    tl_frame_plan *fp = &p->pub;
    uint32_t block_end[TL_TARGET_COUNT], block_class[TL_TARGET_COUNT];
    for (uint32_t step = 0; step <= fp->pass_count; step++)
        for (int t = 0; t < TL_TARGET_COUNT; t++) {
            tl_plan_target *ti = &fp->target_info[t];
            if (!ti->bytes_per_pixel || ti->first_pass != step) continue;
            /* a block is one texture of the frame's size and one level: a reduced target keeps its own */
            unsigned cls = tl__target_shift(p->targets[t], o) || ti->levels > 1 ? 0u : tl__format_view_class(ti->format);
            cls = cls ? cls * 16u + ti->samples : 0u; /* a view has its storage's samples */
            size_t b = fp->block_count;
            for (size_t k = 0; cls && k < fp->block_count; k++)
                if (block_class[k] == cls && block_end[k] < ti->first_pass) {
                    b = k;
                    break;
                }
            if (b == fp->block_count) {
                fp->block_count++;
                fp->blocks[b].bytes_per_pixel = ti->bytes_per_pixel;
                fp->allocated_bytes_per_pixel += ti->bytes_per_pixel;
                fp->allocated_bytes += ti->bytes;
            } else {
                p->shared |= fp->blocks[b].targets; /* earlier members are overwritten by this one */
            }
            fp->blocks[b].targets |= TL__BIT(t);
            block_class[b] = cls;
            block_end[b] = ti->last_pass;
            ti->block = (uint32_t)b;
        }
}

/* ---- programs ------------------------------------------------------------------------------- */

/* TL_OUT_<TARGET>=<location> for every colour write: attachments in tl_target_id order (what
 * programs.c gives the program too); 0 when they do not fit `size`. */
static int tl__output_defines(const tl__plan *p, tl_target_set writes, char *out, size_t size)
{
    size_t len = 0;
    int loc = 0;
    out[0] = '\0';
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if ((writes & TL__BIT(t)) && !p->targets[t]->depth && !p->targets[t]->buffer_bytes) {
            int n = snprintf(out + len, size - len, "%sTL_OUT_%s=%d", len ? " " : "", p->targets[t]->macro, loc++);
            if (n < 0 || (size_t)n >= size - len) return 0;
            len += (size_t)n;
        }
    return 1;
}

#define TL__OUTS_TEXT_MAX (TL__FRAMEBUFFER_MAX_COLORS * 48)
_Static_assert(TL__OUTS_TEXT_MAX + 1 + TL__PERM_TEXT_MAX <= TL_PLAN_DEFINES_SIZE,
               "tl_plan_program.defines holds every switch a key can make");

/* Each planned program with its permutation key (p->perms) and its text (tl_plan_program.defines);
 * a key with a value past its switch is refused naming it (tl__perm_check). */
static tl_result tl__programs(const tl__plan_input *in, tl__plan *p)
{
    tl_frame_plan *fp = &p->pub;
    for (size_t i = 0; i < fp->pass_count; i++) {
        const tl__pass_def *def = p->def[i];
        if (!def) continue;
        tl__pass_defines defs;
        memset(&defs, 0, sizeof defs);
        def->permute(in, &p->decl[i], &defs);
        char outs[TL__OUTS_TEXT_MAX];
        if (!tl__output_defines(p, p->decl[i].writes, outs, sizeof outs)) return TL_ERROR_LIMIT;
        for (uint32_t s = 0; s < TL__PASS_MAX_PROGRAMS && fp->program_count < TL_PLAN_MAX_PROGRAMS; s++) {
            if (!defs.used[s]) continue;
            if (!tl__perm_check(&defs.slot[s], p->refused, sizeof p->refused)) return TL_ERROR_LIMIT;
            p->perms[fp->program_count] = defs.slot[s];
            tl_plan_program *pr = &fp->programs[fp->program_count++];
            pr->pass = def->id;
            pr->slot = s;
            snprintf(pr->name, sizeof pr->name, "%s", def->programs[s].name);
            size_t n = strlen(outs);
            memcpy(pr->defines, outs, n + 1);
            if (n && tl__perm_format(&defs.slot[s], NULL, 0)) pr->defines[n++] = ' ';
            tl__perm_format(&defs.slot[s], pr->defines + n, sizeof pr->defines - n);
        }
    }
    return TL_OK;
}

/* The plan's choices with their reasons, and the downgrades among them. */
static void tl__plan_choices(const tl__plan_input *in, tl_frame_plan *p)
{
    const tl_renderer_options *o = in->o;
    p->light_strategy = in->strategy;
    p->lighting = in->lighting;
    p->fresnel = in->fresnel;
    snprintf(p->lighting_reason, sizeof p->lighting_reason, "%s", in->lighting_reason);
    snprintf(p->strategy_reason, sizeof p->strategy_reason, "%s", in->strategy_reason);
    p->light_scale = 1.0f / (float)(1u << in->light_shift);
    if (o->light_scale != 1.0f)
        snprintf(p->light_scale_reason, sizeof p->light_scale_reason, "%s",
                 in->light_shift ? "asked; lights on the reduced depth, upsampled, edges re-lit"
                                 : "asked, but only thin-lpp has a light buffer to reduce");
    p->msaa = in->msaa;
    p->shadow_lights = in->shadows;
    if (o->msaa > 1) {
        const char *why = tl__msaa_refusal(o);
        snprintf(p->msaa_reason, sizeof p->msaa_reason, "%s%s", why ? "asked, but " : "", why ? why : tl__msaa_how(o));
    }
    p->transparency = in->stipple ? TL_TRANSPARENCY_STIPPLE : TL_TRANSPARENCY_FORWARD;
    snprintf(p->transparency_reason, sizeof p->transparency_reason, "%s", in->transparency_reason);
    tl__plan_clearcoat(in, p);
    tl__plan_downgrades(in, p);
    /* tiles with the tiled strategy, and for the light scale's re-lit pixels (pass_light_upsample.c) */
    if (in->strategy == TL_LIGHT_STRATEGY_TILED || (in->lights && in->light_shift && in->mode->material_pass)) {
        p->tile_size = in->tile_size;
        p->tiles_x = in->tiles_x;
        p->tiles_y = in->tiles_y;
        if (!in->mode->forward)
            p->tiled_shading = in->tiled_compute ? TL_TILED_SHADING_COMPUTE : TL_TILED_SHADING_FRAGMENT;
    }
}

tl_result tl__plan_build(const tl_renderer_desc *desc, const tl_scene_feature_set *features, const tl__app_pass *apps,
                         size_t app_count, tl__plan *p)
{
    if (!desc || !features || !p) return TL_ERROR_INVALID_ARGUMENT;
    tl_renderer_desc d;
    tl_result res = tl__renderer_desc_resolve(desc, &d, NULL);
    if (res != TL_OK) return res;
    tl__plan_input in;
    tl__plan_input_init(&d, features, &in);
    in.asked = desc->options;
    memset(p, 0, sizeof *p);
    tl__target_defs(p->targets);
    p->pub.mode = d.options.mode;
    p->pub.width = d.width;
    p->pub.height = d.height;
    /* the output is read after the frame; kept targets too, when the plan has them at all */
    const tl_target_id output = tl__target_frame_output();
    tl_target_set kept = TL__BIT(output) | (d.options.keep_targets & TL__TARGETS_EVERY);
    tl__plan_choices(&in, &p->pub);
    tl__select(&in, apps, app_count, p);
    tl_target_set debug = 0; /* debug outputs: read after the frame, like the output */
    for (size_t i = 0; i < p->pub.pass_count; i++) debug |= p->decl[i].sinks;
    kept |= debug;
    tl__cull_passes(p, TL__BIT(output) | debug);
    tl__lifetimes(p, &d, kept);
    tl__share_memory(p, &d.options);
    tl_result r = tl__programs(&in, p);
    if (r != TL_OK) return r;
    p->pub.vertex_attributes = TL_ATTRIBUTE_POSITION | TL_ATTRIBUTE_NORMAL;
    if (in.f.has_textures) p->pub.vertex_attributes |= TL_ATTRIBUTE_UV;
    if (in.f.has_normal_maps) p->pub.vertex_attributes |= TL_ATTRIBUTE_TANGENT;
    if (in.f.has_vertex_colors) p->pub.vertex_attributes |= TL_ATTRIBUTE_COLOR;
    if (in.f.has_uv1 && in.f.has_textures) p->pub.vertex_attributes |= TL_ATTRIBUTE_UV1;
    if (in.f.point_lights) p->pub.light_types |= 1u << TL_LIGHT_POINT;
    if (in.f.spot_lights) p->pub.light_types |= 1u << TL_LIGHT_SPOT;
    if (in.f.directional_lights) p->pub.light_types |= 1u << TL_LIGHT_DIRECTIONAL;
    return TL_OK;
}

tl_result tl_frame_plan_build(const tl_renderer_desc *desc, const tl_scene_feature_set *features, tl_frame_plan *plan)
{
    if (!plan) return TL_ERROR_INVALID_ARGUMENT;
    tl__plan p;
    tl_result res = tl__plan_build(desc, features, NULL, 0, &p);
    if (res == TL_OK) *plan = p.pub;
    return res;
}
