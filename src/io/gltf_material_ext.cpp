// glTF material extensions to tl_material's models (docs/gltf.md, "Material extensions"):
// KHR_materials_unlit, _clearcoat and _sheen choose the model (one per material: unlit, then
// clearcoat, then sheen, the others ignored with a warning); _ior and _specular give the dielectric
// F0 of the metallic-roughness conversion. Their textures are not read (a warning names them).
#include <cmath>

#include "gltf_internal.h"
#include "gltf_math.h"

namespace tl_gltf {
namespace {

const tinygltf::Value *extension(const tinygltf::Material &g, const char *name)
{
    auto it = g.extensions.find(name);
    return it != g.extensions.end() ? &it->second : nullptr;
}

// A number of `v`'s object, or `fallback` when absent or not a finite number.
double number(const tinygltf::Value *v, const char *key, double fallback)
{
    if (!v || !v->IsObject() || !v->Has(key)) return fallback;
    const tinygltf::Value &x = v->Get(key);
    double d = x.IsNumber() || x.IsInt() ? x.GetNumberAsDouble() : NAN;
    return std::isfinite(d) ? d : fallback;
}

// An RGB array of `v`'s object into out (left as it is when absent or malformed).
void colour(const context &c, const tinygltf::Value *v, const char *key, const std::string &what, double out[3])
{
    if (!v || !v->IsObject() || !v->Has(key)) return;
    const tinygltf::Value &a = v->Get(key);
    if (!a.IsArray() || a.ArrayLen() != 3) {
        warn(c, what + "." + key + " needs 3 numbers; using the default");
        return;
    }
    for (int i = 0; i < 3; i++) {
        double d = a.Get(i).IsNumber() || a.Get(i).IsInt() ? a.Get(i).GetNumberAsDouble() : NAN;
        out[i] = std::isfinite(d) ? d : out[i];
    }
}

double clamp01(double v) { return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v; }

void textures_ignored(const context &c, const tinygltf::Value *v, const std::string &what, const char *const *keys)
{
    for (; v && v->IsObject() && *keys; keys++)
        if (v->Has(*keys)) warn(c, what + "." + *keys + " is not read (the factor alone is used)");
}

// _ior and _specular: F0 = min(((ior - 1) / (ior + 1))^2 specularColorFactor, 1) specularFactor,
// into dielectric_f0 and the constant conversion in specular.
void dielectric(const context &c, const tinygltf::Material &g, const std::string &name, const float base[3],
                float metal, tl_material *out)
{
    const tinygltf::Value *ior = extension(g, "KHR_materials_ior"), *spec = extension(g, "KHR_materials_specular");
    if (!ior && !spec) return;
    double eta = number(ior, "ior", 1.5);
    if (eta < 1.0 && eta != 0.0) eta = 1.5; // the specification: ior is 0 or >= 1
    double r = eta == 0.0 ? 1.0 : (eta - 1.0) / (eta + 1.0);
    double tint[3] = {1, 1, 1}, factor = clamp01(number(spec, "specularFactor", 1.0));
    colour(c, spec, "specularColorFactor", name + ".KHR_materials_specular", tint);
    static const char *const keys[] = {"specularTexture", "specularColorTexture", nullptr};
    textures_ignored(c, spec, name + ".KHR_materials_specular", keys);
    for (int i = 0; i < 3; i++) {
        double f0 = std::fmin(r * r * std::fmax(tint[i], 0.0), 1.0) * factor;
        out->dielectric_f0[i] = f0 > 0.0 ? to_float(f0) : -1.0f; // negative: exactly 0
        out->specular[i] = to_float(f0 + (base[i] - f0) * metal);
    }
}

} // namespace

void convert_material_extensions(const context &c, const tinygltf::Material &g, const std::string &name,
                                 const float base[3], float metal, tl_material *out)
{
    dielectric(c, g, name, base, metal, out);
    const tinygltf::Value *unlit = extension(g, "KHR_materials_unlit");
    const tinygltf::Value *coat = extension(g, "KHR_materials_clearcoat"), *sheen = extension(g, "KHR_materials_sheen");
    double coat_factor = clamp01(number(coat, "clearcoatFactor", 0.0));
    double sheen_colour[3] = {0, 0, 0};
    colour(c, sheen, "sheenColorFactor", name + ".KHR_materials_sheen", sheen_colour);
    bool has_sheen = sheen_colour[0] > 0.0 || sheen_colour[1] > 0.0 || sheen_colour[2] > 0.0;
    if (unlit) { // the base colour as it is: no metal, no light
        out->model = TL_MATERIAL_MODEL_UNLIT;
        for (int i = 0; i < 3; i++) out->albedo[i] = base[i] > 0.0f ? base[i] : -1.0f;
        out->flags &= ~TL_MATERIAL_METALLIC_ROUGHNESS;
    } else if (coat && coat_factor > 0.0) {
        out->model = TL_MATERIAL_MODEL_CLEARCOAT;
        out->clearcoat = to_float(coat_factor);
        out->clearcoat_roughness = to_float(clamp01(number(coat, "clearcoatRoughnessFactor", 0.0)));
        static const char *const keys[] = {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture",
                                           nullptr};
        textures_ignored(c, coat, name + ".KHR_materials_clearcoat", keys);
    } else if (has_sheen) {
        out->model = TL_MATERIAL_MODEL_SHEEN;
        for (int i = 0; i < 3; i++) out->sheen_color[i] = sheen_colour[i] > 0.0 ? to_float(sheen_colour[i]) : -1.0f;
        out->sheen_roughness = to_float(std::fmax(clamp01(number(sheen, "sheenRoughnessFactor", 0.0)), 0.07));
        static const char *const keys[] = {"sheenColorTexture", "sheenRoughnessTexture", nullptr};
        textures_ignored(c, sheen, name + ".KHR_materials_sheen", keys);
    }
    const char *chosen = tl_material_model_name(out->model);
    if (unlit && coat && coat_factor > 0.0)
        warn(c, name + ": KHR_materials_clearcoat ignored: the material is " + chosen);
    if ((unlit || (coat && coat_factor > 0.0)) && has_sheen)
        warn(c, name + ": KHR_materials_sheen ignored: the material is " + chosen);
}

} // namespace tl_gltf
