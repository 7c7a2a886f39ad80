// CVT remeshing: the energy goes down, L-BFGS beats Lloyd, smooth closed surfaces come out as
// well-shaped closed manifolds of the same topology, deterministically, and bad settings fail.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/sampling.hpp"
#include "cvtmesh/topology.hpp"
#include "support/shapes.hpp"
#include "support/shared_data.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// The targets for smooth closed surfaces: θmin ≥ 30°, Qmin ≥ 0.6, under 0.1% of the
// triangles with an angle below 30°, and a small mean Hausdorff distance (in % of the bbox
// diagonal).
void expect_good_remesh(const TriangleMesh& input, std::size_t vertices,
                        double hausdorff_mean_pct = 0.1, bool sharp_edges = true) {
  RemeshSettings s;
  s.vertices = vertices;
  s.features.sharp_edges = sharp_edges;
  const RemeshResult r = remesh(input, s);
  const TopologyReport t = analyze_topology(r.mesh), in = analyze_topology(input);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(t.is_closed());
  EXPECT_TRUE(t.consistently_oriented);
  EXPECT_TRUE(same_topology(t, in));
  EXPECT_NEAR(static_cast<double>(t.vertices), static_cast<double>(vertices), 0.01 * vertices);
  const QualityReport q = measure_quality(r.mesh);
  EXPECT_GE(q.angle_min_deg, 30.0);
  EXPECT_GE(q.q_min, 0.6);
  EXPECT_LT(q.pct_angle_below_30, 0.1);
  EXPECT_LE(hausdorff_distance(r.mesh, input, {.samples = 200'000}).mean_pct(), hausdorff_mean_pct);
  EXPECT_LT(r.energy_final, r.energy_initial);
}

TEST(Remesh, SphereBecomesWellShapedAndKeepsItsTopology) {
  expect_good_remesh(icosphere(5), 2000);
}

TEST(Remesh, TorusBecomesWellShapedAndKeepsItsTopology) {
  expect_good_remesh(torus(1, 0.4, 160, 64), 2500);
}

TEST(Remesh, ReportsTheHausdorffDistanceWhenAsked) {
  // Measured with the remesher's own AABB tree of the input: the same figures as a separate
  // measurement with the same settings.
  const TriangleMesh input = torus(1, 0.4, 80, 32);
  RemeshSettings s;
  s.vertices = 500;
  EXPECT_FALSE(remesh(input, s).hausdorff);
  s.hausdorff = HausdorffSettings{.samples = 5000};
  const RemeshResult r = remesh(input, s);
  ASSERT_TRUE(r.hausdorff);
  const HausdorffReport alone = hausdorff_distance(r.mesh, input, {.samples = 5000});
  // The remesher's tree holds the input's triangles in its own order: the same distances, up
  // to the rounding of the projections.
  EXPECT_NEAR(r.hausdorff->max, alone.max, 1e-12);
  EXPECT_NEAR(r.hausdorff->mean, alone.mean, 1e-12);
  EXPECT_EQ(r.hausdorff->samples_per_surface, 5000u);
  EXPECT_GT(r.hausdorff->mean, 0);
}

TEST(RemeshSharedData, BunnyAt10kVerticesMeetsTheTargets) {
  if (!std::filesystem::exists(shared_data() / "bunny.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  // The smooth-surface targets: the scan's few sharp folds (where holes were filled) kept as
  // features cost a few degrees next to their corners (θmin 28.9° measured), as on any mesh
  // with features; scans are remeshed with --no-features.
  expect_good_remesh(shared_mesh("bunny.off"), 10'000, 0.05, false);
}

TEST(RemeshSharedData, Knot1At3kVerticesMeetsTheTargets) {
  if (!std::filesystem::exists(shared_data() / "knot1.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  expect_good_remesh(shared_mesh("knot1.off"), 3'000);  // genus 1, thin tube: coarse for 3k
}

// The last step's balancing flips (improve_shapes): these inputs' worst triangles sat at a vertex
// of valence 4 beside ones of 7 and 8, which no move and no flip that must better its own two
// triangles mends. At 5k vertices, without them: 3torus θmin 26.4°, Qmin 0.459 (geogram's
// vorpalite: 24.1° and 0.536), lion-head Qmin 0.613 (vorpalite 0.617). (The boundary rule, where
// a vertex wants 3 triangles rather than 6, was checked on mech-holes-shark at 1k: 22.5° without
// it, 26.7° with; since the integrals' rounding changed (order-independent polygons), that
// output's worst triangle is at a saw tooth's tip, which no valence mends.)
TEST(RemeshSharedData, ValenceDefectsAreEvenedOut) {
  if (!std::filesystem::exists(shared_data() / "corpus" / "3torus.off"))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  RemeshSettings s;
  s.vertices = 5000;
  const QualityReport torus = measure_quality(remesh(shared_mesh("corpus/3torus.off"), s).mesh);
  EXPECT_GE(torus.angle_min_deg, 30.0);
  EXPECT_GE(torus.q_min, 0.6);
  const QualityReport lion = measure_quality(remesh(shared_mesh("corpus/lion-head.off"), s).mesh);
  EXPECT_GE(lion.q_min, 0.63);
}

TEST(Remesh, EnergyDecreasesAlongAcceptedLbfgsSteps) {
  RemeshSettings s;
  s.vertices = 800;
  s.mode = CvtMode::rcvt;
  s.iterations = 20;
  const RemeshResult r = remesh(icosphere(4), s);
  ASSERT_GT(r.energies.size(), 5u);
  for (std::size_t k = 1; k < r.energies.size(); ++k) EXPECT_LE(r.energies[k], r.energies[k - 1]);
}

TEST(Remesh, LbfgsReachesAToleranceInFewerEvaluationsThanLloyd) {
  RemeshSettings s;
  s.vertices = 600;
  s.mode = CvtMode::rcvt;
  s.gradient_tolerance = 0.05;
  s.iterations = 500;
  const TriangleMesh m = icosphere(4);
  const RemeshResult lbfgs = remesh(m, s);
  s.optimizer = Optimizer::lloyd;
  const RemeshResult lloyd = remesh(m, s);
  EXPECT_LE(lbfgs.gradient_norm_final, 0.05 * lbfgs.gradient_norm_initial);
  EXPECT_LE(lloyd.gradient_norm_final, 0.05 * lloyd.gradient_norm_initial);
  EXPECT_LT(lbfgs.rvd_evaluations, lloyd.rvd_evaluations);
}

// Spread initial seeds start RCVT half way: it gets half the iteration cap, with a sizing field
// too; given seeds, random or not, get it all.
TEST(Remesh, RcvtFromSpreadSeedsTakesHalfTheIterations) {
  const TriangleMesh m = icosphere(4);
  RemeshSettings s;
  s.vertices = 600;
  s.mode = CvtMode::rcvt;
  s.gradient_tolerance = 1e-12;  // the cap stops it
  s.iterations = 10;
  const RemeshResult spread = remesh(m, s);
  EXPECT_EQ(spread.iterations, 5);
  s.vertices = 0;
  s.initial_seeds = sample_surface(m, 600, 1);
  const RemeshResult given = remesh(m, s);
  EXPECT_EQ(given.iterations, 10);
  // Spread, they start nearer to centroidal than random ones, and end at least as near.
  EXPECT_LT(spread.energy_initial, 0.75 * given.energy_initial);
  EXPECT_LT(spread.energy_final, 1.005 * given.energy_final);
  s.initial_seeds.clear();
  s.vertices = 600;
  s.sizing.edge_length_at = [](const Vec3& p) { return 1.5 + p.z; };
  EXPECT_EQ(remesh(m, s).iterations, 5);
}

// With features to bind seeds to, RCVT then CCVT; without, and with ρ = 1, RCVT alone takes
// both phases' iterations (its free seeds approximate the surface better, see the pipeline);
// with a density, CCVT stays.
TEST(Remesh, AFeatureFreeSurfaceSpendsBothPhasesOnRcvt) {
  RemeshSettings s;
  s.vertices = 600;
  s.gradient_tolerance = 1e-12;  // the caps stop the phases
  s.iterations = 4;
  std::vector<std::string> phases;
  s.progress = [&](const RemeshProgress& p) { phases.emplace_back(p.phase); };
  const auto count = [&](const char* phase) {
    return std::count(phases.begin(), phases.end(), phase);
  };
  const RemeshResult smooth = remesh(icosphere(4), s);
  EXPECT_EQ(count("rcvt"), 2 + 4);
  EXPECT_EQ(count("rcvt"), static_cast<std::ptrdiff_t>(phases.size()));
  EXPECT_EQ(smooth.iterations, 6);
  EXPECT_EQ(smooth.seconds_ccvt, 0);
  EXPECT_TRUE(same_topology(analyze_topology(smooth.mesh), analyze_topology(icosphere(4))));
  phases.clear();
  const RemeshResult creased = remesh(cube(3), s);
  EXPECT_EQ(count("rcvt"), 2);
  EXPECT_GE(count("ccvt"), 4);
  EXPECT_GT(creased.feature_edges.size(), 0u);
  phases.clear();
  s.sizing.edge_length_at = [](const Vec3& p) { return 1.5 + p.z; };
  remesh(icosphere(4), s);
  EXPECT_EQ(count("rcvt"), 2);
  EXPECT_GE(count("ccvt"), 4);
}

TEST(Remesh, SameOutputOnOneAndAllThreads) {
  RemeshSettings s;
  s.vertices = 500;
  s.iterations = 10;
  const TriangleMesh m = torus(1, 0.4, 60, 24);
  RemeshResult one;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = remesh(m, s);
  }
  const RemeshResult all = remesh(m, s);
  EXPECT_EQ(one.mesh.vertices, all.mesh.vertices);
  EXPECT_EQ(one.mesh.triangles, all.mesh.triangles);
  EXPECT_EQ(one.energies, all.energies);
}

TEST(Remesh, SizeSettingsAreValidated) {
  const TriangleMesh m = icosphere(3);
  RemeshSettings s;
  EXPECT_THROW(requested_vertex_count(m, s), InvalidArgument);  // no size
  s.vertices = 3;
  EXPECT_THROW(requested_vertex_count(m, s), InvalidArgument);  // too few
  s.vertices = 100'000'000;
  EXPECT_THROW(requested_vertex_count(m, s), InvalidArgument);  // absurdly many
  s.vertices = 0;
  s.edge_length = -0.1;
  EXPECT_THROW(requested_vertex_count(m, s), InvalidArgument);
  s.edge_length = 1e-6;
  EXPECT_THROW(requested_vertex_count(m, s), InvalidArgument);  // ≈ 10¹³ vertices
  s.edge_length = 0.1;
  const double expected = surface_area(m) / (std::sqrt(3.0) / 2 * 0.01);
  EXPECT_NEAR(static_cast<double>(requested_vertex_count(m, s)), expected, 1.0);
  s.edge_length_rel = 0.05;
  EXPECT_THROW(requested_vertex_count(m, s), InvalidArgument);  // two sizes
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// Issue 22: the same shape in any units. A torus scaled by 2^k is remeshed exactly as the
// unscaled one, up to that scale, bit for bit: the remesher works on the input scaled by a
// power of two to unit size, which is exact. An edge length in input units scales with it.
TEST(RemeshScale, AShapeScaledByAPowerOfTwoGivesTheSameOutputScaled) {
  const TriangleMesh shape = torus(1, 0.4, 48, 20);
  RemeshSettings s;
  s.edge_length = 0.25;
  s.hausdorff = HausdorffSettings{.samples = 2000};
  const RemeshResult unit = remesh(shape, s);
  ASSERT_GT(unit.mesh.vertices.size(), 100u);
  for (const int k : {-600, -20, 20, 600}) {
    const TriangleMesh scaled = scaled_by_power_of_two(shape, k);
    RemeshSettings sk = s;
    sk.edge_length = std::ldexp(s.edge_length, k);
    const RemeshResult r = remesh(scaled, sk);
    ASSERT_EQ(r.mesh.vertices.size(), unit.mesh.vertices.size()) << "2^" << k;
    EXPECT_EQ(r.mesh.triangles, unit.mesh.triangles) << "2^" << k;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < r.mesh.vertices.size(); ++i) {
      const Vec3& a = r.mesh.vertices[i];
      const Vec3& b = unit.mesh.vertices[i];
      differing += a != scaled_by_power_of_two(b, k);
    }
    EXPECT_EQ(differing, 0u) << "2^" << k;
    const QualityReport q = measure_quality(r.mesh);
    EXPECT_EQ(q.q_min, measure_quality(unit.mesh).q_min) << "2^" << k;
    ASSERT_TRUE(r.hausdorff);
    EXPECT_EQ(r.hausdorff->max_pct(), unit.hausdorff->max_pct()) << "2^" << k;
    EXPECT_EQ(r.hausdorff->max, std::ldexp(unit.hausdorff->max, k)) << "2^" << k;
  }
}

}  // namespace
}  // namespace cvtmesh
