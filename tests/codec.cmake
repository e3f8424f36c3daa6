# Codec precision-loss suite (ctest -L codec): every bound is an assertion, golden values come
# from double-precision references and exhaustive sweeps. One executable per topic.
tl_add_test(test_oct SOURCES test_oct.c LABELS codec TIMEOUT 240
  CASES
    oct12_random_plain_error_bounds
    oct12_random_precise_error_bounds
    oct8_random_plain_max_error
    oct16_random_plain_max_error
    oct_plain_max_error_halves_per_bit
    oct_precise_picks_best_candidate_double_reference
    oct_plain_code_matches_double_projection
    oct_project_unproject_round_trip_unquantised
    oct8_exhaustive_decode_encode_idempotent
    oct10_exhaustive_decode_encode_idempotent
    oct12_exhaustive_decode_encode_idempotent
    oct9_oct11_exhaustive_decode_encode_idempotent
    oct_encode_n_matches_scalar_bit_exact
    oct_encode_precise_n_matches_scalar_bit_exact
    oct_decode_n_matches_scalar_bit_exact
    oct_batch_short_counts_and_lanes_match_scalar
    normal_encode_n_all_encodings_match_scalar
    normal_alt_encodings_extreme_inputs_finite
    normal_alt12_error_bounds_vs_grid_spacing
    oct12_precise_beats_alt_encodings_max_error)

tl_add_test(test_oct_extreme SOURCES test_oct_extreme.c LABELS codec TIMEOUT 120
  CASES
    oct_pole_positive_z_round_trip
    oct_pole_negative_z_decodes_to_negative_z
    oct12_negative_z_needs_sign_not_zero
    oct12_fold_edge_positive_zero
    oct12_fold_edge_negative_zero
    oct12_fold_one_ulp_off
    oct_square_edges_and_corners_round_trip
    oct_non_unit_lengths_same_code
    oct_zero_vector_encodes_as_positive_z
    oct_denormal_components_keep_direction
    oct_inf_components_give_their_direction
    oct_nan_components_give_positive_z
    oct_bits_out_of_range_clamped
    oct_extreme_inputs_never_nan_or_inf)

tl_add_test(test_oct_grid SOURCES test_oct_grid.c LABELS codec TIMEOUT 240
  CASES
    oct12_axis_normals_exact
    oct_axis_normals_exact_every_budget
    oct_zero_vector_decodes_exactly_positive_z
    oct_unused_code_decodes_as_top
    oct_odd_grid_vs_even_grid_error
    oct_even_grid_exhaustive_decode_encode_idempotent)

tl_add_test(test_half_gloss_rt0 SOURCES test_half_gloss_rt0.c LABELS codec TIMEOUT 120
  CASES
    half_all_65536_round_trip
    half_from_float_every_boundary_matches_reference
    half_from_float_random_matches_reference
    half_saturation_nan_inf_and_signed_zero
    gloss_power_endpoints_and_monotonic
    gloss_power_and_alpha_round_trips
    gloss_bad_inputs_clamp
    gloss8_exhaustive_encode_decode
    gloss10_exhaustive_encode_decode
    gloss_all_bits_1_to_16_exhaustive
    rt0_rgba8_matches_oct12_precise_and_gloss8
    rt0_rgba8_batch_matches_scalar
    rt0_rgba8_byte_layout
    rt0_rgb10a2_matches_oct10_precise_gloss10_flags
    rt0_rgb10a2_bit_layout
    rt0_extreme_inputs_finite)

tl_add_test(test_albedo
  SOURCES test_albedo.c ${PROJECT_SOURCE_DIR}/examples/common/test_images.c
  LABELS codec TIMEOUT 300
  CASES
    albedo_ycbcr8_all_srgb8_round_trip
    albedo_ycocg8_all_srgb8_round_trip
    albedo_black_white_primaries_round_trip
    albedo_checkerboard_parity
    albedo_encode_pixel_matches_double_reference
    chroma_psnr_ycbcr_edge_beats_bilinear_beats_nearest
    chroma_psnr_ycocg_edge_beats_bilinear_beats_nearest
    chroma_missing_chroma_matches_documented_rules_all_sizes
    chroma_reconstruct_1x1_neutral_chroma
    chroma_reconstruct_one_pixel_wide_images
    chroma_reconstruct_invalid_arguments
    chroma_hard_edge_no_bleeding
    chroma_single_pixel_line_keeps_luma)
target_include_directories(test_albedo PRIVATE ${PROJECT_SOURCE_DIR}/examples/common)

tl_add_test(test_depth SOURCES test_depth.c LABELS codec TIMEOUT 120
  CASES
    depth_reversed_d32f_relative_error_all_ratios
    depth_grazing_rays_wide_fov
    depth_positions_at_near_and_far_plane
    depth_special_windows_give_finite_positions
    depth_projection_rejects_bad_arguments
    depth_projection_matrix_matches_double
    depth_d24_exhaustive_code_round_trip
    depth_view_position_batch_matches_scalar)
