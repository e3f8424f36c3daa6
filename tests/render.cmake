# Renderer tests on OSMesa: light volumes vs full-screen lights, FXAA, bad input.
if(TARGET thinlight AND THINLIGHT_WITH_OSMESA)
  tl_add_test(test_render
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_render.c
    LIBS tl_render_fixture thinlight::thinlight
    LABELS gl render
    TIMEOUT 600
    ENVIRONMENT ${TL_GL_TEST_ENVIRONMENT})
endif()
