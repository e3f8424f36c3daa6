/* The environment on the GPU (environment.h): checked, baked on the CPU (ibl_bake.c), uploaded. */
#include "environment.h"

#include <math.h>
#include <string.h>

#include "ibl_bake.h"

#define TL__ENV_MAX_WIDTH 16384u
#define TL__ENV_BLOCK_FLOATS (10 * 4) /* 9 SH vec4, then intensity, top level, 0, 0 */

static tl_result tl__environment_check(tl__device *dev, const tl_environment_desc *d)
{
    if (!d->rgb) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "environment: no pixels (rgb is NULL)");
    if (d->height < 2 || d->width != 2 * d->height)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT,
                        "environment: an equirectangular image is twice as wide as high, at least 4x2 (got %ux%u)",
                        (unsigned)d->width, (unsigned)d->height);
    if (d->width > TL__ENV_MAX_WIDTH || (GLint)d->width > dev->lim.max_texture_size)
        return tl__fail(dev, TL_ERROR_LIMIT, "environment: %ux%u is larger than %ux%u", (unsigned)d->width,
                        (unsigned)d->height, TL__ENV_MAX_WIDTH, TL__ENV_MAX_WIDTH / 2);
    return TL_OK;
}

/* The pixels as the renderer uses them: NaN and negative 0, at most FP16's largest value. */
static void tl__environment_sanitise(const float *in, size_t n, float *out)
{
    for (size_t i = 0; i < n; i++) {
        float c = in[i];
        out[i] = !(c > 0.0f) ? 0.0f : c > 65504.0f ? 65504.0f : c;
    }
}

static GLuint tl__env_texture(const GladGLContext *gl, GLsizei levels, GLenum format, GLsizei w, GLsizei h,
                              int wrap_u, const char *label)
{
    GLuint t = 0;
    gl->CreateTextures(GL_TEXTURE_2D, 1, &t);
    gl->TextureStorage2D(t, levels, format, w, h);
    gl->TextureParameteri(t, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    gl->TextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TextureParameteri(t, GL_TEXTURE_WRAP_S, wrap_u ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    gl->TextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    tl__gl_label(gl, GL_TEXTURE, t, label);
    return t;
}

/* The prefiltered chain, level by level through `scratch` (the largest level's RGBA floats). */
static GLuint tl__environment_chain(const GladGLContext *gl, const tl__ibl_pyramid *p, float *scratch)
{
    uint32_t bw = tl__ibl_base_width(p->w[0]), bh = bw / 2;
    GLuint t = tl__env_texture(gl, TL__IBL_LEVELS, GL_RGBA16F, (GLsizei)bw, (GLsizei)bh, 1, "environment.specular");
    for (uint32_t k = 0; k < TL__IBL_LEVELS; k++) {
        uint32_t w = bw >> k, h = bh >> k;
        tl__ibl_prefilter_level(p, k, w, h, scratch);
        gl->TextureSubImage2D(t, (GLint)k, 0, 0, (GLsizei)w, (GLsizei)h, GL_RGBA, GL_FLOAT, scratch);
    }
    return t;
}

/* The split-sum table, the same for every environment: computed once per renderer (it is the
 * largest part of the first set's time) and kept while an environment is. */
static GLuint tl__environment_table(const GladGLContext *gl, float *scratch)
{
    tl__ibl_brdf_table(scratch);
    GLuint t = tl__env_texture(gl, 1, GL_RG32F, TL__IBL_BRDF_SIZE, TL__IBL_BRDF_SIZE, 0, "environment.brdf");
    gl->TextureSubImage2D(t, 0, 0, 0, TL__IBL_BRDF_SIZE, TL__IBL_BRDF_SIZE, GL_RG, GL_FLOAT, scratch);
    return t;
}

/* Everything on the CPU, then the GL objects into *e (zeroed; e->brdf the table to keep, or 0);
 * TL_ERROR_OUT_OF_MEMORY before any. */
static tl_result tl__environment_make(tl__device *dev, const tl_environment_desc *d, tl__environment *e)
{
    const GladGLContext *gl = &dev->gl;
    size_t n = (size_t)d->width * d->height * 3, pyr = tl__ibl_pyramid_floats(d->width, d->height);
    uint32_t bw = tl__ibl_base_width(d->width);
    size_t chain = (size_t)bw * (bw / 2) * 4, table = (size_t)TL__IBL_BRDF_SIZE * TL__IBL_BRDF_SIZE * 2;
    float *buf = (float *)tl__alloc_array(&dev->alloc, n + pyr + (chain > table ? chain : table), sizeof(float));
    if (!buf) return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "environment: out of memory for %ux%u", d->width, d->height);
    float *img = buf, *scratch = buf + n + pyr;
    tl__environment_sanitise(d->rgb, n, img);
    tl__ibl_pyramid p;
    tl__ibl_pyramid_build(img, d->width, d->height, buf + n, &p);
    double sh[9][3];
    float block[TL__ENV_BLOCK_FLOATS] = {0};
    tl__ibl_sh9(img, d->width, d->height, sh);
    tl__ibl_sh_diffuse(sh, (float(*)[4])block);
    block[36] = 1.0f;
    block[37] = (float)(TL__IBL_LEVELS - 1);
    tl__pixel_store saved; /* uploads with GL's unpack defaults; the application's come back */
    tl__pixel_store_enter(gl, 1, &saved);
    e->sky = tl__env_texture(gl, 1, GL_RGBA16F, (GLsizei)d->width, (GLsizei)d->height, 1, "environment.sky");
    gl->TextureSubImage2D(e->sky, 0, 0, 0, (GLsizei)d->width, (GLsizei)d->height, GL_RGB, GL_FLOAT, img);
    e->specular = tl__environment_chain(gl, &p, scratch);
    if (!e->brdf) e->brdf = tl__environment_table(gl, scratch);
    tl__pixel_store_leave(gl, &saved);
    gl->CreateBuffers(1, &e->ubo);
    gl->NamedBufferStorage(e->ubo, sizeof block, block, GL_DYNAMIC_STORAGE_BIT);
    tl__gl_label(gl, GL_BUFFER, e->ubo, "environment.block");
    tl__free(&dev->alloc, buf);
    e->intensity = 1.0f;
    e->width = d->width;
    e->height = d->height;
    e->loaded = 1;
    return TL_OK;
}

tl_result tl__environment_set(tl__device *dev, tl__environment *e, const tl_environment_desc *d)
{
    if (!d) {
        tl__environment_release(dev, e);
        return TL_OK;
    }
    tl_result res = tl__environment_check(dev, d);
    if (res != TL_OK) return res;
    double t0 = tl__now_ms();
    tl__environment next;
    memset(&next, 0, sizeof next);
    next.brdf = e->loaded ? e->brdf : 0; /* the table does not depend on the environment */
    if ((res = tl__environment_make(dev, d, &next)) != TL_OK) return res;
    GLenum err = dev->gl.GetError();
    if (err != GL_NO_ERROR) {
        if (next.brdf == e->brdf) next.brdf = 0; /* still the current environment's */
        tl__environment_release(dev, &next);
        return tl__fail(dev, TL_ERROR_GL, "environment: %s while uploading it", tl__gl_error_string(err));
    }
    if (next.brdf == e->brdf) e->brdf = 0; /* handed over */
    tl__environment_release(dev, e);
    *e = next;
    e->bake_ms = tl__now_ms() - t0;
    return TL_OK;
}

void tl__environment_release(tl__device *dev, tl__environment *e)
{
    const GLuint t[3] = {e->sky, e->specular, e->brdf};
    if (e->loaded || e->sky) {
        dev->gl.DeleteTextures(3, t); /* 0 (a table handed over) is ignored */
        dev->gl.DeleteBuffers(1, &e->ubo);
    }
    memset(e, 0, sizeof *e);
}

void tl__environment_bind(const GladGLContext *gl, tl__environment *e, const tl_environment_options *o)
{
    if (!e->loaded) return;
    if (o->intensity != e->intensity) {
        gl->NamedBufferSubData(e->ubo, 36 * sizeof(float), sizeof(float), &o->intensity);
        e->intensity = o->intensity;
    }
    gl->BindTextureUnit(TL__UNIT_ENV_SKY, e->sky);
    gl->BindTextureUnit(TL__UNIT_ENV_SPECULAR, e->specular);
    gl->BindTextureUnit(TL__UNIT_ENV_BRDF, e->brdf);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, TL__UBO_ENVIRONMENT, e->ubo);
}
