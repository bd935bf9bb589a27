// Distances on a unit right triangle from its right-angle corner: 0, 1, 1.
#include <CGAL_ext/geodesic_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

int main()
{
  Mesh mesh;
  const auto a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({1, 0, 0}), c = mesh.add_vertex({0, 1, 0});
  mesh.add_face(a, b, c);
  auto distance = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance", -1.).first;
  CGAL_ext::geodesic_distances(mesh, distance, a);
  const bool ok = distance[a] == 0 && std::abs(distance[b] - 1) < 1e-15 && std::abs(distance[c] - 1) < 1e-15;
  std::cout << distance[a] << " " << distance[b] << " " << distance[c] << "\n";
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
