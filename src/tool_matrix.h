// Copyright (c) 2026 The CGAL_ext geodesics developers.
// `geodesic matrix`: the distances from each source alone to a set of targets, one row per
// source, streamed to a .npy (NumPy), .mtx (Matrix Market, SciPy) or .txt file.

#ifndef GEODESIC_TOOL_MATRIX_H
#define GEODESIC_TOOL_MATRIX_H

#include "tool_mesh.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
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

/// The columns of each mesh vertex: those whose file point is that vertex (a point may be a
/// column several times, and merged points share a vertex), by increasing column.
class Columns_of_vertices
{
public:
  Columns_of_vertices(const Mesh_file& file, const std::vector<std::size_t>& columns)
    : m_begin(file.mesh.number_of_vertices() + 1, 0)
    , m_column(columns.size())
  {
    for(std::size_t p : columns)
      ++m_begin[file.vertex_of_point[p].idx() + 1];
    std::partial_sum(m_begin.begin(), m_begin.end(), m_begin.begin());
    std::vector<std::size_t> next(m_begin.begin(), m_begin.end() - 1);
    for(std::size_t j = 0; j < columns.size(); ++j)
      m_column[next[file.vertex_of_point[columns[j]].idx()]++] = j;
  }
  struct Range
  {
    const std::size_t *first, *last;
    const std::size_t* begin() const { return first; }
    const std::size_t* end() const { return last; }
  };
  /// The columns of the vertex of index v.
  Range vertex(std::size_t v) const
  {
    if(v + 1 >= m_begin.size())
      return Range{nullptr, nullptr};
    return Range{m_column.data() + m_begin[v], m_column.data() + m_begin[v + 1]};
  }

private:
  std::vector<std::size_t> m_begin; // by vertex index: where its columns start in m_column
  std::vector<std::size_t> m_column;
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
