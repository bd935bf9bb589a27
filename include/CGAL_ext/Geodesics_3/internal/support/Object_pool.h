// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_OBJECT_POOL_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_OBJECT_POOL_H

#include <CGAL_ext/Geodesics_3/internal/support/Inlining.h>
#include <CGAL_ext/Geodesics_3/internal/support/Parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// Makes room for one more element of `v` before it is needed (so that a push_back that follows
/// the making of an object cannot throw and lose the object), growing it as push_back would.
template <class T>
void reserve_one_more(std::vector<T>& v)
{
  if(v.size() == v.capacity())
    v.reserve(2 * v.size() + 8);
}

/// An allocator that leaves the elements a container adds without a value uninitialized (for
/// trivial types: `std::vector::resize` then writes nothing), for buffers whose every element is
/// written before it is read. So `vector(n)`, `resize(n)` and `emplace_back()` give elements of
/// no value (`resize(n, value)`, `insert` and `push_back` still copy theirs).
template <class T>
struct Uninitialized_allocator : std::allocator<T>
{
  template <class U>
  struct rebind
  {
    typedef Uninitialized_allocator<U> other;
  };
  Uninitialized_allocator() = default;
  template <class U>
  Uninitialized_allocator(const Uninitialized_allocator<U>&) noexcept
  {
  }
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new(static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args)
  {
    ::new(static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// What both pools below keep per thread: one slot per thread of the task arena, each with the
/// count of its objects alive. `Slot` has a `live` member.
template <class Slot>
class Pool_slots
{
public:
  /// Gives the pool one slot per thread of the task arena the caller runs in when `parallel`,
  /// one slot otherwise, and returns the calling thread's slot. (For `Object_pool`: only with
  /// every object freed, since the objects of the slots that go are freed with their blocks;
  /// `Run_pool` hands them over first.)
  std::size_t use_one_slot_per_thread(bool parallel)
  {
    m_slots.resize(parallel ? arena_concurrency() : 1);
    return parallel ? this_thread_slot() : 0;
  }
  std::size_t number_of_slots() const { return m_slots.size(); }

  /// Objects alive (exact between parallel steps).
  std::size_t live() const
  {
    std::ptrdiff_t n = 0;
    for(const Slot& s : m_slots)
      n += s.live;
    return std::size_t(n);
  }

protected:
  std::vector<Slot> m_slots = std::vector<Slot>(1);
};

/// A thread's part of an `Object_pool`.
template <class T>
struct Object_pool_slot
{
  static constexpr std::size_t block_size = 4096;
  alignas(64) T* free = nullptr;
  std::vector<std::unique_ptr<T[]>> blocks;
  std::size_t used = block_size;
  std::ptrdiff_t live = 0; // may go below zero in one slot: windows are freed where they are used
};

/// Storage of windows (any type with a `next` pointer to its own type): no allocation per
/// window once the pool has grown to the size of the wavefront, and no sharing between threads.
/// Each thread uses its own slot: blocks it carved and a list of freed windows (a window freed
/// by another thread than the one that made it simply joins that thread's list). Windows never
/// move, so they are linked by pointer.
template <class T>
class Object_pool : public Pool_slots<Object_pool_slot<T>>
{
public:
  /// An object of the slot, as it was left when freed (default-initialized when new).
  T* allocate(std::size_t slot)
  {
    auto& s = this->m_slots[slot];
    constexpr std::size_t block_size = Object_pool_slot<T>::block_size;
    ++s.live;
    if(T* p = s.free) {
      s.free = p->next;
      return p;
    }
    if(s.used == block_size) {
      // default-initialized, not zeroed: a window is written whole when it is made
      s.blocks.push_back(std::unique_ptr<T[]>(new T[block_size]));
      s.used = 0;
    }
    return &s.blocks.back()[s.used++];
  }
  /// Frees `w` and the objects linked after it.
  void release_chain(std::size_t slot, T* w)
  {
    auto& s = this->m_slots[slot];
    while(w) {
      T* next = w->next;
      w->next = s.free;
      s.free = w;
      --s.live;
      w = next;
    }
  }
  /// Frees `w` alone.
  void release(std::size_t slot, T* w)
  {
    w->next = nullptr;
    release_chain(slot, w);
  }
  std::size_t bytes() const
  {
    std::size_t blocks = 0;
    for(const auto& s : this->m_slots)
      blocks += s.blocks.size();
    return blocks * Object_pool_slot<T>::block_size * sizeof(T);
  }
};

/// A thread's part of a `Run_pool`.
template <class T>
struct Run_pool_slot
{
  static constexpr std::uint32_t nil = 0xFFFFFFFFu;
  static constexpr unsigned lanes = 2;
  static constexpr unsigned block_bits = 6;
  static constexpr std::uint32_t block_size = 1u << block_bits;
  static constexpr unsigned group_bits = 6; // blocks a group
  static constexpr std::uint32_t group_size = 1u << group_bits;
  static constexpr std::size_t alignment = 64;
  // Where a lane makes its next objects: its block, and the objects made in it so far.
  struct Lane
  {
    std::uint32_t block = nil;
    T* start = nullptr;
    std::uint32_t used = block_size; // (none: a block is entered first)
  };
  struct Free_group
  {
    void operator()(void* memory) const { ::operator delete(memory, std::align_val_t(alignment)); }
  };
  alignas(64) Lane lane[lanes];
  std::vector<std::unique_ptr<void, Free_group>> groups; // the memory of the groups it made
  std::vector<std::uint32_t> free_blocks; // blocks whose objects were all freed, to make again
  std::uint32_t group = 0;                // the group it carves blocks from
  std::uint32_t group_used = group_size;  // and its blocks carved so far (all: none to carve)
  std::ptrdiff_t live = 0; // may go below zero in one slot: objects are freed where they are used
};

/// Storage of VTP's windows in runs: each thread makes its objects one after the other in
/// blocks of 64, so that the objects a thread makes in a row for one chain lie side by side (a
/// *run*, named by its first object's index and its length) and are found without a link. A
/// block counts its objects not yet freed; the thread that frees the last one takes the block
/// back, to make new objects in it. Objects are named by a 32-bit index (a group of blocks and a
/// place in it); groups are numbered across threads (the number taken atomically) and never
/// move, so a thread may read objects that another thread made, once the step that made them has
/// ended. Each thread has two *lanes*, each making in its own block, so that it can make two
/// runs at once (the children of a list on both sides of its face).
///
/// A run never crosses from one block into the next: `continues_run` says whether a new object
/// extends a run.
template <class T>
class Run_pool : public Pool_slots<Run_pool_slot<T>>
{
  using Pool_slots<Run_pool_slot<T>>::m_slots;
  typedef Run_pool_slot<T> Slot;

public:
  static constexpr std::uint32_t nil = Slot::nil;
  static constexpr unsigned lanes = Slot::lanes;
  static constexpr unsigned block_bits = Slot::block_bits;
  static constexpr std::uint32_t block_size = Slot::block_size;
  static constexpr unsigned group_bits = Slot::group_bits;
  static constexpr std::uint32_t group_size = Slot::group_size;
  static constexpr unsigned group_index_bits = block_bits + group_bits;
  static constexpr std::uint32_t max_groups = (1u << (32 - group_index_bits)) - 1; // (nil names no object)

  // The table of groups is left uninitialized: only the entries of groups made are read, and
  // the memory of the rest is never touched.
  Run_pool() : m_groups(new Group[max_groups]) {}

  /// Gives the pool one slot per thread of the task arena the caller runs in when `parallel`
  /// (`Pool_slots`); returns the calling thread's slot. The slots that go give their blocks
  /// (those whose objects are all freed, and what their lanes did not make) to the first one,
  /// and so do the threads' shared blocks when one slot is left; with several, the first slot
  /// shares what it has beyond a few. Objects may be alive: they are freed in any slot.
  std::size_t use_one_slot_per_thread(bool parallel)
  {
    const std::size_t count = parallel ? arena_concurrency() : 1;
    for(std::size_t k = count; k < m_slots.size(); ++k) {
      Slot& s = m_slots[k];
      for(typename Slot::Lane& l : s.lane)
        leave_block(0, l);
      Slot& first = m_slots[0];
      first.free_blocks.insert(first.free_blocks.end(), s.free_blocks.begin(), s.free_blocks.end());
      std::move(s.groups.begin(), s.groups.end(), std::back_inserter(first.groups));
      s.groups.clear();
      for(std::uint32_t b = s.group_used; b < group_size; ++b)
        first.free_blocks.push_back((s.group << group_bits) | b);
      first.live += s.live;
    }
    std::vector<std::uint32_t>& blocks = m_slots[0].free_blocks;
    if(count == 1) {
      blocks.insert(blocks.end(), m_shared_free_blocks.begin(), m_shared_free_blocks.end());
      m_shared_free_blocks.clear();
    } else if(blocks.size() > shared_batch) { // (the others would make new groups beside them)
      m_shared_free_blocks.insert(m_shared_free_blocks.end(), blocks.begin() + shared_batch, blocks.end());
      blocks.resize(shared_batch);
    }
    return Pool_slots<Slot>::use_one_slot_per_thread(parallel);
  }

  T& operator[](std::uint32_t i) const { return m_groups[i >> group_index_bits].objects[i & group_mask]; }

  /// Makes an object in the next place of the slot's `lane` by `make(object)` (the object as it
  /// was left when freed, or default-initialized), and keeps it if `make` returns true: then
  /// sets `index` to it and returns true. (Inlined: GCC leaves it out of line in VTP's
  /// `propagate`, which costs a call a window.)
  template <class Make>
  CGAL_EXT_ALWAYS_INLINE bool make(std::size_t slot, unsigned lane, std::uint32_t& index, Make make)
  {
    Slot& s = m_slots[slot];
    typename Slot::Lane& l = s.lane[lane];
    if(l.used == block_size)
      enter_new_block(slot, l);
    if(!make(l.start[l.used]))
      return false;
    index = (l.block << block_bits) | l.used;
    ++l.used;
    ++s.live;
    return true;
  }
  /// The same, the object set to `value`; returns its index.
  std::uint32_t make_copy(std::size_t slot, unsigned lane, const T& value)
  {
    std::uint32_t index = nil;
    make(slot, lane, index, [&](T& object) {
      object = value;
      return true;
    });
    return index;
  }

  /// Whether an object made at `index` extends the run of `count` objects from `first`.
  static bool continues_run(std::uint32_t first, std::uint32_t count, std::uint32_t index)
  {
    return index == first + count && (index & (block_size - 1)) != 0;
  }

  /// Frees the run of `count` objects from `first` into the slot (the thread's).
  void free_run(std::size_t slot, std::uint32_t first, std::uint32_t count)
  {
    m_slots[slot].live -= std::ptrdiff_t(count);
    release(slot, first >> block_bits, count);
  }

  std::size_t bytes() const { return std::size_t(m_group_count.load()) * group_bytes; }

private:
  static_assert(std::is_trivially_destructible<T>::value, "the groups' objects are not destroyed");
  static constexpr std::uint32_t group_mask = (1u << group_index_bits) - 1;
  static constexpr std::size_t alignment = Slot::alignment;
  // A group's objects, then each block's count of objects not yet freed (and one while a lane
  // makes in it).
  static constexpr std::size_t group_bytes = (std::size_t(1) << group_index_bits) * sizeof(T) +
                                             group_size * sizeof(std::atomic<std::int32_t>);
  struct Group
  {
    T* objects;
    std::atomic<std::int32_t>* counts;
  };

  std::atomic<std::int32_t>& count_of(std::uint32_t block) const
  {
    return m_groups[block >> group_bits].counts[block & (group_size - 1)];
  }

  // Takes `count` from the block's count; the thread that takes it to zero gets the block back.
  // A thread that has many blocks to make in gives some to the others: a block goes to the
  // thread that frees its last object, which need not be the one that will need it.
  void release(std::size_t slot, std::uint32_t block, std::uint32_t count)
  {
    if(count_of(block).fetch_sub(std::int32_t(count), std::memory_order_acq_rel) != std::int32_t(count))
      return;
    std::vector<std::uint32_t>& blocks = m_slots[slot].free_blocks;
    blocks.push_back(block);
    if(blocks.size() >= 2 * shared_batch && m_slots.size() > 1) {
      std::lock_guard<std::mutex> lock(m_shared_mutex);
      m_shared_free_blocks.insert(m_shared_free_blocks.end(), blocks.end() - shared_batch, blocks.end());
      blocks.resize(blocks.size() - shared_batch);
    }
  }

  // Takes blocks that other threads gave, if any.
  void take_shared_blocks(std::vector<std::uint32_t>& blocks)
  {
    std::lock_guard<std::mutex> lock(m_shared_mutex);
    const std::size_t n = std::min(m_shared_free_blocks.size(), shared_batch);
    blocks.insert(blocks.end(), m_shared_free_blocks.end() - std::ptrdiff_t(n), m_shared_free_blocks.end());
    m_shared_free_blocks.resize(m_shared_free_blocks.size() - n);
  }

  // The lane leaves its block: the places it did not make and the lane's own count go.
  void leave_block(std::size_t slot, typename Slot::Lane& l)
  {
    if(l.block != nil)
      release(slot, l.block, block_size - l.used + 1);
    l.block = nil;
    l.used = block_size;
  }

  void enter_new_block(std::size_t slot, typename Slot::Lane& l)
  {
    leave_block(slot, l);
    Slot& s = m_slots[slot];
    std::uint32_t block;
    if(s.free_blocks.empty() && m_slots.size() > 1)
      take_shared_blocks(s.free_blocks);
    if(!s.free_blocks.empty()) {
      block = s.free_blocks.back();
      s.free_blocks.pop_back();
    } else {
      if(s.group_used == group_size)
        new_group(s);
      block = (s.group << group_bits) | s.group_used++;
    }
    count_of(block).store(std::int32_t(block_size + 1), std::memory_order_relaxed);
    l.block = block;
    l.start = &(*this)[block << block_bits];
    l.used = 0;
  }

  void new_group(Slot& s)
  {
    std::unique_ptr<void, typename Slot::Free_group> memory(::operator new(group_bytes, std::align_val_t(alignment)));
    reserve_one_more(s.groups);
    // (numbered once made, so that bytes() counts only groups that exist)
    const std::uint32_t g = m_group_count.fetch_add(1, std::memory_order_relaxed);
    if(g >= max_groups) {
      m_group_count.fetch_sub(1, std::memory_order_relaxed);
      throw std::length_error("geodesic windows: the pool's 2^32 places are used up");
    }
    s.groups.push_back(std::move(memory));
    T* objects = static_cast<T*>(s.groups.back().get());
    // default-initialized, not zeroed, as in Object_pool: an object is written whole when it is
    // made
    std::uninitialized_default_construct_n(objects, std::size_t(1) << group_index_bits);
    auto* counts = reinterpret_cast<std::atomic<std::int32_t>*>(objects + (std::size_t(1) << group_index_bits));
    for(std::uint32_t b = 0; b < group_size; ++b)
      new(counts + b) std::atomic<std::int32_t>(0);
    m_groups[g] = Group{objects, counts};
    s.group = g;
    s.group_used = 0;
  }

  static constexpr std::size_t shared_batch = 16; // blocks

  std::unique_ptr<Group[]> m_groups;
  // (on lines of their own: every thread reads m_groups and m_slots at every object)
  alignas(64) std::atomic<std::uint32_t> m_group_count{0};
  alignas(64) std::mutex m_shared_mutex;
  std::vector<std::uint32_t> m_shared_free_blocks;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_OBJECT_POOL_H
