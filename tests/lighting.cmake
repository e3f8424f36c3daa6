# The lighting models: the double-precision reference (tests/reference) against numerical
# integration (ctest -L lighting), and the GLSL functions of shaders/lighting.glsl against it on
# OSMesa (ctest -R '^glsl_lighting_'). lighting_doc regenerates the tables of docs/lighting.md.
add_library(tl_lighting_ref STATIC
  ${CMAKE_CURRENT_LIST_DIR}/reference/lighting_ref.c
  ${CMAKE_CURRENT_LIST_DIR}/reference/lighting_integrals.c
  ${CMAKE_CURRENT_LIST_DIR}/reference/lighting_tables.c)
target_include_directories(tl_lighting_ref PUBLIC ${CMAKE_CURRENT_LIST_DIR}/reference)
target_link_libraries(tl_lighting_ref PUBLIC thinlight_warnings m)

tl_add_test(test_lighting_ref SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_lighting_ref.c LIBS tl_lighting_ref
  LABELS lighting TIMEOUT 300
  CASES
    ggx_d_integrates_to_one
    ggx_directional_albedo_at_most_one
    sphere_irradiance_matches_monte_carlo
    sphere_irradiance_limits_and_continuity
    sphere_representative_point_vs_monte_carlo
    ggx_two_specular_sums_are_exact
    ggx_punctual_diffuse_equals_blinn_phong
    ggx_metallic_roughness_surface
    ggx_extreme_cases_finite)

add_executable(lighting_doc ${CMAKE_CURRENT_LIST_DIR}/lighting_doc.c)
target_link_libraries(lighting_doc PRIVATE tl_lighting_ref)

if(TARGET thinlight_platform AND TARGET thinlight_gl AND THINLIGHT_WITH_OSMESA)
  set(TL_GLSL_LIGHTING_CASES
    glsl_lighting_gloss_to_ggx_alpha_bit_exact
    glsl_lighting_ggx_d_matches_reference
    glsl_lighting_ggx_vis_matches_reference
    glsl_lighting_fresnel_matches_reference
    glsl_lighting_sphere_irradiance_matches_reference
    glsl_lighting_sphere_specular_dir_matches_reference
    glsl_lighting_sphere_normalization_matches_reference
    glsl_lighting_ggx_terms_match_reference
    glsl_lighting_blinn_phong_terms_match_reference
    glsl_lighting_specular_resolve_matches_reference
    glsl_lighting_ggx_extreme_cases_finite)
  tl_add_test(test_lighting_glsl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_lighting_glsl.c
    LIBS tl_lighting_ref thinlight_gl thinlight_platform
    CASES ${TL_GLSL_LIGHTING_CASES}
    LABELS gl
    TIMEOUT 300)
  set_tests_properties(${TL_GLSL_LIGHTING_CASES} PROPERTIES ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
