# Every public header compiles alone, as C11 and as C++17, with -Wall -Wextra -Wpedantic -Werror
# (docs/architecture.md, "Layers"). One generated translation unit per header per language, containing only
# `#include "thinlight/X.h"`, goes into an OBJECT library that is part of the normal build, so a
# header that does not stand alone fails the build. The tests:
#   headers_compile_alone        rebuilds those targets;
#   headers_all_covered          checks that the headers compiled are exactly include/thinlight/*.h.
#
# Run with `cmake -P` (CMAKE_SCRIPT_MODE_FILE set) this file is the checker of the second test:
#   -DINCLUDE_DIR=<include/thinlight> -DLIST=<file with the headers compiled>

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.25)
  file(GLOB now RELATIVE "${INCLUDE_DIR}" "${INCLUDE_DIR}/*.h")
  list(SORT now)
  file(STRINGS "${LIST}" compiled)
  list(SORT compiled)
  if(NOT now STREQUAL compiled)
    message(FATAL_ERROR "headers compiled alone: ${compiled}\nheaders in ${INCLUDE_DIR}: ${now}\n"
      "(reconfigure: the list is made at configure time)")
  endif()
  list(LENGTH now n)
  message(STATUS "all ${n} public headers compile alone: ${now}")
  return()
endif()

set(TL_HEADER_DIR ${PROJECT_SOURCE_DIR}/include/thinlight)
set(TL_HEADER_TU_DIR ${CMAKE_CURRENT_BINARY_DIR}/headers)
file(GLOB TL_PUBLIC_HEADERS CONFIGURE_DEPENDS RELATIVE ${TL_HEADER_DIR} ${TL_HEADER_DIR}/*.h)
list(SORT TL_PUBLIC_HEADERS)

set(TL_HEADER_LANGUAGES C)
if(THINLIGHT_HAVE_CXX)
  list(APPEND TL_HEADER_LANGUAGES CXX)
else()
  message(WARNING "thinlight: no C++ compiler; public headers are compiled alone as C11 only")
endif()

set(TL_HEADER_TARGETS)
foreach(lang IN LISTS TL_HEADER_LANGUAGES)
  if(lang STREQUAL "C")
    set(ext c)
  else()
    set(ext cpp)
  endif()
  set(tus)
  foreach(h IN LISTS TL_PUBLIC_HEADERS)
    string(REGEX REPLACE "\\.h$" "" stem "${h}")
    set(tu ${TL_HEADER_TU_DIR}/${ext}/${stem}.${ext})
    # file(CONFIGURE) rewrites only on change: no rebuild on every configure.
    file(CONFIGURE OUTPUT ${tu} CONTENT "#include \"thinlight/${h}\"\n" @ONLY)
    list(APPEND tus ${tu})
  endforeach()
  string(TOLOWER ${lang} lower)
  set(tgt tl_headers_alone_${lower})
  add_library(${tgt} OBJECT ${tus})
  # Only the public include directory: no TL_BUILDING_LIBRARY, as a consumer sees them.
  target_include_directories(${tgt} PRIVATE ${PROJECT_SOURCE_DIR}/include)
  target_compile_options(${tgt} PRIVATE -Wall -Wextra -Wpedantic -Werror)
  if(lang STREQUAL "C")
    set_target_properties(${tgt} PROPERTIES C_STANDARD 11 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
  else()
    set_target_properties(${tgt} PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON
      CXX_EXTENSIONS OFF)
  endif()
  list(APPEND TL_HEADER_TARGETS ${tgt})
endforeach()

list(JOIN TL_PUBLIC_HEADERS "\n" _tl_header_list)
file(CONFIGURE OUTPUT ${TL_HEADER_TU_DIR}/headers.list CONTENT "${_tl_header_list}\n" @ONLY)

set(_tl_build_headers)
foreach(tgt IN LISTS TL_HEADER_TARGETS)
  list(APPEND _tl_build_headers --target ${tgt})
endforeach()
add_test(NAME headers_compile_alone
  COMMAND ${CMAKE_COMMAND} --build ${PROJECT_BINARY_DIR} --config $<CONFIG> ${_tl_build_headers})
add_test(NAME headers_all_covered
  COMMAND ${CMAKE_COMMAND} -DINCLUDE_DIR=${TL_HEADER_DIR} -DLIST=${TL_HEADER_TU_DIR}/headers.list
          -P ${CMAKE_CURRENT_LIST_FILE})
set_tests_properties(headers_compile_alone headers_all_covered PROPERTIES LABELS "headers;packaging"
  TIMEOUT 300)
set_tests_properties(headers_compile_alone PROPERTIES RESOURCE_LOCK thinlight_build_tree)
