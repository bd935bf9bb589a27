// Copyright (c) 2026 The CGAL_ext geodesics developers.
// How many threads the tool's parallel runs may take.

#ifndef GEODESIC_TOOL_THREADS_H
#define GEODESIC_TOOL_THREADS_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cstddef>
#include <optional>

namespace geodesic_tool {

/// While alive, lets the library's arena of `threads` threads (0: TBB's default) have them all.
/// Otherwise TBB caps its workers at the number of cores minus one and, asked for more, prints a
/// warning on the standard error. The tool owns its process, so a process-wide limit is fine here.
class Thread_allowance
{
public:
  explicit Thread_allowance(int threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(threads > 0)
      m_control.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#else
    (void)threads;
#endif
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> m_control;
#endif
};

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_THREADS_H
