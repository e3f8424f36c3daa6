# glTF loading (tl_scene_load_gltf, no GL): good scenes checked against hand-computed values, bad
# input (one test per case), allocator failure at every allocation, fuzzed files. gltf_fixtures.c
# writes every file at run time into the build tree; nothing binary is committed.
if(TARGET thinlight AND THINLIGHT_WITH_IO)
  # The fixture generator, for other tests too: tl_test_write_gltf_scenes(dir) writes the three
  # test scenes (textured_boxes.gltf, materials.glb, lights.gltf); gltf_fixtures.h.
  add_library(tl_gltf_fixtures STATIC ${CMAKE_CURRENT_LIST_DIR}/gltf_fixtures.c)
  target_include_directories(tl_gltf_fixtures PUBLIC ${CMAKE_CURRENT_LIST_DIR})
  target_link_libraries(tl_gltf_fixtures PRIVATE thinlight_warnings PUBLIC thinlight_io thinlight::thinlight)

  # make_gltf_scenes DIR: the same scenes from the command line (docs, manual renders).
  add_executable(make_gltf_scenes ${CMAKE_CURRENT_LIST_DIR}/gltf_fixtures.c)
  target_compile_definitions(make_gltf_scenes PRIVATE TLF_MAIN)
  target_link_libraries(make_gltf_scenes PRIVATE thinlight_warnings thinlight_io thinlight::thinlight)

  set(TL_GLTF_TEST_CASES
    gltf_textured_boxes_hierarchy
    gltf_textured_boxes_materials_textures
    gltf_materials_conversion
    gltf_lights_punctual
    gltf_index_sizes
    gltf_normalized_uvs
    gltf_glb_and_data_uri_equal_gltf
    gltf_generated_normals_tangents
    gltf_default_light_rig
    gltf_extra_lights_deterministic
    gltf_camera_from_file
    gltf_multiple_scenes
    gltf_mirrored_instance_winding
    gltf_test_scenes_written
    gltf_allocator_counting
    gltf_malformed_json
    gltf_wrong_types
    gltf_missing_bin
    gltf_missing_file
    gltf_missing_image
    gltf_bufferview_out_of_range
    gltf_accessor_past_buffer_view
    gltf_buffer_view_past_buffer
    gltf_accessor_reference_out_of_range
    gltf_mesh_reference_out_of_range
    gltf_vertex_index_out_of_range
    gltf_node_cycle
    gltf_node_self_child
    gltf_node_two_parents
    gltf_node_child_out_of_range
    gltf_nan_position
    gltf_inf_position
    gltf_zero_length_normals
    gltf_texture_unsupported_format
    gltf_texture_jpeg
    gltf_texture_truncated_png
    gltf_texture_absurd_size
    gltf_texture_pixel_limit_option
    gltf_triangle_limit
    gltf_accessor_without_buffer_view
    gltf_empty_scene
    gltf_truncated_glb
    gltf_required_extension_unsupported
    gltf_sparse_accessor_unsupported
    gltf_non_triangle_mode_skipped
    gltf_bad_arguments
    gltf_error_message_one_line
    gltf_fuzz_mutations)
  tl_add_test(test_gltf
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gltf.c
    LIBS tl_gltf_fixtures thinlight_io thinlight::thinlight m
    CASES ${TL_GLTF_TEST_CASES}
    LABELS gltf io)
  # Each case writes into its own directory below this one, so cases may run in parallel.
  target_compile_definitions(test_gltf PRIVATE TL_GLTF_TEST_DIR="${CMAKE_CURRENT_BINARY_DIR}/gltf_work")
endif()
