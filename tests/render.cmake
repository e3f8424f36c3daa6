# Renderer tests on OSMesa: light volumes vs full-screen lights, FXAA, bad input.
if(TARGET thinlight AND THINLIGHT_WITH_OSMESA)
  set(TL_RENDER_TEST_CASES
    light_volume_camera_inside
    light_volume_crossing_near_plane
    light_volume_crossing_far_plane
    light_volume_spot_camera_inside
    light_volume_mixed_types_draw_calls
    fxaa_reduces_edge_gradient
    fxaa_flat_and_text_pattern_bounded
    renderer_bad_input
    default_scene_image_sanity)
  tl_add_test(test_render
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_render.c
    LIBS thinlight::thinlight
    CASES ${TL_RENDER_TEST_CASES}
    LABELS gl render
    TIMEOUT 600)
  set_tests_properties(${TL_RENDER_TEST_CASES} PROPERTIES ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
