# API reference: `cmake --build build --target thinlight_docs` runs doxygen (Debian: apt-get install
# doxygen) over include/thinlight/*.h into build/docs/api/html. Every documented header must
# document every public name: any warning fails the target (ctest -L docs).

include_guard(GLOBAL)

find_program(THINLIGHT_DOXYGEN NAMES doxygen DOC "doxygen, for the thinlight_docs target")
if(NOT THINLIGHT_DOXYGEN)
  message(STATUS "thinlight: doxygen not found, no thinlight_docs target")
  return()
endif()

set(THINLIGHT_DOCS_DIR ${PROJECT_BINARY_DIR}/docs/api)
file(GLOB THINLIGHT_PUBLIC_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/include/thinlight/*.h)
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${THINLIGHT_DOCS_DIR}/Doxyfile @ONLY)
add_custom_command(
  OUTPUT ${THINLIGHT_DOCS_DIR}/html/index.html
  COMMAND ${CMAKE_COMMAND} -E make_directory ${THINLIGHT_DOCS_DIR}
  COMMAND ${THINLIGHT_DOXYGEN} ${THINLIGHT_DOCS_DIR}/Doxyfile
  DEPENDS ${THINLIGHT_PUBLIC_HEADERS} ${THINLIGHT_DOCS_DIR}/Doxyfile
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMENT "API reference (doxygen) in ${THINLIGHT_DOCS_DIR}/html"
  VERBATIM)
add_custom_target(thinlight_docs DEPENDS ${THINLIGHT_DOCS_DIR}/html/index.html)
