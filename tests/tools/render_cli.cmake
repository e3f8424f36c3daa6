# thinlight-render's command-line contract (DESIGN.md section 6): exit 0 with an image (bad input
# and bad usage: tests/input/render_cli_bad_input.cmake).
# The checker of the tests tests/tools/CMakeLists.txt adds (tl_add_cli_test), run as
#   cmake -DTOOL=<thinlight-render> -DCHECK=<writes_png|dump_targets|gltf_plans> -DWORK=<scratch dir> -P render_cli.cmake

cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../common/cli_checks.cmake)

function(check_writes_png)
  run_tool(default --size 160x90 --lights 8 -o "${WORK}/out.png")
  expect_exit(0 "render to png")
  file(GLOB files "${WORK}/*")
  if(NOT files STREQUAL "${WORK}/out.png")
    message(FATAL_ERROR "expected exactly out.png, found: ${files}")
  endif()
  file(READ "${WORK}/out.png" head LIMIT 8 HEX)
  if(NOT head STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "out.png is not a PNG (starts with ${head})")
  endif()
endfunction()

function(check_dump_targets)
  run_tool(default --size 96x54 --lights 8 -o "${WORK}/out.exr" --dump-targets "${WORK}/targets")
  expect_exit(0 "render with --dump-targets")
  foreach(t out.exr targets/depth.exr targets/rt0_normal_gloss.exr targets/light_diffuse.exr
            targets/light_specular.exr targets/hdr.exr targets/ldr.exr targets/output.exr)
    if(NOT EXISTS "${WORK}/${t}")
      message(FATAL_ERROR "missing ${t}")
    endif()
  endforeach()
endfunction()

function(check_gltf_plans)
  # glTF scenes render, and --print-plan shows a different plan for each
  execute_process(COMMAND ${MAKE_SCENES} "${WORK}/scenes" RESULT_VARIABLE r)
  if(NOT r EQUAL 0)
    message(FATAL_ERROR "make_gltf_scenes failed")
  endif()
  set(plans "")
  foreach(f textured_boxes.gltf materials.glb lights.gltf)
    execute_process(COMMAND ${TOOL} "${WORK}/scenes/${f}" --size 96x54 -o "${WORK}/${f}.png" --print-plan
                    RESULT_VARIABLE r OUTPUT_VARIABLE plan ERROR_VARIABLE err)
    if(NOT r EQUAL 0 OR NOT EXISTS "${WORK}/${f}.png")
      message(FATAL_ERROR "rendering ${f}: exit ${r}\n${err}")
    endif()
    string(REGEX REPLACE "scene: [^\n]*" "" plan "${plan}")
    string(REPLACE ";" "," plan "${plan}") # a CMake list separator otherwise
    if(plan IN_LIST plans)
      message(FATAL_ERROR "${f} has the same plan as another scene:\n${plan}")
    endif()
    list(APPEND plans "${plan}")
  endforeach()
  list(GET plans 1 materials_plan)
  if(NOT materials_plan MATCHES "transparent")
    message(FATAL_ERROR "materials.glb (alpha BLEND) has no transparent pass:\n${materials_plan}")
  endif()
  # glTF materials are lit with GGX, the crypt with Blinn-Phong; --lighting forces either
  foreach(plan IN LISTS plans)
    if(NOT plan MATCHES "lighting: ggx \\(auto")
      message(FATAL_ERROR "a glTF scene is not planned with GGX:\n${plan}")
    endif()
  endforeach()
  execute_process(COMMAND ${TOOL} default --size 96x54 --lights 8 --print-plan RESULT_VARIABLE r OUTPUT_VARIABLE plan)
  if(NOT r EQUAL 0 OR NOT plan MATCHES "lighting: blinn-phong \\(auto")
    message(FATAL_ERROR "the crypt is not planned with Blinn-Phong (exit ${r}):\n${plan}")
  endif()
  execute_process(COMMAND ${TOOL} default --size 96x54 --lights 8 --print-plan --lighting ggx --fresnel nv
                  RESULT_VARIABLE r OUTPUT_VARIABLE plan)
  if(NOT r EQUAL 0 OR NOT plan MATCHES "lighting: ggx \\(forced" OR NOT plan MATCHES "TL_GGX TL_FRESNEL_NV")
    message(FATAL_ERROR "--lighting ggx --fresnel nv is not in the plan (exit ${r}):\n${plan}")
  endif()
endfunction()

# The effects (docs/effects.md): on, they render and dump their targets; a bad value is one line
# and exit 2, with no output written.
function(check_effects)
  run_tool(default --size 96x54 --lights 8 --ssao --ssao-method hemisphere --fog --fog-mode height --fog-noise 0.5
           --dof --bloom --bloom-threshold 0 --bloom-levels 3 -o "${WORK}/out.png" --dump-targets "${WORK}/targets")
  expect_exit(0 "render with every effect")
  foreach(t out.png targets/ao.exr targets/ao_raw.exr targets/dof.exr targets/bloom.exr)
    if(NOT EXISTS "${WORK}/${t}")
      message(FATAL_ERROR "missing ${t}")
    endif()
  endforeach()
  foreach(bad "--ssao-samples;0" "--ssao-method;foo" "--fog-color;1,2" "--dof-aperture;2" "--ssao-radius;nan"
          "--bloom-levels;9" "--bloom-threshold;-1" "--bloom-knee;2" "--bloom-scatter;0" "--bloom-intensity;inf")
    run_tool(default --size 32x18 ${bad} -o "${WORK}/bad.png")
    expect_exit(2 "bad effect value ${bad}")
    if(EXISTS "${WORK}/bad.png")
      message(FATAL_ERROR "${bad}: an output was written")
    endif()
  endforeach()
endfunction()

cli_run_check()
