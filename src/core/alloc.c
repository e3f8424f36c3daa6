/* Allocation through the caller's allocator (alloc.h). */
#include "core/alloc.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static void *tl__malloc(size_t size, void *user)
{
    (void)user;
    return malloc(size);
}

static void tl__std_free(void *ptr, void *user)
{
    (void)user;
    free(ptr);
}

tl_result tl__allocator_resolve(const tl_allocator *in, tl_allocator *out)
{
    if (!in || (!in->alloc && !in->free)) {
        *out = (tl_allocator){tl__malloc, tl__std_free, NULL};
        return TL_OK;
    }
    if (!in->alloc || !in->free) return TL_ERROR_INVALID_ARGUMENT;
    *out = *in;
    return TL_OK;
}

void *tl__alloc(const tl_allocator *a, size_t size)
{
    if (!size) size = 1;
    return a && a->alloc ? a->alloc(size, a->user) : malloc(size);
}

void *tl__alloc_array(const tl_allocator *a, size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size) return NULL;
    return tl__alloc(a, count * size);
}

void *tl__calloc(const tl_allocator *a, size_t count, size_t size)
{
    void *p = tl__alloc_array(a, count, size);
    size_t bytes = count * size;
    if (p) memset(p, 0, bytes ? bytes : 1);
    return p;
}

void tl__free(const tl_allocator *a, void *ptr)
{
    if (!ptr) return;
    if (a && a->free) a->free(ptr, a->user);
    else free(ptr);
}
