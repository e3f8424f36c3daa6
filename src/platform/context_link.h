/* Private: what a tl_context tells the objects that depend on it (the renderers that load GL
 * through tl_context_proc_loader) when it is destroyed first. A dependant embeds a link and adds it
 * to the context; tl_context_destroy clears every link's `context`, so a dependant learns that its
 * context is gone without reading the freed context (no global state: the list is the context's). */
#ifndef TL_PLATFORM_CONTEXT_LINK_H
#define TL_PLATFORM_CONTEXT_LINK_H

#include "thinlight/context.h"

typedef struct tl__context_link {
    tl_context *context; /* NULL: never linked, removed, or the context was destroyed */
    struct tl__context_link *prev, *next;
} tl__context_link;

/* Adds `link` (not linked) to ctx's dependants; link->context = ctx. */
void tl__context_link_add(tl_context *ctx, tl__context_link *link);
/* Takes `link` off its context's list, if it is still on one; link->context = NULL. */
void tl__context_link_remove(tl__context_link *link);

#endif
