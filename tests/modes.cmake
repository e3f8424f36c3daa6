# The frame planner (pure) and the four render modes against the fat reference, on OSMesa.
if(TARGET thinlight AND THINLIGHT_WITH_OSMESA)
  set(TL_MODES_TEST_CASES
    plan_rules_exhaustive
    plan_fat_layout_44_bytes
    plan_format_and_bad_input
    plan_allocations_match_renderer
    plan_saving_same_image
    modes_match_fat_default_scene
    modes_match_fat_many_lights
    modes_transparent_materials
    render_to_caller_framebuffer)
  set(_tl_modes_libs thinlight::thinlight)
  if(TARGET tl_gltf_fixtures)
    list(APPEND TL_MODES_TEST_CASES modes_match_fat_gltf_scenes)
    list(APPEND _tl_modes_libs tl_gltf_fixtures)
  endif()
  tl_add_test(test_modes
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_modes.c
    LIBS ${_tl_modes_libs}
    CASES ${TL_MODES_TEST_CASES}
    LABELS gl render
    TIMEOUT 900)
  if(TARGET tl_gltf_fixtures)
    target_compile_definitions(test_modes PRIVATE TL_TEST_GLTF "TL_TEST_WORK_DIR=\"${CMAKE_CURRENT_BINARY_DIR}\"")
  endif()
  set_tests_properties(${TL_MODES_TEST_CASES} PROPERTIES ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
