// The scene's camera: the first perspective camera node of the scene, or else one that frames the
// scene's bounds (tl_camera has no orthographic projection, so orthographic cameras fall back).
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "gltf_internal.h"
#include "gltf_math.h"
#include "scene/validate.h"

namespace tl_gltf {
namespace {

const double pi = 3.14159265358979323846;

// The renderer's default view (a zeroed tl_camera, scene/validate.h) at 60 degrees: from the front,
// right and above, the bounding sphere in the vertical field of view with 5% to spare.
void framing_camera(const float bmin[3], const float bmax[3], tl_camera *out)
{
    tl__camera_frame(bmin, bmax, pi / 3.0, out);
}

// The file's camera as the renderer will resolve it (scene/validate.h, with the default D24
// depth): what the renderer would refuse is a warning and the framing camera; a near plane below
// the floor is raised here, with a warning, so that the renderer has nothing left to say.
bool renderable(const context &c, const std::string &name, const float *bmin, const float *bmax, tl_camera *cam)
{
    tl__camera_view v;
    char msg[TL__CHECK_MESSAGE_SIZE];
    if (tl__camera_resolve(cam, "camera", TL_DEPTH_FORMAT_D24, bmin, bmax, &v, msg, sizeof msg) != TL_OK) {
        warn(c, name + ": " + msg + "; using a camera that frames the scene");
        return false;
    }
    if (v.near_raised) {
        warn(c, name + ": " + msg);
        cam->near_z = v.near_z;
    }
    return true;
}

} // namespace

void make_camera(const context &c, const tinygltf::Model &m, const scene_graph &g, const float bmin[3],
                 const float bmax[3], const tl_scene *s, tl_camera *out)
{
    framing_camera(bmin, bmax, out);
    if (g.camera_node < 0) return;
    int ci = m.nodes[(size_t)g.camera_node].camera;
    const tinygltf::Camera &cam = m.cameras[(size_t)ci];
    const std::string name = element("cameras", (size_t)ci);
    if (cam.type != "perspective") {
        warn(c, name + ": type \"" + cam.type + "\" is not supported; using a camera that frames the scene");
        return;
    }
    const tinygltf::PerspectiveCamera &p = cam.perspective;
    // glTF has no zero defaults: yfov and znear must be > 0 (0 would mean the renderer's default)
    if (!(p.yfov > 0.0) || !(p.znear > 0.0) || (float)p.yfov == 0.0f || (float)p.znear == 0.0f) {
        char msg[160];
        std::snprintf(msg, sizeof msg, ": yfov = %g, znear = %g: both must be > 0 in single precision", p.yfov, p.znear);
        warn(c, name + msg + "; using a camera that frames the scene");
        return;
    }
    const double origin[3] = {0, 0, 0}, minus_z[3] = {0, 0, -1}, plus_y[3] = {0, 1, 0};
    double pos[3], fwd[3], up[3];
    mat_point(g.camera_world, origin, pos);
    mat_dir(g.camera_world, minus_z, fwd);
    mat_dir(g.camera_world, plus_y, up);
    if (!normalize3(fwd) || !normalize3(up)) {
        warn(c, element("nodes", (size_t)g.camera_node) + ": degenerate camera transform; using a camera that frames the scene");
        return;
    }
    // The target only gives the direction; put it at the scene centre's depth, so that tools
    // orbiting around the target orbit around something sensible.
    double depth = 0.0;
    for (int k = 0; k < 3; k++) depth += (0.5 * ((double)bmin[k] + bmax[k]) - pos[k]) * fwd[k];
    if (!(depth > p.znear)) depth = 1.0;
    tl_camera file = {};
    for (int k = 0; k < 3; k++) {
        file.position[k] = (float)pos[k];
        file.target[k] = to_float(pos[k] + fwd[k] * depth);
        file.up[k] = (float)up[k];
    }
    file.fov_y = (float)p.yfov;
    file.near_z = (float)p.znear;
    // glTF: zfar absent (tinygltf: 0) means an infinite projection; one past float's range too
    file.far_z = p.zfar > FLT_MAX ? INFINITY : (float)p.zfar; // below -FLT_MAX: -Inf, refused
    float omin[3], omax[3];
    bool drawn = tl__objects_bounds(s->objects, s->object_count, omin, omax);
    if (renderable(c, name, drawn ? omin : nullptr, drawn ? omax : nullptr, &file)) *out = file;
}

} // namespace tl_gltf
