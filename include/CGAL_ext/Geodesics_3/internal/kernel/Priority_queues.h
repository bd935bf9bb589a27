// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_PRIORITY_QUEUES_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_PRIORITY_QUEUES_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

// The priority queues of the solvers: vertices (VTP) and windows or pseudo-sources (MMP), each
// entry a (distance, payload) pair.

/// A vertex waiting with the tentative distance it had when it was queued. An entry whose
/// distance is no longer the vertex's distance is stale and skipped (lazy deletion).
typedef std::pair<double, int> Vertex_entry;

/// Exact order: a binary min-heap of (distance, payload) entries, ties broken by the payload's
/// `operator<` (sequential VTP takes vertices one at a time, sequential MMP windows).
template <class Payload>
class Min_heap
{
public:
  typedef std::pair<double, Payload> Entry;

  void push(double d, const Payload& p)
  {
    m_heap.emplace_back(d, p);
    std::push_heap(m_heap.begin(), m_heap.end(), std::greater<Entry>());
  }
  bool empty() const { return m_heap.empty(); }
  std::size_t size() const { return m_heap.size(); }
  void clear() { m_heap.clear(); }
  const Entry& top() const { return m_heap.front(); }
  void pop()
  {
    std::pop_heap(m_heap.begin(), m_heap.end(), std::greater<Entry>());
    m_heap.pop_back();
  }
  template <class Function>
  void for_each(Function f) const
  {
    for(const Entry& e : m_heap)
      f(e);
  }

private:
  std::vector<Entry> m_heap;
};

typedef Min_heap<int> Vertex_heap;

/// Approximate order in O(1): bucket i holds the (distance, payload) entries with distance in
/// [i w, (i+1) w) (thesis 4.2.2, w = h / tau), in no particular order inside a bucket. The
/// buckets grow on demand. The batched solvers take whole buckets at a time.
template <class Payload>
class Bucket_queue
{
public:
  typedef std::pair<double, Payload> Entry;

  explicit Bucket_queue(double width = 1.) : m_width(width) {}

  void push(double d, const Payload& v)
  {
    const std::size_t i = index_of(d);
    if(i >= m_buckets.size())
      m_buckets.resize(i + 1);
    m_buckets[i].emplace_back(d, v);
    if(i < m_first) {
      forget_consumed();
      m_first = i;
    }
    ++m_size;
  }
  bool empty() const { return m_size == 0; }
  std::size_t size() const { return m_size; }
  /// Empties the queue, keeping the buffers of the buckets in use.
  void clear()
  {
    for(std::size_t i = m_first; i < m_buckets.size(); ++i)
      m_buckets[i].clear();
    m_first = 0;
    m_consumed = 0;
    m_size = 0;
  }

  /// Moves the entries of the lowest non-empty bucket to `out` (which is cleared first), at
  /// most `max_count` of them, oldest first.
  void pop_lowest(std::vector<Entry>& out, std::size_t max_count = std::size_t(-1))
  {
    out.clear();
    // A bucket the wavefront has passed gives its memory back: otherwise every bucket ever
    // used would keep a buffer of its largest size (as much as all entries ever pushed).
    while(m_first < m_buckets.size() && m_buckets[m_first].size() == m_consumed) {
      std::vector<Entry>().swap(m_buckets[m_first]);
      m_consumed = 0;
      ++m_first;
    }
    if(m_first == m_buckets.size())
      return;
    std::vector<Entry>& b = m_buckets[m_first];
    if(m_consumed == 0 && b.size() <= max_count) {
      out.swap(b);
      std::vector<Entry>().swap(b);
    } else {
      const std::size_t n = std::min(max_count, b.size() - m_consumed);
      out.assign(b.begin() + std::ptrdiff_t(m_consumed), b.begin() + std::ptrdiff_t(m_consumed + n));
      m_consumed += n;
    }
    m_size -= out.size();
  }
  /// The bucket a key goes to; right after `pop_lowest()`, `index_of_lowest()` is the one it
  /// took from.
  std::size_t index_of(double d) const
  {
    // Far beyond any wavefront the order hardly matters; cap the number of buckets. (A cast
    // rounds a non-negative quotient down, without a call to floor.)
    const double q = d / m_width;
    return q > 0 ? (q < double(max_buckets) ? std::size_t(q) : max_buckets) : 0;
  }
  std::size_t index_of_lowest() const { return m_first; }
  template <class Function>
  void for_each(Function f) const
  {
    for(std::size_t i = m_first; i < m_buckets.size(); ++i)
      for(std::size_t k = i == m_first ? m_consumed : 0; k < m_buckets[i].size(); ++k)
        f(m_buckets[i][k]);
  }

private:
  static constexpr std::size_t max_buckets = std::size_t(1) << 20;
  double m_width;
  std::vector<std::vector<Entry>> m_buckets;
  std::size_t m_first = 0;
  std::size_t m_consumed = 0; // entries at the front of bucket m_first already popped
  std::size_t m_size = 0;

  void forget_consumed()
  {
    if(m_first < m_buckets.size() && m_consumed > 0) {
      std::vector<Entry>& b = m_buckets[m_first];
      b.erase(b.begin(), b.begin() + std::ptrdiff_t(m_consumed));
    }
    m_consumed = 0;
  }
};

typedef Bucket_queue<int> Vertex_buckets;

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_PRIORITY_QUEUES_H
