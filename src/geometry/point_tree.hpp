// Seeds nearest to a point: a kd-tree over the seeds (nanoflann).
#pragma once

#include <memory>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class NearestSeed {
 public:
  explicit NearestSeed(const std::vector<Vec3>& seeds);
  ~NearestSeed();
  // Thread-safe after construction; deterministic (the tree is built the same way every time).
  Index operator()(const Vec3& p) const;
  // The k seeds nearest to p (all seeds if fewer), in no particular order.
  void nearest(const Vec3& p, std::size_t k, std::vector<Index>& out) const;
  // Every seed within squared distance r2 of p, in no particular order.
  void within(const Vec3& p, double r2, std::vector<Index>& out) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace cvtmesh
