/* A cube environment (tl_renderer_set_environment_cube): checked, then resampled into the
 * equirectangular image the environment's bake takes (environment.c), in GL's cube-map convention
 * (OpenGL 4.5 core, 8.13 "Cube Map Texture Selection"). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "plan_internal.h"
#include "renderer_internal.h"

#define TL__CUBE_MAX_SIZE 4096u /* 4 * size is the equirectangular image's width, at most 16384 */

static const char *const tl__face_names[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

/* The face, and the face's s and t in [0, 1], GL's table 8.19. */
static int tl__cube_face(const double d[3], double *s, double *t)
{
    double ax = fabs(d[0]), ay = fabs(d[1]), az = fabs(d[2]), sc, tc, ma;
    int f;
    if (ax >= ay && ax >= az) {
        f = d[0] >= 0.0 ? 0 : 1;
        ma = ax, sc = d[0] >= 0.0 ? -d[2] : d[2], tc = -d[1];
    } else if (ay >= az) {
        f = d[1] >= 0.0 ? 2 : 3;
        ma = ay, sc = d[0], tc = d[1] >= 0.0 ? d[2] : -d[2];
    } else {
        f = d[2] >= 0.0 ? 4 : 5;
        ma = az, sc = d[2] >= 0.0 ? d[0] : -d[0], tc = -d[1];
    }
    *s = 0.5 * (sc / ma + 1.0);
    *t = 0.5 * (tc / ma + 1.0);
    return f;
}

static const float *tl__face_texel(const tl_environment_face *f, long x, long y)
{
    size_t row = f->row_floats ? f->row_floats : (size_t)f->width * 3u;
    return f->rgb + (size_t)y * row + (size_t)x * 3u;
}

/* Bilinear within the face, clamped at its edges (GL's CLAMP_TO_EDGE on one face). */
static void tl__face_sample(const tl_environment_face *f, double s, double t, float out[3])
{
    long n = (long)f->width;
    double x = s * (double)n - 0.5, y = t * (double)n - 0.5;
    x = x < 0.0 ? 0.0 : x > (double)(n - 1) ? (double)(n - 1) : x;
    y = y < 0.0 ? 0.0 : y > (double)(n - 1) ? (double)(n - 1) : y;
    long x0 = (long)x, y0 = (long)y, x1 = x0 + 1 < n ? x0 + 1 : x0, y1 = y0 + 1 < n ? y0 + 1 : y0;
    double fx = x - (double)x0, fy = y - (double)y0;
    const float *a = tl__face_texel(f, x0, y0), *b = tl__face_texel(f, x1, y0);
    const float *c = tl__face_texel(f, x0, y1), *d = tl__face_texel(f, x1, y1);
    for (int k = 0; k < 3; k++)
        out[k] = (float)((1.0 - fy) * ((1.0 - fx) * a[k] + fx * b[k]) + fy * ((1.0 - fx) * c[k] + fx * d[k]));
}

void tl_environment_cube_to_equirect(const tl_environment_cube_desc *desc, float *rgb)
{
    uint32_t n = desc->faces[0].width, w = 4u * n, h = 2u * n;
    const double pi = 3.14159265358979323846;
    for (uint32_t j = 0; j < h; j++) {
        double theta = pi * ((double)j + 0.5) / (double)h; /* v = acos(y) / pi */
        for (uint32_t i = 0; i < w; i++) {
            double phi = 2.0 * pi * (((double)i + 0.5) / (double)w - 0.5); /* u = atan2(z, x) / 2 pi + 1/2 */
            double d[3] = {sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi)}, s, t;
            int f = tl__cube_face(d, &s, &t);
            tl__face_sample(&desc->faces[f], s, t, rgb + ((size_t)j * w + i) * 3u);
        }
    }
}

/* NULL for a good cube, else the problem (written into why). */
static const char *tl__cube_problem(const tl_environment_cube_desc *d, char *why, size_t size)
{
    uint32_t n = d->faces[0].width;
    for (int f = 0; f < 6; f++) {
        const tl_environment_face *fc = &d->faces[f];
        size_t row = fc->row_floats ? fc->row_floats : (size_t)fc->width * 3u;
        if (!fc->rgb) snprintf(why, size, "face %s has no pixels (rgb is NULL)", tl__face_names[f]);
        else if (!fc->width || fc->width != fc->height)
            snprintf(why, size, "face %s is %ux%u, not square", tl__face_names[f], (unsigned)fc->width, (unsigned)fc->height);
        else if (fc->width != n)
            snprintf(why, size, "face %s is %ux%u, face +X %ux%u: every face the same size", tl__face_names[f],
                     (unsigned)fc->width, (unsigned)fc->height, (unsigned)n, (unsigned)n);
        else if (row < (size_t)fc->width * 3u)
            snprintf(why, size, "face %s: row_floats %u is less than width * 3", tl__face_names[f], (unsigned)row);
        else continue;
        return why;
    }
    for (int f = 0; f < 6; f++)
        for (uint32_t y = 0; y < n; y++)
            for (uint32_t x = 0; x < 3u * n; x++)
                if (isnan(tl__face_texel(&d->faces[f], 0, (long)y)[x])) {
                    snprintf(why, size, "face %s has a NaN at pixel (%u, %u)", tl__face_names[f], (unsigned)(x / 3u),
                             (unsigned)y);
                    return why;
                }
    return NULL;
}

tl_result tl_renderer_set_environment_cube(tl_renderer *r, const tl_environment_cube_desc *desc)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    if (!desc) return tl_renderer_set_environment(r, NULL);
    char why[160];
    if (tl__cube_problem(desc, why, sizeof why))
        return tl__fail(&r->dev, TL_ERROR_INVALID_ARGUMENT, "environment cube: %s", why);
    uint32_t n = desc->faces[0].width;
    if (n > TL__CUBE_MAX_SIZE)
        return tl__fail(&r->dev, TL_ERROR_LIMIT, "environment cube: faces of %ux%u, at most %ux%u", (unsigned)n,
                        (unsigned)n, TL__CUBE_MAX_SIZE, TL__CUBE_MAX_SIZE);
    size_t floats = (size_t)(4u * n) * (2u * n) * 3u;
    float *rgb = (float *)tl__alloc_array(&r->dev.alloc, floats, sizeof(float));
    if (!rgb) return tl__fail(&r->dev, TL_ERROR_OUT_OF_MEMORY, "environment cube: out of memory for %ux%u faces", n, n);
    tl_environment_cube_to_equirect(desc, rgb);
    tl_result res = tl_renderer_set_environment(r, &(tl_environment_desc){.rgb = rgb, .width = 4u * n, .height = 2u * n});
    tl__free(&r->dev.alloc, rgb);
    return res;
}
