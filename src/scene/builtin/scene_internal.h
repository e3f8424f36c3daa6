/* Private to the built-in scenes (src/scene/builtin): allocation through the scene's allocator, the
 * mesh builder the primitive generators write into, the procedural textures and the crypt's
 * dimensions shared by the geometry and the light placement. */
#ifndef TL_SCENE_INTERNAL_H
#define TL_SCENE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/scene.h"

/* Allocation: src/core/alloc.h (through the scene's allocator, zeroed = malloc/free). */
#include "core/alloc.h"

/* ---- deterministic random numbers (splitmix64) ---------------------------------------------- */

typedef struct tl__rng {
    uint64_t s;
} tl__rng;

static inline uint64_t tl__rng_u64(tl__rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1). */
static inline double tl__rng_unit(tl__rng *r) { return (double)(tl__rng_u64(r) >> 11) * 0x1.0p-53; }

/* Uniform in [lo, hi). */
static inline float tl__rng_range(tl__rng *r, float lo, float hi)
{
    return lo + (hi - lo) * (float)tl__rng_unit(r);
}

/* ---- mesh builder (mesh_build.c) ------------------------------------------------------------ */

/* The layout runs twice: once with `counting` set, which only counts vertices, indices and objects
 * (nothing is written, the arrays may be NULL), then with arrays of exactly those sizes. Every
 * generator makes the same calls in both passes, so the counts agree. */
typedef struct tl__builder {
    int counting;
    tl_vertex *vertices;
    size_t vertex_count;
    size_t vertex_capacity;
    uint32_t *indices;
    size_t index_count;
    size_t index_capacity;
    tl_object *objects;
    size_t object_count;
    size_t object_capacity;
    /* the object being built */
    size_t object_first_vertex;
    size_t object_first_index;
    uint32_t material;
    float uv_scale;  /* texture repeats per metre for the current object */
    int overflow;    /* a capacity would be exceeded (a bug: the passes disagreed) */
} tl__builder;

void tl__begin_object(tl__builder *b, uint32_t material, float uv_scale);
/* Closes the object: index range and world bounds (from its vertices). Returns its index. */
size_t tl__end_object(tl__builder *b);

/* Appends a vertex. The tangent is dpdu made orthogonal to n; w is the sign that makes
 * cross(n, tangent) * w follow dpdv. Returns its index (relative to the whole scene). */
uint32_t tl__vertex(tl__builder *b, const float p[3], const float n[3], const float uv[2],
                    const float dpdu[3], const float dpdv[3]);
/* Appends a triangle; in the writing pass its order is made counter-clockwise as seen from the
 * side its vertex normals point to. */
void tl__triangle(tl__builder *b, uint32_t i0, uint32_t i1, uint32_t i2);
/* Two triangles (a, b, c) and (a, c, d). */
void tl__quad_indices(tl__builder *b, uint32_t a, uint32_t c1, uint32_t c2, uint32_t d);

/* A flat quad p0..p3 (in order around its edge) with normal n, subdivided nu x nv; UVs are the
 * world position projected on the unit axes (p1 - p0) and n x (p1 - p0), times the object's uv
 * scale, so neighbouring quads in one plane continue each other's texture. */
void tl__flat_quad(tl__builder *b, const float p0[3], const float p1[3], const float p2[3],
                   const float p3[3], const float n[3], uint32_t nu, uint32_t nv);

/* A right prism: the convex polygon pts[0..count) (coordinates along axes a and bax, from origin)
 * extruded by `length` along the unit vector e. Hard edges everywhere. */
void tl__prism(tl__builder *b, const float origin[3], const float a[3], const float bax[3],
               const float e[3], float length, const float (*pts)[2], size_t count);

/* An axis-aligned box rotated by yaw (radians, about +Y) around its centre. */
void tl__box(tl__builder *b, const float centre[3], const float half[3], float yaw);

/* A surface of revolution about the vertical axis through `centre`. The profile runs from the
 * bottom of the object to its top (outward normals) or, with `inward`, is seen from inside.
 * Points with r == 0 are poles. A `crease` point splits the profile into smooth runs with a hard
 * edge there. `square` (>= 2, 0 meaning 2) turns the cross-section into the superellipse
 * |x|^s + |z|^s = r^s (2 is a circle), for cushion capitals. */
typedef struct tl__profile_point {
    float r;
    float y;
    float square;
    int crease;
} tl__profile_point;

typedef struct tl__lathe_desc {
    float centre[3];
    const tl__profile_point *points;
    size_t count;
    uint32_t segments;
    float phi0, phi1;  /* angle range (radians, measured from +X towards +Z); equal = full turn */
    int inward;
} tl__lathe_desc;

void tl__lathe(tl__builder *b, const tl__lathe_desc *d);

/* One bay of a groin vault: two semicircular barrels of radius r springing at y0 over the square
 * bay [cx - r, cx + r] x [cz - r, cz + r], crossing in four groins; seen from below. */
void tl__groin_vault(tl__builder *b, float cx, float cz, float r, float y0, uint32_t n);

/* A round arch of rectangular section: centre at the springing line, span along unit `span`
 * (horizontal), intrados radius ri, extrados ro, thickness 2 * hw across the span. */
void tl__arch(tl__builder *b, const float centre[3], const float span[3], float ri, float ro,
              float hw, uint32_t segments);

/* A wall panel seen from the side its normal n points to. u runs along unit U = Y x n from
 * `origin` (at y = origin[1]); the panel spans u in [u0, u1] and rises to a lunette: height
 * y_spring above the origin, then a semicircle of radius (w / 2) centred at u = w / 2, clamped to
 * y_spring outside [0, w]; `top_margin` is added to the whole top edge. With `niche`, a
 * round-headed opening of half-width na centred at w / 2 (sill ns, head springing at nh) is cut
 * out and a recess of depth nd is built behind it (as part of the same object). */
typedef struct tl__wall_desc {
    float origin[3];
    float normal[3];
    float w;
    float u0, u1;
    float y_spring;
    float top_margin;
    float level_sill;    /* horizontal edges every wall shares, so neighbours match */
    float level_spring;
    uint32_t lunette_segments;
    int niche;
    float na, nd;
    uint32_t niche_segments;
} tl__wall_desc;

void tl__wall(tl__builder *b, const tl__wall_desc *d);
/* The recess behind a wall's niche, as its own object (call between begin/end). */
void tl__niche_recess(tl__builder *b, const tl__wall_desc *d);

/* ---- procedural textures (textures.c) ------------------------------------------------------- */

enum {
    TL__TEX_FLAGSTONE = 0,
    TL__TEX_ASHLAR,
    TL__TEX_MARBLE,
    TL__TEX_TILES,
    TL__TEX_COUNT
};

/* Size (width = height) of each generated texture, and metres one repeat covers. */
uint32_t tl__texture_size(int which);
float tl__texture_metres(int which);
const char *tl__texture_name(int which);
/* Fills size * size * 4 bytes of sRGB-encoded RGBA8 (alpha 255), rows top to bottom. */
void tl__texture_generate(int which, uint8_t *rgba);

/* ---- the crypt's plan (default_scene.c, crypt_lights.c) ------------------------------------- */

/* Metres. The hall spans x in [-TL__HALL_HALF_X, +], z in [TL__HALL_Z0, TL__HALL_Z1], floor at 0;
 * square bays of TL__BAY with groin vaults springing at TL__SPRING, crown TL__SPRING + TL__BAY/2.
 * Columns stand at x = +-TL__BAY / 2 on every interior bay line; the apse is a half-cylinder of
 * radius TL__BAY / 2 behind the middle bay of the z = TL__HALL_Z0 wall. */
#define TL__BAY 5.0f
#define TL__BAYS_X 3
#define TL__BAYS_Z 8
#define TL__HALL_HALF_X 7.5f
#define TL__HALL_Z0 (-20.0f)
#define TL__HALL_Z1 20.0f
#define TL__SPRING 5.0f
#define TL__RIB_DEPTH 0.35f
#define TL__RIB_HALF_WIDTH 0.25f
#define TL__COLUMN_CLEAR 0.7f /* half-width of the square around a column axis kept free of lights */

/* Height of the underside of the vault or of a rib at plan point (x, z) (>= TL__SPRING - small
 * inside the hall); used to keep lights below the ceiling. */
float tl__crypt_ceiling(float x, float z);

/* The scene's lights (after its geometry): point, spot then directional. `solids` are world
 * AABBs (min xyz, max xyz) that lights must avoid. */
typedef struct tl__light_plan {
    uint32_t point_lights;
    uint32_t spot_lights;
    int directional;
    uint64_t seed;
    const float (*solids)[6];
    size_t solid_count;
    const float (*warm_spots)[3]; /* brazier tops: the first point lights sit above them */
    size_t warm_spot_count;
    int shadows;                  /* the braziers and the moonlight cast shadows */
} tl__light_plan;

void tl__crypt_lights(const tl__light_plan *plan, tl_light *out);

#endif
