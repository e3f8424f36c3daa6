/* glTF loading (tl_scene_load_gltf), no GL: the test scenes against hand-computed transforms,
 * bounds, materials and lights, and the allocator (every allocation freed, failure at every k-th
 * allocation). Bad files and fuzzing are in tests/input. Every file is written at run time by
 * gltf_fixtures.h into TL_GLTF_TEST_DIR/<test name> (gltf_checks.h). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_checks.h"

static const float PI_F = 3.14159265358979f;

static void xform(const float m[16], const float p[3], float out[3])
{
    for (int r = 0; r < 3; r++) out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}

/* ---- good input -------------------------------------------------------------------------- */

TL_TEST(gltf_textured_boxes_hierarchy)
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

TL_TEST(gltf_textured_boxes_materials_textures)
{
    loaded l;
    load(&l, "gltf_textured_boxes_materials_textures", "textured_boxes");
    TL_CHECK(l.result == TL_OK);
    if (l.result != TL_OK || l.scene->material_count != 2 || l.scene->texture_count != 3) return;
    const tl_scene *s = l.scene;
    const tl_material *m = &s->materials[0];
    TL_CHECK(strcmp(m->name, "checker") == 0);
    TL_CHECK(m->flags == (TL_MATERIAL_MICROFACET | TL_MATERIAL_METALLIC_ROUGHNESS));
    TL_CHECK(near3(m->albedo, 1.0f, 0.9f, 0.8f, 1e-6f)); /* base colour, converted per pixel */
    TL_CHECK(near(m->metallic, 0.5f, 1e-6f) && near(m->roughness, 0.75f, 1e-6f));
    TL_CHECK(near(m->normal_scale, 0.8f, 1e-6f));
    /* maps are texture indices + 1: albedo.png is texture 0, the metallic-roughness map 1, the normal map 2 */
    TL_CHECK(m->albedo_map == 1 && m->metallic_roughness_map == 2 && m->normal_map == 3);
    TL_CHECK(m->emissive_map == 0 && m->occlusion_map == 0);
    m = &s->materials[1];
    TL_CHECK(strcmp(m->name, "painted") == 0);
    TL_CHECK(m->flags == TL_MATERIAL_MICROFACET); /* every glTF material is authored for GGX */
    TL_CHECK(near3(m->albedo, 0.2f, 0.4f, 0.6f, 1e-6f)); /* metal 0: diffuse = base */
    TL_CHECK(near3(m->specular, 0.04f, 0.04f, 0.04f, 1e-6f));
    TL_CHECK(near(m->gloss, 0.5f, 1e-6f));
    TL_CHECK(m->albedo_map == TL_TEXTURE_MAP(0) && m->normal_map == 0);

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

TL_TEST(gltf_materials_conversion)
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
    for (int i = 0; i < 3; i++) TL_CHECK(m[i].flags == TL_MATERIAL_MICROFACET);
    TL_CHECK(m[3].flags == (TL_MATERIAL_MICROFACET | TL_MATERIAL_ALPHA_MASK));
    TL_CHECK(near(m[3].alpha_cutoff, 0.3f, 1e-6f) && near(m[3].alpha, 0.9f, 1e-6f));
    TL_CHECK(m[3].albedo_map == TL_TEXTURE_MAP(0));
    TL_CHECK(m[4].flags == (TL_MATERIAL_MICROFACET | TL_MATERIAL_ALPHA_BLEND | TL_MATERIAL_DOUBLE_SIDED));
    TL_CHECK(near(m[4].alpha, 0.5f, 1e-6f));
    TL_CHECK(m[5].flags == (TL_MATERIAL_MICROFACET | TL_MATERIAL_DOUBLE_SIDED));
    TL_CHECK(near3(m[5].emissive, 2.0f, 1.0f, 0.0f, 1e-6f)); /* KHR_materials_emissive_strength 2 */
    TL_CHECK(m[6].flags == (TL_MATERIAL_MICROFACET | TL_MATERIAL_METALLIC_ROUGHNESS));
    TL_CHECK(near3(m[6].albedo, 1, 1, 1, 1e-6f));
    TL_CHECK(near(m[6].metallic, 0.7f, 1e-6f) && near(m[6].roughness, 0.6f, 1e-6f));
    TL_CHECK(m[6].metallic_roughness_map == TL_TEXTURE_MAP(1) && m[6].occlusion_map == TL_TEXTURE_MAP(1));
    TL_CHECK(near(m[6].occlusion_strength, 0.5f, 1e-6f));
    /* glTF's default material: white, metallic 1, roughness 1 */
    TL_CHECK(strcmp(m[7].name, "default material") == 0);
    TL_CHECK(near3(m[7].albedo, 0, 0, 0, 1e-6f) && near3(m[7].specular, 1, 1, 1, 1e-6f) && m[7].gloss == 0.0f);
    /* Quads 4..7 have no NORMAL: generated flat, facing +Z as the given ones. */
    for (size_t i = 0; i < s->vertex_count; i++) TL_CHECK(near3(s->vertices[i].normal, 0, 0, 1, 1e-6f));
    unload(&l);
}

TL_TEST(gltf_lights_punctual)
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

/* Shadows from a file (docs/gltf.md, "Shadows"): "extras": {"thinlight_shadow": true} casts and
 * false never does, whatever the rule; a value that is not a boolean is a warning naming it and
 * counts as absent; with options.shadow_lights = N the rule adds every other directional light and
 * then the brightest point and spot lights while fewer than N cast. */
TL_TEST(gltf_light_shadow_flags_and_rule)
{
    static const struct {
        uint32_t budget;
        int casts[8];
    } want[] = {
        {0, {0, 0, 1, 0, 0, 0, 0, 0}}, /* the flags alone */
        {1, {1, 0, 1, 0, 0, 0, 0, 0}}, /* directional lights cast past the budget */
        {3, {1, 0, 1, 1, 0, 0, 0, 0}}, /* then the brightest point light (100 cd) */
        {4, {1, 0, 1, 1, 1, 0, 0, 0}}, /* then the next (10 cd) */
        {8, {1, 0, 1, 1, 1, 1, 1, 1}}, /* all but the one flagged false */
    };
    for (size_t k = 0; k < sizeof want / sizeof want[0]; k++) {
        loaded l;
        tl_gltf_options o = {.shadow_lights = want[k].budget};
        load_opts(&l, "gltf_light_shadow_flags_and_rule", "light_shadow_flags", &o);
        if (l.result != TL_OK) printf("%s\n", l.error);
        TL_CHECK(l.result == TL_OK);
        if (l.result != TL_OK) return;
        TL_CHECK_EQ_U(l.scene->light_count, 8);
        for (size_t i = 0; i < l.scene->light_count && i < 8; i++) {
            if ((l.scene->lights[i].shadow != 0) != want[k].casts[i])
                printf("budget %u: light %zu shadow %d, expected %d\n", want[k].budget, i, l.scene->lights[i].shadow,
                       want[k].casts[i]);
            TL_CHECK((l.scene->lights[i].shadow != 0) == want[k].casts[i]);
        }
        /* the two values that are not booleans, each one line naming the light, the field and the value */
        TL_CHECK_EQ_U(l.log.warnings, 2);
        TL_CHECK(strstr(l.log.warnings_text, "KHR_lights_punctual.lights[5].extras.thinlight_shadow = \"yes\"") != NULL);
        TL_CHECK(strstr(l.log.warnings_text, "KHR_lights_punctual.lights[6].extras.thinlight_shadow = 1") != NULL);
        unload(&l);
    }
}

/* The rule covers the default rig: a file without lights gets its key light (directional) and
 * its fill lights casting up to the budget; without the rule none casts. */
TL_TEST(gltf_default_rig_shadow_rule)
{
    for (uint32_t budget = 0; budget <= 3; budget += 3) {
        loaded l;
        tl_gltf_options o = {.shadow_lights = budget};
        load_opts(&l, "gltf_default_rig_shadow_rule", "textured_boxes", &o);
        TL_CHECK(l.result == TL_OK);
        if (l.result != TL_OK) return;
        size_t casting = 0, directional = 0;
        for (size_t i = 0; i < l.scene->light_count; i++) {
            casting += l.scene->lights[i].shadow != 0;
            directional += l.scene->lights[i].shadow && l.scene->lights[i].type == TL_LIGHT_DIRECTIONAL;
        }
        TL_CHECK_EQ_U(l.scene->light_count, 5);
        TL_CHECK_EQ_U(casting, budget);
        TL_CHECK_EQ_U(directional, budget ? 1 : 0);
        unload(&l);
    }
}

TL_TEST(gltf_index_sizes)
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

TL_TEST(gltf_normalized_uvs)
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

TL_TEST(gltf_glb_and_data_uri_equal_gltf)
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

TL_TEST(gltf_generated_normals_tangents)
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

TL_TEST(gltf_default_light_rig)
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

TL_TEST(gltf_extra_lights_deterministic)
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

TL_TEST(gltf_camera_from_file)
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

TL_TEST(gltf_multiple_scenes)
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

TL_TEST(gltf_mirrored_instance_winding)
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

TL_TEST(gltf_test_scenes_written)
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

TL_TEST(gltf_allocator_counting)
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
