// The node hierarchy: pick the scene, prove the node graph is a forest (every reference in range,
// at most one parent, no cycle) and walk it depth-first without recursion, so that neither a
// cyclic nor a very deep file can hang the loader or overflow the stack.
#include <cmath>

#include "gltf_internal.h"
#include "gltf_math.h"

namespace tl_gltf {
namespace {

// The node's local matrix: `matrix` if given, else T * R * S.
void local_matrix(const tinygltf::Node &n, size_t index, double out[16])
{
    const std::string name = element("nodes", index);
    auto check = [&](const std::vector<double> &v, size_t want, const char *what) {
        if (!v.empty() && v.size() != want)
            fail(TL_ERROR_PARSE, name + ": " + what + " has " + std::to_string(v.size()) + " numbers, not " +
                                     std::to_string(want));
        for (double x : v)
            if (!std::isfinite(x)) fail(TL_ERROR_PARSE, name + ": " + what + " is not finite");
    };
    check(n.matrix, 16, "matrix");
    check(n.translation, 3, "translation");
    check(n.rotation, 4, "rotation");
    check(n.scale, 3, "scale");
    if (!n.matrix.empty()) {
        for (int i = 0; i < 16; i++) out[i] = n.matrix[(size_t)i];
        return;
    }
    double t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1};
    for (size_t i = 0; i < n.translation.size(); i++) t[i] = n.translation[i];
    for (size_t i = 0; i < n.scale.size(); i++) s[i] = n.scale[i];
    if (!n.rotation.empty()) {
        // glTF asks for unit quaternions; normalising keeps a sloppy exporter's rotations rigid.
        double l = std::sqrt(n.rotation[0] * n.rotation[0] + n.rotation[1] * n.rotation[1] +
                             n.rotation[2] * n.rotation[2] + n.rotation[3] * n.rotation[3]);
        if (!(l > 1e-12)) fail(TL_ERROR_PARSE, name + ": rotation is a zero quaternion");
        for (int i = 0; i < 4; i++) q[i] = n.rotation[(size_t)i] / l;
    }
    mat_trs(t, q, s, out);
}

// Light index from the node's KHR_lights_punctual extension, or -1.
int node_light(const tinygltf::Node &n, size_t index, size_t light_count)
{
    auto it = n.extensions.find("KHR_lights_punctual");
    if (it == n.extensions.end() || !it->second.IsObject() || !it->second.Has("light")) return -1;
    const tinygltf::Value &v = it->second.Get("light");
    if (!v.IsNumber()) fail(TL_ERROR_PARSE, element("nodes", index) + ": KHR_lights_punctual.light is not a number");
    double d = v.GetNumberAsDouble();
    if (!(d >= 0.0) || d >= (double)light_count || d != std::floor(d))
        fail(TL_ERROR_PARSE, element("nodes", index) + ": light " + std::to_string(d) + " out of range (" +
                                 std::to_string(light_count) + " lights)");
    return (int)d;
}

// Every child reference in range, at most one parent per node, no cycle. Fills parent[].
void check_forest(const tinygltf::Model &m, vec<int> *parent)
{
    size_t n = m.nodes.size();
    parent->assign(n, -1);
    for (size_t i = 0; i < n; i++) {
        for (int child : m.nodes[i].children) {
            if (child < 0 || (size_t)child >= n)
                fail(TL_ERROR_PARSE, element("nodes", i) + ": child " + std::to_string(child) + " out of range (" +
                                         std::to_string(n) + " nodes)");
            if ((size_t)child == i) fail(TL_ERROR_PARSE, element("nodes", i) + ": cycle in the node hierarchy (the node is its own child)");
            if ((*parent)[(size_t)child] >= 0)
                fail(TL_ERROR_PARSE, element("nodes", (size_t)child) + ": has two parents (nodes " +
                                         std::to_string((*parent)[(size_t)child]) + " and " + std::to_string(i) + ")");
            (*parent)[(size_t)child] = (int)i;
        }
    }
    // With one parent each, a cycle is a parent chain that comes back to itself. Colour the
    // chains: 1 = on the chain being followed, 2 = known to reach a root. O(nodes) in all.
    vec<unsigned char> state(n, 0, stl_allocator<unsigned char>(parent->get_allocator().c));
    for (size_t i = 0; i < n; i++) {
        size_t j = i;
        while (state[j] == 0) {
            state[j] = 1;
            if ((*parent)[j] < 0) break;
            j = (size_t)(*parent)[j];
        }
        if (state[j] == 1 && (*parent)[j] >= 0)
            fail(TL_ERROR_PARSE, element("nodes", j) + ": cycle in the node hierarchy (the node is its own ancestor)");
        for (j = i; state[j] == 1; j = (size_t)(*parent)[j]) {
            state[j] = 2;
            if ((*parent)[j] < 0) break;
        }
    }
}

} // namespace

namespace {

// The root list: the chosen scene's nodes, or every root node of a file without scenes. Returns
// the name messages use for the list.
std::string choose_roots(const context &c, const tinygltf::Model &m, const vec<int> &parent, vec<int> *roots)
{
    if (c.scene_number > 0) {
        if (c.scene_number > m.scenes.size())
            fail(TL_ERROR_INVALID_ARGUMENT, "scene number " + std::to_string(c.scene_number) + " but the file has " +
                                                std::to_string(m.scenes.size()) + " scenes");
        size_t s = c.scene_number - 1;
        roots->assign(m.scenes[s].nodes.begin(), m.scenes[s].nodes.end());
        return element("scenes", s);
    }
    if (!m.scenes.empty()) {
        if (m.defaultScene >= 0 && (size_t)m.defaultScene >= m.scenes.size())
            fail(TL_ERROR_PARSE, "scene " + std::to_string(m.defaultScene) + " out of range (" +
                                     std::to_string(m.scenes.size()) + " scenes)");
        size_t s = m.defaultScene >= 0 ? (size_t)m.defaultScene : 0;
        roots->assign(m.scenes[s].nodes.begin(), m.scenes[s].nodes.end());
        return element("scenes", s);
    }
    for (size_t i = 0; i < m.nodes.size(); i++)
        if (parent[i] < 0) roots->push_back((int)i);
    if (!roots->empty()) warn(c, "no scenes: drawing all " + std::to_string(roots->size()) + " root nodes");
    return "nodes";
}

// What node ni with world transform `world` puts in the scene: a mesh instance, the first
// camera, a light.
void visit_node(const context &c, const tinygltf::Model &m, size_t ni, const double world[16], scene_graph *g,
                bool *skin_warned)
{
    const tinygltf::Node &n = m.nodes[ni];
    if (n.mesh >= 0) {
        if ((size_t)n.mesh >= m.meshes.size())
            fail(TL_ERROR_PARSE, element("nodes", ni) + ": mesh " + std::to_string(n.mesh) + " out of range (" +
                                     std::to_string(m.meshes.size()) + " meshes)");
        if (n.skin >= 0 && !*skin_warned) {
            warn(c, element("nodes", ni) + ": skinning is not supported; drawing the bind pose");
            *skin_warned = true;
        }
        mesh_instance mi;
        mi.node = (int)ni;
        mi.mesh = n.mesh;
        std::copy(world, world + 16, mi.world);
        g->meshes.push_back(mi);
    }
    if (n.camera >= 0) {
        if ((size_t)n.camera >= m.cameras.size())
            fail(TL_ERROR_PARSE, element("nodes", ni) + ": camera " + std::to_string(n.camera) + " out of range (" +
                                     std::to_string(m.cameras.size()) + " cameras)");
        if (g->camera_node < 0) {
            g->camera_node = (int)ni;
            std::copy(world, world + 16, g->camera_world);
        }
    }
    int light = node_light(n, ni, m.lights.size());
    if (light >= 0) {
        light_instance li;
        li.node = (int)ni;
        li.light = light;
        std::copy(world, world + 16, li.world);
        g->lights.push_back(li);
    }
}

} // namespace

void walk_scene(const context &c, const tinygltf::Model &m, scene_graph *g)
{
    vec<int> parent = make_vec<int>(c);
    check_forest(m, &parent);
    vec<int> roots = make_vec<int>(c);
    std::string scene_name = choose_roots(c, m, parent, &roots);

    struct item {
        int node;
        double parent_world[16];
    };
    vec<item> stack = make_vec<item>(c);
    double identity[16];
    mat_identity(identity);
    for (size_t i = roots.size(); i-- > 0;) {
        if (roots[i] < 0 || (size_t)roots[i] >= m.nodes.size())
            fail(TL_ERROR_PARSE, scene_name + ": node " + std::to_string(roots[i]) + " out of range (" +
                                     std::to_string(m.nodes.size()) + " nodes)");
        item it;
        it.node = roots[i];
        std::copy(identity, identity + 16, it.parent_world);
        stack.push_back(it);
    }
    bool skin_warned = false;
    while (!stack.empty()) {
        item it = stack.back();
        stack.pop_back();
        size_t ni = (size_t)it.node;
        const tinygltf::Node &n = m.nodes[ni];
        double local[16], world[16];
        local_matrix(n, ni, local);
        mat_mul(it.parent_world, local, world);
        // The scene stores transforms in float.
        for (double x : world)
            if (!fits_float(x))
                fail(TL_ERROR_PARSE, element("nodes", ni) + ": world transform overflows single precision");
        visit_node(c, m, ni, world, g, &skin_warned);
        // Children in reverse so that they pop in file order (pre-order, first child first).
        for (size_t k = n.children.size(); k-- > 0;) {
            item child;
            child.node = n.children[k];
            std::copy(world, world + 16, child.parent_world);
            stack.push_back(child);
        }
    }
}

} // namespace tl_gltf
