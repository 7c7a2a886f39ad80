// The remeshing pipeline (paper §4): initial seeds, RCVT then CCVT, restricted Delaunay output.
#include "cvtmesh/remesh.hpp"

#include <chrono>
#include <cmath>

#include "cvt/minimize.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/sampling.hpp"

namespace cvtmesh {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

constexpr std::size_t kMaxVertices = 50'000'000;

}  // namespace

std::size_t requested_vertex_count(const TriangleMesh& mesh, const RemeshSettings& s) {
  const int given = (s.vertices > 0) + (s.edge_length != 0) + (s.edge_length_rel != 0);
  if (given != 1)
    throw InvalidArgument(
        "give exactly one output size: a vertex count, an edge length, or a relative edge length");
  double count = static_cast<double>(s.vertices);
  if (s.vertices == 0) {
    const double h =
        s.edge_length != 0 ? s.edge_length : s.edge_length_rel * bounding_box(mesh).diagonal();
    if (!(h > 0) || !std::isfinite(h)) throw InvalidArgument("the edge length must be positive");
    // Equilateral triangles of side h, about two per vertex: V ≈ A / (√3/2 · h²).
    count = std::round(surface_area(mesh) / (std::sqrt(3.0) / 2 * h * h));
  }
  if (count < 4)
    throw InvalidArgument("the output would have " + std::to_string(static_cast<long long>(count)) +
                          " vertices; at least 4 are needed");
  if (count > static_cast<double>(kMaxVertices))
    throw InvalidArgument("the output would have " + std::to_string(static_cast<long long>(count)) +
                          " vertices, more than the limit of 50 million");
  return static_cast<std::size_t>(count);
}

RemeshResult remesh(const TriangleMesh& mesh, const RemeshSettings& settings) {
  const auto start = Clock::now();
  if (settings.iterations < 0) throw InvalidArgument("the iteration cap must not be negative");
  if (!(settings.gradient_tolerance > 0))
    throw InvalidArgument("the gradient tolerance must be positive");
  if (!(surface_area(mesh) > 0)) throw InputError("the surface has no area");
  RemeshResult result;
  std::vector<Vec3> seeds =
      settings.initial_seeds.empty()
          ? sample_surface(mesh, requested_vertex_count(mesh, settings), settings.seed)
          : settings.initial_seeds;
  const SurfaceProjector projector(mesh);
  result.seconds_initialization = seconds(start);

  auto run_phase = [&](const char* name, bool constrained, double& phase_seconds) {
    const auto phase_start = Clock::now();
    CvtObjective objective(mesh, projector, constrained);
    const PhaseOptions options{name, settings.iterations, settings.gradient_tolerance,
                               &settings.progress, start};
    const PhaseResult phase = settings.optimizer == Optimizer::lbfgs
                                  ? minimize_lbfgs(objective, seeds, options)
                                  : minimize_lloyd(objective, seeds, options);
    if (result.rvd_evaluations == 0) {
      result.energy_initial = phase.energy_initial;
      result.gradient_norm_initial = phase.gradient_initial;
    }
    result.rvd_evaluations += objective.evaluations();
    result.iterations += phase.iterations;
    result.energy_final = phase.energy_final;
    result.gradient_norm_final = phase.gradient_final;
    result.energies.insert(result.energies.end(), phase.energies.begin(), phase.energies.end());
    phase_seconds = seconds(phase_start);
  };
  if (settings.mode != CvtMode::ccvt) run_phase("rcvt", false, result.seconds_rcvt);
  if (settings.mode != CvtMode::rcvt) run_phase("ccvt", true, result.seconds_ccvt);

  // Output vertices lie on the surface: project (a no-op after CCVT), then triangulate.
  const auto extraction_start = Clock::now();
  CvtObjective(mesh, projector, true).project(seeds);
  const RestrictedVoronoiDiagram rvd(mesh, seeds);
  RestrictedDelaunayBuilder rdt(rvd);
  rvd.traverse(rdt);
  result.mesh = rdt.result();
  repair_mesh(result.mesh);  // drops seeds whose cells are empty
  result.seconds_extraction = seconds(extraction_start);
  return result;
}

}  // namespace cvtmesh
