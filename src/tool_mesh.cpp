// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_mesh.h"

#include "tool_error.h"
#include "tool_text.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>
#include <sstream>

namespace geodesic_tool {

namespace {

// Corner c of the soup is corner c % 3 of triangle c / 3.
class Union_find
{
public:
  explicit Union_find(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), 0); }
  std::size_t find(std::size_t i)
  {
    while(m_parent[i] != i)
      i = m_parent[i] = m_parent[m_parent[i]];
    return i;
  }
  void unite(std::size_t i, std::size_t j) { m_parent[find(i)] = find(j); }

private:
  std::vector<std::size_t> m_parent;
};

std::size_t corner_of(const Polygons& triangles, std::size_t f, std::size_t v)
{
  const auto& t = triangles[f];
  return 3 * f + std::size_t(std::find(t.begin(), t.end(), v) - t.begin());
}

std::string edge_text(std::size_t a, std::size_t b)
{
  return "(" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

/// Names what keeps a triangle soup from being a manifold, oriented mesh, for the error message.
std::string describe_non_manifold(const Polygons& triangles, std::size_t number_of_points)
{
  // the faces around each undirected edge (smaller id first), in file order
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> edge_faces;
  for(std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f];
    if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      return "face " + std::to_string(f) + " uses a vertex twice";
    for(int k = 0; k < 3; ++k)
      edge_faces[std::minmax(t[k], t[(k + 1) % 3])].push_back(f);
  }
  Union_find fans(3 * triangles.size());
  for(const auto& [edge, faces] : edge_faces) {
    const auto [a, b] = edge;
    if(faces.size() > 2)
      return "non-manifold edge " + edge_text(a, b) + ": shared by " + std::to_string(faces.size()) +
             " faces";
    if(faces.size() < 2)
      continue;
    // consistently oriented neighbours run along the edge in opposite directions
    const std::size_t ca = corner_of(triangles, faces[0], a), cb = corner_of(triangles, faces[0], b);
    const std::size_t da = corner_of(triangles, faces[1], a), db = corner_of(triangles, faces[1], b);
    if((cb % 3 == (ca + 1) % 3) == (db % 3 == (da + 1) % 3))
      return "faces " + std::to_string(faces[0]) + " and " + std::to_string(faces[1]) +
             " are inconsistently oriented across edge " + edge_text(a, b);
    fans.unite(ca, da);
    fans.unite(cb, db);
  }
  // a vertex is manifold when the corners around it form a single fan
  std::vector<std::size_t> fan_of(number_of_points, std::size_t(-1));
  for(std::size_t c = 0; c < 3 * triangles.size(); ++c) {
    const std::size_t v = triangles[c / 3][c % 3];
    const std::size_t fan = fans.find(c);
    if(fan_of[v] == std::size_t(-1))
      fan_of[v] = fan;
    else if(fan_of[v] != fan)
      return "non-manifold vertex " + std::to_string(v) + ": its faces form more than one fan";
  }
  return "the mesh is not a manifold triangle mesh";
}

} // namespace

Soup read_soup(const std::string& path)
{
  const std::string ext = lowercase_extension(path);
  Soup soup;
  if((ext != ".off" && ext != ".obj" && ext != ".ply") || !std::filesystem::is_regular_file(path) ||
     !CGAL::IO::read_polygon_soup(path, soup.points, soup.polygons))
    throw Tool_error("cannot read mesh '" + path + "'");
  if(soup.polygons.empty())
    throw Tool_error("mesh '" + path + "' has no faces");
  return soup;
}

void check_soup(const Soup& soup)
{
  for(std::size_t v = 0; v < soup.points.size(); ++v) {
    const Point& p = soup.points[v];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      std::ostringstream msg;
      msg << "vertex " << v << " has a non-finite coordinate (" << p << ")";
      throw Tool_error(msg.str());
    }
  }
  for(std::size_t f = 0; f < soup.polygons.size(); ++f) {
    const auto& polygon = soup.polygons[f];
    if(polygon.size() != 3)
      throw Tool_error("face " + std::to_string(f) + " has " + std::to_string(polygon.size()) +
                       " vertices; only triangle meshes are supported");
    for(std::size_t v : polygon)
      if(v >= soup.points.size())
        throw Tool_error("face " + std::to_string(f) + " uses vertex " + std::to_string(v) +
                         " but the mesh has " + std::to_string(soup.points.size()) + " vertices");
  }
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.polygons))
    throw Tool_error(describe_non_manifold(soup.polygons, soup.points.size()));
}

Mesh soup_to_mesh(const Soup& soup)
{
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  if(mesh.number_of_vertices() != soup.points.size() || mesh.number_of_faces() != soup.polygons.size())
    throw Tool_error("the mesh is not a manifold triangle mesh");
  return mesh;
}

Mesh read_checked_mesh(const std::string& path, Soup& soup)
{
  soup = read_soup(path);
  check_soup(soup);
  return soup_to_mesh(soup);
}

} // namespace geodesic_tool
