# Extreme and stiff cases of DESIGN.md section 5 in rendered frames on OSMesa (ctest -L stability);
# the codec-level cases live in codec.cmake, the light-volume cases in render.cmake.
if(TARGET thinlight AND THINLIGHT_WITH_OSMESA)
  tl_add_test(test_stability
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_stability.c
    LIBS tl_render_fixture thinlight::thinlight
    LABELS gl render stability
    TIMEOUT 300
    ENVIRONMENT ${TL_GL_TEST_ENVIRONMENT})
endif()
