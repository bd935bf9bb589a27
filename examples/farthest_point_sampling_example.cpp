// Exact geodesic farthest-point sampling on a bundled mesh: 16 samples, the covering radius
// after each, and the geodesic Voronoi cell of each sample (its nearest vertices).
// Usage: farthest_point_sampling_example [mesh.off]   (default: data/elephant.off)
#include <CGAL_ext/farthest_point_sampling.h>
#include "example_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
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
    std::vector<vertex_descriptor> samples;
    std::vector<double> radii;
    auto cell = mesh.add_property_map<vertex_descriptor, int>("v:cell", -1).first;
    // Each propagation in parallel when TBB is linked: the same samples for every thread count.
    CGAL_ext::farthest_point_sampling<CGAL::Parallel_if_available_tag>(
      mesh, 16, std::back_inserter(samples),
      CGAL_ext::parameters::covering_radius_output_iterator(std::back_inserter(radii)).vertex_source_map(cell));

    std::vector<std::size_t> cell_size(samples.size(), 0);
    for(vertex_descriptor v : mesh.vertices())
      ++cell_size[std::size_t(cell[v])];
    std::cout << "sample  vertex  covering radius after it  vertices in its cell\n";
    for(std::size_t k = 0; k < samples.size(); ++k)
      std::cout << k << "  " << samples[k] << "  " << radii[k] << "  " << cell_size[k] << "\n";
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
