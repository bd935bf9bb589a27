// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The compiled part of the Python package `cgal_ext_geodesics`: the module, its exceptions and
// its parts (python_mesh.cpp, python_paths.cpp, python_applications.cpp).

#include "python_support.h"

#include "tool_error.h"

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>

namespace py = pybind11;

PYBIND11_MODULE(_geodesics, m)
{
  m.doc() = "The compiled part of cgal_ext_geodesics; import cgal_ext_geodesics instead.";
  static py::exception<CGAL_ext::Geodesic_error> geodesic_error(m, "GeodesicError", PyExc_ValueError);
  geodesic_error.doc() = "Bad input: the message names the problem and where it is (a vertex, a face, a value).";
  static py::exception<CGAL_ext::Geodesic_cancelled> cancelled(m, "Cancelled", PyExc_Exception);
  cancelled.doc() = "The progress function returned False: the computation stopped and returned nothing.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if(p)
        std::rethrow_exception(p);
    } catch(const CGAL_ext::Geodesic_cancelled& e) {
      cancelled(e.what());
    } catch(const CGAL_ext::Geodesic_error& e) {
      geodesic_error(e.what());
    } catch(const geodesic_tool::Tool_error& e) {
      geodesic_error(e.what());
    }
  });
  cgal_ext_python::bind_mesh(m);
  cgal_ext_python::bind_paths(m);
  cgal_ext_python::bind_applications(m);
}
