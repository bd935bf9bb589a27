// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_mesh.h"

#include "tool_error.h"
#include "tool_text.h"

#include <CGAL_ext/polygon_soup_to_geodesic_mesh.h>

#include <CGAL/IO/polygon_soup_io.h>

#include <filesystem>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace geodesic_tool {

Soup read_soup(const std::string& path)
{
  const std::string ext = lowercase_extension(path);
  Soup soup;
  std::vector<std::vector<std::size_t>> polygons; // as CGAL's readers make them
  if((ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl") || !std::filesystem::is_regular_file(path) ||
     !CGAL::IO::read_polygon_soup(path, soup.points, polygons))
    throw Tool_error("cannot read mesh '" + path + "'");
  if(ext == ".stl")
    soup.points_merged_when_read = 3 * polygons.size() - soup.points.size();
  soup.polygons = Polygons(polygons);
  return soup;
}

Mesh_file make_mesh_file(Soup soup)
{
  Mesh_file file;
  file.soup = std::move(soup);
  std::vector<Vertex_index> vertex_of_point;
  std::vector<Face_index> face_of_polygon;
  file.repairs = CGAL_ext::polygon_soup_to_geodesic_mesh(
    file.soup.points, file.soup.polygons, file.mesh, vertex_of_point, face_of_polygon,
    CGAL_ext::parameters::glued_vertices_output(std::back_inserter(file.glued_vertices)));
  file.repairs.merged_points += file.soup.points_merged_when_read;
  file.vertex_of_point = File_to_mesh<Vertex_index>(std::move(vertex_of_point));
  file.face_of_polygon = File_to_mesh<Face_index>(std::move(face_of_polygon));
#if defined(__GLIBC__)
  // The repair's temporaries are freed by now, but glibc keeps their pages; given back, they do
  // not stay under what the solver allocates next.
  malloc_trim(0);
#endif
  return file;
}

Mesh_file read_mesh_file(const std::string& path) { return make_mesh_file(read_soup(path)); }

} // namespace geodesic_tool
