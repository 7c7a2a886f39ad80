#include "remesh/flip_links.hpp"

#include <algorithm>

#include "geometry/triangles_around.hpp"
#include "quality/min_shape.hpp"

namespace cvtmesh {

namespace {

Vec3 normal(const TriangleMesh& m, const Triangle& t) {
  const Vec3& a = m.vertices[t[0]];
  return cross(m.vertices[t[1]] - a, m.vertices[t[2]] - a);
}

double smallest_angle(const TriangleMesh& m, const Triangle& t) {
  return min_shape(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]).min_angle;
}

// The triangles at each vertex, kept up to date through the flips.
class VertexTriangles {
 public:
  explicit VertexTriangles(const TriangleMesh& m) : of_(triangles_around(m)) {}
  const std::vector<Index>& operator()(Index v) const { return of_[v]; }
  void add(Index v, Index t) { of_[v].push_back(t); }
  void remove(Index v, Index t) { std::erase(of_[v], t); }

 private:
  std::vector<std::vector<Index>> of_;
};

// Where vertex v is in t (0-2), or 3.
int position(const Triangle& t, Index v) {
  return t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : 3;
}

bool has_edge(const TriangleMesh& m, const VertexTriangles& at, Index a, Index b) {
  return std::any_of(at(a).begin(), at(a).end(),
                     [&](Index t) { return position(m.triangles[t], b) != 3; });
}

// Flips in edge (a, b) if one flip makes it with no angle under `min_angle`; whether it did.
bool flip_in(TriangleMesh& m, VertexTriangles& at, Index a, Index b, double min_angle) {
  for (const Index t1 : at(a)) {
    const Triangle& first = m.triangles[t1];
    const int k = position(first, a);
    const Index c = first[(k + 1) % 3], d = first[(k + 2) % 3];
    // Edge (c, d) has just two triangles: this one and (d, c, b).
    std::vector<Index> on_edge;
    for (const Index t : at(c))
      if (position(m.triangles[t], d) != 3) on_edge.push_back(t);
    if (on_edge.size() != 2) continue;
    const Index t2 = on_edge[0] == t1 ? on_edge[1] : on_edge[0];
    const Triangle& second = m.triangles[t2];
    const int j = position(second, d);
    if (second[(j + 1) % 3] != c || second[(j + 2) % 3] != b) continue;
    const Triangle new1{a, c, b}, new2{a, b, d};
    const Vec3 facing = normal(m, first) + normal(m, second);
    if (!(dot(normal(m, new1), facing) > 0 && dot(normal(m, new2), facing) > 0)) continue;
    if (smallest_angle(m, new1) < min_angle || smallest_angle(m, new2) < min_angle) continue;
    m.triangles[t1] = new1;
    m.triangles[t2] = new2;
    at.add(a, t2);
    at.add(b, t1);
    at.remove(c, t2);
    at.remove(d, t1);
    return true;
  }
  return false;
}

}  // namespace

std::vector<bool> flip_in_links(TriangleMesh& mesh, const std::vector<Edge>& links,
                                double min_angle_deg) {
  VertexTriangles at(mesh);
  std::vector<bool> flipped;
  for (const auto& [a, b] : links)
    // Orientation makes (a, b) and (b, a) the same search.
    flipped.push_back(!has_edge(mesh, at, a, b) && flip_in(mesh, at, a, b, min_angle_deg));
  return flipped;
}

std::size_t close_corner_tips(TriangleMesh& mesh, const std::vector<Index>& corners,
                              const std::vector<Edge>& links) {
  VertexTriangles at(mesh);
  std::size_t added = 0;
  for (const Index corner : corners) {
    if (!at(corner).empty()) continue;
    std::vector<Index> ends;  // the other ends of the corner's links
    for (const auto& [a, b] : links)
      if (a == corner || b == corner) ends.push_back(a == corner ? b : a);
    if (ends.size() != 2) continue;
    std::vector<Index> on_edge;  // the triangles on edge (ends[0], ends[1])
    for (const Index t : at(ends[0]))
      if (position(mesh.triangles[t], ends[1]) != 3) on_edge.push_back(t);
    if (on_edge.size() != 1) continue;
    // The new triangle runs the shared edge the other way round, as orientation requires.
    const Triangle& old = mesh.triangles[on_edge[0]];
    const bool forward = old[(position(old, ends[0]) + 1) % 3] == ends[1];
    const Triangle tip =
        forward ? Triangle{ends[1], ends[0], corner} : Triangle{ends[0], ends[1], corner};
    if (!(dot(normal(mesh, tip), normal(mesh, old)) > 0)) continue;
    const auto t = static_cast<Index>(mesh.triangles.size());
    mesh.triangles.push_back(tip);
    for (const Index v : tip) at.add(v, t);
    ++added;
  }
  return added;
}

}  // namespace cvtmesh
