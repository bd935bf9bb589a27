// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_GEODESIC_STATISTICS_H
#define CGAL_EXT_GEODESICS_3_GEODESIC_STATISTICS_H

#include <cstddef>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// What a geodesic solver did, filled in when the caller passes `statistics(stats)` to
/// `geodesic_distances()`, `Surface_mesh_geodesic_paths::build()`, `geodesic_voronoi_diagram()`,
/// `farthest_point_sampling()` or the distance-matrix functions. Seconds are named
/// `seconds_<phase>`, counts by what they count.
struct Geodesic_statistics
{
  std::size_t vertices = 0;          ///< vertices of the mesh
  std::size_t faces = 0;             ///< faces of the mesh
  std::size_t windows_created = 0;   ///< windows that entered a window list
  std::size_t peak_windows = 0;      ///< largest number of windows alive at one time
  std::size_t peak_window_bytes = 0; ///< memory held by the window pool at its peak
  std::size_t vertices_popped = 0;   ///< vertices taken from the priority queue (with repeats)
  std::size_t lists_propagated = 0;  ///< window lists propagated across a triangle
  std::size_t wavefront_resets = 0;  ///< approximation only: times the wavefront was reset
  std::size_t windows_propagated = 0; ///< MMP family: windows taken from the queue and propagated
  std::size_t windows_deferred = 0;  ///< FWP-MMP and PMMP: windows taken whose distance had moved to a later bucket, queued again
  std::size_t windows_stored = 0;    ///< MMP family, and VTP's windows kept for paths: windows kept on the edges for queries after the build
  std::size_t stored_window_bytes = 0; ///< the same: memory of the kept windows and the edge lists
  std::size_t batched_runs_kept = 0;  ///< farthest-point sampling on two threads or more: samples whose run went at once with an earlier sample's and was kept
  std::size_t batched_runs_undone = 0; ///< the same, undone (the next sample was another vertex, or the runs met)
  double seconds_setup = 0;          ///< building the solver mesh and checking the input
  double seconds_solve = 0;          ///< the propagation alone
  // The phases of the batched solvers (parallel, or approximate): 0 for sequential exact VTP.
  double seconds_selection = 0;      ///< batched: taking vertices, resetting the wavefront; PMMP: taking windows
  double seconds_propagation = 0;    ///< batched: propagating the window lists (PMMP: the windows) of each batch, with the recording of their windows when they are kept (`Surface_mesh_geodesic_paths`, Voronoi diagrams)
  double seconds_merge = 0;          ///< batched: distance updates and list merges
  // The phases of PMMP (thesis figure 3.16, with seconds_selection and seconds_propagation);
  // sequential MMP and FWP-MMP clip each window as it is made and report seconds_solve only.
  double seconds_organization = 0;   ///< PMMP: filing the new windows by edge
  double seconds_clipping = 0;       ///< MMP family: clipping new windows against the stored ones
  double seconds_pushing = 0;        ///< PMMP: queue and vertex updates after clipping
  double seconds_diagram = 0;        ///< `geodesic_voronoi_diagram()`: cutting the faces and joining the bisectors, after the solve
};

/// \ingroup PkgGeodesics3Ref
/// The time of each step of `detect_repetitive_patterns()` and what it counted.
struct Pattern_statistics
{
  double seconds_sampling = 0;     ///< farthest-point sampling
  double seconds_signatures = 0;   ///< curvatures, signatures and the distances between samples
  double seconds_matching = 0;     ///< candidate matches
  double seconds_clustering = 0;   ///< spectral embedding and mean shift
  double seconds_optimization = 0; ///< refinement of correspondences and placement of centres
  double seconds_arrangement = 0;  ///< the Voronoi diagram of the centres
  std::size_t samples = 0;         ///< farthest-point samples of the mesh
  std::size_t patch_samples = 0;   ///< of them in the patch
  std::size_t matches = 0;         ///< candidate matches, summed over the searches
  std::size_t clusters = 0;        ///< candidate instances, summed over the searches
  std::size_t searches = 0;        ///< rounds of region growing
  std::size_t distance_rows = 0;   ///< local distance rows solved (one single-source run each)
  double patch_radius = 0;         ///< the largest distance from the patch's centre to its vertices
};

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_GEODESIC_STATISTICS_H
