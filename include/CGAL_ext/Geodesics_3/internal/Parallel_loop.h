// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PARALLEL_LOOP_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PARALLEL_LOOP_H

#include <CGAL_ext/Geodesics_3/internal/Thread_sanitizer.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#endif

#include <CGAL/assertions.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The calling thread's index in the task arena it runs in: its slot in per-thread storage
/// (0 outside an arena, or without TBB).
inline std::size_t this_thread_slot()
{
#ifdef CGAL_LINKED_WITH_TBB
  return std::size_t(std::max(0, tbb::this_task_arena::current_thread_index()));
#else
  return 0;
#endif
}

/// Gives a pool one slot per thread of the task arena the caller runs in, and returns the slot
/// of the calling thread. (Sequentially: one slot, slot 0.)
template <class Pool>
std::size_t use_one_slot_per_thread(Pool& pool, bool parallel)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel) {
    pool.set_number_of_slots(std::size_t(tbb::this_task_arena::max_concurrency()));
    return this_thread_slot();
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
/// next loop by spinning, then yielding the processor for about a millisecond, and only then
/// sleep (so that a sequential step is never starved by waiting helpers on a busy machine).
///
/// Race-free by construction: a loop is published under a lock, with a ticket that carries its
/// generation; a thread takes chunks of indices by compare-and-swap on the ticket, so a helper
/// that looks late at an earlier loop can take nothing from a newer one. The caller returns from
/// a loop once every index is done (release/acquire on the count), and never waits for a
/// particular helper, so a helper that TBB never starts delays nothing. Which thread runs an
/// index never changes a result: callers write per index, or per slot with ranges kept per
/// index.
///
/// Restrictions: loops do not nest (a loop function must not call `for_each_index`), and only
/// the thread that called `run()` starts loops. A thread that is already in a team (a TBB wait
/// inside a loop function may pick up a queued helper task) does not join another one.
class Thread_team
{
public:
  /// Runs `body(team)` on the calling thread; when `parallel` (and TBB is there), the other
  /// threads of the current task arena help in the team's loops until `body` returns.
  template <class Body>
  static void run(bool parallel, Body body)
  {
    Thread_team team;
    const Membership member;
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel) {
      team.m_main_slot = this_thread_slot();
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
            if(!Membership::of_this_thread()) {
              const Membership member;
              team.help();
            }
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
  /// may be skipped. Only the thread that called `run()` may call this, and not from a loop.
  template <class Function>
  void for_each_index(std::size_t n, std::size_t grain, Function&& f)
  {
    typedef std::remove_reference_t<Function> F;
    CGAL_assertion(!m_in_loop);
    grain = std::max<std::size_t>(grain, 1);
    if(!m_has_helpers || n <= grain || n >= index_mask) {
      for(std::size_t i = 0; i < n; ++i)
        f(i, m_main_slot);
      return;
    }
    m_in_loop = true;
    Loop loop{0, n, grain, &call<F>, const_cast<void*>(static_cast<const void*>(std::addressof(f)))};
    lock();
    loop.generation = ++m_generation;
    m_loop = loop;
    m_done.store(0, std::memory_order_relaxed);
    m_ticket.store(std::uint64_t(loop.generation) << 32, std::memory_order_seq_cst);
    unlock();
    wake_sleepers();
    work(loop, m_main_slot);
    for(Back_off wait; m_done.load(std::memory_order_acquire) != n;)
      wait.pause();
    m_in_loop = false;
    if(m_failed.load(std::memory_order_acquire)) {
      lock();
      std::exception_ptr error = m_error;
      m_error = nullptr;
      m_failed.store(false, std::memory_order_relaxed);
      unlock();
      std::rethrow_exception(error);
    }
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

  // Marks the current thread as a member of a team for the lifetime of the object.
  class Membership
  {
  public:
    Membership() : m_was_member(flag()) { flag() = true; }
    ~Membership() { flag() = m_was_member; }
    Membership(const Membership&) = delete;
    Membership& operator=(const Membership&) = delete;
    static bool of_this_thread() { return flag(); }

  private:
    static bool& flag()
    {
      static thread_local bool member = false;
      return member;
    }
    bool m_was_member;
  };

  // Waiting: spin (a step takes microseconds), then yield for about a millisecond (a few
  // sequential steps), then report that the caller should sleep.
  class Back_off
  {
  public:
    // Returns false once the waiter should block instead.
    bool pause()
    {
      if(m_spins < 4096) {
        ++m_spins;
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#endif
        return true;
      }
      if(m_spins == 4096) {
        ++m_spins;
        m_yield_start = std::chrono::steady_clock::now();
      }
      std::this_thread::yield();
      return std::chrono::steady_clock::now() - m_yield_start < std::chrono::milliseconds(1);
    }

  private:
    unsigned m_spins = 0;
    std::chrono::steady_clock::time_point m_yield_start;
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
        m_failed.store(true, std::memory_order_relaxed);
        unlock();
      }
      m_done.fetch_add(end - begin, std::memory_order_release);
      ticket = m_ticket.load(std::memory_order_acquire);
    }
  }

  bool has_new_loop(std::uint32_t seen) const
  {
    return std::uint32_t(m_ticket.load(std::memory_order_seq_cst) >> 32) != seen ||
           m_stop.load(std::memory_order_seq_cst);
  }

  void help()
  {
    const std::size_t slot = this_thread_slot();
    std::uint32_t seen = 0;
    for(;;) {
      for(Back_off wait; !has_new_loop(seen);)
        if(!wait.pause())
          sleep_until_new_loop(seen);
      if(m_stop.load(std::memory_order_acquire))
        return;
      lock();
      const Loop loop = m_loop;
      unlock();
      seen = loop.generation;
      work(loop, slot);
    }
  }

  // Blocks until a loop newer than `seen` is published or the team stops. The count of
  // sleepers and the ticket are sequentially consistent: either the publisher sees this
  // sleeper and notifies, or this sleeper sees the new ticket before it waits.
  void sleep_until_new_loop(std::uint32_t seen)
  {
    std::unique_lock<std::mutex> guard(m_sleep_mutex);
    m_sleepers.fetch_add(1, std::memory_order_seq_cst);
    m_wake.wait(guard, [&] { return has_new_loop(seen); });
    m_sleepers.fetch_sub(1, std::memory_order_relaxed);
  }

  void wake_sleepers()
  {
    if(m_sleepers.load(std::memory_order_seq_cst) > 0) {
      std::lock_guard<std::mutex> guard(m_sleep_mutex);
      m_wake.notify_all();
    }
  }

  void stop()
  {
    m_stop.store(true, std::memory_order_seq_cst);
    wake_sleepers();
  }

  // A test-and-test-and-set lock: waiters read until it looks free.
  void lock()
  {
    for(Back_off wait;;) {
      if(!m_locked.load(std::memory_order_relaxed) && !m_locked.exchange(true, std::memory_order_acquire))
        return;
      wait.pause();
    }
  }
  void unlock() { m_locked.store(false, std::memory_order_release); }

  // Each word that threads write often has its own cache line.
  alignas(64) std::atomic<std::uint64_t> m_ticket{0}; // generation << 32 | next index
  alignas(64) std::atomic<std::size_t> m_done{0};     // indices of the current loop done
  alignas(64) std::atomic<bool> m_locked{false};
  Loop m_loop{0, 0, 1, nullptr, nullptr}; // under the lock
  std::exception_ptr m_error;             // under the lock
  alignas(64) std::atomic<bool> m_stop{false};
  std::atomic<bool> m_failed{false};
  std::atomic<int> m_sleepers{0};
  alignas(64) std::mutex m_sleep_mutex;
  std::condition_variable m_wake;
  // Used by the calling thread only.
  alignas(64) std::uint32_t m_generation = 0;
  std::size_t m_main_slot = 0;
  bool m_has_helpers = false;
  bool m_in_loop = false;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PARALLEL_LOOP_H
