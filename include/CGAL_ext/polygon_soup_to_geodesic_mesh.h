// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_POLYGON_SOUP_TO_GEODESIC_MESH_H
#define CGAL_EXT_POLYGON_SOUP_TO_GEODESIC_MESH_H

/// \file polygon_soup_to_geodesic_mesh.h
/// The triangle mesh the solvers take, made from the meshes users have: polygon soups (STL
/// files, one triangle's points after another's), quads and polygons, non-manifold meshes.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_mesh_repairs.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Soup_repair.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// makes the triangle mesh `tm`, which `geodesic_distances()` and `Surface_mesh_geodesic_paths`
/// take, from a polygon soup, and tells which vertex each input point became. Every step keeps
/// the surface, and so the geodesic distances, exactly (CGAL's Polygon_mesh_processing does
/// each one):
/// - in a soup (no point shared by two polygons, as in an STL file or a mesh saved face by face),
///   points at identical coordinates are merged into one vertex
///   (`merge_duplicate_points_in_polygon_soup()`); a mesh whose polygons share their points
///   keeps them as they are (two vertices at one place may be the two sides of a cut), unless
///   `merge_duplicate_points(true)` is given;
/// - repeated consecutive points of a polygon are dropped, a polygon passing twice through a
///   point is cut there into loops, and what has fewer than 3 points is removed (segments and
///   points have no area);
/// - the polygons are oriented consistently; where the surface is not a manifold (more than two
///   polygons on an edge, polygons meeting at a point only, orientation conflicts) points are
///   duplicated (`orient_polygon_soup()`). The named parameter `glued_vertices_output` gives the
///   vertices of each duplicated point; given to the solvers as `glued_vertices`, they are one
///   point again, so geodesics pass through such a vertex; across a non-manifold edge they pass
///   through its end points only;
/// - `tm` is built (`polygon_soup_to_polygon_mesh()`), points in no polygon as isolated
///   vertices, and its faces of 4 or more vertices are triangulated without new vertices
///   (`triangulate_face()`).
///
/// \tparam PointRange a range of points convertible to the point type of `tm`
/// \tparam PolygonRange a range of polygons, each a range of integer indices into `points`
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`
/// \tparam NamedParameters a sequence of named parameters, started from `CGAL_ext::parameters`
///
/// \param points the points of the soup
/// \param polygons the polygons of the soup, as indices into `points`, in the order of their corners
/// \param tm receives the triangle mesh (cleared first); unspecified when an exception is thrown
/// \param vertex_of_point receives, per input point, its vertex of `tm` (merged points share
///        one, a point in no polygon is an isolated vertex, at distance `+infinity` from other sources)
/// \param np optional named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and a 3D point type as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{merge_duplicate_points}
///     \cgalParamDescription{whether points at identical coordinates become one vertex}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true` when no point is shared by two polygons (a soup), `false` otherwise}
///   \cgalParamNEnd
///   \cgalParamNBegin{glued_vertices_output}
///     \cgalParamDescription{receives, for each point duplicated to make the surface a manifold, the
///       `std::vector` of its vertices; pass the groups to the solvers with `glued_vertices` so
///       that geodesics pass through these points (see the example `geodesic_distances_on_a_soup`)}
///     \cgalParamType{an output iterator accepting `std::vector<boost::graph_traits<TriangleMesh>::%vertex_descriptor>`}
///     \cgalParamDefault{none: the groups are not reported}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return what was changed, for the user's information
///
/// \throws Geodesic_error when a coordinate is not finite (naming the point), a polygon uses an
///         index out of range (naming the polygon), the soup has no polygon (a point cloud) or no
///         polygon of 3 distinct points, or a polygon cannot be triangulated without new points
///         (naming the polygon)
template <class PointRange, class PolygonRange, class TriangleMesh,
          class NamedParameters = parameters::Default_named_parameters_type>
Geodesic_mesh_repairs polygon_soup_to_geodesic_mesh(
  const PointRange& points, const PolygonRange& polygons, TriangleMesh& tm,
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_of_point,
  const NamedParameters& np = parameters::default_values())
{
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_of_polygon;
  return polygon_soup_to_geodesic_mesh(points, polygons, tm, vertex_of_point, face_of_polygon, np);
}

/// \ingroup PkgGeodesics3Ref
/// does what the function above does, and also tells which face each input triangle became,
/// so that points given on the input's faces can be placed on `tm`.
///
/// \tparam PointRange, PolygonRange, TriangleMesh, NamedParameters as above
/// \param points, polygons, tm, vertex_of_point, np as above
/// \param face_of_polygon receives, per input polygon of 3 distinct points, its face of `tm`,
///        whose corners are the polygon's points, possibly in the reverse order (match them by
///        position to order barycentric coordinates); `boost::graph_traits<TriangleMesh>::null_face()`
///        for the other polygons (removed, split or triangulated)
/// \return what was changed
/// \throws Geodesic_error as above
template <class PointRange, class PolygonRange, class TriangleMesh,
          class NamedParameters = parameters::Default_named_parameters_type>
Geodesic_mesh_repairs polygon_soup_to_geodesic_mesh(
  const PointRange& points, const PolygonRange& polygons, TriangleMesh& tm,
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_of_point,
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_of_polygon,
  const NamedParameters& np = parameters::default_values())
{
  namespace internal = Geodesics_3::internal;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::type Vertex_point_map;
  const Vertex_point_map vpm = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, tm));
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;

  Geodesic_mesh_repairs repairs;
  internal::Soup_in_repair<Point> soup = internal::checked_soup<Point>(points, polygons);
  bool merge = internal::shares_no_point(soup);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::merge_duplicate_points_t>::value)
    merge = parameters::get_parameter(np, internal_np::merge_duplicate_points);
  if(merge)
    internal::merge_duplicate_points(soup, repairs);
  else
    internal::keep_points(soup);
  internal::remove_repeated_points(soup, repairs);
  internal::orient(soup, repairs);
  repairs.isolated_points = internal::count_isolated_points(soup);

  const auto vertex_of_soup_point = internal::build_mesh(soup, tm, vpm);
  const auto face_of_soup_polygon = internal::faces_of_polygons(soup, tm, vertex_of_soup_point);
  internal::triangulate(soup, face_of_soup_polygon, tm, vpm, repairs);

  vertex_of_point.clear();
  for(std::size_t p : soup.point_of_input)
    vertex_of_point.push_back(vertex_of_soup_point[p]);
  face_of_polygon = internal::faces_of_input_triangles(polygons, soup, face_of_soup_polygon,
                                                       boost::graph_traits<TriangleMesh>::null_face());
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::glued_vertices_output_t>::value)
    internal::write_glued_groups(soup, vertex_of_soup_point,
                                 parameters::get_parameter(np, internal_np::glued_vertices_output));
  return repairs;
}

/// \ingroup PkgGeodesics3Ref
/// makes the triangle mesh `tm` from a polygon mesh `pm` (quads, polygons, vertices at one
/// position, ...) as `polygon_soup_to_geodesic_mesh()` does from its faces
/// (`polygon_mesh_to_polygon_soup()`), and tells which vertex of `tm` each vertex of `pm` became.
///
/// \tparam PolygonMesh a model of `FaceListGraph`
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`
/// \tparam VertexToVertexMap a model of `WritablePropertyMap` with
///         `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and
///         `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as value type
/// \tparam NamedParametersPM a sequence of named parameters for `pm`: CGAL's `vertex_point_map`
/// \tparam NamedParametersTM a sequence of named parameters for `tm`: CGAL's `vertex_point_map`
///
/// \param pm the polygon mesh
/// \param tm receives the triangle mesh (cleared first)
/// \param vertex_to_vertex_map receives the vertex of `tm` of each vertex of `pm`
/// \param np_pm optional named parameters for `pm`
/// \param np_tm optional named parameters for `tm`
///
/// \return what was changed, for the user's information
///
/// \throws Geodesic_error as `polygon_soup_to_geodesic_mesh()`, a polygon being a face of `pm`
///         (numbered in the order of `faces(pm)`) and a point a vertex (in the order of `vertices(pm)`)
template <class PolygonMesh, class TriangleMesh, class VertexToVertexMap,
          class NamedParametersPM = parameters::Default_named_parameters_type,
          class NamedParametersTM = parameters::Default_named_parameters_type>
Geodesic_mesh_repairs polygon_mesh_to_geodesic_mesh(const PolygonMesh& pm, TriangleMesh& tm,
                                                    VertexToVertexMap vertex_to_vertex_map,
                                                    const NamedParametersPM& np_pm = parameters::default_values(),
                                                    const NamedParametersTM& np_tm = parameters::default_values())
{
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParametersPM>::const_type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  // the points are in the order of vertices(pm)
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(pm, points, polygons, np_pm);
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vertex_of_point;
  const Geodesic_mesh_repairs repairs = polygon_soup_to_geodesic_mesh(points, polygons, tm, vertex_of_point, np_tm);
  std::size_t i = 0;
  for(auto v : vertices(pm))
    put(vertex_to_vertex_map, v, vertex_of_point[i++]);
  return repairs;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_POLYGON_SOUP_TO_GEODESIC_MESH_H
