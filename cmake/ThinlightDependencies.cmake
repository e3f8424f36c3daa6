# Finds what libthinlight links against, once, at the top level, and records it for packaging.
#
# Every dependency is private to libthinlight.so (no public header includes a dependency's header),
# but libthinlight.a's consumers link them, so this file also collects:
#   THINLIGHT_LINK_DEPS        targets linked PRIVATE by libthinlight (shared and static)
#   THINLIGHT_PKG_MODULES      "<prefix>=<pkg-config module>" pairs, recreated by thinlightConfig.cmake
#                              (imported targets PkgConfig::<prefix>) and listed in thinlight.pc's
#                              Requires.private
#   THINLIGHT_CMAKE_PACKAGES   CMake packages found by config (find_dependency in thinlightConfig.cmake)
#   THINLIGHT_PC_LIBS_PRIVATE  flags for thinlight.pc's Libs.private (libm, threads, the C++ runtime)
#
# Imported targets are GLOBAL so that src/ and tests/ see the same ones. Options:
#   THINLIGHT_WITH_OSMESA, THINLIGHT_WITH_EGL, THINLIGHT_WITH_GLFW, THINLIGHT_WITH_IO (each off
#   removes its dependency).

include_guard(GLOBAL)

set(THINLIGHT_LINK_DEPS "")
set(THINLIGHT_PKG_MODULES "")
set(THINLIGHT_CMAKE_PACKAGES "")
set(THINLIGHT_PC_LIBS_PRIVATE "-lm")

if(NOT THINLIGHT_WITH_RENDERER)
  # The codec alone: libm and a C compiler.
  set(THINLIGHT_WITH_GLFW OFF)
  message(STATUS "thinlight: codec only (THINLIGHT_WITH_RENDERER=OFF)")
  return()
endif()

find_package(Threads REQUIRED)
list(APPEND THINLIGHT_LINK_DEPS Threads::Threads)
if(CMAKE_THREAD_LIBS_INIT)
  string(APPEND THINLIGHT_PC_LIBS_PRIVATE " ${CMAKE_THREAD_LIBS_INIT}")
endif()
find_package(PkgConfig QUIET)

# thinlight_pkg_dependency(<prefix> <module> <option> <hint>): a required pkg-config module for
# an enabled option, as the GLOBAL imported target PkgConfig::<prefix>.
function(thinlight_pkg_dependency prefix module option hint)
  if(NOT PKG_CONFIG_FOUND)
    message(FATAL_ERROR "${option} needs pkg-config to find '${module}' (Debian/Ubuntu: apt-get "
      "install pkg-config ${hint}), or configure with -D${option}=OFF")
  endif()
  pkg_check_modules(${prefix} QUIET IMPORTED_TARGET GLOBAL ${module})
  if(NOT ${prefix}_FOUND)
    message(FATAL_ERROR "${option} is ON but pkg-config finds no '${module}' (Debian/Ubuntu: "
      "apt-get install ${hint}); or configure with -D${option}=OFF")
  endif()
  set(THINLIGHT_LINK_DEPS ${THINLIGHT_LINK_DEPS} PkgConfig::${prefix} PARENT_SCOPE)
  set(THINLIGHT_PKG_MODULES ${THINLIGHT_PKG_MODULES} "${prefix}=${module}" PARENT_SCOPE)
  set(${prefix}_VERSION "${${prefix}_VERSION}" PARENT_SCOPE)
endfunction()

# OSMesa: the headless context (default back end).
if(THINLIGHT_WITH_OSMESA)
  thinlight_pkg_dependency(thinlight_osmesa osmesa THINLIGHT_WITH_OSMESA libosmesa6-dev)
  message(STATUS "thinlight: OSMesa back end ${thinlight_osmesa_VERSION}")
endif()

# EGL: headless contexts on GPU devices (EGL_EXT_platform_device) and Mesa's surfaceless platform.
# libEGL is the only library it links (glvnd's libEGL.so.1 on Linux); GL itself is loaded through
# eglGetProcAddress.
if(THINLIGHT_WITH_EGL)
  thinlight_pkg_dependency(thinlight_egl egl THINLIGHT_WITH_EGL libegl-dev)
  message(STATUS "thinlight: EGL back end ${thinlight_egl_VERSION}")
endif()

# GLFW: windows. Defaults to ON when it can be found (pkg-config first, then its CMake package).
set(THINLIGHT_GLFW_TARGET "")
if(NOT DEFINED THINLIGHT_WITH_GLFW OR THINLIGHT_WITH_GLFW)
  if(PKG_CONFIG_FOUND)
    pkg_check_modules(thinlight_glfw3 QUIET IMPORTED_TARGET GLOBAL glfw3)
    if(thinlight_glfw3_FOUND)
      set(THINLIGHT_GLFW_TARGET PkgConfig::thinlight_glfw3)
    endif()
  endif()
  if(NOT THINLIGHT_GLFW_TARGET)
    find_package(glfw3 CONFIG QUIET GLOBAL)
    if(TARGET glfw)
      set(THINLIGHT_GLFW_TARGET glfw)
    endif()
  endif()
endif()
if(THINLIGHT_GLFW_TARGET)
  set(_tl_glfw_default ON)
else()
  set(_tl_glfw_default OFF)
endif()
option(THINLIGHT_WITH_GLFW "Build the GLFW (window) context back end into libthinlight" ${_tl_glfw_default})
if(THINLIGHT_WITH_GLFW)
  if(NOT THINLIGHT_GLFW_TARGET)
    message(FATAL_ERROR "THINLIGHT_WITH_GLFW is ON but glfw3 was not found by pkg-config or "
      "find_package (Debian/Ubuntu: apt-get install libglfw3-dev); or configure with "
      "-DTHINLIGHT_WITH_GLFW=OFF")
  endif()
  list(APPEND THINLIGHT_LINK_DEPS ${THINLIGHT_GLFW_TARGET})
  if(THINLIGHT_GLFW_TARGET STREQUAL "glfw")
    list(APPEND THINLIGHT_CMAKE_PACKAGES glfw3)
  else()
    list(APPEND THINLIGHT_PKG_MODULES "thinlight_glfw3=glfw3")
  endif()
  message(STATUS "thinlight: GLFW back end (${THINLIGHT_GLFW_TARGET})")
endif()

# io: OpenImageIO through pkg-config rather than its CMake package (Debian's references tool
# binaries that the -dev package does not install, which fails configure). tinygltf is compiled
# into libthinlight from its header (src/io/gltf_tinygltf.cpp) with nlohmann-json: a build-time
# dependency only, nothing for consumers to link.
if(THINLIGHT_WITH_IO)
  thinlight_pkg_dependency(thinlight_oiio OpenImageIO THINLIGHT_WITH_IO libopenimageio-dev)
  find_path(THINLIGHT_TINYGLTF_INCLUDE_DIR tiny_gltf.h DOC "Directory of tiny_gltf.h")
  find_path(THINLIGHT_NLOHMANN_JSON_INCLUDE_DIR nlohmann/json.hpp DOC "Directory of nlohmann/json.hpp")
  if(NOT THINLIGHT_TINYGLTF_INCLUDE_DIR OR NOT THINLIGHT_NLOHMANN_JSON_INCLUDE_DIR)
    message(FATAL_ERROR "THINLIGHT_WITH_IO is ON but tiny_gltf.h or nlohmann/json.hpp was not "
      "found (Debian/Ubuntu: apt-get install libtinygltf-dev nlohmann-json3-dev); or configure "
      "with -DTHINLIGHT_WITH_IO=OFF")
  endif()
  # The C++ runtime: libthinlight.so records it itself; a C program linking libthinlight.a with
  # a C compiler must name it.
  set(_tl_cxx_runtime "")
  foreach(lib stdc++ c++)
    if(lib IN_LIST CMAKE_CXX_IMPLICIT_LINK_LIBRARIES)
      set(_tl_cxx_runtime ${lib})
      break()
    endif()
  endforeach()
  if(_tl_cxx_runtime)
    set(THINLIGHT_CXX_RUNTIME ${_tl_cxx_runtime})
    string(APPEND THINLIGHT_PC_LIBS_PRIVATE " -l${_tl_cxx_runtime}")
  endif()
  message(STATUS "thinlight: io (OpenImageIO ${thinlight_oiio_VERSION}, ${THINLIGHT_TINYGLTF_INCLUDE_DIR}/tiny_gltf.h)")
endif()

list(APPEND THINLIGHT_LINK_DEPS m)
