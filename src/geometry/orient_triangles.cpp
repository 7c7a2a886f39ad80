#include "geometry/orient_triangles.hpp"

#include "geometry/triangle_sides.hpp"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>

namespace cvtmesh {

namespace {

// Per triangle, the triangles across its manifold edges, and whether the two run along that edge
// the same way (one of them must then flip): compressed lists.
struct Neighbours {
  std::vector<std::size_t> start;
  std::vector<std::pair<std::size_t, bool>> across;
};

Neighbours manifold_neighbours(const TriangleMesh& mesh) {
  const std::size_t nt = mesh.triangles.size();
  const std::vector<TriangleSide> sides = sorted_sides(mesh);
  std::vector<std::tuple<std::size_t, std::size_t, bool>> links;  // both ways
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    if (j - i == 2) {
      const bool same_way = sides[i].forward == sides[i + 1].forward;
      links.emplace_back(sides[i].triangle, sides[i + 1].triangle, same_way);
      links.emplace_back(sides[i + 1].triangle, sides[i].triangle, same_way);
    }
    i = j;
  }
  std::sort(links.begin(), links.end());
  Neighbours n;
  n.start.assign(nt + 1, 0);
  for (const auto& [t, u, same] : links) ++n.start[t + 1];
  for (std::size_t t = 0; t < nt; ++t) n.start[t + 1] += n.start[t];
  for (const auto& [t, u, same] : links) n.across.emplace_back(u, same);
  return n;
}

double area(const TriangleMesh& mesh, std::size_t t) {
  const auto [a, b, c] = mesh.corners(t);
  return 0.5 * norm(cross(b - a, c - a));
}

}  // namespace

std::vector<std::size_t> triangles_to_flip(const TriangleMesh& mesh) {
  const std::size_t nt = mesh.triangles.size();
  const Neighbours n = manifold_neighbours(mesh);
  std::vector<std::int8_t> flip(nt, -1);  // -1: not reached yet
  std::vector<std::size_t> flips, patch;
  for (std::size_t first = 0; first < nt; ++first) {
    if (flip[first] >= 0) continue;
    // Breadth first over the patch, each triangle flipped or not as the one it was reached from
    // requires.
    patch.assign(1, first);
    flip[first] = 0;
    bool consistent = true;
    for (std::size_t k = 0; k < patch.size(); ++k) {
      const std::size_t t = patch[k];
      for (std::size_t e = n.start[t]; e < n.start[t + 1]; ++e) {
        const auto [u, same_way] = n.across[e];
        const std::int8_t wanted = static_cast<std::int8_t>(flip[t] ^ (same_way ? 1 : 0));
        if (flip[u] < 0) {
          flip[u] = wanted;
          patch.push_back(u);
        } else if (flip[u] != wanted) {
          consistent = false;
        }
      }
    }
    if (!consistent) continue;
    double flipped_area = 0, kept_area = 0;
    for (const std::size_t t : patch) (flip[t] ? flipped_area : kept_area) += area(mesh, t);
    const std::int8_t flipped = flipped_area > kept_area ? 0 : 1;  // the minority flips
    for (const std::size_t t : patch)
      if (flip[t] == flipped) flips.push_back(t);
  }
  std::sort(flips.begin(), flips.end());
  return flips;
}

std::size_t orient_consistently(TriangleMesh& mesh) {
  const std::vector<std::size_t> flips = triangles_to_flip(mesh);
  for (const std::size_t t : flips) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
  return flips.size();
}

}  // namespace cvtmesh
