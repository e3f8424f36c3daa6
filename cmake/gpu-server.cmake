# The GPU-server build (docs/gpu-servers.md): libthinlight with the EGL back end only, and the
# tools thinlight-bench and thinlight-render, with no OpenImageIO, tinygltf, GLFW, OSMesa or C++.
# The binaries need nothing at run time beyond libc, libm and libEGL (the GPU driver's, through
# glvnd), and the build directory can be copied to another machine and run from wherever it lands:
#
#   cmake -S . -B build-gpu -C cmake/gpu-server.cmake && cmake --build build-gpu -j
#
# (an initial-cache file: -D options given after it still apply). Test: gpu_server_build.
set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type")
set(THINLIGHT_WITH_RENDERER ON CACHE BOOL "")
set(THINLIGHT_WITH_EGL ON CACHE BOOL "")
set(THINLIGHT_WITH_OSMESA OFF CACHE BOOL "")
set(THINLIGHT_WITH_GLFW OFF CACHE BOOL "")
set(THINLIGHT_WITH_IO OFF CACHE BOOL "")
set(THINLIGHT_BUILD_EXAMPLES ON CACHE BOOL "")
set(THINLIGHT_BUILD_TESTS OFF CACHE BOOL "")
set(THINLIGHT_BENCH_EMBREE OFF CACHE BOOL "")
# Build-tree RUNPATHs relative to $ORIGIN: the tools find libthinlight.so wherever the directory goes.
set(CMAKE_BUILD_RPATH_USE_ORIGIN ON CACHE BOOL "")
