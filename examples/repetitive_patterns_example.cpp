// Repetitive pattern detection from one marked instance: a plane with round bumps laid out
// irregularly is built here, one bump is marked by its centre and radius, and every other bump
// is found, with its centre, its scale, its energy and its neighbours in the arrangement.
// Usage: repetitive_patterns_example [mesh.off vertex radius]   (default: the plane built here)
#include <CGAL_ext/detect_repetitive_patterns.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <array>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;

// A 100 x 100 grid of the unit square with smooth bumps of radius 0.07 at these centres.
Mesh bumpy_plane(const std::vector<std::array<double, 2>>& centres, double radius)
{
  Mesh mesh;
  const int n = 100;
  CGAL::make_grid(n, n, mesh, [n](int i, int j) { return Point(double(i) / n, double(j) / n, 0); }, true);
  for(vertex_descriptor v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    double z = 0;
    for(const auto& c : centres) {
      const double s = ((p.x() - c[0]) * (p.x() - c[0]) + (p.y() - c[1]) * (p.y() - c[1])) / (radius * radius);
      if(s < 1)
        z += 0.4 * radius * (1 - s) * (1 - s);
    }
    mesh.point(v) = Point(p.x(), p.y(), z);
  }
  return mesh;
}

int main(int argc, char** argv)
{
  Mesh mesh;
  vertex_descriptor centre;
  double radius = 0.07;
  if(argc >= 4) {
    if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh)) {
      std::cerr << "error: cannot read a triangle mesh from " << argv[1] << "\n";
      return EXIT_FAILURE;
    }
    centre = vertex_descriptor(std::stoi(argv[2]));
    radius = std::stod(argv[3]);
  } else {
    const std::vector<std::array<double, 2>> centres = {{0.2, 0.2}, {0.45, 0.15}, {0.8, 0.2},  {0.15, 0.5},
                                                        {0.5, 0.45}, {0.75, 0.6}, {0.3, 0.8}, {0.62, 0.85}};
    mesh = bumpy_plane(centres, radius);
    centre = vertex_descriptor(20 * 101 + 20); // the vertex at (0.2, 0.2)
  }
  try {
    // The marked instance: the vertices within geodesic distance `radius` of `centre`.
    CGAL_ext::Pattern_statistics st;
    const auto patterns = CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(
      mesh, CGAL_ext::Pattern_patch<Mesh>::disk(centre, radius), CGAL_ext::parameters::statistics(st));
    std::cout << patterns.instances.size() << " instances (the marked one first):\n";
    for(const auto& instance : patterns.instances)
      std::cout << "  centre vertex " << instance.center_vertex << " at (" << instance.center << "), scale "
                << instance.scale << ", energy " << instance.energy << ", " << instance.vertices.size()
                << " vertices\n";
    std::cout << "arrangement (neighbouring instances):";
    for(const auto& [a, b] : patterns.arrangement_edges)
      std::cout << " " << a << "-" << b;
    std::cout << "\n";
    std::cout << "seconds: sampling " << st.seconds_sampling << ", signatures " << st.seconds_signatures
              << ", matching " << st.seconds_matching << ", clustering " << st.seconds_clustering
              << ", optimization " << st.seconds_optimization << ", arrangement " << st.seconds_arrangement << "\n";
    return patterns.instances.size() >= 2 ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
