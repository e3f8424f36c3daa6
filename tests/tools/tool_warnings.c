/* The glTF loader's and the renderer's warnings reach the user: thinlight-render, thinlight-bench
 * (many renderers of one scene) and thinlight-viewer print each warning on stderr once, marked
 * "warning:". The file, made here, has conditions the loader warns about: a light of an unknown
 * type (skipped), a light with a negative intensity (skipped), an image that is not there (a flat
 * colour). Before, the tools kept only the loader's error line: no warning at all (the viewer
 * printed them unmarked). */
#define _POSIX_C_SOURCE 200809L /* popen */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_hostile.h"
#include "tl_test.h"

static void write_scene(const char *dir, char *gltf, size_t size)
{
    const float pos[9] = {-1, 0, -1, 1, 0, -1, 0, 0, 1};
    tlh_text j = {0};
    tlh_put(&j, "{\"asset\":{\"version\":\"2.0\"},\"extensionsUsed\":[\"KHR_lights_punctual\"],"
                "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"area\"},"
                "{\"type\":\"point\",\"intensity\":-1},{\"type\":\"directional\"}]}},"
                "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64,");
    tlh_base64(&j, (const unsigned char *)pos, sizeof pos);
    tlh_put(&j, "\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],\"accessors\":[{\"bufferView\":0,"
                "\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"min\":[-1,0,-1],\"max\":[1,0,1]}],"
                "\"images\":[{\"uri\":\"missing.png\"}],\"textures\":[{\"source\":0}],"
                "\"materials\":[{\"emissiveTexture\":{\"index\":0}}],"
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":0}]}],"
                "\"nodes\":[{\"mesh\":0},{\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}},"
                "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}}},"
                "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":2}}}],"
                "\"scenes\":[{\"nodes\":[0,1,2,3]}],\"scene\":0}");
    snprintf(gltf, size, "%s/warns.gltf", dir);
    TL_CHECK(j.p && tlh_write(gltf, j.p, j.n) == 0);
    free(j.p);
}

/* The command's stderr; malloc'ed. */
static char *stderr_of(const char *cmd)
{
    char full[4096];
    snprintf(full, sizeof full, "%s 2>&1 >/dev/null", cmd);
    FILE *f = popen(full, "r");
    size_t cap = 1 << 16, n = 0;
    char *text = malloc(cap);
    if (!f || !text) {
        if (f) pclose(f);
        free(text);
        return NULL;
    }
    size_t got;
    while (n + 1 < cap && (got = fread(text + n, 1, cap - 1 - n, f)) > 0) n += got;
    text[n] = '\0';
    pclose(f);
    return text;
}

/* Times `line` occurs as a whole line of `text`. */
static int count_lines(const char *text, const char *line)
{
    int n = 0;
    size_t len = strlen(line);
    for (const char *p = text; p && *p;) {
        const char *end = strchr(p, '\n');
        size_t l = end ? (size_t)(end - p) : strlen(p);
        n += l == len && !strncmp(p, line, len);
        p = end ? end + 1 : NULL;
    }
    return n;
}

/* Each warning line of `tool` once; the loader's three among them. */
static void check_warnings(const char *tool, const char *err)
{
    static const char *const expected[] = {
        "lights[0]: unknown type \"area\"; skipped",
        "lights[1]: intensity is negative or not finite; skipped",
        "missing.png",
    };
    printf("%s stderr:\n%s", tool, err);
    int warnings = 0;
    for (const char *p = err; p && *p;) {
        const char *end = strchr(p, '\n');
        char line[1024];
        size_t l = end ? (size_t)(end - p) : strlen(p);
        snprintf(line, sizeof line, "%.*s", (int)(l < sizeof line - 1 ? l : sizeof line - 1), p);
        if (strstr(line, ": warning: ")) {
            warnings++;
            int times = count_lines(err, line);
            if (times != 1) printf("printed %d times: %s\n", times, line);
            TL_CHECK(times == 1);
        }
        p = end ? end + 1 : NULL;
    }
    for (size_t i = 0; i < sizeof expected / sizeof expected[0]; i++) {
        char prefix[128];
        snprintf(prefix, sizeof prefix, "%s: warning: ", tool);
        int found = 0;
        for (const char *p = strstr(err, prefix); p; p = strstr(p + 1, prefix)) {
            const char *end = strchr(p, '\n');
            const char *hit = strstr(p, expected[i]);
            found |= hit && (!end || hit < end);
        }
        if (!found) printf("no warning with \"%s\"\n", expected[i]);
        TL_CHECK(found);
    }
    TL_CHECK(warnings >= 3);
}

TL_TEST(render_prints_each_loader_warning_once)
{
    char gltf[1024], cmd[4096];
    tlh_rmtree(TL_WARNINGS_DIR "/render");
    TL_CHECK(tlh_mkdirs(TL_WARNINGS_DIR "/render") == 0);
    write_scene(TL_WARNINGS_DIR "/render", gltf, sizeof gltf);
    snprintf(cmd, sizeof cmd, "'%s' '%s' --size 32x32 --lights 2 -o '%s/render/out.png'", TL_RENDER_TOOL, gltf,
             TL_WARNINGS_DIR);
    char *err = stderr_of(cmd);
    TL_CHECK(err != NULL);
    if (err) check_warnings("thinlight-render", err);
    free(err);
}

/* Every configuration's renderer and each mode's planned and unplanned ones take the scene. */
TL_TEST(bench_prints_each_warning_once_across_its_renderers)
{
    char gltf[1024], cmd[4096];
    tlh_rmtree(TL_WARNINGS_DIR "/bench");
    TL_CHECK(tlh_mkdirs(TL_WARNINGS_DIR "/bench") == 0);
    write_scene(TL_WARNINGS_DIR "/bench", gltf, sizeof gltf);
    snprintf(cmd, sizeof cmd, "'%s' --scene '%s' --size 32x32 --lights 2 --frames 1 --warmup 0 --no-plot "
             "--json '%s/bench/b.json'", TL_BENCH_TOOL, gltf, TL_WARNINGS_DIR);
    char *err = stderr_of(cmd);
    TL_CHECK(err != NULL);
    if (err) check_warnings("thinlight-bench", err);
    free(err);
}

/* The viewer reads the scene before it opens a window: its warnings come whether a display is
 * there or not (without one it then fails, exit 1). */
TL_TEST(viewer_prints_each_loader_warning_once)
{
#ifdef TL_VIEWER_TOOL
    char gltf[1024], cmd[4096];
    tlh_rmtree(TL_WARNINGS_DIR "/viewer");
    TL_CHECK(tlh_mkdirs(TL_WARNINGS_DIR "/viewer") == 0);
    write_scene(TL_WARNINGS_DIR "/viewer", gltf, sizeof gltf);
    snprintf(cmd, sizeof cmd, "%s'%s' '%s' --size 64x64 --frames 1 --grid --no-panel --screenshot '%s/viewer/v.png'",
             TL_VIEWER_ENV, TL_VIEWER_TOOL, gltf, TL_WARNINGS_DIR);
    char *err = stderr_of(cmd);
    TL_CHECK(err != NULL);
    if (err) check_warnings("thinlight-viewer", err);
    free(err);
#else
    printf("no thinlight-viewer in this build\n");
#endif
}

/* ---- downgrades ---------------------------------------------------------------------------------
 * An option the plan does not honour (MSAA at a light scale below 1: the upsample runs at one
 * sample) is printed once as a warning by each renderer tool: the renderer logs it when it first
 * appears in a plan, the tool prints its logger's lines once. Before, it was said only in the
 * plan's msaa_reason (--print-plan). */
#define DOWNGRADE_LINE "warning: renderer: options.msaa = 4 is planned as 1: the reduced light buffer's upsample runs at one sample"

static void check_downgrade(const char *tool, const char *err)
{
    char want[512];
    snprintf(want, sizeof want, "%s: %s", tool, DOWNGRADE_LINE);
    printf("%s stderr:\n%s", tool, err);
    int times = count_lines(err, want);
    if (times != 1) printf("printed %d times: %s\n", times, want);
    TL_CHECK(times == 1);
}

TL_TEST(render_prints_each_downgrade_once)
{
    char cmd[4096];
    tlh_rmtree(TL_WARNINGS_DIR "/downgrade");
    TL_CHECK(tlh_mkdirs(TL_WARNINGS_DIR "/downgrade") == 0);
    snprintf(cmd, sizeof cmd, "'%s' default --size 32x18 --lights 4 --msaa 4 --light-scale 0.5 -o '%s/downgrade/out.png'",
             TL_RENDER_TOOL, TL_WARNINGS_DIR);
    char *err = stderr_of(cmd);
    TL_CHECK(err != NULL);
    if (err) check_downgrade("thinlight-render", err);
    free(err);
}

/* The viewer renders only with a display: under Xvfb (xvfb-run when DISPLAY is unset), several
 * frames. */
TL_TEST(viewer_prints_each_downgrade_once)
{
#ifdef TL_VIEWER_TOOL
    const char *display = getenv("DISPLAY");
    int xvfb = !(display && display[0]);
    if (xvfb && system("command -v xvfb-run >/dev/null 2>&1") != 0) {
        printf("no display and no xvfb-run: not run\n");
        return;
    }
    char cmd[4096];
    tlh_rmtree(TL_WARNINGS_DIR "/downgrade_viewer");
    TL_CHECK(tlh_mkdirs(TL_WARNINGS_DIR "/downgrade_viewer") == 0);
    snprintf(cmd, sizeof cmd, "%s%s'%s' --size 64x36 --frames 3 --no-panel --msaa 4 --light-scale 0.5 "
             "--screenshot '%s/downgrade_viewer/v.png'",
             xvfb ? "xvfb-run -a -s '-screen 0 1280x1024x24 -noreset' " : "", TL_VIEWER_ENV, TL_VIEWER_TOOL,
             TL_WARNINGS_DIR);
    char *err = stderr_of(cmd);
    TL_CHECK(err != NULL);
    if (err) check_downgrade("thinlight-viewer", err);
    free(err);
#else
    printf("no thinlight-viewer in this build\n");
#endif
}
