// Exact geodesic distance matrices on a bundled mesh: the square matrix among a few vertices,
// and local rows (every vertex within a radius) streamed one by one, the sources solved in
// parallel when TBB is linked.
// Usage: geodesic_distance_matrix_example [mesh.off]   (default: data/elephant.off)
#include <CGAL_ext/geodesic_distance_matrix.h>
#include "example_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
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
    // Four vertices spread over the mesh: the 4 x n matrix, then its 4 x 4 block among them.
    const std::size_t n = mesh.number_of_vertices();
    const std::vector<vertex_descriptor> samples = {vertex_descriptor(0), vertex_descriptor(std::uint32_t(n / 4)),
                                                    vertex_descriptor(std::uint32_t(n / 2)),
                                                    vertex_descriptor(std::uint32_t(3 * n / 4))};
    const std::vector<double> matrix =
      CGAL_ext::geodesic_distance_matrix<CGAL::Parallel_if_available_tag>(mesh, samples);
    std::cout << "geodesic distances among " << samples.size() << " vertices:\n";
    for(std::size_t i = 0; i < samples.size(); ++i) {
      for(vertex_descriptor t : samples)
        std::cout << "  " << matrix[i * n + std::size_t(t)];
      std::cout << "\n";
    }

    // Local rows: for each of 20 sources, the vertices within 0.05 (a sparse matrix row),
    // handed over in order as they are done.
    std::vector<vertex_descriptor> sources;
    for(std::size_t i = 0; i < 20; ++i)
      sources.push_back(vertex_descriptor(std::uint32_t(i * n / 20)));
    std::size_t entries = 0;
    CGAL_ext::geodesic_distance_rows<CGAL::Parallel_if_available_tag>(
      mesh, sources,
      [&](std::size_t, const std::vector<double>& row) {
        for(double d : row)
          entries += std::isfinite(d);
      },
      CGAL_ext::parameters::max_distance(0.05));
    std::cout << "20 local rows within 0.05: " << entries << " entries of " << 20 * n << "\n";
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
