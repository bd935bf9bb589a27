// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESIC_DISTANCE_MATRIX_H
#define CGAL_EXT_GEODESIC_DISTANCE_MATRIX_H

/// \file geodesic_distance_matrix.h
/// Exact geodesic distances from each of several sources to every vertex: one row per source,
/// the sources solved in parallel.

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/Distance_rows.h>

#include <CGAL/tags.h>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// computes, for each of `sources` in turn, the exact geodesic distance from it alone to every
/// vertex of `tm` (a row of the distance matrix), and hands the row to `row`. With
/// `CGAL::Parallel_tag` the sources are solved in parallel on TBB threads, one sequential VTP
/// solve each on one mesh cache built once; the rows are the same for every number of threads,
/// and `row` is always called from the calling thread, in the order of `sources`. At most a few
/// rows per thread are held at once, so a matrix larger than memory can be streamed to a file.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam Sources a range of sources, each a vertex or a face location (as for `geodesic_distances()`)
/// \tparam RowFunction callable as `row(std::size_t i, const std::vector<double>& distances)`
///
/// \param tm the triangle mesh
/// \param sources the sources, one row each
/// \param row receives source `i`'s row: `distances[j]` is the distance to the vertex of index
///        `j` (the `vertex_index_map`), `+infinity` where unreached or beyond `max_distance`;
///        the vector is reused after the call returns
/// \param np optional named parameters: `max_distance` (the rows of a local, sparse matrix),
///        `approximation`, `number_of_threads`, `glued_vertices`, and CGAL's `vertex_point_map`,
///        `vertex_index_map` and `face_index_map`, as for `geodesic_distances()`
///
/// \throws Geodesic_error for what `geodesic_distances()` throws, when there is no source, or
///         when `algorithm` is not `CGAL_ext::VTP`
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class Sources, class RowFunction,
          class NamedParameters = parameters::Default_named_parameters_type>
void geodesic_distance_rows(const TriangleMesh& tm, const Sources& sources, RowFunction row,
                            const NamedParameters& np = parameters::default_values())
{
  Geodesics_3::internal::distance_rows<Geodesics_3::internal::is_parallel_tag<ConcurrencyTag>()>(tm, sources, row, np);
}

/// \ingroup PkgGeodesics3Ref
/// the dense distance matrix from `sources` to every vertex of `tm`, row-major: entry
/// `i * num_vertices(tm) + j` is the distance from source `i` to the vertex of index `j`.
/// The same as collecting the rows of `geodesic_distance_rows()`, with the same parameters.
///
/// \tparam ConcurrencyTag, TriangleMesh, Sources as for `geodesic_distance_rows()`
/// \param tm the triangle mesh
/// \param sources the sources, one row each
/// \param np optional named parameters, as for `geodesic_distance_rows()`
/// \return the `sources.size()` x `num_vertices(tm)` matrix, row-major
/// \throws Geodesic_error as `geodesic_distance_rows()`
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class Sources,
          class NamedParameters = parameters::Default_named_parameters_type>
std::vector<double> geodesic_distance_matrix(const TriangleMesh& tm, const Sources& sources,
                                             const NamedParameters& np = parameters::default_values())
{
  std::vector<double> matrix;
  geodesic_distance_rows<ConcurrencyTag>(
    tm, sources, [&](std::size_t, const std::vector<double>& row) { matrix.insert(matrix.end(), row.begin(), row.end()); },
    np);
  return matrix;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESIC_DISTANCE_MATRIX_H
