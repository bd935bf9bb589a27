// Copyright (c) 2026 The CGAL_ext geodesics developers.
// What every example does first: read a triangle mesh from the file named on the command line,
// or the bundled elephant when none is named.
#ifndef CGAL_EXT_EXAMPLES_EXAMPLE_MESH_H
#define CGAL_EXT_EXAMPLES_EXAMPLE_MESH_H

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <iostream>
#include <string>

// Reads `argv[index]` (or data/elephant.off) into `mesh`; false, with a message, on failure.
template <class Mesh>
bool read_example_mesh(int argc, char** argv, int index, Mesh& mesh)
{
  const std::string filename = argc > index ? argv[index] : std::string(CGAL_EXT_DATA_DIR) + "/elephant.off";
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "error: cannot read a triangle mesh from " << filename << "\n";
    return false;
  }
  return true;
}

#endif // CGAL_EXT_EXAMPLES_EXAMPLE_MESH_H
