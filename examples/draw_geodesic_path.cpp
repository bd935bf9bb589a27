// Draws shortest geodesic paths on a mesh: computes the paths from one source vertex to a few
// targets with CGAL_ext::Surface_mesh_geodesic_paths and writes ONE coloured PLY file holding the
// mesh (shaded by geodesic distance, pale) and each path as a thin tube of triangles in its own
// colour, so that any viewer (MeshLab, ParaView, Blender, ...) shows the paths on the surface.
// The file is then read back and checked.
// Usage: draw_geodesic_path [output.ply] [mesh.off]
//        (defaults: geodesic_paths.ply in the current directory, data/elephant.off)
#include <CGAL_ext/Surface_mesh_geodesic_paths.h>
#include "example_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;
typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh> Geodesic_paths;
typedef Mesh::Property_map<vertex_descriptor, CGAL::IO::Color> Color_map;

namespace {

Vector_3 normalized(const Vector_3& v) { return v / std::sqrt(v.squared_length()); }

// Adds to `out` a tube of radius `r` around the polyline `p`, with closed ends, coloured `color`:
// a ring of `sides` vertices at each point, turned along the polyline by parallel transport so that
// the tube does not twist.
void add_tube(const std::vector<Point_3>& p, double r, const CGAL::IO::Color& color, Mesh& out, Color_map colors)
{
  const int sides = 8;
  const double pi = std::acos(-1.);
  const std::size_t n = p.size();
  if(n < 2)
    return;
  std::vector<std::vector<vertex_descriptor>> rings(n);
  Vector_3 normal;
  for(std::size_t i = 0; i < n; ++i) {
    // the tangent at a point: the mean of the directions of its two segments
    Vector_3 t = CGAL::NULL_VECTOR;
    if(i > 0)
      t = t + normalized(p[i] - p[i - 1]);
    if(i + 1 < n)
      t = t + normalized(p[i + 1] - p[i]);
    t = normalized(t);
    if(i == 0) { // any direction orthogonal to the first tangent
      const Vector_3 axis = std::abs(t.x()) < 0.9 ? Vector_3(1, 0, 0) : Vector_3(0, 1, 0);
      normal = normalized(CGAL::cross_product(t, axis));
    } else { // the previous normal, made orthogonal to the new tangent
      normal = normalized(normal - (normal * t) * t);
    }
    const Vector_3 binormal = CGAL::cross_product(t, normal);
    for(int k = 0; k < sides; ++k) {
      const double a = 2 * pi * k / sides;
      const vertex_descriptor v = out.add_vertex(p[i] + r * (std::cos(a) * normal + std::sin(a) * binormal));
      colors[v] = color;
      rings[i].push_back(v);
    }
  }
  for(std::size_t i = 0; i + 1 < n; ++i)
    for(int k = 0; k < sides; ++k) {
      const int l = (k + 1) % sides;
      out.add_face(rings[i][k], rings[i + 1][k], rings[i + 1][l]);
      out.add_face(rings[i][k], rings[i + 1][l], rings[i][l]);
    }
  // end caps: a fan around the end point
  for(std::size_t i : {std::size_t(0), n - 1}) {
    const vertex_descriptor c = out.add_vertex(p[i]);
    colors[c] = color;
    for(int k = 0; k < sides; ++k) {
      const int l = (k + 1) % sides;
      if(i == 0)
        out.add_face(c, rings[i][l], rings[i][k]);
      else
        out.add_face(c, rings[i][k], rings[i][l]);
    }
  }
}

// A pale colour from white-blue (near the source) to sand (far away), so that the paths stand out.
CGAL::IO::Color distance_color(double x)
{
  x = std::clamp(x, 0., 1.);
  const std::array<double, 3> near{{200, 215, 245}}, far{{245, 225, 185}};
  return CGAL::IO::Color((unsigned char)(near[0] + x * (far[0] - near[0])),
                         (unsigned char)(near[1] + x * (far[1] - near[1])),
                         (unsigned char)(near[2] + x * (far[2] - near[2])));
}

} // namespace

int main(int argc, char** argv)
{
  const std::string output = argc > 1 ? argv[1] : std::string("geodesic_paths.ply");
  Mesh mesh;
  if(!read_example_mesh(argc, argv, 2, mesh))
    return EXIT_FAILURE;

  // The output starts as a copy of the mesh, coloured by the distance from the source.
  Mesh out = mesh;
  Color_map colors = out.add_property_map<vertex_descriptor, CGAL::IO::Color>("v:color").first;
  std::size_t paths_drawn = 0;
  try {
    const vertex_descriptor source(0);
    Geodesic_paths paths(mesh);
    paths.add_source(source);
    paths.build();

    double farthest_distance = 0;
    vertex_descriptor farthest = source;
    for(vertex_descriptor v : vertices(mesh))
      if(paths.distance(v) > farthest_distance)
        farthest_distance = paths.distance(v), farthest = v;
    for(vertex_descriptor v : vertices(mesh))
      colors[v] = distance_color(paths.distance(v) / farthest_distance);

    // Targets: the farthest vertex, a few vertices spread over the index range, and a face point.
    const std::size_t n = num_vertices(mesh);
    std::vector<vertex_descriptor> targets = {farthest};
    for(std::size_t k = 1; k <= 4; ++k)
      targets.push_back(vertex_descriptor(static_cast<Mesh::size_type>(k * n / 5)));
    const std::array<CGAL::IO::Color, 6> palette = {
      {CGAL::IO::Color(200, 20, 20), CGAL::IO::Color(20, 140, 20), CGAL::IO::Color(30, 60, 200),
       CGAL::IO::Color(230, 130, 0), CGAL::IO::Color(140, 30, 160), CGAL::IO::Color(0, 150, 160)}};

    CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    const double radius = 0.004 * diagonal;

    auto draw = [&](const std::vector<Point_3>& raw) {
      // consecutive points closer than round-off (a path through a vertex) would give no tangent
      std::vector<Point_3> points;
      for(const Point_3& q : raw)
        if(points.empty() || CGAL::squared_distance(points.back(), q) > CGAL::square(1e-9 * diagonal))
          points.push_back(q);
      add_tube(points, radius, palette[paths_drawn % palette.size()], out, colors);
      double length = 0;
      for(std::size_t i = 1; i < points.size(); ++i)
        length += std::sqrt(CGAL::squared_distance(points[i - 1], points[i]));
      std::cout << "path " << paths_drawn << ": " << raw.size() << " points, length " << length << "\n";
      ++paths_drawn;
    };
    for(vertex_descriptor t : targets) {
      std::vector<Point_3> points;
      paths.shortest_path_points(t, std::back_inserter(points));
      draw(points);
    }
    std::vector<Point_3> points;
    paths.shortest_path_points(Geodesic_paths::Face_location(face_descriptor(100), {{0.2, 0.3, 0.5}}),
                               std::back_inserter(points));
    draw(points);
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  {
    std::ofstream file(output);
    if(!file || !CGAL::IO::write_PLY(file, out, "geodesic paths drawn as tubes by draw_geodesic_path") || !file.flush()) {
      std::cerr << "error: cannot write " << output << "\n";
      return EXIT_FAILURE;
    }
  }

  // Read the file back: the same numbers of vertices and faces, and the colours.
  Mesh check;
  std::ifstream in(output);
  if(!in || !CGAL::IO::read_PLY(in, check)) {
    std::cerr << "error: cannot read back " << output << "\n";
    return EXIT_FAILURE;
  }
  const auto read_colors = check.property_map<vertex_descriptor, CGAL::IO::Color>("v:color");
  if(num_vertices(check) != num_vertices(out) || num_faces(check) != num_faces(out) || !read_colors.second) {
    std::cerr << "error: " << output << " reads back as " << num_vertices(check) << " vertices and "
              << num_faces(check) << " faces" << (read_colors.second ? "" : " without colours") << ", wrote "
              << num_vertices(out) << " and " << num_faces(out) << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << output << ": the mesh (" << num_faces(mesh) << " faces) and " << paths_drawn
            << " paths as tubes, " << num_vertices(out) << " vertices and " << num_faces(out) << " faces in all\n";
  return EXIT_SUCCESS;
}
