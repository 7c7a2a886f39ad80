#include "remesh/by_component.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "features/curve_projector.hpp"
#include "features/curve_spacing.hpp"
#include "features/feature_seeds.hpp"
#include "features/renumber_features.hpp"
#include "geometry/surface_projector.hpp"
#include "geometry/union_find.hpp"
#include "quality/hausdorff_with_tree.hpp"
#include "remesh/edge_length_ratio.hpp"
#include "remesh/pipeline.hpp"

namespace cvtmesh {

namespace {

// The fewest vertices remesh_unit accepts (a tetrahedron's).
constexpr std::size_t kFewestVertices = 4;

struct Component {
  TriangleMesh mesh;
  std::vector<Index> input_vertex;  // per vertex of `mesh`: its id in the whole
  double area = 0;
};

// Connected components (triangles sharing a vertex), ordered by their first triangle.
std::vector<Component> split_components(const TriangleMesh& mesh) {
  UnionFind sets(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles) sets.unite(t[0], t[1]), sets.unite(t[0], t[2]);
  constexpr Index kNone = std::numeric_limits<Index>::max();
  std::vector<Index> component_of_root(mesh.vertices.size(), kNone);
  std::vector<Index> local(mesh.vertices.size(), kNone);  // a vertex's id in its component
  std::vector<Component> parts;
  for (const Triangle& t : mesh.triangles) {
    Index& c = component_of_root[sets.find(t[0])];
    if (c == kNone) {
      c = static_cast<Index>(parts.size());
      parts.emplace_back();
    }
    Component& part = parts[c];
    Triangle mapped;
    for (int k = 0; k < 3; ++k) {
      if (local[t[k]] == kNone) {
        local[t[k]] = static_cast<Index>(part.input_vertex.size());
        part.input_vertex.push_back(t[k]);
        part.mesh.vertices.push_back(mesh.vertices[t[k]]);
      }
      mapped[k] = local[t[k]];
    }
    part.mesh.triangles.push_back(mapped);
  }
  for (Component& part : parts) part.area = surface_area(part.mesh);
  return parts;
}

// `total` shared in proportion to `weights` (largest remainders, ties to the first), summing to
// `total`.
std::vector<std::size_t> apportion(std::size_t total, const std::vector<double>& weights) {
  const double sum = std::accumulate(weights.begin(), weights.end(), 0.0);
  std::vector<std::size_t> share(weights.size());
  std::vector<double> remainder(weights.size());
  std::size_t given = 0;
  for (std::size_t c = 0; c < weights.size(); ++c) {
    const double exact = static_cast<double>(total) * weights[c] / sum;
    share[c] = static_cast<std::size_t>(std::floor(exact));
    remainder[c] = exact - std::floor(exact);
    given += share[c];
  }
  std::vector<std::size_t> order(weights.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t k = 0; given < total && k < order.size(); ++k, ++given) ++share[order[k]];
  return share;
}

// At least `count`, and more than the feature seeds the component's features want at the
// spacing that count gives it (which shrinks as the count grows, so this settles in a few steps;
// curve seeds grow with the square root of the count).
std::size_t enough_for_features(const Component& part, const FeatureSettings& settings,
                                std::size_t count) {
  const TriangleMesh& mesh = part.mesh;
  count = std::max(count, kFewestVertices);
  const Features features = detect_features(mesh, settings);
  if (features.empty()) return count;
  const CurveProjector curves(mesh, features);
  const double area = part.area;
  for (int step = 0; step < 16; ++step) {
    const std::size_t need =
        feature_seed_count(features, curves, CurveSpacing(edge_length_for(area, count))) + 1;
    if (need <= count) break;
    count = need;
  }
  return count;
}

// Per component, the settings of its own remesh: its share of the count (or, for lengths given
// without one, its lengths), its user feature edges, the features' scale of the whole, no
// Hausdorff distance (measured on the whole), progress for the largest only.
std::vector<RemeshSettings> component_settings(const TriangleMesh& mesh,
                                               const std::vector<Component>& parts,
                                               const RemeshSettings& settings) {
  std::vector<RemeshSettings> all(parts.size(), settings);
  constexpr Index kNone = std::numeric_limits<Index>::max();  // on no component with area
  std::vector<Index> component(mesh.vertices.size(), kNone), local(mesh.vertices.size());
  for (Index c = 0; c < parts.size(); ++c)
    for (Index v = 0; v < parts[c].input_vertex.size(); ++v) {
      component[parts[c].input_vertex[v]] = c;
      local[parts[c].input_vertex[v]] = v;
    }
  for (RemeshSettings& s : all) {
    s.hausdorff.reset();
    s.features.user_edges.clear();
    s.sizing.edge_lengths.clear();
  }
  if (!settings.features.user_edges.empty()) {
    // Checked on the whole, so that an error names the caller's vertex ids; an edge of the mesh
    // lies in one component.
    FeatureSettings check = settings.features;
    check.sharp_edges = false;
    detect_features(mesh, check);
  }
  for (const Edge& e : settings.features.user_edges) {
    if (component[e[0]] == kNone) continue;  // on a component without area: nothing to keep
    const Index a = local[e[0]], b = local[e[1]];
    all[component[e[0]]].features.user_edges.push_back({std::min(a, b), std::max(a, b)});
  }
  if (!settings.sizing.edge_lengths.empty())
    for (Index c = 0; c < parts.size(); ++c)
      for (const Index v : parts[c].input_vertex)
        all[c].sizing.edge_lengths.push_back(settings.sizing.edge_lengths[v]);

  const bool lengths_as_given = settings.sizing.active() && settings.vertices == 0 &&
                                settings.edge_length == 0 && settings.edge_length_rel == 0;
  if (!lengths_as_given) {
    const std::size_t total = requested_vertex_count(mesh, settings);
    std::vector<double> areas;
    for (const Component& part : parts) areas.push_back(part.area);
    const std::vector<std::size_t> counts = apportion(total, areas);
    // Features at the scale of the whole output, in every component alike.
    const double spacing = edge_length_for(surface_area(mesh), total);
    for (Index c = 0; c < parts.size(); ++c) {
      RemeshSettings& s = all[c];
      if (s.features.scale == 0) s.features.scale = spacing;
      s.vertices = settings.mode == CvtMode::rcvt
                       ? std::max(counts[c], kFewestVertices)
                       : enough_for_features(parts[c], s.features, counts[c]);
      s.edge_length = s.edge_length_rel = 0;
    }
  }
  std::size_t largest = 0;
  for (Index c = 1; c < parts.size(); ++c)
    if (parts[c].mesh.triangles.size() > parts[largest].mesh.triangles.size()) largest = c;
  for (Index c = 0; c < parts.size(); ++c)
    if (c != largest) all[c].progress = nullptr;
  return all;
}

// Appends one component's output to the whole's. Counts add up; rounds are the most any
// component took; energies add up (integrals over disjoint surfaces), iteration by iteration, a
// component that stopped early counting at its last energy.
void append(RemeshResult& all, RemeshResult part, const Component& component,
            double& gradient2_initial, double& gradient2_final) {
  const auto offset = static_cast<Index>(all.mesh.vertices.size());
  all.mesh.vertices.insert(all.mesh.vertices.end(), part.mesh.vertices.begin(),
                           part.mesh.vertices.end());
  for (Triangle t : part.mesh.triangles) {
    for (Index& v : t) v += offset;
    all.mesh.triangles.push_back(t);
  }
  all.iterations += part.iterations;
  all.rvd_evaluations += part.rvd_evaluations;
  all.energy_initial += part.energy_initial;
  all.energy_final += part.energy_final;
  gradient2_initial += part.gradient_norm_initial * part.gradient_norm_initial;
  gradient2_final += part.gradient_norm_final * part.gradient_norm_final;
  all.seconds_initialization += part.seconds_initialization;
  all.seconds_rcvt += part.seconds_rcvt;
  all.seconds_ccvt += part.seconds_ccvt;
  all.seconds_extraction += part.seconds_extraction;
  const double last_all = all.energies.empty() ? 0 : all.energies.back();
  const double last_part = part.energies.empty() ? 0 : part.energies.back();
  const std::size_t n = std::max(all.energies.size(), part.energies.size());
  all.energies.resize(n, last_all);
  for (std::size_t k = 0; k < n; ++k)
    all.energies[k] += k < part.energies.size() ? part.energies[k] : last_part;
  all.defects_polished += part.defects_polished;
  all.polish_rounds = std::max(all.polish_rounds, part.polish_rounds);
  const Features features = renumbered(part.features, component.input_vertex);
  all.features.edges.insert(all.features.edges.end(), features.edges.begin(), features.edges.end());
  all.features.corners.insert(all.features.corners.end(), features.corners.begin(),
                              features.corners.end());
  all.features.curves.insert(all.features.curves.end(), features.curves.begin(),
                             features.curves.end());
  for (Edge e : part.feature_edges) all.feature_edges.push_back({e[0] + offset, e[1] + offset});
  all.feature_edges_missing += part.feature_edges_missing;
  all.links_mended += part.links_mended;
  all.islands_seeded += part.islands_seeded;
  all.seeds_refined += part.seeds_refined;
  for (const Index v : part.vertices_added) all.vertices_added.push_back(v + offset);
  all.links_flipped += part.links_flipped;
  all.tips_closed += part.tips_closed;
  all.mend_rounds = std::max(all.mend_rounds, part.mend_rounds);
  all.triangles_removed += part.triangles_removed;
  all.time_limit_reached |= part.time_limit_reached;
}

}  // namespace

RemeshResult remesh_by_component(const TriangleMesh& mesh, const RemeshSettings& settings) {
  if (!settings.initial_seeds.empty()) return remesh_unit(mesh, settings).result;
  std::vector<Component> parts = split_components(mesh);
  // A component without area (degenerate triangles only) has nothing to remesh: the whole
  // gives it no seed either.
  std::erase_if(parts, [](const Component& part) { return !(part.area > 0); });
  if (parts.size() <= 1) return remesh_unit(mesh, settings).result;

  const auto start = std::chrono::steady_clock::now();
  std::vector<RemeshSettings> part_settings = component_settings(mesh, parts, settings);
  RemeshResult all;
  std::vector<double> ratios;
  double gradient2_initial = 0, gradient2_final = 0;
  for (std::size_t c = 0; c < parts.size(); ++c) {
    RemeshSettings& s = part_settings[c];
    if (settings.time_limit > 0) {
      // What is left of the limit; a component that starts after it works not at all (its
      // seeds as sampled make its output), as the whole would.
      const double spent =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      s.time_limit = std::max(settings.time_limit - spent, 1e-9);
    }
    UnitRemesh part = remesh_unit(parts[c].mesh, s);
    ratios.insert(ratios.end(), part.edge_ratios.begin(), part.edge_ratios.end());
    append(all, std::move(part.result), parts[c], gradient2_initial, gradient2_final);
  }
  all.gradient_norm_initial = std::sqrt(gradient2_initial);
  all.gradient_norm_final = std::sqrt(gradient2_final);
  std::sort(all.features.edges.begin(), all.features.edges.end());
  std::sort(all.features.corners.begin(), all.features.corners.end());
  std::sort(all.feature_edges.begin(), all.feature_edges.end());
  all.input_topology = analyze_topology(mesh);
  all.edge_length_ratio = ratio_percentiles(std::move(ratios));
  if (settings.hausdorff && !all.mesh.triangles.empty())
    all.hausdorff = hausdorff_distance(all.mesh, mesh, SurfaceProjector(mesh), *settings.hausdorff);
  return all;
}

}  // namespace cvtmesh
