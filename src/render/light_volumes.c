/* Low-poly light volumes that contain the true light shapes: a UV sphere scaled by the inverse of
 * its inradius, and a cone whose base polygon is scaled by 1 / cos(pi / segments). */
#include <math.h>

#include "light_volumes.h"

static float tl__plane_distance(const float *a, const float *b, const float *c)
{
    float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    float n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return l > 0.0f ? fabsf(n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) / l : 1.0f;
}

void tl__sphere_volume(tl__volume_mesh *m)
{
    const uint32_t seg = TL__SPHERE_SEGMENTS, rings = TL__SPHERE_RINGS;
    uint32_t nv = 0, ni = 0;
    for (uint32_t r = 0; r <= rings; r++) {
        float th = 3.14159265f * (float)r / (float)rings;
        for (uint32_t s = 0; s < seg; s++) {
            float ph = 6.28318531f * (float)s / (float)seg;
            m->vertices[nv * 3 + 0] = sinf(th) * cosf(ph);
            m->vertices[nv * 3 + 1] = sinf(th) * sinf(ph);
            m->vertices[nv * 3 + 2] = cosf(th);
            nv++;
        }
    }
    for (uint32_t r = 0; r < rings; r++)
        for (uint32_t s = 0; s < seg; s++) {
            uint32_t a = r * seg + s, b = r * seg + (s + 1) % seg, c = a + seg, d = b + seg;
            if (r != 0) { m->indices[ni++] = a; m->indices[ni++] = c; m->indices[ni++] = b; }
            if (r != rings - 1) { m->indices[ni++] = b; m->indices[ni++] = c; m->indices[ni++] = d; }
        }
    /* scale so that every face plane lies at distance >= 1 from the centre */
    float inr = 1.0f;
    for (uint32_t i = 0; i < ni; i += 3) {
        float d = tl__plane_distance(&m->vertices[m->indices[i] * 3], &m->vertices[m->indices[i + 1] * 3],
                                     &m->vertices[m->indices[i + 2] * 3]);
        if (d < inr) inr = d;
    }
    float k = 1.0f / inr * 1.001f;
    for (uint32_t i = 0; i < nv * 3; i++) m->vertices[i] *= k;
    m->vertex_count = nv;
    m->index_count = ni;
}

void tl__cone_volume(tl__volume_mesh *m)
{
    const uint32_t seg = TL__CONE_SEGMENTS;
    float k = 1.001f / cosf(3.14159265f / (float)seg);
    uint32_t nv = 0, ni = 0;
    m->vertices[0] = m->vertices[1] = m->vertices[2] = 0.0f; /* apex */
    nv = 1;
    for (uint32_t s = 0; s < seg; s++) {
        float ph = 6.28318531f * (float)s / (float)seg;
        m->vertices[nv * 3 + 0] = cosf(ph) * k;
        m->vertices[nv * 3 + 1] = sinf(ph) * k;
        m->vertices[nv * 3 + 2] = 1.001f;
        nv++;
    }
    m->vertices[nv * 3 + 0] = 0.0f; /* base centre */
    m->vertices[nv * 3 + 1] = 0.0f;
    m->vertices[nv * 3 + 2] = 1.001f;
    uint32_t centre = nv++;
    for (uint32_t s = 0; s < seg; s++) {
        uint32_t a = 1 + s, b = 1 + (s + 1) % seg;
        m->indices[ni++] = 0; m->indices[ni++] = b; m->indices[ni++] = a;
        m->indices[ni++] = centre; m->indices[ni++] = a; m->indices[ni++] = b;
    }
    m->vertex_count = nv;
    m->index_count = ni;
}
