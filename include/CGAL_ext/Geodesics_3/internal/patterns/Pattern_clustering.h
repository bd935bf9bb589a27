// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_CLUSTERING_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_CLUSTERING_H

// Candidate matches grouped into candidate instances (thesis Algorithm 6): the geodesic
// consistency matrix W of the matches (Eq. 5.1-5.2, with the scales of Eq. 5.6), its spectral
// embedding in R^3, and a mean shift weighted by Eq. 5.3 in that embedding.
//
// W has no entry between matches that no pair of samples can make consistent, so it falls apart
// into connected components (groups of nearby instances); each component is embedded by its own
// three leading eigenvectors (the leading eigenvectors of a block-diagonal matrix are those of
// its blocks), which keeps three coordinates enough to tell the instances of a component apart.

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// A candidate match: sample `patch_sample` of the marked patch (its index among the patch's
/// samples) looks like sample `sample` of the mesh at scale `scale` (instance size over patch size).
struct Pattern_match
{
  std::size_t patch_sample;
  std::size_t sample;
  double scale = 1;
  double signature_distance = 0;
};

/// Eq. 5.2 with the scales of Eq. 5.6: how well the distance between two samples of the patch is
/// kept between their matches; 1 when kept exactly, 0 when either distance is missing.
/// Samples are placed only to within the sampling's spacing, which makes the ratio of two short
/// distances meaningless; `slack` (the spacing) is added to both distances so that a pair counts
/// by how far apart its samples are relative to that uncertainty.
inline double match_consistency(double patch_distance, double mesh_distance, double scale_a, double scale_b,
                                double slack)
{
  const double scale = 0.5 * (scale_a + scale_b);
  const double expected = (patch_distance + slack) * scale;
  const double measured = mesh_distance + slack * scale;
  if(!(patch_distance > 0) || !(mesh_distance > 0) || !std::isfinite(mesh_distance))
    return 0;
  return std::min(expected / measured, measured / expected);
}

/// Up to this many rows, the embedding's eigenvectors come from a dense solver; above, from
/// Lanczos iterations, whose cost does not grow as the cube of the rows.
constexpr Eigen::Index embedding_dense_limit = 48;

/// The leading eigenvectors of a symmetric matrix as rows of coordinates, scaled by the square
/// root of their eigenvalues; dense for matrices of up to `dense_limit` rows, Spectra's Lanczos
/// above (the dense solver computes every eigenvector, where three are wanted).
inline std::vector<std::array<double, 3>> spectral_embedding(const Eigen::SparseMatrix<double>& w,
                                                             Eigen::Index dense_limit = embedding_dense_limit)
{
  const Eigen::Index n = w.rows();
  std::vector<std::array<double, 3>> points(std::size_t(n), std::array<double, 3>{0, 0, 0});
  Eigen::MatrixXd vectors;
  Eigen::VectorXd values;
  // the leading (up to three) eigenpairs by the dense solver, largest first
  const auto solve_dense = [&] {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver{Eigen::MatrixXd(w)};
    const Eigen::Index m = std::min<Eigen::Index>(3, n);
    vectors = solver.eigenvectors().rightCols(m).rowwise().reverse();
    values = solver.eigenvalues().tail(m).reverse();
  };
  // Lanczos needs more basis vectors than it finds eigenvectors, and no more than the rows
  if(n <= std::max<Eigen::Index>(dense_limit, 4)) {
    solve_dense();
  } else {
    Spectra::SparseSymMatProd<double> product(w);
    Spectra::SymEigsSolver<Spectra::SparseSymMatProd<double>> solver(product, 3, std::min<Eigen::Index>(n, 24));
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-10);
    if(solver.info() == Spectra::CompInfo::Successful) {
      vectors = solver.eigenvectors();
      values = solver.eigenvalues();
    } else {
      solve_dense(); // Lanczos did not converge
    }
  }
  for(Eigen::Index c = 0; c < vectors.cols(); ++c) {
    // an eigenvector's sign is arbitrary: fix it so that its largest entry is positive
    Eigen::Index largest;
    vectors.col(c).cwiseAbs().maxCoeff(&largest);
    const double sign = vectors(largest, c) < 0 ? -1.0 : 1.0;
    const double scale = std::sqrt(std::max(0.0, values(c))) * sign;
    for(Eigen::Index r = 0; r < n; ++r)
      points[std::size_t(r)][std::size_t(c)] = vectors(r, c) * scale;
  }
  return points;
}

/// Mean shift of Algorithm 6 on embedded points: the points in decreasing `weight` are moved to
/// the mean of their `k` nearest until they stop, and the `k` nearest of where a point stops
/// open a cluster when none of them is in one yet. Neighbours by CGAL's k-d tree.
inline std::vector<std::vector<std::size_t>> weighted_mean_shift(const std::vector<std::array<double, 3>>& points,
                                                                 const std::vector<double>& weight, std::size_t k)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Point_3 Point;
  typedef CGAL::Search_traits_adapter<std::size_t, CGAL::Pointer_property_map<Point>::type, CGAL::Search_traits_3<K>>
    Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef typename Search::Tree Tree;
  typedef typename Search::Distance Distance;

  std::vector<std::vector<std::size_t>> clusters;
  const std::size_t n = points.size();
  if(n == 0)
    return clusters;
  k = std::max<std::size_t>(1, std::min(k, n));
  std::vector<Point> location(n);
  double extent = 0;
  for(std::size_t i = 0; i < n; ++i) {
    location[i] = Point(points[i][0], points[i][1], points[i][2]);
    extent = std::max({extent, std::abs(points[i][0]), std::abs(points[i][1]), std::abs(points[i][2])});
  }
  const auto map = CGAL::make_property_map(location);
  std::vector<std::size_t> keys(n);
  std::iota(keys.begin(), keys.end(), std::size_t(0));
  Tree tree(keys.begin(), keys.end(), typename Tree::Splitter(), Traits(map));
  const Distance distance(map);
  const auto nearest = [&](const Point& x) {
    std::vector<std::size_t> found;
    Search search(tree, x, unsigned(k), 0, true, distance);
    for(const auto& hit : search)
      found.push_back(hit.first);
    return found;
  };

  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return weight[a] > weight[b]; });
  std::vector<bool> clustered(n, false);
  const double still = 1e-9 * std::max(extent, 1e-300);
  for(std::size_t start : order) {
    if(clustered[start])
      continue;
    Point x = location[start];
    std::vector<std::size_t> near = nearest(x);
    for(int iteration = 0; iteration < 50; ++iteration) {
      double sum[3] = {0, 0, 0};
      for(std::size_t j : near) {
        sum[0] += location[j].x();
        sum[1] += location[j].y();
        sum[2] += location[j].z();
      }
      const Point moved(sum[0] / near.size(), sum[1] / near.size(), sum[2] / near.size());
      const bool stopped = CGAL::squared_distance(moved, x) <= still * still;
      x = moved;
      near = nearest(x);
      if(stopped)
        break;
    }
    if(std::none_of(near.begin(), near.end(), [&](std::size_t j) { return bool(clustered[j]); })) {
      for(std::size_t j : near)
        clustered[j] = true;
      std::sort(near.begin(), near.end());
      clusters.push_back(near);
    }
  }
  return clusters;
}

/// Algorithm 6: the candidate instances among `matches`, each a list of match indices.
/// `patch_distance(i, j)` is the geodesic distance between patch samples i and j,
/// `sample_distance(a, b)` that between two mesh samples (`+infinity` when farther than any
/// consistent pair can be); `cutoff` is c0.
inline std::vector<std::vector<std::size_t>>
cluster_matches(const std::vector<Pattern_match>& matches,
                const std::function<double(std::size_t, std::size_t)>& patch_distance,
                const std::function<double(std::size_t, std::size_t)>& sample_distance, double cutoff,
                double slack, std::size_t patch_samples)
{
  const std::size_t n = matches.size();
  // W, kept as the consistency of each pair above the cut-off (Eq. 5.1 is read from it)
  std::vector<std::vector<std::pair<std::size_t, double>>> consistent(n);
  for(std::size_t a = 0; a < n; ++a)
    for(std::size_t b = a + 1; b < n; ++b) {
      const Pattern_match& ma = matches[a];
      const Pattern_match& mb = matches[b];
      if(ma.patch_sample == mb.patch_sample || ma.sample == mb.sample)
        continue;
      const double c = match_consistency(patch_distance(ma.patch_sample, mb.patch_sample),
                                         sample_distance(ma.sample, mb.sample), ma.scale, mb.scale, slack);
      if(c > cutoff) {
        consistent[a].emplace_back(b, c);
        consistent[b].emplace_back(a, c);
      }
    }
  // connected components of W
  std::vector<std::size_t> component(n, n);
  std::vector<std::vector<std::size_t>> members;
  for(std::size_t s = 0; s < n; ++s) {
    if(component[s] != n || consistent[s].empty())
      continue;
    members.emplace_back();
    std::vector<std::size_t> stack{s};
    component[s] = members.size() - 1;
    while(!stack.empty()) {
      const std::size_t a = stack.back();
      stack.pop_back();
      members.back().push_back(a);
      for(const auto& [b, c] : consistent[a])
        if(component[b] == n) {
          component[b] = members.size() - 1;
          stack.push_back(b);
        }
    }
    std::sort(members.back().begin(), members.back().end());
  }

  std::vector<std::vector<std::size_t>> clusters;
  std::vector<std::size_t> local(n, 0);
  for(const std::vector<std::size_t>& group : members) {
    const std::size_t m = group.size();
    for(std::size_t i = 0; i < m; ++i)
      local[group[i]] = i;
    std::vector<Eigen::Triplet<double>> entries;
    for(std::size_t a : group)
      for(const auto& [b, c] : consistent[a])
        entries.emplace_back(Eigen::Index(local[a]), Eigen::Index(local[b]), (c - cutoff) / (1 - cutoff));
    Eigen::SparseMatrix<double> w{Eigen::Index(m), Eigen::Index(m)};
    w.setFromTriplets(entries.begin(), entries.end());
    const std::vector<std::array<double, 3>> points = spectral_embedding(w);

    // Eq. 5.3: a point's weight is the consistency among its k nearest in the embedding
    const std::size_t k = std::min(patch_samples, m);
    std::vector<double> weight(m, 0.0);
    {
      std::vector<std::size_t> by_distance(m);
      for(std::size_t i = 0; i < m; ++i) {
        std::iota(by_distance.begin(), by_distance.end(), std::size_t(0));
        const auto squared = [&](std::size_t j) {
          double s = 0;
          for(int c = 0; c < 3; ++c)
            s += (points[j][c] - points[i][c]) * (points[j][c] - points[i][c]);
          return s;
        };
        std::partial_sort(by_distance.begin(), by_distance.begin() + std::ptrdiff_t(k), by_distance.end(),
                          [&](std::size_t x, std::size_t y) { return squared(x) < squared(y) || (squared(x) == squared(y) && x < y); });
        std::vector<bool> near(m, false);
        for(std::size_t j = 0; j < k; ++j)
          near[by_distance[j]] = true;
        for(std::size_t j = 0; j < k; ++j)
          for(const auto& [b, c] : consistent[group[by_distance[j]]])
            if(near[local[b]])
              weight[i] += c;
      }
    }
    for(std::vector<std::size_t>& cluster : weighted_mean_shift(points, weight, k)) {
      for(std::size_t& i : cluster)
        i = group[i];
      clusters.push_back(std::move(cluster));
    }
  }
  return clusters;
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_CLUSTERING_H
