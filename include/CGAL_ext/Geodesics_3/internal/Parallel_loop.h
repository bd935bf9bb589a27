// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PARALLEL_LOOP_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PARALLEL_LOOP_H

#include <CGAL_ext/Geodesics_3/internal/Thread_sanitizer.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <thread>
#include <type_traits>
#include <vector>

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

/// The threads of a parallel solver, for its whole run: a long sequence of short parallel
/// loops, each after a sequential step of the calling thread.
///
/// Why not one `tbb::parallel_for` per loop: a propagation round holds a few hundred
/// microseconds of work, and between two loops TBB's worker threads go to sleep; waking them
/// costs 15-20 microseconds per loop on a virtual machine, more than a tenth of the round. The
/// team's helpers (TBB tasks of the caller's arena, one per other thread) instead wait for the
/// next loop by spinning briefly, then yielding the processor.
///
/// Race-free by construction: a loop is published under a lock, with a ticket that carries its
/// generation; a thread takes chunks of indices by compare-and-swap on the ticket, so a helper
/// that looks late at an earlier loop can take nothing from a newer one. The caller returns from
/// a loop once every index is done (release/acquire on the count), and never waits for a
/// particular helper, so a helper that TBB never starts delays nothing. Which thread runs an
/// index never changes a result: callers write per index, or per slot with ranges kept per
/// index.
class Thread_team
{
public:
  /// Runs `body(team)` on the calling thread; when `parallel` (and TBB is there), the other
  /// threads of the current task arena help in the team's loops until `body` returns.
  template <class Body>
  static void run(bool parallel, Body body)
  {
    Thread_team team;
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel) {
      team.m_main_slot = std::size_t(std::max(0, tbb::this_task_arena::current_thread_index()));
      const int helpers = tbb::this_task_arena::max_concurrency() - 1;
      if(helpers > 0) {
        team.m_has_helpers = true;
        tbb::task_group group;
        // The hand-over through TBB's tasks, stated once the tasks are built, on a token whose
        // address a helper knows before it reads anything the caller wrote (its captures too).
        static char handover;
        std::vector<tbb::task_handle> tasks;
        for(int i = 0; i < helpers; ++i)
          tasks.push_back(group.defer([&team] {
            sanitizer_acquire(&handover);
            team.help();
            sanitizer_release(&team.m_stop);
          }));
        sanitizer_release(&handover);
        for(tbb::task_handle& task : tasks)
          group.run(std::move(task));
        try {
          body(team);
        } catch(...) {
          team.stop();
          group.wait();
          sanitizer_acquire(&team.m_stop);
          throw;
        }
        team.stop();
        group.wait();
        sanitizer_acquire(&team.m_stop);
        return;
      }
    }
#endif
    (void)parallel;
    body(team);
  }

  /// The slot (index in the arena) of the thread that called `run()`.
  std::size_t main_slot() const { return m_main_slot; }

  /// Calls `f(i, slot)` for i in [0, n), in chunks of `grain` indices taken by whichever thread
  /// of the team is free; `slot` is the calling thread's index in the arena. What the caller
  /// wrote before happens before every call, and every call before the return. An exception
  /// of `f` is rethrown here once no call of the loop is running; indices not yet run by then
  /// may be skipped.
  template <class Function>
  void for_each_index(std::size_t n, std::size_t grain, Function&& f)
  {
    typedef std::remove_reference_t<Function> F;
    grain = std::max<std::size_t>(grain, 1);
    if(!m_has_helpers || n <= grain || n >= index_mask) {
      for(std::size_t i = 0; i < n; ++i)
        f(i, m_main_slot);
      return;
    }
    Loop loop{0, n, grain, &call<F>, const_cast<void*>(static_cast<const void*>(std::addressof(f)))};
    lock();
    loop.generation = ++m_generation;
    m_loop = loop;
    m_done.store(0, std::memory_order_relaxed);
    m_ticket.store(std::uint64_t(loop.generation) << 32, std::memory_order_release);
    unlock();
    work(loop, m_main_slot);
    for(unsigned spins = 0; m_done.load(std::memory_order_acquire) != n;)
      back_off(spins);
    lock();
    std::exception_ptr error = m_error;
    m_error = nullptr;
    unlock();
    if(error)
      std::rethrow_exception(error);
  }

private:
  static constexpr std::uint64_t index_mask = 0xffffffffu;

  struct Loop
  {
    std::uint32_t generation;
    std::size_t n, grain;
    void (*function)(void*, std::size_t, std::size_t);
    void* context;
  };

  template <class Function>
  static void call(void* f, std::size_t i, std::size_t slot)
  {
    (*static_cast<Function*>(f))(i, slot);
  }

  // Takes chunks of `loop` until none is left (or a newer loop has replaced it).
  void work(const Loop& loop, std::size_t slot)
  {
    std::uint64_t ticket = m_ticket.load(std::memory_order_acquire);
    for(;;) {
      const std::size_t begin = std::size_t(ticket & index_mask);
      if(std::uint32_t(ticket >> 32) != loop.generation || begin >= loop.n)
        return;
      const std::size_t end = std::min(loop.n, begin + loop.grain);
      if(!m_ticket.compare_exchange_weak(ticket, (ticket & ~index_mask) | end, std::memory_order_acq_rel))
        continue;
      try {
        for(std::size_t i = begin; i < end; ++i)
          loop.function(loop.context, i, slot);
      } catch(...) {
        lock();
        if(!m_error)
          m_error = std::current_exception();
        unlock();
      }
      m_done.fetch_add(end - begin, std::memory_order_release);
      ticket = m_ticket.load(std::memory_order_acquire);
    }
  }

  void help()
  {
#ifdef CGAL_LINKED_WITH_TBB
    const std::size_t slot = std::size_t(tbb::this_task_arena::current_thread_index());
#else
    const std::size_t slot = 0;
#endif
    std::uint32_t seen = 0;
    for(unsigned spins = 0; !m_stop.load(std::memory_order_acquire);) {
      if(std::uint32_t(m_ticket.load(std::memory_order_acquire) >> 32) == seen) {
        back_off(spins);
        continue;
      }
      lock();
      const Loop loop = m_loop;
      unlock();
      seen = loop.generation;
      work(loop, slot);
      spins = 0;
    }
  }

  void stop()
  {
    lock();
    m_stop.store(true, std::memory_order_release);
    unlock();
  }

  // Spins for about the length of a short sequential step, then lets other threads run: the
  // team may have more threads than the machine has free cores.
  static void back_off(unsigned& spins)
  {
    if(spins < 4096) {
      ++spins;
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    } else {
      std::this_thread::yield();
    }
  }

  void lock()
  {
    for(unsigned spins = 0; m_locked.exchange(true, std::memory_order_acquire);)
      back_off(spins);
  }
  void unlock() { m_locked.store(false, std::memory_order_release); }

  alignas(64) std::atomic<std::uint64_t> m_ticket{0}; // generation << 32 | next index
  alignas(64) std::atomic<std::size_t> m_done{0};     // indices of the current loop done
  alignas(64) std::atomic<bool> m_locked{false};
  std::atomic<bool> m_stop{false};
  Loop m_loop{0, 0, 1, nullptr, nullptr}; // under the lock
  std::exception_ptr m_error;             // under the lock
  std::uint32_t m_generation = 0;
  std::size_t m_main_slot = 0;
  bool m_has_helpers = false;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PARALLEL_LOOP_H
