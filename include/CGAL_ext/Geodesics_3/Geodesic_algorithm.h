// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_GEODESIC_ALGORITHM_H
#define CGAL_EXT_GEODESICS_3_GEODESIC_ALGORITHM_H

/// \file Geodesic_algorithm.h
/// The solvers of the package, chosen with the named parameter `algorithm`, their defaults, and
/// the index that means "no source".

#include <cstddef>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// The solvers that `geodesic_distances()` and `Surface_mesh_geodesic_paths` can run, chosen
/// with the named parameter `algorithm`.
enum Geodesic_algorithm
{
  /// exact vertex-oriented triangle propagation (thesis chapter 4.1), the default of
  /// `geodesic_distances()`; with `CGAL::Parallel_tag`: PVTP
  VTP,
  /// exact window propagation with the windows kept on the edges, taken in exact order of
  /// distance from a binary heap (Mitchell, Mount and Papadimitriou; thesis chapter 3)
  MMP,
  /// MMP with the windows taken bucket by bucket (fast wavefront propagation), the default of
  /// `Surface_mesh_geodesic_paths`; with `CGAL::Parallel_tag`: PMMP
  FWP_MMP
};

/// \ingroup PkgGeodesics3Ref
/// The default of the named parameter `batch_size`: how many window lists the batched solvers
/// (parallel or approximate) propagate together at most.
constexpr std::size_t default_batch_size = 512;

/// \ingroup PkgGeodesics3Ref
/// The default of the named parameter `batch_size` for PMMP: how many windows are selected and
/// propagated together at most (the thesis's K; its running time stops changing beyond 1000).
constexpr std::size_t default_window_batch_size = 1024;

/// \ingroup PkgGeodesics3Ref
/// The nearest-source index of a vertex or point that no source reaches (as written to a
/// `vertex_source_map`, converted to its value type: -1 for a signed integer type).
constexpr std::size_t no_source = std::size_t(-1);

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_GEODESIC_ALGORITHM_H
