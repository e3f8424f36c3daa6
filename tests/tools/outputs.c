/* Outputs are never half-written: thinlight-render is killed (SIGKILL) in the middle of an EXR
 * dump (--dump-targets), at several moments, over files from an earlier run. Every output name
 * must then hold either its old content or the whole new file (byte for byte what an
 * uninterrupted run writes, the EXR capDate aside), never a truncated one, and nothing else may
 * be left beside the outputs: the writer's file has no name until it is whole (thinlight/file.h);
 * a kill in the two system calls between its link and its rename leaves a whole file under a
 * temporary name, which the next run's write of that output must remove. */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "gltf_hostile.h"
#include "tl_test.h"

#ifndef TL_RENDER_TOOL
#define TL_RENDER_TOOL "thinlight-render"
#endif
#ifndef TL_OUTPUTS_TEST_DIR
#define TL_OUTPUTS_TEST_DIR "outputs_work"
#endif

#define SIZE_ARG "768x768"
#define SMALL_SIZE_ARG "384x384" /* the 20 kills: shorter runs, the same writers */
static const char OLD[] = "OLD CONTENT\n";
static const char *const NAMES[] = {"out.exr",          "targets/depth.exr",          "targets/rt0_normal_gloss.exr",
                                    "targets/hdr.exr",  "targets/light_diffuse.exr",  "targets/light_specular.exr",
                                    "targets/ldr.exr",  "targets/output.exr"};
#define NAME_COUNT (sizeof NAMES / sizeof NAMES[0])

/* The EXR header's capDate (the time of writing) is the one part two runs do not share. */
static void mask_date(unsigned char *b, size_t n)
{
    for (size_t i = 0; i + 38 <= n && i < 4096; i++)
        if (!memcmp(b + i, "capDate\0string\0", 15)) memset(b + i + 19, 0, 19);
}

static int same_file(const char *a, const char *b)
{
    size_t na = 0, nb = 0;
    unsigned char *x = tlh_read(a, &na), *y = tlh_read(b, &nb);
    int same = x && y && na == nb;
    if (same) {
        mask_date(x, na);
        mask_date(y, nb);
        same = !memcmp(x, y, na);
    }
    free(x);
    free(y);
    return same;
}

static pid_t spawn_sized(const char *dir, const char *size)
{
    char out[1100], targets[1100];
    snprintf(out, sizeof out, "%s/out.exr", dir);
    snprintf(targets, sizeof targets, "%s/targets", dir);
    pid_t pid = fork();
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0) {
            dup2(null, 1);
            dup2(null, 2);
        }
        execl(TL_RENDER_TOOL, TL_RENDER_TOOL, "default", "--size", size, "--lights", "8", "-o", out,
              "--dump-targets", targets, (char *)NULL);
        _exit(127);
    }
    return pid;
}

static pid_t spawn(const char *dir) { return spawn_sized(dir, SIZE_ARG); }

/* Names in DIR and DIR/targets other than the outputs ("targets/NAME" for the latter), up to
 * `max`; how many. */
static int other_names(const char *dir, char names[][256], int max)
{
    int n = 0;
    for (int s = 0; s < 2; s++) {
        char sub[1100];
        snprintf(sub, sizeof sub, "%s%s", dir, s ? "/targets" : "");
        DIR *d = opendir(sub);
        struct dirent *e;
        while (d && (e = readdir(d)) != NULL) {
            char name[256];
            if (snprintf(name, sizeof name, "%s%s", s ? "targets/" : "", e->d_name) >= (int)sizeof name) continue;
            int known = !strcmp(e->d_name, ".") || !strcmp(e->d_name, "..") || !strcmp(name, "targets");
            for (size_t i = 0; i < NAME_COUNT; i++) known |= !strcmp(name, NAMES[i]);
            if (!known && n < max) memcpy(names[n++], name, sizeof name);
        }
        if (d) closedir(d);
    }
    return n;
}

/* What a killed run left beside the outputs, counted and printed. */
static int strays(const char *dir)
{
    char names[64][256];
    int n = other_names(dir, names, 64);
    for (int i = 0; i < n; i++) fprintf(stderr, "left beside the outputs: %s/%s\n", dir, names[i]);
    return n;
}

/* What a killed run left beside the outputs once the next run over the same folder ended: a
 * kill between a writer's link and its rename leaves a whole file under a temporary name, which
 * the next write of that output removes (thinlight/file.h); nothing may stay. */
static int left_after_next_run(const char *dir, const char *size)
{
    if (strays(dir) == 0) return 0;
    pid_t pid = spawn_sized(dir, size);
    int status = -1;
    TL_CHECK(pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0);
    int left = strays(dir);
    printf("a temporary name was left by the kill; after the next run: %d\n", left);
    return left;
}

/* Distinct files seen being written so far (appended to `seen`): temporary names in DIR and
 * DIR/targets, and output names whose content is no longer the old one (a writer that wrote in
 * place would be caught there, mid-write). */
static int scan_temps(const char *dir, char seen[][256], int count)
{
    for (size_t i = 0; i < NAME_COUNT; i++) {
        char path[1200];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", dir, NAMES[i]);
        if (stat(path, &st) != 0 || st.st_size == (off_t)(sizeof OLD - 1)) continue;
        int known = 0;
        for (int k = 0; k < count; k++) known |= !strcmp(seen[k], NAMES[i]);
        if (!known && count < 64) snprintf(seen[count++], 256, "%s", NAMES[i]);
    }
    char others[64][256];
    int n = other_names(dir, others, 64);
    for (int j = 0; j < n; j++) {
        if (!strstr(others[j], ".tmp")) continue;
        int known = 0;
        for (int i = 0; i < count; i++) known |= !strcmp(seen[i], others[j]);
        if (!known && count < 64) memcpy(seen[count++], others[j], sizeof others[j]);
    }
    return count;
}

/* Old content under every output name, as an earlier run would have left. */
static void prepare(const char *dir)
{
    char path[1200];
    tlh_rmtree(dir);
    snprintf(path, sizeof path, "%s/targets", dir);
    TL_CHECK(tlh_mkdirs(path) == 0);
    for (size_t i = 0; i < NAME_COUNT; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, NAMES[i]);
        TL_CHECK(tlh_write(path, OLD, sizeof OLD - 1) == 0);
    }
}

/* Every output is its old content or the reference's, never anything else. Returns how many
 * are new. */
static int check_outputs(const char *dir, const char *ref)
{
    int fresh = 0;
    for (size_t i = 0; i < NAME_COUNT; i++) {
        char path[1200], want[1200];
        snprintf(path, sizeof path, "%s/%s", dir, NAMES[i]);
        snprintf(want, sizeof want, "%s/%s", ref, NAMES[i]);
        size_t n = 0;
        unsigned char *b = tlh_read(path, &n);
        int old = b && n == sizeof OLD - 1 && !memcmp(b, OLD, n);
        free(b);
        int whole = !old && same_file(path, want);
        if (!old && !whole) fprintf(stderr, "%s: neither the old content nor the whole new file (%zu bytes)\n", path, n);
        TL_CHECK(old || whole);
        fresh += whole;
    }
    return fresh;
}

static void sleep_us(long us)
{
    struct timespec t = {0, us * 1000};
    nanosleep(&t, NULL);
}

/* Runs the tool and kills it once `kth` files have been seen being written; 1 when it was
 * killed, 0 when it finished first. */
static int run_killed(const char *dir, int kth, char *caught, size_t caught_size)
{
    prepare(dir);
    pid_t pid = spawn(dir);
    TL_CHECK(pid > 0);
    if (pid <= 0) return 0;
    char seen[64][256];
    int count = 0, killed = 0, status = 0;
    for (long waited = 0; waited < 300L * 1000 * 1000; waited += 200) {
        count = scan_temps(dir, seen, count);
        if (count >= kth) {
            kill(pid, SIGKILL);
            killed = 1;
            snprintf(caught, caught_size, "%s", seen[count - 1]);
            break;
        }
        if (waitpid(pid, &status, WNOHANG) == pid) return 0;
        sleep_us(200);
    }
    waitpid(pid, &status, 0);
    TL_CHECK(killed && WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    return killed;
}

TL_TEST(outputs_killed_mid_exr_dump_leave_old_or_whole)
{
    char ref[512], dir[512];
    snprintf(ref, sizeof ref, "%s/reference", TL_OUTPUTS_TEST_DIR);
    snprintf(dir, sizeof dir, "%s/killed", TL_OUTPUTS_TEST_DIR);
    /* the whole run, uninterrupted, over old files: every output replaced */
    prepare(ref);
    pid_t pid = spawn(ref);
    int status = -1;
    TL_CHECK(pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0);
    for (size_t i = 0; i < NAME_COUNT; i++) {
        char path[1200];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", ref, NAMES[i]);
        TL_CHECK(stat(path, &st) == 0 && st.st_size > 100000); /* a real EXR, not the old text */
    }
    /* killed while the 1st, 3rd and 6th file are being written */
    const int moments[] = {1, 3, 6};
    int mid_write = 0;
    for (size_t m = 0; m < sizeof moments / sizeof moments[0]; m++) {
        char caught[256] = "";
        int killed = run_killed(dir, moments[m], caught, sizeof caught);
        int fresh = check_outputs(dir, ref);
        printf("killed while writing file %d (%s): %d of %zu outputs new, the rest old\n", moments[m], caught, fresh,
               NAME_COUNT);
        TL_CHECK(left_after_next_run(dir, SIZE_ARG) == 0);
        mid_write += killed;
        TL_CHECK(fresh < (int)NAME_COUNT); /* it was killed before the end */
    }
    TL_CHECK(mid_write == 3);
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

/* 20 kills spread over the part of the run that writes (from the first new output to the end,
 * as an uninterrupted run times it): every output old or whole, nothing left beside them. */
TL_TEST_FULL(outputs_killed_20_times_leave_nothing_beside_them)
{
    char ref[512], dir[512];
    snprintf(ref, sizeof ref, "%s/reference_small", TL_OUTPUTS_TEST_DIR);
    snprintf(dir, sizeof dir, "%s/killed_small", TL_OUTPUTS_TEST_DIR);
    prepare(ref);
    char seen[64][256];
    double t0 = now_ms(), first = -1, end = 0;
    pid_t pid = spawn_sized(ref, SMALL_SIZE_ARG);
    int status = -1;
    TL_CHECK(pid > 0);
    while (pid > 0 && waitpid(pid, &status, WNOHANG) == 0) {
        if (first < 0 && scan_temps(ref, seen, 0) > 0) first = now_ms() - t0;
        sleep_us(200);
    }
    end = now_ms() - t0;
    TL_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0 && strays(ref) == 0);
    if (first < 0) first = 0.5 * end;
    double from = 0.8 * first; /* the first write began before its file appeared */
    int stray_runs = 0, partly_new = 0;
    for (int i = 0; i < 20; i++) {
        prepare(dir);
        double at = from + (end - from) * (i + 0.5) / 20, start = now_ms();
        pid = spawn_sized(dir, SMALL_SIZE_ARG);
        TL_CHECK(pid > 0);
        if (pid <= 0) return;
        while (now_ms() - start < at && waitpid(pid, &status, WNOHANG) == 0) sleep_us(200);
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        int fresh = check_outputs(dir, ref);
        partly_new += fresh > 0 && fresh < (int)NAME_COUNT;
        stray_runs += left_after_next_run(dir, SMALL_SIZE_ARG) > 0;
    }
    printf("20 kills from %.0f to %.0f ms (a run: %.0f ms, first output at %.0f ms): %d with outputs partly new, "
           "%d with files left beside them\n", from, end, end, first, partly_new, stray_runs);
    TL_CHECK(stray_runs == 0);
}
