// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The files the geodesic tool writes: distances (.txt, .ply) and paths (.txt, .obj, .ply), and
// writing them so that an error never leaves a partial file.

#ifndef GEODESIC_TOOL_OUTPUT_H
#define GEODESIC_TOOL_OUTPUT_H

#include "tool_mesh.h"

#include <CGAL/IO/Color.h>

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace geodesic_tool {

/// Writes with `write` (false: the stream failed) to the file `path`, or to the standard output
/// when `path` is empty. A file is written through a temporary file next to it, renamed over it
/// only once complete, so that an error never leaves a partial file behind nor clobbers an
/// existing one. Throws Tool_error naming the file when writing fails.
void write_output(const std::string& path, const std::function<bool(std::ostream&)>& write);

// ---------------------------------------------------------------------------------------------
// Distances

/// One distance per line, in the order of the file's points, with 17 significant digits; `inf`
/// for +infinity.
bool write_distances_txt(std::ostream& os, const std::vector<double>& distances);

/// Binary PLY of the file's points and polygons as they are: each point has its distance as
/// the PLY property `distance`, exactly, and a colour following distance_color().
bool write_distances_ply(std::ostream& os, const Soup& soup, const std::vector<double>& distances);

/// The largest finite distance (0 if there is none).
double farthest_finite(const std::vector<double>& distances);

/// The colour ramp of the PLY output: blue at 0, red at `farthest`, grey where unreached.
CGAL::IO::Color distance_color(double d, double farthest);

// ---------------------------------------------------------------------------------------------
// Paths, from the source to the target

/// One `x y z` line per point, with 17 significant digits.
bool write_path_txt(std::ostream& os, const std::vector<Point>& points);

/// `v` lines and one `l` line through them (none for a single point: a line needs two).
bool write_path_obj(std::ostream& os, const std::vector<Point>& points);

/// ASCII PLY: the points, and an edge between consecutive ones.
bool write_path_ply(std::ostream& os, const std::vector<Point>& points);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_OUTPUT_H
