/* The glTF tests' shared loading and checks (gltf_checks.h). */
#include "gltf_checks.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void capture_fn(void *user, tl_log_level level, const char *message)
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

void *count_alloc(size_t size, void *user)
{
    counter *c = user;
    c->calls++;
    if (c->fail_at && c->calls == c->fail_at) return NULL;
    void *p = malloc(size);
    if (p) c->live++;
    return p;
}

void count_free(void *ptr, void *user)
{
    counter *c = user;
    if (ptr) c->live--;
    free(ptr);
}

void case_dir(char *out, size_t n, const char *test)
{
    snprintf(out, n, "%s/%s", TL_GLTF_TEST_DIR, test);
    tlf_mkdir_p(out);
}

/* Writes fixture `fixture` into the test's directory; its path into `path`. */
int fixture(const char *test, const char *fixture_name, char *path, size_t n)
{
    char dir[1024];
    case_dir(dir, sizeof dir, test);
    int rc = tlf_write_case(dir, fixture_name, path, n);
    TL_CHECK(rc == 0);
    return rc;
}

void load_opts(loaded *l, const char *test, const char *fixture_name, const tl_gltf_options *base)
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

void load(loaded *l, const char *test, const char *fixture_name) { load_opts(l, test, fixture_name, NULL); }

void unload(loaded *l)
{
    tl_scene_destroy(l->scene);
    l->scene = NULL;
    TL_CHECK(l->count.live == 0);
}

/* Expects failure `want` whose message contains `needle` (may be NULL). */
void expect_failure(const char *test, const char *fixture_name, tl_result want, const char *needle)
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

int near(float a, float b, float tol) { return fabsf(a - b) <= tol; }
int near3(const float *a, float x, float y, float z, float tol)
{
    return near(a[0], x, tol) && near(a[1], y, tol) && near(a[2], z, tol);
}

float len3(const float v[3]) { return sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
float dot3f(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Every index in range, every vertex finite with a unit normal. */
void check_geometry(const tl_scene *s)
{
    for (size_t i = 0; i < s->index_count; i++) TL_CHECK(s->indices[i] < s->vertex_count);
    int points_lines = 0; /* whose vertices may have a zero normal: they face the viewer */
    for (size_t i = 0; i < s->object_count; i++) points_lines |= s->objects[i].primitive != TL_PRIMITIVE_TRIANGLES;
    for (size_t i = 0; i < s->vertex_count; i++) {
        const tl_vertex *v = &s->vertices[i];
        TL_CHECK_FINITE3(v->position);
        TL_CHECK(near(len3(v->normal), 1.0f, 1e-5f) || (points_lines && len3(v->normal) == 0.0f));
    }
    for (size_t i = 0; i < s->object_count; i++) {
        const tl_object *o = &s->objects[i];
        TL_CHECK((size_t)o->first_index + o->index_count <= s->index_count);
        TL_CHECK(o->primitive < TL_PRIMITIVE_COUNT_);
        TL_CHECK(o->index_count % (o->primitive == TL_PRIMITIVE_LINES ? 2u : o->primitive == TL_PRIMITIVE_POINTS ? 1u : 3u) == 0);
        TL_CHECK(o->material < s->material_count);
        for (int k = 0; k < 3; k++) {
            TL_CHECK(o->bounds_min[k] <= o->bounds_max[k]);
            TL_CHECK(o->bounds_min[k] >= s->bounds_min[k] && o->bounds_max[k] <= s->bounds_max[k]);
        }
    }
    for (size_t i = 0; i < s->material_count; i++) {
        const tl_material *m = &s->materials[i];
        const uint32_t t[5] = {m->albedo_map, m->normal_map, m->metallic_roughness_map, m->emissive_map, m->occlusion_map};
        for (int k = 0; k < 5; k++) TL_CHECK(t[k] == 0 || t[k] - 1 < s->texture_count); /* index + 1, 0 = none */
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
void check_tangents(const tl_scene *s, size_t first, size_t count)
{
    for (size_t i = first; i < first + count; i++) {
        const tl_vertex *v = &s->vertices[i];
        TL_CHECK(near(len3(v->tangent), 1.0f, 1e-5f));
        TL_CHECK(fabsf(dot3f(v->tangent, v->normal)) < 1e-5f);
        TL_CHECK(v->tangent[3] == 1.0f || v->tangent[3] == -1.0f);
    }
}
