#include "remesh/by_component.hpp"

#include <tbb/parallel_for_each.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <numeric>
#include <optional>
#include <tuple>

#include "cvtmesh/quality.hpp"
#include "cvtmesh/topology.hpp"
#include "features/curve_projector.hpp"
#include "features/curve_spacing.hpp"
#include "features/edge_uses.hpp"
#include "features/feature_seeds.hpp"
#include "features/renumber_features.hpp"
#include "geometry/even_spacing.hpp"
#include "geometry/self_crossings.hpp"
#include "geometry/surface_projector.hpp"
#include "geometry/triangle_sides.hpp"
#include "geometry/union_find.hpp"
#include "quality/hausdorff_with_tree.hpp"
#include "remesh/branch_curves.hpp"
#include "remesh/edge_length_ratio.hpp"
#include "remesh/flip_links.hpp"
#include "remesh/pipeline.hpp"
#include "remesh/topology_first.hpp"
#include "remesh/zip_sheets.hpp"
#include "sizing/size_field.hpp"
#include "system/elapsed.hpp"

namespace cvtmesh {

namespace {

// The fewest vertices remesh_unit accepts (a tetrahedron's).
constexpr std::size_t kFewestVertices = 4;

struct Component {
  TriangleMesh mesh;
  std::vector<Index> input_vertex;  // per vertex of `mesh`: its id in the whole
  std::vector<Index> pinches;       // vertices (of `mesh`) that other components have too
  std::vector<Edge> branch_edges;   // its edges (of `mesh`) that are edges of three or more
                                    // triangles in the whole
  double area = 0;
};

// Whether the triangles joined in `sets` make one component whose vertices each lie in one fan,
// but those on edges of three or more triangles (`branching`), which have a copy per component:
// then the whole is its one part, without pinches, and split_components makes no copy of it.
bool one_part_without_pinches(const TriangleMesh& mesh, UnionFind& sets, UnionFind& fans,
                              const std::vector<bool>& branching) {
  const std::size_t triangles = mesh.triangles.size();
  for (std::size_t t = 1; t < triangles; ++t)
    if (sets.find(t) != sets.find(0)) return false;
  const std::size_t corners = 3 * triangles, none = corners;  // fans are named by corners
  std::vector<std::size_t> fan_of(mesh.vertices.size(), none);
  for (std::size_t c = 0; c < corners; ++c) {
    const Index v = mesh.triangles[c / 3][c % 3];
    if (branching[v]) continue;
    const std::size_t root = fans.find(c);
    if (fan_of[v] == none)
      fan_of[v] = root;
    else if (fan_of[v] != root)
      return false;
  }
  return true;
}

// Connected components (triangles sharing an edge), ordered by their first triangle. A vertex
// where components touch (a non-manifold vertex, as where two cones meet tip to tip) is in each
// of them, as one of their `pinches`. So is one where sheets of a component touch (its triangles
// in several fans, joined across edges of two triangles, and no edge of three or more there): it
// has a copy per fan. Each pinch is remeshed as a corner, and the copies welded in the output.
//
// With `passed_by` (per vertex, one on a junction curve that no sheet keeps: see
// resample_branch_curves), the parts are sheets instead: triangles joined across edges of exactly
// two triangles. An edge of three or more triangles (where sheets meet, as in a T or a flap glued
// to a surface) parts them, so that no seed of one sheet owns another's surface however shallow
// the angle between them; the triangles of one sheet there stay joined (a sphere with a flap glued
// along two edges is a sphere and a flap, not a sphere slit open, whose two sides no seed tells
// apart), and a sheet touching itself there stays non-manifold, remeshed as a whole mesh is. Every
// vertex has a copy per fan, the junction's vertices (but those passed by) are pinches, and its
// edges are each part's `branch_edges`.
// Without `passed_by`, none where the whole is one part without pinches (most inputs): a copy of
// it would only be freed again (igea.ply: 35 of the 107 ms that splitting took). `sides`: the
// mesh's sorted_sides where the caller has them (empty: found here).
std::vector<Component> split_components(const TriangleMesh& mesh,
                                        const std::vector<bool>* passed_by,
                                        std::vector<TriangleSide> sides) {
  const std::size_t triangles = mesh.triangles.size();
  UnionFind sets(triangles), fans(3 * triangles);
  std::vector<bool> branching(mesh.vertices.size(), false);
  if (sides.empty()) sides = sorted_sides(mesh);
  const auto corner = [&](std::size_t t, Index v) {
    const Triangle& f = mesh.triangles[t];
    return 3 * t + static_cast<std::size_t>(f[0] == v ? 0 : f[1] == v ? 1 : 2);
  };
  std::vector<Edge> branch;  // edges of three or more triangles, sorted
  for_each_side_run(sides, [&](std::size_t i, std::size_t j) {
    if (!passed_by)
      for (std::size_t k = i + 1; k < j; ++k) sets.unite(sides[k].triangle, sides[i].triangle);
    if (passed_by && j - i > 2) {  // undone: the edge's triangles join as sheets only
      branch.push_back({sides[i].lo, sides[i].hi});
      return;
    }
    for (const Index v : {sides[i].lo, sides[i].hi}) {
      if (j - i == 2) fans.unite(corner(sides[i].triangle, v), corner(sides[i + 1].triangle, v));
      if (j - i > 2) branching[v] = true;
    }
  });
  if (passed_by) {
    // Sheets: triangles joined across edges of two triangles; then one sheet's triangles on a
    // junction edge joined in their fans.
    for_each_side_run(sides, [&](std::size_t i, std::size_t j) {
      if (j - i == 2) sets.unite(sides[i + 1].triangle, sides[i].triangle);
    });
    for_each_side_run(sides, [&](std::size_t i, std::size_t j) {
      if (j - i <= 2) return;
      for (std::size_t k = i; k < j; ++k)
        for (std::size_t l = k + 1; l < j; ++l)
          if (sets.find(sides[k].triangle) == sets.find(sides[l].triangle))
            for (const Index v : {sides[i].lo, sides[i].hi})
              fans.unite(corner(sides[k].triangle, v), corner(sides[l].triangle, v));
    });
  }
  std::vector<TriangleSide>().swap(sides);  // freed before the parts are copied out
  if (!passed_by && one_part_without_pinches(mesh, sets, fans, branching)) return {};
  std::vector<Index> component_of_root(triangles, kNoIndex);
  std::vector<std::vector<Index>> triangles_of;  // per component, in input order
  for (Index t = 0; t < triangles; ++t) {
    Index& c = component_of_root[sets.find(t)];
    if (c == kNoIndex) {
      c = static_cast<Index>(triangles_of.size());
      triangles_of.emplace_back();
    }
    triangles_of[c].push_back(t);
  }
  std::vector<Component> parts(triangles_of.size());
  // A vertex's id in a part: per fan (a fan lies in one part), or, at the end of an edge of
  // three or more triangles in a component, per component.
  std::vector<Index> fan_local(3 * triangles, kNoIndex);
  std::vector<Index> owner(mesh.vertices.size(), kNoIndex);  // the last component that has it
  std::vector<Index> local(mesh.vertices.size());            // and its id there
  std::vector<Index> copies(mesh.vertices.size(), 0);
  for (Index c = 0; c < parts.size(); ++c) {
    Component& part = parts[c];
    for (const Index t : triangles_of[c]) {
      Triangle mapped;
      for (int k = 0; k < 3; ++k) {
        const Index v = mesh.triangles[t][k];
        Index& id = branching[v] ? local[v] : fan_local[fans.find(3 * t + k)];
        if (branching[v] ? owner[v] != c : id == kNoIndex) {
          owner[v] = c;
          ++copies[v];
          id = static_cast<Index>(part.input_vertex.size());
          part.input_vertex.push_back(v);
          part.mesh.vertices.push_back(mesh.vertices[v]);
        }
        mapped[k] = id;
      }
      part.mesh.triangles.push_back(mapped);
      for (int k = 0; k < 3; ++k)
        if (std::binary_search(branch.begin(), branch.end(),
                               edge_of(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])))
          part.branch_edges.push_back(edge_of(mapped[k], mapped[(k + 1) % 3]));
    }
  }
  for (Component& part : parts) {
    part.area = surface_area(part.mesh);
    for (Index v = 0; v < part.input_vertex.size(); ++v)
      if (copies[part.input_vertex[v]] > 1 && !(passed_by && (*passed_by)[part.input_vertex[v]]))
        part.pinches.push_back(v);
    std::sort(part.branch_edges.begin(), part.branch_edges.end());
    part.branch_edges.erase(std::unique(part.branch_edges.begin(), part.branch_edges.end()),
                            part.branch_edges.end());
  }
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

// Per component, its share of the count: its area, or under a sizing the vertices that the sizing
// on the whole asks of it. An adaptive sizing on its own area would give a small part, whose local
// feature size is small, as few seeds as an even one: bones.off at 2k, 26 bones, took 23 seeds
// from topology control on its smallest bones (even sizes 10).
std::vector<double> part_weights(const TriangleMesh& mesh, const std::vector<Component>& parts,
                                 const RemeshSettings& settings) {
  std::vector<double> weights;
  std::optional<SizeField> field;
  if (settings.sizing.active()) field = make_size_field(mesh, {}, settings);
  if (!field) {
    for (const Component& part : parts) weights.push_back(part.area);
    return weights;
  }
  for (const Component& part : parts) {
    std::vector<double> sizes;
    for (const Index v : part.input_vertex) sizes.push_back(field->at_vertex(v));
    weights.push_back(SizeField(part.mesh, std::move(sizes)).vertex_count());
  }
  return weights;
}

// Per component, the settings of its own remesh: its share of the count (or, for lengths given
// without one, its lengths), its user feature edges, the features' scale of the whole, no
// Hausdorff distance (measured on the whole), progress for the largest only.
std::vector<RemeshSettings> component_settings(const TriangleMesh& mesh,
                                               const std::vector<Component>& parts,
                                               const RemeshSettings& settings) {
  std::vector<RemeshSettings> all(parts.size(), settings);
  // kNoIndex: on no component with area
  std::vector<Index> component(mesh.vertices.size(), kNoIndex), local(mesh.vertices.size());
  std::vector<bool> pinch(mesh.vertices.size(), false);
  for (Index c = 0; c < parts.size(); ++c) {
    for (Index v = 0; v < parts[c].input_vertex.size(); ++v) {
      component[parts[c].input_vertex[v]] = c;
      local[parts[c].input_vertex[v]] = v;
    }
    for (const Index v : parts[c].pinches) pinch[parts[c].input_vertex[v]] = true;
  }
  for (RemeshSettings& s : all) {
    s.hausdorff.reset();
    s.features.user_edges.clear();
    s.features.user_corners.clear();
    s.sizing.edge_lengths.clear();
  }
  // Where components touch, each gets the vertex as a corner, and the outputs are welded there.
  // Where sheets meet along edges of three or more triangles, each keeps those edges: welded,
  // they are the input's edges of three or more triangles again.
  for (Index c = 0; c < parts.size(); ++c) {
    all[c].features.user_corners = parts[c].pinches;
    all[c].features.user_edges = parts[c].branch_edges;
  }
  if (!settings.features.user_edges.empty() || !settings.features.user_corners.empty()) {
    // Checked on the whole, so that an error names the caller's vertex ids; an edge of the mesh
    // lies in one component.
    FeatureSettings check = settings.features;
    check.sharp_edges = false;
    detect_features(mesh, check);
  }
  // The edge in component c's ids, if c has it. A vertex where components or sheets touch has
  // an id in each part, and one per fan: the edge's is the one whose triangles have the edge.
  auto local_edge = [&](Index c, const Edge& e) -> std::optional<Edge> {
    if (!pinch[e[0]] && !pinch[e[1]])
      return Edge{std::min(local[e[0]], local[e[1]]), std::max(local[e[0]], local[e[1]])};
    const std::vector<Index>& ids = parts[c].input_vertex;
    for (const Triangle& t : parts[c].mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        const Index a = t[k], b = t[(k + 1) % 3];
        if ((ids[a] == e[0] && ids[b] == e[1]) || (ids[a] == e[1] && ids[b] == e[0]))
          return Edge{std::min(a, b), std::max(a, b)};
      }
    return std::nullopt;
  };
  for (const Edge& e : settings.features.user_edges) {
    // The component of its triangles: that of an end in one component only, or else (both ends
    // where components touch) the one that has the edge; at a vertex where sheets touch, the
    // copy whose fan has it.
    const Index home = !pinch[e[0]] ? component[e[0]] : !pinch[e[1]] ? component[e[1]] : kNoIndex;
    if (home == kNoIndex && !pinch[e[0]]) continue;  // on a component without area
    for (Index c = home == kNoIndex ? 0 : home; c < parts.size(); ++c) {
      if (const std::optional<Edge> local_e = local_edge(c, e)) {
        all[c].features.user_edges.push_back(*local_e);
        break;
      }
      if (home != kNoIndex) break;
    }
  }
  // A vertex where components touch is a corner anyway.
  for (const Index v : settings.features.user_corners)
    if (component[v] != kNoIndex && !pinch[v])
      all[component[v]].features.user_corners.push_back(local[v]);
  if (!settings.sizing.edge_lengths.empty())
    for (Index c = 0; c < parts.size(); ++c)
      for (const Index v : parts[c].input_vertex)
        all[c].sizing.edge_lengths.push_back(settings.sizing.edge_lengths[v]);

  if (!lengths_as_given(settings)) {
    // A vertex where components touch is one output vertex made of a copy in each: the copies
    // beyond the first are vertices on top of the count.
    std::size_t copies = 0;
    for (const Component& part : parts) copies += part.pinches.size();
    copies -= static_cast<std::size_t>(std::count(pinch.begin(), pinch.end(), true));
    const std::size_t total = requested_vertex_count(mesh, settings) + copies;
    const std::vector<std::size_t> counts =
        apportion(total, part_weights(mesh, parts, at_count(settings, total)));
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

// The parts' phase times, summed by append, scaled to `wall`, the time the parts took side by
// side: the report's time is the remesh's wall time, and each phase keeps its share of the work.
void in_wall_time(RemeshResult& all, double wall) {
  const double summed =
      all.seconds_initialization + all.seconds_rcvt + all.seconds_ccvt + all.seconds_extraction;
  if (!(summed > wall)) return;
  const double k = wall / summed;
  for (double* phase : {&all.seconds_initialization, &all.seconds_rcvt, &all.seconds_ccvt,
                        &all.seconds_extraction, &all.seconds_topology})
    *phase *= k;
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
  all.seconds_topology += part.seconds_topology;
  const double last_all = all.energies.empty() ? 0 : all.energies.back();
  const double last_part = part.energies.empty() ? 0 : part.energies.back();
  const std::size_t n = std::max(all.energies.size(), part.energies.size());
  all.energies.resize(n, last_all);
  for (std::size_t k = 0; k < n; ++k)
    all.energies[k] += k < part.energies.size() ? part.energies[k] : last_part;
  all.defects_polished += part.defects_polished;
  all.polish_rounds = std::max(all.polish_rounds, part.polish_rounds);
  all.shape_flips += part.shape_flips;
  all.shape_moves += part.shape_moves;
  all.short_edges_collapsed += part.short_edges_collapsed;
  all.vertices_onto_own_sheet += part.vertices_onto_own_sheet;
  all.vertices_on_cell_normals += part.vertices_on_cell_normals;
  all.vertices_snapped += part.vertices_snapped;
  all.vertices_fitted += part.vertices_fitted;
  const Features features = renumbered(part.features, component.input_vertex);
  all.features.edges.insert(all.features.edges.end(), features.edges.begin(), features.edges.end());
  all.features.corners.insert(all.features.corners.end(), features.corners.begin(),
                              features.corners.end());
  all.features.curves.insert(all.features.curves.end(), features.curves.begin(),
                             features.curves.end());
  for (Edge e : part.feature_edges) all.feature_edges.push_back({e[0] + offset, e[1] + offset});
  all.feature_edges_missing += part.feature_edges_missing;
  for (const Edge& e : part.feature_edges_dropped) {
    const Index a = component.input_vertex[e[0]], b = component.input_vertex[e[1]];
    all.feature_edges_dropped.push_back({std::min(a, b), std::max(a, b)});
  }
  all.sizes_adapted = all.sizes_adapted || part.sizes_adapted;
  if (part.gap_length_min > 0)
    all.gap_length_min = all.gap_length_min > 0 ? std::min(all.gap_length_min, part.gap_length_min)
                                                : part.gap_length_min;
  all.count_grown += part.count_grown;
  all.links_mended += part.links_mended;
  all.islands_seeded += part.islands_seeded;
  all.seeds_refined += part.seeds_refined;
  for (const Index v : part.vertices_added) all.vertices_added.push_back(v + offset);
  all.links_flipped += part.links_flipped;
  all.tips_closed += part.tips_closed;
  all.mend_rounds = std::max(all.mend_rounds, part.mend_rounds);
  all.triangles_removed += part.triangles_removed;
  all.holes_closed += part.holes_closed;
  all.triangles_closing_holes += part.triangles_closing_holes;
  all.vertices_closing_holes += part.vertices_closing_holes;
  all.input_crossing_triangles += part.input_crossing_triangles;
  all.output_crossing_triangles += part.output_crossing_triangles;
  all.vertices_guarded += part.vertices_guarded;
  all.vertices_splitting_crossings += part.vertices_splitting_crossings;
  all.flat_ears_removed += part.flat_ears_removed;
  all.flat_pairs_merged += part.flat_pairs_merged;
  all.valence_three_removed += part.valence_three_removed;
  all.obtuse_corners_split += part.obtuse_corners_split;
  all.time_limit_reached |= part.time_limit_reached;
}

// The triangles of `output`, the parts' outputs put together, that cross another away from where
// `input` crosses itself (crossings_of_its_own); `input_crossing`, the parts' sum, becomes the
// whole input's count where the input was searched (its parts may cross one another).
std::size_t whole_crossings(const TriangleMesh& output, const TriangleMesh& input,
                            std::size_t& input_crossing) {
  InputCrossings crossings(input);
  const std::size_t own = crossings_of_its_own(output, crossings).size();
  if (crossings.searched()) input_crossing = crossings.count();
  return own;
}

// The output vertices at the positions of component c's pinches, as (input vertex, output vertex)
// pairs; the output's vertices start at `offset` in the whole's.
void find_pinches(const Component& part, const TriangleMesh& output, Index offset,
                  std::vector<std::pair<Index, Index>>& found) {
  std::map<Vec3, Index> wanted;
  for (const Index v : part.pinches) wanted.emplace(part.mesh.vertices[v], part.input_vertex[v]);
  if (wanted.empty()) return;
  for (Index v = 0; v < output.vertices.size(); ++v)
    if (const auto at = wanted.find(output.vertices[v]); at != wanted.end())
      found.emplace_back(at->second, offset + v);
}

// The neighbours of vertex v in `mesh`, sorted.
std::vector<Index> neighbours_of(const TriangleMesh& mesh, Index v) {
  std::vector<Index> n;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] == v) n.insert(n.end(), {t[(k + 1) % 3], t[(k + 2) % 3]});
  std::sort(n.begin(), n.end());
  n.erase(std::unique(n.begin(), n.end()), n.end());
  return n;
}

// Where the output vertices at one pinch (`found`, sorted: runs by input vertex) share a
// neighbour w, welding them would join their edges to w into one edge of four triangles. The
// edge from each vertex but the first to such a w, unless a feature edge, is taken out (flipped
// or halved: take_out_edge): the copies then meet only at the pinch, as the input's fans do
// (cow.obj of a public test set at 1k: one shared neighbour, a seed topology control had added,
// left its pinch unwelded and the output a sphere, Euler characteristic 2 for the input's 1).
void part_pinch_copies(TriangleMesh& mesh, const std::vector<Edge>& feature_edges,
                       const std::vector<std::pair<Index, Index>>& found) {
  for (std::size_t i = 0, j = 0; i < found.size(); i = j) {
    j = i + 1;
    while (j < found.size() && found[j].first == found[i].first) ++j;
    std::vector<Index> seen = neighbours_of(mesh, found[i].second);
    for (std::size_t k = i + 1; k < j; ++k) {
      const Index copy = found[k].second;
      for (const Index w : neighbours_of(mesh, copy)) {
        const Edge e = edge_of(copy, w);
        if (std::binary_search(seen.begin(), seen.end(), w) &&
            std::find(feature_edges.begin(), feature_edges.end(), e) == feature_edges.end())
          take_out_edge(mesh, e);
      }
      const std::vector<Index> more = neighbours_of(mesh, copy);
      seen.insert(seen.end(), more.begin(), more.end());
      std::sort(seen.begin(), seen.end());
    }
  }
}

// Welds the output vertices found at the same pinch (one per component or sheet that kept it)
// into the first, so that the output touches itself where the input did, and drops the others;
// but not those of a pinch whose vertices still share a neighbour once part_pinch_copies has
// flipped what it can (topology control failed to part the sheets there), whose edges to it the
// weld would make non-manifold.
void weld_pinches(RemeshResult& all, std::vector<std::pair<Index, Index>> found) {
  std::sort(found.begin(), found.end());
  part_pinch_copies(all.mesh, all.feature_edges, found);
  std::vector<std::vector<Index>> neighbours(all.mesh.vertices.size());
  std::vector<bool> at_pinch(all.mesh.vertices.size(), false);
  for (const auto& [input, output] : found) at_pinch[output] = true;
  for (const Triangle& t : all.mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (at_pinch[t[k]])
        for (const int j : {1, 2}) neighbours[t[k]].push_back(t[(k + j) % 3]);
  std::vector<Index> into(all.mesh.vertices.size());
  std::iota(into.begin(), into.end(), Index{0});
  bool welded = false;
  for (std::size_t i = 0, j = 0; i < found.size(); i = j) {
    // The pinch's vertices and their neighbours, each vertex's listed once: a repeat is shared.
    std::vector<Index> around;
    for (j = i; j < found.size() && found[j].first == found[i].first; ++j) {
      std::vector<Index>& n = neighbours[found[j].second];
      std::sort(n.begin(), n.end());
      n.erase(std::unique(n.begin(), n.end()), n.end());
      around.insert(around.end(), n.begin(), n.end());
      around.push_back(found[j].second);
    }
    std::sort(around.begin(), around.end());
    if (j - i < 2 || std::adjacent_find(around.begin(), around.end()) != around.end()) continue;
    for (std::size_t k = i + 1; k < j; ++k) into[found[k].second] = found[i].second;
    welded = true;
  }
  if (!welded) return;
  std::vector<Index> new_id(into.size());
  std::vector<Vec3> kept;
  for (Index v = 0; v < into.size(); ++v)
    if (into[v] == v) {
      new_id[v] = static_cast<Index>(kept.size());
      kept.push_back(all.mesh.vertices[v]);
    }
  auto renumber = [&](Index v) { return new_id[into[v]]; };
  all.mesh.vertices = std::move(kept);
  for (Triangle& t : all.mesh.triangles)
    for (Index& v : t) v = renumber(v);
  for (Edge& e : all.feature_edges) {
    e = {renumber(e[0]), renumber(e[1])};
    if (e[0] > e[1]) std::swap(e[0], e[1]);
  }
  for (Index& v : all.vertices_added) v = renumber(v);
}

// The features of `all`, found on the input with its junction split, in the input's ids: a
// piece of an edge split is that edge, and the points added are no corners or curve vertices.
void in_input_ids(RemeshResult& all, const BranchCurves& junction, std::size_t input_vertices) {
  const auto whole = [&](const Edge& e) {
    for (const Index v : e)
      if (v >= input_vertices) {
        const BranchCurves::Added& x = junction.added[v - input_vertices];
        return Edge{x.a, x.b};
      }
    return e;
  };
  for (Edge& e : all.features.edges) e = whole(e);
  for (Edge& e : all.feature_edges_dropped) e = whole(e);
  std::erase_if(all.features.corners, [&](Index v) { return v >= input_vertices; });
  for (FeatureCurve& curve : all.features.curves)
    std::erase_if(curve.vertices, [&](Index v) { return v >= input_vertices; });
}

// `settings` for the input with its junction split: a caller's feature edge that was split is
// its pieces, and a length per vertex is interpolated at the points added.
RemeshSettings with_junction_split(RemeshSettings settings, const BranchCurves& junction) {
  std::vector<Edge> edges;
  for (const Edge& e : settings.features.user_edges) {
    const Edge key = edge_of(e[0], e[1]);
    const auto at = std::lower_bound(junction.split.begin(), junction.split.end(), key);
    if (at == junction.split.end() || *at != key) {
      edges.push_back(e);
      continue;
    }
    const std::vector<Index>& piece = junction.pieces[at - junction.split.begin()];
    for (std::size_t i = 0; i + 1 < piece.size(); ++i) edges.push_back({piece[i], piece[i + 1]});
  }
  settings.features.user_edges = std::move(edges);
  std::vector<double>& lengths = settings.sizing.edge_lengths;
  if (!lengths.empty())
    for (const BranchCurves::Added& x : junction.added) {
      const double length = (1 - x.t) * lengths[x.a] + x.t * lengths[x.b];
      lengths.push_back(length);
    }
  return settings;
}

// The components (or, with `junction`, the sheets) of `input` remeshed apart and welded; none
// when the sheets' outputs do not meet along the junction. `sides`: the input's sorted_sides, or
// empty.
std::optional<RemeshResult> remesh_parts(const TriangleMesh& input, const RemeshSettings& given,
                                         const BranchCurves* junction,
                                         std::vector<TriangleSide> sides) {
  const bool split = junction && !junction->added.empty();
  const TriangleMesh& mesh = split ? junction->mesh : input;
  const RemeshSettings settings = split ? with_junction_split(given, *junction) : given;
  std::vector<bool> passed_by(junction ? mesh.vertices.size() : 0);
  for (Index v = 0; v < passed_by.size(); ++v)
    passed_by[v] = junction->on_curve[v] && !junction->corner[v];
  if (split) sides.clear();  // the input's, not the split mesh's
  std::vector<Component> parts =
      split_components(mesh, junction ? &passed_by : nullptr, std::move(sides));
  // A component without area (degenerate triangles only) has nothing to remesh: the whole
  // gives it no seed either.
  std::erase_if(parts, [](const Component& part) { return !(part.area > 0); });
  if (parts.empty() || (parts.size() == 1 && parts[0].pinches.empty())) {
    if (junction) return std::nullopt;  // one sheet: the whole, remeshed already
    // A lone part, where split_components made one, is a copy of the whole: freed first
    // (igea.ply at 10k: 13 MB of a 205 MB peak).
    std::vector<Component>().swap(parts);
    return remesh_unit_topology_first(input, given).result;
  }

  const auto start = std::chrono::steady_clock::now();
  std::vector<RemeshSettings> part_settings = component_settings(mesh, parts, settings);
  // A sheet of a non-manifold input too small for two vertices of its own (a sliver glued to a
  // surface along an edge) stays as it is: its remesh would put its share of a vertex on a
  // dozen corners and sides (conrod.stl's slivers of area 1e-6 asked a thousand).
  const double area_per_vertex =
      surface_area(mesh) /
      static_cast<double>(std::max<std::size_t>(requested_vertex_count(mesh, settings), 1));
  const auto as_it_is = [&](const Component& part) {
    return !part.branch_edges.empty() && part.area < 2 * area_per_vertex;
  };
  // The input's edges of three or more triangles, each with the parts that have it.
  std::map<Edge, std::vector<std::size_t>> sharing;
  for (std::size_t c = 0; c < parts.size(); ++c)
    for (const Edge& e : parts[c].branch_edges)
      sharing[edge_of(parts[c].input_vertex[e[0]], parts[c].input_vertex[e[1]])].push_back(c);
  std::vector<SharedSegment> shared;
  for (const std::vector<Index>& stretch :
       junction ? junction->stretches : std::vector<std::vector<Index>>{}) {
    std::vector<std::size_t>& with = sharing[edge_of(stretch[0], stretch[1])];
    with.erase(std::unique(with.begin(), with.end()), with.end());
    if (with.size() < 2) continue;  // in one part only: nothing to zip
    SharedSegment& s = shared.emplace_back();
    for (const Index v : stretch) s.points.push_back(mesh.vertices[v]);
    s.sheets = with;
  }
  RemeshResult all;
  std::vector<double> ratios;
  double gradient2_initial = 0, gradient2_final = 0;
  std::vector<std::pair<Index, Index>> pinches;  // (input vertex, output vertex)
  std::vector<SheetVertices> sheets;             // per part, its output's vertices in the whole
  // The parts are remeshed side by side, the largest first: a small part alone keeps few cores
  // busy (on two cores, bones.off's 26 components at 5k: the whole 0.77-0.83 of the time one after
  // another took). Each part's output depends on neither the thread count nor the order, so the
  // whole's does not. Isolated, a thread that waits inside one part's parallel work takes none
  // of another part's: no part's remesh runs nested on another's stack.
  std::vector<UnitRemesh> remeshed(parts.size());
  std::vector<std::size_t> order(parts.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return parts[a].mesh.triangles.size() > parts[b].mesh.triangles.size();
  });
  // A part that throws lets the others run to their end: an exception leaving the loop would
  // cancel the parallel work inside the others, whose loops would then return half done. The
  // first part's error, in part order, is the one thrown (the same whatever the timing).
  std::vector<std::exception_ptr> failed(parts.size());
  const auto parts_start = std::chrono::steady_clock::now();
  tbb::parallel_for_each(order.begin(), order.end(), [&](std::size_t c) {
    RemeshSettings& s = part_settings[c];
    if (settings.time_limit > 0) {
      // What is left of the limit; a component that starts after it works not at all (its
      // seeds as sampled make its output), as the whole would.
      s.time_limit = std::max(settings.time_limit - seconds_since(start), 1e-9);
    }
    try {
      if (as_it_is(parts[c]))
        remeshed[c].result.mesh = parts[c].mesh;
      else
        tbb::this_task_arena::isolate(
            [&] { remeshed[c] = remesh_unit_topology_first(parts[c].mesh, s); });
    } catch (...) {
      failed[c] = std::current_exception();
    }
  });
  for (const std::exception_ptr& error : failed)
    if (error) std::rethrow_exception(error);
  const double parts_seconds = seconds_since(parts_start);
  for (std::size_t c = 0; c < parts.size(); ++c) {
    UnitRemesh& part = remeshed[c];
    sheets.push_back(
        {static_cast<Index>(all.mesh.vertices.size()),
         static_cast<Index>(all.mesh.vertices.size() + part.result.mesh.vertices.size())});
    find_pinches(parts[c], part.result.mesh, static_cast<Index>(all.mesh.vertices.size()), pinches);
    ratios.insert(ratios.end(), part.edge_ratios.begin(), part.edge_ratios.end());
    append(all, std::move(part.result), parts[c], gradient2_initial, gradient2_final);
  }
  if (!shared.empty()) {
    // Sheets meet edge to edge: each gets the others' vertices along the edges they share.
    std::optional<std::vector<std::pair<Index, Index>>> zipped = zip_shared_segments(
        all.mesh, all.feature_edges, sheets, shared, static_cast<Index>(mesh.vertices.size()));
    if (!zipped) return std::nullopt;
    pinches.insert(pinches.end(), zipped->begin(), zipped->end());
  }
  weld_pinches(all, std::move(pinches));
  // Each part counted the crossings of its own output only; parts that lie closer than their
  // chords sag (a hollow ball's two spheres a wall apart thinner than that) pass through one
  // another where no part looks: the whole output is searched, and its count is the report's.
  all.output_crossing_triangles = whole_crossings(all.mesh, mesh, all.input_crossing_triangles);
  in_wall_time(all, parts_seconds);
  all.gradient_norm_initial = std::sqrt(gradient2_initial);
  all.gradient_norm_final = std::sqrt(gradient2_final);
  if (split) in_input_ids(all, *junction, input.vertices.size());
  std::sort(all.features.edges.begin(), all.features.edges.end());
  all.features.edges.erase(std::unique(all.features.edges.begin(), all.features.edges.end()),
                           all.features.edges.end());  // a junction edge is one of each sheet
  std::sort(all.features.corners.begin(), all.features.corners.end());
  all.features.corners.erase(std::unique(all.features.corners.begin(), all.features.corners.end()),
                             all.features.corners.end());  // a pinch is a corner of each part
  std::sort(all.feature_edges.begin(), all.feature_edges.end());
  std::sort(all.feature_edges_dropped.begin(), all.feature_edges_dropped.end());
  all.feature_edges_dropped.erase(
      std::unique(all.feature_edges_dropped.begin(), all.feature_edges_dropped.end()),
      all.feature_edges_dropped.end());
  all.input_topology = analyze_topology(input);
  if (junction) all.sheets_apart = parts.size();
  all.edge_length_ratio = ratio_percentiles(std::move(ratios));
  if (settings.hausdorff && !all.mesh.triangles.empty()) {
    const auto hausdorff_start = std::chrono::steady_clock::now();
    all.hausdorff =
        hausdorff_distance(all.mesh, input, SurfaceProjector(input), *settings.hausdorff);
    all.seconds_hausdorff = seconds_since(hausdorff_start);
  }
  return all;
}

// How well an output of an input with `in`'s topology keeps its junction: first the topology and
// the junction kept (no edge of three or more triangles off it, no more non-manifold vertices),
// then fewer such edges off it, then the larger θmin.
std::tuple<bool, std::ptrdiff_t, double> junction_score(const RemeshResult& r,
                                                        const TopologyReport& in,
                                                        const BranchCurves& junction) {
  const TopologyReport t = analyze_topology(r.mesh);
  const std::size_t off = edges_off_junction(r.mesh, junction);
  const bool kept =
      same_topology(t, in) && off == 0 && t.nonmanifold_vertices <= in.nonmanifold_vertices;
  return {kept, -static_cast<std::ptrdiff_t>(off), measure_quality(r.mesh).angle_min_deg};
}

}  // namespace

RemeshResult remesh_by_component(const TriangleMesh& input, const RemeshSettings& given,
                                 std::vector<TriangleSide> sides) {
  if (!given.initial_seeds.empty()) return remesh_unit_topology_first(input, given).result;
  const auto start = std::chrono::steady_clock::now();
  RemeshResult first = *remesh_parts(input, given, nullptr, std::move(sides));
  if (first.input_topology.nonmanifold_edges == 0 || first.time_limit_reached) return first;
  // Sheets meeting along edges of three or more triangles, remeshed whole, may join beside the
  // junction where they meet at a shallow angle (an icosphere with flaps 4.5° off it; MeshLab's
  // conrod.stl and office_chair.obj lost their topology). Then each sheet is remeshed on its
  // own, and the better output kept. Not first: the sheets take longer (triple_vierbein.obj at
  // 5k, six sheets: 1.9x), and lose the junction where a sheet's own output does (one sheet
  // passing through another, as in sub.obj).
  const std::size_t count = std::max<std::size_t>(requested_vertex_count(input, given), 1);
  const BranchCurves junction =
      resample_branch_curves(input, edge_length_for(surface_area(input), count));
  const TopologyReport in = first.input_topology;
  const auto first_score = junction_score(first, in, junction);
  if (std::get<0>(first_score)) return first;
  if (given.progress) given.progress({"sheets", 0, 0, 0, seconds_since(start)});
  RemeshSettings settings = given;
  if (given.time_limit > 0)
    settings.time_limit = std::max(given.time_limit - seconds_since(start), 1e-9);
  std::optional<RemeshResult> sheets = remesh_parts(input, settings, &junction, {});
  if (!sheets) return first;
  // Both tries' time counted in the output kept, the other's as topology control's (as a redo
  // not taken is).
  const auto count_other = [](RemeshResult& kept, const RemeshResult& other) {
    const double seconds = other.seconds_initialization + other.seconds_rcvt + other.seconds_ccvt +
                           other.seconds_extraction;
    kept.seconds_topology += seconds;
    kept.seconds_extraction += seconds;
  };
  if (junction_score(*sheets, in, junction) > first_score) {
    count_other(*sheets, first);
    return std::move(*sheets);
  }
  count_other(first, *sheets);
  return first;
}

}  // namespace cvtmesh
