# Codec precision-loss suite (ctest -L codec): every bound is an assertion, golden values come
# from double-precision references and exhaustive sweeps. One executable per topic.
tl_add_test(test_oct SOURCES test_oct.c LABELS codec TIMEOUT 240)

tl_add_test(test_oct_extreme SOURCES test_oct_extreme.c LABELS codec TIMEOUT 120)

tl_add_test(test_half_gloss_rt0 SOURCES test_half_gloss_rt0.c LABELS codec TIMEOUT 120)

tl_add_test(test_albedo
  SOURCES test_albedo.c ${PROJECT_SOURCE_DIR}/examples/common/test_images.c
  LABELS codec TIMEOUT 300)
target_include_directories(test_albedo PRIVATE ${PROJECT_SOURCE_DIR}/examples/common)

tl_add_test(test_depth SOURCES test_depth.c LABELS codec TIMEOUT 120)
