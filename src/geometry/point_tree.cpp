#include "geometry/point_tree.hpp"

#include <nanoflann.hpp>

#include "geometry/index_range.hpp"
#include "geometry/kd_nearest.hpp"

namespace cvtmesh {

namespace {

// nanoflann's dataset adaptor over the point array.
struct PointCloud {
  const std::vector<Vec3>& points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return points[i][static_cast<int>(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

// 32-bit ids: the tree keeps one per point (the surface projector's tree has one per input
// triangle: 8 MB less on a 2M-triangle input than with size_t).
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                                   PointCloud, 3, Index>;

}  // namespace

struct PointTree::Tree {
  PointCloud cloud;
  KdTree index;
  explicit Tree(const std::vector<Vec3>& points)
      : cloud{points}, index(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    index.buildIndex();
  }
};

PointTree::PointTree(const std::vector<Vec3>& points) {
  require_index_range(points.size(), "points for a kd-tree");
  tree_ = std::make_unique<Tree>(points);
}
PointTree::~PointTree() = default;

Index PointTree::operator()(const Vec3& p) const {
  return nearest_id(tree_->index, p);
}

void PointTree::nearest(const Vec3& p, std::size_t k, std::vector<Index>& out,
                        double bound2) const {
  // Per thread, not per query: the RVD asks for every seed's neighbours in most evaluations.
  thread_local std::vector<Index> indices;
  thread_local std::vector<double> d2;
  indices.resize(k);
  d2.resize(k);
  const double query[3] = {p.x, p.y, p.z};
  nanoflann::KNNResultSet<double, Index> result(k);
  result.init(indices.data(), d2.data());
  // The result set's worst distance until it is full: nanoflann prunes every branch farther.
  if (k > 0 && bound2 < d2[k - 1]) d2[k - 1] = bound2;
  tree_->index.findNeighbors(result, query, nanoflann::SearchParams());
  out.assign(indices.begin(), indices.begin() + static_cast<std::ptrdiff_t>(result.size()));
}

void PointTree::within(const Vec3& p, double r2, std::vector<Index>& out) const {
  std::vector<std::pair<Index, double>> found;
  const double query[3] = {p.x, p.y, p.z};
  tree_->index.radiusSearch(query, r2, found, nanoflann::SearchParams(32, 0, false));
  out.clear();
  for (const auto& [index, d2] : found) out.push_back(index);
}

}  // namespace cvtmesh
