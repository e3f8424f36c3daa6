# The EGL back end (Mesa's, in CI: the surfaceless platform and the software device, both llvmpipe):
#   test_egl                device listing, surfaceless and device contexts, the AUTO order, bad
#                           input, and egl_same_pixels_as_osmesa_every_mode: the crypt through EGL
#                           and through OSMesa, 0 bytes of difference in every render mode
#   egl_<case>              the render-mode cases of test_modes run again with the fixture on EGL
#                           (THINLIGHT_TEST_CONTEXT=egl, tests/context_fixture.h)
if(NOT TARGET thinlight OR NOT THINLIGHT_WITH_EGL)
  return()
endif()

set(_tl_egl_env "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
set(TL_EGL_TEST_CASES
  context_backend_names_round_trip
  egl_devices_listed
  egl_context_surfaceless_core45
  egl_context_each_device
  egl_bad_input
  context_auto_order)
if(THINLIGHT_WITH_OSMESA)
  list(APPEND TL_EGL_TEST_CASES egl_same_pixels_as_osmesa_every_mode)
endif()
tl_add_test(test_egl
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_egl.c
  LIBS thinlight::thinlight
  CASES ${TL_EGL_TEST_CASES}
  LABELS "gl;egl"
  TIMEOUT 600)
set_tests_properties(${TL_EGL_TEST_CASES} PROPERTIES ENVIRONMENT "${_tl_egl_env}")
if(THINLIGHT_WITH_OSMESA)
  # Mesa's surfaceless platform would take a GPU's render node where there is one: the comparison
  # is only meaningful on the same rasteriser.
  set_tests_properties(egl_same_pixels_as_osmesa_every_mode PROPERTIES ENVIRONMENT
    "${_tl_egl_env};LIBGL_ALWAYS_SOFTWARE=1")
endif()

# test_modes (tests/modes.cmake, built with OSMesa) once more on EGL. add_test resolves the target
# name when the build system is generated, so the order of the tests/*.cmake files does not matter.
if(THINLIGHT_WITH_OSMESA)
  set(_tl_egl_modes_cases
    plan_allocations_match_renderer
    plan_saving_same_image
    modes_match_fat_default_scene
    modes_match_fat_many_lights
    modes_transparent_materials
    render_to_caller_framebuffer)
  foreach(c IN LISTS _tl_egl_modes_cases)
    add_test(NAME egl_${c} COMMAND test_modes ${c})
    set_tests_properties(egl_${c} PROPERTIES LABELS "gl;render;egl" TIMEOUT 900 ENVIRONMENT
      "${_tl_egl_env};THINLIGHT_TEST_CONTEXT=egl")
  endforeach()
endif()
