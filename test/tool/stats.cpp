// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: --stats, the statistics on stderr of `geodesic distances` for
// each solver and of `geodesic path`.

#include "tool_test_support.h"

namespace tool_test::stats {

/// Expects each of `keys` once in the --stats output `stats` parsed as `kv`, with a finite,
/// non-negative number.
void expect_non_negative_numbers(const std::map<std::string, std::string>& kv, const std::vector<std::string>& keys,
                                 const std::string& stats)
{
  for(const std::string& key : keys) {
    ASSERT_EQ(kv.count(key), 1u) << "missing " << key << " in:\n" << stats;
    char* end = nullptr;
    const double value = std::strtod(kv.at(key).c_str(), &end);
    EXPECT_TRUE(*end == '\0' && std::isfinite(value) && value >= 0) << key << "=" << kv.at(key);
  }
}

// --stats for each solver: the common keys, and the solver's own.
struct Algorithm_case
{
  const char* name;
  std::string args;      // the solver options
  const char* algorithm; // the expected algorithm=
  const char* threads;   // the expected threads=, "" if absent, "*" for any positive count
  const char* lambda;    // the expected lambda=, "" if absent
};

void PrintTo(const Algorithm_case& c, std::ostream* os) { *os << c.name; }

const Algorithm_case algorithm_cases[] = {
  {"default", "", "pvtp", "*", ""},
  {"vtp", "--algorithm vtp", "vtp", "", ""},
  {"pvtp", "--algorithm pvtp --threads 2", "pvtp", "2", ""},
  {"pvtp_all_cores", "--algorithm pvtp --batch-size 64", "pvtp", "*", ""},
  {"avtp_default_lambda", "--algorithm avtp", "avtp", "", "8"},
  {"avtp", "--algorithm avtp --lambda 0.5", "avtp", "", "0.5"},
  {"pavtp", "--algorithm pavtp --lambda 2 --threads 3", "pavtp", "3", "2"},
  {"mmp", "--algorithm mmp", "mmp", "", ""},
  {"fwp_mmp", "--algorithm fwp-mmp", "fwp-mmp", "", ""},
  {"pmmp", "--algorithm pmmp --threads 2", "pmmp", "2", ""},
  {"pmmp_all_cores", "--algorithm pmmp --batch-size 64", "pmmp", "*", ""},
};

/// The solvers that keep their windows on the edges, and report on them.
bool is_mmp(const std::string& algorithm) { return algorithm == "mmp" || algorithm == "fwp-mmp" || algorithm == "pmmp"; }

/// The keys of the MMP family's statistics.
const std::vector<std::string> mmp_keys = {"windows_propagated", "windows_deferred", "windows_stored", "stored_window_bytes",
                                           "seconds_organization", "seconds_clipping", "seconds_pushing"};

/// The keys of what was repaired to make the file a mesh (all 0 for a clean file).
const std::vector<std::string> repair_keys = {"merged_points",     "removed_polygons",  "split_polygons",
                                              "triangulated_polygons", "reversed_polygons", "duplicated_points", "non_manifold_edges",
                                              "isolated_points"};

/// Expects every key of `repair_keys` to be 0 in the --stats output parsed as `kv`.
void expect_no_repair(const std::map<std::string, std::string>& kv)
{
  for(const std::string& key : repair_keys)
    EXPECT_EQ(kv.count(key) ? kv.at(key) : "missing", "0") << key;
}

class Stats : public Tool, public ::testing::WithParamInterface<Algorithm_case> {};

TEST_P(Stats, on_stderr)
{
  const Algorithm_case& c = GetParam();
  const Result r =
    run("distances '" + elephant + "' --source 0,f:3:0.2:0.2:0.6 " + c.args + " --stats --output d.txt");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> d = parse_distances(read_text(path("d.txt")));
  const auto kv = parse_key_values(r.err);
  std::vector<std::string> keys = {"vertices", "faces", "sources", "seconds_read", "seconds_setup",
                                   "seconds_solve", "seconds_selection", "seconds_propagation",
                                   "seconds_merge", "windows_created", "peak_windows", "lists_propagated",
                                   "wavefront_resets", "peak_rss_mb", "max_distance"};
  if(*c.threads)
    keys.push_back("threads");
  if(*c.lambda)
    keys.push_back("lambda");
  if(is_mmp(c.algorithm))
    keys.insert(keys.end(), mmp_keys.begin(), mmp_keys.end());
  keys.insert(keys.end(), repair_keys.begin(), repair_keys.end());
  ASSERT_NO_FATAL_FAILURE(expect_non_negative_numbers(kv, keys, r.err));
  expect_no_repair(kv);
  ASSERT_EQ(kv.count("algorithm"), 1u) << r.err;
  EXPECT_EQ(kv.at("algorithm"), c.algorithm);
  EXPECT_EQ(kv.size(), keys.size() + 1) << r.err;
  EXPECT_EQ(kv.at("vertices"), "2775");
  EXPECT_EQ(kv.at("faces"), "5558");
  EXPECT_EQ(kv.at("sources"), "2");
  EXPECT_GT(std::stod(kv.at("windows_created")), 0);
  EXPECT_GT(std::stod(kv.at("peak_windows")), 0);
  if(is_mmp(c.algorithm)) {
    // the windows are kept for queries: all of those alive at the end, some of them clipped
    EXPECT_GT(std::stod(kv.at("windows_propagated")), 0);
    EXPECT_GT(std::stod(kv.at("windows_stored")), 0);
    EXPECT_LE(std::stod(kv.at("windows_stored")), std::stod(kv.at("windows_created")));
    EXPECT_GT(std::stod(kv.at("stored_window_bytes")), 0);
  } else {
    EXPECT_GT(std::stod(kv.at("lists_propagated")), 0);
  }
  EXPECT_GT(std::stod(kv.at("peak_rss_mb")), 1);
  EXPECT_EQ(std::stod(kv.at("max_distance")), *std::max_element(d.begin(), d.end()));
  if(std::string(c.threads) == "*")
    EXPECT_GE(std::stoi(kv.at("threads")), 1);
  else if(*c.threads)
    EXPECT_EQ(kv.at("threads"), c.threads);
  if(*c.lambda) {
    EXPECT_EQ(kv.at("lambda"), c.lambda);
    EXPECT_GT(std::stod(kv.at("wavefront_resets")), 0); // the elephant is many lambdas across
  } else {
    EXPECT_EQ(kv.at("wavefront_resets"), "0");
  }
}

INSTANTIATE_TEST_SUITE_P(Tool, Stats, ::testing::ValuesIn(algorithm_cases),
                         [](const ::testing::TestParamInfo<Algorithm_case>& info) { return info.param.name; });

TEST_F(Tool, path_stats_on_stderr)
{
  const Soup soup = read_soup(elephant);
  const std::vector<double> from_0 = distances("distances '" + elephant + "' --source 0");
  const std::vector<double> from_2000 = distances("distances '" + elephant + "' --source 2000");
  ASSERT_LT(from_2000[1000], from_0[1000]) << "the test wants the second source to be the nearest";
  for(const std::string& algorithm : {"fwp-mmp", "mmp", "pmmp", "vtp", "pvtp"}) {
    SCOPED_TRACE(algorithm);
    const bool parallel = algorithm == "pmmp" || algorithm == "pvtp";
    const Result r = run("path '" + elephant + "' --source 0 --source 2000 --target 1000 --algorithm " + algorithm +
                         (parallel ? " --threads 2" : "") + " --stats --output p.txt");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<Point> p = parse_points(read_text(path("p.txt")));
    ASSERT_GE(p.size(), 2u);
    EXPECT_EQ(p.front(), soup.points[2000]);
    EXPECT_EQ(p.back(), soup.points[1000]);

    const auto kv = parse_key_values(r.err);
    std::vector<std::string> keys = {"vertices", "faces", "sources", "seconds_read", "seconds_build",
                                     "seconds_query", "seconds_setup", "seconds_solve", "seconds_selection",
                                     "seconds_propagation", "seconds_merge", "windows_created", "peak_windows",
                                     "lists_propagated", "wavefront_resets", "peak_rss_mb", "length",
                                     "distance", "points", "nearest_source"};
    if(is_mmp(algorithm))
      keys.insert(keys.end(), mmp_keys.begin(), mmp_keys.end());
    else // VTP's windows are kept too, and reported so
      keys.insert(keys.end(), {"windows_stored", "stored_window_bytes"});
    keys.insert(keys.end(), repair_keys.begin(), repair_keys.end());
    if(parallel)
      keys.push_back("threads");
    ASSERT_NO_FATAL_FAILURE(expect_non_negative_numbers(kv, keys, r.err));
    expect_no_repair(kv);
    EXPECT_EQ(kv.size(), keys.size() + 1) << r.err;
    EXPECT_EQ(kv.at("algorithm"), algorithm);
    if(parallel)
      EXPECT_EQ(kv.at("threads"), "2");
    EXPECT_EQ(kv.at("vertices"), "2775");
    EXPECT_EQ(kv.at("faces"), "5558");
    EXPECT_EQ(kv.at("sources"), "2");
    EXPECT_EQ(kv.at("nearest_source"), "1");
    EXPECT_EQ(kv.at("points"), std::to_string(p.size()));
    const double length = std::stod(kv.at("length")), distance = std::stod(kv.at("distance"));
    EXPECT_NEAR(length, distance, 1e-9 * distance);
    EXPECT_NEAR(distance, from_2000[1000], 1e-9 * distance);
    EXPECT_NEAR(length, polyline_length(p), 1e-12 * length);
    EXPECT_GT(std::stod(kv.at("windows_stored")), 0);
  }
}

} // namespace tool_test::stats
