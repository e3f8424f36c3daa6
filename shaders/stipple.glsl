// Inferred Lighting's stipple (Kircher & Lawrance 2009; docs/frame.md, "2d. Transparency through
// the light buffer"): transparent layer L = 1, 2, 3 owns one pixel of every 2x2 quad of the G-buffer,
// (1, 1), (1, 0) and (0, 1); the opaque surface keeps (0, 0) and every pixel no layer covers. The
// frame gives each visible blended object its own layer, far to near (tl_object_data.lights.z).
#ifndef TL_STIPPLE_GLSL
#define TL_STIPPLE_GLSL

#include "object.glsl"

ivec2 tl_stipple_slot(uint layer)
{
    return layer == 1u ? ivec2(1, 1) : layer == 2u ? ivec2(1, 0) : ivec2(0, 1);
}

uint tl_stipple_layer() { return tl_objects[v_object].lights.z; }

// Whether `layer` owns pixel px (layer 0, an object the frame gave no layer, owns none).
bool tl_stipple_owns(uint layer, ivec2 px)
{
    return layer >= 1u && layer <= 3u && all(equal(px & 1, tl_stipple_slot(layer)));
}

#endif
