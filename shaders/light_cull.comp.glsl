// Tiled light culling (the light-cull pass): one invocation per screen tile and chunk of
// TL_CULL_CHUNK local lights (tiles.glsl says why chunks), no shared memory
// (a barrier on llvmpipe is a coroutine switch; docs/frame.md says what that cost). It finds the
// tile's depth bounds, then keeps every local light whose range (a sphere; for spot lights also
// the cone) meets the tile's frustum between those depths: first counting, then writing the list
// into space taken with one atomic add. A list that does not fit marks its tile as overflowed.
#define TL_TILES_WRITE
#include "codec.glsl"
#include "tiles.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
#ifdef TL_DEPTH_SAMPLES // MSAA: the bounds of every sample (forward's depth, thin-lpp's depth.msaa)
#ifdef TL_CULL_DEPTH_MSAA
layout(binding = TL_UNIT_DEPTH_MSAA) uniform sampler2DMS u_depth;
#else
layout(binding = TL_UNIT_DEPTH) uniform sampler2DMS u_depth;
#endif
#define TL_CULL_SAMPLES TL_DEPTH_SAMPLES
#define tl_cull_depth(p, s) texelFetch(u_depth, p, s).r
#define tl_cull_size() textureSize(u_depth)
#else
layout(binding = TL_UNIT_DEPTH) uniform sampler2D u_depth;
#define TL_CULL_SAMPLES 1
#define tl_cull_depth(p, s) texelFetch(u_depth, p, 0).r
#define tl_cull_size() textureSize(u_depth, 0)
#endif

// The tile's frustum: four side planes through the eye (inward unit normals) and a bounding
// sphere of its part between the depth bounds (for the cone test).
struct tl_tile_frustum {
    vec3 planes[4];
    float zmin, zmax; // distances along -Z
    vec4 sphere;
    uint depth_mask;  // 2.5D culling: bit i set when a surface lies in the i-th of 32 slices of [zmin, zmax]
    float slice_scale; // slices per unit of distance
};

vec3 tl_tile_point(vec2 ndc, float dist)
{
    return vec3(dist * (ndc.x + u_ray_params.z) / u_ray_params.x, dist * (ndc.y + u_ray_params.w) / u_ray_params.y, -dist);
}

tl_tile_frustum tl_tile_frustum_make(vec2 ndc0, vec2 ndc1, float zmin, float zmax)
{
    tl_tile_frustum f;
    f.planes[0] = normalize(vec3(u_ray_params.x, 0.0, u_ray_params.z + ndc0.x));
    f.planes[1] = normalize(vec3(-u_ray_params.x, 0.0, -(u_ray_params.z + ndc1.x)));
    f.planes[2] = normalize(vec3(0.0, u_ray_params.y, u_ray_params.w + ndc0.y));
    f.planes[3] = normalize(vec3(0.0, -u_ray_params.y, -(u_ray_params.w + ndc1.y)));
    f.zmin = zmin;
    f.zmax = zmax;
    vec3 lo = vec3(3.0e38), hi = vec3(-3.0e38);
    for (int i = 0; i < 8; i++) {
        vec2 c = vec2((i & 1) != 0 ? ndc1.x : ndc0.x, (i & 2) != 0 ? ndc1.y : ndc0.y);
        vec3 p = tl_tile_point(c, (i & 4) != 0 ? zmax : zmin);
        lo = min(lo, p);
        hi = max(hi, p);
    }
    vec3 centre = 0.5 * (lo + hi);
    f.sphere = vec4(centre, length(hi - centre));
    f.depth_mask = 0u;
    f.slice_scale = 32.0 / max(zmax - zmin, 1.0e-6 * max(zmax, 1.0));
    return f;
}

uint tl_slice(tl_tile_frustum f, float dist)
{
    return uint(clamp((dist - f.zmin) * f.slice_scale, 0.0, 31.0));
}

// The per-light tests run twice (counting, then writing): `precise` keeps the compiler from
// contracting or reordering them differently in the two loops, so both give the same answer.
bool tl_sphere_in_tile(tl_tile_frustum f, vec3 c, float r)
{
    for (int i = 0; i < 4; i++) {
        precise float d = (f.planes[i].x * c.x + f.planes[i].y * c.y) + f.planes[i].z * c.z;
        if (d < -r) return false;
    }
    precise float zn = -c.z + r, zf = -c.z - r;
    if (!(zn >= f.zmin && zf <= f.zmax)) return false;
    // 2.5D culling (Harada, "A 2.5D culling for Forward+", 2012): the slices the sphere spans
    // against the slices that hold a surface of the tile
    uint s0 = tl_slice(f, zf), s1 = tl_slice(f, zn);
    uint mask = (0xFFFFFFFFu >> (31u - (s1 - s0))) << s0;
    return (mask & f.depth_mask) != 0u;
}

// Spot cone against the tile's bounding sphere (Wronski, "Cull that cone", 2017).
bool tl_cone_meets_sphere(vec3 apex, vec3 dir, float range, float cos_a, vec4 s)
{
    if (cos_a <= 0.0) return true; // wider than a half space: the range sphere decides
    precise vec3 v = s.xyz - apex;
    precise float len2 = (v.x * v.x + v.y * v.y) + v.z * v.z;
    precise float along = (v.x * dir.x + v.y * dir.y) + v.z * dir.z;
    precise float sin_a = sqrt(max(1.0 - cos_a * cos_a, 0.0));
    precise float closest = cos_a * sqrt(max(len2 - along * along, 0.0)) - along * sin_a;
    precise float reach = s.w + range;
    return !(closest > s.w || along > reach || along < -s.w);
}

bool tl_light_in_tile(tl_tile_frustum f, tl_light_data l)
{
    vec3 c = l.position_radius.xyz;
    float r = l.position_radius.w;
    if (l.color_type.w != 2.0) return tl_sphere_in_tile(f, c, r);
    // spot: the cone's bounding sphere (centred half-way along the axis), then the cone itself
    float co = max(l.direction_cos_outer.w, 0.05);
    vec3 d = l.direction_cos_outer.xyz;
    precise float half_len = 0.5 * r, base = r * sqrt(1.0 - co * co) / co;
    precise float br = max(sqrt(half_len * half_len + base * base), r);
    precise vec3 centre = c + d * half_len;
    return tl_sphere_in_tile(f, centre, br) && tl_cone_meets_sphere(c, d, r, l.direction_cos_outer.w, f.sphere);
}

float tl_distance(float window_depth)
{
    return -tl_depth_linearize(window_depth, u_depth_params.x, u_depth_params.y, u_depth_params.z, u_depth_params.w > 0.5);
}

void main()
{
    uvec2 tile = gl_GlobalInvocationID.xy;
    uint chunk = gl_GlobalInvocationID.z;
    if (tile.x >= u_tiles.y || tile.y >= u_tiles.z || chunk >= tl_tile_chunks()) return;
    uint index = tl_tile_header_index(tile.y * u_tiles.y + tile.x, chunk);
    ivec2 size = tl_cull_size();
    ivec2 p0 = ivec2(tile * u_tiles.x), p1 = min(p0 + int(u_tiles.x), size);
    // depth bounds of the tile's surfaces (window depth: nearer is smaller, larger when reversed)
    bool reversed = u_depth_params.w > 0.5;
    float nearest = reversed ? -1.0 : 2.0, farthest = reversed ? 2.0 : -1.0;
    uint pixels = 0u;
    for (int y = p0.y; y < p1.y; y++)
        for (int x = p0.x; x < p1.x; x++)
            for (int s = 0; s < TL_CULL_SAMPLES; s++) {
                float d = tl_cull_depth(ivec2(x, y), s);
                if (d == u_clear_depth) continue;
                nearest = reversed ? max(nearest, d) : min(nearest, d);
                farthest = reversed ? min(farthest, d) : max(farthest, d);
                pixels++;
            }
    pixels = (pixels + uint(TL_CULL_SAMPLES) - 1u) / uint(TL_CULL_SAMPLES);
    if (pixels == 0u) {
        tl_tile_headers[index] = uvec2(0u, 0u);
        return;
    }
    vec2 ndc0 = vec2(p0) * u_inv_size * 2.0 - 1.0, ndc1 = vec2(p1) * u_inv_size * 2.0 - 1.0;
    tl_tile_frustum f = tl_tile_frustum_make(ndc0, ndc1, tl_distance(nearest), tl_distance(farthest));
    for (int y = p0.y; y < p1.y; y++)
        for (int x = p0.x; x < p1.x; x++)
            for (int s = 0; s < TL_CULL_SAMPLES; s++) {
                float d = tl_cull_depth(ivec2(x, y), s);
                if (d != u_clear_depth) f.depth_mask |= 1u << tl_slice(f, tl_distance(d));
            }
    uint first = u_light_counts.x + chunk * uint(TL_CULL_CHUNK);
    uint last = min(first + uint(TL_CULL_CHUNK), u_light_counts.x + u_light_counts.y), n = 0u;
    for (uint i = first; i < last; i++) n += tl_light_in_tile(f, tl_lights[i]) ? 1u : 0u;
#ifdef TL_LIGHT_SHIFT
    // the light pass shades the light buffer's texels: a tile of the frame holds 4^shift times fewer
    pixels = (pixels + (1u << (2 * TL_LIGHT_SHIFT)) - 1u) >> (2 * TL_LIGHT_SHIFT);
#endif
#ifndef TL_CULL_NO_PAIRS // the volumes light at a light scale: the lists serve light-upsample's re-lit pixels only
    uint pairs = pixels * n, before = atomicAdd(tl_counters.z, pairs);
    if (before > 0xFFFFFFFFu - pairs) atomicAdd(tl_counters.w, 1u);
#endif
    uint offset = n > 0u ? atomicAdd(tl_counters.x, n) : 0u;
    if (n > 0u && offset + n > u_tiles.w) {
        atomicAdd(tl_counters.y, 1u);
        tl_tile_headers[index] = uvec2(TL_TILE_OVERFLOW, n);
        return;
    }
    uint k = offset;
    for (uint i = first; i < last && k < offset + n; i++)
        if (tl_light_in_tile(f, tl_lights[i])) tl_tile_entries[k++] = i;
    tl_tile_headers[index] = uvec2(offset, k - offset); /* never an entry that was not written */
}
