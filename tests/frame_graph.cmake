# The frame as a graph (issue 10): steady-frame GL calls, the render_to state promise, application
# passes, shared memory, plan lifetimes, the statistics ring, resizing. On OSMesa.
if(TARGET thinlight AND TARGET thinlight_gl AND THINLIGHT_WITH_OSMESA)
  set(TL_FRAME_GRAPH_TEST_CASES
    frame_graph_steady_frame_gl_calls
    frame_graph_stats_ring_read_later
    frame_graph_render_to_state_promise
    frame_graph_app_pass_tints_hdr
    frame_graph_app_pass_bad_input
    frame_graph_shared_targets_readback
    frame_graph_plan_lifetimes_exhaustive
    frame_graph_pass_table
    frame_graph_resize_reallocates)
  tl_add_test(test_frame_graph
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_frame_graph.c
    LIBS thinlight::thinlight thinlight_gl
    CASES ${TL_FRAME_GRAPH_TEST_CASES}
    LABELS gl render
    TIMEOUT 600)
  set_tests_properties(${TL_FRAME_GRAPH_TEST_CASES} PROPERTIES ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
