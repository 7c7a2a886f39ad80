// The L-BFGS phases: a line search that finds no acceptable step ends the phase within
// kMaxLineSearch RVD passes.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>

#include "cvt/cvt_objective.hpp"
#include "cvt/minimize.hpp"
#include "cvtmesh/sampling.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// RCVT of 20 seeds on a sphere with no gradient tolerance runs until rounding leaves no step
// that lowers the energy (about 480 iterations); liblbfgs's default would then spend 20 passes on
// the last line search.
TEST(Minimize, ALineSearchThatFindsNoStepEndsThePhaseWithinTheCap) {
  const TriangleMesh sphere = icosphere(3);
  CvtObjective objective(sphere, nullptr);
  std::vector<Vec3> seeds = sample_surface(sphere, 20, 7);
  int at_last_step = 0;
  const std::function<void(const RemeshProgress&)> progress = [&](const RemeshProgress&) {
    at_last_step = objective.evaluations();
  };
  const int cap = 5000;
  const PhaseOptions options{"rcvt", cap, 1e-300, &progress, std::chrono::steady_clock::now()};
  const PhaseResult result = minimize_lbfgs(objective, seeds, options);
  ASSERT_LT(result.iterations, cap);  // it ended on a line search, not on the cap
  EXPECT_LT(result.energy_final, result.energy_initial);
  EXPECT_GE(objective.evaluations() - at_last_step, 1);
  EXPECT_LE(objective.evaluations() - at_last_step, kMaxLineSearch);
}

}  // namespace
}  // namespace cvtmesh
