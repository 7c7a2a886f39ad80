#include "finish/snap_to_creases.hpp"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "features/edge_uses.hpp"
#include "finish/move_limits.hpp"
#include "geometry/shortest_edges.hpp"
#include "geometry/surface_projector.hpp"
#include "geometry/triangles_around.hpp"
#include "geometry/unit_vector.hpp"
#include "quality/min_shape.hpp"

namespace cvtmesh {

namespace {

// A crease turns the surface by more than this between its two triangles (cosine of 20°): less
// than a sweep's flips fold, more than a smooth input bends between neighbouring triangles.
constexpr double kCreaseCos = 0.9397;
// A crease shorter than the output's mean edge bends below its resolution: following it gains
// little and costs shapes (scorpion_low_resolution.obj at 5k, whose 12.6k triangles have 2,740
// edges over 30°: Hausdorff mean 0.0314% -> 0.0296% snapping to all, with its max 0.75% -> 0.84%
// and θmin_ave 52.5° -> 51.1°; to those an edge long, 0.0311%, 0.75% and 52.3°; a low-poly input's
// creases are all longer).
constexpr double kMinCreaseLength = 1;
// How far a vertex looks for a crease, in its shortest edges: a crease that passes through its
// star, not one its neighbour is nearer.
constexpr double kReach = 0.3;

Vec3 unit_normal_of(const TriangleMesh& m, const Triangle& t) {
  return unit_normal(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
}

using Kernel = CGAL::Simple_cartesian<double>;
using Segment = Kernel::Segment_3;
using Primitive = CGAL::AABB_segment_primitive<Kernel, std::vector<Segment>::const_iterator>;
using CreaseTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const Vec3& v) {
  return {v.x, v.y, v.z};
}

// The mean length of the triangles' sides (a side of two triangles counts twice: not the
// report's edge_length_mean, over distinct edges, which moves the crease floor a hair and changed
// ChineseDragon-10kv.off at 10k).
double mean_edge_length(const TriangleMesh& m) {
  double sum = 0;
  for (const Triangle& f : m.triangles)
    for (int k = 0; k < 3; ++k) sum += distance(m.vertices[f[k]], m.vertices[f[(k + 1) % 3]]);
  return m.triangles.empty() ? 0 : sum / (3.0 * static_cast<double>(m.triangles.size()));
}

// The surface's creases at least `min_length` long, as segments, and the unit normals of the two
// triangles of each.
struct Creases {
  std::vector<Segment> segments;
  std::vector<std::array<Vec3, 2>> normals;
};

Creases creases_of(const TriangleMesh& surface, const Features& features, double min_length) {
  Creases creases;
  // Only the uses of edges long enough are listed: an input finer than the output has none, and
  // listing all its edges' uses was 2% of a remesh of igea.ply's 270k triangles to 1k.
  const std::vector<EdgeUse> uses = edge_uses(surface, [&](const Edge& e) {
    return distance(surface.vertices[e[0]], surface.vertices[e[1]]) >= min_length;
  });
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    const Edge& e = uses[i].edge;
    if (j - i != 2 || std::binary_search(features.edges.begin(), features.edges.end(), e)) return;
    const Vec3 n0 = unit_normal_of(surface, surface.triangles[uses[i].triangle()]);
    const Vec3 n1 = unit_normal_of(surface, surface.triangles[uses[i + 1].triangle()]);
    if (dot(n0, n1) >= kCreaseCos) return;
    creases.segments.emplace_back(point(surface.vertices[e[0]]), point(surface.vertices[e[1]]));
    creases.normals.push_back({n0, n1});
  });
  return creases;
}

// A star's triangles: their worst shape, their normals, and their distance to the surface at
// centroids and edge midpoints: summed, weighted by area, and the farthest.
struct StarState {
  double min_angle = 180, min_quality = 1, distance = 0, farthest = 0;
  std::vector<Vec3> normals;
};

// The vertices with a value in `flagged`, in rounds no two members of which share an edge
// (triangles `star` per vertex): each takes the first round none of its earlier neighbours is in.
template <class T>
std::vector<std::vector<Index>> independent_rounds(const TriangleMesh& mesh,
                                                   const std::vector<std::vector<Index>>& star,
                                                   const std::vector<std::optional<T>>& flagged) {
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> round_of(flagged.size(), kNone);
  std::vector<std::vector<Index>> rounds;
  std::vector<bool> taken;  // per round: a neighbour is in it
  for (Index v = 0; v < flagged.size(); ++v) {
    if (!flagged[v]) continue;
    taken.assign(rounds.size(), false);
    for (const Index t : star[v])
      for (const Index u : mesh.triangles[t])
        if (u != v && round_of[u] != kNone) taken[round_of[u]] = true;
    const std::size_t r =
        static_cast<std::size_t>(std::find(taken.begin(), taken.end(), false) - taken.begin());
    if (r == rounds.size()) rounds.emplace_back();
    rounds[r].push_back(v);
    round_of[v] = r;
  }
  return rounds;
}

}  // namespace

std::size_t snap_to_creases(TriangleMesh& output, const TriangleMesh& surface,
                            const Features& features, const SurfaceProjector& projector,
                            const std::vector<bool>& movable) {
  const Creases creases =
      creases_of(surface, features, kMinCreaseLength * mean_edge_length(output));
  if (creases.segments.empty()) return 0;
  CreaseTree tree(creases.segments.begin(), creases.segments.end());
  tree.build();  // before the queries, which run in parallel
  tree.accelerate_distance_queries();
  const std::size_t nv = output.vertices.size();
  const std::vector<std::vector<Index>> star = triangles_around(output);
  const std::vector<double> shortest = shortest_edges(output);
  const std::vector<bool> fixed = on_edges_not_of_two(output);

  // The star of v with v at x (the mesh itself is only read, so stars are judged in parallel).
  const auto state_of = [&](std::size_t v, const Vec3& x, const SurfaceProjector::Foot& hint) {
    StarState s;
    const auto to_surface = [&](const Vec3& p) {
      return distance(p, projector.nearest(p, hint).point);
    };
    const auto at = [&](Index u) -> const Vec3& { return u == v ? x : output.vertices[u]; };
    for (const Index t : star[v]) {
      const Triangle& f = output.triangles[t];
      const Vec3 &a = at(f[0]), &b = at(f[1]), &c = at(f[2]);
      const MinShape shape = min_shape(a, b, c);
      s.min_angle = std::min(s.min_angle, shape.min_angle);
      s.min_quality = std::min(s.min_quality, shape.quality);
      s.normals.push_back(unit_normal(a, b, c));
      const double area = 0.5 * norm(cross(b - a, c - a));
      double sum = 0;
      for (const Vec3& p : {(1.0 / 3) * (a + b + c), 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)}) {
        const double d = to_surface(p);
        sum += d;
        s.farthest = std::max(s.farthest, d);
      }
      s.distance += area * sum;
    }
    return s;
  };

  // Each vertex's target (the nearest crease point within reach, the crease facing its side)
  // depends on its own position only: all found at once.
  struct Target {
    Vec3 to;
    SurfaceProjector::Foot foot;
  };
  std::vector<std::optional<Target>> target(nv);
  tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t v) {
    if (v >= movable.size() || !movable[v] || fixed[v] || star[v].empty()) return;
    const Vec3& x = output.vertices[v];
    const auto [q, crease] = tree.closest_point_and_primitive(point(x));
    const Vec3 to{q.x(), q.y(), q.z()};
    if (!(distance(to, x) < kReach * shortest[v]) || to == x) return;
    // A crease of the part's other side, where it is thinner than the reach, faces away.
    const SurfaceProjector::Foot foot = projector.nearest(x);
    const auto& faces =
        creases.normals[static_cast<std::size_t>(crease - creases.segments.begin())];
    if (dot(faces[0], foot.normal) <= 0 && dot(faces[1], foot.normal) <= 0) return;
    target[v] = Target{to, foot};
  });
  // One pass, in rounds of vertices no two of which are neighbours (a greedy colouring in vertex
  // order): a move is judged on its star alone, which no other move of its round changes, so a
  // round's moves are judged at once, and the outcome depends neither on the thread count nor on
  // the order within a round. (A second pass, after the neighbours moved, took hand.off's
  // Hausdorff mean at 5k from 0.02315% to 0.02311%, for a quarter more time.)
  const std::vector<std::vector<Index>> rounds = independent_rounds(output, star, target);
  std::size_t moved = 0;
  for (const std::vector<Index>& round : rounds) {
    std::vector<char> keep(round.size(), 0);
    tbb::parallel_for(std::size_t{0}, round.size(), [&](std::size_t k) {
      const Index v = round[k];
      const Target& t = *target[v];
      const StarState before = state_of(v, output.vertices[v], t.foot);
      const StarState after = state_of(v, t.to, t.foot);
      bool ok = after.distance < before.distance && after.farthest <= before.farthest &&
                after.min_angle >= std::min(before.min_angle, kAimAngleDeg) &&
                after.min_quality >= std::min(before.min_quality, kAimQuality);
      for (std::size_t i = 0; ok && i < star[v].size(); ++i)
        ok = dot(after.normals[i], before.normals[i]) >= kMaxShiftTurnCos;
      keep[k] = ok;
    });
    for (std::size_t k = 0; k < round.size(); ++k) {
      if (!keep[k]) continue;
      output.vertices[round[k]] = target[round[k]]->to;
      ++moved;
    }
  }
  return moved;
}

}  // namespace cvtmesh
