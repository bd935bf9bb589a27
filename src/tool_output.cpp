// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_output.h"

#include "tool_error.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace geodesic_tool {

namespace {

std::string temporary_path(const std::string& path) { return path + ".tmp" + std::to_string(::getpid()); }

/// Writes each file to a temporary file next to it, then renames them all: an error on any of
/// them leaves none of them written.
void write_files_atomically(const std::vector<Output_file>& files)
{
  try {
    for(const Output_file& f : files) {
      std::ofstream os(temporary_path(f.path), std::ios::binary);
      if(!os || !f.write(os) || !os.flush())
        throw Tool_error("cannot write '" + f.path + "'");
    }
    // a rename cannot be taken back: what would make one fail is checked before any is done
    for(const Output_file& f : files)
      if(std::filesystem::is_directory(f.path))
        throw Tool_error("cannot write '" + f.path + "'");
    for(const Output_file& f : files)
      if(std::rename(temporary_path(f.path).c_str(), f.path.c_str()) != 0)
        throw Tool_error("cannot write '" + f.path + "'");
  } catch(...) {
    for(const Output_file& f : files)
      std::remove(temporary_path(f.path).c_str());
    throw;
  }
}

} // namespace

std::string point_text(const Point& p)
{
  char text[96];
  std::snprintf(text, sizeof(text), "%.17g %.17g %.17g", p.x(), p.y(), p.z());
  return text;
}

void write_outputs(const std::vector<Output_file>& outputs)
{
  std::vector<Output_file> files;
  for(const Output_file& f : outputs)
    if(!f.path.empty())
      files.push_back(f);
  write_files_atomically(files);
  for(const Output_file& f : outputs)
    if(f.path.empty() && (!f.write(std::cout) || !std::cout.flush()))
      throw Tool_error("cannot write to the standard output");
}

void write_output(const std::string& path, const std::function<bool(std::ostream&)>& write)
{
  write_outputs({Output_file{path, write}});
}

// ---------------------------------------------------------------------------------------------
// Distances

bool write_distances_txt(std::ostream& os, const std::vector<double>& distances)
{
  char line[64];
  for(double d : distances) {
    std::snprintf(line, sizeof(line), "%.17g\n", d); // prints inf for +infinity
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

double farthest_finite(const std::vector<double>& distances)
{
  double farthest = 0;
  for(double d : distances)
    if(std::isfinite(d))
      farthest = std::max(farthest, d);
  return farthest;
}

namespace {

// CGAL writes PLY properties of a Surface_mesh only, which cannot hold every soup (non-manifold
// ones); the file's points and polygons are written here, in the machine's byte order, each
// point with `point_properties` (PLY property lines) that `write_point(i, binary)` writes.
template <class WritePoint>
bool write_soup_ply(std::ostream& os, const Soup& soup, const char* comment, const char* point_properties,
                    const WritePoint& write_point)
{
  const auto binary = [&](auto value) { os.write(reinterpret_cast<const char*>(&value), sizeof(value)); };
  const std::uint16_t one = 1;
  const bool little_endian = *reinterpret_cast<const unsigned char*>(&one) == 1;
  std::size_t largest_polygon = 0;
  for(const auto& polygon : soup.polygons)
    largest_polygon = std::max(largest_polygon, polygon.size());
  const bool small_polygons = largest_polygon <= 255;
  os << "ply\n"
     << "format " << (little_endian ? "binary_little_endian" : "binary_big_endian") << " 1.0\n"
     << "comment " << comment << "\n"
     << "element vertex " << soup.points.size() << "\n"
     << "property double x\nproperty double y\nproperty double z\n"
     << point_properties << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
     << "element face " << soup.polygons.size() << "\n"
     << "property list " << (small_polygons ? "uchar" : "int") << " int vertex_indices\n"
     << "end_header\n";
  for(std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    binary(p.x());
    binary(p.y());
    binary(p.z());
    const CGAL::IO::Color color = write_point(i, binary);
    binary(color.red());
    binary(color.green());
    binary(color.blue());
  }
  for(const auto& polygon : soup.polygons) {
    if(small_polygons)
      binary(static_cast<std::uint8_t>(polygon.size()));
    else
      binary(static_cast<std::int32_t>(polygon.size()));
    for(std::size_t id : polygon)
      binary(static_cast<std::int32_t>(id));
  }
  return bool(os);
}

} // namespace

bool write_distances_ply(std::ostream& os, const Soup& soup, const std::vector<double>& distances)
{
  const double farthest = farthest_finite(distances);
  return write_soup_ply(os, soup, "geodesic distances from the geodesic tool", "property double distance\n",
                        [&](std::size_t i, const auto& binary) {
                          binary(distances[i]);
                          return distance_color(distances[i], farthest);
                        });
}

// ---------------------------------------------------------------------------------------------
// Nearest-source labels

bool write_labels_txt(std::ostream& os, const std::vector<long>& labels)
{
  for(long label : labels)
    os << label << "\n";
  return bool(os);
}

CGAL::IO::Color label_color(long label)
{
  if(label < 0)
    return CGAL::IO::Color(128, 128, 128);
  // hues spread by the golden angle: neighbouring indices far apart on the colour wheel
  const double hue = std::fmod(double(label) * 0.618033988749895, 1.) * 6.;
  const double x = 1. - std::fabs(std::fmod(hue, 2.) - 1.);
  const int sector = int(hue);
  const double r[6] = {1, x, 0, 0, x, 1}, g[6] = {x, 1, 1, x, 0, 0}, b[6] = {0, 0, x, 1, 1, x};
  const auto level = [](double c) { return static_cast<unsigned char>(std::lround(40 + 200 * c)); };
  return CGAL::IO::Color(level(r[sector]), level(g[sector]), level(b[sector]));
}

bool write_labels_ply(std::ostream& os, const Soup& soup, const std::vector<double>& distances,
                      const std::vector<long>& labels)
{
  return write_soup_ply(os, soup, "nearest sources (geodesic Voronoi cells) from the geodesic tool",
                        "property double distance\nproperty int source\n", [&](std::size_t i, const auto& binary) {
                          binary(distances[i]);
                          binary(static_cast<std::int32_t>(labels[i]));
                          return label_color(labels[i]);
                        });
}

bool write_instances_ply(std::ostream& os, const Soup& soup, const std::vector<long>& instances)
{
  return write_soup_ply(os, soup, "repetitive pattern instances from the geodesic tool (-1: none)",
                        "property int instance\n", [&](std::size_t i, const auto& binary) {
                          binary(static_cast<std::int32_t>(instances[i]));
                          return label_color(instances[i]);
                        });
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
