// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The iterator of the tool's containers that make their elements when asked (operator[] by value)
// rather than hold them: the file's polygons, the maps from the file to the mesh.

#ifndef GEODESIC_TOOL_INDEX_ITERATOR_H
#define GEODESIC_TOOL_INDEX_ITERATOR_H

#include <cstddef>
#include <iterator>

namespace geodesic_tool {

/// Element i, i + 1, ... of `Container`, given by value.
template <class Container, class Value>
class Index_iterator
{
public:
  typedef std::forward_iterator_tag iterator_category;
  typedef Value value_type;
  typedef std::ptrdiff_t difference_type;
  typedef const Value* pointer;
  typedef Value reference;

  Index_iterator(const Container* container, std::size_t i) : m_container(container), m_i(i) {}
  Value operator*() const { return (*m_container)[m_i]; }
  Index_iterator& operator++() { return ++m_i, *this; }
  Index_iterator operator++(int)
  {
    Index_iterator old = *this;
    ++m_i;
    return old;
  }
  bool operator==(const Index_iterator& o) const { return m_i == o.m_i; }
  bool operator!=(const Index_iterator& o) const { return m_i != o.m_i; }

private:
  const Container* m_container;
  std::size_t m_i;
};

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_INDEX_ITERATOR_H
