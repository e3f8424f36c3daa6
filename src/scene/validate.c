/* The checks of validate.h, shared by the glTF loader and the renderer. */
#include "scene/validate.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "core/log.h"

static tl_result tl__say(tl_result res, char *message, size_t size, const char *fmt, ...) TL__PRINTF_LIKE(4, 5);
static tl_result tl__say(tl_result res, char *message, size_t size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (message && size) vsnprintf(message, size, fmt, ap);
    va_end(ap);
    return res;
}

static int tl__finite3(const float v[3]) { return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]); }

/* A double as a float, saturated at float's largest finite magnitude. */
static float tl__to_float(double v) { return v > FLT_MAX ? FLT_MAX : v < -FLT_MAX ? -FLT_MAX : (float)v; }

/* "(x, y, z)" for messages. */
typedef struct tl__vec_text { char s[80]; } tl__vec_text;
static tl__vec_text tl__v3(const float v[3])
{
    tl__vec_text t;
    snprintf(t.s, sizeof t.s, "(%g, %g, %g)", (double)v[0], (double)v[1], (double)v[2]);
    return t;
}

/* ---- bounds ------------------------------------------------------------------------------------ */

int tl__objects_bounds(const tl_object *objects, size_t count, float min[3], float max[3])
{
    int any = 0;
    for (size_t i = 0; objects && i < count; i++) {
        const tl_object *o = &objects[i];
        if (!tl__finite3(o->bounds_min) || !tl__finite3(o->bounds_max)) continue;
        for (int k = 0; k < 3; k++) {
            min[k] = any && min[k] < o->bounds_min[k] ? min[k] : o->bounds_min[k];
            max[k] = any && max[k] > o->bounds_max[k] ? max[k] : o->bounds_max[k];
        }
        any = 1;
    }
    return any;
}

uint32_t tl__primitive_indices(uint32_t primitive)
{
    static const uint32_t n[TL_PRIMITIVE_COUNT_] = {3, 2, 1};
    return primitive < TL_PRIMITIVE_COUNT_ ? n[primitive] : 0u;
}

const char *tl__primitive_name(uint32_t primitive)
{
    static const char *const names[TL_PRIMITIVE_COUNT_] = {"triangles", "lines", "points"};
    return primitive < TL_PRIMITIVE_COUNT_ ? names[primitive] : "unknown";
}

tl_result tl__object_check(const tl_object *o, const char *what, char *message, size_t size)
{
    if (o->primitive >= TL_PRIMITIVE_COUNT_)
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.primitive = %u: not a tl_primitive", what,
                       o->primitive);
    for (int k = 0; k < 16; k++)
        if (!isfinite(o->transform[k]))
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.transform[%d] = %g: not finite", what, k,
                           (double)o->transform[k]);
    if (!o->index_count || tl__bounds_are_zero(o)) return TL_OK;
    const struct { const float *v; const char *name; } b[2] = {{o->bounds_min, "bounds_min"},
                                                                {o->bounds_max, "bounds_max"}};
    for (int i = 0; i < 2; i++)
        if (!tl__finite3(b[i].v))
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.%s = %s: not finite (all six zero: computed)",
                           what, b[i].name, tl__v3(b[i].v).s);
    for (int k = 0; k < 3; k++)
        if (o->bounds_max[k] < o->bounds_min[k])
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.bounds_max = %s: below bounds_min = %s on %c",
                           what, tl__v3(o->bounds_max).s, tl__v3(o->bounds_min).s, "xyz"[k]);
    return TL_OK;
}

/* ---- cameras ----------------------------------------------------------------------------------- */

#define TL__DEFAULT_FOV_Y 1.0471975511965976 /* 60 degrees */
#define TL__DEFAULT_NEAR 0.1f

/* The near plane below which the frame loses the scene, as a power of two of the distance to the
 * scene's farthest point (its "reach"): with D24 a surface at distance z lies n / z below the far
 * plane's depth 1, so below 2^-24 of the reach every surface rounds onto the far plane (near =
 * 1e-30: a frame with no light). Reversed D32F stores n / z itself, a normal float down to 2^-126,
 * but a triangle clipped at such a near plane gets a vertex at w = n whose x / w and y / w carry
 * the clip's rounding times reach / n: on llvmpipe near = 1e-30 (2^-104 of the reach) dropped a
 * floor triangle from the G-buffer in 1 to 6 of 30 frames, an unlit wedge. The floor is 2^-24 for
 * both. Such a near plane is a mistake, not a choice (1:10^7 is a choice, and stays), so it is
 * replaced by one that keeps the scene well: 2^-16 of the reach leaves D24 256 steps in front of
 * the farthest surface (positions within 0.4 %). */
static int tl__near_floor_exponent(tl_depth_format depth)
{
    (void)depth;
    return -24;
}
#define TL__NEAR_RAISED_EXPONENT (-16)

static void tl__sub3(const float a[3], const float b[3], double out[3])
{
    for (int k = 0; k < 3; k++) out[k] = (double)a[k] - (double)b[k];
}

static double tl__dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void tl__cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static double tl__normalize3(double v[3])
{
    double l = sqrt(tl__dot3(v, v));
    if (l > 0.0)
        for (int k = 0; k < 3; k++) v[k] /= l;
    return l;
}

/* The screen's up when `up` is parallel to the view direction `f`: the limit of views tilted from
 * f towards h, h being -Z (the default camera's view) made perpendicular to up, or +Y when up lies
 * along Z. Looking along -up (down) that limit's screen up is h; looking along +up it is -h. */
static void tl__fallback_up(const double f[3], const double up[3], double out[3])
{
    static const double refs[2][3] = {{0, 0, -1}, {0, 1, 0}};
    const double *h = refs[fabs(up[2]) > 0.5];
    double d = tl__dot3(h, up), s = tl__dot3(f, up) < 0.0 ? 1.0 : -1.0;
    for (int k = 0; k < 3; k++) out[k] = h[k] - d * up[k];
    tl__normalize3(out);
    for (int k = 0; k < 3; k++) out[k] *= s;
}

void tl__camera_frame(const float bmin[3], const float bmax[3], double fov_y, tl_camera *out)
{
    double c[3], d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        c[k] = 0.5 * ((double)bmin[k] + bmax[k]);
        double e = (double)bmax[k] - bmin[k];
        d2 += e * e;
    }
    double r = 0.5 * sqrt(d2);
    r = r > 1e-6 ? (r < 1e18 ? r : 1e18) : 0.5;
    double dist = 1.05 * r / sin(0.5 * fov_y);
    double dir[3] = {0.5, 0.4, 1.0};
    tl__normalize3(dir);
    memset(out, 0, sizeof *out);
    for (int k = 0; k < 3; k++) {
        out->position[k] = tl__to_float(c[k] + dir[k] * dist);
        out->target[k] = tl__to_float(c[k]);
    }
    out->up[1] = 1.0f;
    out->fov_y = (float)fov_y;
    out->near_z = tl__to_float(0.5 * (dist - r)); /* the sphere starts at dist - r > 0 */
    out->far_z = tl__to_float(2.0 * (dist + r));
}

/* The default view of a camera whose position and target are both zero (tl_camera): the framing
 * camera of the bounds with the camera's own fov_y (already resolved in `v`) and, unless given,
 * its near plane; without bounds, the origin looking down -Z. */
static tl_camera tl__camera_default_view(const tl_camera *c, const float *bmin, const float *bmax, tl__camera_view *v)
{
    tl_camera out = *c;
    if (!bmin || !bmax) {
        out.target[2] = -1.0f;
        return out;
    }
    tl_camera frame;
    tl__camera_frame(bmin, bmax, v->fov_y, &frame);
    memcpy(out.position, frame.position, sizeof out.position);
    memcpy(out.target, frame.target, sizeof out.target);
    if (c->near_z == 0.0f && (v->far_z == 0.0f || frame.near_z < v->far_z)) v->near_z = frame.near_z;
    return out;
}

static int tl__zero3(const float v[3]) { return v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f; }

/* The orthonormal basis from position, target and up (already finite). */
static tl_result tl__camera_basis(const tl_camera *c, const char *what, tl__camera_view *out, char *message, size_t size)
{
    double f[3], up[3] = {c->up[0], c->up[1], c->up[2]}, s[3];
    tl__sub3(c->target, c->position, f);
    double dist = tl__normalize3(f);
    if (!(dist > 0.0))
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.target = %s: the position, no view direction",
                       what, tl__v3(c->position).s);
    if (tl__normalize3(up) == 0.0) up[1] = 1.0;
    tl__cross3(f, up, s);
    if (sqrt(tl__dot3(s, s)) <= 1e-9) { /* parallel: a defined limit instead of a zero right vector */
        double h[3];
        tl__fallback_up(f, up, h);
        tl__cross3(f, h, s);
    }
    tl__normalize3(s);
    for (int k = 0; k < 3; k++) {
        out->eye[k] = c->position[k];
        out->right[k] = s[k];
        out->back[k] = -f[k];
    }
    tl__cross3(s, f, out->up);
    out->target_distance = (float)dist;
    return TL_OK;
}

/* fov_y, near_z and far_z with their defaults; the projection is the arbiter of the range. */
static tl_result tl__camera_lens(const tl_camera *c, const char *what, tl__camera_view *out, char *message, size_t size)
{
    tl_projection p;
    out->fov_y = c->fov_y == 0.0f ? (float)TL__DEFAULT_FOV_Y : c->fov_y;
    /* the narrowest target (1 x 16384) must still give a finite matrix */
    const float min_aspect = 1.0f / (float)TL__GL45_MAX_TEXTURE_SIZE;
    if (tl_projection_perspective(TL_DEPTH_FORMAT_D24, out->fov_y, min_aspect, 1.0f, 0.0f, &p) != TL_OK ||
        !isfinite(p.m[0]) || !isfinite(p.m[5]))
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.fov_y = %g: outside (0, pi)", what,
                       (double)c->fov_y);
    out->near_z = c->near_z == 0.0f ? TL__DEFAULT_NEAR : c->near_z;
    if (!(out->near_z > 0.0f) || !isfinite(out->near_z))
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size,
                       "%s.near_z = %g: not a finite distance > 0 (0 means the default 0.1)", what, (double)c->near_z);
    if (isnan(c->far_z) || c->far_z < 0.0f)
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size,
                       "%s.far_z = %g: not a distance (0 or +Inf: an infinite far plane)", what, (double)c->far_z);
    out->far_z = isinf(c->far_z) ? 0.0f : c->far_z;
    if (out->far_z != 0.0f && !(out->far_z > out->near_z))
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.far_z = %g: not beyond near_z = %g", what,
                       (double)c->far_z, (double)out->near_z);
    return TL_OK;
}

/* Raises a near_z below the depth format's floor, relative to the farthest corner of the bounds
 * (or the far plane, when nearer). */
static void tl__camera_near_floor(const char *what, tl_depth_format depth, const float *bmin, const float *bmax,
                                  tl__camera_view *out, char *message, size_t size)
{
    if (!bmin || !bmax) return;
    double far_corner[3];
    for (int k = 0; k < 3; k++)
        far_corner[k] = fmax(fabs((double)bmin[k] - out->eye[k]), fabs((double)bmax[k] - out->eye[k]));
    double reach = sqrt(tl__dot3(far_corner, far_corner));
    if (out->far_z > 0.0f && out->far_z < reach) reach = out->far_z;
    int e = tl__near_floor_exponent(depth);
    float floor_z = (float)ldexp(reach, e), raised = (float)ldexp(reach, TL__NEAR_RAISED_EXPONENT);
    if (!(floor_z > 0.0f) || !isfinite(raised) || !(out->near_z < floor_z)) return;
    tl__say(TL_OK, message, size,
            "%s.near_z = %g: below 2^%d of the distance to the scene's farthest point (%g), where %s; raised to 2^%d "
            "of it, %g",
            what, (double)out->near_z, e, reach,
            depth == TL_DEPTH_FORMAT_D32F_REVERSED ? "clipping at the near plane loses triangles"
                                                   : "D24 depth holds nothing of the scene",
            TL__NEAR_RAISED_EXPONENT, (double)raised);
    out->near_z = raised;
    out->near_raised = 1;
}

tl_result tl__camera_resolve(const tl_camera *c, const char *what, tl_depth_format depth, const float *bounds_min,
                             const float *bounds_max, tl__camera_view *out, char *message, size_t size)
{
    memset(out, 0, sizeof *out);
    if (message && size) message[0] = '\0';
    const struct { const float *v; const char *name; } fields[] = {
        {c->position, "position"}, {c->target, "target"}, {c->up, "up"}};
    for (size_t i = 0; i < 3; i++)
        if (!tl__finite3(fields[i].v))
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.%s = %s: not finite", what, fields[i].name,
                           tl__v3(fields[i].v).s);
    tl_result res = tl__camera_lens(c, what, out, message, size);
    tl_camera view = *c;
    if (res == TL_OK && tl__zero3(c->position) && tl__zero3(c->target))
        view = tl__camera_default_view(c, bounds_min, bounds_max, out);
    if (res == TL_OK) res = tl__camera_basis(&view, what, out, message, size);
    if (res == TL_OK) tl__camera_near_floor(what, depth, bounds_min, bounds_max, out, message, size);
    return res;
}

void tl__camera_view_matrix(const tl__camera_view *v, float m[16])
{
    const double *rows[3] = {v->right, v->up, v->back};
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++) m[k * 4 + i] = (float)rows[i][k];
        m[12 + i] = (float)-tl__dot3(rows[i], v->eye);
        m[i * 4 + 3] = 0.0f;
    }
    m[15] = 1.0f;
}

/* ---- textures and materials -------------------------------------------------------------------- */

tl_result tl__texture_check(const tl_texture *t, const char *what, uint32_t max_side, char *message, size_t size)
{
    const struct { uint32_t v; const char *name; } sides[2] = {{t->width, "width"}, {t->height, "height"}};
    const char *name = t->name[0] && memchr(t->name, '\0', sizeof t->name) && strcmp(t->name, what) ? t->name : NULL;
    for (int i = 0; i < 2; i++) {
        if (sides[i].v == 0)
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.%s = 0: outside 1..%u%s%s%s", what,
                           sides[i].name, max_side, name ? " (\"" : "", name ? name : "", name ? "\")" : "");
        if (sides[i].v > max_side)
            return tl__say(TL_ERROR_LIMIT, message, size,
                           "%s.%s = %u: over the largest texture side, %u (GL_MAX_TEXTURE_SIZE)%s%s%s", what,
                           sides[i].name, sides[i].v, max_side, name ? " (\"" : "", name ? name : "", name ? "\")" : "");
    }
    if (!t->rgba)
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.rgba = NULL: a %ux%u texture without pixels%s%s%s",
                       what, t->width, t->height, name ? " (\"" : "", name ? name : "", name ? "\")" : "");
    return TL_OK;
}

const tl__texture_slot tl__material_texture_slots[TL__MATERIAL_TEXTURE_SLOTS] = {
    {"albedo_map", offsetof(tl_material, albedo_map), 1},
    {"normal_map", offsetof(tl_material, normal_map), 0},
    {"metallic_roughness_map", offsetof(tl_material, metallic_roughness_map), 0},
    {"emissive_map", offsetof(tl_material, emissive_map), 1},
    {"occlusion_map", offsetof(tl_material, occlusion_map), 0},
};

static uint32_t tl__material_map(const tl_material *m, int k)
{
    uint32_t map;
    memcpy(&map, (const char *)m + tl__material_texture_slots[k].offset, sizeof map);
    return map;
}

uint32_t tl__material_texture(const tl_material *m, int k)
{
    uint32_t map = tl__material_map(m, k);
    return map ? map - 1u : TL__NO_TEXTURE;
}

int tl__material_has_texture(const tl_material *m, int k, size_t texture_count)
{
    uint32_t map = tl__material_map(m, k);
    return map != 0 && map - 1u < texture_count;
}

tl_result tl__material_check(const tl_material *m, const char *what, size_t texture_count, char *message, size_t size)
{
    for (int k = 0; k < TL__MATERIAL_TEXTURE_SLOTS; k++) {
        uint32_t map = tl__material_map(m, k);
        if (map != 0 && map - 1u >= texture_count)
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size,
                           "%s.%s = %u: texture %u, past the scene's %zu textures (a map is a texture's index + 1, "
                           "TL_TEXTURE_MAP; 0 for none)",
                           what, tl__material_texture_slots[k].name, map, map - 1u, texture_count);
    }
    return tl__material_model_check(m, what, message, size);
}

void tl__material_defaults(const tl_material *in, tl_material *out)
{
    *out = *in;
    int colour = 0;
    for (int k = 0; k < 3; k++) colour |= in->albedo[k] != 0.0f || in->specular[k] != 0.0f || in->emissive[k] != 0.0f;
    for (int k = 0; k < 3; k++)
        out->albedo[k] = !colour ? TL_MATERIAL_DEFAULT_ALBEDO : in->albedo[k] < 0.0f ? 0.0f : in->albedo[k];
    if (out->normal_scale == 0.0f) out->normal_scale = 1.0f;
    if (out->occlusion_strength == 0.0f) out->occlusion_strength = 1.0f;
    tl__material_model_defaults(out);
}

/* ---- lights ------------------------------------------------------------------------------------ */

static const char *const tl__light_type_names[TL_LIGHT_TYPE_COUNT_] = {"point", "point", "spot", "directional"};

/* The cone: cosines of half angles up to 90 degrees (glTF's outerConeAngle <= pi/2; a wider cone
 * has no volume that the light-volume pass could draw alike), the inner cone inside the outer. */
static tl_result tl__spot_check(const tl_light *l, const char *what, char *message, size_t size)
{
    const struct { float v; const char *name; } cosines[2] = {{l->cos_inner, "cos_inner"}, {l->cos_outer, "cos_outer"}};
    for (int i = 0; i < 2; i++)
        if (!(cosines[i].v >= -1.0f && cosines[i].v <= 1.0f))
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size,
                           "%s.%s = %g: not a cosine (-1..1; the cone's half angles enter as their cosines, "
                           "cos_inner = cos(inner angle))", what, cosines[i].name, (double)cosines[i].v);
    if (l->cos_outer < -TL__SPOT_COS_SLACK)
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size,
                       "%s.cos_outer = %g: a cone wider than 90 degrees (cos_outer >= 0, as glTF's outerConeAngle <= "
                       "pi/2)", what, (double)l->cos_outer);
    if (!(l->cos_outer < l->cos_inner))
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.cos_outer = %g: not below cos_inner = %g", what,
                       (double)l->cos_outer, (double)l->cos_inner);
    return TL_OK;
}

tl_result tl__light_check(const tl_light *l, const char *what, char *message, size_t size)
{
    if ((unsigned)l->type >= TL_LIGHT_TYPE_COUNT_)
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.type = %d: not a tl_light_type", what, (int)l->type);
    const char *type = tl__light_type_names[l->type];
    const struct { const float *v; const char *name; } fields[] = {
        {l->position, "position"}, {l->direction, "direction"}, {l->color, "color"}};
    for (size_t i = 0; i < 3; i++)
        if (!tl__finite3(fields[i].v))
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.%s = %s: not finite", what, fields[i].name,
                           tl__v3(fields[i].v).s);
    if (l->type != TL_LIGHT_DIRECTIONAL) {
        if (!(l->radius > 0.0f) || !isfinite(l->radius))
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.radius = %g: a %s light needs a finite radius > 0",
                           what, (double)l->radius, type);
        if (!(l->source_radius >= 0.0f) || !isfinite(l->source_radius))
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.source_radius = %g: not a finite radius >= 0",
                           what, (double)l->source_radius);
    }
    if (l->type == TL_LIGHT_SPOT || l->type == TL_LIGHT_DIRECTIONAL) {
        if (l->direction[0] == 0.0f && l->direction[1] == 0.0f && l->direction[2] == 0.0f)
            return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size, "%s.direction = (0, 0, 0): a %s light needs a direction",
                           what, type);
    }
    if (!isfinite(l->specular) || (l->specular < 0.0f && l->specular != TL_LIGHT_SPECULAR_NONE))
        return tl__say(TL_ERROR_INVALID_ARGUMENT, message, size,
                       "%s.specular = %g: not a finite scale >= 0 (0: 1) or TL_LIGHT_SPECULAR_NONE", what,
                       (double)l->specular);
    if (l->type == TL_LIGHT_SPOT) return tl__spot_check(l, what, message, size);
    return TL_OK;
}
