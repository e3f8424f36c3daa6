/**
 * @file thinlight/version.h
 * @brief The version of the headers (macros) and of the library actually linked (functions).
 *
 * The three TL_VERSION_* lines below are the project's only version: CMake reads them for
 * project(VERSION), the SOVERSION (= major), the package version file and the .pc files. Within
 * one major version the ABI is compatible (README, "Using thinlight as a library").
 */
#ifndef THINLIGHT_VERSION_H
#define THINLIGHT_VERSION_H

#include "thinlight/base.h"

/** Major version: changes when the API or ABI breaks; the shared libraries' SOVERSION. */
#define TL_VERSION_MAJOR 0
/** Minor version: additions that keep the ABI (0.x: see the README). Kept below 100. */
#define TL_VERSION_MINOR 2
/** Patch version: fixes only. Kept below 100. */
#define TL_VERSION_PATCH 0
/** Version as one comparable number: major * 10000 + minor * 100 + patch. */
#define TL_VERSION (TL_VERSION_MAJOR * 10000 + TL_VERSION_MINOR * 100 + TL_VERSION_PATCH)

#ifdef __cplusplus
extern "C" {
#endif

/** Version of the linked library, encoded as TL_VERSION; compare with the header's TL_VERSION
 *  (same major: compatible). */
TL_API uint32_t tl_version(void);
/** Version of the linked library as "major.minor.patch" (static storage). */
TL_API const char *tl_version_string(void);

#ifdef __cplusplus
}
#endif
#endif
