# GLSL/C parity (ctest -R '^parity_'): shaders/codec.glsl runs in compute shaders on OSMesa and
# must give the C codec's bits. Same OSMesa requirements as tests/gl.cmake.
if(TARGET thinlight_platform AND TARGET thinlight_gl AND THINLIGHT_WITH_OSMESA)
  tl_add_test(test_parity
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_parity.c
    LIBS thinlight_gl thinlight_platform
    LABELS gl
    TIMEOUT 300
    ENVIRONMENT ${TL_GL_TEST_ENVIRONMENT})
endif()
