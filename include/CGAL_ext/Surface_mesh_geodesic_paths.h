// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_SURFACE_MESH_GEODESIC_PATHS_H
#define CGAL_EXT_SURFACE_MESH_GEODESIC_PATHS_H

/// \file Surface_mesh_geodesic_paths.h
/// Exact geodesic distances at any surface point and shortest paths, from the windows of VTP or
/// PVTP (the default), MMP, FWP-MMP or PMMP.

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Mesh_setup.h>
#include <CGAL_ext/Geodesics_3/internal/paths/Exact_window_build.h>
#include <CGAL_ext/Geodesics_3/internal/paths/Geodesic_path_tracer.h>
#include <CGAL_ext/Geodesics_3/internal/support/Solver_arena.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/tags.h>

#include <array>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// Exact geodesic distances from a set of sources to any point of a triangle mesh, the nearest
/// source of any point, and shortest paths, computed once by `build()` and then queried.
///
/// `build()` propagates windows (bundles of straight paths unfolded across faces) and keeps
/// them on the edges. With `CGAL_ext::VTP` (the default) it keeps the windows that VTP (PVTP on
/// TBB threads with `CGAL::Parallel_tag`) propagates across each face, clipped against each
/// other on each edge; with `CGAL_ext::MMP` the windows of MMP in exact order of distance
/// (Mitchell, Mount and Papadimitriou), with `CGAL_ext::FWP_MMP` bucket by bucket, PMMP with
/// `CGAL::Parallel_tag` (thesis chapter 3). All give the same distances up to round-off; PVTP
/// and PMMP give the same for every number of threads. VTP's build is the quickest (it keeps
/// fewer windows; the manual's benchmark compares them).
///
/// After `build()` every query is `const` and may run on any number of threads at once.
/// A point is a vertex or a face location: a face and barycentric coordinates in the order of the
/// face's vertices, starting at `source(halfedge(f, tm), tm)`. Points that no source reaches
/// (another connected component, or beyond `max_distance`) are at distance `+infinity` and have
/// no path.
///
/// Paths run from the nearest source to the target; a path is a polyline on the surface whose
/// segments each lie in one face (or along an edge), crossing edges at their interior or passing
/// through vertices where a geodesic must (saddle and border vertices). Its length is the
/// distance of the target.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` (for example
///         `CGAL::Surface_mesh`), manifold, made of triangles
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` (PMMP or
///         PVTP, needs TBB) or `CGAL::Parallel_if_available_tag`
/// \tparam VertexPointMap the vertex point map; its value type is the point type of paths
template <class TriangleMesh, class ConcurrencyTag = CGAL::Sequential_tag,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Surface_mesh_geodesic_paths
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "CGAL_ext::Surface_mesh_geodesic_paths: CGAL::Parallel_tag needs TBB (CGAL_LINKED_WITH_TBB); "
                "use CGAL::Sequential_tag or CGAL::Parallel_if_available_tag");
#endif
  typedef Geodesics_3::internal::Surface_location Location;
  typedef Geodesics_3::internal::Mesh_setup<TriangleMesh, VertexPointMap> Mesh_setup;

public:
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  /// the point type of the vertex point map
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  /// its kernel
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel Kernel;
  /// its number type
  typedef typename Kernel::FT FT;
  /// barycentric coordinates in the order of the face's vertices, from `source(halfedge(f))`
  /// (CGAL's `Polygon_mesh_processing::Barycentric_coordinates`)
  typedef CGAL::Polygon_mesh_processing::Barycentric_coordinates<FT> Barycentric_coordinates;
  /// a point of a face, as CGAL's `Polygon_mesh_processing::locate()` gives it and
  /// `construct_point()` takes it
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, FT> Face_location;

  /// What `nearest_source()` returns for a point that no source reaches.
  static constexpr std::size_t no_source = CGAL_ext::no_source;

  /// A point of a path: where it lies on the mesh, and its position.
  struct Path_point
  {
    /// where the point lies
    enum Kind
    {
      VERTEX, ///< at `vertex`
      EDGE,   ///< on the edge of `halfedge`, at `(1 - t) source + t target`, `0 < t < 1`
      FACE    ///< inside `face`, at `barycentric` (only a source or a target)
    };
    Kind kind;
    vertex_descriptor vertex;             ///< when `kind == VERTEX`
    halfedge_descriptor halfedge;         ///< when `kind == EDGE`
    FT t;                                 ///< when `kind == EDGE`
    face_descriptor face;                 ///< when `kind == FACE`
    Barycentric_coordinates barycentric;  ///< when `kind == FACE`
    Point_3 point;                        ///< the position
  };

  /// prepares queries on `tm`, which must stay alive and unchanged while this object is used;
  /// checks the mesh.
  ///
  /// \param tm the triangle mesh
  /// \param np optional named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
  ///     \cgalParamType{`VertexPointMap`}
  ///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_index_map}
  ///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with an integer value type}
  ///     \cgalParamDefault{an automatically indexed internal map}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{face_index_map}
  ///     \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1`}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with an integer value type}
  ///     \cgalParamDefault{an automatically indexed internal map}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{glued_vertices}
  ///     \cgalParamDescription{groups of vertices that are one point of the surface (the copies of a point that
  ///                           `polygon_soup_to_geodesic_mesh()` duplicated at a non-manifold vertex or edge): a
  ///                           path reaching one goes on from all of them. Vertices whose faces form several fans
  ///                           need no gluing: they are split and glued inside}
  ///     \cgalParamType{a range of ranges of `boost::graph_traits<TriangleMesh>::%vertex_descriptor`}
  ///     \cgalParamDefault{none: vertices at one place stay apart (the two sides of a cut)}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// Non-manifold vertices and degenerate (zero-area) triangles are taken (see the manual).
  ///
  /// \throws Geodesic_error when `tm` is empty, has a face that is not a triangle, a non-finite
  ///         coordinate, a glued vertex out of range, or only degenerate triangles
  template <class NamedParameters = parameters::Default_named_parameters_type>
  explicit Surface_mesh_geodesic_paths(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
    : m_mesh(tm, np)
  {
  }

  /// \name Sources
  /// Adding a source discards the result of the last `build()`.
  /// @{

  /// adds a source at a vertex.
  /// \param v the vertex
  /// \return the index of the source (the number of sources added before it)
  /// \throws Geodesic_error when `v` is not a vertex of the mesh (index out of range)
  std::size_t add_source(vertex_descriptor v) { return add(m_mesh.source_point(v)); }
  /// adds a source at a point of a face.
  /// \param location the face and barycentric coordinates of the point
  /// \return the index of the source
  /// \throws Geodesic_error when the face is out of range or the coordinates are not a convex
  ///         combination
  std::size_t add_source(const Face_location& location) { return add(m_mesh.source_point(location)); }
  /// adds a source at a point of a face given with barycentric coordinates of another number
  /// type (`double` on an exact kernel, say).
  /// \param location the face and barycentric coordinates of the point
  /// \return the index of the source
  template <class T>
  std::size_t add_source(const std::pair<face_descriptor, std::array<T, 3>>& location)
  {
    return add(m_mesh.source_point(location));
  }
  /// adds a source at a point of a face.
  /// \param f the face
  /// \param b barycentric coordinates of the point in `f`
  /// \return the index of the source
  std::size_t add_source(face_descriptor f, const Barycentric_coordinates& b) { return add_source(Face_location(f, b)); }
  /// adds sources.
  /// \param sources a range of vertices or of face locations
  template <class Range>
  void add_sources(const Range& sources)
  {
    for(const auto& s : sources)
      add_source(s);
  }
  /// \return the number of sources added, duplicates included
  std::size_t number_of_sources() const { return m_sources.size(); }
  /// removes every source.
  void clear_sources()
  {
    m_sources.clear();
    forget_build();
  }
  /// @}

  /// computes the windows from which every query is answered; sources may be added and `build()`
  /// called again.
  ///
  /// \param np optional named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{algorithm}
  ///     \cgalParamDescription{`CGAL_ext::VTP` (the windows VTP propagates across each face, clipped
  ///                           against each other on each edge; PVTP with `CGAL::Parallel_tag`),
  ///                           `CGAL_ext::MMP` (windows in exact order, from a binary heap, sequential
  ///                           only) or `CGAL_ext::FWP_MMP` (bucket by bucket; PMMP with
  ///                           `CGAL::Parallel_tag`): all exact, the same distances to round-off}
  ///     \cgalParamType{`CGAL_ext::Geodesic_algorithm`}
  ///     \cgalParamDefault{`CGAL_ext::VTP`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_threads}
  ///     \cgalParamDescription{PVTP and PMMP: the number of threads (in a `tbb::task_arena`), `0` for as many as TBB chooses}
  ///     \cgalParamType{`int`, non-negative}
  ///     \cgalParamDefault{`0`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{batch_size}
  ///     \cgalParamDescription{PVTP: how many window lists, PMMP: how many windows are propagated together at most}
  ///     \cgalParamType{`std::size_t`, positive}
  ///     \cgalParamDefault{`CGAL_ext::default_batch_size` (512) for PVTP, `CGAL_ext::default_window_batch_size` (1024) for PMMP}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{max_distance}
  ///     \cgalParamDescription{the propagation stops beyond this distance; farther points are at `+infinity`}
  ///     \cgalParamType{`double`, non-negative}
  ///     \cgalParamDefault{`+infinity`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{told the fraction of the build done, a few times a second at most, from
  ///                           the calling thread; returning `false` stops with `Geodesic_cancelled` and no result}
  ///     \cgalParamType{callable as `bool(double)`}
  ///     \cgalParamDefault{none}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{statistics}
  ///     \cgalParamDescription{receives windows created and kept, memory and seconds per phase}
  ///     \cgalParamType{`CGAL_ext::Geodesic_statistics&`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Geodesic_error when no source was added, `max_distance` is negative,
  ///         `number_of_threads` negative or `batch_size` zero, or when `approximation` or
  ///         `stop_vertices` are given
  template <class NamedParameters = parameters::Default_named_parameters_type>
  void build(const NamedParameters& np = parameters::default_values())
  {
    namespace internal = Geodesics_3::internal;
    // (CGAL::Parallel_if_available_tag is CGAL::Parallel_tag when TBB is linked)
    constexpr bool parallel = std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value;
    internal::check_has_sources(m_mesh.cache(), m_sources);
    const internal::Solver_settings settings =
      internal::read_window_build_settings(np, "Surface_mesh_geodesic_paths::build()");
    auto windows = std::make_unique<internal::Exact_window_build>(m_mesh.cache(), settings, parallel);
    for(const auto& s : m_sources)
      windows->solver().add_source(s);
    // The parameters are valid: the previous result goes now, so that two sets of windows are
    // never held at once.
    forget_build();
    windows->template run<parallel>(settings.number_of_threads);
    const internal::Solver_base& solver = windows->solver();
    m_tracer = std::make_unique<internal::Geodesic_path_tracer>(windows->windows(), solver.distances(),
                                                                solver.nearest_sources(), solver.sources(),
                                                                solver.max_distance());
    m_statistics = internal::report_statistics(settings, windows->statistics(), m_mesh.seconds());
    m_build = std::move(windows);
  }

  /// \return whether `build()` ran since the sources last changed
  bool is_built() const { return m_build != nullptr; }

  /// \name Queries
  /// Each throws `Geodesic_error` when `build()` has not run since the sources last changed, or
  /// when a face location is out of range or not a convex combination.
  /// @{

  /// \param v a vertex
  /// \return the distance from the nearest source to `v`
  FT distance(vertex_descriptor v) const { return FT(m_mesh.to_mesh_unit(built().distances()[std::size_t(checked(v))])); }
  /// \param p a point of a face
  /// \return the distance from the nearest source to `p`
  FT distance(const Face_location& p) const
  {
    int source;
    return FT(m_mesh.to_mesh_unit(tracer().distance(locate(p), source)));
  }
  /// \param v a vertex
  /// \return the index of the nearest source of `v` (in the order sources were added; of duplicated
  ///         sources the first; of different sources at the same distance, either), or `no_source`
  std::size_t nearest_source(vertex_descriptor v) const
  {
    const int s = built().nearest_sources()[std::size_t(checked(v))];
    return s < 0 ? no_source : std::size_t(s);
  }
  /// \param p a point of a face
  /// \return the index of the nearest source of `p`, or `no_source`
  std::size_t nearest_source(const Face_location& p) const
  {
    int s;
    tracer().distance(locate(p), s);
    return s < 0 ? no_source : std::size_t(s);
  }
  /// writes the distance of every vertex.
  /// \param vertex_distance_map a writable property map with `vertex_descriptor` keys and `FT`
  ///        or `double` values
  template <class VertexDistanceMap>
  void vertex_distances(VertexDistanceMap vertex_distance_map) const
  {
    m_mesh.write_vertex_distances(vertex_distance_map, built().distances());
  }
  /// writes the index of the nearest source of every vertex (as `nearest_source()`; `no_source`,
  /// converted to the map's value type, where no source reaches).
  /// \param vertex_source_map a writable property map with `vertex_descriptor` keys and integer values
  template <class VertexSourceMap>
  void vertex_sources(VertexSourceMap vertex_source_map) const
  {
    m_mesh.write_vertex_sources(vertex_source_map, built().nearest_sources());
  }

  /// writes the points of the shortest path from the nearest source to `target`, the source
  /// first; writes nothing when no source reaches `target`.
  /// \param target a vertex or a `Face_location`
  /// \param out an output iterator accepting `Point_3`
  /// \return the output iterator past the last point
  template <class Target, class OutputIterator>
  OutputIterator shortest_path_points(const Target& target, OutputIterator out) const
  {
    for_each_path_point(target, [&](const Path_point& p) { *out++ = p.point; });
    return out;
  }
  /// writes the points of the shortest path from the nearest source to `target` with where each
  /// lies on the mesh, the source first.
  /// \param target a vertex or a `Face_location`
  /// \param out an output iterator accepting `Path_point`
  /// \return the output iterator past the last point
  template <class Target, class OutputIterator>
  OutputIterator shortest_path_surface_points(const Target& target, OutputIterator out) const
  {
    for_each_path_point(target, [&](const Path_point& p) { *out++ = p; });
    return out;
  }
  /// calls `visitor` on each point of the shortest path from the nearest source to `target`, the
  /// source first: `visitor(v)` with a `vertex_descriptor` at a vertex, `visitor(h, t)` with a
  /// `halfedge_descriptor` and an `FT` on an edge (at `(1 - t) source(h) + t target(h)`), and
  /// `visitor(f, b)` with a `face_descriptor` and `Barycentric_coordinates` inside a face.
  /// \param target a vertex or a `Face_location`
  /// \param visitor the visitor, taken by value
  /// \return the visitor after the visit
  template <class Target, class Visitor>
  Visitor shortest_path_sequence(const Target& target, Visitor visitor) const
  {
    for_each_path_point(target, [&](const Path_point& p) {
      if(p.kind == Path_point::VERTEX)
        visitor(p.vertex);
      else if(p.kind == Path_point::EDGE)
        visitor(p.halfedge, p.t);
      else
        visitor(p.face, p.barycentric);
    });
    return visitor;
  }
  /// \return what the last `build()` did: windows created and kept, their memory, seconds per phase
  /// \deprecated pass `statistics(s)` to `build()` instead, as to every long-running function of
  /// the package; this accessor goes in the next release
  const Geodesic_statistics& statistics() const { return m_statistics; }
  /// @}

private:
  std::size_t add(Geodesics_3::internal::Source_point s)
  {
    // checked here, so that the error names the source being added
    s = Geodesics_3::internal::normalized_source(m_mesh.cache(), s);
    m_sources.push_back(s);
    forget_build();
    return m_sources.size() - 1;
  }

  void forget_build()
  {
    m_tracer.reset(); // it refers to the build
    m_build.reset();
  }

  const Geodesics_3::internal::Solver_base& built() const
  {
    if(!m_build)
      throw Geodesic_error("build() must be called after the sources are added and before any query");
    return m_build->solver();
  }
  const Geodesics_3::internal::Geodesic_path_tracer& tracer() const
  {
    built();
    return *m_tracer;
  }

  int checked(vertex_descriptor v) const { return tracer().locate_vertex(m_mesh.index(v)).vertex; }
  Location locate(vertex_descriptor v) const { return tracer().locate_vertex(m_mesh.index(v)); }
  Location locate(const Face_location& p) const
  {
    std::array<double, 3> b;
    for(int k = 0; k < 3; ++k)
      b[k] = CGAL::to_double(p.second[k]);
    return tracer().locate(m_mesh.index(p.first), b);
  }

  template <class Target, class Function>
  void for_each_path_point(const Target& target, Function f) const
  {
    std::vector<Location> path;
    const Geodesics_3::internal::Geodesic_path_tracer& t = tracer();
    t.trace(locate(target), path);
    for(auto it = path.rbegin(); it != path.rend(); ++it)
      f(to_path_point(*it));
  }

  Path_point to_path_point(const Location& l) const
  {
    Path_point p;
    p.kind = l.kind == Location::VERTEX ? Path_point::VERTEX
                                        : (l.kind == Location::EDGE ? Path_point::EDGE : Path_point::FACE);
    p.t = FT(0);
    p.barycentric = {{FT(0), FT(0), FT(0)}};
    if(l.kind == Location::VERTEX) {
      p.vertex = m_mesh.vertex_of(l.vertex);
      p.point = get(m_mesh.vertex_point_map(), p.vertex);
      return p;
    }
    const std::array<double, 3> x = m_tracer->position(l);
    const Geodesics_3::internal::Solver_mesh& cache = m_mesh.cache();
    if(cache.is_face_changed(l.kind == Location::EDGE ? l.halfedge / 3 : l.face)) {
      // a face the solver mesh split (at a degenerate neighbour): a point of the caller's face
      int f;
      std::array<double, 3> b;
      cache.mesh_face_point(l.kind == Location::EDGE ? l.halfedge / 3 : l.face, x, f, b);
      p.kind = Path_point::FACE;
      p.face = m_mesh.face_of(f);
      for(int k = 0; k < 3; ++k)
        p.barycentric[k] = FT(b[k]);
    } else if(l.kind == Location::EDGE) {
      p.halfedge = m_mesh.halfedge_of(l.halfedge);
      p.t = FT(l.t);
    } else {
      p.face = m_mesh.face_of(l.face);
      for(int k = 0; k < 3; ++k)
        p.barycentric[k] = FT(l.barycentric[k]);
    }
    p.point = Point_3(m_mesh.to_mesh_unit(x[0]), m_mesh.to_mesh_unit(x[1]), m_mesh.to_mesh_unit(x[2]));
    return p;
  }

  // Solver and tracer on the heap, like the solver mesh, so that their references survive a
  // move of this object.
  Mesh_setup m_mesh;
  std::vector<Geodesics_3::internal::Source_point> m_sources;
  std::unique_ptr<Geodesics_3::internal::Exact_window_build> m_build; // the windows of the last build
  std::unique_ptr<Geodesics_3::internal::Geodesic_path_tracer> m_tracer;
  Geodesic_statistics m_statistics;
};

} // namespace CGAL_ext

#endif // CGAL_EXT_SURFACE_MESH_GEODESIC_PATHS_H
