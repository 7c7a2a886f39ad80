#include "remesh/pinch_defects.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

std::vector<Triangle> pinch_defects(const TriangleMesh& surface, const std::vector<Index>& corners,
                                    const TriangleMesh& out) {
  std::map<Vec3, int> sheets;  // per point where sheets touch, how many
  for (const Index c : corners) ++sheets[surface.vertices[c]];
  std::erase_if(sheets, [](const auto& point) { return point.second < 2; });
  if (sheets.empty()) return {};
  // Per vertex of a triangle at such a point, the first such vertex: the point's id.
  std::vector<Index> pinch_of(out.vertices.size(), kNoIndex);
  std::map<Vec3, Index> first;
  std::map<Vec3, int> used;  // per point, how many vertices of triangles are there
  for (const Triangle& t : out.triangles)
    for (const Index v : t)
      if (pinch_of[v] == kNoIndex && sheets.contains(out.vertices[v])) {
        pinch_of[v] = first.emplace(out.vertices[v], v).first->second;
        ++used[out.vertices[v]];
      }
  // (point, neighbour, vertex at the point) for every edge from a vertex at a point.
  std::vector<std::array<Index, 3>> edges;
  for (const Triangle& t : out.triangles)
    for (int k = 0; k < 3; ++k)
      if (const Index p = pinch_of[t[k]]; p != kNoIndex)
        for (const int j : {1, 2}) edges.push_back({p, t[(k + j) % 3], t[k]});
  std::sort(edges.begin(), edges.end());
  std::set<Edge> shared;  // (vertex at a point, neighbour) where two vertices there have it
  for (std::size_t i = 0, j = 0; i < edges.size(); i = j) {
    bool several = pinch_of[edges[i][1]] == edges[i][0];  // an edge between two of them
    for (j = i; j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1]; ++j)
      several = several || edges[j][2] != edges[i][2];
    if (several)
      for (std::size_t k = i; k < j; ++k) shared.insert({edges[k][2], edges[k][1]});
  }
  std::vector<Vec3> short_of;  // points with fewer vertices than sheets
  for (const auto& [point, count] : sheets)
    if (used[point] < count) short_of.push_back(point);
  const auto near = [&](const Triangle& t, const Vec3& point) {
    const Vec3 &a = out.vertices[t[0]], &b = out.vertices[t[1]], &c = out.vertices[t[2]];
    const double reach = std::max({distance(a, b), distance(b, c), distance(c, a)});
    return distance((1.0 / 3) * (a + b + c), point) <= reach;
  };
  std::vector<Triangle> defects;
  for (const Triangle& t : out.triangles)
    if (std::any_of(t.begin(), t.end(),
                    [&](Index v) {
                      return std::any_of(t.begin(), t.end(), [&](Index n) {
                        return shared.contains({v, n});
                      });
                    }) ||
        std::any_of(short_of.begin(), short_of.end(), [&](const Vec3& p) { return near(t, p); }))
      defects.push_back(t);
  return defects;
}

}  // namespace cvtmesh
