/* Outputs are whole or absent (thinlight/file.h): tl_image_write in every format it is tested
 * with and tl_file_write on a full disk, with the k-th write, fsync or close failing for every k
 * (common/fault_inject.h, preloaded into this test), leave the old file byte for byte and nothing
 * beside it, with one error line; without a fault the file is whole. A FIFO, a device, a
 * directory, a symbolic link or `-` at the output path is refused and left as it was. Each write
 * runs in a child process, so that a writer that ends the process (libjpeg's error handler) is a
 * failed check rather than the end of the test. */
#define _GNU_SOURCE /* dlsym's RTLD_DEFAULT, realpath */

#include <dirent.h>
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "fault_inject.h"
#include "gltf_hostile.h"
#include "thinlight/file.h"
#include "thinlight/io.h"
#include "tl_test.h"

#ifndef TL_OUTPUTS_TEST_DIR
#define TL_OUTPUTS_TEST_DIR "file_outputs_work"
#endif

static const char OLD[] = "OLD CONTENT\n";

/* A fresh folder for one case, as an absolute path (the injector matches real paths). */
static void work(const char *test, char *dir, size_t n)
{
    char rel[1024];
    snprintf(rel, sizeof rel, "%s/%s", TL_OUTPUTS_TEST_DIR, test);
    tlh_rmtree(rel);
    TL_CHECK(tlh_mkdirs(rel) == 0);
    char real[PATH_MAX];
    TL_CHECK(realpath(rel, real) != NULL && strlen(real) < n);
    memcpy(dir, real, strlen(real) + 1);
}

/* EXR's capDate and TIFF's DateTime ("YYYY:MM:DD HH:MM:SS") are the time of writing: masked. */
static void mask_dates(unsigned char *b, size_t n)
{
    static const char shape[] = "dddd:dd:dd dd:dd:dd";
    for (size_t i = 0; i + 19 <= n && i < 8192; i++) {
        size_t k = 0;
        for (int c; k < 19; k++) {
            c = b[i + k];
            if (shape[k] == 'd' ? c < '0' || c > '9' : c != shape[k]) break;
        }
        if (k == 19) memset(b + i, '0', 19);
    }
}

/* 1 when the file holds exactly `want` (dates aside). */
static int holds(const char *path, const unsigned char *want, size_t want_n)
{
    size_t n = 0;
    unsigned char *b = tlh_read(path, &n);
    int same = b && n == want_n;
    if (same) {
        unsigned char *w = malloc(n ? n : 1);
        if (w) memcpy(w, want, n);
        mask_dates(b, n);
        if (w) mask_dates(w, n);
        same = w && !memcmp(b, w, n);
        free(w);
    }
    free(b);
    return same;
}

static int holds_old(const char *path) { return holds(path, (const unsigned char *)OLD, sizeof OLD - 1); }

/* The names in `dir` (one level), comma-separated into `out`; how many. */
static int listing(const char *dir, char *out, size_t size)
{
    int n = 0;
    out[0] = '\0';
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        size_t len = strlen(out);
        snprintf(out + len, size - len, "%s%s", n ? "," : "", e->d_name);
        n++;
    }
    if (d) closedir(d);
    return n;
}

/* ---- one write in a child process ---------------------------------------------------------- */

typedef enum fmt { FMT_PNG, FMT_EXR, FMT_JPEG, FMT_TIFF, FMT_RAW, FMT_COUNT } fmt;
static const char *const fmt_ext[FMT_COUNT] = {"png", "exr", "jpg", "tif", "bin"};

typedef struct outcome {
    int exited;          /* the child returned from the writer (did not exit or die inside it) */
    tl_result result;
    int lines;           /* error lines logged */
    char line[1024];     /* the last one */
    unsigned long seen;  /* calls of the armed kind the injector counted */
} outcome;

#define W 61
#define H 37
enum { RAW_SIZE = 3 << 20 }; /* written by one write call, split by the injector's short write */

static void child_log(void *user, tl_log_level level, const char *message)
{
    if (level == TL_LOG_ERROR) dprintf(*(int *)user, "log %s\n", message);
}

/* The write itself, in the child: the result, the lines and the count go up the pipe. */
static void child(int fd, fmt f, const char *path, const char *call, unsigned long k, const char *dir,
                  const char *lacking)
{
    void *arm_sym = dlsym(RTLD_DEFAULT, "tl_fault_arm"), *seen_sym = dlsym(RTLD_DEFAULT, "tl_fault_seen");
    void *without_sym = dlsym(RTLD_DEFAULT, "tl_fault_without");
    tl_fault_arm_fn arm;
    tl_fault_seen_fn seen;
    tl_fault_without_fn without;
    if (!arm_sym || !seen_sym || !without_sym) _exit(90); /* the injector is not preloaded */
    memcpy(&arm, &arm_sym, sizeof arm);
    memcpy(&seen, &seen_sym, sizeof seen);
    memcpy(&without, &without_sym, sizeof without);
    without(lacking);
    static float fpx[W * H * 4];
    static uint8_t px[W * H * 4];
    for (size_t i = 0; i < W * H * 4; i++) {
        px[i] = (uint8_t)(i * 7u + i / 5u);
        fpx[i] = (float)(i % 97) / 13.0f;
    }
    tl_logger logger = {child_log, &fd};
    tl_image_desc d = {.width = W, .height = H, .channels = 4, .type = f == FMT_EXR ? TL_PIXEL_F32 : TL_PIXEL_U8,
                       .logger = logger};
    unsigned char *raw = f == FMT_RAW ? malloc(RAW_SIZE) : NULL;
    for (size_t i = 0; raw && i < RAW_SIZE; i++) raw[i] = (unsigned char)(i * 31u >> 3);
    arm(dir, call, k);
    tl_result r = f == FMT_RAW ? tl_file_write(path, raw, RAW_SIZE, &(tl_file_write_desc){logger})
                               : tl_image_write(path, &d, f == FMT_EXR ? (const void *)fpx : (const void *)px);
    unsigned long n = seen(call);
    arm(NULL, NULL, 0);
    dprintf(fd, "result %d seen %lu\n", (int)r, n);
    free(raw);
    _exit(0);
}

/* Reads the child's lines until it closes the pipe or `deadline` passes; 0 on time. */
static int read_lines(int fd, outcome *o, time_t deadline)
{
    char buf[4096], line[sizeof o->line];
    size_t len = 0;
    for (;;) {
        struct pollfd p = {fd, POLLIN, 0};
        int left = (int)(deadline - time(NULL));
        if (left <= 0 || poll(&p, 1, left * 1000) <= 0) return -1;
        ssize_t n = read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return 0;
        for (ssize_t i = 0; i < n; i++) {
            if (buf[i] != '\n') {
                if (len + 1 < sizeof line) line[len++] = buf[i];
                continue;
            }
            line[len] = '\0';
            len = 0;
            int r;
            if (!strncmp(line, "log ", 4)) {
                o->lines++;
                memcpy(o->line, line + 4, sizeof line - 4);
            } else if (sscanf(line, "result %d seen %lu", &r, &o->seen) == 2) {
                o->exited = 1;
                o->result = (tl_result)r;
            }
        }
    }
}

static outcome run_child(fmt f, const char *path, const char *call, unsigned long k, const char *dir,
                         const char *lacking)
{
    outcome o = {0};
    o.result = TL_RESULT_COUNT_;
    int p[2];
    if (pipe(p) != 0) return o;
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        close(p[0]);
        child(p[1], f, path, call, k, dir, lacking);
    }
    close(p[1]);
    /* a writer that calls exit() inside OIIO may hang in OIIO's exit handlers: 60 s at most */
    int hung = read_lines(p[0], &o, time(NULL) + 60) != 0;
    close(p[0]);
    if (hung) kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!o.exited)
        fprintf(stderr, "the writer ended the child process (%s %d)\n", hung ? "hung, killed; signal"
                        : WIFEXITED(status) ? "exit status" : "signal",
                WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status));
    return o;
}

/* Every k from 1 until the write succeeds, for each failing call: old file kept and alone, one
 * line naming it; the first success equals the reference. `lacking`: what the system is to lack
 * (tl_fault_without: "tmpfile", "link"), NULL for nothing. Returns the k values tried. */
static int full_disk_every_k(fmt f, const char *name, const char *lacking)
{
    char dir[1024], path[1200], ref[1200], list[4096];
    work(name, dir, sizeof dir);
    snprintf(ref, sizeof ref, "%s/reference.%s", dir, fmt_ext[f]);
    outcome clean = run_child(f, ref, "write", 0, dir, NULL);
    TL_CHECK(clean.exited && clean.result == TL_OK);
    size_t ref_n = 0;
    unsigned char *ref_bytes = tlh_read(ref, &ref_n);
    TL_CHECK(ref_bytes && ref_n > 0);
    remove(ref);
    char sub[1100];
    snprintf(sub, sizeof sub, "%s/out", dir);
    TL_CHECK(tlh_mkdirs(sub) == 0);
    snprintf(path, sizeof path, "%s/out/image.%s", dir, fmt_ext[f]);
    static const char *const calls[] = {"write", "short", "fsync", "close"};
    int tried = 0;
    for (size_t c = 0; c < sizeof calls / sizeof calls[0]; c++) {
        int succeeded = 0;
        unsigned long k;
        for (k = 1; k <= 200 && !succeeded; k++, tried++) {
            TL_CHECK(tlh_write(path, OLD, sizeof OLD - 1) == 0);
            outcome o = run_child(f, path, calls[c], k, sub, lacking);
            int n = listing(sub, list, sizeof list);
            succeeded = o.exited && o.result == TL_OK;
            if (!o.exited) {
                TL_CHECK(o.exited);
                break;
            }
            if (succeeded) {
                /* the injector saw every call: a k past the count is the first to succeed */
                TL_CHECK(k > o.seen || (fprintf(stderr, "%s %s: k=%lu succeeded, %lu calls\n", name, calls[c], k,
                                                o.seen), 0));
                TL_CHECK(holds(path, ref_bytes, ref_n));
            } else {
                int old = holds_old(path), one = o.lines == 1 && strstr(o.line, path) != NULL;
                if (!old || !one)
                    fprintf(stderr, "%s %s k=%lu: result %d, %d lines (%s), old file %s\n", name, calls[c], k,
                            (int)o.result, o.lines, o.line, old ? "kept" : "lost");
                TL_CHECK(o.result == TL_ERROR_IO && old && one);
            }
            if (n != 1) fprintf(stderr, "%s %s k=%lu: left in the folder: %s\n", name, calls[c], k, list);
            TL_CHECK(n == 1);
        }
        TL_CHECK(succeeded && k > 2); /* at least one k failed: the injector reached the writer */
        if (succeeded && k > 2)
            printf("%s: %s failing at k = 1..%lu kept the old file; k = %lu wrote it whole\n", name, calls[c], k - 2,
                   k - 1);
    }
    free(ref_bytes);
    return tried;
}

TL_TEST(file_write_full_disk_every_k_png) { full_disk_every_k(FMT_PNG, "full_disk_png", NULL); }
TL_TEST(file_write_full_disk_every_k_exr) { full_disk_every_k(FMT_EXR, "full_disk_exr", NULL); }
TL_TEST(file_write_full_disk_every_k_jpeg) { full_disk_every_k(FMT_JPEG, "full_disk_jpeg", NULL); }
TL_TEST(file_write_full_disk_every_k_tiff) { full_disk_every_k(FMT_TIFF, "full_disk_tiff", NULL); }
TL_TEST(file_write_full_disk_every_k_raw_bytes) { full_disk_every_k(FMT_RAW, "full_disk_raw", NULL); }
/* the fallbacks: a file system without O_TMPFILE (a temporary name from the start), and an
 * unnamed file that cannot be linked (written again through a temporary name) */
TL_TEST(file_write_full_disk_every_k_without_o_tmpfile)
{
    full_disk_every_k(FMT_PNG, "full_disk_no_tmpfile_png", "tmpfile");
    full_disk_every_k(FMT_RAW, "full_disk_no_tmpfile_raw", "tmpfile");
}
TL_TEST(file_write_full_disk_every_k_without_linkat)
{
    full_disk_every_k(FMT_EXR, "full_disk_no_link_exr", "link");
    full_disk_every_k(FMT_RAW, "full_disk_no_link_raw", "link");
}

/* libjpeg's default error handler calls exit(): an image it cannot hold is refused before. */
TL_TEST(image_write_jpeg_too_large_refused_process_lives)
{
    char dir[1024], path[1200];
    work("jpeg_too_large", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/wide.jpg", dir);
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        static uint8_t row[65501 * 3];
        tl_image_desc d = {.width = 65501, .height = 1, .channels = 3};
        _exit(tl_image_write(path, &d, row) == TL_ERROR_UNSUPPORTED ? 42 : 43);
    }
    int status = 0;
    for (int waited = 0; waitpid(pid, &status, WNOHANG) == 0; waited++) {
        if (waited == 600) { /* 60 s: exit() inside OIIO can hang in its exit handlers */
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            break;
        }
        nanosleep(&(struct timespec){0, 100000000}, NULL);
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 42)
        fprintf(stderr, "tl_image_write of a 65501-wide JPEG: %s %d (42: refused and returned)\n",
                WIFEXITED(status) ? "exit" : "signal", WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status));
    TL_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 42);
    char list[256];
    TL_CHECK(listing(dir, list, sizeof list) == 0);
}

/* ---- what is not a regular file ------------------------------------------------------------ */

/* Writes `path` both ways (the image through tl_image_write when it names one); 1 when both
 * refused it with one line each and left it as it was (`same` says how that is checked). */
static int refused(const char *path, int image, int (*same)(const char *, const struct stat *),
                   const struct stat *before)
{
    tlh_log log = {0};
    uint8_t px[4 * 4 * 4] = {0};
    tl_image_desc d = {.width = 4, .height = 4, .channels = 4, .logger = TLH_LOGGER(&log)};
    tl_result ri = image ? tl_image_write(path, &d, px) : TL_ERROR_IO;
    int lines = image ? 1 : 0;
    int ok = ri != TL_OK && log.errors == lines && same(path, before);
    if (ok) { /* tl_file_write only after the image writer left it alone (the old one replaced it) */
        tl_result rf = tl_file_write(path, "new\n", 4, &(tl_file_write_desc){TLH_LOGGER(&log)});
        tl_result rc = tl_file_check_writable(path, &(tl_file_write_desc){TLH_LOGGER(&log)});
        lines += 2;
        ok = rf != TL_OK && rc == rf && same(path, before);
        if (log.errors == lines) printf("%s\n", log.error);
    }
    ok = ok && log.errors == lines && log.multiline == 0 && strstr(log.error, path) != NULL;
    if (!ok) fprintf(stderr, "%s: not refused as it should be (%d error lines: %s)\n", path, log.errors, log.error);
    return ok;
}

static int same_node(const char *path, const struct stat *before)
{
    struct stat st;
    return lstat(path, &st) == 0 && st.st_ino == before->st_ino && st.st_mode == before->st_mode &&
           st.st_rdev == before->st_rdev && st.st_size == before->st_size;
}

TL_TEST(file_write_refuses_fifo_device_directory_symlink_dash)
{
    char dir[1024], p[6][1200], list[4096];
    work("not_regular", dir, sizeof dir);
    const char *names[6] = {"fifo.png", "dir.png", "link.png", "dangling.png", "target.png", "device.png"};
    for (int i = 0; i < 6; i++) snprintf(p[i], sizeof p[i], "%s/%s", dir, names[i]);
    TL_CHECK(mkfifo(p[0], 0644) == 0);
    TL_CHECK(mkdir(p[1], 0755) == 0);
    TL_CHECK(tlh_write(p[4], OLD, sizeof OLD - 1) == 0);
    TL_CHECK(symlink("target.png", p[2]) == 0);
    TL_CHECK(symlink("nowhere.png", p[3]) == 0);
    /* a device node of our own (/dev/null's numbers) where this process may make one */
    int have_device = mknod(p[5], S_IFCHR | 0666, makedev(1, 3)) == 0;
    if (!have_device) printf("no device node in the work folder (mknod: %s); /dev/null only\n", strerror(errno));
    int all = 1;
    for (int i = 0; i < 6; i++) {
        struct stat st;
        if (i == 4 || (i == 5 && !have_device)) continue;
        TL_CHECK(lstat(p[i], &st) == 0);
        int ok = refused(p[i], 1, same_node, &st);
        TL_CHECK(ok);
        all &= ok;
    }
    TL_CHECK(holds_old(p[4])); /* the link's target is untouched */
    int n = listing(dir, list, sizeof list);
    TL_CHECK(n == 5 + have_device);
    if (n != 5 + have_device) fprintf(stderr, "left in %s: %s\n", dir, list);
    /* `-` is not standard output, and no file of that name is made (here: the working folder) */
    tlh_log log = {0};
    struct stat st;
    int dash_existed = lstat("-", &st) == 0;
    TL_CHECK(tl_file_write("-", "x", 1, &(tl_file_write_desc){TLH_LOGGER(&log)}) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(log.errors == 1 && strstr(log.error, "standard output") != NULL);
    TL_CHECK(dash_existed || lstat("-", &st) != 0);
    /* /dev/null itself, only once every node above was left alone: a writer that replaced them
     * would replace /dev/null too when run as root */
    if (!all) {
        fprintf(stderr, "not trying /dev/null: the writer replaced what is not a regular file\n");
        return;
    }
    struct stat null_before, null_after;
    TL_CHECK(stat("/dev/null", &null_before) == 0 && S_ISCHR(null_before.st_mode));
    TL_CHECK(refused("/dev/null", 0, same_node, &null_before));
    TL_CHECK(stat("/dev/null", &null_after) == 0 && S_ISCHR(null_after.st_mode) &&
             null_after.st_rdev == null_before.st_rdev);
}

/* ---- regular files ------------------------------------------------------------------------- */

TL_TEST(file_write_replaces_keeps_mode_and_leaves_nothing)
{
    char dir[1024], path[1200], list[4096];
    work("regular", dir, sizeof dir);
    tlh_log log = {0};
    tl_file_write_desc d = {TLH_LOGGER(&log)};
    /* a new file: 0666 less the umask */
    mode_t mask = umask(022);
    umask(mask);
    snprintf(path, sizeof path, "%s/new.txt", dir);
    TL_CHECK(tl_file_check_writable(path, &d) == TL_OK);
    TL_CHECK(listing(dir, list, sizeof list) == 0); /* the check makes nothing */
    TL_CHECK(tl_file_write(path, "one\n", 4, &d) == TL_OK && holds(path, (const unsigned char *)"one\n", 4));
    struct stat st;
    TL_CHECK(stat(path, &st) == 0 && (st.st_mode & 07777) == (0666 & ~mask));
    /* a replaced file keeps its permission bits */
    TL_CHECK(chmod(path, 0600) == 0);
    TL_CHECK(tl_file_write(path, "two, longer\n", 12, &d) == TL_OK);
    TL_CHECK(holds(path, (const unsigned char *)"two, longer\n", 12));
    TL_CHECK(stat(path, &st) == 0 && (st.st_mode & 07777) == 0600);
    /* empty, and a file really named '-' */
    TL_CHECK(tl_file_write(path, NULL, 0, &d) == TL_OK && stat(path, &st) == 0 && st.st_size == 0);
    snprintf(path, sizeof path, "%s/-", dir);
    TL_CHECK(tl_file_write(path, "dash\n", 5, &d) == TL_OK && holds(path, (const unsigned char *)"dash\n", 5));
    TL_CHECK(log.errors == 0);
    /* bad arguments and a missing folder: one line each, nothing made */
    TL_CHECK(tl_file_write(NULL, "x", 1, &d) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_file_write("", "x", 1, &d) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_file_write(path, NULL, 1, &d) == TL_ERROR_INVALID_ARGUMENT);
    snprintf(path, sizeof path, "%s/", dir);
    TL_CHECK(tl_file_write(path, "x", 1, &d) == TL_ERROR_IO);
    snprintf(path, sizeof path, "%s/no/such/folder/x.txt", dir);
    TL_CHECK(tl_file_write(path, "x", 1, &d) == TL_ERROR_IO && strstr(log.error, "x.txt") != NULL);
    TL_CHECK(tl_file_check_writable(path, &d) == TL_ERROR_IO);
    TL_CHECK(tl_file_write(path, "x", 1, NULL) == TL_ERROR_IO); /* no desc: silent */
    TL_CHECK(log.errors == 6 && log.multiline == 0);
    TL_CHECK(listing(dir, list, sizeof list) == 2); /* new.txt and - */
}

/* ---- killed while writing ------------------------------------------------------------------ */

enum { BIG = 16 << 20 };

static void fill(unsigned char *b, size_t n, unsigned seed)
{
    for (size_t i = 0; i < n; i++) b[i] = (unsigned char)((i * 2654435761u) >> 13 ^ seed);
}

/* A child writes a 16 MiB file over and over; SIGKILL at 20 moments spread over one write. */
TL_TEST(file_write_killed_mid_write_leaves_old_or_new_nothing_else)
{
    char dir[1024], path[1200], list[4096];
    work("killed", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/big.bin", dir);
    unsigned char *mine = malloc(BIG), *back = NULL;
    TL_CHECK(mine != NULL);
    if (!mine) return;
    fill(mine, BIG, 1);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    TL_CHECK(tl_file_write(path, mine, BIG, NULL) == TL_OK);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    long one_us = (t1.tv_sec - t0.tv_sec) * 1000000L + (t1.tv_nsec - t0.tv_nsec) / 1000;
    int stray = 0, torn = 0, unreclaimed = 0;
    for (int i = 0; i < 20; i++) {
        fflush(NULL);
        pid_t pid = fork();
        if (pid == 0) {
            for (;;) tl_file_write(path, mine, BIG, NULL);
        }
        struct timespec wait = {0, (long)((one_us * (2 * i + 1)) / 40 + 2000) * 1000};
        nanosleep(&wait, NULL);
        kill(pid, SIGKILL);
        waitpid(pid, NULL, 0);
        size_t n = 0;
        back = tlh_read(path, &n);
        torn += !back || n != BIG || memcmp(back, mine, BIG) != 0;
        free(back);
        if (listing(dir, list, sizeof list) != 1) {
            /* killed between the link and the rename: the next write must remove the name */
            stray++;
            fprintf(stderr, "kill %d: left %s\n", i, list);
            TL_CHECK(tl_file_write(path, mine, BIG, NULL) == TL_OK);
            unreclaimed += listing(dir, list, sizeof list) != 1;
        }
    }
    printf("20 kills during writes of %ld us: %d torn files, %d with a temporary name left beside them, "
           "%d of those not removed by the next write\n",
           one_us, torn, stray, unreclaimed);
    TL_CHECK(torn == 0 && unreclaimed == 0);
    free(mine);
}

/* What a killed writer's temporary name looks like when its process is gone: removed by the next
 * write of that path; a live process's name, another path's name and a directory are kept. */
TL_TEST(file_write_removes_temporary_names_of_dead_writers)
{
    char dir[1024], path[1200], name[1400], list[4096];
    work("reclaim", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/out.bin", dir);
    pid_t dead = fork();
    if (dead == 0) _exit(0);
    TL_CHECK(dead > 0 && waitpid(dead, NULL, 0) == dead);
    snprintf(name, sizeof name, "%s.tmp%ld-0", path, (long)dead);
    TL_CHECK(tlh_write(name, "whole\n", 6) == 0);
    snprintf(name, sizeof name, "%s.tmp%ld-3", path, (long)getppid()); /* alive */
    TL_CHECK(tlh_write(name, "alive\n", 6) == 0);
    snprintf(name, sizeof name, "%s/other.bin.tmp%ld-0", dir, (long)dead); /* another output's */
    TL_CHECK(tlh_write(name, "other\n", 6) == 0);
    snprintf(name, sizeof name, "%s.tmp%ld-1", path, (long)dead); /* a directory of that shape */
    TL_CHECK(mkdir(name, 0755) == 0);
    snprintf(name, sizeof name, "%s.tmp%ldx-0", path, (long)dead); /* not the shape */
    TL_CHECK(tlh_write(name, "shape\n", 6) == 0);
    TL_CHECK(listing(dir, list, sizeof list) == 5);
    TL_CHECK(tl_file_write(path, "new\n", 4, NULL) == TL_OK && holds(path, (const unsigned char *)"new\n", 4));
    TL_CHECK(listing(dir, list, sizeof list) == 5); /* out.bin in, the dead writer's name out */
    snprintf(name, sizeof name, "%s.tmp%ld-0", path, (long)dead);
    TL_CHECK(access(name, F_OK) != 0);
    printf("left after the write: %s\n", list);
}
