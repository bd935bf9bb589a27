// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Benchmark of distance-matrix rows: K sources spread over the mesh, each solved alone (exact
// VTP), all rows or local rows within R mean edge lengths, dense (a distance per vertex) or
// sparse (the vertices reached), on T threads; against one full single-source VTP solve of the
// same mesh. Prints one key=value line.
// With --one-call-per-row ALGORITHM (mmp, fwp-mmp or vtp), the rows are instead made the way a
// library without matrix functions makes them, as tvb-gdist's local_gdist_matrix does with its
// MMP: one sequential `geodesic_distances` call per source with the max distance, each with its
// own set-up and |V|-sized arrays (a stand-in for such tools, not a measurement of them).
// Usage: bench_matrix --mesh FILE --rows K [--radius R] [--threads T] [--sparse 1]
//                     [--one-call-per-row ALGORITHM]

#include <CGAL_ext/geodesic_distance_matrix.h>
#include <CGAL_ext/geodesic_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef std::chrono::steady_clock Clock;

static double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

int main(int argc, char** argv)
{
  std::string file;
  std::size_t rows = 16;
  double radius_edges = std::numeric_limits<double>::infinity();
  int threads = 1;
  bool sparse = false;
  std::string one_call_per_row; // empty: the matrix functions
  for(int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if(a == "--mesh")
      file = v;
    else if(a == "--rows")
      rows = std::size_t(std::stoul(v));
    else if(a == "--radius")
      radius_edges = std::stod(v);
    else if(a == "--threads")
      threads = std::stoi(v);
    else if(a == "--sparse")
      sparse = v == "1";
    else if(a == "--one-call-per-row" && (v == "mmp" || v == "fwp-mmp" || v == "vtp"))
      one_call_per_row = v;
    else {
      std::cerr << "usage: bench_matrix --mesh FILE --rows K [--radius R] [--threads T] [--sparse 1] "
                   "[--one-call-per-row mmp|fwp-mmp|vtp]\n";
      return 2;
    }
  }
  Mesh mesh;
  if(file.empty() || !CGAL::IO::read_polygon_mesh(file, mesh)) {
    std::cerr << "bench_matrix: cannot read '" << file << "'\n";
    return 1;
  }
  const std::size_t n = mesh.number_of_vertices();
  double length = 0;
  for(auto e : edges(mesh))
    length += std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
  const double mean_edge = length / double(mesh.number_of_edges());
  const double radius = radius_edges * mean_edge;

  // one full solve, the unit of comparison
  auto distance = mesh.add_property_map<vertex_descriptor, double>("v:d", 0.).first;
  CGAL_ext::Geodesic_statistics full;
  CGAL_ext::geodesic_distances(mesh, distance, vertex_descriptor(0), CGAL_ext::parameters::statistics(full));

  std::vector<vertex_descriptor> sources;
  for(std::size_t i = 0; i < rows; ++i)
    sources.push_back(vertex_descriptor(std::uint32_t(i * n / rows)));
  const tbb::global_control allowance(tbb::global_control::max_allowed_parallelism, std::size_t(std::max(threads, 1)));
  std::size_t entries = 0;
  double solve_seconds = 0; // --one-call-per-row: the solves alone, without each call's set-up
  const auto np = CGAL_ext::parameters::number_of_threads(threads).max_distance(radius);
  const auto start = Clock::now();
  if(!one_call_per_row.empty()) {
    const CGAL_ext::Geodesic_algorithm algorithm =
      one_call_per_row == "mmp" ? CGAL_ext::MMP : one_call_per_row == "fwp-mmp" ? CGAL_ext::FWP_MMP : CGAL_ext::VTP;
    for(vertex_descriptor s : sources) {
      CGAL_ext::Geodesic_statistics call;
      CGAL_ext::geodesic_distances(mesh, distance, s,
                                   CGAL_ext::parameters::algorithm(algorithm).max_distance(radius).statistics(call));
      solve_seconds += call.seconds_solve;
      for(vertex_descriptor v : vertices(mesh))
        entries += std::isfinite(distance[v]);
    }
  } else if(sparse)
    CGAL_ext::geodesic_sparse_distance_rows<CGAL::Parallel_tag>(
      mesh, sources, [&](std::size_t, const std::vector<std::pair<std::size_t, double>>& row) { entries += row.size(); },
      np);
  else
    CGAL_ext::geodesic_distance_rows<CGAL::Parallel_tag>(
      mesh, sources,
      [&](std::size_t, const std::vector<double>& row) {
        for(double d : row)
          entries += std::isfinite(d);
      },
      np);
  const double seconds = seconds_since(start);
  std::cout << "vertices=" << n << " rows=" << rows << " radius_edges=" << radius_edges << " threads=" << threads
            << " sparse=" << sparse << " one_call_per_row=" << (one_call_per_row.empty() ? "no" : one_call_per_row)
            << " seconds_rows=" << seconds << " seconds_per_row=" << seconds / double(rows)
            << " entries_per_row=" << double(entries) / double(rows)
            << (one_call_per_row.empty() ? std::string()
                                         : " solve_seconds_per_row=" + std::to_string(solve_seconds / double(rows)))
            << " seconds_full_solve=" << full.seconds_solve + full.seconds_setup
            << " full_solve_per_row=" << (full.seconds_solve + full.seconds_setup) / (seconds / double(rows)) << "\n";
  return 0;
}
