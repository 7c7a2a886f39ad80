#include "sizing/gradation.hpp"

#include <functional>
#include <queue>
#include <utility>

namespace cvtmesh {

std::vector<double> graded(const TriangleMesh& mesh, std::vector<double> size, double gradation) {
  // Each vertex's neighbours, as a compressed adjacency list (each edge of a triangle both ways).
  const std::size_t n = mesh.vertices.size();
  std::vector<std::size_t> first(n + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (const Index v : t) first[v + 1] += 2;
  for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  std::vector<Index> neighbour(first[n]);
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      neighbour[next[t[k]]++] = t[(k + 1) % 3];
      neighbour[next[t[k]]++] = t[(k + 2) % 3];
    }

  using Entry = std::pair<double, Index>;  // tentative size, vertex: smallest first
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (Index v = 0; v < n; ++v) queue.push({size[v], v});
  std::vector<bool> done(n, false);
  while (!queue.empty()) {
    const auto [s, v] = queue.top();
    queue.pop();
    if (done[v] || s > size[v]) continue;
    done[v] = true;
    for (std::size_t i = first[v]; i < first[v + 1]; ++i) {
      const Index u = neighbour[i];
      const double through_v = s + distance(mesh.vertices[u], mesh.vertices[v]) / gradation;
      if (through_v < size[u]) {
        size[u] = through_v;
        queue.push({through_v, u});
      }
    }
  }
  return size;
}

}  // namespace cvtmesh
