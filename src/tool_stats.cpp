// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_stats.h"

#include "tool_solvers.h"
#include "tool_text.h"

#include <sys/resource.h>
#include <unistd.h>

#include <iostream>
#include <string>

namespace geodesic_tool {

Progress_line::Progress_line() : m_on_terminal(::isatty(2)) {}

bool Progress_line::due()
{
  const Clock::time_point now = Clock::now();
  if(!m_on_terminal || now - m_start <= std::chrono::seconds(1) || now - m_last_shown <= std::chrono::milliseconds(500))
    return false;
  m_last_shown = now;
  return true;
}

void Progress_line::show(const char* what, std::size_t done, std::size_t total)
{
  if(due())
    std::cerr << "\r" << what << " " << done << " of " << total << std::flush;
}

void Progress_line::show_percent(const char* what, double fraction)
{
  if(due())
    std::cerr << "\r" << what << " " << int(100 * fraction) << " %" << std::flush;
}

void Progress_line::clear()
{
  if(m_last_shown != m_start)
    std::cerr << "\r" << std::string(40, ' ') << "\r" << std::flush;
  m_last_shown = m_start;
}

double peak_rss_mb()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.; // kilobytes on Linux
}

void write_input_stats(std::ostream& s, const Solver_choice& choice, const Mesh_file& file, std::size_t sources,
                       double seconds_read)
{
  s << "algorithm=" << choice.algorithm->name << "\n";
  if(choice.algorithm->parallel)
    s << "threads=" << effective_threads(choice) << "\n";
  if(choice.algorithm->approximate)
    s << "lambda=" << number_text(choice.lambda) << "\n";
  const CGAL_ext::Geodesic_mesh_repairs& repairs = file.repairs;
  s << "vertices=" << file.soup.points.size() << "\n"
    << "faces=" << file.soup.polygons.size() << "\n"
    << "merged_points=" << repairs.merged_points << "\n"
    << "removed_polygons=" << repairs.removed_polygons << "\n"
    << "split_polygons=" << repairs.split_polygons << "\n"
    << "triangulated_polygons=" << repairs.triangulated_polygons << "\n"
    << "reversed_polygons=" << repairs.reversed_polygons << "\n"
    << "duplicated_points=" << repairs.duplicated_points << "\n"
    << "non_manifold_edges=" << repairs.non_manifold_edges << "\n"
    << "isolated_points=" << repairs.isolated_points << "\n"
    << "sources=" << sources << "\n"
    << "seconds_read=" << seconds_read << "\n";
}

void write_solver_stats(std::ostream& s, const Solver_choice& choice, const CGAL_ext::Geodesic_statistics& stats)
{
  s << "seconds_setup=" << stats.seconds_setup << "\n"
    << "seconds_solve=" << stats.seconds_solve << "\n"
    << "seconds_selection=" << stats.seconds_selection << "\n"
    << "seconds_propagation=" << stats.seconds_propagation << "\n"
    << "seconds_merge=" << stats.seconds_merge << "\n"
    << "windows_created=" << stats.windows_created << "\n"
    << "peak_windows=" << stats.peak_windows << "\n"
    << "lists_propagated=" << stats.lists_propagated << "\n"
    << "wavefront_resets=" << stats.wavefront_resets << "\n";
  const bool mmp = is_mmp_family(*choice.algorithm);
  if(mmp)
    s << "windows_propagated=" << stats.windows_propagated << "\n"
      << "windows_deferred=" << stats.windows_deferred << "\n";
  // VTP keeps windows too when they are read anywhere (path, voronoi)
  if(mmp || stats.stored_window_bytes > 0)
    s << "windows_stored=" << stats.windows_stored << "\n"
      << "stored_window_bytes=" << stats.stored_window_bytes << "\n";
  if(mmp)
    s << "seconds_organization=" << stats.seconds_organization << "\n"
      << "seconds_clipping=" << stats.seconds_clipping << "\n"
      << "seconds_pushing=" << stats.seconds_pushing << "\n";
}

} // namespace geodesic_tool
