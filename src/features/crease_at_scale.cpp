#include "features/crease_at_scale.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <unordered_set>

#include "geometry/median.hpp"

namespace cvtmesh {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
constexpr std::size_t kMeasuredEdges = 9;  // per curve: enough for a vote, cheap on long curves
// The narrowest side a crease may have, against the scale (see is_crease).
constexpr double kNarrowestSide = 0.3;
// The most the input may bend around a crease, against the feature angle (see is_crease).
constexpr double kInputBendShare = 0.1;

Vec3 raw_normal(const TriangleMesh& mesh, std::size_t t) {
  const auto [a, b, c] = mesh.corners(t);
  return cross(b - a, c - a);
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = dot(d, d);
  const double t = dd > 0 ? std::clamp(dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
  return distance(p, a + t * d);
}

// How many of a curve's edges are measured, and the i-th of them, spread along it.
std::size_t measured_edges(const FeatureCurve& curve) {
  return std::min(curve.vertices.size() - (curve.closed ? 0 : 1), kMeasuredEdges);
}

Edge measured_edge(const FeatureCurve& curve, std::size_t i, std::size_t measured) {
  const std::size_t edges = curve.vertices.size() - (curve.closed ? 0 : 1);
  const std::size_t k = (2 * i + 1) * edges / (2 * measured);
  return edge_of(curve.vertices[k], curve.vertices[(k + 1) % curve.vertices.size()]);
}

double angle_deg(const Vec3& u, const Vec3& v) {
  const double lengths = norm(u) * norm(v);
  if (!(lengths > 0)) return 0;
  return std::acos(std::clamp(dot(u, v) / lengths, -1.0, 1.0)) * 180 / std::numbers::pi;
}

}  // namespace

CreaseScale::CreaseScale(const TriangleMesh& mesh, const std::vector<EdgeUse>& uses,
                         const std::vector<Edge>& barrier)
    : mesh_(mesh),
      uses_(uses),
      across_(3 * mesh.triangles.size(), kNone),
      on_boundary_(3 * mesh.triangles.size(), 0) {
  for_each_edge(uses, [&](std::size_t k, std::size_t end) {
    if (end - k == 1) on_boundary_[uses[k].corner] = 1;
    if (end - k == 2 && !std::binary_search(barrier.begin(), barrier.end(), uses[k].edge)) {
      across_[uses[k].corner] = uses[k + 1].corner / 3;
      across_[uses[k + 1].corner] = uses[k].corner / 3;
    }
  });
  around_start_.assign(mesh.vertices.size() + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (Index v : t) ++around_start_[v + 1];
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) around_start_[v + 1] += around_start_[v];
  around_.resize(around_start_.back());
  std::vector<std::size_t> fill(around_start_.begin(), around_start_.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (Index v : mesh.triangles[t]) around_[fill[v]++] = t;
}

double CreaseScale::dihedral_deg(std::size_t t, int k) const {
  const std::size_t u = across(t, k);
  const Triangle& tt = mesh_.triangles[t];
  // Consistent neighbours run their shared edge in opposite directions.
  const double sign = runs_forward(mesh_.triangles[u], tt[k], tt[(k + 1) % 3]) ? -1 : 1;
  return angle_deg(raw_normal(mesh_, t), sign * raw_normal(mesh_, u));
}

double CreaseScale::input_bend_deg(const Edge& edge) const {
  struct Slot {
    Edge edge;
    std::size_t triangle;
    int k;
  };
  std::vector<Slot> slots;
  for (const Index v : edge)
    for (std::size_t s = around_start_[v]; s < around_start_[v + 1]; ++s)
      for (int k = 0; k < 3; ++k) {
        const std::size_t t = around_[s];
        const Triangle& tt = mesh_.triangles[t];
        if (across(t, k) != kNone) slots.push_back({edge_of(tt[k], tt[(k + 1) % 3]), t, k});
      }
  std::sort(slots.begin(), slots.end(),
            [](const Slot& x, const Slot& y) { return x.edge < y.edge; });
  std::vector<double> bends;
  for (std::size_t i = 0; i < slots.size(); ++i)
    if (i == 0 || slots[i].edge != slots[i - 1].edge)
      bends.push_back(dihedral_deg(slots[i].triangle, slots[i].k));
  return bends.empty() ? 0 : median_of(std::move(bends));
}

CreaseScale::Side CreaseScale::side(std::size_t first, bool flip, const Vec3& centre,
                                    double radius) const {
  // Breadth-first over the triangles whose centroid is within `radius`, each normal turned to
  // agree with its neighbour's across the shared edge (the input may not be oriented).
  std::vector<std::pair<std::size_t, bool>> region{{first, flip}};
  std::unordered_set<std::size_t> seen{first};
  std::deque<std::pair<std::size_t, bool>> queue{{first, flip}};
  while (!queue.empty()) {
    const auto [t, flipped] = queue.front();
    queue.pop_front();
    for (int k = 0; k < 3; ++k) {
      const std::size_t u = across(t, k);
      if (u == kNone || seen.contains(u)) continue;
      const auto [a, b, c] = mesh_.corners(u);
      if (distance((1.0 / 3) * (a + b + c), centre) > radius) continue;
      // Consistent neighbours run their shared edge in opposite directions.
      const Triangle& tt = mesh_.triangles[t];
      const bool f = flipped != runs_forward(mesh_.triangles[u], tt[k], tt[(k + 1) % 3]);
      seen.insert(u);
      region.push_back({u, f});
      queue.push_back({u, f});
    }
  }
  std::vector<Vec3> normals;  // oriented, area-weighted
  Side s{{}, 0};
  for (const auto& [t, f] : region) {
    normals.push_back((f ? -1.0 : 1.0) * raw_normal(mesh_, t));
    s.normal_sum = s.normal_sum + normals.back();
  }
  double area = 0;
  for (const Vec3& n : normals) {
    area += norm(n);
    s.roughness_deg += norm(n) * angle_deg(n, s.normal_sum);
  }
  s.roughness_deg = area > 0 ? s.roughness_deg / area : 0;
  return s;
}

double CreaseScale::side_width(std::size_t first, const Vec3& a, const Vec3& b,
                               double radius) const {
  // Triangles joined by edges that pass within `radius` of the centre: unlike centroids, this
  // reaches across the long slivers of a coarse CAD tessellation, whose far corners can lie
  // near the crease however wide the face.
  const Vec3 centre = 0.5 * (a + b), along = b - a;
  const double length = norm(along);
  double width = 0, gap = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> stack{first};
  std::unordered_set<std::size_t> seen{first};
  while (!stack.empty()) {
    const std::size_t t = stack.back();
    stack.pop_back();
    const std::array<Vec3, 3> corners = mesh_.corners(t);
    for (int k = 0; k < 3; ++k) {
      width = std::max(width, norm(cross(along, corners[k] - a)) / length);
      const auto to_edge = [&] {
        return distance_to_segment(centre, corners[k], corners[(k + 1) % 3]);
      };
      // A boundary that comes close bounds the side, however far the side reaches elsewhere
      // within the radius: the narrow ends of a strip between a crease and a hole's rim reach
      // its wide middle (lion.off at 5k: a scan's lip, 0.1-0.5 edge lengths from the rim).
      if (on_boundary_[3 * t + k]) gap = std::min(gap, to_edge());
      const std::size_t u = across(t, k);
      if (u == kNone || seen.contains(u) || to_edge() > radius) continue;
      seen.insert(u);
      stack.push_back(u);
    }
  }
  return std::min(width, gap);
}

CreaseScale::Measure CreaseScale::measure(const Edge& edge, double radius) const {
  const auto first = std::lower_bound(uses_.begin(), uses_.end(), edge,
                                      [](const EdgeUse& u, const Edge& e) { return u.edge < e; });
  if (uses_.end() - first < 2 || first->edge != edge || first[1].edge != edge ||
      (uses_.end() - first > 2 && first[2].edge == edge))
    return {};  // not an edge of two triangles
  const std::size_t t0 = first->corner / 3, t1 = first[1].corner / 3;
  const auto k0 = static_cast<int>(first->corner % 3);
  const Triangle& a = mesh_.triangles[t0];
  const bool same_direction = runs_forward(mesh_.triangles[t1], a[k0], a[(k0 + 1) % 3]);
  const Vec3 &p = mesh_.vertices[edge[0]], &q = mesh_.vertices[edge[1]];
  const Vec3 centre = 0.5 * (p + q);
  const Side s0 = side(t0, false, centre, radius), s1 = side(t1, same_direction, centre, radius);
  return {angle_deg(s0.normal_sum, s1.normal_sum), std::max(s0.roughness_deg, s1.roughness_deg),
          std::min(side_width(t0, p, q, radius), side_width(t1, p, q, radius))};
}

bool CreaseScale::is_crease(const FeatureCurve& curve, double scale, double angle_deg) const {
  const std::size_t measured = measured_edges(curve);
  std::size_t passed = 0;
  for (std::size_t i = 0; i < measured; ++i) {
    const Measure m = measure(measured_edge(curve, i, measured), scale);
    passed += m.fold_deg >= angle_deg && m.roughness_deg <= angle_deg / 6 &&
              m.width >= kNarrowestSide * scale;
  }
  return 2 * passed >= measured;
}

CreaseScale::Votes CreaseScale::smooth_around(const FeatureCurve& curve, double angle_deg) const {
  Votes votes;
  votes.measured = measured_edges(curve);
  for (std::size_t i = 0; i < votes.measured; ++i)
    votes.smooth +=
        input_bend_deg(measured_edge(curve, i, votes.measured)) <= kInputBendShare * angle_deg;
  return votes;
}

}  // namespace cvtmesh
