/* What a glTF file may read (docs/gltf.md, "External files"): by default only regular files in
 * its own folder and below; "..", absolute paths, file: and other URI schemes, and symbolic links
 * that lead out are errors for buffers and warnings for images, with messages that say nothing
 * about the file outside; a FIFO, a device or a directory is refused at once, never waited on.
 * The application's tl_gltf_files may choose otherwise, and tl_scene_parse_gltf loads from
 * memory exactly what tl_scene_load_gltf loads from the file. */
#define _XOPEN_SOURCE 700

#include <signal.h>
#include <stdint.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gltf_fixtures.h"
#include "gltf_hostile.h"
#include "thinlight/io.h"
#include "thinlight/scene.h"
#include "tl_test.h"

#ifndef TL_GLTF_FILES_TEST_DIR
#define TL_GLTF_FILES_TEST_DIR "gltf_files_work"
#endif

/* The outside file: a distinctive size and content that no message may show. */
#define SECRET "SECRET-CONTENT-4711"
#define SECRET_SIZE 777

/* Every case in its own folder: DIR/case/sub holds the glTF file, DIR/case the outside files. */
static void folders(const char *test, char top[512], char sub[1024])
{
    snprintf(top, 512, "%s/%s", TL_GLTF_FILES_TEST_DIR, test);
    tlh_rmtree(top);
    snprintf(sub, 1024, "%s/sub", top);
    TL_CHECK(tlh_mkdirs(sub) == 0);
}

/* tri.bin: one triangle; tex.png: a 2x2 image; outside.bin (SECRET_SIZE bytes) above. */
static void write_files(const char *top, const char *sub)
{
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint8_t rgba[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    char path[2048];
    snprintf(path, sizeof path, "%s/tri.bin", sub);
    TL_CHECK(tlh_write(path, tri, sizeof tri) == 0);
    size_t n = 0;
    unsigned char *png = tlh_png(2, 2, rgba, &n);
    snprintf(path, sizeof path, "%s/tex.png", sub);
    TL_CHECK(png && tlh_write(path, png, n) == 0);
    free(png);
    char secret[SECRET_SIZE];
    memset(secret, 'x', sizeof secret);
    memcpy(secret, SECRET, strlen(SECRET));
    snprintf(path, sizeof path, "%s/outside.bin", top);
    TL_CHECK(tlh_write(path, secret, sizeof secret) == 0);
    snprintf(path, sizeof path, "%s/outside36.bin", top); /* a valid buffer, for the callbacks */
    TL_CHECK(tlh_write(path, tri, sizeof tri) == 0);
}

/* The glTF text of a textured triangle with the given buffer and image URIs. */
static void scene_json(char *out, size_t n, const char *buffer_uri, const char *image_uri)
{
    snprintf(out, n,
             "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"uri\":\"%s\",\"byteLength\":36}],"
             "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
             "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],"
             "\"images\":[{\"uri\":\"%s\"}],\"textures\":[{\"source\":0}],"
             "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
             "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":0}]}],"
             "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}",
             buffer_uri, image_uri);
}

typedef struct loaded {
    tl_result result;
    tl_scene *scene;
    tlh_log log;
    tlh_counter count;
} loaded;

/* Writes sub/scene.gltf with these URIs and loads it by path. */
static void load_uris(loaded *l, const char *sub, const char *buffer_uri, const char *image_uri,
                      const tl_gltf_options *base)
{
    char json[4096], path[2048];
    scene_json(json, sizeof json, buffer_uri, image_uri);
    snprintf(path, sizeof path, "%s/scene.gltf", sub);
    TL_CHECK(tlh_write(path, json, strlen(json)) == 0);
    memset(l, 0, sizeof *l);
    tl_gltf_options o = base ? *base : (tl_gltf_options){0};
    o.logger = TLH_LOGGER(&l->log);
    o.allocator = TLH_ALLOCATOR(&l->count);
    alarm(30); /* a FIFO that blocked the load would fail the test here, not hang it */
    l->result = tl_scene_load_gltf(path, &o, &l->scene);
    alarm(0);
    TL_CHECK(l->log.multiline == 0);
    TL_CHECK((l->result == TL_OK) == (l->scene != NULL));
}

static void unload(loaded *l)
{
    tl_scene_destroy(l->scene);
    l->scene = NULL;
    TL_CHECK(l->count.live_blocks == 0);
}

/* Nothing about the outside file in any message: not its content, not its size. */
static void check_silent_about_outside(const loaded *l)
{
    const char *texts[2] = {l->log.error, l->log.warnings_text};
    for (int i = 0; i < 2; i++) {
        TL_CHECK(strstr(texts[i], SECRET) == NULL);
        TL_CHECK(strstr(texts[i], "777") == NULL);
    }
}

static void expect_buffer_refused(const char *sub, const char *uri, const char *why)
{
    loaded l;
    load_uris(&l, sub, uri, "tex.png", NULL);
    if (l.result != TL_ERROR_IO || !strstr(l.log.error, why))
        fprintf(stderr, "buffer '%s': %s (%s)\n", uri, tl_result_string(l.result), l.log.error);
    TL_CHECK(l.result == TL_ERROR_IO);
    TL_CHECK(strstr(l.log.error, why) != NULL);
    check_silent_about_outside(&l);
    unload(&l);
}

static void expect_image_refused(const char *sub, const char *uri, const char *why)
{
    loaded l;
    load_uris(&l, sub, "tri.bin", uri, NULL);
    TL_CHECK(l.result == TL_OK);
    if (!strstr(l.log.warnings_text, why)) fprintf(stderr, "image '%s': %s\n", uri, l.log.warnings_text);
    TL_CHECK(strstr(l.log.warnings_text, why) != NULL);
    if (l.scene) TL_CHECK(l.scene->texture_count == 0 && l.scene->materials[0].albedo_map == 0);
    check_silent_about_outside(&l);
    unload(&l);
}

/* ---- the folder and what climbs out of it ------------------------------------------------ */

TL_TEST(gltf_files_inside_the_folder_load)
{
    char top[512], sub[1024];
    folders("inside", top, sub);
    write_files(top, sub);
    char dir[2048];
    snprintf(dir, sizeof dir, "%s/deeper", sub);
    TL_CHECK(tlh_mkdirs(dir) == 0);
    static const char *const buffers[] = {"tri.bin", "./tri.bin", "deeper/../tri.bin", "tr%69.bin"};
    for (size_t i = 0; i < sizeof buffers / sizeof buffers[0]; i++) {
        loaded l;
        load_uris(&l, sub, buffers[i], "deeper/../tex.png", NULL);
        if (l.result != TL_OK) fprintf(stderr, "%s: %s\n", buffers[i], l.log.error);
        TL_CHECK(l.result == TL_OK && l.log.warnings == 0);
        if (l.scene) TL_CHECK(l.scene->texture_count == 1 && l.scene->vertex_count == 3);
        unload(&l);
    }
}

TL_TEST(gltf_files_parent_folder_refused)
{
    char top[512], sub[1024];
    folders("parent", top, sub);
    write_files(top, sub);
    static const char *const uris[] = {"../outside.bin", "deeper/../../outside.bin", "%2E%2E/outside.bin",
                                       "..%2Foutside.bin", "../nonexistent.bin"};
    for (size_t i = 0; i < sizeof uris / sizeof uris[0]; i++) {
        expect_buffer_refused(sub, uris[i], "outside the glTF file's folder");
        expect_image_refused(sub, uris[i], "outside the glTF file's folder");
    }
}

TL_TEST(gltf_files_absolute_and_file_uris_refused)
{
    char top[512], sub[1024];
    folders("absolute", top, sub);
    write_files(top, sub);
    char real[4096], abs_uri[4200], file_uri[4200];
    TL_CHECK(realpath(top, real) != NULL);
    snprintf(abs_uri, sizeof abs_uri, "%s/outside.bin", real);
    snprintf(file_uri, sizeof file_uri, "file://%s/sub/tri.bin", real);
    expect_buffer_refused(sub, abs_uri, "an absolute path");
    expect_image_refused(sub, abs_uri, "an absolute path");
    const char *schemes[] = {file_uri, "file:tri.bin", "FILE:tex.png", "http://example.com/tri.bin"};
    for (int i = 0; i < 4; i++) {
        expect_buffer_refused(sub, schemes[i], "URI schemes");
        expect_image_refused(sub, schemes[i], "URI schemes");
    }
}

TL_TEST(gltf_files_symbolic_links_out_refused)
{
    char top[512], sub[1024], link[2048], up[2048], in[2048];
    folders("symlinks", top, sub);
    write_files(top, sub);
    snprintf(link, sizeof link, "%s/link.bin", sub);
    snprintf(up, sizeof up, "%s/up", sub);
    snprintf(in, sizeof in, "%s/inlink.bin", sub);
    TL_CHECK(symlink("../outside.bin", link) == 0);
    TL_CHECK(symlink("..", up) == 0);
    TL_CHECK(symlink("tri.bin", in) == 0);
    expect_buffer_refused(sub, "link.bin", "a symbolic link leads out");
    expect_buffer_refused(sub, "up/outside.bin", "a symbolic link leads out");
    expect_image_refused(sub, "link.bin", "a symbolic link leads out");
    loaded l; /* a link that stays inside is fine */
    load_uris(&l, sub, "inlink.bin", "tex.png", NULL);
    TL_CHECK(l.result == TL_OK);
    unload(&l);
}

/* ---- what is not a regular file ------------------------------------------------------------ */

TL_TEST(gltf_files_fifo_device_directory_refused_at_once)
{
    char top[512], sub[1024], fifo[2048], dir[2048];
    folders("special", top, sub);
    write_files(top, sub);
    snprintf(fifo, sizeof fifo, "%s/fifo.bin", sub);
    snprintf(dir, sizeof dir, "%s/dir.png", sub);
    TL_CHECK(mkfifo(fifo, 0600) == 0);
    TL_CHECK(tlh_mkdirs(dir) == 0);
    expect_buffer_refused(sub, "fifo.bin", "not a regular file");
    expect_image_refused(sub, "fifo.bin", "not a regular file");
    expect_buffer_refused(sub, "dir.png", "a directory");
    expect_image_refused(sub, "dir.png", "a directory");
    /* the glTF file itself: a FIFO, a device, a directory */
    const char *mains[] = {fifo, "/dev/zero", dir};
    for (int i = 0; i < 3; i++) {
        tlh_log log = {0};
        tl_gltf_options o = {.logger = TLH_LOGGER(&log)};
        tl_scene *s = NULL;
        alarm(30);
        tl_result r = tl_scene_load_gltf(mains[i], &o, &s);
        alarm(0);
        TL_CHECK(r == TL_ERROR_IO && s == NULL);
        TL_CHECK(strstr(log.error, i == 2 ? "a directory" : "not a regular file") != NULL);
    }
}

/* ---- the application's file callbacks ---------------------------------------------------- */

typedef struct app_files {
    char top[1024];
    int reads, releases;
    size_t last_max;
    tl_result force; /* TL_OK: read; else return this */
} app_files;

/* Reads any URI relative to `top` (so "../x" and "sub/x" are its choice), through malloc. */
static tl_result app_read(void *user, const char *uri, size_t max_size, void **data, size_t *size, const char **why)
{
    app_files *a = user;
    a->reads++;
    a->last_max = max_size;
    if (a->force != TL_OK) {
        *why = "the application says no";
        return a->force;
    }
    char path[2048];
    snprintf(path, sizeof path, "%s/sub/%s", a->top, uri);
    size_t n = 0;
    unsigned char *b = tlf_read_file(path, &n);
    if (!b) return TL_ERROR_IO;
    *data = b;
    *size = n;
    return TL_OK;
}

static void app_release(void *user, void *data, size_t size)
{
    (void)size;
    ((app_files *)user)->releases++;
    free(data);
}

TL_TEST(gltf_files_callbacks_choose)
{
    char top[512], sub[1024];
    folders("callbacks", top, sub);
    write_files(top, sub);
    app_files a = {0};
    snprintf(a.top, sizeof a.top, "%s", top);
    tl_gltf_options o = {.files = {app_read, app_release, &a}};
    loaded l;
    load_uris(&l, sub, "../outside36.bin", "../sub/tex.png", &o);
    TL_CHECK(l.result == TL_OK && a.reads == 2 && a.releases == 2);
    if (l.scene) TL_CHECK(l.scene->texture_count == 1);
    TL_CHECK(a.last_max > 0 && a.last_max < TL_GLTF_DEFAULT_MAX_MEMORY);
    unload(&l);
    /* their failures keep their result, and their reason is in the message */
    const tl_result forced[3] = {TL_ERROR_IO, TL_ERROR_LIMIT, TL_ERROR_OUT_OF_MEMORY};
    for (int i = 0; i < 3; i++) {
        a.force = forced[i];
        load_uris(&l, sub, "tri.bin", "tex.png", &o);
        TL_CHECK(l.result == forced[i]);
        TL_CHECK(strstr(l.log.error, "'tri.bin': the application says no") != NULL);
        unload(&l);
    }
}

/* ---- memory loads -------------------------------------------------------------------------- */

static int same_scene(const tl_scene *a, const tl_scene *b)
{
    int same = a->vertex_count == b->vertex_count && a->index_count == b->index_count &&
               a->object_count == b->object_count && a->material_count == b->material_count &&
               a->texture_count == b->texture_count && a->light_count == b->light_count;
    if (!same) return 0;
    same &= !a->vertex_count || !memcmp(a->vertices, b->vertices, a->vertex_count * sizeof *a->vertices);
    same &= !a->index_count || !memcmp(a->indices, b->indices, a->index_count * sizeof *a->indices);
    same &= !a->object_count || !memcmp(a->objects, b->objects, a->object_count * sizeof *a->objects);
    same &= !a->material_count || !memcmp(a->materials, b->materials, a->material_count * sizeof *a->materials);
    same &= !a->light_count || !memcmp(a->lights, b->lights, a->light_count * sizeof *a->lights);
    for (size_t i = 0; same && i < a->texture_count; i++)
        same &= a->textures[i].width == b->textures[i].width && a->textures[i].height == b->textures[i].height &&
                !memcmp(a->textures[i].rgba, b->textures[i].rgba, (size_t)a->textures[i].width * a->textures[i].height * 4);
    return same && !memcmp(&a->camera, &b->camera, sizeof a->camera);
}

TL_TEST(gltf_memory_load_equals_path_load)
{
    char top[512], sub[1024];
    folders("memory", top, sub);
    int (*const writers[3])(const char *, const char *, tlf_storage) = {tlf_write_textured_boxes, tlf_write_materials,
                                                                         tlf_write_lights};
    const char *names[3] = {"textured_boxes", "materials", "lights"};
    for (int w = 0; w < 3; w++)
        for (int storage = TLF_EXTERNAL; storage <= TLF_GLB; storage++) {
            char path[2048];
            TL_CHECK(writers[w](sub, names[w], (tlf_storage)storage) == 0);
            snprintf(path, sizeof path, "%s/%s.%s", sub, names[w], storage == TLF_GLB ? "glb" : "gltf");
            tl_scene *by_path = NULL, *by_memory = NULL;
            TL_CHECK(tl_scene_load_gltf(path, NULL, &by_path) == TL_OK);
            size_t n = 0;
            unsigned char *bytes = tlf_read_file(path, &n);
            app_files a = {0};
            snprintf(a.top, sizeof a.top, "%s", top);
            /* external files through the application's callbacks; the others need none */
            tl_gltf_options o = {.files = {app_read, app_release, &a}};
            TL_CHECK(bytes && tl_scene_parse_gltf(bytes, n, storage == TLF_EXTERNAL ? &o : NULL, &by_memory) == TL_OK);
            TL_CHECK(by_path && by_memory && same_scene(by_path, by_memory));
            TL_CHECK(a.reads == a.releases);
            tl_scene_destroy(by_path);
            tl_scene_destroy(by_memory);
            free(bytes);
        }
}

TL_TEST(gltf_memory_load_without_callbacks_reads_no_file)
{
    char top[512], sub[1024], json[4096];
    folders("nofiles", top, sub);
    write_files(top, sub);
    scene_json(json, sizeof json, "tri.bin", "tex.png");
    tlh_log log = {0};
    tl_gltf_options o = {.logger = TLH_LOGGER(&log), .name = "in-memory.gltf"};
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_parse_gltf(json, strlen(json), &o, &s) == TL_ERROR_IO && s == NULL);
    TL_CHECK(strstr(log.error, "in-memory.gltf: 'tri.bin': external files cannot be read here") != NULL);
    /* the buffer as a data URI: loads, and the external image is a warning */
    char data_json[4096];
    scene_json(data_json, sizeof data_json,
               "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA", "tex.png");
    memset(&log, 0, sizeof log);
    TL_CHECK(tl_scene_parse_gltf(data_json, strlen(data_json), &o, &s) == TL_OK && s != NULL);
    TL_CHECK(strstr(log.warnings_text, "'tex.png': external files cannot be read here") != NULL);
    tl_scene_destroy(s);
    /* NULL data is an argument error, and no name means "memory" */
    memset(&log, 0, sizeof log);
    o.name = NULL;
    TL_CHECK(tl_scene_parse_gltf(NULL, 5, &o, &s) == TL_ERROR_INVALID_ARGUMENT && s == NULL);
    TL_CHECK(tl_scene_parse_gltf("", 0, &o, &s) == TL_ERROR_PARSE && strstr(log.error, "memory: empty file"));
    tl_gltf_options half = {.files = {NULL, app_release, NULL}};
    TL_CHECK(tl_scene_parse_gltf(json, strlen(json), &half, &s) == TL_ERROR_INVALID_ARGUMENT);
}
