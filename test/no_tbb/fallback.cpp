// Built without TBB: CGAL::Parallel_if_available_tag must fall back to the sequential solver
// and give exactly its distances.
#include <CGAL_ext/geodesic_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <iostream>
#include <type_traits>

#ifdef CGAL_LINKED_WITH_TBB
#error "this file must be built without TBB"
#endif
static_assert(std::is_same<CGAL::Parallel_if_available_tag, CGAL::Sequential_tag>::value,
              "without TBB, Parallel_if_available_tag is the sequential tag");

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

int main()
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(CGAL_EXT_DATA_DIR "/elephant.off", mesh))
    return EXIT_FAILURE;
  auto a = mesh.add_property_map<Mesh::Vertex_index, double>("v:a", -1.).first;
  auto b = mesh.add_property_map<Mesh::Vertex_index, double>("v:b", -2.).first;
  CGAL_ext::geodesic_distances<CGAL::Parallel_if_available_tag>(mesh, a, Mesh::Vertex_index(0));
  CGAL_ext::geodesic_distances<CGAL::Sequential_tag>(mesh, b, Mesh::Vertex_index(0));
  for(auto v : vertices(mesh))
    if(a[v] != b[v] || !(a[v] >= 0)) {
      std::cerr << "vertex " << v << ": " << a[v] << " != " << b[v] << "\n";
      return EXIT_FAILURE;
    }
  std::cout << "Parallel_if_available_tag without TBB: sequential, same distances\n";
  return EXIT_SUCCESS;
}
