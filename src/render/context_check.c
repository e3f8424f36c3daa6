/* Whether the renderer's GL context is current before a call uses GL, and whether the framebuffer
 * render_to is given exists and is complete (renderer.h, docs/getting-started.md). */
#include "thinlight/context.h"

#include "device.h"

void tl__context_check_init(tl__device *r, tl_is_current_fn is_current)
{
    r->is_current = is_current;
    /* thinlight's own contexts can always tell, and say when they are destroyed */
    if (!r->is_current && r->get_proc_address == tl_context_proc_loader && r->get_proc_address_user) {
        r->own_context = 1;
        tl__context_link_add((tl_context *)r->get_proc_address_user, &r->context_link);
    }
    r->thread = thrd_current();
    r->thread_known = 1;
}

void tl__context_check_release(tl__device *r) { tl__context_link_remove(&r->context_link); }

int tl__context_gone(const tl__device *r) { return r->own_context && !r->context_link.context; }

/* Without a callback: the thread that last had the context may use it. On any other thread one GL
 * query (a vertex array of the renderer's exists only in its context; with no context current it
 * answers false) before the thread is trusted, so a steady frame makes none. */
static int tl__thread_has_context(tl__device *r)
{
    thrd_t self = thrd_current();
    if (r->thread_known && thrd_equal(self, r->thread)) return 1;
    if (!r->vao_empty || !r->gl.IsVertexArray || !r->gl.IsVertexArray(r->vao_empty)) return 0;
    r->thread = self;
    r->thread_known = 1;
    return 1;
}

int tl__context_current(tl__device *r)
{
    if (r->own_context) return r->context_link.context && tl_context_is_current(r->context_link.context);
    if (r->is_current) return r->is_current(r->get_proc_address_user) != 0;
    return tl__thread_has_context(r);
}

tl_result tl__need_context(tl__device *r, const char *call)
{
    if (tl__context_current(r)) return TL_OK;
    if (tl__context_gone(r))
        return tl__fail(r, TL_ERROR_GL,
                        "renderer: %s: the renderer's context was destroyed (tl_context_destroy) before the renderer; "
                        "only tl_renderer_destroy is left to call",
                        call);
    return tl__fail(r, TL_ERROR_GL,
                    "renderer: %s: the renderer's GL context is not current on this thread (make it current first, "
                    "e.g. tl_context_make_current); nothing was changed",
                    call);
}

/* A name render_to checked: glIsFramebuffer and glCheckNamedFramebufferStatus return values, so
 * on a driver with a command thread each would wait for it; a steady frame into the same few
 * framebuffers asks neither again. */
static int tl__output_known(const tl__device *r, GLuint fb)
{
    for (unsigned i = 0; i < r->output_known_count; i++)
        if (r->outputs_known[i] == fb) return 1;
    return 0;
}

tl_result tl__output_check(tl__device *r, const tl_render_output *out)
{
    GLuint fb = out->framebuffer;
    if (tl__output_known(r, fb)) return TL_OK;
    const GladGLContext *gl = &r->gl;
    if (fb != 0 && !gl->IsFramebuffer(fb))
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: render_to: framebuffer %u is not a framebuffer object of the current context", fb);
    GLenum status = gl->CheckNamedFramebufferStatus(fb, GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: render_to: framebuffer %u%s is not complete (%s)", fb,
                        fb ? "" : " (the default framebuffer)", tl__framebuffer_status_string(status));
    r->outputs_known[r->output_next] = fb;
    r->output_next = (r->output_next + 1) % TL__OUTPUTS_KNOWN;
    if (r->output_known_count < TL__OUTPUTS_KNOWN) r->output_known_count++;
    return TL_OK;
}
