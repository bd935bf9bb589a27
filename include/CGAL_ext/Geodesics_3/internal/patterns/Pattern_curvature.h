// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_CURVATURE_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_CURVATURE_H

// Per-vertex principal curvatures and areas, what the pattern signatures are made of.
// The curvatures are CGAL's Monge_via_jet_fitting on the rings around each vertex.

#include <CGAL_ext/Geodesics_3/internal/support/Parallel_for.h>

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_svd.h>
#include <CGAL/Eigen_vector.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/QR>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// Principal curvatures of a vertex, `k_max >= k_min`, signed with respect to the normal of the
/// faces' orientation; 0 where the jet fitting has too few points (isolated or tiny components).
struct Principal_curvatures
{
  double k_max = 0;
  double k_min = 0;
};

/// The least-squares solver of the jet fitting (a model of CGAL's `SvdTraits`, in place of
/// `CGAL::Eigen_svd`, whose singular value decomposition with both factors took most of the
/// fitting's time): a QR decomposition with column pivoting, as accurate on the fitting's tall,
/// full-rank systems (CGAL preconditions them). A system the pivoting finds rank-deficient (a
/// degenerate neighbourhood) goes to `Eigen_svd`, whose minimum-norm solution stays bounded. The
/// condition number returned on the QR's path is the ratio of the largest to the smallest
/// diagonal entry of its triangular factor, a lower bound of it (the fitting only reports it).
struct Jet_least_squares
{
  typedef double FT;
  typedef CGAL::Eigen_vector<FT> Vector;
  typedef CGAL::Eigen_matrix<FT> Matrix;

  static FT solve(const Matrix& M, Vector& B)
  {
    const Eigen::ColPivHouseholderQR<Matrix::EigenType> qr(M.eigen_object());
    if(qr.rank() < M.eigen_object().cols())
      return CGAL::Eigen_svd::solve(M, B);
    B.eigen_object() = qr.solve(Vector::EigenType(B.eigen_object()));
    const auto diagonal = qr.matrixQR().diagonal().cwiseAbs();
    return diagonal.maxCoeff() / diagonal.minCoeff();
  }
};

/// Fits a degree-2 jet to each vertex and the rings around it (as many rings as bring at least
/// `min_points` points, at most `max_rings`), oriented by the vertex normal. By vertex index.
/// `LeastSquares`: the fitting's `SvdTraits`.
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class LeastSquares = Jet_least_squares>
std::vector<Principal_curvatures> vertex_principal_curvatures(const TriangleMesh& tm, VertexPointMap vpm,
                                                             VertexIndexMap vim, bool parallel,
                                                             std::size_t min_points = 16, int max_rings = 4)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel Kernel;
  typedef CGAL::Monge_via_jet_fitting<Kernel, CGAL::Simple_cartesian<double>, LeastSquares> Fitting;

  std::vector<vertex_descriptor> vertex_of_index(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm))
    vertex_of_index[std::size_t(get(vim, v))] = v;
  std::vector<Principal_curvatures> curvatures(vertex_of_index.size());
  for_each_index(parallel, vertex_of_index.size(), 256, [&](std::size_t i, std::size_t) {
    const vertex_descriptor v = vertex_of_index[i];
    if(halfedge(v, tm) == GT::null_halfedge())
      return;
    // breadth-first rings; `ring_begin` marks where the last complete ring starts
    std::vector<vertex_descriptor> ring{v};
    std::size_t ring_begin = 0;
    for(int r = 0; r < max_rings && ring.size() < min_points; ++r) {
      const std::size_t ring_end = ring.size();
      for(std::size_t k = ring_begin; k < ring_end; ++k)
        for(vertex_descriptor w : CGAL::vertices_around_target(ring[k], tm))
          if(std::find(ring.begin(), ring.end(), w) == ring.end())
            ring.push_back(w);
      if(ring.size() == ring_end)
        break;
      ring_begin = ring_end;
    }
    if(ring.size() < 6) // a degree-2 jet has six coefficients
      return;
    std::vector<Point_3> points;
    points.reserve(ring.size());
    for(vertex_descriptor w : ring)
      points.push_back(get(vpm, w));
    const auto normal = CGAL::Polygon_mesh_processing::compute_vertex_normal(
      v, tm, CGAL::parameters::vertex_point_map(vpm));
    if(normal == CGAL::NULL_VECTOR)
      return;
    Fitting fitting;
    typename Fitting::Monge_form monge = fitting(points.begin(), points.end(), 2, 2);
    monge.comply_wrt_given_normal(normal);
    const double k1 = double(monge.principal_curvatures(0)), k2 = double(monge.principal_curvatures(1));
    if(std::isfinite(k1) && std::isfinite(k2))
      curvatures[i] = Principal_curvatures{std::max(k1, k2), std::min(k1, k2)};
  });
  return curvatures;
}

/// The area of each vertex: a third of the area of its faces. By vertex index.
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap>
std::vector<double> vertex_areas(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim)
{
  std::vector<double> area(num_vertices(tm), 0.0);
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const auto a = get(vpm, source(h, tm)), b = get(vpm, target(h, tm)), c = get(vpm, target(next(h, tm), tm));
    const double third = std::sqrt(double(CGAL::cross_product(b - a, c - a).squared_length())) / 6.0;
    for(auto v : CGAL::vertices_around_face(h, tm))
      area[std::size_t(get(vim, v))] += third;
  }
  return area;
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_CURVATURE_H
