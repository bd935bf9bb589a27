// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The files the geodesic tool writes: distances and nearest-source labels (.txt, .ply) and paths
// (.txt, .obj, .ply), and writing them so that an error never leaves a partial file.

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

/// A file to write (empty path: the standard output) and how.
struct Output_file
{
  std::string path;
  std::function<bool(std::ostream&)> write;
};

/// Writes several files as `write_output()` does; either all files are written or, on an error,
/// none (the standard output, which cannot be taken back, comes after every file).
void write_outputs(const std::vector<Output_file>& outputs);

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
// Nearest-source labels (the geodesic Voronoi cell of each point)

/// One label per line, in the order of the file's points: the index of the nearest source in
/// the order given, -1 where no source reaches.
bool write_labels_txt(std::ostream& os, const std::vector<long>& labels);

/// Binary PLY of the file's points and polygons: each point has its `distance` (double) and
/// its nearest `source` (int, -1 where none reaches), and the colour of its cell.
bool write_labels_ply(std::ostream& os, const Soup& soup, const std::vector<double>& distances,
                      const std::vector<long>& labels);

/// Binary PLY of the file's points and polygons: each point has its pattern `instance` (int, -1
/// outside every instance) and the colour of its instance.
bool write_instances_ply(std::ostream& os, const Soup& soup, const std::vector<long>& instances);

/// A colour per source index (hues far apart for neighbouring indices), grey for -1.
CGAL::IO::Color label_color(long label);

/// A point as `x y z`, each with 17 significant digits.
std::string point_text(const Point& p);

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
