// The exact geodesic Voronoi diagram of a few points of a bundled mesh: the size of each cell,
// the bisectors cut across faces, the Voronoi vertices and the dual (geodesic Delaunay) graph.
// Usage: geodesic_voronoi_example [mesh.off]   (default: data/elephant.off)
#include <CGAL_ext/geodesic_voronoi_diagram.h>
#include "example_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(!read_example_mesh(argc, argv, 1, mesh))
    return EXIT_FAILURE;
  try {
    // six sites: five vertices spread over the mesh and a point inside a face
    std::vector<std::pair<Mesh::Face_index, std::array<double, 3>>> sites;
    const std::size_t n = mesh.number_of_vertices();
    for(std::size_t i = 0; i < 5; ++i) {
      const vertex_descriptor v(std::uint32_t(i * n / 5));
      const auto h = mesh.halfedge(v); // v is the target of h: the third corner of face(h)'s order below
      const Mesh::Face_index f = mesh.face(mesh.is_border(h) ? mesh.opposite(h) : h);
      std::array<double, 3> b{{0., 0., 0.}};
      int k = 0;
      for(auto g : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
        b[std::size_t(k++)] = mesh.source(g) == v ? 1. : 0.;
      sites.emplace_back(f, b);
    }
    sites.emplace_back(Mesh::Face_index(std::uint32_t(mesh.number_of_faces() / 3)), std::array<double, 3>{{0.2, 0.3, 0.5}});

    // each vertex's cell (the index of its nearest site) comes back through a property map
    auto cell = mesh.add_property_map<Mesh::Vertex_index, std::size_t>("v:cell").first;
    CGAL_ext::Geodesic_statistics statistics;
    const auto diagram = CGAL_ext::geodesic_voronoi_diagram(
      mesh, sites, CGAL_ext::parameters::vertex_source_map(cell).statistics(statistics));
    std::vector<std::size_t> cell_size(sites.size(), 0);
    for(Mesh::Vertex_index v : vertices(mesh))
      if(cell[v] != CGAL_ext::no_source)
        ++cell_size[cell[v]];
    std::cout << statistics.windows_created << " windows propagated\n";
    for(std::size_t i = 0; i < sites.size(); ++i)
      std::cout << "cell " << i << ": " << cell_size[i] << " vertices\n";
    for(const auto& b : diagram.bisectors)
      std::cout << "bisector " << b.first_source << "-" << b.second_source << ": " << b.points.size()
                << " points, from " << b.points.front().point << " to " << b.points.back().point << "\n";
    for(const auto& v : diagram.vertices)
    {
      std::cout << "Voronoi vertex of";
      for(std::size_t s : v.sources)
        std::cout << " " << s;
      std::cout << " at " << v.point.point << "\n";
    }
    std::cout << "dual graph: " << diagram.dual_edges.size() << " edges, " << diagram.dual_triangles.size()
              << " triangles\n";
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
