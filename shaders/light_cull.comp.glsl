// Tiled light culling (the light-cull pass): one invocation per screen tile and chunk of
// TL_CULL_CHUNK local lights (tiles.glsl says why chunks), no shared memory
// (a barrier on llvmpipe is a coroutine switch; docs/frame.md says what that cost). It finds the
// tile's depth bounds, then keeps every local light whose range (a sphere; for spot lights also
// the cone) meets the tile's frustum between those depths and may reach one of its 4 x 4 blocks
// (each block's box between its own depth bounds): each entry carries the mask of those blocks.
// The list goes into space taken with one atomic add; a list that does not fit marks its tile as
// overflowed. The pairs counted are those the light pass evaluates:
// each entry over the pixels of its blocks (every light of the chunk over every pixel on overflow).
#define TL_TILES_WRITE
#include "codec.glsl"
#include "tiles.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
#define TL_CULL_KEEP 64 // entries a tile keeps in registers while it culls (more: a second pass)
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

// The per-light tests run twice for a list longer than TL_CULL_KEEP: `precise` keeps the compiler from
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

// Blocks: a tile is cut into 4 x 4 blocks (of tile / 4 pixels a side); each list entry carries a
// 16-bit mask of the blocks whose surfaces the light may reach (tiles.glsl), so a pixel skips the
// lights of its tile that cannot reach its block before reading their records. A block's surfaces
// are bounded by the box of its frustum between its own depth bounds. Each row of 4 blocks is
// tested at once in vec4s, with no loop: llvmpipe ends an invocation's loops after 65535
// iterations in all (tiles.glsl), which a loop per light and block would reach with long lists.
struct tl_tile_blocks {
    vec4 lo_x[4], lo_y[4], lo_z[4], hi_x[4], hi_y[4], hi_z[4]; // row r's 4 boxes
    uint occupied; // bit 4 r + c: block (c, r) has a surface
};

// The 4-bit mask of row r's boxes that sphere (c, r) meets, and for a spot whose cone (apex, dir,
// range, cos_a) meets the box's bounding sphere (tl_cone_meets_sphere, four at once).
uint tl_row_blocks(tl_tile_blocks b, int row, vec3 c, float r, bool spot, vec3 apex, vec3 dir, float range, float cos_a)
{
    precise vec4 dx = max(b.lo_x[row] - c.x, 0.0) + max(c.x - b.hi_x[row], 0.0);
    precise vec4 dy = max(b.lo_y[row] - c.y, 0.0) + max(c.y - b.hi_y[row], 0.0);
    precise vec4 dz = max(b.lo_z[row] - c.z, 0.0) + max(c.z - b.hi_z[row], 0.0);
    precise vec4 d2 = (dx * dx + dy * dy) + dz * dz;
    bvec4 in_range = lessThanEqual(d2, vec4(r * r));
    if (spot && cos_a > 0.0) {
        precise vec4 sx = 0.5 * (b.lo_x[row] + b.hi_x[row]), sy = 0.5 * (b.lo_y[row] + b.hi_y[row]);
        precise vec4 sz = 0.5 * (b.lo_z[row] + b.hi_z[row]);
        precise vec4 hx = 0.5 * (b.hi_x[row] - b.lo_x[row]), hy = 0.5 * (b.hi_y[row] - b.lo_y[row]);
        precise vec4 hz = 0.5 * (b.hi_z[row] - b.lo_z[row]);
        precise vec4 sw = sqrt((hx * hx + hy * hy) + hz * hz);
        precise vec4 vx = sx - apex.x, vy = sy - apex.y, vz = sz - apex.z;
        precise vec4 len2 = (vx * vx + vy * vy) + vz * vz;
        precise vec4 along = (vx * dir.x + vy * dir.y) + vz * dir.z;
        precise float sin_a = sqrt(max(1.0 - cos_a * cos_a, 0.0));
        precise vec4 closest = cos_a * sqrt(max(len2 - along * along, 0.0)) - along * sin_a;
        bvec4 outside = bvec4(uvec4(greaterThan(closest, sw)) | uvec4(greaterThan(along, sw + range)) |
                              uvec4(lessThan(along, -sw)));
        in_range = bvec4(uvec4(in_range) & (uvec4(1u) - uvec4(outside)));
    }
    uvec4 bits = uvec4(in_range) << uvec4(0u, 1u, 2u, 3u);
    return (bits.x | bits.y | bits.z | bits.w) << (4 * row);
}

// The blocks of the tile that light l may reach: its range sphere (a spot's bounding sphere)
// against each occupied block's box, and a spot's cone against the box's bounding sphere.
uint tl_light_blocks(tl_tile_blocks b, tl_light_data l)
{
    vec3 c = l.position_radius.xyz, dir = l.direction_cos_outer.xyz;
    float r = l.position_radius.w;
    bool spot = l.color_type.w == 2.0;
    vec3 sc = c;
    float sr = r;
    if (spot) {
        float co = max(l.direction_cos_outer.w, 0.05);
        precise float half_len = 0.5 * r, base = r * sqrt(1.0 - co * co) / co;
        sr = max(sqrt(half_len * half_len + base * base), r);
        sc = c + dir * half_len;
    }
    float cos_a = l.direction_cos_outer.w;
    uint mask = tl_row_blocks(b, 0, sc, sr, spot, c, dir, r, cos_a) | tl_row_blocks(b, 1, sc, sr, spot, c, dir, r, cos_a) |
                tl_row_blocks(b, 2, sc, sr, spot, c, dir, r, cos_a) | tl_row_blocks(b, 3, sc, sr, spot, c, dir, r, cos_a);
    return mask & b.occupied;
}

// The pixels of the blocks in mask (row r's counts in counts[r]).
uint tl_mask_pixels(uint mask, uvec4 counts[4])
{
    uvec4 b0 = (uvec4(mask) >> uvec4(0u, 1u, 2u, 3u)) & 1u, b1 = (uvec4(mask) >> uvec4(4u, 5u, 6u, 7u)) & 1u;
    uvec4 b2 = (uvec4(mask) >> uvec4(8u, 9u, 10u, 11u)) & 1u, b3 = (uvec4(mask) >> uvec4(12u, 13u, 14u, 15u)) & 1u;
    uvec4 t = b0 * counts[0] + b1 * counts[1] + b2 * counts[2] + b3 * counts[3];
    return t.x + t.y + t.z + t.w;
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
    int block = int(u_tiles.x) / 4; // a block's side in pixels
    // depth bounds of the tile's surfaces and of each block's (window depth: nearer is smaller,
    // larger when reversed), and each block's pixels with a surface
    bool reversed = u_depth_params.w > 0.5;
    float far_init = reversed ? 2.0 : -1.0, near_init = reversed ? -1.0 : 2.0;
    float nearest = near_init, farthest = far_init;
    float block_near[16], block_far[16];
    uint block_pixels[16];
    for (int k = 0; k < 16; k++) {
        block_near[k] = near_init;
        block_far[k] = far_init;
        block_pixels[k] = 0u;
    }
    uint pixels = 0u;
    for (int y = p0.y; y < p1.y; y++)
        for (int x = p0.x; x < p1.x; x++) {
            int k = ((y - p0.y) / block) * 4 + (x - p0.x) / block;
            uint samples = 0u;
            for (int s = 0; s < TL_CULL_SAMPLES; s++) {
                float d = tl_cull_depth(ivec2(x, y), s);
                if (d == u_clear_depth) continue;
                nearest = reversed ? max(nearest, d) : min(nearest, d);
                farthest = reversed ? min(farthest, d) : max(farthest, d);
                block_near[k] = reversed ? max(block_near[k], d) : min(block_near[k], d);
                block_far[k] = reversed ? min(block_far[k], d) : max(block_far[k], d);
                samples++;
            }
            pixels += samples;
            block_pixels[k] += samples;
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
    // each occupied block's box: its frustum's corners at its nearest and farthest surface
    tl_tile_blocks b;
    b.occupied = 0u;
    uvec4 block_counts[4]; // each block's pixels (light buffer texels at a light scale), row by row
    for (int k = 0; k < 16; k++) {
        int row = k / 4, col = k % 4;
        vec3 lo = vec3(0.0), hi = vec3(0.0);
        if (block_pixels[k] > 0u) {
            b.occupied |= 1u << uint(k);
            ivec2 q0 = p0 + ivec2(col, row) * block, q1 = min(q0 + block, p1);
            vec2 c0 = vec2(q0) * u_inv_size * 2.0 - 1.0, c1 = vec2(q1) * u_inv_size * 2.0 - 1.0;
            float z0 = tl_distance(block_near[k]), z1 = tl_distance(block_far[k]);
            lo = vec3(3.0e38);
            hi = vec3(-3.0e38);
            for (int i = 0; i < 8; i++) {
                vec3 q = tl_tile_point(vec2((i & 1) != 0 ? c1.x : c0.x, (i & 2) != 0 ? c1.y : c0.y), (i & 4) != 0 ? z1 : z0);
                lo = min(lo, q);
                hi = max(hi, q);
            }
        }
        b.lo_x[row][col] = lo.x;
        b.lo_y[row][col] = lo.y;
        b.lo_z[row][col] = lo.z;
        b.hi_x[row][col] = hi.x;
        b.hi_y[row][col] = hi.y;
        b.hi_z[row][col] = hi.z;
#ifdef TL_LIGHT_SHIFT
        // the light pass shades the light buffer's texels: a block of the frame holds 4^shift times fewer
        block_counts[row][col] = (block_pixels[k] + (1u << (2 * TL_LIGHT_SHIFT)) - 1u) >> (2 * TL_LIGHT_SHIFT);
#else
        block_counts[row][col] = (block_pixels[k] + uint(TL_CULL_SAMPLES) - 1u) / uint(TL_CULL_SAMPLES);
#endif
    }
    uint first = u_light_counts.x + chunk * uint(TL_CULL_CHUNK);
    uint last = min(first + uint(TL_CULL_CHUNK), u_light_counts.x + u_light_counts.y), n = 0u, pairs = 0u;
    // one pass over the chunk: the entries of the first TL_CULL_KEEP lights kept wait in `keep`; a
    // longer list is written by a second pass over the chunk
    uint keep[TL_CULL_KEEP];
    for (uint i = first; i < last; i++) {
        if (!tl_light_in_tile(f, tl_lights[i])) continue;
        uint mask = tl_light_blocks(b, tl_lights[i]);
        if (mask == 0u) continue;
        if (n < uint(TL_CULL_KEEP)) keep[n] = (i - first) | (mask << 16);
        n++;
        pairs += tl_mask_pixels(mask, block_counts);
    }
    uint offset = n > 0u ? atomicAdd(tl_counters.x, n) : 0u;
    if (n > 0u && offset + n > u_tiles.w) {
        // the list does not fit: its pixels loop over every light of the chunk
        atomicAdd(tl_counters.y, 1u);
        tl_tile_headers[index] = uvec2(TL_TILE_OVERFLOW, n);
#ifdef TL_LIGHT_SHIFT
        pixels = (pixels + (1u << (2 * TL_LIGHT_SHIFT)) - 1u) >> (2 * TL_LIGHT_SHIFT);
#endif
        pairs = pixels * (last - first);
    } else {
        uint k = offset;
        for (uint j = 0u; j < min(n, uint(TL_CULL_KEEP)); j++) tl_tile_entries[k++] = keep[j];
        if (n > uint(TL_CULL_KEEP)) {
            uint seen = 0u;
            for (uint i = first; i < last && k < offset + n; i++) {
                if (!tl_light_in_tile(f, tl_lights[i])) continue;
                uint mask = tl_light_blocks(b, tl_lights[i]);
                if (mask == 0u || seen++ < uint(TL_CULL_KEEP)) continue;
                tl_tile_entries[k++] = (i - first) | (mask << 16);
            }
        }
        tl_tile_headers[index] = uvec2(offset, k - offset); /* never an entry that was not written */
    }
    // the pixel-light pairs the light pass evaluates: each entry over the pixels of its blocks
#ifndef TL_CULL_NO_PAIRS // the volumes light at a light scale: the lists serve light-upsample's re-lit pixels only
    uint before = atomicAdd(tl_counters.z, pairs);
    if (before > 0xFFFFFFFFu - pairs) atomicAdd(tl_counters.w, 1u);
#endif
}
