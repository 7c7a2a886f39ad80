#include "voronoi/cell_normals.hpp"

#include <algorithm>
#include <mutex>
#include <utility>

#include "geometry/unit_vector.hpp"

namespace cvtmesh {

namespace {

// Per seed, over its polygons: Σ of their area vectors (twice the area × the input triangle's
// unit normal) and Σ of twice their areas times their centroids. Chunks are summed in order as
// they complete, and freed: the same sums on any thread count, without holding a record per
// polygon.
class CellMomentSink : public PolygonSink {
 public:
  explicit CellMomentSink(std::size_t seeds) : sums_(seeds) {}
  struct Sums {
    Vec3 area2{0, 0, 0}, moment2{0, 0, 0};
    double mass2 = 0;
  };
  void begin(std::size_t chunks) override {
    sums_.assign(sums_.size(), {});
    chunks_.assign(chunks, {});
    done_.assign(chunks, 0);
    added_ = 0;
  }
  void polygon(std::size_t chunk, const RvdPolygon& p) override {
    Sums s;
    const auto& v = p.vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      const Vec3 fan = cross(v[k].point - v[0].point, v[k + 1].point - v[0].point);
      const double area2 = norm(fan);
      s.area2 += fan;
      s.moment2 += (area2 / 3) * (v[0].point + v[k].point + v[k + 1].point);
      s.mass2 += area2;
    }
    chunks_[chunk].push_back({p.seed, s});
  }
  void chunk_done(std::size_t chunk) override {
    const std::lock_guard lock(adding_);
    done_[chunk] = 1;
    add_done();
  }
  void end() override {
    std::fill(done_.begin(), done_.end(), 1);
    add_done();
  }
  const std::vector<Sums>& sums() const { return sums_; }

 private:
  void add_done() {
    for (; added_ < chunks_.size() && done_[added_]; ++added_) {
      for (const auto& [seed, s] : chunks_[added_]) {
        Sums& to = sums_[seed];
        to.area2 += s.area2;
        to.moment2 += s.moment2;
        to.mass2 += s.mass2;
      }
      std::vector<std::pair<Index, Sums>>().swap(chunks_[added_]);
    }
  }
  std::vector<Sums> sums_;
  std::vector<std::vector<std::pair<Index, Sums>>> chunks_;
  std::vector<char> done_;
  std::size_t added_ = 0;
  std::mutex adding_;
};

}  // namespace

std::vector<CellNormal> cell_normals(const TriangleMesh& surface, const std::vector<Vec3>& seeds,
                                     TraversalMemory& memory) {
  const RestrictedVoronoiDiagram rvd(surface, seeds, memory);
  CellMomentSink moments(seeds.size());
  PolygonSink* sinks[] = {&moments};
  rvd.traverse(sinks, memory);
  std::vector<CellNormal> out(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const CellMomentSink::Sums& c = moments.sums()[s];
    out[s] = {c.mass2 > 0 ? (1 / c.mass2) * c.moment2 : seeds[s], unit_or_zero(c.area2)};
  }
  return out;
}

}  // namespace cvtmesh
