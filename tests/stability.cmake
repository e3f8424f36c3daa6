# Extreme and stiff cases of DESIGN.md section 5 in rendered frames on OSMesa (ctest -L stability);
# the codec-level cases live in codec.cmake, the light-volume cases in render.cmake.
if(TARGET thinlight AND THINLIGHT_WITH_OSMESA)
  set(TL_STABILITY_TEST_CASES
    stability_gloss_0_and_1
    stability_grazing_light_n_dot_l
    stability_grazing_view_n_dot_v
    stability_light_at_shaded_point
    stability_light_radius_zero
    stability_light_radius_huge
    stability_10k_lights_fp16_accumulation
    stability_intensity_fp16_max
    stability_no_lights
    stability_empty_scene
    stability_1x1_target
    stability_largest_target
    stability_degenerate_triangles
    stability_nan_inf_vertices
    stability_missing_textures
    stability_positions_at_near_and_far_plane
    stability_grazing_view_rays_positions)
  tl_add_test(test_stability
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_stability.c
    LIBS thinlight::thinlight
    CASES ${TL_STABILITY_TEST_CASES}
    LABELS gl render stability
    TIMEOUT 300)
  set_tests_properties(${TL_STABILITY_TEST_CASES} PROPERTIES ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
