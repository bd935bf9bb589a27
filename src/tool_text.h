// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The text of numbers and of file extensions, as the geodesic tool prints and reads them.

#ifndef GEODESIC_TOOL_TEXT_H
#define GEODESIC_TOOL_TEXT_H

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <string>

namespace geodesic_tool {

/// The extension of `path` with its dot, in lower case (".ply"); empty if it has none.
inline std::string lowercase_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// The shortest text that reads back as `value` (nan and inf as such).
template <class T>
std::string number_text(T value)
{
  char text[64];
  const auto result = std::to_chars(text, text + sizeof(text), value);
  return std::string(text, result.ptr);
}

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_TEXT_H
