// Disjoint sets over 0..n-1 with path halving and union by size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "geometry/index_range.hpp"

namespace cvtmesh {

class UnionFind {
 public:
  // At most 2^32 - 1 elements, stored in 32 bits: half the memory of size_t ids (cell pieces
  // hold one per RVD polygon).
  explicit UnionFind(std::size_t n) : parent_(checked(n)), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
  }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = static_cast<std::uint32_t>(a);
    size_[a] += size_[b];
  }

 private:
  static std::size_t checked(std::size_t n) {
    require_index_range(n, "elements for a union-find");
    return n;
  }
  std::vector<std::uint32_t> parent_, size_;
};

}  // namespace cvtmesh
