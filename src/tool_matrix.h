// Copyright (c) 2026 The CGAL_ext geodesics developers.
// `geodesic matrix`: the distances from each source alone to a set of targets, one row per
// source, streamed to a .npy (NumPy), .mtx (Matrix Market, SciPy) or .txt file.

#ifndef GEODESIC_TOOL_MATRIX_H
#define GEODESIC_TOOL_MATRIX_H

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace geodesic_tool {

struct Matrix_options
{
  std::string mesh;
  std::vector<std::string> sources;
  bool all = false;                 // every point of the file is a source
  std::vector<std::string> targets; // default: every point; "sources": the sources
  double max_distance = std::numeric_limits<double>::infinity();
  std::optional<int> threads;
  std::string output;
  bool stats = false;
};

void add_matrix_command(CLI::App& app, Matrix_options& options);

enum class Matrix_format { npy, mtx, txt };

/// The format of a matrix file, by its extension; throws Tool_error for another one.
Matrix_format matrix_format(const std::string& path);

/// Writes a matrix of `rows` x `columns` to `os` one row at a time: .npy (float64, C order,
/// +infinity kept), .mtx (coordinate real general, 1-based; only finite entries, which are held
/// until `finish()` since the header counts them), .txt (one row per line, `inf` where unreached).
class Matrix_writer
{
public:
  Matrix_writer(std::ostream& os, Matrix_format format, std::size_t rows, std::size_t columns);
  void add_row(const std::vector<double>& row);
  /// .mtx only: the next row given by its finite entries, (column, value) by increasing column.
  void add_sparse_row(const std::vector<std::pair<std::size_t, double>>& entries);
  /// Writes what is held; false if the stream failed.
  bool finish();

private:
  struct Entry
  {
    std::size_t row, column;
    double value;
  };
  std::ostream& m_os;
  Matrix_format m_format;
  std::size_t m_rows, m_columns, m_written = 0;
  std::vector<Entry> m_entries; // .mtx
};

/// Throws Tool_error, saying how much is needed and what to do instead, when a matrix of `rows`
/// x `columns` cannot be written: a dense file (.npy, .txt) larger than `free_disk` bytes, or a
/// .mtx file without `max_distance` whose entries (held in memory until the end, as its header
/// counts them) could exceed `available_memory` bytes. 0 for an amount that is not known.
void check_matrix_fits(Matrix_format format, std::size_t rows, std::size_t columns, bool local,
                       std::uintmax_t available_memory, std::uintmax_t free_disk);

/// The memory the system can still give (MemAvailable of /proc/meminfo), 0 if not known.
std::uintmax_t available_memory_bytes();

int run_matrix(const Matrix_options& options);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_MATRIX_H
