// SPDX-License-Identifier: GPL-3.0-or-later
// The package's own named parameters, as an X-macro list in the manner of CGAL's
// <CGAL/STL_Extension/internal/parameters_interface.h>: (tag type, tag value, function).
// Deliberately without an include guard: it is included several times with different
// definitions of FS_add_named_parameter.

// Principal curvatures (principal_curvatures.h)
FS_add_named_parameter(neighborhood_rings_t, neighborhood_rings, neighborhood_rings)
FS_add_named_parameter(neighborhood_radius_t, neighborhood_radius, neighborhood_radius)
FS_add_named_parameter(principal_curvature_map_t, principal_curvature_map, principal_curvature_map)
FS_add_named_parameter(concurrency_tag_t, concurrency_tag, concurrency_tag)

// Crest lines (crest_lines.h)
FS_add_named_parameter(strength_threshold_t, strength_threshold, strength_threshold)
FS_add_named_parameter(umbilic_ratio_t, umbilic_ratio, umbilic_ratio)
FS_add_named_parameter(detect_ridges_t, detect_ridges, detect_ridges)
FS_add_named_parameter(detect_valleys_t, detect_valleys, detect_valleys)

// Weights and segmentation
FS_add_named_parameter(edge_is_feature_t, edge_is_feature, edge_is_feature_map)
FS_add_named_parameter(edge_alpha_t, edge_alpha, edge_alpha_map)
FS_add_named_parameter(alpha_t, alpha, alpha)
FS_add_named_parameter(gamma_t, gamma, gamma)
FS_add_named_parameter(solver_t, solver, solver)
FS_add_named_parameter(feature_lines_t, feature_lines, feature_lines)
FS_add_named_parameter(crease_angle_t, crease_angle, crease_angle)
FS_add_named_parameter(crease_filter_iterations_t, crease_filter_iterations, crease_filter_iterations)
FS_add_named_parameter(tangent_discontinuities_t, tangent_discontinuities, tangent_discontinuities)
FS_add_named_parameter(crest_lines_on_clean_tessellations_t, crest_lines_on_clean_tessellations,
                       crest_lines_on_clean_tessellations)
FS_add_named_parameter(cut_cost_output_t, cut_cost_output, cut_cost_output)
FS_add_named_parameter(use_oversegmentation_t, use_oversegmentation, use_oversegmentation)
FS_add_named_parameter(watershed_distance_t, watershed_distance, watershed_distance)
FS_add_named_parameter(smoothing_iterations_t, smoothing_iterations, smoothing_iterations)
FS_add_named_parameter(smoothing_tolerance_t, smoothing_tolerance, smoothing_tolerance)
FS_add_named_parameter(snapping_ratio_t, snapping_ratio, snapping_ratio)
