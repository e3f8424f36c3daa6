/* FXAA on a caller's image (tl_renderer_apply_fxaa) through the frame's own passes: the luma pass,
 * then the compiled FXAA pass, with the caller's image in the frame's output target. */
#include <string.h>

#include "renderer_internal.h"

static const tl__compiled_pass *tl__fxaa_pass(const tl__graph *g, size_t *index)
{
    for (size_t i = 0; i < g->pass_count; i++)
        if (g->passes[i].def && g->passes[i].def->id == TL_PASS_FXAA) {
            *index = i;
            return &g->passes[i];
        }
    return NULL;
}

/* The luma pass's program, and the caller's image in the output target. */
static tl_result tl__fxaa_input(tl_renderer *r, const uint8_t *rgba)
{
    tl__device *dev = &r->dev;
    tl__graph *g = &r->graph;
    tl_result res = TL_OK;
    if (!g->programs_ready && (res = tl__graph_programs(dev, g)) != TL_OK) return res;
    if (!g->luma.programs[0] &&
        (res = tl__program_get(dev, "luma", &tl__pass_luma.programs[0], NULL,
                               &(tl__program_units){g->luma_decl.samples, g->luma_decl.images, g->luma_decl.writes},
                               &g->luma.programs[0])) != TL_OK)
        return res;
    tl__pixel_store saved;
    tl__pixel_store_enter(&dev->gl, 1, &saved);
    dev->gl.TextureSubImage2D(g->targets[tl__target_frame_output()].texture, 0, 0, 0, (GLsizei)r->desc.width,
                              (GLsizei)r->desc.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    tl__pixel_store_leave(&dev->gl, &saved);
    return TL_OK;
}

tl_result tl_renderer_apply_fxaa(tl_renderer *r, const uint8_t *rgba, uint8_t *out, size_t *size)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    tl__device *dev = &r->dev;
    tl_result res;
    if (!tl__size_check(r, out, size, (size_t)r->desc.width * r->desc.height * 4, "the FXAA image", &res)) return res;
    if (!rgba) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: apply_fxaa needs an input image");
    if ((res = tl__need_context(dev, "tl_renderer_apply_fxaa")) != TL_OK) return res;
    size_t fxaa_index = 0;
    const tl__compiled_pass *fxaa = tl__fxaa_pass(&r->graph, &fxaa_index);
    if (!fxaa || !r->graph.luma.fbo)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: FXAA is off in this renderer");
    if ((res = tl__fxaa_input(r, rgba)) != TL_OK) return res;
    const GladGLContext *gl = &dev->gl;
    size_t offset = 0;
    size_t need = sizeof(tl__frame_ubo) + dev->lim.ubo_align + tl__params_bytes(r, fxaa, 1);
    if (tl__stream_begin(gl, &dev->stream, need, "buffer.frame") != TL_OK)
        return tl__fail(dev, TL_ERROR_GL, "renderer: could not map the per-frame buffer");
    tl__frame_ubo *u = (tl__frame_ubo *)tl__stream_reserve(&dev->stream, sizeof *u, dev->lim.ubo_align, &offset);
    tl__frame_ubo_post(&r->desc, u);
    tl__stream_bind_range(gl, &dev->stream, GL_UNIFORM_BUFFER, TL__UBO_FRAME, offset, sizeof *u);
    tl__frame_record rec;
    memset(&rec, 0, sizeof rec);
    tl__state_enter(gl, &dev->state, TL__TEXTURE_UNITS_USED);
    tl__run_pass(r, &r->graph.luma, &rec, 0);
    tl__run_pass(r, fxaa, &rec, fxaa_index);
    tl__state_reset(gl, &dev->state, TL__TEXTURE_UNITS_USED, TL__BUFFER_BINDINGS_USED, TL__IMAGE_UNITS_USED);
    tl__stream_end(gl, &dev->stream);
    res = tl__read_output(r, out, *size);
    GLenum e = gl->GetError();
    if (res == TL_OK && e != GL_NO_ERROR)
        return tl__fail(dev, TL_ERROR_GL, "renderer: %s in FXAA", tl__gl_error_string(e));
    return res;
}

