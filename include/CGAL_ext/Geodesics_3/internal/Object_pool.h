// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_OBJECT_POOL_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_OBJECT_POOL_H

#include <CGAL_ext/Geodesics_3/internal/Inlining.h>
#include <CGAL_ext/Geodesics_3/internal/Parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <new>
#include <stdexcept>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// What both pools below keep per thread: one slot per thread of the task arena, each with the
/// count of its objects alive. `Slot` has a `live` member.
template <class Slot>
class Pool_slots
{
public:
  /// Gives the pool one slot per thread of the task arena the caller runs in when `parallel`,
  /// one slot otherwise, and returns the calling thread's slot; only with every object freed
  /// (the objects of the slots that go are freed with their blocks).
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

/// A thread's part of an `Indexed_pool`.
template <class T>
struct Indexed_pool_slot
{
  static constexpr std::uint32_t nil = 0xFFFFFFFFu; // no object
  // Objects of a cache line start on one.
  static constexpr std::size_t block_alignment = 64;
  static constexpr unsigned block_bits = 12;
  static constexpr std::uint32_t block_size = 1u << block_bits;
  // A block holds its objects, then their links (used when they are kept apart).
  static constexpr std::size_t block_bytes = (sizeof(T) + sizeof(std::uint32_t)) * block_size;
  struct Free_block
  {
    void operator()(T* block) const
    {
      std::destroy_n(block, block_size);
      ::operator delete(block, std::align_val_t(block_alignment));
    }
  };
  alignas(64) std::vector<std::unique_ptr<T, Free_block>> blocks; // the blocks this slot carved
  std::uint32_t free = nil;
  std::uint32_t block = 0; // the number of the block being carved
  T* block_start = nullptr;  // and its first object
  std::uint32_t used = block_size;
  std::ptrdiff_t live = 0; // may go below zero in one slot: objects are freed where they are used
};

/// The same storage for objects linked by a 32-bit index (`link(i)`, `nil` at the end) instead
/// of a pointer. An index names a block of the pool and a place in it; blocks are numbered
/// across slots (the number taken atomically) and never move, so a thread may follow links into
/// blocks that another thread carved, once the step that linked them has ended.
///
/// Where a link is kept depends on the number of slots. With one, the links are kept apart
/// from the objects, at the end of each block: a walk along a chain reads only them (a few kB
/// that stay in cache) and fetches the objects, far apart in the pool, ahead of their use
/// (`collect_chain`) instead of one after the other. With several, a link is the object's own
/// `std::uint32_t next` member: the objects pass from thread to thread, and kept apart, sixteen
/// links to a cache line, the links of objects that different threads use would share lines,
/// which the cores would pass to and fro (doc/design.md); chains are then walked side by side
/// (`prefetch_chains`), so that their fetches overlap.
template <class T>
class Indexed_pool : public Pool_slots<Indexed_pool_slot<T>>
{
  using Pool_slots<Indexed_pool_slot<T>>::m_slots;
  typedef Indexed_pool_slot<T> Slot;

public:
  static constexpr std::uint32_t nil = Slot::nil;
  static constexpr unsigned block_bits = Slot::block_bits;
  static constexpr std::uint32_t block_size = Slot::block_size;
  static constexpr std::uint32_t max_blocks = 1u << (32 - block_bits);

  // The table of blocks is left uninitialized: only the entries of blocks made are read, and
  // the memory of the rest is never touched.
  Indexed_pool() : m_blocks(new T*[max_blocks]) {}

  /// Gives the pool one slot per thread of the task arena the caller runs in when `parallel`
  /// (`Pool_slots`), and keeps the links where that number of slots wants them when no object is
  /// in use. The blocks and free objects of slots that go are kept by the first one. Returns the
  /// calling thread's slot.
  std::size_t use_one_slot_per_thread(bool parallel)
  {
    const std::size_t count = parallel ? arena_concurrency() : 1;
    for(std::size_t k = count; k < m_slots.size(); ++k) {
      Slot& first = m_slots[0];
      Slot& s = m_slots[k];
      std::move(s.blocks.begin(), s.blocks.end(), std::back_inserter(first.blocks));
      s.blocks.clear();
      first.live += s.live;
      while(s.free != nil) {
        const std::uint32_t i = s.free;
        s.free = link(i);
        link(i) = first.free;
        first.free = i;
      }
    }
    const std::size_t slot = Pool_slots<Slot>::use_one_slot_per_thread(parallel);
    const bool apart = m_slots.size() == 1;
    // (objects still in use, as a run that threw may leave, keep the links where they are: the
    // layout only costs time)
    if(apart == m_links_apart || this->live() != 0)
      return slot;
    for(Slot& s : m_slots) // the free lists move to the other place of the links
      for(std::uint32_t i = s.free; i != nil;) {
        T* block = block_of(i);
        std::uint32_t& from = *link_in(block, place_of(i), m_links_apart);
        *link_in(block, place_of(i), apart) = from;
        i = from;
      }
    m_links_apart = apart;
    return slot;
  }

  T& operator[](std::uint32_t i) const { return block_of(i)[place_of(i)]; }

  /// The index of the object after object i in its chain (or in the free list), or nil.
  std::uint32_t& link(std::uint32_t i) const { return *link_in(block_of(i), place_of(i), m_links_apart); }

  /// Fetches the objects of several chains, `cursors[0..count)` their first objects: one object
  /// of each in turn, so that the reads of the chains overlap (a chain that another thread wrote
  /// is a chain of cache misses). The cursors are left at nil.
  void prefetch_chains(std::uint32_t* cursors, std::size_t count) const
  {
    for(bool any = true; any;) {
      any = false;
      for(std::size_t k = 0; k < count; ++k) {
        if(cursors[k] == nil)
          continue;
        cursors[k] = prefetch_and_follow(cursors[k]);
        any = true;
      }
    }
  }

  /// An object of the slot set to `value`; returns it, and its index in `index`. Its link is
  /// left as it was, or as `value` has it. (Inlined: GCC leaves it out of line in VTP's
  /// `propagate`.)
  CGAL_EXT_ALWAYS_INLINE T* allocate(std::size_t slot, const T& value, std::uint32_t& index)
  {
    std::uint32_t* link;
    return allocate(slot, value, index, link);
  }
  /// The same, giving the object's link too.
  CGAL_EXT_ALWAYS_INLINE T* allocate(std::size_t slot, const T& value, std::uint32_t& index, std::uint32_t*& link)
  {
    T* p = allocate(slot, index, link);
    *p = value;
    return p;
  }
  /// The same, the object left as it was (to be set by the caller).
  CGAL_EXT_ALWAYS_INLINE T* allocate(std::size_t slot, std::uint32_t& index, std::uint32_t*& link)
  {
    Slot& s = m_slots[slot];
    T* p;
    if(s.free != nil) {
      index = s.free;
      T* block = block_of(index);
      p = block + place_of(index);
      link = link_in(block, place_of(index), m_links_apart);
      s.free = *link;
    } else {
      if(s.used == block_size)
        new_block(s);
      index = (s.block << block_bits) | s.used;
      p = s.block_start + s.used;
      link = link_in(s.block_start, s.used, m_links_apart);
      ++s.used;
    }
    ++s.live;
    return p;
  }

  /// A chain walked along its links, to be freed whole by `free_chain`.
  struct Walked_chain
  {
    std::uint32_t first = nil;
    std::uint32_t* last_link = nullptr;
    std::ptrdiff_t count = 0;
  };

  /// Appends the addresses of the objects from `i` on along their links to `objects`, asking the
  /// processor to fetch each when the links are apart (their reads then overlap instead of
  /// waiting for each other); returns what `free_chain` needs.
  Walked_chain collect_chain(std::uint32_t i, std::vector<T*>& objects) const
  {
    if(m_links_apart)
      return walk_chain<true>(i, [&](T* object) {
#if defined(__GNUC__)
        __builtin_prefetch(object);
#endif
        objects.push_back(object);
      });
    return walk_chain<false>(i, [&](T* object) { objects.push_back(object); });
  }

  /// Frees a walked chain into the slot. It joins the free list as it is linked: only its last
  /// link is written.
  void free_chain(std::size_t slot, const Walked_chain& chain)
  {
    if(chain.first == nil)
      return;
    Slot& s = m_slots[slot];
    *chain.last_link = s.free;
    s.free = chain.first;
    s.live -= chain.count;
  }

  /// Frees object i alone into the slot.
  void free_one(std::size_t slot, std::uint32_t i) { free_one(slot, i, &link(i)); }
  /// The same, `i_link` its link.
  void free_one(std::size_t slot, std::uint32_t i, std::uint32_t* i_link)
  {
    Slot& s = m_slots[slot];
    *i_link = s.free;
    s.free = i;
    --s.live;
  }

  /// Frees the objects from `i` on along their links.
  void release_chain(std::size_t slot, std::uint32_t i)
  {
    free_chain(slot, m_links_apart ? walk_chain<true>(i, [](T*) {}) : walk_chain<false>(i, [](T*) {}));
  }

  std::size_t bytes() const { return std::size_t(m_block_count.load()) * Slot::block_bytes; }

private:
  T* block_of(std::uint32_t i) const { return m_blocks[i >> block_bits]; }
  // Calls `visit(address)` for the objects from `i` on along their links (it must not change
  // them); returns the chain's first object, last link and length.
  template <bool Apart, class Visit>
  CGAL_EXT_ALWAYS_INLINE Walked_chain walk_chain(std::uint32_t i, Visit visit) const
  {
    Walked_chain chain;
    chain.first = i;
    while(i != nil) {
      T* block = block_of(i);
      chain.last_link = link_in(block, place_of(i), Apart);
      visit(block + place_of(i));
      i = *chain.last_link;
      ++chain.count;
    }
    return chain;
  }
  // A step of the prefetching walks: asks for object i, returns its link.
  std::uint32_t prefetch_and_follow(std::uint32_t i) const
  {
    T* block = block_of(i);
#if defined(__GNUC__)
    if(m_links_apart) // (otherwise reading the link fetches the object)
      __builtin_prefetch(block + place_of(i));
#endif
    return *link_in(block, place_of(i), m_links_apart);
  }
  static std::uint32_t place_of(std::uint32_t i) { return i & (block_size - 1); }
  // Where the link of the object at `place` of `block` is: in the block's array of links
  // (`apart`), or the object's `next`.
  static std::uint32_t* link_in(T* block, std::uint32_t place, bool apart)
  {
    return apart ? reinterpret_cast<std::uint32_t*>(block + block_size) + place : &block[place].next;
  }

  void new_block(Slot& s)
  {
    const std::uint32_t b = m_block_count.fetch_add(1, std::memory_order_relaxed);
    if(b >= max_blocks)
      throw std::length_error("geodesic windows: more than 2^32 windows alive at once");
    T* block = static_cast<T*>(::operator new(Slot::block_bytes, std::align_val_t(Slot::block_alignment)));
    // default-initialized, not zeroed, as in Object_pool: an object is written whole when it is
    // made (`allocate`, or its caller), and a link before it is read
    std::uninitialized_default_construct_n(block, block_size);
    s.blocks.emplace_back(block);
    m_blocks[b] = block;
    s.block = b;
    s.block_start = block;
    s.used = 0;
  }

  std::unique_ptr<T*[]> m_blocks;
  bool m_links_apart = true; // one slot
  std::atomic<std::uint32_t> m_block_count{0};
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_OBJECT_POOL_H
