/* The glTF fixture writer's named good and bad cases (tlf_write_case, gltf_fixtures.h), which
 * tests/io and tests/input load. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_doc.h"
#include "thinlight/io.h"

/* ---- named cases --------------------------------------------------------------------------- */

/* One quad (4 float positions, u16 indices) as accessors 0 and 1, with `members` appended; the
 * default mesh/node/scene members unless `custom` is set. */
static int quad_case(const char *dir, const char *name, tlf_storage storage, const char *members, int custom, char *path,
                     size_t path_size)
{
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    make_quad(&m, 0.0f, 0.0f, 0.0f, 1.0f);
    doc_accessor(&d, m.pos, 4, F32, "VEC3", 0);
    doc_accessor(&d, m.idx, 6, U16, "SCALAR", 0);
    tlf_buf all = {0};
    if (!custom)
        buf_printf(&all, "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]%s",
                   members && *members ? "," : "");
    buf_printf(&all, "%s", members ? members : "");
    int rc = all.oom ? -1 : doc_write(&d, name, storage, buf_str(&all), path, path_size);
    buf_free(&all);
    doc_free(&d);
    return rc;
}

static int write_text(const char *dir, const char *file, const char *text, char *path, size_t path_size)
{
    tlf_join(path, path_size, dir, file);
    return tlf_write_file(path, text, strlen(text));
}

/* A quad whose positions, normals or indices are given. */
static int geometry_case(const char *dir, const char *name, const float (*pos)[3], const float (*nrm)[3], size_t nv,
                         const uint32_t *idx, size_t ni, char *path, size_t path_size)
{
    tlf_doc d = {.dir = dir};
    int p = doc_accessor(&d, pos, nv, F32, "VEC3", 0);
    int n = nrm ? doc_accessor(&d, nrm, nv, F32, "VEC3", 0) : -1;
    int i = idx ? doc_accessor(&d, idx, ni, U32, "SCALAR", 0) : -1;
    tlf_buf members = {0};
    buf_printf(&members, "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":%d", p);
    if (n >= 0) buf_printf(&members, ",\"NORMAL\":%d", n);
    buf_printf(&members, "}");
    if (i >= 0) buf_printf(&members, ",\"indices\":%d", i);
    buf_printf(&members, "}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]");
    int rc = members.oom ? -1 : doc_write(&d, name, TLF_EXTERNAL, buf_str(&members), path, path_size);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

static uint32_t crc32_png(const unsigned char *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
}

/* A valid 4x4 PNG whose header then claims w x h (CRC fixed, so only the size is absurd). */
static int huge_png(const char *dir, const char *file, uint32_t w, uint32_t h)
{
    uint8_t px[64] = {0};
    if (write_png(dir, file, 4, 4, px)) return -1;
    char path[1024];
    tlf_join(path, sizeof path, dir, file);
    size_t n = 0;
    unsigned char *b = tlf_read_file(path, &n);
    if (!b || n < 33 || memcmp(b + 12, "IHDR", 4) != 0) {
        free(b);
        return -1;
    }
    for (int k = 0; k < 4; k++) {
        b[16 + k] = (unsigned char)(w >> (24 - 8 * k));
        b[20 + k] = (unsigned char)(h >> (24 - 8 * k));
    }
    uint32_t crc = crc32_png(b + 12, 17);
    for (int k = 0; k < 4; k++) b[29 + k] = (unsigned char)(crc >> (24 - 8 * k));
    int rc = tlf_write_file(path, b, n);
    free(b);
    return rc;
}

/* A quad with TEXCOORD_0 and a material whose base colour texture is image 0 given by `image`
 * JSON (or by the document's first image when `image` is NULL). */
static int textured_quad_case(const char *dir, const char *name, tlf_storage storage, const char *image_file,
                              const char *image_json, char *path, size_t path_size)
{
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    make_quad(&m, 0.0f, 0.0f, 0.0f, 1.0f);
    add_mesh(&d, &m);
    if (image_file) doc_image(&d, image_file, "image/png");
    tlf_buf members = {0};
    buf_printf(&members,
               "%s%s\"textures\":[{\"source\":0}],"
               "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.25,0.5,0.75,1],\"baseColorTexture\":{\"index\":0},"
               "\"metallicFactor\":0}}],"
               "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,\"material\":0}]}],"
               "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
               image_json ? image_json : "", image_json ? "," : "");
    int rc = members.oom ? -1 : doc_write(&d, name, storage, buf_str(&members), path, path_size);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

static int case_indices(const char *dir, const char *name, char *path, size_t path_size)
{
    /* Four quads at x = 0, 3, 6, 9: u8, u16, u32 indices and non-indexed; UVs as normalised u8,
     * normalised u16, float, float. */
    tlf_doc d = {.dir = dir};
    tlf_buf prims = {0};
    for (int q = 0; q < 4; q++) {
        tlf_mesh m;
        make_quad(&m, 3.0f * (float)q, 0.0f, 0.0f, 1.0f);
        int pos, uv, idx = -1;
        if (q < 3) {
            pos = doc_accessor(&d, m.pos, 4, F32, "VEC3", 0);
        } else {
            float flat[6][3];
            for (int k = 0; k < 6; k++) memcpy(flat[k], m.pos[m.idx[k]], sizeof flat[k]);
            pos = doc_accessor(&d, flat, 6, F32, "VEC3", 0);
        }
        if (q == 0) {
            uint8_t t[8] = {0, 255, 255, 255, 255, 0, 0, 0};
            uv = doc_accessor(&d, t, 4, U8, "VEC2", 1);
            uint8_t i8[6];
            for (int k = 0; k < 6; k++) i8[k] = (uint8_t)m.idx[k];
            idx = doc_accessor(&d, i8, 6, U8, "SCALAR", 0);
        } else if (q == 1) {
            uint16_t t[8] = {0, 65535, 65535, 65535, 65535, 0, 0, 0};
            uv = doc_accessor(&d, t, 4, U16, "VEC2", 1);
            idx = doc_accessor(&d, m.idx, 6, U16, "SCALAR", 0);
        } else if (q == 2) {
            float t[8] = {0, 1, 1, 1, 1, 0, 0, 0};
            uv = doc_accessor(&d, t, 4, F32, "VEC2", 0);
            uint32_t i32[6];
            for (int k = 0; k < 6; k++) i32[k] = m.idx[k];
            idx = doc_accessor(&d, i32, 6, U32, "SCALAR", 0);
        } else {
            float t[12] = {0, 1, 1, 1, 1, 0, 0, 1, 1, 0, 0, 0};
            uv = doc_accessor(&d, t, 6, F32, "VEC2", 0);
        }
        buf_printf(&prims, "%s{\"attributes\":{\"POSITION\":%d,\"TEXCOORD_0\":%d}", q ? "," : "", pos, uv);
        if (idx >= 0) buf_printf(&prims, ",\"indices\":%d", idx);
        buf_printf(&prims, "}");
    }
    tlf_buf members = {0};
    buf_printf(&members, "\"meshes\":[{\"primitives\":[%s]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
               buf_str(&prims));
    int rc = members.oom || prims.oom ? -1 : doc_write(&d, name, TLF_EXTERNAL, buf_str(&members), path, path_size);
    buf_free(&prims);
    buf_free(&members);
    doc_free(&d);
    return rc;
}

/* A box of 8 shared corners (indexed, no NORMAL), with a normal-mapped material: the loader
 * generates normals (flat: unshared; smooth: shared) and tangents. */
static int case_generated_frames(const char *dir, const char *name, char *path, size_t path_size)
{
    if (write_images(dir)) return -1;
    tlf_doc d = {.dir = dir};
    tlf_mesh m;
    const float origin[3] = {0, 0, 0};
    make_box(&m, origin, 0.5f);
    float pos[8][3], uv[8][2];
    uint16_t idx[36];
    size_t n = 0;
    for (size_t i = 0; i < m.ni; i++) {
        const float *p = m.pos[m.idx[i]];
        size_t k = 0;
        while (k < n && memcmp(pos[k], p, sizeof pos[k]) != 0) k++;
        if (k == n) {
            memcpy(pos[n], p, sizeof pos[n]);
            /* A planar projection: some faces get no UV area (their tangents need a fallback). */
            uv[n][0] = p[0] + 0.5f;
            uv[n][1] = 0.5f - p[2] + 0.25f * p[1];
            n++;
        }
        idx[i] = (uint16_t)k;
    }
    doc_accessor(&d, pos, n, F32, "VEC3", 0);
    doc_accessor(&d, uv, n, F32, "VEC2", 0);
    doc_accessor(&d, idx, 36, U16, "SCALAR", 0);
    doc_image(&d, "normal.png", "image/png");
    const char *members =
        "\"textures\":[{\"source\":0}],\"materials\":[{\"normalTexture\":{\"index\":0}}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1},\"indices\":2,\"material\":0}]}],"
        "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]";
    int rc = doc_write(&d, name, TLF_EXTERNAL, members, path, path_size);
    doc_free(&d);
    return rc;
}

/* The shadow scenes (tlf_write_shadow_scene): shadow_spot and shadow_sun without a flag, _cast
 * "thinlight_shadow": true, _no_cast false, _bad_flag "yes". */
static int case_shadow_scene(const char *dir, const char *name, char *path, size_t path_size)
{
    int sun = strncmp(name, "shadow_sun", 10) == 0;
    const char *suffix = name + 10 + !sun; /* after "shadow_sun" or "shadow_spot" */
    const char *flag = !*suffix                             ? NULL
                       : strcmp(suffix, "_cast") == 0       ? "true"
                       : strcmp(suffix, "_no_cast") == 0    ? "false"
                       : strcmp(suffix, "_bad_flag") == 0   ? "\"yes\""
                                                            : "";
    if (flag && !*flag) return -1;
    char file[96];
    snprintf(file, sizeof file, "%s.gltf", name);
    tlf_join(path, path_size, dir, file);
    return tlf_write_shadow_scene(dir, name, TLF_DATA_URI, sun, flag);
}

/* Eight lights on a quad, for the shadow flags and the rule (docs/gltf.md, "Shadows"): 0 a
 * directional light without a flag, 1 one flagged false, 2 a spot flagged true, 3 a point light of
 * intensity 100 and 4 one of 10 (no flags), 5 a point light flagged "yes", 6 one flagged 1 (both
 * not booleans), 7 one whose extras are not an object; all point and spot lights range 10. */
static int case_light_shadow_flags(const char *dir, const char *name, char *path, size_t path_size)
{
    static const char *const lights[8] = {
        "{\"type\":\"directional\"}", "{\"type\":\"directional\",\"extras\":{\"thinlight_shadow\":false}}",
        "{\"type\":\"spot\",\"range\":10,\"spot\":{},\"extras\":{\"thinlight_shadow\":true}}",
        "{\"type\":\"point\",\"intensity\":100,\"range\":10}", "{\"type\":\"point\",\"intensity\":10,\"range\":10}",
        "{\"type\":\"point\",\"range\":10,\"extras\":{\"thinlight_shadow\":\"yes\"}}",
        "{\"type\":\"point\",\"range\":10,\"extras\":{\"thinlight_shadow\":1}}",
        "{\"type\":\"point\",\"range\":10,\"extras\":[true]}"};
    tlf_buf m = {0};
    buf_printf(&m, "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                   "\"extensionsUsed\":[\"KHR_lights_punctual\"],\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[");
    for (int k = 0; k < 8; k++) buf_printf(&m, "%s%s", k ? "," : "", lights[k]);
    buf_printf(&m, "]}},\"nodes\":[{\"mesh\":0}");
    for (int k = 0; k < 8; k++)
        buf_printf(&m, ",{\"translation\":[0,%d,0],\"extensions\":{\"KHR_lights_punctual\":{\"light\":%d}}}", k + 1, k);
    buf_printf(&m, "],\"scenes\":[{\"nodes\":[0,1,2,3,4,5,6,7,8]}]");
    int rc = m.oom ? -1 : quad_case(dir, name, TLF_EXTERNAL, buf_str(&m), 1, path, path_size);
    buf_free(&m);
    return rc;
}

int tlf_write_case(const char *dir, const char *name, char *path, size_t path_size)
{
    if (tlf_mkdir_p(dir)) return -1;
    const float nan = strtof("nan", NULL), inf = strtof("inf", NULL);
    if (strcmp(name, "textured_boxes") == 0 || strcmp(name, "textured_boxes_glb") == 0 ||
        strcmp(name, "textured_boxes_data_uri") == 0) {
        tlf_storage s = strcmp(name, "textured_boxes") == 0 ? TLF_EXTERNAL
                        : strcmp(name, "textured_boxes_glb") == 0 ? TLF_GLB : TLF_DATA_URI;
        if (tlf_write_textured_boxes(dir, name, s)) return -1;
        char file[256];
        snprintf(file, sizeof file, "%s.%s", name, s == TLF_GLB ? "glb" : "gltf");
        tlf_join(path, path_size, dir, file);
        return 0;
    }
    if (strcmp(name, "materials") == 0) {
        if (tlf_write_materials(dir, name, TLF_GLB)) return -1;
        tlf_join(path, path_size, dir, "materials.glb");
        return 0;
    }
    if (strcmp(name, "lights") == 0) {
        if (tlf_write_lights(dir, name, TLF_DATA_URI)) return -1;
        tlf_join(path, path_size, dir, "lights.gltf");
        return 0;
    }
    if (strncmp(name, "shadow_spot", 11) == 0 || strncmp(name, "shadow_sun", 10) == 0)
        return case_shadow_scene(dir, name, path, path_size);
    if (strcmp(name, "light_shadow_flags") == 0) return case_light_shadow_flags(dir, name, path, path_size);
    if (strcmp(name, "indices") == 0) return case_indices(dir, name, path, path_size);
    if (strcmp(name, "generated_frames") == 0) return case_generated_frames(dir, name, path, path_size);
    if (strcmp(name, "quad") == 0) return quad_case(dir, name, TLF_EXTERNAL, "", 0, path, path_size);
    if (strcmp(name, "malformed_json") == 0)
        return write_text(dir, "malformed_json.gltf", "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}", path,
                          path_size);
    if (strcmp(name, "wrong_types") == 0) {
        /* accessors[0].count is a string */
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        doc_view(&d, p, sizeof p);
        doc_raw_accessor(&d, "{\"bufferView\":0,\"componentType\":5126,\"count\":\"three\",\"type\":\"VEC3\"}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "missing_bin") == 0) {
        if (quad_case(dir, name, TLF_EXTERNAL, "", 0, path, path_size)) return -1;
        char bin[1024];
        tlf_join(bin, sizeof bin, dir, "missing_bin.bin");
        return remove(bin) == 0 ? 0 : -1;
    }
    if (strcmp(name, "missing_image") == 0) {
        /* the image file is never written */
        return textured_quad_case(dir, name, TLF_EXTERNAL, NULL, "\"images\":[{\"uri\":\"no_such_image.png\"}]", path,
                                  path_size);
    }
    if (strcmp(name, "texture_unsupported") == 0) {
        char file[1024];
        tlf_join(file, sizeof file, dir, "not_an_image.png");
        const char junk[] = "this is not an image, whatever its name says";
        if (tlf_write_file(file, junk, sizeof junk)) return -1;
        return textured_quad_case(dir, name, TLF_GLB, "not_an_image.png", NULL, path, path_size);
    }
    if (strcmp(name, "texture_truncated_png") == 0) {
        /* a valid PNG cut in half */
        if (write_images(dir)) return -1;
        char file[1024];
        tlf_join(file, sizeof file, dir, "albedo.png");
        size_t n = 0;
        unsigned char *b = tlf_read_file(file, &n);
        tlf_join(file, sizeof file, dir, "half.png");
        int rc = b ? tlf_write_file(file, b, n / 2) : -1;
        free(b);
        return rc ? rc : textured_quad_case(dir, name, TLF_EXTERNAL, "half.png", NULL, path, path_size);
    }
    if (strcmp(name, "texture_jpeg") == 0) {
        /* an 8x8 mid-grey RGB JPEG, embedded in a GLB (decoded from memory) */
        uint8_t rgb[8 * 8 * 3];
        memset(rgb, 128, sizeof rgb);
        char file[1024];
        tlf_join(file, sizeof file, dir, "grey.jpg");
        tl_image_desc jd = {.width = 8, .height = 8, .channels = 3, .type = TL_PIXEL_U8, .logger = {tlf_log_stderr, NULL}};
        if (tl_image_write(file, &jd, rgb) != TL_OK) return -1;
        tlf_doc d = {.dir = dir};
        tlf_mesh m;
        make_quad(&m, 0.0f, 0.0f, 0.0f, 1.0f);
        add_mesh(&d, &m);
        doc_image(&d, "grey.jpg", "image/jpeg");
        int rc = doc_write(&d, name, TLF_GLB,
                           "\"textures\":[{\"source\":0}],\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,\"material\":0}]}],"
                           "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "texture_huge") == 0) {
        if (huge_png(dir, "huge.png", 60000, 60000)) return -1;
        return textured_quad_case(dir, name, TLF_EXTERNAL, "huge.png", NULL, path, path_size);
    }
    if (strcmp(name, "texture_4x4") == 0) {
        if (write_images(dir)) return -1;
        return textured_quad_case(dir, name, TLF_EXTERNAL, "albedo.png", NULL, path, path_size);
    }
    if (strcmp(name, "bufferview_out_of_range") == 0) {
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        doc_view(&d, p, sizeof p);
        doc_raw_accessor(&d, "{\"bufferView\":99,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "accessor_past_view") == 0) {
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        doc_view(&d, p, sizeof p);
        doc_raw_accessor(&d, "{\"bufferView\":0,\"componentType\":5126,\"count\":300,\"type\":\"VEC3\"}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "view_past_buffer") == 0) {
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        doc_view(&d, p, sizeof p);
        /* a second view that starts inside the buffer and runs past its end */
        buf_printf(&d.views, ",{\"buffer\":0,\"byteOffset\":24,\"byteLength\":4096}");
        d.view_count++;
        doc_raw_accessor(&d, "{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "accessor_ref_out_of_range") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":42},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "mesh_ref_out_of_range") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":7}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "index_out_of_range") == 0) {
        const float pos[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        const uint32_t idx[6] = {0, 1, 2, 0, 2, 99};
        return geometry_case(dir, name, pos, NULL, 3, idx, 6, path, path_size);
    }
    if (strcmp(name, "node_cycle") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"children\":[1]},{\"children\":[2],\"mesh\":0},{\"children\":[0]}],"
                         "\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "node_self_child") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"children\":[0],\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "node_two_parents") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"children\":[2]},{\"children\":[2]},{\"mesh\":0}],\"scenes\":[{\"nodes\":[0,1]}]",
                         1, path, path_size);
    if (strcmp(name, "node_child_out_of_range") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"children\":[5],\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "nan_position") == 0 || strcmp(name, "inf_position") == 0) {
        float bad = name[0] == 'n' ? nan : inf;
        const float pos[3][3] = {{0, 0, 0}, {1, bad, 0}, {0, 1, 0}};
        return geometry_case(dir, name, pos, NULL, 3, NULL, 0, path, path_size);
    }
    if (strcmp(name, "zero_normals") == 0) {
        const float pos[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {0, 0, -1}};
        const float nrm[4][3] = {{0, 0, 0}, {0, 2, 0}, {nan, 0, 0}, {0, 0, 0}};
        const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
        return geometry_case(dir, name, pos, nrm, 4, idx, 6, path, path_size);
    }
    if (strcmp(name, "empty_scene") == 0)
        return write_text(dir, "empty_scene.gltf",
                          "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"name\":\"nothing\"}],\"scenes\":[{\"nodes\":[0]}]}",
                          path, path_size);
    if (strcmp(name, "no_scenes") == 0)
        return write_text(dir, "no_scenes.gltf", "{\"asset\":{\"version\":\"2.0\"}}", path, path_size);
    if (strcmp(name, "required_extension") == 0)
        return quad_case(dir, name, TLF_EXTERNAL, "\"extensionsRequired\":[\"KHR_draco_mesh_compression\"],"
                                                  "\"extensionsUsed\":[\"KHR_draco_mesh_compression\"]",
                         0, path, path_size);
    if (strcmp(name, "sparse_accessor") == 0) {
        tlf_doc d = {.dir = dir};
        float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        uint16_t si[1] = {1};
        float sv[3] = {5, 5, 5};
        doc_view(&d, p, sizeof p);
        doc_view(&d, si, sizeof si);
        doc_view(&d, sv, sizeof sv);
        doc_raw_accessor(&d, "{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"sparse\":{\"count\":1,"
                             "\"indices\":{\"bufferView\":1,\"componentType\":5123},\"values\":{\"bufferView\":2}}}");
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],"
                           "\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "lines_mode") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"mode\":1},"
                         "{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "unknown_mode") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"mode\":7},"
                         "{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                         1, path, path_size);
    if (strcmp(name, "multi_scene") == 0)
        /* scene 0 draws node 0 (x = 0), scene 1 (the default) node 1 (x = 5) */
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"translation\":[5,0,0]}],"
                         "\"scenes\":[{\"nodes\":[0]},{\"nodes\":[1]}],\"scene\":1",
                         1, path, path_size);
    if (strcmp(name, "zero_accessors") == 0) {
        /* POSITION and NORMAL without buffer views (all zeros, glTF says) for 300000 vertices,
         * one triangle drawn */
        tlf_doc d = {.dir = dir};
        uint16_t idx[3] = {0, 1, 2};
        doc_raw_accessor(&d, "{\"componentType\":5126,\"count\":300000,\"type\":\"VEC3\"}");
        doc_raw_accessor(&d, "{\"componentType\":5126,\"count\":300000,\"type\":\"VEC3\"}");
        doc_accessor(&d, idx, 3, U16, "SCALAR", 0);
        int rc = doc_write(&d, name, TLF_EXTERNAL,
                           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":2}]}],"
                           "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
                           path, path_size);
        doc_free(&d);
        return rc;
    }
    if (strcmp(name, "mirrored") == 0)
        /* the same quad as is (x = 0) and mirrored in x (at x = 5) */
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"translation\":[5,0,0],\"scale\":[-1,1,1]}],"
                         "\"scenes\":[{\"nodes\":[0,1]}]",
                         1, path, path_size);
    if (strcmp(name, "orthographic_camera") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"cameras\":[{\"type\":\"orthographic\",\"orthographic\":{\"xmag\":1,\"ymag\":1,\"znear\":0.1,\"zfar\":10}}],"
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,5]}],\"scenes\":[{\"nodes\":[0,1]}]",
                         1, path, path_size);
    if (strcmp(name, "camera_zfar") == 0)
        return quad_case(dir, name, TLF_EXTERNAL,
                         "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":1.0,\"znear\":0.5,\"zfar\":50}}],"
                         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                         "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,3,0],"
                         "\"rotation\":[-0.70710678118654752,0,0,0.70710678118654752]}],\"scenes\":[{\"nodes\":[0,1]}]",
                         1, path, path_size);
    fprintf(stderr, "gltf fixtures: unknown case '%s'\n", name);
    return -1;
}

const char *const tlf_case_names[] = {
    "textured_boxes", "textured_boxes_glb", "textured_boxes_data_uri", "materials", "lights", "indices",
    "generated_frames", "quad", "malformed_json", "wrong_types", "missing_bin", "missing_image",
    "texture_unsupported", "texture_truncated_png", "texture_jpeg", "texture_huge", "texture_4x4", "bufferview_out_of_range", "accessor_past_view",
    "view_past_buffer", "accessor_ref_out_of_range", "mesh_ref_out_of_range", "index_out_of_range", "node_cycle",
    "node_self_child", "node_two_parents", "node_child_out_of_range", "nan_position", "inf_position",
    "zero_normals", "empty_scene", "no_scenes", "required_extension", "sparse_accessor", "lines_mode", "unknown_mode",
    "multi_scene", "zero_accessors", "mirrored", "orthographic_camera", "camera_zfar", "shadow_spot",
    "shadow_spot_cast", "shadow_spot_no_cast", "shadow_spot_bad_flag", "shadow_sun", "shadow_sun_no_cast",
    "light_shadow_flags", NULL};
