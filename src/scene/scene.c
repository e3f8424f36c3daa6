/* Scene ownership (allocation through the scene's allocator, destruction) and the feature summary
 * the frame planner reads. */
#include <stdlib.h>

#include "core/alloc.h"
#include "scene_internal.h"

void tl_scene_destroy(tl_scene *scene)
{
    if (!scene) return;
    tl_allocator a = scene->allocator; /* the struct itself goes last */
    if (scene->textures) {
        for (size_t i = 0; i < scene->texture_count; i++) tl__free(&a, scene->textures[i].rgba);
    }
    tl__free(&a, scene->textures);
    tl__free(&a, scene->vertices);
    tl__free(&a, scene->indices);
    tl__free(&a, scene->objects);
    tl__free(&a, scene->materials);
    tl__free(&a, scene->lights);
    tl__free(&a, scene);
}

static int tl__nonzero3(const float v[3]) { return v[0] > 0.0f || v[1] > 0.0f || v[2] > 0.0f; }

void tl_scene_features(const tl_scene *scene, tl_scene_feature_set *out)
{
    if (!out) return;
    *out = (tl_scene_feature_set){0};
    if (!scene) return;

    for (size_t i = 0; i < scene->light_count && scene->lights; i++) {
        switch (scene->lights[i].type) {
        case TL_LIGHT_DEFAULT:
        case TL_LIGHT_POINT: out->point_lights++; break;
        case TL_LIGHT_SPOT: out->spot_lights++; break;
        case TL_LIGHT_DIRECTIONAL: out->directional_lights++; break;
        case TL_LIGHT_TYPE_COUNT_: break;
        }
    }

    /* Only materials that some non-empty object draws with count: an unused material needs no
     * shader branch. A texture index past the texture array counts as no texture. */
    for (size_t i = 0; i < scene->object_count && scene->objects; i++) {
        const tl_object *o = &scene->objects[i];
        if (o->index_count == 0 || o->material >= scene->material_count || !scene->materials) continue;
        const tl_material *m = &scene->materials[o->material];
        size_t nt = scene->textures ? scene->texture_count : 0;
        int mr = (m->flags & TL_MATERIAL_METALLIC_ROUGHNESS) != 0;
        if (tl__nonzero3(m->specular) || mr) out->has_specular = 1;
        if (mr && m->metallic_roughness_texture < nt) out->has_metallic_roughness = 1;
        if (m->albedo_texture < nt || m->emissive_texture < nt || m->occlusion_texture < nt ||
            (mr && m->metallic_roughness_texture < nt))
            out->has_textures = 1;
        if (m->occlusion_texture < nt) out->has_occlusion = 1;
        if (m->emissive_texture < nt && tl__nonzero3(m->emissive)) out->has_emissive_texture = 1;
        if (m->flags & TL_MATERIAL_DOUBLE_SIDED) out->has_double_sided = 1;
        if (mr || (m->flags & TL_MATERIAL_MICROFACET)) out->has_microfacet = 1;
        if (m->normal_texture < nt) {
            out->has_textures = 1;
            out->has_normal_maps = 1;
        }
        if (tl__nonzero3(m->emissive) && (m->emissive_texture == TL_NO_TEXTURE || m->emissive_texture < nt))
            out->has_emissive = 1;
        if (m->flags & TL_MATERIAL_ALPHA_MASK) out->has_alpha_mask = 1;
        if (m->flags & TL_MATERIAL_ALPHA_BLEND) out->has_alpha_blend = 1;
    }

    out->triangle_count = scene->indices ? scene->index_count / 3 : 0;
    out->object_count = scene->object_count;
}
