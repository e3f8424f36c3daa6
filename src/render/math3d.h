/* Small column-major matrix helpers for the renderer (private). */
#ifndef TL_RENDER_MATH3D_H
#define TL_RENDER_MATH3D_H

#include <math.h>
#include <string.h>

typedef struct tl__mat4 { float m[16]; } tl__mat4;

static inline tl__mat4 tl__mat4_mul(const tl__mat4 *a, const tl__mat4 *b)
{
    tl__mat4 r;
    for (int c = 0; c < 4; c++)
        for (int i = 0; i < 4; i++) {
            float s = 0.0f;
            for (int k = 0; k < 4; k++) s += a->m[k * 4 + i] * b->m[c * 4 + k];
            r.m[c * 4 + i] = s;
        }
    return r;
}

static inline void tl__vec3_normalize(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0.0f) {
        v[0] /= l;
        v[1] /= l;
        v[2] /= l;
    }
}

/* Inverse transpose of the upper 3x3 of m, column-major 3x3 (normal matrix). */
static inline void tl__normal_matrix(const tl__mat4 *m, float out[9])
{
    const float *a = m->m;
    float c00 = a[5] * a[10] - a[9] * a[6], c01 = a[8] * a[6] - a[4] * a[10], c02 = a[4] * a[9] - a[8] * a[5];
    float c10 = a[9] * a[2] - a[1] * a[10], c11 = a[0] * a[10] - a[8] * a[2], c12 = a[8] * a[1] - a[0] * a[9];
    float c20 = a[1] * a[6] - a[5] * a[2], c21 = a[4] * a[2] - a[0] * a[6], c22 = a[0] * a[5] - a[4] * a[1];
    float det = a[0] * c00 + a[4] * c10 + a[8] * c20;
    float inv = det != 0.0f ? 1.0f / det : 0.0f;
    /* inverse = adj / det with adj[i][j] = c[j][i]; its transpose stored column-major */
    out[0] = c00 * inv; out[1] = c01 * inv; out[2] = c02 * inv;
    out[3] = c10 * inv; out[4] = c11 * inv; out[5] = c12 * inv;
    out[6] = c20 * inv; out[7] = c21 * inv; out[8] = c22 * inv;
}

/* Frustum planes (a, b, c, d with inside >= 0) from a view-projection matrix; the far plane is
 * left out (it may be infinite). */
static inline void tl__frustum_planes(const tl__mat4 *vp, float planes[5][4])
{
    const float *m = vp->m;
    for (int i = 0; i < 4; i++) {
        float row3 = m[i * 4 + 3];
        planes[0][i] = row3 + m[i * 4 + 0];
        planes[1][i] = row3 - m[i * 4 + 0];
        planes[2][i] = row3 + m[i * 4 + 1];
        planes[3][i] = row3 - m[i * 4 + 1];
        planes[4][i] = row3 + m[i * 4 + 2]; /* near for GL clip; for [0,1] clip it is near z>=0 */
    }
    for (int p = 0; p < 5; p++) {
        float l = sqrtf(planes[p][0] * planes[p][0] + planes[p][1] * planes[p][1] + planes[p][2] * planes[p][2]);
        if (l > 0.0f)
            for (int i = 0; i < 4; i++) planes[p][i] /= l;
    }
}

static inline int tl__sphere_visible(float planes[5][4], const float c[3], float r)
{
    for (int p = 0; p < 5; p++)
        if (planes[p][0] * c[0] + planes[p][1] * c[1] + planes[p][2] * c[2] + planes[p][3] < -r) return 0;
    return 1;
}

static inline int tl__box_visible(float planes[5][4], const float lo[3], const float hi[3])
{
    for (int p = 0; p < 5; p++) {
        float x = planes[p][0] >= 0 ? hi[0] : lo[0], y = planes[p][1] >= 0 ? hi[1] : lo[1];
        float z = planes[p][2] >= 0 ? hi[2] : lo[2];
        if (planes[p][0] * x + planes[p][1] * y + planes[p][2] * z + planes[p][3] < 0) return 0;
    }
    return 1;
}

#endif
