// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_matrix.h"

#include "tool_error.h"
#include "tool_mesh.h"
#include "tool_options.h"
#include "tool_output.h"
#include "tool_solvers.h"
#include "tool_stats.h"
#include "tool_text.h"

#include <CLI/CLI.hpp>


#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <sstream>

namespace geodesic_tool {

void add_matrix_command(CLI::App& app, Matrix_options& options)
{
  CLI::App* cmd = app.add_subcommand(
    "matrix", "Geodesic distances from each source alone to the targets: one row per source, one column per target");
  add_mesh_argument(*cmd, options.mesh);
  auto* sources = cmd->add_option("--source", options.sources,
                                  "Sources, comma-separated: a vertex id, or f:FACE:b0:b1:b2 (a point of a face)")
                    ->delimiter(',')
                    ->allow_extra_args(false);
  auto* all = cmd->add_flag("--all", options.all, "Every vertex of the file is a source, in file order");
  sources->excludes(all);
  cmd->add_option("--target", options.targets,
                  "Columns, comma-separated vertex ids, or 'sources' (the sources' vertices: a square matrix); "
                  "default: every vertex in file order")
    ->delimiter(',')
    ->allow_extra_args(false);
  cmd->add_option("--max-distance", options.max_distance,
                  "Leave out (.mtx) or write inf for (.npy, .txt) the distances beyond this: a local, sparse matrix");
  cmd->add_option("--threads", options.threads, "Sources solved in parallel on this many threads; default: all cores");
  cmd->add_option("--output", options.output,
                  "Output file: .npy (dense float64, numpy.load), .mtx (Matrix Market coordinate, "
                  "scipy.io.mmread; only the finite entries) or .txt (one row per line)")
    ->required();
  cmd->add_flag("--stats", options.stats, "Print key=value statistics on the standard error");
}

Matrix_format matrix_format(const std::string& path)
{
  const std::string ext = lowercase_extension(path);
  if(ext == ".npy")
    return Matrix_format::npy;
  if(ext == ".mtx")
    return Matrix_format::mtx;
  if(ext == ".txt")
    return Matrix_format::txt;
  throw Tool_error("unknown output format '" + ext + "' for a matrix (use .npy, .mtx or .txt)");
}

Matrix_writer::Matrix_writer(std::ostream& os, Matrix_format format, std::size_t rows, std::size_t columns)
  : m_os(os), m_format(format), m_rows(rows), m_columns(columns)
{
  if(m_format != Matrix_format::npy)
    return;
  // NPY 1.0: magic, version, header length, then a Python dict padded with spaces to a multiple
  // of 64 bytes, ending with a newline.
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(rows) + ", " +
                       std::to_string(columns) + "), }";
  const std::size_t preamble = 10;
  header.append(64 - (preamble + header.size() + 1) % 64, ' ');
  header += '\n';
  const std::uint16_t length = std::uint16_t(header.size());
  m_os.write("\x93NUMPY\x01\x00", 8);
  const char little_endian_length[2] = {char(length & 0xff), char(length >> 8)};
  m_os.write(little_endian_length, 2);
  m_os << header;
}

void Matrix_writer::add_row(const std::vector<double>& row)
{
  switch(m_format) {
  case Matrix_format::npy:
    // the machines the tool runs on are little-endian, as '<f8' says
    m_os.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(double)));
    break;
  case Matrix_format::mtx:
    for(std::size_t j = 0; j < row.size(); ++j)
      if(std::isfinite(row[j]))
        m_entries.push_back(Entry{m_written, j, row[j]});
    break;
  case Matrix_format::txt: {
    char number[32];
    for(std::size_t j = 0; j < row.size(); ++j) {
      std::snprintf(number, sizeof(number), "%.17g", row[j]);
      m_os << (j ? " " : "") << number;
    }
    m_os << '\n';
    break;
  }
  }
  ++m_written;
}

void Matrix_writer::add_sparse_row(const std::vector<std::pair<std::size_t, double>>& entries)
{
  for(const auto& [column, value] : entries)
    m_entries.push_back(Entry{m_written, column, value});
  ++m_written;
}

bool Matrix_writer::finish()
{
  if(m_format == Matrix_format::mtx) {
    m_os << "%%MatrixMarket matrix coordinate real general\n"
         << "% geodesic distances: row = source, column = target; entries left out are beyond reach\n"
         << m_rows << ' ' << m_columns << ' ' << m_entries.size() << '\n';
    char line[96];
    for(const Entry& e : m_entries) {
      std::snprintf(line, sizeof(line), "%zu %zu %.17g\n", e.row + 1, e.column + 1, e.value);
      m_os << line;
    }
  }
  return bool(m_os);
}

namespace {

std::vector<Surface_point> every_point(std::size_t n)
{
  std::vector<Surface_point> points(n);
  for(std::size_t i = 0; i < n; ++i) {
    points[i].text = std::to_string(i);
    points[i].vertex = i;
  }
  return points;
}

/// The columns: file point ids.
std::vector<std::size_t> target_columns(const Matrix_options& options, const std::vector<Surface_point>& sources,
                                        std::size_t number_of_points)
{
  std::vector<std::size_t> columns;
  if(options.targets.empty()) {
    for(std::size_t i = 0; i < number_of_points; ++i)
      columns.push_back(i);
  } else if(options.targets.size() == 1 && options.targets[0] == "sources") {
    for(const Surface_point& s : sources) {
      if(!s.vertex)
        throw Tool_error("--target sources: source '" + s.text + "' is a face point; give vertex sources");
      columns.push_back(*s.vertex);
    }
  } else {
    for(const std::string& t : options.targets) {
      const Surface_point p = parse_surface_point(t, "target");
      if(!p.vertex)
        throw Tool_error("target '" + t + "': the columns of a matrix are vertices");
      check_surface_point_range(p, number_of_points, 0, "target");
      columns.push_back(*p.vertex);
    }
  }
  return columns;
}

std::string gigabytes(double bytes)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g GB", bytes / 1e9);
  return text;
}

} // namespace

void check_matrix_fits(Matrix_format format, std::size_t rows, std::size_t columns, bool local,
                       std::uintmax_t available_memory, std::uintmax_t free_disk)
{
  const double entries = double(rows) * double(columns);
  if(format == Matrix_format::mtx) {
    // an entry is held as two indices and a value until the header can count them
    const double held = entries * double(sizeof(std::size_t) * 2 + sizeof(double));
    if(!local && available_memory > 0 && held > double(available_memory))
      throw Tool_error("a .mtx matrix of " + std::to_string(rows) + " x " + std::to_string(columns) +
                       " without --max-distance holds up to " + gigabytes(held) + " in memory, more than the " +
                       gigabytes(double(available_memory)) +
                       " available; give --max-distance (a local, sparse matrix) or write .npy");
    return;
  }
  const double bytes = entries * (format == Matrix_format::npy ? 8. : 24.);
  if(free_disk > 0 && bytes > double(free_disk))
    throw Tool_error("a dense matrix of " + std::to_string(rows) + " x " + std::to_string(columns) + " needs about " +
                     gigabytes(bytes) + " on disk, more than the " + gigabytes(double(free_disk)) +
                     " free; give --max-distance and write .mtx (only the entries within it)");
}

std::uintmax_t available_memory_bytes()
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::uintmax_t kilobytes = 0;
  std::string unit;
  while(in >> key >> kilobytes >> unit)
    if(key == "MemAvailable:")
      return kilobytes * 1024;
  return 0;
}

int run_matrix(const Matrix_options& options)
{
  // Validate the command line before the (possibly long) reading and solving.
  if(!options.all && options.sources.empty())
    throw Tool_error("give the sources with --source, or --all");
  if(!(options.max_distance >= 0))
    throw Tool_error("--max-distance must be non-negative, got " + number_text(options.max_distance));
  if(options.threads && *options.threads < 1)
    throw Tool_error("--threads must be at least 1, got " + std::to_string(*options.threads));
  const Matrix_format format = matrix_format(options.output);
  std::vector<Surface_point> sources = options.all ? std::vector<Surface_point>() : parse_sources(options.sources);

  const Stopwatch read_watch;
  const Mesh_file file = read_mesh_file(options.mesh);
  const double seconds_read = read_watch.seconds();
  if(options.all)
    sources = every_point(file.soup.points.size());
  for(const Surface_point& s : sources)
    check_surface_point_range(s, file.soup.points.size(), file.soup.polygons.size());
  const std::vector<std::size_t> columns = target_columns(options, sources, file.soup.points.size());
  {
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::absolute(options.output).parent_path();
    const std::filesystem::space_info space = std::filesystem::space(folder, error);
    check_matrix_fits(format, sources.size(), columns.size(), std::isfinite(options.max_distance),
                      available_memory_bytes(), error ? 0 : space.available);
  }

  Progress_line progress;
  std::size_t entries = 0;
  const Stopwatch solve_watch;
  write_output(options.output, [&](std::ostream& os) {
    Matrix_writer writer(os, format, sources.size(), columns.size());
    if(format == Matrix_format::mtx && std::isfinite(options.max_distance)) {
      // a local matrix: sparse rows, so that a row costs its entries, not the number of columns
      const Columns_of_vertices columns_of(file, columns);
      std::vector<std::pair<std::size_t, double>> selected;
      compute_sparse_distance_rows(file, sources, options.max_distance, options.threads.value_or(0),
                                   [&](std::size_t i, const std::vector<std::pair<std::size_t, double>>& row) {
                                     selected.clear();
                                     for(const auto& [vertex, distance] : row)
                                       for(std::size_t j : columns_of.vertex(vertex))
                                         selected.emplace_back(j, distance);
                                     std::sort(selected.begin(), selected.end());
                                     entries += selected.size();
                                     writer.add_sparse_row(selected);
                                     progress.show("row", i + 1, sources.size());
                                   });
    } else {
      std::vector<double> selected(columns.size());
      compute_distance_rows(file, sources, options.max_distance, options.threads.value_or(0),
                            [&](std::size_t i, const std::vector<double>& row) {
                              for(std::size_t j = 0; j < columns.size(); ++j) {
                                selected[j] = row[columns[j]];
                                entries += std::isfinite(selected[j]);
                              }
                              writer.add_row(selected);
                              progress.show("row", i + 1, sources.size());
                            });
    }
    progress.clear();
    return writer.finish();
  });

  if(!file.repairs.summary().empty())
    std::cerr << "note: " << file.repairs.summary() << std::endl;
  if(options.stats) {
    std::ostringstream s;
    s << "vertices=" << file.soup.points.size() << "\n"
      << "rows=" << sources.size() << "\n"
      << "columns=" << columns.size() << "\n"
      << "finite_entries=" << entries << "\n"
      << "seconds_read=" << seconds_read << "\n"
      << "seconds_rows=" << solve_watch.seconds() << "\n"
      << "peak_rss_mb=" << peak_rss_mb() << "\n";
    std::cerr << s.str() << std::flush;
  }
  return 0;
}

} // namespace geodesic_tool
