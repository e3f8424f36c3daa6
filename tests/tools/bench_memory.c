/* thinlight-bench holds a scene once, not once per configuration: on a glTF with one 8192x8192
 * texture (the loader's default pixel limit; 256 MiB decoded, 341 MiB with its mip chain in each
 * renderer that uploads it) its peak resident memory stays within thinlight-render's on the same
 * file (one renderer) plus two more copies of the texture and 128 MiB, however many
 * configurations it renders: llvmpipe frees a deleted texture only once later draws have replaced
 * the driver's bindings to it, so a renderer's upload can meet the copies of the one or two before
 * it. Before, every configuration's renderer held its own copy at once: 4.0 GiB for --quick
 * (thinlight-render: 0.8 GiB). The file is made here (a compressed PNG of one colour, 4 MiB); the
 * peaks come from wait4's rusage. */
#define _DEFAULT_SOURCE /* wait4 */

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gltf_hostile.h"
#include "tl_test.h"

#define MiB ((size_t)1 << 20)
#define SIDE 8192u

/* A quad with texture coordinates whose base colour is the texture in tex.png. */
static int write_scene(const char *dir, char *gltf, size_t size)
{
    const uint8_t rgba[4] = {200, 120, 60, 255};
    size_t png_size = 0;
    unsigned char *png = tlh_png_flat(SIDE, SIDE, rgba, &png_size);
    char path[1024];
    snprintf(path, sizeof path, "%s/tex.png", dir);
    int err = !png || tlh_write(path, png, png_size);
    free(png);
    const float pos[12] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1}, uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    const uint16_t idx[6] = {0, 2, 1, 0, 3, 2};
    unsigned char bin[92];
    memcpy(bin, pos, 48);
    memcpy(bin + 48, uv, 32);
    memcpy(bin + 80, idx, 12);
    tlh_text j = {0};
    tlh_put(&j, "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":92,\"uri\":\"data:application/octet-stream;base64,");
    tlh_base64(&j, bin, sizeof bin);
    tlh_put(&j, "\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":48},{\"buffer\":0,\"byteOffset\":48,\"byteLength\":32},"
                "{\"buffer\":0,\"byteOffset\":80,\"byteLength\":12}],\"accessors\":["
                "{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\",\"min\":[-1,0,-1],\"max\":[1,0,1]},"
                "{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC2\"},"
                "{\"bufferView\":2,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}],"
                "\"images\":[{\"uri\":\"tex.png\"}],\"textures\":[{\"source\":0}],"
                "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1},\"indices\":2,\"material\":0}]}],"
                "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0}");
    snprintf(gltf, size, "%s/big.gltf", dir);
    err |= !j.p || tlh_write(gltf, j.p, j.n);
    free(j.p);
    return err;
}

/* Runs argv[0] with stdout and stderr into LOG; its exit status (-1: did not exit) and peak
 * resident memory in bytes. */
static int run(char *const *argv, const char *log, size_t *peak)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
        }
        execv(argv[0], argv);
        _exit(127);
    }
    int status = 0;
    struct rusage ru;
    memset(&ru, 0, sizeof ru);
    if (pid < 0 || wait4(pid, &status, 0, &ru) != pid) return -1;
    *peak = (size_t)ru.ru_maxrss * 1024; /* KiB on Linux */
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static void show(const char *log)
{
    char *text = NULL;
    FILE *f = fopen(log, "rb");
    if (!f) return;
    text = malloc(4096);
    size_t n = text ? fread(text, 1, 4095, f) : 0;
    fclose(f);
    if (text) {
        text[n] = '\0';
        printf("%s", text);
    }
    free(text);
}

TL_TEST_FULL(bench_holds_a_large_texture_once_not_per_configuration)
{
    const char *dir = TL_BENCH_MEMORY_DIR;
    tlh_rmtree(dir);
    TL_CHECK(tlh_mkdirs(dir) == 0);
    char gltf[1024], png_out[1024], log_render[1024], log_bench[1024];
    TL_CHECK(write_scene(dir, gltf, sizeof gltf) == 0);
    snprintf(png_out, sizeof png_out, "%s/render.png", dir);
    snprintf(log_render, sizeof log_render, "%s/render.log", dir);
    snprintf(log_bench, sizeof log_bench, "%s/bench.log", dir);
    char *render[] = {TL_RENDER_TOOL, gltf, "--size", "64x64", "--lights", "4", "-o", png_out, NULL};
    size_t one = 0, bench_peak = 0;
    int rc = run(render, log_render, &one);
    if (rc != 0) show(log_render);
    TL_CHECK(rc == 0);
    /* six configurations (fat, thin-lpp, thin-deferred, forward+, and thin-lpp's R11G11B10F and n.v
     * variants), each mode's planned and unplanned renderers */
    char *bench[] = {TL_BENCH_TOOL, "--scene", gltf, "--size", "64x64", "--lights", "4", "--frames", "1", "--warmup",
                     "0", "--strategies", "tiled", "--no-plot", NULL};
    rc = run(bench, log_bench, &bench_peak);
    if (rc != 0) show(log_bench);
    TL_CHECK(rc == 0);
    size_t texture = (size_t)SIDE * SIDE * 4, copy = texture / 3 * 4, bound = one + 2 * copy + 128 * MiB;
    printf("texture %zu MiB (%zu MiB with mips); peak: thinlight-render %zu MiB, thinlight-bench %zu MiB (bound %zu "
           "MiB)\n", texture / MiB, copy / MiB, one / MiB, bench_peak / MiB, bound / MiB);
    TL_CHECK(one > texture);     /* the run measured what it should */
    TL_CHECK_LE(bench_peak, bound);
    tlh_rmtree(dir);
}
