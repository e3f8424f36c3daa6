# Outputs are never half-written (every tool writes a temporary file in the same folder, flushes
# it and renames it into place): thinlight-render killed with SIGKILL in the middle of an EXR
# dump leaves each output old or whole (test_outputs.c). Needs the tool and OSMesa.
if(TARGET thinlight-render AND TARGET tl_gltf_hostile)
  tl_add_test(test_outputs
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_outputs.c
    LIBS tl_gltf_hostile
    CASES outputs_killed_mid_exr_dump_leave_old_or_whole
    LABELS tools outputs
    TIMEOUT 900)
  target_compile_definitions(test_outputs PRIVATE TL_RENDER_TOOL="$<TARGET_FILE:thinlight-render>"
    TL_OUTPUTS_TEST_DIR="${CMAKE_CURRENT_BINARY_DIR}/outputs_work")
  add_dependencies(test_outputs thinlight-render)
  # Under THINLIGHT_SANITIZE the tool's Mesa leaks are suppressed (tests/lsan.supp: Mesa only).
  set_tests_properties(outputs_killed_mid_exr_dump_leave_old_or_whole PROPERTIES ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
