// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Benchmark of distance-matrix rows: K sources spread over the mesh, each solved alone (exact
// VTP), all rows or local rows within R mean edge lengths, dense (a distance per vertex) or
// sparse (the vertices reached), on T threads; against one full single-source VTP solve of the
// same mesh. Prints one key=value line.
// Usage: bench_matrix --mesh FILE --rows K [--radius R] [--threads T] [--sparse 1]

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
    else {
      std::cerr << "usage: bench_matrix --mesh FILE --rows K [--radius R] [--threads T] [--sparse 1]\n";
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
  const auto np = CGAL_ext::parameters::number_of_threads(threads).max_distance(radius);
  const auto start = Clock::now();
  if(sparse)
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
            << " sparse=" << sparse
            << " seconds_rows=" << seconds << " seconds_per_row=" << seconds / double(rows)
            << " entries_per_row=" << double(entries) / double(rows)
            << " seconds_full_solve=" << full.seconds_solve + full.seconds_setup
            << " full_solve_per_row=" << (full.seconds_solve + full.seconds_setup) / (seconds / double(rows)) << "\n";
  return 0;
}
