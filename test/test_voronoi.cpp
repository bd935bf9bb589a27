// The exact geodesic Voronoi diagram, read from FWP-MMP's windows and from VTP's: bisector
// points equidistant from their two sources (by single-source MMP queries at those surface
// points) with no third source nearer, Voronoi vertices equidistant from three, every vertex in
// its nearest cell, the dual graph; the analytic answer on a flat square; a cell that holds no
// vertex of the mesh.
#include "support/analytic_surfaces.h"
#include "support/checks.h"
#include "support/mesh_transformations.h"

#include <CGAL_ext/Surface_mesh_geodesic_paths.h>
#include <CGAL_ext/geodesic_voronoi_diagram.h>

#include <limits>
#include <memory>
#include <random>
#include <set>
#include <vector>

namespace {

using namespace test_support;

typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh> Paths;

/// One single-source build per source: the distance from each source alone, anywhere.
std::vector<std::unique_ptr<Paths>> single_source_paths(const Mesh& m, const std::vector<Face_location>& sources)
{
  std::vector<std::unique_ptr<Paths>> single;
  for(const Face_location& s : sources) {
    single.push_back(std::make_unique<Paths>(m));
    single.back()->add_source(s);
    single.back()->build();
  }
  return single;
}

/// The face of a planar mesh (z = 0) that holds point p, with p's barycentric coordinates.
Face_location planar_location(const Mesh& m, const Point& p)
{
  for(Face f : faces(m)) {
    const auto c = face_corners(m, f);
    const K::Point_2 a(m.point(c[0]).x(), m.point(c[0]).y()), b(m.point(c[1]).x(), m.point(c[1]).y()),
      e(m.point(c[2]).x(), m.point(c[2]).y()), q(p.x(), p.y());
    const double area = CGAL::area(a, b, e);
    const double l0 = CGAL::area(q, b, e) / area, l1 = CGAL::area(a, q, e) / area, l2 = 1 - l0 - l1;
    if(l0 >= 0 && l1 >= 0 && l2 >= 0)
      return Face_location(f, Barycentric{{l0, l1, l2}});
  }
  return Face_location(Face(), Barycentric{{0., 0., 0.}});
}

/// `count` vertices spread over the mesh (from `offset`), and a point of a face, as sources.
std::vector<Face_location> spread_sources(const Mesh& m, int count, std::size_t offset, const Face_location& face_point)
{
  std::vector<Face_location> sources;
  for(Vertex v : spread_vertices(m, count, offset))
    sources.push_back(corner_location(m, v));
  sources.push_back(face_point);
  return sources;
}

template <class Diagram>
void expect_exact_diagram(const Mesh& m, const std::vector<Face_location>& sources, const Diagram& d,
                          const std::string& label)
{
  const double tolerance = 1e-9 * bbox_diagonal(m);
  const auto single = single_source_paths(m, sources);
  EXPECT_EQ(d.unresolved_parts, 0u) << label;
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  std::size_t points = 0;
  for(const auto& b : d.bisectors) {
    ASSERT_LT(b.first_source, b.second_source) << label;
    pairs.insert({b.first_source, b.second_source});
    for(const auto& p : b.points) {
      ++points;
      const double da = single[b.first_source]->distance(p.location);
      const double db = single[b.second_source]->distance(p.location);
      EXPECT_NEAR(da, db, tolerance) << label << ": bisector " << b.first_source << "-" << b.second_source;
      for(std::size_t k = 0; k < sources.size(); ++k)
        if(k != b.first_source && k != b.second_source)
          EXPECT_GE(single[k]->distance(p.location), std::min(da, db) - tolerance) << label << ": source " << k;
      EXPECT_LE(std::sqrt(CGAL::squared_distance(p.point, location_point(m, p.location))), tolerance) << label;
    }
  }
  EXPECT_GT(points, 0u) << label;
  const std::vector<std::pair<std::size_t, std::size_t>> bisector_pairs(pairs.begin(), pairs.end());
  EXPECT_EQ(bisector_pairs, d.dual_edges) << label;
  std::set<std::array<std::size_t, 3>> triples;
  for(const auto& v : d.vertices) {
    ASSERT_GE(v.sources.size(), 3u) << label;
    for(std::size_t i = 0; i < v.sources.size(); ++i)
      for(std::size_t j = i + 1; j < v.sources.size(); ++j)
        for(std::size_t k = j + 1; k < v.sources.size(); ++k)
          triples.insert({{v.sources[i], v.sources[j], v.sources[k]}});
    const double a = single[v.sources[0]]->distance(v.point.location);
    for(std::size_t s : v.sources)
      EXPECT_NEAR(single[s]->distance(v.point.location), a, tolerance) << label;
    for(std::size_t k = 0; k < sources.size(); ++k)
      EXPECT_GE(single[k]->distance(v.point.location), a - tolerance) << label << ": source " << k;
  }
  const std::vector<std::array<std::size_t, 3>> vertex_triples(triples.begin(), triples.end());
  EXPECT_EQ(vertex_triples, d.dual_triangles) << label;
  // the cell of each vertex is its nearest source (either of two within round-off), and its
  // distance the distance to it
  for(Vertex v : vertices(m)) {
    double nearest = std::numeric_limits<double>::infinity();
    for(const auto& s : single)
      nearest = std::min(nearest, s->distance(v));
    const std::size_t cell = d.vertex_cell[v.idx()];
    if(!(nearest < std::numeric_limits<double>::infinity())) {
      EXPECT_EQ(cell, CGAL_ext::no_source) << label << ": vertex " << v.idx();
      continue;
    }
    ASSERT_LT(cell, sources.size()) << label << ": vertex " << v.idx();
    EXPECT_LE(single[cell]->distance(v), nearest + tolerance) << label << ": vertex " << v.idx();
    EXPECT_NEAR(d.vertex_distance[v.idx()], nearest, tolerance) << label << ": vertex " << v.idx();
  }
}

/// The diagram read from FWP-MMP's windows, or from VTP's (the default).
auto diagram_of(const Mesh& m, const std::vector<Face_location>& sources, CGAL_ext::Geodesic_algorithm algorithm)
{
  return CGAL_ext::geodesic_voronoi_diagram(m, sources, CGAL_ext::parameters::algorithm(algorithm));
}

constexpr CGAL_ext::Geodesic_algorithm diagram_algorithms[] = {CGAL_ext::FWP_MMP, CGAL_ext::VTP};

std::string name_of(CGAL_ext::Geodesic_algorithm algorithm) { return algorithm == CGAL_ext::VTP ? " (VTP)" : " (FWP-MMP)"; }

TEST(Geodesic_voronoi, bisectors_and_vertices_are_exact_on_real_meshes)
{
  for(const char* name : {"elephant", "mushroom"}) {
    const Mesh& m = test_mesh(name);
    const std::vector<Face_location> sources =
      spread_sources(m, 5, 3, location(m.number_of_faces() / 3, 0.3, 0.3));
    const auto d = diagram_of(m, sources, CGAL_ext::FWP_MMP);
    expect_exact_diagram(m, sources, d, name);
    EXPECT_GE(d.vertices.size(), 2u) << name;
    // the diagram read from VTP's windows is exact too, and has the same cells and dual graph
    const auto v = diagram_of(m, sources, CGAL_ext::VTP);
    expect_exact_diagram(m, sources, v, name + name_of(CGAL_ext::VTP));
    EXPECT_EQ(v.dual_edges, d.dual_edges) << name;
    EXPECT_EQ(v.dual_triangles, d.dual_triangles) << name;
    // the default is VTP's
    const auto by_default = CGAL_ext::geodesic_voronoi_diagram(m, sources);
    EXPECT_EQ(by_default.vertex_distance, v.vertex_distance) << name;
    EXPECT_EQ(by_default.vertex_cell, v.vertex_cell) << name;
    EXPECT_EQ(by_default.dual_edges, v.dual_edges) << name;
    // PMMP and PVTP give the same diagram for every thread count (FWP_MMP with Parallel_tag: PMMP)
    for(int threads : {1, 2}) {
      for(CGAL_ext::Geodesic_algorithm algorithm : diagram_algorithms) {
        const auto p = CGAL_ext::geodesic_voronoi_diagram<CGAL::Parallel_tag>(
          m, sources, CGAL_ext::parameters::number_of_threads(threads).algorithm(algorithm));
        EXPECT_EQ(p.dual_edges, d.dual_edges) << name << ", " << threads << " threads";
        EXPECT_EQ(p.dual_triangles, d.dual_triangles) << name << ", " << threads << " threads";
        EXPECT_EQ(p.vertex_cell, d.vertex_cell) << name << ", " << threads << " threads";
      }
    }
  }
}

// The way the tracer says a point is reached (what the diagram's search of changes and of
// Voronoi vertices works from) comes from the point's nearest source and gives its distance:
// inside a face, and on an edge, where the winning way may come from the face beyond (unfolded
// across the edge); points are drawn anywhere, and in the face of a face-point source.
TEST(Geodesic_voronoi, the_way_a_point_is_reached_gives_its_distance)
{
  namespace internal = CGAL_ext::Geodesics_3::internal;
  const Mesh& m = test_mesh("elephant");
  internal::Solver_mesh cache;
  internal::build_solver_mesh(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m), get(CGAL::face_index, m), cache);
  const internal::Solver_settings settings =
    internal::read_solver_settings(CGAL_ext::parameters::default_values(), CGAL_ext::FWP_MMP);
  internal::MMP_solver solver(cache, settings, false);
  for(Vertex v : spread_vertices(m, 12, 5)) {
    internal::Source_point s;
    s.vertex = cache.cache_vertex(int(v.idx()));
    solver.add_source(s);
  }
  internal::Source_point in_face;
  in_face.face = int(cache.number_of_faces / 2);
  in_face.barycentric = {{0.2, 0.5, 0.3}};
  solver.add_source(in_face);
  solver.run();
  const internal::Geodesic_path_tracer tracer(solver.windows(), solver.distances(), solver.nearest_sources(),
                                              solver.sources(), solver.max_distance());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0., 1.);
  std::uniform_int_distribution<int> face(0, int(cache.number_of_faces) - 1);
  std::size_t edge_points = 0;
  for(int i = 0; i < 4000; ++i) {
    const int f = i % 8 == 0 ? in_face.face : face(rng);
    std::array<double, 3> b{{u(rng), u(rng), u(rng)}};
    if(i % 2 == 1)
      b[std::size_t(i % 3)] = 0; // a point of an edge
    const double sum = b[0] + b[1] + b[2];
    for(double& c : b)
      c /= sum;
    const internal::Surface_location p = internal::surface_location(cache, f, b);
    int nearest = -1;
    const double d = tracer.distance(p, nearest);
    ASSERT_GE(nearest, 0);
    const internal::Geodesic_path_tracer::Planar_way way = tracer.way_at(p, f, b, nearest);
    EXPECT_EQ(way.source, nearest) << "face " << f << ", point " << i;
    EXPECT_NEAR(way.distance, d, 1e-12 * (d + cache.mean_edge_length)) << "face " << f << ", point " << i;
    edge_points += p.kind == internal::Surface_location::EDGE;
    const std::array<double, 2> x = cache.point_in_frame(3 * f, b), c = cache.point_in_frame(3 * f, way.centre);
    EXPECT_NEAR(way.sigma + std::hypot(x[0] - c[0], x[1] - c[1]), d, 1e-12 * (d + cache.mean_edge_length))
      << "face " << f << ", point " << i;
  }
  EXPECT_GT(edge_points, 1000u);
}

// On a flat square the bisectors are straight: every point is at equal Euclidean distance from
// its two sources, and three sources meet at their circumcentre.
TEST(Geodesic_voronoi, a_flat_square_has_straight_bisectors_and_the_circumcentre)
{
  const Mesh m = make_grid(11, 0.1, 0.2);
  const std::vector<Point> site{Point(0.21, 0.23, 0), Point(0.77, 0.31, 0), Point(0.45, 0.81, 0)};
  std::vector<Face_location> sources;
  for(const Point& s : site)
    sources.push_back(planar_location(m, s));
  ASSERT_EQ(sources.size(), 3u);
  for(std::size_t count : {2, 3})
    for(CGAL_ext::Geodesic_algorithm algorithm : diagram_algorithms) {
      const std::vector<Face_location> some(sources.begin(), sources.begin() + std::ptrdiff_t(count));
      const auto d = diagram_of(m, some, algorithm);
      expect_exact_diagram(m, some, d, std::to_string(count) + " sources" + name_of(algorithm));
      for(const auto& b : d.bisectors)
        for(const auto& p : b.points)
          EXPECT_NEAR(std::sqrt(CGAL::squared_distance(p.point, site[b.first_source])),
                      std::sqrt(CGAL::squared_distance(p.point, site[b.second_source])), 1e-12);
      if(count == 2) {
        EXPECT_TRUE(d.vertices.empty());
        EXPECT_EQ(d.bisectors.size(), 1u) << "one straight bisector across the square";
      } else {
        ASSERT_EQ(d.vertices.size(), 1u);
        const Point centre = CGAL::circumcenter(site[0], site[1], site[2]);
        EXPECT_LE(std::sqrt(CGAL::squared_distance(d.vertices[0].point.point, centre)), 1e-9);
        EXPECT_EQ(d.bisectors.size(), 3u) << "three bisectors from the circumcentre";
      }
    }
}

// Four sources at the corners of a square on a flat grid: the four cells meet at its centre, one
// Voronoi vertex of four cells, with four straight bisectors. (The centre and the bisectors are
// kept off the grid's vertices and edges.) Which three cells round-off lets meet first differs
// from one centre to another; the vertex is of all four every time.
TEST(Geodesic_voronoi, four_cells_meet_at_the_centre_of_a_square)
{
  const Mesh m = make_grid(9, 0.125);
  for(const Point& centre : {Point(0.53, 0.47, 0), Point(0.51, 0.46, 0), Point(0.455, 0.535, 0)})
    for(CGAL_ext::Geodesic_algorithm algorithm : diagram_algorithms) {
      SCOPED_TRACE(centre);
      SCOPED_TRACE(name_of(algorithm));
      std::vector<Face_location> sources;
      for(const auto& [dx, dy] : {std::make_pair(-0.2, -0.2), std::make_pair(0.2, -0.2), std::make_pair(0.2, 0.2),
                                  std::make_pair(-0.2, 0.2)})
        sources.push_back(planar_location(m, Point(centre.x() + dx, centre.y() + dy, 0)));
      const auto d = diagram_of(m, sources, algorithm);
      expect_exact_diagram(m, sources, d, "four symmetric sources");
      ASSERT_EQ(d.vertices.size(), 1u);
      EXPECT_EQ(d.vertices[0].sources, (std::vector<std::size_t>{0, 1, 2, 3}));
      EXPECT_LE(std::sqrt(CGAL::squared_distance(d.vertices[0].point.point, centre)), 1e-9);
      EXPECT_EQ(d.bisectors.size(), 4u);
      EXPECT_EQ(d.dual_triangles.size(), 4u) << "every three of the four";
    }
}

// The step behind the test above, on its own: a bisector of cells a and b that ends at a vertex of
// a makes the vertex one of b, and a cell so gained lets its own bisectors at that point in.
TEST(Geodesic_voronoi, a_vertex_takes_the_cells_of_the_bisectors_that_end_at_it)
{
  using namespace CGAL_ext::Geodesics_3::internal;
  std::vector<Voronoi_vertex_found> vertices(2);
  vertices[0].sources = {0, 1, 3};
  vertices[1].sources = {5, 6, 7};
  const std::vector<std::array<double, 3>> vertex_point{{{0., 0., 0.}}, {{10., 0., 0.}}};
  std::vector<Bisector_piece> pieces;
  std::vector<std::array<double, 3>> first, last;
  auto piece = [&](int a, int b, std::array<double, 3> from, std::array<double, 3> to) {
    Bisector_piece p;
    p.first_source = a;
    p.second_source = b;
    pieces.push_back(p);
    first.push_back(from);
    last.push_back(to);
  };
  piece(2, 4, {{0., -1., 0.}}, {{0., 1e-12, 0.}}); // reaches vertex 0 through cell 2 only
  piece(1, 2, {{1e-12, 0., 0.}}, {{0., 1., 0.}});  // brings cell 2 to vertex 0
  piece(3, 8, {{5., 5., 0.}}, {{6., 6., 0.}});     // ends at no vertex
  piece(0, 9, {{0., 1e-3, 0.}}, {{0., 2., 0.}});   // ends near vertex 0, beyond the tolerance
  piece(2, 5, {{9., 0., 0.}}, {{10., 0., 1e-12}}); // ends at vertex 1, a vertex of cell 5
  add_cells_of_bisector_ends(pieces, first, last, vertices, vertex_point, 1e-9);
  EXPECT_EQ(vertices[0].sources, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(vertices[1].sources, (std::vector<int>{2, 5, 6, 7}));
}

// A face point at the middle of a face, with three others around it in the same face: its cell
// is a small triangle inside the face, holding no vertex of the mesh, and is still found (three
// bisectors around it, three Voronoi vertices, and its place in the dual graph).
TEST(Geodesic_voronoi, a_cell_without_any_vertex_is_found)
{
  const Mesh m = make_grid(6, 0.2);
  const Face f(7);
  const std::vector<Face_location> sources{corner_location(m, Vertex(0)),
                                           {f, Barycentric{{1. / 3, 1. / 3, 1. / 3}}},
                                           {f, Barycentric{{0.4, 0.3, 0.3}}},
                                           {f, Barycentric{{0.3, 0.4, 0.3}}},
                                           {f, Barycentric{{0.3, 0.3, 0.4}}}};
  for(CGAL_ext::Geodesic_algorithm algorithm : diagram_algorithms) {
    SCOPED_TRACE(name_of(algorithm));
    const auto d = diagram_of(m, sources, algorithm);
    expect_exact_diagram(m, sources, d, "a cell inside a face");
    EXPECT_EQ(std::count(d.vertex_cell.begin(), d.vertex_cell.end(), std::size_t(1)), 0) << "a cell without vertices";
    for(std::size_t other : {2, 3, 4})
      EXPECT_TRUE(std::count(d.dual_edges.begin(), d.dual_edges.end(), std::make_pair(std::size_t(1), other)))
        << "cells 1 and " << other << " share a bisector";
    std::size_t around = 0;
    for(const auto& v : d.vertices)
      around += std::count(v.sources.begin(), v.sources.end(), std::size_t(1));
    EXPECT_EQ(around, 3u) << "three Voronoi vertices around the small cell";
  }
}

// A point one snap (1e-12) from a vertex, on an edge, is as far as the vertex (within its
// offset): the tracer once skipped the vertex there without snapping the point onto it.
TEST(Geodesic_voronoi, a_point_at_the_snap_distance_from_a_vertex_is_measured_through_it)
{
  const Mesh& m = test_mesh("elephant");
  Paths paths(m);
  paths.add_source(Vertex(0));
  paths.add_source(Vertex(1000));
  paths.build();
  for(Face f : {Face(3506), Face(100), Face(4000)}) {
    const Vertex v = source(halfedge(f, m), m);
    for(const Barycentric& b : {Barycentric{{1 - 1e-12, 1e-12, 0}}, Barycentric{{1 - 1e-12, 0, 1e-12}}})
      EXPECT_NEAR(paths.distance(Face_location(f, b)), paths.distance(v), 1e-11) << "face " << f.idx();
  }
}

// A source alone in its connected component: its cell is the whole component, with no bisector
// to the sources of the other component; the diagram of the other component is as without it.
TEST(Geodesic_voronoi, a_source_alone_in_its_component_owns_it)
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  for(int c = 0; c < 2; ++c) {
    const int o = int(points.size());
    for(int j = 0; j <= 6; ++j)
      for(int i = 0; i <= 6; ++i)
        points.push_back(Point(i / 6. + 5 * c, j / 6., 0.1 * std::sin(i + j)));
    for(int j = 0; j < 6; ++j)
      for(int i = 0; i < 6; ++i)
        add_quad(triangles, o + j * 7 + i, o + j * 7 + i + 1, o + (j + 1) * 7 + i + 1, o + (j + 1) * 7 + i, (i + j) % 2 == 0);
  }
  const Mesh m = mesh_from_soup(points, triangles);
  const std::vector<Face_location> sources{corner_location(m, Vertex(0)), corner_location(m, Vertex(48)),
                                           corner_location(m, Vertex(49 + 24))};
  for(CGAL_ext::Geodesic_algorithm algorithm : diagram_algorithms) {
    SCOPED_TRACE(name_of(algorithm));
    const auto d = diagram_of(m, sources, algorithm);
    expect_exact_diagram(m, sources, d, "two components");
    for(std::size_t v = 49; v < 98; ++v)
      EXPECT_EQ(d.vertex_cell[v], 2u) << "vertex " << v;
    EXPECT_EQ(d.dual_edges, (std::vector<std::pair<std::size_t, std::size_t>>{{0, 1}}));
    EXPECT_TRUE(d.vertices.empty());
  }
}

// Meshes the package has never seen: the elephant scaled by 1e-3 and 1e3, subdivided,
// jittered, cut open, and with a copy of the mushroom as a second component (sources in both): the
// diagram stays exact, its cells the labels of one propagation.
TEST(Geodesic_voronoi, exact_on_transformed_and_disconnected_meshes)
{
  const Mesh& elephant = test_mesh("elephant");
  auto sources_of = [](const Mesh& m) { return spread_sources(m, 4, 11, location(m.number_of_faces() - 10, 0.25, 0.4)); };
  for(CGAL_ext::Geodesic_algorithm algorithm : diagram_algorithms) {
    for(Transform t : {SCALED_DOWN, SCALED_UP, LOOP_SUBDIVIDED, JITTERED, CUT_OPEN}) {
      const Mesh m = transformed(elephant, t);
      const std::vector<Face_location> sources = sources_of(m);
      expect_exact_diagram(m, sources, diagram_of(m, sources, algorithm),
                           std::string("elephant ") + transform_names[t] + name_of(algorithm));
    }
    const Mesh both = disjoint_union({&elephant, &test_mesh("mushroom")});
    const std::vector<Face_location> sources = sources_of(both);
    ASSERT_LT(sources.front().first.idx(), elephant.number_of_faces());
    ASSERT_GE(sources.back().first.idx(), elephant.number_of_faces());
    expect_exact_diagram(both, sources, diagram_of(both, sources, algorithm), "elephant and mushroom" + name_of(algorithm));
  }
}

TEST(Geodesic_voronoi, bad_requests_are_named)
{
  const Mesh& m = test_mesh("elephant");
  EXPECT_TRUE(throws_geodesic_error([&] { CGAL_ext::geodesic_voronoi_diagram(m, std::vector<Vertex>{}); },
                                    {"no source"}));
  EXPECT_TRUE(throws_geodesic_error(
    [&] {
      CGAL_ext::geodesic_voronoi_diagram(m, Vertex(0), CGAL_ext::parameters::algorithm(CGAL_ext::VTP).approximation(4.));
    },
    {"approximation"}));
  EXPECT_TRUE(throws_geodesic_error(
    [&] {
      CGAL_ext::geodesic_voronoi_diagram(m, Vertex(0),
                                         CGAL_ext::parameters::algorithm(CGAL_ext::VTP).stop_vertices(std::vector<Vertex>{Vertex(5)}));
    },
    {"stop_vertices"}));
  EXPECT_TRUE(throws_geodesic_error(
    [&] { CGAL_ext::geodesic_voronoi_diagram(m, Vertex(0), CGAL_ext::parameters::max_distance(1.)); }, {"max_distance"}));
  EXPECT_TRUE(throws_geodesic_error([&] { CGAL_ext::geodesic_voronoi_diagram(m, Vertex(9999)); }, {"out of range"}));
}

} // namespace
