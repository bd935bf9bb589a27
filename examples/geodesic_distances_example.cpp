// Exact geodesic distances from one vertex and from a point inside a face, on a bundled mesh.
// Usage: geodesic_distances_example [mesh.off]   (default: data/elephant.off)
#include <CGAL_ext/geodesic_distances.h>
#include "example_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(!read_example_mesh(argc, argv, 1, mesh))
    return EXIT_FAILURE;
  auto distance = mesh.add_property_map<vertex_descriptor, double>("v:distance", 0.).first;

  try {
    // From one vertex, asking for the solver's statistics.
    CGAL_ext::Geodesic_statistics stats;
    CGAL_ext::geodesic_distances(mesh, distance, vertex_descriptor(0),
                                 CGAL_ext::parameters::statistics(stats));
    vertex_descriptor farthest = vertex_descriptor(0);
    for(vertex_descriptor v : vertices(mesh))
      if(distance[v] > distance[farthest])
        farthest = v;
    std::cout << "from vertex 0: farthest vertex " << farthest << " at " << distance[farthest] << "\n"
              << "  " << stats.windows_created << " windows in " << stats.seconds_solve << " s\n";

    // From two points inside faces at once, only within a radius.
    std::vector<std::pair<face_descriptor, std::array<double, 3>>> points = {
      {face_descriptor(0), {{1. / 3, 1. / 3, 1. / 3}}}, {face_descriptor(100), {{0.2, 0.3, 0.5}}}};
    auto distance2 = mesh.add_property_map<vertex_descriptor, double>("v:distance2", 0.).first;
    CGAL_ext::geodesic_distances(mesh, distance2, points,
                                 CGAL_ext::parameters::max_distance(0.2));
    std::size_t within = 0;
    for(vertex_descriptor v : vertices(mesh))
      if(distance2[v] <= 0.2)
        ++within;
    std::cout << "from two face points: " << within << " vertices within 0.2\n";
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
