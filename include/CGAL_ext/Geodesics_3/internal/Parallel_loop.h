// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PARALLEL_LOOP_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PARALLEL_LOOP_H

#include <CGAL_ext/Geodesics_3/internal/Thread_sanitizer.h>

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

/// Gives a pool one slot per thread of the task arena the caller runs in, and returns the slot
/// of the calling thread. (Sequentially: one slot, slot 0.)
template <class Pool>
std::size_t use_one_slot_per_thread(Pool& pool, bool parallel)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel) {
    pool.set_number_of_slots(std::size_t(tbb::this_task_arena::max_concurrency()));
    return std::size_t(std::max(0, tbb::this_task_arena::current_thread_index()));
  }
#endif
  (void)pool;
  (void)parallel;
  return 0;
}

/// How a parallel loop cuts its range: in chunks of exactly `grain` (uniform work), or
/// adaptively (work of uneven size).
enum class Chunks
{
  FIXED,
  ADAPTIVE
};

/// Calls `f(i, slot)` for i in [0, n), where slot is the calling thread's index in the arena:
/// on TBB threads when `parallel`, in order on this thread (slot `main_slot`) otherwise. What
/// the caller wrote before happens before every call, and every call before the return (stated
/// to ThreadSanitizer too).
template <class Function>
void for_each_index(bool parallel, std::size_t n, std::size_t grain, Chunks chunks, std::size_t main_slot, Function f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel && n > 1) {
    char handoff = 0, handback = 0;
    sanitizer_release(&handoff);
    auto body = [&](const tbb::blocked_range<std::size_t>& r) {
      sanitizer_acquire(&handoff);
      const std::size_t slot = std::size_t(tbb::this_task_arena::current_thread_index());
      for(std::size_t i = r.begin(); i != r.end(); ++i)
        f(i, slot);
      sanitizer_release(&handback);
    };
    const tbb::blocked_range<std::size_t> range(0, n, std::max<std::size_t>(grain, 1));
    if(chunks == Chunks::FIXED)
      tbb::parallel_for(range, body, tbb::simple_partitioner());
    else
      tbb::parallel_for(range, body);
    sanitizer_acquire(&handback);
    return;
  }
#endif
  (void)parallel;
  (void)grain;
  (void)chunks;
  for(std::size_t i = 0; i < n; ++i)
    f(i, main_slot);
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PARALLEL_LOOP_H
