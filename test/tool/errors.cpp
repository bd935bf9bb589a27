// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: bad input. One line `error: ...` on stderr, a non-zero exit code,
// and no output file, nor a temporary one; an existing output file is left as it was.

#include "tool_test_support.h"

#include <cstdint>

namespace tool_test::errors {

// ---------------------------------------------------------------------------------------------
// Bad input: one line `error: ...` on stderr, a non-zero exit code, and no output file.

struct Bad_case
{
  const char* name;
  std::string args;   // the output option is appended
  const char* output; // the output file, which must not appear
  const char* message; // a piece of the expected error message
};

void PrintTo(const Bad_case& c, std::ostream* os) { *os << c.name; }

std::string binary_ply_with_nan()
{
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
                    "property double y\nproperty double z\nelement face 1\n"
                    "property list uchar int vertex_indices\nend_header\n";
  const double xyz[9] = {0, 0, 0, 1, 0, 0, 0, std::nan(""), 0};
  ply.append(reinterpret_cast<const char*>(xyz), sizeof(xyz));
  const unsigned char n = 3;
  const std::int32_t ids[3] = {0, 1, 2};
  ply.append(reinterpret_cast<const char*>(&n), 1);
  ply.append(reinterpret_cast<const char*>(ids), sizeof(ids));
  return ply;
}

const std::string triangle_points = "0 0 0\n1 0 0\n0 1 0\n";

const std::vector<std::pair<std::string, std::string>> bad_files = {
  {"tri.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
  {"far.txt", "0\n99999\n"},
  {"apart.txt", "# two vertices far apart\n0\n1500\n"},
  {"quad.off", "OFF\n4 1 0\n" + triangle_points + "1 1 0\n4 0 1 3 2\n"},
  {"nan.ply", binary_ply_with_nan()},
  {"nan.off", "OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n"},
  {"empty.off", ""},
  {"no_faces.off", "OFF\n3 0 0\n" + triangle_points},
  {"flat.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n"},
  {"flat_quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n4 0 1 2 3\n"},
  // point 3 is point 0 again: the only triangle has 2 distinct points
  {"segment.off", "OFF\n4 1 0\n" + triangle_points + "0 0 0\n3 0 1 3\n"},
  {"with_segment.off", "OFF\n4 2 0\n" + triangle_points + "0 0 0\n3 0 1 3\n3 0 1 2\n"},
  {"out_of_range.off", "OFF\n3 1 0\n" + triangle_points + "3 0 1 7\n"},
  {"empty.stl", "solid x\nendsolid x\n"},
  {"mesh.vtk", "# vtk DataFile Version 2.0\n"},
  {"triangle.off", "OFF\n3 1 0\n" + triangle_points + "3 0 1 2\n"},
  // point 3 in no face
  {"isolated.off", "OFF\n4 1 0\n" + triangle_points + "5 5 5\n3 0 1 2\n"},
  // two triangles that share nothing: two connected components
  {"two.off", "OFF\n6 2 0\n" + triangle_points + "10 0 0\n11 0 0\n10 1 0\n3 0 1 2\n3 3 4 5\n"},
  // a unit square and point 4 = point 2, joined by a zero-length edge: 5 vertices, 4 distinct points
  {"needle.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n1 1 0\n3 0 1 2\n3 0 2 3\n3 1 4 2\n"},
  // a soup of two triangles: points 3 and 4 repeat points 0 and 2, and are merged with them
  {"soup.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 3 4 5\n"},
};

const std::string E = "distances '" + elephant + "'";
const std::string P = "path '" + elephant + "'";
const std::string S = "sample '" + elephant + "'";
const std::string V = "voronoi '" + elephant + "'";

const Bad_case bad_cases[] = {
  {"face_point_on_a_quad", "distances quad.off --source f:0:0.2:0.3:0.5", "d.txt",
   "error: source 'f:0:0.2:0.3:0.5': face 0 of the file is not a triangle of the surface (it has 4 vertices)"},
  {"nan_coordinate", "distances nan.ply --source 0", "d.ply", "error: point 2 has a non-finite coordinate (0, nan, 0)"},
  {"nan_text", "distances nan.off --source 0", "d.txt", "cannot read mesh 'nan.off'"},
  {"empty_file", "distances empty.off --source 0", "d.txt", "empty.off"},
  {"point_cloud", "distances no_faces.off --source 0", "d.txt",
   "error: no faces: the soup has 3 points and no polygon (a point cloud)"},
  {"empty_stl", "distances empty.stl --source 0", "d.txt", "error: no faces: the soup is empty"},
  {"nothing_left", "distances segment.off --source 0", "d.ply",
   "error: no faces left: the only polygon has fewer than 3 distinct points"},
  {"index_out_of_range", "distances out_of_range.off --source 0", "d.txt", "cannot read mesh 'out_of_range.off'"},
  {"degenerate_triangle", "distances flat.off --source 0", "d.txt", "degenerate"},
  {"flat_quad", "distances flat_quad.off --source 0", "d.txt",
   "error: polygon 0 (4 points) cannot be triangulated without new points"},
  {"isolated_source", "distances isolated.off --source 3", "d.txt",
   "error: source '3': vertex 3 is in no face of the mesh, so it reaches no other vertex"},
  {"isolated_sources", "distances isolated.off --source 3,3", "d.ply", "error: every source is a vertex in no face"},
  {"isolated_source_with_a_face_point", "distances isolated.off --source 3,f:0:1:0:0", "d.txt",
   "source '3': an isolated vertex cannot be mixed with face-point sources"},
  {"missing_file", "distances missing.off --source 0", "d.txt", "cannot read mesh 'missing.off'"},
  {"unknown_mesh_format", "distances mesh.vtk --source 0", "d.txt", "cannot read mesh 'mesh.vtk'"},
  {"unknown_output_format", "distances triangle.off --source 0", "d.vtk", "unknown output format"},
  {"vertex_out_of_range", E + " --source 0,2775", "d.txt", "source '2775'"},
  {"face_out_of_range", E + " --source f:5558:0.2:0.3:0.5", "d.ply", "source 'f:5558:0.2:0.3:0.5'"},
  {"negative_vertex", E + " --source=-1", "d.txt", "source '-1'"},
  {"malformed_vertex", E + " --source 12x", "d.txt", "source '12x'"},
  {"face_point_too_short", E + " --source f:1:0.5:0.5", "d.txt", "source 'f:1:0.5:0.5'"},
  {"face_point_not_a_number", E + " --source f:1:0.5:x:0.5", "d.txt", "source 'f:1:0.5:x:0.5'"},
  {"face_point_nan", E + " --source f:1:nan:0.5:0.5", "d.txt", "source 'f:1:nan:0.5:0.5'"},
  {"face_point_negative", E + " --source f:1:1.5:-0.5:0", "d.txt", "source 'f:1:1.5:-0.5:0'"},
  {"face_point_bad_sum", E + " --source f:1:0.5:0.5:0.5", "d.txt", "source 'f:1:0.5:0.5:0.5'"},
  {"negative_max_distance", E + " --source 0 --max-distance=-1", "d.txt", "max-distance"},
  {"non_numeric_max_distance", E + " --source 0 --max-distance far", "d.txt", "max-distance"},
  {"unknown_option", E + " --source 0 --colour", "d.txt", "--colour"},
  {"unknown_subcommand", "distance '" + elephant + "' --source 0", "d.txt", "distance"},
  {"no_subcommand", "", "d.txt", "not expected"},
  {"missing_source", E, "d.txt", "--source"},
  {"missing_mesh", "distances --source 0", "d.txt", "MESH"},
  {"unknown_algorithm", E + " --source 0 --algorithm dijkstra", "d.txt", "unknown algorithm 'dijkstra'"},
  {"lambda_zero", E + " --source 0 --algorithm avtp --lambda 0", "d.txt", "--lambda must be a positive"},
  {"lambda_negative", E + " --source 0 --algorithm pavtp --lambda -1", "d.txt", "got -1"},
  {"lambda_nan", E + " --source 0 --algorithm avtp --lambda nan", "d.txt", "got nan"},
  {"lambda_infinite", E + " --source 0 --algorithm avtp --lambda inf", "d.ply", "got inf"},
  {"lambda_not_a_number", E + " --source 0 --algorithm avtp --lambda coarse", "d.txt", "--lambda"},
  {"lambda_with_vtp", E + " --source 0 --lambda 8 --algorithm vtp", "d.txt", "error: --lambda applies to avtp and pavtp only"},
  {"lambda_with_pvtp", E + " --source 0 --algorithm pvtp --lambda 8", "d.txt", "--lambda applies to"},
  {"threads_zero", E + " --source 0 --algorithm pvtp --threads 0", "d.txt", "--threads must be a positive integer"},
  {"threads_huge", E + " --source 0 --algorithm pvtp --threads 100000", "d.txt", "--threads must be at most 1024"},
  {"threads_negative", E + " --source 0 --algorithm pavtp --threads -2", "d.txt", "got -2"},
  {"threads_not_a_number", E + " --source 0 --algorithm pvtp --threads x", "d.txt", "--threads"},
  {"threads_fraction", E + " --source 0 --algorithm pvtp --threads 1.5", "d.txt", "--threads"},
  {"threads_with_vtp", E + " --source 0 --threads 2 --algorithm vtp", "d.txt", "error: --threads applies to pvtp, pavtp and pmmp only"},
  {"threads_with_avtp", E + " --source 0 --algorithm avtp --threads 2", "d.ply", "--threads applies to"},
  {"batch_size_zero", E + " --source 0 --algorithm pvtp --batch-size 0", "d.txt", "--batch-size must be a positive integer"},
  {"batch_size_negative", E + " --source 0 --algorithm pvtp --batch-size=-5", "d.txt", "got -5"},
  {"batch_size_with_vtp", E + " --source 0 --batch-size 8 --algorithm vtp", "d.txt", "--batch-size applies to pvtp, avtp, pavtp and pmmp only"},
  {"lambda_with_mmp", E + " --source 0 --algorithm mmp --lambda 8", "d.txt", "error: --lambda applies to avtp and pavtp only"},
  {"lambda_with_fwp_mmp", E + " --source 0 --algorithm fwp-mmp --lambda 8", "d.txt", "--lambda applies to"},
  {"lambda_with_pmmp", E + " --source 0 --algorithm pmmp --lambda 8", "d.ply", "--lambda applies to"},
  {"threads_with_mmp", E + " --source 0 --algorithm mmp --threads 2", "d.txt", "--threads applies to"},
  {"threads_with_fwp_mmp", E + " --source 0 --algorithm fwp-mmp --threads 2", "d.txt", "--threads applies to"},
  {"pmmp_threads_zero", E + " --source 0 --algorithm pmmp --threads 0", "d.txt", "--threads must be a positive integer"},
  {"batch_size_with_mmp", E + " --source 0 --algorithm mmp --batch-size 8", "d.txt", "--batch-size applies to"},
  {"batch_size_with_fwp_mmp", E + " --source 0 --algorithm fwp-mmp --batch-size 8", "d.txt", "--batch-size applies to"},
  {"pmmp_batch_size_zero", E + " --source 0 --algorithm pmmp --batch-size 0", "d.txt", "--batch-size must be a positive integer"},
  {"unknown_algorithm_lists_mmp", E + " --source 0 --algorithm MMP", "d.txt", "(use vtp, pvtp, avtp, pavtp, fwp-mmp, mmp or pmmp)"},
  {"obj_distances", "distances triangle.off --source 0", "d.obj", "unknown output format 'd.obj' (use .txt or .ply)"},
  // geodesic path
  {"path_unreachable_vertex", "path two.off --source 0 --target 4", "p.txt", "error: target '4' is not reached by any source"},
  {"path_unreachable_face_point", "path two.off --source f:0:0.2:0.3:0.5,1 --target f:1:0.2:0.3:0.5", "p.obj",
   "target 'f:1:0.2:0.3:0.5' is not reached by any source"},
  {"path_unreachable_with_pmmp", "path two.off --source 3 --target 2 --algorithm pmmp --threads 2", "p.ply", "is not reached"},
  {"path_beyond_max_distance", P + " --source 0 --target 1500 --max-distance 0.1", "p.txt", "beyond --max-distance"},
  {"path_target_out_of_range", P + " --source 0 --target 2775", "p.txt", "target '2775': vertex 2775 is out of range"},
  {"path_target_face_out_of_range", P + " --source 0 --target f:5558:0.2:0.3:0.5", "p.ply", "target 'f:5558:0.2:0.3:0.5'"},
  {"path_target_bad_sum", P + " --source 0 --target f:1:0.5:0.5:0.5", "p.txt", "target 'f:1:0.5:0.5:0.5': barycentric coordinates sum to"},
  {"path_target_negative", P + " --source 0 --target f:1:1.5:-0.5:0", "p.obj", "target 'f:1:1.5:-0.5:0'"},
  {"path_target_nan", P + " --source 0 --target f:1:nan:0.5:0.5", "p.txt", "target 'f:1:nan:0.5:0.5'"},
  {"path_target_too_short", P + " --source 0 --target f:1:0.5:0.5", "p.txt", "target 'f:1:0.5:0.5'"},
  {"path_target_malformed", P + " --source 0 --target 12x", "p.txt", "target '12x'"},
  {"path_target_negative_vertex", P + " --source 0 --target=-1", "p.txt", "target '-1'"},
  {"path_missing_target", P + " --source 0", "p.txt", "--target"},
  {"path_two_targets", P + " --source 0 --target 1 --target 2", "p.txt", "--target"},
  {"path_missing_source", P + " --target 5", "p.txt", "--source"},
  {"path_source_out_of_range", P + " --source 0,2775 --target 5", "p.txt", "source '2775'"},
  {"path_source_bad_barycentric", P + " --source f:1:0.5:0.5:0.5 --target 5", "p.txt", "source 'f:1:0.5:0.5:0.5'"},
  {"path_missing_mesh", "path --source 0 --target 5", "p.txt", "MESH"},
  {"path_with_avtp", P + " --source 0 --target 5 --algorithm avtp", "p.txt", "--algorithm avtp is approximate"},
  {"path_with_pavtp", P + " --source 0 --target 5 --algorithm pavtp", "p.txt",
   "paths and Voronoi diagrams are exact (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {"path_unknown_algorithm", P + " --source 0 --target 5 --algorithm dijkstra", "p.txt",
   "unknown algorithm 'dijkstra' (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {"path_lambda", P + " --source 0 --target 5 --lambda 8", "p.txt", "--lambda"},
  {"path_lambda_with_mmp", P + " --source 0 --target 5 --algorithm mmp --lambda 8", "p.txt", "--lambda"},
  {"path_threads_with_fwp_mmp", P + " --source 0 --target 5 --algorithm fwp-mmp --threads 2", "p.txt", "error: --threads applies to pvtp and pmmp only"},
  {"path_threads_zero", P + " --source 0 --target 5 --algorithm pmmp --threads 0", "p.txt", "--threads must be a positive integer"},
  {"path_batch_size_with_mmp", P + " --source 0 --target 5 --algorithm mmp --batch-size 8", "p.txt",
   "error: --batch-size applies to pvtp and pmmp only"},
  {"path_batch_size_zero", P + " --source 0 --target 5 --algorithm pmmp --batch-size 0", "p.txt", "--batch-size must be"},
  {"path_negative_max_distance", P + " --source 0 --target 5 --max-distance=-1", "p.txt", "max-distance"},
  {"path_unknown_output_format", P + " --source 0 --target 5", "p.vtk", "unknown output format 'p.vtk' (use .txt, .obj or .ply)"},
  {"path_face_point_on_a_quad", "path quad.off --source 0 --target f:0:1:0:0", "p.txt",
   "error: target 'f:0:1:0:0': face 0 of the file is not a triangle of the surface (it has 4 vertices)"},
  {"path_source_on_a_quad", "path quad.off --source f:0:1:0:0 --target 2", "p.obj", "source 'f:0:1:0:0': face 0"},
  {"path_isolated_target", "path isolated.off --source 0 --target 3", "p.txt", "target '3' is not reached"},
  {"path_point_cloud", "path no_faces.off --source 0 --target 1", "p.txt", "a point cloud"},
  {"path_nan_coordinate", "path nan.ply --source 0 --target 1", "p.ply", "point 2 has a non-finite coordinate"},
  {"path_degenerate_triangle", "path flat.off --source 0 --target 1", "p.txt", "degenerate"},
  {"path_missing_file", "path missing.off --source 0 --target 1", "p.txt", "cannot read mesh 'missing.off'"},
  {"labels_obj", E + " --source 0 --labels l.obj", "d.txt", "unknown output format 'l.obj'"},
  {"labels_same_file", E + " --source 0 --labels d.txt", "d.txt", "--output and --labels name the same file 'd.txt'"},
  {"sample_no_count", S, "s.txt", "give --count, --radius, or both"},
  {"sample_count_zero", S + " --count 0", "s.txt", "--count must be at least 1, got 0"},
  {"sample_count_above_vertices", S + " --count 2776", "s.txt", "--count 2776 is more than the 2775 vertices"},
  {"sample_radius_zero", S + " --radius 0", "s.txt", "--radius must be positive, got 0"},
  {"sample_first_out_of_range", S + " --count 3 --first 2775", "s.txt", "first sample '2775'"},
  {"sample_first_face_point", S + " --count 3 --first f:1:0.2:0.3:0.5", "s.txt", "give a vertex id"},
  {"sample_first_twice", S + " --count 3 --first 4,9,4", "s.txt", "first sample '4' is given twice"},
  {"sample_first_more_than_count", S + " --count 2 --first 4,9,5", "s.txt", "--first gives 3 samples, more than --count 2"},
  {"sample_initial_out_of_range", S + " --count 3 --first 4,2775", "s.txt", "first sample '2775'"},
  {"sample_initial_one_point", "sample needle.off --count 3 --first 2,4", "s.txt", "2 and 4"},
  {"sample_initial_merged_points", "sample soup.off --count 3 --first 0,3", "s.txt",
   "first samples '0' and '3' are one vertex of the mesh"},
  {"sample_with_mmp", S + " --count 3 --algorithm fwp-mmp", "s.txt", "sampling runs vtp, pvtp, avtp or pavtp"},
  {"sample_ply_output", S + " --count 3", "s.ply", "the samples are written as .txt"},
  {"sample_labels_same_file", S + " --count 3 --labels s.txt", "s.txt", "name the same file 's.txt'"},
  {"sample_more_than_distinct", "sample needle.off --count 5", "s.txt", "after 4 every vertex is a sample or at distance 0"},
  {"sample_point_cloud", "sample no_faces.off --count 1", "s.txt", "a point cloud"},
  {"voronoi_cells_obj", V + " --source 0,100", "c.obj", "unknown output format 'c.obj'"},
  {"voronoi_bisectors_ply", V + " --source 0,100 --bisectors b.ply", "c.txt", "--bisectors 'b.ply': use .obj or .txt"},
  {"voronoi_dual_txt", V + " --source 0,100 --dual d.txt", "c.txt", "the dual graph is written as .obj"},
  {"voronoi_with_avtp", V + " --source 0,100 --algorithm avtp", "c.txt",
   "--algorithm avtp is approximate: paths and Voronoi diagrams are exact (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {"voronoi_same_files", V + " --source 0,100 --bisectors c.txt", "c.txt", "name the same file 'c.txt'"},
  {"voronoi_source_out_of_range", V + " --source 0,2775", "c.txt", "source '2775'"},
  {"voronoi_missing_source", V, "c.txt", "--source"},
  {"patterns_no_patch", "patterns '" + elephant + "'", "p.json", "mark the pattern"},
  {"patterns_radius_zero", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0", "p.json",
   "--patch-radius must be positive"},
  {"patterns_center_out_of_range", "patterns '" + elephant + "' --patch-center 2775 --patch-radius 0.1", "p.json",
   "patch centre '2775'"},
  {"patterns_empty_scales", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1 --scales 2:1", "p.json",
   "empty scale range"},
  {"patterns_bad_scales", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1 --scales 2", "p.json",
   "expected A:B"},
  {"patterns_txt_output", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1", "p.txt",
   "the instances are written as .json"},
  {"patterns_missing_list", "patterns '" + elephant + "' --patch-vertices missing.txt", "p.json",
   "cannot read --patch-vertices 'missing.txt'"},
  {"patterns_list_out_of_range", "patterns '" + elephant + "' --patch-vertices far.txt", "p.json",
   "far.txt line 2: vertex 99999 is out of range"},
  {"patterns_list_not_connected", "patterns '" + elephant + "' --patch-vertices apart.txt", "p.json",
   "not connected"},
  {"patterns_stroke_out_of_range", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1 --scales 1:2 --stroke 0,9999",
   "p.json", "--stroke vertex 9999 is out of range"},
  {"patterns_stroke_outside_the_patch", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.05 --scales 1:2 --stroke 2000,1000",
   "p.json", "the stroke must start in the marked instance"},
  {"patterns_property_of_an_off", "patterns '" + elephant + "' --patch-property selected", "p.json",
   "--patch-property reads a per-vertex property of a .ply mesh"},
  {"patterns_property_missing", "patterns tri.ply --patch-property selected", "p.json",
   "'tri.ply' has no per-vertex property 'selected'"},
  {"patterns_radius_beyond_the_mesh", "patterns '" + elephant + "' --patch-center 0 --patch-radius 100", "p.json",
   "larger than the mesh"},
  {"patterns_negative_lambda", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1 --lambda -1", "p.json",
   "approximation must be 0 (exact) or positive"},
};

class Bad_input : public Tool, public ::testing::WithParamInterface<Bad_case>
{
protected:
  void SetUp() override
  {
    Tool::SetUp();
    for(const auto& [name, content] : bad_files)
      write(name, content);
  }

  void expect_error(const Result& r) const
  {
    const Bad_case& c = GetParam();
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << "expected '" << c.message << "' in: " << r.err;
    EXPECT_EQ(r.out, "");
  }
};

TEST_P(Bad_input, fails_cleanly)
{
  const Bad_case& c = GetParam();
  const std::set<std::string> before = files();
  const std::string args = c.args + " --output " + c.output;
  expect_error(run(args));
  EXPECT_EQ(files(), before) << "the output file or a temporary file was left behind";

  // an existing output file is not touched
  write(c.output, "previous content\n");
  expect_error(run(args));
  EXPECT_EQ(read_text(path(c.output)), "previous content\n");
  std::set<std::string> with_output = before;
  with_output.insert(c.output);
  EXPECT_EQ(files(), with_output);
}

INSTANTIATE_TEST_SUITE_P(Tool, Bad_input, ::testing::ValuesIn(bad_cases),
                         [](const ::testing::TestParamInfo<Bad_case>& info) { return info.param.name; });

// The control case of the table above: the same small files do work when they are good.
TEST_F(Tool, a_good_triangle_works)
{
  write("triangle.off", "OFF\n3 1 0\n" + triangle_points + "3 0 1 2\n");
  const std::vector<double> d = distances("distances triangle.off --source f:0:0:0.5:0.5");
  ASSERT_EQ(d.size(), 3u);
  EXPECT_NEAR(d[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(d[1], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(d[2], std::sqrt(0.5), 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Failed writes

// An error while writing (here the target is a folder) leaves no temporary file behind.
TEST_F(Tool, failed_write_leaves_no_file)
{
  expect_failed_write("distances '" + elephant + "' --source 0 --output d.txt", "d.txt");
}

TEST_F(Tool, path_failed_write_leaves_no_file)
{
  expect_failed_write("path '" + elephant + "' --source 0 --target 5 --output p.obj", "p.obj");
}

} // namespace tool_test::errors
