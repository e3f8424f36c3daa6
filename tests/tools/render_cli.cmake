# thinlight-render's command-line contract (docs/tools.md): exit 0 with an image (bad input
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

# The component type of an EXR file's first channel: FLOAT, HALF or UINT (the "channels" attribute,
# a chlist: name, NUL, then the pixel type as a little-endian int32; OpenEXR's file layout).
function(exr_pixel_type file out)
  file(READ "${file}" hex HEX)
  string(FIND "${hex}" "6368616e6e656c730063686c69737400" at) # "channels\0chlist\0"
  if(at LESS 0)
    message(FATAL_ERROR "${file}: no channel list")
  endif()
  math(EXPR at "${at} + 32 + 8") # the names, then the attribute's size
  string(SUBSTRING "${hex}" ${at} 2 c)
  while(NOT c STREQUAL "00")
    math(EXPR at "${at} + 2")
    string(SUBSTRING "${hex}" ${at} 2 c)
  endwhile()
  math(EXPR at "${at} + 2")
  string(SUBSTRING "${hex}" ${at} 8 t)
  set(names 00000000 UINT 01000000 HALF 02000000 FLOAT)
  list(FIND names "${t}" i)
  math(EXPR i "${i} + 1")
  list(GET names ${i} name)
  set(${out} "${name}" PARENT_SCOPE)
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
  # targets the plan does not have are not files and not errors: only the "wrote" lines
  string(REGEX REPLACE "(thinlight-render: context [^\n]*|wrote [^\n]*)\n" "" rest "${err}")
  if(NOT rest STREQUAL "")
    message(FATAL_ERROR "--dump-targets printed more than what it wrote:\n${err}")
  endif()
  if(EXISTS "${WORK}/targets/rt1_albedo.exr" OR EXISTS "${WORK}/targets/fat_position.exr")
    message(FATAL_ERROR "--dump-targets wrote a target thin-lpp's plan does not have")
  endif()
  # each target at its own precision: depth, the decoded normals and 32-bit targets as floats
  run_tool(default --size 96x54 --lights 8 --mode fat --dump-targets "${WORK}/fat" --stats)
  expect_exit(0 "fat with --dump-targets")
  foreach(pair depth.exr:FLOAT rt0_normal_gloss.exr:FLOAT light_diffuse.exr:HALF hdr.exr:HALF
               output.exr:HALF)
    string(REPLACE ":" ";" pair "${pair}")
    list(GET pair 0 f)
    list(GET pair 1 want)
    exr_pixel_type("${WORK}/targets/${f}" got)
    if(NOT got STREQUAL want)
      message(FATAL_ERROR "targets/${f} holds ${got}, expected ${want}")
    endif()
  endforeach()
  foreach(pair fat_position.exr:FLOAT fat_normal.exr:HALF depth.exr:FLOAT)
    string(REPLACE ":" ";" pair "${pair}")
    list(GET pair 0 f)
    list(GET pair 1 want)
    exr_pixel_type("${WORK}/fat/${f}" got)
    if(NOT got STREQUAL want)
      message(FATAL_ERROR "fat/${f} holds ${got}, expected ${want}")
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
  if(NOT materials_plan MATCHES "transparent|stipple-blend")
    message(FATAL_ERROR "materials.glb (alpha BLEND) has no transparent or stipple pass:\n${materials_plan}")
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

# Shadows from a glTF file (docs/gltf.md, "Shadows"): a box floating over a floor under a spot light
# (make_gltf_scenes' shadow_spot cases). --shadows makes the spot cast (the image changes, --stats
# says one light has a map); without it nothing casts; the light's "thinlight_shadow" flag casts
# without --shadows (the same bytes as the rule's image) and false keeps it dark even with it; a
# value that is not a boolean is one warning naming the field and the value, and counts as absent.
function(check_gltf_shadows)
  execute_process(COMMAND ${MAKE_SCENES} "${WORK}" shadow_spot shadow_spot_cast shadow_spot_no_cast shadow_spot_bad_flag
                  RESULT_VARIABLE r)
  if(NOT r EQUAL 0)
    message(FATAL_ERROR "make_gltf_scenes failed")
  endif()
  # name|file|extra argument (- for none)
  set(runs "plain|shadow_spot|-" "rule|shadow_spot|--shadows" "cast|shadow_spot_cast|-"
           "no_cast|shadow_spot_no_cast|--shadows" "bad|shadow_spot_bad_flag|-")
  foreach(run IN LISTS runs)
    string(REPLACE "|" ";" run "${run}")
    list(GET run 0 name)
    list(GET run 1 file)
    list(GET run 2 extra)
    set(args "${WORK}/${file}.gltf" --size 96x54 --stats -o "${WORK}/${name}.png")
    if(NOT extra STREQUAL "-")
      list(APPEND args ${extra})
    endif()
    run_tool(${args})
    expect_exit(0 "${name}")
    file(SHA256 "${WORK}/${name}.png" sum_${name})
    set(out_${name} "${out}")
    set(err_${name} "${err}")
  endforeach()
  if(sum_plain STREQUAL sum_rule)
    message(FATAL_ERROR "--shadows changed nothing in a glTF file's image")
  endif()
  if(NOT out_rule MATCHES "shadows: 1 lights with a map" OR out_plain MATCHES "shadows:")
    message(FATAL_ERROR "--stats: --shadows should give one light a map, none without it:
${out_rule}
---
${out_plain}")
  endif()
  if(NOT sum_cast STREQUAL sum_rule)
    message(FATAL_ERROR "\"thinlight_shadow\": true without --shadows is not the image of the rule")
  endif()
  if(NOT sum_no_cast STREQUAL sum_plain OR NOT sum_bad STREQUAL sum_plain)
    message(FATAL_ERROR "\"thinlight_shadow\": false (with --shadows) or \"yes\" (without) cast a shadow")
  endif()
  if(NOT err_bad MATCHES "KHR_lights_punctual.lights\\[0\\].extras.thinlight_shadow = \"yes\": not true or false; ignored")
    message(FATAL_ERROR "no warning naming the bad flag:\n${err_bad}")
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
