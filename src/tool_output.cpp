// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_output.h"

#include "tool_error.h"

#include <CGAL/IO/PLY.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace geodesic_tool {

namespace {

void write_atomically(const std::string& path, const std::function<bool(std::ostream&)>& write)
{
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  try {
    std::ofstream os(temporary, std::ios::binary);
    if(!os || !write(os) || !os.flush())
      throw Tool_error("cannot write '" + path + "'");
    os.close();
    if(std::rename(temporary.c_str(), path.c_str()) != 0)
      throw Tool_error("cannot write '" + path + "'");
  } catch(...) {
    std::remove(temporary.c_str());
    throw;
  }
}

/// One point of a polyline, full precision.
std::string point_text(const Point& p)
{
  char text[96];
  std::snprintf(text, sizeof(text), "%.17g %.17g %.17g", p.x(), p.y(), p.z());
  return text;
}

} // namespace

void write_output(const std::string& path, const std::function<bool(std::ostream&)>& write)
{
  if(path.empty()) {
    if(!write(std::cout) || !std::cout.flush())
      throw Tool_error("cannot write to the standard output");
  } else {
    write_atomically(path, write);
  }
}

// ---------------------------------------------------------------------------------------------
// Distances

bool write_distances_txt(std::ostream& os, const Mesh& mesh, Distance_map distance)
{
  char line[64];
  for(Vertex_index v : mesh.vertices()) {
    std::snprintf(line, sizeof(line), "%.17g\n", distance[v]); // prints inf for +infinity
    os << line;
  }
  return bool(os);
}

CGAL::IO::Color distance_color(double d, double farthest)
{
  if(!std::isfinite(d))
    return CGAL::IO::Color(128, 128, 128);
  const double t = farthest > 0 ? d / farthest : 0.;
  const auto level = [](double x) { return static_cast<unsigned char>(std::lround(255 * x)); };
  return CGAL::IO::Color(level(t), 0, level(1 - t)); // blue near, red far
}

double farthest_finite(const Mesh& mesh, Distance_map distance)
{
  double farthest = 0;
  for(Vertex_index v : mesh.vertices())
    if(std::isfinite(distance[v]))
      farthest = std::max(farthest, distance[v]);
  return farthest;
}

bool write_distances_ply(std::ostream& os, Mesh& mesh, Distance_map distance)
{
  const double farthest = farthest_finite(mesh, distance);
  auto color = mesh.add_property_map<Vertex_index, CGAL::IO::Color>("v:color").first;
  for(Vertex_index v : mesh.vertices())
    color[v] = distance_color(distance[v], farthest);
  CGAL::IO::set_mode(os, CGAL::IO::BINARY);
  return CGAL::IO::write_PLY(os, mesh, "geodesic distances from the geodesic tool");
}

// ---------------------------------------------------------------------------------------------
// Paths

bool write_path_txt(std::ostream& os, const std::vector<Point>& points)
{
  for(const Point& p : points)
    os << point_text(p) << "\n";
  return bool(os);
}

bool write_path_obj(std::ostream& os, const std::vector<Point>& points)
{
  os << "# geodesic path from the geodesic tool, from the source to the target\n";
  for(const Point& p : points)
    os << "v " << point_text(p) << "\n";
  if(points.size() >= 2) {
    os << "l";
    for(std::size_t i = 1; i <= points.size(); ++i)
      os << " " << i;
    os << "\n";
  }
  return bool(os);
}

bool write_path_ply(std::ostream& os, const std::vector<Point>& points)
{
  const std::size_t edges = points.empty() ? 0 : points.size() - 1;
  os << "ply\n"
     << "format ascii 1.0\n"
     << "comment geodesic path from the geodesic tool, from the source to the target\n"
     << "element vertex " << points.size() << "\n"
     << "property double x\n"
     << "property double y\n"
     << "property double z\n"
     << "element edge " << edges << "\n"
     << "property int vertex1\n"
     << "property int vertex2\n"
     << "end_header\n";
  for(const Point& p : points)
    os << point_text(p) << "\n";
  for(std::size_t i = 0; i < edges; ++i)
    os << i << " " << i + 1 << "\n";
  return bool(os);
}

} // namespace geodesic_tool
