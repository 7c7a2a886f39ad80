// The seed nearest to a point: a kd-tree over the seeds (nanoflann).
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

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace cvtmesh
