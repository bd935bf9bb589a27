// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_DOUBLE_PAIR_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_DOUBLE_PAIR_H

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// Two doubles that go through the same arithmetic side by side: the two ends of a window's
/// interval (where their rays hit an edge, the distances there). With GCC and Clang a vector of
/// two doubles, which x86-64 computes with SSE2's packed instructions, one for both; each lane
/// is rounded as the scalar operation would be, so the results are the same bits as computing
/// the two one after the other. Elsewhere, two doubles.
struct Double_pair
{
#if defined(__GNUC__)
  typedef double Vector __attribute__((vector_size(16)));
  Vector v;
  Double_pair(double a, double b) : v(Vector{a, b}) {}
  explicit Double_pair(Vector x) : v(x) {}
  double first() const { return v[0]; }
  double second() const { return v[1]; }
  friend Double_pair operator+(Double_pair a, Double_pair b) { return Double_pair(a.v + b.v); }
  friend Double_pair operator-(Double_pair a, Double_pair b) { return Double_pair(a.v - b.v); }
  friend Double_pair operator*(Double_pair a, Double_pair b) { return Double_pair(a.v * b.v); }
  friend Double_pair operator/(Double_pair a, Double_pair b) { return Double_pair(a.v / b.v); }
  /// Each of x clamped to [0, upper] as `x > 0 ? (x < upper ? x : upper) : 0` (NaN gives 0).
  friend Double_pair clamp_to(Double_pair x, double upper)
  {
    const Vector u = Vector{upper, upper}, zero = Vector{0., 0.};
    const Vector below = x.v < u ? x.v : u;
    return Double_pair(x.v > zero ? below : zero);
  }
  friend Double_pair square_roots(Double_pair x)
  {
#if defined(__SSE2__)
    return Double_pair(Vector(_mm_sqrt_pd(__m128d(x.v))));
#else
    return Double_pair(__builtin_sqrt(x.v[0]), __builtin_sqrt(x.v[1]));
#endif
  }
#else
  double a, b;
  Double_pair(double x, double y) : a(x), b(y) {}
  double first() const { return a; }
  double second() const { return b; }
  friend Double_pair operator+(Double_pair x, Double_pair y) { return Double_pair(x.a + y.a, x.b + y.b); }
  friend Double_pair operator-(Double_pair x, Double_pair y) { return Double_pair(x.a - y.a, x.b - y.b); }
  friend Double_pair operator*(Double_pair x, Double_pair y) { return Double_pair(x.a * y.a, x.b * y.b); }
  friend Double_pair operator/(Double_pair x, Double_pair y) { return Double_pair(x.a / y.a, x.b / y.b); }
  friend Double_pair clamp_to(Double_pair x, double upper)
  {
    auto clamp = [upper](double t) { return t > 0 ? (t < upper ? t : upper) : 0.; };
    return Double_pair(clamp(x.a), clamp(x.b));
  }
  friend Double_pair square_roots(Double_pair x) { return Double_pair(std::sqrt(x.a), std::sqrt(x.b)); }
#endif
  /// Both set to x.
  static Double_pair both(double x) { return Double_pair(x, x); }
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_DOUBLE_PAIR_H
