/* glTF material extensions into the material models (tl_scene_load_gltf, no GL; docs/gltf.md,
 * "Material extensions"): KHR_materials_unlit, _clearcoat and _sheen choose the model and its
 * parameters, _ior and _specular the dielectric F0 (checked against the formula in double),
 * _emissive_strength scales the emission; textures of the extensions and a second model are
 * ignored with a warning. The file is written at run time (gltf_prims.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "gltf_checks.h"
#include "gltf_prims.h"

#define QUADS 9

static const char *const materials =
    "{\"name\":\"unlit\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.9,0.5,0.1,1]},"
    "\"extensions\":{\"KHR_materials_unlit\":{}}},"
    "{\"name\":\"coat\",\"pbrMetallicRoughness\":{\"metallicFactor\":0},\"extensions\":{\"KHR_materials_clearcoat\":"
    "{\"clearcoatFactor\":0.7,\"clearcoatRoughnessFactor\":0.2,\"clearcoatTexture\":{\"index\":0}}}},"
    "{\"name\":\"sheen\",\"pbrMetallicRoughness\":{\"metallicFactor\":0},\"extensions\":{\"KHR_materials_sheen\":"
    "{\"sheenColorFactor\":[0.5,0.4,0.3],\"sheenRoughnessFactor\":0.6}}},"
    "{\"name\":\"ior\",\"pbrMetallicRoughness\":{\"metallicFactor\":0},\"extensions\":{\"KHR_materials_ior\":"
    "{\"ior\":2.0}}},"
    "{\"name\":\"specular\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.2,0.4,0.6,1],\"metallicFactor\":0.5},"
    "\"extensions\":{\"KHR_materials_specular\":{\"specularFactor\":0.5,\"specularColorFactor\":[1,0.5,0.25]}}},"
    "{\"name\":\"strength\",\"emissiveFactor\":[0.5,0.25,0],\"extensions\":{\"KHR_materials_emissive_strength\":"
    "{\"emissiveStrength\":4}}},"
    "{\"name\":\"unlit_sheen\",\"extensions\":{\"KHR_materials_unlit\":{},\"KHR_materials_sheen\":"
    "{\"sheenColorFactor\":[1,1,1]}}},"
    "{\"name\":\"no_coat\",\"extensions\":{\"KHR_materials_clearcoat\":{\"clearcoatFactor\":0}}},"
    "{\"name\":\"no_specular\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.5,0.5,1],\"metallicFactor\":0.25},"
    "\"extensions\":{\"KHR_materials_specular\":{\"specularFactor\":0}}}";

static const char *const required =
    "\"extensionsUsed\":[\"KHR_materials_unlit\",\"KHR_materials_clearcoat\",\"KHR_materials_sheen\","
    "\"KHR_materials_ior\",\"KHR_materials_specular\",\"KHR_materials_emissive_strength\"],"
    "\"extensionsRequired\":[\"KHR_materials_unlit\",\"KHR_materials_clearcoat\",\"KHR_materials_sheen\","
    "\"KHR_materials_ior\",\"KHR_materials_specular\"]";

static const tl_material *named(const tl_scene *s, const char *name)
{
    for (size_t i = 0; i < s->material_count; i++)
        if (strcmp(s->materials[i].name, name) == 0) return &s->materials[i];
    TL_CHECK(0 && "material by name");
    return NULL;
}

TL_TEST(gltf_material_extensions_into_models)
{
    static float pos[QUADS][4][3];
    static uint32_t idx[QUADS][6];
    tlf_prim p[QUADS];
    for (int q = 0; q < QUADS; q++) {
        const float c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int k = 0; k < 4; k++) {
            pos[q][k][0] = c[k][0] + 1.5f * (float)q;
            pos[q][k][1] = c[k][1];
            pos[q][k][2] = 0.0f;
        }
        const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
        memcpy(idx[q], t, sizeof t);
        p[q] = (tlf_prim){.mode = -1, .pos = (const float(*)[3])pos[q], .nv = 4, .idx = idx[q], .ni = 6, .material = q};
    }
    char dir[1024], path[1024];
    case_dir(dir, sizeof dir, "gltf_material_extensions_into_models");
    TL_CHECK(tlf_write_prims(dir, "models", p, QUADS, materials, required, path, sizeof path) == 0);
    capture log;
    memset(&log, 0, sizeof log);
    tl_gltf_options o = {.logger = {capture_fn, &log}};
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(path, &o, &s) == TL_OK);
    if (!s) return;
    const tl_material *m;
    if ((m = named(s, "unlit"))) { /* the base colour as it is, though glTF's default metal is 1 */
        TL_CHECK_EQ_U(m->model, TL_MATERIAL_MODEL_UNLIT);
        TL_CHECK(near3(m->albedo, 0.9f, 0.5f, 0.1f, 1e-6f));
    }
    if ((m = named(s, "coat"))) {
        TL_CHECK_EQ_U(m->model, TL_MATERIAL_MODEL_CLEARCOAT);
        TL_CHECK(near(m->clearcoat, 0.7f, 1e-6f) && near(m->clearcoat_roughness, 0.2f, 1e-6f));
    }
    TL_CHECK(strstr(log.warnings_text, "clearcoatTexture is not read") != NULL);
    if ((m = named(s, "sheen"))) {
        TL_CHECK_EQ_U(m->model, TL_MATERIAL_MODEL_SHEEN);
        TL_CHECK(near3(m->sheen_color, 0.5f, 0.4f, 0.3f, 1e-6f) && near(m->sheen_roughness, 0.6f, 1e-6f));
    }
    if ((m = named(s, "ior"))) { /* F0 = ((ior - 1) / (ior + 1))^2 = 1/9 */
        double f0 = (1.0 / 3.0) * (1.0 / 3.0);
        TL_CHECK_EQ_U(m->model, TL_MATERIAL_MODEL_STANDARD);
        TL_CHECK(near3(m->dielectric_f0, (float)f0, (float)f0, (float)f0, 1e-6f));
        TL_CHECK(near3(m->specular, (float)f0, (float)f0, (float)f0, 1e-6f));
    }
    if ((m = named(s, "specular"))) { /* F0 = min(0.04 colour, 1) factor, then mix(F0, base, metal) */
        const double colour[3] = {1, 0.5, 0.25}, base[3] = {0.2, 0.4, 0.6};
        for (int k = 0; k < 3; k++) {
            double f0 = 0.04 * colour[k] * 0.5;
            TL_CHECK(near(m->dielectric_f0[k], (float)f0, 1e-7f));
            TL_CHECK(near(m->specular[k], (float)(f0 + (base[k] - f0) * 0.5), 1e-6f));
        }
    }
    if ((m = named(s, "strength"))) TL_CHECK(near3(m->emissive, 2.0f, 1.0f, 0.0f, 1e-6f));
    if ((m = named(s, "unlit_sheen"))) TL_CHECK_EQ_U(m->model, TL_MATERIAL_MODEL_UNLIT);
    TL_CHECK(strstr(log.warnings_text, "KHR_materials_sheen ignored: the material is unlit") != NULL);
    if ((m = named(s, "no_coat"))) TL_CHECK_EQ_U(m->model, TL_MATERIAL_MODEL_STANDARD);
    if ((m = named(s, "no_specular"))) { /* F0 exactly 0: negative in tl_material, specular = base metal */
        TL_CHECK(m->dielectric_f0[0] < 0.0f && m->dielectric_f0[1] < 0.0f && m->dielectric_f0[2] < 0.0f);
        TL_CHECK(near3(m->specular, 0.125f, 0.125f, 0.125f, 1e-6f));
    }
    TL_CHECK_EQ_U(log.errors, 0);
    tl_scene_destroy(s);
}
