/* Writing the optional message buffers of the GL layer. */
#ifndef TL_GL_MSG_H
#define TL_GL_MSG_H

#include <stdarg.h>
#include <stdio.h>

#if defined(__GNUC__)
#  define TL__PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#  define TL__PRINTF(f, a)
#endif

/* Replaces the buffer's text (buf may be NULL, size 0). */
static inline TL__PRINTF(3, 4) void tl__msg(char *buf, size_t size, const char *fmt, ...)
{
    if (!buf || size == 0) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, size, fmt, ap);
    va_end(ap);
}

/* Appends to the buffer's text, truncating at its end. */
static inline TL__PRINTF(3, 4) void tl__msg_append(char *buf, size_t size, const char *fmt, ...)
{
    if (!buf || size == 0) return;
    size_t used = 0;
    while (used < size - 1 && buf[used]) used++;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf + used, size - used, fmt, ap);
    va_end(ap);
}

#endif
