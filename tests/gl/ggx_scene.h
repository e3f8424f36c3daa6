/* The lit plane and sphere of the lighting-model tests (test_ggx_render.c, ggx_scene.c): a ground
 * plane y = 0 and a UV sphere above it, whose interpolated vertex normal at a rasterised point p is
 * exactly normalize(p - centre) (the vertex normals are (v - centre) / radius, affine in v), so the
 * double-precision reference can shade every pixel of the renderer's own geometry. */
#ifndef TL_GGX_SCENE_H
#define TL_GGX_SCENE_H

#include <stdint.h>

#include "lighting_ref.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

#define GGX_SPHERE_SEGMENTS 48
#define GGX_SPHERE_RINGS 24
#define GGX_SPHERE_VERTICES ((GGX_SPHERE_SEGMENTS + 1) * (GGX_SPHERE_RINGS + 1))
#define GGX_MAX_LIGHTS 4

typedef struct ggx_scene {
    tl_vertex v[4 + GGX_SPHERE_VERTICES];
    uint32_t idx[6 + GGX_SPHERE_SEGMENTS * GGX_SPHERE_RINGS * 6];
    tl_object obj[2];
    tl_material mat[2]; /* 0 plane, 1 sphere */
    tl_light lights[GGX_MAX_LIGHTS];
    tl_scene s;
    double centre[3], radius; /* the sphere, world space */
} ggx_scene;

/* Plane [-6,6]^2 at y = 0, sphere of radius 1 at (0, 1.3, 0); a point, a spot and a directional
 * light; camera at (0, 2.6, 5.2) looking at (0, 0.9, 0). Materials: a rough grey dielectric plane
 * and a gold metal sphere (F0 from the base colour, albedo 0, as the glTF loader converts a metal),
 * glosses that 8 bits store exactly. */
void ggx_scene_build(ggx_scene *g);

/* The view matrix of the scene's camera (column-major, as the renderer builds it: right-handed,
 * looking down -Z). */
void ggx_view_matrix(const tl_camera *c, double m[16]);

/* The scene's lights in view space for the reference. */
size_t ggx_ref_lights(const ggx_scene *g, const double view[16], tl_ref_light *out);

/* Which surface a view-space point of the frame lies on: 0 plane, 1 sphere, -1 neither (an edge). */
int ggx_classify(const ggx_scene *g, const double view[16], const double p[3], double n_view[3]);

/* The reference surface of material `m` as a mode stores it: thin modes keep gloss in 8 bits;
 * thin-deferred keeps F0 as the 8-bit square root of its luminance (grey). */
void ggx_ref_surface(const tl_material *m, tl_render_mode mode, tl_ref_surface *out);

#endif
