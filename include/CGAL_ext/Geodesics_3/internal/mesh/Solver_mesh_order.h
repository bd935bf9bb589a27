// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOLVER_MESH_ORDER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOLVER_MESH_ORDER_H

// The order of the solver mesh in memory: faces along a Z-order curve of their centroids, vertices
// in the order the faces first name them, so that what a propagation reads around a face is near.

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

// Spreads the 10 low bits of x to every third bit (bit i goes to bit 3i).
inline std::uint64_t spread_bits_by_three(std::uint64_t x)
{
  x &= 0x3ff;
  x = (x | x << 16) & 0x30000ffULL;
  x = (x | x << 8) & 0x300f00fULL;
  x = (x | x << 4) & 0x30c30c3ULL;
  x = (x | x << 2) & 0x9249249ULL;
  return x;
}

inline void Solver_mesh::order_faces()
{
  const std::size_t nf = corner_vertex.size() / 3;
  const auto [low, high] = bounding_box();
  const double extent = std::max({high[0] - low[0], high[1] - low[1], high[2] - low[2]});
  const double scale = extent > 0 ? 1023. / (3 * extent) : 0.;
  // Each face's key: the Morton code of its centroid on a grid of 1024 steps a side (the bits of
  // x, y and z interleaved), then its index. Sorted, the faces follow a Z-order curve, those of
  // one cell in the caller's order. (CGAL's hilbert_sort orders points directly but costs far
  // more here; doc/design.md.)
  std::vector<std::uint64_t> key(nf);
  for(std::size_t f = 0; f < nf; ++f) {
    std::uint64_t code = 0;
    for(int i = 0; i < 3; ++i) {
      double sum = 0;
      for(int k = 0; k < 3; ++k)
        sum += position[std::size_t(corner_vertex[3 * f + k])][i] - low[i];
      code |= spread_bits_by_three(std::uint64_t(sum * scale)) << i;
    }
    key[f] = code << 32 | f;
  }
  std::sort(key.begin(), key.end());
  cache_face_of_mesh_face.resize(nf);
  mesh_face_of_cache_face.resize(nf);
  for(std::size_t c = 0; c < nf; ++c) {
    const std::uint32_t f = std::uint32_t(key[c]);
    cache_face_of_mesh_face[f] = std::int32_t(c);
    mesh_face_of_cache_face[c] = std::int32_t(f);
  }
  std::vector<std::uint64_t>().swap(key);
  // the corners moved to their faces' places, cycle by cycle of the permutation
  std::vector<bool> placed(nf, false);
  for(std::size_t start = 0; start < nf; ++start) {
    if(placed[start])
      continue;
    const std::array<std::int32_t, 3> first{
      {corner_vertex[3 * start], corner_vertex[3 * start + 1], corner_vertex[3 * start + 2]}};
    std::size_t c = start;
    for(;;) {
      placed[c] = true;
      const std::size_t f = std::size_t(mesh_face_of_cache_face[c]);
      if(f == start) {
        std::copy(first.begin(), first.end(), corner_vertex.begin() + std::ptrdiff_t(3 * c));
        break;
      }
      std::copy_n(corner_vertex.begin() + std::ptrdiff_t(3 * f), 3, corner_vertex.begin() + std::ptrdiff_t(3 * c));
      c = f;
    }
  }
}

// Renumbers the caller's vertices (not the copies, numbered after them) in the order in which
// the faces, already in the order of a curve, first name them; vertices in no face come last, in
// the caller's order. Every vertex index stored so far is the caller's and is renumbered here:
// the messages of the checks above name the caller's vertices.
inline void Solver_mesh::order_vertices()
{
  const std::size_t n = number_of_mesh_vertices;
  constexpr std::int32_t unnumbered = -1;
  cache_vertex_of_mesh_vertex.assign(n, unnumbered);
  mesh_vertex_of_cache_vertex.resize(n);
  std::int32_t next_number = 0;
  auto number = [&](std::size_t v) {
    if(v < n && cache_vertex_of_mesh_vertex[v] == unnumbered) {
      cache_vertex_of_mesh_vertex[v] = next_number;
      mesh_vertex_of_cache_vertex[std::size_t(next_number++)] = std::int32_t(v);
    }
  };
  for(std::int32_t v : corner_vertex)
    number(std::size_t(v));
  for(std::size_t v = 0; v < n; ++v)
    number(v);
  auto renumber = [&](std::int32_t& v) {
    if(v >= 0 && std::size_t(v) < n)
      v = cache_vertex_of_mesh_vertex[std::size_t(v)];
  };
  // In place, cycle by cycle of the permutation: a copy of the arrays, freed at once, would
  // still raise the tool's peak memory (the allocator keeps it).
  std::vector<bool> moved(n);
  auto move_values = [&](auto& per_vertex) {
    moved.assign(n, false);
    for(std::size_t start = 0; start < n; ++start) {
      if(moved[start])
        continue;
      auto carried = per_vertex[start];
      for(std::size_t v = start;;) {
        moved[v] = true;
        const std::size_t to = std::size_t(cache_vertex_of_mesh_vertex[v]);
        if(to == start) {
          per_vertex[to] = carried;
          break;
        }
        std::swap(carried, per_vertex[to]);
        v = to;
      }
    }
  };
  for(std::int32_t& v : corner_vertex)
    renumber(v);
  for(std::int32_t& v : mesh_corner_vertex)
    renumber(v);
  move_values(position);
  move_values(first_outgoing);
  move_values(is_border_vertex);
  move_values(is_pseudo_source);
  if(!next_glued.empty()) {
    for(std::int32_t& v : next_glued)
      renumber(v);
    move_values(next_glued);
  }
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOLVER_MESH_ORDER_H
