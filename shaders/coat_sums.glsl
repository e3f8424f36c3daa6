// TL_COAT_SUMS (thin-lpp, tl_renderer_options.clearcoat = TL_CLEARCOAT_SUMS, a clearcoat drawn):
// the coat's own specular sum S1 + S2 (F = 1) at the coat's roughness, beside the base's sums at
// its own (docs/lighting.md, "Material models"). The G-buffer pass writes the coat's gloss into
// COAT_GLOSS as 1 + 254 gloss (0: no coat there); the light passes add each light's coat weight
// into LIGHT_COAT where a coat is; the clearcoat material program reads that sum.
#ifndef TL_COAT_SUMS_GLSL
#define TL_COAT_SUMS_GLSL

#ifdef TL_LIGHT_ACCUM
layout(binding = TL_UNIT_COAT_GLOSS) uniform sampler2D u_coat_gloss;

// The coat's gloss at px; false where no clearcoat was drawn.
bool tl_coat_gloss(ivec2 px, out float gloss)
{
    float q = floor(texelFetch(u_coat_gloss, px, 0).r * 255.0 + 0.5);
    gloss = clamp((q - 1.0) / 254.0, 0.0, 1.0);
    return q > 0.5;
}
#endif

#ifdef TL_OUT_COAT_GLOSS
// The G-buffer pass's byte: the coat's gloss (1 - its perceptual roughness) on 254 steps.
float tl_coat_gloss_byte()
{
    if (u_material_model != 2) return 0.0;
    return (1.0 + floor(254.0 * clamp(1.0 - u_clearcoat_roughness, 0.0, 1.0) + 0.5)) / 255.0;
}
#endif

#endif
