/* The plan's render targets and one framebuffer per pass, made from the passes' declared outputs
 * (colour attachments in tl_target_id order, which the shaders' output locations follow). */
#include <stdio.h>
#include <string.h>

#include "renderer_internal.h"

void tl__targets_destroy(tl_renderer *r)
{
    const GladGLContext *gl = &r->gl;
    for (int p = 0; p < TL_PASS_COUNT; p++) tl__framebuffer_destroy(gl, &r->fbo[p]);
    tl__framebuffer_destroy(gl, &r->fbo_tonemap_ldr);
    for (int t = 0; t < TL_TARGET_COUNT; t++) tl__target_destroy(gl, &r->targets[t]);
}

static tl_result tl__fbo(tl_renderer *r, const char *label, uint32_t writes, GLuint *out)
{
    const tl__target *c[TL__FRAMEBUFFER_MAX_COLORS];
    size_t n = 0;
    for (int t = 0; t < TL_TARGET_COUNT && n < TL__FRAMEBUFFER_MAX_COLORS; t++)
        if (t != TL_TARGET_DEPTH && (writes & (1u << t))) c[n++] = &r->targets[t];
    char msg[256];
    tl_result res = tl__framebuffer_create(&r->gl, label, c, n, (writes & 1u) ? &r->targets[TL_TARGET_DEPTH] : NULL,
                                           out, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(r, res, "framebuffer %s: %s", label, msg);
    return TL_OK;
}

tl_result tl__plan_targets(tl_renderer *r)
{
    tl__targets_destroy(r);
    for (int t = 0; t < TL_TARGET_COUNT; t++) {
        if (!(r->plan.targets & (1u << t))) continue;
        char label[64], msg[256];
        snprintf(label, sizeof label, "target.%s", tl_target_name((tl_target_id)t));
        tl__target_desc td = {label, tl__target_format(&r->desc, (tl_target_id)t), r->desc.width, r->desc.height};
        tl_result res = tl__target_create(&r->gl, &td, &r->targets[t], msg, sizeof msg);
        if (res != TL_OK) return tl__fail(r, res, "%s: %s", label, msg);
    }
    for (size_t i = 0; i < r->plan.pass_count; i++) {
        const tl_plan_pass *pp = &r->plan.passes[i];
        char label[64];
        snprintf(label, sizeof label, "fbo.%s", tl_pass_name(pp->pass));
        uint32_t writes = pp->writes;
        /* passes that test against depth attach it even when they only read it */
        if (pp->pass != TL_PASS_TONEMAP && pp->pass != TL_PASS_FXAA) writes |= 1u << TL_TARGET_DEPTH;
        tl_result res = tl__fbo(r, label, writes, &r->fbo[pp->pass]);
        if (res != TL_OK) return res;
    }
    if (r->plan.targets & (1u << TL_TARGET_LDR))
        return tl__fbo(r, "fbo.ldr", 1u << TL_TARGET_LDR, &r->fbo_tonemap_ldr);
    return TL_OK;
}

tl_result tl__replan(tl_renderer *r)
{
    tl_frame_plan plan;
    tl_result res = tl_frame_plan_build(&r->desc, &r->features, &plan);
    if (res != TL_OK) return tl__fail(r, res, "renderer: planning the frame failed");
    int same_targets = r->plan.pass_count && plan.targets == r->plan.targets && plan.pass_count == r->plan.pass_count &&
                       memcmp(plan.passes, r->plan.passes, sizeof plan.passes) == 0;
    r->plan = plan;
    if (!same_targets && (res = tl__plan_targets(r)) != TL_OK) return res;
    /* programs are compiled once a scene says which are needed (apply_fxaa compiles its own) */
    if (r->has_scene && (res = tl__plan_programs(r)) != TL_OK) return res;
    return tl__scene_vao(r);
}
