#include "geometry/spatial_order.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <tuple>

namespace cvtmesh {

namespace {

constexpr int kBits = 21;  // per axis: 63 bits in all

// The low 21 bits of v, spread out to every third bit.
std::uint64_t spread(std::uint64_t v) {
  v &= (std::uint64_t{1} << kBits) - 1;
  v = (v | v << 32) & 0x001f00000000ffffULL;
  v = (v | v << 16) & 0x001f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

// Each point's Morton key in the points' bounding cube.
std::vector<std::uint64_t> morton_keys(const std::vector<Vec3>& points) {
  std::vector<std::uint64_t> key(points.size());
  if (points.empty()) return key;
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  // One scale for all axes (a cube), so that the curve's cells are cubes.
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double cells = static_cast<double>(std::uint64_t{1} << kBits);
  const double scale = extent > 0 ? cells / extent : 0;
  auto cell = [&](double x, double origin) {  // NaN (an unchecked input) goes to cell 0
    const double c = (x - origin) * scale;
    return static_cast<std::uint64_t>(c >= 0 ? std::min(c, cells - 1) : 0.0);
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    key[i] = spread(cell(p.x, lo.x)) | spread(cell(p.y, lo.y)) << 1 | spread(cell(p.z, lo.z)) << 2;
  }
  return key;
}

}  // namespace

std::vector<Index> spatial_order(const std::vector<Vec3>& points) {
  const std::vector<std::uint64_t> key = morton_keys(points);
  std::vector<Index> order(points.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    const Vec3 &p = points[a], &q = points[b];
    return std::tie(key[a], p.x, p.y, p.z, a) < std::tie(key[b], q.x, q.y, q.z, b);
  });
  return order;
}

SpatiallySorted spatially_sorted(const TriangleMesh& mesh) {
  SpatiallySorted sorted;
  const std::vector<Index> vertex_order = spatial_order(mesh.vertices);
  sorted.new_id.resize(mesh.vertices.size());
  sorted.mesh.vertices.resize(mesh.vertices.size());
  for (std::size_t k = 0; k < vertex_order.size(); ++k) {
    sorted.new_id[vertex_order[k]] = static_cast<Index>(k);
    sorted.mesh.vertices[k] = mesh.vertices[vertex_order[k]];
  }
  std::vector<Triangle> triangles(mesh.triangles.size());
  std::vector<Vec3> centroids(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Triangle f = mesh.triangles[t];
    for (Index& v : f) v = sorted.new_id[v];
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    triangles[t] = f;
    const auto& v = sorted.mesh.vertices;
    centroids[t] = (1.0 / 3) * (v[f[0]] + v[f[1]] + v[f[2]]);
  }
  // Ties (triangles with the same centroid: the same vertices, or mirrored ones) are broken by
  // the new vertex ids, so that the order does not depend on the given one.
  const std::vector<std::uint64_t> key = morton_keys(centroids);
  std::vector<Index> triangle_order(triangles.size());
  std::iota(triangle_order.begin(), triangle_order.end(), Index{0});
  std::sort(triangle_order.begin(), triangle_order.end(), [&](Index a, Index b) {
    const Vec3 &p = centroids[a], &q = centroids[b];
    return std::tie(key[a], p.x, p.y, p.z, triangles[a]) <
           std::tie(key[b], q.x, q.y, q.z, triangles[b]);
  });
  sorted.mesh.triangles.reserve(triangles.size());
  for (const Index t : triangle_order) sorted.mesh.triangles.push_back(triangles[t]);
  return sorted;
}

}  // namespace cvtmesh
