// Points nearest to a query: a kd-tree over a point set (nanoflann), for the RVD's seeds and
// other point sets. (The surface projector has its own over triangle centroids that it keeps no
// array of.)
#pragma once

#include <limits>
#include <memory>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class PointTree {
 public:
  // Keeps a reference to `points`, which must outlive the tree.
  explicit PointTree(const std::vector<Vec3>& points);
  ~PointTree();
  // Thread-safe after construction; deterministic (the tree is built the same way every time).
  Index operator()(const Vec3& p) const;
  // The k points nearest to p (all points if fewer), in no particular order. `bound2`, if given,
  // must be a squared distance within which at least k points lie: the search skips what lies
  // beyond it from its start instead of from its k-th find.
  void nearest(const Vec3& p, std::size_t k, std::vector<Index>& out,
               double bound2 = std::numeric_limits<double>::infinity()) const;
  // Every point within squared distance r2 of p, in no particular order.
  void within(const Vec3& p, double r2, std::vector<Index>& out) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace cvtmesh
