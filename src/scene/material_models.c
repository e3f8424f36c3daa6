/* The material models' parameters (scene.h tl_material.model; docs/lighting.md, "Material
 * models"): their zero defaults and their checks, in one place for the renderer and the tools. */
#include <math.h>
#include <stdio.h>

#include "scene/validate.h"

static const char *const tl__model_names[TL_MATERIAL_MODEL_COUNT_] = {"standard", "unlit", "clearcoat",
                                                                      "sheen",    "wrap",  "toon"};

const char *tl_material_model_name(uint32_t model)
{
    return model < TL_MATERIAL_MODEL_COUNT_ ? tl__model_names[model] : "unknown";
}

static float tl__clamp01(float v) { return !(v > 0.0f) ? 0.0f : v > 1.0f ? 1.0f : v; }

void tl__material_model_defaults(tl_material *m)
{
    int f0 = m->dielectric_f0[0] != 0.0f || m->dielectric_f0[1] != 0.0f || m->dielectric_f0[2] != 0.0f;
    for (int k = 0; k < 3; k++) m->dielectric_f0[k] = !f0 ? 0.04f : tl__clamp01(m->dielectric_f0[k]);
    m->clearcoat = m->clearcoat == 0.0f ? 1.0f : tl__clamp01(m->clearcoat);
    m->clearcoat_roughness = tl__clamp01(m->clearcoat_roughness);
    int sheen = m->sheen_color[0] != 0.0f || m->sheen_color[1] != 0.0f || m->sheen_color[2] != 0.0f;
    for (int k = 0; k < 3; k++) m->sheen_color[k] = !sheen ? 1.0f : m->sheen_color[k] < 0.0f ? 0.0f : m->sheen_color[k];
    m->sheen_roughness = m->sheen_roughness == 0.0f ? 0.5f : tl__clamp01(m->sheen_roughness);
    if (m->sheen_roughness < 0.07f) m->sheen_roughness = 0.07f;
    m->wrap = m->wrap == 0.0f ? 0.5f : tl__clamp01(m->wrap);
    if (m->toon_steps == 0) m->toon_steps = 3;
}

tl_result tl__material_model_check(const tl_material *m, const char *what, char *message, size_t size)
{
    if (m->model >= TL_MATERIAL_MODEL_COUNT_) {
        snprintf(message, size, "%s.model = %u: not a tl_material_model (0..%d)", what, m->model,
                 TL_MATERIAL_MODEL_COUNT_ - 1);
        return TL_ERROR_INVALID_ARGUMENT;
    }
    const struct { float v; const char *name; } fields[] = {
        {m->dielectric_f0[0], "dielectric_f0[0]"}, {m->dielectric_f0[1], "dielectric_f0[1]"},
        {m->dielectric_f0[2], "dielectric_f0[2]"}, {m->clearcoat, "clearcoat"},
        {m->clearcoat_roughness, "clearcoat_roughness"}, {m->sheen_color[0], "sheen_color[0]"},
        {m->sheen_color[1], "sheen_color[1]"}, {m->sheen_color[2], "sheen_color[2]"},
        {m->sheen_roughness, "sheen_roughness"}, {m->wrap, "wrap"}};
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; i++) {
        if (!isfinite(fields[i].v)) {
            snprintf(message, size, "%s.%s = %g: not finite", what, fields[i].name, (double)fields[i].v);
            return TL_ERROR_INVALID_ARGUMENT;
        }
    }
    if (m->toon_steps > 64) {
        snprintf(message, size, "%s.toon_steps = %u: at most 64 (0 = 3)", what, m->toon_steps);
        return TL_ERROR_INVALID_ARGUMENT;
    }
    return TL_OK;
}
