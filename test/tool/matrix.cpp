// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: `geodesic matrix`, distance matrices as text, NumPy .npy and
// sparse Matrix Market .mtx, and their bad input.

#include "tool_test_support.h"

#include "tool_matrix.h"

#include <cstdio>
#include <cstring>

namespace tool_test::matrix {

/// The numbers of a text matrix, row by row.
std::vector<std::vector<double>> parse_rows(const std::string& text)
{
  std::vector<std::vector<double>> rows;
  for(const std::string& line : lines_of(text)) {
    std::istringstream in(line);
    rows.emplace_back();
    std::string word;
    while(in >> word)
      rows.back().push_back(std::strtod(word.c_str(), nullptr));
  }
  return rows;
}

TEST_F(Tool, matrix_rows_are_the_distances_of_each_source)
{
  const std::string args = "matrix '" + elephant + "' --source 0,10,f:5:0.2:0.3:0.5 --threads 2";
  const auto rows = parse_rows(output_of(args, "m.txt"));
  ASSERT_EQ(rows.size(), 3u);
  // each row is a VTP solve
  EXPECT_EQ(rows[0], distances("distances '" + elephant + "' --source 0 --algorithm vtp"));
  EXPECT_EQ(rows[1], distances("distances '" + elephant + "' --source 10 --algorithm vtp"));
  EXPECT_EQ(rows[2], distances("distances '" + elephant + "' --source f:5:0.2:0.3:0.5 --algorithm vtp"));
  // the same with one thread
  EXPECT_EQ(parse_rows(output_of("matrix '" + elephant + "' --source 0,10,f:5:0.2:0.3:0.5 --threads 1", "m1.txt")),
            rows);
}

TEST_F(Tool, matrix_square_npy_and_sparse_mtx)
{
  output_of("matrix '" + elephant + "' --source 0,10,100,1000 --target sources", "m.txt");
  const auto square = parse_rows(read_text(path("m.txt")));
  ASSERT_EQ(square.size(), 4u);
  for(std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(square[i][i], 0.);
    for(std::size_t j = 0; j < i; ++j)
      EXPECT_NEAR(square[i][j], square[j][i], 1e-12);
  }
  // .npy: NumPy's header (magic, version 1.0, a dict with the shape), then the rows as float64
  const std::string npy = output_of("matrix '" + elephant + "' --source 0,10,100,1000 --target sources", "m.npy");
  ASSERT_GE(npy.size(), 10u);
  EXPECT_EQ(npy.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t header = std::size_t((unsigned char)npy[8]) + 256 * std::size_t((unsigned char)npy[9]);
  EXPECT_EQ((10 + header) % 64, 0u);
  EXPECT_NE(npy.find("'descr': '<f8', 'fortran_order': False, 'shape': (4, 4)"), std::string::npos);
  ASSERT_EQ(npy.size(), 10 + header + 16 * sizeof(double));
  for(std::size_t k = 0; k < 16; ++k) {
    double x;
    std::memcpy(&x, npy.data() + 10 + header + k * sizeof(double), sizeof x);
    EXPECT_EQ(x, square[k / 4][k % 4]);
  }
  // .mtx within a radius: exactly the finite entries of the rows cut at that distance
  const double radius = 0.2;
  const auto full = parse_rows(output_of("matrix '" + elephant + "' --source 0,10", "full.txt"));
  const std::string mtx = output_of("matrix '" + elephant + "' --source 0,10 --max-distance 0.2", "m.mtx");
  const std::vector<std::string> lines = lines_of(mtx);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0], "%%MatrixMarket matrix coordinate real general");
  std::size_t expected_entries = 0;
  for(const auto& row : full)
    for(double d : row)
      expected_entries += d <= radius;
  std::istringstream size_line(lines[2]);
  std::size_t rows = 0, columns = 0, entries = 0;
  size_line >> rows >> columns >> entries;
  EXPECT_EQ(rows, 2u);
  EXPECT_EQ(columns, full[0].size());
  EXPECT_EQ(entries, expected_entries);
  ASSERT_EQ(lines.size(), 3 + entries);
  for(std::size_t k = 3; k < lines.size(); ++k) {
    std::istringstream in(lines[k]);
    std::size_t i = 0, j = 0;
    double d = 0;
    in >> i >> j >> d;
    ASSERT_TRUE(i >= 1 && i <= 2 && j >= 1 && j <= columns) << lines[k];
    EXPECT_EQ(d, full[i - 1][j - 1]);
  }
}

// A local .mtx matrix is made of sparse rows (each costs its entries, not the number of
// columns): the same entries as the dense rows cut at the distance, with columns repeated, in
// any order, and on points that the reading merges (a duplicate) or copies (a non-manifold vertex).
TEST_F(Tool, local_mtx_matrix_equals_the_dense_rows_cut_at_the_distance)
{
  // a bowtie with a non-manifold vertex 0, and point 5 a duplicate of point 2
  write("bowtie.off", "OFF\n6 3 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n0 1 0\n3 0 1 2\n3 0 3 4\n3 0 5 3\n");
  const std::string targets = " --target 3,5,1,3,2,0,4";
  const double radius = 1.9;
  for(const std::string sources : {" --all", " --source 1,f:1:0.2:0.3:0.5"}) {
    const Result dense_run = run("matrix bowtie.off" + sources + targets + " --output m.txt");
    ASSERT_EQ(dense_run.exit_code, 0) << dense_run.err;
    const auto dense = parse_rows(read_text(path("m.txt")));
    const Result sparse_run = run("matrix bowtie.off" + sources + targets + " --max-distance 1.9 --output m.mtx");
    ASSERT_EQ(sparse_run.exit_code, 0) << sparse_run.err;
    const std::vector<std::string> lines = lines_of(read_text(path("m.mtx")));
    ASSERT_GE(lines.size(), 3u);
    std::istringstream size_line(lines[2]);
    std::size_t rows = 0, columns = 0, entries = 0;
    size_line >> rows >> columns >> entries;
    ASSERT_EQ(rows, dense.size());
    ASSERT_EQ(columns, 7u);
    std::vector<std::string> expected;
    for(std::size_t i = 0; i < dense.size(); ++i)
      for(std::size_t j = 0; j < dense[i].size(); ++j)
        if(dense[i][j] <= radius) {
          char line[96];
          std::snprintf(line, sizeof(line), "%zu %zu %.17g", i + 1, j + 1, dense[i][j]);
          expected.push_back(line);
        }
    EXPECT_EQ(entries, expected.size()) << sources;
    EXPECT_EQ(std::vector<std::string>(lines.begin() + 3, lines.end()), expected) << sources;
    EXPECT_GT(expected.size(), 2 * dense.size()) << "the rows reach beyond their sources";
  }
}

// A matrix that cannot be written says how much it needs and what to do instead.
TEST(Tool_matrix, a_matrix_too_large_is_refused_before_it_is_solved)
{
  const std::size_t mb = 1000000;
  const std::string mtx = tool_error_of([&] { tool::check_matrix_fits(tool::Matrix_format::mtx, 1000, 1000, false, mb, 0); });
  EXPECT_NE(mtx.find("holds up to 0.024 GB in memory, more than the 0.001 GB available"), std::string::npos) << mtx;
  EXPECT_NE(mtx.find("give --max-distance"), std::string::npos) << mtx;
  EXPECT_NO_THROW(tool::check_matrix_fits(tool::Matrix_format::mtx, 1000, 1000, true, mb, 0)) << "a local matrix";
  EXPECT_NO_THROW(tool::check_matrix_fits(tool::Matrix_format::mtx, 1000, 1000, false, 0, 0)) << "memory unknown";
  const std::string npy = tool_error_of([&] { tool::check_matrix_fits(tool::Matrix_format::npy, 1000, 1000, false, 0, mb); });
  EXPECT_NE(npy.find("needs about 0.008 GB on disk, more than the 0.001 GB free"), std::string::npos) << npy;
  EXPECT_NE(npy.find("write .mtx"), std::string::npos) << npy;
  EXPECT_NO_THROW(tool::check_matrix_fits(tool::Matrix_format::npy, 1000, 1000, false, 0, 100 * mb));
  EXPECT_GT(tool::available_memory_bytes(), 0u) << "/proc/meminfo is read";
}

TEST_F(Tool, matrix_bad_input_writes_no_file)
{
  const std::string mesh = "matrix '" + elephant + "'";
  const std::vector<std::pair<std::string, std::string>> cases = {
    {mesh + " --source 0 --output m.vtk", "unknown output format '.vtk' for a matrix"},
    {mesh + " --output m.npy", "give the sources with --source, or --all"},
    {mesh + " --source 0 --target f:1:0.2:0.3:0.5 --output m.npy", "the columns of a matrix are vertices"},
    {mesh + " --source f:1:0.2:0.3:0.5 --target sources --output m.npy", "is a face point"},
    {mesh + " --source 0 --target 99999 --output m.npy", "out of range"},
    {mesh + " --source 99999 --output m.npy", "out of range"},
    {mesh + " --source 0 --max-distance -1 --output m.npy", "--max-distance must be non-negative"},
  };
  for(const auto& [args, message] : cases) {
    const Result r = run(args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << "expected '" << message << "' in: " << r.err;
    EXPECT_FALSE(fs::exists(path("m.npy")) || fs::exists(path("m.vtk"))) << args;
  }
}

} // namespace tool_test::matrix
