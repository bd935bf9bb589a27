// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_OBJECT_POOL_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_OBJECT_POOL_H

#include <CGAL_ext/Geodesics_3/internal/Parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// Storage of windows (any type with a `next` pointer to its own type): no allocation per
/// window once the pool has grown to the size of the wavefront, and no sharing between threads.
/// Each thread uses its own slot: blocks it carved and a list of freed windows (a window freed
/// by another thread than the one that made it simply joins that thread's list). Windows never
/// move, so they are linked by pointer.
template <class T>
class Object_pool
{
public:
  static constexpr std::size_t block_size = 4096;

  /// Gives the pool one slot per thread of the task arena the caller runs in when `parallel`,
  /// one slot otherwise, and returns the calling thread's slot; only before any allocation.
  std::size_t use_one_slot_per_thread(bool parallel)
  {
    m_slots.resize(parallel ? arena_concurrency() : 1);
    return parallel ? this_thread_slot() : 0;
  }
  std::size_t number_of_slots() const { return m_slots.size(); }

  /// An object of the slot, as it was left when freed (value-initialized when new).
  T* allocate(std::size_t slot)
  {
    Slot& s = m_slots[slot];
    T* p = s.free;
    if(p)
      s.free = p->next;
    else {
      if(s.used == block_size) {
        s.blocks.push_back(std::make_unique<T[]>(block_size));
        s.used = 0;
      }
      p = &s.blocks.back()[s.used++];
    }
    ++s.live;
    return p;
  }
  T* allocate(std::size_t slot, const T& w)
  {
    T* p = allocate(slot);
    *p = w;
    return p;
  }
  /// Frees `w` and the objects linked after it.
  void release_chain(std::size_t slot, T* w)
  {
    Slot& s = m_slots[slot];
    while(w) {
      T* next = w->next;
      w->next = s.free;
      s.free = w;
      --s.live;
      w = next;
    }
  }
  /// Frees `w` alone, whatever it links to.
  void release_one(std::size_t slot, T* w)
  {
    Slot& s = m_slots[slot];
    w->next = s.free;
    s.free = w;
    --s.live;
  }
  /// Frees `w` alone.
  void release(std::size_t slot, T* w)
  {
    w->next = nullptr;
    release_chain(slot, w);
  }
  /// Windows alive (exact between parallel steps).
  std::size_t live() const
  {
    std::ptrdiff_t n = 0;
    for(const Slot& s : m_slots)
      n += s.live;
    return std::size_t(n);
  }
  std::size_t bytes() const
  {
    std::size_t blocks = 0;
    for(const Slot& s : m_slots)
      blocks += s.blocks.size();
    return blocks * block_size * sizeof(T);
  }

private:
  struct alignas(64) Slot
  {
    T* free = nullptr;
    std::vector<std::unique_ptr<T[]>> blocks;
    std::size_t used = block_size;
    std::ptrdiff_t live = 0; // may go below zero in one slot: windows are freed where they are used
  };
  std::vector<Slot> m_slots = std::vector<Slot>(1);
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_OBJECT_POOL_H
