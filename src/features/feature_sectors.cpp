// The narrowest sector of the surface between two feature edges at a vertex: a bound on the
// smallest angle of any output that traces both (paper §5's θmin, on CAD parts).
#include <algorithm>
#include <optional>
#include <span>

#include "cvtmesh/features.hpp"
#include "features/feature_sectors.hpp"
#include "geometry/angle.hpp"

namespace cvtmesh {

namespace {

// One triangle seen from one of its vertices: the other two, and its angle there.
struct FanEntry {
  Index apex, x, y;
  double angle_deg;
};

bool is_feature(const Features& f, Index a, Index b) {
  return std::binary_search(f.edges.begin(), f.edges.end(), a < b ? Edge{a, b} : Edge{b, a});
}

// A vertex's fan walked from feature neighbour `start` through the triangle `from`, summing
// angles until the next feature neighbour. None when the walk ends without one (an open fan),
// comes back to `start`, or goes round a non-manifold fan's cycle.
std::optional<FeatureSector> sector_from(const Features& f, std::span<const FanEntry> fan,
                                         const FanEntry* from, Index start) {
  double sum = 0;
  Index at = start;
  const FanEntry* e = from;
  for (std::size_t steps = fan.size(); e != nullptr && steps > 0; --steps) {
    sum += e->angle_deg;
    at = e->x == at ? e->y : e->x;
    if (at == start) return std::nullopt;
    if (is_feature(f, e->apex, at)) return FeatureSector{e->apex, start, at, sum};
    const FanEntry* next = nullptr;
    for (const FanEntry& g : fan)
      if (&g != e && (g.x == at || g.y == at)) next = &g;
    e = next;
  }
  return std::nullopt;
}

// Per vertex with two feature edges or more, the narrowest sector between two of them, by vertex.
std::vector<std::pair<Index, double>> narrowest_sectors(const TriangleMesh& mesh,
                                                        const Features& features) {
  std::vector<std::pair<Index, double>> out;
  for (const FeatureSector& s : feature_sectors(mesh, features))
    if (out.empty() || out.back().first != s.apex)
      out.push_back({s.apex, s.angle_deg});
    else
      out.back().second = std::min(out.back().second, s.angle_deg);
  return out;
}

}  // namespace

std::vector<FeatureSector> feature_sectors(const TriangleMesh& mesh, const Features& features) {
  std::vector<int> degree(mesh.vertices.size(), 0);
  for (const Edge& e : features.edges) ++degree[e[0]], ++degree[e[1]];
  std::vector<FanEntry> fans;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index apex = t[k], x = t[(k + 1) % 3], y = t[(k + 2) % 3];
      if (degree[apex] < 2) continue;
      const Vec3& p = mesh.vertices[apex];
      fans.push_back({apex, x, y, angle_deg(mesh.vertices[x] - p, mesh.vertices[y] - p)});
    }
  std::sort(fans.begin(), fans.end(),
            [](const FanEntry& a, const FanEntry& b) { return a.apex < b.apex; });
  std::vector<FeatureSector> out;
  for (auto first = fans.begin(); first != fans.end();) {
    const auto last =
        std::find_if(first, fans.end(), [&](const FanEntry& e) { return e.apex != first->apex; });
    // Each triangle at a feature edge starts a walk (both ways round, from each end); in a
    // non-manifold fan a neighbour has three or more triangles and the walk takes any.
    const std::span<const FanEntry> fan(first, last);
    for (const FanEntry& e : fan)
      for (const Index start : {e.x, e.y})
        if (is_feature(features, e.apex, start))
          if (const auto s = sector_from(features, fan, &e, start)) out.push_back(*s);
    first = last;
  }
  return out;
}

double narrowest_feature_sector_deg(const TriangleMesh& mesh, const Features& features) {
  double narrowest = 360;
  for (const auto& [v, angle] : narrowest_sectors(mesh, features))
    narrowest = std::min(narrowest, angle);
  return narrowest;
}

std::vector<NarrowAngle> narrow_feature_angles(const TriangleMesh& mesh, const Features& features,
                                               double below_deg) {
  std::vector<NarrowAngle> out;
  for (const auto& [v, angle] : narrowest_sectors(mesh, features))
    if (angle < below_deg) out.push_back({mesh.vertices[v], angle});
  return out;
}

}  // namespace cvtmesh
