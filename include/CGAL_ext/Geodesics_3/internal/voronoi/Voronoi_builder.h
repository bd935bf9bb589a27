// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_VORONOI_VORONOI_BUILDER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_VORONOI_VORONOI_BUILDER_H

// The geodesic Voronoi diagram of the sources of a multi-source MMP build, cut across faces: the
// bisectors (where two cells meet) and the Voronoi vertices (where three meet), read from the
// nearest source at any surface point that the path tracer gives exactly.

#include <CGAL_ext/Geodesics_3/internal/kernel/Edge_window_store.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Source_windows.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/paths/Geodesic_path_tracer.h>
#include <CGAL_ext/Geodesics_3/internal/support/Parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// A point of a face of the solver mesh: the face and barycentric coordinates in its corner order.
struct Face_point
{
  int face = -1;
  std::array<double, 3> b{{0., 0., 0.}};
};

/// A piece of bisector inside one face, from one boundary point to another, or to a Voronoi
/// vertex (`vertex_at_end`).
struct Bisector_piece
{
  int first_source, second_source; // first < second
  std::vector<Face_point> points;
  int start_vertex = -1, end_vertex = -1; // Voronoi vertex at an end, if any
};

struct Voronoi_vertex_found
{
  Face_point location;
  std::vector<int> sources; // increasing: three, or more where more cells meet at one point
};

/// Finds the bisectors and Voronoi vertices face by face. In a face, the nearest source is
/// known along the boundary (each edge is cut where the windows kept on it change, and every
/// change of the nearest source between two points is located to 1e-12 of the segment, from
/// the ways that reach its two sides, checked by labels); then:
/// - two changes: one bisector between them, its inner points found across the chord;
/// - three changes (three cells): one Voronoi vertex, where the three cells' ways give equal
///   distances (or else found by shrinking a triangle around it to round-off), and three
///   bisectors to it; more changes around as many distinct cells, in a
///   part cut down to round-off: a Voronoi vertex of all of them (four cells meet at the middle
///   of four symmetric sources);
/// - four, one cell on two opposite arcs of the boundary: it runs across the part, and the two
///   other cells each meet it along one bisector;
/// - more, or a source inside the face: the face is cut in four, each part handled the same way,
///   a few times at most (`max_depth`); a part still unresolved then is counted, not guessed.
///   A part of three cells whose vertex the shrinking missed is cut the same way, down to
///   round-off.
class Voronoi_builder
{
public:
  /// Cuts of a part where more than three cells meet, or that hides a cell.
  static constexpr int max_depth = 10;
  /// Cuts of a part where three cells meet, when the vertex was not found directly; the part is
  /// then small enough (`vertex_size`) to put the vertex in its middle.
  static constexpr int max_vertex_depth = 48;
  static constexpr double vertex_size = 1e-13;

  Voronoi_builder(const Solver_mesh& mesh, const Edge_window_store& windows, const Geodesic_path_tracer& tracer)
    : m_mesh(mesh)
    , m_windows(windows)
    , m_tracer(tracer)
  {
  }

  /// `sources` as the build had them (face points relocated out of removed faces). When
  /// `parallel`, blocks of faces are handled on the threads of the caller's task arena; each
  /// block writes its own output, joined in block order: the same diagram for every thread count.
  void run(const std::vector<Source_point>& sources, bool parallel)
  {
    std::vector<std::vector<std::pair<int, Face_point>>> sources_in_face(m_mesh.number_of_faces);
    for(std::size_t i = 0; i < sources.size(); ++i)
      if(sources[i].vertex < 0) {
        Face_point p;
        p.face = sources[i].face;
        p.b = sources[i].barycentric;
        m_mesh.relocate_face_point(p.face, p.b);
        sources_in_face[std::size_t(p.face)].emplace_back(int(i), p);
      }
    const std::size_t faces = m_mesh.number_of_faces;
    const std::size_t blocks = (faces + faces_per_block - 1) / faces_per_block;
    std::vector<Output> outputs(blocks);
    for_each_index(parallel, blocks, 1, [&](std::size_t b, std::size_t) {
      Output& out = outputs[b];
      for(std::size_t f = b * faces_per_block; f < std::min(faces, (b + 1) * faces_per_block); ++f) {
        if(m_mesh.is_face_removed(int(f)))
          continue;
        std::array<Face_point, 3> corners;
        for(int k = 0; k < 3; ++k) {
          corners[std::size_t(k)].face = int(f);
          corners[std::size_t(k)].b[std::size_t(k)] = 1.;
        }
        out.face_sources = &sources_in_face[f];
        if(out.face_sources->empty() && in_one_cell(int(f)))
          continue;
        handle_triangle(corners, 0, out);
      }
    });
    for(Output& out : outputs) {
      const int offset = int(m_vertices.size());
      for(Bisector_piece& piece : out.pieces) {
        if(piece.start_vertex >= 0)
          piece.start_vertex += offset;
        if(piece.end_vertex >= 0)
          piece.end_vertex += offset;
        m_pieces.push_back(std::move(piece));
      }
      m_vertices.insert(m_vertices.end(), out.vertices.begin(), out.vertices.end());
      m_unresolved += out.unresolved;
    }
  }

  const std::vector<Bisector_piece>& pieces() const { return m_pieces; }
  std::vector<Bisector_piece>& pieces() { return m_pieces; }
  const std::vector<Voronoi_vertex_found>& vertices() const { return m_vertices; }
  /// Parts of faces whose cells could not be told apart within `max_depth` cuts.
  std::size_t unresolved() const { return m_unresolved; }

  /// The nearest source of a point (-1 if none reaches it).
  int label(const Face_point& p) const
  {
    int s = -1;
    m_tracer.distance(location(p), s);
    return s;
  }

  std::array<double, 3> position(const Face_point& p) const { return m_tracer.position(location(p)); }

private:
  /// Whether every way into face f comes from one source: its corners' and every window's on its
  /// edges (every window an edge ever held: the store keeps that, and walking the lists would
  /// cost more than the few faces this sends to `handle_triangle` for nothing). Then every point
  /// of the face has that nearest source (the tracer takes the best of these ways), and the face
  /// holds no bisector. Most faces are so.
  bool in_one_cell(int f) const
  {
    const int cell = label_of_vertex(m_mesh.source(3 * f));
    for(int k = 0; k < 3; ++k) {
      const int h = 3 * f + k;
      if(k > 0 && label_of_vertex(m_mesh.source(h)) != cell)
        return false;
      const int sole = m_windows.sole_source_of_edge(h);
      if(sole != cell && sole != Edge_window_store::no_window)
        return false;
    }
    return true;
  }

  int label_of_vertex(int v) const
  {
    int s = -1;
    m_tracer.distance(Surface_location::at_vertex(v), s);
    return s;
  }

  /// What the faces of one block give.
  struct Output
  {
    std::vector<Bisector_piece> pieces;
    std::vector<Voronoi_vertex_found> vertices;
    std::size_t unresolved = 0;
    const std::vector<std::pair<int, Face_point>>* face_sources = nullptr; // of the face being handled
  };

  /// A change of the nearest source along a segment of the boundary of a part: at `point`,
  /// from `before` to `after` going along the boundary.
  struct Crossing
  {
    Face_point point;
    int before, after;
    Geodesic_path_tracer::Planar_way way_before; // how the cell before is reached there
  };

  // As the tracer's public queries see the point: coordinates below the snap are 0.
  Surface_location location(const Face_point& p) const
  {
    return surface_location(m_mesh, p.face, snapped_barycentric(p.b));
  }

  static Face_point along(const Face_point& p, const Face_point& q, double t)
  {
    Face_point r;
    r.face = p.face;
    for(std::size_t k = 0; k < 3; ++k)
      r.b[k] = (1 - t) * p.b[k] + t * q.b[k];
    // exact zeros stay zero, so that a point of an edge is an edge point
    for(std::size_t k = 0; k < 3; ++k)
      if(p.b[k] == 0 && q.b[k] == 0)
        r.b[k] = 0;
    return r;
  }

  /// The nearest source at a point of a face, and how the shortest way inside the face reaches it.
  struct Probe
  {
    int label;
    Geodesic_path_tracer::Planar_way way;
  };

  Probe probe(const Face_point& p) const
  {
    Probe r;
    const Surface_location x = location(p);
    const std::array<double, 3> b = snapped_barycentric(p.b);
    if(x.kind == Surface_location::FACE) {
      r.way = m_tracer.way_in_face(p.face, b);
      r.label = r.way.source; // the tracer's label of a face point is that way's source
    } else {
      m_tracer.distance(x, r.label);
      // a vertex's own distance may come through a face around it other than this one: no
      // way is guessed there
      if(x.kind == Surface_location::EDGE)
        r.way = m_tracer.way_at(x, p.face, b, r.label);
    }
    return r;
  }

  /// A point of the plane of p's face, in the frame of its half-edge 3f.
  std::array<double, 2> in_plane(const Face_point& p, const std::array<double, 3>& b) const
  {
    return m_mesh.point_in_frame(3 * p.face, b);
  }

  /// Where, in (lo, hi) of the segment from p to q, the way wp (which wins at lo) and the way
  /// wq (which wins at hi) give equal distances, to `tolerance`: by regula falsi (Illinois) on
  /// the difference of the two, which is smooth; false when that difference does not change
  /// sign between lo and hi (one of the ways no longer wins there).
  bool equal_distance_on_segment(const Face_point& p, const Face_point& q, const Geodesic_path_tracer::Planar_way& wp,
                                 const Geodesic_path_tracer::Planar_way& wq, double lo, double hi, double tolerance,
                                 double& t) const
  {
    const std::array<double, 2> p0 = in_plane(p, p.b), p1 = in_plane(p, q.b);
    const std::array<double, 2> cp = in_plane(p, wp.centre), cq = in_plane(p, wq.centre);
    auto difference = [&](double s) {
      const double x = p0[0] + s * (p1[0] - p0[0]), y = p0[1] + s * (p1[1] - p0[1]);
      return wp.sigma + norm2d(x - cp[0], y - cp[1]) - wq.sigma - norm2d(x - cq[0], y - cq[1]);
    };
    double a = lo, b = hi, ga = difference(a), gb = difference(b);
    if(!(ga < 0 && gb > 0))
      return false;
    int kept_side = 0; // -1: a was kept by the last step, 1: b was
    for(int i = 0; i < max_search_steps && b - a > tolerance; ++i) {
      const double c = (a * gb - b * ga) / (gb - ga);
      if(!(c > a && c < b))
        break;
      const double gc = difference(c);
      if(gc == 0) {
        a = b = c;
        break;
      }
      if(gc < 0) {
        a = c;
        ga = gc;
        if(kept_side == 1)
          gb *= 0.5;
        kept_side = 1;
      } else {
        b = c;
        gb = gc;
        if(kept_side == -1)
          ga *= 0.5;
        kept_side = -1;
      }
    }
    const double root = 0.5 * (a + b);
    if(!(root > lo && root < hi))
      return false;
    t = root;
    return true;
  }

  /// Every change of the nearest source between p (label lp) and q (label lq), in order from p,
  /// each located to `crossing_precision` of the segment: where the ways that reach the two
  /// ends of the bracket give equal distances, checked by the labels just before and after it
  /// (two queries when those ways stay the best up to there), or else by halving the bracket.
  void find_changes(const Face_point& p, int lp, const Face_point& q, int lq, std::vector<Crossing>& out,
                    int depth = 0) const
  {
    if(lp == lq)
      return;
    double lo = 0, hi = 1;
    Face_point a = p, c = q;
    Geodesic_path_tracer::Planar_way wa = probe(p).way, wc = probe(q).way;
    // When the ways give no guess (an end at a vertex or beyond the face, or a change where
    // other ways take over), the change is most often right at an end: each is looked at once.
    bool looked_near_p = false, looked_near_q = false;
    bool halve = false; // the last guess did not halve the bracket: halve it now
    for(int i = 0; i < max_search_steps && hi - lo > crossing_precision; ++i) {
      const double width = hi - lo;
      const double step = 0.25 * crossing_precision;
      double guess = 0.5 * (lo + hi);
      const bool from_ways =
        !halve && wa.source == lp && wc.source == lq && equal_distance_on_segment(p, q, wa, wc, lo, hi, 0.1 * step, guess);
      double looks[2] = {guess - step, guess + step};
      if(!from_ways) {
        if(!looked_near_p) {
          looked_near_p = true;
          looks[0] = lo + 2 * step;
        } else if(!looked_near_q) {
          looked_near_q = true;
          looks[0] = hi - 2 * step;
        } else {
          looks[0] = guess;
        }
      }
      for(int k = 0; k < (from_ways ? 2 : 1); ++k) {
        const double t = looks[k];
        if(!(t > lo && t < hi))
          continue;
        const Face_point m = along(p, q, t);
        const Probe pm = probe(m);
        if(pm.label == lp) {
          lo = t;
          a = m;
          wa = pm.way;
        } else if(pm.label == lq) {
          hi = t;
          c = m;
          wc = pm.way;
        } else { // a third cell in between: the changes on each side of it
          if(depth < 8) {
            find_changes(a, lp, m, pm.label, out, depth + 1);
            find_changes(m, pm.label, c, lq, out, depth + 1);
          }
          return;
        }
      }
      halve = from_ways && hi - lo > 0.5 * width;
    }
    out.push_back(Crossing{along(p, q, 0.5 * (lo + hi)), lp, lq, wa});
  }

  /// The changes along the side from corner `from` to corner `to` of a part (labels lf, lt),
  /// looking at `side_samples` points in between (and, on an edge of the mesh, at every place
  /// where the windows kept on that edge change); the points looked at go to `seen`.
  void changes_on_side(const Face_point& from, int lf, const Face_point& to, int lt, std::vector<Crossing>& out,
                       std::vector<std::pair<Face_point, int>>& seen) const
  {
    std::vector<double> cuts;
    edge_window_cuts(from, to, cuts);
    for(int i = 1; i < side_samples; ++i)
      cuts.push_back(double(i) / side_samples);
    std::sort(cuts.begin(), cuts.end());
    Face_point previous = from;
    int lprevious = lf;
    for(double t : cuts) {
      if(!(t > 0 && t < 1))
        continue;
      const Face_point p = along(from, to, t);
      const int lp = label(p);
      seen.emplace_back(p, lp);
      find_changes(previous, lprevious, p, lp, out);
      previous = p;
      lprevious = lp;
    }
    find_changes(previous, lprevious, to, lt, out);
  }

  /// Where, between `from` and `to` (both on one edge of the mesh), the nearest source may change
  /// along the windows kept on that edge (as parameters in (0, 1) of the side): where one window
  /// ends and the next one has another source or does not start there. Along a run of windows
  /// of one source that follow each other, the nearest source is that one. None when the side
  /// is inside a face.
  void edge_window_cuts(const Face_point& from, const Face_point& to, std::vector<double>& cuts) const
  {
    for(int k = 0; k < 3; ++k) {
      const std::size_t z = std::size_t((k + 2) % 3); // the coordinate that is 0 on half-edge 3f+k
      if(from.b[z] != 0 || to.b[z] != 0)
        continue;
      const int h = 3 * from.face + k;
      const double s0 = from.b[std::size_t((k + 1) % 3)], s1 = to.b[std::size_t((k + 1) % 3)];
      if(s0 == s1)
        return;
      // the windows are sorted along the edge's reference half-edge, in whose frame they are kept
      const double length = m_mesh.length(h);
      auto cut_at = [&](double stored_x) {
        cuts.push_back((m_windows.position_across_frames(stored_x, h) / length - s0) / (s1 - s0));
      };
      const Edge_window* previous = nullptr;
      for(const Edge_window* w = m_windows.windows_of_edge(h); w; previous = w, w = w->next) {
        const bool continues = previous && previous->source == w->source && previous->geometry.b1 == w->geometry.b0;
        if(!continues) {
          if(previous)
            cut_at(previous->geometry.b1);
          cut_at(w->geometry.b0);
        }
      }
      if(previous)
        cut_at(previous->geometry.b1);
      return;
    }
  }

  void handle_triangle(const std::array<Face_point, 3>& corner, int depth, Output& out)
  {
    std::vector<std::pair<Face_point, int>> seen; // boundary points and their cells
    for(std::size_t k = 0; k < 3; ++k)
      seen.emplace_back(corner[k], label(corner[k]));
    std::vector<Crossing> crossings;
    for(std::size_t k = 0; k < 3; ++k)
      changes_on_side(corner[k], seen[k].second, corner[(k + 1) % 3], seen[(k + 1) % 3].second, crossings, seen);
    drop_blips(crossings);
    // A source inside whose cell does not reach the boundary is a cell the boundary cannot show.
    bool hidden_cell = false;
    for(const auto& s : *out.face_sources)
      if(holds(corner, s.second) && std::none_of(seen.begin(), seen.end(), [&](const auto& x) { return x.second == s.first; }))
        hidden_cell = true;
    const std::size_t n = crossings.size();
    if(!hidden_cell) {
      if(n == 0)
        return;
      if(n == 2 && crossings[0].after == crossings[1].before && crossings[1].after == crossings[0].before) {
        add_piece(crossings[0].point, crossings[1].point, crossings[0].before, crossings[0].after, -1, out);
        return;
      }
      if(n == 4) { // one cell on two opposite arcs of the boundary, and two other cells: two bisectors
        for(std::size_t i = 0; i < 2; ++i) {
          // the cells after crossings i and i+2 (cyclic arcs i and i+2)
          const int x = crossings[i].after, y = crossings[i + 1].after, z = crossings[(i + 3) % 4].after;
          if(x == crossings[i + 2].after && y != z) {
            add_piece(crossings[i + 1].point, crossings[i + 2].point, y, x, -1, out);
            add_piece(crossings[(i + 3) % 4].point, crossings[i].point, z, x, -1, out);
            return;
          }
        }
      }
      if(n >= 3 && chain_of_distinct_cells(crossings)) {
        int v = n == 3 ? vertex_of_ways(corner, crossings, seen, out) : -1;
        if(v < 0 && n == 3)
          v = find_voronoi_vertex(crossings, seen, out);
        if(v < 0 && size_of(corner) <= vertex_size) // cut down to round-off around the vertex
          v = add_vertex(corner, crossings, out);
        if(v >= 0) {
          for(const Crossing& c : crossings)
            add_piece(c.point, out.vertices[std::size_t(v)].location, c.before, c.after, v, out);
          return;
        }
      }
    }
    const bool around_a_vertex = !hidden_cell && n >= 3 && chain_of_distinct_cells(crossings);
    if(depth >= (around_a_vertex ? max_vertex_depth : max_depth)) {
#ifdef VORONOI_DEBUG
      std::cerr << "unresolved face " << corner[0].face << " n=" << n << " hidden=" << hidden_cell << ":";
      for(const Crossing& c : crossings) std::cerr << " " << c.before << ">" << c.after;
      std::cerr << "\n";
#endif
      ++out.unresolved;
      return;
    }
    // cut in four: the corners and the middles of the sides
    std::array<Face_point, 3> middle;
    for(std::size_t k = 0; k < 3; ++k)
      middle[k] = along(corner[k], corner[(k + 1) % 3], 0.5);
    for(std::size_t k = 0; k < 3; ++k)
      handle_triangle({corner[k], middle[k], middle[(k + 2) % 3]}, depth + 1, out);
    handle_triangle(middle, depth + 1, out);
  }

  /// Removes pairs of neighbouring changes there and back (a to b, then b to a) closer than
  /// round-off: the sides of a part that meet on a bisector, or a sample that fell on one.
  static void drop_blips(std::vector<Crossing>& c)
  {
    for(bool dropped = true; dropped && c.size() >= 2;) {
      dropped = false;
      for(std::size_t i = 0; i < c.size() && !dropped; ++i) {
        const std::size_t j = (i + 1) % c.size();
        if(c[i].before != c[j].after || c[i].after != c[j].before)
          continue;
        double gap = 0;
        for(std::size_t k = 0; k < 3; ++k)
          gap = std::max(gap, std::abs(c[i].point.b[k] - c[j].point.b[k]));
        if(gap <= blip) {
          c.erase(c.begin() + std::ptrdiff_t(std::max(i, j)));
          c.erase(c.begin() + std::ptrdiff_t(std::min(i, j)));
          dropped = true;
        }
      }
    }
  }

  /// Whether point p of the face lies in the part (corners c, points of the same face).
  static bool holds(const std::array<Face_point, 3>& c, const Face_point& p)
  {
    // barycentric coordinates are affine: p's signs against each side of the part, in (b1, b2)
    auto cross = [](const Face_point& o, const Face_point& a, const Face_point& b) {
      return (a.b[1] - o.b[1]) * (b.b[2] - o.b[2]) - (a.b[2] - o.b[2]) * (b.b[1] - o.b[1]);
    };
    const double s0 = cross(c[0], c[1], p), s1 = cross(c[1], c[2], p), s2 = cross(c[2], c[0], p);
    return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
  }

  /// Whether the changes go once around distinct cells (a to b, b to c, ..., back to a): the
  /// cells of a Voronoi vertex, when the part is small enough.
  static bool chain_of_distinct_cells(const std::vector<Crossing>& c)
  {
    for(std::size_t i = 0; i < c.size(); ++i) {
      if(c[i].after != c[(i + 1) % c.size()].before)
        return false;
      for(std::size_t j = 0; j < i; ++j)
        if(c[i].before == c[j].before)
          return false;
    }
    return true;
  }

  /// The point where the three cells of `crossings` meet inside the part, from the ways that
  /// reach each cell at the crossings: where the three give equal distances (Newton's method in
  /// the plane of the face), kept only if the labels of three points around it, a round-off
  /// distance away towards a boundary point of each cell, are the three cells. -1 otherwise.
  int vertex_of_ways(const std::array<Face_point, 3>& corner, const std::vector<Crossing>& crossings,
                     const std::vector<std::pair<Face_point, int>>& seen, Output& out) const
  {
    const int f = corner[0].face;
    std::array<int, 3> cell;
    std::array<std::array<double, 2>, 3> centre;
    std::array<double, 3> sigma;
    std::array<double, 2> x{{0., 0.}};
    for(std::size_t k = 0; k < 3; ++k) {
      const Crossing& c = crossings[k];
      if(c.way_before.source != c.before)
        return -1;
      cell[k] = c.before;
      centre[k] = in_plane(corner[0], c.way_before.centre);
      sigma[k] = c.way_before.sigma;
      const std::array<double, 2> at = in_plane(corner[0], c.point.b);
      x[0] += at[0] / 3;
      x[1] += at[1] / 3;
    }
    const double size = std::max({m_mesh.length(3 * f), m_mesh.length(3 * f + 1), m_mesh.length(3 * f + 2)});
    const double reach = vertex_check_distance * size;
    if(size_of(corner) * size < 4 * reach)
      return -1; // no room around it for the check: a part cut down near round-off
    // Newton's method on D0 - D1 = 0, D0 - D2 = 0; done when both are round-off of the distances
    std::array<double, 3> d;
    bool converged = false;
    for(int i = 0; i < max_newton_steps && !converged; ++i) {
      std::array<double, 3> gx, gy;
      for(std::size_t k = 0; k < 3; ++k) {
        const double ux = x[0] - centre[k][0], uy = x[1] - centre[k][1], r = norm2d(ux, uy);
        if(!(r > 0))
          return -1;
        d[k] = sigma[k] + r;
        gx[k] = ux / r;
        gy[k] = uy / r;
      }
      const double f1 = d[0] - d[1], f2 = d[0] - d[2];
      const double round_off = 8 * std::numeric_limits<double>::epsilon() * std::max({d[0], d[1], d[2]});
      converged = std::abs(f1) <= round_off && std::abs(f2) <= round_off;
      if(converged)
        break;
      const double a = gx[0] - gx[1], b = gy[0] - gy[1], c = gx[0] - gx[2], e = gy[0] - gy[2];
      const double det = a * e - b * c;
      if(!(std::abs(det) > 0))
        return -1;
      x[0] -= (f1 * e - b * f2) / det;
      x[1] -= (a * f2 - c * f1) / det;
    }
    Face_point v;
    v.face = f;
    v.b = m_mesh.barycentric_in_frame(3 * f, x[0], x[1]);
    if(!converged || !holds(corner, v))
      return -1;
    // the ways' common distance is the point's distance (the ways are the winners there)
    int nearest = -1;
    const double at_v = m_tracer.distance(location(v), nearest);
    if(std::find(cell.begin(), cell.end(), nearest) == cell.end() ||
       !(std::abs(at_v - d[0]) <= vertex_distance_tolerance * (d[0] + size)))
      return -1;
    for(std::size_t k = 0; k < 3; ++k) {
      const auto in_cell = std::find_if(seen.begin(), seen.end(), [&](const auto& s) { return s.second == cell[k]; });
      if(in_cell == seen.end())
        return -1;
      const std::array<double, 2> toward = in_plane(corner[0], in_cell->first.b);
      const double ux = toward[0] - x[0], uy = toward[1] - x[1], r = norm2d(ux, uy);
      if(!(r > reach))
        return -1;
      Face_point near;
      near.face = f;
      near.b = m_mesh.barycentric_in_frame(3 * f, x[0] + reach * ux / r, x[1] + reach * uy / r);
      if(!holds(corner, near) || label(near) != cell[k])
        return -1;
    }
    return add_vertex({{v, v, v}}, crossings, out);
  }

  /// The point where the three cells of `crossings` meet inside the part: a triangle with a
  /// corner in each cell (points of the boundary, `seen`) is shrunk, keeping a quarter whose
  /// corners are still in the three cells, down to round-off. -1 if it does not get there.
  int find_voronoi_vertex(const std::vector<Crossing>& crossings, const std::vector<std::pair<Face_point, int>>& seen,
                          Output& out) const
  {
    const std::array<int, 3> wanted{{crossings[0].before, crossings[1].before, crossings[2].before}};
    auto all_three = [&](const std::array<int, 3>& l) { return std::is_permutation(l.begin(), l.end(), wanted.begin()); };
    std::array<Face_point, 3> t;
    std::array<int, 3> l;
    for(std::size_t k = 0; k < 3; ++k) {
      const auto in_cell = std::find_if(seen.begin(), seen.end(), [&](const auto& x) { return x.second == wanted[k]; });
      if(in_cell == seen.end())
        return -1;
      t[k] = in_cell->first;
      l[k] = wanted[k];
    }
    const double start_size = size_of(t);
    for(int i = 0; i < 200 && size_of(t) > 1e-13 * start_size; ++i) {
      std::array<Face_point, 3> middle;
      std::array<int, 3> lm;
      for(std::size_t k = 0; k < 3; ++k) {
        middle[k] = along(t[k], t[(k + 1) % 3], 0.5);
        lm[k] = label(middle[k]);
      }
      const std::array<std::array<Face_point, 3>, 4> parts{
        {{{t[0], middle[0], middle[2]}}, {{middle[0], t[1], middle[1]}}, {{middle[2], middle[1], t[2]}}, middle}};
      const std::array<std::array<int, 3>, 4> labels{
        {{{l[0], lm[0], lm[2]}}, {{lm[0], l[1], lm[1]}}, {{lm[2], lm[1], l[2]}}, lm}};
      std::size_t k = 0;
      while(k < 4 && !all_three(labels[k]))
        ++k;
      if(k == 4)
        return -1;
      t = parts[k];
      l = labels[k];
    }
    if(!(size_of(t) <= 1e-13 * start_size))
      return -1;
    return add_vertex(t, crossings, out);
  }

  /// A Voronoi vertex of the cells of `crossings` at the middle of the tiny triangle t.
  static int add_vertex(const std::array<Face_point, 3>& t, const std::vector<Crossing>& crossings, Output& out)
  {
    Voronoi_vertex_found v;
    v.location.face = t[0].face;
    for(std::size_t k = 0; k < 3; ++k)
      v.location.b[k] = (t[0].b[k] + t[1].b[k] + t[2].b[k]) / 3;
    for(const Crossing& c : crossings)
      v.sources.push_back(c.before);
    std::sort(v.sources.begin(), v.sources.end());
    out.vertices.push_back(v);
    return int(out.vertices.size()) - 1;
  }

  /// The largest barycentric extent of a part (a size that shrinks by half at each quartering).
  static double size_of(const std::array<Face_point, 3>& t)
  {
    double size = 0;
    for(std::size_t k = 0; k < 3; ++k)
      for(std::size_t j = 0; j < 3; ++j)
        size = std::max(size, std::abs(t[k].b[j] - t[(k + 1) % 3].b[j]));
    return size;
  }

  /// A bisector from p to q between cells a and b, with inner points found across the chord.
  void add_piece(const Face_point& p, const Face_point& q, int a, int b, int vertex_at_q, Output& out) const
  {
    Bisector_piece piece;
    piece.first_source = std::min(a, b);
    piece.second_source = std::max(a, b);
    piece.points.push_back(p);
    refine(p, q, a, b, 0, piece.points);
    piece.points.push_back(q);
    piece.end_vertex = vertex_at_q;
    out.pieces.push_back(std::move(piece));
  }

  /// Inner points of the bisector between p and q: from the middle of the chord, across it (in
  /// the face's plane), to the change from a to b; recursively while the bisector bends.
  void refine(const Face_point& p, const Face_point& q, int a, int b, int depth, std::vector<Face_point>& out) const
  {
    if(depth == refine_depth)
      return;
    const Face_point m = along(p, q, 0.5);
    // the chord in the plane of the face: corner 0 at the origin, corner 1 on +x
    const Halfedge_frame f = m_mesh.frame(3 * p.face);
    auto to_plane = [&](const Face_point& x) { return m_mesh.point_in_frame(3 * p.face, x.b); };
    auto from_plane = [&](double x, double y) {
      Face_point r;
      r.face = p.face;
      r.b = m_mesh.barycentric_in_frame(3 * p.face, x, y);
      return r;
    };
    const auto pp = to_plane(p), qq = to_plane(q), mm = to_plane(m);
    const double dx = qq[0] - pp[0], dy = qq[1] - pp[1];
    const double chord = std::sqrt(dx * dx + dy * dy);
    if(!(chord > 1e-9 * f.length))
      return;
    // across the chord, half its length each way, as far as the face goes
    const double nx = -dy / chord, ny = dx / chord;
    auto inside = [](const Face_point& x) { return x.b[0] >= 0 && x.b[1] >= 0 && x.b[2] >= 0; };
    Face_point s0 = m, s1 = m;
    for(double reach = 0.5 * chord; reach > 1e-3 * chord; reach *= 0.5) {
      const Face_point c0 = from_plane(mm[0] - reach * nx, mm[1] - reach * ny);
      const Face_point c1 = from_plane(mm[0] + reach * nx, mm[1] + reach * ny);
      if(inside(c0) && inside(c1)) {
        s0 = c0;
        s1 = c1;
        break;
      }
    }
    const int l0 = label(s0), l1 = label(s1);
    if(!((l0 == a && l1 == b) || (l0 == b && l1 == a)))
      return; // the bisector leaves the band here: the chord's ends are kept as they are
    std::vector<Crossing> found;
    find_changes(s0, l0, s1, l1, found);
    if(found.size() != 1)
      return;
    const Face_point x = found[0].point;
    refine(p, x, a, b, depth + 1, out);
    out.push_back(x);
    refine(x, q, a, b, depth + 1, out);
  }

  static constexpr int side_samples = 4;
  /// How far from a Voronoi vertex found from the ways its three cells are checked, as a
  /// fraction of the face's longest edge.
  static constexpr double vertex_check_distance = 1e-10;
  /// How close the tracer's distance at such a vertex must be to the ways' common distance
  /// there (relative): round-off, far below the 1e-9 of the diagonal the vertices are promised to.
  static constexpr double vertex_distance_tolerance = 1e-12;
  /// Newton's method converges in a few steps from the crossings' centroid when the ways are
  /// right; when it does not, the triangle shrinking takes over.
  static constexpr int max_newton_steps = 16;
  /// Where the search of a change stops, as a fraction of the segment searched (of a side: at
  /// most an edge long): 1e-12 of an edge is far below the 1e-9 of the diagonal that a bisector
  /// point is promised to.
  static constexpr double crossing_precision = 1e-12;
  /// A failed guess is followed by a halving: this many steps halve the bracket at least 62
  /// times, past the 40 that the precision needs.
  static constexpr int max_search_steps = 128;
  static constexpr std::size_t faces_per_block = 256;
  static constexpr double blip = 1e-9; // in barycentric coordinates
  static constexpr int refine_depth = 2;

  const Solver_mesh& m_mesh;
  const Edge_window_store& m_windows;
  const Geodesic_path_tracer& m_tracer;
  std::vector<Bisector_piece> m_pieces;
  std::vector<Voronoi_vertex_found> m_vertices;
  std::size_t m_unresolved = 0;
};

/// The Voronoi vertices of each cell, in increasing order (a cell no source reaches, -1, has none).
inline std::vector<std::vector<std::size_t>> vertices_of_cells(const std::vector<Voronoi_vertex_found>& vertices)
{
  std::vector<std::vector<std::size_t>> of_cell;
  for(std::size_t v = 0; v < vertices.size(); ++v)
    for(int c : vertices[v].sources) {
      if(c < 0)
        continue;
      if(std::size_t(c) >= of_cell.size())
        of_cell.resize(std::size_t(c) + 1);
      of_cell[std::size_t(c)].push_back(v);
    }
  return of_cell;
}

/// Whether two points are within `tolerance` of each other in every coordinate: how ends of
/// pieces are joined, and found vertices merged.
inline bool within(const std::array<double, 3>& a, const std::array<double, 3>& b, double tolerance)
{
  return std::abs(a[0] - b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance && std::abs(a[2] - b[2]) <= tolerance;
}

/// Where more than three cells meet at one point (four symmetric sources), round-off may find
/// the vertex of only three of them, and the bisectors of the others end there all the same: a
/// bisector of cells a and b that ends (within `tolerance`) at a vertex of a is equidistant
/// from a and b there, so the vertex is one of b too. Repeated until no vertex gains a cell: a
/// cell gained lets the bisectors of its own neighbours at that point in (five or more cells).
inline void add_cells_of_bisector_ends(const std::vector<Bisector_piece>& pieces,
                                       const std::vector<std::array<double, 3>>& first_point,
                                       const std::vector<std::array<double, 3>>& last_point,
                                       std::vector<Voronoi_vertex_found>& vertices,
                                       const std::vector<std::array<double, 3>>& vertex_point, double tolerance)
{
  for(bool gained = true; gained;) {
    gained = false;
    const std::vector<std::vector<std::size_t>> of_cell = vertices_of_cells(vertices);
    for(std::size_t i = 0; i < pieces.size(); ++i) {
      const Bisector_piece& p = pieces[i];
      for(int cell : {p.first_source, p.second_source}) {
        if(cell < 0 || std::size_t(cell) >= of_cell.size())
          continue;
        for(std::size_t v : of_cell[std::size_t(cell)]) {
          if(!within(first_point[i], vertex_point[v], tolerance) && !within(last_point[i], vertex_point[v], tolerance))
            continue;
          std::vector<int>& s = vertices[v].sources;
          for(int c : {p.first_source, p.second_source})
            if(c >= 0 && !std::count(s.begin(), s.end(), c)) {
              s.insert(std::upper_bound(s.begin(), s.end(), c), c);
              gained = true;
            }
        }
      }
    }
  }
}

/// Ends of pieces that lie at a Voronoi vertex of their two cells (within `tolerance`: a part
/// cut down near a vertex leaves short pieces that end there) become that vertex; pieces shorter
/// than `tolerance` from end to end are dropped.
inline void attach_to_vertices(std::vector<Bisector_piece>& pieces, std::vector<std::array<double, 3>>& first_point,
                               std::vector<std::array<double, 3>>& last_point,
                               const std::vector<Voronoi_vertex_found>& vertices,
                               const std::vector<std::array<double, 3>>& vertex_point, double tolerance)
{
  // a piece looks only at the vertices of its second cell, the larger index
  const std::vector<std::vector<std::size_t>> vertices_of_cell = vertices_of_cells(vertices);
  const std::vector<std::size_t> no_vertex;
  std::size_t kept = 0;
  for(std::size_t i = 0; i < pieces.size(); ++i) {
    Bisector_piece& p = pieces[i];
    if(within(first_point[i], last_point[i], tolerance))
      continue;
    const std::size_t cell = std::size_t(p.second_source);
    for(std::size_t v : p.second_source >= 0 && cell < vertices_of_cell.size() ? vertices_of_cell[cell] : no_vertex) {
      const std::vector<int>& s = vertices[v].sources;
      if(!std::count(s.begin(), s.end(), p.first_source))
        continue;
      if(p.start_vertex < 0 && within(first_point[i], vertex_point[v], tolerance))
        p.start_vertex = int(v);
      if(p.end_vertex < 0 && within(last_point[i], vertex_point[v], tolerance))
        p.end_vertex = int(v);
    }
    if(p.start_vertex >= 0 && p.start_vertex == p.end_vertex)
      continue;
    if(kept != i) {
      pieces[kept] = std::move(p);
      first_point[kept] = first_point[i];
      last_point[kept] = last_point[i];
    }
    ++kept;
  }
  pieces.resize(kept);
  first_point.resize(kept);
  last_point.resize(kept);
}

/// The pieces joined into polylines: pieces of the same two cells whose ends meet (within
/// `tolerance`, in space) are one curve; a curve ends at a Voronoi vertex, at a border, or closes.
/// Returns, per polyline, the indices of its pieces in order and whether each is reversed.
inline std::vector<std::vector<std::pair<std::size_t, bool>>>
join_pieces(const std::vector<Bisector_piece>& pieces, const std::vector<std::array<double, 3>>& first_point,
            const std::vector<std::array<double, 3>>& last_point, double tolerance)
{
  const std::size_t n = pieces.size();
  // ends: 2i the start of piece i, 2i+1 its end; a Voronoi vertex end joins nothing
  std::vector<std::size_t> order;
  for(std::size_t e = 0; e < 2 * n; ++e)
    if((e % 2 == 1 ? pieces[e / 2].end_vertex : pieces[e / 2].start_vertex) < 0)
      order.push_back(e);
  auto at = [&](std::size_t e) -> const std::array<double, 3>& { return e % 2 ? last_point[e / 2] : first_point[e / 2]; };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return at(a)[0] < at(b)[0]; });
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> mate(2 * n, none);
  for(std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t a = order[i];
    for(std::size_t j = i + 1; j < order.size() && at(order[j])[0] - at(a)[0] <= tolerance && mate[a] == none; ++j) {
      const std::size_t b = order[j];
      const Bisector_piece &pa = pieces[a / 2], &pb = pieces[b / 2];
      if(mate[b] != none || a / 2 == b / 2 || pa.first_source != pb.first_source || pa.second_source != pb.second_source)
        continue;
      if(within(at(a), at(b), tolerance)) {
        mate[a] = b;
        mate[b] = a;
      }
    }
  }
  std::vector<std::vector<std::pair<std::size_t, bool>>> lines;
  std::vector<char> used(n, 0);
  for(std::size_t start = 0; start < n; ++start) {
    if(used[start])
      continue;
    // walk back from the start of this piece to the first piece of its curve (or around a loop)
    std::size_t piece = start, entry = 2 * start; // the end by which the walk enters `piece`
    for(std::size_t steps = 0; steps < n && mate[entry] != none && mate[entry] / 2 != start; ++steps) {
      const std::size_t other = mate[entry];
      piece = other / 2;
      entry = other ^ 1; // leave by the far end
    }
    if(mate[entry] != none && mate[entry] / 2 == start) { // a loop: begin at `start`
      piece = start;
      entry = 2 * start;
    }
    // walk forward: enter each piece by `entry`, leave by the other end
    std::vector<std::pair<std::size_t, bool>> line;
    for(std::size_t steps = 0; steps <= n && !used[piece]; ++steps) {
      used[piece] = 1;
      const bool reversed = entry % 2 == 1;
      line.emplace_back(piece, reversed);
      const std::size_t exit = entry ^ 1;
      if(mate[exit] == none)
        break;
      piece = mate[exit] / 2;
      entry = mate[exit];
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_VORONOI_VORONOI_BUILDER_H
