# GLSL/C parity (ctest -R '^parity_'): shaders/codec.glsl runs in compute shaders on OSMesa and
# must give the C codec's bits. Same OSMesa requirements and LSan environment as tests/gl.cmake.
if(TARGET thinlight_platform AND TARGET thinlight_gl AND THINLIGHT_WITH_OSMESA)
  set(TL_PARITY_TEST_CASES
    parity_oct8_encode
    parity_oct10_encode
    parity_oct12_encode
    parity_oct16_encode
    parity_oct8_encode_precise
    parity_oct10_encode_precise
    parity_oct12_encode_precise
    parity_oct16_encode_precise
    parity_oct8_decode_all_codes
    parity_oct10_decode_all_codes
    parity_oct12_decode
    parity_oct16_decode
    parity_oct_extreme_cases
    parity_oct_axes_exact
    parity_rt0_rgba8
    parity_rt0_rgb10a2
    parity_gloss8
    parity_gloss10
    parity_gloss_specular_power
    parity_luma_chroma_ycbcr
    parity_luma_chroma_ycocg
    parity_albedo_ycbcr
    parity_albedo_ycocg
    parity_albedo_edge_chroma
    parity_depth_d24
    parity_depth_d32f
    parity_depth_reversed)
  tl_add_test(test_parity
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_parity.c
    LIBS thinlight_gl thinlight_platform
    CASES ${TL_PARITY_TEST_CASES}
    LABELS gl
    TIMEOUT 300)
  # tests/gl.cmake defines TL_GL_TEST_ENVIRONMENT, but the parts are included in glob order
  # (gl.cmake before parity.cmake today); set the same value here so the order never matters.
  set_tests_properties(${TL_PARITY_TEST_CASES} PROPERTIES ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
