// KHR_lights_punctual to tl_light, the default rig for files without lights, and the seeded extra
// lights. The renderer's light colours have pi folded in (docs/renderer.md: diffuse radiance =
// albedo * colour * attenuation * N.L), so a glTF intensity I (candela, or lux for directional
// lights) becomes colour * I / pi: the radiance glTF's own Lambert term albedo / pi * I / d^2
// gives. The numbers are documented in docs/gltf.md.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gltf_internal.h"
#include "gltf_math.h"
#include "scene/validate.h"

namespace tl_gltf {
namespace {

const double pi = 3.14159265358979323846;

// Without a glTF range, the radius is where colour / d^2 falls to this (1/256 of a white
// surface's radiance under a unit light: below one 8-bit step).
const double range_threshold = 1.0 / 256.0;

float auto_radius(const float color[3])
{
    double peak = std::fmax(color[0], std::fmax(color[1], color[2]));
    double r = std::sqrt(peak / range_threshold);
    return (float)std::fmax(r, 1e-3);
}

// splitmix64, as the built-in scene uses: same seed, same lights, on every platform.
struct rng {
    uint64_t s;
    uint64_t next()
    {
        uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double unit() { return (double)(next() >> 11) * 0x1.0p-53; }
};

// What the renderer checks (scene/validate.h): a light it would refuse is skipped with a warning.
bool renderable(const context &c, const std::string &name, const tl_light &l)
{
    char msg[TL__CHECK_MESSAGE_SIZE];
    if (tl__light_check(&l, name.c_str(), msg, sizeof msg) == TL_OK) return true;
    warn(c, std::string(msg) + "; skipped");
    return false;
}

// glTF: 0 <= inner < outer <= pi/2. An angle outside is clamped into it (docs/gltf.md, "Spot
// cones"), with a warning naming the field and both values: outer to [0.001, pi/2] (not finite:
// pi/4, glTF's default), then inner to [0, 0.999 outer] (not finite: 0). The renderer's
// cos_outer < cos_inner stays true.
void spot_cone(const context &c, const std::string &name, double inner, double outer, tl_light *l)
{
    char msg[160];
    if (!(outer > 0.0 && outer <= pi / 2)) {
        double to = std::isfinite(outer) ? std::fmin(std::fmax(outer, 1e-3), pi / 2) : pi / 4;
        std::snprintf(msg, sizeof msg, ".spot.outerConeAngle = %g: outside (0, pi/2]; clamped to %g", outer, to);
        warn(c, name + msg);
        outer = to;
    }
    if (!(inner >= 0.0 && inner < outer)) {
        double to = std::isfinite(inner) ? std::fmin(std::fmax(inner, 0.0), outer * 0.999) : 0.0;
        std::snprintf(msg, sizeof msg, ".spot.innerConeAngle = %g: outside [0, outerConeAngle = %g); clamped to %g",
                      inner, outer, to);
        warn(c, name + msg);
        inner = to;
    }
    l->cos_inner = (float)std::cos(inner);
    l->cos_outer = (float)std::cos(outer);
    if (!(l->cos_outer < l->cos_inner)) l->cos_outer = std::nextafter(l->cos_inner, -1.0f);
}

// A JSON value in a message: numbers and booleans as written, strings quoted (cut at 40 bytes).
std::string describe(const tinygltf::Value &v)
{
    if (v.IsBool()) return v.Get<bool>() ? "true" : "false";
    if (v.IsNumber()) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", v.GetNumberAsDouble());
        return text;
    }
    if (v.IsString()) {
        const std::string &s = v.Get<std::string>();
        return "\"" + s.substr(0, 40) + (s.size() > 40 ? "...\"" : "\"");
    }
    return v.IsArray() ? "an array" : v.IsObject() ? "an object" : "null";
}

// A light's "extras": {"thinlight_shadow": true | false} (docs/gltf.md, "Shadows"): 1, 0, or -1
// when absent; any other value is ignored with a warning naming it.
signed char shadow_flag(const context &c, const std::string &name, const tinygltf::Value &extras)
{
    if (!extras.IsObject() || !extras.Has("thinlight_shadow")) return -1;
    const tinygltf::Value &v = extras.Get("thinlight_shadow");
    if (v.IsBool()) return v.Get<bool>() ? 1 : 0;
    warn(c, name + ".extras.thinlight_shadow = " + describe(v) + ": not true or false; ignored");
    return -1;
}

} // namespace

void shadow_rule(const context &c, const vec<signed char> &flags, vec<tl_light> *lights)
{
    size_t casting = 0;
    vec<size_t> local = make_vec<size_t>(c);
    for (size_t i = 0; i < lights->size(); i++) {
        tl_light &l = (*lights)[i];
        signed char f = i < flags.size() ? flags[i] : -1;
        l.shadow = f == 1 || (f < 0 && c.shadow_lights && l.type == TL_LIGHT_DIRECTIONAL);
        casting += (size_t)l.shadow;
        if (f < 0 && c.shadow_lights && l.type != TL_LIGHT_DIRECTIONAL) local.push_back(i);
    }
    // brightest first: the largest colour channel times radius^2 (the renderer's screen ranking
    // without the camera: its light over the area it reaches); the file's order on ties
    auto power = [&](size_t i) {
        const tl_light &l = (*lights)[i];
        return std::fmax(l.color[0], std::fmax(l.color[1], l.color[2])) * (double)l.radius * (double)l.radius;
    };
    std::stable_sort(local.begin(), local.end(), [&](size_t a, size_t b) { return power(a) > power(b); });
    for (size_t k = 0; k < local.size() && casting < c.shadow_lights; k++, casting++) (*lights)[local[k]].shadow = 1;
}

void convert_lights(const context &c, const tinygltf::Model &m, const scene_graph &g, vec<tl_light> *out,
                    vec<signed char> *flags)
{
    for (const light_instance &li : g.lights) {
        const tinygltf::Light &L = m.lights[(size_t)li.light];
        const std::string name = "KHR_lights_punctual.lights[" + std::to_string(li.light) + "]";
        tl_light l = {};
        if (L.type == "point") {
            l.type = TL_LIGHT_POINT;
        } else if (L.type == "spot") {
            l.type = TL_LIGHT_SPOT;
        } else if (L.type == "directional") {
            l.type = TL_LIGHT_DIRECTIONAL;
        } else {
            warn(c, name + ": unknown type \"" + L.type + "\"; skipped");
            continue;
        }
        if (!std::isfinite(L.intensity) || L.intensity < 0.0) {
            warn(c, name + ": intensity is negative or not finite; skipped");
            continue;
        }
        double rgb[3] = {1, 1, 1};
        if (L.color.size() == 3) {
            for (int k = 0; k < 3; k++) rgb[k] = std::isfinite(L.color[(size_t)k]) ? std::fmax(L.color[(size_t)k], 0.0) : 1.0;
        } else if (!L.color.empty()) {
            warn(c, name + ": color needs 3 numbers; using white");
        }
        double col[3];
        for (int k = 0; k < 3; k++) col[k] = rgb[k] * L.intensity / pi;
        if (!fits_float(col[0]) || !fits_float(col[1]) || !fits_float(col[2])) {
            warn(c, name + ": intensity overflows single precision; skipped");
            continue;
        }
        for (int k = 0; k < 3; k++) l.color[k] = (float)col[k];

        const double origin[3] = {0, 0, 0}, minus_z[3] = {0, 0, -1};
        double pos[3], dir[3];
        mat_point(li.world, origin, pos);
        mat_dir(li.world, minus_z, dir);
        if (l.type != TL_LIGHT_POINT) {
            if (!normalize3(dir)) {
                warn(c, element("nodes", (size_t)li.node) + ": light direction is degenerate (zero scale); skipped");
                continue;
            }
            for (int k = 0; k < 3; k++) l.direction[k] = (float)dir[k];
        }
        if (l.type != TL_LIGHT_DIRECTIONAL) {
            for (int k = 0; k < 3; k++) l.position[k] = (float)pos[k];
            if (L.range > 0.0 && fits_float(L.range)) {
                l.radius = (float)L.range;
            } else {
                if (L.range != 0.0) warn(c, name + ": invalid range; derived from the intensity");
                l.radius = auto_radius(l.color);
            }
        }
        if (l.type == TL_LIGHT_SPOT) spot_cone(c, name, L.spot.innerConeAngle, L.spot.outerConeAngle, &l);
        if (!renderable(c, name, l)) continue;
        out->push_back(l);
        flags->push_back(shadow_flag(c, name, L.extras));
    }
}

void drop_unrenderable(const context &c, const char *what, size_t first, vec<tl_light> *lights)
{
    size_t kept = first;
    for (size_t i = first; i < lights->size(); i++)
        if (renderable(c, what + std::to_string(i - first) + "]", (*lights)[i])) (*lights)[kept++] = (*lights)[i];
    lights->resize(kept);
}

void default_rig(const float bmin[3], const float bmax[3], vec<tl_light> *out)
{
    double c[3], r;
    scene_frame(bmin, bmax, c, &r);
    // A warm key light from above, front right (glTF's front is +Z, up +Y)...
    tl_light key = {};
    key.type = TL_LIGHT_DIRECTIONAL;
    double d[3] = {-0.4, -1.0, -0.6};
    normalize3(d);
    for (int k = 0; k < 3; k++) key.direction[k] = (float)d[k];
    key.color[0] = 1.0f;
    key.color[1] = 0.95f;
    key.color[2] = 0.88f;
    out->push_back(key);
    // ...and four fill lights on a ring 1.5 half-diagonals out, half that above the centre, each
    // giving about 0.15 at the centre (before the window), alternately cool and warm.
    double ring = 1.5 * r;
    for (int i = 0; i < 4; i++) {
        double a = pi / 4 + i * pi / 2;
        tl_light p = {};
        p.type = TL_LIGHT_POINT;
        p.position[0] = to_float(c[0] + ring * std::cos(a));
        p.position[1] = to_float(c[1] + 0.5 * ring);
        p.position[2] = to_float(c[2] + ring * std::sin(a));
        double dist2 = ring * ring * 1.25;
        float k = (float)(0.15 * dist2);
        p.color[0] = k * (i % 2 ? 1.0f : 0.85f);
        p.color[1] = k * 0.95f;
        p.color[2] = k * (i % 2 ? 0.85f : 1.0f);
        p.radius = (float)(2.5 * ring);
        out->push_back(p);
    }
}

void extra_lights(const context &c, const float bmin[3], const float bmax[3], vec<tl_light> *out)
{
    double centre[3], r;
    scene_frame(bmin, bmax, centre, &r);
    // Each axis at least a tenth of the diagonal wide, so that a flat scene (a floor) still gets
    // lights above it rather than in it.
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        double half = std::fmax(0.5 * ((double)bmax[k] - bmin[k]), 0.1 * r);
        lo[k] = centre[k] - half;
        hi[k] = centre[k] + half;
    }
    rng g{c.seed};
    double radius = 0.5 * r; // a quarter of the diagonal
    for (uint32_t i = 0; i < c.extra_lights; i++) {
        tl_light l = {};
        l.type = TL_LIGHT_POINT;
        for (int k = 0; k < 3; k++) l.position[k] = to_float(lo[k] + (hi[k] - lo[k]) * g.unit());
        // A random colour with its largest channel 1, times 0.1 radius^2: about 0.35 at half the
        // radius.
        double rgb[3] = {0.25 + 0.75 * g.unit(), 0.25 + 0.75 * g.unit(), 0.25 + 0.75 * g.unit()};
        double peak = std::fmax(rgb[0], std::fmax(rgb[1], rgb[2]));
        for (int k = 0; k < 3; k++) l.color[k] = (float)(rgb[k] / peak * 0.1 * radius * radius);
        l.radius = (float)radius;
        out->push_back(l);
    }
}

} // namespace tl_gltf
