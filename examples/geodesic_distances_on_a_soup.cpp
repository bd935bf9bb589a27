// Exact geodesic distances on the meshes users have (STL files, polygon soups, quads, non-manifold
// meshes), made into a triangle mesh by CGAL_ext::polygon_soup_to_geodesic_mesh.
// Usage: geodesic_distances_on_a_soup [mesh.stl|.off|.obj|.ply]
//   (default: data/elephant.off, taken apart into a soup of one triangle's points after another's,
//   as an STL file holds it)
#include <CGAL_ext/geodesic_distances.h>
#include <CGAL_ext/polygon_soup_to_geodesic_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <string>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef std::vector<std::vector<std::size_t>> Polygons;

// Gives each polygon its own copy of its points.
void take_apart(std::vector<Point>& points, Polygons& polygons)
{
  std::vector<Point> copies;
  for(auto& polygon : polygons)
    for(std::size_t& id : polygon) {
      copies.push_back(points[id]);
      id = copies.size() - 1;
    }
  points.swap(copies);
}

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : std::string(CGAL_EXT_DATA_DIR) + "/elephant.off";
  std::vector<Point> points;
  Polygons polygons;
  if(!CGAL::IO::read_polygon_soup(filename, points, polygons)) {
    std::cerr << "error: cannot read " << filename << "\n";
    return EXIT_FAILURE;
  }
  if(argc <= 1)
    take_apart(points, polygons);

  try {
    // vertex_of_point[i]: the vertex of input point i (merged points share one)
    Mesh mesh;
    std::vector<vertex_descriptor> vertex_of_point;
    std::vector<std::vector<vertex_descriptor>> glued; // copies of a point at a non-manifold vertex or edge
    const CGAL_ext::Geodesic_mesh_repairs repairs = CGAL_ext::polygon_soup_to_geodesic_mesh(
      points, polygons, mesh, vertex_of_point, CGAL_ext::parameters::glued_vertices_output(std::back_inserter(glued)));
    std::cout << points.size() << " points and " << polygons.size() << " polygons: a mesh of "
              << mesh.number_of_vertices() << " vertices and " << mesh.number_of_faces() << " triangles\n";
    if(!repairs.summary().empty())
      std::cout << "  " << repairs.summary() << "\n";

    auto distance = mesh.add_property_map<vertex_descriptor, double>("v:distance", 0.).first;
    CGAL_ext::geodesic_distances(mesh, distance, vertex_of_point[0], CGAL_ext::parameters::glued_vertices(glued));

    // every input point has its distance
    std::size_t farthest = 0;
    for(std::size_t i = 0; i < points.size(); ++i) {
      const double d = distance[vertex_of_point[i]];
      if(std::isfinite(d) && d > distance[vertex_of_point[farthest]])
        farthest = i;
    }
    std::cout << "from point 0: the farthest point is point " << farthest << " at "
              << distance[vertex_of_point[farthest]] << "\n";
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
