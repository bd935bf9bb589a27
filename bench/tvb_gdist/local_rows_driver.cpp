// Copyright (c) 2026 The CGAL_ext geodesics developers.
//
// Times tvb-gdist's local_gdist_matrix, row by row, on a triangle mesh. Each row is made the way
// local_gdist_matrix makes it: the mesh and one GeodesicAlgorithmExact are built once; for each
// source, propagate from that one vertex with the max distance and no stop points, then ask
// best_source for every vertex of the mesh and keep the distances d with d != GEODESIC_INF,
// d != 0 and d <= max distance. Only K sources i*n/K are done, not all n.
//
// Not built by CMake: run.sh compiles it against a tvb-gdist source folder the user brings.
//
// Usage: local_rows_driver MESH [K=200] [R=10] [DUMP_PREFIX]
//   max distance = R * mean length of the mesh's edges. With DUMP_PREFIX, after the timed loop
//   the rows of the first, middle and last sources are computed again and written one distance
//   per vertex (inf outside the row) to DUMP_PREFIX<source>.txt.

#include "geodesic_algorithm_exact.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace {

// The mesh as a soup, read by CGAL (OFF, OBJ, PLY, STL...); triangles only.
bool read_mesh(const std::string& file, std::vector<double>& points, std::vector<unsigned>& faces)
{
  std::vector<CGAL::Simple_cartesian<double>::Point_3> positions;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(file, positions, polygons))
    return false;
  for(const auto& p : positions)
    points.insert(points.end(), {p.x(), p.y(), p.z()});
  for(const auto& polygon : polygons) {
    if(polygon.size() != 3)
      return false;
    for(std::size_t v : polygon)
      faces.push_back(unsigned(v));
  }
  return true;
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: local_rows_driver MESH.off [K=200] [R=10] [DUMP_PREFIX]\n";
    return 2;
  }
  const std::size_t k_rows = argc > 2 ? std::stoul(argv[2]) : 200;
  const double radius_edges = argc > 3 ? std::stod(argv[3]) : 10.;
  const std::string dump = argc > 4 ? argv[4] : "";

  std::vector<double> points;
  std::vector<unsigned> faces;
  if(!read_mesh(argv[1], points, faces)) {
    std::cerr << "local_rows_driver: cannot read '" << argv[1] << "'\n";
    return 1;
  }
  const std::size_t n = points.size() / 3;

  // set-up, done once by local_gdist_matrix as well: mesh, algorithm, the n target points
  auto t0 = Clock::now();
  geodesic::Mesh mesh;
  mesh.initialize_mesh_data(points, faces, false);
  geodesic::GeodesicAlgorithmExact algorithm(&mesh);
  std::vector<geodesic::SurfacePoint> targets, source;
  for(std::size_t v = 0; v < n; ++v)
    targets.push_back(geodesic::SurfacePoint(&mesh.vertices()[v]));
  const double seconds_mesh = seconds_since(t0);

  double length = 0;
  for(auto& e : mesh.edges())
    length += e.length();
  const double mean_edge = length / double(mesh.edges().size());
  const double max_distance = radius_edges * mean_edge;

  std::vector<unsigned> sources;
  for(std::size_t i = 0; i < k_rows; ++i)
    sources.push_back(unsigned(i * n / k_rows));

  // one row as local_gdist_matrix makes it; the kept entries are appended to rows/columns/data
  std::vector<unsigned> rows, columns;
  std::vector<double> data;
  auto make_row = [&](unsigned s) {
    source.push_back(geodesic::SurfacePoint(&mesh.vertices()[s]));
    algorithm.propagate(source, max_distance, NULL);
    source.pop_back();
    double distance = 0;
    for(std::size_t v = 0; v < n; ++v) {
      algorithm.best_source(targets[v], distance);
      if(distance != geodesic::GEODESIC_INF && distance != 0 && distance <= max_distance) {
        rows.push_back(s);
        columns.push_back(unsigned(v));
        data.push_back(distance);
      }
    }
  };

  t0 = Clock::now();
  for(unsigned s : sources)
    make_row(s);
  const double seconds_rows = seconds_since(t0);
  const double entries_per_row = double(data.size()) / double(k_rows);

  std::cout << std::setprecision(6) << "vertices=" << n << " rows=" << k_rows << " radius_edges=" << radius_edges
            << " mean_edge=" << mean_edge << " seconds_rows=" << seconds_rows
            << " seconds_per_row=" << seconds_rows / double(k_rows) << " entries_per_row=" << entries_per_row
            << " entries_per_row_with_source=" << entries_per_row + 1 << " seconds_mesh=" << seconds_mesh << "\n";

  if(!dump.empty() && !sources.empty()) {
    for(unsigned s : {sources.front(), sources[sources.size() / 2], sources.back()}) {
      rows.clear();
      columns.clear();
      data.clear();
      make_row(s);
      std::vector<double> row(n, std::numeric_limits<double>::infinity());
      row[s] = 0;
      for(std::size_t j = 0; j < data.size(); ++j)
        row[columns[j]] = data[j];
      std::ofstream out(dump + std::to_string(s) + ".txt");
      out << std::setprecision(17);
      for(double d : row)
        out << d << "\n";
    }
  }
  return 0;
}
