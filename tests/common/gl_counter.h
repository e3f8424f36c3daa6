/* The GL call counter of the renderer tests: a loader that hands out the context's entry points,
 * wrapping the ones listed in gl_counter.c so that each call is counted, for tests of what a frame,
 * an option change or a scene update asks of GL. Give it as tl_renderer_desc.get_proc_address
 * (user: the tl_context, or zero with tl_test_renderer for g_ctx). It is not
 * tl_context_proc_loader, so a renderer loading through it checks the context as one with an
 * application's loader does. One set of counts per process: a test reads them between its calls. */
#ifndef TL_GL_COUNTER_H
#define TL_GL_COUNTER_H

#include "thinlight/renderer.h"

/* The loader: `ctx` is the tl_context the entry points come from. */
tl_gl_function tl_test_gl_counting_loader(void *ctx, const char *name);

/* Every count back to zero. */
void tl_test_gl_counts_reset(void);
/* Calls of `name` ("glLinkProgram") since the reset; a name the counter does not wrap fails the
 * running case. */
unsigned long tl_test_gl_calls(const char *name);
/* Calls that sent buffer data from the CPU (glNamedBufferStorage and glNamedBufferData with data,
 * glNamedBufferSubData, glBufferSubData), and their bytes. */
unsigned long tl_test_gl_uploads(void);
unsigned long long tl_test_gl_upload_bytes(void);
/* "label: Name count ..." for every count above zero, on stdout. */
void tl_test_gl_counts_print(const char *label);

#endif
