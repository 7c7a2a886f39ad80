#include "finish/flat_ears.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "features/edge_uses.hpp"
#include "geometry/triangle_sides.hpp"

namespace cvtmesh {

namespace {

// An angle at least kFlatBoundaryAngleDeg wide has a cosine at most this.
const double kFlatEarCos = std::cos(kFlatBoundaryAngleDeg * M_PI / 180);
// cos 120°: the same for an ear whose vertex is no seed. A cell in two pieces along a boundary
// gives its far piece a vertex there, between two boundary seeds whose link it takes; without it
// the boundary runs along that link, as between any two seeds (alligator.obj of a public test set:
// θmin 14.3° → 17.4° at 1k, 15.8° → 40.0° at 5k, the Hausdorff max the same).
const double kSeedlessEarCos = std::cos(120 * M_PI / 180);

// cos 120°: an ear whose normal turns more than this from its neighbour's across the chord lies
// folded back over it. A cell in two pieces along a boundary curve makes one: the far piece's
// vertex (alligator.obj of a public test set, cut flat along a staircase of corners, at 1k:
// 9 ears folded flat, θmin 8.5°).
const double kFoldedCos = std::cos(120 * M_PI / 180);

// A vertex this close to a neighbour, relative to the ear's third edge, lies on top of it.
constexpr double kOnTop = 1e-12;

// How many triangles use each edge, counted down as ears go, and which: the mesh's sides sorted
// (sorted_sides), each edge's run of them found by binary search.
class EdgeCounts {
 public:
  explicit EdgeCounts(const TriangleMesh& mesh) : sides_(sorted_sides(mesh)) {
    for (std::size_t i = 0; i < sides_.size(); ++i) {
      const Edge e{sides_[i].lo, sides_[i].hi};
      if (edges_.empty() || edges_.back() != e)
        edges_.push_back(e), uses_.push_back(0), first_.push_back(i);
      ++uses_.back();
    }
    first_.push_back(sides_.size());
  }
  int at(const Edge& e) const { return uses_[slot(e)]; }
  void remove(const Triangle& t) {
    for (int k = 0; k < 3; ++k) --uses_[slot(edge_of(t[k], t[(k + 1) % 3]))];
  }
  // A triangle on edge `e` other than `t` and not `removed`, if there is one.
  std::optional<std::size_t> other(const Edge& e, std::size_t t,
                                   const std::vector<bool>& removed) const {
    const std::size_t s = slot(e);
    for (std::size_t i = first_[s]; i < first_[s + 1]; ++i)
      if (sides_[i].triangle != t && !removed[sides_[i].triangle]) return sides_[i].triangle;
    return std::nullopt;
  }

 private:
  std::size_t slot(const Edge& e) const {
    return static_cast<std::size_t>(std::lower_bound(edges_.begin(), edges_.end(), e) -
                                    edges_.begin());
  }
  std::vector<TriangleSide> sides_;
  std::vector<Edge> edges_;
  std::vector<int> uses_;
  std::vector<std::size_t> first_;  // per edge, its first side; then the number of sides
};

// Whether vertex a of triangle t lies on top of its vertex n: nearer than kOnTop times the
// triangle's edge across from a.
bool on_top(const TriangleMesh& mesh, Index a, Index n, const Triangle& t) {
  const Index b = t[0] == a ? t[1] : t[0], c = t[2] == a ? t[1] : t[2];
  return distance(mesh.vertices[a], mesh.vertices[n]) <=
         kOnTop * distance(mesh.vertices[b], mesh.vertices[c]);
}

// Whether triangle (a, b, c) folds back onto triangle `across` (on its edge b-c): their normals
// more than 120° apart.
bool folded_onto(const TriangleMesh& mesh, Index a, Index b, Index c, const Triangle& across) {
  const auto normal = [&](Index u, Index v, Index w) {
    const Vec3& p = mesh.vertices[u];
    return cross(mesh.vertices[v] - p, mesh.vertices[w] - p);
  };
  const Vec3 n = normal(a, b, c), m = normal(across[0], across[1], across[2]);
  return dot(n, m) < kFoldedCos * norm(n) * norm(m);
}

// The corner of triangle `i` that is a flat or folded ear's vertex, or -1. `triangles_at`: per
// vertex, the triangles that use it (an ear's vertex has no other: where it has, it is a pinch
// of two fans, which an ear's removal would change).
int flat_ear_corner(const TriangleMesh& mesh, std::size_t i, const EdgeCounts& uses,
                    const std::vector<int>& triangles_at, const std::vector<bool>& kept,
                    const std::vector<bool>& seedless, const std::vector<bool>& removed) {
  const Triangle& t = mesh.triangles[i];
  for (int k = 0; k < 3; ++k) {
    const Index a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
    if (triangles_at[a] != 1) continue;
    if (uses.at(edge_of(a, b)) != 1 || uses.at(edge_of(a, c)) != 1) continue;
    // The third edge must be an interior edge: a triangle alone is a component, not an ear.
    if (uses.at(edge_of(b, c)) != 2) continue;
    // An ear whose vertex lies on top of a neighbour, a zero-area triangle, goes even at a
    // corner: the neighbour stands there. (octagonal_pocket.stl of trimesh's test models has two
    // corners 6e-34 apart at a non-manifold vertex; their ear, θmin 0°, goes at 5k, and with it
    // one of the two.)
    if (on_top(mesh, a, b, t) || on_top(mesh, a, c, t)) return k;
    if (kept[a]) continue;
    const Vec3 u = mesh.vertices[b] - mesh.vertices[a], v = mesh.vertices[c] - mesh.vertices[a];
    const double lengths = norm(u) * norm(v);
    const double flat_cos = seedless[a] ? kSeedlessEarCos : kFlatEarCos;
    if (lengths > 0 && dot(u, v) <= flat_cos * lengths) return k;
    const std::optional<std::size_t> across = uses.other(edge_of(b, c), i, removed);
    if (across && folded_onto(mesh, a, b, c, mesh.triangles[*across])) return k;
  }
  return -1;
}

}  // namespace

std::size_t remove_flat_ears(TriangleMesh& mesh, const std::vector<bool>& kept,
                             const std::vector<bool>& seedless) {
  EdgeCounts uses(mesh);
  std::vector<int> triangles_at(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (const Index v : t) ++triangles_at[v];
  std::vector<bool> removed(mesh.triangles.size(), false);
  std::size_t ears = 0;
  // A removal can make an ear of the triangle across the chord: sweep again until none is found.
  for (bool found = true; found;) {
    found = false;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      if (removed[i] || flat_ear_corner(mesh, i, uses, triangles_at, kept, seedless, removed) < 0)
        continue;
      uses.remove(mesh.triangles[i]);
      for (const Index v : mesh.triangles[i]) --triangles_at[v];
      removed[i] = true;
      ++ears;
      found = true;
    }
  }
  std::size_t next = 0;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    if (!removed[i]) mesh.triangles[next++] = mesh.triangles[i];
  mesh.triangles.resize(next);
  return ears;
}

}  // namespace cvtmesh
