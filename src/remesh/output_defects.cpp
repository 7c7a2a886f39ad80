#include "remesh/output_defects.hpp"

#include <algorithm>
#include <tuple>

#include "cvtmesh/rvd.hpp"
#include "geometry/union_find.hpp"
#include "voronoi/dual_triangle.hpp"

namespace cvtmesh {

namespace {

Triangle rotated_to_smallest(Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// One use of an edge by a triangle: the edge's ends (smaller first), whether the triangle runs
// from the smaller to the larger, and the triangle.
struct EdgeUse {
  Index a, b;
  bool forward;
  std::size_t triangle;
  auto key() const { return std::tie(a, b, triangle); }
};

// The crossing points of the listed triangles' dual Voronoi edges (their RVD vertices of type
// C), each with its ball radius.
class CrossingCollector : public PolygonSink {
 public:
  CrossingCollector(const std::vector<Vec3>& seeds, const std::vector<Triangle>& wanted)
      : seeds_(seeds), wanted_(wanted) {
    for (Triangle& t : wanted_) t = rotated_to_smallest(t);
    std::sort(wanted_.begin(), wanted_.end());
  }
  struct Crossing {
    Vec3 point;
    double radius;
  };
  void begin(std::size_t chunks) override { chunks_.assign(chunks, {}); }
  void polygon(std::size_t chunk, const RvdPolygon& poly) override {
    for (std::size_t k = 0; k < poly.vertices.size(); ++k) {
      const auto t = dual_triangle(poly, k);
      if (!t || !std::binary_search(wanted_.begin(), wanted_.end(), *t)) continue;
      const Vec3& p = poly.vertices[k].point;
      chunks_[chunk].push_back({p, distance(p, seeds_[poly.seed])});
    }
  }
  std::vector<Crossing> result() const {
    std::vector<Crossing> all;
    for (const auto& c : chunks_) all.insert(all.end(), c.begin(), c.end());
    return all;
  }

 private:
  const std::vector<Vec3>& seeds_;
  std::vector<Triangle> wanted_;
  std::vector<std::vector<Crossing>> chunks_;
};

}  // namespace

OutputDefects find_output_defects(const TriangleMesh& rdt, const std::vector<bool>& may_bound,
                                  bool folds) {
  const auto& tris = rdt.triangles;
  std::vector<EdgeUse> uses;
  uses.reserve(3 * tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index u = tris[t][k], w = tris[t][(k + 1) % 3];
      uses.push_back({std::min(u, w), std::max(u, w), u < w, t});
    }
  std::sort(uses.begin(), uses.end(),
            [](const EdgeUse& x, const EdgeUse& y) { return x.key() < y.key(); });

  OutputDefects d;
  std::vector<bool> bad(tris.size(), false);
  // Corners (triangle, vertex) joined across the manifold edges they share: a vertex whose
  // corners form several classes has several fans.
  UnionFind fans(3 * tris.size());
  auto corner = [&](std::size_t t, Index v) {
    const Triangle& f = tris[t];
    return 3 * t + static_cast<std::size_t>(f[0] == v ? 0 : f[1] == v ? 1 : 2);
  };
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
    const std::size_t count = j - i;
    const bool folded = folds && count == 2 && uses[i].forward == uses[i + 1].forward;
    const bool stray = count == 1 && !(may_bound[uses[i].a] && may_bound[uses[i].b]);
    if (count >= 3 || folded || stray)
      for (std::size_t k = i; k < j; ++k) bad[uses[k].triangle] = true;
    d.nonmanifold_edges += count >= 3;
    d.folded_edges += folded;
    d.stray_boundary_edges += stray;
    if (count == 2) {
      const std::size_t s = uses[i].triangle, t = uses[i + 1].triangle;
      fans.unite(corner(s, uses[i].a), corner(t, uses[i].a));
      fans.unite(corner(s, uses[i].b), corner(t, uses[i].b));
    }
    i = j;
  }
  // Per vertex, its corners' classes: sorted (vertex, class) pairs, then runs per vertex.
  std::vector<std::pair<Index, std::size_t>> classes;
  classes.reserve(3 * tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) classes.push_back({tris[t][k], fans.find(3 * t + k)});
  std::sort(classes.begin(), classes.end());
  for (std::size_t i = 0; i < classes.size();) {
    std::size_t j = i;
    bool several = false;
    while (j < classes.size() && classes[j].first == classes[i].first) {
      several = several || classes[j].second != classes[i].second;
      ++j;
    }
    if (several) {
      ++d.nonmanifold_vertices;
      for (std::size_t k = i; k < j; ++k) bad[classes[k].second / 3] = true;
    }
    i = j;
  }
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (bad[t]) d.triangles.push_back(tris[t]);
  return d;
}

std::vector<Vec3> refinement_points(const TriangleMesh& surface, const std::vector<Vec3>& seeds,
                                    const std::vector<Triangle>& triangles) {
  if (triangles.empty()) return {};
  const RestrictedVoronoiDiagram rvd(surface, seeds);
  CrossingCollector collector(seeds, triangles);
  rvd.traverse(collector);
  std::vector<Vec3> kept;
  std::vector<double> radius;
  for (const auto& c : collector.result()) {
    // A crossing at a seed (radius 0) would duplicate it; one near a point kept already adds
    // nothing the other does not.
    if (!(c.radius > 0)) continue;
    bool near = false;
    for (std::size_t k = 0; k < kept.size() && !near; ++k)
      near = distance(kept[k], c.point) < 0.5 * std::max(c.radius, radius[k]);
    if (near) continue;
    kept.push_back(c.point);
    radius.push_back(c.radius);
  }
  return kept;
}

}  // namespace cvtmesh
