#include "cvt/minimize.hpp"

#include <lbfgs.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>

#include "cvtmesh/errors.hpp"
#include "system/elapsed.hpp"

namespace cvtmesh {

namespace {

double norm_of(const std::vector<Vec3>& g) {
  double s = 0;
  for (const Vec3& v : g) s += dot(v, v);
  return std::sqrt(s);
}

void report(const PhaseOptions& o, int iteration, double energy, double gradient) {
  if (!o.progress || !*o.progress) return;
  (*o.progress)({o.name, iteration, energy, gradient, seconds_since(o.start)});
}

// liblbfgs calls back through a void*: this is what it points to. liblbfgs works on
// y_k = x_k / (scale · weight_k) (see minimize_lbfgs; no weights: all 1); `first` is the
// evaluation at the starting point, made before liblbfgs starts and handed over at its first
// call, which is always at that point.
struct LbfgsState {
  CvtObjective& objective;
  std::vector<Vec3>& seeds;
  const PhaseOptions& options;
  PhaseResult& result;
  double scale;
  std::optional<CvtObjective::Evaluation> first;
  // A cancel thrown during an evaluation: exceptions must not unwind through liblbfgs's C code,
  // so it is kept here, liblbfgs is made to stop, and it is thrown again once it has.
  std::exception_ptr cancelled;
  std::vector<double> weight;
  double gradient_norm = 0;  // |dF/dx| at the last evaluation, with weights
  double factor(int k) const { return weight.empty() ? scale : scale * weight[k]; }
};

lbfgsfloatval_t evaluate(void* instance, const lbfgsfloatval_t* y, lbfgsfloatval_t* g, int n,
                         lbfgsfloatval_t) {
  auto& s = *static_cast<LbfgsState*>(instance);
  CvtObjective::Evaluation e;
  if (s.first) {
    e = std::move(*s.first);
    s.first.reset();
  } else {
    if (s.cancelled) return std::numeric_limits<double>::infinity();  // the line search fails
    for (int k = 0; k < n / 3; ++k)
      s.seeds[k] = s.factor(k) * Vec3{y[3 * k], y[3 * k + 1], y[3 * k + 2]};
    try {
      e = s.objective(s.seeds);
    } catch (const Cancelled&) {
      s.cancelled = std::current_exception();
      return std::numeric_limits<double>::infinity();
    }
  }
  for (int k = 0; k < n / 3; ++k) {
    const Vec3 gy = s.factor(k) * e.gradient[k];  // dF/dy = scale · weight · dF/dx
    g[3 * k] = gy.x, g[3 * k + 1] = gy.y, g[3 * k + 2] = gy.z;
  }
  if (!s.weight.empty()) s.gradient_norm = norm_of(e.gradient);
  return e.energy;
}

int progress(void* instance, const lbfgsfloatval_t*, const lbfgsfloatval_t*, lbfgsfloatval_t fx,
             lbfgsfloatval_t, lbfgsfloatval_t gnorm_y, lbfgsfloatval_t, int, int k, int) {
  auto& s = *static_cast<LbfgsState*>(instance);
  // The accepted point is the line search's last evaluation.
  const double gnorm = s.weight.empty() ? gnorm_y / s.scale : s.gradient_norm;
  s.result.iterations = k;
  s.result.energies.push_back(fx);
  s.result.energy_final = fx;
  s.result.gradient_final = gnorm;
  report(s.options, k, fx, gnorm);
  // Non-zero stops liblbfgs: the relative gradient tolerance is met, or the time is up.
  if (s.cancelled) return 1;
  try {
    if (s.objective.interrupt().out_of_time()) return 1;
  } catch (const Cancelled&) {
    s.cancelled = std::current_exception();
    return 1;
  }
  return gnorm <= s.options.gradient_tolerance * s.result.gradient_initial ? 1 : 0;
}

// With a density, the cells' masses m_k differ by orders of magnitude, and F's Hessian (about
// 2 m_k per seed) with them: L-BFGS, scaled alike for all seeds, converges slowly (igea.ply at
// 2k, --adaptive: 342 triangles left below 35° after 20 iterations, 2 with ρ = 1). Weights
// √(m̄ / m_k) make every seed's gradient step a Lloyd step (x_k → c_k = x_k - ∇_k F / 2m_k):
// a diagonal preconditioner, as a change of variables. Bounded to 1/10..10; 1 for empty cells.
std::vector<double> lloyd_weights(const std::vector<double>& masses) {
  double sum = 0;
  std::size_t count = 0;
  for (const double m : masses)
    if (m > 0) sum += m, ++count;
  std::vector<double> weight(masses.size(), 1.0);
  if (count == 0) return weight;
  const double mean = sum / static_cast<double>(count);
  for (std::size_t k = 0; k < masses.size(); ++k)
    if (masses[k] > 0) weight[k] = std::clamp(std::sqrt(mean / masses[k]), 0.1, 10.0);
  return weight;
}

}  // namespace

PhaseResult minimize_lbfgs(CvtObjective& objective, std::vector<Vec3>& seeds,
                           const PhaseOptions& o) {
  PhaseResult result;
  if (o.max_iterations <= 0) return result;
  LbfgsState state{objective, seeds, o, result, 1.0, objective(seeds), nullptr, {}};
  result.energy_initial = state.first->energy;
  result.gradient_initial = norm_of(state.first->gradient);
  // liblbfgs tries a first step of unit length along -∇F. Scaling the variables by the length
  // of a Lloyd step (x_i → c_i) makes that first trial a Lloyd-sized step: without it, the
  // first line search of each phase costs several RVD evaluations.
  double lloyd = 0;
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const Vec3 d = state.first->centroids[k] - seeds[k];
    lloyd += dot(d, d);
  }
  if (lloyd > 0) state.scale = std::sqrt(lloyd);
  if (objective.density()) state.weight = lloyd_weights(state.first->masses);
  const int n = static_cast<int>(3 * seeds.size());
  lbfgsfloatval_t* y = lbfgs_malloc(n);
  if (!y) throw std::bad_alloc();
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const Vec3 yk = (1 / state.factor(static_cast<int>(k))) * seeds[k];
    y[3 * k] = yk.x, y[3 * k + 1] = yk.y, y[3 * k + 2] = yk.z;
  }
  lbfgs_parameter_t parameters;
  lbfgs_parameter_init(&parameters);
  parameters.m = 7;        // history pairs, as in Liu et al. 2009 (paper's [LWL*09])
  parameters.epsilon = 0;  // stopping is ours (relative gradient), in `progress`
  parameters.max_iterations = o.max_iterations;
  parameters.max_linesearch = kMaxLineSearch;
  lbfgsfloatval_t fx = 0;
  const int status = lbfgs(n, y, &fx, evaluate, progress, &state, &parameters);
  // liblbfgs leaves y at its best point; a line search that cannot progress (rounding) is a
  // normal end this close to a minimum, not an error.
  (void)status;
  for (std::size_t k = 0; k < seeds.size(); ++k)
    seeds[k] = state.factor(static_cast<int>(k)) * Vec3{y[3 * k], y[3 * k + 1], y[3 * k + 2]};
  lbfgs_free(y);
  if (state.cancelled) std::rethrow_exception(state.cancelled);
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
    if (k == o.max_iterations || g <= o.gradient_tolerance * result.gradient_initial ||
        objective.interrupt().out_of_time())
      break;
    seeds = e.centroids;  // x_i ← c_i
  }
  return result;
}

}  // namespace cvtmesh
