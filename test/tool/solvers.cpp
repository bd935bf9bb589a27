// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: its solvers. The default one, exact and the same on any number
// of threads; the parallel and approximate solvers and the MMP family against the exact
// sequential one, on each mesh.

#include "tool_test_support.h"

namespace tool_test::solvers {

double bbox_diagonal(const Soup& soup)
{
  const CGAL::Bbox_3 box = CGAL::bbox_3(soup.points.begin(), soup.points.end());
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

/// Equal within `relative` times the larger magnitude (so exactly equal at 0 and at infinity).
void expect_relatively_close(const std::vector<double>& a, const std::vector<double>& b, double relative)
{
  ASSERT_EQ(a.size(), b.size());
  for(std::size_t i = 0; i < a.size(); ++i) {
    if(std::isinf(a[i]) || std::isinf(b[i]))
      EXPECT_EQ(a[i], b[i]) << "vertex " << i;
    else
      EXPECT_NEAR(a[i], b[i], relative * std::max(std::abs(a[i]), std::abs(b[i]))) << "vertex " << i;
  }
}

// With no --algorithm, distances and sample run the exact parallel solver: the same output for
// every number of threads (the file's bytes), and VTP's distances and samples to round-off.
TEST_F(Tool, default_solver_is_exact_and_the_same_on_any_number_of_threads)
{
  const std::string mesh = "distances '" + elephant + "' --source 100,f:40:0.6:0.3:0.1 --output d.txt";
  ASSERT_EQ(run(mesh).exit_code, 0);
  const std::string by_default = read_text(path("d.txt"));
  for(const char* threads : {"1", "2", "4"}) {
    ASSERT_EQ(run(mesh + " --threads " + threads).exit_code, 0) << threads;
    EXPECT_EQ(read_text(path("d.txt")), by_default) << threads << " threads";
  }
  const std::vector<double> vtp = distances("distances '" + elephant + "' --source 100,f:40:0.6:0.3:0.1 --algorithm vtp");
  const double largest = *std::max_element(vtp.begin(), vtp.end());
  expect_same_distances(parse_distances(by_default), vtp, 1e-12 * largest);

  const std::string sample = "sample '" + elephant + "' --count 30";
  const std::string samples = output_of(sample + " --threads 2", "s.txt");
  EXPECT_EQ(output_of(sample + " --threads 1", "s.txt"), samples);
  EXPECT_EQ(output_of(sample, "s.txt"), samples);
  const auto parallel = parse_samples(samples), sequential = parse_samples(output_of(sample + " --algorithm vtp", "s.txt"));
  ASSERT_EQ(parallel.size(), sequential.size());
  for(std::size_t k = 0; k < parallel.size(); ++k) {
    EXPECT_EQ(parallel[k].first, sequential[k].first) << "sample " << k;
    EXPECT_NEAR(parallel[k].second, sequential[k].second, 1e-12 * largest) << "radius after sample " << k;
  }
}

// ---------------------------------------------------------------------------------------------
// The parallel and approximate solvers against the exact sequential one, on each mesh

class Solvers : public Tool, public ::testing::WithParamInterface<std::string>
{
protected:
  /// The distances from two sources (a vertex and a face point) with the solver options `args`.
  std::vector<double> solve(const std::string& args, const std::string& output = "d.txt") const
  {
    return distances("distances '" + GetParam() + "' --source 0,f:7:0.2:0.5:0.3 " + args, output);
  }

  /// The same, and the text of the output file.
  std::string solve_text(const std::string& args) const
  {
    solve(args, "t.txt");
    return read_text(path("t.txt"));
  }
};

TEST_P(Solvers, pvtp_is_vtp_on_any_number_of_threads)
{
  const std::vector<double> vtp = solve("--algorithm vtp");
  const std::string one = solve_text("--algorithm pvtp --threads 1");
  EXPECT_EQ(solve_text("--algorithm pvtp --threads 2"), one);
  EXPECT_EQ(solve_text("--algorithm pvtp --threads 4"), one);
  expect_relatively_close(parse_distances(one), vtp, 1e-12);
  expect_relatively_close(solve("--algorithm pvtp --threads 2 --batch-size 7"), vtp, 1e-12);
  expect_relatively_close(solve("--algorithm pvtp"), vtp, 1e-12);
}

TEST_P(Solvers, avtp_is_pavtp_and_never_below_vtp)
{
  const std::vector<double> vtp = solve("--algorithm vtp");
  const std::string avtp = solve_text("--algorithm avtp --lambda 8");
  EXPECT_EQ(solve_text("--algorithm pavtp --lambda 8 --threads 2"), avtp);
  EXPECT_EQ(solve_text("--algorithm avtp"), avtp) << "the default lambda is not 8";
  const std::vector<double> d = parse_distances(avtp);
  ASSERT_EQ(d.size(), vtp.size());
  std::size_t above = 0;
  for(std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_GE(d[i], vtp[i] - 1e-12) << "vertex " << i;
    above += d[i] > vtp[i] + 1e-9;
  }
  EXPECT_GT(above, 0u) << "lambda 8 did not approximate anything";
}

TEST_P(Solvers, avtp_with_a_huge_lambda_is_vtp)
{
  const std::vector<double> vtp = solve("--algorithm vtp");
  expect_relatively_close(solve("--algorithm avtp --lambda 1e12"), vtp, 1e-12);
  expect_relatively_close(solve("--algorithm pavtp --lambda 1e12 --threads 2"), vtp, 1e-12);
}

// MMP, FWP-MMP and PMMP keep windows for paths; their distances are VTP's up to round-off.
TEST_P(Solvers, mmp_family_is_vtp)
{
  const std::vector<double> vtp = solve("--algorithm vtp");
  const double tolerance = 1e-12 * bbox_diagonal(read_soup(GetParam()));
  for(const char* args : {"--algorithm mmp", "--algorithm fwp-mmp", "--algorithm pmmp",
                          "--algorithm pmmp --threads 2 --batch-size 7"}) {
    SCOPED_TRACE(args);
    expect_same_distances(solve(args), vtp, tolerance);
  }
}

TEST_P(Solvers, pmmp_is_the_same_on_any_number_of_threads)
{
  const std::string one = solve_text("--algorithm pmmp --threads 1");
  EXPECT_EQ(solve_text("--algorithm pmmp --threads 2"), one);
  // the batch size orders the windows, hence the round-off (batch 7 differs in the last digits
  // on both meshes today): 1024 is the default
  EXPECT_EQ(solve_text("--algorithm pmmp --threads 2 --batch-size 1024"), one);
}

INSTANTIATE_TEST_SUITE_P(Tool, Solvers, ::testing::Values(elephant, mushroom),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return fs::path(info.param).stem().string();
                         });

} // namespace tool_test::solvers
