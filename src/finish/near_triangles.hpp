// The triangles of a changing mesh whose boxes may overlap a given box: for improve_shapes's
// checks that a flip, move or collapse at a guarded vertex passes no triangle through another
// (finish/crossing_guard), which looked at every triangle each time (man.off at 10k, its
// finishing steps guarded at 139 vertices: a third of the remesh). A grid of the triangles'
// boxes as they were when it was built; since then, how far any vertex has moved from where the
// grid saw it (every box grows by at most that: `drift`), and the triangles whose corners were
// set anew (flips, collapses, their undoing), which are looked at always. Rebuilt when either
// grows large. The triangles found are a superset of those whose boxes overlap, so a check that
// looks at them decides as one that looks at all.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class NearTriangles {
 public:
  // Whether it must be built (again) before the next search.
  bool stale() const;
  // Over `mesh` as it is, but for the triangles flagged in `gone`.
  void build(const TriangleMesh& mesh, const std::vector<bool>& gone);
  // Vertex v was put at `to` (as the last step of a move, or where an undo puts it back).
  void moved(Index v, const Vec3& to);
  // Triangle t's corners were set anew.
  void rewired(Index t);
  // Calls visit(s), once each, for every triangle s whose box may overlap [lo, hi] now: those in
  // the grid's cells within `drift` of it, and every triangle rewired since the build.
  template <class Visit>
  void for_each_near(const Vec3& lo, const Vec3& hi, const Visit& visit) const {
    ++stamp_;
    const auto once = [&](Index s) {
      if (seen_[s] == stamp_) return;
      seen_[s] = stamp_;
      visit(s);
    };
    const Cell a = cell_of({lo.x - drift_, lo.y - drift_, lo.z - drift_}),
               b = cell_of({hi.x + drift_, hi.y + drift_, hi.z + drift_});
    // A box wider than the grid's filled cells (a long sliver searched) takes them all: no search
    // costs more than a pass over the triangles.
    const double span = static_cast<double>(b.i - a.i + 1) * static_cast<double>(b.j - a.j + 1) *
                        static_cast<double>(b.k - a.k + 1);
    if (span > static_cast<double>(cells_.size())) {
      for (const auto& [cell, listed] : cells_)
        for (const Index s : listed) once(s);
    } else {
      for (std::int64_t i = a.i; i <= b.i; ++i)
        for (std::int64_t j = a.j; j <= b.j; ++j)
          for (std::int64_t k = a.k; k <= b.k; ++k)
            if (const auto found = cells_.find(key({i, j, k})); found != cells_.end())
              for (const Index s : found->second) once(s);
    }
    for (const Index s : everywhere_) once(s);
    for (const Index s : rewired_) once(s);
  }

 private:
  struct Cell {
    std::int64_t i, j, k;
  };
  Cell cell_of(const Vec3& p) const;
  static std::uint64_t key(const Cell& c);

  bool built_ = false;
  std::vector<Vec3> at_;  // the vertices where the grid saw them
  double cell_ = 1, drift_ = 0;
  std::unordered_map<std::uint64_t, std::vector<Index>> cells_;
  std::vector<Index> everywhere_;  // triangles spanning too many cells to list in each
  std::vector<Index> rewired_;
  std::vector<char> is_rewired_;
  mutable std::vector<std::uint64_t> seen_;
  mutable std::uint64_t stamp_ = 0;
};

}  // namespace cvtmesh
