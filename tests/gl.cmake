# GL foundation tests (src/gl, src/platform) on a headless OSMesa context: no display needed.
if(TARGET thinlight_platform AND TARGET thinlight_gl AND THINLIGHT_WITH_OSMESA)
  tl_add_test(test_gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/gl_test.c
    LIBS thinlight_platform thinlight_gl
    LABELS gl
    TIMEOUT 300
    ENVIRONMENT ${TL_GL_TEST_ENVIRONMENT})
endif()
