// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOLVER_SETTINGS_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOLVER_SETTINGS_H

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The named parameters that steer a solver, read and checked.
struct Solver_settings
{
  Geodesic_algorithm algorithm = VTP;
  double max_distance = std::numeric_limits<double>::infinity();
  double approximation = 0; // lambda of AVTP; 0: exact
  int number_of_threads = 0; // 0: TBB's choice
  std::size_t batch_size = default_batch_size;
  Geodesic_statistics* statistics = nullptr; // where to report, if anywhere
  // The caller's `callback`: told the fraction done a few times a second; false cancels.
  std::function<bool(double)> callback;
};

/// The checks of a max distance and of an approximation's lambda, wherever one is given.
inline void check_max_distance(double max_distance)
{
  if(!(max_distance >= 0)) {
    std::ostringstream msg;
    msg << "max distance must be non-negative, got " << max_distance;
    throw Geodesic_error(msg.str());
  }
}
inline void check_approximation(double lambda)
{
  if(!(lambda > 0) || !std::isfinite(lambda)) {
    std::ostringstream msg;
    msg << "approximation lambda must be positive and finite, got " << lambda;
    throw Geodesic_error(msg.str());
  }
}

/// Reads `algorithm` (default `default_algorithm`), `max_distance`, `approximation`,
/// `number_of_threads`, `batch_size` (default by algorithm) and `statistics` from `np`, and
/// checks each, with one message each; `approximation` and `stop_vertices` go with VTP only.
template <class NamedParameters>
Solver_settings read_solver_settings(const NamedParameters& np, Geodesic_algorithm default_algorithm)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  Solver_settings s;
  s.algorithm = choose_parameter(get_parameter(np, CGAL::internal_np::algorithm), default_algorithm);
  if(s.algorithm != VTP && s.algorithm != MMP && s.algorithm != FWP_MMP)
    throw Geodesic_error("unknown geodesic algorithm " + std::to_string(int(s.algorithm)));

  s.max_distance = choose_parameter(get_parameter(np, internal_np::max_distance), s.max_distance);
  check_max_distance(s.max_distance);

  if constexpr(!is_default_parameter<NamedParameters, internal_np::approximation_t>::value) {
    s.approximation = double(get_parameter(np, internal_np::approximation));
    check_approximation(s.approximation);
    if(s.algorithm != VTP)
      throw Geodesic_error("approximation works with the VTP algorithm only");
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::stop_vertices_t>::value) {
    if(s.algorithm != VTP)
      throw Geodesic_error("stop_vertices works with the VTP algorithm only");
  }

  const long threads = static_cast<long>(choose_parameter(get_parameter(np, internal_np::number_of_threads), 0));
  if(threads < 0)
    throw Geodesic_error("number of threads must be non-negative, got " + std::to_string(threads));
  s.number_of_threads = int(threads);

  const auto batch = choose_parameter(get_parameter(np, internal_np::batch_size),
                                      s.algorithm == VTP ? default_batch_size : default_window_batch_size);
  if(!(batch > 0))
    throw Geodesic_error("batch size must be positive, got " + std::to_string(batch));
  s.batch_size = static_cast<std::size_t>(batch);

  if constexpr(!is_default_parameter<NamedParameters, internal_np::statistics_t>::value) {
    typedef std::decay_t<decltype(get_parameter(np, internal_np::statistics))> Given;
    static_assert(std::is_convertible<Given, Geodesic_statistics*>::value,
                  "CGAL_ext: this function reports a CGAL_ext::Geodesic_statistics through `statistics`");
    s.statistics = static_cast<Geodesic_statistics*>(get_parameter(np, internal_np::statistics));
  }
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::callback_t>::value)
    s.callback = get_parameter(np, CGAL::internal_np::callback);
  return s;
}

/// Adds what one run did to `total`, for a call made of many runs (the rows of a matrix, the
/// samples' runs): counts and seconds add up, peaks are the largest of one run; the mesh's sizes
/// are the caller's to set.
inline void add_run_statistics(Geodesic_statistics& total, const Geodesic_statistics& run)
{
  total.windows_created += run.windows_created;
  total.peak_windows = std::max(total.peak_windows, run.peak_windows);
  total.peak_window_bytes = std::max(total.peak_window_bytes, run.peak_window_bytes);
  total.vertices_popped += run.vertices_popped;
  total.lists_propagated += run.lists_propagated;
  total.wavefront_resets += run.wavefront_resets;
  total.seconds_solve += run.seconds_solve;
  total.seconds_selection += run.seconds_selection;
  total.seconds_propagation += run.seconds_propagation;
  total.seconds_merge += run.seconds_merge;
}

/// What a solver did, with the seconds of the set-up; also given to the caller when it asked
/// with `statistics`.
inline Geodesic_statistics report_statistics(const Solver_settings& settings, Geodesic_statistics statistics,
                                             double seconds_setup)
{
  statistics.seconds_setup = seconds_setup;
  if(settings.statistics)
    *settings.statistics = statistics;
  return statistics;
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOLVER_SETTINGS_H
