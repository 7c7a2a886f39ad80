#include "cvt/cell_islands.hpp"

#include <algorithm>
#include <array>
#include <tuple>

#include "cvtmesh/rvd.hpp"
#include "geometry/union_find.hpp"

namespace cvtmesh {

namespace {

// Per polygon: its cell, area and moment; per polygon side on an input edge: that edge.
class PieceCollector : public PolygonSink {
 public:
  explicit PieceCollector(const TriangleMesh& surface) : surface_(surface) {}
  struct Polygon {
    Index seed, triangle;
    double area;
    Vec3 moment;  // area × centroid
  };
  struct Side {
    Index seed;
    std::array<Index, 2> edge;  // input vertex ids, the smaller first
    std::size_t polygon;
  };
  void begin(std::size_t chunks) override {
    polygons_.assign(chunks, {});
    sides_.assign(chunks, {});
  }
  void polygon(std::size_t chunk, const RvdPolygon& p) override {
    const auto& v = p.vertices;
    Polygon out{p.seed, p.triangle, 0, {}};
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      const double a = triangle_area(v[0].point, v[k].point, v[k + 1].point);
      out.area += a;
      out.moment += (a / 3) * (v[0].point + v[k].point + v[k + 1].point);
    }
    const Triangle& t = surface_.triangles[p.triangle];
    for (std::size_t k = 0; k < v.size(); ++k) {
      const RvdVertex &a = v[k], &b = v[(k + 1) % v.size()];
      // The side lies on input edge e when both ends are on it (symbol -(e+1)).
      for (std::int32_t s : a.symbols) {
        if (s >= 0 || (s != b.symbols[0] && s != b.symbols[1])) continue;
        const int e = -(s + 1);
        const Index u = t[e], w = t[(e + 1) % 3];
        sides_[chunk].push_back(
            {p.seed, {std::min(u, w), std::max(u, w)}, polygons_[chunk].size()});
      }
    }
    polygons_[chunk].push_back(out);
  }
  std::vector<CellIsland> islands() const;

 private:
  const TriangleMesh& surface_;
  std::vector<std::vector<Polygon>> polygons_;
  std::vector<std::vector<Side>> sides_;
};

std::vector<CellIsland> PieceCollector::islands() const {
  // Number the polygons in chunk order: the same on any thread count.
  std::vector<Polygon> polygons;
  std::vector<Side> sides;
  for (std::size_t c = 0; c < polygons_.size(); ++c) {
    for (Side s : sides_[c]) {
      s.polygon += polygons.size();
      sides.push_back(s);
    }
    polygons.insert(polygons.end(), polygons_[c].begin(), polygons_[c].end());
  }
  // A cell meets an input edge in one segment (the cell is convex): its polygons on either
  // side of the edge both have that segment as a side, and are one piece.
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return std::tie(a.seed, a.edge, a.polygon) < std::tie(b.seed, b.edge, b.polygon);
  });
  UnionFind pieces(polygons.size());
  for (std::size_t i = 1; i < sides.size(); ++i)
    if (sides[i].seed == sides[i - 1].seed && sides[i].edge == sides[i - 1].edge)
      pieces.unite(sides[i].polygon, sides[i - 1].polygon);
  // Per cell, its pieces (by root) with their area and moment; all but the largest are islands.
  struct Piece {
    Index seed;
    std::size_t first;  // the piece's first polygon, for a stable order
    double area;
    Vec3 moment;
  };
  std::vector<Piece> by_root(polygons.size(), {0, 0, 0, {}});
  std::vector<bool> seen(polygons.size(), false);
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    const std::size_t r = pieces.find(p);
    if (!seen[r]) by_root[r] = {polygons[p].seed, p, 0, {}}, seen[r] = true;
    by_root[r].area += polygons[p].area;
    by_root[r].moment += polygons[p].moment;
  }
  std::vector<Piece> all;
  for (std::size_t r = 0; r < polygons.size(); ++r)
    if (seen[r]) all.push_back(by_root[r]);
  std::sort(all.begin(), all.end(), [](const Piece& a, const Piece& b) {
    return std::make_tuple(a.seed, -a.area, a.first) < std::make_tuple(b.seed, -b.area, b.first);
  });
  std::vector<CellIsland> islands;
  for (std::size_t i = 1; i < all.size(); ++i)
    if (all[i].seed == all[i - 1].seed && all[i].area > 0)
      islands.push_back({all[i].seed, (1 / all[i].area) * all[i].moment, all[i].area});
  return islands;
}

}  // namespace

std::vector<CellIsland> cell_islands(const TriangleMesh& surface, const std::vector<Vec3>& seeds) {
  const RestrictedVoronoiDiagram rvd(surface, seeds);
  PieceCollector collector(surface);
  rvd.traverse(collector);
  return collector.islands();
}

}  // namespace cvtmesh
