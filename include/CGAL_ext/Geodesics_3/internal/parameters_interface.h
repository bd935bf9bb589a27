// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The package's own named parameters, as an X-macro list (no include guard on purpose):
// each user defines CGAL_ext_add_named_parameter(tag_type, tag_value, function_name).
// `statistics` is not listed: it takes its argument by reference and is written by hand.
CGAL_ext_add_named_parameter(max_distance_t, max_distance, max_distance)
CGAL_ext_add_named_parameter(stop_vertices_t, stop_vertices, stop_vertices)
CGAL_ext_add_named_parameter(vertex_source_map_t, vertex_source_map, vertex_source_map)
CGAL_ext_add_named_parameter(vertex_distance_map_t, vertex_distance_map, vertex_distance_map)
CGAL_ext_add_named_parameter(first_sample_t, first_sample, first_sample)
CGAL_ext_add_named_parameter(covering_radius_t, covering_radius, covering_radius)
CGAL_ext_add_named_parameter(covering_radius_output_iterator_t, covering_radius_output_iterator, covering_radius_output_iterator)
CGAL_ext_add_named_parameter(approximation_t, approximation, approximation)
CGAL_ext_add_named_parameter(number_of_threads_t, number_of_threads, number_of_threads)
CGAL_ext_add_named_parameter(batch_size_t, batch_size, batch_size)
CGAL_ext_add_named_parameter(glued_vertices_t, glued_vertices, glued_vertices)
CGAL_ext_add_named_parameter(glued_vertices_output_t, glued_vertices_output, glued_vertices_output)
CGAL_ext_add_named_parameter(merge_duplicate_points_t, merge_duplicate_points, merge_duplicate_points)
