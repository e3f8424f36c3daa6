# The EGL back end (Mesa's, in CI: the surfaceless platform and the software device, both llvmpipe):
#   test_egl                device listing, surfaceless and device contexts, the AUTO order, bad
#                           input, and egl_same_pixels_as_osmesa_every_mode: the crypt through EGL
#                           and through OSMesa, 0 bytes of difference in every render mode
#   egl_<case>              the render-mode cases of test_modes run again with the fixture on EGL
#                           (THINLIGHT_TEST_CONTEXT=egl, tests/context_fixture.h)
if(NOT TARGET thinlight OR NOT THINLIGHT_WITH_EGL)
  return()
endif()

set(_tl_egl_env ${TL_GL_TEST_ENVIRONMENT})
# Mesa's surfaceless platform would take a GPU's render node where there is one: the pixel
# comparison with OSMesa is only meaningful on the same rasteriser (egl_same_pixels_as_osmesa_every_mode
# needs OSMesa and is skipped in C without it).
tl_add_test(test_egl
  SOURCES test_egl.c
  LIBS thinlight::thinlight
  LABELS gl egl
  TIMEOUT 600
  ENVIRONMENT ${_tl_egl_env} LIBGL_ALWAYS_SOFTWARE=1)
if(THINLIGHT_WITH_OSMESA)
  target_compile_definitions(test_egl PRIVATE TL_TEST_OSMESA)
endif()

# test_modes (built with OSMesa) once more on EGL. add_test resolves the target
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
    set(_tl_labels "gl;render;egl")
    if(c STREQUAL "modes_match_fat_many_lights") # 1,024 lights: the full tier (tests/README.md)
      list(APPEND _tl_labels full)
    endif()
    add_test(NAME egl_${c} COMMAND test_modes ${c})
    set_tests_properties(egl_${c} PROPERTIES LABELS "${_tl_labels}" TIMEOUT 900 ENVIRONMENT
      "${_tl_egl_env};THINLIGHT_TEST_CONTEXT=egl")
  endforeach()
endif()
