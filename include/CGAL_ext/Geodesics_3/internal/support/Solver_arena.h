// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_SOLVER_ARENA_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_SOLVER_ARENA_H

// The threads of one call: a task arena of the requested size when parallel (never a
// process-wide setting), and the concurrency tag read at compile time.

#include <CGAL_ext/Geodesics_3/internal/support/Thread_sanitizer.h>

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <type_traits>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// Whether `ConcurrencyTag` asks for the parallel solvers; `CGAL::Parallel_tag` without TBB does
/// not compile, with a message saying why.
template <class ConcurrencyTag>
constexpr bool is_parallel_tag()
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "CGAL_ext: CGAL::Parallel_tag needs TBB (CGAL_LINKED_WITH_TBB); "
                "use CGAL::Sequential_tag or CGAL::Parallel_if_available_tag");
#endif
  return std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value;
}

/// A task arena of `threads` threads (0: TBB's choice) when parallel, nothing otherwise: it
/// bounds the threads of one call only, never a process-wide setting. Kept by a caller that
/// runs many short solves (one per sample), since making an arena costs as much as a small run.
template <bool parallel>
class Solver_arena
{
public:
  explicit Solver_arena(int threads)
#ifdef CGAL_LINKED_WITH_TBB
    : m_arena(threads > 0 ? threads : tbb::task_arena::automatic)
#endif
  {
    (void)threads;
  }

  /// Calls `f()` in the arena when parallel, here otherwise.
  template <class Function>
  void execute(const Function& f)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if constexpr(parallel) {
      // libtbb is not instrumented: state the hand-over into the arena and back
      char start = 0, done = 0;
      sanitizer_release(&start);
      const Sanitizer_on_exit back(sanitizer_acquire, &done);
      m_arena.execute([&] {
        sanitizer_acquire(&start);
        const Sanitizer_on_exit end(sanitizer_release, &done);
        f();
      });
      return;
    }
#endif
    f();
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  tbb::task_arena m_arena;
#endif
};

/// Calls `f()` in a task arena of `threads` threads when parallel, here otherwise.
template <bool parallel, class Function>
void run_in_arena(int threads, const Function& f)
{
  Solver_arena<parallel>(threads).execute(f);
}

/// Runs a solver, on `threads` threads when parallel (see `run_in_arena`).
template <bool parallel, class Solver>
void run_solver(Solver& solver, int threads)
{
  run_in_arena<parallel>(threads, [&solver] { solver.run(); });
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_SOLVER_ARENA_H
