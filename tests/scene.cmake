# The built-in scene (pure C, no GL): built from the scene's object library, so it runs with or
# without a GL stack.
if(TARGET thinlight_scene)
  tl_add_test(test_scene
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_scene.c $<TARGET_OBJECTS:thinlight_scene>
    LIBS m
    CASES
      scene_default_counts
      scene_default_detail_levels
      scene_default_deterministic
      scene_default_geometry_valid
      scene_default_convex_props_outward
      scene_default_objects_reachable
      scene_default_lights_inside
      scene_light_count_limit
      scene_allocator_honoured
      scene_bad_arguments
      scene_features
      scene_materials_textures_valid
      scene_camera_inside
    LABELS scene)
endif()
