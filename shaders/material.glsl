// Material evaluation shared by every geometry pass (G-buffer, material, forward, transparent).
// Permutations (frame plan): TL_HAS_UV, TL_NORMAL_MAP, TL_MR_TEXTURE, TL_EMISSIVE_TEXTURE,
// TL_OCCLUSION, TL_ALPHA_MASK, TL_VCOLOR (vertex colours), TL_UV1 (a second UV set); per-material
// switches are uniforms (u_texture_mask, u_uv1_mask, u_material_flags).

#ifndef TL_MATERIAL_GLSL
#define TL_MATERIAL_GLSL

// One std140 record per material (tl__material_ubo in src/render/scene/scene_gpu.h), bound as a
// range of the scene's material buffer when the material changes.
layout(std140, binding = TL_UBO_MATERIAL) uniform tl_material_block {
    vec3 u_albedo;
    float u_gloss;
    vec3 u_specular;
    float u_alpha;
    vec3 u_emissive;
    float u_alpha_cutoff;
    float u_metallic;
    float u_roughness;
    float u_normal_scale;
    float u_occlusion_strength;
    int u_material_flags; // TL_MATERIAL_* of scene.h
    int u_texture_mask;   // 1 albedo, 2 normal, 4 metallic-roughness, 8 emissive, 16 occlusion
    int u_uv1_mask;       // the same bits: the maps that read the second UV set
    int u_material_model; // tl_material_model (material_models.glsl); the parameters below
    vec3 u_dielectric_f0; // TL_MATERIAL_METALLIC_ROUGHNESS: F0 of the dielectric (0.04 by default)
    float u_clearcoat;
    vec3 u_sheen_color;
    float u_sheen_roughness;
    float u_clearcoat_roughness;
    float u_wrap;
    float u_toon_steps;
    uint u_material_index; // visibility's resolve: the material whose pixels it shades
};
layout(binding = TL_UNIT_ALBEDO_TEXTURE) uniform sampler2D u_albedo_texture;       // sRGB
layout(binding = TL_UNIT_NORMAL_TEXTURE) uniform sampler2D u_normal_texture;
layout(binding = TL_UNIT_MR_TEXTURE) uniform sampler2D u_mr_texture;
layout(binding = TL_UNIT_EMISSIVE_TEXTURE) uniform sampler2D u_emissive_texture;   // sRGB
layout(binding = TL_UNIT_OCCLUSION_TEXTURE) uniform sampler2D u_occlusion_texture;

#ifdef TL_VIS_RESOLVE
// visibility's resolve (vis_resolve.comp.glsl): the attributes rebuilt from the pixel's triangle
// (vis_rebuild.glsl), and each UV set's screen-space derivatives for the texture's level of detail
vec3 v_normal = vec3(0.0);
vec2 v_uv = vec2(0.0), v_uv_dx = vec2(0.0), v_uv_dy = vec2(0.0), v_uv1_dx = vec2(0.0), v_uv1_dy = vec2(0.0);
vec4 v_tangent = vec4(0.0);
vec3 v_view_position = vec3(0.0);
uint v_object = 0u;
bool v_front_facing = true;
#define TL_FRONT_FACING v_front_facing
#ifdef TL_VCOLOR
vec4 v_color = vec4(1.0);
#endif
#ifdef TL_UV1
vec2 v_uv1 = vec2(0.0);
#endif
#else
#define TL_FRONT_FACING gl_FrontFacing
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
in vec3 v_view_position;
flat in uint v_object;
#ifdef TL_VCOLOR
in vec4 v_color;
#endif
#ifdef TL_UV1
in vec2 v_uv1;
#endif
#endif

// The texture coordinates of map `bit` (a bit of u_texture_mask).
vec2 tl_uv(int bit)
{
#ifdef TL_UV1
    return (u_uv1_mask & bit) != 0 ? v_uv1 : v_uv;
#else
    return v_uv;
#endif
}

// Map `bit` (a bit of u_texture_mask) of `tex` at the pixel: the rasteriser's derivatives, or in
// visibility's resolve the analytic ones of the rebuilt UVs (the same level of detail).
#ifdef TL_VIS_RESOLVE
vec4 tl_map(sampler2D tex, int bit)
{
#ifdef TL_UV1
    if ((u_uv1_mask & bit) != 0) return textureGrad(tex, v_uv1, v_uv1_dx, v_uv1_dy);
#endif
    return textureGrad(tex, v_uv, v_uv_dx, v_uv_dy);
}
#else
vec4 tl_map(sampler2D tex, int bit) { return texture(tex, tl_uv(bit)); }
#endif

struct tl_surface {
    vec3 albedo;   // linear diffuse colour
    vec3 specular; // F0
    float gloss;
    vec3 emissive;
    float alpha;
    float occlusion; // scales the ambient term
};

// The metallic-roughness conversion of scene.h / docs/gltf.md, per pixel.
tl_surface tl_material_surface()
{
    tl_surface s;
    vec4 base = vec4(u_albedo, u_alpha);
#ifdef TL_HAS_UV
    if ((u_texture_mask & 1) != 0) base *= tl_map(u_albedo_texture, 1);
#endif
#ifdef TL_VCOLOR
    base *= v_color;
#endif
    s.albedo = base.rgb;
    s.alpha = base.a;
    s.specular = u_specular;
    s.gloss = u_gloss;
#ifdef TL_MR_TEXTURE
    if ((u_material_flags & 8) != 0) {
        float metal = u_metallic, rough = u_roughness;
        if ((u_texture_mask & 4) != 0) {
            vec4 mr = tl_map(u_mr_texture, 4);
            metal *= mr.b;
            rough *= mr.g;
        }
        metal = clamp(metal, 0.0, 1.0);
        s.specular = mix(u_dielectric_f0, base.rgb, metal);
        s.albedo = base.rgb * (1.0 - metal);
        s.gloss = clamp(1.0 - rough, 0.0, 1.0);
    }
#endif
    s.emissive = u_emissive;
#ifdef TL_EMISSIVE_TEXTURE
    if ((u_texture_mask & 8) != 0) s.emissive *= tl_map(u_emissive_texture, 8).rgb;
#endif
    s.occlusion = 1.0;
#ifdef TL_OCCLUSION
    if ((u_texture_mask & 16) != 0)
        s.occlusion = 1.0 + u_occlusion_strength * (tl_map(u_occlusion_texture, 16).r - 1.0);
#endif
    return s;
}

// Alpha test of MASK materials; true when the fragment is to be discarded.
bool tl_material_masked(tl_surface s)
{
#ifdef TL_ALPHA_MASK
    return (u_material_flags & 2) != 0 && s.alpha < u_alpha_cutoff;
#else
    return false;
#endif
}

// View-space shading normal: the interpolated normal facing the viewer, perturbed by the normal map.
vec3 tl_material_normal()
{
    vec3 n = v_normal;
    float len2 = dot(n, n);
    n = len2 > 1e-30 ? n * inversesqrt(len2) : vec3(0.0, 0.0, 1.0);
    if (!TL_FRONT_FACING) n = -n; // double-sided surfaces face the viewer
#ifdef TL_NORMAL_MAP
    if ((u_texture_mask & 2) != 0) {
        vec3 t = v_tangent.xyz - n * dot(n, v_tangent.xyz);
        float tl2 = dot(t, t);
        if (tl2 > 1e-20) {
            t *= inversesqrt(tl2);
            vec3 b = cross(n, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
            vec3 m = tl_map(u_normal_texture, 2).xyz * 2.0 - 1.0;
            m.xy *= u_normal_scale;
            vec3 p = t * m.x + b * m.y + n * m.z;
            float pl2 = dot(p, p);
            if (pl2 > 1e-20) n = p * inversesqrt(pl2);
        }
    }
#endif
    return n;
}

#endif
