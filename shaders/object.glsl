// Per-object data of the geometry passes: one std430 record per object, selected by the object id
// the draw passes as its base instance (tl__object_gpu in src/render/scene/scene_gpu.h).

#ifndef TL_OBJECT_GLSL
#define TL_OBJECT_GLSL

// The normal matrix's columns, each followed in its 16 bytes by a word of visibility's resolve.
struct tl_object_data {
    mat4 model;       // object to world
    vec3 normal_view0; // the inverse transpose of (view * model), upper 3x3, by column
    uint first_index;  // visibility: the object's first index in the scene's index buffer
    vec3 normal_view1;
    uint material;     // visibility: its material
    vec3 normal_view2;
    uint pad;
    uvec4 lights;     // forward: first index and count in the light index list; z: stipple layer (0: none)
};

layout(std430, binding = TL_SSBO_OBJECTS) readonly buffer tl_object_buffer { tl_object_data tl_objects[]; };

mat3 tl_object_normal_view(uint o)
{
    return mat3(tl_objects[o].normal_view0, tl_objects[o].normal_view1, tl_objects[o].normal_view2);
}
uint tl_object_first_index(uint o) { return tl_objects[o].first_index; }
uint tl_object_material(uint o) { return tl_objects[o].material; }

#endif
