/* Bad glTF input (tl_scene_load_gltf), each case its own test: malformed JSON, out-of-range
 * references, cycles, non-finite values, bad textures, limits, unsupported features, bad
 * arguments; the result code, a one-line message naming the file and the problem, and nothing
 * left allocated (gltf_checks.h). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_checks.h"

TL_TEST(gltf_malformed_json) { expect_failure("gltf_malformed_json", "malformed_json", TL_ERROR_PARSE, NULL); }
TL_TEST(gltf_wrong_types) { expect_failure("gltf_wrong_types", "wrong_types", TL_ERROR_PARSE, "count"); }
TL_TEST(gltf_missing_bin) { expect_failure("gltf_missing_bin", "missing_bin", TL_ERROR_IO, "missing_bin.bin"); }
TL_TEST(gltf_missing_file)
{
    capture log = {0};
    tl_scene *s = NULL;
    tl_gltf_options o = {.logger = {capture_fn, &log}};
    TL_CHECK(tl_scene_load_gltf(TL_GLTF_TEST_DIR "/no/such/file.gltf", &o, &s) == TL_ERROR_IO);
    TL_CHECK(s == NULL && strstr(log.last_error, "file.gltf") != NULL);
}

TL_TEST(gltf_missing_image)
{
    loaded l;
    load(&l, "gltf_missing_image", "missing_image");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "images[0]") != NULL);
    if (l.result == TL_OK) {
        TL_CHECK_EQ_U(l.scene->texture_count, 0);
        TL_CHECK(l.scene->materials[0].albedo_map == 0);
        TL_CHECK(near3(l.scene->materials[0].albedo, 0.25f, 0.5f, 0.75f, 1e-6f)); /* the flat colour */
    }
    unload(&l);
}

TL_TEST(gltf_bufferview_out_of_range)
{
    expect_failure("gltf_bufferview_out_of_range", "bufferview_out_of_range", TL_ERROR_PARSE, "accessors[0]: bufferView 99");
}
TL_TEST(gltf_accessor_past_buffer_view)
{
    expect_failure("gltf_accessor_past_buffer_view", "accessor_past_view", TL_ERROR_PARSE, "accessors[0]");
}
TL_TEST(gltf_buffer_view_past_buffer)
{
    expect_failure("gltf_buffer_view_past_buffer", "view_past_buffer", TL_ERROR_PARSE, "bufferViews[1]");
}
TL_TEST(gltf_accessor_reference_out_of_range)
{
    expect_failure("gltf_accessor_reference_out_of_range", "accessor_ref_out_of_range", TL_ERROR_PARSE, "accessor 42");
}
TL_TEST(gltf_mesh_reference_out_of_range)
{
    expect_failure("gltf_mesh_reference_out_of_range", "mesh_ref_out_of_range", TL_ERROR_PARSE, "nodes[0]: mesh 7");
}
TL_TEST(gltf_vertex_index_out_of_range)
{
    expect_failure("gltf_vertex_index_out_of_range", "index_out_of_range", TL_ERROR_PARSE, "accessors[1]: index 99");
}
TL_TEST(gltf_node_cycle) { expect_failure("gltf_node_cycle", "node_cycle", TL_ERROR_PARSE, "cycle"); }
TL_TEST(gltf_node_self_child) { expect_failure("gltf_node_self_child", "node_self_child", TL_ERROR_PARSE, "cycle"); }
TL_TEST(gltf_node_two_parents)
{
    expect_failure("gltf_node_two_parents", "node_two_parents", TL_ERROR_PARSE, "nodes[2]: has two parents");
}
TL_TEST(gltf_node_child_out_of_range)
{
    expect_failure("gltf_node_child_out_of_range", "node_child_out_of_range", TL_ERROR_PARSE, "nodes[0]: child 5");
}
TL_TEST(gltf_nan_position)
{
    expect_failure("gltf_nan_position", "nan_position", TL_ERROR_PARSE, "accessors[0]: POSITION element 1 is not finite");
}
TL_TEST(gltf_inf_position)
{
    expect_failure("gltf_inf_position", "inf_position", TL_ERROR_PARSE, "accessors[0]: POSITION element 1 is not finite");
}

TL_TEST(gltf_zero_length_normals)
{
    loaded l;
    load(&l, "gltf_zero_length_normals", "zero_normals");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "3 zero-length or non-finite normals regenerated") != NULL);
    if (l.result == TL_OK)
        for (size_t i = 0; i < l.scene->vertex_count; i++) TL_CHECK(near3(l.scene->vertices[i].normal, 0, 1, 0, 1e-6f));
    unload(&l);
}

TL_TEST(gltf_texture_unsupported_format)
{
    loaded l;
    load(&l, "gltf_texture_unsupported_format", "texture_unsupported");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "images[0]") != NULL);
    if (l.result == TL_OK) {
        TL_CHECK_EQ_U(l.scene->texture_count, 0);
        TL_CHECK(l.scene->materials[0].albedo_map == 0);
    }
    unload(&l);
}

TL_TEST(gltf_texture_jpeg)
{
    loaded l;
    load(&l, "gltf_texture_jpeg", "texture_jpeg");
    TL_CHECK(l.result == TL_OK && l.log.warnings == 0);
    if (l.result == TL_OK && l.scene->texture_count == 1) {
        const tl_texture *t = &l.scene->textures[0];
        TL_CHECK(t->width == 8 && t->height == 8);
        for (size_t i = 0; i < 64; i++) {
            for (int k = 0; k < 3; k++) TL_CHECK(abs((int)t->rgba[4 * i + (size_t)k] - 128) <= 2); /* lossy */
            TL_CHECK(t->rgba[4 * i + 3] == 255);
        }
    } else {
        TL_CHECK(l.scene && l.scene->texture_count == 1);
    }
    unload(&l);
}

TL_TEST(gltf_texture_truncated_png)
{
    loaded l;
    load(&l, "gltf_texture_truncated_png", "texture_truncated_png");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "images[0]: truncated PNG") != NULL);
    if (l.result == TL_OK) TL_CHECK(l.scene->materials[0].albedo_map == 0);
    unload(&l);
}

TL_TEST(gltf_texture_absurd_size)
{
    expect_failure("gltf_texture_absurd_size", "texture_huge", TL_ERROR_LIMIT, "images[0]: 60000x60000");
}

TL_TEST(gltf_texture_pixel_limit_option)
{
    tl_gltf_options o = {.max_texture_pixels = 15};
    loaded l;
    load_opts(&l, "gltf_texture_pixel_limit_option", "texture_4x4", &o);
    TL_CHECK(l.result == TL_ERROR_LIMIT);
    unload(&l);
    o.max_texture_pixels = 16;
    load_opts(&l, "gltf_texture_pixel_limit_option", "texture_4x4", &o);
    TL_CHECK(l.result == TL_OK && l.scene && l.scene->texture_count == 1);
    unload(&l);
}

TL_TEST(gltf_triangle_limit)
{
    tl_gltf_options o = {.max_triangles = 37}; /* textured_boxes draws 12 + 12 + 12 + 2 */
    loaded l;
    load_opts(&l, "gltf_triangle_limit", "textured_boxes", &o);
    TL_CHECK(l.result == TL_ERROR_LIMIT);
    unload(&l);
    o.max_triangles = 38;
    load_opts(&l, "gltf_triangle_limit", "textured_boxes", &o);
    TL_CHECK(l.result == TL_OK);
    unload(&l);
}

TL_TEST(gltf_accessor_without_buffer_view)
{
    /* glTF: an accessor without a buffer view reads as zeros. 300000 such vertices load (their
     * zero normals are regenerated), but not past 3 vertices per triangle of max_triangles. */
    loaded l;
    load(&l, "gltf_accessor_without_buffer_view", "zero_accessors");
    TL_CHECK(l.result == TL_OK);
    if (l.result == TL_OK) {
        TL_CHECK_EQ_U(l.scene->vertex_count, 300000);
        TL_CHECK_EQ_U(l.scene->object_count, 1);
        TL_CHECK(near3(l.scene->vertices[299999].position, 0, 0, 0, 0.0f));
        TL_CHECK(near(len3(l.scene->vertices[123].normal), 1.0f, 1e-6f));
    }
    unload(&l);
    tl_gltf_options o = {.max_triangles = 99999};
    load_opts(&l, "gltf_accessor_without_buffer_view", "zero_accessors", &o);
    TL_CHECK(l.result == TL_ERROR_LIMIT);
    TL_CHECK(strstr(l.error, "300000 vertices") != NULL);
    unload(&l);
}

TL_TEST(gltf_empty_scene)
{
    /* An empty but valid scene (documented): no objects, a warning, the default rig and a
     * camera around the origin. */
    const char *cases[2] = {"empty_scene", "no_scenes"};
    for (int i = 0; i < 2; i++) {
        loaded l;
        load(&l, "gltf_empty_scene", cases[i]);
        TL_CHECK(l.result == TL_OK);
        if (l.result == TL_OK) {
            const tl_scene *s = l.scene;
            TL_CHECK(s->object_count == 0 && s->vertex_count == 0 && s->index_count == 0);
            TL_CHECK(s->objects == NULL && s->vertices == NULL);
            TL_CHECK(strstr(l.log.warnings_text, "no triangles") != NULL);
            TL_CHECK_EQ_U(s->light_count, 5);
            check_geometry(s);
            tl_scene_feature_set f;
            tl_scene_features(s, &f);
            TL_CHECK(f.triangle_count == 0);
        }
        unload(&l);
    }
}

TL_TEST(gltf_truncated_glb)
{
    char path[1024], cut[1024], dir[1024];
    if (fixture("gltf_truncated_glb", "textured_boxes_glb", path, sizeof path)) return;
    case_dir(dir, sizeof dir, "gltf_truncated_glb");
    tlf_join(cut, sizeof cut, dir, "cut.glb");
    size_t n = 0;
    unsigned char *b = tlf_read_file(path, &n);
    TL_CHECK(b != NULL && n > 100);
    if (!b) return;
    for (size_t len = 0; len < n; len += (len < 64 || n - len < 64) ? 1 : 7) {
        if (tlf_write_file(cut, b, len)) break;
        counter cnt = {0};
        tl_gltf_options o = {.allocator = {count_alloc, count_free, &cnt}};
        tl_scene *s = NULL;
        tl_result r = tl_scene_load_gltf(cut, &o, &s);
        TL_CHECK(r == TL_ERROR_PARSE);
        TL_CHECK(s == NULL && cnt.live == 0);
    }
    /* A BIN chunk whose length reaches past the file by its own 8-byte header. */
    uint32_t json_len = (uint32_t)b[12] | (uint32_t)b[13] << 8 | (uint32_t)b[14] << 16 | (uint32_t)b[15] << 24;
    size_t at = 20 + json_len;
    uint32_t bin_len = (uint32_t)b[at] | (uint32_t)b[at + 1] << 8 | (uint32_t)b[at + 2] << 16 | (uint32_t)b[at + 3] << 24;
    bin_len += 8;
    for (int k = 0; k < 4; k++) b[at + (size_t)k] = (unsigned char)(bin_len >> (8 * k));
    tlf_write_file(cut, b, n);
    capture log = {0};
    tl_gltf_options o = {.logger = {capture_fn, &log}};
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(cut, &o, &s) == TL_ERROR_PARSE);
    TL_CHECK(strstr(log.last_error, "BIN chunk") != NULL);
    free(b);
}

TL_TEST(gltf_required_extension_unsupported)
{
    expect_failure("gltf_required_extension_unsupported", "required_extension", TL_ERROR_UNSUPPORTED,
                   "KHR_draco_mesh_compression");
}
TL_TEST(gltf_sparse_accessor_unsupported)
{
    expect_failure("gltf_sparse_accessor_unsupported", "sparse_accessor", TL_ERROR_UNSUPPORTED, "accessors[0]: sparse");
}

TL_TEST(gltf_lines_mode_loaded_as_lines)
{
    loaded l;
    load(&l, "gltf_lines_mode_loaded_as_lines", "lines_mode");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK_EQ_U(l.log.warnings, 0);
    if (l.result == TL_OK && l.scene->object_count == 2) {
        const tl_object *o = l.scene->objects;
        TL_CHECK_EQ_U(o[0].primitive, TL_PRIMITIVE_LINES);
        TL_CHECK_EQ_U(o[1].primitive, TL_PRIMITIVE_TRIANGLES);
        TL_CHECK_EQ_U(o[0].index_count, o[1].index_count); /* the same indices: 6 make 3 lines or 2 triangles */
    } else {
        TL_CHECK(0 && "two objects");
    }
    unload(&l);
}

TL_TEST(gltf_unknown_mode_skipped)
{
    loaded l;
    load(&l, "gltf_unknown_mode_skipped", "unknown_mode");
    TL_CHECK(l.result == TL_OK);
    TL_CHECK(strstr(l.log.warnings_text, "meshes[0].primitives[0]: mode 7 is not a glTF primitive mode") != NULL);
    if (l.result == TL_OK) TL_CHECK_EQ_U(l.scene->object_count, 1);
    unload(&l);
}

TL_TEST(gltf_bad_arguments)
{
    char path[1024];
    if (fixture("gltf_bad_arguments", "quad", path, sizeof path)) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(NULL, NULL, &s) == TL_ERROR_INVALID_ARGUMENT && s == NULL);
    TL_CHECK(tl_scene_load_gltf(path, NULL, NULL) == TL_ERROR_INVALID_ARGUMENT);
    counter cnt = {0};
    tl_gltf_options half = {.allocator = {count_alloc, NULL, &cnt}};
    TL_CHECK(tl_scene_load_gltf(path, &half, &s) == TL_ERROR_INVALID_ARGUMENT && s == NULL);
    tl_gltf_options bad_mode = {.normals = TL_GLTF_NORMALS_COUNT_};
    TL_CHECK(tl_scene_load_gltf(path, &bad_mode, &s) == TL_ERROR_INVALID_ARGUMENT && s == NULL);
    tl_gltf_options many = {.extra_lights = 65537};
    TL_CHECK(tl_scene_load_gltf(path, &many, &s) == TL_ERROR_LIMIT && s == NULL);
    many.extra_lights = 65536;
    TL_CHECK(tl_scene_load_gltf(path, &many, &s) == TL_OK && s && s->light_count == 65536 + 5);
    tl_scene_destroy(s);
    s = NULL;
    TL_CHECK(tl_scene_load_gltf(path, NULL, &s) == TL_OK && s != NULL); /* NULL options: defaults */
    tl_scene_destroy(s);
}

TL_TEST(gltf_error_message_one_line)
{
    /* The one error line goes to the logger: it starts with the file and names the element;
     * without a logger the load is silent; success logs no error. */
    char path[1024];
    if (fixture("gltf_error_message_one_line", "node_cycle", path, sizeof path)) return;
    capture log = {0};
    tl_gltf_options o = {.logger = {capture_fn, &log}};
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_load_gltf(path, &o, &s) == TL_ERROR_PARSE);
    TL_CHECK(log.errors == 1 && log.multiline == 0);
    TL_CHECK(strncmp(log.last_error, path, strlen(path)) == 0 && strstr(log.last_error, ": nodes[") != NULL);
    TL_CHECK(tl_scene_load_gltf(path, NULL, &s) == TL_ERROR_PARSE && s == NULL);
    if (fixture("gltf_error_message_one_line", "quad", path, sizeof path)) return;
    memset(&log, 0, sizeof log);
    TL_CHECK(tl_scene_load_gltf(path, &o, &s) == TL_OK && log.errors == 0);
    tl_scene_destroy(s);
}
