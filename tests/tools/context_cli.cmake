# The tools' --context, --device and --list-devices (docs/tools.md: every renderer tool takes
# --context auto|osmesa|egl|glfw): bad values exit 2 with one line, the device list exits 0, an
# EGL run says on stderr which context it got; thinlight-codec-report makes no context and refuses
# the options. Included by tests/CMakeLists.txt it adds the tests; run with `cmake -P` it is the
# checker: -DTOOL=<tool> -DCHECK=<case> -DWORK=<scratch dir>.

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.25)
  include(${CMAKE_CURRENT_LIST_DIR}/../common/cli_checks.cmake)
  file(REMOVE_RECURSE "${WORK}")
  file(MAKE_DIRECTORY "${WORK}")
  get_filename_component(name "${TOOL}" NAME)
  # What the tool needs besides the options under test to do any work.
  if(name STREQUAL "thinlight-render")
    set(job default --size 64x36 --lights 4 -o "${WORK}/out.png")
  else()
    set(job --quick --modes thin-lpp --lights 8 --size 64x36 --frames 1 --warmup 0 --no-plot --json "${WORK}/b.json")
  endif()

  if(CHECK STREQUAL "bad_values")
    # pairs of (arguments joined by '|', what the case is): a ';' would split them apart
    set(cases
      "--context|bogus" "unknown back end"
      "--context|default" "default is no --context value"
      "--context|EGL" "names are lower case"
      "--context" "--context without a value"
      "--device|x" "a device that is not a number"
      "--device|-1" "a negative device"
      "--device|99" "a device EGL does not list"
      "--context|osmesa|--device|0" "--device with OSMesa")
    list(LENGTH cases n)
    math(EXPR last "${n} - 1")
    foreach(i RANGE 0 ${last} 2)
      math(EXPR j "${i} + 1")
      list(GET cases ${i} args)
      list(GET cases ${j} what)
      string(REPLACE "|" ";" args "${args}")
      run_tool(${job} ${args})
      if(NOT rc STREQUAL "2")
        message(FATAL_ERROR "${what}: exit status '${rc}', expected 2\n${err}")
      endif()
      string(REGEX MATCH "^[^\n]*" first "${err}")
      if(NOT first MATCHES "^${name}: .*(--context|--device|missing value)")
        message(FATAL_ERROR "${what}: the first line does not name the option:\n${err}")
      endif()
    endforeach()
    file(GLOB left "${WORK}/*")
    if(left)
      message(FATAL_ERROR "bad values left files behind: ${left}")
    endif()

  elseif(CHECK STREQUAL "list_devices")
    run_tool(--list-devices)
    expect_exit(0 "--list-devices")
    if(NOT out MATCHES "EGL devices: [1-9]" OR NOT out MATCHES "\n  0: " OR NOT out MATCHES "--context auto takes")
      message(FATAL_ERROR "--list-devices printed:\n${out}")
    endif()
    message(STATUS "${out}")

  elseif(CHECK STREQUAL "egl_run")
    # Mesa's surfaceless platform (llvmpipe in CI): the context line names back end, platform, GL.
    run_tool(${job} --context egl)
    expect_exit(0 "--context egl")
    if(NOT err MATCHES "${name}: context egl: EGL [^\n]*; GL_RENDERER [^\n]+; GL_VERSION [0-9]")
      message(FATAL_ERROR "no context line on stderr:\n${err}")
    endif()
    run_tool(${job} --device 0)
    expect_exit(0 "--device 0")
    if(NOT err MATCHES "context egl: EGL device 0")
      message(FATAL_ERROR "--device 0 did not use EGL device 0:\n${err}")
    endif()
    run_tool(${job} --context auto)
    expect_exit(0 "--context auto")
    string(REGEX MATCH "context [a-z]+: [^\n]*" line "${err}")
    message(STATUS "--context auto: ${line}")

  elseif(CHECK STREQUAL "codec_report_no_context")
    foreach(args "--context|egl" "--device|0" "--list-devices")
      string(REPLACE "|" ";" args "${args}")
      run_tool(--quick --no-plot ${args})
      expect_exit(2 "codec report ${args}")
      if(NOT err MATCHES "makes no GL context")
        message(FATAL_ERROR "codec report ${args}: ${err}")
      endif()
    endforeach()
    run_tool(--help)
    if(NOT out MATCHES "no GL context")
      message(FATAL_ERROR "the codec report's --help does not say it makes no GL context")
    endif()
  else()
    message(FATAL_ERROR "unknown CHECK '${CHECK}'")
  endif()
  return()
endif()

# tl_add_context_cli_test(<tool target> <check> <labels>)
function(tl_add_context_cli_test tool check labels)
  set(name ${tool}_${check})
  string(REPLACE "thinlight-" "" name "${name}")
  set(name context_cli_${name})
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:${tool}> -DCHECK=${check}
            -DWORK=${CMAKE_CURRENT_BINARY_DIR}/${name} -P ${CMAKE_CURRENT_FUNCTION_LIST_FILE})
  set_tests_properties(${name} PROPERTIES TIMEOUT 300 LABELS "${labels}" ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../common/lsan.supp:print_suppressions=0")
endfunction()

if(TARGET thinlight-codec-report)
  tl_add_context_cli_test(thinlight-codec-report codec_report_no_context tools)
endif()
if(THINLIGHT_WITH_EGL)
  foreach(tool thinlight-render thinlight-bench)
    if(TARGET ${tool})
      tl_add_context_cli_test(${tool} bad_values tools)
      tl_add_context_cli_test(${tool} list_devices "tools;egl")
      if(tool STREQUAL "thinlight-bench") # the bench's run on EGL: the full tier (render's stays)
        tl_add_context_cli_test(${tool} egl_run "tools;gl;egl;full")
      else()
        tl_add_context_cli_test(${tool} egl_run "tools;gl;egl")
      endif()
    endif()
  endforeach()
endif()
