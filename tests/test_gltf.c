/* glTF loading (tl_scene_load_gltf), no GL: the test scenes against hand-computed transforms,
 * bounds, materials and lights; bad input (each case its own test); the allocator (every
 * allocation freed, failure at every k-th allocation); fuzzed files. Every file is written at run
 * time by gltf_fixtures.c into TL_GLTF_TEST_DIR/<test name>. */
#include <stdint.h>

#include "gltf_fixtures.h"
#include "thinlight/io.h"
#include "thinlight/scene.h"
#include "tl_test.h"

#ifndef TL_GLTF_TEST_DIR
#define TL_GLTF_TEST_DIR "gltf_work"
#endif

static const float PI_F = 3.14159265358979f;

/* ---- helpers ----------------------------------------------------------------------------- */

/* The logger: counts, keeps the last error and all warnings, and checks one line per message. */
typedef struct capture {
    int errors, warnings, multiline;
    char last_error[1024];
    char warnings_text[8192];
} capture;

static void capture_fn(void *user, tl_log_level level, const char *message)
{
    capture *c = user;
    if (strchr(message, '\n')) c->multiline++;
    if (level == TL_LOG_ERROR) {
        c->errors++;
        snprintf(c->last_error, sizeof c->last_error, "%s", message);
    } else if (level == TL_LOG_WARNING) {
        c->warnings++;
        size_t n = strlen(c->warnings_text);
        snprintf(c->warnings_text + n, sizeof c->warnings_text - n, "%s\n", message);
    }
}

/* Counts live allocations; fails the fail_at-th call (1-based) when set. */
typedef struct counter {
    long live;
    size_t calls, fail_at;
} counter;

static void *count_alloc(size_t size, void *user)
{
    counter *c = user;
    c->calls++;
    if (c->fail_at && c->calls == c->fail_at) return NULL;
    void *p = malloc(size);
    if (p) c->live++;
    return p;
}

static void count_free(void *ptr, void *user)
{
    counter *c = user;
    if (ptr) c->live--;
    free(ptr);
}

static void case_dir(char *out, size_t n, const char *test)
{
    snprintf(out, n, "%s/%s", TL_GLTF_TEST_DIR, test);
    tlf_mkdir_p(out);
}

/* Writes fixture `fixture` into the test's directory; its path into `path`. */
static int fixture(const char *test, const char *fixture_name, char *path, size_t n)
{
    char dir[1024];
    case_dir(dir, sizeof dir, test);
    int rc = tlf_write_case(dir, fixture_name, path, n);
    TL_CHECK(rc == 0);
    return rc;
}

/* Loads with a capture logger and a counting allocator on top of `base` options. */
typedef struct loaded {
    tl_result result;
    tl_scene *scene;
    capture log;
    counter count;
    char error[1024];
    char path[1024];
} loaded;

static void load_opts(loaded *l, const char *test, const char *fixture_name, const tl_gltf_options *base)
{
    memset(l, 0, sizeof *l);
    if (fixture(test, fixture_name, l->path, sizeof l->path)) {
        l->result = TL_ERROR_IO;
        return;
    }
    tl_gltf_options o = base ? *base : (tl_gltf_options){0};
    o.logger = (tl_logger){capture_fn, &l->log};
    o.allocator = (tl_allocator){count_alloc, count_free, &l->count};
    l->result = tl_scene_load_gltf(l->path, &o, &l->scene);
    snprintf(l->error, sizeof l->error, "%s", l->log.last_error);
    TL_CHECK(l->log.multiline == 0);
    if (l->result != TL_OK) {
        TL_CHECK(l->scene == NULL);
        TL_CHECK(l->count.live == 0);
        TL_CHECK(l->log.errors == 1);
        TL_CHECK(strcmp(l->error, l->log.last_error) == 0);
        /* one line that starts with the file */
        TL_CHECK(strncmp(l->error, l->path, strlen(l->path)) == 0);
        TL_CHECK(strchr(l->error, '\n') == NULL);
    } else {
        TL_CHECK(l->scene != NULL);
        TL_CHECK(l->log.errors == 0);
        TL_CHECK(l->error[0] == '\0');
    }
}

static void load(loaded *l, const char *test, const char *fixture_name) { load_opts(l, test, fixture_name, NULL); }

static void unload(loaded *l)
{
    tl_scene_destroy(l->scene);
    l->scene = NULL;
    TL_CHECK(l->count.live == 0);
}

/* Expects failure `want` whose message contains `needle` (may be NULL). */
static void expect_failure(const char *test, const char *fixture_name, tl_result want, const char *needle)
{
    loaded l;
    load(&l, test, fixture_name);
    if (l.result != want) fprintf(stderr, "%s: got %s (%s)\n", test, tl_result_string(l.result), l.error);
    TL_CHECK(l.result == want);
    if (needle && !strstr(l.error, needle)) {
        fprintf(stderr, "%s: '%s' not in '%s'\n", test, needle, l.error);
        TL_CHECK(strstr(l.error, needle) != NULL);
    }
    unload(&l);
}

static int near(float a, float b, float tol) { return fabsf(a - b) <= tol; }
static int near3(const float *a, float x, float y, float z, float tol)
{
    return near(a[0], x, tol) && near(a[1], y, tol) && near(a[2], z, tol);
}

static void xform(const float m[16], const float p[3], float out[3])
{
    for (int r = 0; r < 3; r++) out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}

static float len3(const float v[3]) { return sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
static float dot3f(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Every index in range, every vertex finite with a unit normal. */
static void check_geometry(const tl_scene *s)
{
    for (size_t i = 0; i < s->index_count; i++) TL_CHECK(s->indices[i] < s->vertex_count);
    for (size_t i = 0; i < s->vertex_count; i++) {
        const tl_vertex *v = &s->vertices[i];
        TL_CHECK_FINITE3(v->position);
        TL_CHECK(near(len3(v->normal), 1.0f, 1e-5f));
    }
    for (size_t i = 0; i < s->object_count; i++) {
        const tl_object *o = &s->objects[i];
        TL_CHECK((size_t)o->first_index + o->index_count <= s->index_count);
        TL_CHECK(o->material < s->material_count);
        for (int k = 0; k < 3; k++) {
            TL_CHECK(o->bounds_min[k] <= o->bounds_max[k]);
            TL_CHECK(o->bounds_min[k] >= s->bounds_min[k] && o->bounds_max[k] <= s->bounds_max[k]);
        }
    }
    for (size_t i = 0; i < s->material_count; i++) {
        const tl_material *m = &s->materials[i];
        const uint32_t t[5] = {m->albedo_texture, m->normal_texture, m->metallic_roughness_texture, m->emissive_texture,
                               m->occlusion_texture};
        for (int k = 0; k < 5; k++) TL_CHECK(t[k] == TL_NO_TEXTURE || t[k] < s->texture_count);
    }
    for (size_t i = 0; i < s->texture_count; i++) {
        TL_CHECK(s->textures[i].rgba != NULL);
        TL_CHECK(s->textures[i].width > 0 && s->textures[i].height > 0);
    }
    for (size_t i = 0; i < s->light_count; i++) {
        const tl_light *l = &s->lights[i];
        TL_CHECK_FINITE3(l->position);
        TL_CHECK_FINITE3(l->color);
        if (l->type != TL_LIGHT_DIRECTIONAL) TL_CHECK(l->radius > 0.0f);
        if (l->type != TL_LIGHT_POINT) TL_CHECK(near(len3(l->direction), 1.0f, 1e-5f));
        if (l->type == TL_LIGHT_SPOT) TL_CHECK(l->cos_outer < l->cos_inner);
    }
    TL_CHECK_FINITE3(s->camera.position);
    TL_CHECK_FINITE3(s->camera.target);
    TL_CHECK(s->camera.fov_y > 0.0f && s->camera.near_z > 0.0f);
}

/* Unit tangents orthogonal to their normals, w = +-1, for vertices [first, first + count). */
static void check_tangents(const tl_scene *s, size_t first, size_t count)
{
    for (size_t i = first; i < first + count; i++) {
        const tl_vertex *v = &s->vertices[i];
        TL_CHECK(near(len3(v->tangent), 1.0f, 1e-5f));
        TL_CHECK(fabsf(dot3f(v->tangent, v->normal)) < 1e-5f);
        TL_CHECK(v->tangent[3] == 1.0f || v->tangent[3] == -1.0f);
    }
}

/* ---- good input -------------------------------------------------------------------------- */

static void gltf_textured_boxes_hierarchy(void)
{
    loaded l;
    load(&l, "gltf_textured_boxes_hierarchy", "textured_boxes");
    TL_CHECK(l.result == TL_OK);
    if (l.result != TL_OK) return;
    const tl_scene *s = l.scene;
    check_geometry(s);
    TL_CHECK_EQ_U(s->object_count, 4);
    TL_CHECK_EQ_U(s->material_count, 2);
    TL_CHECK_EQ_U(s->texture_count, 3);
    TL_CHECK_EQ_U(s->vertex_count, 52); /* box, box (second plan of the shared accessors), quad */
    TL_CHECK_EQ_U(s->index_count, 78);
    if (s->object_count == 4) {
        /* Depth-first: spinner (box), leaf (box, instanced), matrixed (box, top quad).
         * root = T(10,0,0) S(2); spinner = root T(0,1,0) Ry(90); leaf = spinner T(1,0,0);
         * matrixed = root T(0,0,3). Ry(90) maps +x to -z. */
        const float px[3] = {1, 0, 0}, p0[3] = {0, 0, 0};
        float w[3];
        xform(s->objects[0].transform, px, w);
        TL_CHECK(near3(w, 10, 2, -2, 1e-5f));
        xform(s->objects[1].transform, p0, w);
        TL_CHECK(near3(w, 10, 2, -2, 1e-5f));
        xform(s->objects[1].transform, px, w);
        TL_CHECK(near3(w, 10, 2, -4, 1e-5f));
        xform(s->objects[2].transform, p0, w);
        TL_CHECK(near3(w, 10, 0, 6, 1e-5f));
        xform(s->objects[2].transform, px, w);
        TL_CHECK(near3(w, 12, 0, 6, 1e-5f));
        const float want[4][6] = {{9, 1, -1, 11, 3, 1},
                                  {9, 1, -3, 11, 3, -1},
                                  {9, -1, 5, 11, 1, 7},
                                  {9, 1.1f, 5, 11, 1.1f, 7}};
        for (int i = 0; i < 4; i++) {
            TL_CHECK(near3(s->objects[i].bounds_min, want[i][0], want[i][1], want[i][2], 1e-5f));
            TL_CHECK(near3(s->objects[i].bounds_max, want[i][3], want[i][4], want[i][5], 1e-5f));
        }
        TL_CHECK(s->objects[0].first_index == s->objects[1].first_index); /* instances share */
        TL_CHECK_EQ_U(s->objects[0].index_count, 36);
        TL_CHECK_EQ_U(s->objects[3].index_count, 6);
        TL_CHECK_EQ_U(s->objects[0].material, 0);
        TL_CHECK_EQ_U(s->objects[2].material, 1);
        TL_CHECK_EQ_U(s->objects[3].material, 0);
    }
    TL_CHECK(near3(s->bounds_min, 9, -1, -3, 1e-5f));
    TL_CHECK(near3(s->bounds_max, 11, 3, 7, 1e-5f));
    /* The file's camera: (10, 2, 14) looking down -Z; no zfar = infinite. The target lies at the
     * depth of the bounds' centre (z = 2). */
    TL_CHECK(near3(s->camera.position, 10, 2, 14, 1e-6f));
    TL_CHECK(near3(s->camera.target, 10, 2, 2, 1e-5f));
    TL_CHECK(near3(s->camera.up, 0, 1, 0, 1e-6f));
    TL_CHECK(near(s->camera.fov_y, 0.8f, 1e-6f));
    TL_CHECK(near(s->camera.near_z, 0.1f, 1e-7f));
    TL_CHECK(s->camera.far_z == 0.0f);
    TL_CHECK(near3(s->ambient, 0.03f, 0.03f, 0.03f, 1e-7f));
    TL_CHECK(l.log.warnings == 0);
    unload(&l);
}

static void gltf_textured_boxes_materials_textures(void)
{
    loaded l;
    load(&l, "gltf_textured_boxes_materials_textures", "textured_boxes");
    TL_CHECK(l.result == TL_OK);
    if (l.result != TL_OK || l.scene->material_count != 2 || l.scene->texture_count != 3) return;
    const tl_scene *s = l.scene;
    const tl_material *m = &s->materials[0];
    TL_CHECK(strcmp(m->name, "checker") == 0);
    TL_CHECK(m->flags == TL_MATERIAL_METALLIC_ROUGHNESS);
    TL_CHECK(near3(m->albedo, 1.0f, 0.9f, 0.8f, 1e-6f)); /* base colour, converted per pixel */
    TL_CHECK(near(m->metallic, 0.5f, 1e-6f) && near(m->roughness, 0.75f, 1e-6f));
    TL_CHECK(near(m->normal_scale, 0.8f, 1e-6f));
    TL_CHECK(m->albedo_texture == 0 && m->metallic_roughness_texture == 1 && m->normal_texture == 2);
    TL_CHECK(m->emissive_texture == TL_NO_TEXTURE && m->occlusion_texture == TL_NO_TEXTURE);
    m = &s->materials[1];
    TL_CHECK(strcmp(m->name, "painted") == 0);
    TL_CHECK(m->flags == 0);
    TL_CHECK(near3(m->albedo, 0.2f, 0.4f, 0.6f, 1e-6f)); /* metal 0: diffuse = base */
    TL_CHECK(near3(m->specular, 0.04f, 0.04f, 0.04f, 1e-6f));
    TL_CHECK(near(m->gloss, 0.5f, 1e-6f));
    TL_CHECK(m->albedo_texture == 0 && m->normal_texture == TL_NO_TEXTURE);

    const tl_texture *t = &s->textures[0];
    TL_CHECK(t->width == 4 && t->height == 4);
    const uint8_t dark[4] = {40, 60, 90, 255}, light[4] = {230, 200, 160, 255};
    TL_CHECK(memcmp(t->rgba, dark, 4) == 0);      /* row 0 (top), column 0 */
    TL_CHECK(memcmp(t->rgba + 4, light, 4) == 0); /* column 1 */
    TL_CHECK(memcmp(t->rgba + 16, light, 4) == 0); /* row 1 */
    const uint8_t mr[4] = {0, 128, 255, 255}, flat[4] = {128, 128, 255, 255};
    for (int i = 0; i < 16; i++) {
        TL_CHECK(memcmp(s->textures[1].rgba + 4 * i, mr, 4) == 0);
        TL_CHECK(memcmp(s->textures[2].rgba + 4 * i, flat, 4) == 0);
    }
    TL_CHECK(strcmp(t->name, "albedo.png") == 0);

    /* Normal-mapped box (vertices 0..23): generated tangents along +u, w = -1 with the fixture's
     * v-down UVs. The second box (24..47, no normal map) keeps zero tangents. */
    check_tangents(s, 0, 24);
    for (size_t i = 0; i < 24; i++) {
        const tl_vertex *v = &s->vertices[i];
        TL_CHECK(v->tangent[3] == -1.0f);
        /* +u runs along the tangent: the vertex with the larger u lies further along it */
        for (size_t j = i - i % 4; j < i - i % 4 + 4; j++)
            if (s->vertices[j].uv[0] > v->uv[0] + 0.5f) {
                float d[3] = {s->vertices[j].position[0] - v->position[0], s->vertices[j].position[1] - v->position[1],
                              s->vertices[j].position[2] - v->position[2]};
                TL_CHECK(dot3f(d, v->tangent) > 0.99f);
            }
    }
    for (size_t i = 24; i < 48; i++) TL_CHECK(len3(s->vertices[i].tangent) == 0.0f);
    check_tangents(s, 48, 4); /* the top quad uses the normal-mapped material */
    unload(&l);
}

static void gltf_materials_conversion(void)
{
    loaded l;
    load(&l, "gltf_materials_conversion", "materials");
    TL_CHECK(l.result == TL_OK);
    if (l.result != TL_OK) return;
    const tl_scene *s = l.scene;
    check_geometry(s);
    TL_CHECK_EQ_U(s->material_count, 8);
    TL_CHECK_EQ_U(s->object_count, 8);
    TL_CHECK_EQ_U(s->texture_count, 2);
    if (s->material_count != 8) return;
    const tl_material *m = s->materials;
    /* diffuse = base (1 - metal), F0 = mix(0.04, base, metal), gloss = 1 - rough */
    TL_CHECK(near3(m[0].albedo, 0, 0, 0, 1e-6f));
    TL_CHECK(near3(m[0].specular, 0.9f, 0.6f, 0.3f, 1e-6f));
    TL_CHECK(near(m[0].gloss, 0.8f, 1e-6f));
    TL_CHECK(near3(m[1].albedo, 0.5f, 0.5f, 0.5f, 1e-6f));
    TL_CHECK(near3(m[1].specular, 0.04f, 0.04f, 0.04f, 1e-6f));
    TL_CHECK(near(m[1].gloss, 0.0f, 1e-6f));
    TL_CHECK(near3(m[2].albedo, 0.4f, 0.1f, 0.2f, 1e-6f));
    TL_CHECK(near3(m[2].specular, 0.42f, 0.12f, 0.22f, 1e-6f));
    TL_CHECK(near(m[2].gloss, 0.6f, 1e-6f));
    for (int i = 0; i < 3; i++) TL_CHECK(m[i].flags == 0);
    TL_CHECK(m[3].flags == TL_MATERIAL_ALPHA_MASK);
    TL_CHECK(near(m[3].alpha_cutoff, 0.3f, 1e-6f) && near(m[3].alpha, 0.9f, 1e-6f));
    TL_CHECK(m[3].albedo_texture == 0);
    TL_CHECK(m[4].flags == (TL_MATERIAL_ALPHA_BLEND | TL_MATERIAL_DOUBLE_SIDED));
    TL_CHECK(near(m[4].alpha, 0.5f, 1e-6f));
    TL_CHECK(m[5].flags == TL_MATERIAL_DOUBLE_SIDED);
    TL_CHECK(near3(m[5].emissive, 2.0f, 1.0f, 0.0f, 1e-6f)); /* KHR_materials_emissive_strength 2 */
    TL_CHECK(m[6].flags == TL_MATERIAL_METALLIC_ROUGHNESS);
    TL_CHECK(near3(m[6].albedo, 1, 1, 1, 1e-6f));
    TL_CHECK(near(m[6].metallic, 0.7f, 1e-6f) && near(m[6].roughness, 0.6f, 1e-6f));
    TL_CHECK(m[6].metallic_roughness_texture == 1 && m[6].occlusion_texture == 1);
    TL_CHECK(near(m[6].occlusion_strength, 0.5f, 1e-6f));
    /* glTF's default material: white, metallic 1, roughness 1 */
    TL_CHECK(strcmp(m[7].name, "default material") == 0);
    TL_CHECK(near3(m[7].albedo, 0, 0, 0, 1e-6f) && near3(m[7].specular, 1, 1, 1, 1e-6f) && m[7].gloss == 0.0f);
    /* Quads 4..7 have no NORMAL: generated flat, facing +Z as the given ones. */
    for (size_t i = 0; i < s->vertex_count; i++) TL_CHECK(near3(s->vertices[i].normal, 0, 0, 1, 1e-6f));
    unload(&l);
}

static void gltf_lights_punctual(void)
{
    loaded l;
    load(&l, "gltf_lights_punctual", "lights");
    TL_CHECK(l.result == TL_OK);
    if (l.result != TL_OK) return;
    const tl_scene *s = l.scene;
    check_geometry(s);
    TL_CHECK_EQ_U(s->light_count, 4); /* the file's lights, no default rig */
    if (s->light_count != 4) return;
    const tl_light *L = s->lights;
    /* colour = glTF colour * intensity / pi */
    TL_CHECK(L[0].type == TL_LIGHT_POINT);
    TL_CHECK(near3(L[0].position, 1, 2, 3, 1e-6f));
    TL_CHECK(near3(L[0].color, 10 / PI_F, 5 / PI_F, 2.5f / PI_F, 1e-5f));
    TL_CHECK(near(L[0].radius, 5.0f, 1e-6f));
    /* no range: colour / d^2 = 1/256 at the radius, colour 1 -> 16 */
    TL_CHECK(L[1].type == TL_LIGHT_POINT);
    TL_CHECK(near3(L[1].position, -4, 5, 0, 1e-6f));
    TL_CHECK(near3(L[1].color, 1, 1, 1, 1e-5f));
    TL_CHECK(near(L[1].radius, 16.0f, 1e-3f));
    /* the spot hangs under a parent moved by (2, 0, 0) and points down (its -Z rotated) */
    TL_CHECK(L[2].type == TL_LIGHT_SPOT);
    TL_CHECK(near3(L[2].position, 2, 6, 0, 1e-5f));
    TL_CHECK(near3(L[2].direction, 0, -1, 0, 1e-6f));
    TL_CHECK(near(L[2].radius, 10.0f, 1e-6f));
    TL_CHECK(near(L[2].cos_inner, cosf(0.2f), 1e-6f) && near(L[2].cos_outer, cosf(0.5f), 1e-6f));
    TL_CHECK(near3(L[2].color, 10 / PI_F, 10 / PI_F, 20 / PI_F, 1e-5f));
    TL_CHECK(L[3].type == TL_LIGHT_DIRECTIONAL);
    TL_CHECK(near3(L[3].direction, -1, 0, 0, 1e-6f));
    TL_CHECK(near3(L[3].color, 3 / PI_F, 3 / PI_F, 2.7f / PI_F, 1e-5f));
    /* no camera in the file: one that frames the bounds, looking at their centre */
    TL_CHECK(near3(s->bounds_min, -10, 0, -10, 1e-5f) && near3(s->bounds_max, 10, 1, 10, 1e-5f));
    TL_CHECK(near3(s->camera.target, 0, 0.5f, 0, 1e-5f));
    TL_CHECK(s->camera.far_z > s->camera.near_z);
    unload(&l);
}

static void gltf_index_sizes(void)
{
    loaded l;
    load(&l, "gltf_index_sizes", "indices");
    TL_CHECK(l.result == TL_OK);
    if (l.result != TL_OK) return;
    const tl_scene *s = l.scene;
    check_geometry(s);
    TL_CHECK_EQ_U(s->object_count, 4);
    if (s->object_count != 4) return;
    /* u8, u16, u32 and no indices: the same two triangles, 3 apart along x */
    static const float corner[6][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, 1}, {1, -1}, {-1, -1}};
    for (int q = 0; q < 4; q++) {
        const tl_object *o = &s->objects[q];
        TL_CHECK_EQ_U(o->index_count, 6);
        for (int k = 0; k < 6; k++) {
            const tl_vertex *v = &s->vertices[s->indices[o->first_index + (uint32_t)k]];
            TL_CHECK(near3(v->position, 3.0f * (float)q + corner[k][0], 0, corner[k][1], 1e-6f));
            TL_CHECK(near3(v->normal, 0, 1, 0, 1e-6f)); /* generated: no NORMAL */
        }
    }
    TL_CHECK_EQ_U(s->vertex_count, 4 * 6); /* flat normals: the indexed quads are unshared too */
    TL_CHECK(l.log.warnings == 0);
    unload(&l);
}

static void gltf_normalized_uvs(void)
{
    loaded l;
    load(&l, "gltf_normalized_uvs", "indices");
    TL_CHECK(l.result == TL_OK);
    if (l.result != TL_OK || l.scene->object_count != 4) return;
    /* quads 0 (normalised u8), 1 (normalised u16), 2 and 3 (float): 0 and the integer maximum
     * map to exactly 0 and 1, the same as the floats; corners in triangle order */
    static const float want[6][2] = {{0, 1}, {1, 1}, {1, 0}, {0, 1}, {1, 0}, {0, 0}};
    for (int q = 0; q < 4; q++) {
        const tl_object *o = &l.scene->objects[q];
        for (int k = 0; k < 6; k++) {
            const tl_vertex *v = &l.scene->vertices[l.scene->indices[o->first_index + (uint32_t)k]];
            TL_CHECK(v->uv[0] == want[k][0] && v->uv[1] == want[k][1]);
        }
    }
    unload(&l);
    /* materials.glb: quads with u8 (even) and u16 (odd) normalised UVs, all corners 0 or 1 */
    load(&l, "gltf_normalized_uvs", "materials");
    TL_CHECK(l.result == TL_OK);
    if (l.result == TL_OK)
        for (size_t i = 0; i < l.scene->vertex_count; i++)
            for (int k = 0; k < 2; k++) {
                float u = l.scene->vertices[i].uv[k];
                TL_CHECK(u == 0.0f || u == 1.0f);
            }
    unload(&l);
}

static int scenes_equal(const tl_scene *a, const tl_scene *b)
{
    int eq = a->vertex_count == b->vertex_count && a->index_count == b->index_count &&
             a->object_count == b->object_count && a->material_count == b->material_count &&
             a->texture_count == b->texture_count && a->light_count == b->light_count;
    if (!eq) return 0;
    eq = memcmp(a->vertices, b->vertices, a->vertex_count * sizeof *a->vertices) == 0 &&
         memcmp(a->indices, b->indices, a->index_count * sizeof *a->indices) == 0 &&
         memcmp(a->objects, b->objects, a->object_count * sizeof *a->objects) == 0 &&
         memcmp(a->materials, b->materials, a->material_count * sizeof *a->materials) == 0 &&
         memcmp(a->lights, b->lights, a->light_count * sizeof *a->lights) == 0 &&
         memcmp(&a->camera, &b->camera, sizeof a->camera) == 0 && memcmp(a->bounds_min, b->bounds_min, 12) == 0 &&
         memcmp(a->bounds_max, b->bounds_max, 12) == 0;
    for (size_t i = 0; eq && i < a->texture_count; i++) {
        const tl_texture *x = &a->textures[i], *y = &b->textures[i];
        eq = x->width == y->width && x->height == y->height &&
             memcmp(x->rgba, y->rgba, (size_t)x->width * x->height * 4) == 0;
    }
    return eq;
}

static void gltf_glb_and_data_uri_equal_gltf(void)
{
    loaded a, b, c;
    load(&a, "gltf_glb_and_data_uri_equal_gltf", "textured_boxes");
    load(&b, "gltf_glb_and_data_uri_equal_gltf", "textured_boxes_glb");
    load(&c, "gltf_glb_and_data_uri_equal_gltf", "textured_boxes_data_uri");
    TL_CHECK(a.result == TL_OK && b.result == TL_OK && c.result == TL_OK);
    if (a.result == TL_OK && b.result == TL_OK && c.result == TL_OK) {
        TL_CHECK(scenes_equal(a.scene, b.scene));
        TL_CHECK(scenes_equal(a.scene, c.scene));
    }
    unload(&a);
    unload(&b);
    unload(&c);
}

static void gltf_generated_normals_tangents(void)
{
    for (int mode = 0; mode < 2; mode++) {
        tl_gltf_options o = {.normals = mode ? TL_GLTF_NORMALS_SMOOTH : TL_GLTF_NORMALS_DEFAULT};
        loaded l;
        load_opts(&l, "gltf_generated_normals_tangents", "generated_frames", &o);
        TL_CHECK(l.result == TL_OK);
        if (l.result != TL_OK) continue;
        const tl_scene *s = l.scene;
        check_geometry(s);
        TL_CHECK_EQ_U(s->index_count, 36);
        /* flat (the default): a vertex per corner, face normals on the axes; smooth: the 8
         * shared corners, normals pointing outwards */
        TL_CHECK_EQ_U(s->vertex_count, mode ? 8 : 36);
        for (size_t i = 0; i < s->vertex_count; i++) {
            const tl_vertex *v = &s->vertices[i];
            if (mode) {
                TL_CHECK(dot3f(v->normal, v->position) > 0.0f);
                for (int k = 0; k < 3; k++) TL_CHECK(v->normal[k] * v->position[k] > 0.0f);
            } else {
                float ax = fabsf(v->normal[0]) + fabsf(v->normal[1]) + fabsf(v->normal[2]);
                TL_CHECK(near(ax, 1.0f, 1e-6f));
                TL_CHECK(near(dot3f(v->normal, v->position), 0.5f, 1e-6f)); /* on its face, outward */
            }
        }
        check_tangents(s, 0, s->vertex_count);
        unload(&l);
    }
}

static void gltf_default_light_rig(void)
{
    loaded l;
    load(&l, "gltf_default_light_rig", "textured_boxes");
    TL_CHECK(l.result == TL_OK);
    if (l.result == TL_OK) {
        const tl_scene *s = l.scene;
        TL_CHECK_EQ_U(s->light_count, 5);
        if (s->light_count == 5) {
            TL_CHECK(s->lights[0].type == TL_LIGHT_DIRECTIONAL);
            for (int i = 1; i < 5; i++) {
                const tl_light *p = &s->lights[i];
                TL_CHECK(p->type == TL_LIGHT_POINT);
                /* around the bounds, above their centre, reaching past it */
                TL_CHECK(p->position[1] > 0.5f * (s->bounds_min[1] + s->bounds_max[1]));
                float c[3] = {0.5f * (s->bounds_min[0] + s->bounds_max[0]) - p->position[0],
                              0.5f * (s->bounds_min[1] + s->bounds_max[1]) - p->position[1],
                              0.5f * (s->bounds_min[2] + s->bounds_max[2]) - p->position[2]};
                TL_CHECK(len3(c) < p->radius);
            }
        }
        check_geometry(s);
    }
    unload(&l);
    tl_gltf_options o = {.no_default_lights = 1};
    load_opts(&l, "gltf_default_light_rig", "textured_boxes", &o);
    TL_CHECK(l.result == TL_OK && l.scene && l.scene->light_count == 0);
    unload(&l);
}

static void gltf_extra_lights_deterministic(void)
{
    tl_gltf_options o = {.extra_lights = 100, .seed = 7};
    loaded a, b, c, d;
    load_opts(&a, "gltf_extra_lights_deterministic", "textured_boxes", &o);
    load_opts(&b, "gltf_extra_lights_deterministic", "textured_boxes", &o);
    o.seed = 8;
    load_opts(&c, "gltf_extra_lights_deterministic", "textured_boxes", &o);
    o.seed = 7;
    o.no_default_lights = 1;
    load_opts(&d, "gltf_extra_lights_deterministic", "textured_boxes", &o);
    TL_CHECK(a.result == TL_OK && b.result == TL_OK && c.result == TL_OK && d.result == TL_OK);
    if (a.result == TL_OK && b.result == TL_OK && c.result == TL_OK && d.result == TL_OK) {
        TL_CHECK_EQ_U(a.scene->light_count, 105); /* the default rig, then the extra lights */
        TL_CHECK_EQ_U(d.scene->light_count, 100);
        TL_CHECK(a.scene->light_count == b.scene->light_count &&
                 memcmp(a.scene->lights, b.scene->lights, a.scene->light_count * sizeof(tl_light)) == 0);
        TL_CHECK(memcmp(a.scene->lights + 5, c.scene->lights + 5, 100 * sizeof(tl_light)) != 0);
        TL_CHECK(memcmp(a.scene->lights + 5, d.scene->lights, 100 * sizeof(tl_light)) == 0);
        const tl_scene *s = a.scene;
        float diag = 0.0f;
        for (int k = 0; k < 3; k++) diag += (s->bounds_max[k] - s->bounds_min[k]) * (s->bounds_max[k] - s->bounds_min[k]);
        diag = sqrtf(diag);
        for (size_t i = 5; i < s->light_count; i++) {
            const tl_light *p = &s->lights[i];
            TL_CHECK(p->type == TL_LIGHT_POINT);
            TL_CHECK(near(p->radius, 0.25f * diag, 1e-4f));
            for (int k = 0; k < 3; k++)
                TL_CHECK(p->position[k] >= s->bounds_min[k] - 0.05f * diag && p->position[k] <= s->bounds_max[k] + 0.05f * diag);
        }
        check_geometry(s);
    }
    unload(&a);
    unload(&b);
    unload(&c);
    unload(&d);
}

static void gltf_camera_from_file(void)
{
    loaded l;
    load(&l, "gltf_camera_from_file", "camera_zfar");
    TL_CHECK(l.result == TL_OK);
    if (l.result == TL_OK) {
        const tl_camera *c = &l.scene->camera;
        TL_CHECK(near3(c->position, 0, 3, 0, 1e-6f));
        float f[3] = {c->target[0] - c->position[0], c->target[1] - c->position[1], c->target[2] - c->position[2]};
        TL_CHECK(len3(f) > 0.0f);
        float n = len3(f);
        TL_CHECK(near3(f, 0, -n, 0, 1e-5f)); /* -Z rotated -90 degrees about X: down */
        TL_CHECK(near3(c->up, 0, 0, -1, 1e-6f));
        TL_CHECK(near(c->fov_y, 1.0f, 1e-6f) && near(c->near_z, 0.5f, 1e-6f) && near(c->far_z, 50.0f, 1e-5f));
    }
    unload(&l);
    /* orthographic: not expressible, so a warning and the framing camera */
    load(&l, "gltf_camera_from_file", "orthographic_camera");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "orthographic") != NULL);
    if (l.result == TL_OK) TL_CHECK(near3(l.scene->camera.target, 0, 0, 0, 1e-6f));
    unload(&l);
}

static void gltf_multiple_scenes(void)
{
    tl_gltf_options o = {0};
    float want_x[3] = {4, -1, 4}; /* default ("scene": 1), scene number 1, scene number 2 */
    for (uint32_t n = 0; n < 3; n++) {
        o.scene_number = n;
        loaded l;
        load_opts(&l, "gltf_multiple_scenes", "multi_scene", &o);
        TL_CHECK(l.result == TL_OK);
        if (l.result == TL_OK) {
            TL_CHECK_EQ_U(l.scene->object_count, 1);
            TL_CHECK(near(l.scene->bounds_min[0], want_x[n], 1e-6f));
        }
        unload(&l);
    }
    o.scene_number = 3;
    loaded l;
    load_opts(&l, "gltf_multiple_scenes", "multi_scene", &o);
    TL_CHECK(l.result == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strstr(l.error, "scene number 3") != NULL);
    unload(&l);
}

static void gltf_mirrored_instance_winding(void)
{
    /* glTF: a negative determinant flips the winding. The mirrored instance draws a reversed
     * copy of the indices, so its world-space triangles still face their normals (+Y). */
    loaded l;
    load(&l, "gltf_mirrored_instance_winding", "mirrored");
    TL_CHECK(l.result == TL_OK);
    if (l.result != TL_OK || l.scene->object_count != 2) return;
    const tl_scene *s = l.scene;
    TL_CHECK(s->objects[0].first_index != s->objects[1].first_index);
    TL_CHECK_EQ_U(s->index_count, 12);
    for (int i = 0; i < 2; i++) {
        const tl_object *o = &s->objects[i];
        TL_CHECK_EQ_U(o->index_count, 6);
        for (uint32_t t = 0; t < o->index_count; t += 3) {
            float p[3][3];
            for (int k = 0; k < 3; k++) xform(o->transform, s->vertices[s->indices[o->first_index + t + (uint32_t)k]].position, p[k]);
            float e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
            float e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
            float ny = e1[2] * e2[0] - e1[0] * e2[2]; /* y of e1 x e2 */
            TL_CHECK(ny > 0.0f);
        }
    }
    TL_CHECK(near(s->objects[1].bounds_min[0], 4.0f, 1e-6f) && near(s->objects[1].bounds_max[0], 6.0f, 1e-6f));
    unload(&l);
}

static void gltf_test_scenes_written(void)
{
    char dir[1024];
    case_dir(dir, sizeof dir, "gltf_test_scenes_written");
    TL_CHECK(tl_test_write_gltf_scenes(dir) == 0);
    const char *files[3] = {"textured_boxes.gltf", "materials.glb", "lights.gltf"};
    for (int i = 0; i < 3; i++) {
        char path[1024];
        tlf_join(path, sizeof path, dir, files[i]);
        capture log = {0};
        tl_gltf_options o = {.logger = {capture_fn, &log}};
        tl_scene *s = NULL;
        TL_CHECK(tl_scene_load_gltf(path, &o, &s) == TL_OK);
        TL_CHECK(log.errors == 0 && log.warnings == 0);
        if (s) check_geometry(s);
        tl_scene_destroy(s);
    }
}

/* ---- the allocator ------------------------------------------------------------------------- */

static void gltf_allocator_counting(void)
{
    const char *cases[3] = {"textured_boxes", "materials", "lights"};
    for (int c = 0; c < 3; c++) {
        loaded l;
        load(&l, "gltf_allocator_counting", cases[c]);
        TL_CHECK(l.result == TL_OK);
        size_t total = l.count.calls;
        TL_CHECK(total > 0);
        unload(&l);
        /* Fail the k-th allocation for every k: out of memory, nothing leaked. */
        for (size_t k = 1; k <= total; k++) {
            counter cnt = {.fail_at = k};
            capture log = {0};
            tl_gltf_options o = {.allocator = {count_alloc, count_free, &cnt}, .logger = {capture_fn, &log}};
            tl_scene *s = (tl_scene *)&cnt; /* must be reset to NULL */
            tl_result r = tl_scene_load_gltf(l.path, &o, &s);
            if (r != TL_ERROR_OUT_OF_MEMORY)
                fprintf(stderr, "%s: k = %zu: %s (%s)\n", cases[c], k, tl_result_string(r), log.last_error);
            TL_CHECK(r == TL_ERROR_OUT_OF_MEMORY);
            TL_CHECK(s == NULL);
            TL_CHECK(cnt.live == 0);
            tl_scene_destroy(s);
        }
    }
}

/* ---- bad input ----------------------------------------------------------------------------- */

static void gltf_malformed_json(void) { expect_failure("gltf_malformed_json", "malformed_json", TL_ERROR_PARSE, NULL); }
static void gltf_wrong_types(void) { expect_failure("gltf_wrong_types", "wrong_types", TL_ERROR_PARSE, "count"); }
static void gltf_missing_bin(void) { expect_failure("gltf_missing_bin", "missing_bin", TL_ERROR_IO, "missing_bin.bin"); }
static void gltf_missing_file(void)
{
    capture log = {0};
    tl_scene *s = NULL;
    tl_gltf_options o = {.logger = {capture_fn, &log}};
    TL_CHECK(tl_scene_load_gltf(TL_GLTF_TEST_DIR "/no/such/file.gltf", &o, &s) == TL_ERROR_IO);
    TL_CHECK(s == NULL && strstr(log.last_error, "file.gltf") != NULL);
}

static void gltf_missing_image(void)
{
    loaded l;
    load(&l, "gltf_missing_image", "missing_image");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "images[0]") != NULL);
    if (l.result == TL_OK) {
        TL_CHECK_EQ_U(l.scene->texture_count, 0);
        TL_CHECK(l.scene->materials[0].albedo_texture == TL_NO_TEXTURE);
        TL_CHECK(near3(l.scene->materials[0].albedo, 0.25f, 0.5f, 0.75f, 1e-6f)); /* the flat colour */
    }
    unload(&l);
}

static void gltf_bufferview_out_of_range(void)
{
    expect_failure("gltf_bufferview_out_of_range", "bufferview_out_of_range", TL_ERROR_PARSE, "accessors[0]: bufferView 99");
}
static void gltf_accessor_past_buffer_view(void)
{
    expect_failure("gltf_accessor_past_buffer_view", "accessor_past_view", TL_ERROR_PARSE, "accessors[0]");
}
static void gltf_buffer_view_past_buffer(void)
{
    expect_failure("gltf_buffer_view_past_buffer", "view_past_buffer", TL_ERROR_PARSE, "bufferViews[1]");
}
static void gltf_accessor_reference_out_of_range(void)
{
    expect_failure("gltf_accessor_reference_out_of_range", "accessor_ref_out_of_range", TL_ERROR_PARSE, "accessor 42");
}
static void gltf_mesh_reference_out_of_range(void)
{
    expect_failure("gltf_mesh_reference_out_of_range", "mesh_ref_out_of_range", TL_ERROR_PARSE, "nodes[0]: mesh 7");
}
static void gltf_vertex_index_out_of_range(void)
{
    expect_failure("gltf_vertex_index_out_of_range", "index_out_of_range", TL_ERROR_PARSE, "accessors[1]: index 99");
}
static void gltf_node_cycle(void) { expect_failure("gltf_node_cycle", "node_cycle", TL_ERROR_PARSE, "cycle"); }
static void gltf_node_self_child(void) { expect_failure("gltf_node_self_child", "node_self_child", TL_ERROR_PARSE, "cycle"); }
static void gltf_node_two_parents(void)
{
    expect_failure("gltf_node_two_parents", "node_two_parents", TL_ERROR_PARSE, "nodes[2]: has two parents");
}
static void gltf_node_child_out_of_range(void)
{
    expect_failure("gltf_node_child_out_of_range", "node_child_out_of_range", TL_ERROR_PARSE, "nodes[0]: child 5");
}
static void gltf_nan_position(void)
{
    expect_failure("gltf_nan_position", "nan_position", TL_ERROR_PARSE, "accessors[0]: POSITION element 1 is not finite");
}
static void gltf_inf_position(void)
{
    expect_failure("gltf_inf_position", "inf_position", TL_ERROR_PARSE, "accessors[0]: POSITION element 1 is not finite");
}

static void gltf_zero_length_normals(void)
{
    loaded l;
    load(&l, "gltf_zero_length_normals", "zero_normals");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "3 zero-length or non-finite normals regenerated") != NULL);
    if (l.result == TL_OK)
        for (size_t i = 0; i < l.scene->vertex_count; i++) TL_CHECK(near3(l.scene->vertices[i].normal, 0, 1, 0, 1e-6f));
    unload(&l);
}

static void gltf_texture_unsupported_format(void)
{
    loaded l;
    load(&l, "gltf_texture_unsupported_format", "texture_unsupported");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "images[0]") != NULL);
    if (l.result == TL_OK) {
        TL_CHECK_EQ_U(l.scene->texture_count, 0);
        TL_CHECK(l.scene->materials[0].albedo_texture == TL_NO_TEXTURE);
    }
    unload(&l);
}

static void gltf_texture_jpeg(void)
{
    loaded l;
    load(&l, "gltf_texture_jpeg", "texture_jpeg");
    TL_CHECK(l.result == TL_OK && l.log.warnings == 0);
    if (l.result == TL_OK && l.scene->texture_count == 1) {
        const tl_texture *t = &l.scene->textures[0];
        TL_CHECK(t->width == 8 && t->height == 8);
        for (size_t i = 0; i < 64; i++) {
            for (int k = 0; k < 3; k++) TL_CHECK(abs((int)t->rgba[4 * i + (size_t)k] - 128) <= 2); /* lossy */
            TL_CHECK(t->rgba[4 * i + 3] == 255);
        }
    } else {
        TL_CHECK(l.scene && l.scene->texture_count == 1);
    }
    unload(&l);
}

static void gltf_texture_truncated_png(void)
{
    loaded l;
    load(&l, "gltf_texture_truncated_png", "texture_truncated_png");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "images[0]: truncated PNG") != NULL);
    if (l.result == TL_OK) TL_CHECK(l.scene->materials[0].albedo_texture == TL_NO_TEXTURE);
    unload(&l);
}

static void gltf_texture_absurd_size(void)
{
    expect_failure("gltf_texture_absurd_size", "texture_huge", TL_ERROR_LIMIT, "images[0]: 60000x60000");
}

static void gltf_texture_pixel_limit_option(void)
{
    tl_gltf_options o = {.max_texture_pixels = 15};
    loaded l;
    load_opts(&l, "gltf_texture_pixel_limit_option", "texture_4x4", &o);
    TL_CHECK(l.result == TL_ERROR_LIMIT);
    unload(&l);
    o.max_texture_pixels = 16;
    load_opts(&l, "gltf_texture_pixel_limit_option", "texture_4x4", &o);
    TL_CHECK(l.result == TL_OK && l.scene && l.scene->texture_count == 1);
    unload(&l);
}

static void gltf_triangle_limit(void)
{
    tl_gltf_options o = {.max_triangles = 37}; /* textured_boxes draws 12 + 12 + 12 + 2 */
    loaded l;
    load_opts(&l, "gltf_triangle_limit", "textured_boxes", &o);
    TL_CHECK(l.result == TL_ERROR_LIMIT);
    unload(&l);
    o.max_triangles = 38;
    load_opts(&l, "gltf_triangle_limit", "textured_boxes", &o);
    TL_CHECK(l.result == TL_OK);
    unload(&l);
}

static void gltf_accessor_without_buffer_view(void)
{
    /* glTF: an accessor without a buffer view reads as zeros. 300000 such vertices load (their
     * zero normals are regenerated), but not past 3 vertices per triangle of max_triangles. */
    loaded l;
    load(&l, "gltf_accessor_without_buffer_view", "zero_accessors");
    TL_CHECK(l.result == TL_OK);
    if (l.result == TL_OK) {
        TL_CHECK_EQ_U(l.scene->vertex_count, 300000);
        TL_CHECK_EQ_U(l.scene->object_count, 1);
        TL_CHECK(near3(l.scene->vertices[299999].position, 0, 0, 0, 0.0f));
        TL_CHECK(near(len3(l.scene->vertices[123].normal), 1.0f, 1e-6f));
    }
    unload(&l);
    tl_gltf_options o = {.max_triangles = 99999};
    load_opts(&l, "gltf_accessor_without_buffer_view", "zero_accessors", &o);
    TL_CHECK(l.result == TL_ERROR_LIMIT);
    TL_CHECK(strstr(l.error, "300000 vertices") != NULL);
    unload(&l);
}

static void gltf_empty_scene(void)
{
    /* An empty but valid scene (documented): no objects, a warning, the default rig and a
     * camera around the origin. */
    const char *cases[2] = {"empty_scene", "no_scenes"};
    for (int i = 0; i < 2; i++) {
        loaded l;
        load(&l, "gltf_empty_scene", cases[i]);
        TL_CHECK(l.result == TL_OK);
        if (l.result == TL_OK) {
            const tl_scene *s = l.scene;
            TL_CHECK(s->object_count == 0 && s->vertex_count == 0 && s->index_count == 0);
            TL_CHECK(s->objects == NULL && s->vertices == NULL);
            TL_CHECK(strstr(l.log.warnings_text, "no triangles") != NULL);
            TL_CHECK_EQ_U(s->light_count, 5);
            check_geometry(s);
            tl_scene_feature_set f;
            tl_scene_features(s, &f);
            TL_CHECK(f.triangle_count == 0);
        }
        unload(&l);
    }
}

static void gltf_truncated_glb(void)
{
    char path[1024], cut[1024], dir[1024];
    if (fixture("gltf_truncated_glb", "textured_boxes_glb", path, sizeof path)) return;
    case_dir(dir, sizeof dir, "gltf_truncated_glb");
    tlf_join(cut, sizeof cut, dir, "cut.glb");
    size_t n = 0;
    unsigned char *b = tlf_read_file(path, &n);
    TL_CHECK(b != NULL && n > 100);
    if (!b) return;
    for (size_t len = 0; len < n; len += (len < 64 || n - len < 64) ? 1 : 7) {
        if (tlf_write_file(cut, b, len)) break;
        counter cnt = {0};
        tl_gltf_options o = {.allocator = {count_alloc, count_free, &cnt}};
        tl_scene *s = NULL;
        tl_result r = tl_scene_load_gltf(cut, &o, &s);
        TL_CHECK(r == TL_ERROR_PARSE);
        TL_CHECK(s == NULL && cnt.live == 0);
    }
    /* A BIN chunk whose length reaches past the file by its own 8-byte header. */
    uint32_t json_len = (uint32_t)b[12] | (uint32_t)b[13] << 8 | (uint32_t)b[14] << 16 | (uint32_t)b[15] << 24;
    size_t at = 20 + json_len;
    uint32_t bin_len = (uint32_t)b[at] | (uint32_t)b[at + 1] << 8 | (uint32_t)b[at + 2] << 16 | (uint32_t)b[at + 3] << 24;
    bin_len += 8;
    for (int k = 0; k < 4; k++) b[at + (size_t)k] = (unsigned char)(bin_len >> (8 * k));
    tlf_write_file(cut, b, n);
    capture log = {0};
    tl_gltf_options o = {.logger = {capture_fn, &log}};
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(cut, &o, &s) == TL_ERROR_PARSE);
    TL_CHECK(strstr(log.last_error, "BIN chunk") != NULL);
    free(b);
}

static void gltf_required_extension_unsupported(void)
{
    expect_failure("gltf_required_extension_unsupported", "required_extension", TL_ERROR_UNSUPPORTED,
                   "KHR_draco_mesh_compression");
}
static void gltf_sparse_accessor_unsupported(void)
{
    expect_failure("gltf_sparse_accessor_unsupported", "sparse_accessor", TL_ERROR_UNSUPPORTED, "accessors[0]: sparse");
}

static void gltf_non_triangle_mode_skipped(void)
{
    loaded l;
    load(&l, "gltf_non_triangle_mode_skipped", "lines_mode");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "meshes[0].primitives[0]: mode 1") != NULL);
    if (l.result == TL_OK) TL_CHECK_EQ_U(l.scene->object_count, 1);
    unload(&l);
}

static void gltf_bad_arguments(void)
{
    char path[1024];
    if (fixture("gltf_bad_arguments", "quad", path, sizeof path)) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(NULL, NULL, &s) == TL_ERROR_INVALID_ARGUMENT && s == NULL);
    TL_CHECK(tl_scene_load_gltf(path, NULL, NULL) == TL_ERROR_INVALID_ARGUMENT);
    counter cnt = {0};
    tl_gltf_options half = {.allocator = {count_alloc, NULL, &cnt}};
    TL_CHECK(tl_scene_load_gltf(path, &half, &s) == TL_ERROR_INVALID_ARGUMENT && s == NULL);
    tl_gltf_options bad_mode = {.normals = TL_GLTF_NORMALS_COUNT_};
    TL_CHECK(tl_scene_load_gltf(path, &bad_mode, &s) == TL_ERROR_INVALID_ARGUMENT && s == NULL);
    tl_gltf_options many = {.extra_lights = 65537};
    TL_CHECK(tl_scene_load_gltf(path, &many, &s) == TL_ERROR_LIMIT && s == NULL);
    many.extra_lights = 65536;
    TL_CHECK(tl_scene_load_gltf(path, &many, &s) == TL_OK && s && s->light_count == 65536 + 5);
    tl_scene_destroy(s);
    s = NULL;
    TL_CHECK(tl_scene_load_gltf(path, NULL, &s) == TL_OK && s != NULL); /* NULL options: defaults */
    tl_scene_destroy(s);
}

static void gltf_error_message_one_line(void)
{
    /* The one error line goes to the logger: it starts with the file and names the element;
     * without a logger the load is silent; success logs no error. */
    char path[1024];
    if (fixture("gltf_error_message_one_line", "node_cycle", path, sizeof path)) return;
    capture log = {0};
    tl_gltf_options o = {.logger = {capture_fn, &log}};
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(path, &o, &s) == TL_ERROR_PARSE);
    TL_CHECK(log.errors == 1 && log.multiline == 0);
    TL_CHECK(strncmp(log.last_error, path, strlen(path)) == 0 && strstr(log.last_error, ": nodes[") != NULL);
    TL_CHECK(tl_scene_load_gltf(path, NULL, &s) == TL_ERROR_PARSE && s == NULL);
    if (fixture("gltf_error_message_one_line", "quad", path, sizeof path)) return;
    memset(&log, 0, sizeof log);
    TL_CHECK(tl_scene_load_gltf(path, &o, &s) == TL_OK && log.errors == 0);
    tl_scene_destroy(s);
}

/* ---- fuzzing ------------------------------------------------------------------------------- */

static void fuzz_file(const char *test, const char *fixture_name, const char *mutated_name, unsigned long long seed,
                      int rounds)
{
    char path[1024], dir[1024], mutated[1024];
    if (fixture(test, fixture_name, path, sizeof path)) return;
    case_dir(dir, sizeof dir, test);
    tlf_join(mutated, sizeof mutated, dir, mutated_name); /* beside the original: same .bin, PNGs */
    size_t n = 0;
    unsigned char *orig = tlf_read_file(path, &n);
    TL_CHECK(orig != NULL);
    if (!orig) return;
    unsigned char *b = malloc(n);
    tl_rng rng = {seed};
    int ok = 0;
    for (int r = 0; r < rounds && b; r++) {
        memcpy(b, orig, n);
        int edits = 1 + (int)(tl_rng_u64(&rng) % 8);
        for (int e = 0; e < edits; e++) {
            size_t at = (size_t)(tl_rng_u64(&rng) % n);
            switch (tl_rng_u64(&rng) % 4) {
            case 0: b[at] = (unsigned char)tl_rng_u64(&rng); break;            /* random byte */
            case 1: b[at] ^= (unsigned char)(1u << (tl_rng_u64(&rng) % 8)); break; /* bit flip */
            case 2: b[at] = (unsigned char)("0123456789-.e[]{},\":"[tl_rng_u64(&rng) % 20]); break; /* JSON-ish */
            default: b[at] = 0xFF; break;
            }
        }
        size_t len = tl_rng_u64(&rng) % 8 == 0 ? (size_t)(tl_rng_u64(&rng) % n) : n; /* sometimes truncated */
        if (tlf_write_file(mutated, b, len)) break;
        counter cnt = {0};
        tl_gltf_options o = {.allocator = {count_alloc, count_free, &cnt}};
        tl_scene *s = NULL;
        tl_result res = tl_scene_load_gltf(mutated, &o, &s);
        TL_CHECK(res < TL_RESULT_COUNT_);
        TL_CHECK((res == TL_OK) == (s != NULL));
        if (s) {
            ok++;
            check_geometry(s);
        }
        tl_scene_destroy(s);
        TL_CHECK(cnt.live == 0);
    }
    printf("%s: %d of %d mutated files loaded\n", fixture_name, ok, rounds);
    free(b);
    free(orig);
}

/* Mutates the external .bin of textured_boxes in place (positions, normals, UVs, indices). */
static void fuzz_bin(const char *test, unsigned long long seed, int rounds)
{
    char path[1024], dir[1024], bin[1024];
    if (fixture(test, "textured_boxes", path, sizeof path)) return;
    case_dir(dir, sizeof dir, test);
    tlf_join(bin, sizeof bin, dir, "textured_boxes.bin");
    size_t n = 0;
    unsigned char *orig = tlf_read_file(bin, &n);
    TL_CHECK(orig != NULL);
    if (!orig) return;
    unsigned char *b = malloc(n);
    tl_rng rng = {seed};
    int ok = 0;
    for (int r = 0; r < rounds && b; r++) {
        memcpy(b, orig, n);
        int edits = 1 + (int)(tl_rng_u64(&rng) % 4);
        for (int e = 0; e < edits; e++) {
            size_t at = (size_t)(tl_rng_u64(&rng) % n);
            b[at] = tl_rng_u64(&rng) % 2 ? (unsigned char)tl_rng_u64(&rng) : 0xFF; /* 0xFF makes NaNs and big indices */
        }
        if (tlf_write_file(bin, b, n)) break;
        counter cnt = {0};
        tl_gltf_options o = {.allocator = {count_alloc, count_free, &cnt}};
        tl_scene *s = NULL;
        tl_result res = tl_scene_load_gltf(path, &o, &s);
        TL_CHECK(res == TL_OK || res == TL_ERROR_PARSE);
        TL_CHECK((res == TL_OK) == (s != NULL));
        if (s) {
            ok++;
            check_geometry(s);
            check_tangents(s, 0, 24);
        }
        tl_scene_destroy(s);
        TL_CHECK(cnt.live == 0);
    }
    tlf_write_file(bin, orig, n);
    printf("textured_boxes.bin: %d of %d mutated buffers loaded\n", ok, rounds);
    free(b);
    free(orig);
}

static void gltf_fuzz_mutations(void)
{
    fuzz_file("gltf_fuzz_mutations", "textured_boxes_glb", "mutated.glb", 1, 600);
    fuzz_file("gltf_fuzz_mutations", "textured_boxes", "mutated.gltf", 2, 600);
    fuzz_file("gltf_fuzz_mutations", "lights", "mutated_lights.gltf", 3, 300);
    fuzz_bin("gltf_fuzz_mutations", 4, 400);
}

static const tl_test_case cases[] = {
    {"gltf_textured_boxes_hierarchy", gltf_textured_boxes_hierarchy},
    {"gltf_textured_boxes_materials_textures", gltf_textured_boxes_materials_textures},
    {"gltf_materials_conversion", gltf_materials_conversion},
    {"gltf_lights_punctual", gltf_lights_punctual},
    {"gltf_index_sizes", gltf_index_sizes},
    {"gltf_normalized_uvs", gltf_normalized_uvs},
    {"gltf_glb_and_data_uri_equal_gltf", gltf_glb_and_data_uri_equal_gltf},
    {"gltf_generated_normals_tangents", gltf_generated_normals_tangents},
    {"gltf_default_light_rig", gltf_default_light_rig},
    {"gltf_extra_lights_deterministic", gltf_extra_lights_deterministic},
    {"gltf_camera_from_file", gltf_camera_from_file},
    {"gltf_multiple_scenes", gltf_multiple_scenes},
    {"gltf_mirrored_instance_winding", gltf_mirrored_instance_winding},
    {"gltf_test_scenes_written", gltf_test_scenes_written},
    {"gltf_allocator_counting", gltf_allocator_counting},
    {"gltf_malformed_json", gltf_malformed_json},
    {"gltf_wrong_types", gltf_wrong_types},
    {"gltf_missing_bin", gltf_missing_bin},
    {"gltf_missing_file", gltf_missing_file},
    {"gltf_missing_image", gltf_missing_image},
    {"gltf_bufferview_out_of_range", gltf_bufferview_out_of_range},
    {"gltf_accessor_past_buffer_view", gltf_accessor_past_buffer_view},
    {"gltf_buffer_view_past_buffer", gltf_buffer_view_past_buffer},
    {"gltf_accessor_reference_out_of_range", gltf_accessor_reference_out_of_range},
    {"gltf_mesh_reference_out_of_range", gltf_mesh_reference_out_of_range},
    {"gltf_vertex_index_out_of_range", gltf_vertex_index_out_of_range},
    {"gltf_node_cycle", gltf_node_cycle},
    {"gltf_node_self_child", gltf_node_self_child},
    {"gltf_node_two_parents", gltf_node_two_parents},
    {"gltf_node_child_out_of_range", gltf_node_child_out_of_range},
    {"gltf_nan_position", gltf_nan_position},
    {"gltf_inf_position", gltf_inf_position},
    {"gltf_zero_length_normals", gltf_zero_length_normals},
    {"gltf_texture_unsupported_format", gltf_texture_unsupported_format},
    {"gltf_texture_jpeg", gltf_texture_jpeg},
    {"gltf_texture_truncated_png", gltf_texture_truncated_png},
    {"gltf_texture_absurd_size", gltf_texture_absurd_size},
    {"gltf_texture_pixel_limit_option", gltf_texture_pixel_limit_option},
    {"gltf_triangle_limit", gltf_triangle_limit},
    {"gltf_accessor_without_buffer_view", gltf_accessor_without_buffer_view},
    {"gltf_empty_scene", gltf_empty_scene},
    {"gltf_truncated_glb", gltf_truncated_glb},
    {"gltf_required_extension_unsupported", gltf_required_extension_unsupported},
    {"gltf_sparse_accessor_unsupported", gltf_sparse_accessor_unsupported},
    {"gltf_non_triangle_mode_skipped", gltf_non_triangle_mode_skipped},
    {"gltf_bad_arguments", gltf_bad_arguments},
    {"gltf_error_message_one_line", gltf_error_message_one_line},
    {"gltf_fuzz_mutations", gltf_fuzz_mutations},
};

TL_TEST_MAIN(cases)
