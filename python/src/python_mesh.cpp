// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The Python `Mesh`: made of NumPy arrays or read from a file, prepared once, and its distances
// and distance matrices.

#include "python_support.h"

#include "tool_error.h"
#include "tool_matrix.h"
#include "tool_solvers.h"
#include "tool_threads.h"

#include <CGAL_ext/Geodesics_3/internal/distance_rows/Distance_rows.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/MMP_solver.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/VTP_solver.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Mesh_setup.h>

#include <algorithm>
#include <cerrno>
#include <limits>
#include <mutex>
#include <numeric>
#include <type_traits>

namespace cgal_ext_python {

using geodesic_tool::Mesh;
using geodesic_tool::Solver_choice;
using geodesic_tool::Tool_error;
using geodesic_tool::Vertex_index;
namespace internal = CGAL_ext::Geodesics_3::internal;

/// The solver mesh of a `Python_mesh`, built at its first solve, and the VTP solvers of
/// past solves, kept for the next ones: a solve on a prepared mesh costs what it sweeps. Solves
/// may run at once from several Python threads: each takes a solver of its own.
class Prepared_solvers
{
public:
  typedef boost::property_map<Mesh, CGAL::vertex_point_t>::const_type Vertex_point_map;
  typedef internal::Mesh_setup<Mesh, Vertex_point_map> Setup;

  explicit Prepared_solvers(const Mesh_file& file)
    : m_setup(file.mesh, CGAL_ext::parameters::glued_vertices(file.glued_vertices))
    , m_points_of_vertex(file, every_point(file))
  {
    m_index_of_point.reserve(file.vertex_of_point.size());
    for(Vertex_index v : file.vertex_of_point)
      m_index_of_point.push_back(m_setup.index(v));
  }

  /// One run of the solver `choice` names from `sources` until `stops` are settled (point ids;
  /// the VTP family only); writes the distance of every point and, unless null, its nearest
  /// source. The VTP family's solvers are kept for the next runs; the MMP family's hold their
  /// windows and are made for each run, on the same solver mesh.
  void solve(const Mesh_file& file, const std::vector<Surface_point>& sources, const std::vector<std::size_t>& stops,
             const Solver_choice& choice, double* distance, long long* nearest)
  {
    const std::vector<internal::Source_point> points = source_points(file, sources);
    const geodesic_tool::Thread_allowance allowance(choice.threads);
    const bool parallel = choice.algorithm->parallel;
    const auto add_sources = [&](internal::Solver_base& solver) {
      for(const internal::Source_point& s : points)
        solver.add_source(s);
    };
    const auto run = [&](auto& solver) {
      if(parallel)
        internal::run_solver<true>(solver, choice.threads);
      else
        internal::run_solver<false>(solver, 1);
      write(solver, distance, nearest);
    };
    if(geodesic_tool::is_mmp_family(*choice.algorithm)) {
      internal::Solver_settings settings;
      settings.algorithm = choice.algorithm->library;
      settings.batch_size = choice.batch_size;
      settings.max_distance = choice.max_distance;
      settings.callback = choice.callback;
      internal::MMP_solver solver(m_setup.cache(), settings, parallel);
      add_sources(solver);
      run(solver);
      return;
    }
    std::unique_ptr<Kept_solver> kept = take(choice);
    internal::VTP_solver& solver = kept->solver;
    solver.reset();
    solver.set_max_distance_in_mesh_unit(choice.max_distance);
    solver.set_callback(choice.callback);
    add_sources(solver);
    for(std::size_t p : stops)
      solver.add_stop_vertex(m_index_of_point[p]);
    // A run that throws (a cancellation) leaves windows behind: its solver is dropped, not kept.
    run(solver);
    give_back(std::move(kept));
  }

  /// The rows of a distance matrix: a single-source VTP run from each of `sources`, within
  /// `choice.max_distance`, on `choice.threads` (0: every core), in parallel across sources:
  /// `make_row(solver, row)` on the thread that ran it, `hand_over(i, row)` in source order on
  /// this one. The solver mesh is this one's; the row solvers are the call's own, so that calls
  /// from several Python threads run side by side.
  template <class Row, class MakeRow, class HandOver>
  void for_each_row(const Mesh_file& file, const std::vector<Surface_point>& sources, const Solver_choice& choice,
                    MakeRow make_row, HandOver hand_over)
  {
    const std::vector<internal::Source_point> points = source_points(file, sources);
    const geodesic_tool::Thread_allowance allowance(choice.threads);
    internal::Solver_settings settings;
    settings.number_of_threads = choice.threads;
    settings.callback = choice.callback;
    internal::Row_solvers<geodesic_tool::parallel_available, Mesh, Vertex_point_map> rows(m_setup, settings);
    rows.template for_each_row<Row>(
      points, choice.max_distance, std::vector<int>(),
      [&](const internal::VTP_solver& solver, const Setup&, Row& row) { make_row(solver, row); }, hand_over);
  }

  /// The solver-mesh vertex of input point p.
  int solver_vertex(std::size_t p) const { return m_index_of_point[p]; }
  const Setup& setup() const { return m_setup; }

private:
  static std::vector<std::size_t> every_point(const Mesh_file& file)
  {
    std::vector<std::size_t> points(file.vertex_of_point.size());
    std::iota(points.begin(), points.end(), std::size_t(0));
    return points;
  }

  std::vector<internal::Source_point> source_points(const Mesh_file& file, const std::vector<Surface_point>& sources)
  {
    geodesic_tool::check_a_source_is_on_a_face(file, sources);
    std::vector<internal::Source_point> points;
    for(const Surface_point& s : sources)
      points.push_back(s.vertex ? m_setup.source_point(geodesic_tool::mesh_vertex(file, s))
                                : m_setup.source_point(geodesic_tool::library_location(file, s, "source")));
    return points;
  }

  /// The distance and nearest source of every point, from the solver's arrays. After a run that
  /// reached few vertices (a local solve), only theirs are read: the rest are at infinity.
  template <class Solver>
  void write(const Solver& solver, double* distance, long long* nearest) const
  {
    const std::vector<double>& d = solver.distances();
    const std::vector<int>& source = solver.nearest_sources();
    const double unit = m_setup.cache().unit;
    if constexpr(std::is_same<Solver, internal::VTP_solver>::value) {
      const std::vector<int>& reached = solver.reached_vertices();
      if(reached.size() < m_index_of_point.size() / 8) {
        std::fill(distance, distance + m_index_of_point.size(), VTP_infinity);
        if(nearest)
          std::fill(nearest, nearest + m_index_of_point.size(), -1LL);
        const internal::Solver_mesh& cache = m_setup.cache();
        for(int v : reached) {
          if(std::size_t(v) >= cache.number_of_mesh_vertices)
            continue; // a vertex the solver mesh added: no point of the input's
          for(std::size_t p : m_points_of_vertex.vertex(std::size_t(cache.mesh_vertex(v)))) {
            distance[p] = d[std::size_t(v)] * unit;
            if(nearest)
              nearest[p] = source[std::size_t(v)];
          }
        }
        return;
      }
    }
    for(std::size_t p = 0; p < m_index_of_point.size(); ++p) {
      const std::size_t v = std::size_t(m_index_of_point[p]);
      distance[p] = d[v] * unit;
      if(nearest)
        nearest[p] = source[v];
    }
  }
  static constexpr double VTP_infinity = std::numeric_limits<double>::infinity();

  struct Kept_solver
  {
    Kept_solver(const internal::Solver_mesh& mesh, const internal::Solver_settings& settings, bool parallel)
      : parallel(parallel), lambda(settings.approximation), solver(mesh, settings, parallel)
    {
    }
    bool parallel;
    double lambda;
    internal::VTP_solver solver;
  };

  std::unique_ptr<Kept_solver> take(const Solver_choice& choice)
  {
    const bool parallel = choice.algorithm->parallel;
    const double lambda = choice.algorithm->approximate ? choice.lambda : 0.;
    {
      const std::lock_guard<std::mutex> lock(m_mutex);
      for(auto it = m_idle.begin(); it != m_idle.end(); ++it)
        if((*it)->parallel == parallel && (*it)->lambda == lambda) {
          std::unique_ptr<Kept_solver> kept = std::move(*it);
          m_idle.erase(it);
          return kept;
        }
    }
    internal::Solver_settings settings;
    settings.approximation = lambda;
    settings.batch_size = choice.batch_size;
    return std::make_unique<Kept_solver>(m_setup.cache(), settings, parallel);
  }

  void give_back(std::unique_ptr<Kept_solver> kept)
  {
    kept->solver.set_callback({}); // the caller's Python function is not kept alive here
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_idle.push_back(std::move(kept));
    // a few of each kind are enough for the threads of a Python program
    if(m_idle.size() > max_idle_solvers)
      m_idle.erase(m_idle.begin());
  }

  static constexpr std::size_t max_idle_solvers = 4;
  Setup m_setup;
  std::vector<int> m_index_of_point; // the solver mesh's vertex of each point
  geodesic_tool::Columns_of_vertices m_points_of_vertex; // the points of each mesh vertex (for local solves)
  std::mutex m_mutex;
  std::vector<std::unique_ptr<Kept_solver>> m_idle;
};

Python_mesh::Python_mesh(Mesh_file f) : file(std::move(f)) {}
Python_mesh::~Python_mesh() = default;

Prepared_solvers& Python_mesh::prepared_solvers()
{
  std::call_once(m_prepare_once, [this] { prepared = std::make_unique<Prepared_solvers>(file); });
  return *prepared;
}

namespace {

typedef std::shared_ptr<Python_mesh> Mesh_ptr;

/// The points of an (n, 3) array.
std::vector<geodesic_tool::Point> read_vertices(py::handle vertices)
{
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vertices);
  if(!a)
    throw Tool_error("vertices: expected an (n, 3) array of numbers");
  if(a.ndim() != 2 || a.shape(1) != 3)
    throw Tool_error("vertices: expected an array of shape (n, 3), got one of " + std::to_string(a.ndim()) +
                     " dimensions" + (a.ndim() == 2 ? " and shape (" + std::to_string(a.shape(0)) + ", " +
                                                        std::to_string(a.shape(1)) + ")"
                                                  : std::string()));
  std::vector<geodesic_tool::Point> points;
  points.reserve(std::size_t(a.shape(0)));
  const double* xyz = a.data();
  for(py::ssize_t i = 0; i < a.shape(0); ++i, xyz += 3)
    points.emplace_back(xyz[0], xyz[1], xyz[2]);
  return points;
}

/// The polygons of an (m, k) integer array, or of a sequence of sequences of ids.
geodesic_tool::Polygons read_faces(py::handle faces, std::size_t number_of_points)
{
  const auto check = [&](long long id, std::size_t f) {
    if(id < 0 || std::size_t(id) >= number_of_points)
      throw Tool_error("faces: face " + std::to_string(f) + " has vertex id " + std::to_string(id) +
                       ", out of range (there are " + std::to_string(number_of_points) + " vertices)");
  };
  geodesic_tool::Polygons polygons;
  std::vector<long long> polygon;
  if(py::isinstance<py::array>(faces)) {
    const py::array a = py::reinterpret_borrow<py::array>(faces);
    if(a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
      throw Tool_error(std::string("faces: expected an array of an integer dtype, got dtype ") +
                       std::string(py::str(a.dtype())));
    if(a.ndim() != 2 || a.shape(1) < 3)
      throw Tool_error("faces: expected an array of shape (m, 3) (or (m, k), k >= 3, of polygons)");
    if(a.dtype().kind() == 'u' && a.itemsize() == 8 && a.size() > 0) {
      // (ids above the largest int64 would wrap to negative ones in the conversion below)
      const py::object largest = a.attr("max")();
      if(largest.cast<unsigned long long>() >= static_cast<unsigned long long>(number_of_points))
        throw Tool_error("faces: vertex id " + std::string(py::str(largest)) + " is out of range (there are " +
                         std::to_string(number_of_points) + " vertices)");
    }
    const auto ids = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
    const std::size_t k = std::size_t(ids.shape(1));
    const long long* id = ids.data();
    for(std::size_t f = 0; f < std::size_t(ids.shape(0)); ++f, id += k) {
      for(std::size_t j = 0; j < k; ++j)
        check(id[j], f);
      polygons.push_back(std::vector<long long>(id, id + k));
    }
    return polygons;
  }
  if(!py::isinstance<py::sequence>(faces) || py::isinstance<py::str>(faces))
    throw Tool_error("faces: expected an (m, 3) integer array or a sequence of polygons (sequences of vertex ids)");
  std::size_t f = 0;
  for(py::handle item : py::reinterpret_borrow<py::sequence>(faces)) {
    polygon.clear();
    if(!py::isinstance<py::sequence>(item) && !py::isinstance<py::array>(item))
      throw Tool_error("faces: face " + std::to_string(f) + " is not a sequence of vertex ids");
    for(py::handle id : item) {
      if(!PyIndex_Check(id.ptr()) || PyBool_Check(id.ptr()))
        throw Tool_error("faces: face " + std::to_string(f) + " has a vertex id that is not an integer: " +
                         std::string(py::str(id)));
      polygon.push_back(id.cast<long long>());
      check(polygon.back(), f);
    }
    polygons.push_back(polygon);
    ++f;
  }
  return polygons;
}

Mesh_ptr make_mesh(py::handle vertices, py::handle faces)
{
  geodesic_tool::Soup soup;
  soup.points = read_vertices(vertices);
  soup.polygons = read_faces(faces, soup.points.size());
  py::gil_scoped_release release;
  return std::make_shared<Python_mesh>(geodesic_tool::make_mesh_file(std::move(soup)));
}

py::dict repairs_dict(const CGAL_ext::Geodesic_mesh_repairs& r)
{
  py::dict d;
  d["merged_points"] = r.merged_points;
  d["removed_polygons"] = r.removed_polygons;
  d["split_polygons"] = r.split_polygons;
  d["triangulated_polygons"] = r.triangulated_polygons;
  d["reversed_polygons"] = r.reversed_polygons;
  d["duplicated_points"] = r.duplicated_points;
  d["non_manifold_edges"] = r.non_manifold_edges;
  d["isolated_points"] = r.isolated_points;
  d["changed"] = r.changed();
  d["summary"] = r.summary();
  return d;
}

py::object distances(const Mesh_ptr& mesh, py::handle sources, std::optional<std::string> algorithm,
                     std::optional<int> threads, std::optional<double> max_distance, py::handle stop_vertices,
                     std::optional<double> lam, bool return_sources, py::object progress)
{
  if(!algorithm && lam) // lam alone asks for the approximation
    algorithm = geodesic_tool::parallel_available ? "pavtp" : "avtp";
  Solver_choice choice = solver_choice(algorithm, threads, lam, max_distance, false);
  const std::vector<Surface_point> points = read_points(*mesh, sources, "source");
  if(points.empty())
    throw Tool_error("no source was given");
  std::vector<std::size_t> stops;
  if(!stop_vertices.is_none()) {
    stops = read_vertex_ids(*mesh, stop_vertices, "stop vertex");
    if(choice.algorithm->library != CGAL_ext::VTP)
      throw Tool_error("stop_vertices works with the VTP family only ('pvtp', 'vtp', 'pavtp', 'avtp')");
  }
  const std::size_t n = mesh->number_of_points();
  py::array_t<double> distance{py::ssize_t(n)};
  py::array_t<long long> nearest{return_sources ? py::ssize_t(n) : py::ssize_t(0)};
  double* d = distance.mutable_data();
  long long* label = return_sources ? nearest.mutable_data() : nullptr;
  Python_callback callback(std::move(progress));
  choice.callback = callback.function();
  without_gil(callback, [&] { mesh->prepared_solvers().solve(mesh->file, points, stops, choice, d, label); });
  if(return_sources)
    return py::make_tuple(distance, nearest);
  return std::move(distance);
}

/// The dense matrix, (sources, targets), or its CSR arrays (data, indices, indptr, shape) with a
/// finite max distance.
py::object distance_matrix(const Mesh_ptr& mesh, py::handle sources, py::handle targets,
                           std::optional<double> max_distance, std::optional<int> threads, py::object progress)
{
  const Solver_choice choice = vtp_family_choice(threads, std::nullopt, max_distance);
  const std::vector<Surface_point> points = read_points(*mesh, sources, "source");
  if(points.empty())
    throw Tool_error("no source was given");
  std::vector<std::size_t> columns;
  if(targets.is_none()) {
    columns.resize(mesh->number_of_points());
    std::iota(columns.begin(), columns.end(), std::size_t(0));
  } else {
    columns = read_vertex_ids(*mesh, targets, "target");
  }
  const std::size_t rows = points.size(), width = columns.size();
  Python_callback callback(std::move(progress));
  Solver_choice rows_choice = choice;
  rows_choice.callback = callback.function();
  const Mesh_file& file = mesh->file;
  const geodesic_tool::Columns_of_vertices columns_of(file, columns);
  // A vertex in no face reaches only itself (and the points merged with it): its row is made
  // here, the others are solved, `solved_row[i]` being the row of the i-th solved source.
  std::vector<Surface_point> solved;
  std::vector<std::size_t> solved_row;
  const auto isolated_vertex = [&](const Surface_point& s) -> std::optional<std::size_t> {
    if(s.vertex && file.mesh.is_isolated(geodesic_tool::mesh_vertex(file, s)))
      return std::size_t(geodesic_tool::mesh_vertex(file, s).idx());
    return std::nullopt;
  };
  for(std::size_t r = 0; r < rows; ++r)
    if(!isolated_vertex(points[r])) {
      solved.push_back(points[r]);
      solved_row.push_back(r);
    }

  if(!(choice.max_distance < std::numeric_limits<double>::infinity())) {
    py::array_t<double> matrix({py::ssize_t(rows), py::ssize_t(width)});
    double* out = matrix.mutable_data();
    for(std::size_t r = 0; r < rows; ++r)
      if(const auto v = isolated_vertex(points[r])) {
        std::fill(out + r * width, out + (r + 1) * width, std::numeric_limits<double>::infinity());
        for(std::size_t j : columns_of.vertex(*v))
          out[r * width + j] = 0.;
      }
    without_gil(callback, [&] {
      if(solved.empty())
        return;
      Prepared_solvers& prepared = mesh->prepared_solvers();
      std::vector<int> vertex_of_column(width);
      for(std::size_t j = 0; j < width; ++j)
        vertex_of_column[j] = prepared.solver_vertex(columns[j]);
      const double unit = prepared.setup().cache().unit;
      prepared.for_each_row<std::vector<double>>(
        file, solved, rows_choice,
        [&](const internal::VTP_solver& solver, std::vector<double>& row) {
          const std::vector<double>& d = solver.distances();
          row.resize(width);
          for(std::size_t j = 0; j < width; ++j)
            row[j] = d[std::size_t(vertex_of_column[j])] * unit;
        },
        [&](std::size_t i, const std::vector<double>& row) {
          std::copy(row.begin(), row.end(), out + solved_row[i] * width);
        });
    });
    return std::move(matrix);
  }

  std::vector<double> data;
  std::vector<long long> indices, indptr{0};
  std::size_t next_row = 0; // rows are appended in order
  const auto append_isolated_rows_before = [&](std::size_t end) {
    for(; next_row < end; ++next_row) {
      for(std::size_t j : columns_of.vertex(*isolated_vertex(points[next_row]))) {
        indices.push_back(static_cast<long long>(j));
        data.push_back(0.);
      }
      indptr.push_back(static_cast<long long>(indices.size()));
    }
  };
  without_gil(callback, [&] {
    if(solved.empty())
      return;
    Prepared_solvers& prepared = mesh->prepared_solvers();
    const internal::Solver_mesh& cache = prepared.setup().cache();
    typedef std::vector<std::pair<long long, double>> Entries;
    prepared.for_each_row<Entries>(
      file, solved, rows_choice,
      [&](const internal::VTP_solver& solver, Entries& row) {
        const std::vector<double>& d = solver.distances();
        row.clear();
        for(int v : solver.reached_vertices())
          if(std::size_t(v) < cache.number_of_mesh_vertices && d[std::size_t(v)] < internal::VTP_solver::infinity())
            for(std::size_t j : columns_of.vertex(std::size_t(cache.mesh_vertex(v))))
              row.emplace_back(static_cast<long long>(j), d[std::size_t(v)] * cache.unit);
        std::sort(row.begin(), row.end());
      },
      [&](std::size_t i, const Entries& row) {
        append_isolated_rows_before(solved_row[i]);
        for(const auto& [j, d] : row) {
          indices.push_back(j);
          data.push_back(d);
        }
        indptr.push_back(static_cast<long long>(indices.size()));
        ++next_row;
      });
  });
  append_isolated_rows_before(rows);
  return py::make_tuple(to_array(std::move(data)), to_array(std::move(indices)), to_array(std::move(indptr)),
                        py::make_tuple(rows, width));
}

} // namespace

void bind_mesh(py::module_& m)
{
  py::class_<Python_mesh, Mesh_ptr>(m, "Mesh", R"doc(
A triangle mesh, prepared once for any number of geodesic computations.

Made of a vertex array (n, 3) and faces, either an (m, 3) integer array of
triangles or a sequence of polygons (sequences of vertex ids). Polygon soups
are repaired as needed (duplicate points merged, polygons triangulated, the
surface oriented, non-manifold vertices and edges split and glued again) and
``repairs`` says what was done. Every id given to or returned by a method is a
vertex or a face of the input, whatever the repair did.

The first distances() or distance_matrix() call builds the solver mesh; later
ones reuse it (and the solvers of earlier distances() calls), so that a solve
costs what it sweeps. GeodesicPaths, voronoi, farthest_point_sampling and
detect_patterns prepare a solver mesh of their own at each call.
)doc")
    .def(py::init(&make_mesh), py::arg("vertices"), py::arg("faces"),
         "Mesh(vertices, faces): vertices (n, 3) of any numeric dtype; faces (m, 3) of any integer dtype, "
         "(m, k) polygons, or a sequence of polygons. Raises GeodesicError naming what cannot be made a mesh.")
    .def_static(
      "read",
      [](py::object path) {
        const py::module_ os = py::module_::import("os");
        const std::string name = py::str(os.attr("fsdecode")(os.attr("fspath")(path)));
        // as open() says it: an OSError with the errno and the file name
        const bool is_folder = os.attr("path").attr("isdir")(name).cast<bool>();
        if(is_folder || !os.attr("path").attr("exists")(name).cast<bool>()) {
          const py::object error = py::module_::import("builtins").attr(is_folder ? "IsADirectoryError" : "FileNotFoundError");
          PyErr_SetObject(error.ptr(), py::make_tuple(is_folder ? EISDIR : ENOENT,
                                                      is_folder ? "a folder, not a mesh file" : "no such mesh file", name)
                                         .ptr());
          throw py::error_already_set();
        }
        py::gil_scoped_release release;
        return std::make_shared<Python_mesh>(geodesic_tool::read_mesh_file(name));
      },
      py::arg("path"), "Reads a mesh file (.off, .obj, .ply or .stl, ASCII or binary) and prepares it; FileNotFoundError "
      "(IsADirectoryError) when there is no such file, GeodesicError when it cannot be read as a mesh.")
    .def_property_readonly(
      "vertices",
      [](py::object self) {
        const Python_mesh& mesh = self.cast<const Python_mesh&>();
        static_assert(sizeof(geodesic_tool::Point) == 3 * sizeof(double), "a point is 3 doubles");
        py::array_t<double> view({py::ssize_t(mesh.number_of_points()), py::ssize_t(3)},
                                 {py::ssize_t(sizeof(geodesic_tool::Point)), py::ssize_t(sizeof(double))},
                                 reinterpret_cast<const double*>(mesh.file.soup.points.data()), self);
        view.attr("setflags")(py::arg("write") = false);
        return view;
      },
      "The input vertices, (n, 3) float64, a read-only view.")
    .def_property_readonly(
      "faces",
      [](const Python_mesh& mesh) -> py::object {
        const geodesic_tool::Polygons& polygons = mesh.file.soup.polygons;
        const bool triangles = std::all_of(polygons.begin(), polygons.end(),
                                           [](const geodesic_tool::Polygons::Polygon& p) { return p.size() == 3; });
        if(triangles) {
          std::vector<long long> ids;
          ids.reserve(3 * polygons.size());
          for(const auto& polygon : polygons)
            ids.insert(ids.end(), polygon.begin(), polygon.end());
          return to_array(std::move(ids), {py::ssize_t(polygons.size()), 3});
        }
        py::list list;
        for(const auto& polygon : polygons)
          list.append(to_array(std::vector<long long>(polygon.begin(), polygon.end())));
        return std::move(list);
      },
      "The input faces: an (m, 3) int64 array when all are triangles, a list of arrays otherwise.")
    .def_property_readonly("n_vertices", &Python_mesh::number_of_points, "The number of input vertices.")
    .def_property_readonly("n_faces", &Python_mesh::number_of_polygons, "The number of input faces.")
    .def_property_readonly(
      "repairs", [](const Python_mesh& mesh) { return repairs_dict(mesh.file.repairs); },
      "What was repaired to make a triangle mesh of the input: counts by kind, 'changed' and a one-line 'summary'.")
    .def("__repr__",
         [](const Python_mesh& mesh) {
           return "<cgal_ext_geodesics.Mesh with " + std::to_string(mesh.number_of_points()) + " vertices and " +
                  std::to_string(mesh.number_of_polygons()) + " faces>";
         })
    .def("distances", &distances, py::arg("sources"), py::arg("algorithm") = py::none(), py::arg("threads") = py::none(),
         py::arg("max_distance") = py::none(), py::arg("stop_vertices") = py::none(), py::arg("lam") = py::none(),
         py::arg("return_sources") = false, py::arg("progress") = py::none(), R"doc(
Geodesic distances from the nearest source to every vertex.

sources: a vertex id, a sequence of vertex ids, a face point
    ``(face, (b0, b1, b2))`` (barycentric coordinates in the order of the
    face's vertices), a sequence of face points, or two arrays
    ``(faces, barycentric)`` of shapes (k,) and (k, 3).
algorithm: the exact 'pvtp' (the default: VTP on threads), 'vtp' (one
    thread, the fastest there), 'pmmp' (on threads), 'fwp_mmp', 'mmp'; the
    approximate 'pavtp' and 'avtp' (never below the exact distance).
threads: None for every core; a number for the parallel algorithms, 1 for
    the others. A parallel algorithm gives the same bytes for every number
    of threads; the sequential ones agree with it to round-off.
max_distance: stop the propagation there; farther vertices get inf.
stop_vertices: stop once these vertices are settled (the VTP family).
lam: the approximation of 'pavtp' and 'avtp' (default 8), positive, the
    smaller the faster and coarser; lam alone selects 'pavtp'.
return_sources: also return the index of each vertex's nearest source (in
    the order of `sources`; -1 where no source reaches).
progress: a function called a few times a second with the fraction done;
    returning False cancels (``Cancelled``). Ctrl-C interrupts in any case.

Returns an (n,) float64 array (inf where unreached), or a tuple
(distances, nearest_sources) with an int64 array.
)doc")
    .def("_distance_matrix", &distance_matrix, py::arg("sources"), py::arg("targets") = py::none(),
         py::arg("max_distance") = py::none(), py::arg("threads") = py::none(), py::arg("progress") = py::none(),
         "The dense matrix, or the CSR arrays (data, indices, indptr, shape) with a finite max_distance; "
         "Mesh.distance_matrix makes a SciPy matrix of them.");
}

} // namespace cgal_ext_python
