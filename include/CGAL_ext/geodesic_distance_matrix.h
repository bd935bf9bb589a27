// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESIC_DISTANCE_MATRIX_H
#define CGAL_EXT_GEODESIC_DISTANCE_MATRIX_H

/// \file geodesic_distance_matrix.h
/// Exact geodesic distances from each of several sources to every vertex: one row per source,
/// dense or sparse (the vertices within a radius), the sources solved in parallel.

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/distance_rows/Distance_rows.h>

#include <CGAL/tags.h>

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// computes, for each of `sources` in turn, the exact geodesic distance from it alone to every
/// vertex of `tm` (a row of the distance matrix), and hands the row to `row`. With
/// `CGAL::Parallel_tag` the sources are solved in parallel on TBB threads, one sequential VTP
/// solve each on one solver mesh built once; the rows are the same for every number of threads,
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
///        `approximation`, `number_of_threads`, `glued_vertices`, `callback` (told the fraction
///        of the rows done before each batch of rows; `false` stops), `statistics` (a
///        `Geodesic_statistics&`: the rows' windows and seconds of solve summed, the largest peak of
///        one row), and CGAL's `vertex_point_map`, `vertex_index_map` and `face_index_map`, as for
///        `geodesic_distances()`
///
/// \throws Geodesic_error for what `geodesic_distances()` throws, when there is no source, or
///         when `algorithm` is not `CGAL_ext::VTP`; `Geodesic_cancelled` when the `callback`
///         returned `false` (the rows handed over until then stay handed over)
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

/// \ingroup PkgGeodesics3Ref
/// computes, for each of `sources` in turn, the vertices within `max_distance` of it alone and
/// their exact geodesic distances (a sparse row of the distance matrix), and hands the row to
/// `row`, as `geodesic_distance_rows()` does (in parallel across sources with
/// `CGAL::Parallel_tag`, the rows in order, from the calling thread). A row costs what its
/// propagation sweeps, not the size of the mesh: each thread keeps one solver and resets only
/// what the last row wrote. This is the local distance matrix (every vertex to the vertices
/// within a radius) without any dense row in memory.
///
/// \tparam ConcurrencyTag, TriangleMesh, Sources as for `geodesic_distance_rows()`
/// \tparam SparseRowFunction callable as `row(std::size_t i, const std::vector<std::pair<std::size_t, double>>& entries)`
///
/// \param tm the triangle mesh
/// \param sources the sources, one row each
/// \param row receives source `i`'s row: the pairs (vertex index, distance) of the vertices
///        reached within `max_distance`, by increasing vertex index (the `vertex_index_map`);
///        the vector is reused after the call returns
/// \param np optional named parameters, as for `geodesic_distance_rows()`; without `max_distance`
///        every reachable vertex is in every row
/// \throws Geodesic_error as `geodesic_distance_rows()`
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class Sources, class SparseRowFunction,
          class NamedParameters = parameters::Default_named_parameters_type>
void geodesic_sparse_distance_rows(const TriangleMesh& tm, const Sources& sources, SparseRowFunction row,
                                   const NamedParameters& np = parameters::default_values())
{
  Geodesics_3::internal::sparse_distance_rows<Geodesics_3::internal::is_parallel_tag<ConcurrencyTag>()>(tm, sources,
                                                                                                       row, np);
}

/// \ingroup PkgGeodesics3Ref
/// A sparse matrix in compressed sparse row (CSR) form, as SciPy's `csr_matrix((value, column,
/// row_begin), shape=(rows, columns))` and Eigen's `Map<SparseMatrix<double, RowMajor>>` take it.
struct Geodesic_sparse_matrix
{
  std::size_t rows = 0;    ///< one per source
  std::size_t columns = 0; ///< one per vertex
  std::vector<std::size_t> row_begin; ///< `rows + 1` offsets: row `i` is entries `[row_begin[i], row_begin[i+1])`
  std::vector<std::size_t> column;    ///< the vertex index of each entry, increasing within a row
  std::vector<double> value;          ///< the distance of each entry
};

/// \ingroup PkgGeodesics3Ref
/// the local distance matrix from `sources` to the vertices within `max_distance` of each, in
/// CSR form: the rows of `geodesic_sparse_distance_rows()`, collected. Its memory is what the
/// entries need.
///
/// \tparam ConcurrencyTag, TriangleMesh, Sources as for `geodesic_distance_rows()`
/// \param tm the triangle mesh
/// \param sources the sources, one row each
/// \param np optional named parameters, as for `geodesic_distance_rows()` (`max_distance`, above all)
/// \return the `sources.size()` x `num_vertices(tm)` matrix
/// \throws Geodesic_error as `geodesic_distance_rows()`
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class Sources,
          class NamedParameters = parameters::Default_named_parameters_type>
Geodesic_sparse_matrix geodesic_sparse_distance_matrix(const TriangleMesh& tm, const Sources& sources,
                                                       const NamedParameters& np = parameters::default_values())
{
  Geodesic_sparse_matrix matrix;
  matrix.columns = num_vertices(tm);
  matrix.row_begin.push_back(0);
  geodesic_sparse_distance_rows<ConcurrencyTag>(
    tm, sources,
    [&](std::size_t, const std::vector<std::pair<std::size_t, double>>& entries) {
      for(const auto& e : entries) {
        matrix.column.push_back(e.first);
        matrix.value.push_back(e.second);
      }
      matrix.row_begin.push_back(matrix.column.size());
    },
    np);
  matrix.rows = matrix.row_begin.size() - 1;
  return matrix;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESIC_DISTANCE_MATRIX_H
