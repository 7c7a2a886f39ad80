// End-to-end tests of the `cvtmesh` program: exit codes, one-line errors, JSON reports.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "cvtmesh/io.hpp"
#include "support/shapes.hpp"
#include "support/temp_dir.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

struct CliRun {
  int code;
  std::string out, err;
};

CliRun run_cli(const TempDir& dir, const std::string& args) {
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = std::string(CVTMESH_CLI) + " " + args + " >" + out.string() + " 2>" +
                              err.string() + " </dev/null";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
}

std::string quoted(const std::filesystem::path& p) {
  return "'" + p.string() + "'";
}

TEST(Cli, VersionAndHelp) {
  TempDir dir;
  CliRun r = run_cli(dir, "--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("cvtmesh 0."), std::string::npos) << r.out;
  r = run_cli(dir, "--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("quality"), std::string::npos);
  EXPECT_NE(r.out.find("repair"), std::string::npos);
  r = run_cli(dir, "quality --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--ref"), std::string::npos);
  EXPECT_NE(run_cli(dir, "repair --help").out.find("OUT"), std::string::npos);
}

TEST(Cli, UsageErrorsExitWithTwo) {
  TempDir dir;
  EXPECT_EQ(run_cli(dir, "").code, 2);
  EXPECT_EQ(run_cli(dir, "frobnicate").code, 2);
  EXPECT_EQ(run_cli(dir, "quality").code, 2);
  EXPECT_EQ(run_cli(dir, "quality x.off --threads -1").code, 2);
}

const char* kRequiredKeys[] = {"vertices",
                               "faces",
                               "components",
                               "boundary_loops",
                               "nonmanifold_edges",
                               "euler_characteristic",
                               "q_min",
                               "q_avg",
                               "angle_min_deg",
                               "angle_min_avg_deg",
                               "angle_max_deg",
                               "pct_angle_below_30",
                               "edge_length_mean",
                               "edge_length_std"};

TEST(Cli, QualityJsonHasEveryKeyWithTheMeshValues) {
  TempDir dir;
  write_mesh(dir / "torus.off", torus(2, 0.5, 24, 12));
  const CliRun r = run_cli(dir, "quality --json " + quoted(dir / "torus.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : kRequiredKeys) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["vertices"], 288);
  EXPECT_EQ(j["faces"], 576);
  EXPECT_EQ(j["euler_characteristic"], 0);
  EXPECT_EQ(j["genus"], 1);
  EXPECT_FALSE(j.contains("hausdorff_max_pct"));
}

// Against a reference with a narrow angle between features (a flat kite whose boundary meets at
// 20° at its tip, the tip split in two triangles of 10° there), the report states θmin away from
// it and, at it, the smallest angle against the input angle (issue 18 item 6).
TEST(Cli, QualityWithReferenceStatesTheQualityAwayFromNarrowAngles) {
  TempDir dir;
  const double s = std::sin(10 * M_PI / 180), c = std::cos(10 * M_PI / 180);
  TriangleMesh kite;
  kite.vertices = {{0, 0, 0}, {c, -s, 0}, {1, 0, 0}, {c, s, 0}, {1.2, 0, 0}};
  kite.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}, {2, 4, 3}};
  write_mesh(dir / "kite.off", kite);
  const CliRun r = run_cli(
      dir, "quality --json " + quoted(dir / "kite.off") + " --ref " + quoted(dir / "kite.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["narrow_input_angles"], 1);
  EXPECT_EQ(j["triangles_at_narrow_angles"], 2);
  EXPECT_NEAR(j["narrow_angle_ratio_min"].get<double>(), 0.5, 1e-9);
  EXPECT_GT(j["angle_min_away_deg"].get<double>(), 10);
  EXPECT_LT(j["angle_min_deg"].get<double>(), 10.0 + 1e-9);
  EXPECT_GT(j["q_min_away"].get<double>(), j["q_min"].get<double>());
}

TEST(Cli, QualityWithReferenceAddsHausdorffAndTopology) {
  TempDir dir;
  write_mesh(dir / "unit.ply", icosphere(3));
  write_mesh(dir / "big.obj", transformed(icosphere(3), 1.01));
  write_mesh(dir / "torus.stl", torus(1, 0.3, 24, 12));
  CliRun r = run_cli(dir, "quality --json --samples 20000 " + quoted(dir / "big.obj") + " --ref " +
                              quoted(dir / "unit.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"hausdorff_max_pct", "hausdorff_mean_pct", "hausdorff_rms_pct"})
    EXPECT_GT(j[key].get<double>(), 0) << key;
  EXPECT_EQ(j["same_topology"], true);
  r = run_cli(dir, "quality --json --samples 20000 " + quoted(dir / "torus.stl") + " --ref " +
                       quoted(dir / "unit.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["same_topology"], false);
  r = run_cli(dir, "quality --samples 20000 " + quoted(dir / "torus.stl") + " --ref " +
                       quoted(dir / "unit.ply"));
  EXPECT_NE(r.out.find("DIFFERS"), std::string::npos) << r.out;
}

// Each side of the distance on its own: a cap of the reference sphere lies on the sphere (nothing
// to it), while the rest of the sphere lies far from the cap; the two-sided figures are the larger.
TEST(Cli, QualityReportsEachSideOfTheHausdorffDistance) {
  TempDir dir;
  const TriangleMesh sphere = icosphere(3);
  TriangleMesh cap = sphere;
  std::erase_if(cap.triangles, [&](const Triangle& t) {
    return sphere.vertices[t[0]].z + sphere.vertices[t[1]].z + sphere.vertices[t[2]].z < 0;
  });
  write_mesh(dir / "sphere.off", sphere);
  write_mesh(dir / "cap.off", cap);
  const CliRun r = run_cli(dir, "quality --json --samples 20000 " + quoted(dir / "cap.off") +
                                    " --ref " + quoted(dir / "sphere.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& to = j["hausdorff_to_reference"];
  const auto& from = j["hausdorff_from_reference"];
  EXPECT_LT(to["max_pct"].get<double>(), 1e-9);
  EXPECT_LT(to["mean_pct"].get<double>(), 1e-9);
  // The lower half lies up to √2 radii from the cap: about 7% of the diagonal on average.
  EXPECT_GT(from["mean_pct"].get<double>(), 3);
  EXPECT_EQ(j["hausdorff_mean_pct"], from["mean_pct"]);
  EXPECT_EQ(j["hausdorff_max_pct"], from["max_pct"]);
  EXPECT_EQ(j["hausdorff_rms_pct"], from["rms_pct"]);
  const CliRun text = run_cli(dir, "quality --samples 20000 " + quoted(dir / "cap.off") +
                                       " --ref " + quoted(dir / "sphere.off"));
  EXPECT_NE(text.out.find("mean to the reference 0.00000%, from it"), std::string::npos)
      << text.out;
}

TEST(Cli, NonManifoldInputIsReportedNotFatal) {
  TempDir dir;
  write_file(dir / "fin.obj",
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
  const CliRun r = run_cli(dir, "quality --json " + quoted(dir / "fin.obj"));
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(nlohmann::json::parse(r.out)["nonmanifold_edges"], 1);
  EXPECT_NE(r.err.find("non-manifold"), std::string::npos) << r.err;
}

struct BadInput {
  std::string name, content, expected;
};

void PrintTo(const BadInput& bad, std::ostream* os) {
  *os << bad.name;
}

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, OneLineErrorNamingFileAndProblem) {
  TempDir dir;
  const BadInput& bad = GetParam();
  const auto path = dir / bad.name;
  if (bad.content == "<directory>")
    std::filesystem::create_directory(path);
  else if (bad.content == "<truncated ply>") {
    write_mesh(path, icosphere(3));
    std::filesystem::resize_file(path, std::filesystem::file_size(path) - 100);
  } else if (bad.content != "<missing>")
    write_file(path, bad.content);
  const CliRun r = run_cli(dir, "quality " + quoted(path));
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find(path.string() + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(bad.expected), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

std::string binary_stl_header(std::uint32_t count) {
  std::string s(80, ' ');
  for (int k = 0; k < 4; ++k) s += static_cast<char>((count >> (8 * k)) & 0xff);
  return s;
}

// An ASCII PLY with 3 vertices and 1 face, whose data follow the header.
std::string one_triangle_ply(const std::string& data) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n" +
         data;
}

INSTANTIATE_TEST_SUITE_P(
    EveryCase, CliBadInput,
    ::testing::Values(
        BadInput{"missing.off", "<missing>", "no such file"},
        BadInput{"folder.off", "<directory>", "is a directory"},
        BadInput{"mesh.xyz", "1 2 3\n", "unknown extension"},
        BadInput{"empty.obj", "", "file is empty"},
        BadInput{"nofaces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "empty mesh"},
        BadInput{"nofaces.off", "OFF\n0 0 0\n", "empty mesh"},
        BadInput{"nan.off", "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n", "non-finite"},
        BadInput{"inf.obj", "v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n", "non-finite"},
        BadInput{"nan.ply", one_triangle_ply("0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n"), "non-finite"},
        BadInput{"range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "out of range"},
        BadInput{"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "out of range"},
        BadInput{"negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -5\n", "out of range"},
        BadInput{"range.ply", one_triangle_ply("0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), "out of range"},
        BadInput{"edge.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "2 corners"},
        BadInput{"edge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "2 corners"},
        BadInput{"short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", "truncated OFF"},
        BadInput{"short.stl", binary_stl_header(2) + std::string(50, '\0'), "truncated binary STL"},
        BadInput{"short.ply", "<truncated ply>", "truncated PLY"}),
    [](const auto& info) {
      std::string name = info.param.name;
      std::replace(name.begin(), name.end(), '.', '_');
      return name;
    });

TEST(Cli, RepairWritesCleanMeshAndReportsWhatItDid) {
  TempDir dir;
  write_file(dir / "in.obj",
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 5 5 5\nf 1 2 3\nf 1 2 3\nf 1 4 2\n");
  const CliRun r =
      run_cli(dir, "repair --json " + quoted(dir / "in.obj") + " " + quoted(dir / "out.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["duplicate_vertices_merged"], 1);
  EXPECT_EQ(j["duplicate_triangles_removed"], 1);
  EXPECT_EQ(j["degenerate_triangles_removed"], 1);
  EXPECT_EQ(j["unreferenced_vertices_removed"], 1);
  EXPECT_NE(r.err.find("duplicate vertices merged"), std::string::npos) << r.err;
  const TriangleMesh out = read_mesh(dir / "out.ply");
  EXPECT_EQ(out.triangles.size(), 1u);
  EXPECT_EQ(out.vertices.size(), 3u);
}

TEST(Cli, RemeshOfAPartWhoseCopiesOfAVertexDifferByRoundingIsClosed) {
  // An STL-like soup of a box, each triangle with its own corners, written where 0 was meant as
  // up to 6e-17 (cos 90° as an exporter computes it): as stored, 48 separate triangles. The
  // remesher sees the closed box, and says what it merged.
  const TriangleMesh box = cube(2);
  std::ostringstream obj;
  obj.precision(17);
  for (std::size_t t = 0; t < box.triangles.size(); ++t)
    for (const Vec3& p : box.corners(t)) {
      const auto rounded = [&](double c) { return c == 0 ? 6e-17 * (t % 3) : c; };
      obj << "v " << rounded(p.x) << ' ' << rounded(p.y) << ' ' << rounded(p.z) << '\n';
    }
  for (std::size_t t = 0; t < box.triangles.size(); ++t)
    obj << "f " << 3 * t + 1 << ' ' << 3 * t + 2 << ' ' << 3 * t + 3 << '\n';
  TempDir dir;
  write_file(dir / "box.obj", obj.str());
  const CliRun r = run_cli(dir, "remesh --json --quiet --vertices 400 " + quoted(dir / "box.obj") +
                                    " " + quoted(dir / "out.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("nearly equal"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["components"], 1);
  EXPECT_EQ(j["boundary_loops"], 0);
  EXPECT_EQ(j["euler_characteristic"], 2);
  EXPECT_EQ(j["nonmanifold_edges"], 0);
  EXPECT_EQ(j["same_topology"], true);
  EXPECT_GE(j["angle_min_deg"].get<double>(), 30);
}

TEST(Cli, RemeshOfABoxWithATJunctionStitchedByZeroAreaTrianglesIsClosed) {
  // Dropping the caps would have opened a slit, remeshed as a boundary loop.
  TempDir dir;
  write_mesh(dir / "box.off", with_t_junction(cube(4), 7, 3));
  const CliRun r = run_cli(dir, "remesh --json --quiet --vertices 400 " + quoted(dir / "box.off") +
                                    " " + quoted(dir / "out.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("3 zero-area triangles split out"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["boundary_loops"], 0);
  EXPECT_EQ(j["euler_characteristic"], 2);
  EXPECT_EQ(j["same_topology"], true);
}

TEST(Cli, RepairNeverWritesOverItsInput) {
  TempDir dir;
  write_mesh(dir / "in.off", icosphere(1));
  const std::string before = read_file(dir / "in.off");
  for (const std::string out : {"in.off", "./in.off"}) {
    const CliRun r = run_cli(dir, "repair " + quoted(dir / "in.off") + " " + quoted(dir / out));
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("refusing to write over the input"), std::string::npos) << r.err;
  }
  EXPECT_EQ(read_file(dir / "in.off"), before);
}

TEST(Cli, UnwritableOutputExitsWithFourAndLeavesNothing) {
  TempDir dir;
  write_mesh(dir / "in.off", icosphere(1));
  const CliRun r =
      run_cli(dir, "repair " + quoted(dir / "in.off") + " " + quoted(dir / "no" / "out.off"));
  EXPECT_EQ(r.code, 4);
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));
}

TEST(Cli, ThreadCountDoesNotChangeTheReport) {
  TempDir dir;
  write_mesh(dir / "a.off", icosphere(3));
  write_mesh(dir / "b.off", transformed(torus(1, 0.5, 30, 15), 1.0, {0.2, 0, 0}));
  const std::string args =
      "quality --json --samples 30000 " + quoted(dir / "a.off") + " --ref " + quoted(dir / "b.off");
  const CliRun one = run_cli(dir, args + " --threads 1"), all = run_cli(dir, args);
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(one.out, all.out);
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

TEST(CliLfs, WritesTheSizesAsAPlyVertexPropertyAndRefusesOtherFormats) {
  TempDir dir;
  write_mesh(dir / "sphere.off", icosphere(3, 2.0));
  const CliRun r =
      run_cli(dir, "lfs --json " + quoted(dir / "sphere.off") + " " + quoted(dir / "sizes.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["vertices"], 642);
  EXPECT_NEAR(j["lfs_min"].get<double>(), 2.0, 0.2);  // a sphere's: its radius
  EXPECT_NEAR(j["lfs_max"].get<double>(), 2.0, 0.2);
  EXPECT_EQ(read_mesh(dir / "sizes.ply").vertices.size(), 642u);
  std::ifstream ply(dir / "sizes.ply", std::ios::binary);
  std::string header((std::istreambuf_iterator<char>(ply)), {});
  EXPECT_NE(header.find("property float lfs\nproperty uchar red"), std::string::npos);
  const CliRun off =
      run_cli(dir, "lfs " + quoted(dir / "sphere.off") + " " + quoted(dir / "sizes.off"));
  EXPECT_EQ(off.code, 2);
  EXPECT_NE(off.err.find("use .ply"), std::string::npos) << off.err;
}

TEST(CliLfs, NarrowsToTheGapsBetweenBoundariesAndFeatures) {
  // A flat strip 6 × 1 has no poles (its lfs is its diagonal) but its sides are 1 apart.
  TempDir dir;
  write_mesh(dir / "strip.off", mapped_grid(60, 6, [](double u, double v) {
               return Vec3{6 * u, v, 0};
             }));
  for (const std::string options : {"", "--no-features ", "--vertices 200 "}) {
    const CliRun r = run_cli(dir, "lfs --json --gradation 0 " + options +
                                      quoted(dir / "strip.off") + " " + quoted(dir / "sizes.ply"));
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["lfs_min"].get<double>(), 1.0, 1e-9) << options;
    EXPECT_GT(j["lfs_max"].get<double>(), 1.5) << options;
    EXPECT_EQ(j["feature_curves"], 4) << options;  // the outline, split at its corners
  }
}

TEST(CliRvd, JsonReportTilesTheSurface) {
  TempDir dir;
  write_mesh(dir / "torus.off", torus(1, 0.4, 48, 24));
  const CliRun r = run_cli(dir, "rvd --json --seeds 500 " + quoted(dir / "torus.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"seeds", "triangles", "polygons", "surface_area", "cells_area_sum", "energy",
        "exact_fallbacks", "radius_searches", "cells_clipped", "threads", "timings"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"sampling", "kdtree", "neighbors", "rvd", "total"})
    EXPECT_TRUE(j["timings"].contains(key)) << key;
  EXPECT_EQ(j["seeds"], 500);
  EXPECT_EQ(j["triangles"], 2304);
  EXPECT_NEAR(j["cells_area_sum"].get<double>(), j["surface_area"].get<double>(),
              1e-12 * j["surface_area"].get<double>());
  EXPECT_GT(j["polygons"].get<int>(), 2304);
}

// Issue 22: the commands that measure work in any units, like remesh (at 2^600 quality --ref
// crashed with SIGFPE, and rvd refused both scales: "cannot sample a surface of zero area").
TEST(Cli, QualityAndRvdGiveTheSameFiguresAtAnyScale) {
  TempDir dir;
  auto figures = [&](int k) {
    write_mesh(dir / "a.off", scaled_by_power_of_two(transformed(icosphere(3), 1.01), k));
    write_mesh(dir / "b.off", scaled_by_power_of_two(icosphere(3), k));
    const CliRun q = run_cli(dir, "quality --json --samples 3000 " + quoted(dir / "a.off") +
                                      " --ref " + quoted(dir / "b.off"));
    const CliRun r = run_cli(dir, "rvd --json --seeds 200 " + quoted(dir / "b.off"));
    EXPECT_EQ(q.code, 0) << "2^" << k << ": " << q.err;
    EXPECT_EQ(r.code, 0) << "2^" << k << ": " << r.err;
    return std::pair{nlohmann::json::parse(q.out), nlohmann::json::parse(r.out)};
  };
  const auto [quality, rvd] = figures(0);
  EXPECT_GT(quality["hausdorff_max_pct"].get<double>(), 0.1);
  EXPECT_LT(rvd["area_relative_difference"].get<double>(), 1e-12);
  for (const int k : {-600, 600}) {
    const auto [q, r] = figures(k);
    for (const char* key : {"hausdorff_max_pct", "hausdorff_mean_pct", "q_min", "same_topology"})
      EXPECT_EQ(q[key], quality[key]) << key << " at 2^" << k;
    for (const char* key : {"polygons", "area_relative_difference", "exact_fallbacks"})
      EXPECT_EQ(r[key], rvd[key]) << key << " at 2^" << k;
  }
}

TEST(CliRvd, SameEnergyOnAnyThreadCountAndForTheSameSeed) {
  TempDir dir;
  write_mesh(dir / "sphere.ply", icosphere(4));
  const std::string args = "rvd --json --seeds 800 --seed 3 " + quoted(dir / "sphere.ply");
  const auto one = nlohmann::json::parse(run_cli(dir, args + " --threads 1").out);
  const auto all = nlohmann::json::parse(run_cli(dir, args).out);
  EXPECT_EQ(one["energy"], all["energy"]);
  EXPECT_EQ(one["polygons"], all["polygons"]);
  const auto other = nlohmann::json::parse(
      run_cli(dir, "rvd --json --seeds 800 --seed 4 " + quoted(dir / "sphere.ply")).out);
  EXPECT_NE(one["energy"], other["energy"]);
}

TEST(CliRvd, WritesCellsAndRestrictedDelaunayTriangulation) {
  TempDir dir;
  write_mesh(dir / "sphere.off", icosphere(4));
  const CliRun r =
      run_cli(dir, "rvd --seeds 300 " + quoted(dir / "sphere.off") + " --cells " +
                       quoted(dir / "cells.ply") + " --rdt " + quoted(dir / "rdt.obj"));
  ASSERT_EQ(r.code, 0) << r.err;
  const TriangleMesh cells = read_mesh(dir / "cells.ply");
  EXPECT_GT(cells.triangles.size(), 0u);
  const TriangleMesh rdt = read_mesh(dir / "rdt.obj");
  EXPECT_LE(rdt.vertices.size(), 300u);
  EXPECT_GT(rdt.triangles.size(), 500u);
}

TEST(CliRvd, SeedsFromATextFileOrAMesh) {
  TempDir dir;
  write_mesh(dir / "sphere.off", icosphere(3));
  write_file(dir / "seeds.txt", "# x y z\n1 0 0\n0 1 0\n\n0 0 1\n-1 0 0\n");
  CliRun r = run_cli(dir, "rvd --json " + quoted(dir / "sphere.off") + " --seeds-file " +
                              quoted(dir / "seeds.txt"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["seeds"], 4);
  write_mesh(dir / "seeds.obj", icosphere(1));
  r = run_cli(dir, "rvd --json " + quoted(dir / "sphere.off") + " --seeds-file " +
                       quoted(dir / "seeds.obj"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["seeds"], 42);
}

TEST(CliRvd, BadSeedsGetClearErrors) {
  TempDir dir;
  write_mesh(dir / "sphere.off", icosphere(2));
  write_file(dir / "bad.txt", "1 0 0\n0 1\n");
  CliRun r = run_cli(
      dir, "rvd " + quoted(dir / "sphere.off") + " --seeds-file " + quoted(dir / "bad.txt"));
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("line 2"), std::string::npos) << r.err;
  write_file(dir / "dup.txt", "1 0 0\n0 1 0\n1 0 0\n");
  r = run_cli(dir,
              "rvd " + quoted(dir / "sphere.off") + " --seeds-file " + quoted(dir / "dup.txt"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("seeds 0 and 2 are identical"), std::string::npos) << r.err;
  EXPECT_EQ(run_cli(dir, "rvd " + quoted(dir / "sphere.off")).code, 2);  // no seeds given
  EXPECT_EQ(run_cli(dir, "rvd " + quoted(dir / "sphere.off") + " --seeds 0").code, 2);
  r = run_cli(
      dir, "rvd " + quoted(dir / "sphere.off") + " --seeds 10 --rdt " + quoted(dir / "sphere.off"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("refusing to write over the input"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// AddressSanitizer reserves terabytes of address space: an address-space limit cannot be set
// under it.
#if defined(__SANITIZE_ADDRESS__)
#define CVTMESH_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CVTMESH_UNDER_ASAN 1
#endif
#endif

TEST(CliRemesh, AJobTooBigForTheMemoryLimitFailsAtOnce) {
#ifdef CVTMESH_UNDER_ASAN
  GTEST_SKIP() << "address-space limits do not work under AddressSanitizer";
#endif
  TempDir dir;
  write_mesh(dir / "tri.off", TriangleMesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}});
  // 2 GB of address space; 10 million vertices need about 15 GB.
  const std::string command = "ulimit -v 2000000 && exec " + std::string(CVTMESH_CLI) + " remesh " +
                              quoted(dir / "tri.off") + " " + quoted(dir / "out.off") +
                              " --vertices 10000000 2>" + quoted(dir / "err.txt");
  const int status = std::system(("sh -c \"" + command + "\"").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 5);
  const std::string err = read_file(dir / "err.txt");
  EXPECT_NE(err.find("1 triangles to 10000000 vertices needs about"), std::string::npos) << err;
  EXPECT_NE(err.find("are available"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
}

TEST(CliRemesh, JsonReportHasQualityAndOptimizerKeys) {
  TempDir dir;
  write_mesh(dir / "sphere.off", icosphere(4));
  const CliRun r = run_cli(dir, "remesh --json --quiet --vertices 400 --iterations 15 " +
                                    quoted(dir / "sphere.off") + " " + quoted(dir / "out.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");  // --quiet
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : kRequiredKeys) EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"hausdorff_max_pct",
                          "hausdorff_mean_pct",
                          "hausdorff_rms_pct",
                          "same_topology",
                          "iterations",
                          "rvd_evaluations",
                          "energy_initial",
                          "energy_final",
                          "gradient_norm_final",
                          "defects_polished",
                          "polish_rounds",
                          "links_mended",
                          "islands_seeded",
                          "links_flipped",
                          "tips_closed",
                          "flat_ears_removed",
                          "flat_pairs_merged",
                          "input_crossing_triangles",
                          "output_crossing_triangles",
                          "vertices_guarded",
                          "vertices_splitting_crossings",
                          "mend_rounds",
                          "shape_flips",
                          "shape_moves",
                          "short_edges_collapsed",
                          "vertices_onto_own_sheet",
                          "vertices_on_cell_normals",
                          "vertices_snapped",
                          "vertices_fitted",
                          "angle_min_away_deg",
                          "q_min_away",
                          "narrow_input_angles",
                          "narrow_angle_ratio_min",
                          "time_s",
                          "timings"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key :
       {"initialization", "rcvt", "ccvt", "extraction", "topology_control", "hausdorff"})
    EXPECT_TRUE(j["timings"].contains(key)) << key;
  EXPECT_GT(j["timings"]["hausdorff"].get<double>(), 0);
  // Its checks and last step run even where it adds no seed: part of the extraction.
  EXPECT_LE(j["timings"]["topology_control"].get<double>(),
            j["timings"]["extraction"].get<double>());
  EXPECT_EQ(j["same_topology"], true);
  EXPECT_EQ(j["mend_rounds"], 0);  // a sphere this well sampled needs no topology control
  EXPECT_LT(j["energy_final"].get<double>(), j["energy_initial"].get<double>());
  EXPECT_EQ(read_mesh(dir / "out.ply").vertices.size(), j["vertices"].get<std::size_t>());
}

TEST(CliRemesh, NoHausdorffLeavesTheDistanceOutOfTheReport) {
  TempDir dir;
  write_mesh(dir / "sphere.off", icosphere(3));
  const std::string io = quoted(dir / "sphere.off") + " " + quoted(dir / "out.off");
  const CliRun r = run_cli(dir, "remesh --json --quiet --vertices 300 --no-hausdorff " + io);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["hausdorff_max_pct"].is_null());
  EXPECT_TRUE(j["hausdorff_mean_pct"].is_null());
  EXPECT_EQ(j["hausdorff_samples"], 0);
  EXPECT_EQ(j["timings"]["hausdorff"], 0);
  EXPECT_EQ(j["same_topology"], true);
  const CliRun text = run_cli(dir, "remesh --quiet --vertices 300 --no-hausdorff " + io);
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("hausdorff not measured"), std::string::npos) << text.out;
  const CliRun measured = run_cli(dir, "remesh --json --quiet --vertices 300 --samples 5000 " + io);
  ASSERT_EQ(measured.code, 0) << measured.err;
  EXPECT_EQ(nlohmann::json::parse(measured.out)["hausdorff_samples"], 5000);
}

TEST(CliRemesh, FeatureKeysFlagsAndEdgeFile) {
  TempDir dir;
  write_mesh(dir / "cube.off", cube(6));
  const std::string io = quoted(dir / "cube.off") + " " + quoted(dir / "out.off");
  auto json = [&](const std::string& flags) {
    const CliRun r = run_cli(dir, "remesh --json --quiet --vertices 600 " + io + " " + flags);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const auto kept = json("");
  for (const char* key : {"feature_edges_in", "corners_in", "corners_out",
                          "feature_hausdorff_max_pct", "feature_edges_missing"})
    EXPECT_TRUE(kept.contains(key)) << key;
  EXPECT_EQ(kept["corners_in"], 8);
  EXPECT_EQ(kept["corners_out"], 8);
  EXPECT_EQ(kept["feature_edges_missing"], 0);
  EXPECT_LT(kept["feature_hausdorff_max_pct"].get<double>(), 1e-6);
  EXPECT_NEAR(kept["feature_sector_min_deg"].get<double>(), 90, 1e-9);  // the cube's corners
  EXPECT_EQ(json("--no-features")["feature_edges_in"], 0);
  EXPECT_EQ(json("--feature-angle 100")["feature_edges_in"], 0);

  std::ofstream(dir / "edges.txt") << "# one edge\n0 99999\n";
  const CliRun bad =
      run_cli(dir, "remesh --vertices 600 " + io + " --feature-edges " + quoted(dir / "edges.txt"));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("edges.txt: feature edge 0 99999: vertex id out of range"),
            std::string::npos)
      << bad.err;
  std::ofstream(dir / "garbage.txt") << "0 1 2\n";
  const CliRun garbage = run_cli(
      dir, "remesh --vertices 600 " + io + " --feature-edges " + quoted(dir / "garbage.txt"));
  EXPECT_NE(garbage.err.find("garbage.txt:1:"), std::string::npos) << garbage.err;
}

// Feature edges name the file's vertices, whatever the repair renumbers: here a vertex used by
// no triangle comes first, so every id moves down by one once it is dropped.
TEST(CliRemesh, FeatureEdgesKeepTheFilesVertexIdsThroughTheRepair) {
  TempDir dir;
  TriangleMesh sphere = icosphere(2);
  TriangleMesh stored;
  stored.vertices.push_back({5, 5, 5});  // unreferenced
  stored.vertices.insert(stored.vertices.end(), sphere.vertices.begin(), sphere.vertices.end());
  for (Triangle t : sphere.triangles) stored.triangles.push_back({t[0] + 1, t[1] + 1, t[2] + 1});
  write_mesh(dir / "sphere.off", stored);
  const Triangle& t = sphere.triangles[7];
  std::ofstream(dir / "edges.txt") << t[0] + 1 << ' ' << t[1] + 1 << '\n'
                                   << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  const CliRun r = run_cli(dir, "remesh --json --quiet --vertices 300 --no-features " +
                                    quoted(dir / "sphere.off") + " " + quoted(dir / "out.off") +
                                    " --feature-edges " + quoted(dir / "edges.txt"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["feature_edges_in"], 2);
  EXPECT_EQ(j["corners_in"], 3);  // the chain's two ends, and its 120° turn between them
}

TEST(CliRemesh, JaggedFoldsAreNoFeaturesByDefaultButAnExplicitAngleForcesThem) {
  TempDir dir;
  TriangleMesh bumpy = icosphere(3);  // vertices alternately in and out: folds of over 60°
  for (Index v = 0; v < bumpy.vertices.size(); ++v)
    bumpy.vertices[v] = (v % 3 == 0 ? 1.2 : 0.95) * bumpy.vertices[v];
  write_mesh(dir / "bumpy.off", bumpy);
  const std::string io = quoted(dir / "bumpy.off") + " " + quoted(dir / "out.off");
  auto features_in = [&](const std::string& flags) {
    const CliRun r =
        run_cli(dir, "remesh --json --quiet --no-hausdorff --vertices 400 " + io + " " + flags);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out)["feature_edges_in"].get<int>();
  };
  EXPECT_EQ(features_in(""), 0);
  EXPECT_GT(features_in("--feature-angle 60"), 0);
}

TEST(CliRemesh, SeedsFileGivesTheStartAndTheSize) {
  TempDir dir;
  const TriangleMesh sphere = icosphere(4);
  write_mesh(dir / "sphere.off", sphere);
  std::ofstream seeds(dir / "seeds.xyz");
  for (std::size_t v = 0; v < sphere.vertices.size(); v += 10)
    seeds << sphere.vertices[v].x << ' ' << sphere.vertices[v].y << ' ' << sphere.vertices[v].z
          << '\n';
  seeds.close();
  const std::string io = quoted(dir / "sphere.off") + " " + quoted(dir / "out.off");
  const CliRun r = run_cli(dir, "remesh --json --quiet --no-hausdorff " + io + " --seeds-file " +
                                    quoted(dir / "seeds.xyz"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::size_t given = (sphere.vertices.size() + 9) / 10;
  EXPECT_EQ(nlohmann::json::parse(r.out)["vertices"].get<std::size_t>(), given);
  // Another start gives another output: the file was used.
  const CliRun random = run_cli(
      dir, "remesh --json --quiet --no-hausdorff " + io + " --vertices " + std::to_string(given));
  ASSERT_EQ(random.code, 0) << random.err;
  EXPECT_NE(nlohmann::json::parse(r.out)["energy_initial"],
            nlohmann::json::parse(random.out)["energy_initial"]);

  std::ofstream(dir / "twice.xyz") << "0 0 1\n0 1 0\n1 0 0\n0 0 1\n0 0 -1\n";
  const CliRun twice = run_cli(dir, "remesh " + io + " --seeds-file " + quoted(dir / "twice.xyz"));
  EXPECT_EQ(twice.code, 3);
  EXPECT_NE(twice.err.find("twice.xyz: two seeds at the same point"), std::string::npos)
      << twice.err;
  const CliRun both =
      run_cli(dir, "remesh " + io + " --vertices 100 --seeds-file " + quoted(dir / "seeds.xyz"));
  EXPECT_EQ(both.code, 2);
  EXPECT_NE(both.err.find("excludes"), std::string::npos) << both.err;
}

TEST(CliRemesh, ProgressGoesToStderr) {
  TempDir dir;
  write_mesh(dir / "cube.off", cube(2));
  const CliRun r = run_cli(dir, "remesh --vertices 200 --iterations 3 " + quoted(dir / "cube.off") +
                                    " " + quoted(dir / "out.obj"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("rcvt    1  energy"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ccvt"), std::string::npos) << r.err;  // the cube's creases bind seeds
}

TEST(CliRemesh, BadArgumentsGetClearErrors) {
  TempDir dir;
  write_mesh(dir / "sphere.off", icosphere(3));
  const std::string in = quoted(dir / "sphere.off"), out = quoted(dir / "out.off");
  auto expect_error = [&](const std::string& args, int code, const std::string& message) {
    const CliRun r = run_cli(dir, "remesh " + args);
    EXPECT_EQ(r.code, code) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
  };
  expect_error(in + " " + out, 2, "--vertices");                       // no size
  expect_error(in + " " + out + " --vertices 3", 2, "at least 4");     // too few
  expect_error(in + " " + out + " --vertices 900000000", 2, "limit");  // absurdly many
  expect_error(in + " " + out + " --edge-length -0.5", 2, "positive");
  expect_error(in + " " + out + " --vertices 10 --edge-length 0.1", 2, "excludes");
  expect_error(in + " " + out + " --vertices 100 --optimizer newton", 2, "optimizer");
  expect_error(quoted(dir / "missing.off") + " " + out + " --vertices 100", 3, "no such file");
  expect_error(in + " " + in + " --vertices 100", 2, "refusing to write over the input");
  expect_error(in + " " + quoted(dir / "out.xyz") + " --vertices 100", 2,
               "unknown output extension");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
}

TEST(Cli, SizingFromAFileAndAdaptive) {
  const TempDir dir;
  const TriangleMesh sphere = icosphere(3);
  write_mesh(dir / "sphere.off", sphere);
  {
    std::ofstream sizes(dir / "sizes.txt");
    for (const Vec3& p : sphere.vertices) sizes << 0.2 + 0.1 * p.z << "\n";
  }
  CliRun r = run_cli(dir, "remesh --json --no-hausdorff " + quoted(dir / "sphere.off") + " " +
                              quoted(dir / "out.off") + " --sizing " + quoted(dir / "sizes.txt"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["edge_length_ratio"]["median"].get<double>(), 1.0, 0.2);
  EXPECT_TRUE(j["same_topology"].get<bool>());
  // One value short: a one-line error naming the file.
  {
    std::ofstream sizes(dir / "short.txt");
    for (std::size_t v = 1; v < sphere.vertices.size(); ++v) sizes << "0.2\n";
  }
  r = run_cli(dir, "remesh " + quoted(dir / "sphere.off") + " " + quoted(dir / "out2.off") +
                       " --sizing " + quoted(dir / "short.txt"));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("short.txt"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out2.off"));
  // --adaptive takes its gradation as an optional value.
  for (const std::string flag : {"--adaptive", "--adaptive 3"}) {
    r = run_cli(dir, "remesh --json --no-hausdorff --vertices 300 " + flag + " " +
                         quoted(dir / "sphere.off") + " " + quoted(dir / "out3.off"));
    ASSERT_EQ(r.code, 0) << flag << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["vertices"].get<int>(), 300) << flag;
  }
  EXPECT_EQ(run_cli(dir, "remesh --vertices 300 --adaptive 0 " + quoted(dir / "sphere.off") + " " +
                             quoted(dir / "out4.off"))
                .code,
            2);
}

// A unit sheet of 100×100 quads with one triangle missing: a hole far narrower than an edge at
// 300 vertices. The even sizes grade down to it by default, the report says how far, and
// --gap-gradation 0 keeps them even; it goes with neither --adaptive nor --sizing.
TEST(Cli, EvenSizesGradeDownToAPinholeUnlessToldNot) {
  const TempDir dir;
  TriangleMesh sheet = mapped_grid(100, 100, [](double u, double v) { return Vec3{u, v, 0}; });
  sheet.triangles.erase(sheet.triangles.begin() + 2 * (50 * 100 + 50));
  write_mesh(dir / "sheet.off", sheet);
  const std::string files = quoted(dir / "sheet.off") + " " + quoted(dir / "out.off");
  CliRun r = run_cli(dir, "remesh --json --no-hausdorff --vertices 300 " + files);
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["gap_length_min"].get<double>(), 0);
  EXPECT_LT(j["gap_length_min"].get<double>(), 0.5);
  EXPECT_TRUE(j["same_topology"].get<bool>());
  r = run_cli(dir, "remesh --no-hausdorff --vertices 300 " + files);
  EXPECT_NE(r.out.find("graded down to feature gaps"), std::string::npos) << r.out;
  r = run_cli(dir, "remesh --json --no-hausdorff --vertices 300 --gap-gradation 0 " + files);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["gap_length_min"].get<double>(), 0);
  EXPECT_EQ(run_cli(dir, "remesh --vertices 300 --adaptive --gap-gradation 2 " + files).code, 2);
  EXPECT_EQ(run_cli(dir, "remesh --vertices 300 --gap-gradation -1 " + files).code, 2);
}

// A sphere with five one-triangle holes (a scan's dropouts): kept by default, each an output
// boundary loop; --fill-holes closes those under 10 edge lengths round first (the report
// compares with the filled input), --fill-holes E under E; 0 is no length.
TEST(Cli, FillHolesClosesTheInputsSmallHolesFirst) {
  const TempDir dir;
  write_mesh(dir / "holed.off", with_one_triangle_holes(icosphere(3), 5, 97));
  const std::string files = quoted(dir / "holed.off") + " " + quoted(dir / "out.off");
  CliRun r = run_cli(dir, "remesh --json --no-hausdorff --vertices 300 " + files);
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["boundary_loops"].get<int>(), 5);
  EXPECT_EQ(j["input_holes_filled"].get<int>(), 0);
  // Kept, they are pointed out with the option that closes them (not with --quiet).
  r = run_cli(dir, "remesh --no-hausdorff --vertices 300 " + files);
  EXPECT_NE(r.err.find("5 holes shorter than 10 edge lengths were kept"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--fill-holes"), std::string::npos) << r.err;
  r = run_cli(dir, "remesh --json --no-hausdorff --vertices 300 --fill-holes " + files);
  ASSERT_EQ(r.code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["boundary_loops"].get<int>(), 0);
  EXPECT_TRUE(j["same_topology"].get<bool>());
  EXPECT_EQ(j["input_holes_filled"].get<int>(), 5);
  EXPECT_EQ(j["input_hole_triangles_added"].get<int>(), 5);
  EXPECT_GE(j["angle_min_deg"].get<double>(), 30);
  EXPECT_NE(r.err.find("5 holes shorter than"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("holed.off"), std::string::npos) << r.err;
  // At 300 vertices an edge is about 0.23 long, a hole about 0.45 round: 2 edge lengths.
  r = run_cli(dir, "remesh --json --no-hausdorff --vertices 300 --fill-holes 1 " + files);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["input_holes_filled"].get<int>(), 0);
  EXPECT_EQ(run_cli(dir, "remesh --vertices 300 --fill-holes 0 " + files).code, 2);
  // `repair` fills them too, given the longest boundary in the mesh's units.
  r = run_cli(dir, "repair --json --fill-holes 1 " + quoted(dir / "holed.off") + " " +
                       quoted(dir / "filled.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["holes_filled"].get<int>(), 5);
  EXPECT_EQ(j["boundary_loops"].get<int>(), 0);
  EXPECT_EQ(j["euler_characteristic"].get<int>(), 2);
}

}  // namespace
}  // namespace cvtmesh
