// Copyright (c) 2026 The CGAL_ext geodesics developers.
// What `--stats` reports: the times, the memory and the solver's counts, as key=value lines.

#ifndef GEODESIC_TOOL_STATS_H
#define GEODESIC_TOOL_STATS_H

#include "tool_mesh.h"
#include "tool_options.h"

#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>

#include <chrono>
#include <cstddef>
#include <ostream>

namespace geodesic_tool {

class Stopwatch
{
public:
  double seconds() const { return std::chrono::duration<double>(Clock::now() - m_start).count(); }

private:
  typedef std::chrono::steady_clock Clock;
  Clock::time_point m_start = Clock::now();
};

/// A progress line on the standard error, `what done of total` or `what N %`, shown only on a
/// terminal, once the run has taken more than a second, and at most twice a second; `clear()`
/// erases it.
class Progress_line
{
public:
  Progress_line();
  ~Progress_line() { clear(); }
  Progress_line(const Progress_line&) = delete;
  Progress_line& operator=(const Progress_line&) = delete;
  void show(const char* what, std::size_t done, std::size_t total);
  /// `fraction` of the work done, in [0, 1]
  void show_percent(const char* what, double fraction);
  void clear();

private:
  bool due();

  typedef std::chrono::steady_clock Clock;
  bool m_on_terminal;
  Clock::time_point m_start = Clock::now(), m_last_shown = m_start;
};

/// The peak resident memory of the process so far, in MiB.
double peak_rss_mb();

/// The first lines of --stats: the solver, the file (its points and polygons), what was
/// repaired to make its mesh, and the reading.
void write_input_stats(std::ostream& s, const Solver_choice& choice, const Mesh_file& file, std::size_t sources,
                       double seconds_read);

/// What the library reports of a solver run; the MMP family adds its own.
void write_solver_stats(std::ostream& s, const Solver_choice& choice, const CGAL_ext::Geodesic_statistics& stats);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_STATS_H
