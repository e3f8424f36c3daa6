/* Helpers shared by the command-line tools in examples/: one-line failures, whole-or-absent file
 * output (tl_file_write, thinlight/file.h), generated doc sections between markers, a small JSON writer, gnuplot
 * plots, a progress line on stderr and a description of the machine. Not part of the library. */
#ifndef TL_TOOL_UTIL_H
#define TL_TOOL_UTIL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#if defined(__GNUC__)
#define TL_TOOL_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define TL_TOOL_PRINTF(f, a)
#endif

/* ---- failures and strings ------------------------------------------------------------------ */

/* Prints "TOOL: message" as one line on stderr. */
void tl_tool_fail(const char *tool, const char *fmt, ...) TL_TOOL_PRINTF(2, 3);
/* A malloc'ed formatted string; NULL when out of memory. */
char *tl_tool_strf(const char *fmt, ...) TL_TOOL_PRINTF(1, 2);

/* ---- files --------------------------------------------------------------------------------- */

typedef int (*tl_tool_write_fn)(FILE *f, const void *ctx);

/* Directory part of a path ("." when there is none); caller frees. */
char *tl_tool_dir_of(const char *path);
/* mkdir -p; 0 on success, else an errno value. */
int tl_tool_make_dirs(const char *path);
/* Whether `path` can be written as an output (tl_file_check_writable: absent or a regular file,
 * not `-`, in a folder where a file can be made); 0, or 1 after one line on stderr. */
int tl_tool_check_output(const char *tool, const char *path);
/* Replaces `path` with the bytes, whole or not at all (tl_file_write); 0, or 1 after one line. */
int tl_tool_write_bytes(const char *tool, const char *path, const void *data, size_t size);
/* Writes through `fn` into memory, then as tl_tool_write_bytes: on failure one line, `path`
 * untouched and nothing left beside it; a process killed at any point leaves `path` old or new. */
int tl_tool_write_atomic(const char *tool, const char *path, tl_tool_write_fn fn, const void *ctx);
/* The whole file, NUL-terminated (size without the NUL); NULL with errno set on failure. */
char *tl_tool_read_file(const char *path, size_t *size);
/* Copies `src` to `dst` atomically; prints one line and returns nonzero on failure. */
int tl_tool_copy_file(const char *tool, const char *src, const char *dst);
/* Whether `path` names a directory that exists. */
int tl_tool_is_dir(const char *path);

/* ---- generated doc sections ---------------------------------------------------------------- */

/* Finds `begin` and, after it, `end` in `text`: *head_len is the length up to and including the
 * begin marker, *tail the end marker onwards. Prints one line naming `path` and returns nonzero
 * when a marker is missing. */
int tl_tool_doc_split(const char *tool, const char *path, const char *text, const char *begin, const char *end,
                      size_t *head_len, const char **tail);

/* ---- JSON ---------------------------------------------------------------------------------- */

/* A JSON string literal with the needed escapes. */
void tl_tool_json_string(FILE *f, const char *s);
/* A number with 9 significant digits; null for NaN and Inf (JSON has neither). */
void tl_tool_json_number(FILE *f, double v);

#define TL_TOOL_JSON_MAX_DEPTH 16

/* A streaming writer that places commas, newlines and indentation. Members of an object opened
 * with `inline_members` stay on one line. Keys are NULL inside arrays and at the top level. */
typedef struct tl_tool_json {
    FILE *f;
    int depth;
    int count[TL_TOOL_JSON_MAX_DEPTH];  /* members written at each depth */
    int inline_[TL_TOOL_JSON_MAX_DEPTH];
} tl_tool_json;

void tl_tool_json_begin(tl_tool_json *j, FILE *f);
void tl_tool_json_object(tl_tool_json *j, const char *key, int inline_members);
void tl_tool_json_array(tl_tool_json *j, const char *key, int inline_members);
void tl_tool_json_close(tl_tool_json *j, char bracket); /* '}' or ']' */
void tl_tool_json_str(tl_tool_json *j, const char *key, const char *value);
void tl_tool_json_num(tl_tool_json *j, const char *key, double value);
void tl_tool_json_uint(tl_tool_json *j, const char *key, uint64_t value);
void tl_tool_json_bool(tl_tool_json *j, const char *key, int value);
/* Ends the document (every object and array closed) with a newline. */
void tl_tool_json_end(tl_tool_json *j);

/* ---- gnuplot ------------------------------------------------------------------------------- */

/* Whether an executable gnuplot is on PATH. */
int tl_tool_have_gnuplot(void);

/* One plot: DIR/NAME.dat (from `data`, may be NULL), DIR/NAME.gp (from `script`), and gnuplot run
 * inside DIR makes DIR/NAME.png. The script must hold the line `set_output` (filled in before the
 * writers run): run by the tool, gnuplot writes the PNG on its standard output, which the tool
 * checks and writes with tl_file_write; run by a user, the script writes NAME.png itself. */
typedef struct tl_tool_plot {
    const char *tool;
    const char *dir;
    const char *name;
    tl_tool_write_fn data;
    tl_tool_write_fn script; /* both receive this struct as ctx */
    const void *user;
    size_t max_bytes;        /* a larger PNG gets a warning; 0: no limit */
    char set_output[256];
} tl_tool_plot;

/* Prints one line and returns nonzero on failure. */
int tl_tool_make_plot(tl_tool_plot *p);

/* ---- progress and machine ------------------------------------------------------------------ */

/* A progress line on stderr, shown only once the work has run for a second: on a terminal one
 * line updated in place, otherwise a plain line per milestone. */
typedef struct tl_tool_progress {
    double start_ms, last_ms;
    uint64_t total;
    int tty;
    int shown;
} tl_tool_progress;

void tl_tool_progress_begin(tl_tool_progress *p, uint64_t total);
/* `milestone`: a step worth a line when stderr is not a terminal. */
void tl_tool_progress_update(tl_tool_progress *p, uint64_t done, const char *label, int milestone);
/* Ends the line (when one was shown). */
void tl_tool_progress_end(tl_tool_progress *p);

/* Monotonic clock in milliseconds. */
double tl_tool_now_ms(void);

/* The 1-minute load average (/proc/loadavg), NaN when unknown: how busy the machine was. */
double tl_tool_load_average(void);

/* CPU model ("unknown CPU" when unknown) and the number of online cores. */
void tl_tool_machine(char *cpu, size_t cpu_size, size_t *cores);

#endif
