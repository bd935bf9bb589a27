// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Assertions on distance fields (against a reference, against exact values, the properties of
// every distance field, a Steiner-point upper bound where no exact reference exists), on the
// errors the package throws, and GoogleTest names.
#ifndef CGAL_EXT_TEST_SUPPORT_CHECKS_H
#define CGAL_EXT_TEST_SUPPORT_CHECKS_H

#include "meshes.h"

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <iostream>
#include <queue>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace test_support {

/// The largest difference between two distance fields. Two infinities agree; an infinity
/// against a finite value, or a NaN, is an infinite difference. `worst` receives the index.
inline double max_difference(const std::vector<double>& a, const std::vector<double>& b,
                             std::size_t* worst = nullptr)
{
  if(a.size() != b.size())
    return inf;
  double e = 0;
  if(worst)
    *worst = 0;
  for(std::size_t i = 0; i < a.size(); ++i) {
    double d;
    if(std::isnan(a[i]) || std::isnan(b[i]))
      d = inf;
    else if(std::isinf(a[i]) || std::isinf(b[i]))
      d = (a[i] == b[i]) ? 0 : inf;
    else
      d = std::abs(a[i] - b[i]);
    if(d > e) {
      e = d;
      if(worst)
        *worst = i;
    }
  }
  return e;
}

/// Prints the error measured against a reference field, so that the run documents what was
/// reached, and checks that it is within the tolerance; on failure, says where the worst
/// vertex is and what both fields hold there.
inline ::testing::AssertionResult error_within(const std::string& label, const std::string& measure,
                                               const std::string& failure, double error, double tolerance,
                                               std::size_t worst, const std::vector<double>& ours,
                                               const std::vector<double>& reference,
                                               const std::string& reference_name)
{
  std::cout << "[ error    ] " << label << ": " << measure << " = " << error << std::endl;
  if(error <= tolerance)
    return ::testing::AssertionSuccess();
  std::ostringstream msg;
  msg.precision(17);
  msg << label << ": " << failure << error << " > " << tolerance << " at vertex " << worst << " (ours "
      << (worst < ours.size() ? ours[worst] : -1) << ", " << reference_name << " "
      << (worst < reference.size() ? reference[worst] : -1) << ")";
  return ::testing::AssertionFailure() << msg.str();
}

/// Checks `max_difference(ours, reference) <= tolerance * diagonal`, printing the measured error
/// relative to the diagonal.
inline ::testing::AssertionResult agrees(const std::vector<double>& ours, const std::vector<double>& reference,
                                         double diagonal, double tolerance, const std::string& label)
{
  std::size_t worst = 0;
  const double e = max_difference(ours, reference, &worst) / diagonal;
  return error_within(label, "max |ours - reference| / diag", "max error / diag = ", e, tolerance, worst, ours,
                      reference, "reference");
}

/// Checks |ours - exact| <= tolerance * exact at every vertex (so a zero distance must be exactly
/// zero), with the same handling of infinities as `max_difference`; prints the worst ratio.
inline ::testing::AssertionResult agrees_relative(const std::vector<double>& ours, const std::vector<double>& exact,
                                                  double tolerance, const std::string& label)
{
  if(ours.size() != exact.size())
    return ::testing::AssertionFailure() << label << ": " << ours.size() << " distances, expected " << exact.size();
  double worst_ratio = 0;
  std::size_t worst = 0;
  for(std::size_t i = 0; i < ours.size(); ++i) {
    const double d = max_difference({ours[i]}, {exact[i]});
    const double ratio = d == 0 ? 0. : (exact[i] > 0 ? d / exact[i] : inf);
    if(ratio > worst_ratio) {
      worst_ratio = ratio;
      worst = i;
    }
  }
  return error_within(label, "max |ours - exact| / exact", "relative error ", worst_ratio, tolerance, worst, ours,
                      exact, "exact");
}

/// Checks the properties every exact distance field has: it is non-negative, zero at a vertex
/// source, at least the straight-line distance to the nearest source, and 1-Lipschitz along
/// every edge (|d(u) - d(v)| <= |uv|, with `slack` times the diagonal for round-off).
inline ::testing::AssertionResult is_distance_field(const Mesh& m, const std::vector<double>& d,
                                                    const std::vector<Vertex>& sources, double slack = 1e-12)
{
  const double eps = slack * bbox_diagonal(m);
  for(Vertex s : sources)
    if(d[s.idx()] != 0)
      return ::testing::AssertionFailure() << "source " << s << " is at " << d[s.idx()];
  for(Vertex v : m.vertices()) {
    double straight = inf;
    for(Vertex s : sources)
      straight = std::min(straight, distance_3(m.point(s), m.point(v)));
    if(!(d[v.idx()] >= straight - eps))
      return ::testing::AssertionFailure() << "vertex " << v << " at " << d[v.idx()] << " below the straight-line "
                                           << straight;
  }
  for(auto e : m.edges()) {
    const Vertex a = m.vertex(e, 0), b = m.vertex(e, 1);
    const double length = distance_3(m.point(a), m.point(b));
    if(!(std::abs(d[a.idx()] - d[b.idx()]) <= length + eps))
      return ::testing::AssertionFailure() << "edge " << a << "-" << b << " of length " << length
                                           << " joins distances " << d[a.idx()] << " and " << d[b.idx()];
  }
  return ::testing::AssertionSuccess();
}

/// An upper bound of the geodesic distance from `source`: Dijkstra over the vertices and
/// `per_edge` evenly spaced points on every edge, joined by straight segments across each face
/// (each such path lies on the surface).
inline std::vector<double> steiner_upper_bound(const Mesh& m, Vertex source, int per_edge)
{
  std::vector<Point> node;
  for(Vertex v : m.vertices())
    node.push_back(m.point(v));
  std::vector<std::size_t> first_on_edge(m.number_of_edges());
  for(auto e : m.edges()) {
    first_on_edge[e.idx()] = node.size();
    const Point a = m.point(m.vertex(e, 0)), b = m.point(m.vertex(e, 1));
    for(int i = 1; i <= per_edge; ++i)
      node.push_back(a + (b - a) * (double(i) / (per_edge + 1)));
  }
  std::vector<std::vector<std::size_t>> around_face;
  std::vector<std::vector<std::size_t>> faces_of_node(node.size());
  for(Face f : m.faces()) {
    std::vector<std::size_t> ids;
    for(auto h : m.halfedges_around_face(m.halfedge(f))) {
      ids.push_back(m.source(h).idx());
      for(int i = 0; i < per_edge; ++i)
        ids.push_back(first_on_edge[m.edge(h).idx()] + i);
    }
    for(std::size_t id : ids)
      faces_of_node[id].push_back(around_face.size());
    around_face.push_back(ids);
  }
  std::vector<double> d(node.size(), inf);
  typedef std::pair<double, std::size_t> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  d[source.idx()] = 0;
  queue.push(Entry(0., source.idx()));
  while(!queue.empty()) {
    const Entry top = queue.top();
    queue.pop();
    if(top.first > d[top.second])
      continue;
    for(std::size_t f : faces_of_node[top.second])
      for(std::size_t j : around_face[f]) {
        const double c = top.first + distance_3(node[top.second], node[j]);
        if(c < d[j]) {
          d[j] = c;
          queue.push(Entry(c, j));
        }
      }
  }
  d.resize(m.number_of_vertices());
  return d;
}

/// Runs `f` and checks that it throws CGAL_ext::Geodesic_error whose message contains every one
/// of `substrings`.
template <class F>
::testing::AssertionResult throws_geodesic_error(F&& f, std::initializer_list<std::string> substrings)
{
  try {
    f();
  } catch(const CGAL_ext::Geodesic_error& e) {
    const std::string what = e.what();
    for(const std::string& s : substrings)
      if(what.find(s) == std::string::npos)
        return ::testing::AssertionFailure() << "the message \"" << what << "\" does not contain \"" << s << "\"";
    return ::testing::AssertionSuccess() << "threw \"" << what << "\"";
  } catch(const std::exception& e) {
    return ::testing::AssertionFailure() << "threw another exception: " << e.what();
  } catch(...) {
    return ::testing::AssertionFailure() << "threw something that is not an exception";
  }
  return ::testing::AssertionFailure() << "did not throw";
}

/// a name GoogleTest accepts for a parameterized case: every character but letters and digits
/// becomes '_' ("elephant-with-holes" gives "elephant_with_holes")
inline std::string test_name(std::string n)
{
  for(char& c : n)
    if(!std::isalnum(static_cast<unsigned char>(c)))
      c = '_';
  return n;
}

} // namespace test_support

#endif // CGAL_EXT_TEST_SUPPORT_CHECKS_H
