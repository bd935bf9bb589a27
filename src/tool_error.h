// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The one error type of the geodesic tool.

#ifndef GEODESIC_TOOL_ERROR_H
#define GEODESIC_TOOL_ERROR_H

#include <stdexcept>
#include <string>

namespace geodesic_tool {

/// An error in the input of the tool (file, source, option) or in writing its output; its
/// message is printed as is, after `error: `.
struct Tool_error : std::runtime_error
{
  explicit Tool_error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_ERROR_H
