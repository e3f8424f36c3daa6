/* thinlight-viewer's --screenshot is whole or absent (docs/outputs.md): with the fault injector
 * (common/fault_inject.h) preloaded into the viewer, a failing write, fsync or close of the
 * screenshot exits 1 with one line and leaves the old file byte for byte, alone in its folder; a
 * FIFO or a symbolic link as the screenshot is refused and left as it was. Under Xvfb, as
 * test_viewer.c. */
#define _GNU_SOURCE /* realpath */
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gltf_hostile.h"
#include "viewer_harness.h"

static const char OLD[] = "OLD CONTENT\n";

/* The viewer writing `shot` (absolute), the injector armed on its folder; exit status and the
 * lines it printed on stderr that name `shot`. */
static int faulted_viewer(const char *shot, const char *call, int k, const char *counts, int *lines)
{
    char dir[PATH_MAX], cmd[4 * PATH_MAX], err[PATH_MAX + 16];
    snprintf(dir, sizeof dir, "%s", shot);
    *strrchr(dir, '/') = '\0';
    snprintf(err, sizeof err, "%s.stderr", dir); /* outside the folder that must stay clean */
    snprintf(cmd, sizeof cmd,
             "%senv LD_PRELOAD='%s' TL_FAULT_DIR='%s' TL_FAULT_CALL=%s TL_FAULT_AT=%d TL_FAULT_REPORT='%s' "
             "ASAN_OPTIONS=verify_asan_link_order=0 '%s' --no-panel --light-strategy tiled --frames 2 --size 64x48 "
             "--screenshot '%s' 2>'%s'",
             xvfb(), TL_FAULT_INJECT, dir, call, k, counts, TL_VIEWER, shot, err);
    int status = run(cmd);
    *lines = 0;
    FILE *f = fopen(err, "r");
    char line[4096];
    while (f && fgets(line, sizeof line, f)) {
        if (strstr(line, shot)) (*lines)++;
        fputs(line, stderr);
    }
    if (f) fclose(f);
    return status;
}

static int holds_old(const char *path)
{
    char buf[64] = {0};
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
    if (f) fclose(f);
    return n == sizeof OLD - 1 && !memcmp(buf, OLD, n);
}

/* Whether `dir` holds exactly one name. */
static int alone(const char *dir)
{
    char cmd[PATH_MAX + 64];
    snprintf(cmd, sizeof cmd, "test $(ls -A '%s' | wc -l) -eq 1", dir);
    return run(cmd) == 0;
}

static void work(const char *name, char *dir, size_t size)
{
    char rel[PATH_MAX];
    snprintf(rel, sizeof rel, "%s/%s", TL_WORK, name);
    tlh_rmtree(rel);
    TL_CHECK(tlh_mkdirs(rel) == 0);
    TL_CHECK(realpath(rel, dir) != NULL && strlen(dir) < size); /* the injector matches real paths */
}

TL_TEST_FULL(viewer_screenshot_full_disk_keeps_old_file)
{
    char dir[PATH_MAX], shot[PATH_MAX + 16], counts[PATH_MAX + 16];
    work("full_disk", dir, sizeof dir);
    snprintf(shot, sizeof shot, "%s/shot.png", dir);
    snprintf(counts, sizeof counts, "%s.counts", dir);
    /* the injector's counts of a run that succeeds: the screenshot is one write, fsync, close */
    static const struct {
        const char *call;
        int k, fails;
    } runs[] = {{"write", 2, 0}, {"write", 1, 1}, {"fsync", 1, 1}, {"close", 1, 1}};
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        TL_CHECK(tlh_write(shot, OLD, sizeof OLD - 1) == 0);
        remove(counts);
        int lines = 0, status = faulted_viewer(shot, runs[i].call, runs[i].k, counts, &lines);
        if (runs[i].fails) {
            if (status != 1 || lines != 1 || !holds_old(shot))
                fprintf(stderr, "%s failing at k=%d: exit %d, %d lines naming the screenshot, old file %s\n",
                        runs[i].call, runs[i].k, status, lines, holds_old(shot) ? "kept" : "lost");
            TL_CHECK(status == 1 && lines == 1 && holds_old(shot));
        } else {
            image im = load("full_disk/shot.png");
            TL_CHECK(status == 0 && im.px && im.w == 64 && im.h == 48);
            release(&im);
            /* what the failing runs below must each reach */
            char *text = NULL;
            size_t n = 0;
            FILE *f = fopen(counts, "r");
            unsigned long w = 0, s = 0, c = 0;
            if (f && getline(&text, &n, f) > 0) sscanf(text, "%*d write %lu fsync %lu close %lu", &w, &s, &c);
            if (f) fclose(f);
            free(text);
            printf("a screenshot: %lu write, %lu fsync, %lu close\n", w, s, c);
            TL_CHECK(w == 1 && s == 1 && c == 1);
        }
        TL_CHECK(alone(dir));
    }
}

TL_TEST(viewer_screenshot_refuses_fifo_and_symlink)
{
    char dir[PATH_MAX], path[PATH_MAX + 16], target[PATH_MAX + 16];
    work("not_regular", dir, sizeof dir);
    snprintf(target, sizeof target, "%s/target.png", dir);
    TL_CHECK(tlh_write(target, OLD, sizeof OLD - 1) == 0);
    for (int kind = 0; kind < 2; kind++) {
        snprintf(path, sizeof path, "%s/%s", dir, kind ? "link.png" : "fifo.png");
        TL_CHECK(kind ? symlink("target.png", path) == 0 : mkfifo(path, 0644) == 0);
        struct stat before, after;
        TL_CHECK(lstat(path, &before) == 0);
        int lines = 0, status = faulted_viewer(path, "write", 0, "", &lines);
        TL_CHECK(lstat(path, &after) == 0 && after.st_ino == before.st_ino && after.st_mode == before.st_mode);
        TL_CHECK(status == 1 && lines == 1);
    }
    TL_CHECK(holds_old(target));
}
