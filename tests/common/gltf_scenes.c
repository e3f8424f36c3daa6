/* The glTF fixture writer's three test scenes (gltf_fixtures.h): their geometry, their images and
 * their documents. */
#include <stdio.h>
#include <string.h>

#include "gltf_doc.h"

/* ---- geometry ------------------------------------------------------------------------------ */
/* An axis-aligned box of half size h around c: 4 vertices per face, counter-clockwise from
 * outside, UVs glTF-style (v grows against the face's second axis, so tangents have w = -1). */
void make_box(tlf_mesh *m, const float c[3], float h)
{
    m->nv = m->ni = 0;
    for (int a = 0; a < 3; a++)
        for (int s = 1; s >= -1; s -= 2) {
            float n[3] = {0, 0, 0}, u[3] = {0, 0, 0}, v[3] = {0, 0, 0};
            n[a] = (float)s;
            /* u x v = n: (e[a+1], e[a+2]) for +, swapped for - */
            u[s > 0 ? (a + 1) % 3 : (a + 2) % 3] = 1.0f;
            v[s > 0 ? (a + 2) % 3 : (a + 1) % 3] = 1.0f;
            static const float cu[4] = {-1, 1, 1, -1}, cv[4] = {-1, -1, 1, 1};
            uint16_t base = (uint16_t)m->nv;
            for (int k = 0; k < 4; k++) {
                for (int j = 0; j < 3; j++) {
                    m->pos[m->nv][j] = c[j] + h * (n[j] + cu[k] * u[j] + cv[k] * v[j]);
                    m->nrm[m->nv][j] = n[j];
                }
                m->uv[m->nv][0] = 0.5f * (cu[k] + 1.0f);
                m->uv[m->nv][1] = 0.5f * (1.0f - cv[k]);
                m->nv++;
            }
            static const uint16_t tri[6] = {0, 1, 2, 0, 2, 3};
            for (int k = 0; k < 6; k++) m->idx[m->ni++] = (uint16_t)(base + tri[k]);
        }
}

/* A horizontal quad facing +Y: centre (cx, y, cz), half size h; UV (0,0) at (-x, -z). */
void make_quad(tlf_mesh *m, float cx, float y, float cz, float h)
{
    static const float corner[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}}; /* (x, z) */
    m->nv = 4;
    for (int k = 0; k < 4; k++) {
        m->pos[k][0] = cx + h * corner[k][0];
        m->pos[k][1] = y;
        m->pos[k][2] = cz + h * corner[k][1];
        m->nrm[k][0] = m->nrm[k][2] = 0.0f;
        m->nrm[k][1] = 1.0f;
        m->uv[k][0] = 0.5f * (corner[k][0] + 1.0f);
        m->uv[k][1] = 0.5f * (corner[k][1] + 1.0f);
    }
    static const uint16_t tri[6] = {0, 1, 2, 0, 2, 3};
    memcpy(m->idx, tri, sizeof tri);
    m->ni = 6;
}

/* A vertical quad facing +Z: centre (cx, cy, z), half size h; UV (0,0) at the top left. */
static void make_wall_quad(tlf_mesh *m, float cx, float cy, float z, float h)
{
    static const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}; /* (x, y) */
    m->nv = 4;
    for (int k = 0; k < 4; k++) {
        m->pos[k][0] = cx + h * corner[k][0];
        m->pos[k][1] = cy + h * corner[k][1];
        m->pos[k][2] = z;
        m->nrm[k][0] = m->nrm[k][1] = 0.0f;
        m->nrm[k][2] = 1.0f;
        m->uv[k][0] = 0.5f * (corner[k][0] + 1.0f);
        m->uv[k][1] = 0.5f * (1.0f - corner[k][1]);
    }
    static const uint16_t tri[6] = {0, 1, 2, 0, 2, 3};
    memcpy(m->idx, tri, sizeof tri);
    m->ni = 6;
}

/* POSITION, NORMAL, TEXCOORD_0 (float) and u16 indices; returns the first accessor index. */
int add_mesh(tlf_doc *d, const tlf_mesh *m)
{
    int first = doc_accessor(d, m->pos, m->nv, F32, "VEC3", 0);
    doc_accessor(d, m->nrm, m->nv, F32, "VEC3", 0);
    doc_accessor(d, m->uv, m->nv, F32, "VEC2", 0);
    doc_accessor(d, m->idx, m->ni, U16, "SCALAR", 0);
    return first;
}

/* ---- images -------------------------------------------------------------------------------- */

/* 4x4: two-colour checker (albedo), flat normal map, metallic-roughness (G 128, B 255), and an
 * alpha ramp. */
int write_images(const char *dir)
{
    uint8_t albedo[64], normal[64], mr[64], alpha[64];
    for (int i = 0; i < 16; i++) {
        int on = ((i % 4) + (i / 4)) % 2;
        uint8_t a[4] = {on ? 230 : 40, on ? 200 : 60, on ? 160 : 90, 255};
        uint8_t n[4] = {128, 128, 255, 255};
        uint8_t r[4] = {0, 128, 255, 255};
        uint8_t t[4] = {255, 255, 255, (uint8_t)(i * 17)};
        memcpy(albedo + 4 * i, a, 4);
        memcpy(normal + 4 * i, n, 4);
        memcpy(mr + 4 * i, r, 4);
        memcpy(alpha + 4 * i, t, 4);
    }
    return write_png(dir, "albedo.png", 4, 4, albedo) || write_png(dir, "normal.png", 4, 4, normal) ||
           write_png(dir, "mr.png", 4, 4, mr) || write_png(dir, "albedo_alpha.png", 4, 4, alpha);
}

/* ---- the three scenes ----------------------------------------------------------------------- */

int tlf_write_textured_boxes(const char *dir, const char *name, tlf_storage storage)
{
    if (write_images(dir)) return -1;
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    const float origin[3] = {0, 0, 0};
    make_box(&m, origin, 0.5f);
    add_mesh(&d, &m); /* accessors 0..3 */
    make_quad(&m, 0.0f, 0.55f, 0.0f, 0.5f); /* a lid just above the box: coplanar faces would z-fight */
    add_mesh(&d, &m); /* accessors 4..7 */
    doc_image(&d, "albedo.png", "image/png");
    doc_image(&d, "normal.png", "image/png");
    doc_image(&d, "mr.png", "image/png");
    const char *members =
        "\"samplers\":[{\"magFilter\":9729,\"minFilter\":9987}],"
        "\"textures\":[{\"source\":0,\"sampler\":0},{\"source\":1,\"sampler\":0},{\"source\":2,\"sampler\":0}],"
        "\"materials\":["
        "{\"name\":\"checker\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0.9,0.8,1],\"baseColorTexture\":{\"index\":0},"
        "\"metallicFactor\":0.5,\"roughnessFactor\":0.75,\"metallicRoughnessTexture\":{\"index\":2}},"
        "\"normalTexture\":{\"index\":1,\"scale\":0.8}},"
        "{\"name\":\"painted\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.2,0.4,0.6,1],\"baseColorTexture\":{\"index\":0},"
        "\"metallicFactor\":0,\"roughnessFactor\":0.5}}],"
        "\"meshes\":["
        "{\"name\":\"box\",\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,\"material\":0}]},"
        "{\"name\":\"two_part\",\"primitives\":["
        "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,\"material\":1},"
        "{\"attributes\":{\"POSITION\":4,\"NORMAL\":5,\"TEXCOORD_0\":6},\"indices\":7,\"material\":0}]}],"
        "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1}}],"
        "\"nodes\":["
        "{\"name\":\"root\",\"translation\":[10,0,0],\"scale\":[2,2,2],\"children\":[1,2]},"
        "{\"name\":\"spinner\",\"translation\":[0,1,0],\"rotation\":[0,0.70710678118654752,0,0.70710678118654752],"
        "\"mesh\":0,\"children\":[3]},"
        "{\"name\":\"matrixed\",\"matrix\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,3,1],\"mesh\":1},"
        "{\"name\":\"leaf\",\"translation\":[1,0,0],\"mesh\":0},"
        "{\"name\":\"camera\",\"translation\":[10,2,14],\"camera\":0}],"
        "\"scenes\":[{\"nodes\":[0,4]}],\"scene\":0";
    char path[1024];
    int rc = doc_write(&d, name, storage, members, path, sizeof path);
    doc_free(&d);
    return rc;
}

int tlf_write_materials(const char *dir, const char *name, tlf_storage storage)
{
    if (write_images(dir)) return -1;
    tlf_doc d = {.dir = dir};
    tlf_buf prims = {0};
    for (int i = 0; i < 8; i++) {
        tlf_mesh m;
        make_wall_quad(&m, 1.5f * (float)i, 0.5f, 0.0f, 0.5f);
        int pos = doc_accessor(&d, m.pos, 4, F32, "VEC3", 0);
        int nrm = i < 4 ? doc_accessor(&d, m.nrm, 4, F32, "VEC3", 0) : -1;
        /* UVs as normalised integers: 8-bit on even quads, 16-bit on odd ones. */
        int uv;
        if (i % 2 == 0) {
            uint8_t q[8];
            for (int k = 0; k < 8; k++) q[k] = (uint8_t)(m.uv[k / 2][k % 2] * 255.0f);
            uv = doc_accessor(&d, q, 4, U8, "VEC2", 1);
        } else {
            uint16_t q[8];
            for (int k = 0; k < 8; k++) q[k] = (uint16_t)(m.uv[k / 2][k % 2] * 65535.0f);
            uv = doc_accessor(&d, q, 4, U16, "VEC2", 1);
        }
        int idx = doc_accessor(&d, m.idx, 6, U16, "SCALAR", 0);
        buf_printf(&prims, "%s{\"attributes\":{\"POSITION\":%d,", i ? "," : "", pos);
        if (nrm >= 0) buf_printf(&prims, "\"NORMAL\":%d,", nrm);
        buf_printf(&prims, "\"TEXCOORD_0\":%d},\"indices\":%d", uv, idx);
        if (i < 7) buf_printf(&prims, ",\"material\":%d", i);
        buf_printf(&prims, "}");
    }
    doc_image(&d, "albedo_alpha.png", "image/png");
    doc_image(&d, "mr.png", "image/png");
    tlf_buf members = {0};
    buf_printf(&members,
               "\"extensionsUsed\":[\"KHR_materials_emissive_strength\"],"
               "\"textures\":[{\"source\":0},{\"source\":1}],"
               "\"materials\":["
               "{\"name\":\"metal\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.9,0.6,0.3,1],\"metallicFactor\":1,\"roughnessFactor\":0.2}},"
               "{\"name\":\"dielectric\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.5,0.5,1],\"metallicFactor\":0,\"roughnessFactor\":1}},"
               "{\"name\":\"half_metal\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.2,0.4,1],\"metallicFactor\":0.5,\"roughnessFactor\":0.4}},"
               "{\"name\":\"mask\",\"alphaMode\":\"MASK\",\"alphaCutoff\":0.3,\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,0.9],"
               "\"baseColorTexture\":{\"index\":0},\"metallicFactor\":0}},"
               "{\"name\":\"blend\",\"alphaMode\":\"BLEND\",\"doubleSided\":true,\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.1,0.8,0.1,0.5],"
               "\"metallicFactor\":0,\"roughnessFactor\":0.3}},"
               "{\"name\":\"emissive_double\",\"doubleSided\":true,\"emissiveFactor\":[1,0.5,0],"
               "\"extensions\":{\"KHR_materials_emissive_strength\":{\"emissiveStrength\":2}},\"pbrMetallicRoughness\":{\"metallicFactor\":0}},"
               "{\"name\":\"mr_textured\",\"pbrMetallicRoughness\":{\"metallicFactor\":0.7,\"roughnessFactor\":0.6,"
               "\"metallicRoughnessTexture\":{\"index\":1}},\"occlusionTexture\":{\"index\":1,\"strength\":0.5}}],"
               "\"meshes\":[{\"name\":\"swatches\",\"primitives\":[%s]}],"
               "\"nodes\":[{\"name\":\"swatches\",\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
               buf_str(&prims));
    char path[1024];
    int rc = prims.oom || members.oom ? -1 : doc_write(&d, name, storage, buf_str(&members), path, sizeof path);
    buf_free(&prims);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

int tlf_write_lights(const char *dir, const char *name, tlf_storage storage)
{
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    make_quad(&m, 0.0f, 0.0f, 0.0f, 10.0f);
    int floor_pos = doc_accessor(&d, m.pos, 4, F32, "VEC3", 0);
    int floor_nrm = doc_accessor(&d, m.nrm, 4, F32, "VEC3", 0);
    uint32_t idx32[6];
    for (int k = 0; k < 6; k++) idx32[k] = m.idx[k];
    int floor_idx = doc_accessor(&d, idx32, 6, U32, "SCALAR", 0);
    const float origin[3] = {0, 0, 0};
    make_box(&m, origin, 0.5f);
    int box = add_mesh(&d, &m);
    tlf_buf members = {0};
    buf_printf(&members,
               "\"extensionsUsed\":[\"KHR_lights_punctual\"],"
               "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":["
               "{\"name\":\"warm_point\",\"type\":\"point\",\"color\":[1,0.5,0.25],\"intensity\":10,\"range\":5},"
               "{\"name\":\"white_point\",\"type\":\"point\",\"intensity\":3.14159265358979},"
               "{\"name\":\"spot\",\"type\":\"spot\",\"color\":[0.5,0.5,1],\"intensity\":20,\"range\":10,"
               "\"spot\":{\"innerConeAngle\":0.2,\"outerConeAngle\":0.5}},"
               "{\"name\":\"sun\",\"type\":\"directional\",\"color\":[1,1,0.9],\"intensity\":3}]}},"
               "\"materials\":[{\"name\":\"floor\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.6,0.6,0.6,1],\"metallicFactor\":0,"
               "\"roughnessFactor\":0.8}}],"
               "\"meshes\":[{\"name\":\"floor\",\"primitives\":[{\"attributes\":{\"POSITION\":%d,\"NORMAL\":%d},\"indices\":%d,\"material\":0}]},"
               "{\"name\":\"box\",\"primitives\":[{\"attributes\":{\"POSITION\":%d,\"NORMAL\":%d,\"TEXCOORD_0\":%d},\"indices\":%d,\"material\":0}]}],"
               "\"nodes\":["
               "{\"name\":\"floor\",\"mesh\":0},"
               "{\"name\":\"box\",\"mesh\":1,\"translation\":[0,0.5,0]},"
               "{\"name\":\"warm\",\"translation\":[1,2,3],\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}},"
               "{\"name\":\"white\",\"translation\":[-4,5,0],\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}}},"
               "{\"name\":\"rig\",\"translation\":[2,0,0],\"children\":[5]},"
               "{\"name\":\"spot\",\"translation\":[0,6,0],\"rotation\":[-0.70710678118654752,0,0,0.70710678118654752],"
               "\"extensions\":{\"KHR_lights_punctual\":{\"light\":2}}},"
               "{\"name\":\"sun\",\"rotation\":[0,0.70710678118654752,0,0.70710678118654752],"
               "\"extensions\":{\"KHR_lights_punctual\":{\"light\":3}}}],"
               "\"scenes\":[{\"nodes\":[0,1,2,3,4,6]}]",
               floor_pos, floor_nrm, floor_idx, box, box + 1, box + 2, box + 3);
    char path[1024];
    int rc = members.oom ? -1 : doc_write(&d, name, storage, buf_str(&members), path, sizeof path);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

int tlf_write_shadow_scene(const char *dir, const char *name, tlf_storage storage, int sun, const char *flag)
{
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    make_quad(&m, 0.0f, 0.0f, 0.0f, 10.0f);
    int floor_pos = doc_accessor(&d, m.pos, 4, F32, "VEC3", 0);
    int floor_nrm = doc_accessor(&d, m.nrm, 4, F32, "VEC3", 0);
    int floor_idx = doc_accessor(&d, m.idx, 6, U16, "SCALAR", 0);
    const float centre[3] = {0.0f, TLF_SHADOW_BOX_Y, 0.0f};
    make_box(&m, centre, TLF_SHADOW_BOX_HALF);
    int box = add_mesh(&d, &m);
    tlf_buf extras = {0}, members = {0};
    if (flag) buf_printf(&extras, ",\"extras\":{\"thinlight_shadow\":%s}", flag);
    /* the light: -90 degrees about X turns its -Z down; the camera: -45 degrees, looking at the origin */
    buf_printf(&members,
               "\"extensionsUsed\":[\"KHR_lights_punctual\"],"
               "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[%s%s}]}},",
               sun ? "{\"name\":\"sun\",\"type\":\"directional\",\"intensity\":3"
                   : "{\"name\":\"spot\",\"type\":\"spot\",\"intensity\":200,\"range\":20,"
                     "\"spot\":{\"innerConeAngle\":0.4,\"outerConeAngle\":0.6}",
               buf_str(&extras));
    buf_printf(&members,
               "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1,\"zfar\":100}}],"
               "\"materials\":[{\"name\":\"grey\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.6,0.6,0.6,1],"
               "\"metallicFactor\":0,\"roughnessFactor\":0.8}}],"
               "\"meshes\":[{\"name\":\"floor\",\"primitives\":[{\"attributes\":{\"POSITION\":%d,\"NORMAL\":%d},"
               "\"indices\":%d,\"material\":0}]},"
               "{\"name\":\"box\",\"primitives\":[{\"attributes\":{\"POSITION\":%d,\"NORMAL\":%d,\"TEXCOORD_0\":%d},"
               "\"indices\":%d,\"material\":0}]}],"
               "\"nodes\":[{\"name\":\"floor\",\"mesh\":0},{\"name\":\"box\",\"mesh\":1},"
               "{\"name\":\"spot\",\"translation\":[0,%g,0],\"rotation\":[-0.70710678118654752,0,0,0.70710678118654752],"
               "\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}},"
               "{\"name\":\"camera\",\"camera\":0,\"translation\":[0,7,7],"
               "\"rotation\":[-0.38268343236508977,0,0,0.92387953251128676]}],"
               "\"scenes\":[{\"nodes\":[0,1,2,3]}]",
               floor_pos, floor_nrm, floor_idx, box, box + 1, box + 2, box + 3, (double)TLF_SHADOW_SPOT_Y);
    char path[1024];
    int rc = members.oom || extras.oom ? -1 : doc_write(&d, name, storage, buf_str(&members), path, sizeof path);
    buf_free(&extras);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

int tl_test_write_gltf_scenes(const char *dir)
{
    if (tlf_mkdir_p(dir)) {
        fprintf(stderr, "gltf fixtures: cannot create %s\n", dir);
        return -1;
    }
    if (tlf_write_textured_boxes(dir, "textured_boxes", TLF_EXTERNAL) || tlf_write_materials(dir, "materials", TLF_GLB) ||
        tlf_write_lights(dir, "lights", TLF_DATA_URI))
        return -1;
    return 0;
}
