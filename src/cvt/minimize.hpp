// Minimising the CVT energy over the seeds: L-BFGS (liblbfgs; paper §4.2) or Lloyd's iteration.
#pragma once

#include <chrono>
#include <vector>

#include "cvt/cvt_objective.hpp"
#include "cvtmesh/remesh.hpp"

namespace cvtmesh {

// Evaluations one L-BFGS line search may take. Near a minimum, rounding, and in CCVT the kinks
// where a curve seed passes a polyline vertex, leave no step that the Wolfe conditions accept;
// liblbfgs's default of 20 trials then spent up to 20 RVD passes to end the phase where it stood
// (lion.off at 5k: 22 of its 101). An accepted step takes 1 or 2 nearly always. On the corpus (57
// meshes at 1k/5k/10k, 171 runs) this cap changed θmin or Qmin on 7 runs and cut the evaluations
// by 3.6%: lion.off at 5k 101 → 79, stanford-bunny.obj at 10k 65 → 53; no run fell under issue
// 18's quality bar (man.off at 1k came out another way: θmin 15.1° → 37.2°, but its Hausdorff
// mean 0.080% → 0.133%, where the last step now closes holes at its crossing fingers).
constexpr int kMaxLineSearch = 5;

struct PhaseOptions {
  const char* name;  // "rcvt" or "ccvt", for progress reports
  int max_iterations;
  double gradient_tolerance;  // relative to the phase's initial gradient norm
  const std::function<void(const RemeshProgress&)>* progress;
  std::chrono::steady_clock::time_point start;  // of the whole remesh, for elapsed times
};

struct PhaseResult {
  int iterations = 0;
  double energy_initial = 0, energy_final = 0, gradient_initial = 0, gradient_final = 0;
  std::vector<double> energies;  // after each accepted iteration
};

PhaseResult minimize_lbfgs(CvtObjective& objective, std::vector<Vec3>& seeds,
                           const PhaseOptions& o);
PhaseResult minimize_lloyd(CvtObjective& objective, std::vector<Vec3>& seeds,
                           const PhaseOptions& o);

}  // namespace cvtmesh
