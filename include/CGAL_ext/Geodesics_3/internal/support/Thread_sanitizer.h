// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_THREAD_SANITIZER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_THREAD_SANITIZER_H

// ThreadSanitizer sees the synchronization of code it instruments only. The TBB library of a
// distribution is not instrumented, so the happens-before edges that a parallel_for (or a
// task_arena::execute) provides are invisible to it: the work handed to the tasks, and the
// results handed back, look like races. In a -fsanitize=thread build these two calls state
// those edges; elsewhere they compile to nothing.

#if defined(__SANITIZE_THREAD__)
#define CGAL_EXT_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define CGAL_EXT_THREAD_SANITIZER 1
#endif
#endif

#ifdef CGAL_EXT_THREAD_SANITIZER
extern "C" void __tsan_acquire(void* address);
extern "C" void __tsan_release(void* address);
#endif

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// Everything this thread wrote before happens before what a thread does after
/// `sanitizer_acquire(token)`.
inline void sanitizer_release(void* token)
{
#ifdef CGAL_EXT_THREAD_SANITIZER
  __tsan_release(token);
#else
  (void)token;
#endif
}

inline void sanitizer_acquire(void* token)
{
#ifdef CGAL_EXT_THREAD_SANITIZER
  __tsan_acquire(token);
#else
  (void)token;
#endif
}

/// Calls `action(token)` (`sanitizer_release` or `sanitizer_acquire`) when it goes out of
/// scope, also by an exception.
class Sanitizer_on_exit
{
public:
  Sanitizer_on_exit(void (*action)(void*), void* token) : m_action(action), m_token(token) {}
  ~Sanitizer_on_exit() { m_action(m_token); }
  Sanitizer_on_exit(const Sanitizer_on_exit&) = delete;
  Sanitizer_on_exit& operator=(const Sanitizer_on_exit&) = delete;

private:
  void (*m_action)(void*);
  void* m_token;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_SUPPORT_THREAD_SANITIZER_H
