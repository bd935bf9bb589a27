// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: its command line. The checking of surface points, of the solver
// options, of output formats and of the patterns' scale ranges and vertex lists, called without
// running the tool; the subcommands parsed as main() declares them; the tool run without a
// subcommand and with --help.

#include "tool_test_support.h"

#include "tool_options.h"
#include "tool_patterns.h"
#include "tool_text.h"

#include <CGAL_ext/Geodesics_3/Tolerances.h>

#include <CLI/CLI.hpp>

#include <optional>

namespace tool_test::options {

TEST(Tool_options, surface_points_are_vertices_or_face_points)
{
  const tool::Surface_point v = tool::parse_surface_point("2774");
  ASSERT_TRUE(v.vertex);
  EXPECT_EQ(*v.vertex, 2774u);
  EXPECT_EQ(v.text, "2774");
  const tool::Surface_point f = tool::parse_surface_point("f:12:0.2:0.3:0.5", "target");
  EXPECT_FALSE(f.vertex);
  EXPECT_EQ(f.face, 12u);
  EXPECT_EQ(f.barycentric, (std::array<double, 3>{{0.2, 0.3, 0.5}}));
  EXPECT_EQ(f.text, "f:12:0.2:0.3:0.5");

  // several sources, in command-line order; a corner is a face point too
  const std::vector<tool::Surface_point> sources = tool::parse_sources({"7", "f:3:0:1:0", "0"});
  ASSERT_EQ(sources.size(), 3u);
  EXPECT_EQ(sources[0].vertex, std::optional<std::size_t>(7));
  EXPECT_EQ(sources[1].vertex, std::nullopt);
  EXPECT_EQ(sources[1].face, 3u);
  EXPECT_EQ(sources[1].barycentric, (std::array<double, 3>{{0., 1., 0.}}));
  EXPECT_EQ(sources[2].vertex, std::optional<std::size_t>(0));
}

// The tool refuses the face points the library would refuse, and no others.
TEST(Tool_options, barycentric_coordinates_sum_to_1_within_the_library_tolerance)
{
  const double tolerance = CGAL_ext::Geodesics_3::barycentric_sum_tolerance;
  const auto last_coordinate = [](double last) { return "f:0:0.25:0.25:" + tool::number_text(last); };
  for(const double off : {0.5 * tolerance, -0.5 * tolerance}) {
    const std::string text = last_coordinate(0.5 + off);
    EXPECT_EQ(tool_error_of([&] { tool::parse_surface_point(text); }), "") << text;
  }
  for(const double off : {2 * tolerance, -2 * tolerance}) {
    const std::string text = last_coordinate(0.5 + off);
    const std::string error = tool_error_of([&] { tool::parse_surface_point(text); });
    EXPECT_EQ(error.rfind("source '" + text + "': barycentric coordinates sum to " +
                            (off > 0 ? "1.000000002" : "0.999999998"),
                          0),
              0u)
      << error;
    const std::string end = ", not 1";
    EXPECT_TRUE(error.size() > end.size() && error.compare(error.size() - end.size(), end.size(), end) == 0)
      << error;
  }
}

struct Bad_point
{
  const char* text;
  const char* role;
  const char* message; // the whole error message
};

const Bad_point bad_points[] = {
  {"12x", "source", "source '12x': expected a vertex id or f:FACE:b0:b1:b2"},
  {"-1", "target", "target '-1': expected a vertex id or f:FACE:b0:b1:b2"},
  {"", "source", "source '': expected a vertex id or f:FACE:b0:b1:b2"},
  {"1.5", "source", "source '1.5': expected a vertex id or f:FACE:b0:b1:b2"},
  {"f:1:0.5:0.5", "source", "source 'f:1:0.5:0.5': expected f:FACE:b0:b1:b2"},
  {"f:1:0.2:0.3:0.5:", "target", "target 'f:1:0.2:0.3:0.5:': expected f:FACE:b0:b1:b2"},
  {"f:x:0.2:0.3:0.5", "source", "source 'f:x:0.2:0.3:0.5': expected f:FACE:b0:b1:b2"},
  {"f:-1:0.2:0.3:0.5", "source", "source 'f:-1:0.2:0.3:0.5': expected f:FACE:b0:b1:b2"},
  {"f:1:0.5:x:0.5", "source", "source 'f:1:0.5:x:0.5': barycentric coordinate 'x' is not a number"},
  {"f:1::0.5:0.5", "target", "target 'f:1::0.5:0.5': barycentric coordinate '' is not a number"},
  {"f:1:nan:0.5:0.5", "target", "target 'f:1:nan:0.5:0.5': barycentric coordinate 'nan' is not a number"},
  {"f:1:inf:0:0", "source", "source 'f:1:inf:0:0': barycentric coordinate 'inf' is not a number"},
  {"f:1:1.5:-0.5:0", "source", "source 'f:1:1.5:-0.5:0': barycentric coordinates must be non-negative"},
  {"f:1:0.5:0.5:0.5", "target", "target 'f:1:0.5:0.5:0.5': barycentric coordinates sum to 1.5, not 1"},
  {"f:1:0:0:0", "source", "source 'f:1:0:0:0': barycentric coordinates sum to 0, not 1"},
};

TEST(Tool_options, bad_surface_points_are_named)
{
  for(const Bad_point& c : bad_points)
    EXPECT_EQ(tool_error_of([&] { tool::parse_surface_point(c.text, c.role); }), c.message);
  EXPECT_EQ(tool_error_of([] { tool::parse_sources({"0", "f:1:0.5:0.5:0.5", "12x"}); }),
            "source 'f:1:0.5:0.5:0.5': barycentric coordinates sum to 1.5, not 1")
    << "the first bad source is named";
}

TEST(Tool_options, points_out_of_the_mesh_are_named)
{
  // the elephant's counts
  const auto error = [](const std::string& text, const char* role) {
    return tool_error_of(
      [&] { tool::check_surface_point_range(tool::parse_surface_point(text, role), 2775, 5558, role); });
  };
  EXPECT_EQ(error("2774", "source"), "");
  EXPECT_EQ(error("f:5557:1:0:0", "target"), "");
  EXPECT_EQ(error("2775", "source"), "source '2775': vertex 2775 is out of range (the mesh has 2775 vertices)");
  EXPECT_EQ(error("f:5558:0.2:0.3:0.5", "target"),
            "target 'f:5558:0.2:0.3:0.5': face 5558 is out of range (the mesh has 5558 faces)");
}

TEST(Tool_options, solver_defaults)
{
  const tool::Solver_choice distances = tool::solver_choice(tool::Distances_options().solver, false);
  // the exact parallel solver (this build has TBB): the same distances on any number of threads
  EXPECT_STREQ(distances.algorithm->name, tool::default_vertex_solver);
  EXPECT_STREQ(tool::default_vertex_solver, "pvtp");
  EXPECT_EQ(distances.lambda, tool::default_lambda);
  EXPECT_EQ(distances.threads, 0);
  EXPECT_EQ(distances.batch_size, CGAL_ext::default_batch_size);
  EXPECT_EQ(distances.max_distance, infinity);

  const tool::Solver_choice path = tool::solver_choice(tool::Path_options().solver, true);
  EXPECT_STREQ(path.algorithm->name, "pvtp");
  EXPECT_EQ(path.batch_size, CGAL_ext::default_batch_size);

  // the batch of PMMP is windows, that of the other batched solvers window lists
  tool::Solver_options pmmp;
  pmmp.algorithm = "pmmp";
  EXPECT_EQ(tool::solver_choice(pmmp, false).batch_size, CGAL_ext::default_window_batch_size);
  tool::Solver_options pvtp;
  pvtp.algorithm = "pvtp";
  EXPECT_EQ(tool::solver_choice(pvtp, false).batch_size, CGAL_ext::default_batch_size);
}

TEST(Tool_options, solver_options_are_taken_as_given)
{
  tool::Solver_options options;
  options.algorithm = "pavtp";
  options.lambda = 0.5;
  options.threads = 3;
  options.batch_size = 16;
  options.max_distance = 0;
  const tool::Solver_choice choice = tool::solver_choice(options, false);
  EXPECT_STREQ(choice.algorithm->name, "pavtp");
  EXPECT_TRUE(choice.algorithm->parallel);
  EXPECT_TRUE(choice.algorithm->approximate);
  EXPECT_EQ(choice.algorithm->library, CGAL_ext::VTP);
  EXPECT_EQ(choice.lambda, 0.5);
  EXPECT_EQ(choice.threads, 3);
  EXPECT_EQ(choice.batch_size, 16u);
  EXPECT_EQ(choice.max_distance, 0.);

  options = tool::Solver_options();
  options.algorithm = "pmmp";
  options.threads = 1;
  options.batch_size = 7;
  const tool::Solver_choice path = tool::solver_choice(options, true);
  EXPECT_STREQ(path.algorithm->name, "pmmp");
  EXPECT_EQ(path.algorithm->library, CGAL_ext::FWP_MMP);
  EXPECT_EQ(path.threads, 1);
  EXPECT_EQ(path.batch_size, 7u);
}

struct Bad_solver
{
  bool for_paths;
  tool::Solver_options options; // {algorithm, lambda, threads, batch_size, max_distance}
  const char* message;          // the whole error message
};

const double not_a_number = std::numeric_limits<double>::quiet_NaN();

const Bad_solver bad_solvers[] = {
  {false, {"dijkstra"}, "unknown algorithm 'dijkstra' (use vtp, pvtp, avtp, pavtp, fwp-mmp, mmp or pmmp)"},
  {true, {"dijkstra"}, "unknown algorithm 'dijkstra' (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {false, {"VTP"}, "unknown algorithm 'VTP' (use vtp, pvtp, avtp, pavtp, fwp-mmp, mmp or pmmp)"},
  {true, {"avtp"}, "--algorithm avtp is approximate: paths and Voronoi diagrams are exact (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {true, {"pavtp"}, "--algorithm pavtp is approximate: paths and Voronoi diagrams are exact (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {false, {"vtp", 8.}, "--lambda applies to avtp and pavtp only"},
  {false, {"pmmp", 8.}, "--lambda applies to avtp and pavtp only"},
  {false, {"avtp", 0.}, "--lambda must be a positive, finite number, got 0"},
  {false, {"pavtp", -1.}, "--lambda must be a positive, finite number, got -1"},
  {false, {"avtp", infinity}, "--lambda must be a positive, finite number, got inf"},
  {false, {"avtp", not_a_number}, "--lambda must be a positive, finite number, got nan"},
  {false, {"vtp", {}, 2}, "--threads applies to pvtp, pavtp and pmmp only"},
  {false, {"avtp", {}, 2}, "--threads applies to pvtp, pavtp and pmmp only"},
  {true, {"fwp-mmp", {}, 2}, "--threads applies to pvtp and pmmp only"},
  {false, {"pvtp", {}, 0}, "--threads must be a positive integer, got 0"},
  {true, {"pmmp", {}, -2}, "--threads must be a positive integer, got -2"},
  {false, {"mmp", {}, {}, 8}, "--batch-size applies to pvtp, avtp, pavtp and pmmp only"},
  {true, {"mmp", {}, {}, 8}, "--batch-size applies to pvtp and pmmp only"},
  {false, {"avtp", {}, {}, 0}, "--batch-size must be a positive integer, got 0"},
  {true, {"pmmp", {}, {}, -5}, "--batch-size must be a positive integer, got -5"},
  {false, {"vtp", {}, {}, {}, -1.}, "--max-distance must be a non-negative number, got -1"},
  {true, {"fwp-mmp", {}, {}, {}, not_a_number}, "--max-distance must be a non-negative number, got nan"},
};

TEST(Tool_options, bad_solver_options_are_named)
{
  for(const Bad_solver& c : bad_solvers)
    EXPECT_EQ(tool_error_of([&] { tool::solver_choice(c.options, c.for_paths); }), c.message)
      << (c.for_paths ? "path " : "distances ") << c.options.algorithm;
}

TEST(Tool_options, output_format_by_extension)
{
  EXPECT_EQ(tool::output_format("d.txt"), tool::Output_format::txt);
  EXPECT_EQ(tool::output_format("out/D.PLY"), tool::Output_format::ply);
  EXPECT_EQ(tool::output_format("p.txt", true), tool::Output_format::txt);
  EXPECT_EQ(tool::output_format("p.Obj", true), tool::Output_format::obj);
  EXPECT_EQ(tool::output_format("p.ply", true), tool::Output_format::ply);
  const auto error = [](const std::string& file, bool obj_allowed) {
    return tool_error_of([&] { tool::output_format(file, obj_allowed); });
  };
  EXPECT_EQ(error("d.obj", false), "unknown output format 'd.obj' (use .txt or .ply)");
  EXPECT_EQ(error("distances", false), "unknown output format 'distances' (use .txt or .ply)");
  EXPECT_EQ(error("d.txt.gz", false), "unknown output format 'd.txt.gz' (use .txt or .ply)");
  EXPECT_EQ(error("p.vtk", true), "unknown output format 'p.vtk' (use .txt, .obj or .ply)");
}

/// The subcommands declared as main() declares them, to parse a command line.
struct Command_line
{
  Command_line()
  {
    app.require_subcommand(0, 1);
    tool::add_distances_command(app, distances);
    tool::add_path_command(app, path);
  }

  /// CLI11's error for `arguments` (without the program name); "" if they parse.
  std::string parse(const std::string& arguments)
  {
    try {
      app.parse(arguments, false);
    } catch(const CLI::ParseError& e) {
      return e.what();
    }
    return "";
  }

  CLI::App app{"", "geodesic"};
  tool::Distances_options distances;
  tool::Path_options path;
};

TEST(Tool_command_line, distances_fills_its_options)
{
  Command_line defaults;
  ASSERT_EQ(defaults.parse("distances m.off --source 0"), "");
  const tool::Distances_options& d = defaults.distances;
  EXPECT_EQ(d.mesh, "m.off");
  EXPECT_EQ(d.sources, std::vector<std::string>{"0"});
  EXPECT_EQ(d.solver.algorithm, tool::default_vertex_solver);
  EXPECT_EQ(d.solver.lambda, std::nullopt);
  EXPECT_EQ(d.solver.threads, std::nullopt);
  EXPECT_EQ(d.solver.batch_size, std::nullopt);
  EXPECT_EQ(d.solver.max_distance, infinity);
  EXPECT_EQ(d.output, "");
  EXPECT_FALSE(d.stats);

  Command_line all;
  ASSERT_EQ(all.parse("distances m.off --source 0,f:1:0.2:0.3:0.5 --source 7 --algorithm pavtp --lambda 2 "
                      "--threads 3 --batch-size 16 --max-distance 0.5 --output d.ply --stats"),
            "");
  const tool::Distances_options& o = all.distances;
  EXPECT_EQ(o.sources, (std::vector<std::string>{"0", "f:1:0.2:0.3:0.5", "7"}));
  EXPECT_EQ(o.solver.algorithm, "pavtp");
  EXPECT_EQ(o.solver.lambda, std::optional<double>(2));
  EXPECT_EQ(o.solver.threads, std::optional<int>(3));
  EXPECT_EQ(o.solver.batch_size, std::optional<long long>(16));
  EXPECT_EQ(o.solver.max_distance, 0.5);
  EXPECT_EQ(o.output, "d.ply");
  EXPECT_TRUE(o.stats);
  EXPECT_EQ(all.path.mesh, "") << "the other subcommand's options are left alone";
}

TEST(Tool_command_line, path_fills_its_options)
{
  Command_line defaults;
  ASSERT_EQ(defaults.parse("path m.off --source 0 --target f:2:1:0:0"), "");
  EXPECT_EQ(defaults.path.mesh, "m.off");
  EXPECT_EQ(defaults.path.sources, std::vector<std::string>{"0"});
  EXPECT_EQ(defaults.path.target, "f:2:1:0:0");
  EXPECT_EQ(defaults.path.solver.algorithm, tool::default_vertex_solver);
  EXPECT_EQ(defaults.path.output, "");
  EXPECT_FALSE(defaults.path.stats);

  Command_line all;
  ASSERT_EQ(all.parse("path m.off --source 1,2 --target 5 --algorithm pmmp --threads 2 --batch-size 64 "
                      "--max-distance 3 --output p.obj --stats"),
            "");
  const tool::Path_options& p = all.path;
  EXPECT_EQ(p.sources, (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(p.target, "5");
  EXPECT_EQ(p.solver.algorithm, "pmmp");
  EXPECT_EQ(p.solver.threads, std::optional<int>(2));
  EXPECT_EQ(p.solver.batch_size, std::optional<long long>(64));
  EXPECT_EQ(p.solver.max_distance, 3.);
  EXPECT_EQ(p.output, "p.obj");
  EXPECT_TRUE(p.stats);
}

TEST(Tool_command_line, bad_command_lines_name_the_argument)
{
  const std::pair<const char*, const char*> bad[] = {
    // the command line, and what its error must name
    {"distances m.off --source 0 --threads 1.5", "--threads"},
    {"distances m.off --source 0 --batch-size many", "--batch-size"},
    {"distances m.off --source 0 --max-distance far", "--max-distance"},
    {"distances m.off --source 0 --lambda coarse", "--lambda"},
    {"distances m.off", "--source"},
    {"distances --source 0", "MESH"},
    {"distances m.off --source 0 --colour", "--colour"},
    {"distance m.off --source 0", "distance"},
    {"path m.off --source 0", "--target"},
    {"path m.off --target 1", "--source"},
    {"path m.off --source 0 --target 1 --target 2", "--target"},
    {"path m.off --source 0 --target 1 --lambda 8", "--lambda"},
  };
  for(const auto& [arguments, named] : bad) {
    const std::string error = Command_line().parse(arguments);
    EXPECT_NE(error.find(named), std::string::npos) << arguments << ": '" << error << "'";
  }
}

TEST(Tool_options, scale_ranges_and_vertex_lists)
{
  using geodesic_tool::parse_scale_range;
  using geodesic_tool::read_vertex_list;
  EXPECT_EQ(parse_scale_range("0.5:2"), std::make_pair(0.5, 2.0));
  EXPECT_EQ(parse_scale_range("1:1"), std::make_pair(1.0, 1.0));
  EXPECT_NE(tool_error_of([] { parse_scale_range("0:2"); }).find("positive"), std::string::npos);
  EXPECT_NE(tool_error_of([] { parse_scale_range("a:b"); }).find("expected A:B"), std::string::npos);
  std::istringstream list("# the patch\n3\n\n  7\n");
  EXPECT_EQ(read_vertex_list(list, 10, "l.txt"), (std::vector<std::size_t>{3, 7}));
  std::istringstream junk("3 4\n");
  EXPECT_NE(tool_error_of([&] { read_vertex_list(junk, 10, "l.txt"); }).find("l.txt line 1"), std::string::npos);
  std::istringstream empty("# nothing\n");
  EXPECT_NE(tool_error_of([&] { read_vertex_list(empty, 10, "l.txt"); }).find("no vertex id"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// The tool run without a subcommand, and for its help

TEST_F(Tool, no_arguments)
{
  const Result r = run("");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err, "error: a subcommand is required (see geodesic --help)\n");
}

TEST_F(Tool, help)
{
  for(const std::string& args : {"--help", "distances --help", "path --help"}) {
    const Result r = run(args);
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_NE(r.out.find(args == "path --help" ? "path" : "distances"), std::string::npos) << args;
    EXPECT_NE(r.out.find(args == "--help" ? "SUBCOMMAND" : "--max-distance"), std::string::npos) << r.out;
  }
  const std::string help = run("distances --help").out;
  for(const char* piece : {"--algorithm", "pavtp", "--lambda", "default: 8", "--threads", "--batch-size"})
    EXPECT_NE(help.find(piece), std::string::npos) << piece << " not in:\n" << help;
  const std::string path_help = run("path --help").out;
  for(const char* piece : {"--source", "--target", "--algorithm", "fwp-mmp", "pmmp", "--threads", "--batch-size",
                           "1024", "--max-distance", ".obj", "--stats"})
    EXPECT_NE(path_help.find(piece), std::string::npos) << piece << " not in:\n" << path_help;
  EXPECT_EQ(path_help.find("--lambda"), std::string::npos) << path_help;
  EXPECT_NE(run("--help").out.find("path"), std::string::npos);
}

} // namespace tool_test::options
