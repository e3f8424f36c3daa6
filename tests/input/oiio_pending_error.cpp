// OpenImageIO keeps the error of a failed ImageInput/ImageOutput::create in a per-thread global
// that OIIO::geterror() returns (and clears): the C tests of io_errors.c ask it through this, to
// check that thinlight leaves none of its own failures there for the application to find.
#include <OpenImageIO/imageio.h>

#include <cstdio>

extern "C" int tl_test_oiio_pending_error(char *out, size_t size)
{
    std::string e = OIIO::geterror();
    if (size) std::snprintf(out, size, "%s", e.c_str());
    return !e.empty();
}
