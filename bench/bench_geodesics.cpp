// Copyright (c) 2026 The CGAL_ext geodesics developers.
//
// bench_geodesics: runs ONE geodesic method on ONE mesh per process and prints ONE line of
// `key=value` pairs on stdout (diagnostics go to stderr). Driven by bench/run_benchmarks.py,
// which starts one process per (mesh, method) so that the peak resident memory of the process
// is the peak of that method alone (plus the mesh, reported separately as rss_base_mb).
//
//   bench_geodesics --mesh FILE --method M [--source V] [--subdivide N] [--dump FILE]
//                   [--threads T] [--batch-size K] [--lambda L] [--paths N]
//   bench_geodesics --mesh FILE --subdivide N --write OUT.off     (cache a Loop subdivision)
//   bench_geodesics --mesh FILE --info                            (size and bounding box only)
//
// Methods: vtp (CGAL_ext::geodesic_distances, exact), pvtp (the same with CGAL::Parallel_tag on
// --threads T threads, --batch-size K lists a batch, exact), avtp (approximation(--lambda L)),
// pavtp (approximation(L) with CGAL::Parallel_tag on T threads), smsp
// (CGAL::Surface_mesh_shortest_path, exact), heat_direct / heat_idt (CGAL::Heat_method_3,
// approximate), dijkstra (graph distance along the mesh edges, an upper bound); mmp, fwp_mmp and
// pmmp (CGAL_ext::Surface_mesh_geodesic_paths built with MMP, FWP-MMP, or PMMP with
// CGAL::Parallel_tag on --threads T threads), which then time --paths N shortest path queries
// (default 200; smsp times them too when --paths is given).
//
// Every time is wall-clock (std::chrono::steady_clock) and excludes reading the mesh.
// `--dump FILE` writes the distances as raw native doubles, one per vertex in index order.

#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED // the heat method needs CGAL's Eigen solver traits
#endif

#include <CGAL_ext/Surface_mesh_geodesic_paths.h>
#include <CGAL_ext/geodesic_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

typedef std::chrono::steady_clock Clock;

double seconds_since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// getrusage's ru_maxrss, in MB (Linux reports kilobytes). Caveat: Linux carries ru_maxrss over
// execve, so a process started by a big parent (the Python script) inherits the parent's peak.
double ru_maxrss_mb()
{
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  return double(ru.ru_maxrss) / 1024.0;
}

// The peak resident memory of this process image: VmHWM of /proc/self/status, which starts
// afresh at execve (unlike ru_maxrss); ru_maxrss where /proc is not available.
double peak_rss_mb()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line)) {
    if(line.compare(0, 6, "VmHWM:") == 0)
      return std::strtod(line.c_str() + 6, nullptr) / 1024.0; // kB
  }
  return ru_maxrss_mb();
}

[[noreturn]] void usage(const std::string& msg)
{
  if(!msg.empty())
    std::cerr << "bench_geodesics: " << msg << "\n";
  std::cerr << "usage: bench_geodesics --mesh FILE --method vtp|pvtp|avtp|pavtp|smsp|heat_direct|heat_idt|dijkstra|\n"
               "                                               mmp|fwp_mmp|pmmp\n"
               "                       [--source V] [--subdivide N] [--dump FILE]\n"
               "                       [--threads T] [--batch-size K]   (pvtp, pavtp, pmmp; T = 0: as many as TBB chooses)\n"
               "                       [--lambda L]                     (avtp, pavtp: required)\n"
               "                       [--paths N]                      (mmp, fwp_mmp, pmmp: default 200; smsp: default 0)\n"
               "       bench_geodesics --mesh FILE --subdivide N --write OUT.off\n"
               "       bench_geodesics --mesh FILE [--subdivide N] --info\n";
  std::exit(2);
}

// The line printed on stdout: keys in insertion order.
struct Result_line
{
  std::ostringstream out;
  Result_line() { out << std::setprecision(9); }
  template <class T>
  void add(const std::string& key, const T& value)
  {
    if(out.tellp() > 0)
      out << ' ';
    out << key << '=' << value;
  }
  void print() { std::cout << out.str() << std::endl; }
};

// Fills `d` (indexed by vertex index) and `r` with the method's own keys.
typedef std::vector<double> Distances;

// The options of the VTP family (vtp, pvtp, avtp, pavtp).
struct Vtp_options
{
  bool parallel = false;
  bool approximate = false;
  int threads = 0;
  std::size_t batch_size = CGAL_ext::default_batch_size;
  double lambda = 0;
};

void run_vtp(const Mesh& tm, vertex_descriptor source, const Vtp_options& o, Distances& d, Result_line& r)
{
  namespace params = CGAL_ext::parameters;
  CGAL_ext::Geodesic_statistics stats;
  d.assign(num_vertices(tm), 0.);
  auto dmap = CGAL::make_property_map(d);
  const auto t = Clock::now();
  if(o.parallel && o.approximate)
    CGAL_ext::geodesic_distances<CGAL::Parallel_tag>(
      tm, dmap, source,
      params::approximation(o.lambda).number_of_threads(o.threads).batch_size(o.batch_size).statistics(stats));
  else if(o.parallel)
    CGAL_ext::geodesic_distances<CGAL::Parallel_tag>(
      tm, dmap, source, params::number_of_threads(o.threads).batch_size(o.batch_size).statistics(stats));
  else if(o.approximate)
    CGAL_ext::geodesic_distances(tm, dmap, source, params::approximation(o.lambda).statistics(stats));
  else
    CGAL_ext::geodesic_distances(tm, dmap, source, params::statistics(stats));
  const double total = seconds_since(t);
  const double nv = double(num_vertices(tm));
  if(o.parallel) {
    r.add("threads", o.threads);
    r.add("batch_size", o.batch_size);
  }
  if(o.approximate)
    r.add("lambda", o.lambda);
  r.add("seconds_setup", stats.seconds_setup);
  r.add("seconds_solve", stats.seconds_solve);
  r.add("seconds_total", total);
  // Phases of the batched solver (pvtp, avtp, pavtp; zero for vtp but the wavefront resets).
  r.add("seconds_selection", stats.seconds_selection);
  r.add("seconds_propagation", stats.seconds_propagation);
  r.add("seconds_merge", stats.seconds_merge);
  r.add("windows_created", stats.windows_created);
  r.add("windows_per_vertex", double(stats.windows_created) / nv);
  r.add("peak_windows", stats.peak_windows);
  r.add("peak_window_bytes", stats.peak_window_bytes);
  r.add("peak_window_mb", double(stats.peak_window_bytes) / (1024.0 * 1024.0));
  r.add("vertices_popped", stats.vertices_popped);
  r.add("lists_propagated", stats.lists_propagated);
  r.add("wavefront_resets", stats.wavefront_resets);
  r.add("ns_per_window", stats.windows_created > 0 ? 1e9 * stats.seconds_solve / double(stats.windows_created) : 0.);
}

// The targets of the path queries: `count` vertices drawn by splitmix64 from a fixed seed, so
// that every method and every run of a mesh queries the same vertices (repeats allowed).
std::vector<vertex_descriptor> path_targets(const Mesh& tm, std::size_t count)
{
  std::uint64_t state = 0x9e3779b97f4a7c15ull;
  std::vector<vertex_descriptor> targets;
  const std::uint64_t n = num_vertices(tm);
  for(std::size_t i = 0; i < count; ++i) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    targets.push_back(vertex_descriptor(static_cast<Mesh::size_type>(z % n)));
  }
  return targets;
}

// Times one path query per target: `query(target, points)` fills `points`. Reports the median and
// largest time of one query (ms), the mean number of points of a path, and the largest
// |path length - distance(target)| over the bounding box diagonal (a sanity check, not timed).
template <class Query, class Distance>
void time_path_queries(const Mesh& tm, std::size_t count, double diagonal, Query query, Distance distance,
                       Result_line& r)
{
  const std::vector<vertex_descriptor> targets = path_targets(tm, count);
  std::vector<double> ms;
  std::vector<Point_3> points;
  points.reserve(4096);
  double total_points = 0, worst_length_error = 0, total_seconds = 0;
  std::size_t empty = 0;
  for(vertex_descriptor t : targets) {
    points.clear();
    const auto tq = Clock::now();
    query(t, points);
    const double seconds = seconds_since(tq);
    total_seconds += seconds;
    ms.push_back(1e3 * seconds);
    total_points += double(points.size());
    if(points.empty()) {
      ++empty;
      continue;
    }
    double length = 0;
    for(std::size_t i = 1; i < points.size(); ++i)
      length += std::sqrt(CGAL::to_double(CGAL::squared_distance(points[i - 1], points[i])));
    worst_length_error = std::max(worst_length_error, std::abs(length - distance(t)));
  }
  std::sort(ms.begin(), ms.end());
  const std::size_t k = ms.size();
  const double median = k == 0 ? 0. : (k % 2 ? ms[k / 2] : 0.5 * (ms[k / 2 - 1] + ms[k / 2]));
  r.add("paths", k);
  r.add("path_query_median_ms", median);
  r.add("path_query_max_ms", k == 0 ? 0. : ms.back());
  r.add("seconds_paths", total_seconds);
  r.add("path_points_mean", k == 0 ? 0. : total_points / double(k));
  r.add("paths_empty", empty);
  r.add("path_length_error_over_diagonal", diagonal > 0 ? worst_length_error / diagonal : worst_length_error);
}

void run_smsp(const Mesh& tm, vertex_descriptor source, std::size_t paths, double diagonal, Distances& d,
              Result_line& r)
{
  typedef CGAL::Surface_mesh_shortest_path_traits<Kernel, Mesh> Traits;
  typedef CGAL::Surface_mesh_shortest_path<Traits> Shortest_path;
  d.assign(num_vertices(tm), 0.);
  const auto t = Clock::now();
  Shortest_path sp(tm);
  sp.add_source_point(source);
  sp.build_sequence_tree();
  const double build = seconds_since(t);
  const auto tq = Clock::now();
  for(vertex_descriptor v : vertices(tm))
    d[v.idx()] = CGAL::to_double(sp.shortest_distance_to_source_points(v).first);
  const double query = seconds_since(tq);
  r.add("seconds_build", build);
  r.add("seconds_query", query);
  r.add("seconds_total", build + query);
  r.add("peak_rss_build_mb", peak_rss_mb());
  if(paths > 0)
    time_path_queries(
      tm, paths, diagonal,
      [&](vertex_descriptor v, std::vector<Point_3>& points) {
        sp.shortest_path_points_to_source_points(v, std::back_inserter(points));
      },
      [&](vertex_descriptor v) { return d[v.idx()]; }, r);
}

// mmp, fwp_mmp, pmmp: CGAL_ext::Surface_mesh_geodesic_paths from one vertex, then the distance of
// every vertex and `paths` path queries.
template <class ConcurrencyTag>
void run_mmp(const Mesh& tm, vertex_descriptor source, CGAL_ext::Geodesic_algorithm algorithm, int threads,
             std::size_t batch_size, std::size_t paths, double diagonal, Distances& d, Result_line& r)
{
  namespace params = CGAL_ext::parameters;
  typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh, ConcurrencyTag> Geodesic_paths;
  constexpr bool parallel = std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value;
  d.assign(num_vertices(tm), 0.);
  const auto t = Clock::now();
  Geodesic_paths gp(tm);
  const double setup = seconds_since(t);
  gp.add_source(source);
  const auto tb = Clock::now();
  CGAL_ext::Geodesic_statistics stats;
  if(parallel)
    gp.build(params::number_of_threads(threads).batch_size(batch_size).statistics(stats));
  else
    gp.build(params::algorithm(algorithm).statistics(stats));
  const double build = seconds_since(tb);
  const double total = seconds_since(t);
  const double rss_build = peak_rss_mb();
  const auto td = Clock::now();
  gp.vertex_distances(CGAL::make_property_map(d));
  const double seconds_distances = seconds_since(td);
  const double nv = double(num_vertices(tm));
  const double mb = 1024.0 * 1024.0;
  if(parallel) {
    r.add("threads", threads);
    r.add("batch_size", batch_size);
  }
  r.add("seconds_setup", setup);
  r.add("seconds_build", build);
  r.add("seconds_solve", stats.seconds_solve);
  r.add("seconds_total", total);
  r.add("seconds_distances", seconds_distances);
  // Phases (thesis figure 3.16): PMMP fills all; sequential MMP and FWP-MMP clip each window as
  // it is made, so their propagation includes the clipping.
  r.add("seconds_selection", stats.seconds_selection);
  r.add("seconds_propagation", stats.seconds_propagation);
  r.add("seconds_organization", stats.seconds_organization);
  r.add("seconds_clipping", stats.seconds_clipping);
  r.add("seconds_pushing", stats.seconds_pushing);
  r.add("seconds_merge", stats.seconds_merge);
  r.add("windows_created", stats.windows_created);
  r.add("windows_propagated", stats.windows_propagated);
  r.add("windows_deferred", stats.windows_deferred);
  r.add("windows_stored", stats.windows_stored);
  r.add("windows_per_vertex", double(stats.windows_created) / nv);
  r.add("windows_stored_per_vertex", double(stats.windows_stored) / nv);
  r.add("peak_windows", stats.peak_windows);
  r.add("peak_window_bytes", stats.peak_window_bytes);
  r.add("peak_window_mb", double(stats.peak_window_bytes) / mb);
  r.add("stored_window_bytes", stats.stored_window_bytes);
  r.add("stored_window_mb", double(stats.stored_window_bytes) / mb);
  r.add("ns_per_window", stats.windows_created > 0 ? 1e9 * stats.seconds_solve / double(stats.windows_created) : 0.);
  r.add("peak_rss_build_mb", rss_build);
  if(paths > 0)
    time_path_queries(
      tm, paths, diagonal,
      [&](vertex_descriptor v, std::vector<Point_3>& points) { gp.shortest_path_points(v, std::back_inserter(points)); },
      [&](vertex_descriptor v) { return d[v.idx()]; }, r);
}

template <class Mode>
void run_heat(const Mesh& tm, vertex_descriptor source, Distances& d, Result_line& r)
{
  typedef CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Mesh, Mode> Heat;
  d.assign(num_vertices(tm), 0.);
  auto dmap = CGAL::make_property_map(d);
  const auto t = Clock::now();
  Heat heat(tm);
  heat.add_source(source);
  const double precompute = seconds_since(t);
  const auto ts = Clock::now();
  heat.estimate_geodesic_distances(dmap);
  const double solve = seconds_since(ts);
  r.add("seconds_precompute", precompute);
  r.add("seconds_solve", solve);
  r.add("seconds_total", precompute + solve);
}

// Indexed binary min-heap over vertex indices with decrease-key.
class Vertex_heap
{
public:
  explicit Vertex_heap(std::size_t n, const Distances& key) : m_pos(n, npos), m_key(key) {}
  bool empty() const { return m_heap.empty(); }
  void push_or_decrease(std::uint32_t v)
  {
    if(m_pos[v] == npos) {
      m_pos[v] = std::uint32_t(m_heap.size());
      m_heap.push_back(v);
    }
    sift_up(m_pos[v]);
  }
  std::uint32_t pop()
  {
    const std::uint32_t top = m_heap.front();
    m_pos[top] = npos;
    const std::uint32_t last = m_heap.back();
    m_heap.pop_back();
    if(!m_heap.empty()) {
      m_heap[0] = last;
      m_pos[last] = 0;
      sift_down(0);
    }
    return top;
  }

private:
  static constexpr std::uint32_t npos = std::numeric_limits<std::uint32_t>::max();
  void place(std::size_t i, std::uint32_t v)
  {
    m_heap[i] = v;
    m_pos[v] = std::uint32_t(i);
  }
  void sift_up(std::size_t i)
  {
    const std::uint32_t v = m_heap[i];
    const double k = m_key[v];
    while(i > 0) {
      const std::size_t p = (i - 1) / 2;
      if(m_key[m_heap[p]] <= k)
        break;
      place(i, m_heap[p]);
      i = p;
    }
    place(i, v);
  }
  void sift_down(std::size_t i)
  {
    const std::uint32_t v = m_heap[i];
    const double k = m_key[v];
    const std::size_t n = m_heap.size();
    for(;;) {
      std::size_t c = 2 * i + 1;
      if(c >= n)
        break;
      if(c + 1 < n && m_key[m_heap[c + 1]] < m_key[m_heap[c]])
        ++c;
      if(m_key[m_heap[c]] >= k)
        break;
      place(i, m_heap[c]);
      i = c;
    }
    place(i, v);
  }
  std::vector<std::uint32_t> m_heap, m_pos;
  const Distances& m_key;
};

void run_dijkstra(const Mesh& tm, vertex_descriptor source, Distances& d, Result_line& r)
{
  const std::size_t n = num_vertices(tm);
  const auto t = Clock::now();
  // Compressed adjacency (CSR) with the edge lengths precomputed.
  std::vector<std::uint32_t> first(n + 1, 0), target;
  std::vector<double> length;
  for(halfedge_descriptor h : halfedges(tm))
    ++first[tm.source(h).idx() + 1];
  for(std::size_t i = 0; i < n; ++i)
    first[i + 1] += first[i];
  target.resize(first[n]);
  length.resize(first[n]);
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for(halfedge_descriptor h : halfedges(tm)) {
      const vertex_descriptor a = tm.source(h), b = tm.target(h);
      const std::uint32_t slot = fill[a.idx()]++;
      target[slot] = std::uint32_t(b.idx());
      length[slot] = std::sqrt(CGAL::to_double(CGAL::squared_distance(tm.point(a), tm.point(b))));
    }
  }
  const double setup = seconds_since(t);

  const auto ts = Clock::now();
  d.assign(n, std::numeric_limits<double>::infinity());
  std::vector<char> settled(n, 0);
  Vertex_heap heap(n, d);
  d[source.idx()] = 0.;
  heap.push_or_decrease(std::uint32_t(source.idx()));
  std::size_t pops = 0;
  while(!heap.empty()) {
    const std::uint32_t u = heap.pop();
    settled[u] = 1;
    ++pops;
    const double du = d[u];
    for(std::uint32_t k = first[u]; k < first[u + 1]; ++k) {
      const std::uint32_t w = target[k];
      const double dw = du + length[k];
      if(!settled[w] && dw < d[w]) {
        d[w] = dw;
        heap.push_or_decrease(w);
      }
    }
  }
  const double solve = seconds_since(ts);
  r.add("seconds_setup", setup);
  r.add("seconds_solve", solve);
  r.add("seconds_total", setup + solve);
  r.add("vertices_popped", pops);
}

bool read_mesh(const std::string& file, Mesh& tm)
{
  if(!CGAL::IO::read_polygon_mesh(file, tm)) {
    std::cerr << "bench_geodesics: cannot read " << file << "\n";
    return false;
  }
  if(CGAL::is_empty(tm) || !CGAL::is_triangle_mesh(tm)) {
    std::cerr << "bench_geodesics: " << file << " is empty or not a triangle mesh\n";
    return false;
  }
  return true;
}

double bbox_diagonal(const Mesh& tm)
{
  CGAL::Bbox_3 b;
  for(vertex_descriptor v : vertices(tm))
    b += tm.point(v).bbox();
  const double dx = b.xmax() - b.xmin(), dy = b.ymax() - b.ymin(), dz = b.zmax() - b.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

} // namespace

int main(int argc, char* argv[])
{
  std::string mesh_file, method, dump_file, write_file;
  long source_index = 0;
  int subdivide = 0;
  bool info = false;
  Vtp_options vtp_options;
  bool threads_given = false, batch_given = false, lambda_given = false;
  long paths = -1; // -1: the method's default
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        usage("missing value after " + a);
      return argv[++i];
    };
    // A number after `a`, the whole of the argument (usage() otherwise).
    auto number = [&](auto convert) {
      const std::string v = value();
      try {
        std::size_t end = 0;
        const auto x = convert(v, &end);
        if(end == v.size())
          return x;
      } catch(const std::exception&) {
      }
      usage("bad number after " + a + ": " + v);
    };
    auto to_long = [](const std::string& v, std::size_t* end) { return std::stol(v, end); };
    auto to_double = [](const std::string& v, std::size_t* end) { return std::stod(v, end); };
    if(a == "--mesh")
      mesh_file = value();
    else if(a == "--method")
      method = value();
    else if(a == "--source")
      source_index = number(to_long);
    else if(a == "--subdivide")
      subdivide = int(number(to_long));
    else if(a == "--dump")
      dump_file = value();
    else if(a == "--write")
      write_file = value();
    else if(a == "--threads") {
      vtp_options.threads = int(number(to_long));
      threads_given = true;
    } else if(a == "--batch-size") {
      const long k = number(to_long);
      if(k <= 0)
        usage("--batch-size must be positive");
      vtp_options.batch_size = std::size_t(k);
      batch_given = true;
    } else if(a == "--lambda") {
      vtp_options.lambda = number(to_double);
      lambda_given = true;
    }
    else if(a == "--paths") {
      paths = number(to_long);
      if(paths < 0)
        usage("--paths must be non-negative");
    } else if(a == "--info")
      info = true;
    else if(a == "-h" || a == "--help")
      usage("");
    else
      usage("unknown argument " + a);
  }
  if(mesh_file.empty())
    usage("--mesh is required");
  if(method.empty() && write_file.empty() && !info)
    usage("one of --method, --write or --info is required");
  if(subdivide < 0)
    usage("--subdivide must be non-negative");

  try {
    Result_line r;
    const auto tl = Clock::now();
    Mesh tm;
    if(!read_mesh(mesh_file, tm))
      return 1;
    const double seconds_load = seconds_since(tl);
    double seconds_subdivide = 0;
    if(subdivide > 0) {
      const auto ts = Clock::now();
      CGAL::Subdivision_method_3::Loop_subdivision(tm, CGAL::parameters::number_of_iterations(subdivide));
      seconds_subdivide = seconds_since(ts);
    }

    if(!write_file.empty()) {
      // Round-trip exact: 17 significant digits.
      if(!CGAL::IO::write_OFF(write_file, tm, CGAL::parameters::stream_precision(17))) {
        std::cerr << "bench_geodesics: cannot write " << write_file << "\n";
        return 1;
      }
      r.add("written", write_file);
      r.add("vertices", num_vertices(tm));
      r.add("faces", num_faces(tm));
      r.add("seconds_subdivide", seconds_subdivide);
      r.print();
      return 0;
    }

    const bool vtp_family = method == "vtp" || method == "pvtp" || method == "avtp" || method == "pavtp";
    const bool mmp_family = method == "mmp" || method == "fwp_mmp" || method == "pmmp";
    if(!method.empty() && !vtp_family && !mmp_family && method != "smsp" && method != "heat_direct" &&
       method != "heat_idt" && method != "dijkstra")
      usage("unknown method " + method);
    vtp_options.parallel = method == "pvtp" || method == "pavtp";
    vtp_options.approximate = method == "avtp" || method == "pavtp";
    if((threads_given || batch_given) && !vtp_options.parallel && method != "pmmp")
      usage("--threads and --batch-size are options of pvtp, pavtp and pmmp");
    if(paths >= 0 && !mmp_family && method != "smsp")
      usage("--paths is an option of mmp, fwp_mmp, pmmp and smsp");
    const std::size_t path_count = std::size_t(paths >= 0 ? paths : (mmp_family ? 200 : 0));
    if(method == "pmmp" && !batch_given)
      vtp_options.batch_size = CGAL_ext::default_window_batch_size;
    if(lambda_given && !vtp_options.approximate)
      usage("--lambda is an option of avtp and pavtp");
    if(vtp_options.approximate && !lambda_given)
      usage(method + " needs --lambda L");
    if(vtp_options.approximate && !(vtp_options.lambda > 0 && std::isfinite(vtp_options.lambda)))
      usage("--lambda must be positive");
    if(vtp_options.threads < 0)
      usage("--threads must be non-negative");

    const std::size_t n = num_vertices(tm);
    if(source_index < 0 || std::size_t(source_index) >= n)
      usage("source vertex " + std::to_string(source_index) + " out of range");
    const vertex_descriptor source(static_cast<Mesh::size_type>(source_index));

    if(!method.empty())
      r.add("method", method);
    r.add("vertices", n);
    r.add("faces", num_faces(tm));
    const double diagonal = bbox_diagonal(tm);
    r.add("bbox_diagonal", diagonal);
    r.add("source", source_index);
    r.add("seconds_load", seconds_load);
    if(subdivide > 0)
      r.add("seconds_subdivide", seconds_subdivide);
    r.add("rss_base_mb", peak_rss_mb());
    if(info) {
      r.print();
      return 0;
    }

    Distances d;
    if(vtp_family)
      run_vtp(tm, source, vtp_options, d, r);
    else if(method == "smsp")
      run_smsp(tm, source, path_count, diagonal, d, r);
    else if(method == "mmp")
      run_mmp<CGAL::Sequential_tag>(tm, source, CGAL_ext::MMP, 0, 0, path_count, diagonal, d, r);
    else if(method == "fwp_mmp")
      run_mmp<CGAL::Sequential_tag>(tm, source, CGAL_ext::FWP_MMP, 0, 0, path_count, diagonal, d, r);
    else if(method == "pmmp")
      run_mmp<CGAL::Parallel_tag>(tm, source, CGAL_ext::FWP_MMP, vtp_options.threads, vtp_options.batch_size,
                                  path_count, diagonal, d, r);
    else if(method == "heat_direct")
      run_heat<CGAL::Heat_method_3::Direct>(tm, source, d, r);
    else if(method == "heat_idt")
      run_heat<CGAL::Heat_method_3::Intrinsic_Delaunay>(tm, source, d, r);
    else
      run_dijkstra(tm, source, d, r);
    r.add("peak_rss_mb", peak_rss_mb());
    r.add("ru_maxrss_mb", ru_maxrss_mb());

    // Cheap sanity numbers; the script does the real comparison from the dump.
    std::size_t nonfinite = 0;
    double max_distance = 0;
    for(double x : d) {
      if(!std::isfinite(x))
        ++nonfinite;
      else
        max_distance = std::max(max_distance, x);
    }
    r.add("nonfinite", nonfinite);
    r.add("max_distance", max_distance);

    if(!dump_file.empty()) {
      std::ofstream out(dump_file, std::ios::binary);
      out.write(reinterpret_cast<const char*>(d.data()), std::streamsize(d.size() * sizeof(double)));
      if(!out) {
        std::cerr << "bench_geodesics: cannot write " << dump_file << "\n";
        return 1;
      }
      r.add("dump", dump_file);
    }
    r.print();
  } catch(const std::exception& e) {
    std::cerr << "bench_geodesics: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
