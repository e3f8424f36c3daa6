# GL foundation tests (src/gl, src/platform) on a headless OSMesa context: no display needed.
if(TARGET thinlight_platform AND TARGET thinlight_gl AND THINLIGHT_WITH_OSMESA)
  set(TL_GL_TEST_CASES
    gl_context_osmesa_core45
    gl_context_bad_input
    gl_program_embedded_include
    gl_render_target_bytes
    gl_fullscreen_readback
    gl_timer_query)
  tl_add_test(test_gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/gl_test.c
    LIBS thinlight_platform thinlight_gl
    CASES ${TL_GL_TEST_CASES}
    LABELS gl
    TIMEOUT 300)
  # Under THINLIGHT_SANITIZE, Mesa's own leaks are suppressed (tests/lsan.supp lists only Mesa and
  # LLVM libraries); leak checking stays on for everything else. Other GL test parts can reuse
  # TL_GL_TEST_ENVIRONMENT.
  set(TL_GL_TEST_ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
  set_tests_properties(${TL_GL_TEST_CASES} PROPERTIES ENVIRONMENT "${TL_GL_TEST_ENVIRONMENT}")
endif()
