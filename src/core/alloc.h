/* Allocation through the caller's tl_allocator, the one set of helpers every layer (render,
 * platform, scene, io) uses. A zeroed allocator means malloc/free (tl__allocator_resolve makes
 * that explicit for objects that keep one). A request for 0 bytes gets a valid, unique pointer,
 * as for an empty array. */
#ifndef TL_CORE_ALLOC_H
#define TL_CORE_ALLOC_H

#include <stddef.h>

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Copies `in` (NULL or zeroed: malloc/free) into `out` with both functions set.
 * TL_ERROR_INVALID_ARGUMENT for an allocator with only one of its two functions. */
tl_result tl__allocator_resolve(const tl_allocator *in, tl_allocator *out);

/* `size` bytes (at least 1); NULL on failure. */
void *tl__alloc(const tl_allocator *a, size_t size);
/* `count * size` bytes, cleared; NULL when the product overflows or on failure. */
void *tl__calloc(const tl_allocator *a, size_t count, size_t size);
/* `count * size` bytes, not cleared; NULL when the product overflows or on failure. */
void *tl__alloc_array(const tl_allocator *a, size_t count, size_t size);
/* Frees memory from the same allocator; NULL is ignored. */
void tl__free(const tl_allocator *a, void *ptr);

#ifdef __cplusplus
}
#endif
#endif
