// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_POLYLINE_LENGTH_H
#define CGAL_EXT_GEODESICS_3_POLYLINE_LENGTH_H

/// \file polyline_length.h
/// The length of a polyline, such as a shortest path's points.

#include <CGAL/number_utils.h>

#include <cmath>
#include <iterator>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// \return the sum of the Euclidean lengths of the segments between consecutive points of
///         `points` (0 for fewer than two points); the length of a shortest path given by
///         `Surface_mesh_geodesic_paths::shortest_path_points()` is the distance of its target.
/// \tparam PointRange a range of 3D points with `x()`, `y()` and `z()` (CGAL's `Point_3`)
/// \param points the polyline's points, in order
template <class PointRange>
double polyline_length(const PointRange& points)
{
  double length = 0;
  auto previous = std::begin(points);
  if(previous == std::end(points))
    return length;
  for(auto p = std::next(previous); p != std::end(points); previous = p++)
  {
    const double dx = CGAL::to_double(p->x()) - CGAL::to_double(previous->x());
    const double dy = CGAL::to_double(p->y()) - CGAL::to_double(previous->y());
    const double dz = CGAL::to_double(p->z()) - CGAL::to_double(previous->z());
    length += std::hypot(dx, dy, dz); // no overflow or underflow at any scale
  }
  return length;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_POLYLINE_LENGTH_H
