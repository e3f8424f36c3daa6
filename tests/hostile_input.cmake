# Hostile glTF and image input, no GL (docs/gltf.md, "Limits" and "External files"): the load's
# memory budget, JSON hostile in shape, counts past 32 bits (test_gltf_limits.c); what a file may
# read and how (test_gltf_files.c); image reading and decoding (test_image_io.c). Every input is
# generated at run time (gltf_hostile.c).
if(TARGET thinlight AND THINLIGHT_WITH_IO)
  add_library(tl_gltf_hostile STATIC ${CMAKE_CURRENT_LIST_DIR}/gltf_hostile.c)
  target_include_directories(tl_gltf_hostile PUBLIC ${CMAKE_CURRENT_LIST_DIR})
  target_link_libraries(tl_gltf_hostile PRIVATE thinlight_warnings PUBLIC thinlight::thinlight)

  tl_add_test(test_gltf_limits
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gltf_limits.c
    LIBS tl_gltf_hostile thinlight_io thinlight::thinlight m
    CASES
      gltf_budget_200_byte_file_asks_for_no_gigabytes
      gltf_budget_small_glb_png_headers_ask_for_nothing
      gltf_budget_counts_each_image_reference
      gltf_budget_objects_from_instancing
      gltf_budget_option_settable
      gltf_json_nested_100000_deep_anywhere
      gltf_json_nesting_at_the_limit_loads
      gltf_json_enormous_array_refused_before_parsing
      gltf_json_enormous_string_counted
      gltf_vertex_count_over_2_32
      gltf_counts_near_2_64_do_not_wrap
    LABELS gltf io limits)
endif()

if(TARGET thinlight AND THINLIGHT_WITH_IO)
  tl_add_test(test_gltf_files
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gltf_files.c
    LIBS tl_gltf_hostile tl_gltf_fixtures thinlight_io thinlight::thinlight m
    CASES
      gltf_files_inside_the_folder_load
      gltf_files_parent_folder_refused
      gltf_files_absolute_and_file_uris_refused
      gltf_files_symbolic_links_out_refused
      gltf_files_fifo_device_directory_refused_at_once
      gltf_files_callbacks_choose
      gltf_memory_load_equals_path_load
      gltf_memory_load_without_callbacks_reads_no_file
    LABELS gltf io files
    TIMEOUT 120)
  target_compile_definitions(test_gltf_files PRIVATE TL_GLTF_FILES_TEST_DIR="${CMAKE_CURRENT_BINARY_DIR}/gltf_files_work")

  tl_add_test(test_image_io
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_image_io.c
    LIBS tl_gltf_hostile thinlight_io thinlight::thinlight m
    CASES
      image_png_round_trip_every_channel_count
      image_jpeg_reads_within_its_error
      image_bad_files_one_line_each
      image_jpeg_header_checked_before_decoding
      image_bad_arguments
      image_write_failures_logged_and_leave_nothing
    LABELS io image
    TIMEOUT 120)
  target_compile_definitions(test_image_io PRIVATE TL_IMAGE_TEST_DIR="${CMAKE_CURRENT_BINARY_DIR}/image_work")
endif()
