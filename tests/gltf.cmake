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

  tl_add_test(test_gltf
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gltf.c
    LIBS tl_gltf_fixtures thinlight_io thinlight::thinlight m
    LABELS gltf io)
  # Each case writes into its own directory below this one, so cases may run in parallel.
  target_compile_definitions(test_gltf PRIVATE TL_GLTF_TEST_DIR="${CMAKE_CURRENT_BINARY_DIR}/gltf_work")
endif()
