// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The mesh of the geodesic tool: its types, and reading a file (OFF, OBJ, PLY, STL) into the
// triangle mesh the library takes, keeping the file's points and polygons, which the tool's ids
// and outputs refer to.

#ifndef GEODESIC_TOOL_MESH_H
#define GEODESIC_TOOL_MESH_H

#include "tool_index_iterator.h"
#include "tool_polygons.h"

#include <CGAL_ext/Geodesics_3/Geodesic_mesh_repairs.h>

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
/// A point inside a face, barycentric coordinates in the library's order of its corners.
typedef std::pair<Face_index, std::array<double, 3>> Face_location;
typedef Polygon_list Polygons;

/// The points and polygons of a mesh file, in the file's order.
struct Soup
{
  std::vector<Point> points;
  Polygons polygons;
  std::size_t points_merged_when_read = 0; // STL: the repeats of points among its triangles' corners
};

/// Reads a .off, .obj, .ply or .stl file; throws Tool_error if it cannot be read. The points of
/// an STL file, which repeats them in every triangle, are each distinct point once, in the order
/// of its first appearance (CGAL's reader merges them).
Soup read_soup(const std::string& path);

/// The index in the mesh of each point (or polygon) of the file: a vector, or nothing at all when
/// each id is its own index, as in a clean file (4 bytes a point and 8 a triangle less).
template <class Index>
class File_to_mesh
{
public:
  typedef Index_iterator<File_to_mesh, Index> const_iterator;

  File_to_mesh() = default;
  explicit File_to_mesh(std::vector<Index> indices) : m_size(indices.size())
  {
    for(std::size_t i = 0; i < m_size; ++i)
      if(indices[i] != Index(typename Index::size_type(i))) {
        m_indices = std::move(indices);
        return;
      }
  }

  std::size_t size() const { return m_size; }
  bool is_identity() const { return m_indices.empty(); }
  Index operator[](std::size_t i) const
  {
    return m_indices.empty() ? Index(typename Index::size_type(i)) : m_indices[i];
  }
  const_iterator begin() const { return const_iterator(this, 0); }
  const_iterator end() const { return const_iterator(this, m_size); }

private:
  std::size_t m_size = 0;
  std::vector<Index> m_indices; // empty when index i is i
};

/// A mesh file as the tool uses it: the file's points and polygons, which the ids of the command
/// line and the outputs refer to, and the triangle mesh the library runs on.
struct Mesh_file
{
  Soup soup;
  Mesh mesh;
  File_to_mesh<Vertex_index> vertex_of_point; // per point of the file
  File_to_mesh<Face_index> face_of_polygon;   // per polygon of the file; null unless a triangle kept as is
  CGAL_ext::Geodesic_mesh_repairs repairs;
  std::vector<std::vector<Vertex_index>> glued_vertices; // the vertices of each point duplicated by the repair
};

/// The mesh of the soup, through CGAL_ext::polygon_soup_to_geodesic_mesh() (which throws
/// Geodesic_error for what it cannot repair); the points merged when reading count as merged.
Mesh_file make_mesh_file(Soup soup);

/// The file at `path`, read and made into a mesh.
Mesh_file read_mesh_file(const std::string& path);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_MESH_H
