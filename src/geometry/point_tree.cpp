#include "voronoi/nearest_seed.hpp"

#include <nanoflann.hpp>

namespace cvtmesh {

namespace {

// nanoflann's dataset adaptor over the seed array.
struct SeedCloud {
  const std::vector<Vec3>& seeds;
  std::size_t kdtree_get_point_count() const { return seeds.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return seeds[i][static_cast<int>(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, SeedCloud>,
                                                   SeedCloud, 3, std::size_t>;

}  // namespace

struct NearestSeed::Tree {
  SeedCloud cloud;
  KdTree index;
  explicit Tree(const std::vector<Vec3>& seeds)
      : cloud{seeds}, index(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    index.buildIndex();
  }
};

NearestSeed::NearestSeed(const std::vector<Vec3>& seeds) : tree_(std::make_unique<Tree>(seeds)) {}
NearestSeed::~NearestSeed() = default;

Index NearestSeed::operator()(const Vec3& p) const {
  std::size_t index = 0;
  double d2 = 0;
  nanoflann::KNNResultSet<double, std::size_t> result(1);
  result.init(&index, &d2);
  const double query[3] = {p.x, p.y, p.z};
  tree_->index.findNeighbors(result, query, nanoflann::SearchParams());
  return static_cast<Index>(index);
}

void NearestSeed::nearest(const Vec3& p, std::size_t k, std::vector<Index>& out) const {
  std::vector<std::size_t> indices(k);
  std::vector<double> d2(k);
  const double query[3] = {p.x, p.y, p.z};
  const std::size_t found = tree_->index.knnSearch(query, k, indices.data(), d2.data());
  out.assign(indices.begin(), indices.begin() + static_cast<std::ptrdiff_t>(found));
}

void NearestSeed::within(const Vec3& p, double r2, std::vector<Index>& out) const {
  std::vector<std::pair<std::size_t, double>> found;
  const double query[3] = {p.x, p.y, p.z};
  tree_->index.radiusSearch(query, r2, found, nanoflann::SearchParams(32, 0, false));
  out.clear();
  for (const auto& [index, d2] : found) out.push_back(static_cast<Index>(index));
}

}  // namespace cvtmesh
