#include "remesh/flip_links.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>

#include "geometry/triangles_around.hpp"
#include "quality/min_shape.hpp"

namespace cvtmesh {

namespace {

Vec3 normal(const TriangleMesh& m, const Triangle& t) {
  const Vec3& a = m.vertices[t[0]];
  return cross(m.vertices[t[1]] - a, m.vertices[t[2]] - a);
}

double smallest_angle(const TriangleMesh& m, const Triangle& t) {
  return min_shape(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]).min_angle;
}

// The triangles at each vertex, kept up to date through the flips.
class VertexTriangles {
 public:
  explicit VertexTriangles(const TriangleMesh& m) : of_(triangles_around(m)) {}
  const std::vector<Index>& operator()(Index v) const { return of_[v]; }
  void add(Index v, Index t) { of_[v].push_back(t); }
  void remove(Index v, Index t) { std::erase(of_[v], t); }

 private:
  std::vector<std::vector<Index>> of_;
};

// Where vertex v is in t (0-2), or 3.
int position(const Triangle& t, Index v) {
  return t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : 3;
}

bool has_edge(const TriangleMesh& m, const VertexTriangles& at, Index a, Index b) {
  return std::any_of(at(a).begin(), at(a).end(),
                     [&](Index t) { return position(m.triangles[t], b) != 3; });
}

// The triangles on edge (a, b).
std::vector<Index> triangles_on(const TriangleMesh& m, const VertexTriangles& at, Index a,
                                Index b) {
  std::vector<Index> on;
  for (const Index t : at(a))
    if (position(m.triangles[t], b) != 3) on.push_back(t);
  return on;
}

// Flips in edge (a, b) if one flip makes it with no angle under `min_angle`; whether it did.
bool flip_in(TriangleMesh& m, VertexTriangles& at, Index a, Index b, double min_angle) {
  for (const Index t1 : at(a)) {
    const Triangle& first = m.triangles[t1];
    const int k = position(first, a);
    const Index c = first[(k + 1) % 3], d = first[(k + 2) % 3];
    // Edge (c, d) has just two triangles: this one and (d, c, b).
    const std::vector<Index> on_edge = triangles_on(m, at, c, d);
    if (on_edge.size() != 2) continue;
    const Index t2 = on_edge[0] == t1 ? on_edge[1] : on_edge[0];
    const Triangle& second = m.triangles[t2];
    const int j = position(second, d);
    if (second[(j + 1) % 3] != c || second[(j + 2) % 3] != b) continue;
    const Triangle new1{a, c, b}, new2{a, b, d};
    const Vec3 facing = normal(m, first) + normal(m, second);
    if (!(dot(normal(m, new1), facing) > 0 && dot(normal(m, new2), facing) > 0)) continue;
    if (smallest_angle(m, new1) < min_angle || smallest_angle(m, new2) < min_angle) continue;
    m.triangles[t1] = new1;
    m.triangles[t2] = new2;
    at.add(a, t2);
    at.add(b, t1);
    at.remove(c, t2);
    at.remove(d, t1);
    return true;
  }
  return false;
}

// Longest chain of missing links followed from a corner, and longest bridge across a wedge
// (close_corner_wedges): far past any wedge seen, short enough that a wrong turn costs little.
constexpr std::size_t kMaxChain = 64;
constexpr std::size_t kMaxBridge = 3;

// The vertices joined to u by an edge of one triangle (the boundary).
std::vector<Index> boundary_neighbours(const TriangleMesh& m, const VertexTriangles& at, Index u) {
  std::vector<Index> found;
  for (const Index t : at(u))
    for (const Index w : m.triangles[t])
      if (w != u && std::find(found.begin(), found.end(), w) == found.end() &&
          triangles_on(m, at, u, w).size() == 1)
        found.push_back(w);
  return found;
}

// The paths from a to b along the boundary, one each way round from a, of at most `longest`
// edges and through no vertex of `avoid` (a and b aside), each as its vertices from a to b.
std::vector<std::vector<Index>> boundary_paths(const TriangleMesh& m, const VertexTriangles& at,
                                               Index a, Index b, const std::set<Index>& avoid,
                                               std::size_t longest) {
  std::vector<std::vector<Index>> paths;
  for (const Index first : boundary_neighbours(m, at, a)) {
    std::vector<Index> path{a, first};
    while (path.back() != b && path.size() <= longest && !avoid.contains(path.back())) {
      const std::vector<Index> next = boundary_neighbours(m, at, path.back());
      if (next.size() != 2) break;  // not along one loop
      path.push_back(next[0] == path[path.size() - 2] ? next[1] : next[0]);
    }
    if (path.back() == b) paths.push_back(std::move(path));
  }
  return paths;
}

// The triangles that close the wedge between chains A and B (from the corner, A[0] = B[0], to
// the first vertices with triangles) and the boundary `bridge` from A's end to B's: a zipper
// between the chains (each step to the shorter rung), then a fan from A's end over the bridge's
// inner vertices. None when they would make an edge the mesh has, or fold against the bridge's
// triangle.
std::optional<std::vector<Triangle>> zipped_wedge(const TriangleMesh& m, const VertexTriangles& at,
                                                  const std::vector<Index>& A,
                                                  const std::vector<Index>& B,
                                                  const std::vector<Index>& bridge) {
  // The new edges inside the loop must be new to the mesh: the last rung and the fan's.
  if (bridge.size() > 2 && has_edge(m, at, A.back(), B.back())) return std::nullopt;
  for (std::size_t k = 2; k + 1 < bridge.size(); ++k)
    if (has_edge(m, at, A.back(), bridge[k])) return std::nullopt;
  const std::vector<Index> across = triangles_on(m, at, bridge[0], bridge[1]);
  if (across.size() != 1) return std::nullopt;
  std::vector<Triangle> wedge{{A[0], A[1], B[1]}};
  for (std::size_t i = 1, j = 1; i + 1 < A.size() || j + 1 < B.size();) {
    const bool along_a = j + 1 == B.size() ||
                         (i + 1 < A.size() && distance(m.vertices[A[i + 1]], m.vertices[B[j]]) <=
                                                  distance(m.vertices[A[i]], m.vertices[B[j + 1]]));
    wedge.push_back(along_a ? Triangle{A[i], A[i + 1], B[j]} : Triangle{A[i], B[j + 1], B[j]});
    (along_a ? i : j) += 1;
  }
  for (std::size_t k = 1; k + 1 < bridge.size(); ++k)
    wedge.push_back({A.back(), bridge[k], bridge[k + 1]});
  // Each triangle in the order of the wedge's loop (A out, across, B back), which runs the
  // bridge's first edge the way its triangle in the mesh must not (else all turn round); every
  // new triangle must face as that one does.
  std::map<Index, std::size_t> place;
  for (std::size_t k = 0; k < A.size(); ++k) place[A[k]] = k;
  for (std::size_t k = 1; k + 1 < bridge.size(); ++k) place[bridge[k]] = A.size() + k;
  for (std::size_t k = 1; k < B.size(); ++k) place[B[k]] = A.size() + bridge.size() + B.size() - k;
  for (Triangle& t : wedge)
    std::sort(t.begin(), t.end(), [&](Index x, Index y) { return place[x] < place[y]; });
  const Triangle& old = m.triangles[across[0]];
  if (old[(position(old, bridge[0]) + 1) % 3] == bridge[1])
    for (Triangle& t : wedge) std::swap(t[1], t[2]);
  for (const Triangle& t : wedge)
    if (!(dot(normal(m, t), normal(m, old)) > 0)) return std::nullopt;
  return wedge;
}

}  // namespace

std::vector<bool> flip_in_links(TriangleMesh& mesh, const std::vector<Edge>& links,
                                double min_angle_deg) {
  VertexTriangles at(mesh);
  std::vector<bool> flipped;
  for (const auto& [a, b] : links)
    // Orientation makes (a, b) and (b, a) the same search.
    flipped.push_back(!has_edge(mesh, at, a, b) && flip_in(mesh, at, a, b, min_angle_deg));
  return flipped;
}

bool take_out_edge(TriangleMesh& mesh, const Edge& e) {
  const VertexTriangles at(mesh);
  const auto [a, b] = e;
  const std::vector<Index> on_edge = triangles_on(mesh, at, a, b);
  if (on_edge.size() != 2) return false;
  // t1 walks a → b, t2 b → a: their third corners c and d.
  Index t1 = on_edge[0], t2 = on_edge[1];
  if (mesh.triangles[t1][(position(mesh.triangles[t1], a) + 1) % 3] != b) std::swap(t1, t2);
  const Triangle first = mesh.triangles[t1], second = mesh.triangles[t2];
  if (first[(position(first, a) + 1) % 3] != b || second[(position(second, b) + 1) % 3] != a)
    return false;
  const Index c = first[(position(first, b) + 1) % 3], d = second[(position(second, a) + 1) % 3];
  if (c == d) return false;
  // The flip: (c, a, d) and (d, b, c), where c-d is no edge yet, a and b keep three triangles
  // each, and neither new triangle folds over.
  const Triangle new1{c, a, d}, new2{d, b, c};
  const Vec3 facing = normal(mesh, first) + normal(mesh, second);
  const bool flippable = at(a).size() >= 4 && at(b).size() >= 4 && !has_edge(mesh, at, c, d) &&
                         dot(normal(mesh, new1), facing) > 0 && dot(normal(mesh, new2), facing) > 0;
  const double flipped_angle =
      flippable ? std::min(smallest_angle(mesh, new1), smallest_angle(mesh, new2)) : -1;
  // The halving: a vertex m at the edge's middle, in the plane of each old triangle, so no fold.
  const std::vector<Vec3>& p = mesh.vertices;
  const Vec3 middle = 0.5 * (p[a] + p[b]);
  const double halved_angle =
      std::min({min_shape(p[a], middle, p[c]).min_angle, min_shape(middle, p[b], p[c]).min_angle,
                min_shape(p[b], middle, p[d]).min_angle, min_shape(middle, p[a], p[d]).min_angle});
  if (flipped_angle >= halved_angle) {
    mesh.triangles[t1] = new1;
    mesh.triangles[t2] = new2;
    return true;
  }
  const auto m = static_cast<Index>(mesh.vertices.size());
  mesh.vertices.push_back(middle);
  const std::array<Triangle, 4> halves{Triangle{a, m, c}, Triangle{m, b, c}, Triangle{b, m, d},
                                       Triangle{m, a, d}};
  mesh.triangles[t1] = halves[0];
  mesh.triangles[t2] = halves[2];
  mesh.triangles.push_back(halves[1]);
  mesh.triangles.push_back(halves[3]);
  return true;
}

std::size_t close_corner_wedges(TriangleMesh& mesh, const std::vector<Index>& corners,
                                const std::vector<Edge>& links) {
  VertexTriangles at(mesh);
  std::map<Index, std::vector<Index>> partners;  // per vertex, the other ends of its links
  for (const auto& [a, b] : links) partners[a].push_back(b), partners[b].push_back(a);
  const auto unused = [&](Index v) { return at(v).empty(); };
  std::size_t added = 0;
  for (const Index corner : corners) {
    const auto found = partners.find(corner);
    if (!unused(corner) || found == partners.end() || found->second.size() != 2) continue;
    // Each side's chain of missing links, from the corner to the first vertex with triangles.
    std::array<std::vector<Index>, 2> side;
    bool chained = true;
    for (int k = 0; k < 2 && chained; ++k) {
      side[k] = {corner, found->second[k]};
      while (chained && unused(side[k].back())) {
        const auto next = partners.find(side[k].back());
        chained = next != partners.end() && next->second.size() == 2 && side[k].size() < kMaxChain;
        if (chained) {
          const Index before = side[k][side[k].size() - 2];
          side[k].push_back(next->second[0] == before ? next->second[1] : next->second[0]);
        }
      }
    }
    if (!chained) continue;
    // The output's boundary across the wedge, between the two chains' ends: the way round from
    // A's end that reaches B's in at most kMaxBridge edges, through vertices of neither chain.
    std::set<Index> in_chains(side[0].begin(), side[0].end());
    in_chains.insert(side[1].begin() + 1, side[1].end());
    if (in_chains.size() != side[0].size() + side[1].size() - 1) continue;  // chains that meet
    std::optional<std::vector<Triangle>> wedge;
    for (const std::vector<Index>& bridge :
         boundary_paths(mesh, at, side[0].back(), side[1].back(), in_chains, kMaxBridge))
      if ((wedge = zipped_wedge(mesh, at, side[0], side[1], bridge))) break;
    if (!wedge) continue;
    for (const Triangle& t : *wedge) {
      const auto id = static_cast<Index>(mesh.triangles.size());
      mesh.triangles.push_back(t);
      for (const Index v : t) at.add(v, id);
    }
    added += wedge->size();
  }
  return added;
}

}  // namespace cvtmesh
