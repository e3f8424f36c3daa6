tl_add_test(test_metrics SOURCES test_metrics.c
  CASES
    ciede2000_sharma_reference_pairs
    srgb_to_lab_white_black_primaries
    angle_deg_tiny_and_opposite
    image_compare_psnr_known
    image_compare_u8_known
    stats_mean_max_percentile
    stats_extreme_values)
