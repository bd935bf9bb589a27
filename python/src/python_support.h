// Copyright (c) 2026 The CGAL_ext geodesics developers.
// What the parts of the Python module share: the mesh object (a mesh as the tool reads it, with
// its prepared solvers), sources and options read from Python, results as NumPy arrays, and the
// bridge that runs C++ without the GIL while Ctrl-C and the caller's progress callback still
// reach it.

#ifndef CGAL_EXT_PYTHON_SUPPORT_H
#define CGAL_EXT_PYTHON_SUPPORT_H

#include "tool_mesh.h"
#include "tool_options.h"

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace cgal_ext_python {

namespace py = pybind11;
using geodesic_tool::Mesh_file;
using geodesic_tool::Surface_point;

class Prepared_solvers; // python_mesh.cpp

/// The Python `Mesh`: the caller's points and polygons, the triangle mesh made of them (repaired
/// when needed), and the solvers prepared on it at the first solve and kept for the next ones.
/// Every id a Python user gives or gets is a point or a polygon of the input, as in the tool.
struct Python_mesh
{
  explicit Python_mesh(Mesh_file file);
  ~Python_mesh();

  /// The solver mesh and the kept solvers, made at the first call.
  Prepared_solvers& prepared_solvers();

  Mesh_file file;
  std::unique_ptr<Prepared_solvers> prepared;
  std::once_flag m_prepare_once;

  std::size_t number_of_points() const { return file.soup.points.size(); }
  std::size_t number_of_polygons() const { return file.soup.polygons.size(); }
};

/// The choices every solving call takes from Python: an algorithm of the tool's (its name with
/// '_' for '-'; None: the default, 'pvtp'), threads, lam, max distance, checked as the tool
/// checks them; `exact_only` refuses the approximate algorithms.
geodesic_tool::Solver_choice solver_choice(const std::optional<std::string>& algorithm, std::optional<int> threads,
                                           std::optional<double> lam, std::optional<double> max_distance,
                                           bool exact_only);
/// The choice of the functions that take no algorithm (matrices, sampling): PVTP, or PAVTP with
/// `lam`, whatever `threads` is, so that every thread count gives the same bytes (VTP and AVTP in
/// a build without TBB).
geodesic_tool::Solver_choice vtp_family_choice(std::optional<int> threads, std::optional<double> lam,
                                               std::optional<double> max_distance);

/// Throws GeodesicError unless `threads` is None or from 1 to geodesic_tool::max_threads.
void check_threads(std::optional<int> threads);

/// Reads sources (or targets) from Python: a vertex id, a sequence of them, a face point
/// `(face, (b0, b1, b2))`, a sequence of face points, or two arrays `(faces, barycentric)`;
/// checked against the mesh. `role` names them in errors.
std::vector<Surface_point> read_points(const Python_mesh& mesh, py::handle points, const char* role);
/// One point: a vertex id or a face point.
Surface_point read_point(const Python_mesh& mesh, py::handle point, const char* role);
/// Vertex ids from an int or a sequence, checked.
std::vector<std::size_t> read_vertex_ids(const Python_mesh& mesh, py::handle ids, const char* role);

/// A NumPy array that owns `values` (moved, not copied).
template <class T>
py::array_t<T> to_array(std::vector<T>&& values, std::vector<py::ssize_t> shape = {})
{
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  if(shape.empty())
    shape.push_back(py::ssize_t(owned->size()));
  return py::array_t<T>(shape, owned->data(), free_when_done);
}

/// Points as an (n, 3) float64 array.
template <class Points>
py::array_t<double> points_array(const Points& points)
{
  std::vector<double> xyz;
  xyz.reserve(3 * points.size());
  for(const auto& p : points)
    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  const py::ssize_t n = py::ssize_t(points.size());
  return to_array(std::move(xyz), {n, 3});
}

/// The caller's progress callback and Ctrl-C as the library's `callback`: called (from the
/// thread that made it only) with the fraction done, it takes the GIL, lets Python handle a
/// pending signal and calls the progress function; a Python exception or a false return
/// cancels the run.
class Python_callback
{
public:
  /// With the GIL held; `progress` may be None.
  explicit Python_callback(py::object progress);
  /// The library's callback, to call without the GIL.
  std::function<bool(double)> function();
  /// With the GIL held, after the library threw Geodesic_cancelled: raises the Python exception
  /// that cancelled the run (KeyboardInterrupt, the callback's own), or `Cancelled`.
  [[noreturn]] void raise_cancellation();

private:
  bool call(double done);

  py::object m_progress;
  std::thread::id m_thread;
  bool m_python_error = false;
};

/// Runs `f` without the GIL; a cancellation of the library becomes the Python exception that
/// caused it.
template <class Function>
auto without_gil(Python_callback& callback, Function f)
{
  try {
    py::gil_scoped_release release;
    return f();
  } catch(const CGAL_ext::Geodesic_cancelled&) {
    callback.raise_cancellation();
  }
}

void bind_mesh(py::module_& m);
void bind_paths(py::module_& m);
void bind_applications(py::module_& m);

} // namespace cgal_ext_python

#endif // CGAL_EXT_PYTHON_SUPPORT_H
