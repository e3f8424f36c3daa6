# The frame planner (pure) and the four render modes against the fat reference, on OSMesa.
if(TARGET thinlight AND THINLIGHT_WITH_OSMESA)
  set(_tl_modes_libs tl_render_fixture thinlight::thinlight)
  if(TARGET tl_gltf_fixtures)
    list(APPEND _tl_modes_libs tl_gltf_fixtures)
  endif()
  tl_add_test(test_modes
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_modes.c
    LIBS ${_tl_modes_libs}
    LABELS gl render
    TIMEOUT 900
    ENVIRONMENT ${TL_GL_TEST_ENVIRONMENT})
  if(TARGET tl_gltf_fixtures)
    target_compile_definitions(test_modes PRIVATE TL_TEST_GLTF "TL_TEST_WORK_DIR=\"${CMAKE_CURRENT_BINARY_DIR}\"")
  endif()
endif()
