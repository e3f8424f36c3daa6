/* Progress on stderr for work longer than a second (docs/tools.md), the monotonic clock and
 * a one-line description of the machine for reports. */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "tool_util.h"

#define TL__PROGRESS_DELAY_MS 1000.0
#define TL__PROGRESS_REDRAW_MS 100.0
#define TL__PROGRESS_WIDTH 20

double tl_tool_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

void tl_tool_progress_begin(tl_tool_progress *p, uint64_t total)
{
    memset(p, 0, sizeof *p);
    p->total = total;
    p->tty = isatty(fileno(stderr));
    p->start_ms = tl_tool_now_ms();
}

void tl_tool_progress_update(tl_tool_progress *p, uint64_t done, const char *label, int milestone)
{
    double now = tl_tool_now_ms();
    if (now - p->start_ms < TL__PROGRESS_DELAY_MS) return;
    if (p->tty ? now - p->last_ms < TL__PROGRESS_REDRAW_MS && done < p->total : !milestone) return;
    p->last_ms = now;
    p->shown = 1;
    if (done > p->total) done = p->total;
    size_t filled = p->total ? (size_t)(done * TL__PROGRESS_WIDTH / p->total) : TL__PROGRESS_WIDTH;
    char bar[TL__PROGRESS_WIDTH + 1];
    for (size_t i = 0; i < TL__PROGRESS_WIDTH; i++) bar[i] = i < filled ? '#' : ' ';
    bar[TL__PROGRESS_WIDTH] = '\0';
    double elapsed = (now - p->start_ms) * 1e-3;
    if (p->tty)
        fprintf(stderr, "\r[%s] %3.0f%% %6.1f s  %-44.44s", bar, p->total ? 100.0 * (double)done / (double)p->total : 100.0,
                elapsed, label);
    else
        fprintf(stderr, "[%s] %3.0f%% %6.1f s  %s\n", bar, p->total ? 100.0 * (double)done / (double)p->total : 100.0,
                elapsed, label);
    fflush(stderr);
}

void tl_tool_progress_end(tl_tool_progress *p)
{
    if (p->shown) {
        p->last_ms = 0.0;
        tl_tool_progress_update(p, p->total, "done", 1);
        if (p->tty) fputc('\n', stderr);
    }
}

double tl_tool_load_average(void)
{
    double load = NAN;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &load) != 1) load = NAN;
        fclose(f);
    }
    return load;
}

void tl_tool_machine(char *cpu, size_t cpu_size, size_t *cores)
{
    snprintf(cpu, cpu_size, "unknown CPU");
    *cores = 0;
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        int have_model = 0;
        while (fgets(line, sizeof line, f)) {
            if (strncmp(line, "processor", 9) == 0) (*cores)++;
            if (!have_model && strncmp(line, "model name", 10) == 0) {
                const char *v = strchr(line, ':');
                if (!v) continue;
                v++;
                while (*v == ' ' || *v == '\t') v++;
                size_t n = strcspn(v, "\r\n");
                snprintf(cpu, cpu_size, "%.*s", (int)n, v);
                have_model = 1;
            }
        }
        fclose(f);
    }
    if (*cores == 0) {
        long n = sysconf(_SC_NPROCESSORS_ONLN);
        *cores = n > 0 ? (size_t)n : 1;
    }
}
