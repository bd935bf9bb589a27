// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "python_support.h"

#include "tool_error.h"

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

namespace cgal_ext_python {

using geodesic_tool::Tool_error;

namespace {

std::string normalized_name(std::string name)
{
  for(char& c : name)
    c = c == '_' ? '-' : char(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

/// Whether `h` is a Python or NumPy integer (not a bool).
bool is_integer(py::handle h)
{
  return PyIndex_Check(h.ptr()) && !PyBool_Check(h.ptr()) && !py::isinstance<py::array>(h);
}

/// A non-negative id from a Python or NumPy integer.
std::size_t read_id(py::handle h, const char* role)
{
  const Py_ssize_t i = PyNumber_AsSsize_t(h.ptr(), PyExc_OverflowError);
  if(i == -1 && PyErr_Occurred())
    throw py::error_already_set();
  if(i < 0)
    throw Tool_error(std::string(role) + " " + std::to_string(i) + " is negative: ids start at 0");
  return std::size_t(i);
}

/// A number as Python writes it (the shortest text that reads back the same).
std::string number_text(double x)
{
  char text[32];
  const auto end = std::to_chars(text, text + sizeof(text), x).ptr;
  return std::string(text, end);
}

/// A face point from a face id and three numbers.
Surface_point face_point(const Python_mesh& mesh, std::size_t face, py::handle barycentric, const char* role)
{
  Surface_point s;
  s.face = face;
  const py::sequence b = py::reinterpret_borrow<py::sequence>(barycentric);
  if(b.size() != 3)
    throw Tool_error(std::string(role) + " on face " + std::to_string(face) + ": 3 barycentric coordinates, got " +
                     std::to_string(b.size()));
  for(std::size_t k = 0; k < 3; ++k) {
    if(!PyNumber_Check(b[k].ptr()) || PyBool_Check(b[k].ptr()))
      throw Tool_error(std::string(role) + " on face " + std::to_string(face) +
                       ": barycentric coordinates must be numbers, got " + std::string(py::str(b[k])));
    s.barycentric[k] = b[k].cast<double>();
  }
  s.text = "face " + std::to_string(face) + " at (" + number_text(s.barycentric[0]) + ", " +
           number_text(s.barycentric[1]) + ", " + number_text(s.barycentric[2]) + ")";
  geodesic_tool::check_barycentric(s, role);
  geodesic_tool::check_surface_point_range(s, mesh.number_of_points(), mesh.number_of_polygons(), role);
  return s;
}

bool is_sequence_of_length(py::handle h, std::size_t n)
{
  return (py::isinstance<py::sequence>(h) || py::isinstance<py::array>(h)) && !py::isinstance<py::str>(h) &&
         py::len(h) == n;
}

} // namespace

void check_threads(std::optional<int> threads)
{
  if(threads && (*threads < 1 || *threads > geodesic_tool::max_threads))
    throw Tool_error("threads must be an integer from 1 to " + std::to_string(geodesic_tool::max_threads) +
                     " (or None: every core), got " + std::to_string(*threads));
}

const geodesic_tool::Algorithm* find_algorithm(const std::string& name)
{
  for(const geodesic_tool::Algorithm& a : geodesic_tool::algorithms)
    if(normalized_name(a.name) == normalized_name(name))
      return &a;
  return nullptr;
}

std::string python_name(const geodesic_tool::Algorithm& a)
{
  std::string name = a.name;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

/// The algorithms a call may take, quoted: every one (or the exact ones), or the parallel ones.
std::string algorithm_names(bool exact_only, bool parallel_only = false)
{
  std::string names;
  for(const geodesic_tool::Algorithm& a : geodesic_tool::algorithms)
    if(!(exact_only && a.approximate) && (geodesic_tool::parallel_available || !a.parallel) &&
       (!parallel_only || a.parallel))
      names += (names.empty() ? "'" : ", '") + python_name(a) + "'";
  return names;
}

geodesic_tool::Solver_choice solver_choice(const std::optional<std::string>& algorithm, std::optional<int> threads,
                                           std::optional<double> lam, std::optional<double> max_distance,
                                           bool exact_only)
{
  const std::string name = algorithm ? *algorithm : std::string(geodesic_tool::default_vertex_solver);
  const geodesic_tool::Algorithm* found = find_algorithm(name);
  if(!found || (exact_only && found->approximate))
    throw Tool_error((found ? "algorithm '" + name + "' is approximate; paths and Voronoi diagrams are exact (use "
                            : "unknown algorithm '" + name + "' (use ") +
                     algorithm_names(exact_only) + ")");
  if(found->parallel && !geodesic_tool::parallel_available)
    throw Tool_error("algorithm '" + name + "' needs TBB, and this module was built without it");
  check_threads(threads);
  if(threads && *threads > 1 && !found->parallel)
    throw Tool_error("algorithm '" + name + "' runs on one thread: for threads=" + std::to_string(*threads) +
                     " use a parallel one (" + algorithm_names(exact_only, true) + ")");
  geodesic_tool::Solver_choice choice;
  choice.algorithm = found;
  choice.batch_size = is_mmp_family(*found) ? CGAL_ext::default_window_batch_size : CGAL_ext::default_batch_size;
  if(lam) {
    if(!found->approximate)
      throw Tool_error("lam (the approximation) applies to algorithm 'avtp' and 'pavtp' only, not '" + name + "'");
    if(!(*lam > 0) || !std::isfinite(*lam))
      throw Tool_error("lam must be a positive, finite number, got " + number_text(*lam));
    choice.lambda = *lam;
  }
  choice.threads = found->parallel && threads ? *threads : 0;
  if(max_distance) {
    if(!(*max_distance >= 0))
      throw Tool_error("max_distance must be a non-negative number, got " + number_text(*max_distance));
    choice.max_distance = *max_distance;
  }
  return choice;
}

geodesic_tool::Solver_choice vtp_family_choice(std::optional<int> threads, std::optional<double> lam,
                                               std::optional<double> max_distance)
{
  const char* name = geodesic_tool::parallel_available ? (lam ? "pavtp" : "pvtp") : (lam ? "avtp" : "vtp");
  return solver_choice(std::string(name), geodesic_tool::parallel_available ? threads : std::nullopt, lam,
                       max_distance, false);
}

Surface_point read_point(const Python_mesh& mesh, py::handle point, const char* role)
{
  if(is_integer(point)) {
    Surface_point s;
    s.vertex = read_id(point, role);
    s.text = std::to_string(*s.vertex);
    geodesic_tool::check_surface_point_range(s, mesh.number_of_points(), mesh.number_of_polygons(), role);
    return s;
  }
  if(is_sequence_of_length(point, 2)) {
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(point);
    if(is_integer(pair[0]) && is_sequence_of_length(pair[1], 3))
      return face_point(mesh, read_id(pair[0], role), pair[1], role);
  }
  throw Tool_error(std::string(role) + ": expected a vertex id or a face point (face, (b0, b1, b2)), got " +
                   std::string(py::str(point)));
}

std::vector<Surface_point> read_points(const Python_mesh& mesh, py::handle points, const char* role)
{
  std::vector<Surface_point> result;
  if(is_integer(points)) {
    result.push_back(read_point(mesh, points, role));
    return result;
  }
  if(py::isinstance<py::array>(points)) {
    const py::array a = py::reinterpret_borrow<py::array>(points);
    if(a.ndim() != 1 || (a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
      throw Tool_error(std::string(role) + "s: an array of vertex ids must be one-dimensional and of an integer dtype");
    const auto ids = py::array_t<long long, py::array::forcecast>::ensure(a);
    for(py::ssize_t i = 0; i < ids.size(); ++i)
      result.push_back(read_point(mesh, py::int_(ids.at(i)), role));
    return result;
  }
  if(!py::isinstance<py::sequence>(points) || py::isinstance<py::str>(points))
    throw Tool_error(std::string(role) + "s: expected a vertex id, a sequence of them, face points (face, (b0, b1, "
                                         "b2)) or two arrays (faces, barycentric), got " +
                     std::string(py::str(points)));
  const py::sequence items = py::reinterpret_borrow<py::sequence>(points);
  if(items.size() == 2 && !is_integer(items[0]) && py::len(items[0]) > 0) {
    // (faces, barycentric): k face ids and a (k, 3) array of numbers; or two points
    const py::array faces = py::array::ensure(items[0]);
    const py::array second = py::array::ensure(items[1]);
    if(faces && faces.ndim() == 1 && (faces.dtype().kind() == 'i' || faces.dtype().kind() == 'u') && second &&
       second.ndim() == 2 && second.shape(1) == 3 &&
       (second.dtype().kind() == 'f' || second.dtype().kind() == 'i' || second.dtype().kind() == 'u')) {
      const auto b = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(items[1]);
      if(!b || b.ndim() != 2 || b.shape(1) != 3 || b.shape(0) != faces.shape(0))
        throw Tool_error(std::string(role) + "s as (faces, barycentric): barycentric must be of shape (" +
                         std::to_string(faces.shape(0)) + ", 3)");
      const auto f = py::array_t<long long, py::array::forcecast>::ensure(faces);
      for(py::ssize_t i = 0; i < f.size(); ++i)
        result.push_back(face_point(mesh, read_id(py::int_(f.at(i)), role),
                                    py::make_tuple(b.at(i, 0), b.at(i, 1), b.at(i, 2)), role));
      return result;
    }
  }
  if(items.size() == 2 && is_integer(items[0]) && is_sequence_of_length(items[1], 3)) { // one face point
    result.push_back(read_point(mesh, points, role));
    return result;
  }
  for(py::handle item : items)
    result.push_back(read_point(mesh, item, role));
  return result;
}

std::vector<std::size_t> read_vertex_ids(const Python_mesh& mesh, py::handle ids, const char* role)
{
  std::vector<std::size_t> result;
  for(const Surface_point& s : read_points(mesh, ids, role)) {
    if(!s.vertex)
      throw Tool_error(std::string(role) + " '" + s.text + "': a vertex id is expected here");
    result.push_back(*s.vertex);
  }
  return result;
}

Python_callback::Python_callback(py::object progress) : m_thread(std::this_thread::get_id())
{
  if(!progress.is_none()) {
    if(!PyCallable_Check(progress.ptr()))
      throw Tool_error("progress must be a function of the fraction done, or None");
    m_progress = std::move(progress);
  }
}

std::function<bool(double)> Python_callback::function()
{
  return [this](double done) { return call(done); };
}

bool Python_callback::call(double done)
{
  // Python handles signals on its main thread only, and the caller's function expects the
  // caller's thread: a report from another thread is skipped.
  if(std::this_thread::get_id() != m_thread)
    return true;
  py::gil_scoped_acquire gil;
  if(PyErr_CheckSignals() != 0) {
    m_python_error = true;
    return false;
  }
  if(m_progress) {
    PyObject* answer = PyObject_CallFunction(m_progress.ptr(), "d", done);
    if(!answer) {
      m_python_error = true;
      return false;
    }
    const int go_on = answer == Py_None ? 1 : PyObject_IsTrue(answer);
    Py_DECREF(answer);
    if(go_on < 0)
      m_python_error = true;
    return go_on == 1;
  }
  return true;
}

void Python_callback::raise_cancellation()
{
  if(m_python_error && PyErr_Occurred())
    throw py::error_already_set();
  throw CGAL_ext::Geodesic_cancelled("cancelled: the progress callback returned False");
}

} // namespace cgal_ext_python
