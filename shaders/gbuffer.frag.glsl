// Pass 1: G-buffer. The plan defines TL_OUT_<TARGET>=<location> for each target the pass writes:
// RT0 (octahedral normal + gloss), RT1 (Y, checkerboard chroma, specular intensity), the FAT_*
// full-float reference layout, HDR (deferred modes: emissive + ambient, which the light pass adds
// to). TL_DEPTH_ONLY writes depth. TL_VISIBILITY: the visibility buffer's id (VIS_ID), and RT0 only
// when an effect reads normals.
#include "codec.glsl"
#include "frame.glsl"
#include "lighting.glsl"
#include "material.glsl"
#ifdef TL_IBL
#include "ibl.glsl" // image-based light into HDR (thin-deferred, fat), as ambient
#endif
#ifdef TL_STIPPLE
#include "stipple.glsl" // transparent layers: one pixel of each 2x2 quad each
#endif

#ifdef TL_OUT_RT0
layout(location = TL_OUT_RT0) out vec4 o_rt0;
#endif
#ifdef TL_OUT_RT1
layout(location = TL_OUT_RT1) out vec4 o_rt1;
#endif
// Each fat target on its own: the plan drops the ones no later pass reads (with SSAO or
// reflections but no lights, position and normal are read and albedo is not).
#if defined(TL_OUT_FAT_POSITION) || defined(TL_OUT_FAT_NORMAL) || defined(TL_OUT_FAT_ALBEDO)
#define TL_OUT_FAT
#endif
#ifdef TL_OUT_FAT_POSITION
layout(location = TL_OUT_FAT_POSITION) out vec4 o_position;
#endif
#ifdef TL_OUT_FAT_NORMAL
layout(location = TL_OUT_FAT_NORMAL) out vec4 o_normal;
#endif
#ifdef TL_OUT_FAT_ALBEDO
layout(location = TL_OUT_FAT_ALBEDO) out vec4 o_albedo;
#endif
#ifdef TL_OUT_FAT_MATERIAL
layout(location = TL_OUT_FAT_MATERIAL) out vec4 o_material;
#endif
#ifdef TL_OUT_HDR
layout(location = TL_OUT_HDR) out vec4 o_hdr;
#endif
#ifdef TL_OUT_VIS_ID
layout(location = TL_OUT_VIS_ID) out uint o_vis_id;
#endif
#ifdef TL_OUT_COAT_GLOSS
layout(location = TL_OUT_COAT_GLOSS) out vec4 o_coat_gloss;
#include "coat_sums.glsl" // the coat's own sums: its gloss here, RT0 keeps the base's
#endif

// The deferred modes' light pass shades by the material model where the G-buffer stores it
// (fat_models.glsl): fat in fat.position.w, thin-deferred in RT1.a (unless SSAO stores occlusion
// there).
#if defined(TL_OUT_RT1) && defined(TL_OUT_HDR) && !defined(TL_AO_STORE)
#define TL_THIN_DEFERRED_BYTE // thin-deferred with RT1.a free
#endif
#if defined(TL_MATERIAL_MODELS) && (defined(TL_OUT_FAT_POSITION) || defined(TL_THIN_DEFERRED_BYTE))
#define TL_DEFERRED_MODELS
#endif

#ifdef TL_DEFERRED_MODELS
// fat: 1 + model + frac / 2 (frac: the wrap, the clearcoat's 8-bit factor and roughness, or the
// sheen's 4-bit colour and 8-bit roughness).
float tl_fat_model_word()
{
    float frac = 0.0;
    if (u_material_model == 4) frac = clamp(u_wrap, 0.0, 1.0);
    if (u_material_model == 2) frac = float(tl_unorm8(u_clearcoat) * 256u + tl_unorm8(u_clearcoat_roughness)) / 65536.0;
    if (u_material_model == 3) {
        uvec3 c = uvec3(clamp(u_sheen_color, 0.0, 1.0) * 15.0 + 0.5);
        frac = float((c.r << 16) | (c.g << 12) | (c.b << 8) | tl_unorm8(u_sheen_roughness)) / 1048576.0;
    }
    return 1.0 + float(u_material_model) + 0.5 * frac;
}

// thin-deferred: model | q5 << 3 (q5: the wrap or the coat's roughness in 5 bits), as RT1.a's unorm.
float tl_thin_model_byte()
{
    float param = u_material_model == 4 ? u_wrap : u_material_model == 2 ? u_clearcoat_roughness : 0.0;
    uint q = uint(clamp(param, 0.0, 1.0) * 31.0 + 0.5);
    return float(uint(u_material_model) | (q << 3)) / 255.0;
}

// The G-buffer pass's HDR (ambient and emissive) under the model, as forward's tl_model_shade has
// them: unlit is its colour, a clearcoat's base is scaled by 1 - the coat's Fresnel.
vec3 tl_deferred_model_hdr(tl_surface s, vec3 n, vec3 c)
{
    if (u_material_model == 1) return s.albedo + s.emissive;
    if (u_material_model != 2) return c;
    float nv = clamp(dot(n, normalize(-v_view_position)), 0.0, 1.0);
#ifdef TL_OUT_FAT_POSITION
    float k = u_clearcoat;
#else
    float k = 1.0; // thin-deferred's light pass takes the coat's factor as 1
#endif
    return c * (1.0 - k * (0.04 + 0.96 * tl_fresnel_weight(nv)));
}
#endif

float tl_linear_to_srgb1(float c)
{
    c = clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? c * 12.92 : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

void main()
{
#ifdef TL_OUT_VIS_ID
    // the object's slot + 1 above the triangle's index within the object's draw (the plan refuses
    // objects and triangles past the bits: pass_visibility.c)
    o_vis_id = ((v_object + 1u) << TL_VIS_TRIANGLE_BITS) | uint(gl_PrimitiveID);
#ifndef TL_OUT_RT0
    // the id alone: the material is read only for the alpha test of a masked material
#ifdef TL_ALPHA_MASK
    if ((u_material_flags & 2) != 0 && tl_material_masked(tl_material_surface())) discard;
#endif
    return;
#endif
#endif
#ifdef TL_STIPPLE
    if (!tl_stipple_owns(tl_stipple_layer(), ivec2(gl_FragCoord.xy))) discard;
#endif
    tl_surface s = tl_material_surface();
    if (tl_material_masked(s)) discard;
#if defined(TL_OUT_RT0) || defined(TL_OUT_FAT)
    vec3 n = tl_material_normal();
#endif
#ifdef TL_OUT_RT0
// thin-lpp (and thin-deferred without the model's byte): a clearcoat's light sums are its coat's
// lobe (material_models.glsl)
#if defined(TL_MATERIAL_MODELS) && !defined(TL_DEFERRED_MODELS) && !defined(TL_COAT_SUMS)
    if (u_material_model == 2) s.gloss = 1.0 - u_clearcoat_roughness;
#endif
#ifdef TL_RT0_RGB10A2
    uint t = tl_rt0_encode_rgb10a2(n, s.gloss, 0u);
    o_rt0 = vec4(float(t & 1023u), float((t >> 10) & 1023u), float((t >> 20) & 1023u), float(t >> 30)) /
            vec4(1023.0, 1023.0, 1023.0, 3.0);
#else
    o_rt0 = vec4(tl_rt0_encode_rgba8(n, s.gloss)) / 255.0;
#endif
#endif
#ifdef TL_OUT_RT1
    // albedo as sRGB-encoded YCbCr (the codec's domain); specular as sqrt of its luminance
    vec3 srgb = vec3(tl_linear_to_srgb1(s.albedo.r), tl_linear_to_srgb1(s.albedo.g), tl_linear_to_srgb1(s.albedo.b));
    uvec2 yc = tl_albedo_encode_pixel(1u, srgb, uvec2(gl_FragCoord.xy));
    uint spec = tl_unorm8(sqrt(clamp(tl_luminance(s.specular), 0.0, 1.0)));
#ifdef TL_AO_STORE
    o_rt1 = vec4(float(yc.x) / 255.0, float(yc.y) / 255.0, float(spec) / 255.0, s.occlusion); // for ssao-apply
#elif defined(TL_DEFERRED_MODELS)
    o_rt1 = vec4(float(yc.x) / 255.0, float(yc.y) / 255.0, float(spec) / 255.0, tl_thin_model_byte());
#else
    o_rt1 = vec4(float(yc.x), float(yc.y), float(spec), 0.0) / 255.0;
#endif
#endif
#ifdef TL_OUT_FAT_POSITION
#ifdef TL_DEFERRED_MODELS
    o_position = vec4(v_view_position, tl_fat_model_word());
#else
    o_position = vec4(v_view_position, 1.0);
#endif
#endif
#ifdef TL_OUT_FAT_NORMAL
    o_normal = vec4(n, s.gloss);
#endif
#ifdef TL_OUT_FAT_ALBEDO
#ifdef TL_AO_STORE
    o_albedo = vec4(s.albedo, s.occlusion); // for ssao-apply
#else
    o_albedo = vec4(s.albedo, 1.0);
#endif
#endif
#ifdef TL_OUT_FAT_MATERIAL
    o_material = vec4(s.specular, 0.0);
#endif
#ifdef TL_OUT_HDR
    vec3 c = s.albedo * u_ambient * s.occlusion + s.emissive;
#ifdef TL_IBL
    c += tl_ibl(s.albedo, s.specular, s.gloss, s.occlusion, tl_material_normal(), normalize(-v_view_position));
#endif
#ifdef TL_DEFERRED_MODELS
    c = tl_deferred_model_hdr(s, n, c); // unlit: albedo and emissive alone (no ambient, no environment)
#endif
    o_hdr = vec4(min(c, vec3(65504.0)), 1.0);
#endif
#ifdef TL_OUT_COAT_GLOSS
    o_coat_gloss = vec4(tl_coat_gloss_byte(), 0.0, 0.0, 0.0);
#endif
}
