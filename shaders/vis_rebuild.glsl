// Visibility's attribute rebuild (vis-resolve): a pixel's triangle from the scene's buffers, the
// perspective-correct barycentrics of the pixel's view ray against it, and the screen-space
// derivatives a rasteriser gives its 2 x 2 quad (the texture's level of detail): the differences
// along the quad's first row and column (coarse derivatives), from the rays through those pixels
// against the triangle's plane, where a rasteriser's helper invocations would have evaluated it. Sets material.glsl's inputs (v_normal, v_uv, ...) as the vertex shader
// (gbuffer.vert.glsl) and interpolation would have them.
#ifndef TL_VIS_REBUILD_GLSL
#define TL_VIS_REBUILD_GLSL

layout(std430, binding = TL_SSBO_VIS_VERTICES) readonly buffer tl_vis_vertex_block { float tl_vis_vertices[]; };
layout(std430, binding = TL_SSBO_VIS_INDICES) readonly buffer tl_vis_index_block { uint tl_vis_indices[]; };
#ifdef TL_VCOLOR
layout(std430, binding = TL_SSBO_VIS_COLORS) readonly buffer tl_vis_color_block { vec4 tl_vis_colors[]; };
#endif
#ifdef TL_UV1
layout(std430, binding = TL_SSBO_VIS_UV1) readonly buffer tl_vis_uv1_block { vec2 tl_vis_uv1[]; };
#endif

// tl_vertex: position 0..2, normal 3..5, uv 6..7, tangent 8..11 (scene.h)
vec3 tl_vis_vec3(uint v, uint at) { return vec3(tl_vis_vertices[v * 12u + at], tl_vis_vertices[v * 12u + at + 1u], tl_vis_vertices[v * 12u + at + 2u]); }
vec2 tl_vis_vec2(uint v, uint at) { return vec2(tl_vis_vertices[v * 12u + at], tl_vis_vertices[v * 12u + at + 1u]); }

// The view ray through window point q (pixels), as a direction with z = -1.
vec3 tl_vis_ray(vec2 q) { return tl_view_position(-1.0, q * u_inv_size * 2.0 - 1.0, u_ray_params); }

// Barycentrics (of p0, p1, p2) of the point where the ray from the eye along d meets the
// triangle's plane (normal n = cross(p1 - p0, p2 - p0)): perspective-correct by construction. The
// point is found first (t along the ray), then each weight is the area of the sub-triangle it and
// an edge make over the whole one, from vectors to the point: a sliver's weights stay exact (a
// Moller-Trumbore determinant of two long, nearly parallel edges would lose them). Not clamped:
// the neighbours' rays may leave the triangle, as the rasteriser's derivatives extend its plane.
vec3 tl_vis_barycentrics(vec3 p0, vec3 p1, vec3 p2, vec3 n, vec3 d)
{
    vec3 p = d * (dot(n, p0) / dot(n, d));
    float inv = 1.0 / dot(n, n);
    float b0 = dot(cross(p1 - p, p2 - p), n) * inv;
    float b1 = dot(cross(p2 - p, p0 - p), n) * inv;
    return vec3(b0, b1, 1.0 - b0 - b1);
}

// A vertex's window position (pixels) from its view-space position (in front of the eye).
vec2 tl_vis_window(vec3 p)
{
    vec2 ndc = vec2(u_ray_params.x * p.x + u_ray_params.z * p.z, u_ray_params.y * p.y + u_ray_params.w * p.z) / -p.z;
    return (ndc * 0.5 + 0.5) / u_inv_size;
}

float tl_vis_cross(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Barycentrics at window point q as a rasteriser has them: the areas of the sub-triangles q makes
// with the window positions s0, s1, s2, each over its vertex's w (perspective-correct), normalised.
// In two dimensions a sliver's weights are as exact as a large triangle's: its short side is small
// in window units, but no depth enters the areas (the three-dimensional plane of a sliver tilts
// with its vertices' depth rounding over its width, moving the point along the sliver).
vec3 tl_vis_barycentrics_window(vec2 s0, vec2 s1, vec2 s2, vec3 inv_w, vec2 q)
{
    vec3 a = vec3(tl_vis_cross(s1 - q, s2 - q), tl_vis_cross(s2 - q, s0 - q), tl_vis_cross(s0 - q, s1 - q)) * inv_w;
    return a / (a.x + a.y + a.z);
}

// A finite derivative: a ray parallel to the plane (the horizon) gives the coarsest level.
vec2 tl_vis_finite(vec2 d) { return any(isnan(d)) || any(isinf(d)) ? vec2(1e8) : d; }

void tl_vis_rebuild(uint object, uint triangle, vec2 q)
{
    uint first = tl_object_first_index(object) + 3u * triangle;
    uint i0 = tl_vis_indices[first], i1 = tl_vis_indices[first + 1u], i2 = tl_vis_indices[first + 2u];
    mat4 model_view = u_view * tl_objects[object].model;
    vec3 p0 = (model_view * vec4(tl_vis_vec3(i0, 0u), 1.0)).xyz;
    vec3 p1 = (model_view * vec4(tl_vis_vec3(i1, 0u), 1.0)).xyz;
    vec3 p2 = (model_view * vec4(tl_vis_vec3(i2, 0u), 1.0)).xyz;
    vec3 e1 = p1 - p0, e2 = p2 - p0;
    // the rasteriser's facing: counter-clockwise on screen is the normal towards the eye
    v_front_facing = dot(cross(e1, e2), p0) < 0.0;

    vec2 quad = floor((q - 0.5) * 0.5) * 2.0 + 0.5; // the quad's first pixel's centre
    vec3 b, bq, bx, by;
    float near = 1e-6 * max(max(-p0.z, -p1.z), -p2.z);
    if (p0.z < -near && p1.z < -near && p2.z < -near) {
        // every vertex in front of the eye: in window space, as the rasteriser interpolates
        vec2 s0 = tl_vis_window(p0), s1 = tl_vis_window(p1), s2 = tl_vis_window(p2);
        vec3 inv_w = 1.0 / vec3(-p0.z, -p1.z, -p2.z);
        b = tl_vis_barycentrics_window(s0, s1, s2, inv_w, q);
        bq = tl_vis_barycentrics_window(s0, s1, s2, inv_w, quad);
        bx = tl_vis_barycentrics_window(s0, s1, s2, inv_w, quad + vec2(1.0, 0.0)) - bq;
        by = tl_vis_barycentrics_window(s0, s1, s2, inv_w, quad + vec2(0.0, 1.0)) - bq;
    } else {
        // a triangle crossing the eye's plane (clipped by the rasteriser): its view rays against
        // its plane, which need no window position of the vertices behind the eye
        vec3 plane_n = cross(e1, e2);
        b = tl_vis_barycentrics(p0, p1, p2, plane_n, tl_vis_ray(q));
        bq = tl_vis_barycentrics(p0, p1, p2, plane_n, tl_vis_ray(quad));
        bx = tl_vis_barycentrics(p0, p1, p2, plane_n, tl_vis_ray(quad + vec2(1.0, 0.0))) - bq;
        by = tl_vis_barycentrics(p0, p1, p2, plane_n, tl_vis_ray(quad + vec2(0.0, 1.0))) - bq;
    }
    // The rasteriser covers a pixel whose centre is inside the triangle at its snapped (sub-pixel
    // fixed-point) vertices and interpolates its attribute planes there, extrapolated where the
    // centre is just outside the triangle in float (a sliver's long edge through the centre): a
    // weight of a few -1e-3. Kept so: clamping it to 0 and renormalising would move the point
    // towards the opposite vertex (for a sliver, along its length: -0.001 x 90 pixels), not onto
    // the edge, shifting uv and position by a tenth of a pixel or more. Only weights that no
    // rounding of a covered centre explains (not finite; half a triangle's height outside: a
    // degenerate triangle whose window area rounding decides) are held to the triangle.
    if (any(isnan(b)) || any(isinf(b))) b = vec3(1.0 / 3.0);
    if (any(lessThan(b, vec3(-0.5)))) {
        b = clamp(b, 0.0, 1.0);
        b /= max(b.x + b.y + b.z, 1e-30);
    }

    v_object = object;
    v_view_position = p0 * b.x + p1 * b.y + p2 * b.z;
    mat3 nv = tl_object_normal_view(object);
    v_normal = nv * (tl_vis_vec3(i0, 3u) * b.x + tl_vis_vec3(i1, 3u) * b.y + tl_vis_vec3(i2, 3u) * b.z);
    vec2 u0 = tl_vis_vec2(i0, 6u), u1 = tl_vis_vec2(i1, 6u), u2 = tl_vis_vec2(i2, 6u);
    v_uv = u0 * b.x + u1 * b.y + u2 * b.z;
    v_uv_dx = tl_vis_finite(u0 * bx.x + u1 * bx.y + u2 * bx.z);
    v_uv_dy = tl_vis_finite(u0 * by.x + u1 * by.y + u2 * by.z);
#ifdef TL_NORMAL_MAP
    vec4 t = vec4(tl_vis_vec3(i0, 8u), tl_vis_vertices[i0 * 12u + 11u]) * b.x +
             vec4(tl_vis_vec3(i1, 8u), tl_vis_vertices[i1 * 12u + 11u]) * b.y +
             vec4(tl_vis_vec3(i2, 8u), tl_vis_vertices[i2 * 12u + 11u]) * b.z;
    v_tangent = vec4(mat3(model_view) * t.xyz, t.w);
#else
    v_tangent = vec4(0.0);
#endif
#ifdef TL_VCOLOR
    v_color = tl_vis_colors[i0] * b.x + tl_vis_colors[i1] * b.y + tl_vis_colors[i2] * b.z;
#endif
#ifdef TL_UV1
    vec2 w0 = tl_vis_uv1[i0], w1 = tl_vis_uv1[i1], w2 = tl_vis_uv1[i2];
    v_uv1 = w0 * b.x + w1 * b.y + w2 * b.z;
    v_uv1_dx = tl_vis_finite(w0 * bx.x + w1 * bx.y + w2 * bx.z);
    v_uv1_dy = tl_vis_finite(w0 * by.x + w1 * by.y + w2 * by.z);
#else
    v_uv1_dx = v_uv1_dy = vec2(0.0);
#endif
}

#endif
