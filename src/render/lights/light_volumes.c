/* Light volumes: low-poly meshes that contain the true light shapes (a UV sphere scaled by the
 * inverse of its inradius, a cone whose base polygon is scaled by 1 / cos(pi / segments)), their
 * vertex arrays, and each frame's instances: the visible lights by type, those the camera is
 * outside of first (drawn by their front faces), then those that contain the camera or cross the
 * near plane (back faces). */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "light_volumes.h"
#include "lights.h"

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

void tl__light_volumes_create(tl__device *dev, tl__lights *r)
{
    const GladGLContext *gl = &dev->gl;
    tl__volume_mesh mesh;
    for (int v = 0; v < 2; v++) {
        if (v == 0) tl__sphere_volume(&mesh);
        else tl__cone_volume(&mesh);
        gl->CreateBuffers(1, &r->vbo_volume[v]);
        gl->NamedBufferStorage(r->vbo_volume[v], (GLsizeiptr)(mesh.vertex_count * 12u), mesh.vertices, 0);
        gl->CreateBuffers(1, &r->ibo_volume[v]);
        gl->NamedBufferStorage(r->ibo_volume[v], (GLsizeiptr)(mesh.index_count * 4u), mesh.indices, 0);
        tl__gl_label(gl, GL_BUFFER, r->vbo_volume[v], v ? "buffer.volume.cone" : "buffer.volume.sphere");
        tl__gl_label(gl, GL_BUFFER, r->ibo_volume[v], v ? "buffer.volume.cone.indices" : "buffer.volume.sphere.indices");
        r->volume_index_count[v] = mesh.index_count;
    }
    gl->CreateVertexArrays(TL__LIGHT_KINDS, r->vao);
    static const char *const names[TL__LIGHT_KINDS] = {"vao.lights.point", "vao.lights.spot", "vao.lights.directional"};
    const GLuint offs[4] = {offsetof(tl__light_record, position_radius), offsetof(tl__light_record, color_type),
                            offsetof(tl__light_record, direction_cos_outer), offsetof(tl__light_record, cos_inner)};
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        GLuint vao = r->vao[k];
        if (k < 2) {
            gl->VertexArrayVertexBuffer(vao, 0, r->vbo_volume[k], 0, 12);
            gl->VertexArrayElementBuffer(vao, r->ibo_volume[k]);
            gl->EnableVertexArrayAttrib(vao, 0);
            gl->VertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
            gl->VertexArrayAttribBinding(vao, 0, 0);
        }
        gl->VertexArrayBindingDivisor(vao, 1, 1);
        for (GLuint a = 0; a < 4; a++) {
            gl->EnableVertexArrayAttrib(vao, a + 1);
            gl->VertexArrayAttribFormat(vao, a + 1, 4, GL_FLOAT, GL_FALSE, offs[a]);
            gl->VertexArrayAttribBinding(vao, a + 1, 1);
        }
        tl__gl_label(gl, GL_VERTEX_ARRAY, vao, names[k]);
    }
}

void tl__light_volumes_destroy(tl__device *dev, tl__lights *r)
{
    const GladGLContext *gl = &dev->gl;
    if (r->vao[0]) gl->DeleteVertexArrays(TL__LIGHT_KINDS, r->vao);
    if (r->vbo_volume[0]) gl->DeleteBuffers(2, r->vbo_volume);
    if (r->ibo_volume[0]) gl->DeleteBuffers(2, r->ibo_volume);
    memset(r->vao, 0, sizeof r->vao);
    memset(r->vbo_volume, 0, sizeof r->vbo_volume);
    memset(r->ibo_volume, 0, sizeof r->ibo_volume);
}

/* -1: culled; 0: the camera is inside or the near plane may cut it; 1: outside (front faces). */
static int tl__light_side(const tl__lights *r, const tl__view *v, const tl_light *l, int type)
{
    if (type == TL_LIGHT_DIRECTIONAL) return 0;
    if (l->radius <= 0.0f || !tl__sphere_visible((float(*)[4])v->planes, l->position, l->radius * 1.2f)) return -1;
    /* bounding sphere of the volume mesh around the light (sphere: < 1.2 r; cone: apex to base rim,
     * < 1.2 r / cos_outer; past 60 degrees the cone of light.vert.glsl whose apex lies 1.1 r behind
     * the light: its base rim, sqrt(1.002^2 + 2.176^2) r < 2.5 r) */
    float bound = type != TL_LIGHT_SPOT ? l->radius * 1.2f
                  : l->cos_outer >= 0.5f ? l->radius * 1.2f / l->cos_outer
                                         : l->radius * 2.5f;
    float d2 = 0.0f;
    for (int a = 0; a < 3; a++) d2 += (l->position[a] - v->eye[a]) * (l->position[a] - v->eye[a]);
    float margin = bound + 4.0f * v->near_z;
    return !r->fullscreen && d2 > margin * margin;
}

void tl__volumes_prepare(tl__lights *r, const tl__view *v, tl_frame_stats *st, size_t *stream_bytes)
{
    size_t n = 0;
    for (int k = 0; k < TL__LIGHT_KINDS; k++) {
        r->instance_base[k] = n;
        r->instance_count[k] = r->instance_outside[k] = 0;
        for (int pass = 0; pass < 2; pass++)
            for (size_t i = 0; i < r->count; i++) {
                const tl_light *l = &r->lights[i];
                int type = l->type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : (int)l->type;
                if (type - 1 != k) continue;
                int side = tl__light_side(r, v, l, type);
                if (side < 0 || side != (pass == 0)) continue;
                tl__light_record_fill(l, NULL, r->shadow_slots ? r->shadow_slots[i] : 0.0f, &r->instances[n]);
                n++;
                r->instance_count[k]++;
                r->instance_outside[k] += (size_t)side;
            }
        st->lights_drawn[k + 1] = (uint32_t)r->instance_count[k];
    }
    *stream_bytes += n * sizeof(tl__light_record) + 16;
}

void tl__volumes_upload(tl__device *dev, tl__lights *r)
{
    const GladGLContext *gl = &dev->gl;
    size_t total = 0;
    for (int k = 0; k < TL__LIGHT_KINDS; k++) total += r->instance_count[k];
    size_t offset = 0;
    uint8_t *dst = total ? (uint8_t *)tl__stream_reserve(&dev->stream, total * sizeof(tl__light_record), 16, &offset) : NULL;
    if (!dst) return;
    memcpy(dst, r->instances, total * sizeof(tl__light_record));
    for (int k = 0; k < TL__LIGHT_KINDS; k++)
        if (r->instance_count[k])
            gl->VertexArrayVertexBuffer(r->vao[k], 1, dev->stream.buffer,
                                        (GLintptr)(offset + r->instance_base[k] * sizeof(tl__light_record)),
                                        sizeof(tl__light_record));
}
