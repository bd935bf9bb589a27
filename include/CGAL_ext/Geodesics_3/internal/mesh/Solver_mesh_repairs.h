// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOLVER_MESH_REPAIRS_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOLVER_MESH_REPAIRS_H

// What the solver mesh changes in the caller's topology so that every propagation is exact: zero-area
// faces removed (their neighbours split), non-manifold vertices split into one copy per fan, and
// copies and the caller's glued vertices glued back together.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

// Face g = face(y) becomes (source(y), c, apex(y)), and a new face (c, target(y), apex(y)) is
// added: y's edge is cut at vertex c. The half-edges of the cut edge are left unpaired.
inline void Solver_mesh::split_face_at(int y, int c)
{
  const int g = face(y), j = y % 3;
  const int b = corner_vertex[std::size_t(y)], a = target(y), x = apex(y);
  const int ax = next(y), ax_opposite = opposite_halfedge[std::size_t(ax)];
  const int n = int(corner_vertex.size() / 3);
  // the added face: c -> a, a -> x (the old a -> x), x -> c
  corner_vertex.insert(corner_vertex.end(), {c, a, x});
  opposite_halfedge.insert(opposite_halfedge.end(), {-1, ax_opposite, 3 * g + (j + 1) % 3});
  if(ax_opposite >= 0)
    opposite_halfedge[std::size_t(ax_opposite)] = 3 * n + 1;
  // face g: b -> c (was b -> a), c -> x (new), x -> b (unchanged)
  corner_vertex[std::size_t(3 * g + (j + 1) % 3)] = c;
  opposite_halfedge[std::size_t(y)] = -1;
  opposite_halfedge[std::size_t(3 * g + (j + 1) % 3)] = 3 * n + 2;
  mesh_face_of_added.push_back(mesh_face(g));
  face_state[std::size_t(g)] |= face_changed;
  face_state.push_back(face_changed);
  (void)b;
}

// Removes the zero-area faces (see `face_state`), keeping the surface they lie on connected:
// a needle's two long edges become one edge, a cap's long edge is cut at its middle vertex in
// the face beyond. The ends of a needle's short edge are glued (added to `glued_groups`).
inline void Solver_mesh::remove_degenerate_faces(std::vector<std::vector<int>>& glued_groups)
{
  using mesh_geometry::distance;
  auto is_degenerate_face = [&](int f) {
    return is_degenerate_triangle(position[std::size_t(corner_vertex[std::size_t(3 * f)])],
                                  position[std::size_t(corner_vertex[std::size_t(3 * f + 1)])],
                                  position[std::size_t(corner_vertex[std::size_t(3 * f + 2)])]);
  };
  std::vector<int> pending;
  for(std::size_t f = 0; f < number_of_faces; ++f)
    if(is_degenerate_face(int(f)))
      pending.push_back(int(f));
  if(pending.empty())
    return;
  face_state.assign(number_of_faces, 0);
  mesh_corner_vertex = corner_vertex;
  auto pair = [&](int h, int g) {
    if(h >= 0)
      opposite_halfedge[std::size_t(h)] = g;
    if(g >= 0)
      opposite_halfedge[std::size_t(g)] = h;
  };
  auto remove = [&](int f) {
    face_state[std::size_t(f)] = face_removed;
    for(int k = 0; k < 3; ++k) {
      const int h = 3 * f + k, o = opposite_halfedge[std::size_t(h)];
      if(o >= 0 && opposite_halfedge[std::size_t(o)] == h)
        opposite_halfedge[std::size_t(o)] = -1;
      opposite_halfedge[std::size_t(h)] = -1;
    }
  };
  std::size_t splits = 0;
  while(!pending.empty()) {
    std::vector<int> waiting;
    bool progressed = false;
    for(int f : pending) {
      if(face_state[std::size_t(f)] & face_removed)
        continue;
      // k: the longest edge, 3f+k from corner k to corner k+1; the middle vertex is corner k+2
      double length[3];
      for(int i = 0; i < 3; ++i)
        length[i] = distance(position[std::size_t(corner_vertex[std::size_t(3 * f + i)])],
                             position[std::size_t(corner_vertex[std::size_t(3 * f + (i + 1) % 3)])]);
      const int k = int(std::max_element(length, length + 3) - length);
      const int longest = 3 * f + k, to_middle = 3 * f + (k + 1) % 3, from_middle = 3 * f + (k + 2) % 3;
      const double shortest = std::min(length[(k + 1) % 3], length[(k + 2) % 3]);
      if(shortest <= degenerate_height_ratio * length[k] || !(length[k] > 0)) {
        // a needle (or a point): glue the ends of its shortest edge, join the other two edges
        const int s = length[(k + 1) % 3] <= length[(k + 2) % 3] ? to_middle : from_middle;
        const int u = s == to_middle ? longest : to_middle, w = s == to_middle ? from_middle : longest;
        const int ou = opposite_halfedge[std::size_t(u)], ow = opposite_halfedge[std::size_t(w)];
        glued_groups.push_back({corner_vertex[std::size_t(s)], corner_vertex[std::size_t(next(s))]});
        if(!(length[k] > 0))
          glued_groups.push_back({corner_vertex[std::size_t(s)], corner_vertex[std::size_t(prev(s))]});
        remove(f);
        if(length[k] > 0)
          pair(ou, ow);
        progressed = true;
        continue;
      }
      // the face beyond may be degenerate too (flat faces stacked on one segment): its halves
      // are, and are split in turn, each time at a vertex strictly inside, so this ends
      const int y = opposite_halfedge[std::size_t(longest)];
      if(++splits > 16 * number_of_mesh_faces + 64)
        break;
      const int c = corner_vertex[std::size_t(from_middle)];
      const int o_to = opposite_halfedge[std::size_t(to_middle)], o_from = opposite_halfedge[std::size_t(from_middle)];
      remove(f);
      progressed = true;
      if(y >= 0) {
        // the face beyond: its half-edge y runs B -> A; B -> c pairs with the cap's c -> B
        // neighbour, c -> A with the cap's A -> c neighbour
        const int n = int(corner_vertex.size() / 3);
        split_face_at(y, c);
        pair(y, o_to);
        pair(3 * n, o_from);
        for(int g : {face(y), n})
          if(is_degenerate_face(g))
            waiting.push_back(g);
      }
    }
    if(!progressed || splits > 16 * number_of_mesh_faces + 64) {
      std::ostringstream msg;
      msg << "degenerate (zero-area) triangles that cannot be resolved: face "
          << mesh_face(waiting.empty() ? pending.front() : waiting.front());
      throw Geodesic_error(msg.str());
    }
    pending.swap(waiting);
  }
  if(std::all_of(face_state.begin(), face_state.end(), [](std::uint8_t s) { return s & face_removed; }))
    throw Geodesic_error("every face of the mesh is degenerate (zero area): there is no surface");
}

// A vertex whose corners do not all lie in the fan of its first outgoing half-edge keeps that
// fan; each other fan gets a copy of the vertex (glued to it afterwards, being at its position).
inline void Solver_mesh::split_non_manifold_vertices(const std::vector<std::int32_t>& corner_count)
{
  const std::size_t nv = position.size();
  std::vector<std::uint8_t> is_split(nv, 0);
  bool any = false;
  for(std::size_t v = 0; v < nv; ++v) {
    int reached = 0;
    for_each_outgoing(int(v), [&](int) { ++reached; });
    if(reached != corner_count[v])
      is_split[v] = any = true;
  }
  if(!any)
    return;
  std::vector<std::uint8_t> in_first_fan(corner_vertex.size(), 0);
  for(std::size_t v = 0; v < nv; ++v)
    if(is_split[v])
      for_each_outgoing(int(v), [&](int h) { in_first_fan[std::size_t(h)] = 1; });
  for(std::size_t h0 = 0; h0 < corner_vertex.size(); ++h0) {
    const int v = corner_vertex[h0];
    if(std::size_t(v) >= nv || !is_split[std::size_t(v)] || in_first_fan[h0] || is_face_removed(face(int(h0))))
      continue;
    // h0 starts a new fan: find its border half-edge, if any, by turning the other way
    int start = int(h0);
    for(int g = start;;) {
      const int o = opposite_halfedge[std::size_t(g)];
      if(o < 0) {
        start = g;
        break;
      }
      g = next(o);
      if(g == int(h0))
        break;
    }
    const int copy = int(position.size());
    position.push_back(position[std::size_t(v)]);
    mesh_vertex_of_copy.push_back(v);
    first_outgoing.push_back(start);
    for_each_outgoing(copy, [&](int h) { corner_vertex[std::size_t(h)] = copy; });
  }
}

// The caller's groups must be points: a wormhole between two places is not a surface.
inline void Solver_mesh::check_glued_groups(const std::vector<std::vector<int>>& groups) const
{
  for(const std::vector<int>& group : groups)
    for(std::size_t i = 1; i < group.size(); ++i) {
      const double apart = mesh_geometry::distance(position[std::size_t(group[i])], position[std::size_t(group[0])]);
      if(apart > glued_distance_ratio * mean_edge_length) {
        std::ostringstream msg;
        msg << "glued vertices " << group[0] << " and " << group[i] << " are " << apart * unit
            << " apart: only vertices at one point of the surface can be glued";
        throw Geodesic_error(msg.str());
      }
    }
}

// Each copy made by `split_non_manifold_vertices` is glued to its vertex, and the vertices of
// each of `groups` (indices checked by the caller) to each other.
inline void Solver_mesh::glue_vertices(const std::vector<std::vector<int>>& groups)
{
  next_glued.clear();
  if(mesh_vertex_of_copy.empty() && groups.empty())
    return;
  const std::size_t nv = position.size();
  std::vector<std::int32_t> root(nv);
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int v) {
    while(root[std::size_t(v)] != v)
      v = root[std::size_t(v)] = root[std::size_t(root[std::size_t(v)])];
    return v;
  };
  auto unite = [&](int a, int b) { root[std::size_t(find(a))] = find(b); };
  for(std::size_t c = 0; c < mesh_vertex_of_copy.size(); ++c)
    unite(int(number_of_mesh_vertices + c), mesh_vertex_of_copy[c]);
  for(const std::vector<int>& group : groups)
    for(std::size_t i = 1; i < group.size(); ++i)
      unite(group[i], group[0]); // a split vertex brings its copies along
  // each class becomes a cycle through next_glued, in index order
  std::vector<std::int32_t> last(nv, -1);
  next_glued.resize(nv);
  for(std::size_t v = 0; v < nv; ++v) {
    const int r = find(int(v));
    next_glued[v] = std::int32_t(v);
    if(last[std::size_t(r)] >= 0) {
      const int previous = last[std::size_t(r)];
      next_glued[v] = next_glued[std::size_t(previous)];
      next_glued[std::size_t(previous)] = std::int32_t(v);
    }
    last[std::size_t(r)] = std::int32_t(v);
  }
  std::size_t glued = 0;
  for(std::size_t v = 0; v < nv; ++v)
    glued += next_glued[v] != std::int32_t(v);
  if(glued == 0)
    next_glued.clear();
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOLVER_MESH_REPAIRS_H
