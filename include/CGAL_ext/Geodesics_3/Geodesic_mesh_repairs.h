// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_GEODESIC_MESH_REPAIRS_H
#define CGAL_EXT_GEODESICS_3_GEODESIC_MESH_REPAIRS_H

/// \file Geodesic_mesh_repairs.h
/// What was changed to make a triangle mesh of a polygon soup.

#include <cstddef>
#include <string>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// What `polygon_soup_to_geodesic_mesh()` changed to make a triangle mesh of a polygon soup.
/// Every change keeps the surface and its geodesic distances: points are merged only at identical
/// coordinates, no point is added or moved.
struct Geodesic_mesh_repairs
{
  /// duplicate points merged into one (identical coordinates); the input points keep one vertex
  std::size_t merged_points = 0;
  /// polygons left with fewer than 3 distinct points (segments, points): removed, which loses no area
  std::size_t removed_polygons = 0;
  /// polygons passing twice through a point: cut there into loops, one face each
  std::size_t split_polygons = 0;
  /// polygons of 4 or more points: triangulated, without new points
  std::size_t triangulated_polygons = 0;
  /// polygons whose order was reversed to orient the surface consistently
  std::size_t reversed_polygons = 0;
  /// extra copies of points where the polygons around a point or an edge do not form a manifold
  /// (non-manifold vertices and edges, orientation conflicts); the solvers glue copies at one
  /// position together again, so that geodesics pass through them
  std::size_t duplicated_points = 0;
  /// edges shared by 3 or more polygons: cut apart, their end points glued, so that paths cross
  /// such an edge only at its end points (a distance across it is at most its length too long)
  std::size_t non_manifold_edges = 0;
  /// points in no face: isolated vertices of the mesh, at distance `+infinity` from any other source
  std::size_t isolated_points = 0;

  /// \return whether the mesh differs from the soup taken as is (isolated points are kept as they are)
  bool changed() const
  {
    return merged_points + removed_polygons + split_polygons + triangulated_polygons + reversed_polygons +
             duplicated_points >
           0;
  }

  /// \return the changes and the isolated points in one line of text, e.g. "merged 1,234
  ///         duplicate points, triangulated 40 polygons"; empty when there is nothing to say
  std::string summary() const
  {
    std::string text;
    const auto add = [&](std::size_t n, const std::string& before, const char* singular, const char* plural,
                         const std::string& after) {
      if(n == 0)
        return;
      text += (text.empty() ? "" : ", ") + before + count_text(n) + " " + (n == 1 ? singular : plural) + after;
    };
    add(merged_points, "merged ", "duplicate point", "duplicate points", "");
    add(removed_polygons, "removed ", "polygon", "polygons", " with fewer than 3 distinct points");
    add(split_polygons, "split ", "polygon", "polygons", " passing twice through a point");
    add(triangulated_polygons, "triangulated ", "polygon", "polygons", "");
    add(reversed_polygons, "reversed ", "polygon", "polygons", " to orient the surface");
    add(duplicated_points, "duplicated ", "point", "points",
        " at non-manifold vertices or edges (glued again: geodesics pass through them)");
    add(non_manifold_edges, "", "edge is", "edges are",
        " shared by 3 or more polygons (paths cross such an edge only at its end points)");
    add(isolated_points, "", "point is", "points are", " in no face (at infinite distance)");
    return text;
  }

private:
  /// `n` with a comma between groups of three digits: 1,234
  static std::string count_text(std::size_t n)
  {
    std::string digits = std::to_string(n);
    for(std::size_t i = digits.size(); i > 3; i -= 3)
      digits.insert(i - 3, ",");
    return digits;
  }
};

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_GEODESIC_MESH_REPAIRS_H
