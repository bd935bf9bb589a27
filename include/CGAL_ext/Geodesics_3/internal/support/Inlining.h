// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_INLINING_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_INLINING_H

// Where the compiler's own choice of what to inline into the kernels' loops was measured worse
// (callgrind's instruction counts, doc/experiments.md). GCC and Clang only; elsewhere no hint.
#if defined(__GNUC__)
#define CGAL_EXT_NOINLINE __attribute__((noinline))
#define CGAL_EXT_ALWAYS_INLINE __attribute__((always_inline))
#else
#define CGAL_EXT_NOINLINE
#define CGAL_EXT_ALWAYS_INLINE
#endif

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_INLINING_H
