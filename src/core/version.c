/* Version of the linked library. */
#include "thinlight/version.h"

#define TL__STR2(x) #x
#define TL__STR(x) TL__STR2(x)

uint32_t tl_version(void) { return TL_VERSION; }

const char *tl_version_string(void)
{
    return TL__STR(TL_VERSION_MAJOR) "." TL__STR(TL_VERSION_MINOR) "." TL__STR(TL_VERSION_PATCH);
}
