// glTF metallic-roughness materials to tl_material, with the one conversion of docs/gltf.md:
//   diffuse = base * (1 - metal), specular F0 = mix(0.04, base, metal), gloss = 1 - rough.
// Without a metallic-roughness texture the constant factors are converted here, on the CPU; with
// one, the renderer converts per pixel (TL_MATERIAL_METALLIC_ROUGHNESS) and albedo holds the base
// colour.
#include <cmath>
#include <cstring>

#include "gltf_internal.h"
#include "gltf_math.h"

namespace tl_gltf {
namespace {

float clamp01(double v, double fallback)
{
    if (!std::isfinite(v)) v = fallback;
    return (float)(v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v);
}

// glTF's default material (no "material" on a primitive): white, fully metallic, fully rough,
// exactly as the specification defines it.
const tinygltf::Material &default_material()
{
    static const tinygltf::Material d;
    return d;
}

// A texture slot: the scene texture's map (index + 1, 0 = none); texCoord 1 sets the map's bit
// (TL_MAP_*) in uv1_maps, and the sets past it are read as TEXCOORD_0 with a warning.
uint32_t slot(const context &c, const tinygltf::Model &m, texture_table *t, const tinygltf::TextureInfo &info,
              uint32_t bit, const std::string &what, uint32_t *uv1_maps)
{
    if (info.index >= 0 && info.texCoord == 1) *uv1_maps |= bit;
    if (info.index >= 0 && info.texCoord > 1)
        warn(c, what + ": texCoord " + std::to_string(info.texCoord) + " is read as TEXCOORD_0");
    return texture_for(c, m, t, info.index, what);
}
template <class Info> tinygltf::TextureInfo plain(const Info &i)
{
    tinygltf::TextureInfo out;
    out.index = i.index;
    out.texCoord = i.texCoord;
    return out;
}

// A positive scale: the material's 0 means "default 1", so an explicit 0 becomes the smallest
// positive value instead.
float positive_scale(double v)
{
    if (!std::isfinite(v)) return 1.0f;
    float f = to_float(v);
    return f == 0.0f ? 1e-6f : f;
}

} // namespace

tl_material convert_material(const context &c, const tinygltf::Model &m, int index, texture_table *t)
{
    if (index >= 0 && (size_t)index >= m.materials.size())
        fail(TL_ERROR_PARSE, "material " + std::to_string(index) + " out of range (" + std::to_string(m.materials.size()) +
                                 " materials)");
    const tinygltf::Material &g = index >= 0 ? m.materials[(size_t)index] : default_material();
    const std::string name = index >= 0 ? element("materials", (size_t)index) : std::string("default material");
    const tinygltf::PbrMetallicRoughness &pbr = g.pbrMetallicRoughness;

    float base[4] = {1, 1, 1, 1};
    if (pbr.baseColorFactor.size() == 4) {
        for (int i = 0; i < 4; i++) base[i] = clamp01(pbr.baseColorFactor[(size_t)i], 1.0);
    } else {
        warn(c, name + ": baseColorFactor needs 4 numbers; using white");
    }
    float metal = clamp01(pbr.metallicFactor, 1.0), rough = clamp01(pbr.roughnessFactor, 1.0);
    float emissive[3] = {0, 0, 0};
    if (g.emissiveFactor.size() == 3) {
        for (int i = 0; i < 3; i++) emissive[i] = clamp01(g.emissiveFactor[(size_t)i], 0.0);
    } else if (!g.emissiveFactor.empty()) {
        warn(c, name + ": emissiveFactor needs 3 numbers; using black");
    }
    auto strength = g.extensions.find("KHR_materials_emissive_strength");
    if (strength != g.extensions.end() && strength->second.Has("emissiveStrength")) {
        double s = strength->second.Get("emissiveStrength").GetNumberAsDouble();
        if (std::isfinite(s) && s >= 0.0)
            for (float &e : emissive) e = to_float(e * s);
    }

    tl_material out = {};
    uint32_t *uv1 = &out.uv1_maps;
    out.albedo_map = slot(c, m, t, pbr.baseColorTexture, TL_MAP_ALBEDO, name + ".baseColorTexture", uv1);
    out.metallic_roughness_map =
        slot(c, m, t, pbr.metallicRoughnessTexture, TL_MAP_METALLIC_ROUGHNESS, name + ".metallicRoughnessTexture", uv1);
    out.normal_map = slot(c, m, t, plain(g.normalTexture), TL_MAP_NORMAL, name + ".normalTexture", uv1);
    out.occlusion_map = slot(c, m, t, plain(g.occlusionTexture), TL_MAP_OCCLUSION, name + ".occlusionTexture", uv1);
    out.emissive_map = slot(c, m, t, g.emissiveTexture, TL_MAP_EMISSIVE, name + ".emissiveTexture", uv1);

    bool mr_map = out.metallic_roughness_map != 0;
    for (int i = 0; i < 3; i++) {
        // With the map, the renderer converts per pixel; without it, here (docs/gltf.md). The
        // specular and gloss fields hold the constant conversion in both cases.
        out.albedo[i] = mr_map ? base[i] : base[i] * (1.0f - metal);
        out.specular[i] = 0.04f + (base[i] - 0.04f) * metal;
        out.emissive[i] = emissive[i];
    }
    // Black on purpose (a black metal that emits nothing): all-zero colour is tl_material's grey
    bool colour = false;
    for (int i = 0; i < 3; i++)
        colour = colour || out.albedo[i] != 0.0f || out.specular[i] != 0.0f || out.emissive[i] != 0.0f;
    if (!colour)
        for (float &a : out.albedo) a = -1.0f;
    out.gloss = 1.0f - rough;
    out.metallic = metal;
    out.roughness = rough;
    out.alpha = base[3];
    out.alpha_cutoff = std::isfinite(g.alphaCutoff) && g.alphaCutoff >= 0.0 ? to_float(g.alphaCutoff) : 0.5f;
    out.normal_scale = positive_scale(g.normalTexture.scale);
    out.occlusion_strength = positive_scale(clamp01(g.occlusionTexture.strength, 1.0));
    out.flags = TL_MATERIAL_MICROFACET; // glTF materials are authored for the GGX model
    if (mr_map) out.flags |= TL_MATERIAL_METALLIC_ROUGHNESS;
    if (g.doubleSided) out.flags |= TL_MATERIAL_DOUBLE_SIDED;
    if (g.alphaMode == "MASK") {
        out.flags |= TL_MATERIAL_ALPHA_MASK;
    } else if (g.alphaMode == "BLEND") {
        out.flags |= TL_MATERIAL_ALPHA_BLEND;
    } else if (g.alphaMode != "OPAQUE") {
        warn(c, name + ": unknown alphaMode \"" + g.alphaMode + "\"; drawing it opaque");
    }
    convert_material_extensions(c, g, name, base, metal, &out); // gltf_material_ext.cpp
    const std::string &label = !g.name.empty() ? g.name : name;
    std::strncpy(out.name, label.c_str(), sizeof out.name - 1);
    return out;
}

} // namespace tl_gltf
