// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_PARALLEL_FOR_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_PARALLEL_FOR_H

// The parallel loops of the solvers, on oneTBB as oneTBB intends: a `tbb::parallel_for` in the
// caller's task arena (which bounds the threads), inline when there is one thread.

#include <CGAL_ext/Geodesics_3/internal/support/Thread_sanitizer.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cstddef>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

// The calling thread's index in the task arena it runs in: its slot in per-thread storage (0
// outside an arena); and how many threads the caller's arena has: the slots storage needs.
#ifdef CGAL_LINKED_WITH_TBB
inline std::size_t this_thread_slot() { return std::size_t(std::max(0, tbb::this_task_arena::current_thread_index())); }
inline std::size_t arena_concurrency() { return std::size_t(std::max(1, tbb::this_task_arena::max_concurrency())); }
#else
inline std::size_t this_thread_slot() { return 0; }
inline std::size_t arena_concurrency() { return 1; }
#endif

/// Calls `f(begin, end, slot)` for ranges [begin, end) that together make [0, n), once each,
/// `slot` being the calling thread's index in the arena. When `parallel`, the arena has more
/// than one thread and n is more than one chunk, the ranges are chunks of at most `grain`
/// indices (a `simple_partitioner` halves the range while it is longer: more than half of
/// `grain` each) run by the arena's threads; otherwise [0, n) runs here. Callers write per
/// index, or per slot with ranges kept per index, so which thread runs an index never changes
/// a result.
template <class Function>
void for_each_chunk(bool parallel, std::size_t n, std::size_t grain, const Function& f)
{
  grain = std::max<std::size_t>(grain, 1);
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel && n > grain && tbb::this_task_arena::max_concurrency() > 1) {
    // libtbb is not instrumented: state the hand-over of the loop to its chunks (`start`) and
    // of the chunks back to the caller (`done`). Two tokens, so that a chunk that starts after
    // another one ended is not ordered after it: a race between two chunks stays visible.
    char start = 0, done = 0;
    sanitizer_release(&start);
    {
      const Sanitizer_on_exit back(sanitizer_acquire, &done);
      tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, n, grain),
        [&f, &start, &done](const tbb::blocked_range<std::size_t>& r) {
          sanitizer_acquire(&start);
          const Sanitizer_on_exit end(sanitizer_release, &done);
          f(r.begin(), r.end(), this_thread_slot());
        },
        tbb::simple_partitioner());
    }
    return;
  }
#endif
  // In order, here; slot 0 when sequential (the only slot of sequential per-thread storage,
  // whichever arena thread the caller is), the caller's slot when the arena has one thread.
  if(n > 0)
    f(std::size_t(0), n, parallel ? this_thread_slot() : 0);
}

/// Calls `f(i, slot)` for every i in [0, n), in the chunks of `for_each_chunk`, in order within
/// a chunk.
template <class Function>
void for_each_index(bool parallel, std::size_t n, std::size_t grain, const Function& f)
{
  for_each_chunk(parallel, n, grain, [&f](std::size_t begin, std::size_t end, std::size_t slot) {
    for(std::size_t i = begin; i != end; ++i)
      f(i, slot);
  });
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_PARALLEL_FOR_H
