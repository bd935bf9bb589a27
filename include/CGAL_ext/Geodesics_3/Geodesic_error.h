// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_GEODESIC_ERROR_H
#define CGAL_EXT_GEODESICS_3_GEODESIC_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// The one exception type of the package. It is thrown for bad input: a mesh that is not a
/// manifold triangle mesh, a non-finite coordinate, a degenerate triangle, a source out of range,
/// an invalid parameter value. Its message names the problem and where it is (vertex or face
/// index, value).
class Geodesic_error : public std::runtime_error
{
public:
  /// builds the exception.
  /// \param what the message: the problem and where it is
  explicit Geodesic_error(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgGeodesics3Ref
/// Thrown when the caller's `callback` (a named parameter of the long-running functions)
/// returned `false`: the run stopped, and nothing was written to the caller's maps.
class Geodesic_cancelled : public Geodesic_error
{
public:
  /// builds the exception.
  /// \param what the message: what was cancelled
  explicit Geodesic_cancelled(const std::string& what) : Geodesic_error(what) {}
};

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_GEODESIC_ERROR_H
