// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOUP_REPAIR_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOUP_REPAIR_H

// The steps of polygon_soup_to_geodesic_mesh(): checking a polygon soup, merging its duplicate
// points, cleaning its polygons, orienting it, building the mesh and triangulating it, with CGAL's
// Polygon_mesh_processing doing each repair and this file keeping track of the input's ids.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_mesh_repairs.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

typedef std::vector<std::size_t> Soup_polygon;

/// A polygon soup on its way to a geodesic mesh, and where its parts come from.
template <class Point>
struct Soup_in_repair
{
  std::vector<Point> points;
  std::vector<Soup_polygon> polygons;
  std::vector<std::size_t> input_polygon;  // per polygon: the input polygon it is (a loop of)
  std::vector<std::size_t> point_of_input; // per input point: its point once duplicates are merged
  std::vector<std::pair<std::size_t, std::size_t>> copies; // (point, its copy) made by the orientation
};

template <class Id>
bool is_index_below(Id id, std::size_t n)
{
  if constexpr(std::is_signed<Id>::value) {
    if(id < 0)
      return false;
  }
  return static_cast<std::size_t>(id) < n;
}

/// A copy of the input as a soup of `Point`s and index polygons; throws `Geodesic_error` for a
/// non-finite coordinate, an index out of range, or no polygon at all.
template <class Point, class PointRange, class PolygonRange>
Soup_in_repair<Point> checked_soup(const PointRange& points, const PolygonRange& polygons)
{
  Soup_in_repair<Point> soup;
  for(const auto& input : points) {
    const Point p(input);
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
      std::ostringstream msg;
      msg << "point " << soup.points.size() << " has a non-finite coordinate (" << x << ", " << y << ", " << z
          << ")";
      throw Geodesic_error(msg.str());
    }
    soup.points.push_back(p);
  }
  const std::size_t n = soup.points.size();
  for(const auto& input : polygons) {
    Soup_polygon polygon;
    for(const auto id : input) {
      if(!is_index_below(id, n))
        throw Geodesic_error("polygon " + std::to_string(soup.polygons.size()) + " uses point " +
                             std::to_string(id) + ", but the soup has " + std::to_string(n) + " points");
      polygon.push_back(static_cast<std::size_t>(id));
    }
    soup.polygons.push_back(std::move(polygon));
  }
  if(soup.polygons.empty())
    throw Geodesic_error(n == 0 ? std::string("no faces: the soup is empty")
                                : "no faces: the soup has " + std::to_string(n) + " points and no polygon (a point cloud)");
  soup.input_polygon.resize(soup.polygons.size());
  std::iota(soup.input_polygon.begin(), soup.input_polygon.end(), std::size_t(0));
  return soup;
}

/// Whether no point is shared by two polygons: a soup, whose polygons meet only where their
/// points coincide.
template <class Point>
bool shares_no_point(const Soup_in_repair<Point>& soup)
{
  std::vector<std::uint8_t> used(soup.points.size(), 0);
  for(const Soup_polygon& polygon : soup.polygons)
    for(std::size_t p : polygon) {
      if(used[p])
        return false;
      used[p] = 1;
    }
  return true;
}

/// Keeps every point as it is.
template <class Point>
void keep_points(Soup_in_repair<Point>& soup)
{
  soup.point_of_input.resize(soup.points.size());
  std::iota(soup.point_of_input.begin(), soup.point_of_input.end(), std::size_t(0));
}

/// Merges the points at identical coordinates and records where each input point went.
template <class Point>
void merge_duplicate_points(Soup_in_repair<Point>& soup, Geodesic_mesh_repairs& repairs)
{
  // CGAL keeps the points in order of first appearance but returns no map from the old indices:
  // a temporary polygon through every point is renumbered with the others and carries it.
  Soup_polygon every_point(soup.points.size());
  std::iota(every_point.begin(), every_point.end(), std::size_t(0));
  soup.polygons.push_back(std::move(every_point));
  repairs.merged_points = CGAL::Polygon_mesh_processing::merge_duplicate_points_in_polygon_soup(soup.points, soup.polygons);
  soup.point_of_input = std::move(soup.polygons.back());
  soup.polygons.pop_back();
}

/// The first places i < k where `polygon` passes through the same point, if any.
inline std::optional<std::pair<std::size_t, std::size_t>> first_repeated_point(const Soup_polygon& polygon)
{
  for(std::size_t i = 0; i < polygon.size(); ++i)
    for(std::size_t k = i + 1; k < polygon.size(); ++k)
      if(polygon[i] == polygon[k])
        return std::make_pair(i, k);
  return std::nullopt;
}

/// The loops of `polygon` with at least 3 points: repeated consecutive points are dropped, and
/// a polygon passing twice through a point is cut there into two loops (recursively).
inline void append_loops(Soup_polygon polygon, std::vector<Soup_polygon>& loops)
{
  for(std::size_t i = 0; i < polygon.size() && polygon.size() > 1;) {
    if(polygon[i] == polygon[(i + 1) % polygon.size()])
      polygon.erase(polygon.begin() + std::ptrdiff_t(i));
    else
      ++i;
  }
  if(const auto repeat = first_repeated_point(polygon)) {
    const auto [i, k] = *repeat;
    append_loops(Soup_polygon(polygon.begin() + std::ptrdiff_t(i), polygon.begin() + std::ptrdiff_t(k)), loops);
    polygon.erase(polygon.begin() + std::ptrdiff_t(i), polygon.begin() + std::ptrdiff_t(k));
    append_loops(std::move(polygon), loops);
    return;
  }
  if(polygon.size() >= 3)
    loops.push_back(std::move(polygon));
}

/// Replaces each polygon by its loops (see `append_loops`); throws `Geodesic_error` when none is left.
template <class Point>
void remove_repeated_points(Soup_in_repair<Point>& soup, Geodesic_mesh_repairs& repairs)
{
  // Most files need nothing here: they keep their polygons instead of a second copy of them.
  if(std::none_of(soup.polygons.begin(), soup.polygons.end(),
                  [](const Soup_polygon& polygon) { return polygon.size() < 3 || first_repeated_point(polygon); }))
    return;
  std::vector<Soup_polygon> polygons;
  std::vector<std::size_t> input_polygon;
  std::vector<Soup_polygon> loops;
  for(std::size_t j = 0; j < soup.polygons.size(); ++j) {
    loops.clear();
    append_loops(soup.polygons[j], loops);
    if(loops.empty())
      ++repairs.removed_polygons;
    else if(loops.size() > 1)
      ++repairs.split_polygons;
    for(Soup_polygon& loop : loops) {
      polygons.push_back(std::move(loop));
      input_polygon.push_back(soup.input_polygon[j]);
    }
  }
  if(polygons.empty())
    throw Geodesic_error(soup.polygons.size() == 1
                           ? std::string("no faces left: the only polygon has fewer than 3 distinct points")
                           : "no faces left: each of the " + std::to_string(soup.polygons.size()) +
                               " polygons has fewer than 3 distinct points");
  soup.polygons = std::move(polygons);
  soup.input_polygon = std::move(input_polygon);
}

/// Counts what CGAL's orientation of a soup changes. CGAL copies the visitor: it holds pointers.
class Orientation_counter : public CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
public:
  Orientation_counter(Geodesic_mesh_repairs& repairs, std::vector<bool>& reversed,
                      std::vector<std::pair<std::size_t, std::size_t>>& copies,
                      std::set<std::pair<std::size_t, std::size_t>>& non_manifold_edges)
    : m_repairs(&repairs), m_reversed(&reversed), m_copies(&copies), m_non_manifold_edges(&non_manifold_edges)
  {}
  // called for each polygon side on such an edge
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t) { m_non_manifold_edges->insert(std::minmax(a, b)); }
  void duplicated_vertex(std::size_t point, std::size_t copy)
  {
    ++m_repairs->duplicated_points;
    m_copies->emplace_back(point, copy);
  }
  void polygon_orientation_reversed(std::size_t polygon) { (*m_reversed)[polygon] = !(*m_reversed)[polygon]; }

private:
  Geodesic_mesh_repairs* m_repairs;
  std::vector<bool>* m_reversed;
  std::vector<std::pair<std::size_t, std::size_t>>* m_copies;
  std::set<std::pair<std::size_t, std::size_t>>* m_non_manifold_edges;
};

/// Whether the soup is already what the orientation below would leave unchanged: each directed
/// edge in one polygon (so an edge in at most two, run in opposite directions), and the polygons
/// around each point one fan. Polygons have 3 distinct points or more.
template <class Point>
bool is_oriented_manifold(const Soup_in_repair<Point>& soup)
{
  const std::size_t n = soup.points.size();
  std::size_t corners = 0;
  for(const Soup_polygon& polygon : soup.polygons)
    corners += polygon.size();
  if(n >= std::numeric_limits<std::uint32_t>::max() || corners >= std::numeric_limits<std::uint32_t>::max())
    return false;
  // The directed edges out of each point (v -> to, from the corner `position` of `polygon` at v),
  // grouped by point.
  struct Out_edge
  {
    std::uint32_t to, polygon, position;
  };
  std::vector<std::uint32_t> first(n + 1, 0);
  for(const Soup_polygon& polygon : soup.polygons)
    for(std::size_t v : polygon)
      ++first[v + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<Out_edge> out(corners);
  {
    std::vector<std::uint32_t> end(first.begin(), first.end() - 1);
    for(std::size_t k = 0; k < soup.polygons.size(); ++k) {
      const Soup_polygon& polygon = soup.polygons[k];
      for(std::size_t i = 0; i < polygon.size(); ++i)
        out[end[polygon[i]]++] = Out_edge{std::uint32_t(polygon[(i + 1) % polygon.size()]), std::uint32_t(k), std::uint32_t(i)};
    }
  }
  for(std::size_t v = 0; v < n; ++v) {
    const auto begin = out.begin() + first[v], end = out.begin() + first[v + 1];
    std::sort(begin, end, [](const Out_edge& a, const Out_edge& b) { return a.to < b.to; });
    if(std::adjacent_find(begin, end, [](const Out_edge& a, const Out_edge& b) { return a.to == b.to; }) != end)
      return false;
  }
  const auto find = [&](std::size_t from, std::size_t to) -> const Out_edge* {
    const auto begin = out.begin() + first[from], end = out.begin() + first[from + 1];
    const auto it = std::lower_bound(begin, end, to, [](const Out_edge& e, std::size_t t) { return e.to < t; });
    return it != end && it->to == to ? &*it : nullptr;
  };
  // Around each point, from one of its corners: forward across the edge leaving it, until the
  // start or a border, then backward across the edge coming in; every corner must be met.
  for(std::size_t v = 0; v < n; ++v) {
    const std::size_t count = first[v + 1] - first[v];
    if(count == 0)
      continue;
    const Out_edge start = out[first[v]];
    std::size_t met = 1;
    bool closed = false;
    for(Out_edge c = start;;) {
      const Out_edge* back = find(c.to, v); // the polygon beyond c's outgoing edge, at its corner before v
      if(!back)
        break;
      const Soup_polygon& polygon = soup.polygons[back->polygon];
      c = Out_edge{std::uint32_t(polygon[(back->position + 2) % polygon.size()]), back->polygon,
                   std::uint32_t((back->position + 1) % polygon.size())};
      if(c.polygon == start.polygon && c.position == start.position) {
        closed = true;
        break;
      }
      if(++met > count)
        return false;
    }
    if(!closed) {
      for(Out_edge c = start;;) {
        const Soup_polygon& polygon = soup.polygons[c.polygon];
        const std::size_t before = polygon[(c.position + polygon.size() - 1) % polygon.size()];
        const Out_edge* next = find(v, before); // the polygon beyond c's incoming edge, at v
        if(!next)
          break;
        c = *next;
        if(++met > count)
          return false;
      }
    }
    if(met != count)
      return false;
  }
  return true;
}

/// Orients the soup consistently; where it cannot be a manifold, CGAL duplicates points (the
/// copies are appended: an input point keeps its index, hence one vertex).
template <class Point>
void orient(Soup_in_repair<Point>& soup, Geodesic_mesh_repairs& repairs)
{
  // CGAL's orientation keeps sets of polygons per edge, several times the soup's memory: a
  // soup that needs no change (most mesh files) does not go through it.
  if(is_oriented_manifold(soup))
    return;
  std::vector<bool> reversed(soup.polygons.size(), false);
  std::set<std::pair<std::size_t, std::size_t>> non_manifold_edges;
  CGAL::Polygon_mesh_processing::orient_polygon_soup(
    soup.points, soup.polygons,
    CGAL::parameters::visitor(Orientation_counter(repairs, reversed, soup.copies, non_manifold_edges)));
  repairs.non_manifold_edges = non_manifold_edges.size();
  repairs.reversed_polygons = std::size_t(std::count(reversed.begin(), reversed.end(), true));
}

/// A vertex point map that also lists the vertices whose point is set, in order.
template <class VertexPointMap>
struct Vertex_listing_point_map
{
  typedef typename boost::property_traits<VertexPointMap>::key_type key_type;
  typedef typename boost::property_traits<VertexPointMap>::value_type value_type;
  typedef typename boost::property_traits<VertexPointMap>::reference reference;
  typedef boost::read_write_property_map_tag category;

  VertexPointMap base;
  std::vector<key_type>* vertices;

  friend reference get(const Vertex_listing_point_map& map, key_type v) { return get(map.base, v); }
  friend void put(const Vertex_listing_point_map& map, key_type v, const value_type& p)
  {
    put(map.base, v, p);
    map.vertices->push_back(v);
  }
};

/// Writes, for each point the orientation duplicated, the group of its vertices (the point's and
/// its copies') to `out`, as a `std::vector` of vertices.
template <class Point, class VertexOfPoint, class OutputIterator>
void write_glued_groups(const Soup_in_repair<Point>& soup, const VertexOfPoint& vertex_of_soup_point, OutputIterator out)
{
  std::vector<std::pair<std::size_t, std::size_t>> copies = soup.copies;
  std::sort(copies.begin(), copies.end());
  for(std::size_t i = 0; i < copies.size();) {
    std::vector<typename VertexOfPoint::value_type> group{vertex_of_soup_point[copies[i].first]};
    std::size_t j = i;
    for(; j < copies.size() && copies[j].first == copies[i].first; ++j)
      group.push_back(vertex_of_soup_point[copies[j].second]);
    *out++ = group;
    i = j;
  }
}

/// Builds `tm` from the oriented soup; returns the vertex of each point of the soup.
template <class Point, class TriangleMesh, class VertexPointMap>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
build_mesh(const Soup_in_repair<Point>& soup, TriangleMesh& tm, VertexPointMap vpm)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  // CGAL 5.5 returns no map from points to vertices; it adds one vertex per point (isolated
  // ones too), in order, and sets its point once.
  std::vector<vertex_descriptor> vertex_of_point;
  vertex_of_point.reserve(soup.points.size());
  CGAL::clear(tm);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(
    soup.points, soup.polygons, tm, CGAL::parameters::default_values(),
    CGAL::parameters::vertex_point_map(Vertex_listing_point_map<VertexPointMap>{vpm, &vertex_of_point}));
  if(vertex_of_point.size() != soup.points.size() || std::size_t(num_faces(tm)) != soup.polygons.size())
    throw Geodesic_error("internal error: the oriented soup of " + std::to_string(soup.polygons.size()) +
                         " polygons made a mesh of " + std::to_string(num_faces(tm)) + " faces; please report it");
  return vertex_of_point;
}

/// The face of `tm` of each polygon of the soup, found by its first edge (after orientation a
/// directed edge belongs to one polygon).
template <class Point, class TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
faces_of_polygons(const Soup_in_repair<Point>& soup, const TriangleMesh& tm,
                  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_of_point)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> faces;
  faces.reserve(soup.polygons.size());
  for(const Soup_polygon& polygon : soup.polygons)
    faces.push_back(face(halfedge(vertex_of_point[polygon[0]], vertex_of_point[polygon[1]], tm).first, tm));
  return faces;
}

/// Triangulates the faces of the polygons of 4 or more points, without new points.
template <class Point, class TriangleMesh, class VertexPointMap>
void triangulate(const Soup_in_repair<Point>& soup,
                 const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_of_polygon,
                 TriangleMesh& tm, VertexPointMap vpm, Geodesic_mesh_repairs& repairs)
{
  for(std::size_t k = 0; k < soup.polygons.size(); ++k) {
    if(soup.polygons[k].size() == 3)
      continue;
    if(!CGAL::Polygon_mesh_processing::triangulate_face(face_of_polygon[k], tm,
                                                        CGAL::parameters::vertex_point_map(vpm)))
      throw Geodesic_error("polygon " + std::to_string(soup.input_polygon[k]) + " (" +
                           std::to_string(soup.polygons[k].size()) +
                           " points) cannot be triangulated without new points: it is flat or crosses itself");
    ++repairs.triangulated_polygons;
  }
}

/// Per input polygon: its face when it is a triangle made into one face as it is (3 distinct
/// points), `null_face` otherwise.
template <class Point, class PolygonRange, class FaceDescriptor>
std::vector<FaceDescriptor> faces_of_input_triangles(const PolygonRange& polygons, const Soup_in_repair<Point>& soup,
                                                     const std::vector<FaceDescriptor>& face_of_soup_polygon,
                                                     FaceDescriptor null_face)
{
  std::vector<bool> is_triangle;
  for(const auto& polygon : polygons)
    is_triangle.push_back(std::distance(std::begin(polygon), std::end(polygon)) == 3);
  std::vector<FaceDescriptor> faces(is_triangle.size(), null_face);
  // a triangle with 3 distinct points is one polygon of the soup; with fewer it is gone
  for(std::size_t k = 0; k < soup.polygons.size(); ++k)
    if(is_triangle[soup.input_polygon[k]])
      faces[soup.input_polygon[k]] = face_of_soup_polygon[k];
  return faces;
}

/// The number of points in no polygon.
template <class Point>
std::size_t count_isolated_points(const Soup_in_repair<Point>& soup)
{
  std::vector<bool> used(soup.points.size(), false);
  for(const Soup_polygon& polygon : soup.polygons)
    for(std::size_t p : polygon)
      used[p] = true;
  return std::size_t(std::count(used.begin(), used.end(), false));
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOUP_REPAIR_H
