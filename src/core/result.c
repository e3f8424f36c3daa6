/* Result codes and their descriptions. */
#include "thinlight/base.h"

const char *tl_result_string(tl_result result)
{
    switch (result) {
    case TL_OK: return "ok";
    case TL_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case TL_ERROR_OUT_OF_MEMORY: return "out of memory";
    case TL_ERROR_IO: return "input/output error";
    case TL_ERROR_PARSE: return "malformed input";
    case TL_ERROR_UNSUPPORTED: return "unsupported input";
    case TL_ERROR_LIMIT: return "limit exceeded";
    case TL_ERROR_GL: return "OpenGL error";
    case TL_RESULT_COUNT_: break;
    }
    return "unknown result";
}
