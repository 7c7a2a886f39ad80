#include "cvt/minimize.hpp"

#include <lbfgs.h>

#include <cmath>
#include <stdexcept>

namespace cvtmesh {

namespace {

double norm_of(const std::vector<Vec3>& g) {
  double s = 0;
  for (const Vec3& v : g) s += dot(v, v);
  return std::sqrt(s);
}

void report(const PhaseOptions& o, int iteration, double energy, double gradient) {
  if (!o.progress || !*o.progress) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - o.start).count();
  (*o.progress)({o.name, iteration, energy, gradient, elapsed});
}

// liblbfgs calls back through a void*: this is what it points to.
struct LbfgsState {
  CvtObjective& objective;
  std::vector<Vec3>& seeds;
  const PhaseOptions& options;
  PhaseResult& result;
};

lbfgsfloatval_t evaluate(void* instance, const lbfgsfloatval_t* x, lbfgsfloatval_t* g, int n,
                         lbfgsfloatval_t) {
  auto& s = *static_cast<LbfgsState*>(instance);
  for (int k = 0; k < n / 3; ++k) s.seeds[k] = {x[3 * k], x[3 * k + 1], x[3 * k + 2]};
  const CvtObjective::Evaluation e = s.objective(s.seeds);
  for (int k = 0; k < n / 3; ++k)
    g[3 * k] = e.gradient[k].x, g[3 * k + 1] = e.gradient[k].y, g[3 * k + 2] = e.gradient[k].z;
  if (s.objective.evaluations() == 1) {  // the phase's starting point
    s.result.energy_initial = e.energy;
    s.result.gradient_initial = norm_of(e.gradient);
  }
  return e.energy;
}

int progress(void* instance, const lbfgsfloatval_t*, const lbfgsfloatval_t*, lbfgsfloatval_t fx,
             lbfgsfloatval_t, lbfgsfloatval_t gnorm, lbfgsfloatval_t, int, int k, int) {
  auto& s = *static_cast<LbfgsState*>(instance);
  s.result.iterations = k;
  s.result.energies.push_back(fx);
  s.result.energy_final = fx;
  s.result.gradient_final = gnorm;
  report(s.options, k, fx, gnorm);
  // Non-zero stops liblbfgs: the relative gradient tolerance is met.
  return gnorm <= s.options.gradient_tolerance * s.result.gradient_initial ? 1 : 0;
}

}  // namespace

PhaseResult minimize_lbfgs(CvtObjective& objective, std::vector<Vec3>& seeds,
                           const PhaseOptions& o) {
  PhaseResult result;
  if (o.max_iterations <= 0) return result;
  const int n = static_cast<int>(3 * seeds.size());
  lbfgsfloatval_t* x = lbfgs_malloc(n);
  if (!x) throw std::bad_alloc();
  for (std::size_t k = 0; k < seeds.size(); ++k)
    x[3 * k] = seeds[k].x, x[3 * k + 1] = seeds[k].y, x[3 * k + 2] = seeds[k].z;
  lbfgs_parameter_t parameters;
  lbfgs_parameter_init(&parameters);
  parameters.m = 7;        // history pairs, as in Liu et al. 2009 (paper's [LWL*09])
  parameters.epsilon = 0;  // stopping is ours (relative gradient), in `progress`
  parameters.max_iterations = o.max_iterations;
  parameters.max_linesearch = 20;
  LbfgsState state{objective, seeds, o, result};
  lbfgsfloatval_t fx = 0;
  const int status = lbfgs(n, x, &fx, evaluate, progress, &state, &parameters);
  // liblbfgs leaves x at its best point; a line search that cannot progress (rounding) is a
  // normal end this close to a minimum, not an error.
  (void)status;
  for (std::size_t k = 0; k < seeds.size(); ++k) seeds[k] = {x[3 * k], x[3 * k + 1], x[3 * k + 2]};
  lbfgs_free(x);
  if (result.energies.empty()) result.energy_final = result.energy_initial;
  return result;
}

PhaseResult minimize_lloyd(CvtObjective& objective, std::vector<Vec3>& seeds,
                           const PhaseOptions& o) {
  PhaseResult result;
  for (int k = 0; k <= o.max_iterations; ++k) {
    const CvtObjective::Evaluation e = objective(seeds);
    const double g = norm_of(e.gradient);
    if (k == 0)
      result.energy_initial = e.energy, result.gradient_initial = g;
    else {
      result.iterations = k;
      result.energies.push_back(e.energy);
      report(o, k, e.energy, g);
    }
    result.energy_final = e.energy;
    result.gradient_final = g;
    if (k == o.max_iterations || g <= o.gradient_tolerance * result.gradient_initial) break;
    seeds = e.centroids;  // x_i ← c_i
  }
  return result;
}

}  // namespace cvtmesh
