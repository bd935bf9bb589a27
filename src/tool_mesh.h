// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The mesh of the geodesic tool: its types, and reading a file into a checked triangle mesh
// whose vertex and face ids are those of the file.

#ifndef GEODESIC_TOOL_MESH_H
#define GEODESIC_TOOL_MESH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace geodesic_tool {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Property_map<Vertex_index, double> Distance_map;
/// A point inside a face, barycentric coordinates in the library's order of its corners.
typedef std::pair<Face_index, std::array<double, 3>> Face_location;
typedef std::vector<std::vector<std::size_t>> Polygons;

/// The points and polygons of a mesh file, in the file's order.
struct Soup
{
  std::vector<Point> points;
  Polygons polygons;
};

/// Reads a .off, .obj or .ply file; throws Tool_error if it cannot be read or has no faces.
Soup read_soup(const std::string& path);

/// Throws Tool_error naming what keeps `soup` from being a manifold, oriented triangle mesh
/// with finite coordinates (the vertex, face or edge, by its id in the file).
void check_soup(const Soup& soup);

/// Vertex i of the mesh is point i of the soup and face j is polygon j (isolated points are kept).
Mesh soup_to_mesh(const Soup& soup);

/// The mesh of the file at `path`, checked; `soup` receives the file's points and polygons.
Mesh read_checked_mesh(const std::string& path, Soup& soup);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_MESH_H
