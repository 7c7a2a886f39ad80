// Minimising the CVT energy over the seeds: L-BFGS (liblbfgs; paper §4.2) or Lloyd's iteration.
#pragma once

#include <chrono>
#include <vector>

#include "cvt/cvt_objective.hpp"
#include "cvtmesh/remesh.hpp"

namespace cvtmesh {

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
