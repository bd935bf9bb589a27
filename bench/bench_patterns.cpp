// Repetitive pattern detection on meshes with planted instances (the thesis's Table 5.1 for our
// code): the time of each step, the instances found, recall and precision.
// Usage: bench_patterns MODEL VERTICES INSTANCES [THREADS [SEED]]
//   SEED (default: the tests' own) draws another layout, noise and orientations (not for golf).
//   MODEL: plane (round bumps), golf (dimples on a sphere), cylinder, elongated, sizes (three sizes)
// Prints one Markdown table row; with BENCH_PATTERNS_OFFSETS set, also each found centre's offset
// from its nearest planted centre, over that instance's radius, on stderr; with
// BENCH_PATTERNS_MESH=FILE, also writes the mesh built (to run the tool on it, or to view it);
// with BENCH_PATTERNS_COUNTS set, the run's counts (samples, searches, rows) on stderr;
// with BENCH_PATTERNS_LAMBDA=L, the local rows are approximate (`approximation(L)`).
#include "support/pattern_meshes.h"

#include <CGAL_ext/detect_repetitive_patterns.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

using namespace test_support;

int main(int argc, char** argv)
{
  if(argc < 4) {
    std::cerr << "usage: bench_patterns plane|golf|cylinder|elongated|sizes VERTICES INSTANCES [THREADS [SEED]]\n";
    return EXIT_FAILURE;
  }
  const std::string model = argv[1];
  const double vertices = std::atof(argv[2]);
  const int count = std::atoi(argv[3]);
  const int threads = argc > 4 ? std::atoi(argv[4]) : 0;
  const auto seed = [&](unsigned own) { return argc > 5 ? unsigned(std::atoi(argv[5])) : own; };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads > 0 ? std::size_t(threads) : 2);
#endif
  // instance sizes that let `count` instances fit at the layouts' spacings
  const int n = int(std::lround(std::sqrt(vertices)));
  Pattern_scene scene;
  if(model == "plane")
    scene = round_bumps_on_a_plane(n, count, 0.85 * std::sqrt(1.0 / (5.41 * count)), seed(3), 0.05);
  else if(model == "golf")
    scene = dimples_on_a_sphere(int(std::lround(std::sqrt((vertices - 2) / 10))), count,
                                0.95 * std::sqrt(2.2 / count), 0.0002);
  else if(model == "cylinder") {
    const int segments = int(std::lround(std::sqrt(vertices * 2 * pi / 6)));
    scene = bumps_around_a_cylinder(segments, int(vertices / segments) - 1, count,
                                    0.85 * std::sqrt(37.7 * 0.8 / (5.41 * count)), seed(8));
  } else if(model == "elongated")
    scene = elongated_bumps_on_a_plane(n, count, 0.85 * std::sqrt(1.0 / (18.3 * count)), seed(21), 0.03);
  else if(model == "sizes")
    scene = bumps_of_three_sizes_on_a_plane(n, count, 0.85 * std::sqrt(1.0 / (10.0 * count)), seed(5), 0.03);
  else {
    std::cerr << "unknown model " << model << "\n";
    return EXIT_FAILURE;
  }
  if(const char* file = std::getenv("BENCH_PATTERNS_MESH"))
    if(!CGAL::IO::write_polygon_mesh(file, scene.mesh, CGAL::parameters::stream_precision(17))) {
      std::cerr << "cannot write " << file << "\n";
      return EXIT_FAILURE;
    }
  const auto patch = scene.patch_radius > 0
                       ? CGAL_ext::Pattern_patch<Mesh>::disk(scene.patch_centre, scene.patch_radius)
                       : CGAL_ext::Pattern_patch<Mesh>::of_vertices(scene.patch_vertices);
  const char* lambda = std::getenv("BENCH_PATTERNS_LAMBDA");
  CGAL_ext::Pattern_statistics st;
  const auto start = std::chrono::steady_clock::now();
  const auto found = CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(
    scene.mesh, patch,
    CGAL_ext::parameters::scale_range(scene.scales)
      .number_of_threads(threads)
      .approximation(lambda ? std::atof(lambda) : 0.0)
      .statistics(st));
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Score s = score(found.instances, scene.truth);
  if(std::getenv("BENCH_PATTERNS_OFFSETS"))
    for(const auto& instance : found.instances) {
      const std::size_t nearest = scene.truth.nearest(instance.center);
      const double r = scene.truth.radii[nearest];
      const auto d = instance.center - scene.truth.centres[nearest];
      std::cerr << "planted " << nearest << " offset/radius " << std::sqrt(d.squared_length()) / r << " (" << d.x() / r
                << ", " << d.y() / r << ", " << d.z() / r << ") energy " << instance.energy;
      if(!scene.truth.angles.empty()) { // on a plane: the offset along and across the instance's long axis
        const double a = scene.truth.angles[nearest];
        std::cerr << " along " << (d.x() * std::cos(a) + d.y() * std::sin(a)) / r << " across "
                  << (-d.x() * std::sin(a) + d.y() * std::cos(a)) / r;
      }
      std::cerr << "\n";
    }
  if(std::getenv("BENCH_PATTERNS_COUNTS"))
    std::cerr << "samples " << st.samples << " patch_samples " << st.patch_samples << " searches " << st.searches
              << " distance_rows " << st.distance_rows << " matches " << st.matches << " clusters " << st.clusters
              << "\n";
  std::cout.precision(3);
  std::cout << "| " << model << " | " << scene.mesh.number_of_vertices() << " | " << s.planted << " | " << s.found
            << " | " << s.recall << " | " << s.precision << " | " << st.samples << " | " << st.seconds_sampling << " | "
            << st.seconds_signatures << " | " << st.seconds_matching + st.seconds_clustering << " | "
            << st.seconds_optimization << " | " << st.seconds_arrangement << " | " << total << " |" << std::endl;
  return EXIT_SUCCESS;
}
