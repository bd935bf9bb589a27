// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_TOLERANCES_H
#define CGAL_EXT_GEODESICS_3_TOLERANCES_H

/// \file Tolerances.h
/// The package's tolerances, in one place: what round-off may do to input and to the windows
/// without changing a result. Relative tolerances are multiplied by the length named with them.

namespace CGAL_ext {
namespace Geodesics_3 {

/// Barycentric coordinates of a face point must sum to 1 within this.
constexpr double barycentric_sum_tolerance = 1e-9;
/// A barycentric coordinate may be this much below 0 (it is then 0); coordinates below it are
/// snapped to 0 (the point is on an edge or at a corner).
constexpr double barycentric_snap = 1e-12;

/// A triangle whose height is below this fraction of its longest side is degenerate: it cannot
/// be unfolded reliably.
constexpr double degenerate_height_ratio = 1e-12;
/// Vertices the caller glues into one point must be within this fraction of the mean edge
/// length of each other.
constexpr double glued_distance_ratio = 1e-9;
/// A vertex whose angle sum exceeds 2 pi minus this (radians) is a pseudo-source: a saddle
/// excess of round-off still leaves a shadow no window covers.
constexpr double saddle_angle_tolerance = 1e-6;

/// Windows (and pieces of windows) narrower than this fraction of the mean edge length are
/// dropped: their wedge is covered by their neighbours up to round-off.
constexpr double min_window_length_ratio = 1e-10;
/// Two windows of a VTP list that overlap by less than this fraction of the mean edge length
/// are not clipped against each other: such overlaps come from windows that meet along a ray,
/// up to the error their unfoldings accumulated; clipping is a pruning, never needed for exact
/// distances, and on so narrow an overlap it costs more than it saves (doc/experiments.md).
constexpr double min_clipped_overlap_ratio = 1e-6;
/// Solving for the points where two windows give the same distance, the quadratic term is zero
/// when below this fraction of the terms it is the difference of.
constexpr double quadratic_cancellation_ratio = 1e-14;

/// Path tracing: a way to a point within this fraction (of the distance plus the mean edge
/// length) of the expected distance is taken at once; a corner replaces an edge way only when
/// shorter by more than this.
constexpr double path_round_off_ratio = 1e-12;
/// Path tracing: the way found straight ahead is trusted while it is within this fraction (of
/// the expected distance plus the mean edge length) of the expected distance; beyond it, every
/// way to the point is searched.
constexpr double path_straight_ahead_ratio = 1e-9;
/// Path tracing: rays crossing an edge within this fraction of its length from a window's
/// interval still count as crossing it through the window (round-off at the interval's ends).
constexpr double path_window_end_ratio = 1e-9;

} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_TOLERANCES_H
