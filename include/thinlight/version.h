/* thinlight version: compile-time macros and the version of the library actually linked. */
#ifndef THINLIGHT_VERSION_H
#define THINLIGHT_VERSION_H

#include "thinlight/base.h"

#define TL_VERSION_MAJOR 0
#define TL_VERSION_MINOR 1
#define TL_VERSION_PATCH 0
/** Version as one comparable number: major * 10000 + minor * 100 + patch. */
#define TL_VERSION (TL_VERSION_MAJOR * 10000 + TL_VERSION_MINOR * 100 + TL_VERSION_PATCH)

#ifdef __cplusplus
extern "C" {
#endif

/** Version of the linked library, encoded as TL_VERSION; compare with the header's TL_VERSION. */
TL_API uint32_t tl_version(void);
/** Version of the linked library as "major.minor.patch". */
TL_API const char *tl_version_string(void);

#ifdef __cplusplus
}
#endif
#endif
