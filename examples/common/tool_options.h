/* The renderer options as command-line flags, generated from the library's option registry
 * (thinlight/options.h): one flag per field, named after it ("ssr.refine" -> --ssr-refine; an
 * effect's `enabled` -> --ssr; the established spellings of a few kept: tool_options.c), its kind,
 * range, choices and --help line taken from the field's row, its value checked and written by
 * tl_option_parse. thinlight-render, thinlight-bench and thinlight-viewer build their renderer
 * flags with it; tool-only options stay in each tool's own table. Not part of the library. */
#ifndef TL_TOOL_OPTIONS_H
#define TL_TOOL_OPTIONS_H

#include <stdio.h>

#include "thinlight/renderer.h"
#include "tool_args.h"

/* Room for the flags of every field plus the established extra spellings. */
#define TL_TOOL_OPTIONS_MAX 128
#define TL_TOOL_OPTION_CHOICES 40

/* How a field's flag is spelled and what its value means. */
typedef struct tl_tool_flag_spec {
    char name[48];     /* "--ssr-refine" */
    double scale;      /* the flag's number is the field's times this (degrees for radians); 1 otherwise */
    int broadcast;     /* a colour given as one number for its three components (--ambient) */
    const char *fixed; /* a flag without value setting the field to this text (--no-depth-prepass: "off") */
} tl_tool_flag_spec;

/* The spelling of `field`'s flag (every tool spells a field alike). */
void tl_tool_flag_spec_of(const tl_option_info *field, tl_tool_flag_spec *out);

/* A tool's renderer flags: build once into storage that lives as long as the parse (static). */
typedef struct tl_tool_options {
    size_t count;
    tl_opt opts[TL_TOOL_OPTIONS_MAX];
    const tl_option_info *field[TL_TOOL_OPTIONS_MAX];
    tl_tool_flag_spec spec[TL_TOOL_OPTIONS_MAX];
    const char *choices[TL_TOOL_OPTIONS_MAX][TL_TOOL_OPTION_CHOICES + 1];
    int values[TL_TOOL_OPTIONS_MAX][TL_TOOL_OPTION_CHOICES];
    char text[TL_TOOL_OPTIONS_MAX][8][16]; /* the choices of powers of two, as numbers */
} tl_tool_options;

/* Every field's flag but those named in `exclude` (field names, NULL-terminated; may be NULL): a
 * tool that sets a field itself (the bench's sweeps) leaves it out. */
void tl_tool_options_build(tl_tool_options *t, const char *const *exclude);
tl_opt_table tl_tool_options_table(const tl_tool_options *t);

/* A parsed option into `o`: 1 when it is one of t's (applied), 0 when it is not, 2 (bad usage)
 * after one line "TOOL: --flag 'value': why" when the library refuses the value. */
int tl_tool_options_apply(const char *tool, const tl_tool_options *t, tl_renderer_options *o, const tl_opt *opt,
                          const tl_opt_value *v);

/* --help: a line (wrapped) per flag: the flag, what it takes, the field's help, range and default. */
void tl_tool_options_help(FILE *f, const tl_tool_options *t);

#endif
