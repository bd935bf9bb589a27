// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_EXT_GEODESICS_3_NAMED_FUNCTION_PARAMETERS_H

#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL_ext {
namespace internal_np {

#ifndef DOXYGEN_RUNNING
#define CGAL_ext_add_named_parameter(X, Y, Z) enum X { Y };
#include <CGAL_ext/Geodesics_3/internal/support/parameters_interface.h>
#undef CGAL_ext_add_named_parameter
#endif
enum statistics_t { statistics };

} // namespace internal_np

/// \ingroup PkgGeodesics3Ref
/// A named-parameter pack that chains CGAL's parameters (`vertex_point_map`,
/// `vertex_index_map`, `algorithm`, ...) with the package's own (`max_distance`,
/// `stop_vertices`, `statistics`). It is a `CGAL::Named_function_parameters`, so CGAL's
/// `get_parameter()` and `choose_parameter()` read it. Start a chain with a function of
/// `CGAL_ext::parameters`.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> cgal_parameters;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : cgal_parameters() {}
  Named_function_parameters(const T& v) : cgal_parameters(v) {}
  Named_function_parameters(const T& v, const Base& b) : cgal_parameters(v, b) {}

#ifndef DOXYGEN_RUNNING // the chaining functions, one per parameter of CGAL and of the package
#define CGAL_ext_chain_parameter(NS, X, Z)                                          \
  template <typename K>                                                             \
  Named_function_parameters<K, NS::X, self> Z(const K& k) const                     \
  {                                                                                 \
    return Named_function_parameters<K, NS::X, self>(k, *this);                     \
  }
#define CGAL_add_named_parameter(X, Y, Z) CGAL_ext_chain_parameter(CGAL::internal_np, X, Z)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#define CGAL_ext_add_named_parameter(X, Y, Z) CGAL_ext_chain_parameter(CGAL_ext::internal_np, X, Z)
#include <CGAL_ext/Geodesics_3/internal/support/parameters_interface.h>
#undef CGAL_ext_add_named_parameter
#undef CGAL_ext_chain_parameter
#endif

  /// asks the function to fill `s` (kept by reference) with what it did: every long-running
  /// function of the package reports this way, a `Geodesic_statistics` for the solvers and the
  /// applications built on one propagation, a `Pattern_statistics` for pattern detection.
  /// \tparam Statistics `Geodesic_statistics` or `Pattern_statistics`
  /// \param s the statistics to fill
  /// \return the pack with `statistics` added
  template <class Statistics>
  Named_function_parameters<Statistics*, internal_np::statistics_t, self> statistics(Statistics& s) const
  {
    return Named_function_parameters<Statistics*, internal_np::statistics_t, self>(&s, *this);
  }
};

/// \ingroup PkgGeodesics3Ref
/// Functions that start a chain of named parameters (CGAL's and the package's).
namespace parameters {

/// the type of the empty pack
typedef Named_function_parameters<bool, CGAL::internal_np::all_default_t> Default_named_parameters_type;

/// the empty pack: every parameter takes its default value.
/// \return the empty pack
inline Named_function_parameters<bool, CGAL::internal_np::all_default_t> default_values()
{
  return Named_function_parameters<bool, CGAL::internal_np::all_default_t>();
}

#ifndef DOXYGEN_RUNNING // the functions starting a chain, one per parameter of CGAL and of the package
#define CGAL_ext_start_parameter(NS, X, Z)                                          \
  template <typename K>                                                             \
  Named_function_parameters<K, NS::X> Z(const K& k)                                 \
  {                                                                                 \
    return Named_function_parameters<K, NS::X>(k);                                  \
  }
#define CGAL_add_named_parameter(X, Y, Z) CGAL_ext_start_parameter(CGAL::internal_np, X, Z)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#define CGAL_ext_add_named_parameter(X, Y, Z) CGAL_ext_start_parameter(CGAL_ext::internal_np, X, Z)
#include <CGAL_ext/Geodesics_3/internal/support/parameters_interface.h>
#undef CGAL_ext_add_named_parameter
#undef CGAL_ext_start_parameter
#endif

/// asks the function to fill `s` (kept by reference) with what it did: a `Geodesic_statistics`
/// for the solvers and the applications built on one propagation, a `Pattern_statistics` for
/// pattern detection.
/// \tparam Statistics `Geodesic_statistics` or `Pattern_statistics`
/// \param s the statistics to fill
/// \return a pack holding `statistics`
template <class Statistics>
Named_function_parameters<Statistics*, internal_np::statistics_t> statistics(Statistics& s)
{
  return Named_function_parameters<Statistics*, internal_np::statistics_t>(&s);
}

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::is_default_parameter;

} // namespace parameters
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_NAMED_FUNCTION_PARAMETERS_H
