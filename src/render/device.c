/* The device: GL loaded through the caller's get_proc_address, the limits read once, the objects
 * every pass shares. */
#include <string.h>

#include "device.h"

static GLADapiproc tl__load_thunk(void *user, const char *name)
{
    tl__device *dev = (tl__device *)user;
    return (GLADapiproc)dev->get_proc_address(dev->get_proc_address_user, name);
}

/* What one storage block may hold (GL's limit, or the descriptor's lower one; at most 4 GiB - 1,
 * since the shaders index with uint), and so how many lights of 64 bytes the renderer takes. */
static void tl__storage_limits(tl__device *dev, size_t desc_max)
{
    GLint64 gl_max = 0;
    dev->gl.GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &gl_max);
    size_t m = gl_max > 0 ? (size_t)gl_max : (size_t)1 << 24; /* GL 4.3's minimum */
    if (m > UINT32_MAX) m = UINT32_MAX;
    if (desc_max && desc_max < m) m = desc_max;
    dev->lim.storage_max = m;
    size_t lights = m / TL__LIGHT_BYTES;
    dev->lim.max_lights = lights < TL_RENDERER_MAX_LIGHTS ? lights : TL_RENDERER_MAX_LIGHTS;
}

/* The sample counts every format a target may be multisampled in has (HDR, depth, the G-buffer
 * and light targets of per-sample lighting, the coat's gloss): a bit per count. */
static void tl__sample_counts(tl__device *dev)
{
    static const GLenum formats[] = {GL_RGBA16F, GL_RGBA32F, GL_RGBA8, GL_RGB10_A2, GL_R11F_G11F_B10F, GL_R8,
                                     GL_DEPTH24_STENCIL8, GL_DEPTH_COMPONENT32F};
    const GladGLContext *gl = &dev->gl;
    uint32_t all = ~0u;
    for (size_t f = 0; f < sizeof formats / sizeof formats[0]; f++) {
        GLint n = 0, counts[16] = {0};
        gl->GetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, formats[f], GL_NUM_SAMPLE_COUNTS, 1, &n);
        gl->GetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, formats[f], GL_SAMPLES, 16, counts);
        uint32_t bits = 0;
        for (GLint i = 0; i < n && i < 16; i++)
            if (counts[i] > 1 && counts[i] < 32) bits |= 1u << counts[i];
        all &= bits;
    }
    dev->lim.sample_counts = all;
}

uint32_t tl__device_samples(const tl__device *dev, uint32_t asked)
{
    if (asked <= 1u) return 1u;
    for (uint32_t n = asked; n < 32u; n++)
        if (dev->lim.sample_counts & (1u << n)) return n;
    return 0u;
}

tl_result tl__device_load(tl__device *dev)
{
    char msg[512];
    tl_result res = tl__gl_load(&dev->gl, tl__load_thunk, dev, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(dev, res, "renderer: %s", msg);
    return TL_OK;
}

tl_result tl__device_init(tl__device *dev, const tl_renderer_desc *desc)
{
    const GladGLContext *gl = &dev->gl;
    GLint max_size = 0, ubo_align = 0, ssbo_align = 0;
    gl->GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    dev->lim.max_texture_size = max_size;
    if ((GLint)desc->width > max_size || (GLint)desc->height > max_size)
        return tl__fail(dev, TL_ERROR_LIMIT, "renderer: %ux%u exceeds GL_MAX_TEXTURE_SIZE %d", desc->width,
                        desc->height, max_size);
    gl->GetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &ubo_align);
    gl->GetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &ssbo_align);
    dev->lim.ubo_align = ubo_align > 16 ? (size_t)ubo_align : 16;
    dev->lim.ssbo_align = ssbo_align > 16 ? (size_t)ssbo_align : 16;
    tl__storage_limits(dev, desc->max_storage_block_bytes);
    tl__sample_counts(dev);
    gl->CreateVertexArrays(1, &dev->vao_empty);
    tl__gl_label(gl, GL_VERTEX_ARRAY, dev->vao_empty, "vao.fullscreen");
    gl->CreateSamplers(1, &dev->sampler_linear);
    tl__gl_label(gl, GL_SAMPLER, dev->sampler_linear, "sampler.linear");
    gl->SamplerParameteri(dev->sampler_linear, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->SamplerParameteri(dev->sampler_linear, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->SamplerParameteri(dev->sampler_linear, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->SamplerParameteri(dev->sampler_linear, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return TL_OK;
}

void tl__device_release(tl__device *dev)
{
    const GladGLContext *gl = &dev->gl;
    tl__program_cache_destroy(dev);
    tl__stream_destroy(gl, &dev->stream);
    if (dev->vao_empty) gl->DeleteVertexArrays(1, &dev->vao_empty);
    if (dev->sampler_linear) gl->DeleteSamplers(1, &dev->sampler_linear);
    dev->vao_empty = dev->sampler_linear = 0;
}
