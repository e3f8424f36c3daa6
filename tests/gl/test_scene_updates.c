/* Scene updates between frames (tl_renderer_set_object_transform, set_object_visible, set_object,
 * add_object, remove_object, add_geometry, set_material): each update renders the same bytes as a
 * renderer given the updated scene whole with tl_renderer_set_scene, in every mode; updates of
 * transforms, visibility and records upload nothing, appended geometry uploads its own bytes and
 * nothing more; refused updates change nothing; and, printed rather than timed, what an update
 * costs the CPU. */
#define _POSIX_C_SOURCE 199309L
#include "tl_test.h"

#include <math.h>
#include <time.h>

#include "gl/gl.h"
#include "gl_counter.h"
#include "render_fixture.h"
#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

/* ---- what an update uploads: the GL call counter (gl_counter.h) ------------------------------- */

#define UPLOADS tl_test_gl_uploads()           /* GL calls that send buffer data */
#define UPLOAD_BYTES tl_test_gl_upload_bytes() /* bytes those calls sent from the CPU */
#define TEXTURES tl_test_gl_calls("glTextureSubImage2D")
#define LINKS tl_test_gl_calls("glLinkProgram")

/* ---- scenes and renderers ------------------------------------------------------------------------ */

enum { W = 160, H = 90 };
#define PIXELS ((size_t)W * H * 4)

static tl_scene *crypt(void)
{
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 24, .detail = 1}, &s) == TL_OK);
    return s;
}

/* Every renderer here counts GL calls. */
static tl_renderer *renderer(const tl_renderer_options *o, const tl_scene *s)
{
    return tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = W, .height = H, .options = *o, .get_proc_address = tl_test_gl_counting_loader}, .scene = s});
}

static int frame(tl_renderer *r, uint8_t *out)
{
    size_t size = PIXELS;
    return tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_read_output(r, out, &size) == TL_OK;
}

/* The scene `s` with its own copies of the objects (room for `extra` more), materials, vertices
 * and indices (room for `extra_vertices` and `extra_indices`): what a caller would give set_scene. */
typedef struct scene_copy {
    tl_scene s;
    tl_object *objects;
    tl_material *materials;
    tl_vertex *vertices;
    uint32_t *indices;
} scene_copy;

static void copy_scene(const tl_scene *s, size_t extra, size_t extra_vertices, size_t extra_indices, scene_copy *c)
{
    c->s = *s;
    c->objects = calloc(s->object_count + extra, sizeof *c->objects);
    c->materials = calloc(s->material_count, sizeof *c->materials);
    c->vertices = calloc(s->vertex_count + extra_vertices, sizeof *c->vertices);
    c->indices = calloc(s->index_count + extra_indices, sizeof *c->indices);
    memcpy(c->objects, s->objects, s->object_count * sizeof *c->objects);
    memcpy(c->materials, s->materials, s->material_count * sizeof *c->materials);
    memcpy(c->vertices, s->vertices, s->vertex_count * sizeof *c->vertices);
    memcpy(c->indices, s->indices, s->index_count * sizeof *c->indices);
    c->s.objects = c->objects;
    c->s.materials = c->materials;
    c->s.vertices = c->vertices;
    c->s.indices = c->indices;
}

static void free_copy(scene_copy *c)
{
    free(c->objects);
    free(c->materials);
    free(c->vertices);
    free(c->indices);
}

/* Bytes of the next frames of `r` and of a renderer given `whole` with the same options. */
static size_t differ(tl_renderer *r, const tl_renderer_options *o, const tl_scene *whole, const char *what)
{
    uint8_t *a = malloc(PIXELS), *b = malloc(PIXELS);
    tl_renderer *fresh = renderer(o, whole);
    size_t diff = SIZE_MAX;
    if (a && b && fresh && frame(r, a) && frame(fresh, b)) {
        diff = 0;
        for (size_t i = 0; i < PIXELS; i++) diff += a[i] != b[i];
        if (diff) fprintf(stderr, "%s, %s: %zu bytes differ from set_scene with the updated scene\n", what,
                          tl_render_mode_name(o->mode), diff);
    }
    tl_renderer_destroy(fresh);
    free(a);
    free(b);
    return diff;
}

/* The options the update tests run under: every mode, both light strategies, both depth formats. */
static const tl_renderer_options k_options[] = {
    {0},
    {.mode = TL_MODE_THIN_DEFERRED, .light_strategy = TL_LIGHT_STRATEGY_TILED},
    {.mode = TL_MODE_FAT, .depth_format = TL_DEPTH_FORMAT_D32F_REVERSED},
    {.mode = TL_MODE_FORWARD},
    {.mode = TL_MODE_FORWARD, .light_strategy = TL_LIGHT_STRATEGY_TILED, .depth_format = TL_DEPTH_FORMAT_D32F_REVERSED},
    /* visibility: the id names the object's slot and its triangle within the object's range, and the
     * resolve reads the object record's first index and material: each update must keep them */
    {.mode = TL_MODE_VISIBILITY},
};
#define OPTIONS (sizeof k_options / sizeof k_options[0])

static void translate_rotate(float m[16], float angle, float scale, float x, float y, float z, const float c[3])
{
    /* about the point c: translate(c + t) * rotate_y(angle) * scale * translate(-c) */
    float cs = cosf(angle) * scale, sn = sinf(angle) * scale;
    float r[16] = {cs, 0, -sn, 0, 0, scale, 0, 0, sn, 0, cs, 0, 0, 0, 0, 1};
    memcpy(m, r, sizeof r);
    for (int k = 0; k < 3; k++) m[12 + k] = c[k] + (k == 0 ? x : k == 1 ? y : z) -
                                            (r[k] * c[0] + r[4 + k] * c[1] + r[8 + k] * c[2]);
}

/* An object other than `not` whose material some other object with indices draws too (so that
 * leaving it out changes no feature of the scene). */
static size_t shared_material_object(const tl_scene *s, size_t from, size_t not)
{
    for (size_t i = from; i < s->object_count; i++) {
        if (i == not || !s->objects[i].index_count) continue;
        for (size_t j = 0; j < s->object_count; j++)
            if (j != i && j != not && s->objects[j].index_count && s->objects[j].material == s->objects[i].material)
                return i;
    }
    return SIZE_MAX;
}

static void centre(const tl_object *o, float c[3])
{
    for (int k = 0; k < 3; k++) c[k] = 0.5f * (o->bounds_min[k] + o->bounds_max[k]);
}

/* ---- moving and hiding ---------------------------------------------------------------------------- */

TL_TEST(updates_move_and_hide_same_bytes_as_set_scene)
{
    if (!ensure_context()) return;
    tl_scene *s = crypt();
    if (!s) return;
    size_t moved[3] = {3, s->object_count / 2, s->object_count - 1};
    /* the hidden object: one whose material another object draws, and which the frame shows */
    size_t hidden = SIZE_MAX;
    tl_renderer *probe = renderer(&k_options[0], s);
    uint8_t *base = malloc(PIXELS), *without = malloc(PIXELS);
    if (probe && base && without && frame(probe, base)) {
        for (size_t i = shared_material_object(s, s->object_count / 3, SIZE_MAX); i != SIZE_MAX && hidden == SIZE_MAX;
             i = shared_material_object(s, i + 1, SIZE_MAX)) {
            size_t diff = 0;
            TL_CHECK(tl_renderer_set_object_visible(probe, (uint32_t)i, 0) == TL_OK);
            if (frame(probe, without))
                for (size_t p = 0; p < PIXELS; p++) diff += base[p] != without[p];
            TL_CHECK(tl_renderer_set_object_visible(probe, (uint32_t)i, 1) == TL_OK);
            if (diff >= 400) hidden = i; /* at least 100 pixels of it */
        }
    }
    tl_renderer_destroy(probe);
    free(base);
    free(without);
    TL_CHECK(hidden != SIZE_MAX);
    for (size_t k = 0; k < OPTIONS && hidden != SIZE_MAX; k++) {
        const tl_renderer_options *o = &k_options[k];
        tl_renderer *r = renderer(o, s);
        if (!r) continue;
        scene_copy c;
        copy_scene(s, 0, 0, 0, &c);
        for (int i = 0; i < 3; i++) {
            float m[16], ctr[3];
            centre(&s->objects[moved[i]], ctr);
            translate_rotate(m, 0.5f * (float)(i + 1), i == 2 ? 1.5f : 1.0f, 0.4f, 0.1f * (float)i, -0.3f, ctr);
            TL_CHECK(tl_renderer_set_object_transform(r, (uint32_t)moved[i], m) == TL_OK);
            tl_object drawn;
            int visible = 0;
            TL_CHECK(tl_renderer_get_object(r, (uint32_t)moved[i], &drawn, &visible) == TL_OK);
            TL_CHECK(visible == 1);
            TL_CHECK(memcmp(drawn.transform, m, sizeof m) == 0);
            /* the bounds follow: they hold the moved triangles' exact box, and are not much larger */
            tl_object exact = s->objects[moved[i]];
            memcpy(exact.transform, m, sizeof m);
            float lo[3], hi[3];
            TL_CHECK(tl_object_compute_bounds(s, &exact, lo, hi) == TL_OK);
            for (int a = 0; a < 3; a++) {
                float slack = 1e-5f * (fabsf(lo[a]) + fabsf(hi[a]) + 1.0f);
                TL_CHECK(drawn.bounds_min[a] <= lo[a] + slack && drawn.bounds_max[a] >= hi[a] - slack);
                /* a box through a rotation: at most sqrt(2) x the extent on the two rotated axes */
                TL_CHECK_LE(drawn.bounds_max[a] - drawn.bounds_min[a], 1.5f * (hi[a] - lo[a]) + 2.0f * slack + 1e-3f);
            }
            c.objects[moved[i]] = drawn; /* the same bounds: the same culling and the same near plane */
        }
        TL_CHECK(tl_renderer_set_object_visible(r, (uint32_t)hidden, 0) == TL_OK);
        c.objects[hidden].index_count = 0;
        TL_CHECK_EQ_U(differ(r, o, &c.s, "moved and hidden"), 0);
        /* shown again and moved back: the scene as it was */
        TL_CHECK(tl_renderer_set_object_visible(r, (uint32_t)hidden, 1) == TL_OK);
        for (int i = 0; i < 3; i++) {
            TL_CHECK(tl_renderer_set_object(r, (uint32_t)moved[i], &s->objects[moved[i]]) == TL_OK);
        }
        TL_CHECK_EQ_U(differ(r, o, s, "moved back"), 0);
        free_copy(&c);
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(s);
}

/* ---- adding and removing objects, appending geometry --------------------------------------------- */

/* A box of 24 vertices and 36 indices, half-size `h`, centred at `c`. */
static void box_mesh(const float c[3], float h, tl_vertex v[24], uint32_t idx[36])
{
    static const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; f++) {
        int a = f / 2, b = (a + 1) % 3, d = (a + 2) % 3;
        float s = n[f][a];
        float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int i = 0; i < 4; i++) {
            tl_vertex *x = &v[f * 4 + i];
            memset(x, 0, sizeof *x);
            x->position[a] = c[a] + s * h;
            x->position[b] = c[b] + corners[i][0] * h;
            x->position[d] = c[d] + corners[i][1] * h * s; /* counter-clockwise seen from outside */
            memcpy(x->normal, n[f], sizeof x->normal);
            x->uv[0] = corners[i][0] * 0.5f + 0.5f;
            x->uv[1] = corners[i][1] * 0.5f + 0.5f;
        }
        static const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
        for (int i = 0; i < 6; i++) idx[f * 6 + i] = (uint32_t)(f * 4) + q[i];
    }
}

TL_TEST(updates_add_remove_and_geometry_same_bytes_as_set_scene)
{
    if (!ensure_context()) return;
    tl_scene *s = crypt();
    if (!s) return;
    const size_t n = s->object_count;
    size_t removed = shared_material_object(s, n / 4, SIZE_MAX);
    size_t instanced = shared_material_object(s, n / 2, removed);
    TL_CHECK(removed != SIZE_MAX && instanced != SIZE_MAX);
    tl_vertex bv[2][24];
    uint32_t bi[2][36];
    float ctr[3];
    centre(&s->objects[instanced], ctr);
    box_mesh((float[3]){ctr[0] + 0.6f, ctr[1] + 0.4f, ctr[2]}, 0.3f, bv[0], bi[0]);
    box_mesh((float[3]){ctr[0] - 0.6f, ctr[1] + 0.5f, ctr[2]}, 0.2f, bv[1], bi[1]);
    for (size_t k = 0; k < OPTIONS && removed != SIZE_MAX && instanced != SIZE_MAX; k++) {
        const tl_renderer_options *o = &k_options[k];
        tl_renderer *r = renderer(o, s);
        if (!r) continue;
        scene_copy c;
        copy_scene(s, 3, 48, 72, &c);
        /* an instance of an object's triangles, moved: the next id */
        tl_object inst = s->objects[instanced];
        memset(inst.bounds_min, 0, sizeof inst.bounds_min);
        memset(inst.bounds_max, 0, sizeof inst.bounds_max);
        translate_rotate(inst.transform, 0.3f, 1.0f, 0.0f, 0.0f, 0.8f, ctr);
        uint32_t id = UINT32_MAX;
        TL_CHECK(tl_renderer_add_object(r, &inst, &id) == TL_OK);
        TL_CHECK_EQ_U(id, n);
        TL_CHECK(tl_renderer_get_object(r, id, &c.objects[n], NULL) == TL_OK);
        /* an object removed: its id comes back with the next add */
        TL_CHECK(tl_renderer_remove_object(r, (uint32_t)removed) == TL_OK);
        c.objects[removed].index_count = 0;
        /* two meshes appended (the second within the grown buffers), each drawn by a new object with
         * zero bounds (computed from the buffers) */
        uint32_t first[2] = {0, 0};
        for (int g = 0; g < 2; g++) {
            TL_CHECK(tl_renderer_add_geometry(r, bv[g], 24, bi[g], 36, &first[g]) == TL_OK);
            TL_CHECK_EQ_U(first[g], s->index_count + 36u * (unsigned)g);
            memcpy(c.vertices + s->vertex_count + 24 * g, bv[g], sizeof bv[g]);
            for (int i = 0; i < 36; i++) c.indices[s->index_count + 36 * g + i] = bi[g][i] + (uint32_t)(s->vertex_count + 24 * g);
            tl_object mesh = {.first_index = first[g], .index_count = 36, .material = s->objects[instanced].material};
            uint32_t mid = UINT32_MAX;
            TL_CHECK(tl_renderer_add_object(r, &mesh, &mid) == TL_OK);
            TL_CHECK_EQ_U(mid, g == 0 ? removed : n + 1); /* the removed id first, then a new one */
            tl_object *into = g == 0 ? &c.objects[removed] : &c.objects[n + 1];
            TL_CHECK(tl_renderer_get_object(r, mid, into, NULL) == TL_OK);
            float lo[3], hi[3];
            c.s.vertex_count = s->vertex_count + 24 * (size_t)(g + 1);
            c.s.index_count = s->index_count + 36 * (size_t)(g + 1);
            TL_CHECK(tl_object_compute_bounds(&c.s, &mesh, lo, hi) == TL_OK);
            TL_CHECK(memcmp(lo, into->bounds_min, sizeof lo) == 0 && memcmp(hi, into->bounds_max, sizeof hi) == 0);
        }
        c.s.object_count = n + 2;
        TL_CHECK_EQ_U(differ(r, o, &c.s, "added, removed, appended"), 0);
        free_copy(&c);
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(s);
}

/* ---- materials -------------------------------------------------------------------------------------- */

TL_TEST(updates_materials_same_bytes_as_set_scene)
{
    if (!ensure_context()) return;
    tl_scene *s = crypt();
    if (!s) return;
    /* a textured material, an untextured one, and an object of the untextured one */
    uint32_t textured = UINT32_MAX, plain = UINT32_MAX;
    for (uint32_t m = 0; m < s->material_count; m++) {
        if (s->materials[m].albedo_map && textured == UINT32_MAX) textured = m;
        if (!s->materials[m].albedo_map && !s->materials[m].normal_map && plain == UINT32_MAX) plain = m;
    }
    size_t obj = SIZE_MAX;
    for (size_t i = 0; i < s->object_count && plain != UINT32_MAX; i++)
        if (s->objects[i].material == plain && s->objects[i].index_count) obj = i;
    TL_CHECK(textured != UINT32_MAX && plain != UINT32_MAX && obj != SIZE_MAX);
    if (textured == UINT32_MAX || obj == SIZE_MAX) {
        tl_scene_destroy(s);
        return;
    }
    for (size_t k = 0; k < OPTIONS; k++) {
        const tl_renderer_options *o = &k_options[k];
        tl_renderer *r = renderer(o, s);
        if (!r) continue;
        scene_copy c;
        copy_scene(s, 0, 0, 0, &c);
        /* an object drawn with another material */
        tl_object changed = s->objects[obj];
        changed.material = textured;
        TL_CHECK(tl_renderer_set_object(r, (uint32_t)obj, &changed) == TL_OK);
        c.objects[obj].material = textured;
        /* a material's values; its texture used as an occlusion map too (linear: copied on the GPU
         * from the sRGB upload) */
        tl_material m = s->materials[plain];
        m.albedo[0] *= 0.5f;
        m.specular[1] = 0.3f;
        m.gloss = 0.7f;
        m.occlusion_map = s->materials[textured].albedo_map;
        TL_CHECK(tl_renderer_set_material(r, plain, &m) == TL_OK);
        c.materials[plain] = m;
        TL_CHECK_EQ_U(differ(r, o, &c.s, "materials changed"), 0);
        /* a material made alpha-blended: a transparent pass the plan had not */
        tl_frame_plan before, after;
        TL_CHECK(tl_renderer_get_plan(r, &before) == TL_OK);
        m.flags |= TL_MATERIAL_ALPHA_BLEND;
        m.alpha = 0.5f;
        TL_CHECK(tl_renderer_set_material(r, plain, &m) == TL_OK);
        c.materials[plain] = m;
        TL_CHECK(tl_renderer_get_plan(r, &after) == TL_OK);
        TL_CHECK(after.pass_count > before.pass_count);
        TL_CHECK_EQ_U(differ(r, o, &c.s, "material blended"), 0);
        free_copy(&c);
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(s);
}

/* ---- refusals ------------------------------------------------------------------------------------- */

static int error_says(tl_renderer *r, tl_result got, const char *text)
{
    const char *e = tl_renderer_last_error(r);
    int ok = got == TL_ERROR_INVALID_ARGUMENT && e && strstr(e, text);
    if (!ok) fprintf(stderr, "expected an error with \"%s\", got %d: %s\n", text, (int)got, e ? e : "(none)");
    return ok;
}

TL_TEST(updates_refused_change_nothing)
{
    if (!ensure_context()) return;
    tl_scene *s = crypt();
    if (!s) return;
    tl_renderer *none = renderer(&k_options[0], NULL);
    if (none) {
        float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        TL_CHECK(error_says(none, tl_renderer_set_object_transform(none, 0, m), "no scene"));
        uint32_t id;
        TL_CHECK(error_says(none, tl_renderer_add_object(none, &s->objects[0], &id), "no scene"));
        tl_renderer_destroy(none);
    }
    tl_renderer *r = renderer(&k_options[0], s);
    uint8_t *before = malloc(PIXELS), *after = malloc(PIXELS);
    if (r && before && after && frame(r, before)) {
        uint32_t n = (uint32_t)s->object_count, id = 0;
        float nan_m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, NAN, 0, 0, 1};
        TL_CHECK(error_says(r, tl_renderer_set_object_transform(r, n, nan_m), "object"));
        TL_CHECK(error_says(r, tl_renderer_set_object_transform(r, 2, nan_m), "transform[12]"));
        TL_CHECK(error_says(r, tl_renderer_set_object_transform(r, 2, NULL), "no transform"));
        TL_CHECK(error_says(r, tl_renderer_set_object_visible(r, n + 5, 0), "does not exist"));
        tl_object bad = s->objects[2];
        bad.first_index = (uint32_t)s->index_count - 3;
        bad.index_count = 6;
        TL_CHECK(error_says(r, tl_renderer_set_object(r, 2, &bad), "first_index"));
        bad = s->objects[2];
        bad.material = (uint32_t)s->material_count;
        TL_CHECK(error_says(r, tl_renderer_add_object(r, &bad, &id), "object.material"));
        bad = s->objects[2];
        bad.bounds_max[1] = bad.bounds_min[1] - 1.0f;
        TL_CHECK(error_says(r, tl_renderer_set_object(r, 2, &bad), "bounds_max"));
        TL_CHECK(error_says(r, tl_renderer_add_object(r, &s->objects[2], NULL), "no place"));
        /* a removed object is gone for every call but add */
        TL_CHECK(tl_renderer_remove_object(r, 2) == TL_OK);
        TL_CHECK(error_says(r, tl_renderer_remove_object(r, 2), "was removed"));
        TL_CHECK(error_says(r, tl_renderer_set_object_visible(r, 2, 1), "was removed"));
        TL_CHECK(error_says(r, tl_renderer_get_object(r, 2, NULL, NULL), "was removed"));
        TL_CHECK(tl_renderer_add_object(r, &s->objects[2], &id) == TL_OK);
        TL_CHECK_EQ_U(id, 2);
        /* geometry: indices past the vertices given, broken triangles, non-finite positions */
        tl_vertex v[3] = {{.position = {0, 0, 0}}, {.position = {1, 0, 0}}, {.position = {0, 1, 0}}};
        uint32_t idx[3] = {0, 1, 3}, first = 0;
        TL_CHECK(error_says(r, tl_renderer_add_geometry(r, v, 3, idx, 3, &first), "indices[2] = 3"));
        TL_CHECK(error_says(r, tl_renderer_add_geometry(r, v, 3, idx, 2, &first), "not whole triangles"));
        v[1].position[2] = INFINITY;
        idx[2] = 2;
        TL_CHECK(error_says(r, tl_renderer_add_geometry(r, v, 3, idx, 3, &first), "vertices[1].position"));
        /* materials: past the count, a map past the textures, a texture no material named */
        tl_material m = s->materials[0];
        TL_CHECK(error_says(r, tl_renderer_set_material(r, (uint32_t)s->material_count, &m), "past the scene's"));
        m.normal_map = (uint32_t)s->texture_count + 1;
        TL_CHECK(error_says(r, tl_renderer_set_material(r, 0, &m), "normal_map"));
        TL_CHECK(frame(r, after));
        size_t diff = 0;
        for (size_t i = 0; i < PIXELS; i++) diff += before[i] != after[i];
        TL_CHECK_EQ_U(diff, 0);
    }
    free(before);
    free(after);
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}

/* A scene with a texture that no material names: a material changed to name it is refused. */
TL_TEST(updates_unkept_texture_refused_naming_the_field)
{
    if (!ensure_context()) return;
    uint8_t px[4 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    tl_texture tex = {.width = 2, .height = 2, .rgba = px};
    tl_vertex v[3] = {{.position = {-1, 0, -3}, .normal = {0, 0, 1}}, {.position = {1, 0, -3}, .normal = {0, 0, 1}},
                      {.position = {0, 1, -3}, .normal = {0, 0, 1}}};
    uint32_t idx[3] = {0, 1, 2};
    tl_object obj = {.index_count = 3};
    tl_material mat = {0};
    tl_light sun = {.type = TL_LIGHT_DIRECTIONAL, .direction = {0, 0, -1}, .color = {1, 1, 1}};
    tl_scene s = {.vertices = v, .vertex_count = 3, .indices = idx, .index_count = 3, .objects = &obj,
                  .object_count = 1, .materials = &mat, .material_count = 1, .textures = &tex, .texture_count = 1,
                  .lights = &sun, .light_count = 1};
    tl_renderer *r = renderer(&k_options[0], &s);
    if (!r) return;
    tl_material named = {.albedo_map = TL_TEXTURE_MAP(0)};
    TL_CHECK(error_says(r, tl_renderer_set_material(r, 0, &named), "materials[0].albedo_map names texture 0"));
    tl_renderer_destroy(r);
}

/* ---- textures and materials added after set_scene ------------------------------------------------ */

/* A 16x16 RGBA texture: red and blue quarters with a gradient, so that a wrong texel, colour space
 * or orientation changes the image. */
static void added_pixels(uint8_t px[16 * 16 * 4])
{
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            uint8_t *p = px + 4 * (y * 16 + x);
            int red = (x < 8) != (y < 8);
            p[0] = red ? (uint8_t)(150 + 6 * x) : 20;
            p[1] = (uint8_t)(10 * y);
            p[2] = red ? 30 : (uint8_t)(140 + 7 * y);
            p[3] = 255;
        }
}

/* A box 2.5 units in front of the scene's camera, 0.3 half-size. */
static void box_before_camera(const tl_scene *s, tl_vertex v[24], uint32_t idx[36])
{
    float d[3], len = 0.0f, c[3];
    for (int k = 0; k < 3; k++) d[k] = s->camera.target[k] - s->camera.position[k], len += d[k] * d[k];
    len = sqrtf(len);
    for (int k = 0; k < 3; k++) c[k] = s->camera.position[k] + 2.5f * d[k] / len;
    box_mesh(c, 0.3f, v, idx);
}

/* The scene `s` with one texture, one material, a box's geometry and one object more: what a caller
 * gives set_scene to draw what add_texture, add_material, add_geometry and add_object added. */
typedef struct grown_scene {
    tl_scene s;
    tl_texture *textures;
    tl_material *materials;
    tl_vertex *vertices;
    uint32_t *indices;
    tl_object *objects;
} grown_scene;

static void grow_scene(const tl_scene *s, const tl_texture *t, const tl_material *m, const tl_vertex v[24],
                       const uint32_t idx[36], const tl_object *o, grown_scene *g)
{
    g->s = *s;
    g->textures = calloc(s->texture_count + 1, sizeof *g->textures);
    g->materials = calloc(s->material_count + 2, sizeof *g->materials);
    g->vertices = calloc(s->vertex_count + 24, sizeof *g->vertices);
    g->indices = calloc(s->index_count + 36, sizeof *g->indices);
    g->objects = calloc(s->object_count + 1, sizeof *g->objects);
    if (!g->textures || !g->materials || !g->vertices || !g->indices || !g->objects) return;
    if (s->texture_count) memcpy(g->textures, s->textures, s->texture_count * sizeof *g->textures);
    if (s->material_count) memcpy(g->materials, s->materials, s->material_count * sizeof *g->materials);
    memcpy(g->vertices, s->vertices, s->vertex_count * sizeof *g->vertices);
    memcpy(g->indices, s->indices, s->index_count * sizeof *g->indices);
    memcpy(g->objects, s->objects, s->object_count * sizeof *g->objects);
    size_t nm = s->material_count ? s->material_count : 1; /* no materials: the zeroed one is material 0 */
    g->textures[s->texture_count] = *t;
    g->materials[nm] = *m;
    memcpy(g->vertices + s->vertex_count, v, 24 * sizeof *v);
    for (int i = 0; i < 36; i++) g->indices[s->index_count + i] = idx[i] + (uint32_t)s->vertex_count;
    g->objects[s->object_count] = *o;
    g->s.textures = g->textures;
    g->s.texture_count = s->texture_count + 1;
    g->s.materials = g->materials;
    g->s.material_count = nm + 1;
    g->s.vertices = g->vertices;
    g->s.vertex_count = s->vertex_count + 24;
    g->s.indices = g->indices;
    g->s.index_count = s->index_count + 36;
    g->s.objects = g->objects;
    g->s.object_count = s->object_count + 1;
}

static void free_grown(grown_scene *g)
{
    free(g->textures);
    free(g->materials);
    free(g->vertices);
    free(g->indices);
    free(g->objects);
}

/* Adds the texture, a material mapping it as albedo and occlusion (sRGB and the linear copy), the
 * box and an object drawing it; checks the new indices and that the object shows. Returns 0 on
 * failure. `o` receives the object as the renderer resolved it. */
static int add_textured_box(tl_renderer *r, const tl_scene *s, const tl_texture *t, const tl_material *m,
                            const tl_vertex v[24], const uint32_t idx[36], tl_object *o)
{
    uint32_t tex = UINT32_MAX, mat = UINT32_MAX, first = 0, id = UINT32_MAX;
    uint32_t want_mat = (uint32_t)(s->material_count ? s->material_count : 1);
    TL_CHECK(tl_renderer_add_texture(r, t, &tex) == TL_OK);
    TL_CHECK_EQ_U(tex, s->texture_count);
    tl_material mine = *m;
    mine.albedo_map = mine.occlusion_map = TL_TEXTURE_MAP(tex);
    TL_CHECK(tl_renderer_add_material(r, &mine, &mat) == TL_OK);
    TL_CHECK_EQ_U(mat, want_mat);
    TL_CHECK(tl_renderer_add_geometry(r, v, 24, idx, 36, &first) == TL_OK);
    TL_CHECK(tl_renderer_add_object(r, &(tl_object){.first_index = first, .index_count = 36, .material = mat}, &id) ==
             TL_OK);
    TL_CHECK_EQ_U(id, s->object_count);
    if (tl_renderer_get_object(r, id, o, NULL) != TL_OK) return 0;
    /* the box is in the frame: hiding it changes pixels */
    uint8_t *shown = malloc(PIXELS), *hidden = malloc(PIXELS);
    size_t diff = 0;
    if (shown && hidden && frame(r, shown) && tl_renderer_set_object_visible(r, id, 0) == TL_OK && frame(r, hidden))
        for (size_t i = 0; i < PIXELS; i += 4) diff += memcmp(shown + i, hidden + i, 4) != 0;
    TL_CHECK(tl_renderer_set_object_visible(r, id, 1) == TL_OK);
    printf("the added box covers %zu of %zu pixels\n", diff, PIXELS / 4);
    TL_CHECK(diff > 200);
    free(shown);
    free(hidden);
    return diff > 0;
}

/* What add_texture, add_material, add_geometry and add_object add draws the bytes of set_scene with
 * a scene that holds the same texture, material, geometry and object, in every mode. */
TL_TEST(updates_add_texture_and_material_same_bytes_as_set_scene)
{
    if (!ensure_context()) return;
    tl_scene *s = crypt();
    if (!s) return;
    TL_CHECK(!s->colors && !s->uv1); /* appended vertices would need theirs */
    static uint8_t px[16 * 16 * 4];
    added_pixels(px);
    tl_texture t = {.width = 16, .height = 16, .rgba = px, .name = "added"};
    tl_material m = {.albedo = {1, 1, 1}, .specular = {0.3f, 0.3f, 0.3f}, .gloss = 0.6f, .name = "added"};
    tl_vertex v[24];
    uint32_t idx[36];
    box_before_camera(s, v, idx);
    for (size_t k = 0; k < OPTIONS; k++) {
        const tl_renderer_options *o = &k_options[k];
        tl_renderer *r = renderer(o, s);
        if (!r) continue;
        tl_object added;
        if (add_textured_box(r, s, &t, &m, v, idx, &added)) {
            grown_scene g;
            tl_material mine = m;
            mine.albedo_map = mine.occlusion_map = TL_TEXTURE_MAP(s->texture_count);
            grow_scene(s, &t, &mine, v, idx, &added, &g);
            if (g.objects) TL_CHECK_EQ_U(differ(r, o, &g.s, "texture and material added"), 0);
            free_grown(&g);
        }
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(s);
}

/* A scene with no materials draws the zeroed material as material 0: an added material is 1, and
 * the scene's objects still draw plain grey. */
TL_TEST(updates_add_material_to_scene_without_materials)
{
    if (!ensure_context()) return;
    tl_vertex fv[4] = {{.position = {-5, 0, -5}, .normal = {0, 1, 0}}, {.position = {-5, 0, 5}, .normal = {0, 1, 0}},
                       {.position = {5, 0, 5}, .normal = {0, 1, 0}}, {.position = {5, 0, -5}, .normal = {0, 1, 0}}};
    uint32_t fi[6] = {0, 1, 2, 0, 2, 3};
    tl_object floor_object = {.index_count = 6};
    tl_light sun = {.type = TL_LIGHT_DIRECTIONAL, .direction = {-0.3f, -1, -0.2f}, .color = {2, 2, 2}};
    tl_scene s = {.vertices = fv, .vertex_count = 4, .indices = fi, .index_count = 6, .objects = &floor_object,
                  .object_count = 1, .lights = &sun, .light_count = 1,
                  .camera = {.position = {0, 3, 6}, .target = {0, 0, 0}}};
    static uint8_t px[16 * 16 * 4];
    added_pixels(px);
    tl_texture t = {.width = 16, .height = 16, .rgba = px};
    tl_material m = {.albedo = {1, 1, 1}};
    tl_vertex v[24];
    uint32_t idx[36];
    box_before_camera(&s, v, idx);
    for (size_t k = 0; k < OPTIONS; k += 3) {
        tl_renderer *r = renderer(&k_options[k], &s);
        if (!r) continue;
        tl_object added;
        if (add_textured_box(r, &s, &t, &m, v, idx, &added)) {
            grown_scene g;
            tl_material mine = m;
            mine.albedo_map = mine.occlusion_map = TL_TEXTURE_MAP(0);
            grow_scene(&s, &t, &mine, v, idx, &added, &g);
            if (g.objects) TL_CHECK_EQ_U(differ(r, &k_options[k], &g.s, "material added to none"), 0);
            free_grown(&g);
        }
        tl_renderer_destroy(r);
    }
}

/* Refusals name the field and change nothing; an added texture can be named by set_material. */
TL_TEST(updates_add_texture_and_material_refused_naming_the_field)
{
    if (!ensure_context()) return;
    static uint8_t px[16 * 16 * 4];
    added_pixels(px);
    tl_texture t = {.width = 16, .height = 16, .rgba = px};
    uint32_t index = 7;
    tl_renderer *none = renderer(&k_options[0], NULL);
    if (none) {
        TL_CHECK(error_says(none, tl_renderer_add_texture(none, &t, &index), "add_texture: no scene"));
        TL_CHECK(error_says(none, tl_renderer_add_material(none, &(tl_material){0}, &index), "add_material: no scene"));
        tl_renderer_destroy(none);
    }
    tl_scene *s = crypt();
    tl_renderer *r = s ? renderer(&k_options[0], s) : NULL;
    uint8_t *before = malloc(PIXELS), *after = malloc(PIXELS);
    if (r && before && after && frame(r, before)) {
        tl_texture bad = t;
        bad.width = 0;
        TL_CHECK(error_says(r, tl_renderer_add_texture(r, &bad, &index), "texture.width = 0"));
        bad = t;
        bad.rgba = NULL;
        TL_CHECK(error_says(r, tl_renderer_add_texture(r, &bad, &index), "texture.rgba"));
        TL_CHECK(error_says(r, tl_renderer_add_texture(r, NULL, &index), "no texture"));
        TL_CHECK(error_says(r, tl_renderer_add_texture(r, &t, NULL), "no place for the index"));
        tl_material m = {.normal_map = TL_TEXTURE_MAP(s->texture_count)};
        TL_CHECK(error_says(r, tl_renderer_add_material(r, &m, &index), "material.normal_map"));
        m = (tl_material){.model = TL_MATERIAL_MODEL_TOON, .toon_steps = 65};
        TL_CHECK(error_says(r, tl_renderer_add_material(r, &m, &index), "material.toon_steps = 65"));
        m = (tl_material){.clearcoat = NAN};
        TL_CHECK(error_says(r, tl_renderer_add_material(r, &m, &index), "material.clearcoat"));
        TL_CHECK(index == 7); /* nothing written on a refusal */
        /* the added texture is the next map, for set_material too */
        TL_CHECK(tl_renderer_add_texture(r, &t, &index) == TL_OK);
        TL_CHECK_EQ_U(index, s->texture_count);
        m = (tl_material){.albedo_map = TL_TEXTURE_MAP(index)};
        TL_CHECK(error_says(r, tl_renderer_set_material(r, (uint32_t)s->material_count, &m), "past the scene's"));
        TL_CHECK(frame(r, after));
        size_t diff = 0;
        for (size_t i = 0; i < PIXELS; i++) diff += before[i] != after[i];
        TL_CHECK_EQ_U(diff, 0); /* an unused texture draws nothing */
        tl_material plain = s->materials[0];
        plain.albedo_map = TL_TEXTURE_MAP(index);
        TL_CHECK(tl_renderer_set_material(r, 0, &plain) == TL_OK);
    }
    free(before);
    free(after);
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}

/* ---- what updates upload, and what they cost ---------------------------------------------------- */

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

TL_TEST(updates_upload_nothing_but_new_geometry)
{
    if (!ensure_context()) return;
    tl_scene *s = crypt();
    tl_renderer *r = s ? renderer(&k_options[0], s) : NULL;
    uint8_t *px = malloc(PIXELS);
    if (r && px && frame(r, px)) {
        /* a steady frame's uploads (the stream is mapped, not uploaded: expected none) */
        tl_test_gl_counts_reset();
        TL_CHECK(frame(r, px));
        unsigned long steady = UPLOADS;
        unsigned long long steady_bytes = UPLOAD_BYTES;
        tl_test_gl_counts_reset();
        for (uint32_t i = 0; i < (uint32_t)s->object_count; i++) {
            float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.01f * (float)(i % 7), 0, 0, 1};
            TL_CHECK(tl_renderer_set_object_transform(r, i, m) == TL_OK);
            TL_CHECK(tl_renderer_set_object_visible(r, i, i % 5 != 0) == TL_OK);
        }
        tl_object same = s->objects[4];
        TL_CHECK(tl_renderer_set_object(r, 4, &same) == TL_OK);
        TL_CHECK(frame(r, px));
        fprintf(stderr, "moved and hid %zu objects, set one, one frame: %lu uploads, %llu bytes (a steady frame: %lu, "
                "%llu); %lu texture uploads, %lu programs linked\n", s->object_count, UPLOADS, UPLOAD_BYTES, steady,
                steady_bytes, TEXTURES, LINKS);
        TL_CHECK_EQ_U(UPLOADS, steady);
        TL_CHECK_EQ_U(UPLOAD_BYTES, steady_bytes);
        TL_CHECK_EQ_U(TEXTURES, 0);
        TL_CHECK_EQ_U(LINKS, 0);
        /* adding past the slots doubles them: the object-id list (4 bytes a slot) is the one upload;
         * an add into a removed slot uploads nothing */
        uint32_t id;
        tl_test_gl_counts_reset();
        TL_CHECK(tl_renderer_add_object(r, &same, &id) == TL_OK);
        TL_CHECK_EQ_U(UPLOADS, 1);
        TL_CHECK_EQ_U(UPLOAD_BYTES, 4 * 2 * s->object_count);
        TL_CHECK(tl_renderer_remove_object(r, 7) == TL_OK);
        tl_test_gl_counts_reset();
        TL_CHECK(tl_renderer_add_object(r, &same, &id) == TL_OK);
        TL_CHECK_EQ_U(id, 7);
        TL_CHECK(tl_renderer_add_object(r, &same, &id) == TL_OK);
        TL_CHECK(frame(r, px));
        TL_CHECK_EQ_U(UPLOADS, steady);
        TL_CHECK_EQ_U(TEXTURES + LINKS, 0);
        /* appended geometry: its own bytes (the shifted indices) and nothing else, grown or not */
        tl_vertex bv[24];
        uint32_t bi[36], first;
        for (int g = 0; g < 3; g++) {
            box_mesh((float[3]){0, 1, (float)g}, 0.25f, bv, bi);
            tl_test_gl_counts_reset();
            TL_CHECK(tl_renderer_add_geometry(r, bv, 24, bi, 36, &first) == TL_OK);
            TL_CHECK_EQ_U(UPLOAD_BYTES, sizeof bv + sizeof bi);
            TL_CHECK_EQ_U(UPLOADS, 2);
        }
        /* a material's record: one std140 block */
        tl_test_gl_counts_reset();
        TL_CHECK(tl_renderer_set_material(r, 1, &s->materials[1]) == TL_OK);
        TL_CHECK_EQ_U(UPLOADS, 1);
        TL_CHECK_LE(UPLOAD_BYTES, 256);
    }
    free(px);
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Printed: the CPU cost of an update against set_scene with the same change, and of a frame in
 * which every object moved against a steady one. */
TL_TEST(updates_cost_printed)
{
    if (!ensure_context()) return;
    tl_scene *s = crypt();
    tl_renderer *r = s ? renderer(&k_options[0], s) : NULL;
    uint8_t *px = malloc(PIXELS);
    if (r && px && frame(r, px)) {
        const uint32_t n = (uint32_t)s->object_count;
        const int reps = 200000;
        double per[3];
        for (int round = 0; round < 3; round++) {
            float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
            double t0 = now_ms();
            for (int i = 0; i < reps; i++) {
                m[12] = 0.001f * (float)(i & 15);
                tl_renderer_set_object_transform(r, (uint32_t)i % n, m);
            }
            per[round] = (now_ms() - t0) * 1e6 / reps;
        }
        qsort(per, 3, sizeof per[0], cmp_double);
        /* lights, for comparison: set_lights with 1024 point lights, per light */
        enum { NL = 1024 };
        tl_light *many = calloc(NL, sizeof *many);
        double light_ns[3] = {0, 0, 0};
        for (int i = 0; many && i < NL; i++)
            many[i] = (tl_light){.position = {(float)(i % 32) * 0.3f - 5.0f, 1.0f, (float)(i / 32) * 0.3f - 5.0f},
                                 .color = {0.01f, 0.01f, 0.01f}, .radius = 1.0f};
        for (int round = 0; many && round < 3; round++) {
            double t0 = now_ms();
            for (int i = 0; i < 200; i++) tl_renderer_set_lights(r, many, NL);
            light_ns[round] = (now_ms() - t0) * 1e6 / (200.0 * NL);
        }
        qsort(light_ns, 3, sizeof light_ns[0], cmp_double);
        fprintf(stderr, "set_lights with %d point lights: %.1f ns CPU per light\n", NL, light_ns[1]);
        TL_CHECK(tl_renderer_set_lights(r, s->lights, s->light_count) == TL_OK);
        free(many);
        double scene[3], moved[3], steady[3];
        for (int round = 0; round < 3; round++) {
            double t0 = now_ms();
            TL_CHECK(tl_renderer_set_scene(r, s) == TL_OK);
            scene[round] = now_ms() - t0;
            TL_CHECK(frame(r, px));
            t0 = now_ms();
            TL_CHECK(frame(r, px));
            steady[round] = now_ms() - t0;
            t0 = now_ms();
            for (uint32_t i = 0; i < n; i++) {
                float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.001f * (float)round, 0, 1};
                tl_renderer_set_object_transform(r, i, m);
            }
            TL_CHECK(frame(r, px));
            moved[round] = now_ms() - t0;
        }
        qsort(scene, 3, sizeof scene[0], cmp_double);
        qsort(steady, 3, sizeof steady[0], cmp_double);
        qsort(moved, 3, sizeof moved[0], cmp_double);
        fprintf(stderr, "scene of %u objects, %zu vertices: set_object_transform %.0f ns CPU each (median of 3 x %d); "
                "set_scene %.2f ms; a frame with every object moved %.2f ms, a steady frame %.2f ms (the per-object "
                "records, %zu bytes each, are written every frame either way)\n", n, s->vertex_count, per[1], reps,
                scene[1], moved[1], steady[1], (size_t)144);
    }
    free(px);
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}
