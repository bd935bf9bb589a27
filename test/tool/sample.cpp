// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: `geodesic sample`, farthest-point sampling.

#include "tool_test_support.h"

#include "tool_text.h"

namespace tool_test::sample {

// Each sample is the vertex farthest from those before it (checked with the tool's own
// distances), the radius after it is the largest distance left; --radius stops there; --labels
// gives each vertex its nearest sample.
TEST_F(Tool, sample_gives_the_farthest_vertices_and_their_radii)
{
  const auto samples = parse_samples(output_of("sample '" + elephant + "' --count 6", "s.txt"));
  ASSERT_EQ(samples.size(), 6u);
  const std::vector<double> from_0 = distances("distances '" + elephant + "' --source 0");
  EXPECT_EQ(from_0[samples[0].first], *std::max_element(from_0.begin(), from_0.end()));
  std::string so_far;
  for(std::size_t k = 0; k < samples.size(); ++k) {
    so_far += (k ? "," : "") + std::to_string(samples[k].first);
    const std::vector<double> d = distances("distances '" + elephant + "' --source " + so_far);
    const double farthest = *std::max_element(d.begin(), d.end());
    EXPECT_NEAR(samples[k].second, farthest, 1e-12 * farthest) << "radius after sample " << k;
    if(k + 1 < samples.size())
      EXPECT_NEAR(d[samples[k + 1].first], farthest, 1e-12 * farthest) << "sample " << k + 1;
  }

  // --first, --radius, --labels, in parallel
  const auto from_7 =
    parse_samples(output_of("sample '" + elephant + "' --first 7 --radius " + tool::number_text(samples[3].second) +
                              " --count 100 --algorithm pvtp --threads 2 --labels l.txt",
                            "s.txt"));
  ASSERT_GE(from_7.size(), 2u);
  EXPECT_EQ(from_7[0].first, 7u);
  EXPECT_LE(from_7.back().second, samples[3].second);
  EXPECT_GT(from_7[from_7.size() - 2].second, samples[3].second);
  const std::vector<std::string> labels = lines_of(read_text(path("l.txt")));
  ASSERT_EQ(labels.size(), 2775u);
  for(std::size_t k = 0; k < from_7.size(); ++k)
    EXPECT_EQ(labels[from_7[k].first], std::to_string(k));

  // several --first: those, in order, each with the radius after all of them; then the farthest
  const auto from_three = parse_samples(output_of("sample '" + elephant + "' --first 900,100,2000 --count 5", "s.txt"));
  ASSERT_EQ(from_three.size(), 5u);
  const std::vector<double> d = distances("distances '" + elephant + "' --source 900,100,2000");
  const double farthest = *std::max_element(d.begin(), d.end());
  for(std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(from_three[k].first, std::vector<std::size_t>({900, 100, 2000})[k]);
    EXPECT_NEAR(from_three[k].second, farthest, 1e-12 * farthest) << "radius after initial sample " << k;
  }
  EXPECT_NEAR(d[from_three[3].first], farthest, 1e-12 * farthest);
}

} // namespace tool_test::sample
