// Per-object data of the geometry passes: one std430 record per object, selected by the object id
// the draw passes as its base instance (tl__object_gpu in src/render/scene/scene_gpu.h).

#ifndef TL_OBJECT_GLSL
#define TL_OBJECT_GLSL

struct tl_object_data {
    mat4 model;       // object to world
    mat3 normal_view; // inverse transpose of (view * model), upper 3x3
    uvec4 lights;     // forward: first index and count in the light index list; z: stipple layer (0: none)
};

layout(std430, binding = TL_SSBO_OBJECTS) readonly buffer tl_object_buffer { tl_object_data tl_objects[]; };

#endif
