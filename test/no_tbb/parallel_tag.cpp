// Built without TBB, asking for CGAL::Parallel_tag must not compile, with a clear message
// (the test that builds this file expects the build to fail with "needs TBB").
#include <CGAL_ext/geodesic_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

int main()
{
  Mesh mesh;
  auto d = mesh.add_property_map<Mesh::Vertex_index, double>("v:d", 0.).first;
  CGAL_ext::geodesic_distances<CGAL::Parallel_tag>(mesh, d, Mesh::Vertex_index(0));
}
