// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The polygons of a mesh file as the tool keeps them while it works: one array of point ids and,
// unless every polygon is a triangle, where each polygon starts (12 bytes a triangle of a triangle
// mesh, 16 in a mix, where a std::vector per polygon takes about 56 with the allocator's own),
// since the file's polygons stay alive beside the mesh and the solver.

#ifndef GEODESIC_TOOL_POLYGONS_H
#define GEODESIC_TOOL_POLYGONS_H

#include "tool_error.h"
#include "tool_index_iterator.h"

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

namespace geodesic_tool {

class Polygon_list
{
public:
  typedef std::uint32_t Id;

  /// One polygon: the range of its point ids.
  class Polygon
  {
  public:
    Polygon(const Id* begin, const Id* end) : m_begin(begin), m_end(end) {}
    const Id* begin() const { return m_begin; }
    const Id* end() const { return m_end; }
    std::size_t size() const { return std::size_t(m_end - m_begin); }
    std::size_t operator[](std::size_t i) const { return m_begin[i]; }

  private:
    const Id* m_begin;
    const Id* m_end;
  };

  typedef Index_iterator<Polygon_list, Polygon> const_iterator;

  Polygon_list() = default;
  Polygon_list(std::initializer_list<std::initializer_list<std::size_t>> polygons)
  {
    for(const auto& polygon : polygons)
      push_back(polygon);
  }
  template <class Polygons>
  explicit Polygon_list(const Polygons& polygons)
  {
    for(const auto& polygon : polygons)
      push_back(polygon);
  }

  /// Appends a polygon, any range of point ids; throws Tool_error past 2^32 - 1 ids in all.
  template <class Range>
  void push_back(const Range& polygon)
  {
    std::size_t n = 0;
    for(const auto id : polygon) {
      if(std::size_t(id) >= std::numeric_limits<Id>::max())
        throw Tool_error("the mesh is too large for the tool: point id " + std::to_string(std::size_t(id)) +
                         " does not fit 32 bits");
      ++n;
    }
    if(m_ids.size() + n >= std::numeric_limits<Id>::max())
      throw Tool_error("the mesh is too large for the tool: more than 2^32 - 1 polygon corners");
    // The first polygon that is not a triangle: the starts are needed from now on. (Made aside,
    // and the ids taken back if anything throws: a failed push_back leaves the list as it was.)
    std::vector<Id> starts;
    if(n != 3 && m_start.empty()) {
      const std::size_t count = size();
      starts.reserve(count + 2);
      for(std::size_t i = 0; i <= count; ++i)
        starts.push_back(Id(3 * i));
    }
    const std::size_t ids_before = m_ids.size();
    try {
      for(const auto id : polygon)
        m_ids.push_back(Id(id));
      if(!starts.empty())
        starts.push_back(Id(m_ids.size()));
      else if(!m_start.empty())
        m_start.push_back(Id(m_ids.size()));
    } catch(...) {
      m_ids.resize(ids_before);
      throw;
    }
    if(!starts.empty())
      m_start.swap(starts);
  }

  std::size_t size() const { return m_start.empty() ? m_ids.size() / 3 : m_start.size() - 1; }
  bool empty() const { return size() == 0; }
  Polygon operator[](std::size_t i) const { return Polygon(m_ids.data() + start(i), m_ids.data() + start(i + 1)); }
  const_iterator begin() const { return const_iterator(this, 0); }
  const_iterator end() const { return const_iterator(this, size()); }

  /// The polygons as a vector per polygon, as CGAL's soup writers take them.
  std::vector<std::vector<std::size_t>> to_vectors() const
  {
    std::vector<std::vector<std::size_t>> polygons;
    for(const Polygon polygon : *this)
      polygons.emplace_back(polygon.begin(), polygon.end());
    return polygons;
  }

  friend bool operator==(const Polygon_list& a, const Polygon_list& b)
  {
    return a.m_ids == b.m_ids && a.m_start == b.m_start;
  }
  friend bool operator!=(const Polygon_list& a, const Polygon_list& b) { return !(a == b); }

private:
  std::size_t start(std::size_t i) const { return m_start.empty() ? 3 * i : std::size_t(m_start[i]); }

  std::vector<Id> m_ids;
  std::vector<Id> m_start; // where each polygon starts in m_ids, and the end; empty while all are triangles
};

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_POLYGONS_H
