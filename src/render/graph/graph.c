/* The compile step of the frame graph: runs when the plan changes, never per frame. It gives each
 * memory block of the plan a texture (several targets with disjoint lifetimes see it through
 * texture views of their own formats), keeping the textures of the previous plan whose format,
 * size, levels and filtering a block of the new one asks for; makes one framebuffer per pass from
 * its declared writes (colour attachments in tl_target_id order, the order of the shaders' TL_OUT_*
 * locations), and records each pass's clears and the texture and image units of the targets it
 * samples and writes as images (0, 1, ... in tl_target_id order, as its programs are told:
 * programs.c, bindings.h). */
#include <stdio.h>
#include <string.h>

#include "graph.h"

/* Textures of a plan that the next plan may take again. */
typedef struct tl__storage_pool {
    tl__target storage[TL_TARGET_COUNT];
    uint8_t linear[TL_TARGET_COUNT];
    size_t count;
} tl__storage_pool;

/* Framebuffers, views and one-level views go; the blocks' storage goes into `pool` (NULL: freed). */
static void tl__graph_release_objects(tl__device *dev, tl__graph *r, tl__storage_pool *pool)
{
    const GladGLContext *gl = &dev->gl;
    for (size_t i = 0; i < r->pass_count; i++) {
        tl__framebuffer_destroy(gl, &r->passes[i].fbo);
        for (uint8_t k = 1; k < r->passes[i].level_count; k++) tl__framebuffer_destroy(gl, &r->passes[i].level_fbos[k]);
        for (uint8_t k = 0; k < r->passes[i].write_count; k++) tl__framebuffer_destroy(gl, &r->passes[i].write_fbos[k]);
    }
    tl__framebuffer_destroy(gl, &r->luma.fbo);
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        if (r->views & TL_TARGET_BIT(t)) tl__target_destroy(gl, &r->targets[t]);
        memset(&r->targets[t], 0, sizeof r->targets[t]);
        for (uint32_t k = 0; k < TL__MAX_LEVELS; k++) tl__target_destroy(gl, &r->levels[t][k]);
        if (!r->blocks[t].texture) continue;
        if (pool) {
            pool->linear[pool->count] = r->block_linear[t];
            pool->storage[pool->count++] = r->blocks[t];
            memset(&r->blocks[t], 0, sizeof r->blocks[t]);
        } else {
            tl__target_destroy(gl, &r->blocks[t]);
        }
    }
    r->views = 0;
    memset(r->passes, 0, sizeof r->passes);
    memset(&r->luma, 0, sizeof r->luma);
    r->pass_count = 0;
    r->programs_ready = 0;
}

void tl__graph_release(tl__device *dev, tl__graph *r) { tl__graph_release_objects(dev, r, NULL); }

/* Block b's storage: a texture of the previous plan with the same format, size, levels and
 * filtering, or a new one. */
static tl_result tl__graph_storage(tl__device *dev, tl__graph *r, tl__storage_pool *pool, size_t b,
                                   const tl__target_desc *td, uint32_t levels, int linear)
{
    for (size_t i = 0; i < pool->count; i++) {
        const tl__target *t = &pool->storage[i];
        if (t->internal_format != td->internal_format || t->width != td->width || t->height != td->height ||
            t->levels != levels || t->samples != (td->samples > 1 ? td->samples : 1u) || pool->linear[i] != linear)
            continue;
        r->blocks[b] = *t;
        pool->storage[i] = pool->storage[--pool->count];
        pool->linear[i] = pool->linear[pool->count];
        tl__gl_label(&dev->gl, GL_TEXTURE, r->blocks[b].texture, td->label);
        r->block_linear[b] = (uint8_t)linear;
        return TL_OK;
    }
    char msg[256];
    tl_result res = tl__target_create_levels(&dev->gl, td, levels, linear, &r->blocks[b], msg, sizeof msg);
    if (res != TL_OK) return tl__fail(dev, res, "renderer: %s", msg);
    r->block_linear[b] = (uint8_t)linear;
    return TL_OK;
}

static tl_result tl__graph_block(tl__device *dev, tl__graph *r, tl__storage_pool *pool, size_t b)
{
    const tl_frame_plan *p = &r->plan.pub;
    const tl_plan_block *blk = &p->blocks[b];
    char label[64], msg[256];
    int first = -1, members = 0;
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if (blk->targets & TL_TARGET_BIT(t)) {
            if (first < 0) first = t;
            members++;
        }
    if (r->plan.targets[first]->buffer_bytes) return TL_OK; /* storage buffers: lights.h, tl__tiles_configure */
    const tl_plan_target *ti = &p->target_info[first];
    tl__target_desc td = {label, ti->format, ti->width, ti->height, ti->samples};
    tl_result res;
    if (members == 1) { /* memory of its own: the target is the texture, with a view per level */
        snprintf(label, sizeof label, "target.%s", tl_target_name((tl_target_id)first));
        res = tl__graph_storage(dev, r, pool, b, &td, ti->levels, r->plan.targets[first]->linear);
        if (res == TL_OK) r->targets[first] = r->blocks[b];
        for (uint32_t k = 0; res == TL_OK && ti->levels > 1 && k < ti->levels; k++) {
            snprintf(label, sizeof label, "target.%s.level%u", tl_target_name((tl_target_id)first), k);
            res = tl__target_create_level(&dev->gl, &r->blocks[b], k, label, &r->levels[first][k], msg, sizeof msg);
            if (res != TL_OK) return tl__fail(dev, res, "renderer: %s", msg);
        }
        return res;
    }
    snprintf(label, sizeof label, "memory.%ubit.%zu", tl__format_view_class(td.internal_format), b);
    res = tl__graph_storage(dev, r, pool, b, &td, 1, 0);
    for (int t = 0; res == TL_OK && t < TL_TARGET_COUNT; t++)
        if (blk->targets & TL_TARGET_BIT(t)) {
            snprintf(label, sizeof label, "target.%s", tl_target_name((tl_target_id)t));
            res = tl__target_create_view(&dev->gl, &r->blocks[b], p->target_info[t].format, label, &r->targets[t], msg,
                                         sizeof msg);
            if (res != TL_OK) return tl__fail(dev, res, "renderer: %s", msg);
            r->views |= TL_TARGET_BIT(t);
        }
    return res;
}

/* The units of the targets a pass samples and writes as images: 0, 1, ... in tl_target_id order
 * (its programs get the same numbers: tl__program_units); a pass past the units a frame binds is
 * refused naming it. */
static tl_result tl__graph_units(tl__device *dev, tl__graph *r, tl__compiled_pass *cp, const tl__pass_decl *d)
{
    memset(cp->unit_of, TL__UNIT_NONE, sizeof cp->unit_of);
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        if (d->samples & TL_TARGET_BIT(t)) {
            if (cp->bind_count == TL__TARGET_UNITS)
                return tl__fail(dev, TL_ERROR_LIMIT, "renderer: pass %s samples more than %d targets", cp->plan->name,
                                (int)TL__TARGET_UNITS);
            cp->unit_of[t] = cp->bind_count;
            cp->textures[cp->bind_count++] = r->targets[t].texture;
        }
        if (d->images & TL_TARGET_BIT(t)) {
            if (cp->image_count == TL__IMAGE_UNITS_USED)
                return tl__fail(dev, TL_ERROR_LIMIT, "renderer: pass %s writes more than %d images", cp->plan->name,
                                (int)TL__IMAGE_UNITS_USED);
            cp->image_textures[cp->image_count] = r->targets[t].texture;
            cp->image_formats[cp->image_count++] = r->targets[t].internal_format;
        }
    }
    return TL_OK;
}

/* A pass whose one colour write has mip levels renders each level through a framebuffer of its own
 * and samples the level above through a one-level view. */
static tl_result tl__graph_levels(tl__device *dev, tl__graph *r, tl__compiled_pass *cp, const tl__target *const *colors,
                                  size_t n)
{
    if (n) {
        cp->level_width = colors[0]->width;
        cp->level_height = colors[0]->height;
    }
    if (n != 1 || colors[0]->levels < 2) return TL_OK;
    size_t t = (size_t)(colors[0] - r->targets);
    cp->level_fbos[0] = cp->fbo;
    cp->level_count = (uint8_t)colors[0]->levels;
    for (uint8_t k = 0; k < cp->level_count; k++) cp->level_textures[k] = r->levels[t][k].texture;
    for (uint8_t k = 1; k < cp->level_count; k++) {
        char label[64], msg[256];
        const tl__target *level = &r->levels[t][k];
        snprintf(label, sizeof label, "fbo.%s.level%u", cp->plan->name, (unsigned)k);
        tl_result res = tl__framebuffer_create(&dev->gl, label, &level, 1, NULL, &cp->level_fbos[k], msg, sizeof msg);
        if (res != TL_OK) return tl__fail(dev, res, "renderer: %s", msg);
    }
    return TL_OK;
}

/* A pass that renders its colour writes one at a time gets a framebuffer with each alone. */
static tl_result tl__graph_split(tl__device *dev, tl__compiled_pass *cp, const tl__target *const *colors, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        char label[64], msg[256];
        snprintf(label, sizeof label, "fbo.%s.write%zu", cp->plan->name, k);
        tl_result res = tl__framebuffer_create(&dev->gl, label, &colors[k], 1, NULL, &cp->write_fbos[k], msg, sizeof msg);
        if (res != TL_OK) return tl__fail(dev, res, "renderer: %s", msg);
        cp->write_textures[k] = colors[k]->texture;
        cp->write_count = (uint8_t)(k + 1);
    }
    return TL_OK;
}

/* Framebuffer, clears and texture bindings of one pass. */
static tl_result tl__graph_pass(tl__device *dev, tl__graph *r, tl__compiled_pass *cp, const tl_plan_pass *pp,
                                const tl__pass_decl *d)
{
    const tl__target *colors[TL__FRAMEBUFFER_MAX_COLORS];
    size_t n = 0;
    cp->plan = pp;
    cp->decl = d;
    for (int t = 0; t < TL_TARGET_COUNT && n < TL__FRAMEBUFFER_MAX_COLORS; t++) {
        if (r->plan.targets[t]->depth || !(d->writes & TL_TARGET_BIT(t))) continue;
        if (r->plan.targets[t]->buffer_bytes) continue; /* a storage buffer (the fix-up list), bound by its module */
        if (d->clears & TL_TARGET_BIT(t)) {
            const tl__format_info *f = tl__format_lookup(r->targets[t].internal_format);
            if (f && (f->format == GL_RED_INTEGER || f->format == GL_RG_INTEGER || f->format == GL_RGBA_INTEGER))
                cp->clear_uint |= (uint8_t)(1u << cp->clear_count);
            cp->clear_locations[cp->clear_count++] = (uint8_t)n;
        }
        colors[n++] = &r->targets[t];
    }
    cp->clear_depth = (d->clears & TL_TARGET_BIT(d->depth_target)) != 0;
    cp->writes_output = (d->writes & TL_TARGET_BIT(tl__target_frame_output())) != 0;
    tl_result res = tl__graph_units(dev, r, cp, d);
    if (res != TL_OK || d->compute) return res;
    char label[64], msg[256];
    snprintf(label, sizeof label, "fbo.%s", pp->name);
    const tl__target *depth = d->attach_depth ? &r->targets[d->depth_target] : NULL;
    /* the viewport is the framebuffer's size: reduced targets (the light scale) have their own */
    cp->fb_width = n ? colors[0]->width : depth ? depth->width : 0;
    cp->fb_height = n ? colors[0]->height : depth ? depth->height : 0;
    res = tl__framebuffer_create(&dev->gl, label, colors, n, depth, &cp->fbo, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(dev, res, "renderer: %s", msg);
    if (res == TL_OK && d->split_writes) res = tl__graph_split(dev, cp, colors, n);
    return res == TL_OK ? tl__graph_levels(dev, r, cp, colors, n) : res;
}

tl_result tl__graph_programs(tl__device *dev, tl__graph *r)
{
    const tl_frame_plan *p = &r->plan.pub;
    for (size_t k = 0; k < p->program_count; k++) {
        const tl_plan_program *pr = &p->programs[k];
        for (size_t i = 0; i < r->pass_count; i++) {
            tl__compiled_pass *cp = &r->passes[i];
            if (!cp->def || cp->def->id != pr->pass) continue;
            const tl__program_src *src = &cp->def->programs[pr->slot];
            tl__program_units units = {cp->decl->samples, cp->decl->images, cp->decl->writes};
            tl_result res = tl__program_get(dev, pr->name, src, &r->plan.perms[k], &units, &cp->programs[pr->slot]);
            if (res != TL_OK) return res;
        }
    }
    r->programs_ready = 1;
    return TL_OK;
}

/* apply_fxaa's luma pass (the caller's image, in the frame's output, into what FXAA reads), when
 * the plan has the targets it declares. */
static tl_result tl__graph_luma(tl__device *dev, tl__graph *r)
{
    tl__plan_input in;
    memset(&in, 0, sizeof in);
    memset(&r->luma_decl, 0, sizeof r->luma_decl);
    tl__pass_luma.declare(&in, &r->luma_decl);
    for (int t = 0; t < TL_TARGET_COUNT; t++)
        if (((r->luma_decl.writes | r->luma_decl.samples) & TL_TARGET_BIT(t)) && !r->targets[t].texture) return TL_OK;
    memset(&r->luma_plan, 0, sizeof r->luma_plan);
    r->luma_plan.pass = TL_PASS_COUNT;
    snprintf(r->luma_plan.name, sizeof r->luma_plan.name, "%s", tl__pass_luma.name);
    r->luma_plan.reads = r->luma_decl.reads;
    r->luma_plan.writes = r->luma_decl.writes;
    r->luma.def = &tl__pass_luma;
    r->luma.app = -1;
    return tl__graph_pass(dev, r, &r->luma, &r->luma_plan, &r->luma_decl);
}

/* The sample positions of the plan's multisampled colour targets (GL_SAMPLE_POSITION of a
 * framebuffer holding the first of them). */
static tl_result tl__graph_sample_positions(tl__device *dev, tl__graph *r)
{
    const tl__target *hdr = NULL;
    for (int t = 0; t < TL_TARGET_COUNT && !hdr; t++)
        if (r->targets[t].texture && r->targets[t].samples > 1 && !r->plan.targets[t]->depth) hdr = &r->targets[t];
    memset(r->sample_positions, 0, sizeof r->sample_positions);
    r->samples = r->plan.pub.msaa;
    if (r->plan.pub.msaa <= 1 || !hdr) return TL_OK;
    const GladGLContext *gl = &dev->gl;
    GLuint fbo = 0;
    char msg[256];
    tl_result res = tl__framebuffer_create(gl, "fbo.sample-positions", &hdr, 1, NULL, &fbo, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(dev, res, "renderer: %s", msg);
    GLint bound = 0; /* compile runs outside a frame: the draw framebuffer is put back as it was */
    gl->GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    GLint samples = 0;
    gl->GetIntegerv(GL_SAMPLES, &samples);
    for (uint32_t s = 0; s < r->samples && s < 8u; s++)
        gl->GetMultisamplefv(GL_SAMPLE_POSITION, s, &r->sample_positions[2 * s]);
    gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, (GLuint)bound);
    tl__framebuffer_destroy(gl, &fbo);
    /* the plan asked for a count the context has (tl__device_samples): every shader loops over
     * exactly that many, so targets with another count would leave samples out */
    if ((uint32_t)samples != r->samples)
        return tl__fail(dev, TL_ERROR_UNSUPPORTED,
                        "renderer: the multisampled targets have %d samples where the plan asked for %u (the context "
                        "listed %u as a sample count of its formats)", (int)samples, r->samples, r->samples);
    return TL_OK;
}

tl_result tl__graph_compile(tl__device *dev, tl__graph *r, int programs)
{
    tl__storage_pool pool;
    pool.count = 0;
    tl__graph_release_objects(dev, r, &pool);
    const tl__plan *plan = &r->plan;
    tl_result res = TL_OK;
    for (size_t b = 0; res == TL_OK && b < plan->pub.block_count; b++) res = tl__graph_block(dev, r, &pool, b);
    for (size_t i = 0; i < pool.count; i++) tl__target_destroy(&dev->gl, &pool.storage[i]);
    r->light_data = 0;
    for (size_t i = 0; i < plan->pub.pass_count; i++) r->light_data |= plan->decl[i].light_data;
    for (size_t i = 0; res == TL_OK && i < plan->pub.pass_count; i++) {
        tl__compiled_pass *cp = &r->passes[i];
        cp->def = plan->def[i];
        cp->app = plan->app[i];
        res = tl__graph_pass(dev, r, cp, &plan->pub.passes[i], &plan->decl[i]);
        r->pass_count = i + 1;
    }
    if (res == TL_OK) res = tl__graph_luma(dev, r);
    if (res == TL_OK) res = tl__graph_sample_positions(dev, r);
    if (res == TL_OK && programs) res = tl__graph_programs(dev, r);
    return res;
}
