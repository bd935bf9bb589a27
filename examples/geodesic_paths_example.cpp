// Exact geodesic distances at any surface point, the nearest of several sources, and shortest
// paths, with CGAL_ext::Surface_mesh_geodesic_paths.
// Usage: geodesic_paths_example [mesh.off]   (default: data/elephant.off)
#include <CGAL_ext/Surface_mesh_geodesic_paths.h>
#include "example_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Halfedge_index halfedge_descriptor;
typedef Mesh::Face_index face_descriptor;
typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh> Geodesic_paths;

// Prints where each point of a path lies on the mesh: at a vertex, on an edge, inside a face.
struct Print_path_point
{
  const Mesh* mesh;
  void operator()(vertex_descriptor v) const { std::cout << "    vertex " << v << "\n"; }
  void operator()(halfedge_descriptor h, double t) const
  {
    std::cout << "    edge " << mesh->source(h) << "-" << mesh->target(h) << " at t = " << t << "\n";
  }
  void operator()(face_descriptor f, const Geodesic_paths::Barycentric_coordinates& b) const
  {
    std::cout << "    face " << f << " at (" << b[0] << ", " << b[1] << ", " << b[2] << ")\n";
  }
};

int main(int argc, char** argv)
{
  Mesh mesh;
  if(!read_example_mesh(argc, argv, 1, mesh))
    return EXIT_FAILURE;
  const vertex_descriptor target(static_cast<Mesh::size_type>(num_vertices(mesh) / 2));
  const Geodesic_paths::Face_location face_point(face_descriptor(100), {{0.2, 0.3, 0.5}});

  try {
    // One source at vertex 0; build() computes the windows every query reads.
    Geodesic_paths paths(mesh);
    paths.add_source(vertex_descriptor(0));
    // VTP's windows; add .algorithm(CGAL_ext::MMP) for classic MMP
    CGAL_ext::Geodesic_statistics statistics;
    paths.build(CGAL_ext::parameters::statistics(statistics));
    std::cout << "distance to vertex " << target << ": " << paths.distance(target) << "\n"
              << "distance to a point of face " << face_point.first << ": " << paths.distance(face_point) << "\n"
              << "(" << statistics.windows_stored << " windows kept on the edges)\n";

    // The shortest path to the point of the face, as points from the source to the target.
    std::vector<Kernel::Point_3> polyline;
    paths.shortest_path_points(face_point, std::back_inserter(polyline));
    double length = 0;
    for(std::size_t i = 1; i < polyline.size(); ++i)
      length += std::sqrt(CGAL::squared_distance(polyline[i - 1], polyline[i]));
    std::cout << "shortest path to the point of face " << face_point.first << ": " << polyline.size()
              << " points, length " << length << "\n";

    // The same path as vertices, edge points and face points, with a visitor.
    paths.shortest_path_sequence(face_point, Print_path_point{&mesh});

    // Two sources: which one is the nearest, for a vertex and for a point of a face.
    Geodesic_paths two(mesh);
    two.add_source(vertex_descriptor(0));
    two.add_source(target);
    two.build();
    const vertex_descriptor v(static_cast<Mesh::size_type>(num_vertices(mesh) / 4));
    std::cout << "with sources at vertices 0 and " << target << ":\n"
              << "  vertex " << v << " is nearest to source " << two.nearest_source(v) << " (at " << two.distance(v)
              << ")\n"
              << "  the point of face " << face_point.first << " is nearest to source "
              << two.nearest_source(face_point) << " (at " << two.distance(face_point) << ")\n";
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
