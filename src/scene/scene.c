/* Scene ownership (allocation through the scene's allocator, destruction) and the feature summary
 * the frame planner reads. */
#include <stdlib.h>

#include "core/alloc.h"
#include "scene/validate.h"

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
    tl__free(&a, scene->colors);
    tl__free(&a, scene->uv1);
    tl__free(&a, scene);
}

static int tl__nonzero3(const float v[3]) { return v[0] > 0.0f || v[1] > 0.0f || v[2] > 0.0f; }

void tl__material_features(const tl_material *material, size_t texture_count, tl_scene_feature_set *out)
{
    /* a map past the texture array counts as no texture */
    tl_material m;
    tl__material_defaults(material, &m);
    size_t nt = texture_count;
    int albedo = tl__material_has_texture(&m, TL__MAP_ALBEDO, nt);
    int normal = tl__material_has_texture(&m, TL__MAP_NORMAL, nt);
    int mr_map = tl__material_has_texture(&m, TL__MAP_METALLIC_ROUGHNESS, nt);
    int emissive = tl__material_has_texture(&m, TL__MAP_EMISSIVE, nt);
    int occlusion = tl__material_has_texture(&m, TL__MAP_OCCLUSION, nt);
    int mr = (m.flags & TL_MATERIAL_METALLIC_ROUGHNESS) != 0;
    if (tl__nonzero3(m.specular) || mr) out->has_specular = 1;
    if (mr && mr_map) out->has_metallic_roughness = 1;
    if (albedo || emissive || occlusion || (mr && mr_map)) out->has_textures = 1;
    if (occlusion) out->has_occlusion = 1;
    if (emissive && tl__nonzero3(m.emissive)) out->has_emissive_texture = 1;
    if (m.flags & TL_MATERIAL_DOUBLE_SIDED) out->has_double_sided = 1;
    if (mr || (m.flags & TL_MATERIAL_MICROFACET)) out->has_microfacet = 1;
    if (normal) {
        out->has_textures = 1;
        out->has_normal_maps = 1;
    }
    if (tl__nonzero3(m.emissive) && (m.emissive_map == 0 || emissive)) out->has_emissive = 1;
    if (m.flags & TL_MATERIAL_ALPHA_MASK) out->has_alpha_mask = 1;
    if (m.flags & TL_MATERIAL_ALPHA_BLEND) out->has_alpha_blend = 1;
    if (m.model < TL_MATERIAL_MODEL_COUNT_) out->material_models |= 1u << m.model;
    if (m.model == TL_MATERIAL_MODEL_CLEARCOAT) out->has_specular = 1; /* the coat reads the specular sums */
    for (int k = 0; k < TL__MATERIAL_TEXTURE_SLOTS; k++) /* the scene's uv1 decides (tl_scene_features) */
        if ((m.uv1_maps & (1u << k)) && tl__material_has_texture(&m, k, nt)) out->has_uv1 = 1;
}

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
        out->shadow_lights += scene->lights[i].shadow != 0;
    }

    /* Only materials that some non-empty object draws with count: an unused material needs no
     * shader branch. In a scene without materials, objects draw the zeroed material, which needs
     * nothing. */
    for (size_t i = 0; i < scene->object_count && scene->objects; i++) {
        const tl_object *o = &scene->objects[i];
        if (o->index_count == 0 || o->material >= scene->material_count || !scene->materials) continue;
        tl__material_features(&scene->materials[o->material], scene->textures ? scene->texture_count : 0, out);
        if (scene->materials[o->material].flags & TL_MATERIAL_ALPHA_BLEND) out->alpha_blend_objects++;
    }
    for (size_t i = 0; i < scene->object_count && scene->objects; i++) {
        const tl_object *o = &scene->objects[i];
        if (!o->index_count) continue;
        if (o->primitive != TL_PRIMITIVE_TRIANGLES) out->has_points_lines = 1;
        if (scene->colors) out->has_vertex_colors = 1;
    }
    if (!scene->uv1) out->has_uv1 = 0;

    out->triangle_count = scene->indices ? scene->index_count / 3 : 0;
    out->object_count = scene->object_count;
}
