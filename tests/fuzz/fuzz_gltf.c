/* libFuzzer target: tl_scene_parse_gltf on arbitrary bytes (.glb or .gltf JSON, content decides;
 * external files are not available, so data: URIs and GLB buffer views are what it reads).
 * Properties: the call returns a result code, a scene exactly on success, one-line messages, no
 * leak through the allocator, and a scene whose every index and range is valid. The budget is
 * small (64 MiB) so that every allocation the budget does not govern shows up as libFuzzer's
 * malloc limit (-malloc_limit_mb, tests/fuzz/CMakeLists.txt). */
#include <math.h>
#include <string.h>

#include "fuzz_common.h"
#include "thinlight/io.h"
#include "thinlight/scene.h"

static int finite3(const float v[3]) { return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]); }

static void check_textures(const tl_scene *s, uint32_t map)
{
    FUZZ_REQUIRE(map == 0 || map - 1 < s->texture_count); /* a map is a texture index + 1, 0 = none */
}

static void check_scene(const tl_scene *s)
{
    FUZZ_REQUIRE(s->vertex_count <= UINT32_MAX);
    for (size_t i = 0; i < s->index_count; i++) FUZZ_REQUIRE(s->indices[i] < s->vertex_count);
    for (size_t i = 0; i < s->vertex_count; i++) {
        FUZZ_REQUIRE(finite3(s->vertices[i].position));
        FUZZ_REQUIRE(finite3(s->vertices[i].normal));
    }
    for (size_t i = 0; i < s->object_count; i++) {
        const tl_object *o = &s->objects[i];
        uint32_t per = o->primitive == TL_PRIMITIVE_LINES ? 2u : o->primitive == TL_PRIMITIVE_POINTS ? 1u : 3u;
        FUZZ_REQUIRE(o->primitive < TL_PRIMITIVE_COUNT_);
        FUZZ_REQUIRE(o->index_count % per == 0 && (size_t)o->first_index + o->index_count <= s->index_count);
        FUZZ_REQUIRE(o->material < s->material_count);
        FUZZ_REQUIRE(finite3(o->bounds_min) && finite3(o->bounds_max));
    }
    for (size_t i = 0; i < s->material_count; i++) {
        const tl_material *m = &s->materials[i];
        check_textures(s, m->albedo_map);
        check_textures(s, m->normal_map);
        check_textures(s, m->metallic_roughness_map);
        check_textures(s, m->emissive_map);
        check_textures(s, m->occlusion_map);
        FUZZ_REQUIRE(memchr(m->name, 0, sizeof m->name) != NULL);
    }
    for (size_t i = 0; i < s->texture_count; i++) {
        const tl_texture *t = &s->textures[i];
        FUZZ_REQUIRE(t->width > 0 && t->height > 0 && t->rgba != NULL);
        FUZZ_REQUIRE(memchr(t->name, 0, sizeof t->name) != NULL);
    }
    for (size_t i = 0; i < s->light_count; i++) {
        const tl_light *l = &s->lights[i];
        FUZZ_REQUIRE(finite3(l->position) && finite3(l->color) && isfinite(l->radius));
        FUZZ_REQUIRE((unsigned)l->type < TL_LIGHT_TYPE_COUNT_);
    }
    FUZZ_REQUIRE(finite3(s->camera.position) && finite3(s->camera.target));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_counter count = {0};
    tl_gltf_options o = {
        .allocator = {fuzz_alloc, fuzz_free, &count},
        .logger = {fuzz_log, NULL},
        .max_memory = (size_t)64 << 20,
        .max_texture_pixels = (size_t)1 << 20,
        .name = "fuzz",
    };
    tl_scene *s = NULL;
    tl_result r = tl_scene_parse_gltf(data, size, &o, &s);
    FUZZ_REQUIRE((unsigned)r < TL_RESULT_COUNT_);
    FUZZ_REQUIRE((r == TL_OK) == (s != NULL));
    if (s) check_scene(s);
    tl_scene_destroy(s);
    FUZZ_REQUIRE(count.live == 0);
    return 0;
}
