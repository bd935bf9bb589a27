// Copyright (c) 2026 The CGAL_ext geodesics developers.
// How many threads the tool's parallel runs may take.

#ifndef GEODESIC_TOOL_THREADS_H
#define GEODESIC_TOOL_THREADS_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/info.h>
#endif

#include <cstddef>
#include <optional>

namespace geodesic_tool {

/// While alive, lets the library's arena of `threads` threads (0: TBB's default) have them all
/// when they are more than the cores: otherwise TBB caps its workers at the number of cores
/// minus one and, asked for more, prints a warning on the standard error. It never lowers the
/// limit: the arena of a call bounds that call's threads, and a process-wide cap below the cores
/// would slow down what other threads of the process (a Python program's) run meanwhile.
class Thread_allowance
{
public:
  explicit Thread_allowance(int threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(threads > tbb::info::default_concurrency())
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
