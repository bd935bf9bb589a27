// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATHS_GEODESIC_PATH_TRACER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATHS_GEODESIC_PATH_TRACER_H

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Edge_window_store.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Source_windows.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Window.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// A point of the surface in the solver mesh's indices: a vertex, a point of an edge
/// ((1 - t) source(h) + t target(h), 0 < t < 1), or a point inside a face (barycentric
/// coordinates in the order of the face's corners).
struct Surface_location
{
  enum Kind
  {
    VERTEX,
    EDGE,
    FACE
  };
  Kind kind = VERTEX;
  int vertex = -1;
  int halfedge = -1;
  double t = 0;
  int face = -1;
  std::array<double, 3> barycentric{{0., 0., 0.}};

  static Surface_location at_vertex(int v)
  {
    Surface_location p;
    p.kind = VERTEX;
    p.vertex = v;
    return p;
  }
};

/// The point of solver-mesh face `face` with snapped barycentric coordinates `b` (see
/// `snapped_barycentric`): a vertex when two coordinates are 0, a point of an edge when one is.
inline Surface_location surface_location(const Solver_mesh& m, int face, const std::array<double, 3>& b)
{
  const int zeros = (b[0] == 0) + (b[1] == 0) + (b[2] == 0);
  for(int k = 0; k < 3; ++k) {
    if(zeros == 2 && b[std::size_t(k)] > 0)
      return Surface_location::at_vertex(m.source(3 * face + k));
    if(zeros == 1 && b[std::size_t((k + 2) % 3)] == 0) { // on half-edge 3f+k
      Surface_location p;
      p.kind = Surface_location::EDGE;
      p.halfedge = 3 * face + k;
      p.t = b[std::size_t((k + 1) % 3)];
      return p;
    }
  }
  Surface_location p;
  p.kind = Surface_location::FACE;
  p.face = face;
  p.barycentric = b;
  return p;
}

/// Distances at any surface point and shortest paths back to the nearest source, read from the
/// windows an `MMP_solver` kept on the edges. Every member is const and reads only what the
/// solver no longer writes, so that any number of threads may query at once.
///
/// A point p of a face is reached (a) through an edge of the face, by a window entering the face
/// whose ray to p crosses the window's interval, (b) through a corner u, at d(u) + |p - u|, or
/// (c) straight from a source inside the face. The shortest of these is p's distance; a path is
/// traced back by moving to where the best one comes from (the crossing on the edge, the corner
/// or the source) and repeating, from an edge point through the faces on both sides of the edge
/// and from a vertex through the faces around it.
class Geodesic_path_tracer
{
public:
  /// Reads the windows kept on the edges, the vertices' distances and nearest sources, the
  /// sources, and the max distance of an MMP build; all must outlive the tracer.
  Geodesic_path_tracer(const Edge_window_store& windows, const std::vector<double>& distances,
                       const std::vector<int>& nearest_sources, const std::vector<Source_point>& sources,
                       double max_distance)
    : m_windows(windows)
    , m_mesh(windows.mesh())
    , m_distance(distances)
    , m_nearest_source(nearest_sources)
    , m_max_distance(max_distance)
  {
    for(std::size_t i = 0; i < sources.size(); ++i) {
      if(sources[i].vertex >= 0)
        continue;
      for_each_face_seeing(m_mesh, sources[i], [&](int face, const std::array<double, 3>& b) {
        m_face_sources.push_back(Face_source{face, int(i), b});
      });
    }
    // by face, then by source index: the first of equal sources is found first
    std::stable_sort(m_face_sources.begin(), m_face_sources.end(),
                     [](const Face_source& a, const Face_source& b) { return a.face < b.face; });
  }

  /// Checks a target given by a face and barycentric coordinates, and makes it a vertex or
  /// an edge point when it lies on one.
  Surface_location locate(int face, const std::array<double, 3>& coordinates) const
  {
    std::array<double, 3> b = checked_barycentric(m_mesh, face, coordinates, "target");
    m_mesh.relocate_face_point(face, b);
    return surface_location(m_mesh, face, b);
  }

  Surface_location locate_vertex(int v) const
  {
    check_vertex_index(m_mesh, v, "target");
    return Surface_location::at_vertex(v);
  }

  /// The distance from the nearest source to p (+infinity if none reaches it), and that source
  /// (-1 if none).
  double distance(const Surface_location& p, int& nearest_source) const
  {
    if(p.kind == Surface_location::VERTEX) {
      nearest_source = m_nearest_source[p.vertex];
      return m_distance[p.vertex];
    }
    const Candidate c = best_way_to(p);
    nearest_source = within_limit(c.distance) ? c.source : -1;
    return within_limit(c.distance) ? c.distance : infinity();
  }

  /// How the shortest way inside face f reaches the point of f with barycentric coordinates b:
  /// its length `distance` there, and, for points of the plane of f near it, sigma + |x - centre|
  /// as long as the same window, corner or source stays the best. The centre is given by
  /// barycentric coordinates of f (of its plane: they may be negative). `source` is -1 when
  /// nothing in f reaches the point.
  struct Planar_way
  {
    std::array<double, 3> centre{{0., 0., 0.}};
    double sigma = 0;
    double distance = std::numeric_limits<double>::infinity();
    int source = -1;
  };

  Planar_way way_in_face(int f, const std::array<double, 3>& b) const
  {
    Candidate best;
    best_in_face(f, b, best);
    Planar_way way;
    if(!within_limit(best.distance))
      return way;
    way.source = best.source;
    way.distance = best.distance;
    if(best.kind == Candidate::WINDOW) {
      // the pseudo-source, or the window's end when the ray to the point misses the window
      const int h = best.index;
      const Window_geometry& w = best.window;
      way.sigma = best.through_end ? distance_at(w, best.x) : w.sigma;
      way.centre = best.through_end ? m_mesh.barycentric_in_frame(h, best.x, 0.) : m_mesh.barycentric_in_frame(h, w.sx, w.sy);
    } else if(best.kind == Candidate::VERTEX) {
      way.sigma = m_distance[best.index];
      for(int k = 0; k < 3; ++k)
        way.centre[std::size_t(k)] = m_mesh.source(3 * f + k) == best.index ? 1. : 0.;
    } else {
      way.centre = m_face_sources[std::size_t(best.index)].barycentric;
    }
    return way;
  }

  /// The same for a point p of the closure of face f (coordinates b in f) whose nearest source
  /// is `nearest`: for a point of an edge, the shorter of the best ways inside f and inside the
  /// face beyond (unfolded into the plane of f), among those from `nearest` (the best inside f
  /// if neither is).
  Planar_way way_at(const Surface_location& p, int f, const std::array<double, 3>& b, int nearest) const
  {
    const Planar_way way = way_in_face(f, b);
    if(p.kind != Surface_location::EDGE)
      return way;
    const int h = Solver_mesh::face(p.halfedge) == f ? p.halfedge : m_mesh.opposite(p.halfedge);
    const int o = m_mesh.opposite(h);
    if(o < 0)
      return way;
    Planar_way beyond = way_in_face(Solver_mesh::face(o), barycentric_in(Solver_mesh::face(o), p));
    if(beyond.source != nearest || (way.source == nearest && way.distance <= beyond.distance))
      return way;
    const std::array<double, 2> c = m_mesh.point_in_frame(o, beyond.centre);
    beyond.centre = m_mesh.barycentric_in_frame(h, m_mesh.length(h) - c[0], -c[1]);
    return beyond;
  }

  /// The shortest path from p back to its nearest source, p first; false (and an empty path)
  /// when no source reaches p.
  bool trace(const Surface_location& target, std::vector<Surface_location>& path) const
  {
    path.clear();
    // The first step is the target's distance: a vertex has it stored, a point is searched once.
    Candidate first;
    if(target.kind == Surface_location::VERTEX) {
      if(!within_limit(m_distance[target.vertex]))
        return false;
    } else {
      first = best_way_to(target);
      if(!within_limit(first.distance))
        return false;
    }
    path.push_back(target);
    Surface_location p = target;
    // After crossing an edge the path goes on in the face beyond it, and the distance left is
    // known: the first way that matches it is the one.
    int face_beyond = -1;
    double left = infinity();
    int crossed = -1; // the half-edge, the place and the window of the last crossing
    double crossed_x = 0;
    Window_geometry crossed_window{0., 0., 0., 0., 0.};
    const std::size_t max_steps = 4 * (m_mesh.number_of_faces + m_mesh.number_of_vertices) + 16;
    for(std::size_t step = 0; step < max_steps; ++step) {
      if(p.kind == Surface_location::VERTEX && m_distance[p.vertex] == 0)
        return true; // a source vertex
      Candidate c = first;
      first = Candidate();
      if(face_beyond >= 0) {
        // The path goes on straight: through one edge of the face beyond, most often the one
        // the last window's pseudo-source lies behind; else anywhere in that face.
        const std::array<double, 3> b = barycentric_in(face_beyond, p);
        const double good_enough = left + path_round_off_ratio * (left + m_mesh.mean_edge_length);
        const int exit = exit_halfedge(crossed, crossed_x, crossed_window);
        if(exit < 0 || !best_through_edge(exit, b, c, good_enough)) {
          c = Candidate();
          best_in_face(face_beyond, b, c, left);
        }
      }
      if(c.kind == Candidate::NONE || (face_beyond >= 0 && c.distance > left + path_straight_ahead_ratio * (left + m_mesh.mean_edge_length)))
        c = best_way_to(p); // the window that led here was clipped since: look everywhere
      if(!(c.distance < infinity()))
        break;
      if(c.kind == Candidate::SOURCE) {
        if(c.distance <= snap * m_mesh.mean_edge_length)
          return true; // the target is the source
        Surface_location s;
        s.kind = Surface_location::FACE;
        s.face = c.face;
        s.barycentric = m_face_sources[std::size_t(c.index)].barycentric;
        path.push_back(s);
        return true;
      }
      face_beyond = -1;
      if(c.kind == Candidate::VERTEX)
        p = Surface_location::at_vertex(c.index);
      else {
        p = on_edge(c.index, c.x / m_mesh.length(c.index));
        if(p.kind == Surface_location::EDGE) {
          face_beyond = Solver_mesh::face(m_mesh.opposite(c.index));
          left = c.distance - c.segment;
          crossed = c.index;
          crossed_x = c.x;
          crossed_window = c.window;
        }
      }
      path.push_back(p);
    }
    throw Geodesic_error("internal error: the shortest path from the target did not reach a source; please report it");
  }

  /// The position of a surface location.
  std::array<double, 3> position(const Surface_location& p) const
  {
    auto corner = [&](int v) { return m_mesh.position[std::size_t(v)]; };
    std::array<double, 3> x{{0., 0., 0.}};
    if(p.kind == Surface_location::VERTEX)
      return corner(p.vertex);
    if(p.kind == Surface_location::EDGE) {
      const auto a = corner(m_mesh.source(p.halfedge)), b = corner(m_mesh.target(p.halfedge));
      for(int i = 0; i < 3; ++i)
        x[i] = (1 - p.t) * a[i] + p.t * b[i];
      return x;
    }
    for(int k = 0; k < 3; ++k) {
      const auto c = corner(m_mesh.source(3 * p.face + k));
      for(int i = 0; i < 3; ++i)
        x[i] += p.barycentric[k] * c[i];
    }
    return x;
  }

private:
  static double infinity() { return std::numeric_limits<double>::infinity(); }
  // Barycentric coordinates and edge parameters below this are zero: the point is on the edge
  // or at the vertex.
  static constexpr double snap = barycentric_snap;

  struct Face_source
  {
    int face;
    int source;
    std::array<double, 3> barycentric;
  };

  struct Candidate
  {
    enum Kind
    {
      NONE,
      WINDOW,
      VERTEX,
      SOURCE
    };
    Kind kind = NONE;
    double distance = std::numeric_limits<double>::infinity();
    int index = -1;  // WINDOW: the half-edge crossed; VERTEX: the vertex; SOURCE: in m_face_sources
    double x = 0;    // WINDOW: where, from the source of the half-edge
    double segment = 0; // WINDOW: the length from the point to the crossing
    bool through_end = false; // WINDOW: the ray to the point misses the window: through its end
    Window_geometry window{0., 0., 0., 0., 0.}; // WINDOW: the window, in the frame of `index`
    int face = -1;   // SOURCE: the face
    int source = -1; // the source the path starts from
  };

  // Reached, and within the max distance.
  bool within_limit(double d) const { return d < infinity() && d <= m_max_distance; }

  Surface_location on_edge(int h, double t) const
  {
    if(t <= snap)
      return Surface_location::at_vertex(m_mesh.source(h));
    if(t >= 1 - snap)
      return Surface_location::at_vertex(m_mesh.target(h));
    Surface_location p;
    p.kind = Surface_location::EDGE;
    p.halfedge = h;
    p.t = t;
    return p;
  }

  // The barycentric coordinates in face f of a point of its closure.
  std::array<double, 3> barycentric_in(int f, const Surface_location& p) const
  {
    std::array<double, 3> b{{0., 0., 0.}};
    if(p.kind == Surface_location::FACE)
      return p.barycentric;
    for(int k = 0; k < 3; ++k) {
      const int h = 3 * f + k;
      if(p.kind == Surface_location::VERTEX && m_mesh.source(h) == p.vertex)
        b[k] = 1;
      if(p.kind == Surface_location::EDGE && (h == p.halfedge || h == m_mesh.opposite(p.halfedge))) {
        const double t = h == p.halfedge ? p.t : 1 - p.t;
        b[k] = 1 - t;
        b[(k + 1) % 3] = t;
      }
    }
    return b;
  }

  // The best way to reach p, over the faces p belongs to.
  Candidate best_way_to(const Surface_location& p) const
  {
    Candidate best;
    if(p.kind == Surface_location::FACE) {
      best_in_face(p.face, p.barycentric, best);
    } else if(p.kind == Surface_location::EDGE) {
      best_in_face(Solver_mesh::face(p.halfedge), barycentric_in(Solver_mesh::face(p.halfedge), p), best);
      const int o = m_mesh.opposite(p.halfedge);
      if(o >= 0)
        best_in_face(Solver_mesh::face(o), barycentric_in(Solver_mesh::face(o), p), best);
    } else {
      // through any face around the vertex, or around a vertex glued to it
      m_mesh.for_each_copy_of_point(p.vertex, [&](int v) {
        m_mesh.for_each_outgoing(v, [&](int h) {
          std::array<double, 3> b{{0., 0., 0.}};
          b[h % 3] = 1;
          best_in_face(Solver_mesh::face(h), b, best);
        });
      });
    }
    return best;
  }

  // Updates `best` with the windows entering face(h) through the edge of h whose ray reaches the
  // point of barycentric coordinates b (in face(h)); true once one within `good_enough` is found.
  bool best_through_edge(int h, const std::array<double, 3>& b, Candidate& best, double good_enough) const
  {
    const std::array<double, 2> q = m_mesh.point_in_frame(h, b);
    const double qx = q[0], qy = q[1];
    const double length = m_mesh.length(h);
    const double tolerance = path_window_end_ratio * length;
    // The windows are kept in the frame of the edge's reference half-edge. The ray is first
    // tested there, with a margin far above the round-off of either frame, so that only the few
    // windows it may cross are turned into h's frame and tested as before: the same windows
    // pass, without a copy of each. (From the reference half-edge, the frames are one: the
    // crossing found there is the one the exact test reads.)
    const bool in_stored_frame = h == m_windows.reference(h);
    const double stored_qx = m_windows.position_across_frames(qx, h);
    for(const Edge_window* ew = m_windows.windows_of_edge(h); ew; ew = ew->next) {
      if(ew->halfedge != h)
        continue; // enters the face on the other side
      const Window_geometry& stored = ew->geometry;
      const double xs = ray_crossing(stored, stored_qx, qy);
      const double margin = tolerance + 1e-12 * (std::abs(xs) + std::abs(stored.sx) + length);
      if(!(xs >= stored.b0 - margin && xs <= stored.b1 + margin))
        continue;
      const Window_geometry w = m_windows.in_frame_of(*ew, h);
      const double x = in_stored_frame ? xs : ray_crossing(w, qx, qy); // where the ray to p crosses
      if(!(x >= w.b0 - tolerance && x <= w.b1 + tolerance))
        continue;
      // A ray just outside the window (round-off) is measured through the window's end, so
      // that a distance is never below a real path's length.
      const double crossing = std::min(std::max(x, w.b0), w.b1);
      const double segment = norm2d(qx - crossing, qy);
      const double d = crossing == x ? w.sigma + norm2d(qx - w.sx, qy - w.sy) : distance_at(w, crossing) + segment;
      if(d < best.distance) {
        best.kind = Candidate::WINDOW;
        best.distance = d;
        best.index = h;
        best.x = crossing;
        best.segment = segment;
        best.through_end = crossing != x;
        best.source = ew->source;
        best.window = w;
        if(d <= good_enough)
          return true;
      }
    }
    return false;
  }

  // Where the ray from w's pseudo-source to (qx, qy) (above the axis) crosses the axis.
  static double ray_crossing(const Window_geometry& w, double qx, double qy)
  {
    return w.sx + (qx - w.sx) * (-w.sy) / (qy - w.sy);
  }

  // After crossing half-edge h at x with the window w (in h's frame), the half-edge of the face
  // beyond through which the straight path back to w's pseudo-source leaves that face, or -1 if
  // it heads for the face's apex (or the pseudo-source is in the face).
  int exit_halfedge(int h, double x, const Window_geometry& w) const
  {
    const int o = m_mesh.opposite(h);
    const Halfedge_frame f = m_mesh.frame(o);
    // In o's frame: the crossing, the pseudo-source (turned by a half turn) and the apex.
    const double px = f.length - x, sx = f.length - w.sx, sy = -w.sy;
    const double cross = (f.apex_x - px) * sy - f.apex_y * (sx - px);
    if(cross > 0)
      return Solver_mesh::prev(o); // left of the way to the apex: the edge from the apex to o's source
    if(cross < 0)
      return Solver_mesh::next(o);
    return -1;
  }

  // Updates `best` with the ways to reach the point of barycentric coordinates b in face f that
  // do not start where the point is (edges and corners it lies on are skipped). A corner wins
  // only when strictly shorter than the other ways, so that ties of round-off never route a
  // path through a vertex that it only grazes.
  // With `expected` (the point's distance when known), the first way within round-off of it
  // is taken without looking further.
  void best_in_face(int f, const std::array<double, 3>& b, Candidate& best,
                    double expected = -std::numeric_limits<double>::infinity()) const
  {
    const double good_enough = expected + path_round_off_ratio * (std::abs(expected) + m_mesh.mean_edge_length);
    // p in the frame of half-edge 3f
    const std::array<double, 2> p = m_mesh.point_in_frame(3 * f, b);
    const double px = p[0], py = p[1];
    Candidate vertex_way;
    for(int k = 0; k < 3; ++k) {
      if(b[k] > 1 - snap)
        continue; // p is this corner (a coordinate of exactly `snap` is not snapped: nor is this)
      const int u = m_mesh.source(3 * f + k);
      const double du = m_distance[u];
      if(!(du < infinity()))
        continue;
      std::array<double, 3> corner{{0., 0., 0.}};
      corner[k] = 1;
      const std::array<double, 2> c = m_mesh.point_in_frame(3 * f, corner);
      const double d = du + norm2d(px - c[0], py - c[1]);
      if(d < vertex_way.distance) {
        vertex_way.kind = Candidate::VERTEX;
        vertex_way.distance = d;
        vertex_way.index = u;
        vertex_way.source = m_nearest_source[u];
      }
    }
    for(int k = 0; k < 3; ++k) {
      if(b[(k + 2) % 3] < snap)
        continue; // p lies on this edge
      if(best_through_edge(3 * f + k, b, best, good_enough))
        break;
    }
    auto first = std::lower_bound(m_face_sources.begin(), m_face_sources.end(), f,
                                  [](const Face_source& s, int face) { return s.face < face; });
    for(auto it = first; it != m_face_sources.end() && it->face == f; ++it) {
      const std::array<double, 2> q = m_mesh.point_in_frame(3 * f, it->barycentric);
      const double d = norm2d(px - q[0], py - q[1]);
      if(d < best.distance) {
        best.kind = Candidate::SOURCE;
        best.distance = d;
        best.index = int(it - m_face_sources.begin());
        best.face = f;
        best.source = it->source;
      }
    }
    if(vertex_way.distance < best.distance - path_round_off_ratio * (best.distance + m_mesh.mean_edge_length))
      best = vertex_way;
    else if(best.kind == Candidate::NONE && vertex_way.kind != Candidate::NONE)
      best = vertex_way;
  }

  const Edge_window_store& m_windows;
  const Solver_mesh& m_mesh;
  const std::vector<double>& m_distance;
  const std::vector<int>& m_nearest_source;
  const double m_max_distance;
  std::vector<Face_source> m_face_sources; // sorted by face
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATHS_GEODESIC_PATH_TRACER_H
