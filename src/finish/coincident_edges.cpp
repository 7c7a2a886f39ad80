#include "finish/coincident_edges.hpp"

#include <algorithm>
#include <iterator>
#include <utility>

#include "geometry/near_points.hpp"
#include "geometry/triangles_around.hpp"

namespace cvtmesh {

namespace {

Triangle sorted(Triangle t) {
  std::sort(t.begin(), t.end());
  return t;
}

bool has(const Triangle& t, Index v) {
  return std::ranges::find(t, v) != t.end();
}

class EdgeCollapser {
 public:
  EdgeCollapser(TriangleMesh& mesh, const std::vector<bool>& on_feature)
      : mesh_(mesh),
        on_feature_(on_feature),
        around_(triangles_around(mesh)),
        gone_(mesh.triangles.size(), false) {}

  bool has_edge(Index x, Index y) const {
    return std::ranges::any_of(around_[x], [&](Index t) { return has(mesh_.triangles[t], y); });
  }

  // Merges `x` into its neighbour `y` where that keeps the topology. Where the link condition
  // fails only for a vertex of three triangles whose neighbours are x, y and a third common
  // neighbour (in a fold, a cell's piece inside the triangle of two others at one point), that
  // vertex goes first, its fan made the one triangle it covers; undone if the collapse still
  // cannot be made.
  bool collapse(Index x, Index y) {
    if (collapsible(x, y)) {
      merge(x, y);
      return true;
    }
    bool removed = false;
    for (const Index w : common_neighbours(x, y))
      if (around_[w].size() == 3 && !on_feature_[w]) {
        const std::vector<Index> nw = neighbours(w);
        if (std::ranges::binary_search(nw, x) && std::ranges::binary_search(nw, y))
          removed = remove_fan(w) || removed;
      }
    const bool done = removed && collapsible(x, y);
    if (done)
      merge(x, y);
    else
      undo();
    saved_triangles_.clear();
    saved_around_.clear();
    return done;
  }

  // Drops the triangles the collapses took away.
  void finish() { erase_marked_triangles(mesh_, gone_); }

 private:
  // The other corners of `v`'s triangles, sorted, each once per triangle: a neighbour across an
  // edge of one triangle comes once.
  std::vector<Index> star_corners(Index v) const {
    std::vector<Index> out;
    for (const Index t : around_[v])
      for (const Index w : mesh_.triangles[t])
        if (w != v) out.push_back(w);
    std::sort(out.begin(), out.end());
    return out;
  }

  // The vertices sharing a triangle with `v`, sorted.
  std::vector<Index> neighbours(Index v) const {
    std::vector<Index> out = star_corners(v);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  std::vector<Index> common_neighbours(Index x, Index y) const {
    const std::vector<Index> nx = neighbours(x), ny = neighbours(y);
    std::vector<Index> common;
    std::ranges::set_intersection(nx, ny, std::back_inserter(common));
    return common;
  }

  // Whether `v` ends an edge of one triangle.
  bool on_boundary(Index v) const {
    const std::vector<Index> corners = star_corners(v);
    for (std::size_t i = 0; i < corners.size(); ++i)
      if ((i == 0 || corners[i - 1] != corners[i]) &&
          (i + 1 == corners.size() || corners[i + 1] != corners[i]))
        return true;
    return false;
  }

  // The link condition: x-y an edge of one or two triangles, whose third corners are the only
  // neighbours x and y share, each left with a triangle beside the one that goes (two, inside
  // the surface); not an inner edge between two boundary vertices (that would pinch them); and
  // no triangle at x made one that y has already.
  bool collapsible(Index x, Index y) const {
    std::vector<Index> opposite;
    std::size_t both = 0;
    for (const Index t : around_[x])
      if (has(mesh_.triangles[t], y)) {
        ++both;
        for (const Index w : mesh_.triangles[t])
          if (w != x && w != y) opposite.push_back(w);
      }
    if (both == 0 || both > 2) return false;
    if (both == 2 && on_boundary(x) && on_boundary(y)) return false;
    std::sort(opposite.begin(), opposite.end());
    if (common_neighbours(x, y) != opposite) return false;
    for (const Index w : opposite)
      if (around_[w].size() <= both + 1) return false;
    for (const Index t : around_[x]) {
      if (has(mesh_.triangles[t], y)) continue;
      Triangle moved = mesh_.triangles[t];
      std::ranges::replace(moved, x, y);
      const Triangle key = sorted(moved);
      for (const Index s : around_[y])
        if (sorted(mesh_.triangles[s]) == key) return false;
    }
    return true;
  }

  // The collapse: x's triangles with y go, the others take y for x.
  void merge(Index x, Index y) {
    for (const Index t : around_[x]) {
      Triangle& f = mesh_.triangles[t];
      if (has(f, y)) {
        gone_[t] = true;
        for (const Index w : f)
          if (w != x) std::erase(around_[w], t);
      } else {
        std::ranges::replace(f, x, y);
        around_[y].push_back(t);
      }
    }
    around_[x].clear();
  }

  // Makes the closed fan of three triangles round `w` the one triangle it covers, where that one
  // is not there already; saved for undo().
  bool remove_fan(Index w) {
    std::vector<Edge> outer;  // each triangle's side across from w, in its orientation
    for (const Index t : around_[w]) {
      const Triangle& f = mesh_.triangles[t];
      const auto i = std::ranges::find(f, w) - f.begin();
      outer.push_back({f[(i + 1) % 3], f[(i + 2) % 3]});
    }
    const auto next = [&](Index from) {
      const auto e = std::ranges::find_if(outer, [&](const Edge& s) { return s[0] == from; });
      return e == outer.end() ? w : (*e)[1];
    };
    const Triangle cover{outer[0][0], outer[0][1], next(outer[0][1])};
    if (cover[2] == w || next(cover[2]) != cover[0] || cover[2] == cover[0]) return false;
    for (const Index t : around_[cover[0]])
      if (sorted(mesh_.triangles[t]) == sorted(cover)) return false;
    const std::vector<Index> fan = around_[w];
    for (const Index v : {w, cover[0], cover[1], cover[2]})
      saved_around_.push_back({v, around_[v]});
    for (const Index t : fan) {
      saved_triangles_.push_back({t, mesh_.triangles[t], gone_[t]});
      gone_[t] = true;
      for (const Index v : mesh_.triangles[t]) std::erase(around_[v], t);
    }
    gone_[fan[0]] = false;
    mesh_.triangles[fan[0]] = cover;
    for (const Index v : cover) around_[v].push_back(fan[0]);
    return true;
  }

  // Puts back what remove_fan changed, last first.
  void undo() {
    for (auto it = saved_around_.rbegin(); it != saved_around_.rend(); ++it)
      around_[it->first] = std::move(it->second);
    for (auto it = saved_triangles_.rbegin(); it != saved_triangles_.rend(); ++it) {
      mesh_.triangles[it->triangle] = it->was;
      gone_[it->triangle] = it->gone;
    }
  }

  struct SavedTriangle {
    Index triangle;
    Triangle was;
    bool gone;
  };
  TriangleMesh& mesh_;
  const std::vector<bool>& on_feature_;
  std::vector<std::vector<Index>> around_;
  std::vector<bool> gone_;
  std::vector<SavedTriangle> saved_triangles_;
  std::vector<std::pair<Index, std::vector<Index>>> saved_around_;
};

}  // namespace

std::size_t collapse_coincident_edges(TriangleMesh& mesh, std::vector<Edge>& features) {
  const double tolerance = near_point_tolerance(mesh.vertices);
  std::vector<Edge> found;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      if (distance(mesh.vertices[a], mesh.vertices[b]) <= tolerance)
        found.push_back({std::min(a, b), std::max(a, b)});
    }
  if (found.empty()) return 0;
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  std::vector<bool> on_feature(mesh.vertices.size(), false);
  for (const Edge& e : features) on_feature[e[0]] = on_feature[e[1]] = true;
  EdgeCollapser collapser(mesh, on_feature);
  std::size_t collapsed = 0;
  for (const Edge& e : found) {
    if (!collapser.has_edge(e[0], e[1])) continue;  // an earlier collapse took it
    // The end off the feature curves goes, else the later one: either way no point moves.
    const bool first_goes = !on_feature[e[0]] && on_feature[e[1]];
    const Index x = first_goes ? e[0] : e[1], y = first_goes ? e[1] : e[0];
    if (!collapser.collapse(x, y)) continue;
    ++collapsed;
    if (!on_feature[x]) continue;
    on_feature[y] = true;  // its curve edges now run from y
    for (Edge& f : features) {
      std::ranges::replace(f, x, y);
      std::sort(f.begin(), f.end());
    }
    std::erase_if(features, [](const Edge& f) { return f[0] == f[1]; });
    std::sort(features.begin(), features.end());
    features.erase(std::unique(features.begin(), features.end()), features.end());
  }
  collapser.finish();
  return collapsed;
}

}  // namespace cvtmesh
