// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_PROGRESS_REPORTER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_PROGRESS_REPORTER_H

// The caller's `callback` named parameter as the long-running loops call it: a few times a
// second at most, with a fraction done that never goes back, and a cancellation when it says so.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <string>
#include <utility>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

class Progress_reporter
{
public:
  typedef std::chrono::steady_clock Clock;
  static constexpr std::chrono::milliseconds interval{100};

  /// `what` names the computation in the message of the cancellation.
  explicit Progress_reporter(std::function<bool(double)> callback = {}, std::string what = "the geodesic computation")
    : m_callback(std::move(callback)), m_what(std::move(what))
  {
  }

  bool active() const { return bool(m_callback); }

  /// Starts the reports of a run: the first comes at the first report asked for, the next one
  /// interval later, and so on.
  void start()
  {
    m_reported = 0;
    m_next = Clock::time_point::min();
  }

  /// Tells the callback the fraction `done()` when an interval has passed since the last report;
  /// throws Geodesic_cancelled when it returns false.
  template <class DoneFraction>
  void report(DoneFraction done)
  {
    if(!m_callback)
      return;
    const Clock::time_point now = Clock::now();
    if(now < m_next)
      return;
    m_next = now + interval;
    call(done());
  }

  /// The same for a loop that calls it very often: the clock is read once in 64 calls.
  template <class DoneFraction>
  void report_often(DoneFraction done)
  {
    if(m_callback && (++m_calls & 63u) == 0)
      report(done);
  }

  /// Tells the callback the fraction `done` now (the end of a step), whatever the time.
  void report_now(double done)
  {
    if(m_callback)
      call(done);
  }

private:
  void call(double done)
  {
    m_reported = std::max(m_reported, std::clamp(done, 0., 1.));
    if(!m_callback(m_reported))
      throw Geodesic_cancelled(m_what + ": cancelled by the callback");
  }

  std::function<bool(double)> m_callback;
  std::string m_what;
  unsigned m_calls = 0;
  Clock::time_point m_next = Clock::time_point::min();
  double m_reported = 0;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_PROGRESS_REPORTER_H
