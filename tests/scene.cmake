# The built-in scene (pure C, no GL): built from the scene's object library, so it runs with or
# without a GL stack.
if(TARGET thinlight_scene)
  tl_add_test(test_scene
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_scene.c $<TARGET_OBJECTS:thinlight_scene>
    LIBS m
    LABELS scene)
endif()
